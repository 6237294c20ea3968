// MeshOutput -> the triangle package's dictionaries (see output_dict.hpp).
#include "output_dict.hpp"

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "numpy_take.hpp"

namespace gpdr::python {
namespace {

static_assert(sizeof(int) == sizeof(std::int32_t), "markers are numpy's int32 (intc)");

// Indices leave as int32, as the triangle package returns them.
void check_int32(std::size_t count, const char* what) {
    if (count > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw std::overflow_error(
            fmt::format("the mesh has {} {}, more than int32 indices can number", count, what));
}

// Adds `values` under `key` as rows x (size / rows), unless empty.
template <class Target, class Source>
void put(py::dict& d, const char* key, std::vector<Source>& values, std::size_t rows) {
    if (rows == 0 || values.empty()) return;
    const std::size_t columns = values.size() / rows;
    d[key] = take<Target>(values, rows, columns);
}

}  // namespace

py::dict mesh_dict(MeshOutput& mesh, const Options& o, const ConvertedInput& input) {
    check_int32(mesh.nodes.size(), "vertices");
    check_int32(mesh.triangles.size(), "triangles");
    const bool markers = !o.no_boundary_markers;
    py::dict d;

    const std::size_t vertices = mesh.nodes.size();
    if (!o.no_node_output) {
        put<double>(d, "vertices", mesh.nodes.xy, vertices);
        if (mesh.nodes.attribute_count > 0)
            put<double>(d, "vertex_attributes", mesh.nodes.attributes, vertices);
        if (markers) put<std::int32_t>(d, "vertex_markers", mesh.nodes.markers, vertices);
    }

    const std::size_t triangles = mesh.triangles.size();
    if (!o.no_ele_output) {
        put<std::int32_t>(d, "triangles", mesh.triangles.corners, triangles);
        if (mesh.triangles.attribute_count > 0)
            put<double>(d, "triangle_attributes", mesh.triangles.attributes, triangles);
    }
    if (o.write_neighbours)
        put<std::int32_t>(d, "neighbors", mesh.neighbours.neighbours, mesh.neighbours.size());

    if ((o.poly || o.convex_hull) && !o.no_poly_output) {
        const std::size_t segments = mesh.segments.size();
        put<std::int32_t>(d, "segments", mesh.segments.endpoints, segments);
        if (markers) put<std::int32_t>(d, "segment_markers", mesh.segments.markers, segments);
        // Triangle's library hands back the input's holes and regions.
        if (o.poly) {
            if (!input.holes.is_none() && py::len(input.holes) > 0) d["holes"] = input.holes;
            if (!input.regions.is_none() && py::len(input.regions) > 0)
                d["regions"] = input.regions;
        }
    }

    if (o.write_edges) {
        const std::size_t edges = mesh.edges.size();
        put<std::int32_t>(d, "edges", mesh.edges.endpoints, edges);
        if (markers) put<std::int32_t>(d, "edge_markers", mesh.edges.markers, edges);
    }
    return d;
}

py::dict voronoi_dict(MeshOutput& mesh) {
    check_int32(mesh.voronoi_vertices.size(), "Voronoi vertices");
    py::dict d;
    const std::size_t vertices = mesh.voronoi_vertices.size();
    put<double>(d, "vertices", mesh.voronoi_vertices.xy, vertices);
    if (mesh.voronoi_vertices.attribute_count > 0)
        put<double>(d, "vertex_attributes", mesh.voronoi_vertices.attributes, vertices);
    const std::size_t edges = mesh.voronoi_edges.size();
    put<std::int32_t>(d, "edges", mesh.voronoi_edges.endpoints, edges);
    put<double>(d, "normals", mesh.voronoi_edges.directions, edges);
    return d;
}

}  // namespace gpdr::python
