// The cascade floor of refinement above 34 degrees (see convergence.hpp).

#include "refine/convergence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/constructions.hpp"
#include "mesh/traverse.hpp"

namespace gpdr::refine {

double cascade_floor_squared(const mesh::Mesh& mesh) {
    double shortest = std::numeric_limits<double>::infinity();
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId, const mesh::Triangle& t) {
        for (int k = 0; k < 3; ++k)
            shortest =
                std::min(shortest, geometry::squared_distance(mesh.point(t.v[mesh::next3(k)]),
                                                              mesh.point(t.v[mesh::prev3(k)])));
    });
    if (!(shortest < std::numeric_limits<double>::infinity())) return 0;
    return shortest * (cascade_depth * cascade_depth);
}

}  // namespace gpdr::refine

namespace gpdr::refine {

double smallest_angle_degrees(const mesh::Mesh& mesh) {
    double smallest_sine = 1;
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId, const mesh::Triangle& t) {
        if (t.small_angle_protected()) return;
        const geometry::Point& a = mesh.point(t.v[0]);
        const geometry::Point& b = mesh.point(t.v[1]);
        const geometry::Point& c = mesh.point(t.v[2]);
        // sin of the smallest angle: twice the area over the product of the
        // two longer sides (the angle between them).
        const double ab = geometry::squared_distance(a, b), bc = geometry::squared_distance(b, c),
                     ca = geometry::squared_distance(c, a);
        const double longer = ab * bc * ca / std::min({ab, bc, ca});
        const double twice_area = 2 * geometry::signed_area(a, b, c);
        if (longer > 0) smallest_sine = std::min(smallest_sine, twice_area / std::sqrt(longer));
    });
    return std::asin(std::clamp(smallest_sine, 0.0, 1.0)) * 180 / std::numbers::pi;
}

}  // namespace gpdr::refine
