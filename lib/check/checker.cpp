// The invariant checker (see checker.hpp for what it checks).

#include "check/checker.hpp"
#include "check/problem_list.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "geometry/predicates.hpp"
#include "mesh/slices.hpp"

namespace gpdr::mesh {

namespace {

using Report = ProblemList;

// Triangles and vertices are named by id plus `base`, as the files number
// them (from 1, or 0 with -z).
template <class Id>
std::uint64_t number(Id id, int base) {
    return std::uint64_t{index(id)} + static_cast<std::uint64_t>(base);
}

std::string describe(TriangleId id, const Triangle& t, int base) {
    return fmt::format("triangle {} ({}, {}, {})", number(id, base), number(t.v[0], base),
                       number(t.v[1], base), number(t.v[2], base));
}

// The corners of triangle `id`: stored, used, distinct vertices in
// counter-clockwise order.  Returns whether they can be read as points
// (stored and distinct), which the Delaunay test needs.
bool check_corners(const Mesh& mesh, TriangleId id, const Triangle& t, int base, Report& report) {
    const std::uint32_t vertex_end = mesh.vertex_end();
    bool corners_ok = true;
    for (int k = 0; k < 3; ++k) {
        const VertexId v = t.v[k];
        if (index(v) >= vertex_end) {
            report.add("{}: corner {} is not a stored vertex", describe(id, t, base), k);
            corners_ok = false;
        } else if (mesh.kind(v) == VertexKind::unused || mesh.kind(v) == VertexKind::duplicate) {
            report.add("{}: corner {} is vertex {}, which is {}", describe(id, t, base), k,
                       number(v, base),
                       mesh.kind(v) == VertexKind::unused ? "unused" : "a duplicate left out");
        }
    }
    if (t.v[0] == t.v[1] || t.v[1] == t.v[2] || t.v[2] == t.v[0]) {
        report.add("{}: a vertex repeats", describe(id, t, base));
        corners_ok = false;
    }
    if (corners_ok &&
        geometry::orient2d(mesh.point(t.v[0]), mesh.point(t.v[1]), mesh.point(t.v[2])) <= 0)
        report.add("{}: not strictly counter-clockwise", describe(id, t, base));
    return corners_ok;
}

// Edge k of triangle `id`: its neighbour links back across the same edge,
// the subsegment flag agrees on both sides and (once per edge, from the
// lower triangle) has its side-table entry, or the edge is locally
// Delaunay.  Flagged edges checked here are counted in `flagged_edges`.
void check_edge(const Mesh& mesh, const CheckOptions& options, TriangleId id, const Triangle& t,
                int k, bool corners_ok, Report& report, std::size_t& flagged_edges) {
    const int base = options.base;
    const auto num = [base](auto x) { return number(x, base); };
    const EdgeRef across = t.n[k];
    const VertexId from = t.v[next3(k)], to = t.v[prev3(k)];
    if (across.is_none()) {
        if (t.is_subsegment(k)) ++flagged_edges;
        if (t.is_subsegment(k) && options.subsegment_table && !mesh.subsegments().find(from, to))
            report.add("{}: edge {}-{} is flagged as subsegment but missing from the side table",
                       describe(id, t, base), num(from), num(to));
        return;
    }
    const TriangleId uid = across.triangle();
    if (index(uid) >= mesh.triangle_end() || !mesh.triangle(uid).live()) {
        report.add("{}: neighbour across edge {}-{} is triangle {}, which is not live",
                   describe(id, t, base), num(from), num(to), num(uid));
        return;
    }
    const Triangle& u = mesh.triangle(uid);
    const int j = across.edge();
    if (j > 2) {
        report.add("{}: neighbour reference names edge {} of triangle {}", describe(id, t, base), j,
                   num(uid));
        return;
    }
    if (u.n[j] != EdgeRef(id, k))
        report.add("{}: neighbour {} across edge {}-{} does not link back", describe(id, t, base),
                   describe(uid, u, base), num(from), num(to));
    if (u.v[next3(j)] != to || u.v[prev3(j)] != from)
        report.add("{}: edge {}-{} is edge {}-{} in neighbour {}", describe(id, t, base), num(from),
                   num(to), num(u.v[next3(j)]), num(u.v[prev3(j)]), describe(uid, u, base));
    if (t.is_subsegment(k) != u.is_subsegment(j))
        report.add("{}: edge {}-{} is a subsegment on one side only (neighbour {})",
                   describe(id, t, base), num(from), num(to), describe(uid, u, base));
    // Edge-wise checks once per edge, from the lower id.
    if (index(id) > index(uid)) return;
    if (t.is_subsegment(k)) {
        ++flagged_edges;
        if (options.subsegment_table && !mesh.subsegments().find(from, to))
            report.add("{}: edge {}-{} is flagged as subsegment but missing from the side table",
                       describe(id, t, base), num(from), num(to));
    } else if (options.delaunay && corners_ok && index(u.v[j]) < mesh.vertex_end()) {
        const Point& a = mesh.point(t.v[0]);
        const Point& b = mesh.point(t.v[1]);
        const Point& c = mesh.point(t.v[2]);
        if (geometry::orient2d(a, b, c) > 0 && geometry::incircle(a, b, c, mesh.point(u.v[j])) > 0)
            report.add(
                "{}: edge {}-{} is not locally Delaunay: vertex {} of {} is inside the "
                "circumcircle",
                describe(id, t, base), num(from), num(to), num(u.v[j]), describe(uid, u, base));
    }
}

// The checks of triangle slots [first, last), the slots of one chunk:
// problems into `report`, and the flagged edges seen (each once, from its
// lower triangle) counted.  A live triangle past the chunk's used part
// (Mesh::triangle_chunk_used) is one that every pass over the mesh misses.
void check_slots(const Mesh& mesh, const CheckOptions& options, std::uint32_t first,
                 std::uint32_t last, Report& report, std::size_t& flagged_edges) {
    const std::uint32_t used = first + mesh.triangle_chunk_used(first >> Mesh::triangle_chunk_bits);
    for (std::uint32_t i = first; i < last; ++i) {
        const TriangleId id{i};
        const Triangle& t = mesh.triangle(id);
        if (!t.live()) continue;
        if (i >= used)
            report.add("{}: live past the {} slots of its chunk that were handed out",
                       describe(id, t, options.base), used - first);
        const bool corners_ok = check_corners(mesh, id, t, options.base, report);
        for (int k = 0; k < 3; ++k)
            check_edge(mesh, options, id, t, k, corners_ok, report, flagged_edges);
    }
}

}  // namespace

std::vector<std::string> check_mesh(const Mesh& mesh, const CheckOptions& options) {
    // The claimed chunks of slots on several threads, their problems in
    // slot order.
    const std::vector<std::uint32_t> chunks = triangle_chunks(mesh);
    const std::uint32_t end = mesh.triangle_end();
    std::vector<Report> reports(chunks.size(), Report(options.max_problems));
    std::vector<std::size_t> flagged(chunks.size(), 0);
    run_pieces(options.threads, chunks.size(), [&](std::size_t i) {
        const ChunkIds ids = chunk_ids(chunks[i], Mesh::triangle_chunk_bits, end);
        check_slots(mesh, options, ids.first, ids.last, reports[i], flagged[i]);
    });
    Report report(options.max_problems);
    std::size_t flagged_edges = 0;
    for (std::size_t i = 0; i < chunks.size(); ++i) {
        report.take(reports[i]);
        flagged_edges += flagged[i];
    }
    if (options.subsegment_table && flagged_edges != mesh.subsegments().size())
        report.add("the side table holds {} subsegments but {} edges are flagged",
                   mesh.subsegments().size(), flagged_edges);
    return report.finish();
}

}  // namespace gpdr::mesh
