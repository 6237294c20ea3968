#pragma once
// Segment conformity: every input segment that the CDT kept is a union of
// subsegments of the mesh (the check mesh::check_mesh cannot make, since it
// does not know the input).  For tests and for -C.
//
// Each segment a-b is walked from a: the next vertex is the far end of a
// flagged edge out of the current vertex that lies exactly on a-b (exact
// orient2d) and strictly closer to b, or was reported on it by the CDT
// (crossings are rounded points; a crossing that cannot be represented
// beside a sliver is snapped to a vertex).  The walk is depth-first, since
// near-coincident vertices can offer two ways on.  Where the walk finds none, the
// segment is accepted as leaving the mesh only if the direction toward b
// enters no triangle of the current vertex (a hole or the exterior ate that
// part); the walk then resumes at the nearest vertex further along the
// segment that still has a triangle (found by a scan of all vertices, so a
// mesh with many eaten segments makes the check slow, never wrong).

#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "triangulate/pslg.hpp"

namespace gpdr::triangulate {

// Problems found, each a sentence naming the segment and vertices; empty
// when the mesh conforms.  `report` is the one the CDT filled (skipped
// segments, duplicate vertices).
std::vector<std::string> check_conformity(const mesh::Mesh& mesh, const Pslg& pslg,
                                          const CdtReport& report, std::size_t max_problems = 100);

}  // namespace gpdr::triangulate
