#pragma once
// Rebuilding a mesh from a list of triangles: Triangle's -r (refine a mesh
// read back from .node and .ele files, with -rp also the .poly's segments).
//
// Vertex ids equal input indices; triangle i of the input becomes
// TriangleId i (created in order by a fresh Pool on a fresh Mesh).
// Neighbour links come from matching edges: every edge is filed under its
// lower vertex (a counting sort), each vertex's short list is sorted by the
// other vertex, and equal neighbours in it are the two sides of one edge.
// O(n) plus tiny sorts; no hashing.
//
// The input is checked, and a GeometryError names the first triangle (in the
// file's numbering, `index_base`) that is wrong:
//   - a corner out of range or repeated, a coordinate that is not finite;
//   - corners not strictly counter-clockwise (clockwise or zero area, by
//     the exact orient2d);
//   - an edge shared by three or more triangles;
//   - two triangles on the same side of an edge (both have it in the same
//     direction: they overlap);
//   - the triangles around a vertex winding around it more than once (its
//     star overlaps itself; counted exactly by coordinate comparisons).
// These are local checks.  They do not prove that the triangles tile the
// plane without overlap: two separate pieces of mesh could lie on top of
// each other, a boundary could cross another, or two vertices at the same
// position could both be used (legitimate along a crack, overlapping
// elsewhere).  Triangle checks none of this.
//
// What refinement must assume of the result.  The mesh is a valid
// triangulation (mesh::check_mesh with delaunay = false passes) but NOT
// necessarily Delaunay nor constrained Delaunay: Triangle's -r accepts any
// mesh.  Bowyer-Watson insertion on a non-Delaunay mesh may grow a cavity
// that is not star-shaped from the new point, so the refiner must first make
// the mesh constrained Delaunay (flip non-locally-Delaunay edges that are not
// subsegments, Lawson's algorithm) or insert by a method that does not rely
// on it.  Every boundary edge (a side with no triangle: hull and hole
// boundaries) is a subsegment, as in Triangle's reconstruct(), so refinement
// never inserts a point outside the mesh.
//
// Segments (-rp): a segment that is an edge of the mesh is flagged on both
// sides and entered in the side table (marker, source index).  On the
// boundary a marker of 0 becomes 1, as Triangle does; other boundary edges
// get marker 1 and no source segment.  A segment that is not an edge of the
// mesh is inserted (constrained.hpp's insert_segment: the triangles it
// crosses are replaced by a constrained Delaunay retriangulation of the two
// sides, subsegments it crosses are split by new vertices) and listed in the
// report.  (Triangle keeps such a segment in its list but not in the mesh:
// it is written to the output .poly and never enforced; gpdr enforces it.)
// A segment that cannot be inserted (it leaves the mesh, or an end is in no
// triangle) is a GeometryError.  Triangles made by insertion take the
// attributes of a neighbour on the same side of the new segment.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/point.hpp"
#include "mesh/mesh.hpp"
#include "triangulate/constrained.hpp"

namespace gpdr::triangulate {

struct TriangleMeshInput {
    std::span<const geometry::Point> points;
    // corners_per_triangle per triangle, 0-based; only the first three are
    // read (a six-node .ele passes its midpoints along, unused).
    std::span<const std::uint32_t> corners;
    std::uint32_t corners_per_triangle = 3;
    // attribute_count values per triangle (may be empty when 0).
    std::span<const double> attributes;
    std::uint32_t attribute_count = 0;
    // Segments: 2 endpoints each, 0-based; markers one per segment or empty.
    std::span<const std::uint32_t> segments;
    std::span<const int> segment_markers;
    // The numbering the messages use for triangles and vertices (the file's
    // first index, 0 or 1).
    int index_base = 0;
};

struct TriangleMeshReport {
    std::size_t boundary_edges = 0;       // edges with a triangle on one side only
    std::size_t unused_vertices = 0;      // vertices no triangle uses
    std::size_t segments_flagged = 0;     // segments that are mesh edges, now subsegments
    std::size_t segments_repeated = 0;    // same endpoints as an earlier segment (the first wins)
    std::size_t segments_degenerate = 0;  // equal endpoints, ignored
    // Segments (input indices) that were not edges of the mesh, inserted;
    // what insertion did beyond flagging edges (new vertices where they
    // crossed subsegments, vertices they pass through), in order.
    std::vector<std::uint32_t> missing_segments;
    std::size_t segments_inserted = 0;
    std::vector<SegmentEvent> segment_events;
    // The triangle attributes in TriangleId order: attribute_count values
    // for each id below the mesh's triangle_end() (0 for dead slots), so the
    // caller can write them back and later stages can carry them.
    std::vector<double> attributes;
};

// Throws gpdr::GeometryError as described above (the caller adds the file
// name).  Does not modify the input.
mesh::Mesh from_triangles(const TriangleMeshInput& input, TriangleMeshReport& report);

}  // namespace gpdr::triangulate
