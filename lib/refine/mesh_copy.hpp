#pragma once
// A copy of a mesh, for refinement that is tried more than once (above 34
// degrees, refine/attempts.hpp): each try starts from a copy of the
// constrained Delaunay mesh, so that a try that does not end leaves nothing
// behind.
//
// The copy holds the same vertices (ids, points, kinds, attributes), the same
// triangle slots (ids, records, generations, dead slots and their free
// lists), the same subsegment entries and the same spare slots for the next
// pool, so that refining the copy makes the same mesh, with the same ids, as
// refining the original would.

#include "mesh/mesh.hpp"

namespace gpdr::refine {

// Copies `from`, which no pool may be using.  `from` is not changed (its
// spare slots are taken and given back in the same order).  Throws
// std::bad_alloc when memory runs out.
mesh::Mesh copy_mesh(mesh::Mesh& from);

}  // namespace gpdr::refine
