#pragma once
// The crossing point of two segments, correctly rounded.
//
// Where two input segments cross, the mesh needs a vertex; its exact
// position is rational and usually not representable.  crossing_point()
// returns each coordinate rounded to the nearest double (ties to even), so
// the result does not depend on the order of the segments or of their ends,
// and it is the best a double can do: the rounded point lies within half an
// ulp per coordinate of both segments' lines.  It may still fall on the
// wrong side of a third segment that passes within rounding distance; the
// arrangement of segments (triangulate/arrangement.hpp) checks for that.

#include "geometry/point.hpp"

namespace gpdr::geometry {

// The intersection of the lines through a, b and through c, d, each
// coordinate correctly rounded.  The lines must not be parallel (callers use
// it for segments that cross properly: a and b strictly on opposite sides of
// line cd, c and d strictly on opposite sides of line ab).  Exact as long as
// no intermediate product overflows or underflows (the range of
// predicates.hpp).
Point crossing_point(const Point& a, const Point& b, const Point& c, const Point& d);

}  // namespace gpdr::geometry
