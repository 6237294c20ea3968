// Fuzz target: a whole run (-p, -pq, -pc, -r) on a small PSLG in memory
// (run_job_in_memory), with -C: the invariant checker (mesh::check_mesh)
// and the check against the input (mesh::check_against_input) run on every
// mesh, and any problem they report aborts.  The input's layout is
// in pslg_bytes.hpp.  A gpdr::Error (input the library refuses, with a
// reason) is not a finding; anything else the library throws is.

#include <cstdint>
#include <string>

#include <gpdr/errors.hpp>
#include <gpdr/memory_job.hpp>

#include "fuzz/fuzz_checks.hpp"
#include "fuzz/pslg_bytes.hpp"

namespace {

using namespace gpdr;

void expect_checked(const MemoryJobResult& r, const char* which) {
    fuzz::expect(r.report.checked, "-C did not run");
    if (r.report.check_problems.empty()) return;
    std::string all = std::string("-C found problems in ") + which + ":";
    for (const std::string& p : r.report.check_problems) all += "\n  " + p;
    fuzz::fail(all);
}

void expect_consistent(const MeshOutput& mesh, const Options& o) {
    const std::size_t n = mesh.nodes.size();
    fuzz::expect_consistent(mesh.nodes);
    fuzz::expect(mesh.triangles.corners_per_triangle == (o.order == 2 ? 6u : 3u),
                 "triangles with the wrong number of corners");
    fuzz::expect_indices(mesh.triangles, n);
    fuzz::expect_indices(mesh.segments, n);
    for (std::uint32_t v : mesh.neighbours.neighbours)
        fuzz::expect(v == NeighbourSet::none || v < mesh.triangles.size(),
                     "a neighbour out of range");
}

// -r: the mesh that the first run made, as the files it writes would give
// it back, with the PSLG's holes and regions.
MeshInput mesh_to_refine(const fuzz::PipelineCase& c, MeshOutput made) {
    MeshInput in;
    in.name = "fuzz";
    in.nodes = std::move(made.nodes);
    in.triangles = std::move(made.triangles);
    in.segments = std::move(made.segments);
    in.holes = c.input.holes;
    in.regions = c.input.regions;
    if (c.options.regional_area) in.areas = fuzz::triangle_area_bounds(c, in.triangles.size());
    return in;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const fuzz::PipelineCase c = fuzz::decode_pipeline_case({data, size});
    try {
        MemoryJobResult result;
        if (c.refine) {
            MemoryJobResult first = run_job_in_memory(c.first, c.input, ignore_warning);
            expect_checked(first, "the mesh to refine");
            result = run_job_in_memory(c.options, mesh_to_refine(c, std::move(first.mesh)),
                                       ignore_warning);
        } else {
            result = run_job_in_memory(c.options, c.input, ignore_warning);
        }
        expect_checked(result, "the mesh");
        expect_consistent(result.mesh, c.options);
    } catch (const gpdr::Error&) {}
    return 0;
}
