#pragma once
// Morton (Z-curve) codes of quadtree cells: the scheduler breaks ties in a
// round's order by them, and the round record orders leaves by them to
// share them out among simulated ranks.

#include <cstdint>

namespace gpdr::parallel {

// The bits of x spread to the even positions of the result.
constexpr std::uint64_t spread_bits(std::uint32_t x) {
    std::uint64_t v = x;
    v = (v | (v << 16)) & 0x0000FFFF0000FFFFull;
    v = (v | (v << 8)) & 0x00FF00FF00FF00FFull;
    v = (v | (v << 4)) & 0x0F0F0F0F0F0F0F0Full;
    v = (v | (v << 2)) & 0x3333333333333333ull;
    v = (v | (v << 1)) & 0x5555555555555555ull;
    return v;
}

// The Morton code of cell (ix, iy) of one level: x's bits at the even
// positions, y's at the odd.
constexpr std::uint64_t morton(std::uint32_t ix, std::uint32_t iy) {
    return spread_bits(ix) | (spread_bits(iy) << 1);
}

static_assert(morton(0b11, 0b01) == 0b0111);

}  // namespace gpdr::parallel
