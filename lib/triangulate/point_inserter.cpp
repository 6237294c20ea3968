// Bowyer-Watson insertion for a point set with ghosts (see point_inserter.hpp).

#include "triangulate/point_inserter.hpp"

#include <algorithm>

#include <gpdr/errors.hpp>

#include "geometry/predicates.hpp"
#include "mesh/cavity.hpp"

namespace gpdr::triangulate {

using namespace gpdr::mesh;
using geometry::Point;

namespace {

// Where p lies against triangle t's circumcircle: > 0 strictly inside, 0 on
// it, < 0 outside.  For a ghost, its "circumcircle" is the open half-plane
// beyond its real edge plus the open edge (mesh::in_circumcircle's rule,
// inlined here: it is asked for every neighbour of the cavity), and the
// answer is 1 or -1, never 0: an edge with a ghost is no interior edge.
inline double circle_side(const Mesh& mesh, const Triangle& t, const Point& p) {
    const VertexId a = t.v[0], b = t.v[1], c = t.v[2];
    if (a != ghost_vertex && b != ghost_vertex && c != ghost_vertex) [[likely]]
        return geometry::incircle(mesh.point(a), mesh.point(b), mesh.point(c), p);
    // The real edge runs from the corner after the ghost to the one before.
    const VertexId from = a == ghost_vertex ? b : b == ghost_vertex ? c : a;
    const VertexId to = a == ghost_vertex ? c : b == ghost_vertex ? a : b;
    const Point& pf = mesh.point(from);
    const Point& pt = mesh.point(to);
    const double o = geometry::orient2d(pf, pt, p);
    return o > 0 || (o == 0 && strictly_between(pf, pt, p)) ? 1.0 : -1.0;
}

// Asks for the record of the triangle across e to be brought into the cache.
inline void prefetch(const Mesh& mesh, EdgeRef e) {
    __builtin_prefetch(&mesh.triangle(e.triangle()));
}

}  // namespace

PointInserter::PointInserter(Pool& pool) : pool_(pool), mesh_(pool.mesh()) {}

// The cavity, breadth-first from the seed with cavity_ as the queue, as
// mesh::search_cavity grows it; each edge out of it is recorded the moment
// the triangle beyond it fails the test.  (A triangle that fails never joins
// later: the test depends only on it and p.  So the recorded edges are
// exactly the boundary, and the first one recorded is the one the general
// boundary walk starts from: the first boundary edge of the first cavity
// triangle that has one.)
template <bool Banded>
bool PointInserter::search(const Point& p, TriangleId seed) {
    cavity_.clear();
    boundary_.clear();
    Triangle& s = mesh_.triangle(seed);
    s.flags |= Triangle::mark_bit;
    cavity_.push_back(seed);
    for (const EdgeRef e : s.n) prefetch(mesh_, e);
    for (std::size_t i = 0; i < cavity_.size(); ++i) {
        const Triangle& t = mesh_.triangle(cavity_[i]);
        for (int k = 0; k < 3; ++k) {
            const EdgeRef across = t.n[k];  // never none: the ghosts close the mesh
            Triangle& u = mesh_.triangle(across.triangle());
            if (u.marked()) continue;
            const double side = circle_side(mesh_, u, p);
            if (side > 0) {
                if (Banded && !owns(u)) {
                    unmark_cavity();
                    return false;
                }
                u.flags |= Triangle::mark_bit;
                cavity_.push_back(across.triangle());
                // Its other neighbours are tested when the queue reaches it:
                // start fetching them now (at millions of points they are
                // mostly cache misses, and the queue has other work first).
                prefetch(mesh_, u.n[next3(across.edge())]);
                prefetch(mesh_, u.n[prev3(across.edge())]);
                continue;
            }
            if (Banded && !owns(u)) {
                unmark_cavity();
                return false;
            }
            // p on the circle of a triangle that stays: the fan's triangle
            // on this edge will share that circle with it.
            if (side == 0 && watching_) cocircular_ = true;
            boundary_.push_back({t.v[next3(k)], t.v[prev3(k)], across, t.v[k]});
        }
    }
    return true;
}

void PointInserter::unmark_cavity() {
    for (const TriangleId t : cavity_)
        mesh_.triangle(t).flags &= static_cast<std::uint8_t>(~Triangle::mark_bit);
}

// ring_: the boundary edges head to tail, counter-clockwise round the cavity
// from the first one found (mesh::chain_boundary).
void PointInserter::chain() {
    if (!chain_boundary(std::span<const BoundaryEdge>(boundary_), ring_, by_from_)) not_a_disk();
}

void PointInserter::not_a_disk() {
    unmark_cavity();
    throw InternalError(
        "mesh: Bowyer-Watson cavity is not simply connected (the mesh is not Delaunay near the "
        "point)");
}

// Kills the cavity (its slots are the first the pool hands out again, last
// killed first) and fills it with the fan round v in ring_ order: triangle
// (from, to, v) per boundary edge, linked across edge 2 to the outside and
// across edges 0 and 1 to the next and previous triangles of the fan.
TriangleId PointInserter::fan(VertexId v) {
    for (const TriangleId t : cavity_) pool_.destroy(t);
    TriangleId first = no_triangle, previous = no_triangle;
    for (const std::uint32_t at : ring_) {
        const BoundaryEdge& b = boundary_[at];
        const TriangleId id = pool_.create(b.from, b.to, v);
        Triangle& t = mesh_.triangle(id);
        t.n[2] = b.outer;
        mesh_.triangle(b.outer.triangle()).n[b.outer.edge()] = EdgeRef(id, 2);
        if (previous == no_triangle) {
            first = id;
        } else {
            t.n[1] = EdgeRef(previous, 0);
            mesh_.triangle(previous).n[0] = EdgeRef(id, 1);
        }
        previous = id;
    }
    mesh_.triangle(previous).n[0] = EdgeRef(first, 1);
    mesh_.triangle(first).n[1] = EdgeRef(previous, 0);
    return first;
}

// The edges from v to the ring's vertices: each is shared by the fan's
// triangles on the boundary edges before and after it, (a, b, v) and
// (b, c, v), which share a circle when c lies on the circle of (a, b, v),
// that is when v lies on the circle of (a, b, c) (incircle changes sign
// with the order of its last two points).  So not when (a, b, c) was a
// triangle of the cavity: v lies strictly inside its circle.  (Edges with
// the ghost vertex are no interior edges.)
void PointInserter::watch_spokes(VertexId v) {
    const std::size_t m = ring_.size();
    const Point& pv = mesh_.point(v);
    for (std::size_t i = 0; i < m; ++i) {
        const BoundaryEdge& before = boundary_[ring_[i]];
        const VertexId c = boundary_[ring_[i + 1 < m ? i + 1 : 0]].to;
        if (before.apex == c || before.from == ghost_vertex || before.to == ghost_vertex ||
            c == ghost_vertex)
            continue;
        if (geometry::incircle(mesh_.point(before.from), mesh_.point(before.to), pv,
                               mesh_.point(c)) == 0)
            cocircular_ = true;
    }
}

TriangleId PointInserter::insert(VertexId v, TriangleId seed) {
    search<false>(mesh_.point(v), seed);
    chain();
    if (watching_) watch_spokes(v);
    return fan(v);
}

TriangleId PointInserter::try_insert(VertexId v, TriangleId seed) {
    if (!search<true>(mesh_.point(v), seed)) return no_triangle;
    chain();
    if (watching_) watch_spokes(v);
    return fan(v);
}

}  // namespace gpdr::triangulate
