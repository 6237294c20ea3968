// Constrained Delaunay triangulation: segment insertion by walking along the
// segment and retriangulating the two pseudo-polygons it cuts out (Anglada
// 1997; the same scheme as Shewchuk's "Fast segment insertion and
// incremental construction of constrained Delaunay triangulations", 2013,
// without the randomisation).  See constrained.hpp for the cases.

#include "triangulate/constrained.hpp"

#include <algorithm>
#include <string>

#include <gpdr/errors.hpp>

#include "geometry/constructions.hpp"
#include "geometry/predicates.hpp"
#include "mesh/locate.hpp"
#include "mesh/split_subsegment.hpp"
#include "triangulate/arrangement.hpp"
#include "triangulate/delaunay.hpp"
#include "triangulate/domain.hpp"

namespace gpdr::triangulate {

using namespace gpdr::mesh;
using geometry::incircle;
using geometry::orient2d;
using geometry::Point;

namespace {

std::string vertex_name(VertexId v) { return std::to_string(index(v)); }

void note_corners(const Mesh& mesh, SegmentBuffer& buf, TriangleId t) {
    if (!buf.track_corners) return;
    for (VertexId v : mesh.triangle(t).v) {
        const std::size_t i = index(v);
        if (i >= buf.corner.size())
            buf.corner.resize(std::max(i + 1, buf.corner.size() * 3 / 2), no_triangle);
        buf.corner[i] = t;
    }
}

bool has_corner(const Mesh& mesh, TriangleId t, VertexId v) {
    return t != no_triangle && index(t) < mesh.triangle_end() && mesh.triangle(t).live() &&
           mesh.triangle(t).corner_of(v) >= 0;
}

// A live triangle with corner v: from the corner map, else located from the
// hint (or from the first live triangle).
TriangleId find_start(const Mesh& mesh, VertexId v, TriangleId hint, SegmentBuffer& buf) {
    if (buf.track_corners && index(v) < buf.corner.size() &&
        has_corner(mesh, buf.corner[index(v)], v))
        return buf.corner[index(v)];
    if (has_corner(mesh, hint, v)) return hint;
    if (hint == no_triangle || index(hint) >= mesh.triangle_end() || !mesh.triangle(hint).live()) {
        hint = no_triangle;
        for (std::uint32_t i = 0; i < mesh.triangle_end() && hint == no_triangle; ++i)
            if (mesh.triangle(TriangleId{i}).live()) hint = TriangleId{i};
        if (hint == no_triangle)
            throw InternalError("segment insertion: the mesh has no triangles");
    }
    const LocateResult r = locate(mesh, mesh.point(v), hint, buf.insert.random_state);
    if (r.where != Location::on_vertex || mesh.triangle(r.triangle).v[r.index] != v)
        throw InternalError("segment insertion: vertex " + vertex_name(v) +
                            " is not in the triangulation");
    return r.triangle;
}

// c is collinear with a-b: does it lie on a's side toward b?  (Both
// products have the sign of the direction, so the sum's sign is exact.)
bool ahead(const Point& a, const Point& b, const Point& c) {
    return (c.x - a.x) * (b.x - a.x) + (c.y - a.y) * (b.y - a.y) > 0;
}

struct Step {
    enum class Kind { edge, vertex, cross } kind;
    EdgeRef edge;  // edge: a-b; vertex: a-v; cross: the edge of a's triangle that a-b crosses
    VertexId vertex = no_vertex;
};

// Around vertex a (a corner of triangle t): the triangle whose closed wedge
// holds the direction to b.  Rotates counter-clockwise; on a hull vertex the
// rotation may stop at the hull and go the other way.
Step find_wedge(const Mesh& mesh, TriangleId t0, VertexId a, VertexId b) {
    const Point& pa = mesh.point(a);
    const Point& pb = mesh.point(b);
    const int i0 = mesh.triangle(t0).corner_of(a);
    for (int dir = 0; dir < 2; ++dir) {
        TriangleId t = t0;
        int i = i0;
        for (;;) {
            const Triangle& r = mesh.triangle(t);
            const VertexId c = r.v[next3(i)], d = r.v[prev3(i)];
            if (c == b) return {Step::Kind::edge, EdgeRef(t, prev3(i)), c};
            if (d == b) return {Step::Kind::edge, EdgeRef(t, next3(i)), d};
            const Point& pc = mesh.point(c);
            const Point& pd = mesh.point(d);
            const double oc = orient2d(pa, pc, pb);
            const double od = orient2d(pa, pd, pb);
            if (oc == 0 && ahead(pa, pb, pc)) return {Step::Kind::vertex, EdgeRef(t, prev3(i)), c};
            if (od == 0 && ahead(pa, pb, pd)) return {Step::Kind::vertex, EdgeRef(t, next3(i)), d};
            if (oc > 0 && od < 0) return {Step::Kind::cross, EdgeRef(t, i), no_vertex};
            const EdgeRef n = r.n[dir == 0 ? next3(i) : prev3(i)];
            if (n.is_none()) break;
            t = n.triangle();
            i = dir == 0 ? next3(n.edge()) : prev3(n.edge());
            if (t == t0) break;
        }
    }
    throw GeometryError("segment " + vertex_name(a) + "-" + vertex_name(b) +
                        " leaves the triangulated region");
}

// Flags edge e (between u and v) on both sides and records its entry.
void make_subsegment(Mesh& mesh, EdgeRef e, VertexId u, VertexId v, const SubsegmentInfo& info) {
    mesh.triangle(e.triangle()).set_subsegment(e.edge(), true);
    const EdgeRef n = mesh.neighbour(e);
    if (!n.is_none()) mesh.triangle(n.triangle()).set_subsegment(n.edge(), true);
    SubsegmentTable& table = mesh.subsegments();
    if (const SubsegmentInfo* old = table.find(u, v)) {
        if (old->marker == 0 && info.marker != 0) table.set(u, v, {info.marker, old->segment});
    } else {
        table.set(u, v, info);
    }
}

// Appends vertex v to a chain, reached by a chain edge whose outside is
// `outer`.  A chain that comes back to the vertex before its last one (x, y,
// x) has walked round y: every triangle of y is crossed, so y lies inside the
// pseudo-polygon, not on it.  y leaves the chain (into `inner`, to be
// inserted again afterwards) and the two sides of the edge x-y, both inside
// the strip, are dropped; if x-y was a subsegment, it is recovered after
// the strip is retriangulated and y is back.
void append(const Mesh& mesh, std::vector<VertexId>& chain, std::vector<EdgeRef>& outer,
            std::vector<std::uint8_t>& flag, VertexId v, EdgeRef out, bool subsegment,
            SegmentBuffer& buf) {
    if (chain.size() >= 2 && chain[chain.size() - 2] == v) {
        // A subsegment x-y hanging into the strip is inserted again later.
        if (flag.back()) {
            SubsegmentInfo info;
            if (const SubsegmentInfo* found = mesh.subsegments().find(v, chain.back()))
                info = *found;
            buf.pending.push_back({v, chain.back(), info});
        }
        buf.inner.push_back(chain.back());
        chain.pop_back();
        outer.pop_back();
        flag.pop_back();
        return;
    }
    chain.push_back(v);
    outer.push_back(out);
    flag.push_back(subsegment);
}

struct Walk {
    bool blocked;  // a subsegment crosses: `edge` is it
    EdgeRef edge;
    VertexId end;  // otherwise: the vertex the crossed strip ends at
};

// From the crossing edge e of a's triangle, collects the crossed triangles
// and the chains left and right of a->b (both from a to the end vertex), with
// the outer neighbour and flag of each chain edge.
Walk walk(const Mesh& mesh, VertexId a, VertexId b, EdgeRef e, SegmentBuffer& buf) {
    const Point& pa = mesh.point(a);
    const Point& pb = mesh.point(b);
    buf.crossed.clear();
    buf.left.clear();
    buf.right.clear();
    buf.left_outer.clear();
    buf.right_outer.clear();
    buf.left_flag.clear();
    buf.right_flag.clear();
    buf.inner.clear();
    {
        const Triangle& r = mesh.triangle(e.triangle());
        const int i = e.edge();
        buf.left.push_back(a);
        buf.right.push_back(a);
        append(mesh, buf.left, buf.left_outer, buf.left_flag, r.v[prev3(i)], r.n[next3(i)],
               r.is_subsegment(next3(i)), buf);
        append(mesh, buf.right, buf.right_outer, buf.right_flag, r.v[next3(i)], r.n[prev3(i)],
               r.is_subsegment(prev3(i)), buf);
        buf.crossed.push_back(e.triangle());
    }
    for (;;) {
        const Triangle& r = mesh.triangle(e.triangle());
        if (r.is_subsegment(e.edge())) return {true, e, no_vertex};
        const EdgeRef n = r.n[e.edge()];
        if (n.is_none())
            throw GeometryError("segment " + vertex_name(a) + "-" + vertex_name(b) +
                                " leaves the triangulated region");
        const Triangle& u = mesh.triangle(n.triangle());
        const int j = n.edge();
        const VertexId apex = u.v[j];
        buf.crossed.push_back(n.triangle());
        const double o = apex == b ? 0.0 : orient2d(pa, pb, mesh.point(apex));
        if (o >= 0)
            append(mesh, buf.left, buf.left_outer, buf.left_flag, apex, u.n[prev3(j)],
                   u.is_subsegment(prev3(j)), buf);
        if (o <= 0)
            append(mesh, buf.right, buf.right_outer, buf.right_flag, apex, u.n[next3(j)],
                   u.is_subsegment(next3(j)), buf);
        if (o == 0) return {false, EdgeRef::none(), apex};
        e = EdgeRef(n.triangle(), o > 0 ? next3(j) : prev3(j));
    }
}

// Triangulates the pseudo-polygon chain[0..last] (vertices left of
// chain[0] -> chain[last]) as constrained Delaunay; returns the edge
// chain[0] -> chain[last] of its top triangle.  outer[k] / flag[k]: the
// outside of chain edge k (chain[k] - chain[k+1]).
EdgeRef build(Pool& pool, SegmentBuffer& buf, const std::vector<VertexId>& chain,
              const std::vector<EdgeRef>& outer, const std::vector<std::uint8_t>& flag,
              std::uint16_t region) {
    Mesh& mesh = pool.mesh();
    auto& tasks = buf.tasks;
    tasks.clear();
    tasks.push_back({0, static_cast<std::uint32_t>(chain.size() - 1), EdgeRef::none()});
    EdgeRef top = EdgeRef::none();
    while (!tasks.empty()) {
        const SegmentBuffer::Task k = tasks.back();
        tasks.pop_back();
        if (k.j == k.i + 1) {
            mesh.link(outer[k.i], k.parent);
            if (flag[k.i]) mesh.triangle(k.parent.triangle()).set_subsegment(k.parent.edge(), true);
            continue;
        }
        const Point& pi = mesh.point(chain[k.i]);
        const Point& pj = mesh.point(chain[k.j]);
        std::uint32_t m = k.i + 1;
        for (std::uint32_t x = k.i + 2; x < k.j; ++x)
            if (incircle(pi, pj, mesh.point(chain[m]), mesh.point(chain[x])) > 0) m = x;
        const TriangleId t = pool.create(chain[k.i], chain[k.j], chain[m]);
        mesh.triangle(t).region = region;
        note_corners(mesh, buf, t);
        if (k.parent.is_none())
            top = EdgeRef(t, 2);
        else
            mesh.link(EdgeRef(t, 2), k.parent);
        tasks.push_back({m, k.j, EdgeRef(t, 0)});
        tasks.push_back({k.i, m, EdgeRef(t, 1)});
    }
    return top;
}

// Replaces the crossed strip by the constrained Delaunay triangulation of its
// two sides with a-end as a subsegment.  Returns a triangle with corner end.
TriangleId retriangulate(Pool& pool, VertexId a, VertexId end, const SubsegmentInfo& info,
                         SegmentBuffer& buf) {
    Mesh& mesh = pool.mesh();
    const std::uint16_t region = mesh.triangle(buf.crossed.front()).region;
    for (TriangleId t : buf.crossed) pool.destroy(t);
    const EdgeRef top_left = build(pool, buf, buf.left, buf.left_outer, buf.left_flag, region);
    std::reverse(buf.right.begin(), buf.right.end());
    std::reverse(buf.right_outer.begin(), buf.right_outer.end());
    std::reverse(buf.right_flag.begin(), buf.right_flag.end());
    const EdgeRef top_right = build(pool, buf, buf.right, buf.right_outer, buf.right_flag, region);
    mesh.link(top_left, top_right);
    make_subsegment(mesh, top_left, a, end, info);
    // Vertices the strip swallowed go back by constrained Bowyer-Watson,
    // which keeps the result constrained Delaunay.
    for (VertexId v : buf.inner) {
        const InsertResult r = insert_vertex(pool, v, top_left.triangle(), buf.insert);
        if (r.status != InsertStatus::inserted)
            throw InternalError("segment insertion: could not put back vertex " + vertex_name(v));
        for (TriangleId c : buf.insert.created) note_corners(mesh, buf, c);
    }
    return find_start(mesh, end, top_left.triangle(), buf);
}

}  // namespace

void track_corners(const Mesh& mesh, SegmentBuffer& buf) {
    buf.track_corners = true;
    buf.corner.assign(mesh.vertex_end(), no_triangle);
    const std::uint32_t end = mesh.triangle_end();
    for (std::uint32_t i = 0; i < end; ++i) {
        const Triangle& t = mesh.triangle(TriangleId{i});
        if (!t.live()) continue;
        for (VertexId v : t.v)
            if (index(v) < buf.corner.size()) buf.corner[index(v)] = TriangleId{i};
    }
}

namespace {

// Whether v is one of the targets still ahead (a vertex where an earlier
// piece was bent to); if so, it and the targets after it are reached.
bool arrived(std::vector<VertexId>& targets, VertexId v) {
    const auto it = std::find(targets.begin(), targets.end(), v);
    if (it == targets.end()) return false;
    targets.erase(it, targets.end());
    return true;
}

// A subsegment x-y that blocks the walk from the current vertex toward the
// target, and where the two meet.
struct Blocker {
    EdgeRef edge;  // x -> y, in the last triangle the walk crossed
    VertexId x, y;
    SubsegmentInfo info;  // x-y's side-table entry
    Point p;              // the crossing point (rounded)
    double near;          // squared distance within which p counts as a vertex
    double dx, dy;        // squared distances from p to x and to y
};

Blocker find_blocker(const Mesh& mesh, EdgeRef edge, VertexId current, VertexId target) {
    Blocker k;
    k.edge = edge;
    k.x = mesh.origin(edge);
    k.y = mesh.destination(edge);
    if (const SubsegmentInfo* found = mesh.subsegments().find(k.x, k.y)) k.info = *found;
    k.p = geometry::segment_intersection(mesh.point(current), mesh.point(target), mesh.point(k.x),
                                         mesh.point(k.y));
    k.near = 1e-24 * std::max(geometry::squared_distance(mesh.point(k.x), mesh.point(k.y)),
                              geometry::squared_distance(mesh.point(current), mesh.point(target)));
    k.dx = geometry::squared_distance(k.p, mesh.point(k.x));
    k.dy = geometry::squared_distance(k.p, mesh.point(k.y));
    return k;
}

// The insertion of one piece a-b of a segment: a walk from a that aims at
// the last of buf.targets (b, then the vertices the piece is bent to on the
// way), with `current` the vertex reached and `t` a triangle with corner
// `current`.  `record` says whether events are reported.
struct PieceInsertion {
    Pool& pool;
    Mesh& mesh;
    SegmentBuffer& buf;
    const SubsegmentInfo& info;
    bool record;
    VertexId current = no_vertex;
    TriangleId t = no_triangle;

