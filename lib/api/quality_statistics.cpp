// The "Mesh quality statistics" block that -V prints, in Triangle's layout:
// extreme areas, edge lengths, altitudes and aspect ratios, and histograms of
// aspect ratio (longest edge over shortest altitude) and of all angles.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "api/mesh_arrays.hpp"

namespace gpdr::api {

std::vector<std::string> quality_statistics(const MeshArrays& mesh) {
    constexpr std::array<double, 16> ratio_bounds{1.5, 2, 2.5, 3, 4, 6, 10, 15, 25, 50, 100, 300, 1000, 10000, 100000,
                                                  std::numeric_limits<double>::infinity()};
    constexpr std::array<const char*, 16> ratio_labels{
        "1.1547 - 1.5      ", "   1.5 - 2        ", "     2 - 2.5      ", "   2.5 - 3        ",
        "     3 - 4        ", "     4 - 6        ", "     6 - 10       ", "    10 - 15       ",
        "    15 - 25       ", "    25 - 50       ", "    50 - 100      ", "   100 - 300      ",
        "   300 - 1000     ", "  1000 - 10000    ", " 10000 - 100000   ", "100000 -          "};
    std::array<std::uint64_t, 16> ratio_histogram{};
    std::array<std::uint64_t, 18> angle_histogram{};

    const double inf = std::numeric_limits<double>::infinity();
    double min_area = inf, max_area = 0, min_edge2 = inf, max_edge2 = 0;
    double min_altitude = inf, max_ratio = 0, min_angle = 180, max_angle = 0;

    const auto& xy = mesh.nodes.xy;
    const io::EleSource triangles = triangle_source(mesh);
    std::uint32_t corners[6];
    std::vector<double> attributes(triangles.attribute_count);
    // The triangles come in mesh order and their corners lie anywhere in
    // the node array (hundreds of megabytes for a large mesh): a batch's
    // corners are read first and their coordinates asked for, so that the
    // cache misses overlap instead of stalling each triangle in turn.
    constexpr std::size_t batch = 256;
    std::array<std::uint32_t, 3 * batch> batch_corners;
    for (std::size_t first = 0; first < triangles.count; first += batch) {
        const std::size_t n = std::min(batch, triangles.count - first);
        for (std::size_t i = 0; i < n; ++i) {
            triangles.next(corners, attributes.data());
            for (std::size_t k = 0; k < 3; ++k) {
                batch_corners[3 * i + k] = corners[k];
                __builtin_prefetch(&xy[2 * std::size_t{corners[k]}]);
            }
        }
        for (std::size_t i = 0; i < n; ++i) {
            std::array<double, 3> px, py, edge2;  // edge2[k]: squared length of the edge opposite corner k
            for (std::size_t k = 0; k < 3; ++k) {
                const std::size_t v = batch_corners[3 * i + k];
                px[k] = xy[2 * v];
                py[k] = xy[2 * v + 1];
            }
            for (std::size_t k = 0; k < 3; ++k) {
                const double dx = px[(k + 2) % 3] - px[(k + 1) % 3], dy = py[(k + 2) % 3] - py[(k + 1) % 3];
                edge2[k] = dx * dx + dy * dy;
            }
            const double twice_area =
                std::abs((px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]));
            const double longest2 = std::max({edge2[0], edge2[1], edge2[2]});
            min_area = std::min(min_area, twice_area / 2);
            max_area = std::max(max_area, twice_area / 2);
            min_edge2 = std::min({min_edge2, edge2[0], edge2[1], edge2[2]});
            max_edge2 = std::max(max_edge2, longest2);
            // The shortest altitude stands on the longest edge.
            const double altitude = twice_area / std::sqrt(longest2);
            min_altitude = std::min(min_altitude, altitude);
            const double ratio = std::sqrt(longest2) / altitude;
            max_ratio = std::max(max_ratio, ratio);
            std::size_t bin = 0;
            while (bin + 1 < ratio_bounds.size() && ratio > ratio_bounds[bin]) ++bin;
            ++ratio_histogram[bin];
            for (std::size_t k = 0; k < 3; ++k) {
                // The angle at corner k lies between the edges opposite k+1 and k+2.
                const double a2 = edge2[(k + 1) % 3], b2 = edge2[(k + 2) % 3], c2 = edge2[k];
                const double cosine = std::clamp((a2 + b2 - c2) / (2 * std::sqrt(a2 * b2)), -1.0, 1.0);
                const double degrees = std::acos(cosine) * 180 / std::numbers::pi;
                min_angle = std::min(min_angle, degrees);
                max_angle = std::max(max_angle, degrees);
                ++angle_histogram[std::min<std::size_t>(17, static_cast<std::size_t>(degrees / 10))];
            }
        }
    }
    if (triangles.count == 0) return {};

    std::vector<std::string> lines;
    lines.push_back("Mesh quality statistics:");
    lines.emplace_back();
    lines.push_back(fmt::format("  Smallest area: {:16.5g}   |  Largest area: {:16.5g}", min_area, max_area));
    lines.push_back(fmt::format("  Shortest edge: {:16.5g}   |  Longest edge: {:16.5g}", std::sqrt(min_edge2),
                                std::sqrt(max_edge2)));
    lines.push_back(fmt::format("  Shortest altitude: {:12.5g}   |  Largest aspect ratio: {:8.5g}", min_altitude,
                                max_ratio));
    lines.emplace_back();
    lines.push_back("  Triangle aspect ratio histogram:");
    for (std::size_t i = 0; i < 8; ++i) {
        lines.push_back(fmt::format("  {}:  {:8}    | {}:  {:8}", ratio_labels[i], ratio_histogram[i],
                                    ratio_labels[i + 8], ratio_histogram[i + 8]));
    }
    lines.push_back("  (Aspect ratio is longest edge divided by shortest altitude)");
    lines.emplace_back();
    lines.push_back(fmt::format("  Smallest angle: {:15.5g}   |  Largest angle: {:15.5g}", min_angle, max_angle));
    lines.emplace_back();
    lines.push_back("  Angle histogram:");
    for (std::size_t i = 0; i < 9; ++i) {
        lines.push_back(fmt::format("    {:3} - {:3} degrees:  {:8}    |    {:3} - {:3} degrees:  {:8}", 10 * i,
                                    10 * i + 10, angle_histogram[i], 10 * i + 90, 10 * i + 100,
                                    angle_histogram[i + 9]));
    }
    return lines;
}

}  // namespace gpdr::api
