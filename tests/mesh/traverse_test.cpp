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
