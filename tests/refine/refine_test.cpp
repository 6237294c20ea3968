// Refinement of point sets (hull edges as subsegments): the result is
// constrained Delaunay and meets the angle and area bounds, for every
// placement strategy; limits (-Y, -S, the safety budget) are respected.

#include "refine_support.hpp"

namespace gpdr::refine::testing {

namespace {

const char* strategy_name(Placement p) {
    return p == Placement::circumcentre ? "circumcentre"
           : p == Placement::off_centre ? "off-centre"
                                        : "optimisation";
}

}  // namespace

TEST_CASE("refined point sets meet the angle and area bounds", "[refine]") {
    const Placement placement =
        GENERATE(Placement::circumcentre, Placement::off_centre, Placement::optimisation);
    const double angle = GENERATE(0.0, 10.0, 20.0, 28.0, 33.0);
    const double area = GENERATE(-1.0, 0.01, 0.0005);
    if (angle == 0 && area < 0) return;  // nothing to do
    INFO(strategy_name(placement) << " q" << angle << " a" << area);
    mesh::Mesh m = point_set_mesh(random_points(60, 7));
    RefineSettings settings;
    settings.placement = placement;
    settings.criteria.min_angle_degrees = angle;
    settings.criteria.max_area = area;
    settings.checked = true;
    RefineReport report;
    refine_mesh(m, settings, report);
    const Outcome o = examine(m, settings);
    CHECK(report.stopped == RefineReport::Stop::none);
    CHECK(o.bad_angles == 0);
    CHECK(o.too_big == 0);
    CHECK(report.left_other == 0);
    CHECK(report.left_precision == 0);
    CHECK(report.encroached_left == 0);
    CHECK(report.steiner_points > 0);
    CHECK(report.new_vertices.size() == report.steiner_points);
}

}  // namespace gpdr::refine::testing
