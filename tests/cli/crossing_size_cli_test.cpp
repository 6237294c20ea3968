// Mesh size on crossing segments: gpdr -j1 -pq<angle> on the generated
// crossing model (tests/data/models/crossing.poly) against Triangle 1.6's
// triangle counts for the same switches, recorded here.  The bounds are the
// ratios scripts/bench-quality.sh reports, with a few percent to spare: a
// change in where subsegments are split at crossing points (or in the
// refinement order) that inflates the mesh fails here.

#include <catch2/catch.hpp>

#include <string>

#include "cli/mesh_files.hpp"

using namespace gpdr::test;

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
