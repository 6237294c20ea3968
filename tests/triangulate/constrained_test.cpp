// Segment insertion and subsegment splitting: hand-made PSLGs for each case
// of constrained.hpp, and random segment soups (crossings, vertices on
// segments, overlaps) checked by check_mesh and the conformity check.

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include <gpdr/errors.hpp>

#include "geometry/constructions.hpp"
#include "mesh/split_subsegment.hpp"
#include "mesh/test_support.hpp"
#include "triangulate/cdt_support.hpp"
#include "triangulate/delaunay.hpp"

using namespace gpdr;
using namespace gpdr::triangulate;
using namespace gpdr::triangulate::testing;
using gpdr::mesh::Mesh;

TEST_CASE("a segment that is not a Delaunay edge is forced in", "[triangulate][cdt]") {
    // Delaunay joins 2-3 (the short diagonal); the segment 0-1 replaces it.
    const Pslg pslg = make_pslg({{0, 0}, {2, 0}, {1, 0.3}, {1, -0.3}}, {0, 1});
    CdtReport report;
    const Mesh m = triangulate_segments(pslg, report);
    require_valid(m, pslg, report);
    CHECK(m.count_triangles() == 2);
    CHECK(has_subsegment(m, 0, 1));
    CHECK_FALSE(has_edge(m, 2, 3));
    const auto* info = m.subsegments().find(VertexId{0}, VertexId{1});
    REQUIRE(info != nullptr);
    CHECK(info->segment == 0);
    CHECK(m.subsegments().size() == 1);
}

TEST_CASE("a long segment through a cloud of points", "[triangulate][cdt]") {
    auto points = gpdr::mesh::testing::uniform_points(400, 7);
    points.push_back({-0.1, 0.31});
    points.push_back({1.1, 0.77});
    const auto n = static_cast<std::uint32_t>(points.size());
    Pslg pslg = make_pslg(points, {n - 2, n - 1});
    CdtReport report;
    const Mesh m = triangulate_segments(pslg, report);
    require_valid(m, pslg, report);
    CHECK(report.new_vertices.empty());
    CHECK(m.subsegments().size() >= 1);
}

TEST_CASE("two crossing segments are both split at the crossing", "[triangulate][cdt]") {
    // Unit square with its two diagonals (and its sides as segments).
    const Pslg pslg =
        make_pslg({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {0, 2, 1, 3, 0, 1, 1, 2, 2, 3, 3, 0});
    CdtReport report;
    const Mesh m = constrained_delaunay(pslg, {}, report);
    require_valid(m, pslg, report);
    REQUIRE(report.new_vertices.size() == 1);
    const NewSegmentVertex& nv = report.new_vertices[0];
    CHECK(index(nv.vertex) == 4);
    // A crossing is a vertex of the input from then on, as in Triangle.
    CHECK(m.kind(nv.vertex) == gpdr::mesh::VertexKind::input);
    CHECK(m.point(nv.vertex).x == Approx(0.5));
    CHECK(m.point(nv.vertex).y == Approx(0.5));
    CHECK(nv.segment == 1);
    CHECK(nv.t == Approx(0.5));
    CHECK(nv.other_segment == 0);
    CHECK(nv.other_t == Approx(0.5));
    CHECK(m.count_triangles() == 4);
    CHECK(m.subsegments().size() == 8);
    for (std::uint32_t c = 0; c < 4; ++c) CHECK(has_subsegment(m, c, 4));
    // Subsegments name the pieces the segments were cut into.
    auto segment_of = [&](std::uint32_t a, std::uint32_t b) {
        return report.pieces[m.subsegments().find(VertexId{a}, VertexId{b})->segment].segment;
    };
    CHECK(segment_of(0, 4) == 0);
    CHECK(segment_of(4, 2) == 0);
    CHECK(segment_of(1, 4) == 1);
    CHECK(segment_of(4, 3) == 1);
    CHECK(report.pieces.size() == 8);
}

TEST_CASE("a star of segments through one point", "[triangulate][cdt]") {
    // The diagonals and midlines of [0,2]^2 all cross at (1, 1): one new
    // vertex, where all four segments are cut.
    const Pslg pslg = make_pslg({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 0}, {1, 2}, {0, 1}, {2, 1}},
                                {0, 2, 1, 3, 4, 5, 6, 7});
    CdtReport report;
    const Mesh m = triangulate_segments(pslg, report);
    require_valid(m, pslg, report);
    REQUIRE(report.new_vertices.size() == 1);
    const VertexId centre = report.new_vertices[0].vertex;
    CHECK(m.point(centre) == geometry::Point{1, 1});
    CHECK(report.segments_through_vertices.empty());
    for (std::uint32_t v = 0; v < 8; ++v) CHECK(has_subsegment(m, v, index(centre)));
    CHECK(m.subsegments().size() == 8);
}

