// A run whose area bounds call for a mesh larger than the memory available
// is refused before refining: exit status 1, a message naming the bound and
// the sizes, no file written.  A sane bound runs as before.

#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "cli/cli_support.hpp"

using namespace gpdr::test;

namespace {

// A 2 x 1 rectangle with one region (attribute 7, area bound 1e-13).
const char* const rectangle_poly =
    "4 2 0 0\n1 0 0\n2 2 0\n3 2 1\n4 0 1\n"
    "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n"
    "0\n"
    "1\n1 1 0.5 7 1e-13\n";

}  // namespace

TEST_CASE("an absurd area bound is refused before refining", "[cli][memory]") {
    TempDir dir;
    dir.write("box.poly", rectangle_poly);
    // 2 / 1e-13 triangles at the bound: petabytes, more than any machine.
    SECTION("-a") {
        const auto r = run_gpdr(dir, "-pa1e-13 box.poly");
        CHECK(r.status == 1);
        CHECK(r.err.find("gpdr: box.poly: -a1e-13 would make about 3.0e13 triangles") == 0);
        CHECK(r.err.find("of memory available; use --force to try anyway\n") != std::string::npos);
    }
    SECTION("the regions' bounds") {
        const auto r = run_gpdr(dir, "-pqa box.poly");
        CHECK(r.status == 1);
        CHECK(r.err.find("gpdr: box.poly: the regions' bounds would make about") == 0);
    }
    CHECK(dir.files() == std::vector<std::string>{"box.poly"});
}

TEST_CASE("a sane area bound is not refused, nor is --force", "[cli][memory]") {
    TempDir dir;
    dir.write("box.poly", rectangle_poly);
    const auto r = run_gpdr(dir, "-pQa0.01 box.poly");
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(dir.exists("box.1.ele"));
    // --force changes nothing when nothing would be refused; -S makes the
    // absurd bound harmless (at most two triangles per Steiner point).
    const auto forced = run_gpdr(dir, "-pQa0.01 --force box.poly");
    CHECK(forced.status == 0);
    const auto capped = run_gpdr(dir, "-pQa1e-13 -S50 box.poly");
    CHECK(capped.status == 0);
    CHECK(capped.err.empty());
}

// Under a limit on address space (`ulimit -v`) the mesh's tables reserve
// half of what can still be mapped instead of their whole ranges: a small
// mesh comes out as without the limit, on one thread and on several, and
// one too large for the limit ends with "out of memory" (exit status 2) and
// no file.
TEST_CASE("a limit on address space meshes what fits and refuses the rest", "[cli][memory]") {
    TempDir dir;
    fs::copy_file(project_samples() / "flow.poly", dir.path() / "flow.poly");
    dir.write("box.poly", rectangle_poly);
    const auto limited = [&dir](const std::string& args) {
        return run_program(
            dir, "/bin/sh",
            "-c \"ulimit -v 400000 && exec '" + std::string(GPDR_EXE) + "' " + args + "\"");
    };
    for (const char* threads : {"-j1", "-j2"}) {
        INFO(threads);
        REQUIRE(run_gpdr(dir, std::string("-Qpq30a0.001 ") + threads + " flow.poly").status == 0);
        const std::string expected = dir.read("flow.1.ele");
        fs::remove(dir.path() / "flow.1.ele");
        const auto r = limited(std::string("-Qpq30a0.001 ") + threads + " flow.poly");
        CHECK(r.status == 0);
        CHECK(r.err.empty());
        CHECK(dir.read("flow.1.ele") == expected);
        for (const char* ext : {".1.node", ".1.ele", ".1.poly"})
            fs::remove(dir.path() / ("flow" + std::string(ext)));
    }
    // About 20 million triangles: more than half of 400 MB holds.
    const auto r = limited("-Qpa1e-7 -j2 box.poly");
    CHECK(r.status == 2);
    CHECK(r.err == "gpdr: out of memory\n");
    CHECK(dir.files() == std::vector<std::string>{"box.poly", "flow.poly"});
}
