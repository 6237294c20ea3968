#pragma once
// Bowyer-Watson insertion specialised for triangulating a point set with
// ghost triangles (delaunay.cpp), the hottest loop of the point-set stage.
//
// It makes exactly the mesh that mesh::insert_located would make, slot for
// slot: the cavity is grown breadth-first in the same order (so its
// triangles die, and their slots return to the pool's free list, in the same
// order), and the fan is created counter-clockwise from the same boundary
// edge, the first one the search meets.  What it leaves out is what a point
// set never has: subsegments, regions, user tags, edges without a neighbour
// (the ghosts close the surface).  And it does in one pass what the general
// code does in two: the search records each boundary edge as it finds it,
// and the edges are chained head to tail by their vertices, instead of a
// second walk round the cavity that pivots through its triangles.

#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/locate.hpp"
#include "mesh/pool.hpp"

namespace gpdr::triangulate {

class PointInserter {
public:
    explicit PointInserter(mesh::Pool& pool);

    // Inserts vertex v at its point, which lies inside `seed`, on one of its
    // edges, or (for a ghost) beyond its real edge: where.triangle of
    // mesh::locate, on_vertex excluded.  Returns the first triangle of the
    // fan (the one a general insertion lists first in InsertBuffer::created).
    mesh::TriangleId insert(mesh::VertexId v, mesh::TriangleId seed);

    mesh::Mesh& mesh() const { return mesh_; }

    // Confines try_insert to the triangles of the band lo < x < hi
    // (strip_inserter.hpp): those whose three corners lie strictly inside it
    // (never a ghost).
    void limit_to(double lo, double hi) {
        lo_ = lo;
        hi_ = hi;
    }
    bool owns(const mesh::Triangle& t) const {
        for (const mesh::VertexId v : t.v) {
            if (v == mesh::ghost_vertex) return false;
            const double x = mesh_.point(v).x;
            if (!(lo_ < x && x < hi_)) return false;
        }
        return true;
    }
    // insert(), unless the cavity holds a triangle the band does not own or
    // borders one (whose link to the cavity would be rewritten): then
    // nothing changes and the answer is no_triangle.  `seed` must be owned.
    mesh::TriangleId try_insert(mesh::VertexId v, mesh::TriangleId seed);

    // From now on, insertions watch the edges they make: whether one of
    // them has its two triangles on one circle (four cocircular vertices),
    // where the Delaunay triangulation is not unique.  Every interior edge
    // of a finished mesh was made, with the two triangles it has at the end,
    // by the insertion that made the later of them: as an edge of its
    // cavity's boundary (the search's own incircle against the triangle
    // outside) or as a spoke of its fan (one incircle more).  So a mesh
    // made only by watching insertions that saw none is the only Delaunay
    // triangulation of its points.
    void watch_cocircular() { watching_ = true; }
    bool cocircular_seen() const { return cocircular_; }

private:
    // A cavity boundary edge, seen from inside: from -> to, the edge of the
    // triangle outside that faces it, and the third corner of the cavity
    // triangle on it.
    struct BoundaryEdge {
        mesh::VertexId from, to;
        mesh::EdgeRef outer;
        mesh::VertexId apex;
    };

    // Grows the cavity; with Banded, false (and no mark left) when it meets
    // a triangle the band does not own.
    template <bool Banded>
    bool search(const geometry::Point& p, mesh::TriangleId seed);
    void unmark_cavity();
    void chain();
    void watch_spokes(mesh::VertexId v);
    mesh::TriangleId fan(mesh::VertexId v);
    [[noreturn]] void not_a_disk();

    mesh::Pool& pool_;
    mesh::Mesh& mesh_;
    std::vector<mesh::TriangleId> cavity_;  // in order of joining (the queue)
    std::vector<BoundaryEdge> boundary_;    // in order of discovery
    std::vector<std::uint32_t> ring_;       // boundary_ indices, counter-clockwise
    // (first vertex, index in boundary_), sorted: for chaining a large cavity.
    std::vector<std::pair<mesh::VertexId, std::uint32_t>> by_from_;
    double lo_ = 0, hi_ = 0;  // the band of try_insert
    bool watching_ = false;
    bool cocircular_ = false;
};

}  // namespace gpdr::triangulate
