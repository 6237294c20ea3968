// triunsuitable= as a JobPlugins (see unsuitable.hpp).
#include "unsuitable.hpp"

#include <string>

#include <dlfcn.h>

#include <gpdr/errors.hpp>

namespace gpdr::python {
namespace {

// One corner as Python sees it: x, y, then the attributes.
py::tuple corner(const double* values, std::uint32_t width) {
    py::tuple t(width);
    for (std::uint32_t i = 0; i < width; ++i) t[i] = py::float_(values[i]);
    return t;
}

}  // namespace

UserTest::UserTest(py::handle test, std::uint32_t attribute_count) : width_(2 + attribute_count) {
    if (test.is_none()) return;
    if (PyCallable_Check(test.ptr())) {
        callable_ = py::reinterpret_borrow<py::object>(test);
        return;
    }
    py::object path;
    try {
        path = py::module_::import("os").attr("fsdecode")(test);
    } catch (py::error_already_set&) {
        throw py::type_error(
            "triunsuitable must be a callable (org, dest, apex, area) -> bool or the path of a "
            "shared object exporting triunsuitable");
    }
    const std::string given = py::str(path);
    // As the gpdr program's --unsuitable: a bare name is the file in the
    // current folder, not one dlopen() would look up along the library path.
    const std::string name = given.find('/') == std::string::npos ? "./" + given : given;
    library_ = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (library_ == nullptr) {
        const char* reason = dlerror();
        throw InputError(given, 0,
                         std::string("cannot load it as a shared object: ") +
                             (reason != nullptr ? reason : "unknown reason"));
    }
    dlerror();
    void* address = dlsym(library_, "triunsuitable");
    if (address == nullptr)
        throw InputError(given, 0,
                         "has no function triunsuitable (a C++ definition needs extern \"C\")");
    // POSIX: a dlsym() result for a function converts to a function pointer.
    function_ = reinterpret_cast<Triunsuitable>(address);
}

UserTest::~UserTest() {
    if (library_ != nullptr) dlclose(library_);
}

JobPlugins UserTest::plugins() const {
    JobPlugins plugins;
    if (function_ != nullptr) {
        plugins.triunsuitable = function_;
    } else if (callable_) {
        // Borrowed: callable_ keeps it alive, and copying a py::object
        // (this std::function is copied inside the library) would touch its
        // reference count without the GIL.
        PyObject* callable = callable_.ptr();
        const std::uint32_t width = width_;
        plugins.unsuitable = [callable, width](double* org, double* dest, double* apex,
                                               double area) -> int {
            py::gil_scoped_acquire gil;
            const py::object said = py::reinterpret_borrow<py::object>(callable)(
                corner(org, width), corner(dest, width), corner(apex, width), area);
            const int truth = PyObject_IsTrue(said.ptr());
            // A Python exception leaves through the library, which unwinds and
            // rethrows it on the calling thread; pybind11 restores it there.
            if (truth < 0) throw py::error_already_set();
            return truth;
        };
    }
    return plugins;
}

}  // namespace gpdr::python
