// The "Mesh quality statistics" block that -V prints, in Triangle's layout:
// extreme areas, edge lengths, altitudes and aspect ratios, and histograms of
// aspect ratio (longest edge over shortest altitude) and of all angles;
// taken over runs of triangles, on several threads when asked.

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "api/mesh_arrays.hpp"

namespace gpdr::api {

namespace {

constexpr std::array<double, 16> ratio_bounds{
    1.5, 2,  2.5, 3,   4,    6,     10,     15,
    25,  50, 100, 300, 1000, 10000, 100000, std::numeric_limits<double>::infinity()};

// An angle in degrees from its cosine, as the statistics report it.
double degrees_of(double cosine) { return std::acos(cosine) * 180 / std::numbers::pi; }

// The angle histogram's bin of a cosine: the bin of its angle,
// min(17, floor(degrees / 10)), found without an arc cosine (three per
// triangle were most of the block's time).  The bin only falls as the
// cosine grows, so it is the number of thresholds at or above the cosine,
// threshold k being the largest cosine whose angle is in bin k or above,
// found once by bisection over the doubles of [-1, 1] with the very
// function that defines the bins: every cosine gets the bin its angle did.
class AngleBins {
public:
    AngleBins() {
        for (std::size_t k = 1; k < 18; ++k) {
            // Bisection over the ordered bit patterns of [-1, 1] (a double's
            // order is its bit pattern's, sign apart).
            double lo = -1, hi = 1;  // bin(lo) >= k, bin(hi) < k
            while (std::nextafter(lo, hi) != hi) {
                const double mid = middle(lo, hi);
                if (bin_by_angle(mid) >= k)
                    lo = mid;
                else
                    hi = mid;
            }
            threshold_[k - 1] = lo;
        }
    }
    // The thresholds fall, so the cosine is at or below a prefix of them:
    // counting them all gives that prefix's length without a branch per
    // threshold (a loop that stopped at the first one above the cosine
    // mispredicted about once an angle).
    std::size_t bin(double cosine) const {
        std::size_t b = 0;
        for (const double t : threshold_) b += cosine <= t ? 1 : 0;
        return b;
    }

private:
    static std::size_t bin_by_angle(double cosine) {
        return std::min<std::size_t>(17, static_cast<std::size_t>(degrees_of(cosine) / 10));
    }
    // A double between lo < hi, halving the count of doubles between them.
    static double middle(double lo, double hi) {
        const auto ordered = [](double x) {
            const auto bits = std::bit_cast<std::int64_t>(x);
            return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
        };
        const auto unordered = [](std::int64_t o) {
            return std::bit_cast<double>(o < 0 ? std::numeric_limits<std::int64_t>::min() - o : o);
        };
        const std::int64_t a = ordered(lo), b = ordered(hi);
        return unordered(a + (b - a) / 2);
    }
    std::array<double, 17> threshold_{};  // falling: threshold_[k - 1] for bin k
};

const AngleBins& angle_bins() {
    static const AngleBins bins;
    return bins;
}

// The figures of a set of triangles; two tallies merge into the tally of
// both sets (extremes and counts only: the result does not depend on how
// the triangles were shared out, or in what order).  Angles are kept as
// their cosines: the smallest angle has the largest.
struct Tally {
    double min_area = std::numeric_limits<double>::infinity(), max_area = 0;
    double min_edge2 = std::numeric_limits<double>::infinity(), max_edge2 = 0;
    double min_altitude = std::numeric_limits<double>::infinity(), max_ratio = 0;
    double max_cosine = -1, min_cosine = 1;
    std::array<std::uint64_t, 16> ratio_histogram{};
    std::array<std::uint64_t, 18> angle_histogram{};

