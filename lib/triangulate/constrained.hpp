#pragma once
// Constrained Delaunay triangulation of a PSLG (Triangle's -p).
//
// The vertices are triangulated first (delaunay.hpp), then the segments are
// inserted one by one, in input order (insert_segment below), and finally
// the domain is carved (domain.hpp: holes, exterior, regions).
//
// Segment insertion, from vertex a toward vertex b (exact orient2d):
//   - around a, find the triangle whose wedge holds the direction to b;
//   - the edge a-b exists: flag it on both sides, record its side-table
//     entry (an existing subsegment keeps its entry; its marker is replaced
//     only when it is 0 and the new one is not, as Triangle does);
//   - a vertex e exactly on the open segment: insert a-e, continue from e;
//   - a subsegment x-y crosses the segment: a new vertex at the crossing
//     point splits x-y (mesh/split_subsegment.hpp), a-p is inserted, then p-b
//     (both segments are split, as in Triangle).  A crossing within rounding
//     distance of a vertex (relative 1e-12) uses that vertex instead of
//     making a near-duplicate: an end of x-y becomes a vertex of the segment;
//     the segment's own end (or current vertex) splits x-y there;
//   - otherwise the triangles crossed by a-e are removed and the two
//     pseudo-polygons on either side are retriangulated as constrained
//     Delaunay by Anglada's recursion ("An improved incremental algorithm for
//     constructing restricted Delaunay triangulations", 1997): the base edge
//     takes the chain vertex whose circumcircle with it holds no other chain
//     vertex.  Exact incircle; an explicit stack, so long chains do not
//     overflow the call stack.  A vertex whose every triangle is crossed
//     (possible for a vertex of degree 3 or more next to the segment) is not
//     on either chain: it is left out and inserted again afterwards by
//     constrained Bowyer-Watson (mesh/insert.hpp); a subsegment that hung
//     from it into the strip is then recovered the same way.
//
// Everything is reused through a SegmentBuffer: no allocation per segment
// once the buffers have grown.

#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/insert.hpp"
#include "mesh/mesh.hpp"
#include "mesh/pool.hpp"
#include "triangulate/pslg.hpp"

namespace gpdr::triangulate {

// Something insert_segment did beyond flagging edges.
struct SegmentEvent {
    enum class Kind : std::uint8_t {
        crossing,        // `vertex` was created where the segment crossed subsegment from-to
        through_vertex,  // the segment passes through existing `vertex` and was split there
    };
    Kind kind = Kind::crossing;
    mesh::VertexId vertex{};
    mesh::VertexId from{}, to{};   // crossing: ends of the subsegment that was split
    mesh::SubsegmentInfo crossed;  // crossing: its side-table entry
    // The input segment the event is about: the one being inserted, or for a
    // through_vertex with from/to set, the crossed one (split at `vertex`,
    // an end of the inserted segment that lay on it within rounding).
    std::uint32_t segment = mesh::SubsegmentInfo::no_segment;
};

// Scratch and results of insert_segment, owned by the caller and reused.
struct SegmentBuffer {
    mesh::InsertBuffer insert;         // for subsegment splits
    std::vector<SegmentEvent> events;  // what the last insert_segment did, in order

    // Optional vertex -> triangle map, kept up to date when track_corners is
    // set: corner[v] is a triangle that had v as a corner when last written
    // (checked before use, so stale entries are harmless).  It saves the
    // point-location walk at the start of each segment.
    bool track_corners = false;
    std::vector<mesh::TriangleId> corner;

    // Scratch.
    struct Task {
        std::uint32_t i, j;
        mesh::EdgeRef parent;
    };
    std::vector<mesh::TriangleId> crossed;
    std::vector<mesh::VertexId> left, right;
    std::vector<mesh::VertexId> inner;  // vertices whose whole star the segment crossed
    struct Pending {
        mesh::VertexId from, to;
        mesh::SubsegmentInfo info;
    };
    std::vector<Pending> pending;  // subsegments to recover after the segment
    std::vector<mesh::EdgeRef> left_outer, right_outer;
    std::vector<std::uint8_t> left_flag, right_flag;
    std::vector<Task> tasks;
    std::vector<mesh::VertexId> targets;
    std::vector<mesh::VertexId> path;  // vertices the current piece has passed
};

// Fills buffer.corner from every live triangle of the mesh (and sets
// track_corners).
void track_corners(const mesh::Mesh& mesh, SegmentBuffer& buffer);

// Inserts segment a-b (a != b, both vertices of the triangulation) as a
// chain of subsegments carrying `info`.  `hint` is any live triangle (best:
// one with corner a).  Returns a live triangle with corner b.  Vertices
// created at crossings are VertexKind::segment.  Throws gpdr::GeometryError
// when the segment leaves the triangulated region (a non-convex mesh, -rp),
// gpdr::InternalError when a vertex is not in the triangulation, and what
// split_subsegment throws.
mesh::TriangleId insert_segment(mesh::Pool& pool, mesh::VertexId a, mesh::VertexId b,
                                mesh::SubsegmentInfo info, mesh::TriangleId hint,
                                SegmentBuffer& buffer);

// The CDT of the convex hull of the points with every segment inserted;
// nothing removed (no holes, no exterior, no regions).  Vertex ids equal
// input indices; new vertices follow.  Throws gpdr::GeometryError for a
// segment endpoint out of range, a marker list of the wrong size, and what
// delaunay() throws.
mesh::Mesh triangulate_segments(const Pslg& pslg, CdtReport& report);

// triangulate_segments, then carve_domain (domain.hpp).
mesh::Mesh constrained_delaunay(const Pslg& pslg, const CdtOptions& options, CdtReport& report);

}  // namespace gpdr::triangulate
