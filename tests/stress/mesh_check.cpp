#include "stress/mesh_check.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <unordered_map>
#include <utility>

#include <gpdr/io.hpp>

#include "geometry/predicates.hpp"

namespace gpdr::stress {

namespace {

using geometry::orient2d;
using geometry::Point;

std::string format(const char* pattern, auto... values) {
    char text[400];
    std::snprintf(text, sizeof text, pattern, values...);
    return text;
}

// Distance from p to the closed segment ab, in long double.
long double distance_to_segment(double px, double py, const Line& line) {
    const long double dx = static_cast<long double>(line.bx) - line.ax;
    const long double dy = static_cast<long double>(line.by) - line.ay;
    const long double ux = static_cast<long double>(px) - line.ax;
    const long double uy = static_cast<long double>(py) - line.ay;
    long double t = (ux * dx + uy * dy) / (dx * dx + dy * dy);
    t = std::clamp(t, 0.0L, 1.0L);
    return std::hypot(ux - t * dx, uy - t * dy);
}

// Reports at most `limit` problems of one kind, then how many more there were.
class Problems {
public:
    void add(const std::string& kind, std::string text) {
        auto& [count, shown] = kinds_[kind];
        if (++count <= limit) list_.push_back(std::move(text));
    }
    std::vector<std::string> finish() {
        for (const auto& [kind, counts] : kinds_)
            if (counts.first > limit)
                list_.push_back(format("... and %zu more: %s", counts.first - limit, kind.c_str()));
        return std::move(list_);
    }

private:
    static constexpr std::size_t limit = 3;
    std::map<std::string, std::pair<std::size_t, std::size_t>> kinds_;
    std::vector<std::string> list_;
};

struct PairHash {
    std::size_t operator()(const std::pair<double, double>& p) const {
        return std::hash<double>()(p.first) * 31 + std::hash<double>()(p.second);
    }
};

}  // namespace

WrittenMesh read_written_mesh(const std::string& stem) {
    WrittenMesh mesh;
    const auto nodes = io::read_node(stem + ".node", ignore_warning);
    mesh.xy = nodes.data.xy;
    const auto ele = io::read_ele(stem + ".ele", nodes.base, nodes.data.size(), ignore_warning);
    const std::size_t per = ele.data.corners_per_triangle;
    for (std::size_t t = 0; t < ele.data.size(); ++t) {
        for (std::size_t k = 0; k < 3; ++k) mesh.triangles.push_back(ele.data.corners[t * per + k]);
        if (ele.data.attribute_count > 0)
            mesh.attributes.push_back(ele.data.attributes[t * ele.data.attribute_count]);
    }
    if (std::filesystem::exists(stem + ".poly"))
        mesh.segments = io::read_poly(stem + ".poly", ignore_warning).data.segments.endpoints;
    return mesh;
}

std::vector<std::string> check_mesh(const PolyFile& input, const ExactDomain& domain,
                                    const WrittenMesh& mesh, const CheckSettings& settings) {
    Problems problems;
    const auto& lines = domain.lines();
    double largest = 0;
    for (double c : input.nodes.xy) largest = std::max(largest, std::abs(c));
    const double tolerance = 16 * DBL_EPSILON * largest;

    const std::size_t triangle_count = mesh.triangles.size() / 3;
    auto point = [&](std::uint32_t v) { return Point{mesh.xy[2 * v], mesh.xy[2 * v + 1]}; };
    auto corner = [&](std::size_t t, std::size_t k) { return mesh.triangles[3 * t + k]; };
    auto on_line = [&](std::uint32_t v, const Line& line) {
        return distance_to_segment(mesh.xy[2 * v], mesh.xy[2 * v + 1], line) <= tolerance;
    };
    auto on_some_line = [&](std::uint32_t u, std::uint32_t v) {
        return std::any_of(lines.begin(), lines.end(),
                           [&](const Line& line) { return on_line(u, line) && on_line(v, line); });
    };
    auto where = [&](std::uint32_t v) {
        return format("%u (%.17g, %.17g)", v + 1, mesh.xy[2 * v], mesh.xy[2 * v + 1]);
    };

    // ------------------------------------------------ a valid triangulation
    std::unordered_map<std::uint64_t, std::size_t> directed;
    std::vector<std::vector<std::uint32_t>> neighbours(mesh.xy.size() / 2);
    std::unordered_map<std::pair<double, double>, std::uint32_t, PairHash> used;
    for (std::size_t t = 0; t < triangle_count; ++t) {
        if (orient2d(point(corner(t, 0)), point(corner(t, 1)), point(corner(t, 2))) <= 0)
            problems.add("triangles clockwise or flat",
                         format("triangle %zu is clockwise or flat", t + 1));
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t u = corner(t, k), v = corner(t, (k + 1) % 3);
            const auto [it, inserted] = directed.try_emplace((std::uint64_t(u) << 32) | v, t);
            if (!inserted)
                problems.add("triangles overlapping",
                             format("triangles %zu and %zu overlap along edge %u-%u",
                                    it->second + 1, t + 1, u + 1, v + 1));
            neighbours[u].push_back(v);
            neighbours[v].push_back(u);
            const auto [at, fresh] = used.try_emplace({mesh.xy[2 * u], mesh.xy[2 * u + 1]}, u);
            if (!fresh && at->second != u)
                problems.add("vertices coinciding",
                             format("vertices %u and %u coincide", at->second + 1, u + 1));
        }
    }

