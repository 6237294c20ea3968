// Refinement of point sets (hull edges as subsegments): the result is
// constrained Delaunay and meets the angle and area bounds, for every
// placement strategy; limits (-Y, -S, the safety budget) are respected.

#include <algorithm>
#include <cmath>

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
    // A linear attribute, x + 2y, stays exact under linear interpolation:
    // every vertex refinement adds must carry it (up to rounding).
    m.attributes() = mesh::VertexAttributes(1);
    for (std::uint32_t v = 0; v < m.vertex_end(); ++v) {
        const auto& p = m.point(mesh::VertexId{v});
        m.attributes().write(mesh::VertexId{v})[0] = p.x + 2 * p.y;
    }
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
    double worst = 0;
    for (std::uint32_t v = 0; v < m.vertex_end(); ++v) {
        if (m.kind(mesh::VertexId{v}) == mesh::VertexKind::unused) continue;
        const auto& p = m.point(mesh::VertexId{v});
        worst =
            std::max(worst, std::abs(m.attributes().row(mesh::VertexId{v})[0] - (p.x + 2 * p.y)));
    }
    CHECK(worst < 1e-12);
}

}  // namespace gpdr::refine::testing
