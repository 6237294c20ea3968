#pragma once
// One call of the module: the switch string and the keyword arguments into
// gpdr::Options, the job run on the arrays with the GIL released, and what
// the call reports (warnings, the -V statistics, -C findings) handed to
// Python.

#include <optional>
#include <string>

#include <pybind11/pybind11.h>

namespace gpdr::python {

namespace py = pybind11;

// gpdr's own keyword arguments.
struct Extras {
    std::optional<long> threads;  // -jN; None: the switches' jN, else 1
    py::object placement;         // -PN by name or number; None: the switches'
    bool check = false;           // -C, raising gpdr.CheckError with the findings
    py::object triunsuitable;     // -u's test (unsuitable.hpp); None: none
    bool force = false;           // --force: skip the memory check
};

// Runs `opts` (Triangle's switches, read as Triangle's library reads them,
// indices from 0) on `tri` (input_dict.hpp).  Returns (mesh, voronoi): the
// two dictionaries of output_dict.hpp, voronoi None unless `opts` has v.
py::tuple run(py::handle tri, const std::string& opts, const Extras& extras);

}  // namespace gpdr::python
