// Point location: every answer is checked against exact predicates, from
// many starting triangles, on a degenerate (grid) mesh and on a fan mesh that
// is far from Delaunay (where plain visibility walks can cycle).

#include <catch2/catch.hpp>

#include <random>

#include "geometry/predicates.hpp"
#include "mesh/locate.hpp"
#include "mesh/test_support.hpp"

using namespace gpdr::mesh;
using namespace gpdr::mesh::testing;
using gpdr::geometry::orient2d;

namespace {

// Checks a locate() answer for p exactly.
void verify(const Mesh& mesh, const Point& p, const LocateResult& r) {
    const Triangle& t = mesh.triangle(r.triangle);
    REQUIRE(t.live());
    double o[3];
    for (int k = 0; k < 3; ++k)
        o[k] = orient2d(mesh.point(t.v[next3(k)]), mesh.point(t.v[prev3(k)]), p);
    switch (r.where) {
        case Location::inside:
            CHECK((o[0] > 0 && o[1] > 0 && o[2] > 0));
            break;
        case Location::on_edge:
            CHECK(o[r.index] == 0);
            CHECK((o[next3(r.index)] > 0 && o[prev3(r.index)] > 0));
            break;
        case Location::on_vertex:
            CHECK(mesh.point(t.v[r.index]) == p);
            break;
        case Location::outside:
            CHECK(o[r.index] < 0);
            CHECK(t.n[r.index].is_none());
            break;
    }
}

std::vector<TriangleId> all_triangles(const Mesh& mesh) {
    std::vector<TriangleId> ids;
    for_each_triangle(mesh, [&](TriangleId id, const Triangle&) { ids.push_back(id); });
    return ids;
}

}  // namespace

TEST_CASE("walks on a grid mesh find vertices, edges and interiors", "[mesh][locate]") {
    const int k = 12;
    std::vector<Point> points;
    std::vector<Tri> triangles;
    for (int y = 0; y <= k; ++y)
        for (int x = 0; x <= k; ++x) points.push_back({double(x), double(y)});
    auto id = [&](int x, int y) { return static_cast<std::uint32_t>(y * (k + 1) + x); };
    for (int y = 0; y < k; ++y)
        for (int x = 0; x < k; ++x) {
            triangles.push_back({id(x, y), id(x + 1, y), id(x + 1, y + 1)});
            triangles.push_back({id(x, y), id(x + 1, y + 1), id(x, y + 1)});
        }
    const Mesh mesh = mesh_from_triangles(points, triangles);
    const auto ids = all_triangles(mesh);
    std::mt19937 rng(11);
    std::uniform_int_distribution<std::size_t> pick(0, ids.size() - 1);
    std::uint32_t state = 1;
    int on_vertex = 0, on_edge = 0, outside = 0;
    for (int q = 0; q < 3000; ++q) {
        // Half-integer coordinates hit vertices, edges and cell centres.
        const Point p{(double(rng() % (2 * k + 5)) - 2) / 2, (double(rng() % (2 * k + 5)) - 2) / 2};
        const LocateResult r = locate(mesh, p, ids[pick(rng)], state);
        verify(mesh, p, r);
        on_vertex += r.where == Location::on_vertex;
        on_edge += r.where == Location::on_edge;
        outside += r.where == Location::outside;
    }
    CHECK(on_vertex > 0);
    CHECK(on_edge > 0);
    CHECK(outside > 0);
}

TEST_CASE("walks terminate on a fan that is far from Delaunay", "[mesh][locate]") {
    // A convex polygon (points on a parabola) triangulated as a fan from one
    // corner: long thin triangles.
    std::vector<Point> points;
    const int n = 200;
    for (int i = 0; i < n; ++i) {
        const double x = i - n / 2;
        points.push_back({x, x * x});
    }
    std::vector<Tri> triangles;
    // Along y = x^2 from left to right the polygon is counter-clockwise.
    for (std::uint32_t i = 1; i + 1 < static_cast<std::uint32_t>(n); ++i)
        triangles.push_back({0, i, i + 1});
    const Mesh mesh = mesh_from_triangles(points, triangles);
    const auto ids = all_triangles(mesh);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> ux(-n / 2.0, n / 2.0), uy(0, n * n / 4.0);
    std::uint32_t state = 9;
    for (int q = 0; q < 2000; ++q) {
        const Point p{ux(rng), uy(rng)};
        verify(mesh, p, locate(mesh, p, ids[rng() % ids.size()], state));
    }
}
