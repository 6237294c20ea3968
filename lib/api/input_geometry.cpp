// What -C compares the mesh with: the input as read (check/input_check.hpp),
// taken before the triangulation stage takes the coordinates.

#include <algorithm>

#include "api/job_stages.hpp"

namespace gpdr::api {

mesh::InputGeometry input_geometry(const Options& options, const Input& in) {
    mesh::InputGeometry g;
    const NodeSet& nodes = in.nodes.data;
    g.points.resize(nodes.size());
    for (std::size_t i = 0; i < g.points.size(); ++i)
        g.points[i] = {nodes.xy[2 * i], nodes.xy[2 * i + 1]};
    if (options.refine) {
        // The domain is the union of the triangles read: its boundary is
        // made of the edges that one triangle only has, and the segments of
        // a .poly (-rp) are kept too.  Holes and regions do not apply.
        const EleSet& ele = *in.triangles;
        std::vector<std::uint64_t> edges;
        edges.reserve(3 * ele.size());
        g.vertex_required.assign(g.points.size(), false);
        for (std::size_t t = 0; t < ele.size(); ++t) {
            const std::uint32_t* c = &ele.corners[t * ele.corners_per_triangle];
            for (int k = 0; k < 3; ++k) {
                const std::uint64_t a = c[k], b = c[(k + 1) % 3];
                edges.push_back(a < b ? (a << 32 | b) : (b << 32 | a));
                if (a < g.vertex_required.size()) g.vertex_required[a] = true;
            }
        }
        std::sort(edges.begin(), edges.end());
        for (std::size_t i = 0; i < edges.size();) {
            std::size_t j = i;
            while (j < edges.size() && edges[j] == edges[i]) ++j;
            if (j - i == 1) {
                g.segments.push_back(static_cast<std::uint32_t>(edges[i] >> 32));
                g.segments.push_back(static_cast<std::uint32_t>(edges[i]));
            }
            i = j;
        }
        if (in.areas)
            g.area_field.emplace(g.points, ele.corners, ele.corners_per_triangle, *in.areas);
        // These are numbered after the .poly's own segments in messages.
        if (in.poly) {
            std::vector<std::uint32_t> boundary = std::move(g.segments);
            g.segments = in.poly->segments.endpoints;
            g.segments.insert(g.segments.end(), boundary.begin(), boundary.end());
        }
        return g;
    }
    if (in.poly) {
        g.segments = in.poly->segments.endpoints;
        if (!options.ignore_holes)
            for (std::size_t h = 0; h + 1 < in.poly->holes.size(); h += 2)
                g.holes.push_back({in.poly->holes[h], in.poly->holes[h + 1]});
        for (const Region& r : in.poly->regions)
            g.regions.push_back({{r.x, r.y}, r.attribute, r.max_area});
        g.hull_bounds_domain = options.convex_hull;
    } else {
        g.hull_bounds_domain = true;
    }
    return g;
}

}  // namespace gpdr::api
