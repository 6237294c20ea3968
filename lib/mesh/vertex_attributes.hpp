#pragma once
// VertexAttributes: each vertex's attributes (the columns of a .node file
// after x and y), kept beside the mesh while it is made and refined.
//
// Triangle gives a vertex it adds the attributes interpolated linearly where
// it lies: along the subsegment it splits, or across the triangle that held
// it.  Both read vertices already in the mesh, so a new vertex's values are
// final the moment it is inserted: refinement computes them then, a user's
// triunsuitable() reads them (each corner pointer addresses x, y and then
// the attributes, as in Triangle), and the output copies them.  Computing
// them at the end instead would need the order in which the vertices were
// inserted, which parallel refinement does not keep.
//
// Rows live in chunks of 2^16 vertices that never move (as ChunkTable's
// elements): worker threads write the rows of their own new vertices at
// once, and read those of vertices that reached them through the scheduler.
// A table of width 0 (no attributes) holds nothing.

#include <atomic>
#include <cstdint>
#include <memory>
#include <span>

#include "mesh/ids.hpp"

namespace gpdr::mesh {

class VertexAttributes {
public:
    static constexpr unsigned chunk_bits = 16;
    static constexpr std::uint32_t chunk_size = 1u << chunk_bits;
    static constexpr std::uint32_t max_chunks = 1u << (32 - chunk_bits);

    VertexAttributes() = default;
    explicit VertexAttributes(std::uint32_t width);
    ~VertexAttributes();
    VertexAttributes(VertexAttributes&& other) noexcept;
    VertexAttributes& operator=(VertexAttributes&& other) noexcept;
    VertexAttributes(const VertexAttributes&) = delete;
    VertexAttributes& operator=(const VertexAttributes&) = delete;

    // Attributes per vertex; 0: none are kept.
    std::uint32_t width() const { return width_; }

    // Whether v's chunk of rows exists (every vertex given attributes has it).
    bool has_row(VertexId v) const {
        return chunks_ &&
               chunks_[index(v) >> chunk_bits].load(std::memory_order_acquire) != nullptr;
    }
    // The row of v, which must have been written (or made by write()).
    std::span<const double> row(VertexId v) const {
        const std::uint32_t i = index(v);
        return {chunks_[i >> chunk_bits].load(std::memory_order_acquire) +
                    std::size_t{i & (chunk_size - 1)} * width_,
                width_};
    }
    // The row of v to write, its chunk made (zero-filled) if need be.
    // Throws std::bad_alloc when memory runs out.
    std::span<double> write(VertexId v);

    // Bytes held by the rows.
    std::size_t bytes() const;

private:
    void release();

    std::uint32_t width_ = 0;
    std::unique_ptr<std::atomic<double*>[]> chunks_;
    std::atomic<std::size_t> allocated_{0};
};

class Mesh;

// v's attributes: those of from and to, weighted 1 - t and t.
void interpolate_on_segment(Mesh& mesh, VertexId v, VertexId from, VertexId to, double t);
// v's attributes: those of the corners, weighted by v's barycentric
// coordinates in their triangle.
void interpolate_in_triangle(Mesh& mesh, VertexId v, const VertexId (&corners)[3]);

}  // namespace gpdr::mesh
