// The mesh against its input (see input_check.hpp for what is checked).
//
// The passes, each linear in what it reads:
//   1. the segments (input segments of non-zero length, and the hull's
//      edges when the hull bounds the domain) go into a uniform grid, and
//      the pairs that share a cell are tested for crossings, which widen
//      the crossed segments' tolerance;
//   2. one pass over the triangles marks the vertices in use and lists the
//      boundary edges;
//   3. one pass over the vertices in use finds, through the grid, the
//      segments each lies on;
//   4. one pass over the triangles lists the edges whose two ends lie on
//      segments, the only ones a segment can be covered by;
//   5. each segment's vertices, in order along it, are joined by those
//      edges, or the piece between them is outside the domain;
//   6. the rest (boundary edges, input vertices, holes, regions, bounds)
//      reads what 1-5 found.

#include "check/input_check.hpp"
#include "check/problem_list.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <numeric>
#include <optional>
#include <unordered_set>

#include <fmt/format.h>

#include "geometry/constructions.hpp"
#include "geometry/convex_hull.hpp"
#include "geometry/edge_strips.hpp"
#include "geometry/predicates.hpp"
#include "geometry/segment_grid.hpp"

namespace gpdr::mesh {
namespace {

using geometry::Point;

using Problems = ProblemList;

std::string at(const Point& p) { return fmt::format("({}, {})", p.x, p.y); }

std::uint64_t edge_key(VertexId u, VertexId w) {
    const std::uint64_t a = index(u), b = index(w);
    return a < b ? (a << 32 | b) : (b << 32 | a);
}

// A segment the mesh must follow: an input segment or an edge of the hull.
struct Segment {
    Point a, b;
    std::uint32_t number = 0;  // index in the input, or of the hull edge
    bool hull = false;
    // How far from its line a vertex may lie and still be on it (rounding,
    // more where another segment crosses it).
    double tolerance = 0;
};

// Orders points along s: the coordinate in which s moves most, signed so
// that it grows from a to b.  Distinct points on the line get distinct keys.
double key_along(const Segment& s, const Point& p) {
    const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
    if (std::abs(dx) >= std::abs(dy)) return dx > 0 ? p.x : -p.x;
    return dy > 0 ? p.y : -p.y;
}

bool on_segment(const Segment& s, const Point& p) {
    if (p == s.a || p == s.b) return true;  // (orient2d is slowest on exact zeros)
    const double side = geometry::orient2d(s.a, s.b, p);
    if (side == 0)
        return p.x >= std::min(s.a.x, s.b.x) && p.x <= std::max(s.a.x, s.b.x) &&
               p.y >= std::min(s.a.y, s.b.y) && p.y <= std::max(s.a.y, s.b.y);
    // |side| is the distance from the line times the length.
    const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
    const double length2 = dx * dx + dy * dy, slack = s.tolerance * std::sqrt(length2);
    if (std::abs(side) > slack) return false;
    const double along = (p.x - s.a.x) * dx + (p.y - s.a.y) * dy;
    return along >= -slack && along <= length2 + slack;
}

bool cross_properly(const Point& a, const Point& b, const Point& c, const Point& d) {
    // Segments whose boxes do not meet, or that share an end, do not cross
    // at a point interior to both; both tests are cheap, and orient2d is
    // slowest where it must prove an exact zero.
    if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
        std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y))
        return false;
    if (a == c || a == d || b == c || b == d) return false;
    const double sc = geometry::orient2d(a, b, c), sd = geometry::orient2d(a, b, d);
    if (!((sc < 0 && sd > 0) || (sc > 0 && sd < 0))) return false;
    const double sa = geometry::orient2d(c, d, a), sb = geometry::orient2d(c, d, b);
    return (sa < 0 && sb > 0) || (sa > 0 && sb < 0);
}

double magnitude(const Point& p) { return std::max(std::abs(p.x), std::abs(p.y)); }

// How far from the line of a-b a vertex split off it may lie: a split point
// is rounded to doubles, and splits of pieces whose ends were rounded
// add up, a few units in the last place of the coordinates each.
double rounding(const Point& a, const Point& b) {
    return 0x1p-44 * std::max(magnitude(a), magnitude(b));
}

double length(const Segment& s) { return std::hypot(s.b.x - s.a.x, s.b.y - s.a.y); }

// A vertex in use lying on a segment.
struct OnSegment {
    std::uint32_t segment;
    std::uint32_t vertex;
    double key;  // key_along
};

constexpr std::uint8_t in_use = 1, on_a_segment = 2;

// A point along a segment where the mesh must have a vertex or leave the
// domain: an end, or a vertex on it.
struct Station {
    Point at;
    std::uint32_t vertex;  // compact number (InputCheck::compact); none for an end alone
    bool exact;            // exactly on the line (orient2d)
};

