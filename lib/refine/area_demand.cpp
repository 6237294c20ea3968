// How many triangles the area bounds call for (see area_demand.hpp).

#include "refine/area_demand.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/area_field.hpp"
#include "geometry/constructions.hpp"
#include "mesh/traverse.hpp"

namespace gpdr::refine {

double area_bound(const QualityCriteria& c, const mesh::Mesh& mesh, const mesh::Triangle& t) {
    double bound = std::numeric_limits<double>::infinity();
    if (c.max_area > 0) bound = c.max_area;
    if (t.region < c.region_max_area.size() && c.region_max_area[t.region] > 0)
        bound = std::min(bound, c.region_max_area[t.region]);
    if (c.area_field != nullptr)
        bound = std::min(bound, c.area_field
                                    ->at(geometry::centroid(mesh.point(t.v[0]), mesh.point(t.v[1]),
                                                            mesh.point(t.v[2])))
                                    .area);
    return bound;
}

AreaDemand area_demand(const mesh::Mesh& mesh, const QualityCriteria& criteria) {
    AreaDemand d;
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId, const mesh::Triangle& t) {
        ++d.triangles;
        const double bound = area_bound(criteria, mesh, t);
        if (!std::isfinite(bound)) {
            d.estimate += 1;
            return;
        }
        const double ratio =
            geometry::signed_area(mesh.point(t.v[0]), mesh.point(t.v[1]), mesh.point(t.v[2])) /
            bound;
        d.at_bound += ratio;
        d.estimate += std::max(1.0, AreaDemand::fill * ratio);
    });
    return d;
}

}  // namespace gpdr::refine
