// The .msh file: gmsh's MSH 4.1 in ASCII, as a solver that reads gmsh
// meshes expects it.  gmsh attaches every element to a geometric entity and
// names groups of entities "physical groups", which is how solvers find
// their boundaries and materials:
//
//   - each region (the triangles with one value of their first attribute,
//     -A) is a surface with a physical group of its own, named
//     "region <value>"; without attributes the one surface is "domain".
//     A region's physical tag is its attribute when every region's is a
//     whole number from 1 up, otherwise the regions are numbered 1, 2, ...
//     in increasing order of attribute;
//   - the segments are lines (3-node with six-node triangles, the middle
//     node last, as gmsh orders them), one curve per boundary marker, each
//     with a physical group named "boundary marker <m>" whose tag is the
//     marker when it is positive (gmsh's tags are), otherwise numbers after
//     the largest marker; without markers (-B) one curve, "segments".
//     Every entity has a group: readers such as meshio expect that.
//
// Nodes are numbered from 1 in the .node file's order (whatever -z says),
// triangles are elements 1 to M in the .ele file's order (written grouped
// by region, as gmsh requires elements of one entity to be together), and
// the lines follow as elements M+1 on.  Vertex markers and attributes go
// in $NodeData sections.  Six-node triangles are gmsh's type 9, midpoints
// in the order (1,2), (2,3), (3,1).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include <fmt/compile.h>
#include <fmt/format.h>
#include <gpdr/errors.hpp>
#include <gpdr/mesh_formats.hpp>

#include "io/output_file.hpp"

