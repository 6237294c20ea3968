// Carving holes and the exterior, and spreading regions (see domain.hpp).
// Follows Triangle's plague: infection across non-subsegment edges from the
// hole points and from the unsegmented hull edges, then removal.

#include "triangulate/domain.hpp"

#include <string>
#include <vector>

#include <gpdr/errors.hpp>

#include "geometry/on_segment.hpp"
#include "mesh/locate.hpp"
#include "mesh/pool.hpp"

namespace gpdr::triangulate {

using namespace gpdr::mesh;

namespace {

constexpr std::uint8_t mark = Triangle::mark_bit;

TriangleId first_live(const Mesh& mesh) {
    const std::uint32_t end = mesh.triangle_end();
    for (std::uint32_t i = 0; i < end; ++i)
        if (mesh.triangle(TriangleId{i}).live()) return TriangleId{i};
    return no_triangle;
}

// The triangle holding p strictly inside or on a non-subsegment edge, or
// no_triangle (outside, on a vertex, on a subsegment).
TriangleId seed_at(const Mesh& mesh, const geometry::Point& p, TriangleId hint,
                   std::uint32_t& random_state) {
    const LocateResult r = locate(mesh, p, hint, random_state);
    if (r.where == Location::inside) return r.triangle;
    if (r.where == Location::on_edge && !mesh.triangle(r.triangle).is_subsegment(r.index))
        return r.triangle;
    return no_triangle;
}

// Marks `seed` and everything reachable from it across non-subsegment edges
// (skipping triangles marked already); appends them to `out`.
void spread(Mesh& mesh, TriangleId seed, std::vector<TriangleId>& out) {
    Triangle& s = mesh.triangle(seed);
    if (s.marked()) return;
    s.flags |= mark;
    const std::size_t begin = out.size();
    out.push_back(seed);
    for (std::size_t i = begin; i < out.size(); ++i) {
        const Triangle& t = mesh.triangle(out[i]);
        for (int k = 0; k < 3; ++k) {
            const EdgeRef n = t.n[k];
            if (n.is_none() || t.is_subsegment(k)) continue;
            Triangle& u = mesh.triangle(n.triangle());
            if (u.marked()) continue;
            u.flags |= mark;
            out.push_back(n.triangle());
        }
    }
}

// -c: every edge of the convex hull that is not a subsegment becomes one
// (marker 1, no source segment), except that the hull, like an input
// segment, bends through a vertex within rounding of one of its edges
// (geometry/on_segment.hpp): the sliver between the edge and that vertex is
// infected, and its two inner edges take the hull edge's place, looked at
// in turn.  A hull edge is an edge with no neighbour, or whose neighbour is
// such a sliver.
void make_hull_subsegments(Mesh& mesh, std::vector<TriangleId>& slivers) {
    std::vector<EdgeRef> hull;
    const std::uint32_t end = mesh.triangle_end();
    for (std::uint32_t i = 0; i < end; ++i) {
        const Triangle& t = mesh.triangle(TriangleId{i});
        if (!t.live()) continue;
        for (int k = 0; k < 3; ++k)
            if (t.n[k].is_none()) hull.push_back(EdgeRef(TriangleId{i}, k));
    }
    while (!hull.empty()) {
        const EdgeRef e = hull.back();
        hull.pop_back();
        Triangle& t = mesh.triangle(e.triangle());
        const int k = e.edge();
        if (t.marked() || t.is_subsegment(k)) continue;
        const VertexId a = t.v[next3(k)], b = t.v[prev3(k)], c = t.v[k];
        const EdgeRef towards_a = t.n[prev3(k)], towards_b = t.n[next3(k)];
        if (!towards_a.is_none() && !towards_b.is_none() &&
            geometry::on_interior(mesh.point(a), mesh.point(b), mesh.point(c))) {
            t.flags |= mark;
            slivers.push_back(e.triangle());
            if (!t.is_subsegment(prev3(k))) hull.push_back(towards_a);
            if (!t.is_subsegment(next3(k))) hull.push_back(towards_b);
            continue;
        }
        t.set_subsegment(k, true);
        mesh.subsegments().set(a, b, SubsegmentInfo{1, SubsegmentInfo::no_segment});
    }
}

}  // namespace

void carve_domain(Mesh& mesh, const Pslg& pslg, const CdtOptions& options) {
    if (pslg.regions.size() > 65534)
        throw GeometryError("too many regions (" + std::to_string(pslg.regions.size()) +
                            "; at most 65534)");
    const TriangleId any = first_live(mesh);
    if (any == no_triangle) return;
    std::uint32_t random_state = 0x9E3779B9u;

    // Locate everything before the mesh loses its convexity.
    std::vector<TriangleId> hole_seeds, region_seeds;
    if (!options.ignore_holes)
        for (const auto& h : pslg.holes) hole_seeds.push_back(seed_at(mesh, h, any, random_state));
    for (const Region& r : pslg.regions)
        region_seeds.push_back(seed_at(mesh, {r.x, r.y}, any, random_state));

    const std::uint32_t end = mesh.triangle_end();
    std::vector<TriangleId> infected;
    if (options.convex_hull) make_hull_subsegments(mesh, infected);
    for (TriangleId s : hole_seeds)
        if (s != no_triangle) spread(mesh, s, infected);
    if (!options.convex_hull) {
        for (std::uint32_t i = 0; i < end; ++i) {
            const Triangle& t = mesh.triangle(TriangleId{i});
            if (!t.live()) continue;
            for (int k = 0; k < 3; ++k)
                if (t.n[k].is_none() && !t.is_subsegment(k)) spread(mesh, TriangleId{i}, infected);
        }
    }

    // Kill: cut the survivors' links, drop subsegments left with no side.
    {
        Pool pool(mesh);
        for (TriangleId id : infected) {
            const Triangle& t = mesh.triangle(id);
            for (int k = 0; k < 3; ++k) {
                const EdgeRef n = t.n[k];
                const bool other_dead = n.is_none() || mesh.triangle(n.triangle()).marked();
                if (!other_dead) mesh.triangle(n.triangle()).n[n.edge()] = EdgeRef::none();
                if (t.is_subsegment(k) && other_dead)
                    mesh.subsegments().erase(t.v[next3(k)], t.v[prev3(k)]);
            }
        }
        for (TriangleId id : infected) pool.destroy(id);
    }

    // Regions: later ones overwrite earlier ones.
    std::vector<TriangleId> reached;
    for (std::size_t r = 0; r < region_seeds.size(); ++r) {
        const TriangleId s = region_seeds[r];
        if (s == no_triangle || !mesh.triangle(s).live()) continue;
        reached.clear();
        spread(mesh, s, reached);
        for (TriangleId id : reached) {
            Triangle& t = mesh.triangle(id);
            t.region = static_cast<std::uint16_t>(r + 1);
            t.flags &= static_cast<std::uint8_t>(~mark);
        }
    }
}

}  // namespace gpdr::triangulate