    // ------------------------------------------------ boundary and segments on the input
    for (const auto& [key, t] : directed) {
        const auto u = static_cast<std::uint32_t>(key >> 32), v = static_cast<std::uint32_t>(key);
        if (directed.count((std::uint64_t(v) << 32) | u)) continue;
        if (!on_some_line(u, v))
            problems.add("boundary edges off the input",
                         format("boundary edge %s - %s lies on no input segment%s",
                                where(u).c_str(), where(v).c_str(),
                                lines.empty() || lines.back().segment >= 0 ? "" : " or hull edge"));
    }
    for (std::size_t s = 0; s < mesh.segments.size() / 2; ++s) {
        const std::uint32_t u = mesh.segments[2 * s], v = mesh.segments[2 * s + 1];
        if (!on_some_line(u, v))
            problems.add("output segments off the input",
                         format("output segment %zu (%s - %s) lies on no input segment", s + 1,
                                where(u).c_str(), where(v).c_str()));
        else if (!directed.count((std::uint64_t(u) << 32) | v) &&
                 !directed.count((std::uint64_t(v) << 32) | u))
            problems.add("output segments not mesh edges",
                         format("output segment %zu (%s - %s) is not a mesh edge", s + 1,
                                where(u).c_str(), where(v).c_str()));
    }

