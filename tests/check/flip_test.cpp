// Edge flips: the drawing's contract (corners, neighbours, flags,
// generations), refusal of unflippable edges, repair of a non-Delaunay edge,
// and Lawson's flips saving the tagged triangles they change.

#include <catch2/catch.hpp>

#include "check/checker.hpp"
#include "mesh/flip.hpp"
#include "mesh/split_subsegment.hpp"
#include "mesh/test_support.hpp"

using namespace gpdr::mesh;
using namespace gpdr::mesh::testing;

namespace {
const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
}

TEST_CASE("flipping the diagonal of a square", "[mesh][flip]") {
    Mesh mesh = mesh_from_triangles(square, {{0, 1, 2}, {0, 2, 3}});
    REQUIRE(check_mesh(mesh).empty());
    const TriangleId t = find_triangle(mesh, 0, 1, 2);
    const TriangleId u = find_triangle(mesh, 0, 2, 3);
    const auto gt = mesh.triangle(t).generation, gu = mesh.triangle(u).generation;
    const EdgeRef e = edge_of(mesh, t, 2, 0);
    REQUIRE(flippable(mesh, e));
    const EdgeRef diagonal = flip(mesh, e);
    CHECK(canonical(mesh) == std::vector<Tri>{{0, 1, 3}, {1, 2, 3}});
    CHECK(check_mesh(mesh).empty());
    CHECK(diagonal.triangle() == t);
    CHECK(mesh.origin(diagonal) == VertexId{3});       // from d ...
    CHECK(mesh.destination(diagonal) == VertexId{1});  // ... to a
    CHECK(mesh.triangle(t).generation == gt + 1);
    CHECK(mesh.triangle(u).generation == gu + 1);
    // Flipping back restores the first triangulation.
    flip(mesh, diagonal);
    CHECK(canonical(mesh) == std::vector<Tri>{{0, 1, 2}, {0, 2, 3}});
    CHECK(check_mesh(mesh).empty());
}

TEST_CASE("a flip keeps outer neighbours and subsegment flags", "[mesh][flip]") {
    // Two squares side by side; flip the diagonal of the left one.
    const std::vector<Point> p{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {2, 1}};
    Mesh mesh = mesh_from_triangles(p, {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}});
    // Hull edge 0-1 is a subsegment.
    const TriangleId t = find_triangle(mesh, 0, 1, 2);
    mesh.triangle(t).set_subsegment(edge_of(mesh, t, 0, 1).edge(), true);
    mesh.subsegments().set(VertexId{0}, VertexId{1}, {7, 0});
    REQUIRE(check_mesh(mesh).empty());
    flip(mesh, edge_of(mesh, t, 2, 0));
    CHECK(canonical(mesh) == std::vector<Tri>{{0, 1, 3}, {1, 2, 3}, {1, 4, 5}, {1, 5, 2}});
    CHECK(check_mesh(mesh).empty());
    const TriangleId a = find_triangle(mesh, 0, 1, 3);
    CHECK(mesh.triangle(a).is_subsegment(edge_of(mesh, a, 0, 1).edge()));
    // The right square still sees the edge 1-2 of the flipped pair.
    const TriangleId r = find_triangle(mesh, 1, 5, 2);
    const EdgeRef across = mesh.neighbour(edge_of(mesh, r, 2, 1));
    CHECK(across.triangle() == find_triangle(mesh, 1, 2, 3));
}

