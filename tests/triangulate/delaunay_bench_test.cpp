// Hidden benchmark (run with `test_triangulate "[.bench]"` on a Release
// build): Delaunay of 1 and 10 million uniform random points.  Prints time,
// throughput and the store's bytes per triangle and per vertex.

#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>

#include "mesh/test_support.hpp"
#include "triangulate/delaunay.hpp"
#include "triangulate/spatial_sort.hpp"

using namespace gpdr;
using namespace gpdr::mesh;

namespace {

void run(std::size_t n) {
    const auto points = testing::uniform_points(n, 1);
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    const auto order = triangulate::brio_order(points);
    const auto t1 = clock::now();
    triangulate::DelaunayReport report;
    const Mesh mesh = triangulate::delaunay(points, report);
    const auto t2 = clock::now();
    const double sort_s = std::chrono::duration<double>(t1 - t0).count();
    const double total_s = std::chrono::duration<double>(t2 - t1).count();
    const std::size_t triangles = mesh.count_triangles();
    std::printf(
        "n = %zu: %.3f s (%.3f us/point; the BRIO sort alone takes %.3f s), %zu triangles, "
        "%.2f M triangles/s\n"
        "  store: %.1f bytes per triangle (%zu bytes of slots for %zu triangles), "
        "%.1f bytes per vertex (%zu bytes)\n",
        n, total_s, 1e6 * total_s / double(n), sort_s, triangles, double(triangles) / total_s / 1e6,
        double(mesh.triangle_store_bytes()) / double(triangles), mesh.triangle_store_bytes(),
        triangles, double(mesh.vertex_store_bytes()) / double(n), mesh.vertex_store_bytes());
    CHECK(triangles > 2 * n - 100);
}

}  // namespace

TEST_CASE("benchmark: Delaunay of 1 million uniform random points", "[.bench][triangulate][1m]") {
    run(1'000'000);
}

TEST_CASE("benchmark: Delaunay of 10 million uniform random points", "[.bench][triangulate][10m]") {
    run(10'000'000);
}
