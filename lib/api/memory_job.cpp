// The ends of a run on data in memory (run_job_in_memory, job.cpp): the
// arrays checked as strictly as the readers check a file, and the finished
// mesh handed back as arrays instead of written.

#include <cmath>
#include <cstdint>
#include <span>
#include <string_view>

#include <fmt/format.h>

#include <gpdr/errors.hpp>

#include "api/job_stages.hpp"

namespace gpdr::api {
namespace {

// Checks one input array and names what is wrong as a reader names a line:
// the input's name, then the entry in the run's numbering.
class InputChecker {
public:
    InputChecker(const std::string& name, int base) : name_(name), base_(base) {}

    [[noreturn]] void fail(const std::string& reason) const { throw InputError(name_, 0, reason); }

    void finite(std::span<const double> values, std::string_view what,
                std::size_t per_entry) const {
        for (std::size_t i = 0; i < values.size(); ++i)
            if (!std::isfinite(values[i]))
                fail(fmt::format("{} {} has a coordinate that is not a finite number", what,
                                 i / per_entry + base_));
    }

    // `size` values for `count` entries of `per_entry` each.
    void size(std::size_t size, std::size_t count, std::size_t per_entry,
              std::string_view what) const {
        if (size != count * per_entry)
            fail(fmt::format("{} has {} values, not {} ({} times {})", what, size,
                             count * per_entry, count, per_entry));
    }

    // Markers are optional: none, or one per entry.
    void markers(std::size_t markers, std::size_t count, std::string_view what) const {
        if (markers != 0 && markers != count)
            fail(fmt::format("{} has {} markers for {} entries", what, markers, count));
    }

    void indices(std::span<const std::uint32_t> indices, std::size_t vertex_count,
                 std::size_t per_entry, std::string_view what) const {
        for (std::size_t i = 0; i < indices.size(); ++i)
            if (indices[i] >= vertex_count)
                fail(fmt::format("{} {} refers to vertex {}, but the vertices are {} to {}", what,
                                 i / per_entry + base_, std::int64_t{indices[i]} + base_, base_,
                                 std::int64_t(vertex_count) - 1 + base_));
    }

private:
    const std::string& name_;
    int base_;
};

}  // namespace

Input input_from_memory(const Options& options, MeshInput input) {
    const int base = options.zero_based ? 0 : 1;
    const InputChecker check(input.name, base);
    NodeSet& nodes = input.nodes;
    check.size(nodes.xy.size(), nodes.size(), 2, "the vertex list");
    check.finite(nodes.xy, "vertex", 2);
    check.size(nodes.attributes.size(), nodes.size(), nodes.attribute_count,
               "the vertex attribute list");
    check.markers(nodes.markers.size(), nodes.size(), "the vertex marker list");

    Input in;
    in.node_file = in.poly_file = in.ele_file = input.name;
    if (options.poly) {
        const SegmentSet& segments = input.segments;
        check.size(segments.endpoints.size(), segments.size(), 2, "the segment list");
        check.indices(segments.endpoints, nodes.size(), 2, "segment");
        check.markers(segments.markers.size(), segments.size(), "the segment marker list");
        if (input.holes.size() % 2 != 0) check.fail("the hole list has an odd number of values");
        check.finite(input.holes, "hole", 2);
        for (std::size_t r = 0; r < input.regions.size(); ++r) {
            const Region& region = input.regions[r];
            if (!std::isfinite(region.x) || !std::isfinite(region.y))
                check.fail(fmt::format("region {} has a coordinate that is not a finite number",
                                       r + std::size_t(base)));
        }
        PolyFile& poly = in.poly.emplace();
        poly.segments = std::move(input.segments);
        poly.holes = std::move(input.holes);
        poly.regions = std::move(input.regions);
    }
    if (options.refine) {
        EleSet& triangles = input.triangles;
        if (triangles.corners_per_triangle < 3)
            check.fail(fmt::format("triangles must have at least 3 corners, not {}",
                                   triangles.corners_per_triangle));
        check.size(triangles.corners.size(), triangles.size(), triangles.corners_per_triangle,
                   "the triangle list");
        check.indices(triangles.corners, nodes.size(), triangles.corners_per_triangle, "triangle");
        check.size(triangles.attributes.size(), triangles.size(), triangles.attribute_count,
                   "the triangle attribute list");
        if (options.regional_area) {
            if (input.areas.size() != triangles.size())
                check.fail(fmt::format("{} area bounds for {} triangles", input.areas.size(),
                                       triangles.size()));
            in.areas = std::move(input.areas);
        }
        in.triangles = std::move(triangles);
    }
    in.nodes.base = base;
    in.nodes.data = std::move(nodes);
    return in;
}

MeshOutput output_in_memory(const Options& o, const mesh::Mesh& mesh, MeshArrays& arrays) {
    PreparedOutputs prepared = prepare_outputs(o, mesh, arrays);
    MeshOutput out;
    if (o.poly || o.convex_hull) out.segments = std::move(arrays.segments);
    out.nodes = std::move(arrays.nodes);
    out.triangles = std::move(arrays.triangles);
    if (o.write_neighbours) out.neighbours = std::move(arrays.neighbours);
    out.edges = std::move(prepared.edges);
    out.voronoi_vertices = std::move(prepared.voronoi.vertices);
    out.voronoi_edges = std::move(prepared.voronoi.edges);
    return out;
}

}  // namespace gpdr::api
