#pragma once
// The Bowyer-Watson cavity search, the walk around its boundary and the fan
// of new triangles that fills it, shared by point insertion (insert.cpp)
// and subsegment splitting (split_subsegment.cpp).  Templates, so that each
// caller's rule for which triangles may join, what it does with each
// boundary edge and what it adds to each new triangle compile into the loop
// (insertion is the hottest code of refinement).
//
// The search marks the cavity triangles (Triangle::mark_bit) and lists them
// in buffer.killed; the caller clears the marks (commit or abandon).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "mesh/insert.hpp"

namespace gpdr::mesh {

// Breadth-first from `seeds` (marked and listed first), buffer.killed
// doubling as the queue: a neighbour joins when p lies strictly inside its
// circumcircle and admit(id) allows it.  Never crosses a subsegment or the
// hull.  Returns the number of boundary edges (each edge out of the cavity
// counted once, from inside), and lists them in buffer.found as they are
// met.  (A triangle that fails the test never joins later: the test
// depends only on it and p.  So the edges listed are exactly the boundary,
// and the first one listed is where walk_cavity_boundary starts: the first
// boundary edge of the first cavity triangle that has one.)
template <class Admit>
std::size_t search_cavity(Mesh& mesh, const Point& p, std::span<const TriangleId> seeds,
                          InsertBuffer& buffer, Admit&& admit) {
    auto& cavity = buffer.killed;
    cavity.clear();
    auto& found = buffer.found;
    found.clear();
    for (const TriangleId seed : seeds) {
        mesh.triangle(seed).flags |= Triangle::mark_bit;
        cavity.push_back(seed);
    }
    for (std::size_t i = 0; i < cavity.size(); ++i) {
        const Triangle& t = mesh.triangle(cavity[i]);
        for (int k = 0; k < 3; ++k) {
            const EdgeRef across = t.n[k];
            if (across.is_none() || t.is_subsegment(k)) {
                found.push_back({t.v[next3(k)], t.v[prev3(k)], across, t.is_subsegment(k)});
                continue;
            }
            Triangle& u = mesh.triangle(across.triangle());
            if (u.marked()) continue;
            if (admit(across.triangle()) && in_circumcircle(mesh, u, p)) {
                u.flags |= Triangle::mark_bit;
                cavity.push_back(across.triangle());
                // Its other neighbours are tested when the queue reaches
                // it: start fetching them now.
                __builtin_prefetch(&mesh.triangle(u.n[next3(across.edge())].triangle()));
                __builtin_prefetch(&mesh.triangle(u.n[prev3(across.edge())].triangle()));
            } else {
                found.push_back({t.v[next3(k)], t.v[prev3(k)], across, false});
            }
        }
    }
    return found.size();
}

// Puts boundary edges (anything with `from` and `to`) head to tail: `ring`
// gets their indices counter-clockwise round the cavity from edges[0].
// False when they do not close into one loop through every edge exactly
// once (the cavity is not a disk: a vertex starts two edges, or the edges
// form more than one loop).  The edge that starts where one ends is found
// by a scan of the few edges (a cavity has six on average), or, in a large
// cavity, by binary search in a copy sorted by first vertex (`by_from`).
template <class Edge>
bool chain_boundary(std::span<const Edge> edges, std::vector<std::uint32_t>& ring,
                    std::vector<std::pair<VertexId, std::uint32_t>>& by_from) {
    const std::size_t m = edges.size();
    constexpr std::size_t scanned = 32;
    if (m > scanned) {
        by_from.clear();
        for (std::uint32_t at = 0; at < m; ++at) by_from.push_back({edges[at].from, at});
        std::sort(by_from.begin(), by_from.end());
    }
    ring.clear();
    std::uint32_t at = 0;
    for (std::size_t i = 0; i < m; ++i) {
        if (i > 0 && at == 0) return false;
        ring.push_back(at);
        const VertexId to = edges[at].to;
        if (m <= scanned) {
            at = 0;
            while (at < m && edges[at].from != to) ++at;
        } else {
            const auto it =
                std::lower_bound(by_from.begin(), by_from.end(), std::pair{to, std::uint32_t{0}});
            at = it != by_from.end() && it->first == to ? it->second
                                                        : static_cast<std::uint32_t>(m);
        }
        if (at == m) return false;
    }
    return m > 0 && at == 0;
}

// Walks the boundary of the marked cavity in buffer.killed counter-clockwise
// around it, calling visit(e) for each boundary edge e (seen from inside);
// visit returns false to stop.  The next edge begins at the current one's
// destination: pivot around it through cavity triangles until an edge leaves
// the cavity.  Returns whether the walk closed after exactly
// `boundary_edges` edges, i.e. the cavity is a disk (false also when visit
// stopped it).
template <class Visit>
bool walk_cavity_boundary(const Mesh& mesh, const InsertBuffer& buffer, std::size_t boundary_edges,
                          Visit&& visit) {
    auto is_boundary = [&](const Triangle& t, int k) {
        const EdgeRef across = t.n[k];
        return across.is_none() || t.is_subsegment(k) || !mesh.triangle(across.triangle()).marked();
    };
    EdgeRef start = EdgeRef::none();
    for (const TriangleId id : buffer.killed) {
        const Triangle& t = mesh.triangle(id);
        for (int k = 0; k < 3 && start.is_none(); ++k)
            if (is_boundary(t, k)) start = EdgeRef(id, k);
        if (!start.is_none()) break;
    }
    std::size_t walked = 0;
    EdgeRef e = start;
    do {
        if (!visit(e)) return false;
        ++walked;
        TriangleId ct = e.triangle();
        int j = next3(e.edge());
        while (!is_boundary(mesh.triangle(ct), j)) {
            const EdgeRef across = mesh.triangle(ct).n[j];
            ct = across.triangle();
            j = next3(across.edge());
        }
        e = EdgeRef(ct, j);
    } while (e != start && walked <= boundary_edges);
    return walked == boundary_edges && e == start;
}

// Fills the cavity, once its triangles are destroyed, with a fan around the
// new vertex v: one triangle per edge of buffer.boundary (in order round the
// cavity), from edge `first` on, with the edge as edge 2 and v at corner 2,
// linked across the edge to the outer triangle and across edges 0 and 1 to
// the triangles after and before it.  The fan closes into a ring unless
// `open`: then the edge before `first`, a hull edge through v, stays out.
// Edge 2 keeps the boundary edge's subsegment flag; dress(t, b) adds what
// else the caller's triangle t, made from boundary edge b, carries (its
// region, flags of its other edges).  buffer.created lists the fan in order.
template <class Dress>
void fan_cavity(Pool& pool, InsertBuffer& buffer, std::size_t first, bool open, VertexId v,
                Dress&& dress) {
    Mesh& mesh = pool.mesh();
    const auto& boundary = buffer.boundary;
    const std::size_t m = boundary.size();
    const std::size_t count = open ? m - 1 : m;
    buffer.created.clear();
    TriangleId previous = no_triangle;
    // The edges from `first` round to it again (a wrapping index rather than
    // a remainder: a division per new triangle cost more than the rest of
    // its making).
    std::size_t at = first < m ? first : first - m;
    for (std::size_t i = 0; i < count; ++i) {
        const InsertBuffer::BoundaryEdge& b = boundary[at];
        if (++at == m) at = 0;
        const TriangleId id = pool.create(b.from, b.to, v);
        Triangle& t = mesh.triangle(id);
        if (b.subsegment) t.set_subsegment(2, true);
        dress(t, b);
        mesh.link(EdgeRef(id, 2), b.outer);
        if (previous != no_triangle) mesh.link(EdgeRef(previous, 0), EdgeRef(id, 1));
        buffer.created.push_back(id);
        previous = id;
    }
    if (!open) mesh.link(EdgeRef(previous, 0), EdgeRef(buffer.created.front(), 1));
}

}  // namespace gpdr::mesh
