// The built gpdr meshing real inputs: every output checked by -C (the
// library's invariant checker) and by measuring the files it wrote.

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <string>

#include "cli/mesh_files.hpp"

using namespace gpdr::test;

namespace {

// A square with a square hole and two regions (attributes 1 and 2, area
// bounds 0.05 and none), in Triangle's .poly format.
const std::string two_regions = R"(# square with a hole, split in two regions by a vertical segment
8 2 0 1
1 0 0 0
2 4 0 0
3 4 4 0
4 0 4 0
5 1.5 1.5 0
6 2.5 1.5 0
7 2.5 2.5 0
8 1.5 2.5 0
10 1
1 1 2 1
2 2 3 1
3 3 4 1
4 4 1 1
5 5 6 2
6 6 7 2
7 7 8 2
8 8 5 2
9 1 5 0
10 3 7 0
1
1 2 2
2
1 0.5 2 1 0.05
2 3.5 2 2 -1
)";

void require_checked(const RunResult& r) {
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.status == 0);
    REQUIRE(r.err.find("check:") == std::string::npos);
}

}  // namespace

TEST_CASE("switch -pq meets the angle bound on the project's samples", "[cli][quality]") {
    const auto angle = GENERATE(20, 30, 33);
    const std::string sample = GENERATE(as<std::string>{}, "flow.poly", "pipe.poly");
    TempDir dir;
    dir.write(sample, sample_text(sample));
    const auto r = run_gpdr(dir, "-pCq" + std::to_string(angle) + " " + sample);
    require_checked(r);
    const std::string stem = sample.substr(0, sample.size() - 5) + ".1";
    CHECK(dir.exists(stem + ".poly"));
    const MeshFiles m = MeshFiles::read(dir, stem);
    REQUIRE(m.triangles.size() > 100);
    double smallest = 180;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        REQUIRE(m.area(t) > 0);
        smallest = std::min(smallest, m.smallest_angle(t));
    }
    // The samples have no input angle below 60 degrees, so no triangle is
    // exempt from the bound.
    CHECK(smallest >= angle - 1e-9);
}

TEST_CASE("switch -a bounds every triangle's area; regions set attributes and bounds",
          "[cli][quality]") {
    TempDir dir;
    dir.write("r.poly", two_regions);
    SECTION("global bound") {
        require_checked(run_gpdr(dir, "-pCa0.01 r.poly"));
        const MeshFiles m = MeshFiles::read(dir, "r.1");
        for (std::size_t t = 0; t < m.triangles.size(); ++t) REQUIRE(m.area(t) <= 0.01);
    }
    SECTION("regional bounds and -A attributes") {
        require_checked(run_gpdr(dir, "-pCAaq r.poly"));
        const MeshFiles m = MeshFiles::read(dir, "r.1");
        REQUIRE(m.triangles.attribute_count == 1);
        std::size_t left = 0, right = 0;
        for (std::size_t t = 0; t < m.triangles.size(); ++t) {
            const double attribute = m.triangles.attributes[t];
            // The hole is gone: no triangle has its centroid inside it.
            const double x = m.centroid_x(t), y = m.centroid_y(t);
            REQUIRE_FALSE((x > 1.5 && x < 2.5 && y > 1.5 && y < 2.5));
            // The segments from (0, 0) and (4, 4) to the hole cut the ring
            // into the half above the diagonal (region 1, holding (0.5, 2))
            // and the half below it (region 2).
            if (y > x) {
                ++left;
                REQUIRE(attribute == 1);
                REQUIRE(m.area(t) <= 0.05);
            } else {
                ++right;
                REQUIRE(attribute == 2);
            }
        }
        CHECK(left > 2 * right);  // only region 1 is bounded
    }
}

TEST_CASE("switch -p then -rp leaves the mesh unchanged; -rq refines it further", "[cli][refine]") {
    TempDir dir;
    // flow.poly has no input angle below 90 degrees: no triangle is exempt
    // from the angle bound.
    dir.write("r.poly", sample_text("flow.poly"));
    require_checked(run_gpdr(dir, "-pq r.poly"));
    require_checked(run_gpdr(dir, "-rpC r.1"));
    const MeshFiles first = MeshFiles::read(dir, "r.1"), second = MeshFiles::read(dir, "r.2");
    CHECK(first.canonical() == second.canonical());
    require_checked(run_gpdr(dir, "-rpCq30a0.5 r.2"));
    const MeshFiles third = MeshFiles::read(dir, "r.3");
    CHECK(third.triangles.size() > second.triangles.size());
    for (std::size_t t = 0; t < third.triangles.size(); ++t) {
        REQUIRE(third.smallest_angle(t) >= 30 - 1e-9);
        REQUIRE(third.area(t) <= 0.5);
    }
}

