#pragma once
// Where a counted triangle is counted (Worker's upkeep of relation (9)): one
// quadtree level k, the cell (ix, iy) of that level where the triangle's
// circumdisk's bounding box starts, and which of that cell and its three
// neighbours towards +x and +y the disk meets (bit b of `cells` for the
// cell (ix + (b & 1), iy + (b >> 1))): the disk's diameter is below half a
// cell, so it meets at most those four.
//
// Packed in 64 bits (a record per triangle passes through hot loops):
//   bit 63 set | level (6 bits) << 56 | cells (4 bits) << 52 |
//   ix (26 bits) << 26 | iy (26 bits),
// and 0 for a triangle too small to be counted.  Cell coordinates fit the
// 26 bits they have because no level is deeper than max_level.

#include <cstdint>

namespace gpdr::parallel {

class CellRecord {
public:
    static constexpr unsigned coordinate_bits = 26;

    // Not counted: too small to matter for any leaf.
    CellRecord() = default;
    CellRecord(int level, unsigned cells, std::uint32_t ix, std::uint32_t iy)
        : bits_(std::uint64_t{1} << 63 | std::uint64_t(level) << 56 | std::uint64_t(cells) << 52 |
                std::uint64_t(ix) << coordinate_bits | std::uint64_t(iy)) {}

    bool counted() const { return bits_ != 0; }
    int level() const { return static_cast<int>((bits_ >> 56) & 63u); }
    unsigned cells() const { return static_cast<unsigned>((bits_ >> 52) & 15u); }
    std::uint32_t ix() const {
        return static_cast<std::uint32_t>((bits_ >> coordinate_bits) & coordinate_mask);
    }
    std::uint32_t iy() const { return static_cast<std::uint32_t>(bits_ & coordinate_mask); }

    // Calls visit(ix, iy) for each cell the record names.
    template <class F>
    void for_each_cell(F&& visit) const {
        for (unsigned b = 0; b < 4; ++b)
            if (cells() & (1u << b)) visit(ix() + (b & 1u), iy() + (b >> 1));
    }

private:
    static constexpr std::uint64_t coordinate_mask = (std::uint64_t{1} << coordinate_bits) - 1;
    std::uint64_t bits_ = 0;
};

}  // namespace gpdr::parallel
