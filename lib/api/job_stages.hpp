#pragma once
// The stages of one gpdr run (job.cpp strings them together): read,
// triangulate, refine, turn the finished mesh into arrays, write the files.

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <gpdr/file_names.hpp>
#include <gpdr/files.hpp>
#include <gpdr/options.hpp>

#include <gpdr/diagnostics.hpp>
#include <gpdr/job.hpp>
#include <gpdr/memory_job.hpp>
#include <gpdr/progress.hpp>

#include <gpdr/io.hpp>

#include "api/mesh_arrays.hpp"
#include "check/input_check.hpp"
#include "geometry/area_field.hpp"
#include "mesh/mesh.hpp"
#include "parallel/refine_parallel.hpp"
#include "refine/refine.hpp"
#include "triangulate/pslg.hpp"

namespace gpdr::api {

// Everything the input files say, read and validated before anything else
// happens, so that a malformed file is reported by file and line whatever
// the switches ask for.
struct Input {
    io::ReadResult<NodeSet> nodes;
    std::string node_file;            // where the vertices came from
    std::string poly_file, ele_file;  // the files read, for messages
    std::optional<PolyFile> poly;     // -p (its nodes moved into `nodes`)
    std::optional<EleSet> triangles;  // -r
    std::optional<AreaSet> areas;     // -r with bare -a
    std::uint64_t content_hash = 0;   // of every file read, in order (the run stamp's)
};
Input read_input(const Options& options, const FileNames& names, const WarningSink& warn);

// The same from arrays in memory (run_job_in_memory): the parts the switches
// use, checked as the readers check a file (indices in range, counts that
// agree, finite coordinates), with `input.name` for the file in messages.
Input input_from_memory(const Options& options, MeshInput input);

// -C: the input geometry the finished mesh is checked against, taken from
// `in` before triangulate_input() takes its coordinates.
mesh::InputGeometry input_geometry(const Options& options, const Input& in);

// The mesh before refinement, and what later stages need to know about how
// it was made.
struct Triangulated {
    mesh::Mesh mesh;
    std::uint64_t duplicates = 0;      // input vertices left out
    std::uint64_t steiner_points = 0;  // vertices -D added
    // Input segment ends (2 per segment), for refinement's small-angle rule.
    std::vector<mesh::VertexId> segment_ends;
    // Triangle attributes by region index (Triangle::region):
    // triangle_attribute_count values per region, region 0 first.
    std::uint32_t triangle_attribute_count = 0;
    std::vector<double> region_attributes;
    // -ra: the .area file's bounds as a field over the triangles read.
    std::unique_ptr<geometry::AreaField> area_field;
    // -p: the PSLG and what the CDT reported, for -C's conformity check.
    std::optional<triangulate::Pslg> pslg;
    triangulate::CdtReport cdt_report;
};
Triangulated triangulate_input(const Options& options, Input& input, const WarningSink& warn);

// Refinement: whether the switches ask for it.
bool wants_refinement(const Options& options);
// What refinement did: the schedule it ran on, the refiner's report (its
// `refine` member as refine_mesh reports it), and the user test it met.
struct Refinement {
    parallel::Schedule schedule;
    parallel::ParallelReport report;
    refine::UserTest user_test;
};
// The refinement stage: the settings the switches ask for (throws
// UsageError for -u with no function), the -S budget left after the
// vertices triangulation added, the memory refusal (refuse_beyond_memory),
// the progress line's count, the refiner on the schedule the options choose,
// and the warnings before and after.
Refinement refine_stage(const Options& options, const JobPlugins& plugins, const Input& input,
                        Triangulated& tri, const WarningSink& warn, Progress* progress);
// -V's lines on a refinement: its schedule and why, and for rounds their
// shape and each thread's time.
std::vector<std::string> refinement_lines(const Refinement& refinement);

// The finished mesh as arrays.  `nodes` are the input vertices (ids 0..n-1 of
// the mesh; attributes and markers kept); the vertices the mesh added after
// them follow in id order, skipping ids claimed but never used, with the
// attributes the mesh keeps for them (mesh/vertex_attributes.hpp).  Vertex markers follow Triangle:
// a non-zero input marker is kept, otherwise a vertex on a subsegment takes its marker, otherwise a
// vertex on the boundary gets 1 and any other 0. Triangles get `attribute_count` attributes each
// from `region_attributes` by their region index.  The neighbour array is filled only when asked
// for; without `materialise` the triangles stay in the mesh, which must then outlive the arrays
// (MeshArrays::stream), and so must region_attributes. Without `mesh_ids` MeshArrays::mesh_ids
// stays empty. The coordinates of all vertices come from
// the mesh, which keeps the input ones exactly: the caller may free nodes.xy once the mesh is
// built, as long as the other arrays of `nodes` keep their input_count entries.  The passes over
// the vertices and the triangles run on `threads` threads; the arrays do not depend on it.
struct ArrayChoices {
    bool neighbours = false;   // fill the neighbour array
    bool materialise = false;  // copy the triangles out of the mesh
    // Fill MeshArrays::mesh_ids (4 bytes a vertex, at the moment memory use
    // peaks): the outputs that need a node's mesh vertex want them.
    bool mesh_ids = true;
    unsigned threads = 1;
    // The mesh being copied, when nothing will read its points once they
    // are in the arrays (the files are written from the arrays): the point
    // table is then given back to the system as the points are copied, so
    // that the points are not held twice at the moment memory use peaks
    // (the coordinates are 16 bytes a vertex, a fifth of the output stage
    // of the graded pipe).  The coordinates are then copied on one thread.
    mesh::Mesh* free_points_of = nullptr;
};
MeshArrays mesh_to_arrays(const mesh::Mesh& mesh, NodeSet nodes, std::size_t input_count,
                          std::uint32_t attribute_count, std::span<const double> region_attributes,
                          const ArrayChoices& choices);

// What mesh_to_arrays would count, without the arrays: the nodes (input
// vertices, duplicates included, and the vertices added), the triangles and
// the hull edges.  For a run that writes no file and prints no statistics.
struct MeshCounts {
    std::uint64_t nodes = 0;
    std::uint64_t triangles = 0;
    std::uint64_t hull_edges = 0;
};
MeshCounts count_mesh(const mesh::Mesh& mesh, std::size_t input_count, unsigned threads);

// The marker of mesh edge {a, b} (Triangle's rules): a subsegment's own
// marker if non-zero, else 1 on the boundary, else 0.
EdgeMarker edge_markers(const mesh::Mesh& mesh);

// What the outputs derive from the arrays.  -j drops the unused vertices
// first; the edges (-e), the Voronoi diagram (-v) and the edge count (-g) are
// taken before -o2 makes the triangles six-node, which it does last.
struct PreparedOutputs {
    EdgeMarker mesh_marker;  // edge markers by mesh vertex ids
    EdgeSet edges;
    VoronoiDiagram voronoi;
    std::uint64_t edge_count = 0;
};
PreparedOutputs prepare_outputs(const Options& options, const mesh::Mesh& mesh, MeshArrays& arrays);

// The outputs the switches ask for, in memory: what write_outputs() would
// write, without the files.  -j and -o2 change `arrays`, and its vectors are
// moved into the result.
MeshOutput output_in_memory(const Options& options, const mesh::Mesh& mesh, MeshArrays& arrays);

// Everything about the output a run needs besides the mesh.
struct OutputRequest {
    const Options* options = nullptr;
    const FileNames* names = nullptr;
    int base = 1;                    // numbering base of the run
    const PolyFile* poly = nullptr;  // the input PSLG (holes, regions), if any
    bool write_hull_poly = false;    // -c on a point set: .poly of the hull
    std::string stamp;               // the run stamp every file's last line carries
    Progress* progress = nullptr;    // the writing stage and the files done, if given
};

// Whether the switches ask for any file (write_hull_poly: as
// OutputRequest's).
bool writes_files(const Options& options, const FileNames& names, bool write_hull_poly);

// Writes every file the switches ask for, all or none (an output
// transaction), and returns their names in the order written.  -j and -o2
// change `arrays`.
std::vector<std::string> write_outputs(const OutputRequest& request, const mesh::Mesh& mesh,
                                       MeshArrays& arrays);

}  // namespace gpdr::api
