// Pool: refilling from the mesh, and giving back what was not used.

#include "mesh/pool.hpp"

#include <string>

#include <gpdr/errors.hpp>

namespace gpdr::mesh {

Pool::Pool(Mesh& mesh, std::uint32_t vertex_block)
    : mesh_(&mesh), vertex_block_(vertex_block == 0 ? 1 : vertex_block) {
    mesh_->take_back(spare_);
}

Pool::Pool(Mesh& mesh, const Lane& lane)
    : mesh_(&mesh), vertex_block_(Mesh::PointTable::chunk_size), on_lane_(true), lane_(lane) {}

Pool::~Pool() {
    mesh_->give_back(spare_);
    mesh_->give_back_vertices(vertex_next_, vertex_end_);
}

void Pool::destroyed_twice(TriangleId t) {
    throw InternalError("mesh: triangle " + std::to_string(index(t)) +
                        " destroyed while already dead");
}

void Pool::refill() {
    // A free list given back earlier comes first; otherwise a fresh chunk.
    // (Only called with an empty free list and fresh range.)
    if (on_lane_) {
        // (Never the slots another pool gave back: which lane took them
        // would depend on timing.)
        const std::uint32_t place = lane_triangle_chunks_++ * lane_.count + lane_.index;
        spare_ = mesh_->claim_triangle_chunk_at(
            Lane::at(lane_.triangle_holes, lane_.triangle_chunk, place));
    } else if (!mesh_->take_back(spare_)) {
        spare_ = mesh_->claim_triangle_chunk();
    }
}

VertexId Pool::new_vertex(const Point& p, VertexKind kind) {
    if (vertex_next_ == vertex_end_) {
        if (on_lane_) {
            const std::uint32_t place = lane_vertex_chunks_++ * lane_.count + lane_.index;
            vertex_next_ = index(mesh_->claim_vertex_chunk_at(
                Lane::at(lane_.vertex_holes, lane_.vertex_chunk, place)));
        } else {
            vertex_next_ = index(mesh_->claim_vertices(vertex_block_));
        }
        vertex_end_ = vertex_next_ + vertex_block_;
    }
    const VertexId v{vertex_next_++};
    mesh_->set_point(v, p);
    mesh_->set_kind(v, kind);
    return v;
}

}  // namespace gpdr::mesh
