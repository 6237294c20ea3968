#pragma once
// Steiner points above 34 degrees: the off-centre where the triangles its
// insertion makes all meet the bound, else a point between it and the
// shortest edge whose new triangles do (after Erten and Üngör, "Quality
// triangulations with locally optimal Steiner points", 2009).
//
// Above about 34 degrees the off-centre's insertion often makes a new
// triangle worse than the bound on the far side of its cavity, and
// refinement may then cascade (convergence.hpp).  Inserting p replaces p's
// cavity by the star of p: one triangle (p, a, b) per edge (a, b) of the
// cavity's boundary.  So the quality of an insertion is known before it is
// made, from the cavity alone (star_quality), and where the off-centre's
// star is poor a better point can be looked for.
//
// Where the point may go.  The new triangle on the shortest edge pq meets
// the bound only where the point sees pq under at least θ and pq's ends see
// it at least θ from pq: a region between the edge and the off-centre, about
// the bisector of pq.  The search looks there on a grid, rows from the
// off-centre's height down towards the edge, each from the bisector out to
// either side.  The first point whose star meets the bound (with a margin)
// wins: the farthest from pq, so the largest new triangles, the fewest
// Steiner points.  Erten and Üngör take the point whose star's smallest
// angle is largest; near pq, that makes small triangles and refinement
// cascades (docs/refinement-order.md, "Above 34 degrees").  When no point's
// star meets the bound, the Move rule says what is inserted: the off-centre,
// or a point whose star has fewer poor triangles.  Which rule lets
// refinement end depends on the input, so -P1 tries them in turn
// (star_placements, api::refine_stage).  A point must stay admissible
// (placement.hpp), must not lie beyond a subsegment, and must not encroach
// on one: the refiner would split the subsegment instead, as it does for
// the off-centre.

#include <array>
#include <cstdint>

#include "refine/placement.hpp"

namespace gpdr::refine {

// What inserting p would make of the neighbourhood of poor triangle t, read
// from the mesh alone (nothing is marked or changed).
struct StarQuality {
    // p lies in the cavity grown from t without crossing subsegments (else
    // it lies beyond a subsegment, which the refiner would split instead).
    bool located = false;
    // p encroaches on a subsegment of the cavity's boundary (the refiner
    // would split it instead of inserting p).
    bool encroaches = false;
    // The sine of the smallest angle of the star's triangles (0 for a
    // degenerate one).
    double smallest_sine = 0;
    // The star's triangles whose smallest angle's sine is below `goal`.
    int poor = 0;
    // The squared length of the star's shortest edge from p.
    double nearest = 0;
};
StarQuality star_quality(const PoorTriangle& t, const geometry::Point& p, double goal,
                         PlacementScratch& scratch);

class StarPlacement final : public PlacementStrategy {
public:
    // When no point's star meets the bound (such a point always wins), what
    // is inserted; a point other than the off-centre only if its star's
    // smallest angle is no smaller than the off-centre star's.
    enum class Move : std::uint8_t {
        to_good_star,   // the off-centre
        to_fewer_poor,  // the first point with the fewest poor triangles in its star
        to_farther,     // of those with the fewest, the farthest from its nearest vertex
    };
    // The goal for a star's smallest angle's sine: the bound's, times this.
    static constexpr double goal_margin = 1.002;

    explicit StarPlacement(Move move = Move::to_good_star) : move_(move) {}
    geometry::Point place(const PoorTriangle& t, PlacementScratch& scratch) const override;
    const char* name() const override;

private:
    Move move_;
};

// The placements -P1 tries in turn above 34 degrees (api::refine_stage), the
// built-in one (builtin_placement) first.
std::array<const PlacementStrategy*, 3> star_placements();

}  // namespace gpdr::refine