    // ------------------------------------------------ input vertices and coverage
    for (std::uint32_t v : domain.required_vertices())
        if (!used.count({input.nodes.xy[2 * v], input.nodes.xy[2 * v + 1]}))
            problems.add("input vertices missing",
                         format("input vertex %u (%.17g, %.17g) lies in the domain but is not in "
                                "the mesh",
                                v + 1, input.nodes.xy[2 * v], input.nodes.xy[2 * v + 1]));
    const auto& points = domain.points();
    std::vector<long> mesh_vertex(points.size(), -2);  // -2: not looked up; -1: none
    auto vertex_at = [&](std::uint32_t p) {
        if (mesh_vertex[p] != -2) return mesh_vertex[p];
        long found = -1;
        if (points[p].input_vertex) {
            const auto it = used.find({points[p].x, points[p].y});
            if (it != used.end()) found = it->second;
        } else {
            long double best = tolerance;
            for (const auto& [xy, v] : used) {
                const long double d = std::hypot(static_cast<long double>(xy.first) - points[p].x,
                                                 static_cast<long double>(xy.second) - points[p].y);
                if (d <= best) best = d, found = v;
            }
            if (found < 0)
                problems.add("crossings missing",
                             format("the crossing at (%.17g, %.17g) is not a mesh vertex",
                                    points[p].x, points[p].y));
        }
        return mesh_vertex[p] = found;
    };
    for (const ArrangementEdge& edge : domain.edges()) {
        if (!edge.in_domain) continue;
        const long from = vertex_at(edge.a), to = vertex_at(edge.b);
        if (from < 0 || to < 0) continue;
        const Line& line = lines[static_cast<std::size_t>(edge.lines.front())];
        const long double dx = static_cast<long double>(points[edge.b].x) - points[edge.a].x;
        const long double dy = static_cast<long double>(points[edge.b].y) - points[edge.a].y;
        auto along = [&](long v) {
            return (static_cast<long double>(mesh.xy[2 * v]) - points[edge.a].x) * dx +
                   (static_cast<long double>(mesh.xy[2 * v + 1]) - points[edge.a].y) * dy;
        };
        // A chain of mesh edges from `from` to `to` through vertices on the
        // segment, each further along it than the last: a depth-first search,
        // since near a cluster of rounded crossing points a step may lead
        // nowhere.  A vertex within rounding of the end may lie a hair past it.
        const long double end = along(to) + tolerance * std::hypot(dx, dy);
        std::vector<long> stack{from};
        std::vector<long> seen{from};
        long at = -1;
        while (!stack.empty() && at != to) {
            at = stack.back();
            stack.pop_back();
            if (at == to) break;
            for (std::uint32_t n : neighbours[static_cast<std::size_t>(at)]) {
                const long next = n;
                if (std::find(seen.begin(), seen.end(), next) != seen.end()) continue;
                const long double a = along(next);
                if (next != to && (a <= along(at) || a >= end || !on_line(n, line))) continue;
                seen.push_back(next);
                stack.push_back(next);
            }
        }
        if (at != to) {
            const int s = line.segment;
            problems.add(
                "segments not covered",
                format("%s %d from (%.17g, %.17g) to (%.17g, %.17g) is not covered by "
                       "mesh edges",
                       s >= 0 ? "segment" : "hull edge", s >= 0 ? s + 1 : 0, points[edge.a].x,
                       points[edge.a].y, points[edge.b].x, points[edge.b].y));
        }
    }

    // ------------------------------------------------ area, holes and regions
    auto area_of = [&](std::size_t t) {
        const Point a = point(corner(t, 0)), b = point(corner(t, 1)), c = point(corner(t, 2));
        return 0.5L *
               ((static_cast<long double>(b.x) - a.x) * (static_cast<long double>(c.y) - a.y) -
                (static_cast<long double>(c.x) - a.x) * (static_cast<long double>(b.y) - a.y));
    };
    long double mesh_area = 0;
    std::map<double, long double> area_by_attribute;
    for (std::size_t t = 0; t < triangle_count; ++t) {
        mesh_area += area_of(t);
        if (settings.attributes && t < mesh.attributes.size())
            area_by_attribute[mesh.attributes[t]] += area_of(t);
    }
    double low_x = 0, high_x = 0, low_y = 0, high_y = 0;
    for (std::size_t v = 0; v < input.nodes.size(); ++v) {
        const double x = input.nodes.xy[2 * v], y = input.nodes.xy[2 * v + 1];
        if (v == 0 || x < low_x) low_x = x;
        if (v == 0 || x > high_x) high_x = x;
        if (v == 0 || y < low_y) low_y = y;
        if (v == 0 || y > high_y) high_y = y;
    }
    const double diameter = std::hypot(high_x - low_x, high_y - low_y);
    std::size_t crossing_count = 0;
    for (const ArrangementPoint& p : points) crossing_count += p.crossing;
    // Each rounded crossing point moves the boundary by at most `tolerance`
    // along a length of at most `diameter`.
    const double area_tolerance =
        1e-12 * diameter * diameter + 4.0 * double(crossing_count + 1) * tolerance * diameter;
    if (std::abs(static_cast<double>(mesh_area) - domain.area()) > area_tolerance)
        problems.add("area", format("the mesh's area is %.17g, the domain's %.17g",
                                    static_cast<double>(mesh_area), domain.area()));

