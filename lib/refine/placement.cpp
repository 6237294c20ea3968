// The built-in placement strategies (see placement.hpp): circumcentre,
// Üngör's off-centre, and the GPDR paper's optimisation over the arc Γ.

#include "refine/placement.hpp"

#include <cmath>
#include <numbers>

#include "mesh/insert.hpp"
#include "refine/star_placement.hpp"

namespace gpdr::refine {

using geometry::Point;

PoorTriangle describe_poor_triangle(const mesh::Mesh& mesh, mesh::TriangleId id,
                                    const QualityTest& quality) {
    const mesh::Triangle& r = mesh.triangle(id);
    const Point a = mesh.point(r.v[0]), b = mesh.point(r.v[1]), c = mesh.point(r.v[2]);
    const geometry::Circle circle = geometry::circumcircle(a, b, c);
    const geometry::EdgeLength e = geometry::shortest_edge(a, b, c);
    const double shortest_length = std::sqrt(e.length_squared);
    // Every member given once (a default-initialised record would be
    // cleared first: a block store per poor triangle taken).
    return PoorTriangle{
        .mesh = &mesh,
        .id = id,
        .corner = {a, b, c},
        .circle = circle,
        .shortest_edge = e.edge,
        .shortest_length = shortest_length,
        .rho_bar = quality.rho_bar(),
        .disk = {circle.centre,
                 std::sqrt(circle.radius_squared) - std::numbers::sqrt2 * shortest_length},
        .quality = &quality,
    };
}

Point CircumcentrePlacement::place(const PoorTriangle& t, PlacementScratch&) const {
    return t.circle.centre;
}

Point OffCentrePlacement::place(const PoorTriangle& t, PlacementScratch&) const {
    // 5% short of Üngör's exact off-centre (as Triangle does): the exact
    // point makes a new triangle with ratio exactly rho_bar, which rounding
    // may leave just poor, costing another Steiner point.  Where the shorter
    // point leaves the selection disk, the exact one (inside it for
    // rho_bar >= sqrt 2) is used.
    const Point near =
        geometry::off_centre(t.corner[0], t.corner[1], t.corner[2], t.rho_bar, off_centre_fraction);
    if (admissible_point(t, near)) return near;
    const Point p = geometry::off_centre(t.corner[0], t.corner[1], t.corner[2], t.rho_bar);
    if (admissible_point(t, p)) return p;
    // A non-empty disk that the off-centre misses (rho_bar < sqrt 2 and a
    // very skinny triangle): the off-centre lies on the ray from the
    // circumcentre towards the shortest edge, beyond the disk; take the
    // disk's point on that ray nearest to it.
    const double dx = p.x - t.circle.centre.x, dy = p.y - t.circle.centre.y;
    const double d = std::sqrt(dx * dx + dy * dy);
    if (!(d > 0) || !(t.disk.radius > 0)) return t.circle.centre;
    const double s = 0.99 * t.disk.radius / d;
    return {t.circle.centre.x + s * dx, t.circle.centre.y + s * dy};
}

int OptimisationPlacement::cavity_penalty(const PoorTriangle& t, const Point& p,
                                          PlacementScratch& scratch) {
    const mesh::Mesh& mesh = *t.mesh;
    auto& cavity = scratch.cavity;
    cavity.clear();
    // p is strictly inside t's circumcircle (it is in the selection disk),
    // so t is in the cavity; grow it without crossing subsegments.  The
    // visited test is a linear search: cavities are a handful of triangles,
    // and the limit keeps a pathological one cheap.
    constexpr std::size_t limit = 256;
    cavity.push_back(t.id);
    int total = 0;
    for (std::size_t i = 0; i < cavity.size(); ++i) {
        const mesh::TriangleId id = cavity[i];
        int penalty = 0;
        bool known = false;
        for (const auto& s : scratch.scores)
            if (s.id == id) {
                penalty = s.penalty;
                known = true;
                break;
            }
        if (!known) {
            const mesh::Triangle& r = mesh.triangle(id);
            const TriangleMeasures m =
                QualityTest::measure(mesh.point(r.v[0]), mesh.point(r.v[1]), mesh.point(r.v[2]));
            penalty = t.quality->assess(mesh, id, m) == Poorness::good ? 1 : -1;
            scratch.scores.push_back({id, penalty});
        }
        total += penalty;
        if (cavity.size() >= limit) continue;
        const mesh::Triangle& r = mesh.triangle(id);
        for (int k = 0; k < 3; ++k) {
            const mesh::EdgeRef across = r.n[k];
            if (across.is_none() || r.is_subsegment(k)) continue;
            const mesh::TriangleId u = across.triangle();
            bool seen = false;
            for (mesh::TriangleId c : cavity) seen = seen || c == u;
            if (!seen && mesh::in_circumcircle(mesh, mesh.triangle(u), p)) cavity.push_back(u);
        }
    }
    return total;
}

Point OptimisationPlacement::place(const PoorTriangle& t, PlacementScratch& scratch) const {
    scratch.scores.clear();
    // Γ runs through the point the off-centre strategy aims at (5% short of
    // Üngör's, see OffCentrePlacement::place): every point of it makes the
    // new triangle on the shortest edge a little better than the bound,
    // rather than exactly at it, where rounding would leave it poor.
    const Point off = geometry::off_centre(t.corner[0], t.corner[1], t.corner[2], t.rho_bar,
                                           OffCentrePlacement::off_centre_fraction);
    // Start from the off-centre strategy's point (admissible, and what ties
    // go to); the arc can only improve on it.
    static const OffCentrePlacement off_centre_strategy;
    Point best = off_centre_strategy.place(t, scratch);
    int best_score = cavity_penalty(t, best, scratch);

    // Γ: the circle through the shortest edge's ends and the off-centre.
    const Point& p = t.corner[mesh::next3(t.shortest_edge)];
    const Point& q = t.corner[mesh::prev3(t.shortest_edge)];
    if (geometry::orient2d(p, q, off) != 0) {
        const geometry::Circle gamma = geometry::circumcircle(p, q, off);
        const double rg = std::sqrt(gamma.radius_squared);
        const double dx = t.disk.centre.x - gamma.centre.x;
        const double dy = t.disk.centre.y - gamma.centre.y;
        const double d = std::sqrt(dx * dx + dy * dy);
        const double R = t.disk.radius;
        // Γ meets the disk's boundary at angles beta ± alpha (seen from Γ's
        // centre); the part of Γ inside the disk is the arc around beta.
        if (d > 0 && d < rg + R && d > std::abs(rg - R)) {
            const double cos_alpha = (d * d + rg * rg - R * R) / (2 * d * rg);
            const double alpha = std::acos(std::fmax(-1.0, std::fmin(1.0, cos_alpha)));
            const double beta = std::atan2(dy, dx);
            for (int i = 0; i < samples_; ++i) {
                const double s = -1.0 + 2.0 * (i + 1) / (samples_ + 1);
                const double phi = beta + alpha * s;
                const Point c{gamma.centre.x + rg * std::cos(phi),
                              gamma.centre.y + rg * std::sin(phi)};
                if (!in_selection_disk(t, c)) continue;
                const int score = cavity_penalty(t, c, scratch);
                if (score < best_score) {
                    best = c;
                    best_score = score;
                }
            }
        }
    }
    return best;
}

const PlacementStrategy& builtin_placement(Placement kind, double min_angle_degrees) {
    static const CircumcentrePlacement circumcentre;
    static const OffCentrePlacement off_centre;
    static const OptimisationPlacement optimisation;
    switch (kind) {
        case Placement::circumcentre:
            return circumcentre;
        case Placement::optimisation:
            return optimisation;
        case Placement::off_centre:
            break;
    }
    if (min_angle_degrees > star_placement_above) return *star_placements()[0];
    return off_centre;
}

}  // namespace gpdr::refine
