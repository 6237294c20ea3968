#pragma once
// The domain a PSLG describes, computed exactly and independently of gpdr's
// meshing code, as the reference a stress test compares meshes with.
//
// The input segments (and, for -c, the edges of the convex hull of all
// vertices) are cut at every input vertex lying on them and at every point
// where two of them cross; the crossing points are exact rationals (GMP).
// The pieces, merged where segments overlap, are the edges of the
// arrangement.  The plane is then cut into vertical slabs at the x of every
// arrangement point; inside a slab no two edges cross, so the edges spanning
// it are ordered by height and the trapezoids between them are pieces of
// faces.  Trapezoids of neighbouring slabs belong to the same face when their
// vertical sides overlap in more than a point not covered by a vertical edge.
//
// As in Triangle, the domain is everything enclosed by segments (-p), or the
// convex hull (-c), less the faces that hold a hole point.  An edge belongs
// to the domain when a face on either side of it does; an input vertex
// belongs to it when an edge of the domain ends at it or, if no edge does,
// when it lies in a face of the domain.

#include <cstdint>
#include <vector>

#include <gpdr/files.hpp>

namespace gpdr::stress {

struct Line {
    double ax, ay, bx, by;
    int segment;  // 0-based input segment, or -1 for an edge of the convex hull
};

struct ArrangementPoint {
    double x, y;                // rounded to the nearest double or next to it
    bool input_vertex = false;  // x, y are then exact
    bool crossing = false;      // where two lines cross properly
};

struct ArrangementEdge {
    std::uint32_t a, b;      // arrangement points, a before b in (x, y) order
    std::vector<int> lines;  // indices into lines(): those the edge lies on
    bool in_domain = false;
};

struct Face {
    double area = 0;
    bool in_domain = false;
    std::vector<double> region_attributes;  // of the region points in it, in file order
};

class ExactDomain {
public:
    ExactDomain(const PolyFile& poly, bool convex_hull);

    const std::vector<Line>& lines() const { return lines_; }
    const std::vector<ArrangementPoint>& points() const { return points_; }
    const std::vector<ArrangementEdge>& edges() const { return edges_; }
    const std::vector<Face>& faces() const { return faces_; }
    // Input vertices (0-based) the mesh must have.
    const std::vector<std::uint32_t>& required_vertices() const { return required_; }
    double area() const;
    // The face each region point lies in, in file order (-1 on an edge).
    const std::vector<long>& region_faces() const { return region_faces_; }

private:
    std::vector<Line> lines_;
    std::vector<ArrangementPoint> points_;
    std::vector<ArrangementEdge> edges_;
    std::vector<Face> faces_;
    std::vector<std::uint32_t> required_;
    std::vector<long> region_faces_;
};

}  // namespace gpdr::stress
