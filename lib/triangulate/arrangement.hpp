#pragma once
// The arrangement of a PSLG's segments: crossings, overlaps and vertices on
// segments, resolved before anything is triangulated.
//
// Input segments may cross, overlap along a stretch, or pass through
// vertices.  Triangle meets these one at a time while inserting segments;
// here they are found first, for all segments at once, and the segments are
// cut into *pieces* that meet only at their ends:
//
//   - a vertex that lies on a segment's interior cuts the segment there:
//     exactly on it (exact orient2d), or within rounding distance of it (a
//     relative 1e-12 of the segment's length plus a few ulps of the
//     vertex's coordinates), which is a vertex meant to be on the segment
//     whose decimal coordinates were rounded off it;
//   - two segments that cross properly get a new vertex at their crossing
//     point, correctly rounded (geometry/crossing.hpp); both are cut there.
//     The vertex is an input vertex from then on (as in Triangle): a corner
//     of the domain for refinement, with segment pieces ending at it;
//   - collinear segments that overlap are cut at each other's ends, and the
//     stretch they share is kept once (the first segment's piece, with the
//     later one's marker if the first has marker 0).
//
// A rounded crossing point lies off both lines by up to half an ulp, so the
// pieces that end at it bend slightly and may now cross a third segment that
// passed within rounding distance, or run through a vertex.  The search is
// therefore repeated on the pieces until a round finds nothing: the result
// is checked with exact predicates, never assumed.  Two rules keep the
// rounds from multiplying near-coincident vertices: a crossing point within
// rounding distance of an end of either piece, or of a vertex already cut
// into either piece in this round, is that vertex (three segments through
// one point meet at one vertex); and a crossing point equal to an existing
// vertex is that vertex.  If rounds still do not settle (they do after one
// or two on every input seen), the function throws GeometryError naming the
// segments.
//
// Candidates are found with a uniform grid over the vertices' bounding box:
// each piece is entered in the cells it passes through, each vertex in its
// cell, and only pairs sharing a cell are tested, so the cost is about
// linear for inputs whose segments are spread out.  Many segments through
// one small area (a fan of thousands of segments) make it quadratic there.

#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/point.hpp"

namespace gpdr::triangulate {

// A segment, or a piece of one, between two vertex indices.
struct SegmentPiece {
    std::uint32_t a = 0, b = 0;
    std::uint32_t segment = 0;  // the input segment it is (a piece of)
    int marker = 0;
};

struct ArrangementReport {
    // A vertex made where two segments cross, in creation order.
    struct Crossing {
        std::uint32_t vertex;
        std::uint32_t segment, other_segment;
    };
    std::vector<Crossing> crossings;
    // (segment, vertex): an input vertex lies on the segment's interior.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> through_vertices;
    // (segment, earlier segment): the two overlap along a stretch, kept once.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> overlaps;
};

// Cuts `segments` (no zero-length ones, no two with the same ends; vertex
// indices into `points`) into pieces that meet only at their ends, and
// returns them: in the order of the segments, each segment's pieces in order
// from its first end.  `vertices` lists the indices of the distinct points
// (duplicates left out); crossing points are appended to `points` (and are
// distinct from every listed point).  Throws GeometryError when rounding
// does not settle.
std::vector<SegmentPiece> arrange_segments(std::vector<geometry::Point>& points,
                                           std::vector<std::uint32_t> vertices,
                                           std::vector<SegmentPiece> segments,
                                           ArrangementReport& report);

}  // namespace gpdr::triangulate
