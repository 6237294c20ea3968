// Rebuilding a mesh from .ele-style triangle lists (Triangle's -r):
// round trips through triangulate::delaunay give the same triangles and the
// same neighbours; hull edges become marker-1 subsegments; segments on mesh
// edges are flagged on both sides with marker and source; broken inputs
// (clockwise, degenerate, repeated corner, an edge in three triangles, two
// triangles on one side of an edge, a star winding twice) throw
// GeometryError naming the culprit.  A hidden benchmark times 5 million
// points' worth of triangles.

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gpdr/errors.hpp>

#include "check/checker.hpp"
#include "mesh/test_support.hpp"
#include "mesh/traverse.hpp"
#include "triangulate/delaunay.hpp"
#include "triangulate/from_triangles.hpp"

using namespace gpdr;
using namespace gpdr::mesh;
using namespace gpdr::mesh::testing;
using triangulate::from_triangles;
using triangulate::TriangleMeshInput;
using triangulate::TriangleMeshReport;

namespace {

// The live triangles of `mesh` in id order, as a corner list with `stride`
// entries per triangle (the extra ones filled with junk, as midpoints of a
// six-node .ele would be).
std::vector<std::uint32_t> corner_list(const Mesh& mesh, std::uint32_t stride = 3) {
    std::vector<std::uint32_t> corners;
    for_each_triangle(mesh, [&](TriangleId, const Triangle& t) {
        for (int k = 0; k < 3; ++k) corners.push_back(index(t.v[k]));
        for (std::uint32_t k = 3; k < stride; ++k) corners.push_back(0xDEADBEEFu);
    });
    return corners;
}

std::string first_problem(const std::vector<std::string>& problems) {
    return problems.empty() ? std::string() : problems.front();
}

void require_valid(const Mesh& mesh) {
    CheckOptions options;
    options.delaunay = false;
    const auto problems = check_mesh(mesh, options);
    INFO(first_problem(problems));
    REQUIRE(problems.empty());
}

// The message of the GeometryError that from_triangles throws on `in`.
std::string error_of(const TriangleMeshInput& in) {
    TriangleMeshReport report;
    try {
        from_triangles(in, report);
    } catch (const GeometryError& e) {
        return e.what();
    }
    FAIL("from_triangles accepted a broken mesh");
    return {};
}

// Unit square with its centre (vertex 4): four triangles around the centre.
const std::vector<Point> square_points{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
const std::vector<std::uint32_t> square_corners{0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};

}  // namespace

TEST_CASE("from_triangles rebuilds a Delaunay mesh with the same neighbours",
          "[triangulate][from_triangles]") {
    const std::uint32_t stride = GENERATE(3u, 6u);
    const std::size_t n = GENERATE(std::size_t{3}, std::size_t{50}, std::size_t{3000});
    const auto points = uniform_points(n, static_cast<std::uint32_t>(n + stride));
    triangulate::DelaunayReport dreport;
    const Mesh original = triangulate::delaunay(points, dreport);
    const auto corners = corner_list(original, stride);
    const std::size_t count = corners.size() / stride;
    std::vector<double> attributes(count * 2);
    for (std::size_t i = 0; i < attributes.size(); ++i) attributes[i] = 0.5 * double(i);

    TriangleMeshInput in;
    in.points = points;
    in.corners = corners;
    in.corners_per_triangle = stride;
    in.attributes = attributes;
    in.attribute_count = 2;
    TriangleMeshReport report;
    const Mesh mesh = from_triangles(in, report);

    require_valid(mesh);
    // A Delaunay input stays Delaunay (hull edges are subsegments now, which
    // the Delaunay check skips; there are no others).
    CHECK(check_mesh(mesh).empty());
    REQUIRE(mesh.count_triangles() == count);
    CHECK(canonical(mesh) == canonical(original));

    // Triangle i is the i-th live triangle of the original, with the same
    // corners in the same rotation and the same neighbours across the same
    // edges.
    const auto number = number_triangles(original);
    std::vector<TriangleId> by_number(count);
    for_each_triangle(original,
                      [&](TriangleId id, const Triangle&) { by_number[number[index(id)]] = id; });
    for (std::uint32_t i = 0; i < count; ++i) {
        const Triangle& t = mesh.triangle(TriangleId{i});
        const Triangle& o = original.triangle(by_number[i]);
        for (int k = 0; k < 3; ++k) {
            REQUIRE(t.v[k] == o.v[k]);
            if (o.n[k].is_none()) {
                REQUIRE(t.n[k].is_none());
                CHECK(t.is_subsegment(k));
            } else {
                REQUIRE(!t.n[k].is_none());
                CHECK(index(t.n[k].triangle()) == number[index(o.n[k].triangle())]);
                CHECK(t.n[k].edge() == o.n[k].edge());
                CHECK(!t.is_subsegment(k));
            }
        }
    }

    CHECK(report.boundary_edges == count_hull_edges(original));
    CHECK(mesh.subsegments().size() == report.boundary_edges);
    mesh.subsegments().for_each([&](VertexId, VertexId, const SubsegmentInfo& info) {
        CHECK(info.marker == 1);
        CHECK(info.segment == SubsegmentInfo::no_segment);
    });
    CHECK(report.unused_vertices == 0);
    REQUIRE(report.attributes.size() >= attributes.size());
    CHECK(std::equal(attributes.begin(), attributes.end(), report.attributes.begin()));
    CHECK(report.attributes.size() == std::size_t{mesh.triangle_end()} * 2);
}

TEST_CASE("from_triangles flags segments that are mesh edges", "[triangulate][from_triangles]") {
    // Segments: an interior edge (marker 7), a boundary edge with marker 0
    // (becomes 1), a boundary edge with marker 5, a repeat of the first
    // (reversed), a degenerate one, one that is not an edge (0-2, a
    // diagonal through the centre, inserted as 0-4 and 4-2).
    const std::vector<std::uint32_t> segments{4, 1, 0, 1, 2, 1, 1, 4, 3, 3, 0, 2};
    const std::vector<int> markers{7, 0, 5, 9, 2, 3};
    TriangleMeshInput in;
    in.points = square_points;
    in.corners = square_corners;
    in.segments = segments;
    in.segment_markers = markers;
    TriangleMeshReport report;
    const Mesh mesh = from_triangles(in, report);
    require_valid(mesh);
    CHECK(check_mesh(mesh).empty());

    CHECK(report.segments_flagged == 3);
    CHECK(report.segments_repeated == 1);
    CHECK(report.segments_degenerate == 1);
    CHECK(report.missing_segments == std::vector<std::uint32_t>{5});
    CHECK(report.segments_inserted == 1);
    REQUIRE(report.segment_events.size() == 1);
    CHECK(report.segment_events[0].kind == triangulate::SegmentEvent::Kind::through_vertex);
    CHECK(report.segment_events[0].vertex == VertexId{4});
    CHECK(report.boundary_edges == 4);
    CHECK(mesh.subsegments().size() == 7);  // 4 boundary edges + 1-4 + 0-4 + 4-2
    CHECK(*mesh.subsegments().find(VertexId{0}, VertexId{4}) == SubsegmentInfo{3, 5});
    CHECK(*mesh.subsegments().find(VertexId{4}, VertexId{2}) == SubsegmentInfo{3, 5});

    const auto* interior = mesh.subsegments().find(VertexId{1}, VertexId{4});
    REQUIRE(interior);
    CHECK(*interior == SubsegmentInfo{7, 0});
    CHECK(*mesh.subsegments().find(VertexId{0}, VertexId{1}) == SubsegmentInfo{1, 1});
    CHECK(*mesh.subsegments().find(VertexId{1}, VertexId{2}) == SubsegmentInfo{5, 2});
    CHECK(*mesh.subsegments().find(VertexId{2}, VertexId{3}) ==
          SubsegmentInfo{1, SubsegmentInfo::no_segment});
    // Both sides of the interior segment carry the flag.
    const EdgeRef e = edge_of(mesh, TriangleId{0}, 1, 4);
    REQUIRE(!e.is_none());
    CHECK(mesh.triangle(e.triangle()).is_subsegment(e.edge()));
    const EdgeRef f = mesh.neighbour(e);
    REQUIRE(!f.is_none());
    CHECK(mesh.triangle(f.triangle()).is_subsegment(f.edge()));
    // The other interior edges are not subsegments.
    const EdgeRef g = edge_of(mesh, TriangleId{2}, 3, 4);
    REQUIRE(!g.is_none());
    CHECK(!mesh.triangle(g.triangle()).is_subsegment(g.edge()));
}

TEST_CASE("from_triangles inserts a segment that crosses triangles",
          "[triangulate][from_triangles]") {
    // A row of three unit squares, each split by its rising diagonal; the
    // segment 0-7 from the bottom-left to the top-right corner crosses
    // them all.  Attributes: 10 + the triangle's index.
    const std::vector<Point> p{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {0, 1}, {1, 1}, {2, 1}, {3, 1}};
    const std::vector<std::uint32_t> c{0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6};
    std::vector<double> attributes{10, 11, 12, 13, 14, 15};
    const std::vector<std::uint32_t> segments{0, 7};
    TriangleMeshInput in;
    in.points = p;
    in.corners = c;
    in.attributes = attributes;
    in.attribute_count = 1;
    in.segments = segments;
    TriangleMeshReport report;
    const Mesh mesh = from_triangles(in, report);
    require_valid(mesh);
    CHECK(report.segments_inserted == 1);
    CHECK(report.segment_events.empty());
    CHECK(mesh.subsegments().find(VertexId{0}, VertexId{7}));
    CHECK(*mesh.subsegments().find(VertexId{0}, VertexId{7}) == SubsegmentInfo{0, 0});
    CHECK(mesh.count_triangles() == 6);
    // Every live triangle has one of the input attribute values.
    for_each_triangle(mesh, [&](TriangleId id, const Triangle&) {
        const double a = report.attributes[index(id)];
        CHECK(a >= 10);
        CHECK(a <= 15);
    });
}

TEST_CASE("from_triangles refuses a segment that leaves the mesh",
          "[triangulate][from_triangles]") {
    // Two triangles forming a non-convex L-ish shape; segment 1-3 runs
    // outside across the notch.
    const std::vector<Point> p{{0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}};
    const std::vector<std::uint32_t> c{0, 1, 2, 0, 2, 4, 2, 3, 4};
    const std::vector<std::uint32_t> segments{1, 3};
    TriangleMeshInput in;
    in.points = p;
    in.corners = c;
    in.segments = segments;
    const std::string error = error_of(in);
    CHECK_THAT(error, Catch::Contains("segment 0 (1-3) is not an edge of the mesh and cannot be "
                                      "inserted: segment"));
    CHECK_THAT(error, Catch::Contains("leaves the triangulated region"));
}

TEST_CASE("from_triangles accepts non-Delaunay meshes, holes and unused vertices",
          "[triangulate][from_triangles]") {
    // A square split by the "wrong" diagonal of a flat quadrilateral (not
    // Delaunay), plus an unused vertex; and a ring with a hole.
    SECTION("not Delaunay") {
        const std::vector<Point> p{{0, 0}, {4, -1}, {8, 0}, {4, 1}, {100, 100}};
        const std::vector<std::uint32_t> c{0, 1, 2, 0, 2, 3};
        TriangleMeshInput in;
        in.points = p;
        in.corners = c;
        TriangleMeshReport report;
        const Mesh mesh = from_triangles(in, report);
        require_valid(mesh);
        CHECK(!check_mesh(mesh).empty());  // edge 0-2 is not locally Delaunay
        CHECK(report.unused_vertices == 1);
        CHECK(report.boundary_edges == 4);
    }
    SECTION("a ring around a square hole") {
        // Outer square 0..3, inner square 4..7, eight triangles between.
        const std::vector<Point> p{{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
        const std::vector<std::uint32_t> c{0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5,
                                           2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
        TriangleMeshInput in;
        in.points = p;
        in.corners = c;
        TriangleMeshReport report;
        const Mesh mesh = from_triangles(in, report);
        require_valid(mesh);
        CHECK(report.boundary_edges == 8);
        CHECK(mesh.subsegments().find(VertexId{4}, VertexId{5}));
        CHECK(mesh.subsegments().find(VertexId{3}, VertexId{0}));
    }
}

TEST_CASE("from_triangles refuses broken meshes, naming the triangle",
          "[triangulate][from_triangles]") {
    TriangleMeshInput in;
    in.points = square_points;
    in.index_base = 1;

    SECTION("clockwise triangle") {
        const std::vector<std::uint32_t> c{0, 1, 4, 1, 4, 2, 2, 3, 4, 3, 0, 4};
        in.corners = c;
        const std::string what = error_of(in);
        CHECK_THAT(what, Catch::Contains("triangle 2 (corners 2, 5, 3) is clockwise"));
    }
    SECTION("zero area") {
        const std::vector<Point> p{{0, 0}, {1, 0}, {2, 0}, {0, 1}};
        const std::vector<std::uint32_t> c{0, 1, 3, 0, 1, 2};
        in.points = p;
        in.corners = c;
        CHECK_THAT(error_of(in), Catch::Contains("triangle 2 (corners 1, 2, 3) has zero area"));
    }
    SECTION("repeated corner") {
        const std::vector<std::uint32_t> c{0, 1, 4, 2, 2, 4};
        in.corners = c;
        CHECK_THAT(error_of(in),
                   Catch::Contains("triangle 2") && Catch::Contains("repeats a vertex"));
    }
    SECTION("corner out of range (the reader's job, but never a crash)") {
        const std::vector<std::uint32_t> c{0, 1, 9};
        in.corners = c;
        CHECK_THAT(error_of(in), Catch::Contains("names vertex 10"));
    }
    SECTION("an edge in three triangles") {
        // Triangles on edge 0-1: (0,1,4) above, and two more: (1,0,5) and
        // (1,0,6) below; all counter-clockwise.
        const std::vector<Point> p{{0, 0},     {1, 0},    {1, 1},   {0, 1},
                                   {0.5, 0.5}, {0.5, -1}, {0.3, -2}};
        const std::vector<std::uint32_t> c{0, 1, 4, 1, 0, 5, 1, 0, 6};
        in.points = p;
        in.corners = c;
        const std::string what = error_of(in);
        CHECK_THAT(what, Catch::Contains("edge 1-2 is shared by 3 triangles"));
        CHECK_THAT(what, Catch::Contains("triangle 3 (corners 2, 1, 7)"));
    }
    SECTION("two triangles on the same side of an edge") {
        const std::vector<Point> p{{0, 0}, {1, 0}, {0.5, 1}, {0.6, 2}};
        const std::vector<std::uint32_t> c{0, 1, 2, 0, 1, 3};
        in.points = p;
        in.corners = c;
        CHECK_THAT(
            error_of(in),
            Catch::Contains("triangle 1 (corners 1, 2, 3) and triangle 2 (corners 1, 2, 4)") &&
                Catch::Contains("same side"));
    }
    SECTION("a star that winds twice around its vertex") {
        // Vertex 0 at the origin, vertices 1..5 on the unit circle 144
        // degrees apart: five counter-clockwise triangles (0, i, i+1) close
        // up after two full turns (a pentagram).
        std::vector<Point> p{{0, 0}};
        for (int i = 0; i < 5; ++i) {
            const double a = 144.0 * i * std::acos(-1.0) / 180.0;
            p.push_back({std::cos(a), std::sin(a)});
        }
        std::vector<std::uint32_t> c;
        for (std::uint32_t i = 0; i < 5; ++i) c.insert(c.end(), {0u, 1 + i, 1 + (i + 1) % 5});
        in.points = p;
        in.corners = c;
        in.index_base = 0;
        CHECK_THAT(error_of(in), Catch::Contains("around vertex 0 turn around it 2 times"));
    }
    SECTION("no triangles") {
        in.corners = {};
        CHECK_THAT(error_of(in), Catch::Contains("no triangles"));
    }
}

TEST_CASE("from_triangles: the star check accepts stars split at angle zero",
          "[triangulate][from_triangles]") {
    // Vertices exactly on the positive and negative x rays from the centre
    // (the boundary cases of the winding count) and a fan of eight.
    std::vector<Point> p{{0, 0}};
    for (int i = 0; i < 8; ++i) {
        const double c[8][2] = {{1, 0},  {1, 1},   {0, 1},  {-1, 1},
                                {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
        p.push_back({c[i][0], c[i][1]});
    }
    std::vector<std::uint32_t> c;
    for (std::uint32_t i = 0; i < 8; ++i) c.insert(c.end(), {0u, 1 + i, 1 + (i + 1) % 8});
    TriangleMeshInput in;
    in.points = p;
    in.corners = c;
    TriangleMeshReport report;
    const Mesh mesh = from_triangles(in, report);
    require_valid(mesh);
    CHECK(report.boundary_edges == 8);
}

TEST_CASE("benchmark: from_triangles on the Delaunay mesh of 5 million points",
          "[.bench][triangulate]") {
    const auto points = uniform_points(5'000'000, 7);
    triangulate::DelaunayReport dreport;
    std::vector<std::uint32_t> corners;
    {
        const Mesh original = triangulate::delaunay(points, dreport);
        corners = corner_list(original);
    }
    TriangleMeshInput in;
    in.points = points;
    in.corners = corners;
    TriangleMeshReport report;
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    const Mesh mesh = from_triangles(in, report);
    const double seconds = std::chrono::duration<double>(clock::now() - t0).count();
    std::printf(
        "from_triangles: %zu vertices, %zu triangles in %.3f s (%.1f M triangles/s), %zu boundary "
        "edges\n",
        points.size(), corners.size() / 3, seconds, double(corners.size() / 3) / seconds / 1e6,
        report.boundary_edges);
    CHECK(mesh.count_triangles() == corners.size() / 3);
}
