// Rebuilding a mesh from a list of triangles (see from_triangles.hpp).
//
// Edge matching files every half-edge under the lower of its two vertices
// with a counting sort, the way a compressed sparse row matrix is built, and
// sorts each vertex's short list by the other vertex: the half-edges of one
// undirected edge end up side by side.  Triangle's reconstruct() does the same
// matching with a linked stack of triangles per vertex; the arrays here are
// friendlier to the cache and make the three-triangle and same-orientation
// errors easy to see.

#include "triangulate/from_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include <gpdr/errors.hpp>

#include "geometry/predicates.hpp"
#include "mesh/pool.hpp"
#include "triangulate/constrained.hpp"

namespace gpdr::triangulate {

using namespace gpdr::mesh;
using geometry::Point;

namespace {

// One half-edge, filed under the lower of its two vertices.
struct HalfEdge {
    std::uint32_t other;  // the higher vertex
    std::uint32_t ref;    // EdgeRef bits of the triangle edge
};

bool operator<(const HalfEdge& a, const HalfEdge& b) {
    return a.other < b.other || (a.other == b.other && a.ref < b.ref);
}

// Insertion sort: almost every list holds two to five entries.
void sort_small(HalfEdge* first, HalfEdge* last) {
    if (last - first > 32) {
        std::sort(first, last);
        return;
    }
    for (HalfEdge* i = first + 1; i < last; ++i) {
        const HalfEdge x = *i;
        HalfEdge* j = i;
        for (; j > first && x < *(j - 1); --j) *j = *(j - 1);
        *j = x;
    }
}

// Whether direction q - v has angle in [0, pi) (upper half-plane, with the
// positive x direction included).  Exact: only coordinate comparisons.
bool upper(const Point& v, const Point& q) { return q.y > v.y || (q.y == v.y && q.x > v.x); }

class Namer {
public:
    Namer(const Mesh& mesh, int base) : mesh_(mesh), base_(base) {}
    std::string vertex(std::uint32_t v) const { return std::to_string(std::int64_t{v} + base_); }
    std::string triangle(TriangleId t) const {
        const Triangle& r = mesh_.triangle(t);
        return fmt::format("triangle {} (corners {}, {}, {})", std::int64_t{index(t)} + base_,
                           vertex(index(r.v[0])), vertex(index(r.v[1])), vertex(index(r.v[2])));
    }
    std::string triangle(std::uint32_t i, std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
        return fmt::format("triangle {} (corners {}, {}, {})", std::int64_t{i} + base_, vertex(a),
                           vertex(b), vertex(c));
    }

private:
    const Mesh& mesh_;
    int base_;
};

// Half-edges filed by lower vertex: bucket v is [begin(v), end(v)).
class EdgeIndex {
public:
    // Built from the live triangles 0..count-1 of `mesh`.
    EdgeIndex(const Mesh& mesh, std::uint32_t vertex_count, std::uint32_t triangle_count)
        : end_(std::size_t{vertex_count} + 1, 0), entries_(std::size_t{triangle_count} * 3) {
        // Count into end_[v + 1], prefix-sum to starts, then fill with
        // end_[v]++ : afterwards end_[v] is the end of bucket v and
        // end_[v - 1] its start (end_ is offset by one for that).
        for (std::uint32_t t = 0; t < triangle_count; ++t) {
            const Triangle& r = mesh.triangle(TriangleId{t});
            for (int k = 0; k < 3; ++k)
                ++end_[std::size_t{std::min(index(r.v[next3(k)]), index(r.v[prev3(k)]))} + 1];
        }
        for (std::size_t v = 1; v < end_.size(); ++v) end_[v] += end_[v - 1];
        for (std::uint32_t t = 0; t < triangle_count; ++t) {
            const Triangle& r = mesh.triangle(TriangleId{t});
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = index(r.v[next3(k)]), b = index(r.v[prev3(k)]);
                entries_[end_[std::min(a, b)]++] =
                    HalfEdge{std::max(a, b), EdgeRef(TriangleId{t}, k).bits()};
            }
        }
        end_.pop_back();
        for (std::uint32_t v = 0; v < vertex_count; ++v) sort_small(begin(v), end(v));
    }

    HalfEdge* begin(std::uint32_t v) { return entries_.data() + (v == 0 ? 0 : end_[v - 1]); }
    HalfEdge* end(std::uint32_t v) { return entries_.data() + end_[v]; }

