#pragma once
// A finished mesh in the array form Triangle's files use, and what the output
// stage derives from it: edges, the Voronoi diagram, six-node triangles,
// jettisoned vertices, -V statistics.  Working on arrays (not on the live
// mesh) keeps these independent of how the mesh is stored.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <gpdr/files.hpp>
#include <gpdr/io.hpp>

namespace gpdr::api {

struct MeshArrays {
    NodeSet nodes;            // every vertex of the output (input vertices first)
    EleSet triangles;         // 3 corners each, counter-clockwise
    NeighbourSet neighbours;  // neighbour k opposite corner k, none on the boundary
    // For each node, the mesh vertex id it came from (the mesh may number
    // differently: ids claimed but never used are skipped).  Kept in step by
    // jettison_unused_vertices(); make_second_order() leaves the new midpoint
    // nodes out (they have no mesh vertex).
    std::vector<std::uint32_t> mesh_ids;
    // Triangles may instead stay in the mesh until they are written
    // (`triangles` is then empty): `stream` makes a source that reads them
    // from the mesh in order, triangle_count of them.  It saves a copy of
    // the mesh at the moment memory use peaks; outputs derived from the
    // triangle array (-e -n -v -g -o2 -j) need them materialised.
    std::size_t triangle_count = 0;
    std::function<io::EleSource()> stream;
    // The mesh's subsegments as segments between nodes, with their markers
    // (in the order of mesh::for_each_edge), and the number of its hull
    // edges, found by the walk that numbers the triangles: the output's
    // segments and -V's count need no other.  jettison_unused_vertices()
    // keeps the segments in step.
    SegmentSet segments;
    std::uint64_t hull_edge_count = 0;
};

// The triangles of `mesh`, from the array or from the stream.
io::EleSource triangle_source(const MeshArrays& mesh);

// The marker of the edge joining vertices a and b: the caller knows which
// edges are subsegments and what their markers are.  Called for every edge;
// `boundary` says whether the edge has a triangle on one side only.
using EdgeMarker = std::function<int(std::uint32_t a, std::uint32_t b, bool boundary)>;

// Every edge once: for each triangle in order, its edges opposite corners
// 0, 1, 2 whose neighbour is none or has a larger index.
EdgeSet edges_of(const MeshArrays& mesh, const EdgeMarker& marker);

// The number of edges (as edges_of would list them) and of boundary edges.
struct EdgeCounts {
    std::uint64_t edges = 0;
    std::uint64_t boundary = 0;
};
EdgeCounts count_edges(const MeshArrays& mesh);

// The Voronoi diagram dual to the mesh: vertex j is triangle j's circumcentre
// (with the vertex attributes interpolated there as Triangle does: a plain
// average would not be linear; we take the barycentric interpolation at the
// circumcentre), one edge per mesh edge; a boundary edge gives a ray leaving
// its triangle's circumcentre along the edge's outward normal.
struct VoronoiDiagram {
    NodeSet vertices;
    io::VoronoiEdgeSet edges;
};
VoronoiDiagram voronoi_of(const MeshArrays& mesh);

// -o2: appends a vertex at the midpoint of every edge (attributes averaged,
// marker from `marker`) and makes every triangle six-node: corners 4, 5, 6 are
// the midpoints of the edges opposite corners 1, 2, 3.
void make_second_order(MeshArrays& mesh, const EdgeMarker& marker);

// -j: drops vertices no triangle uses and renumbers the rest in their order.
// Returns, for each old vertex, its new index (or NeighbourSet::none).
std::vector<std::uint32_t> jettison_unused_vertices(MeshArrays& mesh);

// Triangle's "Mesh quality statistics" block for -V, as lines of text,
// computed on up to `threads` threads over runs of `chunk_size` triangles
// (the same text for any number of threads).
std::vector<std::string> quality_statistics(const MeshArrays& mesh, unsigned threads = 1,
                                            std::size_t chunk_size = 16384);

}  // namespace gpdr::api
