#pragma once
// Segment labels for parallel refinement.
//
// The small-input-angle rule (refine/segments.hpp) needs the two ends of the
// input segment a subsegment lies on.  It looks them up by the subsegment's
// SubsegmentInfo::segment in RefineSettings::segment_ends, and where that
// fails (a library caller gave no ends, or a hull edge of a point set has
// no segment) it walks the chain of subsegments to the segment's ends.  A
// worker must not walk: the chain can run far outside its buffer zone, into
// triangles another worker is changing.  So before the workers start,
// every subsegment without usable ends gets a temporary label, an index
// past the caller's segments whose ends were found by walking now, while
// nothing else runs.  Splits copy a subsegment's info to its halves, so the
// labels cover every later subsegment too.  restore() puts the original
// indices back.

#include <cstdint>
#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace gpdr::parallel {

class SegmentLabels {
public:
    // Labels the subsegments of `mesh` that `given_ends` (2 per segment)
    // cannot answer for.  Single-threaded.
    SegmentLabels(mesh::Mesh& mesh, std::span<const mesh::VertexId> given_ends);

    // Ends by segment index, the caller's first (for RefineSettings::segment_ends).
    std::span<const mesh::VertexId> ends() const { return ends_; }
    // Gives every labelled subsegment (and those split from it) its original
    // index back.  Single-threaded, after refinement.
    void restore();

private:
    mesh::Mesh& mesh_;
    std::uint32_t first_label_;
    std::vector<mesh::VertexId> ends_;
    std::vector<std::uint32_t> original_;  // by label - first_label_
};

}  // namespace gpdr::parallel
