// Readers of .node and .poly files (Triangle 1.6's formats, as described in
// docs/file-formats.md).  Missing optional values take Triangle's
// defaults: header dimension 2, no attributes, no markers; a missing vertex
// attribute or marker is 0; a region line with one value after x y uses it
// as both attribute and area bound (Triangle does the same).  Where Triangle
// prints a warning and skips (a segment endpoint out of range) gpdr refuses
// the file instead: a silently dropped boundary gives a wrong mesh.

#include <limits>
#include <string>

#include <fmt/format.h>
#include <gpdr/io.hpp>

#include "io/content_hash.hpp"
#include "io/parallel_vertices.hpp"
#include "io/read_common.hpp"
#include "io/read_settings.hpp"
#include "io/text_reader.hpp"
#include "io/vertex_lines.hpp"

namespace gpdr::io {

using detail::IdChecker;
using detail::NodeHeader;
using detail::ReadSettings;
using detail::TextReader;

namespace {

NodeHeader read_node_header(TextReader& in) {
    if (!in.next_line())
        in.fail("no data: expected the header '<#vertices> <dimension> <#attributes> <#markers>'");
    NodeHeader h;
    h.line = in.line();
    h.count = in.count("vertex count");
    detail::check_index_capacity(in, h.count, "vertices");
    const std::int64_t dim = in.integer_or(2, "dimension");
    if (dim != 2)
        in.fail(fmt::format("dimension {} is not supported: gpdr meshes in 2 dimensions", dim));
    h.attributes = detail::attribute_count(in, h.count, "vertex attribute count");
    h.markers = detail::marker_count(in, "vertex marker count");
    return h;
}

// Reads the vertices announced by `h`.  The first vertex's index sets the
// numbering base of the run (0 or 1); any other first index keeps the
// default, as in Triangle.
NodeSet read_vertices(TextReader& in, const NodeHeader& h, int default_base, int& base,
                      const WarningSink& warn, const ReadSettings& settings) {
    if (h.count > 0 && detail::vertex_slices(in, settings) > 1)
        return detail::read_vertices_in_parallel(in, h, default_base, base, warn, settings);
    NodeSet nodes;
    nodes.attribute_count = h.attributes;
    const std::size_t expect = in.reserve_hint(h.count, 6);
    nodes.xy.reserve(2 * expect);
    nodes.attributes.reserve(in.reserve_hint(expect * h.attributes, 2));
    if (h.markers) nodes.markers.reserve(expect);
    base = default_base;
    IdChecker ids("vertex", base);
    for (std::size_t k = 0; k < h.count; ++k) {
        if (!in.next_line()) in.fail(fmt::format("expected {} vertices, found {}", h.count, k));
        const std::int64_t id = in.integer("vertex number");
        if (k == 0) {
            if (id == 0 || id == 1) {
                base = static_cast<int>(id);
            } else {
                in.warn(warn, detail::odd_first_id_message(id, default_base));
            }
            ids = IdChecker("vertex", base);
            if (id != base) ids.silence();
        }
        ids.check(in, id, k, warn);
        detail::read_vertex_fields(in, h, nodes);
    }
    return nodes;
}

ReadResult<NodeSet> read_node_impl(const std::string& path, std::string_view why_needed,
                                   const WarningSink& warn, int default_base,
                                   const ReadSettings& settings) {
    TextReader in(path, why_needed);
    const NodeHeader h = read_node_header(in);
    ReadResult<NodeSet> r;
    r.data = read_vertices(in, h, default_base, r.base, warn, settings);
    r.content_hash = in.finish();
    return r;
}

std::string node_file_for(const std::string& poly_path) {
    constexpr std::string_view ext = ".poly";
    if (poly_path.size() > ext.size() &&
        poly_path.compare(poly_path.size() - ext.size(), ext.size(), ext) == 0)
        return poly_path.substr(0, poly_path.size() - ext.size()) + ".node";
    return poly_path + ".node";
}

}  // namespace

ReadResult<NodeSet> read_node(const std::string& path, const WarningSink& warn, int default_base,
                              unsigned threads) {
    return read_node_impl(path, {}, warn, default_base, ReadSettings{threads});
}

ReadResult<NodeSet> detail::read_node_with(const std::string& path, const WarningSink& warn,
                                           int default_base, const ReadSettings& settings) {
    return read_node_impl(path, {}, warn, default_base, settings);
}

namespace {

// The .poly's vertices: its own list, or with a vertex count of 0
// (Triangle's convention) those of the .node beside it, read here unless
// the caller has them (`known`).  Sets r's base and starts its content hash.
void read_poly_vertices(TextReader& in, const std::string& path, const WarningSink& warn,
                        int default_base, const KnownNodes* known, const ReadSettings& settings,
                        ReadResult<PolyFile>& r, std::size_t& vertex_count) {
    PolyFile& poly = r.data;
    const NodeHeader h = read_node_header(in);
    if (h.count != 0) {
        poly.nodes = read_vertices(in, h, default_base, r.base, warn, settings);
        vertex_count = poly.nodes.size();
        return;
    }
    poly.nodes_from_node_file = true;
    if (known != nullptr) {
        r.base = known->base;
        r.content_hash = known->content_hash;
        vertex_count = known->count;
        return;
    }
    const std::string node_path = node_file_for(path);
    auto nodes = read_node_impl(
        node_path,
        fmt::format("{} line {} has vertex count 0, which takes the vertices from {}", path, h.line,
                    node_path),
        warn, default_base, settings);
    poly.nodes = std::move(nodes.data);
    r.base = nodes.base;
    r.content_hash = nodes.content_hash;
    vertex_count = poly.nodes.size();
}

// Segments: "<#segments> <#markers>", then "<i> <a> <b> [marker]".
void read_poly_segments(TextReader& in, int base, std::size_t vertex_count, const WarningSink& warn,
                        SegmentSet& segments) {
    if (!in.next_line())
        in.fail("expected the segment header '<#segments> <#markers>', found the end of the file");
    const std::size_t count = in.count("segment count");
    const bool markers = detail::marker_count(in, "segment marker count");
    const std::size_t expect = in.reserve_hint(count, 6);
    segments.endpoints.reserve(2 * expect);
    if (markers) segments.markers.reserve(expect);
    IdChecker ids("segment", base);
    for (std::size_t k = 0; k < count; ++k) {
        if (!in.next_line()) in.fail(fmt::format("expected {} segments, found {}", count, k));
        ids.check(in, in.integer("segment number"), k, warn);
        const auto a = detail::vertex_index(in, base, vertex_count, "segment endpoint");
        const auto b = detail::vertex_index(in, base, vertex_count, "segment endpoint");
        if (a == b)
            in.warn(warn, fmt::format("segment with both endpoints at vertex {}",
                                      static_cast<std::int64_t>(a) + base));
        segments.endpoints.push_back(a);
        segments.endpoints.push_back(b);
        if (markers) segments.markers.push_back(detail::marker(in, "segment marker"));
    }
}

// Holes: "<#holes>", then "<i> <x> <y>".
void read_poly_holes(TextReader& in, int base, const WarningSink& warn,
                     std::vector<double>& holes) {
    if (!in.next_line()) in.fail("expected the number of holes, found the end of the file");
    const std::size_t count = in.count("hole count", 6);
    holes.reserve(2 * in.reserve_hint(count, 6));
    IdChecker ids("hole", base);
    for (std::size_t k = 0; k < count; ++k) {
        if (!in.next_line()) in.fail(fmt::format("expected {} holes, found {}", count, k));
        ids.check(in, in.integer("hole number"), k, warn);
        holes.push_back(in.real("hole x coordinate"));
        holes.push_back(in.real("hole y coordinate"));
    }
}

// Regions (optional): "<#regions>", then "<i> <x> <y> <attribute> <max area>".
void read_poly_regions(TextReader& in, int base, const WarningSink& warn,
                       std::vector<Region>& regions) {
    if (!in.next_line()) return;
    const std::size_t count = in.count("region count", 8);
    regions.reserve(in.reserve_hint(count, 8));
    IdChecker ids("region", base);
    for (std::size_t k = 0; k < count; ++k) {
        if (!in.next_line()) in.fail(fmt::format("expected {} regions, found {}", count, k));
        ids.check(in, in.integer("region number"), k, warn);
        Region reg;
        reg.x = in.real("region x coordinate");
        reg.y = in.real("region y coordinate");
        reg.attribute = in.real("region attribute");
        // One value after x y: Triangle uses it for both attribute and area bound.
        reg.max_area = in.real_or(reg.attribute, "region maximum area");
        regions.push_back(reg);
    }
    if (in.next_line()) in.warn(warn, "data after the region list is ignored");
}

}  // namespace

ReadResult<PolyFile> read_poly(const std::string& path, const WarningSink& warn, int default_base,
                               const KnownNodes* known, unsigned threads) {
    return detail::read_poly_with(path, warn, default_base, known, ReadSettings{threads});
}

ReadResult<PolyFile> detail::read_poly_with(const std::string& path, const WarningSink& warn,
                                            int default_base, const KnownNodes* known,
                                            const ReadSettings& settings) {
    TextReader in(path);
    ReadResult<PolyFile> r;
    std::size_t vertex_count = 0;
    read_poly_vertices(in, path, warn, default_base, known, settings, r, vertex_count);
    read_poly_segments(in, r.base, vertex_count, warn, r.data.segments);
    read_poly_holes(in, r.base, warn, r.data.holes);
    read_poly_regions(in, r.base, warn, r.data.regions);
    r.content_hash = hash_number(r.content_hash, in.finish());
    return r;
}

}  // namespace gpdr::io
