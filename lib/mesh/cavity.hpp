#pragma once
// The Bowyer-Watson cavity search and the walk around its boundary, shared
// by point insertion (insert.cpp) and subsegment splitting
// (split_subsegment.cpp).  Templates, so that each caller's rule for which
// triangles may join, and what it does with each boundary edge, compile into
// the loop (the search is the hottest code of refinement).
//
// The search marks the cavity triangles (Triangle::mark_bit) and lists them
// in buffer.killed; the caller clears the marks (commit or abandon).

#include <cstddef>
#include <span>

#include "mesh/insert.hpp"

namespace gpdr::mesh {

// Breadth-first from `seeds` (marked and listed first), buffer.killed
// doubling as the queue: a neighbour joins when p lies strictly inside its
// circumcircle and admit(id) allows it.  Never crosses a subsegment or the
// hull.  Returns the number of boundary edges (each edge out of the cavity
// counted once, from inside).
template <class Admit>
std::size_t search_cavity(Mesh& mesh, const Point& p, std::span<const TriangleId> seeds,
                          InsertBuffer& buffer, Admit&& admit) {
    auto& cavity = buffer.killed;
    cavity.clear();
    for (const TriangleId seed : seeds) {
        mesh.triangle(seed).flags |= Triangle::mark_bit;
        cavity.push_back(seed);
    }
    std::size_t boundary_edges = 0;
    for (std::size_t i = 0; i < cavity.size(); ++i) {
        const Triangle& t = mesh.triangle(cavity[i]);
        for (int k = 0; k < 3; ++k) {
            const EdgeRef across = t.n[k];
            if (across.is_none() || t.is_subsegment(k)) {
                ++boundary_edges;
                continue;
            }
            Triangle& u = mesh.triangle(across.triangle());
            if (u.marked()) continue;
            if (admit(across.triangle()) && in_circumcircle(mesh, u, p)) {
                u.flags |= Triangle::mark_bit;
                cavity.push_back(across.triangle());
            } else {
                ++boundary_edges;
            }
        }
    }
    return boundary_edges;
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

}  // namespace gpdr::mesh
