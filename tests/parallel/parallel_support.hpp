#pragma once
// Inputs and settings the parallel refiner's tests share.

#include <cmath>
#include <cstdint>
#include <random>

#include "refine/refine_support.hpp"

namespace gpdr::parallel::testing {

using refine::testing::cdt;
using refine::testing::examine;
using refine::testing::joined;
using refine::testing::point_set_mesh;
using refine::testing::random_points;

// Refinement with these bounds, every Steiner point verified.
inline refine::RefineSettings settings_for(double angle, double area) {
    refine::RefineSettings s;
    s.criteria.min_angle_degrees = angle;
    s.criteria.max_area = area;
    s.checked = true;
    return s;
}

// A square with a square hole and an acute notch (small input angle).
inline triangulate::Pslg notched_square() {
    triangulate::Pslg p;
    p.points = {{0, 0}, {4, 0},   {4, 4},     {2.2, 4}, {2, 1.5}, {1.8, 4},
                {0, 4}, {1, 2.5}, {1.5, 2.5}, {1.5, 3}, {1, 3}};
    p.segments = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 0, 7, 8, 8, 9, 9, 10, 10, 7};
    p.holes = {{1.25, 2.75}};
    return p;
}

// A random PSLG: a polygon with jittered vertices around a circle plus
// random interior points.
inline triangulate::Pslg random_pslg(std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    triangulate::Pslg p;
    const int n = 5 + static_cast<int>(rng() % 12);
    for (int i = 0; i < n; ++i) {
        const double a = 2 * 3.141592653589793 * (i + 0.8 * u(rng)) / n;
        const double r = 0.5 + 0.5 * u(rng);
        p.points.push_back({r * std::cos(a), r * std::sin(a)});
        p.segments.push_back(static_cast<std::uint32_t>(i));
        p.segments.push_back(static_cast<std::uint32_t>((i + 1) % n));
    }
    for (int i = 0; i < 10; ++i) p.points.push_back({0.4 * (u(rng) - 0.5), 0.4 * (u(rng) - 0.5)});
    return p;
}

}  // namespace gpdr::parallel::testing
