#pragma once
// How many triangles the area bounds call for, known before refinement
// starts: the safety budget of RefineRun and the job's memory estimate both
// need it.
//
// A triangle of area A under a bound B is split until its pieces are at
// most B; if they came out exactly B, there would be A / B of them.  They
// come out smaller: the Steiner points land where the mesh is coarse, not
// where the pieces would tile it, and the last split of a region leaves
// pieces between B/2 and B.  Refining to an area bound alone made 1.56 times
// sum(A / B) triangles on the pipe, the flow and a unit square (with -q20
// and -q30 added, 1.56 to 1.59): `fill` is that ratio, rounded down so that
// an estimate made with it errs towards fewer triangles.

#include <cstdint>

#include "mesh/ids.hpp"
#include "mesh/mesh.hpp"
#include "mesh/triangle.hpp"
#include "refine/quality.hpp"

namespace gpdr::refine {

// The area bound of triangle t of `mesh`: the least of the global bound
// (-a), its region's and the .area field's at its centroid (-ra); +infinity
// when none applies.
double area_bound(const QualityCriteria& criteria, const mesh::Mesh& mesh, const mesh::Triangle& t);

struct AreaDemand {
    static constexpr double fill = 1.5;

    std::uint64_t triangles = 0;  // the mesh's triangles now
    double at_bound = 0;          // sum of area / bound over the triangles with a bound
    // The triangles refinement to the area bounds will leave: each triangle
    // with a bound becomes max(1, fill * area / bound), each other one stays.
    double estimate = 0;
};

AreaDemand area_demand(const mesh::Mesh& mesh, const QualityCriteria& criteria);

}  // namespace gpdr::refine
