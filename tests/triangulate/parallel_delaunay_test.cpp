// Delaunay triangulation in bands on several threads (strip_inserter.hpp):
// the same mesh, slot for slot, for every thread count from two up; the
// same triangles as one thread; on a grid (no unique triangulation) and
// with duplicates, the same result as one thread.

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "check/checker.hpp"
#include "mesh/test_support.hpp"
#include "triangulate/delaunay.hpp"

using namespace gpdr;
using namespace gpdr::mesh;
using namespace gpdr::mesh::testing;
using triangulate::delaunay;
using triangulate::DelaunayOptions;
using triangulate::DelaunayReport;

namespace {

// Every slot: live or not, and its corners and neighbours in order.
std::vector<std::uint32_t> slots(const Mesh& mesh) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t i = 0; i < mesh.triangle_end(); ++i) {
        const Triangle& t = mesh.triangle(TriangleId{i});
        out.push_back(t.live() ? 1 : 0);
        if (!t.live()) continue;
        for (const VertexId v : t.v) out.push_back(index(v));
        for (const EdgeRef e : t.n) out.push_back(e.bits());
    }
    return out;
}

// The triangles as corner triples, each rotated to start at its lowest
// corner, sorted: what does not depend on numbering.
std::vector<std::array<std::uint32_t, 3>> triangle_set(const Mesh& mesh) {
    std::vector<std::array<std::uint32_t, 3>> out;
    for (std::uint32_t i = 0; i < mesh.triangle_end(); ++i) {
        const Triangle& t = mesh.triangle(TriangleId{i});
        if (!t.live()) continue;
        std::array<std::uint32_t, 3> v{index(t.v[0]), index(t.v[1]), index(t.v[2])};
        std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
        out.push_back(v);
    }
    std::sort(out.begin(), out.end());
    return out;
}

Mesh triangulate_on(const std::vector<Point>& points, unsigned threads, DelaunayReport& report) {
    DelaunayOptions options;
    options.threads = threads;
    options.parallel_from = 1000;  // the bands even for a test's few points
    return delaunay(points, report, options);
}

std::vector<Point> random_points(std::size_t n, std::uint32_t seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Point> points(n);
    for (Point& p : points) p = {u(random), u(random)};
    return points;
}

// The thread counts agree with each other slot for slot, and with one
// thread in triangles and duplicates; every mesh passes the checker.
void require_same_for_all_threads(const std::vector<Point>& points) {
    DelaunayReport one_report;
    const Mesh one = triangulate_on(points, 1, one_report);
    DelaunayReport two_report;
    const Mesh two = triangulate_on(points, 2, two_report);
    const auto problems = check_mesh(two);
    INFO((problems.empty() ? std::string() : problems.front()));
    REQUIRE(problems.empty());
    REQUIRE(triangle_set(two) == triangle_set(one));
    REQUIRE(two_report.duplicates == one_report.duplicates);
    const std::vector<std::uint32_t> two_slots = slots(two);
    for (const unsigned threads : {3u, 8u}) {
        DelaunayReport report;
        const Mesh mesh = triangulate_on(points, threads, report);
        REQUIRE(slots(mesh) == two_slots);
        REQUIRE(report.duplicates == two_report.duplicates);
    }
}

}  // namespace

TEST_CASE("Delaunay in bands: random points", "[triangulate][delaunay][parallel]") {
    require_same_for_all_threads(random_points(60'000, 7));
}

TEST_CASE("Delaunay in bands: clustered points", "[triangulate][delaunay][parallel]") {
    // Most points in a small disc: the bands' cuts crowd there.
    std::vector<Point> points = random_points(40'000, 11);
    for (std::size_t i = 0; i < points.size(); i += 4)
        points[i] = {0.5 + points[i].x * 1e-3, 0.5 + points[i].y * 1e-3};
    require_same_for_all_threads(points);
}

TEST_CASE("Delaunay in bands: a grid falls back to one thread",
          "[triangulate][delaunay][parallel]") {
    // Every square's four corners are cocircular: no unique triangulation,
    // so the bands' result is discarded and the mesh is one thread's.
    std::vector<Point> points;
    for (int i = 0; i < 120; ++i)
        for (int j = 0; j < 120; ++j) points.push_back({double(i), double(j)});
    DelaunayReport one_report, two_report;
    const Mesh one = triangulate_on(points, 1, one_report);
    const Mesh two = triangulate_on(points, 2, two_report);
    REQUIRE(slots(two) == slots(one));
}

TEST_CASE("Delaunay in bands: duplicates keep the lowest index",
          "[triangulate][delaunay][parallel]") {
    std::vector<Point> points = random_points(30'000, 13);
    // Copies of earlier and later points, some copied twice.
    const std::size_t n = points.size();
    for (std::size_t i = 0; i < n; i += 97) points.push_back(points[i]);
    for (std::size_t i = 50; i < n; i += 301) points[i - 40] = points[i];
    for (std::size_t i = 0; i < n; i += 997) points.push_back(points[i]);
    require_same_for_all_threads(points);
}

TEST_CASE("Delaunay in bands: a few empty cocircular squares fall back to one thread",
          "[triangulate][delaunay][parallel]") {
    // Tiny axis-aligned squares with exact corners among random points: each
    // square's circle is empty, so its diagonal may go either way and only
    // one thread's choice is kept.  The insertions must see it wherever the
    // square's edges are made (a band, the points put off, the first points).
    std::vector<Point> points = random_points(50'000, 17);
    constexpr double side = 0x1p-24;
    std::mt19937_64 random(19);
    for (int k = 0; k < 6; ++k) {
        const double x = std::ldexp(double(random() >> 44), -20);  // a multiple of 2^-20
        const double y = std::ldexp(double(random() >> 44), -20);
        for (const Point corner : {Point{x, y}, Point{x + side, y}, Point{x, y + side},
                                   Point{x + side, y + side}})
            points[random() % points.size()] = corner;
    }
    DelaunayReport one_report, two_report;
    const Mesh one = triangulate_on(points, 1, one_report);
    const Mesh two = triangulate_on(points, 2, two_report);
    REQUIRE(check_mesh(two).empty());
    REQUIRE(slots(two) == slots(one));
}
