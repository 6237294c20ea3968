// Quality refinement on every .poly sample (the project's poly-samples and
// the tests' inputs in tests/data), for angle bounds 0 to 33
// degrees, with and without an area bound, for each placement strategy: the
// result passes the invariant checker and the segment conformity check, and
// every triangle meets the angle bound (unless a small input angle protects
// it, by the refiner's own rule, which is then the only excuse) and the
// area bound (never excused).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <gpdr/io.hpp>

#include "api/api_test_support.hpp"
#include "check/checker.hpp"
#include "cli/cli_support.hpp"
#include "mesh/traverse.hpp"
#include "refine/quality.hpp"
#include "refine/refine.hpp"
#include "triangulate/conformity.hpp"
#include "triangulate/constrained.hpp"

using namespace gpdr;
namespace fs = std::filesystem;

namespace {

void refine_and_check(const fs::path& file) {
    const auto read = io::read_poly(file.string(), ignore_warning);
    const triangulate::Pslg pslg = triangulate::pslg_from(read.data);
    // Bounding-box area, for an area bound that makes a few hundred triangles.
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (const auto& p : pslg.points) {
        x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x),
        y1 = std::max(y1, p.y);
    }
    const double box = (x1 - x0) * (y1 - y0);
    std::vector<mesh::VertexId> ends;
    for (const std::uint32_t v : pslg.segments) ends.push_back(mesh::VertexId{v});

    for (const double angle : {0.0, 10.0, 20.0, 28.0, 33.0}) {
        for (const double area : {-1.0, box / 300}) {
            if (angle == 0 && area < 0) continue;  // nothing to refine
            for (const Placement placement :
                 {Placement::circumcentre, Placement::off_centre, Placement::optimisation}) {
                // -c so that box_hole.poly (no closed boundary) has a mesh too.
                triangulate::CdtOptions cdt;
                cdt.convex_hull = true;
                triangulate::CdtReport report;
                mesh::Mesh m = triangulate::constrained_delaunay(pslg, cdt, report);
                refine::RefineSettings settings;
                settings.criteria.min_angle_degrees = angle;
                settings.criteria.max_area = area;
                settings.placement = placement;
                settings.checked = true;  // every strategy point verified admissible
                settings.segment_ends = ends;
                refine::RefineReport refined;
                refine::refine_mesh(m, settings, refined);

                INFO(file.filename().string()
                     << " q" << angle << " a" << area << " P" << static_cast<int>(placement));
                REQUIRE(refined.stopped == refine::RefineReport::Stop::none);
                const auto problems = mesh::check_mesh(m);
                for (const auto& p : problems) INFO(p);
                REQUIRE(problems.empty());
                const auto conformity = triangulate::check_conformity(m, pslg, report);
                for (const auto& p : conformity) INFO(p);
                REQUIRE(conformity.empty());

                const refine::QualityTest quality(settings.criteria, refine::SegmentEnds{ends});
                std::size_t excused = 0;
                mesh::for_each_triangle(m, [&](mesh::TriangleId id, const mesh::Triangle& t) {
                    const auto& a = m.point(t.v[0]);
                    const auto& b = m.point(t.v[1]);
                    const auto& c = m.point(t.v[2]);
                    const auto measures = refine::QualityTest::measure(a, b, c);
                    if (area > 0) REQUIRE(measures.area <= area);
                    if (test::smallest_angle(a, b, c) >= angle - 1e-9) return;
                    bool protected_angle = false;
                    quality.assess(m, id, measures, &protected_angle);
                    REQUIRE(protected_angle);
                    ++excused;
                });
                CHECK(excused == refined.left_small_input_angle);
            }
        }
    }
}

}  // namespace

TEST_CASE("refinement meets the bounds on the project's samples", "[api][refine][samples]") {
    for (const auto& file : test::poly_files(test::project_samples())) refine_and_check(file);
}

TEST_CASE("refinement meets the bounds on the test data samples", "[api][refine][samples]") {
    const auto files = test::poly_files(test::test_data());
    REQUIRE(!files.empty());
    for (const auto& file : files) refine_and_check(file);
}