class InputCheck {
public:
    InputCheck(const Mesh& mesh, const InputGeometry& input, const InputCheckOptions& options)
        : mesh_(mesh), input_(input), options_(options), problems_(options.max_problems) {}

    std::vector<std::string> run() {
        make_segments();
        find_crossings();
        scan_triangles();
        find_vertices_on_segments();
        list_edges_between_segment_vertices();
        boundary_.emplace(boundary_points());
        follow_segments();
        check_boundary_edges();
        check_input_vertices();
        check_holes();
        check_regions_and_bounds();
        return problems_.finish();
    }

private:
    std::string name(const Segment& s) const {
        if (s.hull) return fmt::format("the convex hull's edge from {} to {}", at(s.a), at(s.b));
        return fmt::format("segment {} (vertices {} and {})", s.number + options_.base,
                           input_.segments[2 * std::size_t{s.number}] + options_.base,
                           input_.segments[2 * std::size_t{s.number} + 1] + options_.base);
    }

    void make_segments() {
        const auto& pts = input_.points;
        for (std::size_t s = 0; s < input_.segments.size() / 2; ++s) {
            const std::uint32_t i = input_.segments[2 * s], j = input_.segments[2 * s + 1];
            if (i >= pts.size() || j >= pts.size() || pts[i] == pts[j]) continue;
            segments_.push_back(
                {pts[i], pts[j], static_cast<std::uint32_t>(s), false, rounding(pts[i], pts[j])});
        }
        if (input_.hull_bounds_domain) {
            const std::vector<std::uint32_t> hull = geometry::convex_hull(pts);
            if (hull.size() >= 3)
                for (std::size_t k = 0; k < hull.size(); ++k)
                    segments_.push_back({pts[hull[k]], pts[hull[(k + 1) % hull.size()]],
                                         static_cast<std::uint32_t>(k), true,
                                         rounding(pts[hull[k]], pts[hull[(k + 1) % hull.size()]])});
        }
    }

    void find_crossings() {
        if (input_.points.empty()) return;
        Point lo = input_.points[0], hi = lo;
        for (const Point& p : input_.points) {
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
        }
        std::vector<Point> ends;
        ends.reserve(2 * segments_.size());
        for (const Segment& s : segments_) {
            ends.push_back(s.a);
            ends.push_back(s.b);
        }
        grid_.emplace(lo, hi, 2 * segments_.size() + 1, ends);
        for (std::size_t c = 0; c < grid_->cell_count(); ++c) {
            const auto cell = grid_->cell(c);
            for (std::size_t x = 0; x < cell.size(); ++x)
                for (std::size_t y = x + 1; y < cell.size(); ++y) {
                    Segment &s = segments_[cell[x]], &t = segments_[cell[y]];
                    if (!cross_properly(s.a, s.b, t.a, t.b)) continue;
                    const Point p = geometry::segment_intersection(s.a, s.b, t.a, t.b);
                    const double big = std::max({magnitude(p), magnitude(s.a), magnitude(s.b),
                                                 magnitude(t.a), magnitude(t.b)});
                    const double tolerance = 1e-11 * std::max(length(s), length(t)) + 0x1p-44 * big;
                    s.tolerance = std::max(s.tolerance, tolerance);
                    t.tolerance = std::max(t.tolerance, tolerance);
                }
        }
    }

    void scan_triangles() {
        flags_.assign(mesh_.vertex_end(), 0);
        const std::uint32_t end = mesh_.triangle_end();
        for (std::uint32_t i = 0; i < end; ++i) {
            const Triangle& t = mesh_.triangle(TriangleId{i});
            if (!t.live()) continue;
            for (int k = 0; k < 3; ++k) {
                if (index(t.v[k]) < flags_.size()) flags_[index(t.v[k])] |= in_use;
                if (t.n[k].is_none()) boundary_edges_.push_back({t.v[next3(k)], t.v[prev3(k)]});
            }
        }
    }

    bool stored(VertexId v) const { return index(v) < flags_.size(); }

    void find_vertices_on_segments() {
        if (!grid_) return;
        for (std::uint32_t v = 0; v < flags_.size(); ++v) {
            if (!(flags_[v] & in_use)) continue;
            const Point& p = mesh_.point(VertexId{v});
            for (const std::uint32_t s : grid_->near(p))
                if (on_segment(segments_[s], p)) {
                    on_.push_back({s, v, key_along(segments_[s], p)});
                    flags_[v] |= on_a_segment;
                }
        }
        std::sort(on_.begin(), on_.end(), [](const OnSegment& x, const OnSegment& y) {
            return x.segment < y.segment || (x.segment == y.segment && x.key < y.key);
        });
    }