    // Returns a triangle with corner b.
    TriangleId run(VertexId a, VertexId b, TriangleId start) {
        buf.targets.clear();
        buf.targets.push_back(b);
        current = a;
        t = start;
        buf.path.clear();
        buf.path.push_back(a);
        // Each step passes a vertex, creates one or removes a constraint, so
        // the loop is bounded; the guard turns a bug into an error, never a
        // hang.
        std::uint64_t steps_left = 8ull * mesh.vertex_end() + 1024;
        while (!buf.targets.empty()) {
            if (--steps_left == 0)
                throw InternalError("segment insertion from vertex " + vertex_name(a) + " to " +
                                    vertex_name(b) + " does not terminate");
            const VertexId target = buf.targets.back();
            const Step step = find_wedge(mesh, t, current, target);
            if (step.kind != Step::Kind::cross) {
                follow(step);
                continue;
            }
            const Walk w = walk(mesh, current, target, step.edge, buf);
            if (w.blocked)
                get_past(find_blocker(mesh, w.edge, current, target), target);
            else
                cross_strip(w.end);
        }
        return t;
    }

    void report_through(VertexId v) {
        if (record)
            buf.events.push_back({SegmentEvent::Kind::through_vertex, v, {}, {}, {}, info.segment});
    }

    void move_to(VertexId v, TriangleId with_v) {
        t = with_v;
        current = v;
        buf.path.push_back(current);
    }

