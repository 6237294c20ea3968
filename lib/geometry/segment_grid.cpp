// The segment grid (see segment_grid.hpp).

#include "geometry/segment_grid.hpp"

#include <algorithm>
#include <cmath>

namespace gpdr::geometry {

SegmentGrid::SegmentGrid(const Point& lo, const Point& hi, std::size_t target_cells,
                         std::span<const Point> ends)
    : grid_(lo, hi, target_cells, 1L << 20) {
    lists_.build(grid_.cell_count(), ends.size() / 2, [&](std::size_t s, auto&& visit) {
        for_each_cell_of(ends[2 * s], ends[2 * s + 1], visit);
    });
}

// Row by row: the part of a-b inside the row's band of y (from the clamped
// parameters where it enters and leaves), widened by a cell each way.
template <class F>
void SegmentGrid::for_each_cell_of(const Point& a, const Point& b, F&& visit) const {
    const long r0 = std::max(0L, grid_.row(std::min(a.y, b.y)) - 1);
    const long r1 = std::min(grid_.rows - 1, grid_.row(std::max(a.y, b.y)) + 1);
    for (long r = r0; r <= r1; ++r) {
        double x0 = std::min(a.x, b.x), x1 = std::max(a.x, b.x);
        if (a.y != b.y) {
            const double y0 = grid_.lo.y + static_cast<double>(r) * grid_.height;
            const double y1 = y0 + grid_.height;
            const double t0 = std::clamp((y0 - a.y) / (b.y - a.y), 0.0, 1.0);
            const double t1 = std::clamp((y1 - a.y) / (b.y - a.y), 0.0, 1.0);
            const double xa = a.x + t0 * (b.x - a.x), xb = a.x + t1 * (b.x - a.x);
            x0 = std::min(xa, xb);
            x1 = std::max(xa, xb);
        }
        const long c0 = std::max(0L, grid_.column(x0) - 1);
        const long c1 = std::min(grid_.columns - 1, grid_.column(x1) + 1);
        for (long c = c0; c <= c1; ++c) visit(grid_.cell(r, c));
    }
}

std::span<const std::uint32_t> SegmentGrid::near(const Point& p) const {
    const double fx = (p.x - grid_.lo.x) / grid_.width, fy = (p.y - grid_.lo.y) / grid_.height;
    if (!(fx >= -1 && fy >= -1 && fx <= static_cast<double>(grid_.columns) + 1 &&
          fy <= static_cast<double>(grid_.rows) + 1))
        return {};
    return cell(grid_.cell_of(p));
}

}  // namespace gpdr::geometry
