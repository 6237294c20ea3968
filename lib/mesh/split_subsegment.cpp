// Splitting a subsegment (see split_subsegment.hpp for the contract).  The
// cavity is Bowyer–Watson's as in insert.cpp, seeded with both triangles of
// the subsegment; what differs is that the split edge itself is crossed, the
// two new halves are flagged, and the fan is checked against the exact
// orientation of every boundary edge because p may be a rounded point.

#include "mesh/split_subsegment.hpp"

#include <algorithm>
#include <string>

#include <gpdr/errors.hpp>

#include "geometry/constructions.hpp"
#include "geometry/predicates.hpp"
#include "mesh/cavity.hpp"
#include "mesh/flip.hpp"

namespace gpdr::mesh {

namespace {

using geometry::orient2d;

// Whether p lies strictly inside the wedges of t1 (and u) at the open edge
// x-y: then the two seed triangles see p from all their outer edges.
bool placeable(const Mesh& mesh, EdgeRef s, EdgeRef across, const Point& p) {
    const Point& x = mesh.point(mesh.origin(s));
    const Point& y = mesh.point(mesh.destination(s));
    const Point& w = mesh.point(mesh.apex(s));
    if (orient2d(y, w, p) <= 0 || orient2d(w, x, p) <= 0) return false;
    if (across.is_none()) return true;
    const Point& z = mesh.point(mesh.apex(across));
    return orient2d(x, z, p) > 0 && orient2d(z, y, p) > 0;
}

Point midpoint(const Point& a, const Point& b) { return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}; }

void clear_marks(Mesh& mesh, const std::vector<TriangleId>& cavity) {
    for (TriangleId t : cavity)
        mesh.triangle(t).flags &= static_cast<std::uint8_t>(~Triangle::mark_bit);
}

enum class Attempt { done, retry, broken };

}  // namespace

// Lawson's flips from the new triangles until every edge that is not a
// subsegment is locally Delaunay.  Needed only when p is off the line x-y (a
// rounded crossing): the bent subsegments x-p-y can leave a fan edge, or an
// edge beside a triangle kept out of the cavity, not locally Delaunay.  A
// non-locally-Delaunay edge always has a convex quadrilateral, so the flips
// never get stuck, and they terminate (Lawson 1977).  The InsertBuffer's
// boundary list, finished with, serves as the stack (in its `outer` field).
void lawson_flips(Mesh& mesh, InsertBuffer& buf) {
    auto& stack = buf.boundary;
    stack.clear();
    for (TriangleId id : buf.created)
        for (int k = 0; k < 3; ++k) stack.push_back({no_vertex, no_vertex, EdgeRef(id, k), false});
    while (!stack.empty()) {
        const EdgeRef e = stack.back().outer;
        stack.pop_back();
        const Triangle& t = mesh.triangle(e.triangle());
        const EdgeRef across = t.n[e.edge()];
        if (!t.live() || across.is_none() || t.is_subsegment(e.edge())) continue;
        const Triangle& u = mesh.triangle(across.triangle());
        if (u.is_ghost() || t.is_ghost()) continue;
        const Point& q = mesh.point(u.v[across.edge()]);
        if (geometry::incircle(mesh.point(t.v[0]), mesh.point(t.v[1]), mesh.point(t.v[2]), q) <= 0)
            continue;
        if (!flippable(mesh, e)) continue;
        const TriangleId other = across.triangle();
        save_if_tagged(mesh.triangle(e.triangle()), buf);
        save_if_tagged(mesh.triangle(other), buf);
        flip(mesh, e);
        if (std::find(buf.created.begin(), buf.created.end(), other) == buf.created.end())
            buf.created.push_back(other);
        for (TriangleId id : {e.triangle(), other})
            for (int k : {0, 2}) stack.push_back({no_vertex, no_vertex, EdgeRef(id, k), false});
    }
}

// One attempt at the cavity: the BFS, then the boundary walk in order.
// `banned` triangles never join.  On `retry`, a non-seed triangle that cannot
// see p has been added to `banned`.
Attempt grow_cavity(Mesh& mesh, EdgeRef s, EdgeRef across, const Point& p, InsertBuffer& buf,
                    std::vector<TriangleId>& banned) {
    auto& boundary = buf.boundary;
    boundary.clear();
    const TriangleId t1 = s.triangle();
    const TriangleId u = across.is_none() ? no_triangle : across.triangle();
    const TriangleId seeds[2] = {t1, u};
    const std::size_t boundary_edges = search_cavity(
        mesh, p, {seeds, u == no_triangle ? 1u : 2u}, buf,
        [&](TriangleId id) { return std::find(banned.begin(), banned.end(), id) == banned.end(); });
    // Every boundary edge but the split one must see p on its left: p may
    // be a rounded point, so a triangle that would fan the wrong way is
    // banned and the search retried.
    Attempt outcome = Attempt::done;
    const bool disk = walk_cavity_boundary(mesh, buf, boundary_edges, [&](EdgeRef e) {
        const Triangle& t = mesh.triangle(e.triangle());
        const VertexId from = t.v[next3(e.edge())], to = t.v[prev3(e.edge())];
        if (e != s && orient2d(mesh.point(from), mesh.point(to), p) <= 0) {
            if (e.triangle() == t1 || e.triangle() == u) {
                outcome = Attempt::broken;
            } else {
                banned.push_back(e.triangle());
                outcome = Attempt::retry;
            }
            return false;
        }
        boundary.push_back({from, to, t.n[e.edge()], t.is_subsegment(e.edge())});
        return true;
    });
    if (outcome != Attempt::done) return outcome;
    return disk ? Attempt::done : Attempt::broken;
}

bool can_split_at(const Mesh& mesh, EdgeRef s, const Point& p) {
    return placeable(mesh, s, mesh.neighbour(s), p);
}

