// The estimate of how many triangles the area bounds make (area_demand.hpp),
// against what refinement then makes: it must neither overshoot (the job
// refuses runs by it) nor fall far short (it must catch absurd bounds).

#include "refine/area_demand.hpp"
#include "refine_support.hpp"

namespace gpdr::refine::testing {

namespace {

// Refines `m` under `criteria` and returns the estimate made before and the
// triangles made.
std::pair<AreaDemand, std::size_t> estimate_and_refine(mesh::Mesh m,
                                                       const QualityCriteria& criteria) {
    const AreaDemand demand = area_demand(m, criteria);
    RefineSettings settings;
    settings.criteria = criteria;
    RefineReport report;
    refine_mesh(m, settings, report);
    return {demand, examine(m, settings).triangles};
}

}  // namespace

TEST_CASE("the area demand estimates the triangles an area bound makes", "[refine][estimate]") {
    triangulate::Pslg square;
    square.points = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
    square.segments = {0, 1, 1, 2, 2, 3, 3, 0};
    for (const double angle : {0.0, 20.0, 30.0}) {
        for (const double bound : {0.01, 0.0005}) {
            QualityCriteria c;
            c.min_angle_degrees = angle;
            c.max_area = bound;
            const auto [demand, made] = estimate_and_refine(cdt(square), c);
            INFO("angle " << angle << ", bound " << bound << ": estimate " << demand.estimate
                          << ", made " << made);
            CHECK(demand.triangles == 2);
            CHECK(demand.at_bound == Approx(2.0 / bound));
            // Close to what refinement makes, and below it on a large mesh
            // (a small one is noisier: 297 made for an estimate of 300).
            CHECK(demand.estimate >= 0.85 * double(made));
            CHECK(demand.estimate <= (bound < 0.001 ? 1.0 : 1.05) * double(made));
        }
    }
}

TEST_CASE("the area demand takes the least bound of each triangle", "[refine][estimate]") {
    // Two regions of area 1: the left one bounded by 0.001 (its region),
    // the right one by the global 0.01.
    triangulate::Pslg p;
    p.points = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}};
    p.segments = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 1, 4};
    p.regions = {Region{0.5, 0.5, 1.0, 0.001}, Region{1.5, 0.5, 2.0, -1}};
    QualityCriteria c;
    c.max_area = 0.01;
    c.region_max_area = {-1.0, 0.001, -1.0};
    const mesh::Mesh m = cdt(p);
    const AreaDemand d = area_demand(m, c);
    CHECK(d.triangles == 4);
    CHECK(d.at_bound == Approx(1 / 0.001 + 1 / 0.01));
    CHECK(d.estimate == Approx(AreaDemand::fill * d.at_bound));

    // Without any bound every triangle stays one triangle.
    const AreaDemand none = area_demand(m, QualityCriteria{});
    CHECK(none.at_bound == 0);
    CHECK(none.estimate == 4);
    // A bound above a triangle's area leaves it one triangle, not a fraction.
    QualityCriteria loose;
    loose.max_area = 100;
    CHECK(area_demand(m, loose).estimate == 4);
}

}  // namespace gpdr::refine::testing
