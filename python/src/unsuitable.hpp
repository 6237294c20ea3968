#pragma once
// triangulate()'s triunsuitable=: Triangle's user test for -u, given as
//
//   * a Python callable (org, dest, apex, area) -> bool: each corner a tuple
//     (x, y, then the vertex attributes), counter-clockwise; a true result
//     refines the triangle.  It is called with the GIL held, so the call
//     refines on one thread; an exception it raises stops the call and
//     propagates to the caller;
//   * a path (str, bytes or os.PathLike) to a shared object exporting
//     `int triunsuitable(double* org, double* dest, double* apex, double
//     area)`, as the gpdr program's --unsuitable loads it: it runs without
//     the GIL, on every thread of the call, and must be thread-safe.

#include <cstdint>

#include <pybind11/pybind11.h>

#include <gpdr/job.hpp>

namespace gpdr::python {

namespace py = pybind11;

class UserTest {
public:
    // Reads triunsuitable= (None: no test).  A path is loaded here (dlopen,
    // RTLD_NOW | RTLD_LOCAL); gpdr.Error if it cannot be loaded or exports no
    // triunsuitable; TypeError for anything that is neither callable nor a path.
    // `attribute_count`: the input's vertex attributes, which each corner carries.
    UserTest(py::handle test, std::uint32_t attribute_count);
    ~UserTest();
    UserTest(const UserTest&) = delete;
    UserTest& operator=(const UserTest&) = delete;

    bool given() const { return function_ != nullptr || callable_; }
    // Whether the test is Python code: the call then refines on one thread.
    bool needs_one_thread() const { return static_cast<bool>(callable_); }
    // The plug-in for run_job_in_memory(); valid while this object lives and,
    // for a Python callable, called only with the GIL released by its caller.
    JobPlugins plugins() const;

private:
    py::object callable_;  // held here, so that the test may borrow it without the GIL
    std::uint32_t width_ = 2;
    void* library_ = nullptr;  // dlopen handle
    Triunsuitable function_ = nullptr;
};

}  // namespace gpdr::python
