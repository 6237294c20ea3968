#pragma once
// Error types thrown by libgpdr.  The library never prints and never exits:
// it throws one of these, and apps/gpdr turns it into "gpdr: <what()>" on
// stderr and exit status 1 (3 for an InternalError: see man/gpdr.1, EXIT
// STATUS).  Every error is one of the subclasses below; Error itself is
// only their base, for callers that treat them all alike.

#include <cstddef>
#include <stdexcept>
#include <string>

namespace gpdr {

// Base of every error the library reports on purpose.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A malformed or unreadable input file.  what() is "FILE:LINE: reason", or
// "FILE: reason" when the problem is not on one line (line == 0).
class InputError : public Error {
public:
    InputError(std::string file, std::size_t line, std::string reason)
        : Error(line == 0 ? file + ": " + reason
                          : file + ":" + std::to_string(line) + ": " + reason),
          file_(std::move(file)),
          line_(line),
          reason_(std::move(reason)) {}

    const std::string& file() const noexcept { return file_; }
    std::size_t line() const noexcept { return line_; }
    const std::string& reason() const noexcept { return reason_; }

private:
    std::string file_;
    std::size_t line_;
    std::string reason_;
};

// A command line (switch string) that cannot be understood.
class UsageError : public Error {
public:
    using Error::Error;
};

// A request beyond what gpdr provides (e.g. more distinct triangle attribute
// tuples than a triangle's region field holds).  Reported, never ignored.
class NotImplemented : public Error {
public:
    using Error::Error;
};

// An output file that cannot be written (permissions, full disk, ...).
class OutputError : public Error {
public:
    using Error::Error;
};

// A run that would need more than the machine can give it, found before the
// work starts (the memory an area bound's mesh would take).
class ResourceError : public Error {
public:
    using Error::Error;
};

// A mesh larger than gpdr can number: more than 2^30 triangle slots or
// 2^32 - 2 vertices (32-bit ids), or a quadtree of more than 2^32 - 2
// nodes.  Found as the mesh grows, so no estimate can refuse it beforehand,
// and more memory or --force would not help.
class CapacityError : public Error {
public:
    using Error::Error;
};

// Invalid input geometry that is not tied to one line of a file (all points
// collinear, fewer than three vertices, a segment of -rp that leaves the
// mesh, ...).
class GeometryError : public Error {
public:
    using Error::Error;
};

// A subsegment that cannot take a vertex: the triangles on its sides are so
// flat that no point of it lies inside both by the exact tests.  The mesh is
// left as it was.  Refinement leaves such a subsegment as it is; the
// triangulation stages report it.
class SubsegmentSplitError : public Error {
public:
    using Error::Error;
};

// A broken invariant inside gpdr: a bug, never a problem with the input.
// The program and the C API say so and ask for a report with the input.
class InternalError : public Error {
public:
    using Error::Error;
};

}  // namespace gpdr
