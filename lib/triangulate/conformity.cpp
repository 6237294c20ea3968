// The segment conformity check (see conformity.hpp).

#include "triangulate/conformity.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "geometry/predicates.hpp"

namespace gpdr::triangulate {

using namespace gpdr::mesh;
using geometry::orient2d;
using geometry::Point;

namespace {

double along(const Point& from, const Point& to, const Point& a, const Point& b) {
    return (to.x - from.x) * (b.x - a.x) + (to.y - from.y) * (b.y - a.y);
}

// The triangles around v (v at corner index), from a triangle with corner v.
void star(const Mesh& mesh, TriangleId t0, VertexId v, std::vector<TriangleId>& out) {
    out.clear();
    TriangleId t = t0;
    for (;;) {
        out.push_back(t);
        const Triangle& r = mesh.triangle(t);
        const EdgeRef n = r.n[next3(r.corner_of(v))];
        if (n.is_none()) break;
        t = n.triangle();
        if (t == t0) return;
    }
    t = t0;
    for (;;) {
        const Triangle& r = mesh.triangle(t);
        const EdgeRef n = r.n[prev3(r.corner_of(v))];
        if (n.is_none()) return;
        t = n.triangle();
        out.push_back(t);
    }
}

}  // namespace

std::vector<std::string> check_conformity(const Mesh& mesh, [[maybe_unused]] const Pslg& pslg,
                                          const CdtReport& report, std::size_t max_problems) {
    std::vector<std::string> problems;
    std::size_t dropped = 0;
    auto add = [&](std::string s) {
        if (problems.size() < max_problems)
            problems.push_back(std::move(s));
        else
            ++dropped;
    };

    const std::uint32_t vertex_end = mesh.vertex_end();
    std::vector<TriangleId> corner(vertex_end, no_triangle);
    for (std::uint32_t i = 0; i < mesh.triangle_end(); ++i) {
        const Triangle& t = mesh.triangle(TriangleId{i});
        if (!t.live()) continue;
        for (VertexId v : t.v)
            if (index(v) < vertex_end) corner[index(v)] = TriangleId{i};
    }

    std::vector<TriangleId> around;
    std::vector<std::uint8_t> visited(vertex_end, 0);
    // The pieces the segments were cut into (arrangement.hpp): each is
    // straight between two vertices, and nothing lies on its interior.
    for (std::size_t s = 0; s < report.pieces.size(); ++s) {
        const SegmentPiece& piece = report.pieces[s];
        const VertexId a{piece.a}, b{piece.b};
        if (a == b) {
            add(fmt::format("segment {} has equal ends but was not reported as skipped", s));
            continue;
        }
        const Point& pa = mesh.point(a);
        const Point& pb = mesh.point(b);
        const double length_squared = (pb.x - pa.x) * (pb.x - pa.x) + (pb.y - pa.y) * (pb.y - pa.y);
        // Depth-first: near-coincident rounded vertices can offer two
        // flagged edges along the segment, only one of which goes on.
        std::vector<VertexId> stack{a};
        std::vector<VertexId> touched;
        VertexId stuck = no_vertex;
        bool reached = false;
        while (!stack.empty() && !reached) {
            const VertexId v = stack.back();
            stack.pop_back();
            if (visited[index(v)]) continue;
            visited[index(v)] = 1;
            touched.push_back(v);
            if (v == b) {
                reached = true;
                break;
            }
            const Point& pv = mesh.point(v);
            bool covered = false;  // the direction toward b enters the mesh at v
            bool moved = false;
            if (corner[index(v)] != no_triangle) {
                star(mesh, corner[index(v)], v, around);
                for (TriangleId id : around) {
                    const Triangle& t = mesh.triangle(id);
                    const int i = t.corner_of(v);
                    const VertexId c = t.v[next3(i)], d = t.v[prev3(i)];
                    const double oc = orient2d(pv, mesh.point(c), pb);
                    const double od = orient2d(pv, mesh.point(d), pb);
                    if (oc > 0 && od < 0) covered = true;
                    const std::pair<VertexId, int> ends[2] = {{c, prev3(i)}, {d, next3(i)}};
                    for (auto [w, k] : ends) {
                        const Point& pw = mesh.point(w);
                        // A vertex joined to v by a subsegment recorded as
                        // part of this piece may lie just off its line
                        // (refinement's split points are rounded): any
                        // direction (the visited marks stop cycles).  Others
                        // must be exactly on it and ahead.
                        const SubsegmentInfo* info =
                            t.is_subsegment(k) ? mesh.subsegments().find(v, w) : nullptr;
                        const bool is_listed = info && info->segment == s;
                        const bool ahead = along(pv, pw, pa, pb) > 0;
                        if (!is_listed && !ahead) continue;
                        if (ahead && orient2d(pv, pw, pb) == 0) covered = true;
                        // So may a Steiner point within rounding of the line.
                        const double o = orient2d(pa, pb, pw);
                        const bool on = is_listed || o == 0 ||
                                        (mesh.kind(w) == VertexKind::segment &&
                                         std::abs(o) <= 1e-9 * length_squared);
                        if (!t.is_subsegment(k) || !on || visited[index(w)]) continue;
                        if (w != b && !is_listed && along(pw, pb, pa, pb) <= 0)
                            continue;  // past the end
                        stack.push_back(w);
                        moved = true;
                    }
                }
            }
            if (moved) continue;
            if (covered) {
                stuck = v;
                continue;
            }
            // The segment leaves the mesh at v: resume at the nearest vertex
            // further along that has a triangle.
            VertexId resume = no_vertex;
            double best = 0;
            for (std::uint32_t w = 0; w < vertex_end; ++w) {
                if (corner[w] == no_triangle || visited[w]) continue;
                const Point& pw = mesh.point(VertexId{w});
                if (orient2d(pa, pb, pw) != 0) continue;
                const double ahead = along(pv, pw, pa, pb);
                if (ahead <= 0 || (VertexId{w} != b && along(pw, pb, pa, pb) <= 0)) continue;
                if (resume == no_vertex || ahead < best) {
                    resume = VertexId{w};
                    best = ahead;
                }
            }
            if (resume == no_vertex) {
                reached = true;  // the rest of the segment was eaten
                break;
            }
            stack.push_back(resume);
        }
        for (VertexId v : touched) visited[index(v)] = 0;
        if (!reached)
            add(fmt::format("segment {} ({}-{}): no subsegment leaves vertex {} along it",
                            piece.segment, index(a), index(b),
                            index(stuck == no_vertex ? a : stuck)));
    }
    if (dropped > 0) problems.push_back(fmt::format("... and {} more problems", dropped));
    return problems;
}

}  // namespace gpdr::triangulate