    // The edge to the target, or to a vertex on the way, exists: it becomes
    // a subsegment.
    void follow(const Step& step) {
        make_subsegment(mesh, step.edge, current, step.vertex, info);
        if (step.kind == Step::Kind::edge)
            buf.targets.pop_back();
        else if (!arrived(buf.targets, step.vertex))
            report_through(step.vertex);
        move_to(step.vertex, step.edge.triangle());
    }

    // Triangles cross the way up to vertex `end`: their strip is
    // retriangulated with current-end as a subsegment.
    void cross_strip(VertexId end) {
        const TriangleId with_end = retriangulate(pool, current, end, info, buf);
        if (!arrived(buf.targets, end)) report_through(end);
        move_to(end, with_end);
    }

    // Subsegment k.edge crosses the way: split it where the segment meets
    // it, then aim at that vertex first; or, where the crossing is (within
    // rounding) a vertex already there, use that vertex.
    void get_past(const Blocker& k, VertexId target) {
        if ((!can_split_at(mesh, k.edge, k.p) || std::min(k.dx, k.dy) <= k.near) && bend_to_end(k))
            return;
        for (const VertexId v : {target, current}) {
            if (geometry::squared_distance(k.p, mesh.point(v)) > k.near) continue;
            split_blocker_at(k, v);
            return;
        }
        split_blocker(k);
    }

