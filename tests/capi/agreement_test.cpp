// libtriangle and the gpdr program agree: the same input and switches give
// the same mesh through triangulate() as through the program's files, array
// for array (on one thread, where both are deterministic; the files hold
// coordinates with 17 significant digits, which read back exactly).  Every
// mesh triangulate() returns is also rebuilt and passed through the
// invariant checker, with its subsegments, and must be constrained Delaunay.

#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include <triangle.h>
#include <gpdr/io.hpp>

#include "check/checker.hpp"
#include "cli/cli_support.hpp"
#include "triangulate/from_triangles.hpp"

using namespace gpdr;

namespace {

const std::string samples = std::string(GPDR_SOURCE_DIR) + "/poly-samples/";

// An output structure whose arrays are freed with trifree() at the end.
struct Output {
    triangulateio io{};
    ~Output() {
        for (void* p : {static_cast<void*>(io.pointlist), static_cast<void*>(io.pointattributelist),
                        static_cast<void*>(io.pointmarkerlist), static_cast<void*>(io.trianglelist),
                        static_cast<void*>(io.triangleattributelist),
                        static_cast<void*>(io.neighborlist), static_cast<void*>(io.segmentlist),
                        static_cast<void*>(io.segmentmarkerlist), static_cast<void*>(io.edgelist),
                        static_cast<void*>(io.edgemarkerlist), static_cast<void*>(io.normlist)})
            trifree(p);
    }
};

template <class T, class U>
std::vector<T> array(const U* data, std::size_t size, T offset = 0) {
    std::vector<T> out(size);
    for (std::size_t i = 0; i < size; ++i) out[i] = static_cast<T>(data[i]) - offset;
    return out;
}

// The invariant checker on the mesh triangulate() returned (0-based).
std::vector<std::string> check(const triangulateio& out, bool delaunay) {
    std::vector<geometry::Point> points;
    for (int v = 0; v < out.numberofpoints; ++v)
        points.push_back({out.pointlist[2 * v], out.pointlist[2 * v + 1]});
    const auto corners = array<std::uint32_t>(
        out.trianglelist, std::size_t(out.numberoftriangles) * out.numberofcorners);
    const auto segments =
        array<std::uint32_t>(out.segmentlist, 2 * std::size_t(out.numberofsegments));
    triangulate::TriangleMeshInput input;
    input.points = points;
    input.corners = corners;
    input.corners_per_triangle = static_cast<std::uint32_t>(out.numberofcorners);
    input.segments = segments;
    triangulate::TriangleMeshReport report;
    const mesh::Mesh mesh = triangulate::from_triangles(input, report);
    CHECK(report.missing_segments.empty());
    mesh::CheckOptions options;
    options.delaunay = delaunay;
    return mesh::check_mesh(mesh, options);
}

}  // namespace

