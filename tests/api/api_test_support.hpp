#pragma once
// Helpers shared by the api tests that mesh whole sample files: finding the
// samples, and measuring a triangle independently of the refiner.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

#include "geometry/point.hpp"

namespace gpdr::test {

// The .poly files in `folder`, sorted by name (none if it is not a folder).
inline std::vector<std::filesystem::path> poly_files(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> out;
    if (folder.empty() || !std::filesystem::is_directory(folder)) return out;
    for (const auto& e : std::filesystem::directory_iterator(folder))
        if (e.path().extension() == ".poly") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

// The smallest angle of triangle abc in degrees, by the law of cosines
// (independent of the refiner's own measures).
inline double smallest_angle(const geometry::Point& a, const geometry::Point& b,
                             const geometry::Point& c) {
    const geometry::Point p[3] = {a, b, c};
    double smallest = 180;
    for (int k = 0; k < 3; ++k) {
        const auto& o = p[k];
        const auto& u = p[(k + 1) % 3];
        const auto& v = p[(k + 2) % 3];
        const double ux = u.x - o.x, uy = u.y - o.y, vx = v.x - o.x, vy = v.y - o.y;
        const double cosine =
            (ux * vx + uy * vy) / std::sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy));
        smallest =
            std::min(smallest, std::acos(std::clamp(cosine, -1.0, 1.0)) * 180 / std::numbers::pi);
    }
    return smallest;
}

}  // namespace gpdr::test
