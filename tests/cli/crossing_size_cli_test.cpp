// Mesh size on crossing segments: gpdr -j1 -pq<angle> on the generated
// crossing model (tests/data/models/crossing.poly) against Triangle 1.6's
// triangle counts for the same switches, recorded here.  The bounds are the
// ratios scripts/bench-quality.sh reports, with a few percent to spare: a
// change in where subsegments are split at crossing points (or in the
// refinement order) that inflates the mesh fails here.  Segments crossing
// at small angles need concentric shells at the crossing points: without
// them the mesh grows more than tenfold.

#include <catch2/catch.hpp>

#include <string>

#include "cli/mesh_files.hpp"

using namespace gpdr::test;

namespace {

// Four tilted rows crossed at 6 to 48 degrees by four more lines: 9
// crossings, most of them at small angles.
const std::string small_angle_crossings = R"(# crossings at small angles
20 2 0 1
1 0 0 1
2 10 0 1
3 10 10 1
4 0 10 1
5 0.5 1.3 3
6 9.5 2.2 3
7 0.5 3.7 3
8 9.5 4.6 3
9 0.5 5.9 3
10 9.5 6.8 3
11 0.5 7.6 3
12 9.5 8.5 3
13 0.5 0.5 3
14 9.5 3.65 3
15 0.4 9.5 3
16 9.6 1.22 3
17 0.6 4.0 3
18 9.4 5.76 3
19 0.5 8.8 3
20 9.5 8.35 3
12 1
1 1 2 1
2 2 3 1
3 3 4 1
4 4 1 1
5 5 6 3
6 7 8 3
7 9 10 3
8 11 12 3
9 13 14 3
10 15 16 3
11 17 18 3
12 19 20 3
0
)";

}  // namespace

TEST_CASE("crossing segments: -j1 meshes within recorded ratios of Triangle's",
          "[cli][quality][size]") {
    struct Row {
        const char* switches;
        double triangle_count;  // Triangle 1.6, -Q plus the same switches
        double bound;           // the largest ratio accepted
    };
    const Row rows[] = {
        {"-pq30", 337, 1.18},
        {"-pq32", 427, 1.06},
        {"-pq33", 507, 1.28},
    };
    for (const Row& row : rows) {
        INFO(row.switches);
        TempDir dir;
        fs::copy_file(test_data() / "models" / "crossing.poly", dir / "crossing.poly");
        const RunResult result =
            run_gpdr(dir, std::string("-Qj1 ") + row.switches + " crossing.poly");
        INFO(result.err);
        REQUIRE(result.status == 0);
        const MeshFiles mesh = MeshFiles::read(dir, "crossing.1");
        const double ratio = static_cast<double>(mesh.triangles.size()) / row.triangle_count;
        INFO("triangles " << mesh.triangles.size() << ", ratio " << ratio);
        CHECK(ratio <= row.bound);
    }
}

TEST_CASE("crossing segments at small angles: -j1 meshes near Triangle's size",
          "[cli][quality][size]") {
    struct Row {
        const char* switches;
        double triangle_count;  // Triangle 1.6, -Q plus the same switches
    };
    for (const Row& row : {Row{"-pq20", 136}, Row{"-pq30", 362}}) {
        INFO(row.switches);
        TempDir dir;
        dir.write("small.poly", small_angle_crossings);
        const RunResult result = run_gpdr(dir, std::string("-Qj1 ") + row.switches + " small.poly");
        INFO(result.err);
        REQUIRE(result.status == 0);
        const MeshFiles mesh = MeshFiles::read(dir, "small.1");
        const double ratio = static_cast<double>(mesh.triangles.size()) / row.triangle_count;
        INFO("triangles " << mesh.triangles.size() << ", ratio " << ratio);
        CHECK(ratio <= 1.3);
    }
}
