// The triangles of a mesh that stays a mesh (MeshArrays::stream): read()
// gives any run of them, from several threads at once, exactly as next()
// gives them in order, across the stream's strides and the dead slots that
// insertion leaves; and the materialised arrays' source agrees.

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <thread>
#include <vector>

#include <gpdr/io.hpp>

#include "api/api_test_support.hpp"
#include "api/job_stages.hpp"
#include "cli/cli_support.hpp"
#include "mesh/traverse.hpp"
#include "parallel/refine_parallel.hpp"
#include "triangulate/constrained.hpp"
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

// n uniform random points in the unit square.
std::vector<geometry::Point> random_points(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> coordinate(0, 1);
    std::vector<geometry::Point> points(n);
    for (auto& p : points) p = {coordinate(rng), coordinate(rng)};
    return points;
}

}  // namespace

TEST_CASE("a streamed mesh's triangles are read in runs as in order", "[stream]") {
    const std::vector<geometry::Point> points = random_points(12000, 3);
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
        api::mesh_to_arrays(mesh, nodes, points.size(), 1, regions, api::ArrayChoices{});
    const api::MeshArrays copied =
        api::mesh_to_arrays(mesh, nodes, points.size(), 1, regions, {false, true, true, 1});
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

TEST_CASE("the arrays number the mesh as one pass in id order would", "[stream]") {
    // The pipe refined on two threads: the lanes leave unused vertex ids,
    // chunks nobody claimed and chunks nearly empty, over many chunks.
    const auto read =
        io::read_poly((test::source_dir() / "poly-samples" / "pipe.poly").string(), ignore_warning);
    const triangulate::Pslg pslg = triangulate::pslg_from(read.data);
    std::vector<mesh::VertexId> ends;
    for (const std::uint32_t v : pslg.segments) ends.push_back(mesh::VertexId{v});
    triangulate::CdtReport cdt;
    mesh::Mesh mesh = triangulate::constrained_delaunay(pslg, {}, cdt);
    refine::RefineSettings settings;
    settings.criteria.min_angle_degrees = 25;
    settings.criteria.max_area = 1.5;
    settings.segment_ends = ends;
    parallel::ParallelReport report;
    parallel::refine_parallel(mesh, settings, 2, 0, report);
    REQUIRE(mesh.triangle_chunks_claimed() >= 6);

    // The reference: vertices and triangles in id order, one pass each.
    const std::size_t input = pslg.points.size();
    std::vector<std::uint32_t> ids;
    std::vector<std::uint32_t> number_of(mesh.vertex_end(), NeighbourSet::none);
    for (std::uint32_t v = 0; v < mesh.vertex_end(); ++v) {
        if (v >= input && (!mesh.has_vertex_chunk(v >> mesh::Mesh::vertex_chunk_bits) ||
                           mesh.kind(mesh::VertexId{v}) == mesh::VertexKind::unused))
            continue;
        number_of[v] = static_cast<std::uint32_t>(ids.size());
        ids.push_back(v);
    }
    REQUIRE(ids.size() < mesh.vertex_end());  // ids to skip
    std::vector<std::uint32_t> triangle_of(mesh.triangle_end(), NeighbourSet::none);
    std::vector<std::uint32_t> corners;
    std::uint32_t triangles = 0;
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId id, const mesh::Triangle& t) {
        triangle_of[index(id)] = triangles++;
        for (const mesh::VertexId v : t.v) corners.push_back(number_of[index(v)]);
    });
    std::vector<std::uint32_t> neighbours, segments;
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId, const mesh::Triangle& t) {
        for (const mesh::EdgeRef n : t.n)
            neighbours.push_back(n.is_none() ? NeighbourSet::none
                                             : triangle_of[index(n.triangle())]);
    });
    std::size_t hull = 0;
    mesh::for_each_edge(mesh, [&](const mesh::EdgeView& e) {
        hull += e.hull ? 1 : 0;
        if (!e.subsegment) return;
        segments.push_back(number_of[index(e.from)]);
        segments.push_back(number_of[index(e.to)]);
    });

    NodeSet nodes;
    nodes.xy.assign(2 * input, 0.0);
    const std::vector<double> regions{0.0};
    for (const unsigned threads : {1u, 3u}) {
        for (const bool materialise : {false, true}) {
            INFO(threads << " threads, materialise " << materialise);
            const api::MeshArrays arrays = api::mesh_to_arrays(
                mesh, nodes, input, 0, regions, {materialise, materialise, true, threads});
            CHECK(arrays.mesh_ids == ids);
            bool points_match = arrays.nodes.xy.size() == 2 * ids.size();
            for (std::size_t i = 0; points_match && i < ids.size(); ++i)
                points_match = arrays.nodes.xy[2 * i] == mesh.point(mesh::VertexId{ids[i]}).x &&
                               arrays.nodes.xy[2 * i + 1] == mesh.point(mesh::VertexId{ids[i]}).y;
            CHECK(points_match);
            CHECK(arrays.segments.endpoints == segments);
            CHECK(arrays.hull_edge_count == hull);
            if (materialise) CHECK(arrays.neighbours.neighbours == neighbours);
            const io::EleSource source = api::triangle_source(arrays);
            REQUIRE(source.count == triangles);
            CHECK(in_order(source).corners == corners);
            if (!source.read) continue;
            // Runs from anywhere, across the chunks' joins.
            for (std::size_t first = 0; first < triangles; first += 7919) {
                const std::size_t length = std::min<std::size_t>(20000, triangles - first);
                std::vector<std::uint32_t> run(3 * length);
                std::vector<double> attributes(length);
                source.read(first, length, run.data(), attributes.data());
                CHECK(std::equal(run.begin(), run.end(), corners.begin() + 3 * first));
            }
        }
    }
}

// ArrayChoices::free_points_of: the mesh's points are given back as they are
// copied, and the arrays are the ones a copy that keeps them makes (over
// several granules of the point table, 131,072 points each).
TEST_CASE("arrays that free the mesh's points as they copy them are the same", "[stream]") {
    const std::vector<geometry::Point> points = random_points(300000, 5);
    triangulate::DelaunayReport report;
    const mesh::Mesh kept = triangulate::delaunay(points, report);
    mesh::Mesh freed = triangulate::delaunay(points, report);
    NodeSet nodes;
    nodes.markers.assign(points.size(), 0);
    for (const auto& p : points) {
        nodes.xy.push_back(p.x);
        nodes.xy.push_back(p.y);
    }
    const std::vector<double> regions;
    api::ArrayChoices choices;
    choices.threads = 2;
    const api::MeshArrays expected =
        api::mesh_to_arrays(kept, nodes, points.size(), 0, regions, choices);
    const std::size_t held = freed.vertex_store_bytes();
    choices.free_points_of = &freed;
    const api::MeshArrays arrays =
        api::mesh_to_arrays(freed, nodes, points.size(), 0, regions, choices);
    CHECK(arrays.nodes.xy == expected.nodes.xy);
    CHECK(arrays.nodes.markers == expected.nodes.markers);
    CHECK(in_order(api::triangle_source(arrays)).corners ==
          in_order(api::triangle_source(expected)).corners);
    // Every granule of points went back (the kinds stay).
    CHECK(freed.vertex_store_bytes() + points.size() * sizeof(geometry::Point) <= held + 4096);
}
