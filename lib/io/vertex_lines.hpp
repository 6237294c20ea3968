#pragma once
// What the readers of .node and .poly files share about a vertex list: its
// header, the fields of one vertex line, and the warning about its first
// vertex number.  Read on one thread (read_poly.cpp) or on several
// (parallel_vertices.cpp), a line gives the same values and errors.

#include <cstddef>
#include <cstdint>
#include <string>

#include <fmt/format.h>
#include <gpdr/files.hpp>

#include "io/read_common.hpp"
#include "io/text_reader.hpp"

namespace gpdr::io::detail {

// The header of a vertex list: "<#vertices> <dimension> <#attributes> <#markers>".
struct NodeHeader {
    std::size_t count = 0;
    std::uint32_t attributes = 0;
    bool markers = false;
    std::size_t line = 0;
};

// The fields after the vertex number: x, y, the attributes (missing: 0)
// and the marker (missing: 0), appended to `nodes`.
inline void read_vertex_fields(TextReader& in, const NodeHeader& h, NodeSet& nodes) {
    nodes.xy.push_back(in.real("x coordinate"));
    nodes.xy.push_back(in.real("y coordinate"));
    for (std::uint32_t a = 0; a < h.attributes; ++a)
        nodes.attributes.push_back(in.real_or(0.0, "vertex attribute"));
    if (h.markers) nodes.markers.push_back(marker(in, "vertex marker"));
}

// The warning for a first vertex number that is neither 0 nor 1.
inline std::string odd_first_id_message(std::int64_t id, int default_base) {
    return fmt::format("first vertex number {} is neither 0 nor 1; numbering from {}", id,
                       default_base);
}

}  // namespace gpdr::io::detail
