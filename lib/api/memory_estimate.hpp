#pragma once
// Before refinement starts: the memory the finished mesh will take, from the
// triangles its area bounds call for, and the refusal of a run whose mesh
// would not fit in the memory available (ResourceError), which --force
// overrides.  An angle bound alone (-q) or a user test (-u) gives no sound
// estimate and is never refused; neither is a run without area bounds.

#include <cstdint>
#include <optional>

#include <gpdr/options.hpp>

#include "mesh/mesh.hpp"
#include "refine/refine.hpp"

namespace gpdr::api {

struct MemoryEstimate {
    bool known = false;    // false: the switches give no estimate
    double triangles = 0;  // the finished mesh's triangles
    double bytes = 0;      // the run's peak memory
};

// The peak memory of a run, per triangle of its finished mesh, measured as
// peak resident size over triangles on the pipe sample refined to an area
// bound (8.7 to 8.9 million triangles, one and two threads): 60 to 64 bytes
// when the outputs are the .node and .ele files, 97 to 99 with .neigh and
// .edge, whose neighbours add 12 bytes a triangle and whose edge list more.
// Vertex attributes add, per vertex (about one for every two triangles), the
// values held twice (beside the mesh and in the output's arrays).
inline constexpr double bytes_per_triangle = 64;
inline constexpr double bytes_per_triangle_with_neighbours = 100;

MemoryEstimate estimate_memory(const Options& options, const mesh::Mesh& mesh,
                               const refine::RefineSettings& settings,
                               std::uint32_t vertex_attributes);

// Throws ResourceError when `estimate` exceeds `available` (none: nothing is
// known, so nothing is refused), unless options.force.
void refuse_beyond_memory(const Options& options, const MemoryEstimate& estimate,
                          std::optional<std::uint64_t> available);

}  // namespace gpdr::api
