#pragma once
// Steiner point placement strategies (GPDR paper §2.2).
//
// The paper's Definition 1: for a poor triangle with circumcentre c,
// circumradius r and shortest edge l, every point strictly inside the
// selection disk (centre c, radius r - sqrt(2) l) keeps Delaunay refinement
// terminating and size-optimal.  So where the point goes is a strategy, and
// any strategy that stays in the disk is correct:
//
//   circumcentre   Ruppert / Chew: the centre of the disk.
//   off_centre     Üngör's off-centre (Triangle's default and gpdr's): on the
//                  shortest edge's bisector, 5% short of the point where the
//                  new triangle on that edge has radius-edge ratio exactly
//                  rho_bar (as Triangle does: at exactly rho_bar rounding
//                  leaves the new triangle poor); the circumcentre when that
//                  is nearer.  (Remark 2 of the paper: inside the disk.)
//   optimisation   the paper's method: candidates on the arc Γ = (circle
//                  through the shortest edge's ends and the off-centre) ∩
//                  disk, 24 evenly spread plus the off-centre; each scored
//                  F(p) = Σ over the cavity of p of P(t), P = -1 for a poor
//                  triangle, +1 for a good one; the minimum wins, ties go to
//                  the off-centre.  The cavity is found by a read-only search
//                  from the poor triangle that never crosses a subsegment.
//   star           -P1's above 34 degrees: the off-centre where the triangles
//                  its insertion makes meet the bound, else a point between it
//                  and the shortest edge whose new triangles do
//                  (star_placement.hpp).
//
// Contract of place(): return an admissible point (admissible_point below):
// strictly inside t.disk when the disk is not empty; when it is empty
// (r <= sqrt(2) l: a triangle poor only by its size, or most poor triangles
// under an angle bound above 20.7 degrees, where the paper's guarantee does
// not reach) strictly inside the circumcircle, so that the point destroys t.
// In checked mode (RefineSettings::checked, on by default in debug builds
// and in the tests) the refiner verifies every returned point and throws
// gpdr::Error naming the strategy if it is not admissible.

// Writing a strategy: derive from PlacementStrategy, implement place() and
// name(), pass a pointer in RefineSettings::strategy.  place() is called from
// several threads at once when refinement runs in parallel: it must not
// change shared state (keep per-call state in `scratch`, which the calling
// thread owns) and must read the mesh only (PoorTriangle::mesh is const).

#include <cstdint>
#include <vector>

#include <gpdr/options.hpp>

#include "geometry/constructions.hpp"
#include "mesh/mesh.hpp"
#include "refine/quality.hpp"

namespace gpdr::refine {

// Everything a strategy may want about the poor triangle.
struct PoorTriangle {
    const mesh::Mesh* mesh = nullptr;
    mesh::TriangleId id = mesh::no_triangle;
    geometry::Point corner[3];             // counter-clockwise, corner k opposite edge k
    geometry::Circle circle;               // circumcircle (centre, squared radius)
    int shortest_edge = 0;                 // index of the shortest edge (opposite that corner)
    double shortest_length = 0;            // l
    double rho_bar = 0;                    // the radius-edge bound (+infinity: no angle test)
    geometry::Disk disk;                   // the selection disk (radius <= 0: empty)
    const QualityTest* quality = nullptr;  // for strategies that judge neighbours
};

// Scratch a strategy may use; owned by the calling thread, reused.
struct PlacementScratch {
    std::vector<mesh::TriangleId> cavity;
    struct Score {
        mesh::TriangleId id;
        int penalty;
    };
    std::vector<Score> scores;
};

class PlacementStrategy {
public:
    virtual ~PlacementStrategy() = default;
    // An admissible point for t (see the contract above).
    virtual geometry::Point place(const PoorTriangle& t, PlacementScratch& scratch) const = 0;
    virtual const char* name() const = 0;
};

class CircumcentrePlacement final : public PlacementStrategy {
public:
    geometry::Point place(const PoorTriangle& t, PlacementScratch& scratch) const override;
    const char* name() const override { return "circumcentre"; }
};

class OffCentrePlacement final : public PlacementStrategy {
public:
    // The fraction of the exact off-centre's distance from the shortest edge
    // at which the point is placed (see place()).
    static constexpr double off_centre_fraction = 0.95;

    geometry::Point place(const PoorTriangle& t, PlacementScratch& scratch) const override;
    const char* name() const override { return "off-centre"; }
};

class OptimisationPlacement final : public PlacementStrategy {
public:
    explicit OptimisationPlacement(int samples = 24) : samples_(samples < 1 ? 1 : samples) {}
    geometry::Point place(const PoorTriangle& t, PlacementScratch& scratch) const override;
    const char* name() const override { return "optimisation"; }

    // F(p) of the paper: Σ P(t) over the cavity of p (read-only search from
    // t.id).  Exposed for tests.
    static int cavity_penalty(const PoorTriangle& t, const geometry::Point& p,
                              PlacementScratch& scratch);

private:
    int samples_;
};

// Above this angle bound, in degrees, -P1 (the default) places Steiner
// points with StarPlacement (star_placement.hpp): the off-centre where its
// new triangles meet the bound, else a better point near it.  At and below
// it, the off-centre alone, as Triangle.
inline constexpr double star_placement_above = 34.0;

// The built-in strategy for -P0/-P1/-P2 with an angle bound of
// min_angle_degrees (0: none); stateless, shared by all threads.
const PlacementStrategy& builtin_placement(Placement kind, double min_angle_degrees = 0);

// Whether p is strictly inside t.disk.
inline bool in_selection_disk(const PoorTriangle& t, const geometry::Point& p) {
    return t.disk.radius > 0 &&
           geometry::squared_distance(p, t.disk.centre) < t.disk.radius * t.disk.radius;
}

// Where a strategy's point may go.  When the selection disk is not empty, in
// it (the paper's Definition 1: termination and size optimality follow for
// rho_bar >= sqrt 2).  When it is empty -- a triangle poor by its size
// rather than its shape (r < sqrt 2 l), or any angle bound above 20.7
// degrees, where rho_bar < sqrt 2 and the theory gives no guarantee -- the
// point must still destroy t: strictly inside its circumcircle.  There the
// off-centre is what Triangle uses, and refinement's own guards ensure it
// ends (refine.hpp).
inline bool admissible_point(const PoorTriangle& t, const geometry::Point& p) {
    if (t.disk.radius > 0) return in_selection_disk(t, p);
    return geometry::squared_distance(p, t.circle.centre) < t.circle.radius_squared;
}

// Fills a PoorTriangle for live triangle id (corners, circle, shortest edge,
// selection disk).
PoorTriangle describe_poor_triangle(const mesh::Mesh& mesh, mesh::TriangleId id,
                                    const QualityTest& quality);

}  // namespace gpdr::refine
