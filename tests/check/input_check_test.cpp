// The check of a mesh against its input (-C) on hand-built meshes: each
// wrong in one way, which must be found, and right ones, which must pass.

#include <catch2/catch.hpp>

#include <algorithm>

#include "check/input_check.hpp"
#include "geometry/constructions.hpp"
#include "geometry/predicates.hpp"
#include "mesh/test_support.hpp"

using namespace gpdr::mesh;
using namespace gpdr::mesh::testing;

namespace {

// The unit square split at (0.5, 0.4) into four triangles.
const std::vector<Point> square_points{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.4}};
Mesh four() {
    return mesh_from_triangles(square_points, {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
}

// The square's input: its vertices and its four sides.
InputGeometry square_input() {
    InputGeometry g;
    g.points = square_points;
    g.segments = {0, 1, 1, 2, 2, 3, 3, 0};
    return g;
}

bool mentions(const std::vector<std::string>& problems, const std::string& what) {
    return std::any_of(problems.begin(), problems.end(),
                       [&](const std::string& s) { return s.find(what) != std::string::npos; });
}

std::string all(const std::vector<std::string>& problems) {
    std::string s;
    for (const auto& p : problems) s += p + "\n";
    return s;
}

}  // namespace

TEST_CASE("the input check accepts a mesh of its input", "[mesh][input_check]") {
    const Mesh mesh = four();
    CHECK(all(check_against_input(mesh, square_input())).empty());
    SECTION("as a point set: the hull bounds the domain") {
        InputGeometry g;
        g.points = square_points;
        g.hull_bounds_domain = true;
        CHECK(all(check_against_input(mesh, g)).empty());
    }
    SECTION("a segment through a mesh edge, and parts of segments outside") {
        InputGeometry g = square_input();
        g.points.push_back({2, 0});
        g.points.push_back({3, 3});
        g.segments.insert(g.segments.end(), {4, 2, 1, 5, 5, 6, 4, 4});  // and a zero-length one
        CHECK(all(check_against_input(mesh, g)).empty());
    }
    SECTION("duplicate vertices and segments, a vertex outside, a hole outside") {
        InputGeometry g = square_input();
        g.points.push_back({1, 1});
        g.points.push_back({5, 5});
        g.segments.insert(g.segments.end(), {0, 1, 5, 3});
        g.holes.push_back({7, 7});
        CHECK(all(check_against_input(mesh, g)).empty());
    }
}

TEST_CASE("the input check finds what is wrong", "[mesh][input_check]") {
    Mesh mesh = four();
    InputGeometry g = square_input();
    InputCheckOptions o;
    o.base = 1;

    SECTION("a segment not covered by mesh edges") {
        g.segments.insert(g.segments.end(), {0, 2});  // the diagonal; no edge lies on it
        const auto p = check_against_input(mesh, g, o);
        CHECK(mentions(p, "segment 5 (vertices 1 and 3) is not covered by mesh edges"));
    }
    SECTION("a boundary edge on no segment") {
        g.segments.resize(6);  // side 3-0 left out
        const auto p = check_against_input(mesh, g, o);
        CHECK(mentions(p, "the boundary edge from (0, 1) to (0, 0) lies on no input segment"));
    }
    SECTION("an input vertex in the domain lost") {
        g.points.push_back({0.25, 0.75});
        const auto p = check_against_input(mesh, g, o);
        CHECK(mentions(p, "input vertex 6 at (0.25, 0.75) lies in the domain"));
    }
    SECTION("an input vertex on the boundary lost") {
        g.points.push_back({0.5, 1});
        g.segments = {0, 1, 1, 2, 2, 5, 5, 3, 3, 0};
        const auto p = check_against_input(mesh, g, o);
        CHECK(mentions(p, "input vertex 6 at (0.5, 1) lies in the domain"));
        CHECK(mentions(p, "segment 3 (vertices 3 and 6) is not covered"));
    }
    SECTION("a triangle in a hole") {
        g.holes.push_back({0.5, 0.1});
        const auto p = check_against_input(mesh, g, o);
        CHECK(mentions(p, "hole 1 at (0.5, 0.1) lies inside a triangle"));
    }
    SECTION("a wrong region attribute") {
        g.regions.push_back({{0.5, 0.1}, 7.0, -1});
        const std::vector<double> attributes{0.0, 7.0};
        o.region_attributes = true;
        o.attribute_of_region = attributes;
        CHECK(mentions(check_against_input(mesh, g, o), "has attribute 0 where region 1 says 7"));
        // Right: the whole square is region 1 (no segment divides it).
        for_each_triangle(mesh,
                          [&](TriangleId t, const Triangle&) { mesh.triangle(t).region = 1; });
        CHECK(all(check_against_input(mesh, g, o)).empty());
        // A segment through the square divides it: the other side is 0.
        g.segments.insert(g.segments.end(), {0, 4, 4, 2});
        CHECK(mentions(check_against_input(mesh, g, o), "has attribute 7 where no region says 0"));
    }
    SECTION("an angle below the bound, unless refinement gave the triangle up") {
        // The smallest angles: 38.7 degrees at (0, 0) and (1, 0).
        o.min_angle = 38;
        CHECK(all(check_against_input(mesh, g, o)).empty());
        o.min_angle = 39;
        const auto p = check_against_input(mesh, g, o);
        CHECK(mentions(p, "the triangle (0, 0) (1, 0) (0.5, 0.4) has an angle of 38.7 degrees"));
        std::vector<TriangleId> exempt;
        for_each_triangle(mesh, [&](TriangleId t, const Triangle&) { exempt.push_back(t); });
        o.exempt = exempt;
        CHECK(all(check_against_input(mesh, g, o)).empty());
    }
    SECTION("an area above the bound, global or regional") {
        o.max_area = 0.3;
        CHECK(all(check_against_input(mesh, g, o)).empty());
        o.max_area = 0.22;
        CHECK(
            mentions(check_against_input(mesh, g, o),
                     "the triangle (1, 0) (1, 1) (0.5, 0.4) has area 0.25, above the bound 0.22"));
        o.max_area = 0;
        g.regions.push_back({{0.9, 0.5}, 0.0, 0.2});
        o.regional_area = true;
        CHECK(mentions(check_against_input(mesh, g, o), "above region 1's bound 0.2"));
    }
    SECTION("an area above the .area file's bound at its centroid") {
        // The .ele read: the square's lower-left half (input triangle 1,
        // bound 0.15) and its upper-right half (input triangle 2, no bound).
        // The mesh's triangles at the bottom (area 0.2) and on the left
        // (0.25) have their centroids in the first; the other two, in the
        // second, are as large but free.
        const std::vector<std::uint32_t> corners{0, 1, 3, 1, 2, 3};
        g.area_field.emplace(square_points, corners, 3, std::vector<double>{0.15, -1});
        CHECK(all(check_against_input(mesh, g, o)).empty());  // not asked for
        o.area_field = true;
        const auto p = check_against_input(mesh, g, o);
        CHECK(p.size() == 2);
        CHECK(mentions(p,
                       "the triangle (0, 0) (1, 0) (0.5, 0.4) has area 0.2, above the bound "
                       "0.15 of input triangle 1, which holds its centroid"));
        CHECK(mentions(p, "has area 0.25, above the bound 0.15 of input triangle 1"));
        g.area_field.emplace(square_points, corners, 3, std::vector<double>{0.25, -1});
        CHECK(all(check_against_input(mesh, g, o)).empty());
        g.area_field.emplace(square_points, corners, 3, std::vector<double>{0.25, 0.29});
        CHECK(mentions(check_against_input(mesh, g, o),
                       "has area 0.3, above the bound 0.29 of input triangle 2"));
    }
    SECTION("a triangle the user's triunsuitable() rejects, unless given up") {
        // The test rejects the triangle whose corners include (1, 1).
        o.unsuitable = [&](TriangleId t) {
            const Triangle& r = mesh.triangle(t);
            return std::any_of(std::begin(r.v), std::end(r.v), [&](VertexId v) {
                return mesh.point(v) == Point{1, 1};
            });
        };
        const auto p = check_against_input(mesh, g, o);
        CHECK(mentions(p, "(1, 1) (0.5, 0.4) is one triunsuitable() asks to refine"));
        CHECK(p.size() == 2);  // the two triangles at (1, 1)
        std::vector<TriangleId> exempt;
        for_each_triangle(mesh, [&](TriangleId t, const Triangle&) { exempt.push_back(t); });
        o.exempt = exempt;
        CHECK(all(check_against_input(mesh, g, o)).empty());
    }
    SECTION("numbers from 0 with base 0") {
        g.points.push_back({0.25, 0.75});
        o.base = 0;
        CHECK(mentions(check_against_input(mesh, g, o), "input vertex 5 at (0.25, 0.75)"));
    }
}

TEST_CASE("the input check accepts crossings at rounded points, and only there",
          "[mesh][input_check]") {
    // Segments 0-2 and 1-3 cross at a point no double holds exactly.
    const Point a{0, 0}, b{3, 0.1}, c{3, 1.3}, d{0.1, 1};
    const Point x = gpdr::geometry::segment_intersection(a, c, b, d);
    REQUIRE(gpdr::geometry::orient2d(a, c, x) != 0);
    REQUIRE(gpdr::geometry::orient2d(b, d, x) != 0);
    InputGeometry g;
    g.points = {a, b, c, d};
    g.segments = {0, 1, 1, 2, 2, 3, 3, 0, 0, 2, 1, 3};
    const auto mesh_with = [&](const Point& centre) {
        return mesh_from_triangles({a, b, c, d, centre},
                                   {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
    };
    CHECK(all(check_against_input(mesh_with(x), g)).empty());
    // Refinement splits the pieces a-x and x-c at their rounded midpoints.
    {
        const Point m = gpdr::geometry::point_on_segment(a, x, 0.5);
        const Mesh split = mesh_from_triangles(
            {a, b, c, d, x, m}, {{0, 1, 5}, {1, 4, 5}, {1, 2, 4}, {2, 3, 4}, {3, 5, 4}, {3, 0, 5}});
        CHECK(all(check_against_input(split, g)).empty());
    }
    // A vertex far from the crossing is not on the segments.
    const Point off{x.x + 1e-6, x.y};
    const auto p = check_against_input(mesh_with(off), g);
    CHECK(mentions(p, "segment 4 (vertices 0 and 2) is not covered"));
    CHECK(mentions(p, "segment 5 (vertices 1 and 3) is not covered"));
}

TEST_CASE("the input check leaves small angles of the input's own", "[mesh][input_check]") {
    // A wedge of 11.4 degrees at (0, 0), closed at x = 10: its one triangle
    // is below a bound of 30 degrees only because the input is.
    const std::vector<Point> points{{0, 0}, {10, -1}, {10, 1}};
    const Mesh mesh = mesh_from_triangles(points, {{0, 1, 2}});
    InputGeometry g;
    g.points = points;
    g.segments = {0, 1, 1, 2, 2, 0};
    InputCheckOptions o;
    o.min_angle = 30;
    CHECK(all(check_against_input(mesh, g, o)).empty());
    // Without the segment from (10, 1) to (0, 0), the short edge's ends lie
    // only on two segments that meet at 84 degrees: the small angle is no
    // longer the input's.
    g.segments = {0, 1, 1, 2};
    const auto p = check_against_input(mesh, g, o);
    CHECK(mentions(p, "has an angle of 11.4 degrees, below the bound 30"));
}
