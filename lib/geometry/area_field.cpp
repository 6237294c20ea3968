// The area field of an .area file (see area_field.hpp).

#include "geometry/area_field.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/predicates.hpp"

namespace gpdr::geometry {

AreaField::AreaField(std::span<const Point> points, std::span<const std::uint32_t> corners,
                     std::uint32_t corners_per_triangle, std::span<const double> bounds) {
    const std::size_t count = corners_per_triangle == 0 ? 0 : corners.size() / corners_per_triangle;
    for (std::size_t t = 0; t < count && t < bounds.size(); ++t) {
        if (!(bounds[t] > 0)) continue;  // no bound: +infinity never wins
        const std::uint32_t* c = &corners[t * corners_per_triangle];
        Point a = points[c[0]], b = points[c[1]], d = points[c[2]];
        const double orientation = orient2d(a, b, d);
        if (orientation == 0) continue;
        if (orientation < 0) std::swap(b, d);
        triangles_.push_back({a, b, d, bounds[t], static_cast<std::uint32_t>(t)});
    }
    if (triangles_.empty()) return;

    lo_ = hi_ = triangles_.front().a;
    for (const Bounded& t : triangles_)
        for (const Point& p : {t.a, t.b, t.c}) {
            lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y)};
            hi_ = {std::max(hi_.x, p.x), std::max(hi_.y, p.y)};
        }
    // About one cell per triangle, square where the box allows.
    grid_ = CellGrid(lo_, hi_, triangles_.size(), 1L << 16);
    lists_.build(grid_.cell_count(), triangles_.size(),
                 [&](std::size_t i, auto&& visit) { for_each_cell_of(triangles_[i], visit); });
}

// Row by row.  row() only grows with y, so the rows from the triangle's
// lowest to its highest corner hold every point of it.  Within a row, the
// triangle's x-extent over the row's band, taken half a cell taller on each
// side and widened by a cell each way, holds every point of the triangle
// whose row this is: the slack absorbs the rounding of the band and of the
// clipped edges, even along an edge that is nearly horizontal.
template <class F>
void AreaField::for_each_cell_of(const Bounded& t, F&& visit) const {
    const Point* corner[3] = {&t.a, &t.b, &t.c};
    const long r0 = grid_.row(std::min({t.a.y, t.b.y, t.c.y}));
    const long r1 = grid_.row(std::max({t.a.y, t.b.y, t.c.y}));
    for (long r = r0; r <= r1; ++r) {
        const double y0 = grid_.lo.y + (static_cast<double>(r) - 0.5) * grid_.height;
        const double y1 = y0 + 2 * grid_.height;
        double x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
        for (int k = 0; k < 3; ++k) {
            const Point& a = *corner[k];
            const Point& b = *corner[(k + 1) % 3];
            double xa = a.x, xb = b.x;  // a horizontal edge: all of it
            if (a.y != b.y) {
                const double t0 = std::clamp((y0 - a.y) / (b.y - a.y), 0.0, 1.0);
                const double t1 = std::clamp((y1 - a.y) / (b.y - a.y), 0.0, 1.0);
                xa = a.x + t0 * (b.x - a.x);
                xb = a.x + t1 * (b.x - a.x);
            }
            x0 = std::min({x0, xa, xb});
            x1 = std::max({x1, xa, xb});
        }
        const long c0 = std::max(0L, grid_.column(x0) - 1);
        const long c1 = std::min(grid_.columns - 1, grid_.column(x1) + 1);
        for (long c = c0; c <= c1; ++c) visit(grid_.cell(r, c));
    }
}

AreaField::Bound AreaField::at(const Point& p) const {
    Bound best;
    if (triangles_.empty() || !(p.x >= lo_.x && p.x <= hi_.x && p.y >= lo_.y && p.y <= hi_.y))
        return best;  // outside every bounded triangle (NaN too)
    for (const std::uint32_t member : lists_.cell(grid_.cell_of(p))) {
        const Bounded& t = triangles_[member];
        // Ties go to the earlier triangle of the .ele, so that a message
        // names the same one every time.
        if (t.bound > best.area || (t.bound == best.area && t.index > best.triangle)) continue;
        if (orient2d(t.a, t.b, p) >= 0 && orient2d(t.b, t.c, p) >= 0 && orient2d(t.c, t.a, p) >= 0)
            best = {t.bound, t.index};
    }
    return best;
}

}  // namespace gpdr::geometry
