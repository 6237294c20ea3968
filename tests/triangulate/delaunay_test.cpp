// Delaunay triangulation of point sets: random, grid (massively cocircular),
// exactly cocircular, clustered and duplicate-laden inputs pass the checker;
// the triangle count obeys Euler's formula with an independently computed
// hull; small random sets match a brute-force oracle exactly; degenerate
// inputs throw GeometryError.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

#include <gpdr/errors.hpp>

#include "check/checker.hpp"
#include "geometry/predicates.hpp"
#include "mesh/test_support.hpp"
#include "mesh/traverse.hpp"
#include "triangulate/delaunay.hpp"

using namespace gpdr;
using namespace gpdr::mesh;
using namespace gpdr::mesh::testing;
using geometry::incircle;
using geometry::orient2d;
using triangulate::delaunay;
using triangulate::DelaunayReport;

namespace {

// Number of distinct points on the boundary of the convex hull (collinear
// ones on hull edges included), by Andrew's monotone chain with exact
// orientation, then a test of every point against every hull edge.
std::size_t hull_vertex_count(std::vector<Point> p) {
    auto less = [](const Point& a, const Point& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    };
    std::sort(p.begin(), p.end(), less);
    p.erase(std::unique(p.begin(), p.end()), p.end());
    std::vector<Point> hull;
    for (int pass = 0; pass < 2; ++pass) {
        const std::size_t base = hull.size();
        for (const Point& q : p) {
            while (hull.size() >= base + 2 && orient2d(hull[hull.size() - 2], hull.back(), q) <= 0)
                hull.pop_back();
            hull.push_back(q);
        }
        hull.pop_back();
        std::reverse(p.begin(), p.end());
    }
    std::size_t on = 0;
    for (const Point& q : p) {
        for (std::size_t i = 0; i < hull.size(); ++i) {
            const Point& a = hull[i];
            const Point& b = hull[(i + 1) % hull.size()];
            if (orient2d(a, b, q) == 0 && std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) &&
                std::min(a.y, b.y) <= q.y && q.y <= std::max(a.y, b.y)) {
                ++on;
                break;
            }
        }
    }
    return on;
}

// Everything a Delaunay triangulation of `points` must satisfy.
void verify(const std::vector<Point>& points, const Mesh& mesh, const DelaunayReport& report) {
    const auto problems = check_mesh(mesh);
    INFO((problems.empty() ? std::string() : problems.front()));
    REQUIRE(problems.empty());

    // Duplicates: equal points, the kept one has the lowest index among its
    // equals, and every point is either used or reported.
    std::map<std::pair<double, double>, std::uint32_t> lowest;
    for (std::uint32_t i = 0; i < points.size(); ++i)
        lowest.try_emplace({points[i].x, points[i].y}, i);
    std::set<std::uint32_t> reported;
    for (auto [lost, kept] : report.duplicates) {
        CHECK(points[lost] == points[kept]);
        CHECK(kept == lowest.at({points[lost].x, points[lost].y}));
        CHECK(mesh.kind(VertexId{lost}) == VertexKind::duplicate);
        reported.insert(lost);
    }
    CHECK(reported.size() == report.duplicates.size());
    const std::size_t distinct = lowest.size();
    CHECK(report.duplicates.size() == points.size() - distinct);

    std::vector<char> used(points.size(), 0);
    for_each_triangle(mesh, [&](TriangleId, const Triangle& t) {
        for (VertexId v : t.v) used[index(v)] = 1;
    });
    for (std::uint32_t i = 0; i < points.size(); ++i)
        CHECK(bool(used[i]) == (reported.count(i) == 0));

    // Euler: 2n - 2 - h triangles, h hull vertices.
    const std::size_t h = hull_vertex_count(points);
    CHECK(mesh.count_triangles() == 2 * distinct - 2 - h);
    CHECK(count_hull_edges(mesh) == h);
    CHECK(count_edges(mesh) == 3 * distinct - 3 - h);

    // The hull is convex: no point strictly outside any hull edge.
    for_each_hull_edge(mesh, [&](const EdgeView& e) {
        for (const Point& q : points)
            REQUIRE(orient2d(mesh.point(e.from), mesh.point(e.to), q) >= 0);
    });
}

std::vector<Point> with_duplicates(std::vector<Point> p, std::size_t copies, std::uint32_t seed) {
    std::mt19937 rng(seed);
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < copies; ++i) p.push_back(p[rng() % n]);
    std::shuffle(p.begin(), p.end(), rng);
    return p;
}

}  // namespace

