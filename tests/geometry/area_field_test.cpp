// Tests of lib/geometry/area_field: the bounds of an .area file as a
// function of position, against a brute-force scan with exact rational
// orientation tests (GMP).

#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "geometry/area_field.hpp"

namespace {

using namespace gpdr::geometry;

constexpr double none = std::numeric_limits<double>::infinity();

// The sign of the orientation of a, b, c in exact rational arithmetic.
int exact_orientation(const Point& a, const Point& b, const Point& c) {
    const mpq_class ax(a.x), ay(a.y), bx(b.x), by(b.y), cx(c.x), cy(c.y);
    const mpq_class d = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    return sgn(d);
}

// The field's rule, by brute force: the smallest bound among the bounded
// triangles that contain p (closed), ties to the lowest index.
AreaField::Bound brute_force(const std::vector<Point>& points,
                             const std::vector<std::uint32_t>& corners,
                             const std::vector<double>& bounds, const Point& p) {
    AreaField::Bound best;
    for (std::size_t t = 0; t < bounds.size(); ++t) {
        if (!(bounds[t] > 0)) continue;
        const Point &a = points[corners[3 * t]], &b = points[corners[3 * t + 1]],
                    &c = points[corners[3 * t + 2]];
        const int o = exact_orientation(a, b, c);
        if (o == 0) continue;
        const int s1 = exact_orientation(a, b, p), s2 = exact_orientation(b, c, p),
                  s3 = exact_orientation(c, a, p);
        const bool inside =
            o > 0 ? (s1 >= 0 && s2 >= 0 && s3 >= 0) : (s1 <= 0 && s2 <= 0 && s3 <= 0);
        if (inside && bounds[t] < best.area) best = {bounds[t], static_cast<std::uint32_t>(t)};
    }
    return best;
}

// The square (0,0)-(4,4) cut into four triangles around (2,2), the first
// three counter-clockwise, the last clockwise (a file may list either).
struct Square {
    std::vector<Point> points{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}};
    std::vector<std::uint32_t> corners{0, 1, 4, 1, 2, 4, 2, 3, 4, 0, 4, 3};
};

}  // namespace

TEST_CASE("the field is the bound of the input triangle holding the point", "[geometry][area]") {
    const Square sq;
    const std::vector<double> bounds{0.5, 0.05, -1, 0.01};
    const AreaField field(sq.points, sq.corners, 3, bounds);
    CHECK(field.bounded_triangles() == 3);
    CHECK(field.at({2, 0.5}).area == 0.5);  // inside triangle 0 (bottom)
    CHECK(field.at({2, 0.5}).triangle == 0);
    CHECK(field.at({3.5, 2}).area == 0.05);  // triangle 1 (right)
    CHECK(field.at({2, 3.5}).area == none);  // triangle 2 (top) has no bound
    CHECK(field.at({2, 3.5}).triangle == AreaField::no_triangle);
    CHECK(field.at({0.5, 2}).area == 0.01);  // triangle 3 (left), listed clockwise
    CHECK(field.at({-1, 2}).area == none);   // outside every triangle
    CHECK(field.at({5, 5}).area == none);
    CHECK(field.at({std::nan(""), 1}).area == none);
}

TEST_CASE("on an edge or a corner the smallest bound wins", "[geometry][area]") {
    const Square sq;
    const AreaField field(sq.points, sq.corners, 3, std::vector<double>{0.5, 0.05, -1, 0.01});
    CHECK(field.at({3, 1}).area == 0.05);  // between 0 (0.5) and 1 (0.05)
    CHECK(field.at({1, 1}).area == 0.01);  // between 0 and 3 (0.01)
    CHECK(field.at({3, 3}).area == 0.05);  // between 1 and 2 (none): 2 counts as infinite
    CHECK(field.at({1, 3}).area == 0.01);  // between 2 and 3
    CHECK(field.at({2, 2}).area == 0.01);  // the centre: all four
    CHECK(field.at({2, 2}).triangle == 3);
    CHECK(field.at({0, 0}).area == 0.01);  // a corner of the square
    CHECK(field.at({2, 0}).area == 0.5);   // on the boundary, one triangle
    // The smallest representable step off an edge leaves it.
    CHECK(field.at({3, std::nextafter(1.0, 0.0)}).area == 0.5);
    CHECK(field.at({3, std::nextafter(1.0, 2.0)}).area == 0.05);
}

TEST_CASE("equal bounds name the earlier triangle", "[geometry][area]") {
    const Square sq;
    const AreaField field(sq.points, sq.corners, 3, std::vector<double>{0.1, 0.1, 0.1, 0.1});
    CHECK(field.at({2, 2}).triangle == 0);
    CHECK(field.at({3, 3}).triangle == 1);
}

TEST_CASE("degenerate triangles and six-node triangles", "[geometry][area]") {
    const std::vector<Point> points{{0, 0}, {1, 0}, {2, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
    // A six-node triangle (its extra corners are ignored) and a flat one.
    const std::vector<std::uint32_t> corners{0, 1, 3, 4, 5, 6, 0, 1, 2, 0, 0, 0};
    const AreaField field(points, corners, 6, std::vector<double>{0.2, 0.001});
    CHECK(field.bounded_triangles() == 1);
    CHECK(field.at({0.5, 0}).area == 0.2);
    CHECK(field.at({1.5, 0}).area == none);
}

TEST_CASE("the field agrees with exact brute force on random meshes", "[geometry][area]") {
    std::mt19937_64 rng(38);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int round = 0; round < 20; ++round) {
        // A jittered grid cut into triangles, far from the origin in some
        // rounds so that the coordinates carry rounding.
        const int n = 6 + round % 7;
        const double offset = round % 2 ? 1e6 : 0.0, step = round % 3 ? 1.0 : 1e-3;
        std::vector<Point> points;
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const bool inner = i > 0 && j > 0 && i < n && j < n;
                const double jx = inner ? 0.3 * (unit(rng) - 0.5) : 0.0;
                const double jy = inner ? 0.3 * (unit(rng) - 0.5) : 0.0;
                points.push_back({offset + step * (i + jx), offset + step * (j + jy)});
            }
        std::vector<std::uint32_t> corners;
        std::vector<double> bounds;
        const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                corners.insert(corners.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                corners.insert(corners.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
                for (int k = 0; k < 2; ++k)
                    bounds.push_back(unit(rng) < 0.2 ? -1.0 : std::ldexp(1.0, -int(rng() % 8)));
            }
        const AreaField field(points, corners, 3, bounds);
        // Random points, the corners and points on edges.
        std::vector<Point> probes;
        for (int k = 0; k < 400; ++k)
            probes.push_back({offset + step * (n * 1.1 * unit(rng) - 0.05 * n),
                              offset + step * (n * 1.1 * unit(rng) - 0.05 * n)});
        for (const Point& p : points) probes.push_back(p);
        for (std::size_t t = 0; t < corners.size(); t += 3) {
            const Point& a = points[corners[t]];
            const Point& b = points[corners[t + 1]];
            probes.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2});
            probes.push_back(centroid(a, b, points[corners[t + 2]]));
        }
        for (const Point& p : probes) {
            const AreaField::Bound want = brute_force(points, corners, bounds, p);
            const AreaField::Bound got = field.at(p);
            INFO("round " << round << " at " << p.x << " " << p.y);
            CHECK(got.area == want.area);
            CHECK(got.triangle == want.triangle);
        }
    }
}
