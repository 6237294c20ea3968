// BRIO rounds with Hilbert order inside each (see spatial_sort.hpp).  Sorting
// is by least-significant-digit radix sort on the 32-bit curve position
// (four 8-bit passes) for large rounds, std::sort for small ones.

#include "triangulate/spatial_sort.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <limits>
#include <utility>

#include "mesh/slices.hpp"
#include "mesh/sort_by_key.hpp"

namespace gpdr::triangulate {

namespace {

std::uint64_t mix(std::uint64_t z) {
    // splitmix64's finaliser: a cheap, well-spread hash of the index.
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// Sorts keys (curve position << 32 | index) by their upper 32 bits.
void sort_by_curve(std::uint64_t* begin, std::uint64_t* end, std::vector<std::uint64_t>& scratch) {
    const std::size_t n = static_cast<std::size_t>(end - begin);
    if (n < 4096) {
        std::sort(begin, end);
        return;
    }
    scratch.resize(n);
    // Four 8-bit passes: 256 output streams stay in cache while scattering.
    std::vector<std::uint32_t> count(256);
    std::uint64_t* from = begin;
    std::uint64_t* to = scratch.data();
    for (int shift : {32, 40, 48, 56}) {
        std::fill(count.begin(), count.end(), 0u);
        for (std::size_t i = 0; i < n; ++i) ++count[(from[i] >> shift) & 0xFFu];
        std::uint32_t sum = 0;
        for (auto& c : count) {
            const std::uint32_t here = c;
            c = sum;
            sum += here;
        }
        for (std::size_t i = 0; i < n; ++i) to[count[(from[i] >> shift) & 0xFFu]++] = from[i];
        std::swap(from, to);
    }
    // An even number of passes: the result is back in `begin`.
}

}  // namespace

namespace {

// The curve's recursion carries two bits from level to level, whether the
// remaining coordinates are complemented and whether they are swapped (the
// textbook loop's rotations: complement both when (rx, ry) = (1, 0), swap
// them when ry = 0; both maps commute).  A step of the table reads four
// levels at once: for each such state and four bits of x and of y, the
// eight bits of the position they add and the state after them.
struct HilbertStep {
    std::uint8_t digits;
    std::uint8_t state;  // bit 0: complemented, bit 1: swapped
};

constexpr std::array<std::array<HilbertStep, 256>, 4> hilbert_steps = [] {
    std::array<std::array<HilbertStep, 256>, 4> table{};
    for (std::uint32_t state = 0; state < 4; ++state)
        for (std::uint32_t xy = 0; xy < 256; ++xy) {
            std::uint32_t complemented = state & 1u, swapped = state >> 1;
            std::uint32_t digits = 0;
            for (int level = 3; level >= 0; --level) {
                const std::uint32_t bx = (xy >> (4 + level)) & 1u, by = (xy >> level) & 1u;
                const std::uint32_t exchange = (bx ^ by) & swapped;
                const std::uint32_t rx = bx ^ exchange ^ complemented;
                const std::uint32_t ry = by ^ exchange ^ complemented;
                digits = (digits << 2) | ((3u * rx) ^ ry);
                const std::uint32_t turn = ry ^ 1u;
                complemented ^= turn & rx;
                swapped ^= turn;
            }
            table[state][xy] = {static_cast<std::uint8_t>(digits),
                                static_cast<std::uint8_t>(complemented | (swapped << 1))};
        }
    return table;
}();

}  // namespace

std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y) {
    // Four table steps of four levels each, the highest first.
    std::uint32_t d = 0, state = 0;
    for (int shift = 12; shift >= 0; shift -= 4) {
        const HilbertStep step =
            hilbert_steps[state][((x >> shift) & 15u) << 4 | ((y >> shift) & 15u)];
        d = (d << 8) | step.digits;
        state = step.state;
    }
    return d;
}

namespace {

// The points' bounding box, on `threads` threads by pieces.
struct Box {
    double min_x = std::numeric_limits<double>::infinity(), max_x = -min_x;
    double min_y = min_x, max_y = max_x;
    void add(const Box& b) {
        min_x = std::min(min_x, b.min_x), max_x = std::max(max_x, b.max_x);
        min_y = std::min(min_y, b.min_y), max_y = std::max(max_y, b.max_y);
    }
};
Box bounding_box(std::span<const geometry::Point> points, unsigned threads) {
    std::vector<Box> boxes(4 * std::size_t{threads});
    const std::size_t pieces = mesh::run_index_pieces(
        threads, points.size(), [&](std::size_t k, std::size_t first, std::size_t last) {
            for (std::size_t i = first; i < last; ++i)
                boxes[k].add({points[i].x, points[i].x, points[i].y, points[i].y});
        });
    Box box;
    for (std::size_t k = 0; k < pieces; ++k) box.add(boxes[k]);
    return box;
}

// A point's cell of the 2^16 x 2^16 grid over the box, for its curve key.
class Grid {
public:
    explicit Grid(const Box& box)
        : min_x_(box.min_x),
          min_y_(box.min_y),
          // Halved to keep the differences finite for any finite coordinates.
          scale_x_(scale(box.max_x / 2 - box.min_x / 2)),
          scale_y_(scale(box.max_y / 2 - box.min_y / 2)) {}
    std::uint32_t curve_position(const geometry::Point& p) const {
        return hilbert_index(cell(p.x / 2 - min_x_ / 2, scale_x_),
                             cell(p.y / 2 - min_y_ / 2, scale_y_));
    }

private:
    static double scale(double span) { return span > 0 ? 65535.0 / span : 0.0; }
    static std::uint32_t cell(double offset, double scale) {
        const double c = offset * scale;
        return c <= 0 ? 0u : c >= 65535.0 ? 65535u : static_cast<std::uint32_t>(c);
    }
    double min_x_, min_y_, scale_x_, scale_y_;
};

}  // namespace

std::vector<std::uint32_t> brio_order(std::span<const geometry::Point> points, std::uint64_t seed,
                                      unsigned threads) {
    const std::size_t n = points.size();
    std::vector<std::uint32_t> order(n);
    if (n == 0) return order;
    threads = std::max(1u, threads);
    const Grid grid(bounding_box(points, threads));

    // Rounds: the first holds about 64 points (or all when n is small).
    int rounds = 0;
    while ((n >> (rounds + 1)) >= 64 && rounds < 40) ++rounds;
    auto round_of = [&](std::size_t i) {
        const std::uint64_t h = mix(i ^ (seed * 0xD1B54A32D192ED03ull));
        return std::min(std::countr_zero(h | (1ull << 63)), rounds);
    };

    // By round (highest round first), each point keyed by its curve
    // position, then the curve inside each round.  (The same on any number
    // of threads: mesh/sort_by_key.hpp.)
    const auto round_count = static_cast<std::uint32_t>(rounds) + 1;
    std::vector<std::uint64_t> keys(n);
    const std::vector<std::size_t> start = mesh::sort_by_key(
        threads, n, round_count, [&](std::size_t i) { return rounds - round_of(i); },
        [&](std::size_t i, std::size_t at) {
            keys[at] = (std::uint64_t{grid.curve_position(points[i])} << 32) | i;
        });
    // On one thread with one scratch buffer, smallest round first; on
    // several, the largest (the last, half the points) first, so that the
    // others share out beside it.
    if (threads == 1) {
        std::vector<std::uint64_t> scratch;
        for (std::uint32_t r = 0; r < round_count; ++r)
            sort_by_curve(keys.data() + start[r], keys.data() + start[r + 1], scratch);
    } else {
        mesh::run_pieces(threads, round_count, [&](std::size_t j) {
            const std::size_t r = round_count - 1 - j;
            std::vector<std::uint64_t> scratch;
            sort_by_curve(keys.data() + start[r], keys.data() + start[r + 1], scratch);
        });
    }
    mesh::run_index_pieces(threads, n, [&](std::size_t, std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) order[i] = static_cast<std::uint32_t>(keys[i]);
    });
    return order;
}

}  // namespace gpdr::triangulate
