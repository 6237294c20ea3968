#pragma once
// The area bounds of an .area file (Triangle's -ra; trianglearealist in the
// C library) as a field over the plane.
//
// An .area file gives one bound per triangle of the .ele it goes with.  A
// bound belongs to the part of the plane that triangle covers, not to the
// triangle record: refinement replaces triangles, flips their edges and
// grows cavities across them, and whatever it makes there must still answer
// to the bound the user wrote for that place.  So the bounds define a
// piecewise-constant function of position:
//
//   at a point p, the smallest bound among the input triangles that contain
//   p (closed: on an edge or a corner shared by several, the smallest of
//   theirs); a bound <= 0 means none, which counts as +infinity; a point in
//   no bounded triangle has no bound.
//
// The input triangles are those of the .ele as read, before any flip that
// makes the mesh Delaunay.  A triangle of the mesh is held to the field at
// its centroid (centroid() below, computed the same way everywhere), so the
// bound a triangle must meet depends only on where its corners are: not on
// the order of insertions, nor on the thread that made it.  Triangle 1.6
// keeps its bounds on triangle records instead and, on a flip, gives both
// new triangles the average of the old two (none if either had none), so a
// small bound fades where refinement flips across it.
//
// Containment is decided with the exact orient2d, so a centroid on an edge
// between two input triangles gets the smaller of their bounds, exactly.
// Points are found through a uniform grid over the bounded triangles (about
// one cell per triangle, each triangle listed in the cells its rows cross,
// widened by a cell for rounding), so a query costs a few orientation tests.
// Immutable after construction: refinement threads share one field.

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "geometry/cell_grid.hpp"
#include "geometry/point.hpp"

namespace gpdr::geometry {

// The centroid by which a triangle is held to an area field.
inline Point centroid(const Point& a, const Point& b, const Point& c) {
    return {(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
}

class AreaField {
public:
    static constexpr std::uint32_t no_triangle = std::numeric_limits<std::uint32_t>::max();

    // The bound at a point and the input triangle it comes from (its index
    // in the .ele, 0-based); area = +infinity and no_triangle: none.
    struct Bound {
        double area = std::numeric_limits<double>::infinity();
        std::uint32_t triangle = no_triangle;
    };

    // Triangle t has corners points[corners[t * corners_per_triangle + k]],
    // k = 0, 1, 2 (further corners, of six-node triangles, are ignored) and
    // bound bounds[t].  Triangles of either orientation are accepted;
    // degenerate ones cover no area and are left out.
    AreaField(std::span<const Point> points, std::span<const std::uint32_t> corners,
              std::uint32_t corners_per_triangle, std::span<const double> bounds);

    Bound at(const Point& p) const;

    // The number of input triangles with a bound.
    std::size_t bounded_triangles() const { return triangles_.size(); }

private:
    struct Bounded {
        Point a, b, c;  // counter-clockwise
        double bound;
        std::uint32_t index;  // in the .ele
    };

    template <class F>
    void for_each_cell_of(const Bounded& t, F&& visit) const;

    std::vector<Bounded> triangles_;
    Point lo_, hi_;
    CellGrid grid_;
    CellLists lists_;  // indices into triangles_
};

}  // namespace gpdr::geometry
