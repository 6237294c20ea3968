#pragma once
// Exact geometric predicates on doubles.  Each returns a value whose SIGN is
// always exactly right (computed with a floating-point filter with a proven
// error bound, and adaptive exact arithmetic behind it); its magnitude is only
// an approximation.  predicates*.cpp are compiled with -ffp-contract=off.
// Exact as long as no intermediate result overflows or underflows, which
// holds when every coordinate is zero or of magnitude within [1e-50, 1e50].
// Thread-safe (no state).  Cost: a few ns when the filter decides (almost
// always); up to ~0.1 us (orient2d) and ~1.3 us (incircle) for inputs that
// are degenerate to within a few ulps and whose differences are inexact.

#include "geometry/point.hpp"

namespace gpdr::geometry {

// > 0 if a, b, c are in counter-clockwise order, < 0 if clockwise, 0 if
// collinear.  (Twice the signed area of triangle abc, up to rounding.)
double orient2d(const Point& a, const Point& b, const Point& c);

// > 0 if d lies inside the circle through a, b, c, < 0 if outside, 0 if on
// it; a, b, c must be in counter-clockwise order (the sign flips otherwise).
double incircle(const Point& a, const Point& b, const Point& c, const Point& d);

// The same, always through the exact expansion arithmetic (no filter): for
// tests and for cross-checking the adaptive versions; much slower.
double orient2d_exact(const Point& a, const Point& b, const Point& c);
double incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d);

}  // namespace gpdr::geometry
