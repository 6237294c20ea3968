#pragma once
// A vector the library filled, handed to numpy without a copy: the vector
// moves into a heap object that a capsule owns, the array's base, and is
// freed when the last array (or view) on it goes.

#include <cstddef>
#include <memory>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace gpdr::python {

namespace py = pybind11;

// `values` (moved from) as a rows x columns array of Target.  Target may
// differ from Source only in signedness (the library's uint32 indices are
// numpy's int32: the "none" index 0xffffffff reads as -1, as Triangle
// writes it); the caller has checked that every other index fits.
template <class Target, class Source>
py::array take(std::vector<Source>& values, std::size_t rows, std::size_t columns) {
    static_assert(sizeof(Target) == sizeof(Source) && alignof(Target) == alignof(Source));
    auto owner = std::make_unique<std::vector<Source>>(std::move(values));
    const auto* data = reinterpret_cast<const Target*>(owner->data());
    py::capsule base(owner.get(), [](void* p) { delete static_cast<std::vector<Source>*>(p); });
    owner.release();  // the capsule owns it now
    return py::array_t<Target>({rows, columns}, data, base);
}

}  // namespace gpdr::python
