#pragma once
// Whether refinement above 34 degrees is converging.
//
// Above about 34 degrees Delaunay refinement may never end, and when it does
// not, it fails in one way: a cascade.  Splitting a poor triangle makes a
// smaller poor triangle beside it, whose split makes a smaller one, size
// class after size class, down to the limits of double precision; there
// the refiner gives triangles up and the cascade moves sideways until the
// safety limit stops it, a million Steiner points later.  A refinement that
// ends also goes below the input's shortest edge where features are close
// or angles small, but by a bounded factor, far above the cascade's
// (docs/refinement-order.md, "Above 34 degrees", has both).
//
// So the rule: refinement is not converging when it is about to split a
// triangle poor by its angle whose shortest edge is below 2^-20 of the
// shortest edge of the mesh it started from.  A run that asks
// (RefineSettings::watch_convergence: api::refine_stage's tries when the
// bound is above 34 degrees) checks it for every split, one comparison
// (other runs leave the floor at 0, which no edge is below), and stops
// (RefineReport::Stop::not_converging) within thousands of Steiner points
// instead of a million.

#include <cstdint>

#include "mesh/mesh.hpp"

namespace gpdr::refine {

// The angle bound, in degrees, above which refinement is watched for the
// cascade (the same as star_placement_above: where the default placement
// changes, placement.hpp).
inline constexpr double watched_above = 34.0;
// How far below the starting mesh's shortest edge a split means a cascade:
// 2^-20 in length.
inline constexpr double cascade_depth = 0x1p-20;

// The squared length below which a split of a triangle poor by its angle
// means a run from `mesh` is not converging (0 for a mesh without edges).
double cascade_floor_squared(const mesh::Mesh& mesh);

// The smallest angle of the mesh's triangles, in degrees, apart from those
// the small-input-angle rule leaves (the mark refinement left on them).
double smallest_angle_degrees(const mesh::Mesh& mesh);

}  // namespace gpdr::refine
