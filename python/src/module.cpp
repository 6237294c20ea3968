// The extension module gpdr._core: gpdr's meshing for Python, behind the
// public functions of gpdr/__init__.py, which give it the triangle
// package's interface (docs/python.md).
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "call.hpp"
#include "errors.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_core, module) {
    module.doc() = "gpdr's meshing on numpy arrays; use it through the package gpdr.";
    module.attr("__version__") = GPDR_VERSION;
    gpdr::python::register_errors(module);
    module.def(
        "run",
        [](py::handle tri, const std::string& opts, std::optional<long> threads,
           py::object placement, bool check, py::object triunsuitable, bool force) {
            gpdr::python::Extras extras;
            extras.threads = threads;
            extras.placement = std::move(placement);
            extras.check = check;
            extras.triunsuitable = std::move(triunsuitable);
            extras.force = force;
            return gpdr::python::run(tri, opts, extras);
        },
        py::arg("tri"), py::arg("opts") = "", py::kw_only(), py::arg("threads") = py::none(),
        py::arg("placement") = py::none(), py::arg("check") = false,
        py::arg("triunsuitable") = py::none(), py::arg("force") = false,
        "Runs gpdr on the dictionary `tri` with Triangle's switches `opts`; returns (mesh, "
        "voronoi), voronoi None unless opts has v.");
}
