// Tests of crossing_point (lib/geometry/predicates_crossing.cpp) against
// exact rational arithmetic: each coordinate must be the double nearest the
// exact crossing (no other double is closer; ties go to the even one), for
// random crossings at several scales and offsets, for nearly parallel
// segments, and regardless of the order of the segments and their ends.

#include <gmpxx.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "geometry/crossing.hpp"
#include "geometry/predicates.hpp"

namespace {

using gpdr::geometry::crossing_point;
using gpdr::geometry::orient2d;
using gpdr::geometry::Point;

struct Exact {
    mpq_class x, y;
};

Exact exact_crossing(const Point& a, const Point& b, const Point& c, const Point& d) {
    const mpq_class ax(a.x), ay(a.y), bx(b.x), by(b.y), cx(c.x), cy(c.y), dx(d.x), dy(d.y);
    const mpq_class oa = (cx - ax) * (dy - ay) - (cy - ay) * (dx - ax);
    const mpq_class ob = (cx - bx) * (dy - by) - (cy - by) * (dx - bx);
    return {(oa * bx - ob * ax) / (oa - ob), (oa * by - ob * ay) / (oa - ob)};
}

// Whether q is the double nearest to v (ties: q's last significand bit 0).
bool nearest(double q, const mpq_class& v) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const mpq_class here = abs(mpq_class(q) - v);
    for (const double other : {std::nextafter(q, inf), std::nextafter(q, -inf)}) {
        const mpq_class there = abs(mpq_class(other) - v);
        if (there < here) return false;
        if (there == here) {
            int e = 0;
            const double m = std::ldexp(std::frexp(q, &e), 53);
            if (std::fmod(m, 2.0) != 0) return false;
        }
    }
    return true;
}

bool crosses(const Point& a, const Point& b, const Point& c, const Point& d) {
    const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
    const double o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
    return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

}  // namespace

TEST_CASE("crossing_point is correctly rounded and symmetric", "[geometry][crossing]") {
    std::mt19937_64 rng(20261125);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int checked = 0;
    for (const double scale : {1e-6, 1.0, 1e3}) {
        for (const double offset : {0.0, 1.0, 1e6}) {
            for (int i = 0; i < 600; ++i) {
                auto random_point = [&] {
                    return Point{offset + scale * unit(rng), offset + scale * unit(rng)};
                };
                const Point a = random_point(), b = random_point(), c = random_point(),
                            d = random_point();
                if (!crosses(a, b, c, d)) continue;
                const Point p = crossing_point(a, b, c, d);
                const Exact e = exact_crossing(a, b, c, d);
                REQUIRE(nearest(p.x, e.x));
                REQUIRE(nearest(p.y, e.y));
                REQUIRE(crossing_point(c, d, a, b) == p);
                REQUIRE(crossing_point(b, a, d, c) == p);
                ++checked;
            }
        }
    }
    REQUIRE(checked > 1000);
}

TEST_CASE("crossing_point of nearly parallel segments", "[geometry][crossing]") {
    // Long, almost parallel segments: the crossing is ill-conditioned, and
    // the naive formula errs by many ulps.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int checked = 0;
    for (int i = 0; i < 2000 && checked < 300; ++i) {
        const Point a{0.1 * unit(rng), 0.1 * unit(rng)};
        const Point b{1000 + unit(rng), 1000 + unit(rng)};
        const double slip = 1e-9 * (unit(rng) - 0.5);
        const Point c{a.x + 1e-7, a.y - 1e-7};
        const Point d{b.x - 1e-7 + slip, b.y + 1e-7 + slip};
        if (!crosses(a, b, c, d)) continue;
        const Point p = crossing_point(a, b, c, d);
        const Exact e = exact_crossing(a, b, c, d);
        REQUIRE(nearest(p.x, e.x));
        REQUIRE(nearest(p.y, e.y));
        ++checked;
    }
    REQUIRE(checked > 50);
}

TEST_CASE("crossing_point of representable crossings is exact", "[geometry][crossing]") {
    REQUIRE(crossing_point({0, 0}, {2, 2}, {0, 2}, {2, 0}) == Point{1, 1});
    REQUIRE(crossing_point({-1, 0}, {5, 0}, {4, 3}, {4, -3}) == Point{4, 0});
    REQUIRE(crossing_point({1e6, 1e6}, {1e6 + 2, 1e6 + 2}, {1e6, 1e6 + 2}, {1e6 + 2, 1e6}) ==
            Point{1e6 + 1, 1e6 + 1});
}
