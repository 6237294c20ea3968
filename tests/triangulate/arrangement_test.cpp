// Tests of the arrangement of segments (lib/triangulate/arrangement.cpp):
// the pieces it returns meet only at their ends (checked with exact
// predicates against every pair), every input segment is covered by its
// pieces, and the reproducers of crossing, overlap and vertex-on-segment
// cases come out as described in arrangement.hpp.

#include <catch2/catch.hpp>
#include <numeric>
#include <random>

#include "geometry/predicates.hpp"
#include "triangulate/arrangement.hpp"

namespace {

using gpdr::geometry::orient2d;
using gpdr::geometry::Point;
using gpdr::triangulate::arrange_segments;
using gpdr::triangulate::ArrangementReport;
using gpdr::triangulate::SegmentPiece;

struct Arranged {
    std::vector<Point> points;
    std::vector<SegmentPiece> pieces;
    ArrangementReport report;
};

Arranged arrange(std::vector<Point> points, const std::vector<std::pair<int, int>>& segments) {
    Arranged r;
    r.points = std::move(points);
    std::vector<std::uint32_t> vertices(r.points.size());
    std::iota(vertices.begin(), vertices.end(), 0u);
    std::vector<SegmentPiece> pieces;
    for (std::size_t s = 0; s < segments.size(); ++s)
        pieces.push_back({static_cast<std::uint32_t>(segments[s].first),
                          static_cast<std::uint32_t>(segments[s].second),
                          static_cast<std::uint32_t>(s), static_cast<int>(s + 1)});
    r.pieces = arrange_segments(r.points, vertices, pieces, r.report);
    return r;
}

int sign(double v) { return (v > 0) - (v < 0); }

// No two pieces cross or overlap, no vertex lies in a piece's interior
// (exactly), all pieces have distinct ends.
void require_clean(const Arranged& r) {
    const auto& p = r.points;
    for (std::size_t i = 0; i < r.pieces.size(); ++i) {
        const Point &a = p[r.pieces[i].a], &b = p[r.pieces[i].b];
        REQUIRE(r.pieces[i].a != r.pieces[i].b);
        for (std::size_t v = 0; v < p.size(); ++v) {
            if (v == r.pieces[i].a || v == r.pieces[i].b || p[v] == a || p[v] == b) continue;
            if (orient2d(a, b, p[v]) != 0) continue;
            const bool between = a.x != b.x
                                     ? (std::min(a.x, b.x) < p[v].x && p[v].x < std::max(a.x, b.x))
                                     : (std::min(a.y, b.y) < p[v].y && p[v].y < std::max(a.y, b.y));
            INFO("vertex " << v << " on piece " << i);
            REQUIRE_FALSE(between);
        }
        for (std::size_t j = i + 1; j < r.pieces.size(); ++j) {
            const Point &c = p[r.pieces[j].a], &d = p[r.pieces[j].b];
            const int o1 = sign(orient2d(a, b, c)), o2 = sign(orient2d(a, b, d));
            const int o3 = sign(orient2d(c, d, a)), o4 = sign(orient2d(c, d, b));
            INFO("pieces " << i << " and " << j);
            REQUIRE_FALSE((o1 * o2 < 0 && o3 * o4 < 0));
            const bool same = (r.pieces[i].a == r.pieces[j].a && r.pieces[i].b == r.pieces[j].b) ||
                              (r.pieces[i].a == r.pieces[j].b && r.pieces[i].b == r.pieces[j].a);
            REQUIRE_FALSE(same);
        }
    }
}

// The pieces of segment s, as a chain of vertex indices from its first end.
std::vector<std::uint32_t> chain(const Arranged& r, std::uint32_t s) {
    std::vector<std::uint32_t> out;
    for (const SegmentPiece& piece : r.pieces) {
        if (piece.segment != s) continue;
        if (out.empty()) out.push_back(piece.a);
        REQUIRE(out.back() == piece.a);
        out.push_back(piece.b);
    }
    return out;
}

}  // namespace

TEST_CASE("arrangement: a proper crossing cuts both segments", "[arrangement]") {
    const Arranged r = arrange({{0, 0}, {2, 2}, {0, 2}, {2, 0}}, {{0, 1}, {2, 3}});
    REQUIRE(r.points.size() == 5);
    REQUIRE(r.points[4] == Point{1, 1});
    REQUIRE(r.report.crossings.size() == 1);
    REQUIRE(chain(r, 0) == std::vector<std::uint32_t>{0, 4, 1});
    REQUIRE(chain(r, 1) == std::vector<std::uint32_t>{2, 4, 3});
    require_clean(r);
}

