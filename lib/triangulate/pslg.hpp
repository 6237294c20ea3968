#pragma once
// A planar straight line graph (Triangle's .poly in memory, with points as
// Points) and what the constrained Delaunay triangulation reports about it.
//
// The library never prints: the report lists everything Triangle would warn
// about, by index, and the caller words the warnings.

#include <cstdint>
#include <utility>
#include <vector>

#include <gpdr/files.hpp>

#include "geometry/point.hpp"
#include "mesh/ids.hpp"
#include "triangulate/arrangement.hpp"

namespace gpdr::triangulate {

struct Pslg {
    std::vector<geometry::Point> points;
    std::vector<std::uint32_t> segments;  // 2 per segment, 0-based vertex indices
    std::vector<int> segment_markers;     // empty, or one per segment
    std::vector<geometry::Point> holes;
    std::vector<Region> regions;

    std::size_t segment_count() const { return segments.size() / 2; }
    int marker(std::size_t s) const { return segment_markers.empty() ? 0 : segment_markers[s]; }
};

struct CdtOptions {
    bool convex_hull = false;  // -c: keep every triangle of the hull; hull edges become subsegments
    bool ignore_holes = false;  // -O
};

// A vertex the CDT created on one or two input segments.  t is the
// parameter along the input segment (0 at its first endpoint, 1 at its
// second), for interpolating attributes.
struct NewSegmentVertex {
    static constexpr std::uint32_t no_segment = 0xFFFFFFFFu;
    mesh::VertexId vertex{};
    std::uint32_t segment = no_segment;  // the segment being inserted
    double t = 0;
    std::uint32_t other_segment = no_segment;  // the segment it crossed (no_segment: none known)
    double other_t = 0;
};

struct CdtReport {
    // (duplicate vertex, the vertex kept in its place), from delaunay().
    // Segments naming a duplicate are attached to the kept vertex.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicate_vertices;
    // Segments whose two ends are the same vertex (after duplicates are
    // merged): skipped.
    std::vector<std::uint32_t> zero_length_segments;
    // (segment, the earlier segment with the same two ends): skipped.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicate_segments;
    // Vertices created where segments cross (input vertices from then on),
    // in creation order.
    std::vector<NewSegmentVertex> new_vertices;
    // (segment, vertex): a vertex lies in the segment's interior; the segment
    // is split there.
    std::vector<std::pair<std::uint32_t, mesh::VertexId>> segments_through_vertices;

    // (segment, earlier segment): collinear segments that share a stretch,
    // kept once.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> overlapping_segments;
    // Whether segment s was skipped (zero length or duplicate).
    std::vector<bool> skipped;
    // The segments cut at crossings and at vertices on them
    // (arrangement.hpp), in input order; SubsegmentInfo::segment of a
    // subsegment is an index into this list.
    std::vector<SegmentPiece> pieces;
};

// The PSLG a .poly file describes (its vertices, segments with markers,
// holes and regions), with the vertices as Points.
Pslg pslg_from(const PolyFile& poly);

}  // namespace gpdr::triangulate
