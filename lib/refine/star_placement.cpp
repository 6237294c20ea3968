// The star placement above 34 degrees (see star_placement.hpp).

#include "refine/star_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/predicates.hpp"
#include "mesh/insert.hpp"
#include "refine/segments.hpp"

namespace gpdr::refine {

using geometry::Point;

namespace {

// The sine of the smallest angle of triangle (a, b, c): twice its area over
// the product of its two longer sides (l_min / 2R, with R = abc / 4 area).
double smallest_sine(const Point& a, const Point& b, const Point& c) {
    const double ab = geometry::squared_distance(a, b);
    const double bc = geometry::squared_distance(b, c);
    const double ca = geometry::squared_distance(c, a);
    const double shortest = std::min({ab, bc, ca});
    const double twice_area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    const double longer = ab * bc * ca / shortest;  // the product of the two longer, squared
    if (!(twice_area > 0) || !(longer > 0)) return 0;
    return twice_area / std::sqrt(longer);
}

bool seen(const std::vector<mesh::TriangleId>& cavity, mesh::TriangleId id) {
    for (const mesh::TriangleId c : cavity)
        if (c == id) return true;
    return false;
}

}  // namespace

StarQuality star_quality(const PoorTriangle& t, const Point& p, double goal,
                         PlacementScratch& scratch) {
    const mesh::Mesh& mesh = *t.mesh;
    auto& cavity = scratch.cavity;
    cavity.clear();
    // p is strictly inside t's circumcircle (it is admissible), so t is in
    // the cavity; grow it as the refiner's insertion does (mesh/cavity.hpp),
    // without crossing subsegments.  The limit keeps a pathological cavity
    // cheap: its star is judged by the triangles seen.
    constexpr std::size_t limit = 64;
    cavity.push_back(t.id);
    StarQuality star;
    star.smallest_sine = 1;
    star.nearest = std::numeric_limits<double>::infinity();
    const double lens = t.quality->encroachment_lens();
    for (std::size_t i = 0; i < cavity.size(); ++i) {
        const mesh::Triangle& r = mesh.triangle(cavity[i]);
        const Point* corner[3] = {&mesh.point(r.v[0]), &mesh.point(r.v[1]), &mesh.point(r.v[2])};
        if (!star.located && geometry::orient2d(*corner[0], *corner[1], p) >= 0 &&
            geometry::orient2d(*corner[1], *corner[2], p) >= 0 &&
            geometry::orient2d(*corner[2], *corner[0], p) >= 0)
            star.located = true;
        for (int k = 0; k < 3; ++k) {
            const mesh::EdgeRef across = r.n[k];
            const Point& a = *corner[mesh::next3(k)];
            const Point& b = *corner[mesh::prev3(k)];
            if (!across.is_none() && !r.is_subsegment(k)) {
                const mesh::TriangleId u = across.triangle();
                if (seen(cavity, u)) continue;
                if (cavity.size() < limit && mesh::in_circumcircle(mesh, mesh.triangle(u), p)) {
                    cavity.push_back(u);
                    continue;
                }
            } else if (r.is_subsegment(k) && encroaches(a, b, p, lens)) {
                star.encroaches = true;
            }
            // (a, b) is an edge of the cavity's boundary: (a, b, p) is new.
            const double sine = smallest_sine(a, b, p);
            star.nearest = std::min(star.nearest, geometry::squared_distance(a, p));
            star.smallest_sine = std::min(star.smallest_sine, sine);
            star.poor += sine < goal ? 1 : 0;
        }
    }
    return star;
}

namespace {

// The grid: rows + 1 rows, the first at first_row of the way from the
// off-centre's height to the lowest, each with 2 sides + 1 points.
constexpr int rows = 8;
constexpr int sides = 3;
constexpr double first_row = 0.02;

// The frame of the grid: the shortest edge's midpoint m, unit direction u
// and inward normal n, the heights of its first and last rows over the
// edge, the tangent of the bound and the edge's length.
struct Grid {
    Point m;
    double ux, uy, nx, ny;
    double top, bottom;
    double tan_bound;
    double shortest;
};

// The grid search of StarPlacement::place: the first point whose star
// meets the goal, else the best by the Move rule against the off-centre,
// whose star is `at_off` (a candidate itself when `off_usable`).
Point best_on_grid(const PoorTriangle& t, const Grid& g, const Point& off,
                   const StarQuality& at_off, bool off_usable, double goal,
                   StarPlacement::Move move, PlacementScratch& scratch) {
    using Move = StarPlacement::Move;
    // Rows from the off-centre's height down towards pq; in each, the
    // bisector first, then either side out to where the angles at p and q
    // would fall under θ.  The first point whose star meets the goal wins;
    // else the best by the Move rule, the off-centre unless one beats it.
    Point best = off;
    int best_poor = off_usable ? at_off.poor : std::numeric_limits<int>::max();
    double best_nearest = off_usable ? at_off.nearest : 0;
    const double top = g.top, bottom = g.bottom, l = g.shortest;
    for (int i = 0; i <= rows; ++i) {
        const double h = top - (top - bottom) * (i == 0 ? first_row : double(i) / (rows + 1));
        const double half_width = std::max(0.0, h / g.tan_bound - 0.5 * l);
        for (int j = 0; j <= 2 * sides; ++j) {
            if (i == 0 && j == 0) continue;  // the off-centre itself
            const int side = (j + 1) / 2 * (j % 2 == 1 ? 1 : -1);
            const double a = half_width * side / (sides + 1);
            const Point x{g.m.x + h * g.nx + a * g.ux, g.m.y + h * g.ny + a * g.uy};
            if (!admissible_point(t, x)) continue;
            const StarQuality s = star_quality(t, x, goal, scratch);
            if (!s.located || s.encroaches) continue;
            if (s.poor == 0) return x;
            // Else, no worse than the off-centre's star in its smallest angle:
            // fewer poor triangles, or as few and farther from its vertices.
            if (move == Move::to_good_star || s.smallest_sine < at_off.smallest_sine) continue;
            const bool fewer = s.poor < best_poor;
            const bool farther =
                move == Move::to_farther && s.poor == best_poor && s.nearest > best_nearest;
            if (fewer || farther) {
                best = x;
                best_poor = s.poor;
                best_nearest = s.nearest;
            }
        }
    }
    return best;
}

}  // namespace

Point StarPlacement::place(const PoorTriangle& t, PlacementScratch& scratch) const {
    static const OffCentrePlacement off_centre;
    const Point off = off_centre.place(t, scratch);
    // Triangles poor only by their size, and runs without an angle bound:
    // the off-centre (the circumcentre for them), as below 34 degrees.
    const double l = t.shortest_length;
    if (!(t.circle.radius_squared > t.rho_bar * t.rho_bar * l * l)) return off;

    // The bound as a sine (sin θ = 1 / (2 rho_bar)), and the goal a little
    // above it, so that rounding does not leave a new triangle just poor.
    const double bound = 0.5 / t.rho_bar;
    const double goal = bound * goal_margin;
    const StarQuality at_off = star_quality(t, off, goal, scratch);
    const bool off_usable = at_off.located && !at_off.encroaches;
    if (off_usable && at_off.poor == 0) return off;

    // The shortest edge pq (counter-clockwise: t lies to its left), its
    // midpoint m, unit direction u and inward normal n; the off-centre's
    // height over pq, and the height below which the angles at p and q of
    // (p, q, x) fall under θ.
    const Point& p = t.corner[mesh::next3(t.shortest_edge)];
    const Point& q = t.corner[mesh::prev3(t.shortest_edge)];
    const Point m{0.5 * (p.x + q.x), 0.5 * (p.y + q.y)};
    const double ux = (q.x - p.x) / l, uy = (q.y - p.y) / l;
    const double nx = -uy, ny = ux;
    const double top = (off.x - m.x) * nx + (off.y - m.y) * ny;
    const double tan_bound = bound / std::sqrt(1 - bound * bound);
    const double bottom = 0.5 * l * tan_bound;
    if (!(top > bottom)) return off;

    const Grid grid{m, ux, uy, nx, ny, top, bottom, tan_bound, l};
    return best_on_grid(t, grid, off, at_off, off_usable, goal, move_, scratch);
}

const char* StarPlacement::name() const {
    switch (move_) {
        case Move::to_good_star:
            return "star, to good stars";
        case Move::to_fewer_poor:
            return "star, to fewer poor";
        case Move::to_farther:
            return "star, to fewer poor and farther";
    }
    return "star";
}

std::array<const PlacementStrategy*, 3> star_placements() {
    static const StarPlacement good_stars(StarPlacement::Move::to_good_star);
    static const StarPlacement farther(StarPlacement::Move::to_farther);
    static const StarPlacement fewer_poor(StarPlacement::Move::to_fewer_poor);
    return {&good_stars, &farther, &fewer_poor};
}

}  // namespace gpdr::refine
