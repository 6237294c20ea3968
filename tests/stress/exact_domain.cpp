#include "stress/exact_domain.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

#include "geometry/predicates.hpp"

namespace gpdr::stress {

namespace {

using geometry::orient2d;
using geometry::Point;

struct QPoint {
    mpq_class x, y;
};

struct QLess {
    bool operator()(const QPoint& p, const QPoint& q) const {
        return p.x < q.x || (p.x == q.x && p.y < q.y);
    }
};

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
    std::size_t find(std::size_t i) {
        while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
        return i;
    }
    void unite(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

private:
    std::vector<std::size_t> parent_;
};

// Whether p lies on segment a-b: exactly, or, as gpdr's documented rule
// has it (docs/architecture.md, "Crossings, overlaps and vertices on
// segments"), within rounding distance of its interior: 1e-12 of its length
// plus 16 ulps of p's coordinates.  Such a vertex was meant to be on the
// segment, and its decimal coordinates missed; the segment bends through it.
bool on_closed_segment(const Point& a, const Point& b, const Point& p) {
    const double o = orient2d(a, b, p);
    if (o == 0)
        return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
               std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double length2 = dx * dx + dy * dy;
    const double along = (p.x - a.x) * dx + (p.y - a.y) * dy;
    if (along <= 0 || along >= length2) return false;
    const double length = std::sqrt(length2);
    const double near = 1e-12 * length + 16 * 0x1p-53 * std::max(std::abs(p.x), std::abs(p.y));
    if (std::abs(o) > near * length) return false;
    const double to_a = (p.x - a.x) * (p.x - a.x) + (p.y - a.y) * (p.y - a.y);
    const double to_b = (p.x - b.x) * (p.x - b.x) + (p.y - b.y) * (p.y - b.y);
    return to_a > near * near && to_b > near * near;
}

bool opposite(double u, double v) { return (u > 0 && v < 0) || (u < 0 && v > 0); }

// Corners of the convex hull, counter-clockwise, no three collinear
// (Andrew's monotone chain with exact orientations).
std::vector<Point> convex_hull(std::vector<Point> points) {
    std::sort(points.begin(), points.end(), [](const Point& p, const Point& q) {
        return p.x < q.x || (p.x == q.x && p.y < q.y);
    });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) return points;
    std::vector<Point> hull;
    for (int pass = 0; pass < 2; ++pass) {
        const std::size_t start = hull.size();
        for (const Point& p : points) {
            while (hull.size() >= start + 2 && orient2d(hull[hull.size() - 2], hull.back(), p) <= 0)
                hull.pop_back();
            hull.push_back(p);
        }
        hull.pop_back();  // the first point of the other chain
        std::reverse(points.begin(), points.end());
    }
    return hull;
}

}  // namespace