    bool lies_on_segment(VertexId v) const {
        return stored(v) && (flags_[index(v)] & on_a_segment);
    }

    void list_edges_between_segment_vertices() {
        const std::uint32_t end = mesh_.triangle_end();
        for (std::uint32_t i = 0; i < end; ++i) {
            const Triangle& t = mesh_.triangle(TriangleId{i});
            if (!t.live()) continue;
            for (int k = 0; k < 3; ++k) {
                const VertexId u = t.v[next3(k)], w = t.v[prev3(k)];
                if (lies_on_segment(u) && lies_on_segment(w)) edges_.push_back(edge_key(u, w));
            }
        }
        std::sort(edges_.begin(), edges_.end());
        edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
    }

    std::vector<Point> boundary_points() const {
        std::vector<Point> ends;
        ends.reserve(2 * boundary_edges_.size());
        for (const auto& [u, w] : boundary_edges_)
            if (stored(u) && stored(w)) {
                ends.push_back(mesh_.point(u));
                ends.push_back(mesh_.point(w));
            }
        return ends;
    }

    // A piece of a segment that no mesh edge covers must lie outside the
    // domain: its midpoint outside (not even on the boundary) and no
    // boundary edge crossing it.
    // A boundary edge crossing within `margin` of p or q (the segment's
    // rounding) is taken to cross at p or q.
    bool outside_domain(const Point& p, const Point& q, double margin = 0) const {
        const Point mid{p.x + 0.5 * (q.x - p.x), p.y + 0.5 * (q.y - p.y)};
        return boundary_->locate(mid) == geometry::EdgeStrips::Where::outside &&
               !boundary_->crossed(p, q, margin);
    }

    // The vertices on segments, compactly numbered (their order in
    // by_vertex_'s distinct vertices), and each one's neighbours among them.
    void index_segment_vertices() {
        by_vertex_ = on_;
        std::sort(by_vertex_.begin(), by_vertex_.end(), [](const OnSegment& x, const OnSegment& y) {
            return x.vertex < y.vertex || (x.vertex == y.vertex && x.segment < y.segment);
        });
        for (const OnSegment& o : by_vertex_)
            if (vertices_.empty() || vertices_.back() != o.vertex) vertices_.push_back(o.vertex);
        adjacency_start_.assign(vertices_.size() + 1, 0);
        for (const std::uint64_t e : edges_) {
            ++adjacency_start_[compact(static_cast<std::uint32_t>(e >> 32)) + 1];
            ++adjacency_start_[compact(static_cast<std::uint32_t>(e)) + 1];
        }
        for (std::size_t i = 0; i < vertices_.size(); ++i)
            adjacency_start_[i + 1] += adjacency_start_[i];
        adjacency_.resize(adjacency_start_.back());
        std::vector<std::size_t> fill(adjacency_start_.begin(), adjacency_start_.end() - 1);
        for (const std::uint64_t e : edges_) {
            const std::uint32_t u = compact(static_cast<std::uint32_t>(e >> 32)),
                                w = compact(static_cast<std::uint32_t>(e));
            adjacency_[fill[u]++] = w;
            adjacency_[fill[w]++] = u;
        }
    }

    std::uint32_t compact(std::uint32_t vertex) const {
        return static_cast<std::uint32_t>(
            std::lower_bound(vertices_.begin(), vertices_.end(), vertex) - vertices_.begin());
    }

    // Each segment is covered where a mesh edge joins two of its vertices
    // with no vertex exactly on it in between (a vertex within rounding of
    // the line may be skipped: it may lie just inside the domain); what no
    // such edge covers must lie outside the domain.
    void follow_segments() {
        index_segment_vertices();
        position_.assign(vertices_.size(), no_position);
        std::vector<bool> seen(segments_.size(), false);
        for (std::size_t first = 0, last = 0; first < on_.size(); first = last) {
            while (last < on_.size() && on_[last].segment == on_[first].segment) ++last;
            seen[on_[first].segment] = true;
            follow(on_[first].segment, first, last);
        }
        // Segments no vertex in use lies on: wholly outside the domain, or
        // not in the mesh at all.
        for (std::uint32_t s = 0; s < segments_.size(); ++s)
            if (!seen[s] && !outside_domain(segments_[s].a, segments_[s].b, segments_[s].tolerance))
                problems_.add("{} lies in the domain but no mesh vertex lies on it",
                              name(segments_[s]));
    }

    static constexpr std::uint32_t no_position = 0xFFFFFFFFu;

