// Every bad-input case of tests/io/bad_input_cases.hpp, through the built
// gpdr: one message "gpdr: FILE:LINE: reason" on stderr, exit status 1, and
// no output file left behind.

#include <catch2/catch.hpp>

#include "cli/cli_support.hpp"
#include "io/bad_input_cases.hpp"

using namespace gpdr::test;

TEST_CASE("bad input gives FILE:LINE, exit status 1 and no output", "[cli][bad-input]") {
    for (const BadInputCase& c : bad_input_cases()) {
        DYNAMIC_SECTION(c.name) {
            TempDir dir;
            for (const auto& [name, contents] : c.files) dir.write(name, contents);
            const auto before = dir.files();
            const auto r = run_gpdr(dir, "'" + c.input + "'");
            INFO("stderr: " << r.err);
            CHECK(r.status == 1);
            const std::string where =
                c.line == 0 ? c.file + ": " : c.file + ":" + std::to_string(c.line) + ": ";
            CHECK(r.err.rfind("gpdr: " + where, 0) == 0);
            CHECK(r.err.find(c.reason_contains) != std::string::npos);
            // One error line (warnings before it are allowed, none after).
            CHECK(r.err.back() == '\n');
            CHECK(r.err.find('\n', r.err.find("gpdr: " + where)) == r.err.size() - 1);
            CHECK(dir.files() == before);
        }
    }
}

TEST_CASE("a failed run keeps the earlier result intact", "[cli][bad-input]") {
    TempDir dir;
    dir.write("p.node", "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n");
    REQUIRE(run_gpdr(dir, "p.node").status == 0);
    const std::string good = dir.read("p.1.ele");
    dir.write("p.node", "4 2 0 0\n1 0 0\n2 1 0\n3 1 nan\n4 0 1\n");
    const auto r = run_gpdr(dir, "p.node");
    CHECK(r.status == 1);
    CHECK(dir.read("p.1.ele") == good);
    CHECK(dir.files() == std::vector<std::string>{"p.1.ele", "p.1.node", "p.node"});
}

TEST_CASE("a segment of -rp outside a non-convex mesh: exit 1, named by the .ele",
          "[cli][bad-input]") {
    // Three triangles in an L around the notch at (1, 1); segment 1 joins
    // vertices 2 and 4 across the notch, outside the mesh.
    TempDir dir;
    dir.write("l.node", "5 2 0 0\n1 0 0\n2 2 0\n3 1 1\n4 2 2\n5 0 2\n");
    dir.write("l.ele", "3 3 0\n1 1 2 3\n2 1 3 5\n3 3 4 5\n");
    dir.write("l.poly", "0 2 0 0\n1 0\n1 2 4\n0\n");
    const auto before = dir.files();
    const auto r = run_gpdr(dir, "-rp l");
    INFO("stderr: " << r.err);
    CHECK(r.status == 1);
    CHECK(r.err.rfind("gpdr: l.ele: segment 1 (2-4) is not an edge of the mesh and cannot be "
                      "inserted: ",
                      0) == 0);
    CHECK(r.err.find("leaves the triangulated region") != std::string::npos);
    CHECK(r.err.find("internal error") == std::string::npos);
    CHECK(dir.files() == before);
}
