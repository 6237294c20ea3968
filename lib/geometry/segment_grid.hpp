#pragma once
// A uniform grid of cells over a box, each cell listing the segments that
// pass through it or near it: what finds, among many segments, the few that
// may meet a point or another segment, in time proportional to the cells a
// segment crosses rather than to the number of segments.
//
// A segment is listed in every cell its path crosses and in the cells around
// them (one more ring), so a point within a fraction of a cell of a segment
// finds it in the point's own cell even where rounding puts the point or the
// segment's path one cell off.  Cells are square where the box allows, about
// `target_cells` of them (cell_grid.hpp).

#include <cstdint>
#include <span>
#include <vector>

#include "geometry/cell_grid.hpp"
#include "geometry/point.hpp"

namespace gpdr::geometry {

class SegmentGrid {
public:
    // Segment i runs from ends[2i] to ends[2i + 1]; all ends lie in the box
    // [lo, hi].
    SegmentGrid(const Point& lo, const Point& hi, std::size_t target_cells,
                std::span<const Point> ends);

    // The segments listed in the cell of p (none for a point more than a
    // cell outside the box).
    std::span<const std::uint32_t> near(const Point& p) const;

    std::size_t cell_count() const { return lists_.cell_count(); }
    std::span<const std::uint32_t> cell(std::size_t c) const { return lists_.cell(c); }

private:
    template <class F>
    void for_each_cell_of(const Point& a, const Point& b, F&& visit) const;

    CellGrid grid_;
    CellLists lists_;
};

}  // namespace gpdr::geometry