    // Segment s through the vertices on_[first, last), in order along it:
    // the stations along it, how far the mesh edges from each reach, and
    // the gaps no edge covers.
    void follow(std::uint32_t s, std::size_t first, std::size_t last) {
        const Segment& seg = segments_[s];
        place_stations(seg, first, last);
        for (std::uint32_t i = 0; i < stations_.size(); ++i)
            if (stations_[i].vertex != no_position) position_[stations_[i].vertex] = i;
        find_reach();
        report_gaps(seg);
        for (const Station& st : stations_)
            if (st.vertex != no_position) position_[st.vertex] = no_position;
    }

    // The stations along seg, into stations_: a unless a vertex is there,
    // the vertices on_[first, last) between a and b, b unless a vertex is
    // there.  A vertex within the tolerance of the line but past an end (a
    // crossing of other segments just beyond it) is no part of seg.
    void place_stations(const Segment& seg, std::size_t first, std::size_t last) {
        std::vector<Station>& stations = stations_;
        stations.clear();
        stations.push_back({seg.a, no_position, true});
        const double dx = seg.b.x - seg.a.x, dy = seg.b.y - seg.a.y;
        const double length2 = dx * dx + dy * dy;
        for (std::size_t k = first; k < last; ++k) {
            const Point& p = mesh_.point(VertexId{on_[k].vertex});
            const double along = (p.x - seg.a.x) * dx + (p.y - seg.a.y) * dy;
            if (p != seg.a && p != seg.b && (along < 0 || along > length2)) continue;
            const bool exact = p == seg.a || p == seg.b || geometry::orient2d(seg.a, seg.b, p) == 0;
            if (p == seg.a && stations.size() == 1 && stations[0].vertex == no_position)
                stations.clear();
            stations.push_back({p, compact(on_[k].vertex), exact});
        }
        if (stations.back().at != seg.b) stations.push_back({seg.b, no_position, true});
    }

    // reach_[i]: the farthest station a covering edge from station i leads
    // to (i itself when none does).  An edge covers the stations it spans
    // only when none of them lies exactly on the line: it would skip a
    // vertex of the segment.  position_ maps the stations' vertices.
    void find_reach() {
        const std::vector<Station>& stations = stations_;
        // exact_before[i]: stations exactly on the line before station i.
        std::vector<std::uint32_t>& exact_before = exact_before_;
        exact_before.assign(stations.size() + 1, 0);
        for (std::size_t i = 0; i < stations.size(); ++i)
            exact_before[i + 1] = exact_before[i] + (stations[i].exact ? 1 : 0);
        std::vector<std::uint32_t>& reach = reach_;
        reach.assign(stations.size(), 0);
        for (std::uint32_t i = 0; i < stations.size(); ++i) {
            reach[i] = i;
            const std::uint32_t v = stations[i].vertex;
            if (v == no_position) continue;
            for (std::size_t k = adjacency_start_[v]; k < adjacency_start_[v + 1]; ++k) {
                const std::uint32_t j = position_[adjacency_[k]];
                if (j == no_position || j <= i) continue;
                if (exact_before[j] - exact_before[i + 1] != 0) continue;  // skips an exact one
                reach[i] = std::max(reach[i], j);
            }
        }
    }

    // A sweep over the covered intervals (reach_): each run of stations no
    // edge covers must lie outside the domain, or seg is reported.
    void report_gaps(const Segment& seg) {
        const std::vector<Station>& stations = stations_;
        const std::vector<std::uint32_t>& reach = reach_;
        std::uint32_t covered_to = 0;
        for (std::uint32_t i = 0; i + 1 < stations.size(); ++i) {
            if (covered_to <= i && reach[i] <= i) {
                // Nothing covers stations i to i + 1: find where cover
                // resumes, and require the gap to lie outside the domain.
                std::uint32_t j = i + 1;
                while (j + 1 < stations.size() && reach[j] <= j) ++j;
                // Station by station: a mesh vertex in the gap (a corner of
                // the boundary there) is not itself outside.
                for (std::uint32_t k = i; k < j; ++k) {
                    if (stations[k].at == stations[k + 1].at ||
                        outside_domain(stations[k].at, stations[k + 1].at, seg.tolerance))
                        continue;
                    problems_.add("{} is not covered by mesh edges between {} and {}", name(seg),
                                  at(stations[k].at), at(stations[k + 1].at));
                    break;
                }
                covered_to = j;
                i = j - 1;
                continue;
            }
            covered_to = std::max(covered_to, reach[i]);
        }
    }

    // Whether two vertices lie on one segment.
    bool on_one_segment(VertexId u, VertexId w) const {
        const auto su = segments_at(index(u)), sw = segments_at(index(w));
        for (const OnSegment& x : su)
            for (const OnSegment& y : sw)
                if (x.segment == y.segment) return true;
        return false;
    }

