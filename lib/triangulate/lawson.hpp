#pragma once
// Lawson's flip algorithm: turns any triangulation into the constrained
// Delaunay triangulation of its vertices and subsegments by flipping edges
// that are not locally Delaunay.  A mesh read back with -r need not be
// Delaunay (Triangle accepts any mesh), but refinement's Bowyer-Watson
// insertion assumes it is constrained Delaunay, so -r runs this first.
//
// Each flip strictly lowers the lifted surface of the triangulation (the
// vertices raised onto the paraboloid z = x^2 + y^2), so no triangulation
// repeats and the loop ends, after O(n^2) flips at worst (Lawson 1977; in
// practice a handful per edge).  Subsegments are never
// flipped.  Triangle ids are kept; a flipped pair gets new generations.

#include <cstddef>

#include "mesh/mesh.hpp"

namespace gpdr::triangulate {

// Returns the number of flips made.
std::size_t make_constrained_delaunay(mesh::Mesh& mesh);

}  // namespace gpdr::triangulate
