#pragma once
// Helpers for the CDT tests: building PSLGs, finding subsegments, and the
// checks every CDT result must pass (check_mesh and segment conformity).

#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "check/checker.hpp"
#include "mesh/traverse.hpp"
#include "triangulate/conformity.hpp"
#include "triangulate/constrained.hpp"

namespace gpdr::triangulate::testing {

using geometry::Point;
using mesh::VertexId;

inline Pslg make_pslg(std::vector<Point> points, std::vector<std::uint32_t> segments,
                      std::vector<Point> holes = {}) {
    Pslg p;
    p.points = std::move(points);
    p.segments = std::move(segments);
    p.holes = std::move(holes);
    return p;
}

// Whether {a, b} is an edge of the mesh flagged as a subsegment (both sides
// are checked by check_mesh).
inline bool has_subsegment(const mesh::Mesh& m, std::uint32_t a, std::uint32_t b) {
    bool found = false;
    mesh::for_each_edge(m, [&](const mesh::EdgeView& e) {
        if (((index(e.from) == a && index(e.to) == b) ||
             (index(e.from) == b && index(e.to) == a)) &&
            e.subsegment)
            found = true;
    });
    return found;
}

inline bool has_edge(const mesh::Mesh& m, std::uint32_t a, std::uint32_t b) {
    bool found = false;
    mesh::for_each_edge(m, [&](const mesh::EdgeView& e) {
        if ((index(e.from) == a && index(e.to) == b) || (index(e.from) == b && index(e.to) == a))
            found = true;
    });
    return found;
}

inline std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
}

// check_mesh and the conformity check; both must find nothing.
inline void require_valid(const mesh::Mesh& m, const Pslg& pslg, const CdtReport& report) {
    const auto problems = mesh::check_mesh(m);
    INFO(joined(problems));
    REQUIRE(problems.empty());
    const auto conformity = check_conformity(m, pslg, report);
    INFO(joined(conformity));
    REQUIRE(conformity.empty());
}

// Random segments between random points in the unit square (or on a small
// integer grid, which makes collinear points, vertices on segments and
// overlapping segments common).
inline Pslg random_pslg(std::mt19937_64& rng, std::size_t points, std::size_t segments, bool grid) {
    Pslg p;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::uniform_int_distribution<int> g(0, 6);
    for (std::size_t i = 0; i < points; ++i)
        p.points.push_back(grid ? Point{double(g(rng)), double(g(rng))} : Point{u(rng), u(rng)});
    std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(points - 1));
    for (std::size_t s = 0; s < segments; ++s) {
        p.segments.push_back(pick(rng));
        p.segments.push_back(pick(rng));
    }
    return p;
}

}  // namespace gpdr::triangulate::testing