    auto inside_triangle = [&](double x, double y) -> long {
        const Point p{x, y};
        for (std::size_t t = 0; t < triangle_count; ++t)
            if (orient2d(point(corner(t, 0)), point(corner(t, 1)), p) > 0 &&
                orient2d(point(corner(t, 1)), point(corner(t, 2)), p) > 0 &&
                orient2d(point(corner(t, 2)), point(corner(t, 0)), p) > 0)
                return static_cast<long>(t);
        return -1;
    };
    for (std::size_t h = 0; h < input.holes.size() / 2; ++h) {
        const long t = inside_triangle(input.holes[2 * h], input.holes[2 * h + 1]);
        if (t >= 0)
            problems.add("holes not empty",
                         format("hole %zu (%.17g, %.17g) lies in triangle %ld", h + 1,
                                input.holes[2 * h], input.holes[2 * h + 1], t + 1));
    }
    if (settings.attributes) {
        // The triangle around each region point carries its face's attribute.
        for (std::size_t r = 0; r < input.regions.size(); ++r) {
            const long f = domain.region_faces()[r];
            if (f < 0 || !domain.faces()[static_cast<std::size_t>(f)].in_domain) continue;
            const double wanted =
                domain.faces()[static_cast<std::size_t>(f)].region_attributes.back();
            const long t = inside_triangle(input.regions[r].x, input.regions[r].y);
            if (t >= 0 && static_cast<std::size_t>(t) < mesh.attributes.size() &&
                mesh.attributes[static_cast<std::size_t>(t)] != wanted)
                problems.add(
                    "region attributes",
                    format("triangle %ld around region point %zu has attribute %g, not %g", t + 1,
                           r + 1, mesh.attributes[static_cast<std::size_t>(t)], wanted));
        }
        std::map<double, long double> expected;
        for (const Face& face : domain.faces())
            if (face.in_domain)
                expected[face.region_attributes.empty() ? 0.0 : face.region_attributes.back()] +=
                    face.area;
        for (const auto& [attribute, area] : area_by_attribute) expected.try_emplace(attribute, 0);
        for (const auto& [attribute, area] : expected) {
            const long double got =
                area_by_attribute.count(attribute) ? area_by_attribute[attribute] : 0;
            if (std::abs(static_cast<double>(got - area)) > area_tolerance)
                problems.add(
                    "region attributes",
                    format("triangles with attribute %g cover %.17g, the regions with "
                           "it %.17g",
                           attribute, static_cast<double>(got), static_cast<double>(area)));
        }
    }