    void check_boundary_edges() {
        for (const auto& [u, w] : boundary_edges_) {
            if (!stored(u) || !stored(w)) continue;  // check_mesh reports these
            if (!lies_on_segment(u) || !lies_on_segment(w) || !on_one_segment(u, w))
                problems_.add("the boundary edge from {} to {} lies on no input segment{}",
                              at(mesh_.point(u)), at(mesh_.point(w)),
                              input_.hull_bounds_domain ? " nor on the convex hull" : "");
        }
    }

    void check_input_vertices() {
        // Usually the input vertex is the mesh vertex of the same number;
        // the others (duplicates, vertices outside the domain) are looked
        // for by their coordinates.
        const auto& pts = input_.points;
        std::vector<std::uint32_t> missing;
        for (std::uint32_t i = 0; i < pts.size(); ++i) {
            if (!input_.vertex_required.empty() && !input_.vertex_required[i]) continue;
            if (i < flags_.size() && (flags_[i] & in_use) && mesh_.point(VertexId{i}) == pts[i])
                continue;
            missing.push_back(i);
        }
        if (missing.empty()) return;
        const auto bits = [](const Point& p) {
            // +0.0 folds -0.0 into 0.0, which compares equal to it.
            const double x = p.x + 0.0, y = p.y + 0.0;
            std::uint64_t a, b;
            std::memcpy(&a, &x, 8);
            std::memcpy(&b, &y, 8);
            return a * 0x9E3779B97F4A7C15ull ^ (b + 0x632BE59BD9B4E019ull + (a << 6) + (a >> 2));
        };
        const auto hash = [&](const Point& p) { return static_cast<std::size_t>(bits(p)); };
        std::unordered_set<Point, decltype(hash)> wanted(missing.size() * 2 + 1, hash);
        for (const std::uint32_t i : missing) wanted.insert(pts[i]);
        std::unordered_set<Point, decltype(hash)> found(missing.size() * 2 + 1, hash);
        for (std::uint32_t v = 0; v < flags_.size(); ++v)
            if ((flags_[v] & in_use) && wanted.count(mesh_.point(VertexId{v})))
                found.insert(mesh_.point(VertexId{v}));
        for (const std::uint32_t i : missing)
            if (!found.count(pts[i]) &&
                boundary_->locate(pts[i]) != geometry::EdgeStrips::Where::outside)
                problems_.add("input vertex {} at {} lies in the domain but is not a mesh vertex",
                              i + options_.base, at(pts[i]));
    }

    void check_holes() {
        for (std::size_t h = 0; h < input_.holes.size(); ++h)
            if (boundary_->locate(input_.holes[h]) == geometry::EdgeStrips::Where::inside &&
                !on_input(input_.holes[h]))
                problems_.add("hole {} at {} lies inside a triangle", h + options_.base,
                              at(input_.holes[h]));
    }

    // Whether p lies exactly on an input vertex or segment: a hole point
    // there eats nothing, as in Triangle.  (A scan, run only for a hole
    // point found inside the mesh, which a right mesh never has.)
    bool on_input(const Point& p) const {
        for (const Point& q : input_.points)
            if (q == p) return true;
        for (const Segment& s : segments_) {
            if (s.hull || geometry::orient2d(s.a, s.b, p) != 0) continue;
            if (std::min(s.a.x, s.b.x) <= p.x && p.x <= std::max(s.a.x, s.b.x) &&
                std::min(s.a.y, s.b.y) <= p.y && p.y <= std::max(s.a.y, s.b.y))
                return true;
        }
        return false;
    }

    // ---- regions and bounds ---------------------------------------------

    bool segment_edge(VertexId u, VertexId w) const {
        return lies_on_segment(u) && lies_on_segment(w) && on_one_segment(u, w);
    }

    std::uint32_t find(std::uint32_t t) {
        while (parent_[t] != t) t = parent_[t] = parent_[parent_[t]];
        return t;
    }

