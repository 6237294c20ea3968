// The CDT of an input in general position is unique, so it can be compared
// with an independent construction: Delaunay, then Sloan's flips until every
// segment is an edge, then Lawson's flips on non-segment edges until all are
// locally Delaunay (a slow O(n^3) path that shares no code with the segment
// insertion).  Also checked: every segment an edge, and the Euler count
// 2n - 2 - h triangles.

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>

#include "geometry/predicates.hpp"
#include "mesh/flip.hpp"
#include "mesh/test_support.hpp"
#include "triangulate/cdt_support.hpp"
#include "triangulate/delaunay.hpp"

using namespace gpdr;
using namespace gpdr::triangulate;
using namespace gpdr::triangulate::testing;
using gpdr::geometry::orient2d;
using gpdr::mesh::EdgeRef;
using gpdr::mesh::Mesh;

namespace {

bool properly_cross(const Point& a, const Point& b, const Point& c, const Point& d) {
    const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
    const double o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
    return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

// Random points and random segments between them, keeping only segments
// that cross no earlier one (random doubles: general position).
Pslg general_position(std::mt19937_64& rng, std::size_t n, std::size_t tries) {
    Pslg p;
    p.points = gpdr::mesh::testing::uniform_points(n, static_cast<std::uint32_t>(rng()));
    std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(n - 1));
    std::set<std::pair<std::uint32_t, std::uint32_t>> used;
    for (std::size_t k = 0; k < tries; ++k) {
        std::uint32_t a = pick(rng), b = pick(rng);
        if (a == b || used.count({std::min(a, b), std::max(a, b)})) continue;
        bool ok = true;
        for (std::size_t s = 0; s < p.segment_count() && ok; ++s) {
            const std::uint32_t c = p.segments[2 * s], d = p.segments[2 * s + 1];
            if (properly_cross(p.points[a], p.points[b], p.points[c], p.points[d])) ok = false;
        }
        for (std::uint32_t v = 0; v < n && ok;
             ++v)  // no vertex on the segment (measure zero, but check)
            if (v != a && v != b && orient2d(p.points[a], p.points[b], p.points[v]) == 0)
                ok = false;
        if (!ok) continue;
        used.insert({std::min(a, b), std::max(a, b)});
        p.segments.insert(p.segments.end(), {a, b});
    }
    return p;
}

// The slow, independent CDT.
Mesh flip_cdt(const Pslg& pslg) {
    DelaunayReport dr;
    Mesh m = delaunay(pslg.points, dr);
    std::set<std::pair<std::uint32_t, std::uint32_t>> constrained;
    for (std::size_t s = 0; s < pslg.segment_count(); ++s) {
        const std::uint32_t a = pslg.segments[2 * s], b = pslg.segments[2 * s + 1];
        constrained.insert({std::min(a, b), std::max(a, b)});
        // Sloan: flip crossing edges of convex quadrilaterals, preferring
        // flips whose new diagonal no longer crosses (else a flip could be
        // undone by the next one).
        for (int guard = 0; guard < 100000; ++guard) {
            bool crossing = false;
            EdgeRef any = EdgeRef::none(), good = EdgeRef::none();
            gpdr::mesh::for_each_edge(m, [&](const gpdr::mesh::EdgeView& e) {
                if (!properly_cross(m.point(e.from), m.point(e.to), pslg.points[a], pslg.points[b]))
                    return;
                crossing = true;
                if (!gpdr::mesh::flippable(m, e.edge)) return;
                if (any.is_none()) any = e.edge;
                const auto& c = m.point(m.apex(e.edge));
                const auto& d = m.point(m.apex(m.neighbour(e.edge)));
                if (good.is_none() && !properly_cross(c, d, pslg.points[a], pslg.points[b]))
                    good = e.edge;
            });
            if (!crossing) break;
            REQUIRE(!any.is_none());
            gpdr::mesh::flip(m, good.is_none() ? any : good);
        }
    }
    for (bool changed = true; changed;) {
        changed = false;
        gpdr::mesh::for_each_edge(m, [&](const gpdr::mesh::EdgeView& e) {
            if (changed || e.hull) return;
            const std::uint32_t u = index(e.from), v = index(e.to);
            if (constrained.count({std::min(u, v), std::max(u, v)})) return;
            const auto& t = m.triangle(e.edge.triangle());
            const EdgeRef across = m.neighbour(e.edge);
            const auto& q = m.point(m.apex(across));
            if (geometry::incircle(m.point(t.v[0]), m.point(t.v[1]), m.point(t.v[2]), q) > 0 &&
                gpdr::mesh::flippable(m, e.edge)) {
                gpdr::mesh::flip(m, e.edge);
                changed = true;
            }
        });
    }
    return m;
}

}  // namespace

TEST_CASE("the CDT equals an independent flip-based construction", "[triangulate][cdt][oracle]") {
    std::mt19937_64 rng(2024);
    for (int round = 0; round < 120; ++round) {
        const std::size_t n = 6 + rng() % 25;
        const Pslg pslg = general_position(rng, n, 4 + rng() % 20);
        CdtReport report;
        const Mesh m = triangulate_segments(pslg, report);
        INFO("round " << round << ", " << n << " points, " << pslg.segment_count() << " segments");
        require_valid(m, pslg, report);
        CHECK(report.new_vertices.empty());
        CHECK(m.subsegments().size() == pslg.segment_count());
        for (std::size_t s = 0; s < pslg.segment_count(); ++s)
            CHECK(has_subsegment(m, pslg.segments[2 * s], pslg.segments[2 * s + 1]));
        const std::size_t hull = gpdr::mesh::count_hull_edges(m);
        CHECK(m.count_triangles() == 2 * n - 2 - hull);
        const Mesh oracle = flip_cdt(pslg);
        for (std::size_t s = 0; s < pslg.segment_count(); ++s)
            CHECK(has_edge(oracle, pslg.segments[2 * s], pslg.segments[2 * s + 1]));
        CHECK(gpdr::mesh::testing::canonical(m) == gpdr::mesh::testing::canonical(oracle));
    }
}
