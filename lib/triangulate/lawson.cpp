// Lawson's flip algorithm (see lawson.hpp): a stack of edges to test,
// seeded with every non-subsegment edge; a flip pushes the four edges
// around the new diagonal.

#include "triangulate/lawson.hpp"

#include <vector>

#include "geometry/predicates.hpp"
#include "mesh/flip.hpp"
#include "mesh/traverse.hpp"

namespace gpdr::triangulate {

using mesh::EdgeRef;

namespace {

// Edge e is locally Delaunay when the apex across it is not strictly inside
// the circumcircle of e's triangle.
bool locally_delaunay(const mesh::Mesh& mesh, EdgeRef e) {
    const EdgeRef across = mesh.neighbour(e);
    if (across.is_none()) return true;
    const mesh::Triangle& t = mesh.triangle(e.triangle());
    return geometry::incircle(mesh.point(t.v[0]), mesh.point(t.v[1]), mesh.point(t.v[2]),
                              mesh.point(mesh.apex(across))) <= 0;
}

}  // namespace

std::size_t make_constrained_delaunay(mesh::Mesh& mesh) {
    std::vector<EdgeRef> stack;
    mesh::for_each_edge(mesh, [&](const mesh::EdgeView& e) {
        if (!e.subsegment && !e.hull) stack.push_back(e.edge);
    });
    std::size_t flips = 0;
    while (!stack.empty()) {
        const EdgeRef e = stack.back();
        stack.pop_back();
        const mesh::Triangle& t = mesh.triangle(e.triangle());
        if (!t.live() || t.is_subsegment(e.edge()) || locally_delaunay(mesh, e)) continue;
        // Not locally Delaunay implies the quadrilateral is strictly convex
        // (the apex inside the circumcircle cannot make it reflex), so the
        // flip is always possible; flippable() guards against rounding in
        // callers' meshes all the same.
        if (!mesh::flippable(mesh, e)) continue;
        const EdgeRef diagonal = mesh::flip(mesh, e);
        ++flips;
        // The four outer edges of the two new triangles may have stopped
        // being locally Delaunay.
        const EdgeRef other = mesh.neighbour(diagonal);
        for (const EdgeRef d : {diagonal, other}) {
            stack.push_back(d.next());
            stack.push_back(d.prev());
        }
    }
    return flips;
}

}  // namespace gpdr::triangulate
