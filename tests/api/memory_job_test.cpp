// run_job_in_memory() against run_job(): the same input and switches give
// the same mesh whether it comes from files and goes to files or comes from
// arrays and goes back into arrays.  On one thread (-j1) both runs are
// deterministic, so the arrays must be equal, number for number; the files
// hold coordinates with 17 significant digits, which read back exactly.

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gpdr/errors.hpp>
#include <gpdr/io.hpp>
#include <gpdr/memory_job.hpp>
#include <gpdr/switches.hpp>

#include "cli/cli_support.hpp"

using namespace gpdr;
namespace fs = std::filesystem;

namespace {

const std::string pipe_poly = std::string(GPDR_SOURCE_DIR) + "/poly-samples/pipe.poly";

Options options_of(const std::string& switches) {
    Options o;
    parse_switches(switches, o);
    return o;
}

MeshInput input_from(const PolyFile& poly) {
    MeshInput in;
    in.nodes = poly.nodes;
    in.segments = poly.segments;
    in.holes = poly.holes;
    in.regions = poly.regions;
    in.name = "pipe";
    return in;
}

}  // namespace

TEST_CASE("in memory and through files, a run makes the same mesh", "[memory_job]") {
    const std::string switches = GENERATE("-pq30a40j1", "-pq25j1eno2", "-pDj1cv");
    CAPTURE(switches);
    const PolyFile poly = io::read_poly(pipe_poly, ignore_warning).data;

    test::TempDir dir;
    fs::copy_file(pipe_poly, dir / "pipe.poly");
    Options files = options_of(switches);
    files.input = (dir / "pipe.poly").string();
    const JobResult written = run_job(files, ignore_warning);
    const NodeSet nodes = io::read_node((dir / "pipe.1.node").string(), ignore_warning).data;
    const EleSet triangles =
        io::read_ele((dir / "pipe.1.ele").string(), 1, nodes.size(), ignore_warning).data;

    const MemoryJobResult memory =
        run_job_in_memory(options_of(switches), input_from(poly), ignore_warning);
    const MeshOutput& mesh = memory.mesh;
    CHECK(memory.report.files_written.empty());
    CHECK(memory.report.triangles == written.triangles);
    CHECK(memory.report.vertices == written.vertices);
    CHECK(memory.report.segments == written.segments);
    CHECK(mesh.nodes.xy == nodes.xy);
    CHECK(mesh.nodes.markers == nodes.markers);
    CHECK(mesh.triangles.corners_per_triangle == triangles.corners_per_triangle);
    CHECK(mesh.triangles.corners == triangles.corners);
    // The subsegments, as the output .poly holds them.
    const PolyFile out_poly = io::read_poly((dir / "pipe.1.poly").string(), ignore_warning).data;
    CHECK(mesh.segments.endpoints == out_poly.segments.endpoints);
    CHECK(mesh.segments.markers == out_poly.segments.markers);

    const Options o = options_of(switches);
    if (o.write_edges) {
        const EdgeSet edges =
            io::read_edge((dir / "pipe.1.edge").string(), 1, nodes.size(), ignore_warning).data;
        CHECK(mesh.edges.endpoints == edges.endpoints);
        CHECK(mesh.edges.markers == edges.markers);
    } else {
        CHECK(mesh.edges.endpoints.empty());
    }
    if (o.write_neighbours) {
        const NeighbourSet neighbours =
            io::read_neigh((dir / "pipe.1.neigh").string(), 1, triangles.size(), ignore_warning)
                .data;
        CHECK(mesh.neighbours.neighbours == neighbours.neighbours);
    } else {
        CHECK(mesh.neighbours.neighbours.empty());
    }
    if (o.write_voronoi) {
        const NodeSet vnodes = io::read_node((dir / "pipe.1.v.node").string(), ignore_warning).data;
        const io::VoronoiEdgeSet vedges = io::read_voronoi_edge((dir / "pipe.1.v.edge").string(), 1,
                                                                vnodes.size(), ignore_warning)
                                              .data;
        CHECK(mesh.voronoi_vertices.xy == vnodes.xy);
        CHECK(mesh.voronoi_edges.endpoints == vedges.endpoints);
        CHECK(mesh.voronoi_edges.directions == vedges.directions);
    } else {
        CHECK(mesh.voronoi_vertices.xy.empty());
    }
}

