#pragma once
// Per-triangle area bounds (Triangle's -ra with an .area file): a side array
// indexed by TriangleId, in never-moving chunks like the triangle store, so
// several refinement threads can write the entries of their own triangles
// without a lock (ensure() is lock-free and idempotent).
//
// Inheritance rule.  A bound belongs to a region of the plane, not to a
// triangle record, so every triangle created by an insertion inherits the
// bound of the triangle that CONTAINED THE NEW VERTEX (the seed of its
// Bowyer-Watson cavity), as Triangle does when it splits a triangle.  For a
// subsegment split, the triangles on each side of the subsegment inherit
// the bound of the old triangle on that side.  A bound <= 0 (and every entry
// never written, which reads 0) means no bound.

#include <cstdint>

#include "mesh/ids.hpp"
#include "mesh/mesh.hpp"
#include "mesh/store.hpp"

namespace gpdr::refine {

class AreaBounds {
public:
    double get(mesh::TriangleId t) const {
        const std::uint32_t i = mesh::index(t);
        return table_.has_chunk(i >> chunk_bits) ? table_[i] : 0.0;
    }
    void set(mesh::TriangleId t, double bound) {
        const std::uint32_t i = mesh::index(t);
        table_.ensure(i >> chunk_bits);
        table_[i] = bound;
    }

private:
    static constexpr unsigned chunk_bits = mesh::Mesh::triangle_chunk_bits;
    mesh::ChunkTable<double, chunk_bits, (mesh::max_triangles >> chunk_bits)> table_;
};

}  // namespace gpdr::refine
