// Placement strategies: every strategy's point lies strictly inside the
// selection disk of the poor triangle (GPDR Definition 1), and the
// optimisation strategy never scores worse than the off-centre.

#include <gpdr/errors.hpp>

#include "refine/placement.hpp"

#include "refine_support.hpp"

namespace gpdr::refine::testing {

namespace {

// Every poor triangle of a mesh, described.
std::vector<PoorTriangle> poor_triangles(const mesh::Mesh& m, const QualityTest& quality) {
    std::vector<PoorTriangle> out;
    mesh::for_each_triangle(m, [&](mesh::TriangleId id, const mesh::Triangle& t) {
        const auto measures =
            QualityTest::measure(m.point(t.v[0]), m.point(t.v[1]), m.point(t.v[2]));
        if (quality.assess(m, id, measures) != Poorness::good)
            out.push_back(describe_poor_triangle(m, id, quality));
    });
    return out;
}

}  // namespace

TEST_CASE("every built-in strategy places its point inside the selection disk",
          "[refine][placement]") {
    const double angle = GENERATE(5.0, 15.0, 20.0, 25.0, 33.0);
    const Placement kind =
        GENERATE(Placement::circumcentre, Placement::off_centre, Placement::optimisation);
    const mesh::Mesh m = point_set_mesh(random_points(400, 11));
    QualityCriteria criteria;
    criteria.min_angle_degrees = angle;
    const QualityTest quality(criteria);
    const PlacementStrategy& strategy = builtin_placement(kind);
    PlacementScratch scratch;
    std::size_t tested = 0;
    for (const PoorTriangle& t : poor_triangles(m, quality)) {
        if (t.disk.radius <= 0) continue;  // the refiner uses the circumcentre itself
        const Point p = strategy.place(t, scratch);
        INFO(strategy.name() << " q" << angle);
        REQUIRE(in_selection_disk(t, p));
        ++tested;
    }
    CHECK(tested > 20);
}

TEST_CASE("the optimisation strategy scores no worse than the off-centre", "[refine][placement]") {
    const mesh::Mesh m = point_set_mesh(random_points(300, 5));
    QualityCriteria criteria;
    criteria.min_angle_degrees = 25;
    criteria.max_area = 0.002;
    const QualityTest quality(criteria);
    PlacementScratch scratch;
    const OptimisationPlacement optimisation;
    int better = 0;
    for (const PoorTriangle& t : poor_triangles(m, quality)) {
        if (t.disk.radius <= 0) continue;
        const Point off = geometry::off_centre(t.corner[0], t.corner[1], t.corner[2], t.rho_bar);
        if (!in_selection_disk(t, off)) continue;
        scratch.scores.clear();
        const int off_score = OptimisationPlacement::cavity_penalty(t, off, scratch);
        const Point best = optimisation.place(t, scratch);
        scratch.scores.clear();
        const int best_score = OptimisationPlacement::cavity_penalty(t, best, scratch);
        REQUIRE(best_score <= off_score);
        if (best_score < off_score) ++better;
    }
    CHECK(better > 0);
}

namespace {

// A user strategy that leaves the disk: checked mode must catch it.
class Outside final : public PlacementStrategy {
public:
    Point place(const PoorTriangle& t, PlacementScratch&) const override {
        return {t.disk.centre.x + 2 * t.disk.radius, t.disk.centre.y};
    }
    const char* name() const override { return "outside"; }
};

// A user strategy in the README's style: halfway between the circumcentre
// and the off-centre (the disk is convex, so inside).
class Halfway final : public PlacementStrategy {
public:
    Point place(const PoorTriangle& t, PlacementScratch&) const override {
        const Point off = geometry::off_centre(t.corner[0], t.corner[1], t.corner[2], t.rho_bar);
        return {0.5 * (off.x + t.circle.centre.x), 0.5 * (off.y + t.circle.centre.y)};
    }
    const char* name() const override { return "halfway"; }
};

}  // namespace

TEST_CASE("user strategies: checked mode refuses a point outside the disk", "[refine][placement]") {
    mesh::Mesh m = point_set_mesh(random_points(80, 3));
    RefineSettings settings;
    settings.criteria.min_angle_degrees = 20;
    settings.checked = true;
    RefineReport report;
    SECTION("outside") {
        const Outside outside;
        settings.strategy = &outside;
        REQUIRE_THROWS_AS(refine_mesh(m, settings, report), Error);
    }
    SECTION("halfway") {
        const Halfway halfway;
        settings.strategy = &halfway;
        refine_mesh(m, settings, report);
        const Outcome o = examine(m, settings);
        CHECK(o.bad_angles == 0);
        CHECK(report.steiner_points > 0);
    }
}

}  // namespace gpdr::refine::testing
