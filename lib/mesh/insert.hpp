#pragma once
// Bowyer–Watson insertion of one point (Bowyer 1981, Watson 1981), the step
// every later stage repeats: triangulation of points, the CDT's vertices,
// and every Steiner point of refinement.
//
//   1. Locate p (locate.hpp), walking from the hint.
//   2. Refuse: p equal to a vertex (duplicate), p in the interior of a
//      subsegment (on_subsegment: the caller splits the subsegment instead),
//      p beyond a hull edge that has no neighbour (outside).  Nothing changes.
//   3. Grow the cavity from the triangle containing p: a neighbour joins when
//      p lies strictly inside its circumcircle (exact incircle).  The search
//      never crosses a subsegment, so in a constrained Delaunay mesh the
//      cavity is the set of triangles visible from p whose circumcircles hold
//      p, and the result is again constrained Delaunay.  With p on an edge,
//      both triangles join (p is inside both circumcircles).
//   4. Kill the cavity, walk its boundary in order and fan it from p.  A
//      hull edge that p lies on (possible when the mesh has no ghosts) is
//      left out of the fan, leaving p on the hull.
//
// Ghost triangles (a hull edge plus ghost_vertex, used while a point set is
// triangulated) take part as triangles whose "circumcircle" is the open
// half-plane beyond their edge plus the open edge itself; so points outside
// the hull are inserted too, and the hull grows.
//
// Memory touched (for the parallel layer's buffer zones): the triangles
// visited by the walk (read), the cavity (rewritten), and the triangles
// just outside it (their incircle is tested and their link across the
// cavity boundary rewritten).  The scratch mark bit is set only on cavity
// triangles and cleared before returning.
//
// The caller owns the InsertBuffer and reuses it, so an insertion allocates
// nothing once the buffer has grown to the largest cavity seen.

#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/predicates.hpp"
#include "mesh/locate.hpp"
#include "mesh/pool.hpp"

namespace gpdr::mesh {

enum class InsertStatus : std::uint8_t { inserted, duplicate, on_subsegment, outside };

struct InsertResult {
    InsertStatus status = InsertStatus::inserted;
    // inserted: the new vertex; duplicate: the vertex already at p.
    VertexId vertex = no_vertex;
    // on_subsegment: the subsegment edge containing p; outside: the hull edge
    // p lies beyond.  Otherwise none.
    EdgeRef edge;
};

// A triangle that carried a user_tag (mesh/triangle.hpp) as it was before it
// died or a flip changed it: its corners, in their order, and the tag.
struct TaggedTriangle {
    VertexId v[3];
    std::uint8_t tag;
};

struct InsertBuffer {
    // After an insertion: the new triangles, each with the new vertex at
    // corner 2 and its cavity-boundary edge as edge 2, in counter-clockwise
    // order around the vertex ...
    std::vector<TriangleId> created;
    // ... and the triangles that died.  Their slots may already be reused in
    // `created`, under a new generation.
    std::vector<TriangleId> killed;
    // The triangles with a nonzero user_tag among those that died, and
    // among those a flip changed in place (a subsegment split's Lawson
    // flips), as they were: saved before a slot could be reused or a corner
    // changed.  A flipped triangle's tag is cleared (it is `created` now).
    std::vector<TaggedTriangle> tagged_gone;
    // State of the walk's random generator (per thread, reproducible).
    std::uint32_t random_state = 0x2545F491u;

    // Scratch: the cavity boundary, counter-clockwise around p.
    struct BoundaryEdge {
        VertexId from, to;
        EdgeRef outer;  // the triangle edge outside the cavity (none on the hull)
        bool subsegment;
    };
    std::vector<BoundaryEdge> boundary;
    // Scratch: the boundary edges in the order the cavity search met them,
    // and what chain_boundary (cavity.hpp) puts them in order with.
    std::vector<BoundaryEdge> found;
    std::vector<std::uint32_t> ring;
    std::vector<std::pair<VertexId, std::uint32_t>> by_from;
};

// Inserts vertex v (already in the mesh store) at its point.
InsertResult insert_vertex(Pool& pool, VertexId v, TriangleId hint, InsertBuffer& buffer);

// Inserts a new vertex at p; the vertex is created (from the pool) only when
// the insertion happens.
InsertResult insert_point(Pool& pool, const Point& p, VertexKind kind, TriangleId hint,
                          InsertBuffer& buffer);

// Steps 2–4 with the location already known (`where` from locate(p)).
// Vertex v must lie at p.
InsertResult insert_located(Pool& pool, VertexId v, const LocateResult& where,
                            InsertBuffer& buffer);

// Steps 3 and 4 apart, for a caller that must look at the cavity before it
// decides (refinement rejects a Steiner point that encroaches a subsegment
// on its cavity's boundary):
//   find_cavity   marks the cavity of p grown from `seed` (a triangle that
//                 contains p; never crossing a subsegment) and lists it in
//                 buffer.killed; changes nothing else.  Returns the number
//                 of cavity boundary edges.
//   abandon_cavity  clears the marks: the mesh is as before.
//   commit_cavity   inserts v (already in the store, at p; `where` as given
//                 by locate(p), with where.triangle the seed) into the
//                 cavity found, as insert_located would.
// Between find_cavity and commit/abandon nothing else may change the mesh.
std::size_t find_cavity(Mesh& mesh, const Point& p, TriangleId seed, InsertBuffer& buffer);
void abandon_cavity(Mesh& mesh, InsertBuffer& buffer);
InsertResult commit_cavity(Pool& pool, VertexId v, const LocateResult& where, InsertBuffer& buffer);

// Kills every triangle of buffer.killed, saving the tagged ones in
// buffer.tagged_gone first (the last step before a cavity is refilled).
void save_tagged_and_destroy(Pool& pool, InsertBuffer& buffer);
// Saves triangle t in buffer.tagged_gone if it has a user tag, and clears
// the tag (before a flip changes t in place).
void save_if_tagged(Triangle& t, InsertBuffer& buffer);

// p collinear with a and b: is it strictly between them?  (Exact: only
// coordinate comparisons.)
inline bool strictly_between(const Point& a, const Point& b, const Point& p) {
    if (a.x != b.x) return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
    return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
}

// Whether p lies strictly inside the circumcircle of live triangle t (for a
// ghost triangle: strictly beyond its edge, or inside the open edge).
// Inline: the cavity search asks it of every triangle round a cavity.
inline bool in_circumcircle(const Mesh& mesh, const Triangle& t, const Point& p) {
    const int g = t.corner_of(ghost_vertex);
    if (g < 0) [[likely]]
        return geometry::incircle(mesh.point(t.v[0]), mesh.point(t.v[1]), mesh.point(t.v[2]), p) >
               0;
    const Point& a = mesh.point(t.v[next3(g)]);
    const Point& b = mesh.point(t.v[prev3(g)]);
    const double o = geometry::orient2d(a, b, p);
    return o > 0 || (o == 0 && strictly_between(a, b, p));
}

}  // namespace gpdr::mesh
