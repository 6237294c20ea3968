// Bowyer–Watson insertion (see insert.hpp for the steps and the contract).

#include "mesh/insert.hpp"

#include <optional>

#include <gpdr/errors.hpp>

#include "geometry/predicates.hpp"

namespace gpdr::mesh {

namespace {

// p collinear with a and b: is it strictly between them?  (Exact: only
// coordinate comparisons.)
bool strictly_between(const Point& a, const Point& b, const Point& p) {
    if (a.x != b.x) return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
    return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
}

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

// Step 3: breadth-first search from the seed, `cavity` doubling as queue.
std::size_t find_cavity(Mesh& mesh, const Point& p, TriangleId seed, InsertBuffer& buf) {
    auto& cavity = buf.killed;
    cavity.clear();
    mesh.triangle(seed).flags |= Triangle::mark_bit;
    cavity.push_back(seed);
    std::size_t boundary_edges = 0;
    for (std::size_t i = 0; i < cavity.size(); ++i) {
        const Triangle& t = mesh.triangle(cavity[i]);
        for (int k = 0; k < 3; ++k) {
            const EdgeRef across = t.n[k];
            if (across.is_none() || t.is_subsegment(k)) {
                ++boundary_edges;
                continue;
            }
            Triangle& u = mesh.triangle(across.triangle());
            if (u.marked()) continue;
            if (in_circumcircle(mesh, u, p)) {
                u.flags |= Triangle::mark_bit;
                cavity.push_back(across.triangle());
            } else {
                ++boundary_edges;
            }
        }
    }
    buf.boundary_edges = boundary_edges;
    return boundary_edges;
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
    buf.created.clear();
    const std::size_t boundary_edges = buf.boundary_edges;
    const TriangleId seed = where.triangle;

    auto is_boundary = [&](const Triangle& t, int k) {
        const EdgeRef across = t.n[k];
        return across.is_none() || t.is_subsegment(k) || !mesh.triangle(across.triangle()).marked();
    };

    // Step 4a: the boundary in order.  Start at any boundary edge; the next
    // one begins at the current one's destination: pivot around it through
    // cavity triangles until an edge leaves the cavity.
    EdgeRef start = EdgeRef::none();
    for (TriangleId id : cavity) {
        const Triangle& t = mesh.triangle(id);
        for (int k = 0; k < 3 && start.is_none(); ++k)
            if (is_boundary(t, k)) start = EdgeRef(id, k);
        if (!start.is_none()) break;
    }
    // A hull edge containing p stays out of the fan (only without ghosts).
    EdgeRef skip = EdgeRef::none();
    if (where.where == Location::on_edge && mesh.triangle(seed).n[where.index].is_none())
        skip = EdgeRef(seed, where.index);
    std::size_t skip_at = 0;

    EdgeRef e = start;
    do {
        const Triangle& t = mesh.triangle(e.triangle());
        if (e == skip) skip_at = boundary.size();
        boundary.push_back(
            {t.v[next3(e.edge())], t.v[prev3(e.edge())], t.n[e.edge()], t.is_subsegment(e.edge())});
        TriangleId ct = e.triangle();
        int j = next3(e.edge());
        while (!is_boundary(mesh.triangle(ct), j)) {
            const EdgeRef across = mesh.triangle(ct).n[j];
            ct = across.triangle();
            j = next3(across.edge());
        }
        e = EdgeRef(ct, j);
    } while (e != start && boundary.size() <= boundary_edges);

    if (boundary.size() != boundary_edges) {
        // The cavity is not a disk: the mesh was not (constrained) Delaunay
        // around p.  Nothing has been changed yet.
        clear_marks(mesh, cavity);
        boundary.clear();
        cavity.clear();
        throw InternalError(
            "mesh: Bowyer-Watson cavity is not simply connected (the mesh is not Delaunay near the "
            "point)");
    }

    // Step 4b: kill the cavity, then fan the boundary from v.  Slots freed
    // here are the first the pool hands out again.
    const std::uint16_t region = mesh.triangle(seed).region;
    save_tagged_and_destroy(pool, buf);

    const std::size_t m = boundary.size();
    const bool open = !skip.is_none();
    const std::size_t first = open ? skip_at + 1 : 0;
    const std::size_t count = open ? m - 1 : m;
    TriangleId previous = no_triangle;
    for (std::size_t i = 0; i < count; ++i) {
        const auto& b = boundary[(first + i) % m];
        const TriangleId id = pool.create(b.from, b.to, v);
        Triangle& t = mesh.triangle(id);
        t.region = region;
        if (b.subsegment) t.set_subsegment(2, true);
        mesh.link(EdgeRef(id, 2), b.outer);
        if (previous != no_triangle) mesh.link(EdgeRef(previous, 0), EdgeRef(id, 1));
        buf.created.push_back(id);
        previous = id;
    }
    if (!open) mesh.link(EdgeRef(previous, 0), EdgeRef(buf.created.front(), 1));
    return {InsertStatus::inserted, v, EdgeRef::none()};
}

namespace {

// Steps 3 and 4.
InsertResult bowyer_watson(Pool& pool, VertexId v, const LocateResult& where, InsertBuffer& buf) {
    find_cavity(pool.mesh(), pool.mesh().point(v), where.triangle, buf);
    return commit_cavity(pool, v, where, buf);
}

}  // namespace

bool in_circumcircle(const Mesh& mesh, const Triangle& t, const Point& p) {
    const int g = t.corner_of(ghost_vertex);
    if (g < 0)
        return geometry::incircle(mesh.point(t.v[0]), mesh.point(t.v[1]), mesh.point(t.v[2]), p) >
               0;
    const Point& a = mesh.point(t.v[next3(g)]);
    const Point& b = mesh.point(t.v[prev3(g)]);
    const double o = geometry::orient2d(a, b, p);
    return o > 0 || (o == 0 && strictly_between(a, b, p));
}

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
