#pragma once
// The convex hull of a point set, by Andrew's monotone chain: the points
// sorted by x then y, a lower and an upper chain, each turn decided by the
// exact orient2d.  O(n log n).

#include <cstdint>
#include <span>
#include <vector>

#include "geometry/point.hpp"

namespace gpdr::geometry {

// Indices of the hull's corners, counter-clockwise, starting at the
// lowest-leftmost point; points on the hull between two corners (collinear)
// and repeats of a point are left out.  Fewer than three corners when the
// points are all collinear (two: the extreme points; one: all equal; none:
// no points).
std::vector<std::uint32_t> convex_hull(std::span<const Point> points);

}  // namespace gpdr::geometry
