// Bowyer–Watson insertion: random points keep the mesh Delaunay (checked
// after every insertion), points on edges, on subsegments, on vertices and
// outside, and cavities that stop at subsegments.

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "check/checker.hpp"
#include "mesh/insert.hpp"
#include "mesh/test_support.hpp"

using namespace gpdr::mesh;
using namespace gpdr::mesh::testing;

namespace {

const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

Mesh square_mesh() { return mesh_from_triangles(square, {{0, 1, 2}, {0, 2, 3}}); }

TriangleId any_triangle(const Mesh& mesh) {
    TriangleId any = no_triangle;
    for_each_triangle(mesh, [&](TriangleId id, const Triangle&) {
        if (any == no_triangle) any = id;
    });
    return any;
}

void flag_subsegment(Mesh& mesh, std::uint32_t a, std::uint32_t b, int marker) {
    for_each_triangle(mesh, [&](TriangleId id, const Triangle&) {
        for (EdgeRef e : {edge_of(mesh, id, a, b), edge_of(mesh, id, b, a)})
            if (!e.is_none()) mesh.triangle(id).set_subsegment(e.edge(), true);
    });
    mesh.subsegments().set(VertexId{a}, VertexId{b}, {marker, 0});
}

}  // namespace

TEST_CASE("random insertions keep a mesh Delaunay", "[mesh][insert]") {
    Mesh mesh = square_mesh();
    Pool pool(mesh);
    InsertBuffer buffer;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    TriangleId hint = any_triangle(mesh);
    const int n = 400;
    for (int i = 0; i < n; ++i) {
        const Point p{u(rng), u(rng)};
        const InsertResult r = insert_point(pool, p, VertexKind::free, hint, buffer);
        REQUIRE(r.status == InsertStatus::inserted);
        CHECK(mesh.point(r.vertex) == p);
        CHECK(mesh.kind(r.vertex) == VertexKind::free);
        // An interior point: the fan has two triangles more than the cavity.
        CHECK(buffer.created.size() == buffer.killed.size() + 2);
        for (TriangleId t : buffer.created) {
            CHECK(mesh.triangle(t).live());
            CHECK(mesh.triangle(t).v[2] == r.vertex);
        }
        hint = buffer.created.front();
        if (i < 60 || i % 50 == 0) REQUIRE(check_mesh(mesh).empty());
    }
    CHECK(check_mesh(mesh).empty());
    // Euler: 2n - 2 - h triangles for n vertices, h of them on the hull.
    CHECK(mesh.count_triangles() == static_cast<std::size_t>(2 * (n + 4) - 2 - 4));
    CHECK(count_hull_edges(mesh) == 4);
}

TEST_CASE("killed triangles get a new generation", "[mesh][insert]") {
    Mesh mesh = square_mesh();
    Pool pool(mesh);
    InsertBuffer buffer;
    const TriangleId t = find_triangle(mesh, 0, 1, 2);
    const TriangleId s = find_triangle(mesh, 0, 2, 3);
    const auto gt = mesh.triangle(t).generation, gs = mesh.triangle(s).generation;
    const InsertResult r = insert_point(pool, {0.6, 0.3}, VertexKind::free, t, buffer);
    REQUIRE(r.status == InsertStatus::inserted);
    // All four corners are cocircular with... no: (0.6, 0.3) is inside the
    // square's circumcircle, so both triangles die.
    CHECK(buffer.killed.size() == 2);
    CHECK(mesh.triangle(t).generation != gt);
    CHECK(mesh.triangle(s).generation != gs);
    CHECK(buffer.created.size() == 4);
    CHECK(mesh.count_triangles() == 4);
    CHECK(check_mesh(mesh).empty());
}

TEST_CASE("a point on an interior edge splits both triangles", "[mesh][insert]") {
    Mesh mesh = square_mesh();
    Pool pool(mesh);
    InsertBuffer buffer;
    const InsertResult r =
        insert_point(pool, {0.5, 0.5}, VertexKind::free, find_triangle(mesh, 0, 1, 2), buffer);
    REQUIRE(r.status == InsertStatus::inserted);
    CHECK(canonical(mesh) == std::vector<Tri>{{0, 1, 4}, {0, 4, 3}, {1, 2, 4}, {2, 3, 4}});
    CHECK(check_mesh(mesh).empty());
}

TEST_CASE("a point on a hull edge stays on the hull", "[mesh][insert]") {
    Mesh mesh = square_mesh();
    Pool pool(mesh);
    InsertBuffer buffer;
    const InsertResult r =
        insert_point(pool, {0.5, 0}, VertexKind::free, find_triangle(mesh, 0, 2, 3), buffer);
    REQUIRE(r.status == InsertStatus::inserted);
    CHECK(check_mesh(mesh).empty());
    CHECK(mesh.count_triangles() == 3);
    CHECK(count_hull_edges(mesh) == 5);
    CHECK(canonical(mesh) == std::vector<Tri>{{0, 4, 3}, {1, 2, 4}, {2, 3, 4}});
}