namespace gpdr::io {
namespace {

using File = OutputTransaction::File;
using Out = std::back_insert_iterator<fmt::memory_buffer>;

struct Group {
    int entity = 0;    // the entity's tag
    int physical = 0;  // its physical group's tag
    std::string name;
    std::size_t count = 0;  // elements
};

struct Box {
    double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
};

Box bounding_box(const NodeSet& nodes) {
    Box b;
    for (std::size_t v = 0; v < nodes.size(); ++v) {
        const double x = nodes.xy[2 * v], y = nodes.xy[2 * v + 1];
        if (v == 0) b = {x, y, x, y};
        b.min_x = std::min(b.min_x, x);
        b.min_y = std::min(b.min_y, y);
        b.max_x = std::max(b.max_x, x);
        b.max_y = std::max(b.max_y, y);
    }
    return b;
}

// The regions, by the first attribute of their triangles, in increasing
// order (one pass over the triangles).
std::map<double, Group> regions_of(const MeshExport& mesh) {
    std::map<double, Group> regions;
    EleSource source = mesh.triangles();
    std::vector<double> attributes(std::max<std::uint32_t>(source.attribute_count, 1), 0.0);
    std::uint32_t c[6];
    for (std::size_t t = 0; t < source.count; ++t) {
        source.next(c, attributes.data());
        ++regions[mesh.attribute_count > 0 ? attributes[0] : 0.0].count;
    }
    bool whole = mesh.attribute_count > 0;
    for (const auto& [value, group] : regions)
        whole = whole && value >= 1 && value < 2147483647.0 && std::floor(value) == value;
    int entity = 0;
    for (auto& [value, group] : regions) {
        group.entity = ++entity;
        group.physical = whole ? static_cast<int>(value) : entity;
        group.name = mesh.attribute_count > 0 ? fmt::format("region {}", value) : "domain";
    }
    return regions;
}

// The curves, by segment marker (all in one without markers).
std::map<int, Group> curves_of(const SegmentSet& segments, bool markers) {
    std::map<int, Group> curves;
    for (std::size_t s = 0; s < segments.size(); ++s)
        ++curves[markers ? segments.markers[s] : 0].count;
    int entity = 0;
    int next_tag = curves.empty() ? 1 : std::max(curves.rbegin()->first, 0) + 1;
    for (auto& [marker, group] : curves) {
        group.entity = ++entity;
        group.physical = !markers ? 1 : marker > 0 ? marker : next_tag++;
        group.name = markers ? fmt::format("boundary marker {}", marker) : "segments";
    }
    return curves;
}

// With six-node triangles, each segment's midpoint node: the node the
// triangle on the segment has opposite the corner facing it (one pass over
// the triangles).  A segment no triangle has (none, in a mesh gpdr made)
// would be an error.
std::vector<std::uint32_t> segment_midpoints(const MeshExport& mesh, const SegmentSet& segments) {
    constexpr std::uint32_t none = 0xffffffffu;
    const auto key = [](std::uint32_t a, std::uint32_t b) {
        return a < b ? std::uint64_t{a} << 32 | b : std::uint64_t{b} << 32 | a;
    };
    std::unordered_map<std::uint64_t, std::size_t> index;
    index.reserve(segments.size());
    for (std::size_t s = 0; s < segments.size(); ++s)
        index.emplace(key(segments.endpoints[2 * s], segments.endpoints[2 * s + 1]), s);
    std::vector<std::uint32_t> middle(segments.size(), none);
    EleSource source = mesh.triangles();
    std::vector<double> attributes(source.attribute_count);
    std::uint32_t c[6];
    for (std::size_t t = 0; t < source.count; ++t) {
        source.next(c, attributes.data());
        for (int k = 0; k < 3; ++k) {
            const auto found = index.find(key(c[(k + 1) % 3], c[(k + 2) % 3]));
            if (found != index.end()) middle[found->second] = c[3 + k];
        }
    }
    for (const std::uint32_t m : middle)
        if (m == none) throw InternalError("a segment of the mesh is no triangle's edge");
    return middle;
}

void put_node_data(File& file, const std::string& name, std::size_t n,
                   const std::function<void(Out, std::size_t)>& value) {
    Out out(file.buffer());
    fmt::format_to(out, "$NodeData\n1\n\"{}\"\n1\n0\n3\n0\n1\n{}\n", name, n);
    for (std::size_t v = 0; v < n; ++v) {
        fmt::format_to(out, FMT_COMPILE("{} "), v + 1);
        value(out, v);
        file.buffer().push_back('\n');
        file.flush_if_full();
    }
    fmt::format_to(out, "$EndNodeData\n");
}

// The caller's arrays must agree in size before anything is written.
void check_consistent(const std::string& path, const MeshExport& mesh) {
    const NodeSet& nodes = *mesh.nodes;
    const std::uint32_t nc = mesh.corners_per_triangle;
    if (nodes.xy.size() % 2 != 0 ||
        nodes.attributes.size() != nodes.size() * nodes.attribute_count ||
        (nodes.has_markers() && nodes.markers.size() != nodes.size()) || (nc != 3 && nc != 6))
        throw OutputError("cannot write " + path + ": inconsistent data");
}

// $PhysicalNames: a named group for every curve and every surface.
void put_physical_names(Out out, const std::map<int, Group>& curves,
                        const std::map<double, Group>& regions) {
    fmt::format_to(out, "$PhysicalNames\n{}\n", regions.size() + curves.size());
    for (const auto& [marker, curve] : curves)
        fmt::format_to(out, "1 {} \"{}\"\n", curve.physical, curve.name);
    for (const auto& [value, region] : regions)
        fmt::format_to(out, "2 {} \"{}\"\n", region.physical, region.name);
    fmt::format_to(out, "$EndPhysicalNames\n");
}

// $Entities: the curves, then the surfaces.  Every entity gets the mesh's
// bounding box, which contains its own.
void put_entities(Out out, const std::map<int, Group>& curves,
                  const std::map<double, Group>& regions, const Box& box) {
    fmt::format_to(out, "$Entities\n0 {} {} 0\n", curves.size(), regions.size());
    const std::string bounds =
        fmt::format("{} {} 0 {} {} 0", box.min_x, box.min_y, box.max_x, box.max_y);
    for (const auto& [marker, curve] : curves)
        fmt::format_to(out, "{} {} 1 {} 0\n", curve.entity, bounds, curve.physical);
    for (const auto& [value, region] : regions)
        fmt::format_to(out, "{} {} 1 {} 0\n", region.entity, bounds, region.physical);
    fmt::format_to(out, "$EndEntities\n");
}

// $Nodes: all nodes in one block, on the first surface: their tags, then
// their coordinates.
void put_nodes(File& file, const NodeSet& nodes) {
    Out out(file.buffer());
    const std::size_t n = nodes.size();
    fmt::format_to(out, "$Nodes\n1 {} 1 {}\n2 1 0 {}\n", n, n, n);
    for (std::size_t v = 0; v < n; ++v) {
        fmt::format_to(out, FMT_COMPILE("{}\n"), v + 1);
        file.flush_if_full();
    }
    for (std::size_t v = 0; v < n; ++v) {
        fmt::format_to(out, FMT_COMPILE("{} {} 0\n"), nodes.xy[2 * v], nodes.xy[2 * v + 1]);
        file.flush_if_full();
    }
    fmt::format_to(out, "$EndNodes\n");
}

// The segments as line elements M + 1 on, one block per curve (a pass over
// the segments per curve).
void put_curve_lines(File& file, const MeshExport& mesh, const SegmentSet& segments, bool markers,
                     const std::map<int, Group>& curves) {
    const std::uint32_t nc = mesh.corners_per_triangle;
    const std::size_t m = mesh.triangle_count;
    const std::vector<std::uint32_t> middle =
        nc == 6 ? segment_midpoints(mesh, segments) : std::vector<std::uint32_t>{};
    auto& buf = file.buffer();
    Out out(buf);
    for (const auto& [marker, curve] : curves) {
        fmt::format_to(out, "1 {} {} {}\n", curve.entity, nc == 6 ? 8 : 1, curve.count);
        for (std::size_t s = 0; s < segments.size(); ++s) {
            if ((markers ? segments.markers[s] : 0) != marker) continue;
            fmt::format_to(out, FMT_COMPILE("{} {} {}"), m + s + 1,
                           std::uint64_t{segments.endpoints[2 * s]} + 1,
                           std::uint64_t{segments.endpoints[2 * s + 1]} + 1);
            if (nc == 6) fmt::format_to(out, FMT_COMPILE(" {}"), std::uint64_t{middle[s]} + 1);
            buf.push_back('\n');
            file.flush_if_full();
        }
    }
}

// The triangles as elements 1 to M, numbered in the .ele file's order but
// written one block per region, as gmsh wants an entity's elements together
// (a pass over the triangles per region).
void put_region_triangles(File& file, const MeshExport& mesh,
                          const std::map<double, Group>& regions) {
    static constexpr int gmsh_order[6] = {0, 1, 2, 5, 3, 4};
    const std::uint32_t nc = mesh.corners_per_triangle;
    auto& buf = file.buffer();
    Out out(buf);
    for (const auto& [value, region] : regions) {
        fmt::format_to(out, "2 {} {} {}\n", region.entity, nc == 6 ? 9 : 2, region.count);
        EleSource source = mesh.triangles();
        std::vector<double> attributes(std::max<std::uint32_t>(source.attribute_count, 1), 0.0);
        std::uint32_t c[6];
        for (std::size_t t = 0; t < source.count; ++t) {
            source.next(c, attributes.data());
            if (mesh.attribute_count > 0 && attributes[0] != value) continue;
            fmt::format_to(out, FMT_COMPILE("{}"), t + 1);
            for (std::uint32_t k = 0; k < nc; ++k)
                fmt::format_to(out, FMT_COMPILE(" {}"), std::uint64_t{c[gmsh_order[k]]} + 1);
            buf.push_back('\n');
            file.flush_if_full();
        }
    }
}

// $Elements: the lines, then the triangles.
void put_elements(File& file, const MeshExport& mesh, const SegmentSet& segments, bool markers,
                  const std::map<int, Group>& curves, const std::map<double, Group>& regions) {
    const std::size_t elements = mesh.triangle_count + segments.size();
    fmt::format_to(Out(file.buffer()), "$Elements\n{} {} 1 {}\n", curves.size() + regions.size(),
                   elements, elements);
    put_curve_lines(file, mesh, segments, markers, curves);
    put_region_triangles(file, mesh, regions);
    fmt::format_to(Out(file.buffer()), "$EndElements\n");
}

// $NodeData: the vertex markers, then each vertex attribute.
void put_vertex_data(File& file, const NodeSet& nodes, const WriteFormat& format) {
    const std::size_t n = nodes.size();
    if (format.markers && nodes.has_markers())
        put_node_data(file, "boundary_marker", n, [&nodes](Out o, std::size_t v) {
            fmt::format_to(o, "{}", nodes.markers[v]);
        });
    for (std::uint32_t a = 0; a < nodes.attribute_count; ++a)
        put_node_data(file, fmt::format("attribute_{}", a), n, [&nodes, a](Out o, std::size_t v) {
            fmt::format_to(o, "{}", nodes.attributes[v * nodes.attribute_count + a]);
        });
}

}  // namespace

void write_msh(OutputTransaction& tx, const std::string& path, const MeshExport& mesh,
               const WriteFormat& format) {
    check_consistent(path, mesh);
    const NodeSet& nodes = *mesh.nodes;
    static const SegmentSet no_segments;
    const SegmentSet& segments = mesh.segments != nullptr ? *mesh.segments : no_segments;
    const bool markers = format.markers && segments.has_markers();
    const std::map<double, Group> regions = regions_of(mesh);
    const std::map<int, Group> curves = curves_of(segments, markers);

    File& file = tx.begin_file(path);
    Out out(file.buffer());
    fmt::format_to(out, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
    put_physical_names(out, curves, regions);
    put_entities(out, curves, regions, bounding_box(nodes));
    put_nodes(file, nodes);
    put_elements(file, mesh, segments, markers, curves, regions);
    put_vertex_data(file, nodes, format);
    file.finish(format.command, format.stamp, File::Closing::gmsh_section);
}

}  // namespace gpdr::io
