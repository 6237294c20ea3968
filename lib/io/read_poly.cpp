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
#include "io/read_common.hpp"
#include "io/text_reader.hpp"

namespace gpdr::io {

using detail::IdChecker;
using detail::TextReader;

namespace {

// The header of a vertex list: "<#vertices> <dimension> <#attributes> <#markers>".
struct NodeHeader {
    std::size_t count = 0;
    std::uint32_t attributes = 0;
    bool markers = false;
    std::size_t line = 0;
};

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
                      const WarningSink& warn) {
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
                in.warn(warn, fmt::format("first vertex number {} is neither 0 nor 1; numbering "
                                          "from {}",
                                          id, default_base));
            }
            ids = IdChecker("vertex", base);
            if (id != base) ids.silence();
        }
        ids.check(in, id, k, warn);
        nodes.xy.push_back(in.real("x coordinate"));
        nodes.xy.push_back(in.real("y coordinate"));
        for (std::uint32_t a = 0; a < h.attributes; ++a)
            nodes.attributes.push_back(in.real_or(0.0, "vertex attribute"));
        if (h.markers) nodes.markers.push_back(detail::marker(in, "vertex marker"));
    }
    return nodes;
}

ReadResult<NodeSet> read_node_impl(const std::string& path, std::string_view why_needed,
                                   const WarningSink& warn, int default_base) {
    TextReader in(path, why_needed);
    const NodeHeader h = read_node_header(in);
    ReadResult<NodeSet> r;
    r.data = read_vertices(in, h, default_base, r.base, warn);
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

ReadResult<NodeSet> read_node(const std::string& path, const WarningSink& warn, int default_base) {
    return read_node_impl(path, {}, warn, default_base);
}

ReadResult<PolyFile> read_poly(const std::string& path, const WarningSink& warn, int default_base) {
    TextReader in(path);
    ReadResult<PolyFile> r;
    PolyFile& poly = r.data;

    const NodeHeader h = read_node_header(in);
    if (h.count == 0) {
        // Triangle's convention: the vertices live in the .node file beside it.
        const std::string node_path = node_file_for(path);
        auto nodes = read_node_impl(
            node_path,
            fmt::format("{} line {} has vertex count 0, which takes the vertices from {}", path,
                        h.line, node_path),
            warn, default_base);
        poly.nodes = std::move(nodes.data);
        poly.nodes_from_node_file = true;
        r.base = nodes.base;
        r.content_hash = nodes.content_hash;
    } else {
        poly.nodes = read_vertices(in, h, default_base, r.base, warn);
    }
    const std::size_t vertex_count = poly.nodes.size();

    // Segments: "<#segments> <#markers>", then "<i> <a> <b> [marker]".
    if (!in.next_line())
        in.fail("expected the segment header '<#segments> <#markers>', found the end of the file");
    const std::size_t segment_count = in.count("segment count");
    const bool segment_markers = detail::marker_count(in, "segment marker count");
    const std::size_t expect = in.reserve_hint(segment_count, 6);
    poly.segments.endpoints.reserve(2 * expect);
    if (segment_markers) poly.segments.markers.reserve(expect);
    IdChecker segment_ids("segment", r.base);
    for (std::size_t k = 0; k < segment_count; ++k) {
        if (!in.next_line())
            in.fail(fmt::format("expected {} segments, found {}", segment_count, k));
        segment_ids.check(in, in.integer("segment number"), k, warn);
        const auto a = detail::vertex_index(in, r.base, vertex_count, "segment endpoint");
        const auto b = detail::vertex_index(in, r.base, vertex_count, "segment endpoint");
        if (a == b)
            in.warn(warn, fmt::format("segment with both endpoints at vertex {}",
                                      static_cast<std::int64_t>(a) + r.base));
        poly.segments.endpoints.push_back(a);
        poly.segments.endpoints.push_back(b);
        if (segment_markers) poly.segments.markers.push_back(detail::marker(in, "segment marker"));
    }

    // Holes: "<#holes>", then "<i> <x> <y>".
    if (!in.next_line()) in.fail("expected the number of holes, found the end of the file");
    const std::size_t hole_count = in.count("hole count", 6);
    poly.holes.reserve(2 * in.reserve_hint(hole_count, 6));
    IdChecker hole_ids("hole", r.base);
    for (std::size_t k = 0; k < hole_count; ++k) {
        if (!in.next_line()) in.fail(fmt::format("expected {} holes, found {}", hole_count, k));
        hole_ids.check(in, in.integer("hole number"), k, warn);
        poly.holes.push_back(in.real("hole x coordinate"));
        poly.holes.push_back(in.real("hole y coordinate"));
    }

    // Regions (optional): "<#regions>", then "<i> <x> <y> <attribute> <max area>".
    if (in.next_line()) {
        const std::size_t region_count = in.count("region count", 8);
        poly.regions.reserve(in.reserve_hint(region_count, 8));
        IdChecker region_ids("region", r.base);
        for (std::size_t k = 0; k < region_count; ++k) {
            if (!in.next_line())
                in.fail(fmt::format("expected {} regions, found {}", region_count, k));
            region_ids.check(in, in.integer("region number"), k, warn);
            Region reg;
            reg.x = in.real("region x coordinate");
            reg.y = in.real("region y coordinate");
            reg.attribute = in.real("region attribute");
            // One value after x y: Triangle uses it for both attribute and area bound.
            reg.max_area = in.real_or(reg.attribute, "region maximum area");
            poly.regions.push_back(reg);
        }
        if (in.next_line()) in.warn(warn, "data after the region list is ignored");
    }
    r.content_hash = hash_number(r.content_hash, in.finish());
    return r;
}

}  // namespace gpdr::io