TEST_CASE("triangulate() and the gpdr program make the same mesh", "[capi]") {
    const std::string sample = GENERATE("pipe", "flow");
    const std::string switches = GENERATE("pq30a40", "pq25Aen", "pDcv", "pq28o2");
    CAPTURE(sample, switches);

    test::TempDir dir;
    std::filesystem::copy_file(samples + sample + ".poly", dir / (sample + ".poly"));
    const auto run = test::run_program(dir, GPDR_EXE, "-Qj1" + switches + " " + sample + ".poly");
    REQUIRE(run.status == 0);
    const std::string base = (dir / (sample + ".1")).string();
    // The program numbers its files as the input file does (from 1).
    const auto node_file = io::read_node(base + ".node", ignore_warning);
    const NodeSet& nodes = node_file.data;
    const int first = node_file.base;
    const EleSet ele = io::read_ele(base + ".ele", first, nodes.size(), ignore_warning).data;
    const PolyFile out_poly = io::read_poly(base + ".poly", ignore_warning).data;

    // The same input, as a C program hands it over (0-based: z).
    const PolyFile poly = io::read_poly(samples + sample + ".poly", ignore_warning).data;
    std::vector<double> xy = poly.nodes.xy;
    std::vector<int> markers = poly.nodes.markers;
    std::vector<int> segments =
        array<int>(poly.segments.endpoints.data(), poly.segments.endpoints.size());
    std::vector<int> segment_markers = poly.segments.markers;
    std::vector<double> holes = poly.holes;
    std::vector<double> regions;
    for (const Region& r : poly.regions)
        regions.insert(regions.end(), {r.x, r.y, r.attribute, r.max_area});
    triangulateio in{};
    in.pointlist = xy.data();
    in.numberofpoints = static_cast<int>(poly.nodes.size());
    in.pointmarkerlist = markers.empty() ? nullptr : markers.data();
    in.segmentlist = segments.data();
    in.segmentmarkerlist = segment_markers.empty() ? nullptr : segment_markers.data();
    in.numberofsegments = static_cast<int>(poly.segments.size());
    in.holelist = holes.empty() ? nullptr : holes.data();
    in.numberofholes = static_cast<int>(holes.size() / 2);
    in.regionlist = regions.empty() ? nullptr : regions.data();
    in.numberofregions = static_cast<int>(poly.regions.size());

    Output out, vor;
    std::string library_switches = "Qz" + switches;
    REQUIRE(::triangulate(library_switches.data(), &in, &out.io, &vor.io) == 0);

    CHECK(array<double>(out.io.pointlist, 2 * nodes.size()) == nodes.xy);
    CHECK(std::size_t(out.io.numberofpoints) == nodes.size());
    CHECK(array<int>(out.io.pointmarkerlist, nodes.size()) == nodes.markers);
    CHECK(std::uint32_t(out.io.numberofcorners) == ele.corners_per_triangle);
    CHECK(std::size_t(out.io.numberoftriangles) == ele.size());
    CHECK(array<std::uint32_t>(out.io.trianglelist, ele.corners.size()) == ele.corners);
    CHECK(std::uint32_t(out.io.numberoftriangleattributes) == ele.attribute_count);
    CHECK(array<double>(out.io.triangleattributelist, ele.attributes.size()) == ele.attributes);
    CHECK(std::size_t(out.io.numberofsegments) == out_poly.segments.size());
    CHECK(array<std::uint32_t>(out.io.segmentlist, out_poly.segments.endpoints.size()) ==
          out_poly.segments.endpoints);
    CHECK(array<int>(out.io.segmentmarkerlist, out_poly.segments.size()) ==
          out_poly.segments.markers);
    if (switches.find('e') != std::string::npos) {
        const EdgeSet edges =
            io::read_edge(base + ".edge", first, nodes.size(), ignore_warning).data;
        CHECK(std::size_t(out.io.numberofedges) == edges.size());
        CHECK(array<std::uint32_t>(out.io.edgelist, edges.endpoints.size()) == edges.endpoints);
        CHECK(array<int>(out.io.edgemarkerlist, edges.size()) == edges.markers);
    }
    if (switches.find('n') != std::string::npos) {
        const NeighbourSet n =
            io::read_neigh(base + ".neigh", first, ele.size(), ignore_warning).data;
        CHECK(array<std::uint32_t>(out.io.neighborlist, n.neighbours.size()) == n.neighbours);
    }
    if (switches.find('v') != std::string::npos) {
        const NodeSet vnodes = io::read_node(base + ".v.node", ignore_warning).data;
        const auto vedges =
            io::read_voronoi_edge(base + ".v.edge", first, vnodes.size(), ignore_warning).data;
        CHECK(array<double>(vor.io.pointlist, vnodes.xy.size()) == vnodes.xy);
        CHECK(array<std::uint32_t>(vor.io.edgelist, vedges.endpoints.size()) == vedges.endpoints);
        CHECK(array<double>(vor.io.normlist, vedges.directions.size()) == vedges.directions);
    }

    // -D promises a Delaunay mesh; a quality mesh is constrained Delaunay,
    // which the checker does not test, so only its structure is checked.
    const bool delaunay = switches.find('D') != std::string::npos;
    CHECK(check(out.io, delaunay).empty());
}