TEST_CASE("a star of segments crossing near one point", "[triangulate][cdt]") {
    // Six diameters of a circle whose ends are rounded: they pass within
    // rounding of the centre, and their crossings there are one vertex (a
    // cluster of near-coincident crossings would leave slivers no
    // refinement can remove).
    std::vector<geometry::Point> pts;
    std::vector<std::uint32_t> segs;
    for (int i = 0; i < 12; ++i) {
        const double a = 2 * M_PI * i / 12 + 0.01;
        pts.push_back({std::cos(a), std::sin(a)});
    }
    for (std::uint32_t i = 0; i < 6; ++i) segs.insert(segs.end(), {i, i + 6});
    const Pslg pslg = make_pslg(pts, segs);
    CdtReport report;
    const Mesh m = triangulate_segments(pslg, report);
    require_valid(m, pslg, report);
    REQUIRE(report.new_vertices.size() == 1);
    const VertexId centre = report.new_vertices[0].vertex;
    CHECK(std::hypot(m.point(centre).x, m.point(centre).y) < 1e-15);
    for (std::uint32_t v = 0; v < 12; ++v) CHECK(has_subsegment(m, v, index(centre)));
}

TEST_CASE("a segment through an input vertex is split there", "[triangulate][cdt]") {
    const Pslg pslg = make_pslg({{0, 0}, {2, 0}, {1, 0}, {1, 1}, {1, -1}}, {0, 1});
    CdtReport report;
    const Mesh m = triangulate_segments(pslg, report);
    require_valid(m, pslg, report);
    REQUIRE(report.segments_through_vertices.size() == 1);
    CHECK(report.segments_through_vertices[0] ==
          std::pair<std::uint32_t, VertexId>{0, VertexId{2}});
    CHECK(has_subsegment(m, 0, 2));
    CHECK(has_subsegment(m, 2, 1));
    CHECK(m.subsegments().size() == 2);
    CHECK(report.new_vertices.empty());
}

TEST_CASE("a segment through a vertex found while walking", "[triangulate][cdt]") {
    // Vertex 2 lies on 0-1 but is not a neighbour of 0: the walk meets it.
    const Pslg pslg =
        make_pslg({{0, 0}, {4, 0}, {3, 0}, {1, 0.2}, {1, -0.2}, {2, 0.1}, {2, -0.1}}, {0, 1});
    CdtReport report;
    const Mesh m = triangulate_segments(pslg, report);
    require_valid(m, pslg, report);
    REQUIRE(report.segments_through_vertices.size() == 1);
    CHECK(report.segments_through_vertices[0].second == VertexId{2});
    CHECK(has_subsegment(m, 0, 2));
    CHECK(has_subsegment(m, 2, 1));
}

TEST_CASE("duplicate and zero-length segments are skipped and reported", "[triangulate][cdt]") {
    // Vertex 4 duplicates vertex 0, so segment 4-0 has zero length.
    const Pslg pslg =
        make_pslg({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}, {0, 1, 1, 0, 2, 2, 0, 1, 4, 0, 4, 2});
    CdtReport report;
    const Mesh m = triangulate_segments(pslg, report);
    require_valid(m, pslg, report);
    CHECK(report.duplicate_vertices ==
          std::vector<std::pair<std::uint32_t, std::uint32_t>>{{4, 0}});
    CHECK(report.zero_length_segments == std::vector<std::uint32_t>{2, 4});
    CHECK(report.duplicate_segments ==
          std::vector<std::pair<std::uint32_t, std::uint32_t>>{{1, 0}, {3, 0}});
    CHECK(report.skipped == std::vector<bool>{false, true, true, true, true, false});
    // Segment 5 (4-2) is attached to the kept vertex 0.
    CHECK(has_subsegment(m, 0, 2));
    CHECK(m.subsegments().size() == 2);
}

TEST_CASE("collinear overlapping segments share subsegments", "[triangulate][cdt]") {
    // 0 --- 2 ===== 1 --- 3 on the x axis; segment 0-1 and 2-3 overlap on 2-1.
    Pslg pslg = make_pslg({{0, 0}, {3, 0}, {1, 0}, {4, 0}, {2, 1}, {2, -1}}, {0, 1, 2, 3});
    pslg.segment_markers = {5, 7};
    CdtReport report;
    const Mesh m = triangulate_segments(pslg, report);
    require_valid(m, pslg, report);
    CHECK(has_subsegment(m, 0, 2));
    CHECK(has_subsegment(m, 2, 1));
    CHECK(has_subsegment(m, 1, 3));
    CHECK(m.subsegments().size() == 3);
    CHECK(m.subsegments().find(VertexId{2}, VertexId{1})->marker == 5);
    CHECK(m.subsegments().find(VertexId{1}, VertexId{3})->marker == 7);
    CHECK(report.segments_through_vertices.size() == 2);
}

