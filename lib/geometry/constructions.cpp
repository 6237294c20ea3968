// The less hot constructions of constructions.hpp: selection disk (GPDR paper,
// Definition 1), Ungor's off-centre ("Off-centers: a new type of Steiner
// point for computing size-optimal quality-guaranteed Delaunay
// triangulations", 2004, as Triangle uses it) and segment intersection.

#include "geometry/constructions.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gpdr::geometry {

Disk selection_disk(const Point& a, const Point& b, const Point& c) {
    const Circle circle = circumcircle(a, b, c);
    const double l = std::sqrt(shortest_edge(a, b, c).length_squared);
    return {circle.centre, std::sqrt(circle.radius_squared) - std::numbers::sqrt2 * l};
}

// With L = |pq| and c' at height h above pq's midpoint m, triangle p q c' is
// isosceles with circumradius R = (h^2 + L^2/4) / (2h).  R = rho L gives
// h^2 - 2 rho L h + L^2/4 = 0, h = L (rho +- sqrt(rho^2 - 1/4)); the larger
// root keeps pq the shortest edge of p q c' (the smaller gives an obtuse
// apex), so its radius-edge ratio is exactly rho.
//
// The circumcentre lies on the same side of pq as the third corner r: pq is
// the shortest edge, so the angle at r is the smallest, at most 60 degrees,
// hence acute.  So c' = m + k n with n = pq rotated a quarter turn towards r
// (|n| = L) and k = rho + sqrt(rho^2 - 1/4), and everything is computed
// relative to p.
Point off_centre(const Point& a, const Point& b, const Point& c, double rho_bar, double fraction) {
    const int edge = shortest_edge(a, b, c).edge;
    // p, q, r in the cyclic order of a, b, c, so orient2d(p, q, r) has the
    // triangle's orientation.
    const Point& p = edge == 0 ? b : edge == 1 ? c : a;
    const Point& q = edge == 0 ? c : edge == 1 ? a : b;
    const Point& r = edge == 0 ? a : edge == 1 ? b : c;

    const double qx = q.x - p.x;
    const double qy = q.y - p.y;
    const double rx = r.x - p.x;
    const double ry = r.y - p.y;
    const double q2 = qx * qx + qy * qy;
    const double r2 = rx * rx + ry * ry;
    const double orientation = orient2d(p, q, r);
    const double denominator = 2.0 * orientation;
    // Circumcentre relative to p, and relative to the midpoint m of pq.
    const double ux = (ry * q2 - qy * r2) / denominator;
    const double uy = (qx * r2 - rx * q2) / denominator;
    const double vx = ux - 0.5 * qx;
    const double vy = uy - 0.5 * qy;

    const double k = fraction * (rho_bar + std::sqrt(rho_bar * rho_bar - 0.25));
    // |v|^2 <= h^2 = k^2 L^2: the circumcentre is no farther than c'.
    if (vx * vx + vy * vy <= k * k * q2) return {p.x + ux, p.y + uy};
    // n: pq turned by +90 degrees when pqr is counter-clockwise, -90 if not.
    const double side = orientation > 0 ? 1.0 : -1.0;
    const double nx = -qy * side;
    const double ny = qx * side;
    return {p.x + 0.5 * qx + k * nx, p.y + 0.5 * qy + k * ny};
}

// Along ab, the signed distance to line cd is linear: t = o_a / (o_a - o_b)
// with o_a = orient2d(c, d, a), o_b = orient2d(c, d, b), whose signs are
// exact, so 0 <= t <= 1 up to rounding; clamp it to be sure.
Point segment_intersection(const Point& a, const Point& b, const Point& c, const Point& d) {
    const double oa = orient2d(c, d, a);
    const double ob = orient2d(c, d, b);
    const double t = std::clamp(oa / (oa - ob), 0.0, 1.0);
    return point_on_segment(a, b, t);
}

}  // namespace gpdr::geometry
