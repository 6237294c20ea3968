// Delaunay triangulation of a point set (see delaunay.hpp).  Follows the
// incremental scheme of Amenta, Choi & Rote (BRIO) with Bowyer–Watson
// insertion and ghost triangles for the hull (as in Shewchuk's lecture notes
// and CGAL's infinite vertex); geogram and CGAL use the same combination.

#include "triangulate/delaunay.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include <gpdr/errors.hpp>

#include "geometry/predicates.hpp"
#include "mesh/insert.hpp"
#include "mesh/locate.hpp"
#include "mesh/pool.hpp"
#include "triangulate/point_inserter.hpp"
#include "triangulate/spatial_sort.hpp"

namespace gpdr::triangulate {

using namespace gpdr::mesh;
using geometry::Point;

namespace {

std::size_t count_distinct(std::span<const Point> points) {
    std::vector<Point> copy(points.begin(), points.end());
    auto less = [](const Point& a, const Point& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    };
    std::sort(copy.begin(), copy.end(), less);
    return static_cast<std::size_t>(std::unique(copy.begin(), copy.end()) - copy.begin());
}

// The first triangle (a, b, c), counter-clockwise, with a ghost triangle on
// each edge.  Returns the real triangle.
TriangleId start(Pool& pool, VertexId a, VertexId b, VertexId c) {
    Mesh& mesh = pool.mesh();
    const TriangleId t = pool.create(a, b, c);
    // Ghost across edge k (from x to y) is (y, x, ghost): its edge 2 faces t.
    TriangleId ghost[3];
    for (int k = 0; k < 3; ++k) {
        const Triangle& r = mesh.triangle(t);
        ghost[k] = pool.create(r.v[prev3(k)], r.v[next3(k)], ghost_vertex);
        mesh.link(EdgeRef(t, k), EdgeRef(ghost[k], 2));
    }
    // Ghost of edge x->y has edge 0 = x->ghost, which is edge 1 (ghost->x)
    // of the ghost of the edge before it, w->x: edge prev3(k) ends where
    // edge k starts (at corner k+1).
    for (int k = 0; k < 3; ++k) mesh.link(EdgeRef(ghost[k], 0), EdgeRef(ghost[prev3(k)], 1));
    return t;
}

// Renames vertex `from` to `to` in every triangle around it (ghosts too: the
// star is a closed cycle while ghosts are present).
void rename_vertex(Mesh& mesh, TriangleId t, VertexId from, VertexId to) {
    const TriangleId first = t;
    do {
        Triangle& r = mesh.triangle(t);
        const int i = r.v[0] == from   ? 0
                      : r.v[1] == from ? 1
                                       : 2;  // `from` is a corner of the star
        r.v[i] = to;
        t = r.n[prev3(i)].triangle();
    } while (t != first);
}

void remove_ghosts(Pool& pool) {
    Mesh& mesh = pool.mesh();
    const std::uint32_t end = mesh.triangle_end();
    for (std::uint32_t i = 0; i < end; ++i) {
        const TriangleId id{i};
        const Triangle& r = mesh.triangle(id);
        if (!r.live() || !r.is_ghost()) continue;
        const EdgeRef real = r.n[r.corner_of(ghost_vertex)];
        mesh.triangle(real.triangle()).n[real.edge()] = EdgeRef::none();
        pool.destroy(id);
    }
}

// Every coordinate is a finite number, and the vertex ids can name every
// point.
void check_points(std::span<const Point> points) {
    const std::size_t n = points.size();
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
            throw GeometryError("vertex " + std::to_string(i) +
                                " has a coordinate that is not a finite number");
    if (n >= index(ghost_vertex))
        throw GeometryError("too many vertices (" + std::to_string(n) + ")");
}

// The first triangle, as positions in `order`: the first point (0), the
// first one different from it (ib), the first one off their line (ic).
// Throws when there is none.
std::pair<std::size_t, std::size_t> first_triangle(std::span<const Point> points,
                                                   const std::vector<std::uint32_t>& order) {
    const std::size_t n = points.size();
    std::size_t ib = 0, ic = 0;
    if (n > 0) {
        const Point& pa = points[order[0]];
        while (ib < n && points[order[ib]] == pa) ++ib;
        if (ib < n) {
            const Point& pb = points[order[ib]];
            while (ic < n && geometry::orient2d(pa, pb, points[order[ic]]) == 0) ++ic;
        }
    }
    if (n == 0 || ib == n || ic == n) {
        const std::size_t distinct = count_distinct(points);
        if (distinct < 3)
            throw GeometryError("the input has " + std::to_string(distinct) +
                                " distinct vertices; a triangulation needs at least three");
        throw GeometryError("all " + std::to_string(distinct) +
                            " distinct input vertices are collinear; no triangle can be formed");
    }
    return {ib, ic};
}

// Duplicate -> the vertex it lost to (input ids).
using KeptBy = std::unordered_map<std::uint32_t, std::uint32_t>;

// Inserts every vertex (vertex id = position in `order`) after the first
// triangle (0, ib, ic).  Of two equal points the lower input index stays in
// the triangulation; the other is recorded in the result.
KeptBy insert_vertices(Pool& pool, const std::vector<std::uint32_t>& order, std::size_t ib,
                       std::size_t ic) {
    Mesh& mesh = pool.mesh();
    KeptBy kept_by;
    VertexId a{0}, b{static_cast<std::uint32_t>(ib)}, c{static_cast<std::uint32_t>(ic)};
    if (geometry::orient2d(mesh.point(a), mesh.point(b), mesh.point(c)) < 0) std::swap(b, c);
    TriangleId hint = start(pool, a, b, c);

    PointInserter inserter(pool);
    std::uint32_t random_state = InsertBuffer{}.random_state;  // the general code's walk, exactly
    const std::size_t n = order.size();
    for (std::size_t i = 1; i < n; ++i) {
        if (i == ib || i == ic) continue;
        const VertexId v{static_cast<std::uint32_t>(i)};
        const LocateResult where = locate(mesh, mesh.point(v), hint, random_state);
        if (where.where == Location::on_vertex) {
            // Keep the lower input index in the triangulation.
            const VertexId there = mesh.triangle(where.triangle).v[where.index];
            if (order[i] < order[index(there)]) {
                rename_vertex(mesh, where.triangle, there, v);
                kept_by[order[index(there)]] = order[i];
            } else {
                kept_by[order[i]] = order[index(there)];
            }
            hint = where.triangle;
            continue;
        }
        hint = inserter.insert(v, where.triangle);
    }
    return kept_by;
}

// From insertion order back to input numbering; the duplicates become
// VertexKind::duplicate.
void renumber_to_input(Mesh& mesh, std::span<const Point> points,
                       const std::vector<std::uint32_t>& order, const KeptBy& kept_by) {
    const std::uint32_t end = mesh.triangle_end();
    for (std::uint32_t t = 0; t < end; ++t) {
        Triangle& r = mesh.triangle(TriangleId{t});
        if (!r.live()) continue;
        for (VertexId& v : r.v) v = VertexId{order[index(v)]};
    }
    for (std::size_t i = 0; i < points.size(); ++i)
        mesh.set_point(VertexId{static_cast<std::uint32_t>(i)}, points[i]);
    for (auto [lost, kept] : kept_by) mesh.set_kind(VertexId{lost}, VertexKind::duplicate);
}

// The (duplicate, vertex kept) pairs, sorted.
std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicate_pairs(const KeptBy& kept_by) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicates;
    duplicates.reserve(kept_by.size());
    for (auto [lost, kept] : kept_by) {
        // A kept vertex may itself have lost later to a lower index.
        for (auto it = kept_by.find(kept); it != kept_by.end(); it = kept_by.find(kept))
            kept = it->second;
        duplicates.emplace_back(lost, kept);
    }
    std::sort(duplicates.begin(), duplicates.end());
    return duplicates;
}

}  // namespace

