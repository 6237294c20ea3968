// gpdr's exceptions as Python exceptions (see errors.hpp).  The types are
// made once, at import, and live as long as the interpreter: the module
// holds a reference, and so do the handles here, which are never released
// (an extension module is never unloaded).
#include "errors.hpp"

#include <exception>

#include <gpdr/errors.hpp>

namespace gpdr::python {
namespace {

PyObject* error_type = nullptr;
PyObject* check_error_type = nullptr;
PyObject* mesh_warning_type = nullptr;

PyObject* new_type(py::module_& module, const char* name, PyObject* base, const char* doc) {
    const std::string qualified = std::string("gpdr.") + name;
    PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base, nullptr);
    if (type == nullptr) throw py::error_already_set();
    module.attr(name) = py::reinterpret_borrow<py::object>(type);
    return type;
}

[[noreturn]] void raise(PyObject* type, const std::string& message) {
    PyErr_SetString(type, message.c_str());
    throw py::error_already_set();
}

// Registered with pybind11: called with any C++ exception that leaves a bound
// function.  What it does not catch falls through to pybind11's own
// translators (std::bad_alloc -> MemoryError, std::overflow_error ->
// OverflowError, other std::exception -> RuntimeError).
void translate(std::exception_ptr failure) {
    try {
        std::rethrow_exception(failure);
    } catch (const InternalError& e) {
        PyErr_SetString(
            PyExc_RuntimeError,
            (std::string(e.what()) + " (an internal error in gpdr: please report it)").c_str());
    } catch (const ResourceError& e) {
        PyErr_SetString(PyExc_MemoryError, e.what());
    } catch (const CapacityError& e) {
        // More ids than gpdr's 32-bit ids hold: as a result past int32 indices.
        PyErr_SetString(PyExc_OverflowError, e.what());
    } catch (const InputError& e) {
        // The caller's arrays are not a file: the reason alone names the entry.
        PyErr_SetString(error_type, e.file() == input_name ? e.reason().c_str() : e.what());
    } catch (const Error& e) {
        PyErr_SetString(error_type, e.what());
    }
}

}  // namespace

void register_errors(py::module_& module) {
    error_type = new_type(module, "Error", PyExc_ValueError,
                          "Bad input or switches: gpdr's message says which entry and why.");
    check_error_type =
        new_type(module, "CheckError", PyExc_RuntimeError,
                 "What check=True (the C switch) found wrong with the mesh; the list is in "
                 "`problems`.");
    mesh_warning_type = new_type(module, "MeshWarning", PyExc_UserWarning,
                                 "A harmless oddity of the input (duplicate vertices, segments "
                                 "that cross ...), as the gpdr program warns of it.");
    py::register_exception_translator(&translate);
}

void raise_error(const std::string& message) { raise(error_type, message); }

void raise_check_error(const std::vector<std::string>& problems) {
    std::string message = std::to_string(problems.size()) +
                          (problems.size() == 1 ? " problem" : " problems") + " found in the mesh";
    for (const std::string& problem : problems) message += "\n  " + problem;
    py::list listed;
    for (const std::string& problem : problems) listed.append(py::str(problem));
    py::object error = py::reinterpret_borrow<py::object>(check_error_type)(message);
    if (PyObject_SetAttrString(error.ptr(), "problems", listed.ptr()) != 0)
        throw py::error_already_set();
    PyErr_SetObject(check_error_type, error.ptr());
    throw py::error_already_set();
}

void warn(const std::string& message) {
    // Level 2: the frame that called the public function (gpdr/__init__.py
    // calls this module), as warnings.warn(..., stacklevel=2) would.
    if (PyErr_WarnEx(mesh_warning_type, message.c_str(), 2) != 0) throw py::error_already_set();
}

}  // namespace gpdr::python