    // The crossing is (within rounding) an end of x-y, or cannot be
    // represented beside a sliver: the segment goes through an end instead,
    // the nearer one not passed already (going back would cycle).  False
    // when both ends are passed.
    bool bend_to_end(const Blocker& k) {
        const VertexId first = k.dx <= k.dy ? k.x : k.y, second = k.dx <= k.dy ? k.y : k.x;
        const auto passed = [&](VertexId v) {
            return std::find(buf.path.begin(), buf.path.end(), v) != buf.path.end();
        };
        const VertexId snap = !passed(first) ? first : !passed(second) ? second : no_vertex;
        if (snap == no_vertex) return false;
        buf.targets.push_back(snap);
        report_through(snap);
        return true;
    }

    // The crossing is (within rounding) vertex v of the segment: x-y is
    // split there instead, as two pieces recovered after this segment, and
    // the walk goes on as if x-y were absent.
    void split_blocker_at(const Blocker& k, VertexId v) {
        mesh.triangle(k.edge.triangle()).set_subsegment(k.edge.edge(), false);
        const EdgeRef twin = mesh.neighbour(k.edge);
        if (!twin.is_none()) mesh.triangle(twin.triangle()).set_subsegment(twin.edge(), false);
        mesh.subsegments().erase(k.x, k.y);
        // Without the constraint x-y the mesh may not be constrained
        // Delaunay there any more; the strip retriangulation needs it.
        buf.insert.created.clear();
        buf.insert.created.push_back(k.edge.triangle());
        if (!twin.is_none()) buf.insert.created.push_back(twin.triangle());
        lawson_flips(mesh, buf.insert);
        for (TriangleId c : buf.insert.created) note_corners(mesh, buf, c);
        t = find_start(mesh, current, k.edge.triangle(), buf);
        buf.pending.push_back({k.x, v, k.info});
        buf.pending.push_back({v, k.y, k.info});
        if (record)
            buf.events.push_back(
                {SegmentEvent::Kind::through_vertex, v, k.x, k.y, k.info, k.info.segment});
    }

