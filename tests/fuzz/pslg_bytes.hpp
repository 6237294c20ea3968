#pragma once
// The pipeline fuzz target's input format: a few bytes of switches, then a
// small PSLG on a grid of 256 x 256 points, mapped by one of a few affine
// maps (some exact, some that make every crossing point inexact: scaled by
// 0.1 or 0.001, offset by a million).  A binary format spends the fuzzer's
// effort on geometry rather than on the file syntax that the reader targets
// cover, and every byte string decodes to some valid input.
//
//   byte 0   bits 0-1  what to run: 0 -p, 1 -pq, 2 -pc, 3 -r (refine the
//                      mesh that -p, or a plain triangulation when there are
//                      no segments, made of the same PSLG)
//            bit 2     -D
//            bit 3     -a: a global bound, a fraction of the bounding box's
//                      area (byte 4), and bare -a (regions' bounds; with -r,
//                      one bound per triangle from the bytes left over)
//            bits 4-5  -P0, -P1, -P2 (3: the default)
//            bit 6     -Y
//            bit 7     -A
//   byte 1   bits 0-2  the -q angle: 20 25 30 33 0 10 15 34 degrees
//            bits 3-5  the map from grid to coordinates (grid_map())
//            bit 6     -j (jettison unused vertices)
//            bit 7     -o2
//   byte 2   vertex count (at most max_vertices)
//   byte 3   segment count (at most max_segments)
//   byte 4   bits 0-1 holes, bits 2-3 regions, bits 4-7 the -a fraction
//            (2^-(k+1) of the bounding box's area)
//   then     2 bytes (signed x, y) per vertex, 2 (endpoint indices, taken
//            modulo the vertex count) per segment, 2 per hole, 4 per region
//            (x, y, attribute, area: 0 none, else the box's area / k)
//   then     with -r -a: one byte per triangle of the mesh refined (as a
//            region's area)
// A count larger than the bytes that follow is cut to what is there.
//
// Every run carries -S with a small Steiner point budget and one thread, so
// that refinement cannot run away and a run does the same on every machine.

#include <cstddef>
#include <cstdint>
#include <span>

#include <gpdr/memory_job.hpp>
#include <gpdr/options.hpp>

namespace gpdr::fuzz {

inline constexpr std::size_t max_vertices = 40;
inline constexpr std::size_t max_segments = 60;
inline constexpr std::uint64_t steiner_budget = 300;

struct PipelineCase {
    Options options;  // the run (for -r: the refining run)
    MeshInput input;  // for -r: the PSLG the mesh to refine is made of
    bool refine = false;
    Options first;                             // -r: the run that makes the mesh to refine
    std::span<const std::uint8_t> area_bytes;  // -r -a: per-triangle bounds
    double box_area = 0;
};

PipelineCase decode_pipeline_case(std::span<const std::uint8_t> bytes);

// -r -a: one bound per triangle of `triangles` from the case's area bytes,
// repeated as needed (none left: no bound).
AreaSet triangle_area_bounds(const PipelineCase& c, std::size_t triangles);

}  // namespace gpdr::fuzz
