#pragma once
// What every fuzz target asserts about what the library hands back.  A
// broken expectation prints what broke and aborts, which libFuzzer reports
// as a crash and saves the input for; a gpdr::Error the target expects
// (malformed input) is not a finding.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include <gpdr/files.hpp>
#include <gpdr/io.hpp>

namespace gpdr::fuzz {

[[noreturn]] inline void fail(std::string_view what) {
    std::fprintf(stderr, "gpdr fuzz: %.*s\n", static_cast<int>(what.size()), what.data());
    std::abort();
}

inline void expect(bool condition, std::string_view what) {
    if (!condition) fail(what);
}

inline void expect_base(int base) { expect(base == 0 || base == 1, "a base that is not 0 or 1"); }

// Sizes that agree, finite coordinates.
inline void expect_consistent(const NodeSet& nodes) {
    expect(nodes.xy.size() % 2 == 0, "an odd number of vertex coordinates");
    for (double v : nodes.xy) expect(std::isfinite(v), "a vertex coordinate that is not finite");
    expect(nodes.attributes.size() == nodes.size() * nodes.attribute_count,
           "vertex attributes that do not match the count");
    expect(nodes.markers.empty() || nodes.markers.size() == nodes.size(),
           "vertex markers that do not match the count");
}

// Every index below `count`, and as many markers as entries (or none).
inline void expect_indices(const SegmentSet& segments, std::size_t vertex_count) {
    expect(segments.endpoints.size() % 2 == 0, "an odd number of segment endpoints");
    for (std::uint32_t v : segments.endpoints)
        expect(v < vertex_count, "a segment endpoint out of range");
    expect(segments.markers.empty() || segments.markers.size() == segments.size(),
           "segment markers that do not match the count");
}

inline void expect_indices(const EleSet& triangles, std::size_t vertex_count) {
    expect(triangles.corners_per_triangle >= 3, "triangles with fewer than 3 corners");
    expect(triangles.corners.size() % triangles.corners_per_triangle == 0,
           "a triangle list that is not whole triangles");
    for (std::uint32_t v : triangles.corners)
        expect(v < vertex_count, "a triangle corner out of range");
    expect(triangles.attributes.size() == triangles.size() * triangles.attribute_count,
           "triangle attributes that do not match the count");
}

}  // namespace gpdr::fuzz
