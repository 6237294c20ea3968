// Conforming Delaunay triangulation by splitting encroached subsegments (see
// conforming.hpp).  Follows Ruppert, "A Delaunay refinement algorithm for
// quality 2-dimensional mesh generation" (J. Algorithms 18, 1995), the
// segment-splitting half of it, with the concentric shells of its section on
// small input angles and of Shewchuk's "Delaunay refinement algorithms for
// triangular mesh generation" (CGTA 22, 2002).  Triangle splits at shells
// whenever a subsegment ends at a segment endpoint; here only where another
// subsegment meets it below 60 degrees, since a wider angle needs no shells.

#include "triangulate/conforming.hpp"

#include <cmath>
#include <optional>

#include "geometry/constructions.hpp"
#include "geometry/predicates.hpp"
#include "mesh/split_subsegment.hpp"
#include "mesh/traverse.hpp"

namespace gpdr::triangulate {

using namespace gpdr::mesh;
using geometry::Point;

namespace {

// Whether w lies strictly inside the circle with diameter x-y, that is,
// whether the angle x w y exceeds 90 degrees: the sign of
// (x - w) . (y - w).  +1 inside, -1 outside, 0 when rounding could have
// changed the sign.  Each product carries a relative error of at most 3u
// (u = 2^-53) from the two differences and the product, the sum one more u
// of its result; 1e-15 covers it with room.
int diametral(const Point& x, const Point& y, const Point& w) {
    const double p1 = (x.x - w.x) * (y.x - w.x);
    const double p2 = (x.y - w.y) * (y.y - w.y);
    const double dot = p1 + p2;
    const double bound = 1e-15 * (std::abs(p1) + std::abs(p2));
    if (dot < -bound) return 1;
    if (dot > bound) return -1;
    return 0;
}

// Whether another subsegment leaves vertex x at an angle below 60 degrees
// from x-y.  `start` is any edge of a live triangle with origin x.  Walks
// the edges leaving x counter-clockwise, and clockwise from the start when
// it meets the boundary.
bool small_angle_at(const Mesh& mesh, EdgeRef start, VertexId y) {
    const VertexId x = mesh.origin(start);
    const Point& px = mesh.point(x);
    const Point& py = mesh.point(y);
    const double ux = py.x - px.x, uy = py.y - px.y;
    const double uu = ux * ux + uy * uy;
    // Both edges of e's triangle at x: e leaves x (far end its
    // destination), e.prev() enters it (far end the apex).
    auto sharp_edge = [&](EdgeRef e, VertexId v) {
        if (v == y || !mesh.triangle(e.triangle()).is_subsegment(e.edge())) return false;
        const Point& pv = mesh.point(v);
        const double wx = pv.x - px.x, wy = pv.y - px.y;
        const double dot = ux * wx + uy * wy;
        return dot > 0 && 4 * dot * dot > uu * (wx * wx + wy * wy);  // cos(angle) > 1/2
    };
    auto sharp = [&](EdgeRef e) {
        return sharp_edge(e, mesh.destination(e)) || sharp_edge(e.prev(), mesh.apex(e));
    };
    // A broken mesh must not loop forever: no vertex has this many edges
    // unless the walk is going round in circles.
    constexpr int max_steps = 1 << 24;
    EdgeRef e = start;
    for (int step = 0; step < max_steps; ++step) {
        if (sharp(e)) return true;
        // Counter-clockwise: across the edge that ends at x (apex -> x); in
        // the neighbour it leaves x.
        const EdgeRef f = mesh.neighbour(e.prev());
        if (f.is_none()) break;
        if (f == start) return false;
        e = f;
    }
    e = start;
    for (int step = 0; step < max_steps; ++step) {
        // Clockwise: across e itself (it enters x in the neighbour), then
        // the neighbour's edge that leaves x.
        const EdgeRef g = mesh.neighbour(e);
        if (g.is_none()) break;
        e = g.next();
        if (sharp(e)) return true;
    }
    return false;
}

// The parameter along x-y (0 at x) where subsegment e (x -> y) is split.
double split_parameter(const Mesh& mesh, EdgeRef e) {
    const VertexId x = mesh.origin(e), y = mesh.destination(e);
    const bool at_x = small_angle_at(mesh, e, y);
    // e.next() leaves y in the same triangle.
    const bool at_y = small_angle_at(mesh, e.next(), x);
    if (at_x == at_y) return 0.5;
    const Point& px = mesh.point(x);
    const Point& py = mesh.point(y);
    const double length = std::sqrt(geometry::squared_distance(px, py));
    // The power of two nearest (in ratio) to half the length, measured from
    // the sharp end: a fraction in [0.35, 0.71] of the length.
    const double d = std::exp2(std::round(std::log2(0.5 * length)));
    const double t = d / length;
    return at_x ? t : 1.0 - t;
}

// Whether p lies strictly inside the quadrilateral x-w-y-z around subsegment
// e (x -> y, apexes w and z; only the wedge of w on the hull): where
// split_subsegment can put a vertex.  Exact orient2d.
bool placeable(const Mesh& mesh, EdgeRef e, const Point& p) {
    const Point& x = mesh.point(mesh.origin(e));
    const Point& y = mesh.point(mesh.destination(e));
    const Point& w = mesh.point(mesh.apex(e));
    if (geometry::orient2d(y, w, p) <= 0 || geometry::orient2d(w, x, p) <= 0) return false;
    const EdgeRef across = mesh.neighbour(e);
    if (across.is_none()) return true;
    const Point& z = mesh.point(mesh.apex(across));
    return geometry::orient2d(x, z, p) > 0 && geometry::orient2d(z, y, p) > 0;
}

// Where subsegment e is split, or nothing when no floating-point point fits
// strictly inside it (the split point and the midpoint both fall on an end
// or outside the thin quadrilateral around it, as next to a vertex a hair's
// breadth from the segment): then it is left as it is, which bounds the
// number of splits even where the input's features are below rounding.
std::optional<Point> split_point(const Mesh& mesh, EdgeRef e) {
    const Point& x = mesh.point(mesh.origin(e));
    const Point& y = mesh.point(mesh.destination(e));
    // An encroaching apex within 1e-12 of the length from x-y's line: it
    // lies on the segment but for rounding (overlapping segments whose
    // rounded pieces interleave, a vertex on a segment missed by a rounded
    // crossing).  Splitting would go on down to the rounding error, 1e12
    // times and more, and never resolve it.
    const double length_squared = geometry::squared_distance(x, y);
    auto on_line = [&](VertexId v) {
        const Point& w = mesh.point(v);
        return diametral(x, y, w) >= 0 &&
               std::abs(geometry::orient2d(x, y, w)) < 1e-12 * length_squared;
    };
    const EdgeRef across = mesh.neighbour(e);
    if (on_line(mesh.apex(e)) || (!across.is_none() && on_line(mesh.apex(across))))
        return std::nullopt;
    const Point p = geometry::point_on_segment(x, y, split_parameter(mesh, e));
    if (p != x && p != y && placeable(mesh, e, p)) return p;
    const Point middle = geometry::point_on_segment(x, y, 0.5);
    if (middle != x && middle != y && placeable(mesh, e, middle)) return middle;
    return std::nullopt;
}

struct Entry {
    EdgeRef edge;
    std::uint32_t generation;
};

}  // namespace

bool encroached(const Mesh& mesh, EdgeRef e) {
    const Triangle& t = mesh.triangle(e.triangle());
    const Point& x = mesh.point(mesh.origin(e));
    const Point& y = mesh.point(mesh.destination(e));
    const int a = diametral(x, y, mesh.point(mesh.apex(e)));
    if (a > 0) return true;
    const EdgeRef across = t.n[e.edge()];
    if (across.is_none()) return false;
    const Point& z = mesh.point(mesh.apex(across));
    const int b = diametral(x, y, z);
    if (b > 0) return true;
    if (a < 0 && b < 0) return false;
    // Undecided: the angles facing x-y are both near 90 degrees or below;
    // x-y is encroached exactly when they sum past 180 degrees, that is when
    // z is strictly inside the circumcircle of e's triangle.
    return geometry::incircle(mesh.point(t.v[0]), mesh.point(t.v[1]), mesh.point(t.v[2]), z) > 0;
}

void make_conforming(Pool& pool, const ConformingOptions& options, ConformingReport& report) {
    report = ConformingReport{};
    Mesh& mesh = pool.mesh();
    std::vector<Entry> queue;
    std::size_t head = 0;
    auto consider = [&](EdgeRef e) {
        const Triangle& t = mesh.triangle(e.triangle());
        if (t.is_subsegment(e.edge()) && encroached(mesh, e))
            queue.push_back(Entry{e, t.generation});
    };
    for_each_edge(mesh, [&](const EdgeView& v) {
        if (v.subsegment) consider(v.edge);
    });

    InsertBuffer buffer;
    while (head < queue.size()) {
        const Entry entry = queue[head++];
        if (head >= 4096 && 2 * head >= queue.size()) {
            queue.erase(queue.begin(), queue.begin() + static_cast<std::ptrdiff_t>(head));
            head = 0;
        }
        // Stale entries: the triangle died (its subsegment, if it survived,
        // was queued again from the new triangle) or the edge was split.
        const Triangle& t = mesh.triangle(entry.edge.triangle());
        if (!t.live() || t.generation != entry.generation || !t.is_subsegment(entry.edge.edge()))
            continue;
        if (!encroached(mesh, entry.edge)) continue;
        const bool boundary = t.n[entry.edge.edge()].is_none();
        if (options.no_segment_splitting >= 2 || (options.no_segment_splitting == 1 && boundary))
            continue;
        if (options.steiner_limit && report.points_added >= options.max_steiner) {
            report.stopped = ConformingReport::Stop::steiner_limit;
            break;
        }
        const VertexId x = mesh.origin(entry.edge), y = mesh.destination(entry.edge);
        const Point px = mesh.point(x), py = mesh.point(y);
        const std::optional<Point> p = split_point(mesh, entry.edge);
        if (!p) continue;  // unsplittable; counted below
        const SubsegmentInfo* info = mesh.subsegments().find(x, y);
        const SubsegmentInfo kept = info ? *info : SubsegmentInfo{};
        const InsertResult r = split_subsegment(pool, entry.edge, *p, VertexKind::segment, buffer);
        const Point& q = mesh.point(r.vertex);
        const double along = ((q.x - px.x) * (py.x - px.x) + (q.y - px.y) * (py.y - px.y)) /
                             geometry::squared_distance(px, py);
        report.splits.push_back(SegmentSplit{r.vertex, x, y, along, kept});
        ++report.points_added;
        for (TriangleId c : buffer.created)
            for (int k = 0; k < 3; ++k) consider(EdgeRef(c, k));
    }

    for_each_edge(mesh, [&](const EdgeView& v) {
        if (!v.subsegment || !encroached(mesh, v.edge)) return;
        ++report.encroached_left;
        if (!split_point(mesh, v.edge)) ++report.unsplittable;
    });
}

}  // namespace gpdr::triangulate
