// The segment grid (see segment_grid.hpp).

#include "geometry/segment_grid.hpp"

#include <algorithm>
#include <cmath>

namespace gpdr::geometry {

SegmentGrid::SegmentGrid(const Point& lo, const Point& hi, std::size_t target_cells,
                         std::span<const Point> ends)
    : lo_(lo) {
    const double w = hi.x - lo.x, h = hi.y - lo.y;
    const double n = static_cast<double>(std::max<std::size_t>(1, target_cells));
    if (w > 0 && h > 0) {
        const double side = std::sqrt(w * h / n);
        columns_ = std::clamp(static_cast<long>(std::ceil(w / side)), 1L, 1L << 20);
        rows_ = std::clamp(static_cast<long>(std::ceil(h / side)), 1L, 1L << 20);
    } else if (w > 0) {
        columns_ = std::clamp(static_cast<long>(n), 1L, 1L << 20);
    } else if (h > 0) {
        rows_ = std::clamp(static_cast<long>(n), 1L, 1L << 20);
    }
    width_ = w > 0 ? w / static_cast<double>(columns_) : 1.0;
    height_ = h > 0 ? h / static_cast<double>(rows_) : 1.0;

    const std::size_t cells = static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_);
    const std::size_t segments = ends.size() / 2;
    offsets_.assign(cells + 1, 0);
    for (std::size_t s = 0; s < segments; ++s)
        for_each_cell_of(ends[2 * s], ends[2 * s + 1], [&](std::size_t c) { ++offsets_[c + 1]; });
    for (std::size_t c = 0; c < cells; ++c) offsets_[c + 1] += offsets_[c];
    members_.resize(offsets_[cells]);
    std::vector<std::size_t> fill(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t s = 0; s < segments; ++s)
        for_each_cell_of(ends[2 * s], ends[2 * s + 1], [&](std::size_t c) {
            members_[fill[c]++] = static_cast<std::uint32_t>(s);
        });
}

long SegmentGrid::column(double x) const {
    const double c = std::floor((x - lo_.x) / width_);
    return c < 0 ? 0 : c >= static_cast<double>(columns_) ? columns_ - 1 : static_cast<long>(c);
}

long SegmentGrid::row(double y) const {
    const double r = std::floor((y - lo_.y) / height_);
    return r < 0 ? 0 : r >= static_cast<double>(rows_) ? rows_ - 1 : static_cast<long>(r);
}

// Row by row: the part of a-b inside the row's band of y (from the clamped
// parameters where it enters and leaves), widened by a cell each way.
template <class F>
void SegmentGrid::for_each_cell_of(const Point& a, const Point& b, F&& visit) const {
    const long r0 = std::max(0L, row(std::min(a.y, b.y)) - 1);
    const long r1 = std::min(rows_ - 1, row(std::max(a.y, b.y)) + 1);
    for (long r = r0; r <= r1; ++r) {
        double x0 = std::min(a.x, b.x), x1 = std::max(a.x, b.x);
        if (a.y != b.y) {
            const double y0 = lo_.y + static_cast<double>(r) * height_;
            const double y1 = y0 + height_;
            const double t0 = std::clamp((y0 - a.y) / (b.y - a.y), 0.0, 1.0);
            const double t1 = std::clamp((y1 - a.y) / (b.y - a.y), 0.0, 1.0);
            const double xa = a.x + t0 * (b.x - a.x), xb = a.x + t1 * (b.x - a.x);
            x0 = std::min(xa, xb);
            x1 = std::max(xa, xb);
        }
        const long c0 = std::max(0L, column(x0) - 1), c1 = std::min(columns_ - 1, column(x1) + 1);
        const std::size_t base = static_cast<std::size_t>(r) * static_cast<std::size_t>(columns_);
        for (long c = c0; c <= c1; ++c) visit(base + static_cast<std::size_t>(c));
    }
}

std::span<const std::uint32_t> SegmentGrid::near(const Point& p) const {
    const double fx = (p.x - lo_.x) / width_, fy = (p.y - lo_.y) / height_;
    if (!(fx >= -1 && fy >= -1 && fx <= static_cast<double>(columns_) + 1 &&
          fy <= static_cast<double>(rows_) + 1))
        return {};
    return cell(static_cast<std::size_t>(row(p.y)) * static_cast<std::size_t>(columns_) +
                static_cast<std::size_t>(column(p.x)));
}

}  // namespace gpdr::geometry