TEST_CASE("arrangement: a vertex on a segment cuts it", "[arrangement]") {
    // The a.poly: vertex 0 (0, 2) lies on segment 1, (-1, 3)-(5, -3).
    const Arranged r =
        arrange({{0, 2}, {0, 3}, {0, 1}, {4, 3}, {-1, -1}, {-1, 3}, {5, -3}, {-1, 0}, {5, 0}},
                {{4, 1}, {5, 6}, {7, 8}, {3, 2}});
    require_clean(r);
    REQUIRE(r.report.through_vertices.size() == 1);
    REQUIRE(r.report.through_vertices[0] == std::pair<std::uint32_t, std::uint32_t>{1, 0});
    REQUIRE(r.report.crossings.size() == 4);
    const auto c = chain(r, 1);
    REQUIRE(std::find(c.begin(), c.end(), 0u) != c.end());
}

TEST_CASE("arrangement: collinear overlaps are kept once", "[arrangement]") {
    // 0-2 and 1-3 on one line overlap along 1-2; 4-5 lies inside 0-2.
    const Arranged r =
        arrange({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {0.25, 0}, {0.5, 0}}, {{0, 2}, {1, 3}, {4, 5}});
    require_clean(r);
    REQUIRE(r.pieces.size() == 5);  // 0-4, 4-5, 5-1, 1-2, 2-3
    REQUIRE(r.report.overlaps.size() == 2);
    for (const SegmentPiece& piece : r.pieces)
        if ((piece.a == 4 && piece.b == 5) || (piece.a == 5 && piece.b == 4))
            REQUIRE(piece.segment == 0);  // the first segment's piece is kept
}

TEST_CASE("arrangement: a vertex rounded off a segment still cuts it", "[arrangement]") {
    // The c.poly: (0.007, 0) is meant to lie on (0.005, -0.002)-
    // (0.011, 0.004), but its decimal coordinates miss the line by 1e-19.
    const Arranged r = arrange({{0.005, -0.002}, {0.011, 0.004}, {0.007, 0.0}}, {{0, 1}});
    REQUIRE(orient2d(r.points[0], r.points[1], r.points[2]) != 0);
    REQUIRE(chain(r, 0) == std::vector<std::uint32_t>{0, 2, 1});
}

TEST_CASE("arrangement: three segments through one inexact point meet at one vertex",
          "[arrangement]") {
    // Concurrent lines whose common point is not representable.
    const double o = 1e6;
    const Arranged r = arrange({{o + 0.1, o + 0.3},
                                {o + 0.7, o + 0.9},
                                {o + 0.1, o + 0.9},
                                {o + 0.7, o + 0.3},
                                {o + 0.4, o + 0.2},
                                {o + 0.4, o + 1.0}},
                               {{0, 1}, {2, 3}, {4, 5}});
    require_clean(r);
    REQUIRE(r.points.size() <= 7 + 2);
}

TEST_CASE("arrangement: random crossing-heavy inputs come out clean", "[arrangement]") {
    std::mt19937_64 rng(42);
    for (int trial = 0; trial < 300; ++trial) {
        const int n = 6 + static_cast<int>(rng() % 15);
        const double scale = std::array{1e-3, 1.0, 7.0, 1e5}[trial % 4];
        const double offset = std::array{0.0, 1e6, -3.5, 0.1}[(trial / 4) % 4];
        std::vector<Point> points;
        for (int i = 0; i < n; ++i)
            points.push_back({offset + scale * static_cast<double>(rng() % 7) / 3.0,
                              offset + scale * static_cast<double>(rng() % 7) / 3.0});
        // Leave duplicates out, as the caller does.
        std::vector<Point> distinct;
        for (const Point& p : points)
            if (std::find(distinct.begin(), distinct.end(), p) == distinct.end())
                distinct.push_back(p);
        if (distinct.size() < 3) continue;
        std::vector<std::pair<int, int>> segments;
        const int m = 8 + static_cast<int>(rng() % 23);
        for (int s = 0; s < m; ++s) {
            const int a = static_cast<int>(rng() % distinct.size());
            const int b = static_cast<int>(rng() % distinct.size());
            const bool repeated =
                std::find_if(segments.begin(), segments.end(), [&](auto e) {
                    return (e.first == a && e.second == b) || (e.first == b && e.second == a);
                }) != segments.end();
            if (a != b && !repeated) segments.emplace_back(a, b);
        }
        INFO("trial " << trial);
        const Arranged r = arrange(distinct, segments);
        require_clean(r);
    }
}
