// Readers of the files that describe a mesh over known vertices: .ele,
// .area, .edge, .neigh and the Voronoi .v.edge (Triangle 1.6's formats, see
// docs/file-formats.md).  Defaults follow Triangle: an .ele
// header without corner or attribute count means 3 and 0, a missing triangle
// attribute is 0, an .area line without a value means no bound (-1).  Every
// index is checked against the numbering base and the list it points into.

#include <string>

#include <fmt/format.h>
#include <gpdr/io.hpp>

#include "io/read_common.hpp"
#include "io/text_reader.hpp"

namespace gpdr::io {

using detail::IdChecker;
using detail::TextReader;

namespace {

// Reads an entry's id; the first one is the base the file itself uses.
std::int64_t entry_id(TextReader& in, IdChecker& ids, std::size_t k, int& seen_base,
                      std::string_view what, const WarningSink& warn) {
    const std::int64_t id = in.integer(what);
    if (k == 0 && (id == 0 || id == 1)) seen_base = static_cast<int>(id);
    ids.check(in, id, k, warn);
    return id;
}

void header_line(TextReader& in, std::string_view layout) {
    if (!in.next_line()) in.fail(fmt::format("no data: expected the header '{}'", layout));
}

void next_entry(TextReader& in, std::size_t expected, std::size_t k, std::string_view entries) {
    if (!in.next_line()) in.fail(fmt::format("expected {} {}, found {}", expected, entries, k));
}

}  // namespace

ReadResult<EleSet> read_ele(const std::string& path, int base, std::size_t vertex_count,
                            const WarningSink& warn) {
    TextReader in(path);
    header_line(in, "<#triangles> <nodes per triangle> <#attributes>");
    const std::size_t count = in.count("triangle count");
    detail::check_index_capacity(in, count, "triangles");
    const std::int64_t corners = in.integer_or(3, "nodes per triangle");
    if (corners != 3 && corners != 6)
        in.fail(fmt::format("nodes per triangle must be 3 or 6, not {}", corners));
    ReadResult<EleSet> r;
    r.base = base;
    EleSet& ele = r.data;
    ele.corners_per_triangle = static_cast<std::uint32_t>(corners);
    ele.attribute_count = detail::attribute_count(in, count, "triangle attribute count");

    const std::size_t expect = in.reserve_hint(count, 2 * std::size_t(corners + 1));
    ele.corners.reserve(expect * ele.corners_per_triangle);
    ele.attributes.reserve(in.reserve_hint(expect * ele.attribute_count, 2));
    IdChecker ids("triangle", base);
    for (std::size_t k = 0; k < count; ++k) {
        next_entry(in, count, k, "triangles");
        entry_id(in, ids, k, r.base, "triangle number", warn);
        for (std::uint32_t c = 0; c < ele.corners_per_triangle; ++c)
            ele.corners.push_back(detail::vertex_index(in, base, vertex_count, "triangle vertex"));
        for (std::uint32_t a = 0; a < ele.attribute_count; ++a)
            ele.attributes.push_back(in.real_or(0.0, "triangle attribute"));
    }
    r.content_hash = in.finish();
    return r;
}

ReadResult<AreaSet> read_area(const std::string& path, int base, std::size_t triangle_count,
                              const WarningSink& warn) {
    TextReader in(path);
    header_line(in, "<#triangles>");
    const std::size_t count = in.count("triangle count");
    if (count != triangle_count)
        in.fail(fmt::format("{} triangles, but the .ele file has {}", count, triangle_count));
    ReadResult<AreaSet> r;
    r.base = base;
    r.data.reserve(in.reserve_hint(count, 2));
    IdChecker ids("triangle", base);
    for (std::size_t k = 0; k < count; ++k) {
        next_entry(in, count, k, "area bounds");
        entry_id(in, ids, k, r.base, "triangle number", warn);
        r.data.push_back(in.real_or(-1.0, "maximum area"));
    }
    r.content_hash = in.finish();
    return r;
}

ReadResult<EdgeSet> read_edge(const std::string& path, int base, std::size_t vertex_count,
                              const WarningSink& warn) {
    TextReader in(path);
    header_line(in, "<#edges> <#markers>");
    const std::size_t count = in.count("edge count");
    const bool markers = detail::marker_count(in, "edge marker count");
    ReadResult<EdgeSet> r;
    r.base = base;
    const std::size_t expect = in.reserve_hint(count, 6);
    r.data.endpoints.reserve(2 * expect);
    if (markers) r.data.markers.reserve(expect);
    IdChecker ids("edge", base);
    for (std::size_t k = 0; k < count; ++k) {
        next_entry(in, count, k, "edges");
        entry_id(in, ids, k, r.base, "edge number", warn);
        const auto a = detail::vertex_index(in, base, vertex_count, "edge endpoint");
        const auto b = detail::vertex_index(in, base, vertex_count, "edge endpoint");
        if (a == b)
            in.warn(warn, fmt::format("edge with both endpoints at vertex {}",
                                      static_cast<std::int64_t>(a) + base));
        r.data.endpoints.push_back(a);
        r.data.endpoints.push_back(b);
        if (markers) r.data.markers.push_back(detail::marker(in, "edge marker"));
    }
    r.content_hash = in.finish();
    return r;
}

ReadResult<NeighbourSet> read_neigh(const std::string& path, int base, std::size_t triangle_count,
                                    const WarningSink& warn) {
    TextReader in(path);
    header_line(in, "<#triangles> 3");
    const std::size_t count = in.count("triangle count");
    if (count != triangle_count)
        in.fail(fmt::format("{} triangles, but the .ele file has {}", count, triangle_count));
    const std::int64_t per = in.integer_or(3, "neighbours per triangle");
    if (per != 3) in.fail(fmt::format("neighbours per triangle must be 3, not {}", per));
    ReadResult<NeighbourSet> r;
    r.base = base;
    r.data.neighbours.reserve(3 * in.reserve_hint(count, 8));
    IdChecker ids("triangle", base);
    for (std::size_t k = 0; k < count; ++k) {
        next_entry(in, count, k, "triangles");
        entry_id(in, ids, k, r.base, "triangle number", warn);
        for (int j = 0; j < 3; ++j) {
            // -1 (no neighbour) is the only value outside the numbering.
            const std::int64_t n = in.integer("neighbour");
            r.data.neighbours.push_back(n == -1 ? NeighbourSet::none
                                                : detail::checked_index(in, n, base, triangle_count,
                                                                        "neighbour", "triangles"));
        }
    }
    r.content_hash = in.finish();
    return r;
}

ReadResult<VoronoiEdgeSet> read_voronoi_edge(const std::string& path, int base,
                                             std::size_t vertex_count, const WarningSink& warn) {
    TextReader in(path);
    header_line(in, "<#edges> <#markers>");
    const std::size_t count = in.count("edge count");
    detail::marker_count(in, "edge marker count");  // Triangle writes 0; markers are not read
    ReadResult<VoronoiEdgeSet> r;
    r.base = base;
    const std::size_t expect = in.reserve_hint(count, 6);
    r.data.endpoints.reserve(2 * expect);
    r.data.directions.reserve(2 * expect);
    IdChecker ids("edge", base);
    for (std::size_t k = 0; k < count; ++k) {
        next_entry(in, count, k, "edges");
        entry_id(in, ids, k, r.base, "edge number", warn);
        r.data.endpoints.push_back(detail::vertex_index(in, base, vertex_count, "edge endpoint"));
        const std::int64_t b = in.integer("edge endpoint");
        if (b == -1) {
            // A ray: "<i> <a> -1 <dx> <dy>".
            r.data.endpoints.push_back(VoronoiEdgeSet::ray);
            const double dx = in.real("ray direction x");
            const double dy = in.real("ray direction y");
            if (dx == 0 && dy == 0) in.fail("ray direction is zero");
            r.data.directions.push_back(dx);
            r.data.directions.push_back(dy);
        } else {
            r.data.endpoints.push_back(
                detail::checked_index(in, b, base, vertex_count, "edge endpoint", "vertices"));
            r.data.directions.push_back(0.0);
            r.data.directions.push_back(0.0);
        }
    }
    r.content_hash = in.finish();
    return r;
}

}  // namespace gpdr::io