TEST_CASE("Delaunay of uniform random points", "[triangulate][delaunay]") {
    const std::size_t n = GENERATE(3, 4, 10, 100, 1000, 30000);
    const auto points = uniform_points(n, static_cast<std::uint32_t>(n));
    DelaunayReport report;
    const Mesh mesh = delaunay(points, report);
    CHECK(report.duplicates.empty());
    verify(points, mesh, report);
}

TEST_CASE("Delaunay of a grid (massively cocircular)", "[triangulate][delaunay]") {
    const int k = GENERATE(2, 3, 17, 120);
    std::vector<Point> points;
    for (int y = 0; y < k; ++y)
        for (int x = 0; x < k; ++x) points.push_back({x * 0.1, y * 0.1});
    DelaunayReport report;
    const Mesh mesh = delaunay(points, report);
    verify(points, mesh, report);
    CHECK(mesh.count_triangles() == static_cast<std::size_t>(2 * (k - 1) * (k - 1)));
}

TEST_CASE("Delaunay of points exactly on a circle", "[triangulate][delaunay]") {
    // All integer points on x^2 + y^2 = 1105^2 (1105 = 5 * 13 * 17): 108
    // exactly cocircular points, plus the centre in one variant.
    std::vector<Point> points;
    const long r = 1105;
    for (long x = -r; x <= r; ++x) {
        const long y2 = r * r - x * x;
        const long y = std::lround(std::sqrt(double(y2)));
        if (y * y != y2) continue;
        points.push_back({double(x), double(y)});
        if (y != 0) points.push_back({double(x), double(-y)});
    }
    REQUIRE(points.size() == 108);
    const bool centre = GENERATE(false, true);
    if (centre) points.push_back({0, 0});
    DelaunayReport report;
    const Mesh mesh = delaunay(points, report);
    verify(points, mesh, report);
}

TEST_CASE("Delaunay of points nearly on a circle", "[triangulate][delaunay]") {
    std::vector<Point> points;
    for (int i = 0; i < 1000; ++i) {
        const double a = 2 * M_PI * i / 1000;
        points.push_back({std::cos(a), std::sin(a)});
    }
    DelaunayReport report;
    const Mesh mesh = delaunay(points, report);
    verify(points, mesh, report);
}

TEST_CASE("Delaunay with a cavity of many edges", "[triangulate][delaunay]") {
    // In the fixed insertion order the centre comes after some 230 points of
    // the circle: its cavity is every triangle so far (each circumcircle is
    // nearly the circle), with far more boundary edges than the point
    // inserter scans for (it chains them by binary search then).
    std::vector<Point> points;
    for (int i = 0; i < 400; ++i) {
        const double a = 2 * M_PI * i / 400;
        points.push_back({std::cos(a), std::sin(a)});
    }
    points.push_back({0, 0});
    DelaunayReport report;
    const Mesh mesh = delaunay(points, report);
    verify(points, mesh, report);
}

TEST_CASE("Delaunay of clustered points", "[triangulate][delaunay]") {
    std::mt19937_64 rng(21);
    std::normal_distribution<double> tight(0.0, 1e-9), loose(0.0, 1.0);
    std::vector<Point> points;
    for (int c = 0; c < 20; ++c) {
        const Point centre{loose(rng), loose(rng)};
        for (int i = 0; i < 300; ++i)
            points.push_back({centre.x + tight(rng), centre.y + tight(rng)});
    }
    DelaunayReport report;
    const Mesh mesh = delaunay(points, report);
    verify(points, mesh, report);
}

TEST_CASE("Delaunay of points with collinear runs", "[triangulate][delaunay]") {
    // Points on the sides of a triangle and on two long lines through it.
    std::vector<Point> points;
    for (int i = 0; i <= 50; ++i) {
        const double t = i / 50.0;
        points.push_back({t, 0});
        points.push_back({0, t});
        points.push_back({t, 1 - t});
        points.push_back({t * 0.5, t * 0.25});
    }
    DelaunayReport report;
    const Mesh mesh = delaunay(points, report);
    verify(points, mesh, report);
}

