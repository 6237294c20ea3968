// Refinement of PSLGs through the CDT: a square with a hole, a star of
// segments 3 degrees apart, two segments meeting at 1 degree, and the
// project's flow sample (the paper's Table 1 shape).

#include "refine_support.hpp"

namespace gpdr::refine::testing {

namespace {

triangulate::Pslg square_with_hole() {
    triangulate::Pslg p;
    p.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}};
    p.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
    p.holes = {{0.5, 0.5}};
    return p;
}

// A box around segments from the origin, `count` of them `step` degrees apart.
triangulate::Pslg star(int count, double step) {
    triangulate::Pslg p;
    p.points = {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}, {0, 0}};
    p.segments = {0, 1, 1, 2, 2, 3, 3, 0};
    for (int i = 0; i < count; ++i) {
        const double a = (10.0 + i * step) * std::numbers::pi / 180.0;
        p.points.push_back({1.5 * std::cos(a), 1.5 * std::sin(a)});
        p.segments.push_back(4);
        p.segments.push_back(static_cast<std::uint32_t>(p.points.size() - 1));
    }
    return p;
}

RefineReport refine(mesh::Mesh& m, RefineSettings& settings,
                    const std::vector<mesh::VertexId>& ends) {
    settings.segment_ends = ends;
    settings.checked = true;
    RefineReport report;
    refine_mesh(m, settings, report);
    return report;
}

}  // namespace

TEST_CASE("a square with a hole meets the bounds for every strategy", "[refine][pslg]") {
    const Placement placement =
        GENERATE(Placement::circumcentre, Placement::off_centre, Placement::optimisation);
    const double angle = GENERATE(0.0, 15.0, 25.0, 33.0);
    const double area = GENERATE(-1.0, 0.002);
    if (angle == 0 && area < 0) return;
    const auto pslg = square_with_hole();
    const auto ends = segment_ends(pslg);
    mesh::Mesh m = cdt(pslg);
    RefineSettings settings;
    settings.placement = placement;
    settings.criteria.min_angle_degrees = angle;
    settings.criteria.max_area = area;
    const RefineReport report = refine(m, settings, ends);
    INFO("placement " << int(placement) << " q" << angle << " a" << area);
    const Outcome o = examine(m, settings);
    CHECK(report.stopped == RefineReport::Stop::none);
    CHECK(o.bad_angles == 0);
    CHECK(o.too_big == 0);
    CHECK(report.left_other + report.left_precision + report.left_no_split == 0);
    CHECK(report.encroached_left == 0);
    // Nothing inside the hole.
    mesh::for_each_triangle(m, [&](mesh::TriangleId, const mesh::Triangle& t) {
        Point c{0, 0};
        for (auto v : t.v) c = {c.x + m.point(v).x / 3, c.y + m.point(v).y / 3};
        CHECK_FALSE((c.x > 0.4 && c.x < 0.6 && c.y > 0.4 && c.y < 0.6));
    });
}

TEST_CASE("small input angles terminate and only protected triangles stay skinny",
          "[refine][pslg]") {
    const bool with_ends = GENERATE(true, false);  // the chain walk when segment ends are not given
    const double angle = GENERATE(20.0, 30.0);
    SECTION("a star of segments 3 degrees apart") {
        const auto pslg = star(8, 3.0);
        const auto ends = with_ends ? segment_ends(pslg) : std::vector<mesh::VertexId>{};
        mesh::Mesh m = cdt(pslg);
        RefineSettings settings;
        settings.criteria.min_angle_degrees = angle;
        const RefineReport report = refine(m, settings, ends);
        const Outcome o = examine(m, settings);
        CHECK(report.stopped == RefineReport::Stop::none);
        CHECK(o.bad_angles == 0);
        INFO("precision " << report.left_precision << " no_split " << report.left_no_split
                          << " budget " << report.left_budget << " other " << report.left_other
                          << " steiner " << report.steiner_points << " smallest "
                          << o.smallest_angle);
        CHECK(report.left_small_input_angle > 0);
        CHECK(report.left_other == 0);
        CHECK(report.encroached_left == 0);
    }
    SECTION("two segments meeting at 1 degree") {
        const auto pslg = star(2, 1.0);
        const auto ends = with_ends ? segment_ends(pslg) : std::vector<mesh::VertexId>{};
        mesh::Mesh m = cdt(pslg);
        RefineSettings settings;
        settings.criteria.min_angle_degrees = angle;
        const RefineReport report = refine(m, settings, ends);
        const Outcome o = examine(m, settings);
        CHECK(report.stopped == RefineReport::Stop::none);
        CHECK(o.bad_angles == 0);
        INFO("precision " << report.left_precision << " no_split " << report.left_no_split
                          << " budget " << report.left_budget << " other " << report.left_other
                          << " steiner " << report.steiner_points << " smallest "
                          << o.smallest_angle);
        CHECK(report.left_small_input_angle > 0);
        CHECK(report.left_other == 0);
    }
}

