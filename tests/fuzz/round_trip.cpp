// Write-then-read round trips of the readers' results (round_trip.hpp).

#include "fuzz/round_trip.hpp"

#include <string>

#include <gpdr/errors.hpp>

#include "fuzz/fuzz_checks.hpp"
#include "fuzz/scratch_files.hpp"

namespace gpdr::fuzz {
namespace {

bool same(const NodeSet& a, const NodeSet& b) {
    return a.xy == b.xy && a.attribute_count == b.attribute_count && a.attributes == b.attributes &&
           a.markers == b.markers;
}

bool same(const SegmentSet& a, const SegmentSet& b) {
    return a.endpoints == b.endpoints && a.markers == b.markers;
}

bool same(const std::vector<Region>& a, const std::vector<Region>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].x != b[i].x || a[i].y != b[i].y || a[i].attribute != b[i].attribute ||
            a[i].max_area != b[i].max_area)
            return false;
    return true;
}

// Writes one file through an output transaction, as a run writes it.
template <class Write>
std::string write_one(std::string_view name, int base, Write write) {
    const std::string path = scratch_path(name);
    io::WriteFormat format;
    format.base = base;
    format.command = "gpdr fuzz";
    io::OutputTransaction out;
    write(out, path, format);
    out.commit();
    return path;
}

// Reads a file the writer wrote: any InputError is a finding.
template <class Read>
auto read_back(std::string_view kind, Read read) {
    try {
        return read();
    } catch (const InputError& e) {
        fail(std::string(kind) + " written by the writer does not read back: " + e.what());
    }
}

}  // namespace

void expect_node_round_trip(const io::ReadResult<NodeSet>& read) {
    const std::string path = write_one("out.node", read.base, [&](auto& out, auto& p, auto& f) {
        io::write_node(out, p, read.data, f);
    });
    const auto again =
        read_back(".node", [&] { return io::read_node(path, ignore_warning, read.base); });
    expect(again.base == read.base, ".node round trip changed the numbering base");
    expect(same(again.data, read.data), ".node round trip changed the vertices");
}

void expect_poly_round_trip(const io::ReadResult<PolyFile>& read) {
    const PolyFile& poly = read.data;
    // A .poly without vertices of its own is written with the count 0 and
    // reads them from the .node of the same name.
    if (poly.nodes_from_node_file)
        write_one("out.node", read.base,
                  [&](auto& out, auto& p, auto& f) { io::write_node(out, p, poly.nodes, f); });
    const std::string path = write_one("out.poly", read.base, [&](auto& out, auto& p, auto& f) {
        io::write_poly(out, p, poly, f);
    });
    const auto again =
        read_back(".poly", [&] { return io::read_poly(path, ignore_warning, read.base); });
    expect(again.base == read.base, ".poly round trip changed the numbering base");
    expect(again.data.nodes_from_node_file == poly.nodes_from_node_file,
           ".poly round trip changed where the vertices come from");
    expect(same(again.data.nodes, poly.nodes), ".poly round trip changed the vertices");
    expect(same(again.data.segments, poly.segments), ".poly round trip changed the segments");
    expect(again.data.holes == poly.holes, ".poly round trip changed the holes");
    expect(same(again.data.regions, poly.regions), ".poly round trip changed the regions");
    remove_scratch_file("out.node");
}

void expect_ele_round_trip(const io::ReadResult<EleSet>& read, int vertex_base,
                           std::size_t vertex_count) {
    // The triangles number from the file's own first index; the writer
    // numbers triangles and corners alike, so the round trip keeps the
    // corners' base, and the triangles' base becomes that.
    const std::string path = write_one("out.ele", vertex_base, [&](auto& out, auto& p, auto& f) {
        io::write_ele(out, p, read.data, f);
    });
    const auto again = read_back(
        ".ele", [&] { return io::read_ele(path, vertex_base, vertex_count, ignore_warning); });
    const EleSet& a = again.data;
    const EleSet& b = read.data;
    expect(a.corners_per_triangle == b.corners_per_triangle && a.corners == b.corners &&
               a.attribute_count == b.attribute_count && a.attributes == b.attributes,
           ".ele round trip changed the triangles");
}

void expect_area_round_trip(const AreaSet& areas, int base) {
    const std::string path = write_one(
        "out.area", base, [&](auto& out, auto& p, auto& f) { io::write_area(out, p, areas, f); });
    const auto again =
        read_back(".area", [&] { return io::read_area(path, base, areas.size(), ignore_warning); });
    expect(again.data.size() == areas.size(), ".area round trip changed the count");
    for (std::size_t i = 0; i < areas.size(); ++i) {
        // A bound of 0 or less means none, whichever way it is written.
        const bool none = areas[i] <= 0 && again.data[i] <= 0;
        expect(none || again.data[i] == areas[i], ".area round trip changed a bound");
    }
}

}  // namespace gpdr::fuzz
