// Refinement above 34 degrees: the star placement (admissible points, the
// off-centre kept where its star meets the bound, better stars found where
// it does not), the cascade watch that stops a run that does not converge,
// the copy of a mesh that each try refines, and the smallest angle the
// warning names.

#include "refine/convergence.hpp"
#include "refine/mesh_copy.hpp"
#include "refine/star_placement.hpp"

#include "refine_support.hpp"

namespace gpdr::refine::testing {

TEST_CASE("the star placement keeps the off-centre where its star is good, and finds better ones",
          "[refine][placement][high-angle]") {
    const double angle = GENERATE(35.0, 36.0, 38.0);
    const mesh::Mesh m = point_set_mesh(random_points(400, 11));
    QualityCriteria criteria;
    criteria.min_angle_degrees = angle;
    const QualityTest quality(criteria);
    const OffCentrePlacement off_centre;
    PlacementScratch scratch;
    std::size_t poor = 0, kept = 0, moved_to_good = 0;
    for (const StarPlacement::Move move :
         {StarPlacement::Move::to_good_star, StarPlacement::Move::to_fewer_poor,
          StarPlacement::Move::to_farther}) {
        const StarPlacement star(move);
        INFO(star.name() << " q" << angle);
        mesh::for_each_triangle(m, [&](mesh::TriangleId id, const mesh::Triangle& t) {
            const auto measures =
                QualityTest::measure(m.point(t.v[0]), m.point(t.v[1]), m.point(t.v[2]));
            if (!quality.bad_shape(measures)) return;
            ++poor;
            const PoorTriangle pt = describe_poor_triangle(m, id, quality);
            const Point p = star.place(pt, scratch);
            REQUIRE(admissible_point(pt, p));
            const Point off = off_centre.place(pt, scratch);
            const double goal = 0.5 / quality.rho_bar() * StarPlacement::goal_margin;
            const StarQuality at_off = star_quality(pt, off, goal, scratch);
            if (at_off.located && !at_off.encroaches && at_off.poor == 0) {
                CHECK(p == off);
                ++kept;
            } else if (!(p == off)) {
                const StarQuality at_p = star_quality(pt, p, goal, scratch);
                CHECK(at_p.located);
                CHECK_FALSE(at_p.encroaches);
                if (move == StarPlacement::Move::to_good_star) CHECK(at_p.poor == 0);
                if (at_p.poor == 0) ++moved_to_good;
            }
        });
    }
    CHECK(poor > 100);
    CHECK(kept > 0);
    CHECK(moved_to_good > 0);
}

TEST_CASE("a watched run that cascades stops long before the safety limit",
          "[refine][limits][high-angle]") {
    mesh::Mesh m = point_set_mesh(random_points(30, 2));
    RefineSettings settings;
    settings.criteria.min_angle_degrees = 45;
    settings.watch_convergence = true;
    RefineReport report;
    refine_mesh(m, settings, report);
    const auto problems = mesh::check_mesh(m);
    INFO(joined(problems));
    CHECK(problems.empty());
    CHECK(report.stopped == RefineReport::Stop::not_converging);
    CHECK(report.steiner_points < 20000);  // the safety limit is over a million
}

TEST_CASE("refining a copy of a mesh makes the original's mesh", "[refine][high-angle]") {
    const triangulate::Pslg pslg = read_poly(GPDR_SOURCE_DIR "/poly-samples/flow.poly");
    mesh::Mesh original = cdt(pslg);
    mesh::Mesh copy = copy_mesh(original);
    const std::vector<mesh::VertexId> ends = segment_ends(pslg);
    RefineSettings settings;
    settings.criteria.min_angle_degrees = 35;
    settings.segment_ends = ends;
    settings.watch_convergence = true;
    RefineReport from_original, from_copy;
    refine_mesh(original, settings, from_original);
    refine_mesh(copy, settings, from_copy);
    REQUIRE(from_original.stopped == RefineReport::Stop::none);
    CHECK(from_copy.steiner_points == from_original.steiner_points);
    REQUIRE(copy.triangle_end() == original.triangle_end());
    REQUIRE(copy.vertex_end() == original.vertex_end());
    for (std::uint32_t v = 0; v < original.vertex_end(); ++v)
        REQUIRE(copy.point(mesh::VertexId{v}) == original.point(mesh::VertexId{v}));
    std::size_t live = 0;
    for (std::uint32_t i = 0; i < original.triangle_end(); ++i) {
        const mesh::Triangle& a = original.triangle(mesh::TriangleId{i});
        const mesh::Triangle& b = copy.triangle(mesh::TriangleId{i});
        REQUIRE(a.live() == b.live());
        if (!a.live()) continue;
        ++live;
        for (int k = 0; k < 3; ++k) {
            REQUIRE(a.v[k] == b.v[k]);
            REQUIRE(a.n[k] == b.n[k]);
        }
        REQUIRE(a.flags == b.flags);
    }
    CHECK(live > 1000);
    CHECK(copy.subsegments().size() == original.subsegments().size());
}

TEST_CASE("the smallest angle leaves out the small input angles", "[refine][high-angle]") {
    const triangulate::Pslg pslg = read_poly(GPDR_SOURCE_DIR "/tests/data/models/star.poly");
    mesh::Mesh m = cdt(pslg);
    const std::vector<mesh::VertexId> ends = segment_ends(pslg);
    RefineSettings settings;
    settings.criteria.min_angle_degrees = 30;
    settings.segment_ends = ends;
    RefineReport report;
    refine_mesh(m, settings, report);
    REQUIRE(report.left_small_input_angle > 0);  // the star's 12-degree tips
    double all = 180, unprotected = 180;
    mesh::for_each_triangle(m, [&](mesh::TriangleId, const mesh::Triangle& t) {
        const double a = min_angle_degrees(m.point(t.v[0]), m.point(t.v[1]), m.point(t.v[2]));
        all = std::min(all, a);
        if (!t.small_angle_protected()) unprotected = std::min(unprotected, a);
    });
    CHECK(all < 13);
    CHECK(unprotected >= 30);
    CHECK(smallest_angle_degrees(m) == Approx(unprotected).epsilon(1e-9));
}

}  // namespace gpdr::refine::testing
