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

// A live triangle with corner v for every vertex v (no_triangle for a
// vertex in none).
std::vector<TriangleId> corner_triangles(const Mesh& mesh) {
    const std::uint32_t vertex_end = mesh.vertex_end();
    std::vector<TriangleId> corner(vertex_end, no_triangle);
    for (std::uint32_t i = 0; i < mesh.triangle_end(); ++i) {
        const Triangle& t = mesh.triangle(TriangleId{i});
        if (!t.live()) continue;
        for (VertexId v : t.v)
            if (index(v) < vertex_end) corner[index(v)] = TriangleId{i};
    }
    return corner;
}

// The depth-first walk along one piece at a time (conformity.hpp).
class PieceWalk {
public:
    explicit PieceWalk(const Mesh& mesh)
        : mesh_(mesh), corner_(corner_triangles(mesh)), visited_(mesh.vertex_end(), 0) {}

    // Whether the subsegments of piece s (a-b, a != b) lead from a to b,
    // the parts outside the mesh aside; if not, `stuck` is the vertex where
    // the direction toward b enters a triangle but no subsegment goes on
    // (no_vertex when there is none: then a is to blame).
    bool conforms(std::uint32_t s, VertexId a, VertexId b, VertexId& stuck) {
        s_ = s;
        a_ = a;
        b_ = b;
        const Point& pa = mesh_.point(a);
        const Point& pb = mesh_.point(b);
        length_squared_ = (pb.x - pa.x) * (pb.x - pa.x) + (pb.y - pa.y) * (pb.y - pa.y);
        // Depth-first: near-coincident rounded vertices can offer two
        // flagged edges along the segment, only one of which goes on.
        stack_.assign(1, a);
        touched_.clear();
        stuck = no_vertex;
        bool reached = false;
        while (!stack_.empty() && !reached) {
            const VertexId v = stack_.back();
            stack_.pop_back();
            if (visited_[index(v)]) continue;
            visited_[index(v)] = 1;
            touched_.push_back(v);
            if (v == b) {
                reached = true;
                break;
            }
            const Outlook seen = look_around(v);
            if (seen.moved) continue;
            if (seen.covered) {
                stuck = v;
                continue;
            }
            // The segment leaves the mesh at v: resume at the nearest vertex
            // further along that has a triangle.
            const VertexId resume = resume_point(v);
            if (resume == no_vertex) {
                reached = true;  // the rest of the segment was eaten
                break;
            }
            stack_.push_back(resume);
        }
        for (VertexId v : touched_) visited_[index(v)] = 0;
        return reached;
    }

private:
    // What the walk sees at a vertex.
    struct Outlook {
        bool covered = false;  // the direction toward b enters the mesh there
        bool moved = false;    // subsegments along the piece lead on (pushed)
    };

    // Pushes the far ends of the subsegments out of v that go on along the
    // piece.
    Outlook look_around(VertexId v) {
        Outlook seen;
        if (corner_[index(v)] == no_triangle) return seen;
        const Point& pa = mesh_.point(a_);
        const Point& pb = mesh_.point(b_);
        const Point& pv = mesh_.point(v);
        star(mesh_, corner_[index(v)], v, around_);
        for (TriangleId id : around_) {
            const Triangle& t = mesh_.triangle(id);
            const int i = t.corner_of(v);
            const VertexId c = t.v[next3(i)], d = t.v[prev3(i)];
            const double oc = orient2d(pv, mesh_.point(c), pb);
            const double od = orient2d(pv, mesh_.point(d), pb);
            if (oc > 0 && od < 0) seen.covered = true;
            const std::pair<VertexId, int> ends[2] = {{c, prev3(i)}, {d, next3(i)}};
            for (auto [w, k] : ends) {
                const Point& pw = mesh_.point(w);
                // A vertex joined to v by a subsegment recorded as part of
                // this piece may lie just off its line (refinement's split
                // points are rounded): any direction (the visited marks
                // stop cycles).  Others must be exactly on it and ahead.
                const SubsegmentInfo* info =
                    t.is_subsegment(k) ? mesh_.subsegments().find(v, w) : nullptr;
                const bool is_listed = info && info->segment == s_;
                const bool ahead = along(pv, pw, pa, pb) > 0;
                if (!is_listed && !ahead) continue;
                if (ahead && orient2d(pv, pw, pb) == 0) seen.covered = true;
                // So may a Steiner point within rounding of the line.
                const double o = orient2d(pa, pb, pw);
                const bool on =
                    is_listed || o == 0 ||
                    (mesh_.kind(w) == VertexKind::segment && std::abs(o) <= 1e-9 * length_squared_);
                if (!t.is_subsegment(k) || !on || visited_[index(w)]) continue;
                if (w != b_ && !is_listed && along(pw, pb, pa, pb) <= 0) continue;  // past the end
                stack_.push_back(w);
                seen.moved = true;
            }
        }
        return seen;
    }

    // The nearest unvisited vertex with a triangle exactly on the piece's
    // line, ahead of v and not past b (no_vertex if none).
    VertexId resume_point(VertexId v) const {
        const Point& pa = mesh_.point(a_);
        const Point& pb = mesh_.point(b_);
        const Point& pv = mesh_.point(v);
        VertexId resume = no_vertex;
        double best = 0;
        for (std::uint32_t w = 0; w < mesh_.vertex_end(); ++w) {
            if (corner_[w] == no_triangle || visited_[w]) continue;
            const Point& pw = mesh_.point(VertexId{w});
            if (orient2d(pa, pb, pw) != 0) continue;
            const double ahead = along(pv, pw, pa, pb);
            if (ahead <= 0 || (VertexId{w} != b_ && along(pw, pb, pa, pb) <= 0)) continue;
            if (resume == no_vertex || ahead < best) {
                resume = VertexId{w};
                best = ahead;
            }
        }
        return resume;
    }

    const Mesh& mesh_;
    std::vector<TriangleId> corner_;
    std::vector<std::uint8_t> visited_;
    std::vector<TriangleId> around_;
    std::vector<VertexId> stack_;
    std::vector<VertexId> touched_;  // visited in the current walk
    std::uint32_t s_ = 0;
    VertexId a_ = no_vertex, b_ = no_vertex;
    double length_squared_ = 0;
};

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
    PieceWalk walk(mesh);
    // The pieces the segments were cut into (arrangement.hpp): each is
    // straight between two vertices, and nothing lies on its interior.
    for (std::uint32_t s = 0; s < report.pieces.size(); ++s) {
        const SegmentPiece& piece = report.pieces[s];
        const VertexId a{piece.a}, b{piece.b};
        if (a == b) {
            add(fmt::format("segment {} has equal ends but was not reported as skipped", s));
            continue;
        }
        VertexId stuck = no_vertex;
        if (!walk.conforms(s, a, b, stuck))
            add(fmt::format("segment {} ({}-{}): no subsegment leaves vertex {} along it",
                            piece.segment, index(a), index(b),
                            index(stuck == no_vertex ? a : stuck)));
    }
    if (dropped > 0) problems.push_back(fmt::format("... and {} more problems", dropped));
    return problems;
}

}  // namespace gpdr::triangulate
