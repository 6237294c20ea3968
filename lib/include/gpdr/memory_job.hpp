#pragma once
// One run of gpdr on data in memory: the same switches and the same stages
// as run_job() (gpdr/job.hpp), but the input comes from arrays instead of
// files and the output goes back into arrays.  This is what libtriangle's
// triangulate() (capi/) calls; C++ programs may call it directly.
//
// Every index is 0-based here, whatever -z says: -z only chooses how
// messages number vertices, triangles and segments (from 0 with -z, from 1
// without), as a file's numbering would.

#include <string>
#include <vector>

#include <gpdr/diagnostics.hpp>
#include <gpdr/files.hpp>
#include <gpdr/io.hpp>
#include <gpdr/job.hpp>
#include <gpdr/options.hpp>

namespace gpdr {

// What the input files would hold.  Which parts are read depends on the
// switches, as for files: `nodes` always; `segments`, `holes` and `regions`
// with -p; `triangles` with -r (and `segments` with -rp); `areas` with -r
// and bare -a.  Every index is checked against `nodes`, every coordinate
// must be finite: an InputError naming `name` reports the first that is not.
struct MeshInput {
    NodeSet nodes;
    SegmentSet segments;          // endpoints index `nodes`
    std::vector<double> holes;    // x, y per hole
    std::vector<Region> regions;  // point, attribute, area bound (negative: none)
    EleSet triangles;             // 3 or more corners each (only the first 3 are used)
    AreaSet areas;                // one per triangle; <= 0: no bound
    std::string name = "input";   // what messages call the input
};

// The finished mesh, as the output files would hold it.  -N, -E, -P and -B,
// which leave out files or marker columns, change nothing here: `nodes` and
// `triangles` are always there, `segments` with -p or -c, and markers always.
struct MeshOutput {
    NodeSet nodes;             // input vertices first (all of them unless -j), then added ones
    EleSet triangles;          // 3 corners each, or 6 with -o2; attributes with -A or -r
    NeighbourSet neighbours;   // -n: neighbour k opposite corner k, NeighbourSet::none outside
    SegmentSet segments;       // -p, -c: the subsegments, with markers
    EdgeSet edges;             // -e: every edge once, with markers
    NodeSet voronoi_vertices;  // -v: one per triangle (no markers)
    io::VoronoiEdgeSet voronoi_edges;  // -v: one per edge, rays pointing outwards
};

struct MemoryJobResult {
    MeshOutput mesh;
    // Counts, stage times, -C findings and -V lines, as run_job() gives them;
    // files_written is empty and write_seconds is the time taken to fill `mesh`.
    // `vertices` leaves out duplicate vertices, which `mesh.nodes` keeps
    // (as the .node file does) unless -j.
    JobResult report;
};

// Runs the job on `input`.  Options::input, -I and -g are ignored (no file
// is read or written), and so are -N, -E, -P and -B (see MeshOutput); -h is
// a UsageError.  Throws gpdr::Error subclasses as
// run_job() does; warnings go to `warn`.
MemoryJobResult run_job_in_memory(const Options& options, MeshInput input, const WarningSink& warn,
                                  const JobPlugins& plugins = {});

}  // namespace gpdr
