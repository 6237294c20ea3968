// The arrangement of a PSLG's segments (see arrangement.hpp).

#include "triangulate/arrangement.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <span>
#include <string>
#include <unordered_map>

#include <gpdr/errors.hpp>

#include "geometry/crossing.hpp"
#include "geometry/on_segment.hpp"
#include "geometry/predicates.hpp"

namespace gpdr::triangulate {

using geometry::on_interior;
using geometry::orient2d;
using geometry::Point;
using geometry::rounding_distance;

namespace {

// A uniform grid of cells over the vertices' bounding box, each listing the
// pieces that pass through it and the vertices in it (compressed rows).
class Grid {
public:
    Grid(const std::vector<Point>& points, const std::vector<std::uint32_t>& vertices,
         const std::vector<SegmentPiece>& pieces) {
        lo_ = hi_ = points[vertices.front()];
        double magnitude = 0;
        for (const std::uint32_t v : vertices) {
            const Point& p = points[v];
            lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y)};
            hi_ = {std::max(hi_.x, p.x), std::max(hi_.y, p.y)};
            magnitude = std::max({magnitude, std::abs(p.x), std::abs(p.y)});
        }
        // Two cells an item, at most 4M cells (32 MB): inputs that follow
        // curves (coastlines) occupy few of the cells, so the grid must be
        // finer than the average density suggests.
        const double target =
            std::clamp(2.0 * static_cast<double>(pieces.size() + vertices.size()), 1.0, 4.0e6);
        const double width = hi_.x - lo_.x, height = hi_.y - lo_.y;
        if (width > 0 && height > 0) {
            columns_ =
                static_cast<int>(std::clamp(std::sqrt(target * width / height), 1.0, target));
            rows_ = static_cast<int>(std::clamp(target / columns_, 1.0, target));
        } else if (width > 0) {
            columns_ = static_cast<int>(target);
        } else if (height > 0) {
            rows_ = static_cast<int>(target);
        }
        cell_w_ = width > 0 ? width / columns_ : 1.0;
        cell_h_ = height > 0 ? height / rows_ : 1.0;
        // A margin, in cells, wider than the rounding of the cell arithmetic
        // below, so that a vertex exactly on a piece always shares a cell
        // with it.
        pad_ = 0.01 + 64 * 0x1p-53 * magnitude / std::min(cell_w_, cell_h_);

        const std::size_t cells = static_cast<std::size_t>(rows_) * columns_;
        piece_start_.assign(cells + 1, 0);
        vertex_start_.assign(cells + 1, 0);
        for (const SegmentPiece& s : pieces)
            for_each_cell(points[s.a], points[s.b], [&](std::size_t c) { ++piece_start_[c + 1]; });
        for (const std::uint32_t v : vertices) ++vertex_start_[cell_of(points[v]) + 1];
        for (std::size_t c = 0; c < cells; ++c) {
            piece_start_[c + 1] += piece_start_[c];
            vertex_start_[c + 1] += vertex_start_[c];
        }
        piece_entries_.resize(piece_start_[cells]);
        vertex_entries_.resize(vertex_start_[cells]);
        std::vector<std::uint32_t> fill(piece_start_.begin(), piece_start_.end() - 1);
        for (std::uint32_t i = 0; i < pieces.size(); ++i)
            for_each_cell(points[pieces[i].a], points[pieces[i].b],
                          [&](std::size_t c) { piece_entries_[fill[c]++] = i; });
        fill.assign(vertex_start_.begin(), vertex_start_.end() - 1);
        for (const std::uint32_t v : vertices) vertex_entries_[fill[cell_of(points[v])]++] = v;
    }

    std::size_t cells() const { return piece_start_.size() - 1; }

    // Calls f for every cell the segment a-b passes through (and a margin):
    // row by row, the x-range of the segment within the row's slab.
    template <class F>
    void for_each_cell(const Point& a, const Point& b, F&& f) const {
        const double y_lo = std::min(a.y, b.y), y_hi = std::max(a.y, b.y);
        const double x_lo = std::min(a.x, b.x), x_hi = std::max(a.x, b.x);
        const int r0 = row(y_lo, -pad_), r1 = row(y_hi, pad_);
        for (int r = r0; r <= r1; ++r) {
            double from = x_lo, to = x_hi;
            if (a.y != b.y) {
                const double slab_lo = std::clamp(lo_.y + r * cell_h_, y_lo, y_hi);
                const double slab_hi = std::clamp(lo_.y + (r + 1) * cell_h_, y_lo, y_hi);
                const double slope = (b.x - a.x) / (b.y - a.y);
                const double x1 = std::clamp(a.x + (slab_lo - a.y) * slope, x_lo, x_hi);
                const double x2 = std::clamp(a.x + (slab_hi - a.y) * slope, x_lo, x_hi);
                from = std::min(x1, x2);
                to = std::max(x1, x2);
            }
            const int c0 = column(from, -pad_), c1 = column(to, pad_);
            for (int c = c0; c <= c1; ++c) f(static_cast<std::size_t>(r) * columns_ + c);
        }
    }

