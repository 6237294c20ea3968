// Bowyer–Watson insertion (see insert.hpp for the steps and the contract).

#include "mesh/insert.hpp"

#include <optional>

#include <gpdr/errors.hpp>

#include "geometry/predicates.hpp"
#include "mesh/cavity.hpp"

namespace gpdr::mesh {

namespace {

// The refusals of step 2, or nothing when p can be inserted.
std::optional<InsertResult> refusal(const Mesh& mesh, const LocateResult& where) {
    const Triangle& t = mesh.triangle(where.triangle);
    switch (where.where) {
        case Location::on_vertex:
            return InsertResult{InsertStatus::duplicate, t.v[where.index], EdgeRef::none()};
        case Location::on_edge:
            if (t.is_subsegment(where.index))
                return InsertResult{InsertStatus::on_subsegment, no_vertex,
                                    EdgeRef(where.triangle, where.index)};
            return std::nullopt;
        case Location::outside:
            if (!t.is_ghost())
                return InsertResult{InsertStatus::outside, no_vertex,
                                    EdgeRef(where.triangle, where.index)};
            return std::nullopt;
        case Location::inside:
            return std::nullopt;
    }
    return std::nullopt;
}

void clear_marks(Mesh& mesh, const std::vector<TriangleId>& cavity) {
    for (TriangleId t : cavity)
        mesh.triangle(t).flags &= static_cast<std::uint8_t>(~Triangle::mark_bit);
}

}  // namespace

// Step 3 (cavity.hpp).
std::size_t find_cavity(Mesh& mesh, const Point& p, TriangleId seed, InsertBuffer& buf) {
    return search_cavity(mesh, p, {&seed, 1}, buf, [](TriangleId) { return true; });
}

void save_if_tagged(Triangle& t, InsertBuffer& buf) {
    if (t.user_tag == 0) return;
    buf.tagged_gone.push_back({{t.v[0], t.v[1], t.v[2]}, t.user_tag});
    t.user_tag = 0;
}

void save_tagged_and_destroy(Pool& pool, InsertBuffer& buf) {
    buf.tagged_gone.clear();
    for (const TriangleId id : buf.killed) {
        save_if_tagged(pool.mesh().triangle(id), buf);
        pool.destroy(id);
    }
}

void abandon_cavity(Mesh& mesh, InsertBuffer& buf) {
    clear_marks(mesh, buf.killed);
    buf.killed.clear();
}

// Step 4, on the cavity find_cavity() left marked in buf.killed.
InsertResult commit_cavity(Pool& pool, VertexId v, const LocateResult& where, InsertBuffer& buf) {
    Mesh& mesh = pool.mesh();
    auto& cavity = buf.killed;
    auto& boundary = buf.boundary;
    boundary.clear();
    const TriangleId seed = where.triangle;

    // A hull edge containing p stays out of the fan (only without ghosts).
    EdgeRef skip = EdgeRef::none();
    if (where.where == Location::on_edge && mesh.triangle(seed).n[where.index].is_none())
        skip = EdgeRef(seed, where.index);
    std::size_t skip_at = 0;

    // Step 4a: the boundary in order, the edges the search found chained
    // head to tail (cavity.hpp).
    const bool disk = chain_boundary(std::span<const InsertBuffer::BoundaryEdge>(buf.found),
                                     buf.ring, buf.by_from);
    if (disk) {
        VertexId skip_from = no_vertex, skip_to = no_vertex;
        if (!skip.is_none()) {
            const Triangle& t = mesh.triangle(seed);
            skip_from = t.v[next3(skip.edge())];
            skip_to = t.v[prev3(skip.edge())];
        }
        for (const std::uint32_t at : buf.ring) {
            const InsertBuffer::BoundaryEdge& e = buf.found[at];
            if (e.from == skip_from && e.to == skip_to) skip_at = boundary.size();
            boundary.push_back(e);
        }
    }

    if (!disk) {
        // The cavity is not a disk: the mesh was not (constrained) Delaunay
        // around p.  Nothing has been changed yet.
        clear_marks(mesh, cavity);
        boundary.clear();
        cavity.clear();
        buf.created.clear();
        throw InternalError(
            "mesh: Bowyer-Watson cavity is not simply connected (the mesh is not Delaunay near the "
            "point)");
    }

    // Step 4b: kill the cavity, then fan the boundary from v (after the
    // skipped hull edge, if any).  Slots freed here are the first the pool
    // hands out again.  The new triangles take the seed's region.
    const std::uint16_t region = mesh.triangle(seed).region;
    save_tagged_and_destroy(pool, buf);
    const bool open = !skip.is_none();
    fan_cavity(pool, buf, open ? skip_at + 1 : 0, open, v,
               [region](Triangle& t, const InsertBuffer::BoundaryEdge&) { t.region = region; });
    return {InsertStatus::inserted, v, EdgeRef::none()};
}

namespace {

// Steps 3 and 4.
InsertResult bowyer_watson(Pool& pool, VertexId v, const LocateResult& where, InsertBuffer& buf) {
    find_cavity(pool.mesh(), pool.mesh().point(v), where.triangle, buf);
    return commit_cavity(pool, v, where, buf);
}

}  // namespace

InsertResult insert_located(Pool& pool, VertexId v, const LocateResult& where,
                            InsertBuffer& buffer) {
    if (auto r = refusal(pool.mesh(), where)) return *r;
    return bowyer_watson(pool, v, where, buffer);
}

InsertResult insert_vertex(Pool& pool, VertexId v, TriangleId hint, InsertBuffer& buffer) {
    const LocateResult where = locate(pool.mesh(), pool.mesh().point(v), hint, buffer.random_state);
    return insert_located(pool, v, where, buffer);
}

InsertResult insert_point(Pool& pool, const Point& p, VertexKind kind, TriangleId hint,
                          InsertBuffer& buffer) {
    const LocateResult where = locate(pool.mesh(), p, hint, buffer.random_state);
    if (auto r = refusal(pool.mesh(), where)) return *r;
    const VertexId v = pool.new_vertex(p, kind);
    return bowyer_watson(pool, v, where, buffer);
}

}  // namespace gpdr::mesh