    // The first half-edge of edge {lo, hi} (lo < hi), or nullptr.
    const HalfEdge* find(std::uint32_t lo, std::uint32_t hi) {
        HalfEdge* e = end(lo);
        HalfEdge* it = std::lower_bound(begin(lo), e, HalfEdge{hi, 0});
        return it != e && it->other == hi ? it : nullptr;
    }

private:
    std::vector<std::uint32_t> end_;
    std::vector<HalfEdge> entries_;
};

// Pass 1: checks each triangle on its own and creates it (TriangleId i).
// Also counts, for every vertex, how often the triangles around it wind past
// the direction of angle 0 (upper[] as defined above): a triangle (v, a, b)
// does exactly when a is in the lower half and b in the upper one, because
// its angle at v is below pi.  A closed star of counter-clockwise triangles
// winds exactly once around its vertex unless it overlaps itself.
void create_triangles(const TriangleMeshInput& in, Pool& pool, const Namer& name,
                      std::vector<std::uint8_t>& used, std::vector<std::uint8_t>& winds) {
    const std::size_t n = in.points.size();
    const std::size_t count = in.corners.size() / in.corners_per_triangle;
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t* c = &in.corners[i * in.corners_per_triangle];
        const auto id = static_cast<std::uint32_t>(i);
        for (int k = 0; k < 3; ++k)
            if (c[k] >= n)
                throw GeometryError(
                    fmt::format("{} names vertex {}, but there are only {} vertices",
                                name.triangle(id, c[0], c[1], c[2]), name.vertex(c[k]), n));
        if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0])
            throw GeometryError(
                fmt::format("{} repeats a vertex", name.triangle(id, c[0], c[1], c[2])));
        const Point& a = in.points[c[0]];
        const Point& b = in.points[c[1]];
        const Point& d = in.points[c[2]];
        const double o = geometry::orient2d(a, b, d);
        if (o < 0)
            throw GeometryError(
                fmt::format("{} is clockwise; corners must be listed counter-clockwise",
                            name.triangle(id, c[0], c[1], c[2])));
        if (o == 0)
            throw GeometryError(fmt::format("{} has zero area (its corners are collinear)",
                                            name.triangle(id, c[0], c[1], c[2])));
        const TriangleId t = pool.create(VertexId{c[0]}, VertexId{c[1]}, VertexId{c[2]});
        if (index(t) != id)
            throw InternalError("from_triangles: the pool did not hand out triangle ids in order");
        const Point* p[3] = {&a, &b, &d};
        for (int k = 0; k < 3; ++k) {
            used[c[k]] = 1;
            const Point& v = *p[k];
            if (!upper(v, *p[next3(k)]) && upper(v, *p[prev3(k)]) && winds[c[k]] < 255)
                ++winds[c[k]];
        }
    }
}

// Pass 2: links the two sides of every edge; flags boundary edges as
// subsegments (recorded in `boundary` for the side table) and their vertices
// as boundary vertices (on_boundary).
void link_edges(Mesh& mesh, EdgeIndex& edges, const Namer& name, std::uint32_t vertex_count,
                std::vector<EdgeRef>& boundary, std::vector<std::uint8_t>& on_boundary) {
    for (std::uint32_t v = 0; v < vertex_count; ++v) {
        HalfEdge* const last = edges.end(v);
        for (HalfEdge* run = edges.begin(v); run != last;) {
            HalfEdge* run_end = run + 1;
            while (run_end != last && run_end->other == run->other) ++run_end;
            const EdgeRef e = EdgeRef::from_bits(run->ref);
            switch (run_end - run) {
                case 1: {
                    mesh.triangle(e.triangle()).set_subsegment(e.edge(), true);
                    boundary.push_back(e);
                    on_boundary[v] = 1;
                    on_boundary[run->other] = 1;
                    break;
                }
                case 2: {
                    const EdgeRef f = EdgeRef::from_bits(run[1].ref);
                    if (mesh.origin(e) == mesh.origin(f))
                        throw GeometryError(
                            fmt::format("{} and {} lie on the same side of their common edge "
                                        "{}-{}: they overlap",
                                        name.triangle(e.triangle()), name.triangle(f.triangle()),
                                        name.vertex(index(mesh.origin(e))),
                                        name.vertex(index(mesh.destination(e)))));
                    mesh.link(e, f);
                    break;
                }
                default: {
                    std::string list;
                    for (HalfEdge* h = run; h != run_end && h - run < 4; ++h)
                        list += (h == run ? "" : ", ") +
                                name.triangle(EdgeRef::from_bits(h->ref).triangle());
                    if (run_end - run > 4) list += fmt::format(" and {} more", run_end - run - 4);
                    throw GeometryError(fmt::format(
                        "edge {}-{} is shared by {} triangles, at most two may share it: {}",
                        name.vertex(v), name.vertex(run->other), run_end - run, list));
                }
            }
            run = run_end;
        }
    }
}

