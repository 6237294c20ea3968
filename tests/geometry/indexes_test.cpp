// The geometric indexes the input check (-C) relies on: the convex hull,
// the segment grid and point location against boundary edges, each against
// a brute-force answer on random inputs.

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>

#include "geometry/convex_hull.hpp"
#include "geometry/edge_strips.hpp"
#include "geometry/predicates.hpp"
#include "geometry/segment_grid.hpp"

using gpdr::geometry::Point;
namespace g = gpdr::geometry;

TEST_CASE("the convex hull keeps every point on its inner side", "[geometry][hull]") {
    std::mt19937_64 rng(7);
    // Points on a coarse grid: many collinear on the hull, many repeats.
    std::uniform_int_distribution<int> coordinate(0, 6);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<Point> points(3 + trial % 40);
        for (auto& p : points) p = {coordinate(rng) * 0.1, coordinate(rng) * 0.3};
        const auto hull = g::convex_hull(points);
        if (hull.size() < 3) continue;
        for (std::size_t k = 0; k < hull.size(); ++k) {
            const Point& a = points[hull[k]];
            const Point& b = points[hull[(k + 1) % hull.size()]];
            const Point& c = points[hull[(k + 2) % hull.size()]];
            CHECK(g::orient2d(a, b, c) > 0);  // a strict corner
            for (const Point& p : points) CHECK(g::orient2d(a, b, p) >= 0);
        }
    }
    const std::vector<Point> line{{0, 0}, {2, 2}, {1, 1}, {2, 2}};
    CHECK(g::convex_hull(line) == std::vector<std::uint32_t>{0, 1});
}

TEST_CASE("the segment grid lists every segment in the cells of its points",
          "[geometry][segment_grid]") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-50, 50);
    std::vector<Point> ends(2 * 300);
    for (std::size_t i = 0; i < ends.size(); i += 2) {
        ends[i] = {u(rng), u(rng)};
        // Mostly short segments, some long ones.
        const double reach = i % 20 == 0 ? 100 : 3;
        ends[i + 1] = {std::clamp(ends[i].x + u(rng) * reach / 50, -50.0, 50.0),
                       std::clamp(ends[i].y + u(rng) * reach / 50, -50.0, 50.0)};
    }
    const g::SegmentGrid grid({-50, -50}, {50, 50}, 600, ends);
    for (std::uint32_t s = 0; s < ends.size() / 2; ++s)
        for (double t = 0; t <= 1.0; t += 1.0 / 64) {
            const Point& a = ends[2 * s];
            const Point& b = ends[2 * s + 1];
            const Point p{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
            const auto near = grid.near(p);
            CHECK(std::find(near.begin(), near.end(), s) != near.end());
        }
    CHECK(grid.near({1000, 1000}).empty());
}

TEST_CASE("edge strips locate points inside, outside and on a boundary",
          "[geometry][edge_strips]") {
    // A square of side 4 with a square hole of side 2 (clockwise): the
    // region is the ring.
    const std::vector<Point> outer{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    const std::vector<Point> inner{{1, 1}, {1, 3}, {3, 3}, {3, 1}};
    std::vector<Point> ends;
    for (const auto* loop : {&outer, &inner})
        for (std::size_t k = 0; k < 4; ++k) {
            ends.push_back((*loop)[k]);
            ends.push_back((*loop)[(k + 1) % 4]);
        }
    const g::EdgeStrips strips(ends);
    using W = g::EdgeStrips::Where;
    CHECK(strips.locate({0.5, 0.5}) == W::inside);
    CHECK(strips.locate({0.5, 1}) == W::inside);  // level with a hole corner
    CHECK(strips.locate({2, 2}) == W::outside);   // in the hole
    CHECK(strips.locate({5, 2}) == W::outside);
    CHECK(strips.locate({2, 4}) == W::on_edge);
    CHECK(strips.locate({1, 2}) == W::on_edge);
    CHECK(strips.locate({3, 3}) == W::on_edge);
    CHECK(strips.crossed({2, 2}, {2, 5}));       // leaves the hole and the square
    CHECK(!strips.crossed({1.5, 1.5}, {2, 2}));  // inside the hole
    CHECK(!strips.crossed({0, 0}, {4, 0}));      // along an edge
}
