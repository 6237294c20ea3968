// -C from the command line: a mesh that fails the check is not written
// (earlier outputs stay as they were), the exit status says the check
// failed, and the problems number vertices and triangles as the files do.
// Meshes of inputs whose segments cross pass.

#include <catch2/catch.hpp>

#include "cli/cli_support.hpp"

using namespace gpdr::test;

namespace {

// A quadrilateral split along its diagonal 2-4 (numbered from 1): vertex 3
// lies inside the circumcircle of triangle 1 2 4, so the mesh is not
// Delaunay.  -r without refinement keeps the triangles read, so `gpdr -rC`
// must find the mesh wrong, whatever gpdr's meshing does.
constexpr const char* kite_node = "4 2 0 0\n1 0 0\n2 3 0\n3 3 1\n4 0 2\n";
constexpr const char* kite_ele = "2 3 0\n1 1 2 4\n2 2 3 4\n";
constexpr const char* kite_node_0 = "4 2 0 0\n0 0 0\n1 3 0\n2 3 1\n3 0 2\n";
constexpr const char* kite_ele_0 = "2 3 0\n0 0 1 3\n1 1 2 3\n";

}  // namespace

TEST_CASE("a failed -C writes nothing and exits with status 4", "[cli][check]") {
    TempDir dir;
    dir.write("kite.node", kite_node);
    dir.write("kite.ele", kite_ele);
    // The outputs of an earlier run, which a failed check must not touch.
    dir.write("kite.1.node", "earlier node\n");
    dir.write("kite.1.ele", "earlier ele\n");
    const auto files = dir.files();

    const auto r = run_gpdr(dir, "-rC kite");
    CHECK(r.status == 4);
    CHECK(r.out.find("Wrote") == std::string::npos);
    CHECK(r.err.find("gpdr: check: triangle 1 (1, 2, 4): edge 2-4 is not locally Delaunay: "
                     "vertex 3 of triangle 2 (2, 3, 4)") != std::string::npos);
    CHECK(r.err.find("1 problem found in the mesh; no file written") != std::string::npos);
    CHECK(dir.files() == files);
    CHECK(dir.read("kite.1.node") == "earlier node\n");
    CHECK(dir.read("kite.1.ele") == "earlier ele\n");

    // Without -C the same run writes its files.
    CHECK(run_gpdr(dir, "-rQ kite").status == 0);
    CHECK(dir.read("kite.1.node") != "earlier node\n");
}

TEST_CASE("a failed -C numbers from 0 with -z", "[cli][check]") {
    TempDir dir;
    dir.write("kite.node", kite_node_0);
    dir.write("kite.ele", kite_ele_0);
    const auto r = run_gpdr(dir, "-rCz kite");
    CHECK(r.status == 4);
    CHECK(r.err.find("triangle 0 (0, 1, 3): edge 1-3 is not locally Delaunay: vertex 2 of "
                     "triangle 1 (1, 2, 3)") != std::string::npos);
    CHECK(dir.files() == std::vector<std::string>{"kite.ele", "kite.node"});
}

TEST_CASE("crossing segments, crossing at rounded points, pass -C", "[cli][check]") {
    TempDir dir;
    // A square far from the origin with two diagonals-ish segments and a
    // segment through both; none of the crossings is a double.
    dir.write("x.poly",
              "7 2 0 0\n"
              "1 1000 1000\n2 1003 1000.1\n3 1003.2 1003\n4 1000.1 1003.3\n"
              "5 1000.3 1001.7\n6 1002.9 1001.1\n7 1001.5 999.9\n"
              "7 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 1 3\n6 2 4\n7 5 6\n"
              "0\n");
    for (const char* switches : {"-pC", "-pcC", "-pq20C", "-pq30C", "-pq30j2C", "-pcq30a0.01C"}) {
        DYNAMIC_SECTION(switches) {
            const auto r = run_gpdr(dir, std::string(switches) + " x.poly");
            CHECK(r.status == 0);
            CHECK(r.out.find("Check: no problems found") != std::string::npos);
            CHECK(r.err.find("check:") == std::string::npos);
        }
    }
}