// Pass 3: every used vertex's star winds around it once, or (on the
// boundary, where the star is open) at most once.
void check_winding(const std::vector<std::uint8_t>& used, const std::vector<std::uint8_t>& winds,
                   const std::vector<std::uint8_t>& on_boundary, const Namer& name) {
    for (std::size_t v = 0; v < used.size(); ++v) {
        if (!used[v]) continue;
        const bool ok = on_boundary[v] ? winds[v] <= 1 : winds[v] == 1;
        if (!ok)
            throw GeometryError(
                fmt::format("the triangles around vertex {} turn around it {} times: they overlap",
                            name.vertex(static_cast<std::uint32_t>(v)),
                            winds[v] == 255 ? std::string("many") : std::to_string(winds[v])));
    }
}

// Pass 4: segments that are mesh edges become subsegments.
void flag_segments(const TriangleMeshInput& in, Mesh& mesh, EdgeIndex& edges, const Namer& name,
                   TriangleMeshReport& report) {
    const std::size_t n = in.points.size();
    const std::size_t count = in.segments.size() / 2;
    for (std::size_t s = 0; s < count; ++s) {
        const std::uint32_t a = in.segments[2 * s], b = in.segments[2 * s + 1];
        if (a >= n || b >= n)
            throw GeometryError(
                fmt::format("segment {} names vertex {}, but there are only {} vertices",
                            std::int64_t(s) + in.index_base, name.vertex(a >= n ? a : b), n));
        if (a == b) {
            ++report.segments_degenerate;
            continue;
        }
        const HalfEdge* h = edges.find(std::min(a, b), std::max(a, b));
        if (h == nullptr) {
            report.missing_segments.push_back(static_cast<std::uint32_t>(s));
            continue;
        }
        if (mesh.subsegments().find(VertexId{a}, VertexId{b})) {
            ++report.segments_repeated;
            continue;
        }
        const EdgeRef e = EdgeRef::from_bits(h->ref);
        const EdgeRef f = mesh.neighbour(e);
        int marker = in.segment_markers.empty() ? 0 : in.segment_markers[s];
        // Triangle gives a boundary subsegment marker 1 unless it has its own.
        if (f.is_none() && marker == 0) marker = 1;
        mesh.triangle(e.triangle()).set_subsegment(e.edge(), true);
        if (!f.is_none()) mesh.triangle(f.triangle()).set_subsegment(f.edge(), true);
        mesh.subsegments().set(VertexId{a}, VertexId{b},
                               SubsegmentInfo{marker, static_cast<std::uint32_t>(s)});
        ++report.segments_flagged;
    }
}

// Pass 5: segments that are not mesh edges are inserted (constrained.hpp:
// the triangles they cross are replaced, subsegments they cross are split).
void insert_missing(const TriangleMeshInput& in, Pool& pool, const std::vector<std::uint8_t>& used,
                    const Namer& name, TriangleMeshReport& report) {
    Mesh& mesh = pool.mesh();
    SegmentBuffer buffer;
    track_corners(mesh, buffer);
    TriangleId hint = no_triangle;
    for (std::uint32_t s : report.missing_segments) {
        const std::uint32_t a = in.segments[2 * s], b = in.segments[2 * s + 1];
        const std::string what =
            fmt::format("segment {} ({}-{}) is not an edge of the mesh",
                        std::int64_t{s} + in.index_base, name.vertex(a), name.vertex(b));
        if (!used[a] || !used[b])
            throw GeometryError(what + fmt::format(", and vertex {} is in no triangle",
                                                   name.vertex(used[a] ? b : a)));
        const SubsegmentInfo info{in.segment_markers.empty() ? 0 : in.segment_markers[s], s};
        const TriangleId start = buffer.corner[a] != no_triangle ? buffer.corner[a] : hint;
        // What the input can cause is reported against the segment; a bug
        // (InternalError) or a mesh beyond gpdr's ids (CapacityError) is not
        // the segment's fault and passes as it is.
        try {
            hint = insert_segment(pool, VertexId{a}, VertexId{b}, info, start, buffer);
        } catch (const GeometryError& e) {  // it leaves the mesh (a non-convex one)
            throw GeometryError(what + " and cannot be inserted: " + e.what());
        } catch (const SubsegmentSplitError& e) {  // a subsegment it crosses takes no vertex
            throw GeometryError(what + " and cannot be inserted: " + e.what());
        }
        report.segment_events.insert(report.segment_events.end(), buffer.events.begin(),
                                     buffer.events.end());
        ++report.segments_inserted;
    }
}