    // A new vertex at the crossing splits x-y; it becomes the next target.
    void split_blocker(const Blocker& k) {
        const InsertResult r = split_subsegment(pool, k.edge, k.p, VertexKind::segment, buf.insert);
        for (TriangleId c : buf.insert.created) note_corners(mesh, buf, c);
        if (record)
            buf.events.push_back(
                {SegmentEvent::Kind::crossing, r.vertex, k.x, k.y, k.info, info.segment});
        buf.targets.push_back(r.vertex);
        t = find_start(mesh, current, buf.insert.created.front(), buf);
    }
};

// The loop of insert_segment for one piece a-b, starting from triangle t
// (corner a); `record` says whether events are reported.  Returns a triangle
// with corner b.
TriangleId insert_piece(Pool& pool, VertexId a, VertexId b, const SubsegmentInfo& info,
                        TriangleId t, SegmentBuffer& buf, bool record) {
    PieceInsertion piece{pool, pool.mesh(), buf, info, record};
    return piece.run(a, b, t);
}

}  // namespace

TriangleId insert_segment(Pool& pool, VertexId a, VertexId b, SubsegmentInfo info, TriangleId hint,
                          SegmentBuffer& buf) {
    Mesh& mesh = pool.mesh();
    buf.events.clear();
    buf.pending.clear();
    if (a == b) throw InternalError("segment insertion: both ends are vertex " + vertex_name(a));
    TriangleId t = insert_piece(pool, a, b, info, find_start(mesh, a, hint, buf), buf, true);
    // Subsegments that hung inside a retriangulated strip (see append()).
    while (!buf.pending.empty()) {
        const SegmentBuffer::Pending piece = buf.pending.back();
        buf.pending.pop_back();
        t = insert_piece(pool, piece.from, piece.to, piece.info,
                         find_start(mesh, piece.from, t, buf), buf, false);
    }
    return find_start(mesh, b, t, buf);
}

namespace {

// The surviving segments as pieces to arrange: duplicate vertices replaced
// by the ones kept, zero-length and repeated segments left out (and
// reported).
std::vector<SegmentPiece> segments_to_arrange(const Pslg& pslg,
                                              const std::vector<std::uint32_t>& kept,
                                              CdtReport& report) {
    const std::size_t segments = pslg.segment_count();
    auto end_of = [&](std::size_t s, int k) { return kept[pslg.segments[2 * s + k]]; };
    report.skipped.assign(segments, false);
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys;
    keys.reserve(segments);
    for (std::uint32_t s = 0; s < segments; ++s) {
        std::uint64_t a = end_of(s, 0), b = end_of(s, 1);
        if (a == b) {
            report.zero_length_segments.push_back(s);
            report.skipped[s] = true;
            continue;
        }
        if (a > b) std::swap(a, b);
        keys.emplace_back((a << 32) | b, s);
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 1; i < keys.size(); ++i) {
        std::size_t first = i - 1;
        while (i < keys.size() && keys[i].first == keys[first].first) {
            report.duplicate_segments.emplace_back(keys[i].second, keys[first].second);
            report.skipped[keys[i].second] = true;
            ++i;
        }
    }
    std::sort(report.duplicate_segments.begin(), report.duplicate_segments.end());
    std::vector<SegmentPiece> pieces;
    pieces.reserve(segments);
    for (std::uint32_t s = 0; s < segments; ++s)
        if (!report.skipped[s]) pieces.push_back({end_of(s, 0), end_of(s, 1), s, pslg.marker(s)});
    return pieces;
}

// The parameter of p along input segment s (0 at its first end, 1 at its
// second), for interpolating attributes.
double parameter(const Pslg& pslg, const std::vector<std::uint32_t>& kept, std::uint32_t s,
                 const Point& p) {
    const Point& a = pslg.points[kept[pslg.segments[2 * std::size_t{s}]]];
    const Point& b = pslg.points[kept[pslg.segments[2 * std::size_t{s} + 1]]];
    const double dx = b.x - a.x, dy = b.y - a.y;
    return ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy);
}

// The segment list is well formed: pairs of ends naming vertices, and as
// many markers as segments (or none).
void check_segment_list(const Pslg& pslg) {
    const std::size_t n = pslg.points.size();
    const std::size_t segments = pslg.segment_count();
    if (pslg.segments.size() % 2 != 0)
        throw GeometryError("segment list has an odd number of endpoints");
    if (!pslg.segment_markers.empty() && pslg.segment_markers.size() != segments)
        throw GeometryError("there are " + std::to_string(segments) + " segments but " +
                            std::to_string(pslg.segment_markers.size()) + " segment markers");
    for (std::size_t s = 0; s < segments; ++s)
        for (int k = 0; k < 2; ++k)
            if (pslg.segments[2 * s + k] >= n)
                throw GeometryError("segment " + std::to_string(s) + " names vertex " +
                                    std::to_string(pslg.segments[2 * s + k]) +
                                    " but there are only " + std::to_string(n) + " vertices");
}

// Inserts the crossing points the arrangement found as vertices like the
// input's (Triangle's rule: the segments' pieces end there, and refinement
// protects them as corners), each reported as a new vertex of both its
// segments.  Returns a live triangle.
TriangleId insert_crossings(Pool& pool, const Pslg& pslg, const std::vector<std::uint32_t>& kept,
                            const std::vector<Point>& points, const ArrangementReport& arranged,
                            SegmentBuffer& buf, CdtReport& report) {
    const Mesh& mesh = pool.mesh();
    TriangleId hint = no_triangle;
    for (std::uint32_t i = 0; i < mesh.triangle_end() && hint == no_triangle; ++i)
        if (mesh.triangle(TriangleId{i}).live()) hint = TriangleId{i};
    for (const ArrangementReport::Crossing& c : arranged.crossings) {
        const InsertResult r =
            insert_point(pool, points[c.vertex], VertexKind::input, hint, buf.insert);
        if (r.status != InsertStatus::inserted || index(r.vertex) != c.vertex)
            throw GeometryError(
                "the crossing point of segments " + std::to_string(c.other_segment) + " and " +
                std::to_string(c.segment) + " rounds to a point outside the input's convex hull");
        hint = buf.insert.created.front();
        NewSegmentVertex nv;
        nv.vertex = r.vertex;
        nv.segment = c.segment;
        nv.t = parameter(pslg, kept, c.segment, points[c.vertex]);
        nv.other_segment = c.other_segment;
        nv.other_t = parameter(pslg, kept, c.other_segment, points[c.vertex]);
        report.new_vertices.push_back(nv);
    }
    return hint;
}

// What inserting piece k reported (buf.events), into `report`.  The pieces
// neither cross nor pass through vertices, so insertion reports nothing,
// unless a vertex swallowed by a retriangulated strip was put back exactly
// on a piece (exact, so still reported here) or an earlier piece's
// constraint must be split.
void report_events(const Mesh& mesh, const Pslg& pslg, const std::vector<std::uint32_t>& kept,
                   std::uint32_t k, const SegmentBuffer& buf, CdtReport& report) {
    const SegmentPiece& piece = report.pieces[k];
    for (const SegmentEvent& e : buf.events) {
        const std::uint32_t segment = e.segment == SubsegmentInfo::no_segment ? k : e.segment;
        if (e.kind == SegmentEvent::Kind::through_vertex) {
            report.segments_through_vertices.emplace_back(report.pieces[segment].segment, e.vertex);
            continue;
        }
        NewSegmentVertex nv;
        nv.vertex = e.vertex;
        nv.segment = piece.segment;
        nv.t = parameter(pslg, kept, piece.segment, mesh.point(e.vertex));
        if (e.crossed.segment != SubsegmentInfo::no_segment) {
            nv.other_segment = report.pieces[e.crossed.segment].segment;
            nv.other_t = parameter(pslg, kept, nv.other_segment, mesh.point(e.vertex));
        }
        report.new_vertices.push_back(nv);
    }
}

}  // namespace

