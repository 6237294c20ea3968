// The remembering stochastic walk (see locate.hpp).

#include "mesh/locate.hpp"

#include <array>

#include "geometry/predicates.hpp"

namespace gpdr::mesh {

namespace {

// first_edge[s][m]: the first edge of the set m (bit k: edge k) in the
// rotation s, s+1, s+2 (mod 3); -1 for the empty set.  The walk computes
// the three orientations at once and picks its edge here: a branch per
// edge on the sign of an orientation is a coin toss for the predictor.
using EdgeTable = std::array<std::array<std::int8_t, 8>, 3>;
constexpr EdgeTable first_edge = [] {
    EdgeTable table{};
    for (int s = 0; s < 3; ++s)
        for (unsigned m = 0; m < 8; ++m) {
            table[s][m] = -1;
            for (int i = 2; i >= 0; --i) {
                const int k = (s + i) % 3;
                if ((m >> k) & 1u) table[s][m] = static_cast<std::int8_t>(k);
            }
        }
    return table;
}();

}  // namespace

LocateResult locate(const Mesh& mesh, const Point& p, TriangleId hint,
                    std::uint32_t& random_state) {
    TriangleId t = hint;
    if (const Triangle& h = mesh.triangle(t); h.is_ghost()) {
        // Start on the real triangle beside the ghost (p may be on either
        // side of the edge they share).
        t = h.n[h.corner_of(ghost_vertex)].triangle();
    }
    unsigned skip = 0;  // bit of the edge of t we came through (p is known to be on its inner side)
    // A loop guard far beyond any real walk; past it, forget the edge we
    // came through.
    std::uint64_t steps_left = 4ull * mesh.triangle_end() + 64;
    bool remember = true;
    for (;;) {
        const Triangle& r = mesh.triangle(t);
        // Only reached across a hull edge with p strictly beyond it.
        if (r.is_ghost()) return {t, Location::outside, r.corner_of(ghost_vertex)};
        // The walk goes on into one of the neighbours, and a caller that
        // inserts p searches them for its cavity: on a mesh far larger than
        // the cache, start fetching them while the orientations are
        // computed.
        for (const EdgeRef e : r.n)
            if (!e.is_none()) __builtin_prefetch(&mesh.triangle(e.triangle()));
        const Point& c0 = mesh.point(r.v[0]);
        const Point& c1 = mesh.point(r.v[1]);
        const Point& c2 = mesh.point(r.v[2]);
        // Edge k runs from corner k+1 to corner k+2.
        const double o0 = geometry::orient2d(c1, c2, p);
        const double o1 = geometry::orient2d(c2, c0, p);
        const double o2 = geometry::orient2d(c0, c1, p);
        const unsigned beyond =
            ((o0 < 0 ? 1u : 0u) | (o1 < 0 ? 2u : 0u) | (o2 < 0 ? 4u : 0u)) & ~skip;
        // The edges are tried in a random rotation.
        random_state = random_state * 1664525u + 1013904223u;
        const unsigned start = (random_state >> 16) % 3u;
        if (beyond != 0) {
            const int k = first_edge[start][beyond];
            const EdgeRef across = r.n[k];
            if (across.is_none()) return {t, Location::outside, k};
            t = across.triangle();
            skip = remember ? 1u << across.edge() : 0u;
            if (remember && --steps_left == 0) remember = false;
            continue;
        }
        // p is on the inner side of (or on) every edge; the edge we came
        // through counts as not containing p.
        const bool z0 = o0 == 0 && (skip & 1u) == 0;
        const bool z1 = o1 == 0 && (skip & 2u) == 0;
        const bool z2 = o2 == 0 && (skip & 4u) == 0;
        const int zeros = z0 + z1 + z2;
        if (zeros == 0) return {t, Location::inside, 0};
        if (zeros == 1) return {t, Location::on_edge, z0 ? 0 : z1 ? 1 : 2};
        // Two edges through p: p is the corner they share, the one whose
        // opposite edge does not contain it.
        return {t, Location::on_vertex, !z0 ? 0 : !z1 ? 1 : 2};
    }
}

}  // namespace gpdr::mesh