TEST_CASE("points on subsegments are refused and reported", "[mesh][insert]") {
    Mesh mesh = square_mesh();
    flag_subsegment(mesh, 0, 1, 3);  // a hull edge
    flag_subsegment(mesh, 0, 2, 4);  // the diagonal
    REQUIRE(check_mesh(mesh).empty());
    const auto before = canonical(mesh);
    Pool pool(mesh);
    InsertBuffer buffer;
    const TriangleId hint = find_triangle(mesh, 0, 2, 3);

    InsertResult r = insert_point(pool, {0.25, 0}, VertexKind::free, hint, buffer);
    CHECK(r.status == InsertStatus::on_subsegment);
    CHECK(r.vertex == no_vertex);
    REQUIRE_FALSE(r.edge.is_none());
    CHECK(mesh.subsegments().find(mesh.origin(r.edge), mesh.destination(r.edge))->marker == 3);

    r = insert_point(pool, {0.75, 0.75}, VertexKind::free, hint, buffer);
    CHECK(r.status == InsertStatus::on_subsegment);
    CHECK(mesh.subsegments().find(mesh.origin(r.edge), mesh.destination(r.edge))->marker == 4);

    CHECK(canonical(mesh) == before);
    CHECK(mesh.vertex_end() == 4);  // no vertex was created
}

TEST_CASE("a cavity does not cross a subsegment", "[mesh][insert]") {
    Mesh mesh = square_mesh();
    flag_subsegment(mesh, 0, 2, 1);
    Pool pool(mesh);
    InsertBuffer buffer;
    const TriangleId other = find_triangle(mesh, 0, 2, 3);
    const auto generation = mesh.triangle(other).generation;
    // (0.6, 0.3) is inside the circumcircle of (0, 2, 3) too, but behind the
    // subsegment 0-2.
    const InsertResult r = insert_point(pool, {0.6, 0.3}, VertexKind::free, other, buffer);
    REQUIRE(r.status == InsertStatus::inserted);
    CHECK(buffer.killed.size() == 1);
    CHECK(buffer.created.size() == 3);
    CHECK(mesh.triangle(other).generation == generation);
    CHECK(find_triangle(mesh, 0, 2, 3) == other);
    // Constrained Delaunay, and the subsegment kept its flag on the new side.
    CHECK(check_mesh(mesh).empty());
    const TriangleId fan = find_triangle(mesh, 0, 2, 4);
    REQUIRE(fan != no_triangle);
    EdgeRef e = edge_of(mesh, fan, 2, 0);
    REQUIRE_FALSE(e.is_none());
    CHECK(mesh.triangle(fan).is_subsegment(e.edge()));
}

TEST_CASE("a point equal to a vertex is a duplicate", "[mesh][insert]") {
    Mesh mesh = square_mesh();
    Pool pool(mesh);
    InsertBuffer buffer;
    const auto before = canonical(mesh);
    InsertResult r =
        insert_point(pool, {1, 1}, VertexKind::free, find_triangle(mesh, 0, 2, 3), buffer);
    CHECK(r.status == InsertStatus::duplicate);
    CHECK(r.vertex == VertexId{2});
    const VertexId copy = mesh.add_vertex({0, 1}, VertexKind::input);
    r = insert_vertex(pool, copy, find_triangle(mesh, 0, 1, 2), buffer);
    CHECK(r.status == InsertStatus::duplicate);
    CHECK(r.vertex == VertexId{3});
    CHECK(canonical(mesh) == before);
}

TEST_CASE("a point outside a mesh without ghosts is refused", "[mesh][insert]") {
    Mesh mesh = square_mesh();
    Pool pool(mesh);
    InsertBuffer buffer;
    const auto before = canonical(mesh);
    const InsertResult r =
        insert_point(pool, {2, 0.5}, VertexKind::free, find_triangle(mesh, 0, 2, 3), buffer);
    CHECK(r.status == InsertStatus::outside);
    REQUIRE_FALSE(r.edge.is_none());
    CHECK(mesh.neighbour(r.edge).is_none());
    CHECK(mesh.origin(r.edge) == VertexId{1});
    CHECK(mesh.destination(r.edge) == VertexId{2});
    CHECK(canonical(mesh) == before);
}

TEST_CASE("insertions on a cocircular grid stay Delaunay", "[mesh][insert]") {
    // Grid points: massively cocircular; many land on existing edges.
    Mesh mesh = mesh_from_triangles({{0, 0}, {8, 0}, {8, 8}, {0, 8}}, {{0, 1, 2}, {0, 2, 3}});
    Pool pool(mesh);
    InsertBuffer buffer;
    TriangleId hint = find_triangle(mesh, 0, 1, 2);
    std::vector<Point> grid;
    for (int x = 0; x <= 8; ++x)
        for (int y = 0; y <= 8; ++y) grid.push_back({double(x), double(y)});
    std::shuffle(grid.begin(), grid.end(), std::mt19937(3));
    int inserted = 0, duplicates = 0;
    for (const Point& p : grid) {
        const InsertResult r = insert_point(pool, p, VertexKind::free, hint, buffer);
        if (r.status == InsertStatus::duplicate) {
            ++duplicates;
            continue;
        }
        REQUIRE(r.status == InsertStatus::inserted);
        ++inserted;
        hint = buffer.created.front();
        REQUIRE(check_mesh(mesh).empty());
    }
    CHECK(duplicates == 4);
    CHECK(inserted == 77);
    // 81 vertices, 32 on the hull.
    CHECK(mesh.count_triangles() == 2 * 81 - 2 - 32);
}
