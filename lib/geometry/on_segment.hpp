#pragma once
// Whether a vertex lies on a segment, by gpdr's rule for input geometry
// (docs/architecture.md, "Crossings, overlaps and vertices on segments"):
// exactly, or within rounding distance.  A vertex a hair off a segment is
// one that was meant to be on it and whose decimal coordinates rounded it
// off; left off, it would make a sliver no refinement could remove, so the
// segment bends through it.  The arrangement applies the rule to the input
// segments, and -c to the edges of the convex hull.

#include <algorithm>
#include <cmath>

#include "geometry/point.hpp"
#include "geometry/predicates.hpp"

namespace gpdr::geometry {

// Rounding distance for points near p on a segment of the given length: a
// relative 1e-12 of the length, and a few ulps of p's coordinates.
inline double rounding_distance(double length, const Point& p) {
    return 1e-12 * length + 16 * 0x1p-53 * std::max(std::abs(p.x), std::abs(p.y));
}

// Whether p lies on the open segment a-b: exactly (exact orient2d), or
// within rounding distance of its line with its projection inside and
// farther than that from both ends.
inline bool on_interior(const Point& a, const Point& b, const Point& p) {
    const double o = orient2d(a, b, p);
    if (o == 0) {
        if (a.x != b.x) return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
        return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
    }
    auto squared_distance = [](const Point& u, const Point& v) {
        const double dx = u.x - v.x, dy = u.y - v.y;
        return dx * dx + dy * dy;
    };
    const double length_squared = squared_distance(a, b);
    const double length = std::sqrt(length_squared);
    const double near = rounding_distance(length, p);
    if (std::abs(o) > near * length) return false;  // |o| / length is the distance to the line
    const double along = (p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y);
    if (along <= 0 || along >= length_squared) return false;
    return squared_distance(p, a) > near * near && squared_distance(p, b) > near * near;
}

}  // namespace gpdr::geometry