    // ------------------------------------------------ angles
    if (settings.min_angle > 0) {
        // Whether input segments (or hull edges) meet at v at less than 60 degrees.
        auto sharp_input_angle = [&](std::uint32_t v) {
            std::vector<std::pair<long double, long double>> directions;
            const long double x = mesh.xy[2 * v], y = mesh.xy[2 * v + 1];
            for (const Line& line : lines) {
                if (!on_line(v, line)) continue;
                const bool at_a = std::hypot(x - line.ax, y - line.ay) <= tolerance;
                const bool at_b = std::hypot(x - line.bx, y - line.by) <= tolerance;
                const long double dx = static_cast<long double>(line.bx) - line.ax;
                const long double dy = static_cast<long double>(line.by) - line.ay;
                if (!at_b) directions.emplace_back(dx, dy);
                if (!at_a) directions.emplace_back(-dx, -dy);
            }
            for (std::size_t i = 0; i < directions.size(); ++i)
                for (std::size_t j = i + 1; j < directions.size(); ++j) {
                    const auto [ax, ay] = directions[i];
                    const auto [bx, by] = directions[j];
                    const long double angle =
                        std::atan2(std::abs(ax * by - ay * bx), ax * bx + ay * by);
                    if (angle < std::numbers::pi_v<long double> / 3) return true;
                }
            return false;
        };
        // Whether the edge pq spans an input angle below 60 degrees: p and q
        // lie on two input segments that meet (at an end or where they cross)
        // at a point x where the angle p-x-q is below 60 degrees, at the same
        // distance from x (within 1%).  Splitting such an edge would only
        // make a smaller copy of the triangle, so Ruppert's algorithm, as
        // Triangle runs it, leaves these triangles.
        auto spans_sharp_input_angle = [&](std::uint32_t p, std::uint32_t q) {
            const long double px = mesh.xy[2 * p], py = mesh.xy[2 * p + 1];
            const long double qx = mesh.xy[2 * q], qy = mesh.xy[2 * q + 1];
            for (const Line& one : lines) {
                if (!on_line(p, one)) continue;
                for (const Line& other : lines) {
                    if (&one == &other || !on_line(q, other)) continue;
                    const long double dx = static_cast<long double>(one.bx) - one.ax;
                    const long double dy = static_cast<long double>(one.by) - one.ay;
                    const long double ex = static_cast<long double>(other.bx) - other.ax;
                    const long double ey = static_cast<long double>(other.by) - other.ay;
                    const long double denominator = dx * ey - dy * ex;
                    if (denominator == 0) continue;
                    const long double fx = static_cast<long double>(other.ax) - one.ax;
                    const long double fy = static_cast<long double>(other.ay) - one.ay;
                    const long double t = (fx * ey - fy * ex) / denominator;
                    const long double u = (fx * dy - fy * dx) / denominator;
                    if (t < -1e-9L || t > 1 + 1e-9L || u < -1e-9L || u > 1 + 1e-9L) continue;
                    const long double xx = one.ax + t * dx, xy = one.ay + t * dy;
                    const long double ax = px - xx, ay = py - xy, bx = qx - xx, by = qy - xy;
                    const long double to_p = std::hypot(ax, ay), to_q = std::hypot(bx, by);
                    if (to_p <= tolerance || to_q <= tolerance ||
                        std::abs(to_p - to_q) > 0.01L * std::max(to_p, to_q))
                        continue;
                    if (std::atan2(std::abs(ax * by - ay * bx), ax * bx + ay * by) <
                        std::numbers::pi_v<long double> / 3)
                        return true;
                }
            }
            return false;
        };
        std::size_t bad = 0;
        double worst = 180;
        std::uint32_t worst_at = 0;
        // Counting stops a little past the allowance: a mesh with a million
        // poor triangles is wrong without counting them all.
        const std::size_t enough = settings.left_by_precision + 1000;
        for (std::size_t t = 0; t < triangle_count && bad <= enough; ++t) {
            bool counted = false;
            for (std::size_t k = 0; k < 3 && !counted; ++k) {
                const std::uint32_t v = corner(t, k);
                const Point p = point(v), q = point(corner(t, (k + 1) % 3)),
                            r = point(corner(t, (k + 2) % 3));
                const long double ux = static_cast<long double>(q.x) - p.x,
                                  uy = static_cast<long double>(q.y) - p.y;
                const long double wx = static_cast<long double>(r.x) - p.x,
                                  wy = static_cast<long double>(r.y) - p.y;
                const double angle =
                    static_cast<double>(std::atan2(std::abs(ux * wy - uy * wx), ux * wx + uy * wy) *
                                        180 / std::numbers::pi_v<long double>);
                if (angle >= settings.min_angle - 1e-5 || sharp_input_angle(v) ||
                    (settings.excuse_spanning_edges &&
                     spans_sharp_input_angle(corner(t, (k + 1) % 3), corner(t, (k + 2) % 3))))
                    continue;
                ++bad;
                counted = true;
                if (angle < worst) worst = angle, worst_at = v;
            }
        }
        if (bad > settings.left_by_precision)
            problems.add(
                "angles",
                format("%s%zu triangles have an angle below %g degrees not at an input "
                       "angle below 60 (the smallest, %.3g, at vertex %s); %zu were "
                       "reported left by precision",
                       bad > enough ? "more than " : "", bad - (bad > enough), settings.min_angle,
                       worst, where(worst_at).c_str(), settings.left_by_precision));
    }
    return problems.finish();
}

}  // namespace gpdr::stress