TEST_CASE("unflippable edges are refused", "[mesh][flip]") {
    SECTION("hull edge") {
        Mesh mesh = mesh_from_triangles(square, {{0, 1, 2}, {0, 2, 3}});
        const TriangleId t = find_triangle(mesh, 0, 1, 2);
        CHECK_FALSE(flippable(mesh, edge_of(mesh, t, 0, 1)));
    }
    SECTION("subsegment") {
        Mesh mesh = mesh_from_triangles(square, {{0, 1, 2}, {0, 2, 3}});
        const TriangleId t = find_triangle(mesh, 0, 1, 2);
        mesh.triangle(t).set_subsegment(edge_of(mesh, t, 2, 0).edge(), true);
        CHECK_FALSE(flippable(mesh, edge_of(mesh, t, 2, 0)));
    }
    SECTION("non-convex quadrilateral") {
        const std::vector<Point> p{{0, 0}, {2, 0}, {0.5, 0.5}, {0, 2}};
        Mesh mesh = mesh_from_triangles(p, {{0, 1, 2}, {0, 2, 3}});
        const TriangleId t = find_triangle(mesh, 0, 1, 2);
        CHECK_FALSE(flippable(mesh, edge_of(mesh, t, 2, 0)));
    }
    SECTION("degenerate: the new diagonal would pass through a corner") {
        const std::vector<Point> p{{0, 0}, {2, 0}, {1, 1}, {0, 2}};
        Mesh mesh = mesh_from_triangles(p, {{0, 1, 2}, {0, 2, 3}});
        const TriangleId t = find_triangle(mesh, 0, 1, 2);
        CHECK_FALSE(flippable(mesh, edge_of(mesh, t, 2, 0)));
    }
}

TEST_CASE("a flip repairs a non-Delaunay edge", "[mesh][flip]") {
    const std::vector<Point> kite{{0, 0}, {1, -0.3}, {2, 0}, {1, 0.3}};
    Mesh mesh = mesh_from_triangles(kite, {{0, 1, 2}, {0, 2, 3}});
    const auto problems = check_mesh(mesh);
    REQUIRE(problems.size() == 1);
    CHECK_THAT(problems[0], Catch::Contains("not locally Delaunay"));
    const TriangleId t = find_triangle(mesh, 0, 1, 2);
    REQUIRE(flippable(mesh, edge_of(mesh, t, 2, 0)));
    flip(mesh, edge_of(mesh, t, 2, 0));
    CHECK(check_mesh(mesh).empty());
    CHECK(canonical(mesh) == std::vector<Tri>{{0, 1, 3}, {1, 2, 3}});
}

TEST_CASE("Lawson's flips save the tagged triangles they change and clear their tags",
          "[mesh][flip]") {
    // The kite's diagonal 0-2 is not locally Delaunay; the flip from the
    // "created" triangle 0-1-2 changes it and the triangle beyond.
    const std::vector<Point> kite{{0, 0}, {1, -0.3}, {2, 0}, {1, 0.3}};
    Mesh mesh = mesh_from_triangles(kite, {{0, 1, 2}, {0, 2, 3}});
    const TriangleId t = find_triangle(mesh, 0, 1, 2), beyond = find_triangle(mesh, 0, 2, 3);
    InsertBuffer buffer;
    buffer.created = {t};
    const auto corners = [](const TaggedTriangle& g) {
        return Tri{index(g.v[0]), index(g.v[1]), index(g.v[2])};
    };
    SECTION("only the triangle beyond is tagged") {
        mesh.triangle(beyond).user_tag = 7;
        lawson_flips(mesh, buffer);
        REQUIRE(buffer.tagged_gone.size() == 1);
        CHECK(corners(buffer.tagged_gone[0]) == Tri{0, 2, 3});
        CHECK(buffer.tagged_gone[0].tag == 7);
    }
    SECTION("both are tagged") {
        mesh.triangle(t).user_tag = 5;
        mesh.triangle(beyond).user_tag = 7;
        lawson_flips(mesh, buffer);
        REQUIRE(buffer.tagged_gone.size() == 2);
        CHECK(corners(buffer.tagged_gone[0]) == Tri{0, 1, 2});
        CHECK(buffer.tagged_gone[0].tag == 5);
        CHECK(corners(buffer.tagged_gone[1]) == Tri{0, 2, 3});
        CHECK(buffer.tagged_gone[1].tag == 7);
    }
    CHECK(check_mesh(mesh).empty());
    CHECK(canonical(mesh) == std::vector<Tri>{{0, 1, 3}, {1, 2, 3}});
    CHECK(mesh.triangle(t).user_tag == 0);
    CHECK(mesh.triangle(beyond).user_tag == 0);
    CHECK(buffer.created.size() == 2);  // the changed triangle beyond joined them
}
