#pragma once
// Segment conformity: every piece of an input segment (the segments cut at
// crossings and vertices, arrangement.hpp) is a union of subsegments of the
// mesh (the check mesh::check_mesh cannot make, since it does not know the
// input).  Only tests make it (of the CDT, and of whole runs in tests/api),
// so it lives beside them: it reads the subsegment flags and side table,
// which -C's check against the input (check/input_check.hpp) deliberately
// ignores.
//
// Each piece a-b is walked from a: the next vertex is the far end of a
// flagged edge out of the current vertex that lies exactly on a-b (exact
// orient2d) and strictly closer to b, or that refinement recorded as a split
// point of the piece (rounded, so possibly just off the line).  The walk is
// depth-first, since near-coincident vertices can offer two ways on.  Where the walk finds none,
// the segment is accepted as leaving the mesh only if the direction toward b enters no triangle of
// the current vertex (a hole or the exterior ate that part); the walk then resumes at the nearest
// vertex further along the segment that still has a triangle (found by a scan of all vertices, so a
// mesh with many eaten segments makes the check slow, never wrong).

#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "triangulate/pslg.hpp"

namespace gpdr::triangulate {

// Problems found, each a sentence naming the segment and vertices; empty
// when the mesh conforms.  `report` is the one the CDT filled: its pieces are
// what is walked (`pslg` is the input they came from).
std::vector<std::string> check_conformity(const mesh::Mesh& mesh, const Pslg& pslg,
                                          const CdtReport& report, std::size_t max_problems = 100);

}  // namespace gpdr::triangulate
