#pragma once
// Where a point lies with respect to a region bounded by edges (the
// boundary of a mesh: the edges with a triangle on one side only): outside,
// on an edge, or inside, by the parity of the edges a ray from the point to
// +x crosses.  Every decision is the exact orient2d or a comparison of
// coordinates: an edge counts when one end is at or below the point's y and
// the other above (so a vertex the ray passes is counted once), and the
// point is on the edge's left for an upward edge, its right for a downward
// one.
//
// The edges are sorted into horizontal strips (as many as edges) by the
// range of y they span, so a query tests only the edges of its strip.

#include <cstdint>
#include <span>
#include <vector>

#include "geometry/point.hpp"

namespace gpdr::geometry {

class EdgeStrips {
public:
    enum class Where { outside, on_edge, inside };

    // Edge i runs from ends[2i] to ends[2i + 1]; the edges must bound a
    // region (each vertex has as many edges in as out).
    explicit EdgeStrips(std::vector<Point> ends);

    Where locate(const Point& p) const;
    // Whether some edge crosses the open segment a-b at a point interior to
    // both (an edge through a or b, or along a-b, does not count), farther
    // than `margin` from a and from b (a crossing within rounding of an end
    // is the end's).
    bool crossed(const Point& a, const Point& b, double margin = 0) const;

private:
    std::size_t strip(double y) const;

    std::vector<Point> ends_;
    double lo_ = 0, hi_ = 0, height_ = 1;
    std::size_t strips_ = 1;
    std::vector<std::size_t> offsets_;
    std::vector<std::uint32_t> members_;
};

}  // namespace gpdr::geometry