    // Groups the triangles into faces (connected across edges on no
    // segment) and gives each face the last region whose point lies in it:
    // region_of_face_, by the face's root; no_region where none, ambiguous
    // where a region point lies on an edge between two faces.
    static constexpr std::uint32_t no_region = 0xFFFFFFFFu, ambiguous = 0xFFFFFFFEu;
    void find_faces() {
        const std::uint32_t end = mesh_.triangle_end();
        parent_.resize(end);
        std::iota(parent_.begin(), parent_.end(), 0u);
        for (std::uint32_t i = 0; i < end; ++i) {
            const Triangle& t = mesh_.triangle(TriangleId{i});
            if (!t.live()) continue;
            for (int k = 0; k < 3; ++k) {
                if (t.n[k].is_none()) continue;
                const std::uint32_t j = index(t.n[k].triangle());
                if (j <= i || j >= end || !mesh_.triangle(TriangleId{j}).live()) continue;
                if (segment_edge(t.v[next3(k)], t.v[prev3(k)])) continue;
                const std::uint32_t a = find(i), b = find(j);
                if (a != b) parent_[std::max(a, b)] = std::min(a, b);
            }
        }
        // Region points sorted by x, to find those in a triangle's box.
        const auto& regions = input_.regions;
        std::vector<std::uint32_t> by_x(regions.size());
        std::iota(by_x.begin(), by_x.end(), 0u);
        std::sort(by_x.begin(), by_x.end(), [&](std::uint32_t a, std::uint32_t b) {
            return regions[a].at.x < regions[b].at.x;
        });
        std::vector<std::vector<std::uint32_t>> faces_of(regions.size());
        for (std::uint32_t i = 0; i < end && !regions.empty(); ++i) {
            const Triangle& t = mesh_.triangle(TriangleId{i});
            if (!t.live()) continue;
            const Point &a = mesh_.point(t.v[0]), &b = mesh_.point(t.v[1]),
                        &c = mesh_.point(t.v[2]);
            const double x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
            auto it =
                std::lower_bound(by_x.begin(), by_x.end(), x0,
                                 [&](std::uint32_t r, double x) { return regions[r].at.x < x; });
            for (; it != by_x.end() && regions[*it].at.x <= x1; ++it) {
                const Point& p = regions[*it].at;
                if (geometry::orient2d(a, b, p) >= 0 && geometry::orient2d(b, c, p) >= 0 &&
                    geometry::orient2d(c, a, p) >= 0)
                    faces_of[*it].push_back(find(i));
            }
        }
        region_of_face_.assign(end, no_region);
        for (std::uint32_t r = 0; r < regions.size(); ++r) {
            auto& faces = faces_of[r];
            std::sort(faces.begin(), faces.end());
            faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
            for (const std::uint32_t f : faces)
                region_of_face_[f] = faces.size() == 1 ? r : ambiguous;
        }
    }

    bool exempt(TriangleId t) const {
        return std::binary_search(options_.exempt.begin(), options_.exempt.end(), t,
                                  [](TriangleId x, TriangleId y) { return index(x) < index(y); });
    }

    // The segments vertex v lies on.
    std::span<const OnSegment> segments_at(std::uint32_t v) const {
        const auto range = std::equal_range(
            by_vertex_.begin(), by_vertex_.end(), OnSegment{0, v, 0},
            [](const OnSegment& x, const OnSegment& y) { return x.vertex < y.vertex; });
        return {range.first, range.second};
    }

    // Whether u and w lie on two segments that meet at 60 degrees or less:
    // at an end of both, or where one crosses or touches the other (a
    // crossing is a vertex of the input's too).  Such a small angle is the
    // input's own, which refinement need not (and cannot always) get rid of.
    bool at_small_input_angle(VertexId u, VertexId w) {
        // cos^2 >= 0.2499: up to 60.0066 degrees, so that an input meaning
        // 60 degrees, written with a few digits, counts too.
        const auto small = [](double px, double py, double qx, double qy, bool lines) {
            const double dot = px * qx + py * qy;
            return (lines || dot > 0) &&
                   dot * dot >= 0.2499 * (px * px + py * py) * (qx * qx + qy * qy);
        };
        for (const OnSegment& x : segments_at(index(u)))
            for (const OnSegment& y : segments_at(index(w))) {
                if (x.segment == y.segment) continue;
                const Segment &s = segments_[x.segment], &t = segments_[y.segment];
                bool shared_end = false;
                for (const auto& [z, p] : {std::pair{s.a, s.b}, std::pair{s.b, s.a}})
                    for (const auto& [z2, q] : {std::pair{t.a, t.b}, std::pair{t.b, t.a}}) {
                        if (!(z == z2)) continue;
                        shared_end = true;
                        if (small(p.x - z.x, p.y - z.y, q.x - z.x, q.y - z.y, false)) return true;
                    }
                if (!shared_end && meet(s, t) &&
                    small(s.b.x - s.a.x, s.b.y - s.a.y, t.b.x - t.a.x, t.b.y - t.a.y, true))
                    return true;
            }
        return false;
    }