    std::span<const std::uint32_t> pieces_in(std::size_t c) const {
        return {piece_entries_.data() + piece_start_[c], piece_start_[c + 1] - piece_start_[c]};
    }
    std::span<const std::uint32_t> vertices_in(std::size_t c) const {
        return {vertex_entries_.data() + vertex_start_[c], vertex_start_[c + 1] - vertex_start_[c]};
    }

private:
    int column(double x, double pad) const {
        return static_cast<int>(
            std::clamp(std::floor((x - lo_.x) / cell_w_ + pad), 0.0, columns_ - 1.0));
    }
    int row(double y, double pad) const {
        return static_cast<int>(
            std::clamp(std::floor((y - lo_.y) / cell_h_ + pad), 0.0, rows_ - 1.0));
    }
    std::size_t cell_of(const Point& p) const {
        return static_cast<std::size_t>(row(p.y, 0)) * columns_ + column(p.x, 0);
    }

    Point lo_, hi_;
    int columns_ = 1, rows_ = 1;
    double cell_w_ = 1, cell_h_ = 1, pad_ = 0;
    std::vector<std::uint32_t> piece_start_, vertex_start_;
    std::vector<std::uint32_t> piece_entries_, vertex_entries_;
};

std::uint64_t pair_key(std::uint32_t hi, std::uint32_t lo) {
    return (std::uint64_t{hi} << 32) | lo;
}

// A piece's bounding box, for cheap rejection before the predicates.
struct Box {
    Point lo, hi;
    double margin;  // rounding distance, for vertices just off the piece

    static Box of(const Point& a, const Point& b) {
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        const double m = std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)});
        return {{std::min(a.x, b.x), std::min(a.y, b.y)},
                {std::max(a.x, b.x), std::max(a.y, b.y)},
                1e-12 * length + 32 * 0x1p-53 * m};
    }
    bool near(const Point& p) const {
        return p.x >= lo.x - margin && p.x <= hi.x + margin && p.y >= lo.y - margin &&
               p.y <= hi.y + margin;
    }
    bool overlaps(const Box& o) const {
        return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y;
    }
};

double squared_distance(const Point& p, const Point& q) {
    const double dx = p.x - q.x, dy = p.y - q.y;
    return dx * dx + dy * dy;
}

int sign(double v) { return (v > 0) - (v < 0); }

// Whether a-b and c-d cross at a point interior to both.
bool cross_properly(const Point& a, const Point& b, const Point& c, const Point& d) {
    const int o1 = sign(orient2d(a, b, c)), o2 = sign(orient2d(a, b, d));
    if (o1 == 0 || o2 == 0 || o1 == o2) return false;
    const int o3 = sign(orient2d(c, d, a)), o4 = sign(orient2d(c, d, b));
    return o3 != 0 && o4 != 0 && o3 != o4;
}

struct PointHash {
    std::size_t operator()(const Point& p) const {
        // + 0.0 turns -0.0 into 0.0, which compares equal to it.
        const std::uint64_t x = std::bit_cast<std::uint64_t>(p.x + 0.0);
        const std::uint64_t y = std::bit_cast<std::uint64_t>(p.y + 0.0);
        return static_cast<std::size_t>(x * 0x9E3779B97F4A7C15ull ^ (y + 0x632BE59BD9B4E019ull));
    }
};

// One round: finds where the pieces must be cut.
class Round {
public:
    Round(std::vector<Point>& points, std::vector<std::uint32_t>& vertices,
          const std::vector<SegmentPiece>& pieces, std::uint32_t input_vertices,
          std::unordered_map<Point, std::uint32_t, PointHash>& at, ArrangementReport& report)
        : points_(points),
          vertices_(vertices),
          pieces_(pieces),
          input_vertices_(input_vertices),
          at_(at),
          report_(report) {}