ExactDomain::ExactDomain(const PolyFile& poly, bool convex_hull_enclosed) {
    const std::size_t vertex_count = poly.nodes.size();
    auto vertex = [&](std::uint32_t v) {
        return Point{poly.nodes.xy[2 * v], poly.nodes.xy[2 * v + 1]};
    };

    // Each segment bends through the vertices within rounding of it, so its
    // lines are the pieces between them, in order along it: crossings are
    // then found with the pieces, as gpdr finds them, and a crossing of the
    // straight segment a hair away from a piece's does not make a sliver face.
    for (std::size_t s = 0; s < poly.segments.size(); ++s) {
        const Point a = vertex(poly.segments.endpoints[2 * s]);
        const Point b = vertex(poly.segments.endpoints[2 * s + 1]);
        if (a == b) continue;
        std::vector<Point> stops;
        for (std::uint32_t v = 0; v < vertex_count; ++v) {
            const Point p = vertex(v);
            if (p != a && p != b && on_closed_segment(a, b, p)) stops.push_back(p);
        }
        const double dx = b.x - a.x, dy = b.y - a.y;
        std::sort(stops.begin(), stops.end(), [&](const Point& p, const Point& q) {
            return (p.x - a.x) * dx + (p.y - a.y) * dy < (q.x - a.x) * dx + (q.y - a.y) * dy;
        });
        stops.erase(std::unique(stops.begin(), stops.end()), stops.end());
        stops.push_back(b);
        Point from = a;
        for (const Point& to : stops) {
            lines_.push_back(Line{from.x, from.y, to.x, to.y, static_cast<int>(s)});
            from = to;
        }
    }
    if (convex_hull_enclosed) {
        std::vector<Point> all;
        for (std::uint32_t v = 0; v < vertex_count; ++v) all.push_back(vertex(v));
        const auto hull = convex_hull(all);
        const std::size_t edge_count = hull.size() == 2 ? 1 : hull.size() < 2 ? 0 : hull.size();
        for (std::size_t i = 0; i < edge_count; ++i) {
            const Point& a = hull[i];
            const Point& b = hull[(i + 1) % hull.size()];
            lines_.push_back(Line{a.x, a.y, b.x, b.y, -1});
        }
    }
    auto line_a = [&](std::size_t i) { return Point{lines_[i].ax, lines_[i].ay}; };
    auto line_b = [&](std::size_t i) { return Point{lines_[i].bx, lines_[i].by}; };

    // ------------------------------------------------ arrangement points
    std::map<QPoint, std::uint32_t, QLess> index;
    std::vector<QPoint> exact;
    auto add_point = [&](QPoint q) {
        const auto [it, inserted] = index.try_emplace(q, static_cast<std::uint32_t>(exact.size()));
        if (inserted) {
            points_.push_back(ArrangementPoint{q.x.get_d(), q.y.get_d()});
            exact.push_back(std::move(q));
        }
        return it->second;
    };
    std::vector<std::uint32_t> vertex_point(vertex_count);
    for (std::uint32_t v = 0; v < vertex_count; ++v) {
        const Point p = vertex(v);
        vertex_point[v] = add_point(QPoint{mpq_class(p.x), mpq_class(p.y)});
        points_[vertex_point[v]].input_vertex = true;
        points_[vertex_point[v]].x = p.x;
        points_[vertex_point[v]].y = p.y;
    }
    std::vector<std::vector<std::uint32_t>> on_line(lines_.size());
    for (std::size_t i = 0; i < lines_.size(); ++i)
        for (std::uint32_t v = 0; v < vertex_count; ++v)
            if (on_closed_segment(line_a(i), line_b(i), vertex(v)))
                on_line[i].push_back(vertex_point[v]);
    for (std::size_t i = 0; i < lines_.size(); ++i) {
        for (std::size_t j = i + 1; j < lines_.size(); ++j) {
            const Point ai = line_a(i), bi = line_b(i), aj = line_a(j), bj = line_b(j);
            if (!opposite(orient2d(ai, bi, aj), orient2d(ai, bi, bj)) ||
                !opposite(orient2d(aj, bj, ai), orient2d(aj, bj, bi)))
                continue;
            const mpq_class aix(ai.x), aiy(ai.y), ajx(aj.x), ajy(aj.y);
            const mpq_class dix = mpq_class(bi.x) - aix, diy = mpq_class(bi.y) - aiy;
            const mpq_class djx = mpq_class(bj.x) - ajx, djy = mpq_class(bj.y) - ajy;
            const mpq_class t = ((ajx - aix) * djy - (ajy - aiy) * djx) / (dix * djy - diy * djx);
            const std::uint32_t id = add_point(QPoint{aix + t * dix, aiy + t * diy});
            points_[id].crossing = true;
            on_line[i].push_back(id);
            on_line[j].push_back(id);
        }
    }

    // ------------------------------------------------ edges
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> edge_index;
    const QLess less;
    for (std::size_t i = 0; i < lines_.size(); ++i) {
        auto& ids = on_line[i];
        std::sort(ids.begin(), ids.end(),
                  [&](std::uint32_t p, std::uint32_t q) { return less(exact[p], exact[q]); });
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        for (std::size_t k = 0; k + 1 < ids.size(); ++k) {
            const auto [it, inserted] = edge_index.try_emplace({ids[k], ids[k + 1]}, edges_.size());
            if (inserted) edges_.push_back(ArrangementEdge{ids[k], ids[k + 1], {}, false});
            edges_[it->second].lines.push_back(static_cast<int>(i));
        }
    }

    // ------------------------------------------------ slabs
    std::vector<mpq_class> xs;
    for (const QPoint& q : exact) xs.push_back(q.x);
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    const std::size_t slab_count = xs.empty() ? 0 : xs.size() - 1;
    auto x_index = [&](const mpq_class& x) {
        return static_cast<std::size_t>(std::lower_bound(xs.begin(), xs.end(), x) - xs.begin());
    };
    std::vector<mpq_class> slope(edges_.size());
    std::vector<std::vector<std::uint32_t>> slab_edges(slab_count);
    std::vector<std::vector<std::uint32_t>> verticals(xs.size());
    for (std::uint32_t e = 0; e < edges_.size(); ++e) {
        const QPoint &a = exact[edges_[e].a], &b = exact[edges_[e].b];
        if (a.x == b.x) {
            verticals[x_index(a.x)].push_back(e);
            continue;
        }
        slope[e] = (b.y - a.y) / (b.x - a.x);
        for (std::size_t k = x_index(a.x); k < x_index(b.x); ++k) slab_edges[k].push_back(e);
    }
    auto y_at = [&](std::uint32_t e, const mpq_class& x) -> mpq_class {
        const QPoint& a = exact[edges_[e].a];
        return a.y + (x - a.x) * slope[e];
    };
    for (std::size_t k = 0; k < slab_count; ++k) {
        const mpq_class mid = (xs[k] + xs[k + 1]) / 2;
        std::vector<std::pair<mpq_class, std::uint32_t>> keyed;
        for (std::uint32_t e : slab_edges[k]) keyed.emplace_back(y_at(e, mid), e);
        std::sort(keyed.begin(), keyed.end());
        for (std::size_t j = 0; j < keyed.size(); ++j) slab_edges[k][j] = keyed[j].second;
    }

    // Node 0 is everything outside the slabs, and joins every unbounded
    // trapezoid; slab k's trapezoids are base[k] .. base[k] + edges.
    std::vector<std::size_t> base(slab_count);
    std::size_t node_count = 1;
    for (std::size_t k = 0; k < slab_count; ++k) {
        base[k] = node_count;
        node_count += slab_edges[k].size() + 1;
    }
    UnionFind faces(node_count);
    for (std::size_t k = 0; k < slab_count; ++k) {
        faces.unite(base[k], 0);
        faces.unite(base[k] + slab_edges[k].size(), 0);
    }
    // Across the line x = xs[k], from slab k - 1 to slab k.
    for (std::size_t k = 0; k < xs.size(); ++k) {
        std::vector<mpq_class> left, right, breaks;
        if (k > 0)
            for (std::uint32_t e : slab_edges[k - 1]) left.push_back(y_at(e, xs[k]));
        if (k < slab_count)
            for (std::uint32_t e : slab_edges[k]) right.push_back(y_at(e, xs[k]));
        std::vector<std::pair<mpq_class, mpq_class>> walls;
        for (std::uint32_t e : verticals[k]) {
            walls.emplace_back(exact[edges_[e].a].y, exact[edges_[e].b].y);
            breaks.push_back(walls.back().first);
            breaks.push_back(walls.back().second);
        }
        breaks.insert(breaks.end(), left.begin(), left.end());
        breaks.insert(breaks.end(), right.begin(), right.end());
        std::sort(breaks.begin(), breaks.end());
        breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
        auto node = [&](const std::vector<mpq_class>& bounds, bool exists, std::size_t slab,
                        std::size_t t) -> std::size_t {
            if (!exists) return 0;
            if (t == 0) return base[slab];
            const auto below = std::upper_bound(bounds.begin(), bounds.end(), breaks[t - 1]);
            return base[slab] + static_cast<std::size_t>(below - bounds.begin());
        };
        // Interval t lies between breaks[t - 1] and breaks[t] (unbounded at the ends).
        for (std::size_t t = 0; t <= breaks.size(); ++t) {
            bool walled = false;
            if (t > 0 && t < breaks.size())
                for (const auto& [lo, hi] : walls)
                    if (lo <= breaks[t - 1] && breaks[t] <= hi) walled = true;
            if (walled) continue;
            faces.unite(node(left, k > 0, k - 1, t), node(right, k < slab_count, k, t));
        }
    }

    // Where a point is: its trapezoid, or -1 on an edge.
    auto locate = [&](const mpq_class& x, const mpq_class& y) -> long {
        if (slab_count == 0 || x < xs.front() || x > xs.back()) return 0;
        const std::size_t i = x_index(x);
        if (i < xs.size() && xs[i] == x)
            for (std::uint32_t e : verticals[i]) {
                const mpq_class &lo = exact[edges_[e].a].y, &hi = exact[edges_[e].b].y;
                if (lo <= y && y <= hi) return -1;
            }
        std::size_t k =
            static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin()) - 1;
        if (k == slab_count) --k;
        std::size_t below = 0;
        for (std::uint32_t e : slab_edges[k]) {
            const mpq_class ye = y_at(e, x);
            if (ye == y) return -1;
            if (ye < y) ++below;
        }
        return static_cast<long>(base[k] + below);
    };

    // ------------------------------------------------ faces and the domain
    std::vector<long> face_of(node_count, -1);
    const std::size_t outside = faces.find(0);
    for (std::size_t n = 0; n < node_count; ++n) {
        const std::size_t root = faces.find(n);
        if (face_of[root] < 0) {
            face_of[root] = static_cast<long>(faces_.size());
            faces_.push_back(Face{0, root != outside, {}});
        }
        face_of[n] = face_of[root];
    }
    for (std::size_t k = 0; k < slab_count; ++k) {
        const auto& es = slab_edges[k];
        for (std::size_t j = 1; j < es.size(); ++j) {
            const mpq_class left = y_at(es[j], xs[k]) - y_at(es[j - 1], xs[k]);
            const mpq_class right = y_at(es[j], xs[k + 1]) - y_at(es[j - 1], xs[k + 1]);
            const mpq_class area = (xs[k + 1] - xs[k]) * (left + right) / 2;
            faces_[static_cast<std::size_t>(face_of[base[k] + j])].area += area.get_d();
        }
    }
    for (std::size_t h = 0; h < poly.holes.size() / 2; ++h) {
        const long n = locate(mpq_class(poly.holes[2 * h]), mpq_class(poly.holes[2 * h + 1]));
        if (n >= 0)
            faces_[static_cast<std::size_t>(face_of[static_cast<std::size_t>(n)])].in_domain =
                false;
    }
    for (const Region& region : poly.regions) {
        const long n = locate(mpq_class(region.x), mpq_class(region.y));
        region_faces_.push_back(n < 0 ? -1 : face_of[static_cast<std::size_t>(n)]);
        if (n >= 0)
            faces_[static_cast<std::size_t>(face_of[static_cast<std::size_t>(n)])]
                .region_attributes.push_back(region.attribute);
    }
    auto node_in_domain = [&](long n) {
        return n >= 0 &&
               faces_[static_cast<std::size_t>(face_of[static_cast<std::size_t>(n)])].in_domain;
    };

    std::vector<bool> touches_domain(points_.size(), false), has_edge(points_.size(), false);
    for (std::uint32_t e = 0; e < edges_.size(); ++e) {
        ArrangementEdge& edge = edges_[e];
        const QPoint &a = exact[edge.a], &b = exact[edge.b];
        if (a.x != b.x) {
            const std::size_t k = x_index(a.x);
            const auto& es = slab_edges[k];
            const auto j =
                static_cast<std::size_t>(std::find(es.begin(), es.end(), e) - es.begin());
            edge.in_domain = node_in_domain(static_cast<long>(base[k] + j)) ||
                             node_in_domain(static_cast<long>(base[k] + j + 1));
        } else {
            const std::size_t k = x_index(a.x);
            const mpq_class mid = (a.y + b.y) / 2;
            auto side = [&](std::size_t slab) {
                std::size_t below = 0;
                for (std::uint32_t f : slab_edges[slab])
                    if (y_at(f, a.x) < mid) ++below;
                return static_cast<long>(base[slab] + below);
            };
            edge.in_domain = (k > 0 && node_in_domain(side(k - 1))) ||
                             (k < slab_count && node_in_domain(side(k)));
        }
        has_edge[edge.a] = has_edge[edge.b] = true;
        if (edge.in_domain) touches_domain[edge.a] = touches_domain[edge.b] = true;
    }
    for (std::uint32_t v = 0; v < vertex_count; ++v) {
        const std::uint32_t p = vertex_point[v];
        const bool required =
            has_edge[p] ? touches_domain[p] : node_in_domain(locate(exact[p].x, exact[p].y));
        if (required) required_.push_back(v);
    }
}

double ExactDomain::area() const {
    double total = 0;
    for (const Face& face : faces_)
        if (face.in_domain) total += face.area;
    return total;
}

}  // namespace gpdr::stress