TEST_CASE("in memory, the input is checked as a file would be", "[memory_job]") {
    MeshInput in;
    in.nodes.xy = {0, 0, 1, 0, 0, 1};
    in.name = "arrays";

    SECTION("a segment endpoint out of range, numbered as -z says") {
        in.segments.endpoints = {0, 1, 1, 3};
        CHECK_THROWS_WITH(run_job_in_memory(options_of("-p"), in, ignore_warning),
                          Catch::Contains("arrays") && Catch::Contains("segment 2") &&
                              Catch::Contains("vertex 4"));
        CHECK_THROWS_WITH(run_job_in_memory(options_of("-pz"), in, ignore_warning),
                          Catch::Contains("segment 1") && Catch::Contains("vertex 3"));
    }
    SECTION("a coordinate that is not finite") {
        in.nodes.xy[3] = std::numeric_limits<double>::quiet_NaN();
        CHECK_THROWS_AS(run_job_in_memory(options_of(""), in, ignore_warning), InputError);
    }
    SECTION("area bounds that do not match the triangles") {
        in.triangles.corners = {0, 1, 2};
        in.areas = {0.1, 0.2};
        CHECK_THROWS_WITH(run_job_in_memory(options_of("-ra"), in, ignore_warning),
                          Catch::Contains("2 area bounds for 1 triangles"));
    }
    SECTION("-h has no meaning here") {
        CHECK_THROWS_AS(run_job_in_memory(options_of("-h"), in, ignore_warning), UsageError);
    }
    SECTION("without a switch that uses them, segments are not looked at") {
        in.segments.endpoints = {0, 7};
        const MemoryJobResult r = run_job_in_memory(options_of(""), in, ignore_warning);
        CHECK(r.mesh.triangles.size() == 1);
        CHECK(r.mesh.segments.endpoints.empty());
    }
}

TEST_CASE("a run that writes nothing counts the mesh as one that writes it", "[memory_job]") {
    // -NEP without -V: only the counts are taken (api::count_mesh), never the
    // arrays; with -V the arrays are made.  The counts must agree: the pipe
    // refined, a point set with duplicate points (-c: hull segments), and
    // one thread and two.
    struct Case {
        std::string file, switches;
    };
    const std::string data = std::string(GPDR_SOURCE_DIR);
    const Case c = GENERATE_COPY(Case{"/poly-samples/pipe.poly", "pq30a40j1"},
                                 Case{"/poly-samples/pipe.poly", "pq25j2"},
                                 Case{"/poly-samples/points.node", "cj1"},
                                 Case{"/poly-samples/points.node", "q30j2"});
    CAPTURE(c.file, c.switches);
    test::TempDir dir;
    const fs::path input = dir / fs::path(c.file).filename();
    fs::copy_file(data + c.file, input);
    // Duplicates: a point set's first vertex again, as one more line.
    if (input.extension() == ".node") {
        std::ifstream in(input);
        std::vector<std::string> lines;
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        const auto data_line = [](const std::string& line) {
            const std::size_t at = line.find_first_not_of(" \t");
            return at != std::string::npos && line[at] != '#';
        };
        const auto header = std::find_if(lines.begin(), lines.end(), data_line);
        const auto first = std::find_if(header + 1, lines.end(), data_line);
        REQUIRE(first != lines.end());
        std::istringstream header_fields(*header), first_fields(*first);
        std::size_t count = 0, index = 0;
        std::string header_rest, first_rest;
        header_fields >> count;
        std::getline(header_fields, header_rest);
        first_fields >> index;
        std::getline(first_fields, first_rest);
        *header = std::to_string(count + 1) + header_rest;
        lines.push_back(std::to_string(index + count) + first_rest);
        std::ofstream out(input);
        for (const std::string& line : lines) out << line << "\n";
    }
    Options counted = options_of(c.switches + "NEPQ");
    counted.input = input.string();
    Options arrays = options_of(c.switches + "NEPV");
    arrays.input = input.string();
    const JobResult a = run_job(counted, ignore_warning);
    const JobResult b = run_job(arrays, ignore_warning);
    CHECK(a.files_written.empty());
    CHECK(b.files_written.empty());
    CHECK(a.vertices == b.vertices);
    CHECK(a.triangles == b.triangles);
    CHECK(a.hull_edges == b.hull_edges);
    CHECK(a.edges == b.edges);
    CHECK(a.segments == b.segments);
    CHECK(a.triangles > 0);
    CHECK(std::distance(fs::directory_iterator(input.parent_path()), fs::directory_iterator()) ==
          1);  // the input alone
}
