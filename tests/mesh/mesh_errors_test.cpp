// What the mesh layer throws, and that it changes nothing when it does: a
// CapacityError past the limits of its 32-bit ids (the program exits 1 with
// no --force hint), and a SubsegmentSplitError for a subsegment whose
// triangles are too flat to take a vertex (the refiner leaves it).

#include <catch2/catch.hpp>

#include <gpdr/errors.hpp>

#include "mesh/mesh.hpp"
#include "mesh/pool.hpp"
#include "mesh/split_subsegment.hpp"
#include "mesh/test_support.hpp"

using namespace gpdr::mesh;
using namespace gpdr::mesh::testing;

TEST_CASE("the mesh refuses more vertices or triangles than its ids number", "[mesh][errors]") {
    Mesh mesh;
    // The checks come before any chunk is touched: nothing is allocated.
    CHECK_THROWS_AS(mesh.claim_vertices(0xFFFFFFFFu), gpdr::CapacityError);
    CHECK(mesh.vertex_end() == 0);
    CHECK_THROWS_AS(mesh.claim_vertex_chunk_at(index(ghost_vertex) >> Mesh::vertex_chunk_bits),
                    gpdr::CapacityError);
    CHECK_THROWS_AS(mesh.claim_triangle_chunk_at(max_triangles >> Mesh::triangle_chunk_bits),
                    gpdr::CapacityError);
    CHECK(mesh.triangle_end() == 0);
}

TEST_CASE("a subsegment whose triangle is flat takes no vertex", "[mesh][errors]") {
    // x = 0, y = 1 and the apex w = 2 on one line: no point of x-y lies
    // strictly inside the triangle, not even its middle.
    Mesh mesh = mesh_from_triangles({{0, 0}, {2, 0}, {3, 0}}, {{0, 1, 2}});
    const TriangleId t = find_triangle(mesh, 0, 1, 2);
    mesh.triangle(t).set_subsegment(2, true);
    const EdgeRef s(t, 2);  // x -> y
    REQUIRE(mesh.origin(s) == VertexId{0});
    REQUIRE(mesh.destination(s) == VertexId{1});
    Pool pool(mesh);
    InsertBuffer buffer;
    const std::uint32_t vertices = mesh.vertex_end();
    CHECK_THROWS_AS(split_subsegment(pool, s, {1, 0}, VertexKind::segment, buffer),
                    gpdr::SubsegmentSplitError);
    CHECK(mesh.vertex_end() == vertices);
    CHECK(mesh.triangle(t).live());
    CHECK(mesh.triangle(t).is_subsegment(2));
}