// Attributes of the triangles segment insertion made (the slot is new, or
// its generation moved on): each takes those of a neighbour that kept its
// own, across edges that are not subsegments first (the same side of the
// new segment), then across any edge.
void spread_attributes(const Mesh& mesh, std::uint32_t original, std::uint32_t count,
                       std::vector<double>& values) {
    const std::uint32_t end = mesh.triangle_end();
    std::vector<std::uint8_t> known(end, 0);
    std::vector<TriangleId> unknown;
    for (std::uint32_t i = 0; i < end; ++i) {
        const Triangle& t = mesh.triangle(TriangleId{i});
        if (!t.live()) continue;
        if (i < original && t.generation == 0)
            known[i] = 1;
        else
            unknown.push_back(TriangleId{i});
    }
    for (int pass = 0; pass < 2; ++pass) {
        for (bool changed = true; changed;) {
            changed = false;
            for (TriangleId id : unknown) {
                if (known[index(id)]) continue;
                const Triangle& t = mesh.triangle(id);
                for (int k = 0; k < 3; ++k) {
                    const EdgeRef n = t.n[k];
                    if (n.is_none() || !known[index(n.triangle())] ||
                        (pass == 0 && t.is_subsegment(k)))
                        continue;
                    std::copy_n(values.begin() + std::ptrdiff_t{index(n.triangle())} * count, count,
                                values.begin() + std::ptrdiff_t{index(id)} * count);
                    known[index(id)] = 1;
                    changed = true;
                    break;
                }
            }
        }
    }
}

}  // namespace

mesh::Mesh from_triangles(const TriangleMeshInput& in, TriangleMeshReport& report) {
    report = TriangleMeshReport{};
    if (in.corners_per_triangle < 3 || in.corners.size() % in.corners_per_triangle != 0)
        throw InternalError("from_triangles: the corner list does not hold whole triangles");
    const std::size_t n = in.points.size();
    const std::size_t count = in.corners.size() / in.corners_per_triangle;
    if (in.attributes.size() != count * in.attribute_count)
        throw InternalError("from_triangles: the attribute list does not match the triangles");
    if (!in.segment_markers.empty() && in.segment_markers.size() * 2 != in.segments.size())
        throw InternalError("from_triangles: the segment markers do not match the segments");
    if (n >= index(ghost_vertex)) throw GeometryError(fmt::format("too many vertices ({})", n));
    if (count >= max_triangles) throw GeometryError(fmt::format("too many triangles ({})", count));
    if (count == 0) throw GeometryError("the mesh has no triangles");
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(in.points[i].x) || !std::isfinite(in.points[i].y))
            throw GeometryError(
                fmt::format("vertex {} has a coordinate that is not a finite number",
                            std::int64_t(i) + in.index_base));

    Mesh mesh;
    mesh.add_vertices(in.points, VertexKind::input);
    const auto vertex_count = static_cast<std::uint32_t>(n);
    const auto triangle_count = static_cast<std::uint32_t>(count);
    const Namer name(mesh, in.index_base);
    {
        Pool pool(mesh);
        std::vector<std::uint8_t> used(n, 0), winds(n, 0), on_boundary(n, 0);
        create_triangles(in, pool, name, used, winds);
        std::vector<EdgeRef> boundary;
        {
            EdgeIndex edges(mesh, vertex_count, triangle_count);
            link_edges(mesh, edges, name, vertex_count, boundary, on_boundary);
            check_winding(used, winds, on_boundary, name);
            flag_segments(in, mesh, edges, name, report);
        }
        for (EdgeRef e : boundary) {
            const VertexId a = mesh.origin(e), b = mesh.destination(e);
            if (!mesh.subsegments().find(a, b))
                mesh.subsegments().set(a, b, SubsegmentInfo{1, SubsegmentInfo::no_segment});
        }
        report.boundary_edges = boundary.size();
        report.unused_vertices =
            static_cast<std::size_t>(std::count(used.begin(), used.end(), std::uint8_t{0}));
        if (!report.missing_segments.empty()) insert_missing(in, pool, used, name, report);
    }
    report.attributes.assign(std::size_t{mesh.triangle_end()} * in.attribute_count, 0.0);
    std::copy(in.attributes.begin(), in.attributes.end(), report.attributes.begin());
    if (report.segments_inserted > 0 && in.attribute_count > 0)
        spread_attributes(mesh, triangle_count, in.attribute_count, report.attributes);
    return mesh;
}

}  // namespace gpdr::triangulate
