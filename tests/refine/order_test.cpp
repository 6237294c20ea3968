// The order of refinement (refine/leaf.hpp): the queue gives the bin of the
// shortest edges first, first-in-first-out within a bin, size-only
// triangles last and newest first; quadtree leaves order by σ level first.

#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "refine/leaf.hpp"

namespace gpdr::refine {

namespace {

QueuedTriangle entry(std::uint32_t i) { return {mesh::TriangleId{i}, i, 0}; }

// Takes the first entry of the lowest level (first_slot over that level
// alone); false when the leaf is empty.
bool pop_lowest(Leaf& leaf, QueuedTriangle& q) {
    PoorSlot at;
    if (!leaf.first_slot(leaf.lowest_level(), at)) return false;
    leaf.pop_poor(at, q);
    return true;
}

// Everything the leaf holds, level by level.
std::vector<std::uint32_t> drain(Leaf& leaf) {
    std::vector<std::uint32_t> out;
    for (QueuedTriangle q{}; pop_lowest(leaf, q);) out.push_back(q.generation);
    return out;
}

// A leaf of side 8 at the origin and its four children, as a split makes
// them (only child 0's corner is needed: the tests read that child).
struct Family {
    Leaf parent{8.0};
    Leaf children[4] = {Leaf(4.0), Leaf(4.0), Leaf(4.0), Leaf(4.0)};
    Leaf* const child_pointers[4] = {&children[0], &children[1], &children[2], &children[3]};
    Family() {
        parent.set_corner({0.0, 0.0});
        children[0].set_corner({0.0, 0.0});
    }
};

// What a run with window levels lowest .. last_level (size bins and size
// edge bins up to last_size_level) takes, in order (Leaf::first_slot across
// the levels, as LeafRefiner::refine_levels).
std::vector<std::uint32_t> drain_window(Leaf& leaf, int last_level,
                                        int last_size_level = Leaf::bucket_count) {
    std::vector<std::uint32_t> out;
    for (PoorSlot at; leaf.first_slot(last_level, at, last_size_level);) {
        QueuedTriangle q{};
        leaf.pop_poor(at, q);
        out.push_back(q.generation);
    }
    return out;
}

}  // namespace

TEST_CASE("edge_bin is the floor of the logarithm to base sqrt 2", "[refine][order]") {
    CHECK(Leaf::edge_bin(1.0) == 0);
    CHECK(Leaf::edge_bin(1.41421) == 0);
    CHECK(Leaf::edge_bin(1.41422) == 1);
    CHECK(Leaf::edge_bin(2.0) == 2);
    CHECK(Leaf::edge_bin(0.5) == -2);
    CHECK(Leaf::edge_bin(0.7) == -2);
    CHECK(Leaf::edge_bin(0.71) == -1);
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> exponent(-300.0, 300.0);
    for (int trial = 0; trial < 10000; ++trial) {
        const double x = std::exp2(exponent(random));
        const int b = Leaf::edge_bin(x);
        // sqrt(2)^b <= x < sqrt(2)^(b+1), away from the boundaries.
        const double l = 2.0 * std::log2(x);
        if (std::abs(l - std::round(l)) > 1e-9) REQUIRE(b == static_cast<int>(std::floor(l)));
        REQUIRE(Leaf::edge_bin(4.0 * x) == b + 4);
    }
    CHECK(Leaf::edge_bin(0.0) <= Leaf::edge_bin(0x1p-1022));
    CHECK(Leaf::edge_bin(INFINITY) >= Leaf::edge_bin(0x1p1023));
}

TEST_CASE("edge_bin reads the bins off the bits as ilogb and scalbn define them",
          "[refine][order]") {
    // The library's definition: 2 e + (m >= √2), x = m 2^e, 1 <= m < 2.
    const auto reference = [](double x) {
        const int e = std::ilogb(x);
        return 2 * e + (std::scalbn(x, -e) >= 1.4142135623730951 ? 1 : 0);
    };
    std::mt19937_64 random(11);
    std::uniform_int_distribution<std::uint64_t> bits(std::bit_cast<std::uint64_t>(0x1p-1022),
                                                      std::bit_cast<std::uint64_t>(0x1p1023));
    for (int trial = 0; trial < 100000; ++trial) {
        const double x = std::bit_cast<double>(bits(random));
        REQUIRE(Leaf::edge_bin(x) == reference(x));
    }
    // Either side of √2 and of 1 at every exponent.
    for (int e = -1022; e <= 1023; ++e) {
        for (const double m : {1.0, 1.4142135623730951}) {
            const double x = std::ldexp(m, e);
            for (const double y : {std::nextafter(x, 0.0), x, std::nextafter(x, INFINITY)}) {
                if (!(y >= 0x1p-1022) || !std::isfinite(y)) continue;
                REQUIRE(Leaf::edge_bin(y) == reference(y));
            }
        }
    }
    // σ the same way: ⌊log2(ℓ²/r²)⌋ / 2, clamped to the last level but one.
    const Leaf leaf(3.0);
    std::uniform_real_distribution<double> exponent(-200.0, 10.0);
    for (int trial = 0; trial < 100000; ++trial) {
        const double r2 = 9.0 * std::exp2(exponent(random));
        const double ratio = 9.0 / r2;
        const int want =
            !(ratio >= 1.0) ? 0 : std::min(std::ilogb(ratio) >> 1, Leaf::bucket_count - 2);
        REQUIRE(leaf.sigma(r2) == want);
    }
    CHECK(leaf.sigma(0.0) == Leaf::bucket_count - 2);
    CHECK(leaf.sigma(NAN) == 0);
}

TEST_CASE("a flat leaf gives the shortest edges' bin first, first in first out within a bin",
          "[refine][order]") {
    Leaf leaf = Leaf::flat();
    // Entry i has shortest edge² lengths[i]; circumradii do not matter.
    const std::vector<double> lengths = {4.0, 1.0, 1.1, 0.25, 4.5, 1.2, 0.26, 1e-6, 1e6, 1.3};
    for (std::uint32_t i = 0; i < lengths.size(); ++i)
        leaf.push_poor(entry(i), leaf.slot(1e9 * (i + 1), lengths[i], PoorKind::angle));
    // Bins: 0.25, 0.26 -> -4; 1.0, 1.1, 1.2, 1.3 -> 0; 4.0, 4.5 -> 4.
    CHECK(drain(leaf) == std::vector<std::uint32_t>{7, 3, 6, 1, 2, 5, 9, 0, 4, 8});
    CHECK(leaf.idle());
}

TEST_CASE("a flat leaf takes the bins in order however the pushes interleave", "[refine][order]") {
    Leaf leaf = Leaf::flat();
    std::mt19937_64 random(21);
    std::uniform_real_distribution<double> exponent(-40.0, 40.0);
    std::vector<double> length;
    std::uint32_t next = 0;
    int last_bin = -100000;
    std::map<int, std::uint32_t> last_taken;  // by bin
    int taken = 0;
    for (int step = 0; step < 20000; ++step) {
        if (random() % 3 != 0 || leaf.poor_entries() == 0) {
            length.push_back(std::exp2(exponent(random)));
            leaf.push_poor(entry(next), leaf.slot(1.0, length[next], PoorKind::angle));
            ++next;
            last_bin = -100000;  // a push may open a lower bin
            continue;
        }
        QueuedTriangle q{};
        REQUIRE(pop_lowest(leaf, q));
        const int bin = Leaf::edge_bin(length[q.generation]);
        // Between pushes the bins only go up; within a bin, always in
        // arrival order.
        REQUIRE(bin >= last_bin);
        last_bin = bin;
        auto [it, fresh] = last_taken.try_emplace(bin, q.generation);
        if (!fresh) REQUIRE(q.generation > it->second);
        it->second = q.generation;
        ++taken;
    }
    CHECK(taken > 3000);
    // What is left comes out in (bin, arrival) order.
    std::vector<std::uint32_t> rest = drain(leaf);
    for (std::size_t i = 1; i < rest.size(); ++i) {
        const int a = Leaf::edge_bin(length[rest[i - 1]]), b = Leaf::edge_bin(length[rest[i]]);
        REQUIRE(a <= b);
        if (a == b) REQUIRE(rest[i - 1] < rest[i]);
    }
}

TEST_CASE("size-only triangles come after every bin, newest first", "[refine][order]") {
    Leaf leaf = Leaf::flat();
    leaf.push_poor(entry(0), leaf.slot(1.0, 1.0, PoorKind::size));
    leaf.push_poor(entry(1), leaf.slot(1.0, 1e3, PoorKind::angle));
    leaf.push_poor(entry(2), leaf.slot(1.0, 1e-3, PoorKind::size));
    leaf.push_poor(entry(3), leaf.slot(1.0, 1e-3, PoorKind::angle));
    CHECK(drain(leaf) == std::vector<std::uint32_t>{3, 1, 2, 0});
}

TEST_CASE("a quadtree leaf orders by σ level, then by shortest edge", "[refine][order]") {
    Leaf leaf(16.0);
    // σ = floor(log2(16 / r)): r = 8 -> 1, r = 2 -> 3.
    leaf.push_poor(entry(0), leaf.slot(4.0, 1.0, PoorKind::angle));    // σ 3, l² 1
    leaf.push_poor(entry(1), leaf.slot(64.0, 16.0, PoorKind::angle));  // σ 1, l² 16
    leaf.push_poor(entry(2), leaf.slot(64.0, 1.0, PoorKind::angle));   // σ 1, l² 1
    leaf.push_poor(entry(3), leaf.slot(4.0, 0.01, PoorKind::angle));   // σ 3, l² 0.01
    leaf.push_poor(entry(4), leaf.slot(64.0, 1.0, PoorKind::size));    // σ 1, size only
    leaf.push_poor(entry(5), leaf.slot(64.0, 1.01, PoorKind::angle));  // σ 1, l² 1 (same bin as 2)
    leaf.push_poor(entry(6), leaf.slot(64.0, 1e-30, PoorKind::angle));  // σ 1, below the last bin
    CHECK(drain(leaf) == std::vector<std::uint32_t>{6, 2, 5, 1, 4, 3, 0});
}

TEST_CASE("a split keeps each bin's order in the children", "[refine][order]") {
    Family f;
    Leaf &parent = f.parent, &c0 = f.children[0];
    // All in child 0's square: σ 2 in the parent (r = 1.5), 1 in the child.
    for (std::uint32_t i = 0; i < 6; ++i) {
        QueuedTriangle q = entry(i);
        q.where = parent.where({1.0 + 0.1 * i, 1.0});
        parent.push_poor(
            q, parent.slot(2.25, i % 2 ? 0.5 : 0.01, i < 4 ? PoorKind::angle : PoorKind::size));
    }
    int used_up = 0;
    parent.move_poor_to_children(f.child_pointers, [&](QueuedTriangle) { ++used_up; });
    CHECK(used_up == 0);
    CHECK(parent.poor_entries() == 0);
    CHECK(c0.lowest_level() == 1);
    // Bins: l² 0.01 (0, 2), l² 0.5 (1, 3), then the size bin as taking
    // from the parent (5, 4) and pushing onto the child leaves it (4, 5).
    CHECK(drain(c0) == std::vector<std::uint32_t>{0, 2, 1, 3, 4, 5});
}

TEST_CASE("after a split, a child takes equal edge bins first in, first out", "[refine][order]") {
    Family f;
    Leaf &parent = f.parent, &c0 = f.children[0];
    // Two entries in child 1's quarter, then entry 2 in child 0's: σ 2 in
    // the parent (r = 1.5), 1 in the child; l² 0.25.
    for (std::uint32_t i = 0; i < 3; ++i) {
        QueuedTriangle q = entry(i);
        q.where = parent.where({i < 2 ? 5.0 : 1.0, 1.0});
        parent.push_poor(q, parent.slot(2.25, 0.25, PoorKind::angle));
    }
    parent.move_poor_to_children(f.child_pointers, [](QueuedTriangle) {});
    // Queued in the child after the split, at σ 2 there (r = 0.75), in the
    // same edge bin: it comes after entry 2, which the child counts on from.
    c0.push_poor(entry(3), c0.slot(0.5625, 0.25, PoorKind::angle));
    CHECK(drain_window(c0, Leaf::bucket_count - 1) == std::vector<std::uint32_t>{2, 3});
}

TEST_CASE("a quadtree leaf's window is taken by shortest edge across its levels",
          "[refine][order]") {
    Leaf leaf(16.0);
    leaf.push_poor(entry(0), leaf.slot(64.0, 16.0, PoorKind::angle));   // σ 1, l² 16
    leaf.push_poor(entry(1), leaf.slot(4.0, 1.0, PoorKind::angle));     // σ 3, l² 1
    leaf.push_poor(entry(2), leaf.slot(64.0, 1.0, PoorKind::angle));    // σ 1, l² 1
    leaf.push_poor(entry(3), leaf.slot(0.01, 0.001, PoorKind::angle));  // σ 7, l² 0.001
    leaf.push_poor(entry(4), leaf.slot(4.0, 2.0, PoorKind::size));      // σ 3, size only
    leaf.push_poor(entry(5), leaf.slot(64.0, 2.0, PoorKind::size));     // σ 1, size only
    const std::vector<std::uint32_t> taken = drain_window(leaf, 4);     // the window: σ 1 .. 4
    // Edge bins first, by edge_bin(l²) whatever the level (1 and 2 share
    // it: first in, first out across the levels), then the size bins
    // lowest level first; σ 7 lies beyond the window.
    CHECK(taken == std::vector<std::uint32_t>{1, 2, 0, 5, 4});
    CHECK(leaf.lowest_level() == 7);
    Leaf flat = Leaf::flat();
    flat.push_poor(entry(0), flat.slot(1.0, 4.0, PoorKind::angle));
    PoorSlot at;
    CHECK_FALSE(flat.first_slot(-1, at));
    CHECK(flat.first_slot(Leaf::bucket_count, at));
}

TEST_CASE("size-only triangles in edge order share the edge bins' order", "[refine][order]") {
    // A flat leaf files them in the edge bins: one first-in-first-out order
    // with the triangles poor by their angle.
    Leaf flat = Leaf::flat();
    flat.push_poor(entry(0), flat.slot(1.0, 1.0, PoorKind::size_edges));
    flat.push_poor(entry(1), flat.slot(1.0, 1.1, PoorKind::angle));
    flat.push_poor(entry(2), flat.slot(1.0, 0.01, PoorKind::size_edges));
    flat.push_poor(entry(3), flat.slot(1.0, 4.0, PoorKind::angle));
    CHECK(drain(flat) == std::vector<std::uint32_t>{2, 0, 1, 3});

    // A quadtree leaf files them in size edge bins of their own, taken in
    // the same order as the edge bins, but only up to last_size_level.
    Leaf leaf(16.0);
    leaf.push_poor(entry(0), leaf.slot(64.0, 1.0, PoorKind::size_edges));  // σ 1, l² 1
    leaf.push_poor(entry(1), leaf.slot(4.0, 1.0, PoorKind::angle));        // σ 3, l² 1
    leaf.push_poor(entry(2), leaf.slot(64.0, 16.0, PoorKind::angle));      // σ 1, l² 16
    leaf.push_poor(entry(3), leaf.slot(4.0, 0.5, PoorKind::size_edges));   // σ 3, l² 0.5
    leaf.push_poor(entry(4), leaf.slot(64.0, 1.2, PoorKind::angle));       // σ 1, l² 1.2
    PoorSlot at;
    REQUIRE(leaf.first_slot(4, at, 2));
    CHECK(at.bin > Leaf::size_bin);
    // l² 1 and 1.2 share a bin (first in, first out across both kinds and
    // levels); entry 3's shorter edge waits beyond the size levels.
    CHECK(drain_window(leaf, 4, 2) == std::vector<std::uint32_t>{0, 1, 4, 2});
    CHECK(leaf.lowest_level() == 3);
    CHECK(drain_window(leaf, 4, 4) == std::vector<std::uint32_t>{3});
    CHECK(leaf.idle());
}

TEST_CASE("a split keeps the order of edge bins and size edge bins together", "[refine][order]") {
    Family f;
    Leaf &parent = f.parent, &c0 = f.children[0];
    // All in child 0's square, σ 2 in the parent (r = 1.5), 1 in the child.
    const double length[4] = {0.5, 0.01, 0.01, 0.5};
    for (std::uint32_t i = 0; i < 4; ++i) {
        QueuedTriangle q = entry(i);
        q.where = parent.where({1.0 + 0.1 * i, 1.0});
        parent.push_poor(
            q, parent.slot(2.25, length[i], i % 2 ? PoorKind::size_edges : PoorKind::angle));
    }
    parent.move_poor_to_children(f.child_pointers, [](QueuedTriangle) {});
    CHECK(parent.poor_entries() == 0);
    CHECK(c0.poor_entries() == 4);
    CHECK(drain(c0) == std::vector<std::uint32_t>{1, 2, 0, 3});
}

}  // namespace gpdr::refine
