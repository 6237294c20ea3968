#pragma once
// Carving the domain out of a constrained Delaunay triangulation of the
// convex hull: holes, the exterior, regions (Triangle's -p without -c, -c,
// -O, and regional attributes / area bounds).
//
// Infection (Triangle calls it the plague): a triangle is infected, and the
// infection spreads to every neighbour across an edge that is not a
// subsegment.  Sources:
//   - each hole point (unless ignore_holes): the triangle containing it; a
//     hole point outside the mesh, on a vertex or on a subsegment does nothing;
//   - without convex_hull, the triangle of every hull edge that is not a
//     subsegment (Triangle's "concavities": what lies outside the segments).
// Infected triangles are killed; their surviving neighbours get `none`
// across the shared edge (it becomes a boundary edge).  A subsegment with no
// triangle left on either side is dropped from the side table.  Vertices
// left with no triangle stay in the store (written unless -j).
//
// With convex_hull every hull edge that is not a subsegment becomes one,
// marker 1 and no source segment; a vertex within rounding of a hull edge
// bends it, as it bends an input segment, and the sliver between them is
// killed.
//
// Regions, after the carving: from the triangle containing each region point
// (located before anything is killed; nothing if it was killed), the region
// spreads across non-subsegment edges and sets Triangle::region = index + 1.
// Later regions overwrite earlier ones, as in Triangle.

#include "mesh/mesh.hpp"
#include "triangulate/pslg.hpp"

namespace gpdr::triangulate {

// Throws gpdr::GeometryError when there are more regions than the triangle
// record can number (65534).
void carve_domain(mesh::Mesh& mesh, const Pslg& pslg, const CdtOptions& options);

}  // namespace gpdr::triangulate
