// Input that is not a text file, through the built gpdr: /dev/zero and
// /dev/urandom named as inputs or fed through a fifo are refused at their
// first lines ("gpdr: NAME:LINE: reason", exit status 1, no output file), as
// is a regular file holding a NUL byte; a valid .node or .poly fed through a
// fifo meshes into the same files, byte for byte, as from a regular file.
//
// gpdr, like Triangle, reads NAME.node (NAME.poly with -p) for an input NAME
// without one of its extensions, so `gpdr /dev/zero` looks for
// /dev/zero.node; the devices are named here through links such as
// zero.node -> /dev/zero.  Fifo writers run under `timeout`
// (io/fifo_support.hpp): a gpdr that stops reading early, as it should, ends
// them by SIGPIPE, and a test cannot hang on them.

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "cli/cli_support.hpp"
#include "io/fifo_support.hpp"

using namespace gpdr::test;

namespace {

// Checks a refused run: exit status 1, one line on stderr that starts with
// `where` (and holds `reason` when given), no output file.
void check_refused(const RunResult& r, const std::string& where, const std::string& reason,
                   const std::vector<std::string>& files_before, const TempDir& dir) {
    INFO("stderr: " << r.err);
    CHECK(r.status == 1);
    CHECK(r.err.rfind("gpdr: " + where, 0) == 0);
    if (!reason.empty()) CHECK(r.err == "gpdr: " + where + reason + "\n");
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(dir.files() == files_before);
}

}  // namespace

TEST_CASE("gpdr /dev/zero looks for /dev/zero.node, as Triangle does", "[cli][hostile]") {
    TempDir dir;
    const auto r = run_gpdr(dir, "/dev/zero");
    check_refused(r, "/dev/zero.node: ", "cannot read: No such file or directory", {}, dir);
    const auto p = run_gpdr(dir, "-p /dev/urandom");
    check_refused(p, "/dev/urandom.poly: ", "cannot read: No such file or directory", {}, dir);
}

TEST_CASE("/dev/zero and /dev/urandom named as inputs are refused at once", "[cli][hostile]") {
    TempDir dir;
    fs::create_symlink("/dev/zero", dir / "zero.node");
    fs::create_symlink("/dev/urandom", dir / "urandom.poly");
    const auto before = dir.files();  // the links are not regular files: none
    check_refused(run_gpdr(dir, "zero.node"), "zero.node:1: ", "a NUL byte: not a text file",
                  before, dir);
    // Random bytes: a NUL byte, or a field that is not a number, on one of
    // the first lines.
    check_refused(run_gpdr(dir, "-p urandom.poly"), "urandom.poly:", "", before, dir);
    check_refused(run_gpdr(dir, "-pq30 urandom.poly"), "urandom.poly:", "", before, dir);
}

TEST_CASE("/dev/zero and /dev/urandom through a fifo are refused at once", "[cli][hostile]") {
    TempDir dir;
    REQUIRE(feed_fifo(dir / "zero.node", "/dev/zero"));
    check_refused(run_gpdr(dir, "zero.node"), "zero.node:1: ", "a NUL byte: not a text file", {},
                  dir);
    REQUIRE(feed_fifo(dir / "noise.poly", "/dev/urandom"));
    check_refused(run_gpdr(dir, "-p noise.poly"), "noise.poly:", "", {}, dir);
}

TEST_CASE("a regular file holding a NUL byte is refused on its line", "[cli][hostile]") {
    TempDir dir;
    dir.write("p.node", std::string("4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n# end \0\n", 41));
    check_refused(run_gpdr(dir, "p.node"), "p.node:6: ", "a NUL byte: not a text file", {"p.node"},
                  dir);
}

TEST_CASE("a .node or .poly through a fifo meshes into the same files", "[cli][hostile]") {
    struct Case {
        fs::path folder;
        std::vector<std::string> inputs;  // the first is named on the command line
        std::string switches;
    };
    const std::vector<Case> cases = {
        {project_samples(), {"points.node"}, "-q"},
        {project_samples(), {"pipe.poly"}, "-pq30"},
        // Vertex count 0: the vertices come from the .node beside it.
        {test_data(), {"nested_hex3.poly", "nested_hex3.node"}, "-pqAa0.05 -e"},
    };
    for (const Case& c : cases) {
        DYNAMIC_SECTION(c.inputs.front() << " " << c.switches) {
            TempDir file_dir, fifo_dir;
            for (const std::string& name : c.inputs) {
                fs::copy_file(c.folder / name, file_dir / name);
                REQUIRE(feed_fifo(fifo_dir / name, file_dir / name));
            }
            const std::string args = c.switches + " " + c.inputs.front();
            const auto from_file = run_gpdr(file_dir, args);
            const auto from_fifo = run_gpdr(fifo_dir, args);
            INFO("stderr: " << from_file.err << from_fifo.err);
            REQUIRE(from_file.status == 0);
            REQUIRE(from_fifo.status == 0);
            CHECK(from_fifo.out == from_file.out);
            // The outputs: every regular file of the fifo's folder (the
            // fifos are not regular), all of them beside the regular input.
            std::vector<std::string> outputs = fifo_dir.files();
            REQUIRE(!outputs.empty());
            std::vector<std::string> expected = outputs;
            expected.insert(expected.end(), c.inputs.begin(), c.inputs.end());
            std::sort(expected.begin(), expected.end());
            CHECK(file_dir.files() == expected);
            for (const std::string& name : outputs) {
                INFO(name);
                CHECK(fifo_dir.read(name) == file_dir.read(name));
            }
        }
    }
}

TEST_CASE("a mesh refined with -rp reads its .node once, so it may come through a fifo",
          "[cli][hostile]") {
    // The .poly of a mesh has vertex count 0: its vertices are the .node's,
    // which a fifo can give only once.
    TempDir first;
    fs::copy_file(project_samples() / "flow.poly", first / "box.poly");
    REQUIRE(run_gpdr(first, "-Qpq box.poly").status == 0);
    const std::vector<std::string> inputs = {"box.1.node", "box.1.ele", "box.1.poly"};
    TempDir file_dir, fifo_dir;
    for (const std::string& name : inputs) {
        fs::copy_file(first / name, file_dir / name);
        REQUIRE(feed_fifo(fifo_dir / name, file_dir / name, 10));
    }
    const auto from_file = run_gpdr(file_dir, "-rpq30 box.1");
    // (Under timeout: a second open of the fifo would wait for a writer
    // that never comes.)
    const auto from_fifo =
        run_program(fifo_dir, "timeout", std::string("30 '") + GPDR_EXE + "' -rpq30 box.1");
    INFO("stderr: " << from_file.err << from_fifo.err);
    REQUIRE(from_file.status == 0);
    REQUIRE(from_fifo.status == 0);
    for (const std::string name : {"box.2.node", "box.2.ele", "box.2.poly"}) {
        INFO(name);
        CHECK(fifo_dir.read(name) == file_dir.read(name));
    }
}