namespace {

std::string edge_name(VertexId x, VertexId y) {
    return std::to_string(index(x)) + "-" + std::to_string(index(y));
}

// Where the vertex goes on x-y (the edge s): the asked point, or pulled
// toward the middle until the triangles on both sides see it.
Point placement(const Mesh& mesh, EdgeRef s, EdgeRef across, VertexId x, VertexId y,
                const Point& asked) {
    Point p = asked;
    const Point middle = midpoint(mesh.point(x), mesh.point(y));
    for (int i = 0; !placeable(mesh, s, across, p); ++i) {
        if (i == 64) {
            if (placeable(mesh, s, across, middle)) return middle;
            throw SubsegmentSplitError("mesh: cannot place a vertex inside subsegment " +
                                       edge_name(x, y) + " (degenerate triangles around it)");
        }
        p = midpoint(p, middle);
    }
    return p;
}

// Sets or clears the subsegment flag of the split edge, on both sides.
void flag_split_edge(Mesh& mesh, EdgeRef s, EdgeRef across, bool subsegment) {
    mesh.triangle(s.triangle()).set_subsegment(s.edge(), subsegment);
    if (!across.is_none())
        mesh.triangle(across.triangle()).set_subsegment(across.edge(), subsegment);
}

// Leaves the mesh as it was before a split that cannot be made.
void abandon_split(Mesh& mesh, EdgeRef s, EdgeRef across, InsertBuffer& buf) {
    clear_marks(mesh, buf.killed);
    buf.killed.clear();
    buf.boundary.clear();
    buf.created.clear();
    flag_split_edge(mesh, s, across, true);
}

// The cavity of p around the split edge x-y (unflagged), in buf.killed and,
// in order, buf.boundary: triangles that cannot see p are banned from it
// and the search is tried again.
void find_split_cavity(Mesh& mesh, EdgeRef s, EdgeRef across, VertexId x, VertexId y,
                       const Point& p, InsertBuffer& buf) {
    // `created` serves as the list of banned triangles until the fan.
    std::vector<TriangleId>& banned = buf.created;
    banned.clear();
    for (;;) {
        const Attempt a = grow_cavity(mesh, s, across, p, buf, banned);
        if (a == Attempt::done) return;
        if (a == Attempt::broken || banned.size() > 64) {
            abandon_split(mesh, s, across, buf);
            throw InternalError(
                "mesh: the cavity of a subsegment split is not a disk (the mesh is broken near " +
                edge_name(x, y) + ")");
        }
        clear_marks(mesh, buf.killed);
    }
}

// The fan starts at the boundary edge leaving y: edges from y round to x
// are on t1's side, from x round to y on the other side.  Its index, or the
// boundary's size when the cavity would swallow x or y.
std::size_t fan_start(const std::vector<InsertBuffer::BoundaryEdge>& boundary, VertexId x,
                      VertexId y) {
    const std::size_t m = boundary.size();
    std::size_t first = m;
    bool sees_x = false;
    for (std::size_t i = 0; i < m; ++i) {
        if (boundary[i].from == y) first = i;
        if (boundary[i].from == x || boundary[i].to == x) sees_x = true;
    }
    return sees_x ? first : m;
}

// Fans the cavity boundary from the new vertex v, from boundary edge
// `first` on, into buf.created (v at corner 2): x-v and v-y become
// subsegments, triangles on t1's side take region1, those past x region2.
// `open`: the hull edge x -> y is on the boundary and stays out.
void fan_split(Pool& pool, InsertBuffer& buf, std::size_t first, bool open, VertexId x, VertexId y,
               VertexId v, std::uint16_t region1, std::uint16_t region2) {
    bool other_side = false;
    fan_cavity(pool, buf, first, open, v, [&](Triangle& t, const InsertBuffer::BoundaryEdge& b) {
        if (b.from == x) other_side = true;
        t.region = other_side ? region2 : region1;
        if (b.to == x || b.to == y) t.set_subsegment(0, true);
        if (b.from == x || b.from == y) t.set_subsegment(1, true);
    });
}

}  // namespace

InsertResult split_subsegment(Pool& pool, EdgeRef s, const Point& asked, VertexKind kind,
                              InsertBuffer& buf) {
    Mesh& mesh = pool.mesh();
    const VertexId x = mesh.origin(s), y = mesh.destination(s);
    const EdgeRef across = mesh.neighbour(s);
    const Point p = placement(mesh, s, across, x, y, asked);

    // The split edge is crossed by the cavity: unflag it for the search.
    const std::uint16_t region1 = mesh.triangle(s.triangle()).region;
    const std::uint16_t region2 =
        across.is_none() ? region1 : mesh.triangle(across.triangle()).region;
    flag_split_edge(mesh, s, across, false);
    find_split_cavity(mesh, s, across, x, y, p, buf);
    const std::size_t first = fan_start(buf.boundary, x, y);
    if (first == buf.boundary.size()) {
        abandon_split(mesh, s, across, buf);
        throw InternalError("mesh: a subsegment split would remove an end of the subsegment");
    }

    SubsegmentInfo info;
    if (const SubsegmentInfo* found = mesh.subsegments().find(x, y)) info = *found;
    const VertexId v = pool.new_vertex(p, kind);
    save_tagged_and_destroy(pool, buf);
    fan_split(pool, buf, first, across.is_none(), x, y, v, region1, region2);
    if (orient2d(mesh.point(x), mesh.point(y), p) != 0) lawson_flips(mesh, buf);

    mesh.subsegments().erase(x, y);
    mesh.subsegments().set(x, v, info);
    mesh.subsegments().set(v, y, info);
    return {InsertStatus::inserted, v, EdgeRef::none()};
}

}  // namespace gpdr::mesh
