// The pieces the deferred counting rests on: the block lists of deferred
// triangles (push, drain, take and sweep against a plain vector), the quadrant path a
// queue entry carries through splits (Leaf::where against the quadtree's own
// child squares), the level a triangle is counted at (Quadtree::level_of
// against long double arithmetic), the quadtree's division-free level test
// against level_of, and its disk-inside-a-square test.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "parallel/deferred_list.hpp"
#include "parallel/quadtree.hpp"
#include "refine/leaf.hpp"

namespace gpdr::parallel {
namespace {

// The look-ahead callbacks of drain: `ahead` sees each entry exactly once,
// before the entry itself is read; `near` sees an entry at most once, after
// `ahead` and before it is read.
struct AheadLog {
    std::vector<std::uint32_t> shown, near_shown;
    std::vector<bool> read;
    bool early = true;       // every entry was shown before it was read
    bool near_right = true;  // every near entry was shown before, once, and not yet read
    void near(const DeferredTriangle& e) {
        const std::uint32_t i = mesh::index(e.t);
        if (std::find(shown.begin(), shown.end(), i) == shown.end() ||
            std::find(near_shown.begin(), near_shown.end(), i) != near_shown.end() ||
            (i < read.size() && read[i]))
            near_right = false;
        near_shown.push_back(i);
    }
    void show(const DeferredTriangle& e) {
        shown.push_back(mesh::index(e.t));
        if (mesh::index(e.t) < read.size() && read[mesh::index(e.t)]) early = false;
    }
    void reading(const DeferredTriangle& e) {
        if (read.size() <= mesh::index(e.t)) read.resize(mesh::index(e.t) + 1);
        read[mesh::index(e.t)] = true;
        if (std::find(shown.begin(), shown.end(), mesh::index(e.t)) == shown.end()) early = false;
    }
    std::vector<std::uint32_t> sorted_shown() const {
        auto s = shown;
        std::sort(s.begin(), s.end());
        return s;
    }
};

std::vector<std::uint32_t> contents(const DeferredList& list) {
    std::vector<std::uint32_t> out;
    list.for_each([&](const DeferredTriangle& e) { out.push_back(mesh::index(e.t)); });
    std::sort(out.begin(), out.end());
    return out;
}

TEST_CASE("deferred lists keep and drain what a vector would", "[parallel][deferred]") {
    BlockPool pool;
    DeferredList list;
    std::vector<std::uint32_t> expected;
    const std::uint32_t n =
        3 * DeferredBlock::capacity + 17;  // several blocks, the last one partial
    for (std::uint32_t i = 0; i < n; ++i) {
        list.push({mesh::TriangleId{i}, i % 7}, pool);
        expected.push_back(i);
    }
    CHECK(list.size() == n);
    CHECK(contents(list) == expected);

    // Draining into two lists while the blocks are given back one by one.
    DeferredList even, odd;
    std::vector<std::uint32_t> drained;
    AheadLog shown;
    list.drain(
        [&](const DeferredTriangle& e) {
            shown.reading(e);
            drained.push_back(mesh::index(e.t));
            (mesh::index(e.t) % 2 == 0 ? even : odd).push(e, pool);
        },
        [&](const DeferredTriangle& e) { shown.show(e); },
        [&](const DeferredTriangle& e) { shown.near(e); }, pool);
    std::sort(drained.begin(), drained.end());
    CHECK(drained == expected);
    CHECK(shown.sorted_shown() == expected);
    CHECK(shown.early);
    CHECK(shown.near_right);
    // All but the first look_near entries of each block (a few blocks here).
    const std::size_t blocks =
        (expected.size() + DeferredBlock::capacity - 1) / DeferredBlock::capacity + 1;
    CHECK(shown.near_shown.size() + blocks * look_near >= expected.size());
    CHECK(list.size() == 0);
    CHECK(even.size() + odd.size() == expected.size());
    for (std::uint32_t i : contents(even)) CHECK(i % 2 == 0);
    for (std::uint32_t i : contents(odd)) CHECK(i % 2 == 1);

    // The drained list is empty and takes pushes again (from the blocks
    // the drain gave back).
    CHECK(contents(list).empty());
    list.push({mesh::TriangleId{5}, 0}, pool);
    CHECK(contents(list) == std::vector<std::uint32_t>{5});
}

// take() moves every entry without reading it, into an empty list (a new
// leaf's) or one that has entries already, and leaves the source empty and
// usable.
TEST_CASE("a deferred list takes over another's entries", "[parallel][deferred]") {
    BlockPool pool;
    DeferredList from, into;
    std::vector<std::uint32_t> expected;
    const std::uint32_t n = 2 * DeferredBlock::capacity + 5;
    for (std::uint32_t i = 0; i < n; ++i) {
        from.push({mesh::TriangleId{i}, 0}, pool);
        expected.push_back(i);
    }
    into.take(from);  // into an empty list
    CHECK(into.size() == n);
    CHECK(contents(into) == expected);
    CHECK(from.size() == 0);
    CHECK(contents(from).empty());

    for (std::uint32_t i = n; i < n + 7; ++i) {  // a partial block
        from.push({mesh::TriangleId{i}, 0}, pool);
        expected.push_back(i);
    }
    into.take(from);  // onto a list with entries
    into.push({mesh::TriangleId{n + 7}, 0}, pool);
    expected.push_back(n + 7);
    CHECK(into.size() == expected.size());
    CHECK(contents(into) == expected);
    CHECK(contents(from).empty());
    DeferredList empty;
    into.take(empty);  // nothing to take
    CHECK(contents(into) == expected);
    from.push({mesh::TriangleId{1}, 0}, pool);
    CHECK(contents(from) == std::vector<std::uint32_t>{1});
}

// sweep() keeps exactly the entries its test calls alive, in the order a
// drain reads them, shows every entry to `ahead`, and
// gives the blocks it emptied back (the next pushes take them); a list
// whose entries all died is left empty.  worth_sweeping() asks for a list
// that has doubled since its last sweep.
TEST_CASE("a deferred list sweeps out stale entries", "[parallel][deferred]") {
    BlockPool pool;
    DeferredList list;
    const std::uint32_t n = 9 * DeferredBlock::capacity + 40;
    for (std::uint32_t i = 0; i < n; ++i) list.push({mesh::TriangleId{i}, 0}, pool);
    CHECK(list.worth_sweeping());
    const auto drain_order = [&pool](DeferredList& l) {
        std::vector<std::uint32_t> order;
        l.drain([&](const DeferredTriangle& e) { order.push_back(mesh::index(e.t)); },
                [](const DeferredTriangle&) {}, [](const DeferredTriangle&) {}, pool);
        return order;
    };
    struct EveryThird {
        std::vector<std::uint32_t>* shown;
        bool operator()(const DeferredTriangle& e) const { return mesh::index(e.t) % 3 == 0; }
        void ahead(const DeferredTriangle& e) const { shown->push_back(mesh::index(e.t)); }
    };
    // The order a drain would read them in, then the same list swept.
    DeferredList copy;
    for (std::uint32_t i = 0; i < n; ++i) copy.push({mesh::TriangleId{i}, 0}, pool);
    std::vector<std::uint32_t> expected;
    for (const std::uint32_t i : drain_order(copy))
        if (i % 3 == 0) expected.push_back(i);
    std::vector<std::uint32_t> shown;
    list.sweep(EveryThird{&shown}, pool);
    std::sort(shown.begin(), shown.end());
    std::vector<std::uint32_t> all(n);
    for (std::uint32_t i = 0; i < n; ++i) all[i] = i;
    CHECK(shown == all);
    CHECK(list.size() == expected.size());
    CHECK_FALSE(list.worth_sweeping());
    DeferredList swept;
    swept.take(list);
    CHECK(drain_order(swept) == expected);

    // All dead: the list is empty and usable.
    for (std::uint32_t i = 0; i < n; ++i) list.push({mesh::TriangleId{3 * i + 1}, 0}, pool);
    std::vector<std::uint32_t> ignored;
    list.sweep(EveryThird{&ignored}, pool);
    CHECK(list.size() == 0);
    CHECK(contents(list).empty());
    list.push({mesh::TriangleId{6}, 0}, pool);
    CHECK(contents(list) == std::vector<std::uint32_t>{6});
}

// The child a split picks from an entry's quadrant path is the child whose
// square holds the point, level after level, as long as the path lasts.
TEST_CASE("a queue entry's quadrant path follows the quadtree's child squares",
          "[parallel][deferred]") {
    Quadtree tree(-3.25, 10.5, 7.0);
    NodeAllocator alloc;
    std::mt19937_64 random(12345);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Square root = tree.square(Quadtree::root());
    for (int trial = 0; trial < 2000; ++trial) {
        const geometry::Point p{root.x0 + unit(random) * root.side,
                                root.y0 + unit(random) * root.side};
        refine::Leaf leaf(root.side);
        leaf.set_corner({root.x0, root.y0});
        std::uint32_t where = leaf.where(p);
        CHECK((where & 15u) == refine::Leaf::where_levels);
        NodeId node = Quadtree::root();
        for (std::uint32_t level = 0; level < refine::Leaf::where_levels; ++level) {
            const Square s = tree.square(node);
            const double half = 0.5 * s.side;
            const int expected = (p.x >= s.x0 + half ? 1 : 0) | (p.y >= s.y0 + half ? 2 : 0);
            // Points within rounding of a dividing line may go either way
            // (the worker then hands the triangle on): only clear cases count.
            const bool clear = std::abs(p.x - (s.x0 + half)) > 1e-9 * root.side &&
                               std::abs(p.y - (s.y0 + half)) > 1e-9 * root.side;
            if (clear) REQUIRE(refine::Leaf::first_quadrant(where) == expected);
            where = refine::Leaf::in_child(where);
            node = tree.child(node, expected, alloc);
        }
        CHECK(refine::Leaf::path_used_up(where));  // used up: the split measures the entry again
    }
}

// ℓ_k > 4r for the level k that level_of gives, and ℓ_(k+1) > 4r fails
// but for the 2^-30 it gives away; the ends: -1 for r >= ℓ_root / 4 and
// max_level + 1 below the deepest level (and for zero, negative, NaN).
TEST_CASE("level_of is the deepest level whose side exceeds 4r, but for a relative 2^-30",
          "[parallel][deferred]") {
    std::mt19937_64 random(99);
    std::uniform_real_distribution<double> exponent(-2.0, 34.0);
    for (const double side : {3.0, 7.0, 1e-3, 12345.678, 0.1}) {
        Quadtree tree(-1.5, 2.25, side);
        // ℓ_j² / 16r², in long double (the squares of side 2^-j are exact there).
        const auto over = [&](int j, double rr) {
            const long double l = std::ldexp(static_cast<long double>(side), -j);
            return l * l / (16.0L * rr);
        };
        for (int trial = 0; trial < 100000; ++trial) {
            const double r = side * std::exp2(-exponent(random));
            const double rr = r * r;
            const int k = tree.level_of(rr);
            REQUIRE(k >= -1);
            REQUIRE(k <= max_level + 1);
            if (k >= 0 && k <= max_level) REQUIRE(over(k, rr) > 1.0L);
            if (k == -1) REQUIRE(over(0, rr) <= 1.0L + 0x1p-28L);
            if (k <= max_level) REQUIRE(over(k + 1, rr) <= 1.0L + 0x1p-28L);
            if (k == max_level + 1) REQUIRE(over(max_level + 1, rr) > 1.0L - 0x1p-28L);
        }
        // Exactly on a level boundary (ℓ_j = 4r): the level above (S is shrunk).
        for (int j = 0; j <= max_level + 1; ++j) {
            const double rr = std::ldexp(side * side / 16, -2 * j);
            CHECK(tree.level_of(rr) == j - 1);
        }
        CHECK(tree.level_of(0.0) == max_level + 1);
        CHECK(tree.level_of(-1.0) == max_level + 1);
        CHECK(tree.level_of(std::nan("")) == max_level + 1);
        CHECK(tree.level_of(std::numeric_limits<double>::infinity()) == -1);
        CHECK(tree.level_of(std::numeric_limits<double>::denorm_min()) == max_level + 1);
    }
}

TEST_CASE("the division-free two-levels-below test agrees with level_of", "[parallel][deferred]") {
    Quadtree tree(0.0, 0.0, 3.0);
    std::mt19937_64 random(777);
    std::uniform_real_distribution<double> exponent(-70.0, 2.0);
    for (int trial = 0; trial < 20000; ++trial) {
        const double r = std::exp2(exponent(random));
        const double rr = r * r;
        const int k = tree.level_of(rr);
        // (m = max_level + 1: a child of the deepest leaves; nothing qualifies.)
        for (int m = 0; m <= max_level + 1; ++m) {
            const bool below = tree.two_levels_below(rr, m);
            // Conservative: never claims a triangle that is not two levels
            // below and countable ...
            if (below) REQUIRE((k >= m + 2 && k <= max_level));
            // ... and misses only ones within a hair of a level boundary.
            if (!below && k >= m + 2 && k <= max_level) {
                const double q = tree.side_at(0) * tree.side_at(0) / 16 / rr;
                const double at = std::log2(q) / 2;
                CHECK((std::abs(at - (m + 2)) < 1e-9 || std::abs(at - (max_level + 1)) < 1e-9));
            }
        }
    }
}

// disk_inside against long double arithmetic: never says inside for a disk
// that reaches a side (or is not a number), and says it for every disk that
// keeps clear of the sides by more than a hair.  Squares away from the
// origin, as in a real quadtree, so that rounding of the centre's offset
// would show.
TEST_CASE("disk_inside is exact but for a hair, on the safe side", "[parallel][deferred]") {
    Quadtree tree(1.0e6 - 3.5, -2.0e6, 4096.0);
    NodeAllocator alloc;
    std::mt19937_64 random(4242);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    NodeId node = Quadtree::root();
    for (int level = 0; level < 12; ++level) {
        const Square s = tree.square(node);
        const Quadtree::Room room = tree.room(s);
        for (int trial = 0; trial < 2000; ++trial) {
            // Centres over the square and a little beyond; radii up to the square's side.
            const geometry::Point c{s.x0 + (1.2 * unit(random) - 0.1) * s.side,
                                    s.y0 + (1.2 * unit(random) - 0.1) * s.side};
            const double r = unit(random) * unit(random) * s.side;
            const long double lo_x = (long double)c.x - s.x0,
                              hi_x = (long double)s.x0 + s.side - c.x;
            const long double lo_y = (long double)c.y - s.y0,
                              hi_y = (long double)s.y0 + s.side - c.y;
            const long double gap = std::min({lo_x, hi_x, lo_y, hi_y}) - (long double)r;
            const bool inside = tree.disk_inside(room, c, r * r);
            if (inside) REQUIRE(gap > 0);
            if (gap > 1e-9L * s.side) REQUIRE(inside);
        }
        node = tree.child(node, static_cast<int>(unit(random) * 4) & 3, alloc);
    }
    const Quadtree::Room room = tree.room(tree.square(Quadtree::root()));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const geometry::Point middle{room.x, room.y};
    CHECK(tree.disk_inside(room, middle, 1.0));
    CHECK_FALSE(tree.disk_inside(room, {nan, room.y}, 1.0));
    CHECK_FALSE(tree.disk_inside(room, {room.x, nan}, 1.0));
    CHECK_FALSE(tree.disk_inside(room, middle, nan));
    CHECK_FALSE(tree.disk_inside(room, middle, std::numeric_limits<double>::infinity()));
    CHECK_FALSE(tree.disk_inside(room, middle, 2048.0 * 2048.0));  // touches all four sides
}

}  // namespace
}  // namespace gpdr::parallel
