// The output stage: every file the switches ask for, written through one
// output transaction so that a failure leaves no partial result and no
// earlier result clobbered.

#include <gpdr/io.hpp>

#include "api/job_stages.hpp"
#include "mesh/traverse.hpp"

namespace gpdr::api {
namespace {

// The subsegments of the mesh as .poly segments, in the arrays' numbering
// (`number`: mesh vertex id -> node index).
SegmentSet subsegments_of(const mesh::Mesh& mesh, const std::vector<std::uint32_t>& number,
                          const EdgeMarker& marker) {
    SegmentSet segments;
    mesh::for_each_edge(mesh, [&](const mesh::EdgeView& e) {
        if (!e.subsegment) return;
        segments.endpoints.push_back(number[index(e.from)]);
        segments.endpoints.push_back(number[index(e.to)]);
        segments.markers.push_back(marker(index(e.from), index(e.to), e.hull));
    });
    return segments;
}

}  // namespace

std::vector<std::string> write_outputs(const OutputRequest& request, const mesh::Mesh& mesh,
                                       MeshArrays& arrays) {
    const Options& o = *request.options;
    const FileNames& names = *request.names;
    const io::WriteFormat format{request.base, !o.no_boundary_markers,
                                 o.command.empty() ? std::string("gpdr") : o.command};

    if (o.jettison) jettison_unused_vertices(arrays);
    // Mesh vertex ids <-> node indices (arrays.mesh_ids is node -> mesh id).
    const std::vector<std::uint32_t> mesh_id = arrays.mesh_ids;
    std::vector<std::uint32_t> number(mesh.vertex_end(), NeighbourSet::none);
    for (std::uint32_t v = 0; v < mesh_id.size(); ++v) number[mesh_id[v]] = v;

    // Edge markers are known by mesh vertex ids; the arrays may be renumbered.
    const EdgeMarker mesh_marker = edge_markers(mesh);
    const EdgeMarker marker = [&](std::uint32_t a, std::uint32_t b, bool boundary) {
        return mesh_marker(mesh_id[a], mesh_id[b], boundary);
    };

    // Computed before -o2 changes the triangles to six nodes.
    const bool want_poly = (o.poly || request.write_hull_poly) && !o.no_poly_output && !names.out_poly.empty();
    EdgeSet edges;
    if (o.write_edges) edges = edges_of(arrays, marker);
    VoronoiDiagram voronoi;
    if (o.write_voronoi) voronoi = voronoi_of(arrays);
    const std::uint64_t edge_count = o.write_off ? count_edges(arrays).edges : 0;
    if (o.order == 2) make_second_order(arrays, marker);

    io::OutputTransaction out;
    if (!o.no_node_output) io::write_node(out, names.out_node, arrays.nodes, format);
    if (!o.no_ele_output) io::write_ele(out, names.out_ele, triangle_source(arrays), format);
    if (want_poly) {
        PolyFile poly;
        poly.nodes_from_node_file = true;  // Triangle's output .poly refers to the .node
        poly.nodes.attribute_count = arrays.nodes.attribute_count;
        // write_poly() takes the header's marker column from nodes.markers.
        if (arrays.nodes.has_markers()) poly.nodes.markers.assign(1, 0);
        poly.segments = subsegments_of(mesh, number, mesh_marker);
        if (request.poly) {
            poly.holes = request.poly->holes;
            poly.regions = request.poly->regions;
        }
        io::write_poly(out, names.out_poly, poly, format);
    }
    if (o.write_edges) io::write_edge(out, names.out_edge, edges, format);
    if (o.write_voronoi) {
        io::WriteFormat plain = format;
        plain.markers = false;
        io::write_node(out, names.out_v_node, voronoi.vertices, plain);
        io::write_voronoi_edge(out, names.out_v_edge, voronoi.edges, plain);
    }
    if (o.write_neighbours) io::write_neigh(out, names.out_neigh, arrays.neighbours, format);
    if (o.write_off) io::write_off(out, names.out_off, arrays.nodes, arrays.triangles, edge_count, format);
    out.commit();
    return out.files();
}

}  // namespace gpdr::api