TEST_CASE("a zero marker is replaced by a later segment's marker", "[triangulate][cdt]") {
    Pslg pslg = make_pslg({{0, 0}, {1, 0}, {0, 1}}, {0, 1, 2, 0, 0, 2});
    pslg.segments = {0, 1, 0, 2};
    pslg.segment_markers = {0, 3};
    pslg.points.push_back({0, 0.5});  // vertex 3 on segment 0-2
    pslg.segments.insert(pslg.segments.end(), {3, 0});
    pslg.segment_markers.push_back(9);
    CdtReport report;
    const Mesh m = triangulate_segments(pslg, report);
    require_valid(m, pslg, report);
    // 0-3 came from segment 1 with marker 3, which is kept over 9.
    CHECK(m.subsegments().find(VertexId{0}, VertexId{3})->marker == 3);
}

TEST_CASE("bad segment lists are refused", "[triangulate][cdt]") {
    CdtReport report;
    CHECK_THROWS_AS(triangulate_segments(make_pslg({{0, 0}, {1, 0}, {0, 1}}, {0, 3}), report),
                    GeometryError);
    Pslg p = make_pslg({{0, 0}, {1, 0}, {0, 1}}, {0, 1});
    p.segment_markers = {1, 2};
    CHECK_THROWS_AS(triangulate_segments(p, report), GeometryError);
}

TEST_CASE("split_subsegment keeps the halves flagged and their entries", "[mesh][cdt]") {
    // Two triangles sharing subsegment 0-1, and a hull subsegment 1-2.
    const Pslg pslg = make_pslg({{0, 0}, {2, 0}, {1, 1}, {1, -1}}, {0, 1, 1, 2});
    CdtReport report;
    Mesh m = triangulate_segments(pslg, report);
    gpdr::mesh::Pool pool(m);
    gpdr::mesh::InsertBuffer buffer;
    auto edge_between = [&](std::uint32_t a, std::uint32_t b) {
        gpdr::mesh::EdgeRef found;
        gpdr::mesh::for_each_edge(m, [&](const gpdr::mesh::EdgeView& e) {
            if ((index(e.from) == a && index(e.to) == b) ||
                (index(e.from) == b && index(e.to) == a))
                found = e.edge;
        });
        return found;
    };
    SECTION("interior subsegment, a point off the line by rounding") {
        const auto r = gpdr::mesh::split_subsegment(pool, edge_between(0, 1), {1, 1e-17},
                                                    gpdr::mesh::VertexKind::segment, buffer);
        REQUIRE(r.status == gpdr::mesh::InsertStatus::inserted);
        const std::uint32_t p = index(r.vertex);
        CHECK(has_subsegment(m, 0, p));
        CHECK(has_subsegment(m, p, 1));
        CHECK_FALSE(has_edge(m, 0, 1));
        CHECK(m.subsegments().find(VertexId{0}, r.vertex)->segment == 0);
        CHECK(m.subsegments().find(r.vertex, VertexId{1})->segment == 0);
        CHECK(buffer.created.size() == 4);
        CHECK(m.count_triangles() == 4);
    }
    SECTION("hull subsegment") {
        const auto r = gpdr::mesh::split_subsegment(pool, edge_between(1, 2), {1.5, 0.5},
                                                    gpdr::mesh::VertexKind::segment, buffer);
        REQUIRE(r.status == gpdr::mesh::InsertStatus::inserted);
        CHECK(has_subsegment(m, 1, index(r.vertex)));
        CHECK(has_subsegment(m, index(r.vertex), 2));
        CHECK(m.subsegments().find(VertexId{1}, r.vertex)->segment == 1);
        CHECK(m.count_triangles() == 3);
    }
    SECTION("a point outside both triangles is pulled inside") {
        const auto r = gpdr::mesh::split_subsegment(pool, edge_between(0, 1), {1, 5},
                                                    gpdr::mesh::VertexKind::segment, buffer);
        REQUIRE(r.status == gpdr::mesh::InsertStatus::inserted);
        CHECK(std::abs(m.point(r.vertex).y) < 1);
    }
    const auto problems = gpdr::mesh::check_mesh(m);
    INFO(joined(problems));
    CHECK(problems.empty());
}

