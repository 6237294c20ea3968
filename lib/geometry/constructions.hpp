#pragma once
// Geometric constructions in ordinary floating point: circumcircle, shortest
// edge, radius-edge ratio, signed area, the selection disk of the GPDR paper
// (Chernikov & Chrisochoides, Definition 1), Ungor's off-centre, segment
// intersection and points on segments.  Their results are approximate; the
// exact predicates keep the topology valid whatever they return.  Each is
// computed relative to a vertex of its input (coordinates differences, not
// absolute coordinates, enter the products), which keeps the relative error
// small when the triangle is far from the origin.  Denominators that are
// orientations use the exact orient2d, so their sign is always right.
//
// Triangle conventions: corners a, b, c; edge i is the edge opposite corner
// i (edge 0 = bc, edge 1 = ca, edge 2 = ab).  A degenerate (collinear)
// triangle has no circumcircle: the functions that need one return
// non-finite values for it.

#include <cmath>

#include "geometry/point.hpp"
#include "geometry/predicates.hpp"

namespace gpdr::geometry {

struct Circle {
    Point centre;
    double radius_squared = 0;
};

// A disk whose radius may be zero or negative (then it contains no point).
struct Disk {
    Point centre;
    double radius = 0;
};

struct EdgeLength {
    int edge = 0;  // index of the edge, opposite that corner
    double length_squared = 0;
};

// Twice the signed area is orient2d; this is the area, > 0 when abc is
// counter-clockwise, with an exact sign.
inline double signed_area(const Point& a, const Point& b, const Point& c) {
    return 0.5 * orient2d(a, b, c);
}

inline double squared_distance(const Point& p, const Point& q) {
    const double dx = q.x - p.x;
    const double dy = q.y - p.y;
    return dx * dx + dy * dy;
}

// The circumcentre relative to a: with B = b - a and C = c - a it is
// (C_y |B|^2 - B_y |C|^2, B_x |C|^2 - C_x |B|^2) / (2 B x C).
// `orientation` is orient2d(a, b, c), for callers that have it already.
inline Circle circumcircle(const Point& a, const Point& b, const Point& c, double orientation) {
    const double bx = b.x - a.x;
    const double by = b.y - a.y;
    const double cx = c.x - a.x;
    const double cy = c.y - a.y;
    const double b2 = bx * bx + by * by;
    const double c2 = cx * cx + cy * cy;
    const double denominator = 2.0 * orientation;
    const double ux = (cy * b2 - by * c2) / denominator;
    const double uy = (bx * c2 - cx * b2) / denominator;
    return {{a.x + ux, a.y + uy}, ux * ux + uy * uy};
}

inline Circle circumcircle(const Point& a, const Point& b, const Point& c) {
    return circumcircle(a, b, c, orient2d(a, b, c));
}

inline Point circumcentre(const Point& a, const Point& b, const Point& c) {
    return circumcircle(a, b, c).centre;
}

inline double circumradius_squared(const Point& a, const Point& b, const Point& c) {
    return circumcircle(a, b, c).radius_squared;
}

// The shortest edge (the lowest index among equals).
inline EdgeLength shortest_edge(const Point& a, const Point& b, const Point& c) {
    EdgeLength best{0, squared_distance(b, c)};
    const double l1 = squared_distance(c, a);
    if (l1 < best.length_squared) best = {1, l1};
    const double l2 = squared_distance(a, b);
    if (l2 < best.length_squared) best = {2, l2};
    return best;
}

// (circumradius / shortest edge)^2: compare with rho_bar^2 to avoid roots.
inline double radius_edge_ratio_squared(const Point& a, const Point& b, const Point& c) {
    return circumradius_squared(a, b, c) / shortest_edge(a, b, c).length_squared;
}

// Circumradius over shortest edge length; 1/sqrt(3) for an equilateral
// triangle, and 1 / (2 sin(smallest angle)) in general.
inline double radius_edge_ratio(const Point& a, const Point& b, const Point& c) {
    return std::sqrt(radius_edge_ratio_squared(a, b, c));
}

// GPDR Definition 1: centred at the circumcentre, radius r - sqrt(2) l with
// r the circumradius and l the shortest edge length.  Any Steiner point
// strictly inside it preserves termination and size optimality.
Disk selection_disk(const Point& a, const Point& b, const Point& c);

// Ungor's off-centre for the radius-edge bound rho_bar (>= 1/2; Triangle's
// -q angle bound theta gives rho_bar = 1 / (2 sin theta)).  With pq the
// shortest edge, it is the point c' on pq's perpendicular bisector, on the
// circumcentre's side, at which triangle p q c' has circumradius exactly
// rho_bar |pq|; if the circumcentre is no farther from pq than c', it is the
// circumcentre itself.
//
// `fraction` < 1 moves c' towards pq by that factor of its distance from the
// midpoint of pq (Triangle stays 5% short of the exact point, so the new
// triangle is not left borderline-poor by rounding).
Point off_centre(const Point& a, const Point& b, const Point& c, double rho_bar,
                 double fraction = 1.0);

// a + t (b - a), computed from the nearer end so that t = 0 and t = 1 give a
// and b exactly.
inline Point point_on_segment(const Point& a, const Point& b, double t) {
    if (t <= 0.5) return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    const double s = 1.0 - t;
    return {b.x + s * (a.x - b.x), b.y + s * (a.y - b.y)};
}

// The crossing point of segments ab and cd, which must cross (a and b on
// opposite sides of line cd, or one of them on it, and not both); the result
// is a point of segment ab.
Point segment_intersection(const Point& a, const Point& b, const Point& c, const Point& d);

}  // namespace gpdr::geometry
