// Tests of the exact predicates (lib/geometry/predicates.cpp) against exact
// rational arithmetic (GMP mpq_class, constructed exactly from the doubles):
// random, nearly degenerate (perturbed by ulps) and exactly degenerate
// inputs, at several scales and offsets.  The sign must match in every case.
// A hidden "[.bench]" case reports nanoseconds per call.

#include <gmpxx.h>

#include <array>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "geometry/predicates.hpp"

namespace {

using gpdr::geometry::incircle;
using gpdr::geometry::incircle_exact;
using gpdr::geometry::orient2d;
using gpdr::geometry::orient2d_exact;
using gpdr::geometry::Point;

int sign(double v) { return (v > 0) - (v < 0); }

mpq_class orient_rational(const Point& a, const Point& b, const Point& c) {
    const mpq_class ax(a.x), ay(a.y), bx(b.x), by(b.y), cx(c.x), cy(c.y);
    return (ax - cx) * (by - cy) - (ay - cy) * (bx - cx);
}

mpq_class incircle_rational(const Point& a, const Point& b, const Point& c, const Point& d) {
    const mpq_class dx(d.x), dy(d.y);
    const mpq_class adx = mpq_class(a.x) - dx, ady = mpq_class(a.y) - dy;
    const mpq_class bdx = mpq_class(b.x) - dx, bdy = mpq_class(b.y) - dy;
    const mpq_class cdx = mpq_class(c.x) - dx, cdy = mpq_class(c.y) - dy;
    return (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
           (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
           (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
}

// Counts checked cases so every test can require that it checked many.
struct Checker {
    int cases = 0;
    int zeros = 0;

    void orient(const Point& a, const Point& b, const Point& c) {
        const mpq_class exact = orient_rational(a, b, c);
        const int expected = sgn(exact);
        INFO("orient2d(" << a.x << "," << a.y << " " << b.x << "," << b.y << " " << c.x << ","
                         << c.y << ")");
        REQUIRE(sign(orient2d(a, b, c)) == expected);
        // Cyclic rotations keep the sign, a transposition flips it.
        REQUIRE(sign(orient2d(b, c, a)) == expected);
        REQUIRE(sign(orient2d(b, a, c)) == -expected);
        ++cases;
        zeros += expected == 0;
    }

    void incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
        const mpq_class exact = incircle_rational(a, b, c, d);
        const int expected = sgn(exact);
        INFO("incircle(" << a.x << "," << a.y << " " << b.x << "," << b.y << " " << c.x << ","
                         << c.y << " " << d.x << "," << d.y << ")");
        REQUIRE(sign(gpdr::geometry::incircle(a, b, c, d)) == expected);
        REQUIRE(sign(gpdr::geometry::incircle(c, a, b, d)) == expected);
        REQUIRE(sign(gpdr::geometry::incircle(a, c, b, d)) == -expected);
        ++cases;
        zeros += expected == 0;
    }

    // The always-exact versions: right sign and, when nonzero, the value to
    // about 1e-12 relative (their magnitude is a faithful estimate).
    void exact_versions(const Point& a, const Point& b, const Point& c, const Point& d) {
        const mpq_class o = orient_rational(a, b, c);
        const double ov = orient2d_exact(a, b, c);
        REQUIRE(sign(ov) == sgn(o));
        if (sgn(o) != 0) REQUIRE(std::abs(ov - o.get_d()) <= 1e-12 * std::abs(o.get_d()));
        const mpq_class i = incircle_rational(a, b, c, d);
        const double iv = incircle_exact(a, b, c, d);
        REQUIRE(sign(iv) == sgn(i));
        if (sgn(i) != 0) REQUIRE(std::abs(iv - i.get_d()) <= 1e-12 * std::abs(i.get_d()));
    }
};

// x moved by k ulps (k may be negative).
double ulps(double x, int k) {
    for (; k > 0; --k) x = std::nextafter(x, INFINITY);
    for (; k < 0; ++k) x = std::nextafter(x, -INFINITY);
    return x;
}

struct Frame {
    double offset;
    double scale;
};
constexpr std::array<Frame, 5> kFrames{{{0, 1}, {0, 1e-10}, {0, 1e10}, {1e7, 1}, {1e7, 1e-10}}};

Point in_frame(const Frame& f, double x, double y) {
    return {f.offset + f.scale * x, f.offset + f.scale * y};
}

}  // namespace

TEST_CASE("predicates agree with rational arithmetic on random points", "[geometry][predicates]") {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    Checker check;
    for (const Frame& f : kFrames) {
        for (int i = 0; i < 400; ++i) {
            const Point a = in_frame(f, coord(rng), coord(rng));
            const Point b = in_frame(f, coord(rng), coord(rng));
            const Point c = in_frame(f, coord(rng), coord(rng));
            const Point d = in_frame(f, coord(rng), coord(rng));
            check.orient(a, b, c);
            check.incircle(a, b, c, d);
            if (i % 20 == 0) check.exact_versions(a, b, c, d);
        }
    }
    REQUIRE(check.cases == 4000);
}

TEST_CASE("orient2d is exact on nearly collinear points", "[geometry][predicates]") {
    Checker check;
    // The classic failure of the naive determinant: a 32 x 32 grid of points
    // one ulp apart near (0.5, 0.5) against the line through (12, 12) and
    // (24, 24).
    const double step = std::ldexp(1.0, -53);
    for (int i = 0; i < 32; ++i)
        for (int j = 0; j < 32; ++j)
            check.orient({0.5 + i * step, 0.5 + j * step}, {12, 12}, {24, 24});

    // Points on a line, rounded, then moved by a few ulps.
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    std::uniform_real_distribution<double> param(-2.0, 3.0);
    std::uniform_int_distribution<int> nudge(-3, 3);
    for (const Frame& f : kFrames) {
        for (int i = 0; i < 300; ++i) {
            const Point a = in_frame(f, coord(rng), coord(rng));
            const Point b = in_frame(f, coord(rng), coord(rng));
            const double t = param(rng);
            Point c{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
            c = {ulps(c.x, nudge(rng)), ulps(c.y, nudge(rng))};
            check.orient(a, b, c);
            if (i % 30 == 0) check.exact_versions(a, b, c, c);
        }
    }
    REQUIRE(check.cases > 2000);
    REQUIRE(check.zeros > 0);
}

TEST_CASE("incircle is exact on nearly cocircular points", "[geometry][predicates]") {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    std::uniform_real_distribution<double> angle(0.0, 2 * M_PI);
    std::uniform_real_distribution<double> radius(0.01, 1.0);
    std::uniform_int_distribution<int> nudge(-3, 3);
    Checker check;
    for (const Frame& f : kFrames) {
        for (int i = 0; i < 300; ++i) {
            const double cx = coord(rng), cy = coord(rng), r = radius(rng);
            auto on_circle = [&] {
                const double t = angle(rng);
                return in_frame(f, cx + r * std::cos(t), cy + r * std::sin(t));
            };
            const Point a = on_circle(), b = on_circle(), c = on_circle();
            Point d = on_circle();
            d = {ulps(d.x, nudge(rng)), ulps(d.y, nudge(rng))};
            check.incircle(a, b, c, d);
            if (i % 30 == 0) check.exact_versions(a, b, c, d);
        }
    }
    // Points one ulp apart around (1, 1), which lies exactly on the circle
    // through (0, 0), (1, 0) and (0, 1).
    for (int i = -8; i < 8; ++i)
        for (int j = -8; j < 8; ++j)
            check.incircle({0, 0}, {1, 0}, {0, 1}, {ulps(1.0, i), ulps(1.0, j)});
    REQUIRE(check.zeros > 0);
    REQUIRE(check.cases > 1500);
}

TEST_CASE("predicates return zero on exactly degenerate inputs", "[geometry][predicates]") {
    Checker check;

    SECTION("integer grids, offset by 1e7 and scaled by 1e-10 and 1e10") {
        std::vector<Point> grid;
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 5; ++j) grid.push_back({double(i), double(j)});
        std::mt19937_64 rng(4);
        std::uniform_int_distribution<std::size_t> pick(0, grid.size() - 1);
        for (const Frame& f : kFrames) {
            std::vector<Point> g;
            for (const Point& p : grid) g.push_back(in_frame(f, p.x, p.y));
            for (int i = 0; i < 600; ++i) {
                const Point a = g[pick(rng)], b = g[pick(rng)], c = g[pick(rng)], d = g[pick(rng)];
                check.orient(a, b, c);
                check.incircle(a, b, c, d);
            }
        }
        REQUIRE(check.zeros > 500);
    }

    SECTION("collinear points with inexact differences") {
        // Points (t, k t) with k in {1, -1, 2, 1/4}: exactly collinear whatever
        // t is, and t drawn across magnitudes so the differences round.
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> mant(-1.0, 1.0);
        std::uniform_int_distribution<int> expo(-30, 30);
        auto t = [&] { return std::ldexp(mant(rng), expo(rng)) + (rng() % 2 ? 1e7 : 0.0); };
        for (double k : {1.0, -1.0, 2.0, 0.25}) {
            for (int i = 0; i < 250; ++i) {
                const double ta = t(), tb = t(), tc = t();
                const Point a{ta, k * ta}, b{tb, k * tb}, c{tc, k * tc};
                REQUIRE(orient2d(a, b, c) == 0.0);
                check.orient(a, b, c);
            }
        }
        REQUIRE(check.zeros == check.cases);
    }

    SECTION("cocircular points on integer circles, shifted and scaled") {
        // The integer points of x^2 + y^2 = 65^2.
        std::vector<Point> circle;
        for (int x = -65; x <= 65; ++x)
            for (int y = -65; y <= 65; ++y)
                if (x * x + y * y == 65 * 65) circle.push_back({double(x), double(y)});
        REQUIRE(circle.size() == 36);
        std::mt19937_64 rng(6);
        std::uniform_int_distribution<std::size_t> pick(0, circle.size() - 1);
        // Powers of two and integer offsets keep them exactly cocircular;
        // 1e-10 and 1e10 scales round them (then only the reference decides).
        const std::array<Frame, 6> frames{
            {{0, 1}, {1e7, 1}, {0, 0x1p-33}, {0, 0x1p33}, {0, 1e-10}, {1e7, 1e10}}};
        for (const Frame& f : frames) {
            for (int i = 0; i < 300; ++i) {
                const Point a = circle[pick(rng)], b = circle[pick(rng)], c = circle[pick(rng)],
                            d = circle[pick(rng)];
                const Point fa = in_frame(f, a.x, a.y), fb = in_frame(f, b.x, b.y),
                            fc = in_frame(f, c.x, c.y), fd = in_frame(f, d.x, d.y);
                if (f.scale == 1 || f.scale == 0x1p-33 || f.scale == 0x1p33)
                    REQUIRE(gpdr::geometry::incircle(fa, fb, fc, fd) == 0.0);
                check.incircle(fa, fb, fc, fd);
                check.orient(fa, fb, fc);
            }
        }
    }

    SECTION("rectangles with inexact differences are cocircular") {
        // The corners of any axis-parallel rectangle are cocircular; with
        // coordinates across magnitudes, no difference is exact, so only the
        // last (fully exact) stage can decide.
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> mant(-1.0, 1.0);
        std::uniform_int_distribution<int> expo(-20, 20);
        auto v = [&] { return std::ldexp(mant(rng), expo(rng)) + (rng() % 2 ? 1e7 : -3.0); };
        for (int i = 0; i < 300; ++i) {
            const double x1 = v(), x2 = v(), y1 = v(), y2 = v();
            const Point a{x1, y1}, b{x2, y1}, c{x2, y2}, d{x1, y2};
            REQUIRE(gpdr::geometry::incircle(a, b, c, d) == 0.0);
            REQUIRE(gpdr::geometry::incircle(d, b, a, c) == 0.0);
            check.incircle(a, b, c, d);
            // ... and moved by one ulp they are not.
            check.incircle(a, b, c, {ulps(d.x, 1), d.y});
            check.incircle(a, b, c, {d.x, ulps(d.y, -1)});
            if (i % 10 == 0) check.exact_versions(a, b, c, d);
        }
        REQUIRE(check.zeros >= 300);
    }
}

TEST_CASE("predicates on coincident and repeated points", "[geometry][predicates]") {
    const Point p{0.1, 0.3}, q{1e7 + 0.5, -2.25}, r{-7.0, 1e-9};
    REQUIRE(orient2d(p, p, q) == 0.0);
    REQUIRE(orient2d(p, q, p) == 0.0);
    REQUIRE(orient2d(p, p, p) == 0.0);
    REQUIRE(incircle(p, q, r, p) == 0.0);
    REQUIRE(incircle(p, q, r, r) == 0.0);
    REQUIRE(incircle(p, p, q, r) == 0.0);
    REQUIRE(orient2d({0, 0}, {1, 0}, {0, 1}) > 0);
    REQUIRE(incircle({0, 0}, {1, 0}, {0, 1}, {0.5, 0.5}) > 0);
    REQUIRE(incircle({0, 0}, {1, 0}, {0, 1}, {2, 2}) < 0);
}

TEST_CASE("predicate speed", "[.bench][geometry]") {
    constexpr int n = 1 << 16;
    constexpr int calls = 20'000'000;
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> coord(0.0, 1.0);
    std::vector<Point> pts(n + 4);
    for (Point& p : pts) p = {coord(rng), coord(rng)};

    auto time = [&](const char* name, auto&& f, int count) {
        const auto start = std::chrono::steady_clock::now();
        long total = 0;
        for (int i = 0; i < count; ++i) total += sign(f(i & (n - 1)));
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("%-20s %8.2f ns/call (checksum %ld)\n", name, s * 1e9 / count, total);
    };
    const Point* p = pts.data();
    time(
        "orient2d naive",
        [p](int i) {
            const Point &a = p[i], &b = p[i + 1], &c = p[i + 2];
            return (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x);
        },
        calls);
    time(
        "orient2d", [p](int i) { return orient2d(p[i], p[i + 1], p[i + 2]); }, calls);
    time(
        "incircle naive",
        [p](int i) {
            const Point &a = p[i], &b = p[i + 1], &c = p[i + 2], &d = p[i + 3];
            const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y,
                         cdx = c.x - d.x, cdy = c.y - d.y;
            return (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                   (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                   (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
        },
        calls);
    time(
        "incircle", [p](int i) { return incircle(p[i], p[i + 1], p[i + 2], p[i + 3]); }, calls);
    time(
        "orient2d_exact", [p](int i) { return orient2d_exact(p[i], p[i + 1], p[i + 2]); },
        calls / 10);
    time(
        "incircle_exact", [p](int i) { return incircle_exact(p[i], p[i + 1], p[i + 2], p[i + 3]); },
        calls / 100);
    SUCCEED();
}
