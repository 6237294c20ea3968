#pragma once
// The mesh against the input it was made from (-C): a check that looks only
// at the finished mesh and at the input as read, never at what the stages
// recorded about it (the subsegment flags and side table, the CDT's report
// of crossings), so that a mistake in that bookkeeping cannot hide itself.
// check_mesh (checker.hpp) checks the mesh on its own: topology,
// orientation and the constrained Delaunay property; this checks that it is
// a mesh of the input:
//
//   segments   every part of an input segment that lies in the domain is
//              covered by mesh edges along it.  A mesh vertex is on segment
//              a-b when orient2d says it is on the line, between a and b
//              (or at them), or when it lies within rounding of the line:
//              split points are rounded, so a vertex within 2^-44 of the
//              segment's largest coordinate counts, and where a-b crosses
//              another input segment (exact orient2d signs) the crossing
//              is a rounded point and the pieces of a-b end there, so each
//              crossing widens that to 1e-11 of the longer segment plus
//              2^-44 of the largest coordinate (computed here, from the
//              input and a floating construction of the crossing point).
//              A mesh edge covers the stretch between two vertices on a-b
//              when no vertex exactly on the line lies between them (one
//              only within rounding may: it may lie just inside the domain);
//              a stretch no edge covers must lie outside the domain: its
//              midpoint outside every triangle (not even on an edge) and no
//              boundary edge crossing it;
//   boundary   every boundary edge of the mesh (a triangle on one side
//              only) joins two vertices on one segment, or on one edge of
//              the convex hull of the input vertices when the hull bounds
//              the domain (-c, or a point set);
//   vertices   every input vertex in the domain (in a triangle or on its
//              boundary) is a mesh vertex (one of equal coordinates:
//              duplicates coincide);
//   holes      no hole point lies inside a triangle;
//   regions    the triangles a region point reaches without crossing a
//              segment (the last region point that reaches them, as in
//              Triangle) carry its attribute, the others 0 (-A);
//   bounds     no triangle has an angle below the bound, or an area above
//              the global bound, its region's, or the .area file's field at
//              its centroid (-ra: the bound of the input triangle that
//              holds the centroid, geometry/area_field.hpp), except those
//              refinement reports it gave up (`exempt`) and those whose
//              shortest edge joins two segments that meet at an end of both
//              at 60 degrees or less (the small angle is the input's); and,
//              with -u, none that the user's triunsuitable() asks to refine.
//
// Zero-length and duplicate segments, and the parts of segments in holes
// or outside the domain, are not problems.  Segments are found near
// vertices through a uniform grid (geometry/segment_grid.hpp), crossings
// among the segments of each cell, and points are located against the
// boundary edges (geometry/edge_strips.hpp), so the check runs in time
// about linear in the mesh and the input.
//
// It never throws on a wrong mesh and never prints: it returns the problems,
// each a sentence naming input vertices, segments, holes and regions by
// their numbers in the input files (`base` is the first number) and mesh
// vertices by coordinates, at most `max_problems` of them and then one
// line saying how many more.

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geometry/area_field.hpp"
#include "geometry/point.hpp"
#include "mesh/mesh.hpp"

namespace gpdr::mesh {

struct InputRegion {
    geometry::Point at;
    double attribute = 0;
    double max_area = -1;  // <= 0: no bound
};

// The input as read.
struct InputGeometry {
    std::vector<geometry::Point> points;
    std::vector<std::uint32_t> segments;  // 2 per segment, indices into points
    std::vector<geometry::Point> holes;
    std::vector<InputRegion> regions;
    bool hull_bounds_domain = false;  // -c, or a point set
    // Which input vertices the mesh must keep when they lie in the domain
    // (empty: all; -r: the corners of the triangles read).
    std::vector<bool> vertex_required;
    // -r with an .area file: its bounds over the triangles read.
    std::optional<geometry::AreaField> area_field;
};

struct InputCheckOptions {
    int base = 0;                    // the number of the first vertex, segment, hole and region
    double min_angle = 0;            // degrees; 0: no angle bound
    double max_area = 0;             // the global area bound; <= 0: none
    bool regional_area = false;      // the regions' area bounds apply
    bool area_field = false;         // the .area field's bounds apply (-ra)
    bool region_attributes = false;  // -A: check each triangle's attribute
    // -A: the attribute of each value of Triangle::region.
    std::span<const double> attribute_of_region;
    // -u: whether the user's triunsuitable() asks to refine a triangle.
    std::function<bool(TriangleId)> unsuitable;
    // Triangles refinement gave up, sorted by id: not held to the bounds.
    std::span<const TriangleId> exempt;
    std::size_t max_problems = 100;
};

std::vector<std::string> check_against_input(const Mesh& mesh, const InputGeometry& input,
                                             const InputCheckOptions& options = {});

}  // namespace gpdr::mesh
