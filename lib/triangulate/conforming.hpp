#pragma once
// Conforming Delaunay triangulation (Triangle's -D): split subsegments until
// every triangle is Delaunay, not only constrained Delaunay.
//
// A subsegment is encroached when a vertex lies strictly inside its
// diametral circle (the circle it is a diameter of).  In a constrained
// Delaunay mesh a subsegment is encroached by some vertex visible from it
// exactly when it is encroached by the apex of one of its (one or two)
// triangles, so only apexes are tested (Ruppert 1995; Shewchuk 1997).  Once
// no apex encroaches, both angles facing each subsegment are at most 90
// degrees, their sum at most 180: every subsegment is locally Delaunay too,
// so the whole mesh is Delaunay.
//
// Splitting: encroached subsegments wait in a queue; each is split with
// mesh::split_subsegment (Bowyer-Watson, keeps the side-table entry), and
// every subsegment among the edges of the new triangles is tested again
// (the new vertex may encroach its neighbours; subsegments away from the
// cavity keep their triangles and so stay unencroached).  The split point is
// the midpoint, except at a vertex where another subsegment meets this one
// at an angle below 60 degrees: there the subsegment is split at a distance
// from that vertex that is a power of two (Ruppert's "concentric circular
// shells", as in Shewchuk's Triangle), so the splits on two segments
// meeting at a small angle land on the same circles and stop encroaching
// each other instead of cascading toward the vertex.  If both ends have such
// an angle, the midpoint.
//
// The encroachment test is a floating-point dot product with an error
// bound; when the bound cannot decide, the exact incircle of the two apexes
// decides (a subsegment whose two facing angles sum to more than 180
// degrees is encroached).  So the result is exactly Delaunay, as
// mesh::check_mesh and incircle see it.
//
// Limits: -Y leaves boundary subsegments (a triangle on one side only)
// unsplit, -YY every subsegment; -S stops after the budget of Steiner
// points is spent.  Then the mesh stays a valid constrained Delaunay mesh,
// and the report says how many encroached subsegments are left.  A
// subsegment encroached by a vertex within 1e-12 of its length from its
// line (on it but for rounding: overlapping segments whose rounded pieces
// interleave), or with no floating-point point strictly inside it where
// split_subsegment can put one, is left as well: splitting could only go on
// down to the rounding error.  Never a hang, never a throw.
//
// Requires: the mesh is constrained Delaunay (the CDT's output, or an -r mesh
// after flipping), with no ghost triangles.

#include <cstdint>
#include <vector>

#include <gpdr/options.hpp>

#include "mesh/pool.hpp"

namespace gpdr::triangulate {

struct ConformingOptions {
    // -Y: 1 (no splitting of boundary subsegments), -YY: 2 (of any).
    int no_segment_splitting = 0;
    // -S: at most max_steiner new vertices (the budget left to this stage).
    bool steiner_limit = false;
    std::uint64_t max_steiner = 0;
};

// The settings of a Triangle-style command line; `steiner_used` is what the
// earlier stages already spent of the -S budget.
inline ConformingOptions conforming_options(const Options& options,
                                            std::uint64_t steiner_used = 0) {
    ConformingOptions o;
    o.no_segment_splitting = options.no_segment_splitting;
    o.steiner_limit = options.steiner_limit;
    o.max_steiner = options.max_steiner > steiner_used ? options.max_steiner - steiner_used : 0;
    return o;
}

// A vertex added on subsegment from-to at parameter t (0 at from, 1 at to),
// and the side-table entry of that subsegment (marker, input segment): what
// the caller needs to interpolate vertex attributes and set markers.
struct SegmentSplit {
    mesh::VertexId vertex{};
    mesh::VertexId from{}, to{};
    double t = 0.5;
    mesh::SubsegmentInfo info;
};

struct ConformingReport {
    enum class Stop : std::uint8_t { none, steiner_limit };

    std::uint64_t points_added = 0;
    Stop stopped = Stop::none;  // stopped early (encroached subsegments may remain)
    // Encroached subsegments left unsplit at the end: by -Y/-YY, by the -S
    // budget, or too short to split.
    std::size_t encroached_left = 0;
    // Of those, the ones no split can help: too short to hold a new vertex,
    // or encroached by a vertex a rounding error (1e-12 of the length) off
    // their line.
    std::size_t unsplittable = 0;
    std::vector<SegmentSplit> splits;  // in the order made
};

void make_conforming(mesh::Pool& pool, const ConformingOptions& options, ConformingReport& report);

// Whether subsegment edge e (a flagged edge of a live triangle) is
// encroached by the apex of either of its triangles (the test above).
bool encroached(const mesh::Mesh& mesh, mesh::EdgeRef e);

}  // namespace gpdr::triangulate
