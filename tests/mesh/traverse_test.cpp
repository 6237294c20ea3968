// Iteration helpers: every edge once with the right hull and subsegment
// flags, hull edges, and the output numbering of triangles.

#include <catch2/catch.hpp>

#include <set>

#include "mesh/pool.hpp"
#include "mesh/test_support.hpp"
#include "mesh/traverse.hpp"

using namespace gpdr::mesh;
using namespace gpdr::mesh::testing;

TEST_CASE("edges are visited once each, hull edges flagged", "[mesh][traverse]") {
    // A square split at its centre: 8 edges, 4 on the hull.
    Mesh mesh = mesh_from_triangles({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}},
                                    {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
    const TriangleId t = find_triangle(mesh, 1, 2, 4);
    mesh.triangle(t).set_subsegment(edge_of(mesh, t, 2, 4).edge(), true);
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    int hull = 0, subsegments = 0;
    for_each_edge(mesh, [&](const EdgeView& e) {
        const auto a = std::min(index(e.from), index(e.to)),
                   b = std::max(index(e.from), index(e.to));
        CHECK(seen.insert({a, b}).second);
        CHECK(e.hull == (b != 4));
        CHECK(mesh.origin(e.edge) == e.from);
        CHECK(mesh.destination(e.edge) == e.to);
        hull += e.hull;
        subsegments += e.subsegment;
    });
    CHECK(seen.size() == 8);
    CHECK(hull == 4);
    CHECK(subsegments == 1);
    CHECK(count_edges(mesh) == 8);
    CHECK(count_hull_edges(mesh) == 4);
    for_each_hull_edge(mesh, [&](const EdgeView& e) { CHECK(mesh.neighbour(e.edge).is_none()); });
}

TEST_CASE("triangle numbering skips dead slots", "[mesh][traverse]") {
    Mesh mesh = mesh_from_triangles({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}},
                                    {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
    const TriangleId dead = find_triangle(mesh, 1, 2, 4);
    {
        Pool pool(mesh);
        pool.destroy(dead);
    }
    const auto number = number_triangles(mesh);
    CHECK(number[index(dead)] == not_numbered);
    std::vector<std::uint32_t> seen;
    for_each_triangle(mesh,
                      [&](TriangleId id, const Triangle&) { seen.push_back(number[index(id)]); });
    CHECK(seen == std::vector<std::uint32_t>{0, 1, 2});
}

TEST_CASE("a range of ids visits its live triangles, across chunks nobody claimed",
          "[mesh][traverse]") {
    // Lane pools leave whole chunks unclaimed between theirs (pool.hpp);
    // count_left shares the ids out between threads by ranges that start
    // and end anywhere.  Every range must see exactly the live triangles a
    // look at each id in it finds (a missing chunk reads as dead slots).
    Mesh mesh = mesh_from_triangles({{0, 0}, {1, 0}, {1, 1}}, {{0, 1, 2}});
    Lane lane = Lane::first(mesh, 3);
    lane.index = 2;
    {
        Pool pool(mesh, lane);
        const std::uint32_t per_chunk = Mesh::TriangleTable::chunk_size;
        for (std::uint32_t i = 0; i < 2 * per_chunk + 10; ++i) {
            const TriangleId t = pool.create(VertexId{0}, VertexId{1}, VertexId{2});
            if (i % 3 == 0) pool.destroy(t);
        }
    }
    const std::uint32_t end = mesh.triangle_end();
    const std::uint32_t chunk = Mesh::TriangleTable::chunk_size;
    REQUIRE(end > 6 * chunk);  // lane 2 of 3: chunks 2 and 5 past the first, holes between
    for (const auto& [first, last] :
         std::vector<std::pair<std::uint32_t, std::uint32_t>>{{0, end},
                                                              {1, chunk - 1},
                                                              {chunk / 2, 4 * chunk + 7},
                                                              {3 * chunk + 5, end},
                                                              {5 * chunk, 5 * chunk}}) {
        INFO("ids " << first << " to " << last);
        std::vector<std::uint32_t> seen, expected;
        for_each_triangle_in(mesh, first, last,
                             [&](TriangleId id, const Triangle&) { seen.push_back(index(id)); });
        for (std::uint32_t i = first; i < last; ++i)
            if (mesh.triangle(TriangleId{i}).live()) expected.push_back(i);
        CHECK(seen == expected);
    }
}
