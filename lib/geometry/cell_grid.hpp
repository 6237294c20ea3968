#pragma once
// A uniform grid of cells over a box, and lists of items by cell: what the
// segment grid (segment_grid.hpp) and the area field (area_field.hpp) find
// their few candidates in.
//
// CellGrid: about `target_cells` cells, square where the box allows (a box
// flat in one direction gets a row or a column of them), at most `max_side`
// along each axis.  A coordinate's row or column is clamped to the grid, and
// only grows with the coordinate, so the cells from an item's lowest to its
// highest row hold every point of it.
//
// CellLists: the items of each cell, stored compactly (one index array and
// one offset per cell), built in two passes over the items: count, then
// fill.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/point.hpp"

namespace gpdr::geometry {

struct CellGrid {
    Point lo;
    double width = 1, height = 1;  // of a cell
    long columns = 1, rows = 1;

    CellGrid() = default;
    CellGrid(const Point& lo_corner, const Point& hi, std::size_t target_cells, long max_side)
        : lo(lo_corner) {
        const double w = hi.x - lo.x, h = hi.y - lo.y;
        const double n = static_cast<double>(std::max<std::size_t>(1, target_cells));
        if (w > 0 && h > 0) {
            const double side = std::sqrt(w * h / n);
            columns = std::clamp(static_cast<long>(std::ceil(w / side)), 1L, max_side);
            rows = std::clamp(static_cast<long>(std::ceil(h / side)), 1L, max_side);
        } else if (w > 0) {
            columns = std::clamp(static_cast<long>(n), 1L, max_side);
        } else if (h > 0) {
            rows = std::clamp(static_cast<long>(n), 1L, max_side);
        }
        width = w > 0 ? w / static_cast<double>(columns) : 1.0;
        height = h > 0 ? h / static_cast<double>(rows) : 1.0;
    }

    std::size_t cell_count() const {
        return static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows);
    }
    long column(double x) const { return clamped(std::floor((x - lo.x) / width), columns); }
    long row(double y) const { return clamped(std::floor((y - lo.y) / height), rows); }
    std::size_t cell(long row_index, long column_index) const {
        return static_cast<std::size_t>(row_index) * static_cast<std::size_t>(columns) +
               static_cast<std::size_t>(column_index);
    }
    std::size_t cell_of(const Point& p) const { return cell(row(p.y), column(p.x)); }

private:
    static long clamped(double c, long count) {
        return c < 0 ? 0 : c >= static_cast<double>(count) ? count - 1 : static_cast<long>(c);
    }
};

class CellLists {
public:
    // Item i (of `items`) is listed in every cell for which
    // cells_of(i, visit) calls visit(cell).
    template <class CellsOf>
    void build(std::size_t cells, std::size_t items, CellsOf&& cells_of) {
        offsets_.assign(cells + 1, 0);
        for (std::size_t i = 0; i < items; ++i)
            cells_of(i, [&](std::size_t c) { ++offsets_[c + 1]; });
        for (std::size_t c = 0; c < cells; ++c) offsets_[c + 1] += offsets_[c];
        members_.resize(offsets_[cells]);
        std::vector<std::size_t> fill(offsets_.begin(), offsets_.end() - 1);
        for (std::size_t i = 0; i < items; ++i)
            cells_of(i,
                     [&](std::size_t c) { members_[fill[c]++] = static_cast<std::uint32_t>(i); });
    }

    std::size_t cell_count() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
    std::span<const std::uint32_t> cell(std::size_t c) const {
        return {members_.data() + offsets_[c], members_.data() + offsets_[c + 1]};
    }

private:
    std::vector<std::size_t> offsets_;
    std::vector<std::uint32_t> members_;
};

}  // namespace gpdr::geometry
