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

std::vector<std::uint32_t> brio_order(std::span<const geometry::Point> points, std::uint64_t seed,
                                      unsigned threads) {
    const std::size_t n = points.size();
    std::vector<std::uint32_t> order(n);
    if (n == 0) return order;

    // On several threads the points are cut into pieces, each of which does
    // in index order what one pass over all of them would do; the pieces'
    // results are joined in piece order, so the order made does not depend
    // on the threads.
    const std::size_t pieces =
        threads <= 1 ? 1 : std::min<std::size_t>(4 * threads, (n + 65535) / 65536);
    const auto piece_range = [&](std::size_t k) {
        return std::pair{k * n / pieces, (k + 1) * n / pieces};
    };

    struct Box {
        double min_x = std::numeric_limits<double>::infinity(), max_x = -min_x;
        double min_y = min_x, max_y = max_x;
    };
    std::vector<Box> boxes(pieces);
    mesh::run_pieces(threads, pieces, [&](std::size_t k) {
        Box& b = boxes[k];
        const auto [first, last] = piece_range(k);
        for (std::size_t i = first; i < last; ++i) {
            const auto& p = points[i];
            b.min_x = std::min(b.min_x, p.x), b.max_x = std::max(b.max_x, p.x);
            b.min_y = std::min(b.min_y, p.y), b.max_y = std::max(b.max_y, p.y);
        }
    });
    Box box;
    for (const Box& b : boxes) {
        box.min_x = std::min(box.min_x, b.min_x), box.max_x = std::max(box.max_x, b.max_x);
        box.min_y = std::min(box.min_y, b.min_y), box.max_y = std::max(box.max_y, b.max_y);
    }
    const double min_x = box.min_x, max_x = box.max_x, min_y = box.min_y, max_y = box.max_y;
    // Halved to keep the differences finite for any finite coordinates.
    const double span_x = max_x / 2 - min_x / 2, span_y = max_y / 2 - min_y / 2;
    const double scale_x = span_x > 0 ? 65535.0 / span_x : 0.0;
    const double scale_y = span_y > 0 ? 65535.0 / span_y : 0.0;
    auto cell = [](double offset, double scale) {
        const double c = offset * scale;
        return c <= 0 ? 0u : c >= 65535.0 ? 65535u : static_cast<std::uint32_t>(c);
    };

    // Rounds: the first holds about 64 points (or all when n is small).
    int rounds = 0;
    while ((n >> (rounds + 1)) >= 64 && rounds < 40) ++rounds;
    auto round_of = [&](std::size_t i) {
        const std::uint64_t h = mix(i ^ (seed * 0xD1B54A32D192ED03ull));
        return std::min(std::countr_zero(h | (1ull << 63)), rounds);
    };

    // Counting sort by round (highest round first), then the curve inside.
    // Each piece counts its points per round; a piece's points of round r go
    // after those of the pieces before it.
    const std::size_t round_count = static_cast<std::size_t>(rounds) + 1;
    std::vector<std::uint8_t> round(n);
    std::vector<std::vector<std::size_t>> next(pieces, std::vector<std::size_t>(round_count, 0));
    mesh::run_pieces(threads, pieces, [&](std::size_t k) {
        const auto [first, last] = piece_range(k);
        for (std::size_t i = first; i < last; ++i) {
            round[i] = static_cast<std::uint8_t>(rounds - round_of(i));
            ++next[k][round[i]];
        }
    });
    std::vector<std::size_t> start(round_count + 1, 0);
    for (std::size_t r = 0; r < round_count; ++r) {
        std::size_t at = start[r];
        for (std::size_t k = 0; k < pieces; ++k) {
            const std::size_t count = next[k][r];
            next[k][r] = at;
            at += count;
        }
        start[r + 1] = at;
    }
    std::vector<std::uint64_t> keys(n);
    mesh::run_pieces(threads, pieces, [&](std::size_t k) {
        const auto [first, last] = piece_range(k);
        std::vector<std::size_t>& at = next[k];
        for (std::size_t i = first; i < last; ++i) {
            const auto& p = points[i];
            const std::uint64_t h = hilbert_index(cell(p.x / 2 - min_x / 2, scale_x),
                                                  cell(p.y / 2 - min_y / 2, scale_y));
            keys[at[round[i]]++] = (h << 32) | static_cast<std::uint64_t>(i);
        }
    });
    // The rounds are sorted apart: on one thread with one scratch buffer,
    // smallest first; on several, the largest (the last, half the points)
    // first, so that the others share out beside it.
    if (threads <= 1) {
        std::vector<std::uint64_t> scratch;
        for (std::size_t r = 0; r < round_count; ++r)
            sort_by_curve(keys.data() + start[r], keys.data() + start[r + 1], scratch);
    } else {
        mesh::run_pieces(threads, round_count, [&](std::size_t j) {
            const std::size_t r = round_count - 1 - j;
            std::vector<std::uint64_t> scratch;
            sort_by_curve(keys.data() + start[r], keys.data() + start[r + 1], scratch);
        });
    }
    mesh::run_pieces(threads, pieces, [&](std::size_t k) {
        const auto [first, last] = piece_range(k);
        for (std::size_t i = first; i < last; ++i) order[i] = static_cast<std::uint32_t>(keys[i]);
    });
    return order;
}

}  // namespace gpdr::triangulate