    void add(const std::array<double, 3>& px, const std::array<double, 3>& py) {
        std::array<double, 3> edge2;  // edge2[k]: squared length of the edge opposite corner k
        for (std::size_t k = 0; k < 3; ++k) {
            const double dx = px[(k + 2) % 3] - px[(k + 1) % 3],
                         dy = py[(k + 2) % 3] - py[(k + 1) % 3];
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
        // The bounds rise: the ratio's bin is the number of bounds below it
        // (the last bin takes everything above), counted without branches.
        std::size_t bin = 0;
        for (std::size_t i = 0; i + 1 < ratio_bounds.size(); ++i)
            bin += ratio > ratio_bounds[i] ? 1 : 0;
        ++ratio_histogram[bin];
        const AngleBins& bins = angle_bins();
        for (std::size_t k = 0; k < 3; ++k) {
            // The angle at corner k lies between the edges opposite k+1 and k+2.
            const double a2 = edge2[(k + 1) % 3], b2 = edge2[(k + 2) % 3], c2 = edge2[k];
            const double cosine = std::clamp((a2 + b2 - c2) / (2 * std::sqrt(a2 * b2)), -1.0, 1.0);
            max_cosine = std::max(max_cosine, cosine);
            min_cosine = std::min(min_cosine, cosine);
            ++angle_histogram[bins.bin(cosine)];
        }
    }

    void merge(const Tally& o) {
        min_area = std::min(min_area, o.min_area);
        max_area = std::max(max_area, o.max_area);
        min_edge2 = std::min(min_edge2, o.min_edge2);
        max_edge2 = std::max(max_edge2, o.max_edge2);
        min_altitude = std::min(min_altitude, o.min_altitude);
        max_ratio = std::max(max_ratio, o.max_ratio);
        max_cosine = std::max(max_cosine, o.max_cosine);
        min_cosine = std::min(min_cosine, o.min_cosine);
        for (std::size_t i = 0; i < ratio_histogram.size(); ++i)
            ratio_histogram[i] += o.ratio_histogram[i];
        for (std::size_t i = 0; i < angle_histogram.size(); ++i)
            angle_histogram[i] += o.angle_histogram[i];
    }
};

// A run of triangles read from the source: three corners each.
struct Chunk {
    std::vector<std::uint32_t> corners;
    std::size_t count = 0;
};

// Reads up to `capacity` triangles into `chunk`; false when none was left.
bool fill(io::EleSource& source, std::size_t& left, std::size_t capacity, Chunk& chunk) {
    if (left == 0) return false;
    std::uint32_t corners[6];
    std::vector<double> attributes(source.attribute_count);  // (read past)
    chunk.count = std::min(capacity, left);
    chunk.corners.resize(3 * capacity);
    for (std::size_t i = 0; i < chunk.count; ++i) {
        source.next(corners, attributes.data());
        std::copy_n(corners, 3, &chunk.corners[3 * i]);
    }
    left -= chunk.count;
    return true;
}

// The triangles come in mesh order and their corners lie anywhere in the
// node array (hundreds of megabytes for a large mesh): each triangle's
// coordinates are asked for a few triangles ahead, so that the cache misses
// overlap instead of stalling each triangle in turn.
void tally(const Chunk& chunk, const std::vector<double>& xy, Tally& into) {
    constexpr std::size_t ahead = 16;
    const auto ask = [&](std::size_t i) {
        for (std::size_t k = 0; k < 3; ++k)
            __builtin_prefetch(&xy[2 * std::size_t{chunk.corners[3 * i + k]}]);
    };
    for (std::size_t i = 0; i < chunk.count && i < ahead; ++i) ask(i);
    for (std::size_t i = 0; i < chunk.count; ++i) {
        if (i + ahead < chunk.count) ask(i + ahead);
        std::array<double, 3> px, py;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t v = chunk.corners[3 * i + k];
            px[k] = xy[2 * v];
            py[k] = xy[2 * v + 1];
        }
        into.add(px, py);
    }
}

// With several threads: each thread claims runs of triangles in turn,
// reads them from the source itself (read() serves any run, from any
// thread) and tallies them: on one thread the reading alone held back the
// others.
Tally tally_in_parallel(const io::EleSource& source, const std::vector<double>& xy,
                        unsigned threads, std::size_t chunk_size) {
    const std::uint32_t nc = source.corners_per_triangle;
    std::atomic<std::size_t> next{0};
    std::vector<Tally> tallies(threads);
    const auto work = [&](Tally& into) {
        Chunk chunk;
        std::vector<std::uint32_t> corners(nc * chunk_size);
        std::vector<double> attributes(source.attribute_count * chunk_size);  // (read past)
        chunk.corners.resize(3 * chunk_size);
        for (std::size_t first; (first = next.fetch_add(chunk_size)) < source.count;) {
            chunk.count = std::min(chunk_size, source.count - first);
            source.read(first, chunk.count, corners.data(), attributes.data());
            for (std::size_t i = 0; i < chunk.count; ++i)
                std::copy_n(&corners[nc * i], 3, &chunk.corners[3 * i]);
            tally(chunk, xy, into);
        }
    };
    {
        std::vector<std::jthread> helpers;
        for (unsigned h = 1; h < threads; ++h) helpers.emplace_back(work, std::ref(tallies[h]));
        work(tallies[0]);
    }
    for (unsigned h = 1; h < threads; ++h) tallies[0].merge(tallies[h]);
    return tallies[0];
}

}  // namespace

std::vector<std::string> quality_statistics(const MeshArrays& mesh, unsigned threads,
                                            std::size_t chunk_size) {
    constexpr std::array<const char*, 16> ratio_labels{
        "1.1547 - 1.5      ", "   1.5 - 2        ", "     2 - 2.5      ", "   2.5 - 3        ",
        "     3 - 4        ", "     4 - 6        ", "     6 - 10       ", "    10 - 15       ",
        "    15 - 25       ", "    25 - 50       ", "    50 - 100      ", "   100 - 300      ",
        "   300 - 1000     ", "  1000 - 10000    ", " 10000 - 100000   ", "100000 -          "};
    io::EleSource triangles = triangle_source(mesh);
    const auto& xy = mesh.nodes.xy;
    Tally t;
    if (triangles.read) {
        t = tally_in_parallel(triangles, xy, threads, chunk_size);
    } else {
        Chunk chunk;
        std::size_t left = triangles.count;
        while (fill(triangles, left, chunk_size, chunk)) tally(chunk, xy, t);
    }
    const auto& [min_area, max_area, min_edge2, max_edge2, min_altitude, max_ratio, max_cosine,
                 min_cosine, ratio_histogram, angle_histogram] = t;
    const double min_angle = degrees_of(max_cosine), max_angle = degrees_of(min_cosine);
    if (triangles.count == 0) return {};

    std::vector<std::string> lines;
    lines.push_back("Mesh quality statistics:");
    lines.emplace_back();
    lines.push_back(
        fmt::format("  Smallest area: {:16.5g}   |  Largest area: {:16.5g}", min_area, max_area));
    lines.push_back(fmt::format("  Shortest edge: {:16.5g}   |  Longest edge: {:16.5g}",
                                std::sqrt(min_edge2), std::sqrt(max_edge2)));
    lines.push_back(fmt::format("  Shortest altitude: {:12.5g}   |  Largest aspect ratio: {:8.5g}",
                                min_altitude, max_ratio));
    lines.emplace_back();
    lines.push_back("  Triangle aspect ratio histogram:");
    for (std::size_t i = 0; i < 8; ++i) {
        lines.push_back(fmt::format("  {}:  {:8}    | {}:  {:8}", ratio_labels[i],
                                    ratio_histogram[i], ratio_labels[i + 8],
                                    ratio_histogram[i + 8]));
    }
    lines.push_back("  (Aspect ratio is longest edge divided by shortest altitude)");
    lines.emplace_back();
    lines.push_back(fmt::format("  Smallest angle: {:15.5g}   |  Largest angle: {:15.5g}",
                                min_angle, max_angle));
    lines.emplace_back();
    lines.push_back("  Angle histogram:");
    for (std::size_t i = 0; i < 9; ++i) {
        lines.push_back(fmt::format(
            "    {:3} - {:3} degrees:  {:8}    |    {:3} - {:3} degrees:  {:8}", 10 * i,
            10 * i + 10, angle_histogram[i], 10 * i + 90, 10 * i + 100, angle_histogram[i + 9]));
    }
    return lines;
}

}  // namespace gpdr::api