TEST_CASE("Table 1 shape: off-centres give no more triangles than circumcentres",
          "[refine][pslg][table1]") {
    const std::string path = std::string(GPDR_SOURCE_DIR) + "/poly-samples/flow.poly";
    const auto pslg = read_poly(path);
    REQUIRE(pslg.points.size() > 100);
    const auto ends = segment_ends(pslg);
    const double angle = GENERATE(20.0, 30.0);
    std::size_t triangles[3] = {};
    for (Placement p : {Placement::circumcentre, Placement::off_centre, Placement::optimisation}) {
        mesh::Mesh m = cdt(pslg);
        RefineSettings settings;
        settings.placement = p;
        settings.criteria.min_angle_degrees = angle;
        const RefineReport report = refine(m, settings, ends);
        const Outcome o = examine(m, settings);
        CHECK(o.bad_angles == 0);
        CHECK(report.stopped == RefineReport::Stop::none);
        triangles[static_cast<int>(p)] = o.triangles;
    }
    INFO("q" << angle << ": circumcentre " << triangles[0] << ", off-centre " << triangles[1]
             << ", optimisation " << triangles[2]);
    CHECK(triangles[1] <= triangles[0]);
    // The optimisation method is reported, not asserted: within 3% of the
    // others here, sometimes above the circumcentre (the paper's Table 1
    // used Triangle's queue order; ours differs).
    WARN("flow q" << angle << ": circumcentre " << triangles[0] << ", off-centre " << triangles[1]
                  << ", optimisation " << triangles[2]);
}

}  // namespace gpdr::refine::testing

namespace gpdr::refine::testing {

// count_left outside checked mode reads the small-angle marks classification
// leaves and counts surviving give-ups instead of assessing every triangle
// again; both ways must give the same counts (the refinement itself is the
// same: checked mode only adds checks).
TEST_CASE("the final count from classification's marks equals assessing every triangle again",
          "[refine][pslg]") {
    struct Case {
        const char* name;
        triangulate::Pslg pslg;
        double angle, area;
        int no_segment_splitting;
    };
    const Case cases[] = {
        {"a star of segments 3 degrees apart, q30", star(8, 3.0), 30, 0, 0},
        {"two segments at 1 degree, q20 a0.01", star(2, 1.0), 20, 0.01, 0},
        {"a star with -Y (give-ups)", star(8, 3.0), 30, 0.05, 1},
        {"a square with a hole, q33 a0.001", square_with_hole(), 33, 0.001, 0},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        RefineReport reports[2];
        std::size_t triangles[2];
        for (int checked = 0; checked < 2; ++checked) {
            mesh::Mesh m = cdt(c.pslg);
            RefineSettings settings;
            settings.criteria.min_angle_degrees = c.angle;
            settings.criteria.max_area = c.area;
            settings.no_segment_splitting = c.no_segment_splitting;
            const auto ends = segment_ends(c.pslg);  // (settings only view it: kept alive here)
            settings.segment_ends = ends;
            settings.checked = checked == 1;
            refine_mesh(m, settings, reports[checked]);
            triangles[checked] = m.count_triangles();
        }
        CHECK(triangles[0] == triangles[1]);
        CHECK(reports[0].left_small_input_angle == reports[1].left_small_input_angle);
        CHECK(reports[0].left_no_split == reports[1].left_no_split);
        CHECK(reports[0].left_precision == reports[1].left_precision);
        CHECK(reports[0].left_budget == reports[1].left_budget);
        CHECK(reports[0].left_other == reports[1].left_other);
        CHECK(reports[0].encroached_left == reports[1].encroached_left);
        if (c.angle >= 30 && c.no_segment_splitting == 0 && c.area == 0)
            CHECK(reports[0].left_small_input_angle > 0);
        if (c.no_segment_splitting != 0)
            CHECK(reports[0].left_no_split + reports[0].encroached_left > 0);
    }
}

}  // namespace gpdr::refine::testing
