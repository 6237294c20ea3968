// The -rp round trip through real files: a .poly read with gpdr::io, its
// constrained Delaunay triangulation written as .node/.ele/.poly with
// gpdr::io, read back and rebuilt with triangulate::from_triangles, gives the
// same triangles (canonical form) and the same subsegments (with Triangle's
// rule that a boundary subsegment's marker 0 reads back as 1).

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gpdr/io.hpp>

#include "check/checker.hpp"
#include "cli/cli_support.hpp"
#include "mesh/traverse.hpp"
#include "triangulate/constrained.hpp"
#include "triangulate/from_triangles.hpp"

using namespace gpdr;
using namespace gpdr::mesh;
namespace fs = std::filesystem;

namespace {

using Tri = std::array<std::uint32_t, 3>;
using Sub = std::tuple<std::uint32_t, std::uint32_t, int>;  // low vertex, high vertex, marker

std::vector<Tri> canonical(const Mesh& m) {
    std::vector<Tri> out;
    for_each_triangle(m, [&](TriangleId, const Triangle& t) {
        Tri r{index(t.v[0]), index(t.v[1]), index(t.v[2])};
        std::rotate(r.begin(), std::min_element(r.begin(), r.end()), r.end());
        out.push_back(r);
    });
    std::sort(out.begin(), out.end());
    return out;
}

// Subsegments as they must read back: every boundary edge is one (marker
// 1 unless its own marker is non-zero), interior ones keep their marker.
std::set<Sub> expected_subsegments(const Mesh& m) {
    std::set<Sub> out;
    for_each_edge(m, [&](const EdgeView& e) {
        const std::uint32_t lo = std::min(index(e.from), index(e.to)),
                            hi = std::max(index(e.from), index(e.to));
        const SubsegmentInfo* info = e.subsegment ? m.subsegments().find(e.from, e.to) : nullptr;
        int marker = info ? info->marker : 0;
        if (e.hull && marker == 0) marker = 1;
        if (info || e.hull) out.insert({lo, hi, marker});
    });
    return out;
}

std::set<Sub> subsegments(const Mesh& m) {
    std::set<Sub> out;
    m.subsegments().for_each([&](VertexId a, VertexId b, const SubsegmentInfo& info) {
        out.insert({std::min(index(a), index(b)), std::max(index(a), index(b)), info.marker});
    });
    return out;
}

// -p and -pc; a PSLG whose segments enclose nothing (box_hole.poly without -c)
// has no mesh to write and is skipped.
void round_trip(const fs::path& input, bool convex_hull) {
    INFO(input.string() << (convex_hull ? " with -c" : ""));
    const auto poly = io::read_poly(input.string(), ignore_warning);
    const triangulate::Pslg pslg = triangulate::pslg_from(poly.data);
    triangulate::CdtReport cdt_report;
    triangulate::CdtOptions cdt_options;
    cdt_options.convex_hull = convex_hull;
    const Mesh original = triangulate::constrained_delaunay(pslg, cdt_options, cdt_report);
    REQUIRE(check_mesh(original).empty());
    if (original.count_triangles() == 0) return;

    // The mesh as Triangle's files: every stored vertex, the live triangles,
    // the subsegments (vertices from the .node file).
    NodeSet nodes;
    for (std::uint32_t v = 0; v < original.vertex_end(); ++v) {
        nodes.xy.push_back(original.point(VertexId{v}).x);
        nodes.xy.push_back(original.point(VertexId{v}).y);
    }
    EleSet triangles;
    for_each_triangle(original, [&](TriangleId, const Triangle& t) {
        for (VertexId v : t.v) triangles.corners.push_back(index(v));
    });
    PolyFile out_poly;
    out_poly.nodes_from_node_file = true;
    original.subsegments().for_each([&](VertexId a, VertexId b, const SubsegmentInfo& info) {
        out_poly.segments.endpoints.push_back(index(a));
        out_poly.segments.endpoints.push_back(index(b));
        out_poly.segments.markers.push_back(info.marker);
    });
    const int base = poly.base;
    test::TempDir dir;
    const std::string stem = (dir / "mesh.1").string();
    {
        io::OutputTransaction tx;
        const io::WriteFormat format{base, true, "refine_round_trip_test"};
        io::write_node(tx, stem + ".node", nodes, format);
        io::write_ele(tx, stem + ".ele", triangles, format);
        io::write_poly(tx, stem + ".poly", out_poly, format);
        tx.commit();
    }

    // Read back as -rp reads them, and rebuild.
    const auto node_back = io::read_node(stem + ".node", ignore_warning);
    const auto ele_back =
        io::read_ele(stem + ".ele", node_back.base, node_back.data.size(), ignore_warning);
    const auto poly_back = io::read_poly(stem + ".poly", ignore_warning);
    CHECK(node_back.base == base);
    std::vector<geometry::Point> points;
    for (std::size_t i = 0; i < node_back.data.size(); ++i)
        points.push_back({node_back.data.xy[2 * i], node_back.data.xy[2 * i + 1]});
    triangulate::TriangleMeshInput in;
    in.points = points;
    in.corners = ele_back.data.corners;
    in.corners_per_triangle = ele_back.data.corners_per_triangle;
    in.segments = poly_back.data.segments.endpoints;
    in.segment_markers = poly_back.data.segments.markers;
    in.index_base = base;
    triangulate::TriangleMeshReport report;
    const Mesh rebuilt = triangulate::from_triangles(in, report);

    CHECK(check_mesh(rebuilt).empty());  // a CDT read back is still one
    CHECK(canonical(rebuilt) == canonical(original));
    CHECK(subsegments(rebuilt) == expected_subsegments(original));
    CHECK(report.missing_segments.empty());
    CHECK(report.segments_flagged == out_poly.segments.size());
    const std::set<std::uint32_t> used(triangles.corners.begin(), triangles.corners.end());
    CHECK(report.unused_vertices == original.vertex_end() - used.size());
}

}  // namespace

TEST_CASE("switch -rp round trip: the project's samples", "[api][refine]") {
    for (const char* name : {"flow.poly", "pipe.poly"})
        for (bool hull : {false, true}) round_trip(test::project_samples() / name, hull);
}

TEST_CASE("switch -rp round trip: the test data samples", "[api][refine]") {
    std::size_t tried = 0;
    for (const auto& entry : fs::directory_iterator(test::test_data()))
        if (entry.path().extension() == ".poly") {
            for (bool hull : {false, true}) round_trip(entry.path(), hull);
            ++tried;
        }
    CHECK(tried > 0);
}
