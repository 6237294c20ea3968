// From the live mesh to the arrays Triangle's files hold: triangles numbered
// in id order with dead slots skipped, neighbours renumbered to match, and
// vertex markers by Triangle's rules.

#include "api/job_stages.hpp"
#include "mesh/traverse.hpp"

namespace gpdr::api {

EdgeMarker edge_markers(const mesh::Mesh& mesh) {
    return [&mesh](std::uint32_t a, std::uint32_t b, bool boundary) {
        if (const auto* s = mesh.subsegments().find(mesh::VertexId{a}, mesh::VertexId{b}); s && s->marker != 0)
            return s->marker;
        return boundary ? 1 : 0;
    };
}

MeshArrays mesh_to_arrays(const mesh::Mesh& mesh, NodeSet nodes) {
    MeshArrays out;
    const std::uint32_t slots = mesh.triangle_end();

    // Compact triangle numbers, in id order.
    std::vector<std::uint32_t> number(slots, NeighbourSet::none);
    std::uint32_t count = 0;
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId id, const mesh::Triangle&) { number[index(id)] = count++; });

    out.triangles.corners_per_triangle = 3;
    out.triangles.corners.reserve(3 * std::size_t{count});
    out.neighbours.neighbours.reserve(3 * std::size_t{count});
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId, const mesh::Triangle& t) {
        for (int k = 0; k < 3; ++k) {
            out.triangles.corners.push_back(index(t.v[k]));
            out.neighbours.neighbours.push_back(t.n[k].is_none() ? NeighbourSet::none
                                                                 : number[index(t.n[k].triangle())]);
        }
    });

    // Vertices the mesh added after the input ones (Steiner points) follow
    // them; their attributes are filled by whoever created them (later).
    const std::size_t input_count = nodes.size();
    const std::uint32_t end = mesh.vertex_end();
    for (std::uint32_t v = static_cast<std::uint32_t>(input_count); v < end; ++v) {
        const auto& p = mesh.point(mesh::VertexId{v});
        nodes.xy.push_back(p.x);
        nodes.xy.push_back(p.y);
    }
    nodes.attributes.resize(nodes.size() * nodes.attribute_count, 0.0);

    // Markers: keep non-zero input markers; otherwise a subsegment's marker,
    // then 1 for any boundary vertex.
    nodes.markers.resize(nodes.size(), 0);
    std::vector<bool> fixed(nodes.size());
    for (std::size_t v = 0; v < nodes.size(); ++v) fixed[v] = nodes.markers[v] != 0;
    mesh.subsegments().for_each([&](mesh::VertexId a, mesh::VertexId b, const mesh::SubsegmentInfo& s) {
        for (const auto v : {index(a), index(b)})
            if (!fixed[v] && s.marker != 0) {
                nodes.markers[v] = s.marker;
                fixed[v] = true;
            }
    });
    mesh::for_each_hull_edge(mesh, [&](const mesh::EdgeView& e) {
        for (const auto v : {index(e.from), index(e.to)})
            if (!fixed[v]) nodes.markers[v] = 1;
    });
    out.nodes = std::move(nodes);
    return out;
}

}  // namespace gpdr::api
