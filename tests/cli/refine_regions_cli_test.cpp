// -r with -p and a bare -a: the area bounds come from the .area file alone.
// A mesh read back has no regions of the .poly (its triangles carry the
// .ele's attributes), so the .poly's regional bounds must not be applied,
// as in Triangle, which reads the regions in this mode and ignores them.

#include <catch2/catch.hpp>

#include <string>

#include "cli/cli_support.hpp"
#include "cli/mesh_files.hpp"

using namespace gpdr::test;

namespace {

// Two unit squares side by side; region 1 (left) asks for tiny triangles.
const std::string two_squares =
    "6 2 0 0\n1 0 0\n2 1 0\n3 2 0\n4 2 1\n5 1 1\n6 0 1\n"
    "7 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n7 2 5\n"
    "0\n"
    "2\n1 0.5 0.5 1 0.001\n2 1.5 0.5 2 -1\n";

}  // namespace

TEST_CASE("switch -rpa takes area bounds from .area, not from .poly regions", "[cli][refine]") {
    TempDir dir;
    dir.write("two.poly", two_squares);
    // A first mesh without area bounds, attributes by region.
    REQUIRE(run_gpdr(dir, "-QpqA two.poly").status == 0);
    const auto first = MeshFiles::read(dir, "two.1");
    REQUIRE(first.triangles.size() > 0);
    // An .area file that bounds nothing: refining must add nothing.
    std::string area = std::to_string(first.triangles.size()) + "\n";
    for (std::size_t t = 0; t < first.triangles.size(); ++t)
        area += std::to_string(t + static_cast<std::size_t>(first.base)) + " -1\n";
    dir.write("two.1.area", area);
    const RunResult r = run_gpdr(dir, "-Qrpa two.1");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto second = MeshFiles::read(dir, "two.2");
    CHECK(second.triangles.size() == first.triangles.size());
    CHECK(second.nodes.size() == first.nodes.size());
}