TEST_CASE("Delaunay with many exact duplicates", "[triangulate][delaunay]") {
    SECTION("random points repeated") {
        const auto points = with_duplicates(uniform_points(500, 3), 700, 4);
        DelaunayReport report;
        const Mesh mesh = delaunay(points, report);
        verify(points, mesh, report);
    }
    SECTION("a small integer lattice drawn with repetition") {
        std::mt19937 rng(8);
        std::vector<Point> points;
        for (int i = 0; i < 2000; ++i) points.push_back({double(rng() % 10), double(rng() % 10)});
        DelaunayReport report;
        const Mesh mesh = delaunay(points, report);
        verify(points, mesh, report);
        CHECK(report.duplicates.size() == 2000 - 100);
    }
    SECTION("three points, one repeated") {
        const std::vector<Point> points{{1, 1}, {0, 0}, {1, 1}, {2, 0}, {0, 0}, {1, 1}};
        DelaunayReport report;
        const Mesh mesh = delaunay(points, report);
        verify(points, mesh, report);
        using P = std::pair<std::uint32_t, std::uint32_t>;
        CHECK(report.duplicates == std::vector<P>{{2, 0}, {4, 1}, {5, 0}});
    }
}

TEST_CASE("Delaunay equals the brute-force oracle on small random sets",
          "[triangulate][delaunay]") {
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const std::size_t n = 3 + trial % 13;
        std::vector<Point> points(n);
        for (auto& p : points) p = {u(rng), u(rng)};
        // Oracle: every counter-clockwise triple whose circumcircle holds no
        // other point (general position: no four cocircular, no three
        // collinear; random doubles give that, and it is checked).
        std::vector<Tri> oracle;
        bool general = true;
        for (std::uint32_t a = 0; a < n; ++a)
            for (std::uint32_t b = a + 1; b < n; ++b)
                for (std::uint32_t c = b + 1; c < n; ++c) {
                    const double o = orient2d(points[a], points[b], points[c]);
                    if (o == 0) general = false;
                    Tri t = o > 0 ? Tri{a, b, c} : Tri{a, c, b};
                    bool empty = true;
                    for (std::uint32_t d = 0; d < n && empty; ++d) {
                        if (d == a || d == b || d == c) continue;
                        const double in =
                            incircle(points[t[0]], points[t[1]], points[t[2]], points[d]);
                        if (in == 0) general = false;
                        empty = in < 0;
                    }
                    if (empty) oracle.push_back(t);
                }
        if (!general) continue;
        std::sort(oracle.begin(), oracle.end());
        DelaunayReport report;
        const Mesh mesh = delaunay(points, report);
        INFO("trial " << trial << ", n = " << n);
        REQUIRE(canonical(mesh) == oracle);
    }
}

TEST_CASE("degenerate inputs throw GeometryError", "[triangulate][delaunay]") {
    DelaunayReport report;
    auto fails = [&](const std::vector<Point>& points, const std::string& what) {
        try {
            (void)delaunay(points, report);
            FAIL("no exception for " << what);
        } catch (const GeometryError& e) {
            CHECK_THAT(std::string(e.what()), Catch::Contains(what));
        }
    };
    fails({}, "0 distinct vertices");
    fails({{1, 2}}, "1 distinct vertices");
    fails({{1, 2}, {3, 4}}, "2 distinct vertices");
    fails({{1, 2}, {1, 2}, {1, 2}, {3, 4}, {3, 4}}, "2 distinct vertices");
    fails({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {0.5, 0.5}}, "collinear");
    // Exactly collinear in binary, not just in decimal: y = 3x with small integers.
    std::vector<Point> line;
    for (int i = 0; i < 1000; ++i) line.push_back({double(i % 37), 3.0 * double(i % 37)});
    fails(line, "collinear");
    fails({{0, 0}, {1, 0}, {std::numeric_limits<double>::quiet_NaN(), 1}}, "vertex 2");
    fails({{0, 0}, {1, 0}, {0, std::numeric_limits<double>::infinity()}}, "not a finite number");
}

TEST_CASE("Delaunay output order is reproducible", "[triangulate][delaunay]") {
    const auto points = uniform_points(5000, 17);
    DelaunayReport r1, r2;
    const Mesh a = delaunay(points, r1);
    const Mesh b = delaunay(points, r2);
    std::vector<Tri> la, lb;
    for_each_triangle(a, [&](TriangleId, const Triangle& t) {
        la.push_back({index(t.v[0]), index(t.v[1]), index(t.v[2])});
    });
    for_each_triangle(b, [&](TriangleId, const Triangle& t) {
        lb.push_back({index(t.v[0]), index(t.v[1]), index(t.v[2])});
    });
    CHECK(la == lb);
}
