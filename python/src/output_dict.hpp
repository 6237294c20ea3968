#pragma once
// gpdr's in-memory result as the triangle package's dictionaries: the
// arrays Triangle's library fills for the same switches (docs/c-api.md),
// under the package's keys and dtypes (float64; int32 for indices and
// markers), every index from 0, each array two-dimensional.  An array
// Triangle would leave empty or unwritten is left out, as the package
// leaves it out.
//
//   key                  when                       columns
//   vertices             unless N                   2
//   vertex_attributes    unless N, if any           attributes
//   vertex_markers       unless N or B              1
//   triangles            unless E                   3, or 6 with o2
//   triangle_attributes  unless E, if any           attributes
//   neighbors            n                          3 (-1: none)
//   segments             p or c, unless P           2
//   segment_markers      p or c, unless P or B      1
//   holes, regions       p, unless P                the input's, copied
//   edges                e                          2
//   edge_markers         e, unless B                1

#include <pybind11/pybind11.h>

#include <gpdr/memory_job.hpp>
#include <gpdr/options.hpp>

#include "input_dict.hpp"

namespace gpdr::python {

namespace py = pybind11;

// The mesh, moved out of `mesh` into numpy arrays without a copy.  Throws
// std::overflow_error (OverflowError) before moving anything when the mesh
// has more vertices or triangles than an int32 index can number.
py::dict mesh_dict(MeshOutput& mesh, const Options& options, const ConvertedInput& input);

// The Voronoi diagram (v): `vertices` (one per triangle, its circumcentre),
// `vertex_attributes` if the input has any, `edges` (one per mesh edge; the
// second end -1 for a ray) and `normals` (a ray's direction; 0, 0 for a
// finite edge), moved out of `mesh`.
py::dict voronoi_dict(MeshOutput& mesh);

}  // namespace gpdr::python