TEST_CASE("switch -c, -e, -n, -v, -o2 and -j write what Triangle writes", "[cli][outputs]") {
    TempDir dir;
    dir.write("p.node", sample_text("points.node"));
    require_checked(run_gpdr(dir, "-cenvo2C p.node"));
    for (const char* f :
         {"p.1.node", "p.1.ele", "p.1.poly", "p.1.edge", "p.1.neigh", "p.1.v.node", "p.1.v.edge"})
        CHECK(dir.exists(f));
    const MeshFiles m = MeshFiles::read(dir, "p.1");
    CHECK(m.triangles.corners_per_triangle == 6);
    // A node per edge midpoint after the 500 vertices, and Euler's formula
    // for a triangulated disk: V - E + T = 1.
    const auto edges = gpdr::io::read_edge((dir / "p.1.edge").string(), m.base, m.nodes.size(),
                                           gpdr::ignore_warning);
    CHECK(m.nodes.size() == 500 + edges.data.size());
    CHECK(500 + m.triangles.size() == edges.data.size() + 1);
    // Every triangle, then -j on a .node with an unused (duplicate) vertex.
    dir.write("d.node", "4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 1 0\n");
    const auto r = run_gpdr(dir, "-j d.node");
    REQUIRE(r.status == 0);
    CHECK(r.err.find("duplicate") != std::string::npos);
    CHECK(MeshFiles::read(dir, "d.1").nodes.size() == 3);
}

TEST_CASE(
    "with several threads the output files are written side by side, the same as one thread writes",
    "[cli][outputs][parallel]") {
    // No refinement, so the mesh is the same for any thread count; only the
    // files' last line (the command) differs.
    TempDir dir;
    dir.write("p.node", sample_text("points.node"));
    const std::vector<std::string> names{"p.1.node",  "p.1.ele",    "p.1.poly",  "p.1.edge",
                                         "p.1.neigh", "p.1.v.node", "p.1.v.edge"};
    const auto without_last_line = [](std::string s) {
        s.pop_back();
        return s.substr(0, s.rfind('\n') + 1);
    };
    std::vector<std::string> one_thread;
    const auto r1 = run_gpdr(dir, "-cenv -j1 p.node");
    REQUIRE(r1.status == 0);
    for (const auto& n : names) one_thread.push_back(without_last_line(dir.read(n)));
    const auto r4 = run_gpdr(dir, "-cenv -j4 p.node");
    REQUIRE(r4.status == 0);
    // The same files, announced in the same order.
    CHECK(r4.out == r1.out);
    for (std::size_t i = 0; i < names.size(); ++i) {
        INFO(names[i]);
        CHECK(without_last_line(dir.read(names[i])) == one_thread[i]);
    }
    CHECK(dir.files().size() == names.size() + 1);  // no temporary file left behind
}

TEST_CASE("the statistics of -V are the same on one thread and on several",
          "[cli][statistics][parallel]") {
    // 12,000 random points: about 24,000 triangles, more than one run of
    // the statistics (16384 triangles), and no refinement, so the mesh is
    // the same for any thread count.
    TempDir dir;
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    std::string node = "12000 2 0 0\n";
    for (int i = 1; i <= 12000; ++i)
        node += std::to_string(i) + " " + std::to_string(coordinate(random)) + " " +
                std::to_string(coordinate(random)) + "\n";
    dir.write("p.node", node);
    const auto statistics = [](const std::string& out) {
        const auto at = out.find("Mesh quality statistics:");
        return at == std::string::npos ? std::string() : out.substr(at);
    };
    const auto r1 = run_gpdr(dir, "-VNE -j1 p.node");
    REQUIRE(r1.status == 0);
    const auto r4 = run_gpdr(dir, "-VNE -j4 p.node");
    REQUIRE(r4.status == 0);
    REQUIRE(statistics(r1.out).find("Angle histogram") != std::string::npos);
    CHECK(statistics(r4.out) == statistics(r1.out));
}