mesh::Mesh triangulate_segments(const Pslg& pslg, CdtReport& report) {
    report = CdtReport{};
    check_segment_list(pslg);
    const std::size_t n = pslg.points.size();

    DelaunayReport dr;
    Mesh mesh = delaunay(pslg.points, dr);
    report.duplicate_vertices = dr.duplicates;
    std::vector<std::uint32_t> kept(n);
    for (std::uint32_t i = 0; i < n; ++i) kept[i] = i;
    for (auto [lost, k] : dr.duplicates) kept[lost] = k;

    // Crossings, overlaps and vertices on segments, resolved before any
    // segment is inserted (arrangement.hpp): the pieces meet only at ends.
    std::vector<std::uint32_t> distinct;
    distinct.reserve(n);
    for (std::uint32_t i = 0; i < n; ++i)
        if (kept[i] == i) distinct.push_back(i);
    std::vector<Point> points(pslg.points.begin(), pslg.points.end());
    ArrangementReport arranged;
    report.pieces = arrange_segments(points, std::move(distinct),
                                     segments_to_arrange(pslg, kept, report), arranged);
    for (const auto& [s, v] : arranged.through_vertices)
        report.segments_through_vertices.emplace_back(s, VertexId{v});
    report.overlapping_segments = std::move(arranged.overlaps);

    Pool pool(mesh);
    SegmentBuffer buf;
    TriangleId hint = insert_crossings(pool, pslg, kept, points, arranged, buf, report);
    track_corners(mesh, buf);
    mesh.subsegments().reserve(report.pieces.size() + report.pieces.size() / 4);
    for (std::uint32_t k = 0; k < report.pieces.size(); ++k) {
        const SegmentPiece& piece = report.pieces[k];
        const SubsegmentInfo info{piece.marker, k};
        hint = insert_segment(pool, VertexId{piece.a}, VertexId{piece.b}, info, hint, buf);
        report_events(mesh, pslg, kept, k, buf, report);
    }
    return mesh;
}

mesh::Mesh constrained_delaunay(const Pslg& pslg, const CdtOptions& options, CdtReport& report) {
    Mesh mesh = triangulate_segments(pslg, report);
    carve_domain(mesh, pslg, options);
    return mesh;
}

}  // namespace gpdr::triangulate