TEST_CASE("split_subsegment on a fine mesh grows a Bowyer-Watson cavity", "[mesh][cdt]") {
    auto points = gpdr::mesh::testing::uniform_points(300, 11);
    points.push_back({0.0, 0.5});
    points.push_back({1.0, 0.5});
    const auto n = static_cast<std::uint32_t>(points.size());
    const Pslg pslg = make_pslg(points, {n - 2, n - 1});
    CdtReport report;
    Mesh m = triangulate_segments(pslg, report);
    gpdr::mesh::Pool pool(m);
    gpdr::mesh::InsertBuffer buffer;
    std::mt19937_64 rng(3);
    for (int k = 0; k < 50; ++k) {
        // Split a random subsegment at a random point of it.
        std::vector<gpdr::mesh::EdgeRef> subs;
        gpdr::mesh::for_each_edge(m, [&](const gpdr::mesh::EdgeView& e) {
            if (e.subsegment) subs.push_back(e.edge);
        });
        const auto e = subs[rng() % subs.size()];
        const auto& a = m.point(m.origin(e));
        const auto& b = m.point(m.destination(e));
        const double t = 0.2 + 0.6 * double(rng() % 1000) / 1000.0;
        buffer.created.clear();
        gpdr::mesh::split_subsegment(pool, e, geometry::point_on_segment(a, b, t),
                                     gpdr::mesh::VertexKind::segment, buffer);
        const auto problems = gpdr::mesh::check_mesh(m);
        INFO(joined(problems));
        REQUIRE(problems.empty());
    }
    CHECK(m.subsegments().size() == 51);
}

TEST_CASE("random segment soups: every result is a valid CDT that conforms",
          "[triangulate][cdt][random]") {
    std::mt19937_64 rng(12345);
    int cases = 0;
    for (int round = 0; round < 300; ++round) {
        const bool grid = round % 2 == 1;
        const std::size_t points = 5 + rng() % 40;
        const std::size_t segments = 1 + rng() % 15;
        const Pslg pslg = random_pslg(rng, points, segments, grid);
        CdtReport report;
        Mesh m;
        try {
            m = triangulate_segments(pslg, report);
        } catch (const GeometryError&) {
            continue;  // all points collinear: not a CDT case
        }
        INFO("round " << round);
        require_valid(m, pslg, report);
        for (const auto& nv : report.new_vertices) {
            CHECK(nv.t > 0);
            CHECK(nv.t < 1);
        }
        ++cases;
    }
    CHECK(cases > 250);
}

TEST_CASE("random long segments with many crossings", "[triangulate][cdt][random]") {
    std::mt19937_64 rng(99);
    for (int round = 0; round < 20; ++round) {
        Pslg pslg = random_pslg(rng, 200, 60, false);
        CdtReport report;
        const Mesh m = triangulate_segments(pslg, report);
        INFO("round " << round);
        require_valid(m, pslg, report);
        CHECK(!report.new_vertices.empty());
    }
}

TEST_CASE("benchmark: CDT of a 1-million-segment star polygon with islands",
          "[.bench][triangulate][cdt]") {
    // A star-shaped polygon (random radius per angle step) and 1000 small
    // square islands inside it: the radii jitter, so most segments are not
    // Delaunay edges of the points and must be forced in.
    const std::uint32_t n = 1'000'000;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> radius(0.7, 1.0);
    Pslg pslg;
    for (std::uint32_t i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n;
        const double r = radius(rng) * 100;
        pslg.points.push_back({r * std::cos(a), r * std::sin(a)});
        pslg.segments.insert(pslg.segments.end(), {i, (i + 1) % n});
    }
    for (int k = 0; k < 1000; ++k) {
        const double cx = -40 + 80 * double(k % 32) / 32, cy = -40 + 80 * double(k / 32) / 32,
                     h = 0.5;
        const auto base = static_cast<std::uint32_t>(pslg.points.size());
        pslg.points.insert(
            pslg.points.end(),
            {{cx - h, cy - h}, {cx + h, cy - h}, {cx + h, cy + h}, {cx - h, cy + h}});
        for (std::uint32_t j = 0; j < 4; ++j)
            pslg.segments.insert(pslg.segments.end(), {base + j, base + (j + 1) % 4});
        pslg.holes.push_back({cx, cy});
    }
    using clock = std::chrono::steady_clock;
    CdtReport report;
    const auto t0 = clock::now();
    const Mesh m = constrained_delaunay(pslg, {}, report);
    const auto t1 = clock::now();
    std::printf("CDT of %zu vertices, %zu segments: %.3f s, %zu triangles, %zu subsegments\n",
                pslg.points.size(), pslg.segment_count(),
                std::chrono::duration<double>(t1 - t0).count(), m.count_triangles(),
                m.subsegments().size());
    CHECK(m.subsegments().size() == pslg.segment_count());
    CHECK(report.new_vertices.empty());
}