    // Whether an end of t lies within rounding distance of s's interior (the
    // arrangement's rule for a vertex on a segment: 1e-12 of s's length
    // plus 16 ulps of the vertex's coordinates).
    static bool end_near(const Segment& s, const Segment& t) {
        const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
        const double length2 = dx * dx + dy * dy;
        if (length2 == 0) return false;
        for (const Point& p : {t.a, t.b}) {
            const double along = (p.x - s.a.x) * dx + (p.y - s.a.y) * dy;
            if (along <= 0 || along >= length2) continue;
            const double near =
                1e-12 * std::sqrt(length2) + 16 * 0x1p-53 * std::max(std::abs(p.x), std::abs(p.y));
            const double off = std::abs(geometry::orient2d(s.a, s.b, p));
            if (off <= near * std::sqrt(length2)) return true;
        }
        return false;
    }

    // Whether s and t have a point in common (exact), or one's end lies on
    // the other within rounding.
    static bool meet(const Segment& s, const Segment& t) {
        if (end_near(s, t) || end_near(t, s)) return true;
        const double o1 = geometry::orient2d(s.a, s.b, t.a), o2 = geometry::orient2d(s.a, s.b, t.b);
        const double o3 = geometry::orient2d(t.a, t.b, s.a), o4 = geometry::orient2d(t.a, t.b, s.b);
        if ((o1 > 0 && o2 > 0) || (o1 < 0 && o2 < 0) || (o3 > 0 && o4 > 0) || (o3 < 0 && o4 < 0))
            return false;
        if (o1 != 0 || o2 != 0) return true;
        // Collinear: their boxes overlap.
        return std::max(s.a.x, s.b.x) >= std::min(t.a.x, t.b.x) &&
               std::max(t.a.x, t.b.x) >= std::min(s.a.x, s.b.x) &&
               std::max(s.a.y, s.b.y) >= std::min(t.a.y, t.b.y) &&
               std::max(t.a.y, t.b.y) >= std::min(s.a.y, s.b.y);
    }

    // What the checks of each triangle ask for, worked out once.
    struct TriangleChecks {
        bool regional = false;  // the regions' area bounds apply
        bool field = false;     // the .area file's bounds apply
        bool faces = false;     // regions are needed, found through faces
        bool bounds = false;    // any angle or area bound applies
        double sine2 = 0;       // the angle bound's sine squared, less rounding
    };

    void check_regions_and_bounds() {
        TriangleChecks checks;
        checks.regional = options_.regional_area &&
                          std::any_of(input_.regions.begin(), input_.regions.end(),
                                      [](const InputRegion& r) { return r.max_area > 0; });
        checks.field = options_.area_field && input_.area_field.has_value();
        checks.faces = options_.region_attributes || checks.regional;
        checks.bounds = !(options_.min_angle <= 0 && options_.max_area <= 0 && !checks.regional &&
                          !checks.field);
        if (checks.faces) find_faces();
        const double sine = std::sin(options_.min_angle * std::numbers::pi / 180);
        checks.sine2 = sine * sine * (1 - 1e-9);
        const std::uint32_t end = mesh_.triangle_end();
        for (std::uint32_t i = 0; i < end; ++i) {
            const Triangle& t = mesh_.triangle(TriangleId{i});
            if (!t.live() || !stored(t.v[0]) || !stored(t.v[1]) || !stored(t.v[2])) continue;
            check_triangle(TriangleId{i}, t, checks);
        }
    }

    // One triangle: its attribute (-A), the user's test (-u), its area and
    // its smallest angle, in that order.
    void check_triangle(TriangleId id, const Triangle& t, const TriangleChecks& checks) {
        const std::uint32_t region = checks.faces ? region_of_face_[find(index(id))] : no_region;
        if (options_.region_attributes && region != ambiguous) check_attribute(t, region);
        if (options_.unsuitable && !exempt(id) && options_.unsuitable(id))
            problems_.add("the triangle {} is one triunsuitable() asks to refine", corners(t));
        if (!checks.bounds) return;
        check_area(id, t, region, checks);
        if (options_.min_angle <= 0) return;
        check_angle(id, t, checks.sine2);
    }

    std::string corners(const Triangle& t) const {
        return fmt::format("{} {} {}", at(mesh_.point(t.v[0])), at(mesh_.point(t.v[1])),
                           at(mesh_.point(t.v[2])));
    }

