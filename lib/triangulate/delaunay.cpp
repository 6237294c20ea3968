// Delaunay triangulation of a point set (see delaunay.hpp).  Follows the
// incremental scheme of Amenta, Choi & Rote (BRIO) with Bowyer–Watson
// insertion and ghost triangles for the hull (as in Shewchuk's lecture notes
// and CGAL's infinite vertex); geogram and CGAL use the same combination.

#include "triangulate/delaunay.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <unordered_map>

#include <gpdr/errors.hpp>

#include "geometry/predicates.hpp"
#include "mesh/insert.hpp"
#include "mesh/locate.hpp"
#include "mesh/pool.hpp"
#include "mesh/slices.hpp"
#include "triangulate/point_inserter.hpp"
#include "triangulate/spatial_sort.hpp"
#include "triangulate/strip_inserter.hpp"

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

// Runs of triangle or vertex ids that threads take in turn.
constexpr std::uint32_t id_run = 1u << 16;
std::size_t id_runs(std::size_t end) { return (end + id_run - 1) / id_run; }

// Destroys the ghosts in ascending order (found on `threads` threads: they
// are a few among millions).
void remove_ghosts(Pool& pool, unsigned threads) {
    Mesh& mesh = pool.mesh();
    const std::uint32_t end = mesh.triangle_end();
    std::vector<std::vector<std::uint32_t>> ghosts(id_runs(end));
    run_pieces(threads, ghosts.size(), [&](std::size_t piece) {
        const auto first = static_cast<std::uint32_t>(piece * id_run);
        for (std::uint32_t i = first; i < std::min(end, first + id_run); ++i) {
            const Triangle& r = mesh.triangle(TriangleId{i});
            if (r.live() && r.is_ghost()) ghosts[piece].push_back(i);
        }
    });
    for (const auto& run : ghosts) {
        for (const std::uint32_t i : run) {
            const TriangleId id{i};
            const Triangle& r = mesh.triangle(id);
            const EdgeRef real = r.n[r.corner_of(ghost_vertex)];
            mesh.triangle(real.triangle()).n[real.edge()] = EdgeRef::none();
            pool.destroy(id);
        }
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
// Inserts vertex v (its position in `order`), located by a walk from
// `hint`, or records it as the duplicate of the vertex at its point: of two
// equal points the lower input index stays in the triangulation.  Returns a
// triangle at v, the next walk's start.
TriangleId insert_one(PointInserter& inserter, const std::vector<std::uint32_t>& order, VertexId v,
                      TriangleId hint, std::uint32_t& random_state, KeptBy& kept_by) {
    Mesh& mesh = inserter.mesh();
    const LocateResult where = locate(mesh, mesh.point(v), hint, random_state);
    if (where.where != Location::on_vertex) return inserter.insert(v, where.triangle);
    const VertexId there = mesh.triangle(where.triangle).v[where.index];
    const std::uint32_t i = index(v);
    if (order[i] < order[index(there)]) {
        rename_vertex(mesh, where.triangle, there, v);
        kept_by[order[index(there)]] = order[i];
    } else {
        kept_by[order[i]] = order[index(there)];
    }
    return where.triangle;
}

// The first triangle (0, ib, ic), counter-clockwise, and its ghosts.
TriangleId start_triangle(Pool& pool, std::size_t ib, std::size_t ic) {
    const Mesh& mesh = pool.mesh();
    VertexId a{0}, b{static_cast<std::uint32_t>(ib)}, c{static_cast<std::uint32_t>(ic)};
    if (geometry::orient2d(mesh.point(a), mesh.point(b), mesh.point(c)) < 0) std::swap(b, c);
    return start(pool, a, b, c);
}

// Inserts every vertex (vertex id = position in `order`) after the first
// triangle (0, ib, ic).  Of two equal points the lower input index stays in
// the triangulation; the other is recorded in the result.
KeptBy insert_vertices(Pool& pool, const std::vector<std::uint32_t>& order, std::size_t ib,
                       std::size_t ic) {
    KeptBy kept_by;
    TriangleId hint = start_triangle(pool, ib, ic);
    PointInserter inserter(pool);
    std::uint32_t random_state = InsertBuffer{}.random_state;  // the general code's walk, exactly
    const std::size_t n = order.size();
    for (std::size_t i = 1; i < n; ++i) {
        if (i == ib || i == ic) continue;
        hint = insert_one(inserter, order, VertexId{static_cast<std::uint32_t>(i)}, hint,
                          random_state, kept_by);
    }
    return kept_by;
}

// The x values that cut the points after the first `prefix` into `bands`
// bands of about equal counts (from a sample of every 64th), ascending and
// distinct.
std::vector<double> band_cuts(const Mesh& mesh, std::size_t prefix, std::size_t n,
                              std::uint32_t bands) {
    std::vector<double> xs;
    for (std::size_t i = prefix; i < n; i += 64)
        xs.push_back(mesh.point(VertexId{static_cast<std::uint32_t>(i)}).x);
    std::sort(xs.begin(), xs.end());
    std::vector<double> cuts;
    for (std::uint32_t k = 1; k < bands && !xs.empty(); ++k) {
        const double x = xs[xs.size() * k / bands];
        if (cuts.empty() || cuts.back() < x) cuts.push_back(x);
    }
    return cuts;
}

// insert_vertices on several threads: the first points (a 128th) one at a
// time, then rounds that double the points inserted, each round in bands
// (strip_inserter.hpp) and then the points the bands put off, one at a time
// in order.  Every insertion watches for edges whose two triangles share a
// circle (PointInserter::watch_cocircular): false, as soon as one was made,
// when the result might not be the only Delaunay triangulation of the
// points (the caller starts again on one thread).
bool insert_vertices_in_bands(Mesh& mesh, const std::vector<std::uint32_t>& order, std::size_t ib,
                              std::size_t ic, unsigned threads, KeptBy& kept_by) {
    constexpr std::uint32_t bands = 16;  // fixed: the mesh must not depend on `threads`
    const std::size_t n = order.size();
    const std::size_t prefix = std::max({n / 128, ib + 1, ic + 1});
    std::uint32_t random_state = InsertBuffer{}.random_state;
    TriangleId hint;
    {
        Pool pool(mesh);
        hint = start_triangle(pool, ib, ic);
        PointInserter inserter(pool);
        inserter.watch_cocircular();
        for (std::size_t i = 1; i < prefix; ++i) {
            if (i == ib || i == ic) continue;
            hint = insert_one(inserter, order, VertexId{static_cast<std::uint32_t>(i)}, hint,
                              random_state, kept_by);
        }
        if (inserter.cocircular_seen()) return false;
    }
    const Point first_point = mesh.point(VertexId{0});
    StripInserter::Box box{first_point.x, first_point.x, first_point.y, first_point.y};
    for (std::size_t i = 0; i < n; ++i) {
        const Point& p = mesh.point(VertexId{static_cast<std::uint32_t>(i)});
        box = {std::min(box.x_low, p.x), std::max(box.x_high, p.x), std::min(box.y_low, p.y),
               std::max(box.y_high, p.y)};
    }
    // The points put off gather along the cuts: a second set of bands, cut
    // half way between the first set's cuts, takes most of them on all
    // threads too; what both put off goes in on one thread.
    const std::vector<double> cuts = band_cuts(mesh, prefix, n, bands);
    std::vector<double> between_cuts;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
        between_cuts.push_back(cuts[k] + (cuts[k + 1] - cuts[k]) / 2);
    StripInserter in_bands(mesh, cuts, box, threads);
    StripInserter in_between(mesh, between_cuts, box, threads);
    std::vector<std::uint32_t> round;
    for (std::size_t first = prefix; first < n;) {
        const std::size_t last = std::min(n, 2 * first);
        round.clear();
        for (std::size_t i = first; i < last; ++i)
            if (i != ib && i != ic) round.push_back(static_cast<std::uint32_t>(i));
        const std::vector<std::uint32_t> put_off = in_bands.insert_round(round, hint);
        hint = in_bands.live_triangle(hint);
        const std::vector<std::uint32_t> deferred = in_between.insert_round(put_off, hint);
        hint = in_between.live_triangle(hint);
        // (The pool whose lane was set last: the lanes' list of chunks is
        // the mesh's as of the last Lane::first.)
        PointInserter inserter(in_between.pool());
        inserter.watch_cocircular();
        for (const std::uint32_t v : deferred)
            hint = insert_one(inserter, order, VertexId{v}, hint, random_state, kept_by);
        if (inserter.cocircular_seen() || in_bands.cocircular_seen() ||
            in_between.cocircular_seen())
            return false;  // (as soon as seen: a grid stops in the first round)
        first = last;
    }
    return true;
}

// From insertion order back to input numbering; the duplicates become
// VertexKind::duplicate.
void renumber_to_input(Mesh& mesh, std::span<const Point> points,
                       const std::vector<std::uint32_t>& order, const KeptBy& kept_by,
                       unsigned threads) {
    const std::uint32_t end = mesh.triangle_end();
    run_pieces(threads, id_runs(end), [&](std::size_t piece) {
        const auto first = static_cast<std::uint32_t>(piece * id_run);
        for (std::uint32_t t = first; t < std::min(end, first + id_run); ++t) {
            Triangle& r = mesh.triangle(TriangleId{t});
            if (!r.live()) continue;
            for (VertexId& v : r.v) v = VertexId{order[index(v)]};
        }
    });
    run_pieces(threads, id_runs(points.size()), [&](std::size_t piece) {
        for (std::size_t i = piece * id_run; i < std::min(points.size(), (piece + 1) * id_run); ++i)
            mesh.set_point(VertexId{static_cast<std::uint32_t>(i)}, points[i]);
    });
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

mesh::Mesh delaunay(std::span<const Point> points, DelaunayReport& report,
                    const DelaunayOptions& options) {
    report.duplicates.clear();
    check_points(points);
    const std::vector<std::uint32_t> order = brio_order(points, 0, options.threads);
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
    run_pieces(options.threads, id_runs(n), [&](std::size_t piece) {
        const std::size_t last = std::min(n, (piece + 1) * id_run);
        for (std::size_t i = piece * id_run; i < last; ++i) {
            const VertexId v{static_cast<std::uint32_t>(i)};
            if (i + ahead < last) __builtin_prefetch(&points[order[i + ahead]]);
            mesh.set_point(v, points[order[i]]);
            mesh.set_kind(v, VertexKind::input);
        }
    });
    KeptBy kept_by;
    if (options.threads >= 2 && n >= options.parallel_from) {
        if (!insert_vertices_in_bands(mesh, order, ib, ic, options.threads, kept_by))
            return delaunay(points, report, DelaunayOptions{.threads = 1});
    }
    {
        Pool pool(mesh);
        if (options.threads < 2 || n < options.parallel_from)
            kept_by = insert_vertices(pool, order, ib, ic);
        remove_ghosts(pool, options.threads);
        renumber_to_input(mesh, points, order, kept_by, options.threads);
    }
    report.duplicates = duplicate_pairs(kept_by);
    return mesh;
}

}  // namespace gpdr::triangulate
