// The smallest angle and the area of a triangle, for the cell data of the
// .vtu file and the shading of the picture.

#include <algorithm>
#include <cmath>
#include <numbers>

#include <gpdr/mesh_formats.hpp>

namespace gpdr::io {

double triangle_area(const double* a, const double* b, const double* c) noexcept {
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
}

// The smallest angle is the one opposite the shortest edge: one atan2 at
// that corner, of |cross| and dot of the two edges leaving it, which is
// accurate for small and for large angles alike (an acos of the cosine is
// not, near 0).
double smallest_angle_degrees(const double* a, const double* b, const double* c) noexcept {
    const double* p[3] = {a, b, c};
    double shortest = 0;
    int opposite = 0;
    for (int k = 0; k < 3; ++k) {
        const double* u = p[(k + 1) % 3];
        const double* v = p[(k + 2) % 3];
        const double d = (u[0] - v[0]) * (u[0] - v[0]) + (u[1] - v[1]) * (u[1] - v[1]);
        if (k == 0 || d < shortest) {
            shortest = d;
            opposite = k;
        }
    }
    const double* o = p[opposite];
    const double* u = p[(opposite + 1) % 3];
    const double* v = p[(opposite + 2) % 3];
    const double ux = u[0] - o[0], uy = u[1] - o[1], vx = v[0] - o[0], vy = v[1] - o[1];
    const double angle = std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy);
    return angle * (180 / std::numbers::pi);
}

}  // namespace gpdr::io
