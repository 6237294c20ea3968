#pragma once
// Delaunay triangulation of a point set.
//
// Incremental Bowyer–Watson insertion (point_inserter.hpp, the point-set form
// of mesh/insert.hpp, making the same mesh) in BRIO order with a
// Hilbert curve inside each round (spatial_sort.hpp), each point located by a
// walk from a triangle of the point inserted before: O(n log n) expected.
//
// The convex hull is handled with a ghost vertex: every hull edge carries a
// ghost triangle (the edge and ghost_vertex) while points are inserted, so a
// point outside the current hull needs no special case and no bounding
// triangle distorts the result.  The ghosts are removed at the end: hull
// edges of the returned mesh have EdgeRef::none() as neighbour, and the mesh
// holds only real triangles.
//
// Vertex ids equal input indices.  Exactly equal points: the one with the
// lowest index is kept in the triangulation; each other one is left out
// (VertexKind::duplicate) and reported as (duplicate index, kept index).
// The mesh is Delaunay; with cocircular points the choice among the
// possible triangulations depends on the insertion order, which is fixed.

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "geometry/point.hpp"
#include "mesh/mesh.hpp"

namespace gpdr::triangulate {

struct DelaunayReport {
    // (duplicate index, kept index), sorted by duplicate index.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicates;
};

// With threads >= 2 and at least parallel_from points, most points are
// inserted in bands on several threads (strip_inserter.hpp).  The mesh then
// has the same triangles as with one thread, numbered otherwise, and the
// same for every thread count: where the Delaunay triangulation is not
// unique (four or more points on an empty circle), the points are
// triangulated again on one thread.
struct DelaunayOptions {
    unsigned threads = 1;
    std::size_t parallel_from = 200'000;
};

// Throws gpdr::GeometryError when the points have fewer than three distinct
// positions, are all collinear, or a coordinate is not finite.
mesh::Mesh delaunay(std::span<const geometry::Point> points, DelaunayReport& report,
                    const DelaunayOptions& options = {});

}  // namespace gpdr::triangulate
