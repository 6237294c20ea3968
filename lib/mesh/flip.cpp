// The 2-2 edge flip (see flip.hpp for the drawing and the contract).

#include "mesh/flip.hpp"

#include "geometry/predicates.hpp"

namespace gpdr::mesh {

bool flippable(const Mesh& mesh, EdgeRef e) {
    const Triangle& t = mesh.triangle(e.triangle());
    const EdgeRef across = t.n[e.edge()];
    if (across.is_none() || t.is_subsegment(e.edge())) return false;
    const Triangle& u = mesh.triangle(across.triangle());
    if (t.is_ghost() || u.is_ghost()) return false;
    const Point& a = mesh.point(t.v[e.edge()]);
    const Point& b = mesh.point(t.v[next3(e.edge())]);
    const Point& c = mesh.point(t.v[prev3(e.edge())]);
    const Point& d = mesh.point(u.v[across.edge()]);
    // b and c must lie strictly on opposite sides of line a-d.
    return geometry::orient2d(a, b, d) > 0 && geometry::orient2d(d, c, a) > 0;
}

EdgeRef flip(Mesh& mesh, EdgeRef e) {
    const TriangleId tid = e.triangle();
    const int k = e.edge();
    Triangle& t = mesh.triangle(tid);
    const EdgeRef across = t.n[k];
    const TriangleId uid = across.triangle();
    const int j = across.edge();
    Triangle& u = mesh.triangle(uid);

    // Names as in the drawing: t = (a, b, c) with k opposite a; u = (d, c, b)
    // with j opposite d.
    const VertexId a = t.v[k], b = t.v[next3(k)], c = t.v[prev3(k)];
    const VertexId d = u.v[j];
    const EdgeRef n_ab = t.n[prev3(k)], n_ca = t.n[next3(k)];
    const bool s_ab = t.is_subsegment(prev3(k)), s_ca = t.is_subsegment(next3(k));
    const EdgeRef n_bd = u.n[next3(j)], n_dc = u.n[prev3(j)];
    const bool s_bd = u.is_subsegment(next3(j)), s_dc = u.is_subsegment(prev3(j));

    const std::uint8_t keep = Triangle::live_bit;
    t.v[0] = a, t.v[1] = b, t.v[2] = d;
    t.flags = keep;
    t.bump_generation();
    u.v[0] = d, u.v[1] = c, u.v[2] = a;
    u.flags = keep;
    u.bump_generation();

    // t: edge 0 = b-d, edge 1 = d-a (diagonal), edge 2 = a-b.
    mesh.link(EdgeRef(tid, 0), n_bd);
    t.set_subsegment(0, s_bd);
    mesh.link(EdgeRef(tid, 2), n_ab);
    t.set_subsegment(2, s_ab);
    // u: edge 0 = c-a, edge 1 = a-d (diagonal), edge 2 = d-c.
    mesh.link(EdgeRef(uid, 0), n_ca);
    u.set_subsegment(0, s_ca);
    mesh.link(EdgeRef(uid, 2), n_dc);
    u.set_subsegment(2, s_dc);
    mesh.link(EdgeRef(tid, 1), EdgeRef(uid, 1));
    return EdgeRef(tid, 1);
}

}  // namespace gpdr::mesh