mesh::Mesh delaunay(std::span<const Point> points, DelaunayReport& report) {
    report.duplicates.clear();
    check_points(points);
    const std::vector<std::uint32_t> order = brio_order(points);
    const auto [ib, ic] = first_triangle(points, order);

    // Work on the points in insertion order: vertex id = position in
    // `order`, so consecutive insertions touch neighbouring memory (the
    // input order is random with respect to the curve: fetching coordinates
    // by input index was a cache miss per predicate).  Renumbered at the end.
    const std::size_t n = points.size();
    Mesh mesh;
    mesh.claim_vertices(static_cast<std::uint32_t>(n));
    // The gather reads the input in curve order, at random: ask for each
    // point some iterations ahead, so that the misses overlap.
    constexpr std::size_t ahead = 16;
    for (std::size_t i = 0; i < n; ++i) {
        const VertexId v{static_cast<std::uint32_t>(i)};
        if (i + ahead < n) __builtin_prefetch(&points[order[i + ahead]]);
        mesh.set_point(v, points[order[i]]);
        mesh.set_kind(v, VertexKind::input);
    }
    KeptBy kept_by;
    {
        Pool pool(mesh);
        kept_by = insert_vertices(pool, order, ib, ic);
        remove_ghosts(pool);
        renumber_to_input(mesh, points, order, kept_by);
    }
    report.duplicates = duplicate_pairs(kept_by);
    return mesh;
}

}  // namespace gpdr::triangulate
