// The checker finds deliberately broken meshes, one kind of damage at a time,
// and names what is wrong.

#include <catch2/catch.hpp>

#include <algorithm>

#include "check/checker.hpp"
#include "mesh/test_support.hpp"

using namespace gpdr::mesh;
using namespace gpdr::mesh::testing;

namespace {

// A square split at its centre into four triangles (vertex 4 in the middle).
Mesh four() {
    return mesh_from_triangles({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.4}},
                               {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
}

bool mentions(const std::vector<std::string>& problems, const std::string& what) {
    return std::any_of(problems.begin(), problems.end(),
                       [&](const std::string& s) { return s.find(what) != std::string::npos; });
}

}  // namespace

TEST_CASE("the checker accepts a valid mesh", "[mesh][checker]") {
    CHECK(check_mesh(four()).empty());
}

TEST_CASE("the checker finds broken meshes", "[mesh][checker]") {
    Mesh mesh = four();
    const TriangleId t = find_triangle(mesh, 0, 1, 4);
    Triangle& r = mesh.triangle(t);

    SECTION("clockwise triangle") {
        std::swap(r.v[0], r.v[1]);
        const auto problems = check_mesh(mesh);
        CHECK(mentions(problems, "not strictly counter-clockwise"));
        CHECK(mentions(problems, "triangle " + std::to_string(index(t))));
    }
    SECTION("degenerate triangle") {
        mesh.set_point(VertexId{4}, {0.5, 0});
        CHECK(mentions(check_mesh(mesh), "not strictly counter-clockwise"));
    }
    SECTION("one-sided neighbour link") {
        const EdgeRef e = edge_of(mesh, t, 1, 4);
        r.n[e.edge()] = EdgeRef::none();
        CHECK(mentions(check_mesh(mesh), "does not link back"));
    }
    SECTION("link to the wrong edge") {
        const EdgeRef e = edge_of(mesh, t, 1, 4);
        const EdgeRef across = r.n[e.edge()];
        r.n[e.edge()] = EdgeRef(across.triangle(), next3(across.edge()));
        CHECK(mentions(check_mesh(mesh), "in neighbour"));
    }
    SECTION("dead triangle referenced") {
        Pool pool(mesh);
        pool.destroy(find_triangle(mesh, 1, 2, 4));
        CHECK(mentions(check_mesh(mesh), "which is not live"));
    }
    SECTION("not Delaunay") {
        // A kite split along its long diagonal: each apex lies inside the
        // other triangle's circumcircle.
        const Mesh kite =
            mesh_from_triangles({{0, 0}, {1, -0.3}, {2, 0}, {1, 0.3}}, {{0, 1, 2}, {0, 2, 3}});
        const auto problems = check_mesh(kite);
        CHECK(mentions(problems, "edge 2-0 is not locally Delaunay: vertex 3"));
        CheckOptions topology_only;
        topology_only.delaunay = false;
        CHECK(check_mesh(kite, topology_only).empty());
    }
    SECTION("subsegment flag on one side only") {
        const EdgeRef e = edge_of(mesh, t, 1, 4);
        r.set_subsegment(e.edge(), true);
        mesh.subsegments().set(VertexId{1}, VertexId{4}, {});
        CHECK(mentions(check_mesh(mesh), "subsegment on one side only"));
    }
    SECTION("flagged edge missing from the side table") {
        const EdgeRef e = edge_of(mesh, t, 0, 1);
        r.set_subsegment(e.edge(), true);
        CHECK(mentions(check_mesh(mesh), "missing from the side table"));
        CheckOptions no_table;
        no_table.subsegment_table = false;
        CHECK(check_mesh(mesh, no_table).empty());
    }
    SECTION("side table entry with no flagged edge") {
        mesh.subsegments().set(VertexId{0}, VertexId{2}, {});
        CHECK(mentions(check_mesh(mesh),
                       "the side table holds 1 subsegments but 0 edges are flagged"));
    }
    SECTION("repeated vertex") {
        r.v[2] = r.v[0];
        CHECK(mentions(check_mesh(mesh), "a vertex repeats"));
    }
    SECTION("ghost vertex left in the mesh") {
        r.v[2] = ghost_vertex;
        CHECK(mentions(check_mesh(mesh), "is not a stored vertex"));
    }
    SECTION("duplicate vertex used") {
        mesh.set_kind(VertexId{4}, VertexKind::duplicate);
        CHECK(mentions(check_mesh(mesh), "a duplicate left out"));
    }
}

TEST_CASE("the checker caps its list of problems", "[mesh][checker]") {
    Mesh mesh = four();
    for_each_triangle(mesh, [&](TriangleId id, const Triangle&) {
        Triangle& r = mesh.triangle(id);
        std::swap(r.v[0], r.v[1]);
    });
    CheckOptions options;
    options.max_problems = 3;
    const auto problems = check_mesh(mesh, options);
    REQUIRE(problems.size() == 4);
    CHECK_THAT(problems.back(), Catch::StartsWith("... and"));
}

TEST_CASE("the checker finds the same problems on several threads", "[mesh][checker]") {
    // A grid of 260 x 260 squares, two triangles each: many chunks of slots.
    const std::uint32_t n = 260;
    std::vector<Point> points;
    for (std::uint32_t y = 0; y <= n; ++y)
        for (std::uint32_t x = 0; x <= n; ++x) points.push_back({double(x), double(y)});
    std::vector<Tri> triangles;
    for (std::uint32_t y = 0; y < n; ++y)
        for (std::uint32_t x = 0; x < n; ++x) {
            const std::uint32_t a = y * (n + 1) + x, b = a + 1, c = a + n + 2, d = a + n + 1;
            triangles.push_back({a, b, c});
            triangles.push_back({a, c, d});
        }
    Mesh mesh = mesh_from_triangles(points, triangles);
    REQUIRE(mesh.triangle_end() >= 100 * Mesh::TriangleTable::chunk_size);
    // Damage spread over the slots: clockwise triangles.
    for (const std::uint32_t i : {5u, 70000u, 100000u, 135000u}) {
        Triangle& t = mesh.triangle(TriangleId{i});
        std::swap(t.v[0], t.v[1]);
    }
    CheckOptions one;
    one.subsegment_table = false;
    CheckOptions three = one;
    three.threads = 3;
    const auto expected = check_mesh(mesh, one);
    CHECK(mentions(expected, "triangle 135000 "));
    CHECK(check_mesh(mesh, three) == expected);
    one.max_problems = three.max_problems = 3;
    const auto few = check_mesh(mesh, one);
    CHECK(few.back().find("more problems") != std::string::npos);
    CHECK(check_mesh(mesh, three) == few);
    CHECK(check_mesh(four(), three).empty());
}
