// Every .poly sample (the tests' inputs in tests/data and the project's
// poly-samples) through the CDT, with and without -c and -O: the
// result passes check_mesh and the segment conformity check.

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include <gpdr/io.hpp>

#include "api/api_test_support.hpp"
#include "check/checker.hpp"
#include "cli/cli_support.hpp"
#include "triangulate/conformity.hpp"
#include "triangulate/constrained.hpp"

using namespace gpdr;
namespace fs = std::filesystem;

namespace {

void check_samples(const std::vector<fs::path>& files) {
    for (const fs::path& file : files) {
        const auto read = io::read_poly(file.string(), ignore_warning);
        const triangulate::Pslg pslg = triangulate::pslg_from(read.data);
        for (int variant = 0; variant < 4; ++variant) {
            triangulate::CdtOptions options;
            options.convex_hull = (variant & 1) != 0;
            options.ignore_holes = (variant & 2) != 0;
            triangulate::CdtReport report;
            const mesh::Mesh m = triangulate::constrained_delaunay(pslg, options, report);
            INFO(file.filename().string() << " convex_hull=" << options.convex_hull
                                          << " ignore_holes=" << options.ignore_holes);
            if (options.convex_hull)
                CHECK(m.count_triangles() > 0);  // box_hole.poly without -c is all eaten
            const auto problems = mesh::check_mesh(m);
            for (const auto& p : problems) INFO(p);
            CHECK(problems.empty());
            const auto conformity = triangulate::check_conformity(m, pslg, report);
            for (const auto& p : conformity) INFO(p);
            CHECK(conformity.empty());
        }
    }
}

}  // namespace

TEST_CASE("the test data PSLGs triangulate into valid conforming CDTs", "[api][cdt][samples]") {
    const auto files = test::poly_files(test::test_data());
    REQUIRE(!files.empty());
    check_samples(files);
}

TEST_CASE("the project's sample PSLGs triangulate into valid conforming CDTs",
          "[api][cdt][samples]") {
    const auto files = test::poly_files(fs::path(GPDR_SOURCE_DIR) / "poly-samples");
    REQUIRE(!files.empty());
    check_samples(files);
}
