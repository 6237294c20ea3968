// The progress line's count of vertices during refinement: the refining
// threads count what they add, whatever the schedule, and once refinement
// is over the count is the mesh's (a count taken from vertex ids would not
// be: parallel refinement claims ids in chunks by a fixed rule, with holes).

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include <gpdr/job.hpp>
#include <gpdr/progress.hpp>
#include <gpdr/switches.hpp>

#include "cli/cli_support.hpp"

using namespace gpdr;
namespace fs = std::filesystem;

TEST_CASE("progress counts the vertices refinement adds, on any number of threads", "[progress]") {
    const std::string switches =
        GENERATE("-pq30a0.001j1", "-pq30a0.001j2", "-pq30a0.001j3", "-pa0.002j3");
    CAPTURE(switches);
    const std::string letter = std::string(GPDR_SOURCE_DIR) + "/tests/data/letter.poly";
    test::TempDir dir;
    fs::copy_file(letter, dir / "letter.poly");
    Options options;
    parse_switches(switches, options);
    options.input = (dir / "letter.poly").string();
    options.no_node_output = options.no_ele_output = options.no_poly_output = true;
    Progress progress;
    const JobResult result = run_job(options, ignore_warning, {}, &progress);
    const Progress::Snapshot s = progress.snapshot();
    REQUIRE(result.vertices > result.input_vertices + 1000);
    CHECK(s.vertices == result.vertices);
}

TEST_CASE("progress counts every file written, the picture too", "[progress]") {
    const std::string letter = std::string(GPDR_SOURCE_DIR) + "/tests/data/letter.poly";
    test::TempDir dir;
    fs::copy_file(letter, dir / "letter.poly");
    Options options;
    parse_switches("-pq30e", options);
    options.write_vtk = options.write_gmsh = options.write_svg = true;
    options.input = (dir / "letter.poly").string();
    Progress progress;
    const JobResult result = run_job(options, ignore_warning, {}, &progress);
    const Progress::Snapshot s = progress.snapshot();
    REQUIRE(result.files_written.size() == 7);  // .node .ele .poly .edge .vtu .msh .svg
    CHECK(s.files_total == result.files_written.size());
    CHECK(s.files_done == s.files_total);
}
