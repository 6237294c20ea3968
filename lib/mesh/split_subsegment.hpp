#pragma once
// Splitting a subsegment by a new vertex: the one operation that puts a
// vertex on a constrained edge.  The CDT uses it where two segments cross;
// refinement will use it for encroached subsegments.
//
/*
                 w                              w
                / \                            /|\
               /   \                          / | \
              / t1  \                        /  |  \
             /       \                      /   |   \
            x====s====y        ==>         x====p====y
             \       /                      \   |   /
              \  u  /                        \  |  /
               \   /                          \ | /
                \ /                            \|/
                 z                              z
*/
// Before: s is the subsegment x -> y of triangle t1 (apex w); u is the
// triangle across it (apex z), or s is a hull edge and u does not exist.
// After: a new vertex p, and x-p, p-y are subsegments (flag on both sides,
// side-table entries with the info x-y had; x-y's entry is erased).  The
// drawing shows the smallest cavity; in general the cavity is Bowyer–Watson's:
// t1 and u, plus every triangle reachable from them without crossing a
// subsegment whose circumcircle holds p strictly (exact incircle), so a
// constrained Delaunay mesh stays constrained Delaunay.  The cavity is fanned
// from p; a hull edge x -> y leaves x-p and p-y on the hull.
//
// p should lie on segment x-y strictly between its ends (a constructed point
// may be off the line by rounding).  The exact predicates decide whether the
// fan is valid: every cavity boundary edge must see p strictly on its inner
// side.  If p falls outside t1 and u (possible only for a point rounded
// across a neighbouring edge), it is pulled toward the midpoint of x-y until
// it is inside; so the vertex may be created at a slightly different point
// than asked, and the result names it.  Cavity triangles that cannot see p
// are left out of the cavity.  When p is not exactly on the line x-y, the
// bent subsegments x-p-y can leave edges that are not locally Delaunay;
// Lawson flips from the new triangles then restore the constrained Delaunay
// property (exact incircle).
//
// The result is the InsertResult of insert.hpp (status inserted, the new
// vertex), and the buffer's `created` / `killed` as insert_vertex leaves them
// (created triangles have p at corner 2, except after the flips of a point
// off the line: then `created` also lists every triangle a flip changed, in
// no particular corner order).  Nothing is allocated once the
// buffer has grown.  Throws gpdr::SubsegmentSplitError when p cannot be
// placed in the open quadrilateral (the refiner then leaves the subsegment
// as it is), and gpdr::InternalError when the mesh around s is broken (a
// cavity that is not a disk); either leaves the mesh as it was.

#include "mesh/insert.hpp"

namespace gpdr::mesh {

// Whether p lies strictly inside the two triangles of `subsegment` (or the
// one, on the hull) as seen from the open subsegment, so that
// split_subsegment would put the vertex exactly at p.  Callers that would
// rather snap to an end than move the point ask first.
bool can_split_at(const Mesh& mesh, EdgeRef subsegment, const Point& p);

// Lawson's flips, starting from every edge of the triangles in
// buffer.created, until each edge that is not a subsegment is locally
// Delaunay (exact incircle).  Triangles a flip changes are appended to
// `created`; those with a user tag are saved (appended) in `tagged_gone` as
// they were before the flip, and their tags cleared.  For repairs after a
// change that can break the constrained Delaunay property only locally (a
// bent subsegment, a removed constraint).
void lawson_flips(Mesh& mesh, InsertBuffer& buffer);

InsertResult split_subsegment(Pool& pool, EdgeRef subsegment, const Point& p, VertexKind kind,
                              InsertBuffer& buffer);

}  // namespace gpdr::mesh
