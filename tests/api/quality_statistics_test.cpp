// The -V "Mesh quality statistics" block: its figures for a mesh whose
// angles and aspect ratios are known, and, for a mesh of several thousand
// jittered triangles (read in runs: more than one, the last partial), its
// extremes and histograms against a triangle-by-triangle computation, and
// the same text from any number of threads.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "api/mesh_arrays.hpp"

using gpdr::api::MeshArrays;

namespace {

MeshArrays arrays(std::vector<double> xy, std::vector<std::uint32_t> corners) {
    MeshArrays m;
    m.nodes.xy = std::move(xy);
    m.triangles.corners = std::move(corners);
    return m;
}

// The numbers on the line that contains `key` (after the key).
std::vector<double> numbers_after(const std::vector<std::string>& lines, const std::string& key) {
    for (const std::string& line : lines) {
        const auto at = line.find(key);
        if (at == std::string::npos) continue;
        std::vector<double> out;
        std::string rest = line.substr(at + key.size());
        for (char& c : rest)
            if (c == ':' || c == '|') c = ' ';
        std::istringstream in(rest);
        std::string word;
        while (in >> word) {
            try {
                std::size_t used = 0;
                const double v = std::stod(word, &used);
                if (used == word.size()) out.push_back(v);
            } catch (const std::exception&) {}
        }
        return out;
    }
    return {};
}

// The counts of a histogram: the last number before and after each '|' of
// the lines that follow `title`, left column first.
std::vector<std::uint64_t> histogram(const std::vector<std::string>& lines,
                                     const std::string& title, int rows) {
    const auto start = std::find_if(lines.begin(), lines.end(), [&](const std::string& l) {
        return l.find(title) != std::string::npos;
    });
    REQUIRE(start != lines.end());
    std::vector<std::uint64_t> left, right;
    for (int r = 1; r <= rows; ++r) {
        const std::string& line = *(start + r);
        const auto bar = line.find('|');
        REQUIRE(bar != std::string::npos);
        const auto last_number = [](const std::string& s) {
            std::istringstream in(s);
            std::string word, last;
            while (in >> word) last = word;
            return std::stoull(last);
        };
        left.push_back(last_number(line.substr(0, bar)));
        right.push_back(last_number(line.substr(bar + 1)));
    }
    left.insert(left.end(), right.begin(), right.end());
    return left;
}

}  // namespace

TEST_CASE("quality statistics of a 3 x 1 rectangle cut along its diagonal", "[api][statistics]") {
    const auto lines =
        gpdr::api::quality_statistics(arrays({0, 0, 3, 0, 3, 1, 0, 1}, {0, 1, 2, 0, 2, 3}));
    CHECK(numbers_after(lines, "Smallest area:") == std::vector<double>{1.5, 1.5});
    const auto edges = numbers_after(lines, "Shortest edge:");
    REQUIRE(edges.size() == 2);
    CHECK(edges[0] == 1);
    CHECK(edges[1] == Approx(std::sqrt(10.0)).epsilon(1e-4));
    const auto altitude = numbers_after(lines, "Shortest altitude:");
    REQUIRE(altitude.size() == 2);
    CHECK(altitude[0] == Approx(3 / std::sqrt(10.0)).epsilon(1e-4));
    CHECK(altitude[1] == Approx(10.0 / 3).epsilon(1e-4));  // longest edge over shortest altitude
    const double small = std::atan(1.0 / 3) * 180 / std::numbers::pi;  // 18.43 degrees
    const auto angle = numbers_after(lines, "Smallest angle:");
    REQUIRE(angle.size() == 2);
    CHECK(angle[0] == Approx(small).epsilon(1e-4));
    CHECK(angle[1] == 90);
    // Aspect ratio 10/3 is in "3 - 4"; two angles each of 18.4, 71.6 and 90 degrees.
    const auto ratios = histogram(lines, "aspect ratio histogram", 8);
    CHECK(ratios == std::vector<std::uint64_t>{0, 0, 0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
    const auto angles = histogram(lines, "Angle histogram", 9);
    CHECK(angles ==
          std::vector<std::uint64_t>{0, 2, 0, 0, 0, 0, 0, 2, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0});
}

namespace {

// A 45 x 40 grid of jittered squares, each cut in two: 3600 triangles
// (their coordinates and corners also left in xy and corners).
MeshArrays jittered_grid(std::vector<double>& xy, std::vector<std::uint32_t>& corners) {
    const int nx = 45, ny = 40;
    std::mt19937_64 random(99);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            xy.push_back(i + jitter(random));
            xy.push_back(j + jitter(random));
        }
    const auto id = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            corners.insert(corners.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            corners.insert(corners.end(), {id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return arrays(xy, corners);
}

}  // namespace

TEST_CASE("quality statistics of thousands of triangles match a triangle-by-triangle count",
          "[api][statistics]") {
    std::vector<double> xy;
    std::vector<std::uint32_t> corners;
    const MeshArrays m = jittered_grid(xy, corners);
    // Runs of 1000 triangles: more than one, the last partial.
    const auto lines = gpdr::api::quality_statistics(m, 1, 1000);

    double min_angle = 180, max_angle = 0;
    std::vector<std::uint64_t> angles(18);
    for (std::size_t t = 0; t < corners.size() / 3; ++t) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = corners[3 * t + k], b = corners[3 * t + (k + 1) % 3],
                                c = corners[3 * t + (k + 2) % 3];
            const double ux = xy[2 * b] - xy[2 * a], uy = xy[2 * b + 1] - xy[2 * a + 1];
            const double vx = xy[2 * c] - xy[2 * a], vy = xy[2 * c + 1] - xy[2 * a + 1];
            const double degrees =
                std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / std::numbers::pi;
            min_angle = std::min(min_angle, degrees);
            max_angle = std::max(max_angle, degrees);
            ++angles[std::min<std::size_t>(17, static_cast<std::size_t>(degrees / 10))];
        }
    }
    const auto extremes = numbers_after(lines, "Smallest angle:");
    REQUIRE(extremes.size() == 2);
    CHECK(extremes[0] == Approx(min_angle).epsilon(1e-4));
    CHECK(extremes[1] == Approx(max_angle).epsilon(1e-4));
    CHECK(histogram(lines, "Angle histogram", 9) == angles);
    const auto ratios = histogram(lines, "aspect ratio histogram", 8);
    std::uint64_t total = 0;
    for (auto r : ratios) total += r;
    CHECK(total == corners.size() / 3);
}

TEST_CASE("quality statistics are the same on any number of threads", "[api][statistics]") {
    std::vector<double> xy;
    std::vector<std::uint32_t> corners;
    const MeshArrays m = jittered_grid(xy, corners);
    const auto one = gpdr::api::quality_statistics(m);
    REQUIRE(one.size() > 20);
    // Runs of 7 to 1000 triangles (the last partial) shared among two to eight threads.
    for (const unsigned threads : {2u, 3u, 8u})
        for (const std::size_t chunk : {std::size_t{7}, std::size_t{100}, std::size_t{1000}}) {
            INFO(threads << " threads, runs of " << chunk);
            CHECK(gpdr::api::quality_statistics(m, threads, chunk) == one);
        }
}
