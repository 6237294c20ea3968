#include "stress/random_pslg.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <set>
#include <utility>
#include <vector>

#include "geometry/predicates.hpp"

namespace gpdr::stress {

namespace {

// splitmix64: a small generator whose sequence is fixed by its definition.
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    // An integer in [lo, hi].
    int between(int lo, int hi) {
        return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
    }
    // A double in [0, 1).
    double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    template <class T, std::size_t N>
    T pick(const std::array<T, N>& choices) {
        return choices[next() % N];
    }

private:
    std::uint64_t state_;
};

// Scales and offsets.  Factors such as 0.1 and 1e-3 make even the grid
// points inexact; a large offset leaves few bits for the shape itself.
constexpr std::array<double, 9> scales{1, 1, 0.1, 1e-3, 0.37, 3.3e-5, 1e3, 7.1e4, 1e6};
constexpr std::array<double, 6> offsets{0, 0, 1e6, -250.75, 1e3 + 0.1, -3.3e5};

bool on_some_segment(const PolyFile& poly, double x, double y) {
    const geometry::Point p{x, y};
    for (std::size_t s = 0; s < poly.segments.size(); ++s) {
        const auto a = poly.segments.endpoints[2 * s], b = poly.segments.endpoints[2 * s + 1];
        const geometry::Point pa{poly.nodes.xy[2 * a], poly.nodes.xy[2 * a + 1]};
        const geometry::Point pb{poly.nodes.xy[2 * b], poly.nodes.xy[2 * b + 1]};
        if (geometry::orient2d(pa, pb, p) != 0) continue;
        if (std::min(pa.x, pb.x) <= x && x <= std::max(pa.x, pb.x) && std::min(pa.y, pb.y) <= y &&
            y <= std::max(pa.y, pb.y))
            return true;
    }
    return false;
}

}  // namespace

const char* family_name(Family family) { return family == Family::dense ? "dense" : "sparse"; }

RandomPslg random_pslg(std::uint64_t seed) {
    Random random(seed);
    RandomPslg out;
    out.seed = seed;
    out.family = seed % 2 == 0 ? Family::dense : Family::sparse;
    const bool dense = out.family == Family::dense;

    // Distinct grid points: many of them collinear, so segments overlap and
    // run through vertices.
    const int low = dense ? 0 : -2;
    const int high = dense ? random.between(3, 6) : 12;
    const int side = high - low + 1;
    const int wanted = dense ? random.between(6, 20) : random.between(4, 14);
    const int vertex_count = std::min(wanted, side * side);
    std::set<std::pair<int, int>> taken;
    std::vector<std::pair<int, int>> grid;
    while (static_cast<int>(grid.size()) < vertex_count) {
        const std::pair<int, int> g{random.between(low, high), random.between(low, high)};
        if (taken.insert(g).second) grid.push_back(g);
    }

    out.scale = random.pick(scales);
    out.offset_x = random.pick(offsets);
    out.offset_y = random.next() % 2 ? out.offset_x : random.pick(offsets);
    auto place = [&](double gx, double gy) {
        return std::pair<double, double>{out.offset_x + out.scale * gx,
                                         out.offset_y + out.scale * gy};
    };
    PolyFile& poly = out.poly;
    for (const auto& [gx, gy] : grid) {
        const auto [x, y] = place(gx, gy);
        poly.nodes.xy.push_back(x);
        poly.nodes.xy.push_back(y);
    }

    const int segment_count = dense ? random.between(8, 30) : random.between(2, 9);
    for (int s = 0; s < segment_count; ++s) {
        const auto a = static_cast<std::uint32_t>(random.between(0, vertex_count - 1));
        auto b = static_cast<std::uint32_t>(random.between(0, vertex_count - 2));
        if (b >= a) ++b;
        poly.segments.endpoints.push_back(a);
        poly.segments.endpoints.push_back(b);
    }

    // Hole and region points off the grid lines, and never exactly on a
    // segment (which side such a point is on is not defined).
    auto free_point = [&] {
        for (;;) {
            const double gx = low + (high - low) * random.unit();
            const double gy = low + (high - low) * random.unit();
            const auto [x, y] = place(gx, gy);
            if (!on_some_segment(poly, x, y)) return std::pair<double, double>{x, y};
        }
    };
    if (random.next() % 4 == 0) {
        const int holes = random.between(1, 2);
        for (int h = 0; h < holes; ++h) {
            const auto [x, y] = free_point();
            poly.holes.push_back(x);
            poly.holes.push_back(y);
        }
    }
    if (random.next() % 4 == 0) {
        const int regions = random.between(1, 3);
        for (int r = 0; r < regions; ++r) {
            const auto [x, y] = free_point();
            poly.regions.push_back(Region{x, y, static_cast<double>(r + 1), -1});
        }
    }
    return out;
}

std::string poly_text(const PolyFile& poly, const std::string& comment) {
    std::string text = "# " + comment + "\n";
    char line[200];
    std::snprintf(line, sizeof line, "%zu 2 0 0\n", poly.nodes.size());
    text += line;
    for (std::size_t v = 0; v < poly.nodes.size(); ++v) {
        std::snprintf(line, sizeof line, "%zu %.17g %.17g\n", v + 1, poly.nodes.xy[2 * v],
                      poly.nodes.xy[2 * v + 1]);
        text += line;
    }
    std::snprintf(line, sizeof line, "%zu 0\n", poly.segments.size());
    text += line;
    for (std::size_t s = 0; s < poly.segments.size(); ++s) {
        std::snprintf(line, sizeof line, "%zu %u %u\n", s + 1, poly.segments.endpoints[2 * s] + 1,
                      poly.segments.endpoints[2 * s + 1] + 1);
        text += line;
    }
    std::snprintf(line, sizeof line, "%zu\n", poly.holes.size() / 2);
    text += line;
    for (std::size_t h = 0; h < poly.holes.size() / 2; ++h) {
        std::snprintf(line, sizeof line, "%zu %.17g %.17g\n", h + 1, poly.holes[2 * h],
                      poly.holes[2 * h + 1]);
        text += line;
    }
    if (!poly.regions.empty()) {
        std::snprintf(line, sizeof line, "%zu\n", poly.regions.size());
        text += line;
        for (std::size_t r = 0; r < poly.regions.size(); ++r) {
            const Region& region = poly.regions[r];
            std::snprintf(line, sizeof line, "%zu %.17g %.17g %.17g %.17g\n", r + 1, region.x,
                          region.y, region.attribute, region.max_area);
            text += line;
        }
    }
    return text;
}

}  // namespace gpdr::stress