    // Fills cuts(): piece -> the vertices to cut it at.
    void find() {
        const Grid grid(points_, vertices_, pieces_);
        // Vertices on pieces first: they are exact, and crossings near them
        // snap to them.  A vertex is in one cell, so each pair is met once.
        std::vector<Box> boxes(pieces_.size());
        for (std::size_t i = 0; i < pieces_.size(); ++i)
            boxes[i] = Box::of(points_[pieces_[i].a], points_[pieces_[i].b]);
        for (std::size_t c = 0; c < grid.cells(); ++c) {
            const auto pieces = grid.pieces_in(c);
            if (pieces.empty()) continue;
            for (const std::uint32_t v : grid.vertices_in(c)) {
                const Point& p = points_[v];
                for (const std::uint32_t i : pieces) {
                    const SegmentPiece& s = pieces_[i];
                    if (v == s.a || v == s.b || !boxes[i].near(p)) continue;
                    if (!on_interior(points_[s.a], points_[s.b], p)) continue;
                    cut(i, v);
                    if (v < input_vertices_) report_.through_vertices.emplace_back(s.segment, v);
                }
            }
        }
        // Pairs of pieces: each piece meets the later pieces in its cells,
        // once each (the stamp remembers which piece last met it).
        std::vector<std::uint32_t> met(pieces_.size(), no_piece);
        for (std::uint32_t i = 0; i < pieces_.size(); ++i) {
            const SegmentPiece& s = pieces_[i];
            // Copies: a crossing found inside appends to points_, which may
            // move it.
            const Point a = points_[s.a], b = points_[s.b];
            grid.for_each_cell(a, b, [&](std::size_t c) {
                for (const std::uint32_t j : grid.pieces_in(c)) {
                    if (j <= i || met[j] == i) continue;
                    met[j] = i;
                    if (boxes[i].overlaps(boxes[j])) consider_crossing(i, j);
                }
            });
        }
    }

    const std::unordered_map<std::uint32_t, std::vector<std::uint32_t>>& cuts() const {
        return cuts_;
    }
    std::pair<std::uint32_t, std::uint32_t> first_crossing() const { return first_crossing_; }

private:
    static constexpr std::uint32_t no_piece = 0xFFFFFFFFu;

    void consider_crossing(std::uint32_t i, std::uint32_t j) {
        const SegmentPiece &s = pieces_[i], &t = pieces_[j];
        if (s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b) return;
        if (!cross_properly(points_[s.a], points_[s.b], points_[t.a], points_[t.b])) return;
        const std::uint32_t w = crossing_vertex(i, j);
        if (w != s.a && w != s.b) cut(i, w);
        if (w != t.a && w != t.b) cut(j, w);
        if (first_crossing_.first == first_crossing_.second)
            first_crossing_ = {std::min(s.segment, t.segment), std::max(s.segment, t.segment)};
    }

    void cut(std::uint32_t piece, std::uint32_t v) {
        auto& list = cuts_[piece];
        if (std::find(list.begin(), list.end(), v) == list.end()) list.push_back(v);
    }

    // The vertex where pieces i and j cross: an existing one within rounding
    // distance of the crossing point (see arrangement.hpp), else a new one.
    std::uint32_t crossing_vertex(std::uint32_t i, std::uint32_t j) {
        const SegmentPiece &s = pieces_[i], &t = pieces_[j];
        const Point p =
            geometry::crossing_point(points_[s.a], points_[s.b], points_[t.a], points_[t.b]);
        const double length = std::sqrt(std::max(squared_distance(points_[s.a], points_[s.b]),
                                                 squared_distance(points_[t.a], points_[t.b])));
        const double near = rounding_distance(length, p);
        std::uint32_t best = 0;
        double best_distance = near * near;
        bool found = false;
        auto consider = [&](std::uint32_t v) {
            const double d = squared_distance(points_[v], p);
            if (d <= best_distance) {
                best = v;
                best_distance = d;
                found = true;
            }
        };
        for (const std::uint32_t v : {s.a, s.b, t.a, t.b}) consider(v);
        for (const std::uint32_t piece : {i, j})
            if (const auto it = cuts_.find(piece); it != cuts_.end())
                for (const std::uint32_t v : it->second) consider(v);
        if (found) return best;
        if (at_.empty())
            for (const std::uint32_t v : vertices_) at_.emplace(points_[v], v);
        if (const auto it = at_.find(p); it != at_.end()) return it->second;
        const auto v = static_cast<std::uint32_t>(points_.size());
        points_.push_back(p);
        vertices_.push_back(v);
        at_.emplace(p, v);
        report_.crossings.push_back(
            {v, std::max(s.segment, t.segment), std::min(s.segment, t.segment)});
        return v;
    }

    std::vector<Point>& points_;
    std::vector<std::uint32_t>& vertices_;
    const std::vector<SegmentPiece>& pieces_;
    std::uint32_t input_vertices_;
    std::unordered_map<Point, std::uint32_t, PointHash>& at_;
    ArrangementReport& report_;
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> cuts_;
    std::pair<std::uint32_t, std::uint32_t> first_crossing_{0, 0};
};

