#pragma once
// The Python exception and warning types of the module, and how the
// library's C++ exceptions become them:
//
//   gpdr::InputError, UsageError, GeometryError ...  -> gpdr.Error (a ValueError)
//   gpdr::ResourceError (the memory check refuses)   -> MemoryError
//   gpdr::CapacityError (past gpdr's 32-bit ids)     -> OverflowError
//   gpdr::InternalError (a bug in gpdr)              -> RuntimeError
//   std::bad_alloc                                   -> MemoryError (pybind11's own)
//   -C findings                                      -> gpdr.CheckError (a RuntimeError)
//
// Warnings go to Python's warnings module as gpdr.MeshWarning (a UserWarning).

#include <string>
#include <vector>

#include <pybind11/pybind11.h>

namespace gpdr::python {

namespace py = pybind11;

// The name run_job_in_memory() gives the arrays of one call, so that the
// translator can tell an error about them (reported by its reason alone,
// "segment 3 refers to vertex 12, ...") from one about a file (the .so of a
// triunsuitable= path, reported with the file's name).
inline constexpr const char* input_name = "triangulate() input";

// Creates gpdr.Error, gpdr.CheckError and gpdr.MeshWarning in `module` and
// registers the translator of the library's exceptions.  Called once, at import.
void register_errors(py::module_& module);

// gpdr.Error: bad input or switches, raised with `message`.
[[noreturn]] void raise_error(const std::string& message);

// gpdr.CheckError: what -C found, as the message and the list `problems`.
[[noreturn]] void raise_check_error(const std::vector<std::string>& problems);

// Issues `message` as a gpdr.MeshWarning pointing at the caller of the
// public function; raises if a warnings filter turns it into an error.
void warn(const std::string& message);

}  // namespace gpdr::python