    // -A: the triangle carries the attribute of the region whose point
    // reaches it, 0 where none does.
    void check_attribute(const Triangle& t, std::uint32_t region) {
        const Point &a = mesh_.point(t.v[0]), &b = mesh_.point(t.v[1]), &c = mesh_.point(t.v[2]);
        // A sliver whose corners are within rounding of one line (an input
        // vertex on a hull edge or segment, as its decimal coordinates
        // meant) may be cut off as a face of its own here while the mesh
        // spreads its neighbour's region into it: it has no area to
        // disagree about.
        const double longest =
            std::max({geometry::squared_distance(a, b), geometry::squared_distance(b, c),
                      geometry::squared_distance(c, a)});
        if (std::abs(geometry::orient2d(a, b, c)) <= 1e-12 * longest) return;
        const double want = region == no_region ? 0.0 : input_.regions[region].attribute;
        if (t.region >= options_.attribute_of_region.size())
            problems_.add("the triangle {} has no attribute", corners(t));
        else if (!(options_.attribute_of_region[t.region] == want))
            problems_.add("the triangle {} has attribute {} where {} says {}", corners(t),
                          options_.attribute_of_region[t.region],
                          region == no_region ? std::string("no region")
                                              : fmt::format("region {}", region + options_.base),
                          want);
    }

    // The global area bound, the region's and the .area file's at the
    // triangle's centroid; not for triangles refinement gave up.
    void check_area(TriangleId id, const Triangle& t, std::uint32_t region,
                    const TriangleChecks& checks) {
        const Point &a = mesh_.point(t.v[0]), &b = mesh_.point(t.v[1]), &c = mesh_.point(t.v[2]);
        const double area = 0.5 * geometry::orient2d(a, b, c);
        const auto too_big = [&](double bound) {
            return bound > 0 && area > bound * (1 + 1e-9) && !exempt(id);
        };
        if (too_big(options_.max_area))
            problems_.add("the triangle {} has area {}, above the bound {}", corners(t), area,
                          options_.max_area);
        if (checks.regional && region < input_.regions.size() &&
            too_big(input_.regions[region].max_area))
            problems_.add("the triangle {} has area {}, above region {}'s bound {}", corners(t),
                          area, region + options_.base, input_.regions[region].max_area);
        if (checks.field) {
            const geometry::AreaField::Bound held =
                input_.area_field->at(geometry::centroid(a, b, c));
            if (too_big(held.area))
                problems_.add(
                    "the triangle {} has area {}, above the bound {} of input triangle {}, "
                    "which holds its centroid",
                    corners(t), area, held.area, held.triangle + options_.base);
        }
    }

    // The angle bound, except on triangles refinement gave up and at small
    // angles of the input's own.  sine2: the bound's sine squared.
    void check_angle(TriangleId id, const Triangle& t, double sine2) {
        const Point &a = mesh_.point(t.v[0]), &b = mesh_.point(t.v[1]), &c = mesh_.point(t.v[2]);
        const double twice_area = geometry::orient2d(a, b, c);
        // The smallest angle is opposite the shortest edge; its sine is
        // twice the area over the product of the other two edges.
        const double ab = geometry::squared_distance(a, b), bc = geometry::squared_distance(b, c),
                     ca = geometry::squared_distance(c, a);
        double product;
        VertexId u, w;
        if (ab <= bc && ab <= ca) {
            product = bc * ca, u = t.v[0], w = t.v[1];
        } else if (bc <= ca) {
            product = ab * ca, u = t.v[1], w = t.v[2];
        } else {
            product = ab * bc, u = t.v[2], w = t.v[0];
        }
        if (!(twice_area * twice_area < product * sine2)) return;
        if (exempt(id) || at_small_input_angle(u, w)) return;
        const double degrees =
            std::asin(std::min(1.0, twice_area / std::sqrt(product))) * 180 / std::numbers::pi;
        problems_.add("the triangle {} has an angle of {:.3g} degrees, below the bound {}",
                      corners(t), degrees, options_.min_angle);
    }

    const Mesh& mesh_;
    const InputGeometry& input_;
    const InputCheckOptions& options_;
    Problems problems_;

    std::vector<Segment> segments_;
    std::optional<geometry::SegmentGrid> grid_;
    std::vector<std::uint8_t> flags_;                            // by vertex id
    std::vector<std::pair<VertexId, VertexId>> boundary_edges_;  // triangle on the left
    std::vector<OnSegment> on_, by_vertex_;                      // by segment, by vertex
    std::vector<std::uint64_t> edges_;                           // between vertices on segments
    std::vector<std::uint32_t> vertices_;                        // on segments, by id
    std::vector<std::size_t> adjacency_start_;
    std::vector<std::uint32_t> adjacency_;  // compact numbers
    std::vector<std::uint32_t> position_;   // compact number -> station (follow)
    std::vector<Station> stations_;
    std::vector<std::uint32_t> exact_before_, reach_;
    std::optional<geometry::EdgeStrips> boundary_;
    std::vector<std::uint32_t> parent_, region_of_face_;
};

}  // namespace

std::vector<std::string> check_against_input(const Mesh& mesh, const InputGeometry& input,
                                             const InputCheckOptions& options) {
    return InputCheck(mesh, input, options).run();
}

}  // namespace gpdr::mesh
