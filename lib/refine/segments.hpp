#pragma once
// What refinement needs to know about subsegments around a vertex:
//   - the edges of a vertex's star (rotation through neighbour links);
//   - whether a subsegment is encroached: a point strictly inside its
//     diametral circle (Ruppert 1995);
//   - where to split it: the midpoint, or Ruppert's concentric shells (as in
//     Shewchuk's Triangle) where the subsegment ends at an input vertex that
//     another subsegment leaves at an angle small enough for the split
//     points of each to encroach the other: then the split point is at a
//     power-of-two distance from that vertex, so splits on two segments
//     meeting at a small angle fall on common circles and stop encroaching
//     on each other.  Wider corners are split at midpoints: shells there
//     buy nothing and cost triangles (a crossing point, where the four
//     pieces meet at the crossing angle and its supplement, is such a
//     vertex);
//   - the small-input-angle rule (Shewchuk, "Delaunay refinement algorithms
//     for triangular mesh generation", 2002, as Triangle applies it): a
//     skinny triangle is left alone when both ends of its shortest edge are
//     segment vertices lying on two different segments that share an input
//     vertex, at equal distance from it (within 0.1% in squared distance),
//     and meeting there at less than 60 degrees.  Concentric-shell
//     splitting puts them exactly there, and such a triangle's small angle
//     is forced by the input angle; at 60 degrees and above the bound is
//     reachable and nothing is left.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/point.hpp"
#include "mesh/mesh.hpp"

namespace gpdr::refine {

// f(EdgeRef e) for every edge incident to v, once each; `t` is a live
// triangle with corner v.  e is an edge of a triangle around v; its other
// end is the vertex of e that is not v.  Rotation stops at boundary edges
// (no neighbour) and goes round the other way from t.
template <class F>
void for_each_edge_at(const mesh::Mesh& mesh, mesh::TriangleId t, mesh::VertexId v, F&& f) {
    using mesh::EdgeRef;
    using mesh::next3;
    using mesh::prev3;
    // Counter-clockwise: each triangle reports its edge v -> next corner and
    // moves across its edge previous corner -> v.
    mesh::TriangleId cur = t;
    for (int guard = 0; guard < (1 << 20); ++guard) {
        const mesh::Triangle& r = mesh.triangle(cur);
        const int i = r.corner_of(v);
        f(EdgeRef(cur, prev3(i)));
        const EdgeRef across = r.n[next3(i)];
        if (across.is_none()) {
            f(EdgeRef(cur, next3(i)));
            break;
        }
        cur = across.triangle();
        if (cur == t) return;
    }
    // Clockwise from t (only reached when a boundary stopped the rotation).
    cur = t;
    for (int guard = 0; guard < (1 << 20); ++guard) {
        const mesh::Triangle& r = mesh.triangle(cur);
        const EdgeRef across = r.n[prev3(r.corner_of(v))];
        if (across.is_none()) return;
        cur = across.triangle();
        const mesh::Triangle& u = mesh.triangle(cur);
        const int j = u.corner_of(v);
        // u's edge next corner -> v is the one just crossed (reported);
        // its edge v -> next corner is new.
        f(EdgeRef(cur, prev3(j)));
    }
}

// The end of edge e that is not v.
inline mesh::VertexId other_end(const mesh::Mesh& mesh, mesh::EdgeRef e, mesh::VertexId v) {
    const mesh::VertexId a = mesh.origin(e);
    return a == v ? mesh.destination(e) : a;
}

// Whether p encroaches subsegment ab: it sees ab at an angle above 90
// degrees (strictly inside the diametral circle) when lens == 0, or above
// 180 - 2 theta degrees (inside the diametral lens) when lens = cos(2 theta).
// Quality refinement uses lenses, as Triangle does (Shewchuk, "Delaunay
// refinement algorithms for triangular mesh generation", 2002): fewer
// subsegment splits, the same guarantees; conforming Delaunay (-D) needs
// circles.  With u = a - p, v = b - p the angle is above 180 - 2 theta when
// u.v < 0 and (u.v)^2 > lens^2 |u|^2 |v|^2.  lens >= 1 (the lens of an
// angle bound of 0: refinement by size alone) is empty: nothing encroaches.
inline bool encroaches(const geometry::Point& a, const geometry::Point& b, const geometry::Point& p,
                       double lens = 0.0) {
    const double ux = a.x - p.x, uy = a.y - p.y, vx = b.x - p.x, vy = b.y - p.y;
    const double dot = ux * vx + uy * vy;
    if (dot >= 0 || lens >= 1.0) return false;
    return lens == 0.0 || dot * dot > lens * lens * (ux * ux + uy * uy) * (vx * vx + vy * vy);
}

// Whether subsegment e (a flagged edge) is encroached by the apex of either
// of its triangles.  In a constrained Delaunay mesh that is the same as being
// encroached by a vertex visible from it.
bool subsegment_encroached(const mesh::Mesh& mesh, mesh::EdgeRef e, double lens = 0.0);

// Whether another subsegment leaves input vertex a at an angle to
// subsegment a-b at which a point of one can encroach a subsegment of the
// other that ends at a (e is an edge with end a, in a triangle around a).
// A point p on one ray at angle phi from the other sees a subsegment a-c
// on it at less than 180 - phi degrees, and encroaches only above
// 180 - 2 theta (the lens of encroaches()): so only phi < 2 theta, that is
// cos(phi) > lens, can encroach.  With diametral circles (lens 0), or
// where no vertex encroaches (lens >= 1: a rejected Steiner point still
// splits), the bound is 90 degrees.
bool acute_corner(const mesh::Mesh& mesh, mesh::EdgeRef e, mesh::VertexId a, mesh::VertexId b,
                  double lens = 0.0);

// Where to split subsegment e: the parameter along origin(e) -> destination(e)
// (0.5, or a concentric-shell parameter as described above); `lens` as
// encroaches() takes it.
double split_parameter(const mesh::Mesh& mesh, mesh::EdgeRef e, double lens = 0.0);

// Input segment ends by SubsegmentInfo::segment: 2 per segment (may be
// empty; then segment ends are found by walking the subsegment chain).  A
// pair of no_vertex means "unknown": no protection.
struct SegmentEnds {
    std::span<const mesh::VertexId> ends;
};

// The ends of the input segment that subsegment e lies on, found by walking
// the chain of subsegments through segment vertices both ways from e (at
// most 256 steps each way); false when a walk is longer or breaks.  The
// walk may go anywhere along the segment: the parallel layer calls it before
// its workers start, never while they run (parallel/segment_labels.hpp).
bool walk_segment_ends(const mesh::Mesh& mesh, mesh::EdgeRef e,
                       std::array<mesh::VertexId, 2>& ends);

// The same walk, however long the chain, also listing every subsegment on it
// (e's first, as (origin, destination); the others as met) in `pieces`: the
// parallel layer labels a whole chain from one walk, so that labelling every
// subsegment costs time linear in their number, where walking from each one
// would cost the chain's length for each.  False when the chain breaks; the
// pieces walked are listed all the same, and `ends` holds no_vertex on the
// broken side.
bool walk_segment_chain(const mesh::Mesh& mesh, mesh::EdgeRef e,
                        std::array<mesh::VertexId, 2>& ends,
                        std::vector<std::array<mesh::VertexId, 2>>& pieces);

// The small-input-angle rule above for triangle t whose shortest edge is
// edge k.
bool small_angle_protected(const mesh::Mesh& mesh, mesh::TriangleId t, int k,
                           const SegmentEnds& segments);

}  // namespace gpdr::refine
