// The remembering stochastic walk (see locate.hpp).

#include "mesh/locate.hpp"

#include "geometry/predicates.hpp"

namespace gpdr::mesh {

LocateResult locate(const Mesh& mesh, const Point& p, TriangleId hint,
                    std::uint32_t& random_state) {
    TriangleId t = hint;
    if (const Triangle& h = mesh.triangle(t); h.is_ghost()) {
        // Start on the real triangle beside the ghost (p may be on either
        // side of the edge they share).
        t = h.n[h.corner_of(ghost_vertex)].triangle();
    }
    int from = -1;  // edge of t we came through (p is known to be on its inner side)
    // A loop guard far beyond any real walk; past it, forget `from`.
    std::uint64_t steps_left = 4ull * mesh.triangle_end() + 64;
    bool remember = true;
    for (;;) {
        const Triangle& r = mesh.triangle(t);
        // Only reached across a hull edge with p strictly beyond it.
        if (r.is_ghost()) return {t, Location::outside, r.corner_of(ghost_vertex)};
        const Point* corner[3] = {&mesh.point(r.v[0]), &mesh.point(r.v[1]), &mesh.point(r.v[2])};
        random_state = random_state * 1664525u + 1013904223u;
        const int start = static_cast<int>((random_state >> 16) % 3u);
        double o[3];
        bool moved = false;
        for (int i = 0; i < 3; ++i) {
            const int k = (start + i) % 3;
            if (k == from) {
                o[k] = 1;
                continue;
            }
            o[k] = geometry::orient2d(*corner[next3(k)], *corner[prev3(k)], p);
            if (o[k] < 0) {
                const EdgeRef across = r.n[k];
                if (across.is_none()) return {t, Location::outside, k};
                t = across.triangle();
                from = remember ? across.edge() : -1;
                moved = true;
                break;
            }
        }
        if (!moved) {
            const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
            if (zeros == 0) return {t, Location::inside, 0};
            if (zeros == 1) return {t, Location::on_edge, o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2};
            // Two edges through p: p is the corner they share, the one whose
            // opposite edge does not contain it.
            return {t, Location::on_vertex, o[0] != 0 ? 0 : o[1] != 0 ? 1 : 2};
        }
        if (remember && --steps_left == 0) remember = false;
    }
}

}  // namespace gpdr::mesh
