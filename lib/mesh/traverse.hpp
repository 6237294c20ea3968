#pragma once
// Iteration over a finished mesh, for writers and statistics.  The order is
// the order of triangle ids, which is stable for a given mesh (the same mesh
// built again gives the same order) but is not a canonical form: compare
// meshes with a canonical order instead (rotate each triangle to its smallest
// vertex, sort).  Call these only while no thread is changing the mesh.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"

namespace gpdr::mesh {

// One edge, seen from one of its triangles (the one with the lower id, or
// the only one on the hull): edge.edge() of edge.triangle(), from -> to
// counter-clockwise in that triangle.
struct EdgeView {
    EdgeRef edge;
    VertexId from;
    VertexId to;
    bool hull;        // no triangle on the other side
    bool subsegment;  // flagged as a subsegment
};

// f(TriangleId, const Triangle&) for every live triangle whose id lies in
// [first, end), in id order.  (Chunks nobody claimed are skipped whole, and
// the unused ends of chunks: mesh.hpp; the parallel refiner's lanes leave
// many.)
template <class F>
void for_each_triangle_in(const Mesh& mesh, std::uint32_t first, std::uint32_t end, F&& f) {
    constexpr std::uint32_t chunk = Mesh::TriangleTable::chunk_size;
    for (std::uint32_t from = first; from < end;) {
        const std::uint32_t to =
            static_cast<std::uint32_t>(std::min<std::uint64_t>(end, (from / chunk + 1ull) * chunk));
        if (mesh.has_triangle_chunk(from / chunk)) {
            // (Slots past the chunk's used part were never live.)
            const std::uint32_t used = std::min<std::uint32_t>(
                to, (from / chunk) * chunk + mesh.triangle_chunk_used(from / chunk));
            for (std::uint32_t i = from; i < used; ++i) {
                const Triangle& t = mesh.triangle(TriangleId{i});
                if (t.live()) f(TriangleId{i}, t);
            }
        }
        from = to;
    }
}

// f(TriangleId, const Triangle&) for every live triangle, in id order.
template <class F>
void for_each_triangle(const Mesh& mesh, F&& f) {
    for_each_triangle_in(mesh, 0, mesh.triangle_end(), std::forward<F>(f));
}

// f(const EdgeView&) for every edge of the mesh, each once.
template <class F>
void for_each_edge(const Mesh& mesh, F&& f) {
    for_each_triangle(mesh, [&](TriangleId id, const Triangle& t) {
        for (int k = 0; k < 3; ++k) {
            const EdgeRef across = t.n[k];
            if (!across.is_none() && index(across.triangle()) < index(id)) continue;
            f(EdgeView{EdgeRef(id, k), t.v[next3(k)], t.v[prev3(k)], across.is_none(),
                       t.is_subsegment(k)});
        }
    });
}

// f(const EdgeView&) for every hull edge (no neighbour), in triangle id order.
template <class F>
void for_each_hull_edge(const Mesh& mesh, F&& f) {
    for_each_triangle(mesh, [&](TriangleId id, const Triangle& t) {
        for (int k = 0; k < 3; ++k)
            if (t.n[k].is_none())
                f(EdgeView{EdgeRef(id, k), t.v[next3(k)], t.v[prev3(k)], true, t.is_subsegment(k)});
    });
}

// Output numbering of triangles: element i is the position of triangle i
// among the live triangles in id order (what for_each_triangle visits), or
// not_numbered for a dead slot.  Writers use it to turn neighbour ids into
// file indices (.neigh).
inline constexpr std::uint32_t not_numbered = 0xFFFFFFFFu;
inline std::vector<std::uint32_t> number_triangles(const Mesh& mesh) {
    std::vector<std::uint32_t> number(mesh.triangle_end(), not_numbered);
    std::uint32_t next = 0;
    for_each_triangle(mesh, [&](TriangleId id, const Triangle&) { number[index(id)] = next++; });
    return number;
}

// Counts, each by one pass.
inline std::size_t count_edges(const Mesh& mesh) {
    std::size_t n = 0;
    for_each_edge(mesh, [&](const EdgeView&) { ++n; });
    return n;
}
inline std::size_t count_hull_edges(const Mesh& mesh) {
    std::size_t n = 0;
    for_each_hull_edge(mesh, [&](const EdgeView&) { ++n; });
    return n;
}

}  // namespace gpdr::mesh
