#pragma once
// The `tri` dictionary of triangulate(), with the triangle package's keys,
// read into gpdr's in-memory input (gpdr/memory_job.hpp).
//
//   key                  rows        columns   read with
//   vertices             vertices    2         always
//   vertex_attributes    vertices    any       always
//   vertex_markers       vertices    1         always
//   segments             segments    2         p
//   segment_markers      segments    1         p
//   holes                holes       2         p
//   regions              regions     4         p  (x, y, attribute, area bound)
//   triangles            triangles   3 or 6    r
//   triangle_attributes  triangles   any       r
//   triangle_max_area    triangles   1         r with a bare a
//
// Each value may be anything numpy turns into an array (a list of lists, an
// array of another dtype); it is converted once, and a one-dimensional one is
// taken as a column, as the triangle package takes it.  The keys that the
// package's own results and loaders hold but Triangle never reads
// (neighbors, edges, edge_markers, triangle_neighbors, ray_origins,
// ray_directions) are accepted and ignored, so that a result can be passed
// back in for -r; any other key is an error.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <gpdr/memory_job.hpp>

namespace gpdr::python {

namespace py = pybind11;

struct ConvertedInput {
    MeshInput mesh;
    // The holes and regions as given, for the result's keys of the same
    // names (Triangle's library hands back the input's arrays); None when absent.
    py::object holes = py::none();
    py::object regions = py::none();
};

// Reads `tri`.  Raises gpdr.Error naming the key for a value numpy cannot
// read as numbers, a wrong number of columns or rows, a negative index, or a
// marker outside a 32-bit int; the library checks the rest (indices past the
// last vertex, coordinates that are not finite).
ConvertedInput read_input(py::handle tri);

}  // namespace gpdr::python
