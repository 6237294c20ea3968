#pragma once
// Helpers of the refinement tests: meshes to refine (a point set whose hull
// edges are flagged as subsegments, as Triangle does for a point set; PSLGs
// through the CDT) and the checks every refined mesh must pass.

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "check/checker.hpp"
#include "geometry/constructions.hpp"
#include "mesh/traverse.hpp"
#include "refine/refine.hpp"
#include "refine/segments.hpp"
#include "triangulate/constrained.hpp"
#include "triangulate/delaunay.hpp"

namespace gpdr::refine::testing {

using geometry::Point;

// Delaunay triangulation of the points, hull edges flagged (marker 1).
inline mesh::Mesh point_set_mesh(const std::vector<Point>& points) {
    triangulate::DelaunayReport report;
    mesh::Mesh m = triangulate::delaunay(points, report);
    std::vector<mesh::EdgeView> hull;
    mesh::for_each_hull_edge(m, [&](const mesh::EdgeView& e) { hull.push_back(e); });
    for (const auto& e : hull) {
        m.triangle(e.edge.triangle()).set_subsegment(e.edge.edge(), true);
        m.subsegments().set(e.from, e.to,
                            mesh::SubsegmentInfo{1, mesh::SubsegmentInfo::no_segment});
    }
    return m;
}

inline std::vector<Point> random_points(std::size_t n, std::uint32_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Point> p(n);
    for (auto& q : p) q = {u(rng), u(rng)};
    return p;
}

inline std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
}

// The smallest angle of triangle abc, in degrees.
inline double min_angle_degrees(const Point& a, const Point& b, const Point& c) {
    auto angle = [](const Point& o, const Point& p, const Point& q) {
        const double ux = p.x - o.x, uy = p.y - o.y, vx = q.x - o.x, vy = q.y - o.y;
        return std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180.0 /
               std::numbers::pi;
    };
    return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

struct Outcome {
    std::size_t triangles = 0;
    std::size_t bad_angles = 0;  // below the bound and not protected
    std::size_t too_big = 0;
    double smallest_angle = 180;
};

// check_mesh passes; counts what violates the bounds (protected triangles
// excepted, by the same rule the refiner uses).
inline Outcome examine(const mesh::Mesh& m, const RefineSettings& settings) {
    const auto problems = mesh::check_mesh(m);
    INFO(joined(problems));
    REQUIRE(problems.empty());
    Outcome o;
    const QualityTest quality(settings.criteria, SegmentEnds{settings.segment_ends});
    mesh::for_each_triangle(m, [&](mesh::TriangleId id, const mesh::Triangle& t) {
        ++o.triangles;
        const Point& a = m.point(t.v[0]);
        const Point& b = m.point(t.v[1]);
        const Point& c = m.point(t.v[2]);
        const TriangleMeasures measures = QualityTest::measure(a, b, c);
        bool protected_angle = false;
        quality.assess(m, id, measures, &protected_angle);
        const double angle = min_angle_degrees(a, b, c);
        o.smallest_angle = std::min(o.smallest_angle, angle);
        // A tiny tolerance: the test is on rho, computed in floating point.
        if (!protected_angle && angle < settings.criteria.min_angle_degrees * (1 - 1e-9))
            ++o.bad_angles;
        if (settings.criteria.max_area > 0 && measures.area > settings.criteria.max_area)
            ++o.too_big;
    });
    return o;
}

}  // namespace gpdr::refine::testing

namespace gpdr::refine::testing {

// A minimal .poly reader for the project's samples (vertices, segments,
// holes; no regions), enough for the tests.
inline triangulate::Pslg read_poly(const std::string& path) {
    std::ifstream in(path);
    std::vector<double> numbers;
    std::string line;
    std::vector<std::vector<double>> lines;
    while (std::getline(in, line)) {
        if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        std::istringstream words(line);
        std::vector<double> row;
        double x;
        while (words >> x) row.push_back(x);
        if (!row.empty()) lines.push_back(row);
    }
    triangulate::Pslg p;
    std::size_t at = 0;
    const auto n = static_cast<std::size_t>(lines.at(at++)[0]);
    const int base = static_cast<int>(lines.at(at)[0]);
    for (std::size_t i = 0; i < n; ++i, ++at) p.points.push_back({lines[at][1], lines[at][2]});
    const auto s = static_cast<std::size_t>(lines.at(at++)[0]);
    for (std::size_t i = 0; i < s; ++i, ++at) {
        p.segments.push_back(static_cast<std::uint32_t>(lines[at][1] - base));
        p.segments.push_back(static_cast<std::uint32_t>(lines[at][2] - base));
    }
    if (at < lines.size()) {
        const auto h = static_cast<std::size_t>(lines.at(at++)[0]);
        for (std::size_t i = 0; i < h; ++i, ++at) p.holes.push_back({lines[at][1], lines[at][2]});
    }
    return p;
}

// The input segments' ends as vertex ids (for RefineSettings::segment_ends).
inline std::vector<mesh::VertexId> segment_ends(const triangulate::Pslg& p) {
    std::vector<mesh::VertexId> ends;
    for (std::uint32_t v : p.segments) ends.push_back(mesh::VertexId{v});
    return ends;
}

inline mesh::Mesh cdt(const triangulate::Pslg& p) {
    triangulate::CdtReport report;
    return triangulate::constrained_delaunay(p, {}, report);
}

}  // namespace gpdr::refine::testing
