// Insertion order: the branch-free Hilbert index equals the textbook
// algorithm, consecutive curve cells are grid neighbours, and the BRIO order
// is a reproducible permutation.

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>
#include <utility>

#include "mesh/test_support.hpp"
#include "triangulate/spatial_sort.hpp"

using gpdr::triangulate::brio_order;
using gpdr::triangulate::hilbert_index;

namespace {

// The textbook conversion (rotate the quadrant at each level).
std::uint32_t textbook(std::uint32_t x, std::uint32_t y) {
    std::uint32_t d = 0;
    for (std::uint32_t s = 1u << 15; s > 0; s >>= 1) {
        const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
        d += s * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) {
                x = 0xFFFF - x;
                y = 0xFFFF - y;
            }
            std::swap(x, y);
        }
    }
    return d;
}

}  // namespace

TEST_CASE("the Hilbert index matches the textbook algorithm", "[triangulate][sort]") {
    std::mt19937 rng(1);
    for (int i = 0; i < 200000; ++i) {
        const std::uint32_t x = rng() & 0xFFFF, y = rng() & 0xFFFF;
        REQUIRE(hilbert_index(x, y) == textbook(x, y));
    }
    CHECK(hilbert_index(0, 0) == 0);
}

TEST_CASE("the Hilbert curve steps between neighbouring cells", "[triangulate][sort]") {
    // The first 4^8 positions fill the 256 x 256 corner cell by cell.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> cell(1u << 16);
    std::vector<char> seen(1u << 16, 0);
    for (std::uint32_t x = 0; x < 256; ++x)
        for (std::uint32_t y = 0; y < 256; ++y) {
            const std::uint32_t d = hilbert_index(x, y);
            REQUIRE(d < (1u << 16));
            REQUIRE_FALSE(seen[d]);
            seen[d] = 1;
            cell[d] = {x, y};
        }
    for (std::size_t d = 1; d < cell.size(); ++d) {
        const auto dx = std::abs(int(cell[d].first) - int(cell[d - 1].first));
        const auto dy = std::abs(int(cell[d].second) - int(cell[d - 1].second));
        REQUIRE(dx + dy == 1);
    }
}

TEST_CASE("the BRIO order is a reproducible permutation", "[triangulate][sort]") {
    const std::size_t n = GENERATE(0, 1, 5, 1000, 100000);
    const auto points = gpdr::mesh::testing::uniform_points(n, 4);
    const auto order = brio_order(points);
    REQUIRE(order.size() == n);
    std::vector<std::uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::uint32_t> identity(n);
    std::iota(identity.begin(), identity.end(), 0u);
    CHECK(sorted == identity);
    CHECK(brio_order(points) == order);
    if (n >= 1000) {
        // Randomised rounds: the order is not simply the curve order.
        CHECK(brio_order(points, 1) != order);
    }
}

TEST_CASE("the BRIO order is the same on any number of threads", "[triangulate][sort]") {
    const auto points = gpdr::mesh::testing::uniform_points(300'000, 5);
    const auto order = brio_order(points);
    for (unsigned threads : {2u, 3u, 8u}) {
        INFO(threads << " threads");
        CHECK(brio_order(points, 0, threads) == order);
    }
}
