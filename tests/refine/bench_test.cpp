// Hidden benchmark: refining a square (plus two interior points) to a few million triangles (-q20
// and a small area bound), seconds and triangles per second.  Run with
//   build/tests/test_refine "[.bench]"

#include <chrono>

#include "refine_support.hpp"

namespace gpdr::refine::testing {

TEST_CASE("refinement speed on a large square", "[.bench][refine]") {
    const Placement placement = GENERATE(Placement::off_centre, Placement::circumcentre);
    triangulate::Pslg p;
    // Two interior points break the square's symmetry (which would make
    // refinement a regular bisection).
    p.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.3141, 0.2718}, {0.7071, 0.5772}};
    p.segments = {0, 1, 1, 2, 2, 3, 3, 0};
    mesh::Mesh m = cdt(p);
    RefineSettings settings;
    settings.placement = placement;
    settings.criteria.min_angle_degrees = 20;
    settings.criteria.max_area = 1e-6;
    settings.checked = false;
    RefineReport report;
    const auto start = std::chrono::steady_clock::now();
    refine_mesh(m, settings, report);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t triangles = m.count_triangles();
    WARN("placement " << int(placement) << ": " << triangles << " triangles, "
                      << report.steiner_points << " Steiner points, " << report.triangles_created
                      << " created, " << seconds << " s, " << triangles / seconds / 1e6
                      << " M triangles/s, " << seconds / double(report.triangles_created) * 1e9
                      << " ns per created triangle");
    CHECK(report.stopped == RefineReport::Stop::none);
    CHECK(report.left_other == 0);
}

}  // namespace gpdr::refine::testing
