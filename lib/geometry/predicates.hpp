#pragma once
// Exact geometric predicates on doubles.  Each returns a value whose SIGN is
// always exactly right (computed with a floating-point filter with a proven
// error bound, and adaptive exact arithmetic behind it); its magnitude is only
// an approximation.  Nothing that computes them may contract multiply-adds
// (the project builds with -ffp-contract=off).
// Exact as long as no intermediate result overflows or underflows, which
// holds when every coordinate is zero or of magnitude within [1e-50, 1e50].
// Thread-safe (no state).  Cost: a few ns when the filter decides (almost
// always); up to ~0.1 us (orient2d) and ~1.3 us (incircle) for inputs that
// are degenerate to within a few ulps and whose differences are inexact.

#include <cmath>

#include "geometry/point.hpp"

namespace gpdr::geometry {

namespace detail {

// The filters' error bounds (stage A; predicates.cpp derives them), with
// u = 2^-53.
inline constexpr double orient_bound_a = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;
inline constexpr double incircle_bound_a = (10.0 + 128.0 * 0x1p-53) * 0x1p-53;

// The stages behind the filters, for the few inputs they cannot decide
// (predicates.cpp); `detsum` and `permanent` are stage A's.
double orient2d_adapt(const Point& a, const Point& b, const Point& c, double detsum);
double incircle_adapt(const Point& a, const Point& b, const Point& c, const Point& d,
                      double permanent);

}  // namespace detail

// > 0 if a, b, c are in counter-clockwise order, < 0 if clockwise, 0 if
// collinear.  (Twice the signed area of triangle abc, up to rounding.)
//
// The filter is inline: refinement asks millions of these, nearly all
// decided here, and a call per predicate cost more than the test itself.
// Its arithmetic must not be contracted into fused multiply-adds: the
// whole project builds with -ffp-contract=off (CMakeLists.txt).
inline double orient2d(const Point& a, const Point& b, const Point& c) {
    const double detleft = (a.x - c.x) * (b.y - c.y);
    const double detright = (a.y - c.y) * (b.x - c.x);
    const double det = detleft - detright;
    // One well-predicted branch decides almost every call (a branch on the
    // signs of detleft and detright first would be mispredicted half the
    // time on random input).
    const double detsum = std::abs(detleft) + std::abs(detright);
    const double errbound = detail::orient_bound_a * detsum;
    if (std::abs(det) > errbound) return det;
    // When detleft and detright do not have the same strict sign there is no
    // cancellation: each has the sign of its exact counterpart (a product is
    // zero only when an exact difference is), so det's sign is exact.  This
    // catches, e.g., exactly collinear points on axis-parallel lines.
    if (!(detleft > 0.0 && detright > 0.0) && !(detleft < 0.0 && detright < 0.0)) return det;
    return detail::orient2d_adapt(a, b, c, detsum);
}

// > 0 if d lies inside the circle through a, b, c, < 0 if outside, 0 if on
// it; a, b, c must be in counter-clockwise order (the sign flips otherwise).
// The filter is inline, as orient2d's.
inline double incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
    const double adx = a.x - d.x;
    const double bdx = b.x - d.x;
    const double cdx = c.x - d.x;
    const double ady = a.y - d.y;
    const double bdy = b.y - d.y;
    const double cdy = c.y - d.y;

    const double bdxcdy = bdx * cdy;
    const double cdxbdy = cdx * bdy;
    const double alift = adx * adx + ady * ady;

    const double cdxady = cdx * ady;
    const double adxcdy = adx * cdy;
    const double blift = bdx * bdx + bdy * bdy;

    const double adxbdy = adx * bdy;
    const double bdxady = bdx * ady;
    const double clift = cdx * cdx + cdy * cdy;

    const double det =
        alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * alift +
                             (std::abs(cdxady) + std::abs(adxcdy)) * blift +
                             (std::abs(adxbdy) + std::abs(bdxady)) * clift;
    const double errbound = detail::incircle_bound_a * permanent;
    if (std::abs(det) > errbound) return det;
    return detail::incircle_adapt(a, b, c, d, permanent);
}

// The same, always through the exact expansion arithmetic (no filter): for
// tests and for cross-checking the adaptive versions; much slower.
double orient2d_exact(const Point& a, const Point& b, const Point& c);
double incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d);

}  // namespace gpdr::geometry