// The pieces cut where the round says, in order along each piece.
std::vector<SegmentPiece> apply_cuts(
    const std::vector<Point>& points, const std::vector<SegmentPiece>& pieces,
    const std::unordered_map<std::uint32_t, std::vector<std::uint32_t>>& cuts) {
    std::vector<SegmentPiece> out;
    out.reserve(pieces.size() + 2 * cuts.size());
    std::vector<std::uint32_t> order;
    for (std::uint32_t i = 0; i < pieces.size(); ++i) {
        const SegmentPiece& s = pieces[i];
        const auto it = cuts.find(i);
        if (it == cuts.end()) {
            out.push_back(s);
            continue;
        }
        // Along the piece's dominant axis, from a; the other axis breaks
        // ties between near-coincident vertices just off the line.
        const Point &a = points[s.a], &b = points[s.b];
        const double dx = b.x - a.x, dy = b.y - a.y;
        const bool by_x = std::abs(dx) >= std::abs(dy);
        auto position = [&](std::uint32_t v) {
            const Point& p = points[v];
            return by_x ? std::pair{(p.x - a.x) * dx, (p.y - a.y) * dy}
                        : std::pair{(p.y - a.y) * dy, (p.x - a.x) * dx};
        };
        order = it->second;
        std::sort(order.begin(), order.end(),
                  [&](std::uint32_t u, std::uint32_t v) { return position(u) < position(v); });
        std::uint32_t from = s.a;
        order.push_back(s.b);
        for (const std::uint32_t v : order) {
            if (v == from) continue;
            out.push_back({from, v, s.segment, s.marker});
            from = v;
        }
    }
    return out;
}

// Keeps the first of pieces with the same two ends (collinear overlaps cut
// at each other's ends become such twins).
void merge_twins(std::vector<SegmentPiece>& pieces, ArrangementReport& report) {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(pieces.size());
    for (std::uint32_t i = 0; i < pieces.size(); ++i)
        keys[i] = {pair_key(std::min(pieces[i].a, pieces[i].b), std::max(pieces[i].a, pieces[i].b)),
                   i};
    std::sort(keys.begin(), keys.end());
    std::vector<bool> gone(pieces.size(), false);
    bool any = false;
    for (std::size_t k = 1; k < keys.size(); ++k) {
        if (keys[k].first != keys[k - 1].first) continue;
        std::size_t first = k - 1;
        while (first > 0 && keys[first - 1].first == keys[k].first) --first;
        SegmentPiece& kept = pieces[keys[first].second];
        const SegmentPiece& twin = pieces[keys[k].second];
        if (kept.marker == 0) kept.marker = twin.marker;
        if (twin.segment != kept.segment)
            report.overlaps.emplace_back(std::max(twin.segment, kept.segment),
                                         std::min(twin.segment, kept.segment));
        gone[keys[k].second] = true;
        any = true;
    }
    if (!any) return;
    std::size_t n = 0;
    for (std::size_t i = 0; i < pieces.size(); ++i)
        if (!gone[i]) pieces[n++] = pieces[i];
    pieces.resize(n);
}

}  // namespace

std::vector<SegmentPiece> arrange_segments(std::vector<Point>& points,
                                           std::vector<std::uint32_t> vertices,
                                           std::vector<SegmentPiece> pieces,
                                           ArrangementReport& report) {
    report = ArrangementReport{};
    if (pieces.empty() || vertices.empty()) return pieces;
    const auto input_vertices = static_cast<std::uint32_t>(points.size());
    std::unordered_map<Point, std::uint32_t, PointHash> at;
    // Each round but the last cuts something; rounding settles in one or
    // two rounds, and the bound turns a case that would not into an error.
    constexpr int max_rounds = 16;
    for (int round = 0; round < max_rounds; ++round) {
        Round r(points, vertices, pieces, input_vertices, at, report);
        r.find();
        if (r.cuts().empty()) {
            std::sort(report.overlaps.begin(), report.overlaps.end());
            report.overlaps.erase(std::unique(report.overlaps.begin(), report.overlaps.end()),
                                  report.overlaps.end());
            return pieces;
        }
        pieces = apply_cuts(points, pieces, r.cuts());
        merge_twins(pieces, report);
        if (round == max_rounds - 1) {
            const auto [s, t] = r.first_crossing();
            throw GeometryError("the crossings of segments near segments " + std::to_string(s) +
                                " and " + std::to_string(t) +
                                " cannot be resolved in floating point (each rounded crossing "
                                "point makes new crossings)");
        }
    }
    return pieces;
}

}  // namespace gpdr::triangulate
