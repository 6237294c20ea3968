// Carving the domain: holes, the exterior (concavities), -c, -O and regions.

#include <catch2/catch.hpp>

#include "triangulate/cdt_support.hpp"
#include "triangulate/domain.hpp"

using namespace gpdr;
using namespace gpdr::triangulate;
using namespace gpdr::triangulate::testing;
using gpdr::mesh::Mesh;

namespace {

geometry::Point centroid(const Mesh& m, const gpdr::mesh::Triangle& t) {
    const auto& a = m.point(t.v[0]);
    const auto& b = m.point(t.v[1]);
    const auto& c = m.point(t.v[2]);
    return {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
}

// Outer square [0, 3]^2 (vertices 0-3), inner square [1, 2]^2 (4-7), all
// sides segments.
Pslg square_with_square(std::vector<geometry::Point> holes) {
    return make_pslg({{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}},
                     {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4}, std::move(holes));
}

bool inside_inner(const geometry::Point& p) { return p.x > 1 && p.x < 2 && p.y > 1 && p.y < 2; }

}  // namespace

TEST_CASE("a square hole eats exactly the triangles inside it", "[triangulate][domain]") {
    const Pslg pslg = square_with_square({{1.5, 1.5}});
    CdtReport report;
    const Mesh m = constrained_delaunay(pslg, {}, report);
    require_valid(m, pslg, report);
    // A polygon with 8 vertices and one hole: 8 + 2*1 - 2 triangles.
    CHECK(m.count_triangles() == 8);
    gpdr::mesh::for_each_triangle(m, [&](gpdr::mesh::TriangleId, const gpdr::mesh::Triangle& t) {
        CHECK_FALSE(inside_inner(centroid(m, t)));
    });
    CHECK(m.subsegments().size() == 8);
    CHECK(gpdr::mesh::count_hull_edges(m) == 8);
}

TEST_CASE("switch -O ignores the holes", "[triangulate][domain]") {
    const Pslg pslg = square_with_square({{1.5, 1.5}});
    CdtReport report;
    CdtOptions options;
    options.ignore_holes = true;
    const Mesh m = constrained_delaunay(pslg, options, report);
    require_valid(m, pslg, report);
    CHECK(m.count_triangles() == 10);
}

TEST_CASE("hole points outside the mesh or on a segment do nothing", "[triangulate][domain]") {
    const Pslg pslg = square_with_square({{5, 5}, {1.5, 1}, {-1, 1.5}});
    CdtReport report;
    const Mesh m = constrained_delaunay(pslg, {}, report);
    require_valid(m, pslg, report);
    CHECK(m.count_triangles() == 10);
}

TEST_CASE("segments inside a hole leave the side table", "[triangulate][domain]") {
    Pslg pslg = square_with_square({{1.2, 1.5}});
    pslg.points.push_back({1.5, 1.2});
    pslg.points.push_back({1.5, 1.8});
    pslg.segments.insert(pslg.segments.end(), {8, 9});  // a dangling segment in the hole
    CdtReport report;
    const Mesh m = constrained_delaunay(pslg, {}, report);
    require_valid(m, pslg, report);
    CHECK(m.count_triangles() == 8);
    CHECK(m.subsegments().size() == 8);
}

TEST_CASE("without -c the concavities are removed; with -c the hull is kept and flagged",
          "[triangulate][domain]") {
    // An L: the notch corner (1, 1) is inside the hull.
    const Pslg pslg = make_pslg({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}},
                                {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0});
    CdtReport report;
    const Mesh m = constrained_delaunay(pslg, {}, report);
    require_valid(m, pslg, report);
    CHECK(m.count_triangles() == 4);
    CHECK(m.subsegments().size() == 6);

    CdtOptions hull;
    hull.convex_hull = true;
    const Mesh h = constrained_delaunay(pslg, hull, report);
    require_valid(h, pslg, report);
    CHECK(h.count_triangles() == 5);  // 2n - 2 - (hull vertices) = 12 - 2 - 5
    CHECK(h.subsegments().size() == 7);
    const auto* closing = h.subsegments().find(gpdr::mesh::VertexId{2}, gpdr::mesh::VertexId{4});
    REQUIRE(closing != nullptr);
    CHECK(closing->marker == 1);
    CHECK(closing->segment == gpdr::mesh::SubsegmentInfo::no_segment);
    gpdr::mesh::for_each_hull_edge(h, [&](const gpdr::mesh::EdgeView& e) { CHECK(e.subsegment); });
}

TEST_CASE("a PSLG without any closed boundary is eaten entirely without -c",
          "[triangulate][domain]") {
    const Pslg pslg = make_pslg({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {0, 2});
    CdtReport report;
    const Mesh m = constrained_delaunay(pslg, {}, report);
    CHECK(m.count_triangles() == 0);
    CHECK(m.subsegments().size() == 0);
    CHECK(gpdr::mesh::check_mesh(m).empty());
}

TEST_CASE("nested regions; later regions overwrite earlier ones", "[triangulate][domain]") {
    Pslg pslg = square_with_square({});
    pslg.regions = {Region{0.5, 0.5, 10, -1}, Region{1.5, 1.5, 20, -1}};
    CdtReport report;
    SECTION("each region gets its index + 1") {
        const Mesh m = constrained_delaunay(pslg, {}, report);
        require_valid(m, pslg, report);
        gpdr::mesh::for_each_triangle(m,
                                      [&](gpdr::mesh::TriangleId, const gpdr::mesh::Triangle& t) {
                                          CHECK(t.region == (inside_inner(centroid(m, t)) ? 2 : 1));
                                      });
    }
    SECTION("an overlapping later region wins") {
        pslg.regions.push_back(Region{1.6, 1.4, 30, -1});
        const Mesh m = constrained_delaunay(pslg, {}, report);
        gpdr::mesh::for_each_triangle(m,
                                      [&](gpdr::mesh::TriangleId, const gpdr::mesh::Triangle& t) {
                                          CHECK(t.region == (inside_inner(centroid(m, t)) ? 3 : 1));
                                      });
    }
    SECTION("a region point in a hole marks nothing") {
        pslg.holes = {{1.5, 1.5}};
        const Mesh m = constrained_delaunay(pslg, {}, report);
        CHECK(m.count_triangles() == 8);
        gpdr::mesh::for_each_triangle(
            m,
            [&](gpdr::mesh::TriangleId, const gpdr::mesh::Triangle& t) { CHECK(t.region == 1); });
    }
    SECTION("no region: 0") {
        pslg.regions.clear();
        const Mesh m = constrained_delaunay(pslg, {}, report);
        gpdr::mesh::for_each_triangle(
            m,
            [&](gpdr::mesh::TriangleId, const gpdr::mesh::Triangle& t) { CHECK(t.region == 0); });
    }
}

TEST_CASE("random soups carved: valid and conforming", "[triangulate][domain][random]") {
    std::mt19937_64 rng(777);
    for (int round = 0; round < 150; ++round) {
        Pslg pslg = random_pslg(rng, 10 + rng() % 30, 3 + rng() % 12, false);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        pslg.holes = {{u(rng), u(rng)}};
        pslg.regions = {Region{u(rng), u(rng), 1, -1}};
        CdtOptions options;
        options.convex_hull = round % 2 == 0;
        CdtReport report;
        const Mesh m = constrained_delaunay(pslg, options, report);
        INFO("round " << round);
        require_valid(m, pslg, report);
    }
}
