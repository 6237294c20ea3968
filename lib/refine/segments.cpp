// Subsegment helpers of refinement (see segments.hpp): encroachment,
// concentric-shell split points, the small-input-angle rule.

#include "refine/segments.hpp"

#include <cmath>

#include "geometry/constructions.hpp"

namespace gpdr::refine {

using geometry::Point;
using mesh::EdgeRef;
using mesh::VertexId;
using mesh::VertexKind;

bool subsegment_encroached(const mesh::Mesh& mesh, EdgeRef e, double lens) {
    const Point& a = mesh.point(mesh.origin(e));
    const Point& b = mesh.point(mesh.destination(e));
    if (encroaches(a, b, mesh.point(mesh.apex(e)), lens)) return true;
    const EdgeRef across = mesh.neighbour(e);
    return !across.is_none() && encroaches(a, b, mesh.point(mesh.apex(across)), lens);
}

bool acute_corner(const mesh::Mesh& mesh, EdgeRef e, VertexId a, VertexId b, double lens) {
    if (mesh.kind(a) != VertexKind::input) return false;
    const Point& pa = mesh.point(a);
    const Point& pb = mesh.point(b);
    const double bx = pb.x - pa.x, by = pb.y - pa.y;
    // cos(phi) > lens, without roots; a lens outside (0, 1) bounds at 90.
    const double bound = lens > 0.0 && lens < 1.0 ? lens * lens : 0.0;
    bool acute = false;
    for_each_edge_at(mesh, e.triangle(), a, [&](EdgeRef f) {
        if (acute || !mesh.triangle(f.triangle()).is_subsegment(f.edge())) return;
        const VertexId c = other_end(mesh, f, a);
        if (c == b) return;
        const Point& pc = mesh.point(c);
        const double cx = pc.x - pa.x, cy = pc.y - pa.y;
        // Below 90 degrees: positive dot product.  (A collinear continuation
        // through a has a negative one.)  Below 2 theta: also its square
        // above lens^2 |b|^2 |c|^2.
        const double dot = bx * cx + by * cy;
        if (dot > 0 && dot * dot > bound * (bx * bx + by * by) * (cx * cx + cy * cy)) acute = true;
    });
    return acute;
}

double split_parameter(const mesh::Mesh& mesh, EdgeRef e, double lens) {
    const VertexId a = mesh.origin(e), b = mesh.destination(e);
    const bool acute_a = acute_corner(mesh, e, a, b, lens);
    const bool acute_b = acute_corner(mesh, e, b, a, lens);
    if (acute_a == acute_b) return 0.5;
    const double length = std::sqrt(geometry::squared_distance(mesh.point(a), mesh.point(b)));
    // The power of two nearest (in ratio) to half the length: the split is
    // between 0.35 and 0.71 of the length from the acute corner.
    const double d = std::exp2(std::round(std::log2(0.5 * length)));
    double t = d / length;
    if (!(t > 0.25 && t < 0.75))
        t = 0.5;  // not finite, or far off (cannot happen for finite lengths)
    return acute_a ? t : 1.0 - t;
}

namespace {

// A flagged edge at segment vertex u, seen from a triangle around u, or none.
EdgeRef subsegment_at(const mesh::Mesh& mesh, mesh::TriangleId t, VertexId u) {
    EdgeRef found = EdgeRef::none();
    for_each_edge_at(mesh, t, u, [&](EdgeRef f) {
        if (found.is_none() && mesh.triangle(f.triangle()).is_subsegment(f.edge())) found = f;
    });
    return found;
}

// From u along the subsegment chain through x (u-x a subsegment, e an edge
// u-x) to the first vertex that is not a segment vertex; no_vertex if the
// chain is longer than `limit` or breaks.
// The subsegment at x that continues u -> x most nearly straight (split
// points are rounded, so not exactly collinear): its far end, or no_vertex
// when none turns by less than about 8 degrees.  `t` has corner x.
VertexId continuation(const mesh::Mesh& mesh, mesh::TriangleId t, VertexId u, VertexId x,
                      EdgeRef& edge) {
    const Point& pu = mesh.point(u);
    const Point& px = mesh.point(x);
    const double dx = px.x - pu.x, dy = px.y - pu.y;
    const double d = std::hypot(dx, dy);
    VertexId best = mesh::no_vertex;
    double best_cos = 0.99;
    for_each_edge_at(mesh, t, x, [&](EdgeRef f) {
        if (!mesh.triangle(f.triangle()).is_subsegment(f.edge())) return;
        const VertexId y = other_end(mesh, f, x);
        if (y == u) return;
        const Point& py = mesh.point(y);
        const double ex = py.x - px.x, ey = py.y - px.y;
        const double c = (dx * ex + dy * ey) / (d * std::hypot(ex, ey));
        if (c > best_cos) {
            best_cos = c;
            best = y;
            edge = f;
        }
    });
    return best;
}

// Appends each subsegment it steps onto (not u-x itself) to `pieces` when
// that is not null.
VertexId chain_end(const mesh::Mesh& mesh, EdgeRef e, VertexId u, VertexId x, std::uint64_t limit,
                   std::vector<std::array<VertexId, 2>>* pieces = nullptr) {
    for (std::uint64_t step = 0; step < limit; ++step) {
        if (mesh.kind(x) != VertexKind::segment) return x;
        EdgeRef next_edge = EdgeRef::none();
        const VertexId next = continuation(mesh, e.triangle(), u, x, next_edge);
        if (next == mesh::no_vertex) return mesh::no_vertex;
        if (pieces != nullptr) pieces->push_back({x, next});
        u = x;
        x = next;
        e = next_edge;
    }
    return mesh::no_vertex;
}

// The two ends of the input segment through segment vertex u.
bool segment_of(const mesh::Mesh& mesh, mesh::TriangleId t, VertexId u, const SegmentEnds& segments,
                std::array<VertexId, 2>& ends) {
    const EdgeRef e = subsegment_at(mesh, t, u);
    if (e.is_none()) return false;
    const VertexId x = other_end(mesh, e, u);
    if (!segments.ends.empty()) {
        if (const mesh::SubsegmentInfo* info = mesh.subsegments().find(u, x);
            info != nullptr && info->segment != mesh::SubsegmentInfo::no_segment &&
            2 * std::size_t{info->segment} + 1 < segments.ends.size()) {
            ends = {segments.ends[2 * info->segment], segments.ends[2 * info->segment + 1]};
            return ends[0] != mesh::no_vertex;
        }
    }
    // Walk both ways along the chain (bounded: a very long chain just
    // leaves the triangle unprotected).
    return walk_segment_ends(mesh, e, ends);
}

}  // namespace

bool walk_segment_ends(const mesh::Mesh& mesh, EdgeRef e, std::array<VertexId, 2>& ends) {
    constexpr int limit = 256;
    const VertexId a = mesh.origin(e), b = mesh.destination(e);
    const VertexId forward = chain_end(mesh, e, a, b, limit);
    if (forward == mesh::no_vertex) return false;
    const VertexId backward = chain_end(mesh, e, b, a, limit);
    if (backward == mesh::no_vertex) return false;
    ends = {forward, backward};
    return true;
}

bool walk_segment_chain(const mesh::Mesh& mesh, EdgeRef e, std::array<VertexId, 2>& ends,
                        std::vector<std::array<VertexId, 2>>& pieces) {
    // A chain has fewer pieces than the mesh has vertices; more steps mean
    // the walk is going round a loop (a broken mesh), and stops.
    const std::uint64_t limit = std::uint64_t{mesh.vertex_end()} + 1;
    const VertexId a = mesh.origin(e), b = mesh.destination(e);
    pieces.push_back({a, b});
    const VertexId forward = chain_end(mesh, e, a, b, limit, &pieces);
    const VertexId backward = chain_end(mesh, e, b, a, limit, &pieces);
    ends = {forward, backward};
    return forward != mesh::no_vertex && backward != mesh::no_vertex;
}

bool small_angle_protected(const mesh::Mesh& mesh, mesh::TriangleId t, int k,
                           const SegmentEnds& segments) {
    const mesh::Triangle& r = mesh.triangle(t);
    const VertexId u = r.v[mesh::next3(k)];
    const VertexId w = r.v[mesh::prev3(k)];
    if (mesh.kind(u) != VertexKind::segment || mesh.kind(w) != VertexKind::segment) return false;
    std::array<VertexId, 2> su{}, sw{};
    if (!segment_of(mesh, t, u, segments, su) || !segment_of(mesh, t, w, segments, sw))
        return false;
    for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j) {
            if (su[i] != sw[j] || su[1 - i] == sw[1 - j])
                continue;  // no shared end, or the same segment
            const Point& o = mesh.point(su[i]);
            const double du = geometry::squared_distance(o, mesh.point(u));
            const double dw = geometry::squared_distance(o, mesh.point(w));
            if (!(du < 1.001 * dw && du > 0.999 * dw)) continue;
            // Only an angle below 60 degrees needs it: at 60 and above,
            // splitting on concentric shells ends by itself, and the bound
            // is reached.  cos(angle) > 1/2, without roots.
            const Point& fu = mesh.point(su[1 - i]);
            const Point& fw = mesh.point(sw[1 - j]);
            const double ax = fu.x - o.x, ay = fu.y - o.y, bx = fw.x - o.x, by = fw.y - o.y;
            const double dot = ax * bx + ay * by;
            if (dot > 0 && 4 * dot * dot > (ax * ax + ay * ay) * (bx * bx + by * by)) return true;
        }
    }
    return false;
}

}  // namespace gpdr::refine
