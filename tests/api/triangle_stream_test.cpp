// The triangles of a mesh that stays a mesh (MeshArrays::stream): read()
// gives any run of them, from several threads at once, exactly as next()
// gives them in order, across the stream's strides and the dead slots that
// insertion leaves; and the materialised arrays' source agrees.

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <thread>
#include <vector>

#include "api/job_stages.hpp"
#include "triangulate/delaunay.hpp"

using namespace gpdr;

namespace {

struct Read {
    std::vector<std::uint32_t> corners;
    std::vector<double> attributes;
};

Read in_order(io::EleSource source) {
    Read r;
    r.corners.resize(3 * source.count);
    r.attributes.resize(source.attribute_count * source.count);
    for (std::size_t t = 0; t < source.count; ++t)
        source.next(&r.corners[3 * t], r.attributes.data() + t * source.attribute_count);
    return r;
}

}  // namespace

TEST_CASE("a streamed mesh's triangles are read in runs as in order", "[stream]") {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> coordinate(0, 1);
    std::vector<geometry::Point> points(12000);
    for (auto& p : points) p = {coordinate(rng), coordinate(rng)};
    triangulate::DelaunayReport report;
    const mesh::Mesh mesh = triangulate::delaunay(points, report);
    REQUIRE(mesh.count_triangles() < mesh.triangle_end());  // dead slots to skip

    NodeSet nodes;
    for (const auto& p : points) {
        nodes.xy.push_back(p.x);
        nodes.xy.push_back(p.y);
    }
    // One attribute per triangle: its region's (all region 0 here).
    const std::vector<double> regions{2.5};
    const api::MeshArrays streamed =
        api::mesh_to_arrays(mesh, nodes, points.size(), 1, regions, false, false);
    const api::MeshArrays copied =
        api::mesh_to_arrays(mesh, nodes, points.size(), 1, regions, false, true);
    REQUIRE(streamed.stream);
    const io::EleSource source = api::triangle_source(streamed);
    REQUIRE(source.read);
    const std::size_t n = source.count;
    REQUIRE(n > 3 * 4096);
    const Read expected = in_order(source);
    CHECK(expected.corners == in_order(api::triangle_source(copied)).corners);

    // Runs starting anywhere, of any length, the last one to the end.
    const std::vector<std::pair<std::size_t, std::size_t>> runs{
        {0, 1}, {0, n}, {1, 4096}, {4095, 2}, {4096, 4096}, {5000, 9000}, {n - 1, 1}, {n, 0}};
    for (const auto& [first, length] : runs) {
        INFO(first << " + " << length);
        Read r;
        r.corners.resize(3 * length);
        r.attributes.resize(length);
        source.read(first, length, r.corners.data(), r.attributes.data());
        CHECK(std::equal(r.corners.begin(), r.corners.end(), expected.corners.begin() + 3 * first));
        CHECK(std::all_of(r.attributes.begin(), r.attributes.end(),
                          [](double a) { return a == 2.5; }));
    }

    // Four threads reading interleaved runs at once.
    std::vector<std::uint32_t> together(3 * n);
    {
        std::vector<std::jthread> threads;
        for (std::size_t k = 0; k < 4; ++k)
            threads.emplace_back([&, k] {
                std::vector<double> attributes(1000);
                for (std::size_t first = 1000 * k; first < n; first += 4000) {
                    const std::size_t length = std::min<std::size_t>(1000, n - first);
                    source.read(first, length, &together[3 * first], attributes.data());
                }
            });
    }
    CHECK(together == expected.corners);
}