namespace {

// Every combination of the PSLG switches -c, -D, -O and -A and two refinements,
// each checked by -C (topology, orientation, constrained Delaunay, segment
// conformity), on every .poly in `folder`.
void mesh_every_sample(const std::filesystem::path& folder) {
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() != ".poly") continue;
        for (const char* switches : {"-pCQ", "-pcCQ", "-pDCQ", "-pcDCQ", "-pOCQ", "-pACQ", "-pcqCQ",
                                     "-pqa0.5CQ", "-pq30CQ"}) {
            DYNAMIC_SECTION(name << " " << switches) {
                TempDir dir;
                std::filesystem::copy(entry.path(), dir / name);
                // A .poly without vertices takes them from its .node.
                auto node = entry.path();
                if (std::filesystem::exists(node.replace_extension(".node")))
                    std::filesystem::copy(node, dir / node.filename());
                // box_hole.poly's only closed loop is its hole: without -c,
                // Triangle eats every triangle, and so does gpdr.
                require_checked(run_gpdr(dir, std::string(switches) + " " + name));
            }
        }
    }
}

}  // namespace

TEST_CASE("the test data samples mesh with -p, -c, -D, -O, -A, -q and pass -C", "[cli][samples]") {
    mesh_every_sample(test_data());
}

TEST_CASE("the project's samples mesh with -p, -c, -D, -O, -A, -q and pass -C", "[cli][samples]") {
    mesh_every_sample(project_samples());
}

TEST_CASE("switch -jN refines in parallel: the same bounds and about the same counts as -j1",
          "[cli][parallel]") {
    // Area bounds that give 25,000 to 40,000 triangles, so that the quadtree
    // splits and several leaves are refined at once.
    const auto [sample, area] =
        GENERATE(table<std::string, std::string>({{"flow.poly", "0.02"}, {"pipe.poly", "5"}}));
    const std::string threads = GENERATE(as<std::string>{}, "-j2 -g1", "-j3 -g2", "-j4 -g4", "-j2");
    TempDir dir;
    dir.write(sample, sample_text(sample));
    const std::string stem = sample.substr(0, sample.size() - 5) + ".1";
    const std::string switches = "-pCVq30a" + area + " ";
    require_checked(run_gpdr(dir, switches + "-j1 " + sample));
    const std::size_t sequential = MeshFiles::read(dir, stem).triangles.size();
    REQUIRE(sequential > 20000);

    INFO(sample << " " << threads);
    const auto r = run_gpdr(dir, switches + threads + " " + sample);
    require_checked(r);
    // -V says where each thread's time went (the paper's Fig. 5), and what
    // the rounds allow.
    CHECK(r.out.find("between rounds") != std::string::npos);
    CHECK(r.out.find("thread 2: refining") != std::string::npos);
    CHECK(r.out.find("work / span") != std::string::npos);
    const MeshFiles m = MeshFiles::read(dir, stem);
    double smallest = 180, largest = 0;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        smallest = std::min(smallest, m.smallest_angle(t));
        largest = std::max(largest, m.area(t));
    }
    CHECK(smallest >= 30 - 1e-9);
    CHECK(largest <= std::stod(area));
    const double ratio = double(m.triangles.size()) / double(sequential);
    CHECK(ratio > 0.95);
    CHECK(ratio < 1.05);
}

TEST_CASE("switch -S counts the vertices where segments cross", "[cli][limits]") {
    TempDir dir;
    // A square whose diagonals cross once: one vertex at (0.5, 0.5).
    dir.write("x.poly",
              "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n"
              "6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 1 3\n6 2 4\n0\n");
    for (const int budget : {0, 1, 3, 6}) {
        INFO("-S" << budget);
        const RunResult r = run_gpdr(dir, "-Qpa0.001S" + std::to_string(budget) + " x.poly");
        REQUIRE(r.status == 0);
        const MeshFiles m = MeshFiles::read(dir, "x.1");
        // The crossing is always made (the segments need it); refinement
        // gets what is left of the budget.
        CHECK(m.nodes.size() == 5 + static_cast<std::size_t>(std::max(budget - 1, 0)));
    }
}
