#pragma once
// Reading a mesh that gpdr wrote, and measuring it: what CLI tests check
// about the files themselves (angles, areas, canonical triangle sets).

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gpdr/io.hpp>

#include "cli/cli_support.hpp"

namespace gpdr::test {

struct MeshFiles {
    NodeSet nodes;
    EleSet triangles;
    int base = 1;

    static MeshFiles read(const TempDir& dir, const std::string& stem) {
        MeshFiles m;
        auto n = io::read_node((dir / (stem + ".node")).string(), ignore_warning);
        m.nodes = std::move(n.data);
        m.base = n.base;
        m.triangles =
            io::read_ele((dir / (stem + ".ele")).string(), m.base, m.nodes.size(), ignore_warning)
                .data;
        return m;
    }

    std::array<double, 2> point(std::uint32_t v) const {
        return {nodes.xy[2 * v], nodes.xy[2 * v + 1]};
    }
    std::uint32_t corner(std::size_t t, int k) const {
        return triangles.corners[t * triangles.corners_per_triangle + static_cast<std::size_t>(k)];
    }

    double area(std::size_t t) const {
        const auto a = point(corner(t, 0)), b = point(corner(t, 1)), c = point(corner(t, 2));
        return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
    }
    double centroid_x(std::size_t t) const {
        return (point(corner(t, 0))[0] + point(corner(t, 1))[0] + point(corner(t, 2))[0]) / 3;
    }
    double centroid_y(std::size_t t) const {
        return (point(corner(t, 0))[1] + point(corner(t, 1))[1] + point(corner(t, 2))[1]) / 3;
    }
    // The smallest angle of triangle t, in degrees.
    double smallest_angle(std::size_t t) const {
        double smallest = 180;
        for (int k = 0; k < 3; ++k) {
            const auto p = point(corner(t, k)), q = point(corner(t, (k + 1) % 3)),
                       r = point(corner(t, (k + 2) % 3));
            const double ux = q[0] - p[0], uy = q[1] - p[1], vx = r[0] - p[0], vy = r[1] - p[1];
            const double cosine =
                (ux * vx + uy * vy) / std::sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy));
            smallest = std::min(smallest,
                                std::acos(std::clamp(cosine, -1.0, 1.0)) * 180 / std::numbers::pi);
        }
        return smallest;
    }

    // The triangles as corner-coordinate triples, each rotated to start at
    // its smallest point, sorted: comparable across vertex numberings.
    std::vector<std::array<double, 6>> canonical() const {
        std::vector<std::array<double, 6>> out;
        for (std::size_t t = 0; t < triangles.size(); ++t) {
            std::array<std::array<double, 2>, 3> c{point(corner(t, 0)), point(corner(t, 1)),
                                                   point(corner(t, 2))};
            std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
            out.push_back({c[0][0], c[0][1], c[1][0], c[1][1], c[2][0], c[2][1]});
        }
        std::sort(out.begin(), out.end());
        return out;
    }
};

inline std::string sample_text(const std::string& name) {
    return TempDir::slurp(project_samples() / name);
}

}  // namespace gpdr::test
