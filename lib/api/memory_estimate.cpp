// The finished mesh's memory, estimated before refinement, and the refusal
// of a run that would not fit (see memory_estimate.hpp).

#include "api/memory_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include <gpdr/errors.hpp>

#include "refine/area_demand.hpp"

namespace gpdr::api {
namespace {

// "9.1e9" for large counts, the number itself below a million.
std::string about(double n) {
    if (n < 1e6) return fmt::format("{:.0f}", n);
    const std::string s = fmt::format("{:.1e}", n);  // "9.1e+09"
    const std::size_t e = s.find('e');
    return s.substr(0, e + 1) + std::to_string(std::stoi(s.substr(e + 1)));
}

// "600 GB", "9.6 GB", "512 MB": two significant figures or more, decimal
// units as the tools that report memory to users mostly use.
std::string bytes_text(double b) {
    static constexpr const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
    int u = 0;
    while (b >= 1000 && u < 6) {
        b /= 1000;
        ++u;
    }
    return b < 10 && u > 0 ? fmt::format("{:.1f} {}", b, units[u])
                           : fmt::format("{:.0f} {}", b, units[u]);
}

// Which bounds make the triangles, as the user gave them.
std::string bounds_text(const Options& o) {
    std::string regional;
    if (o.regional_area) regional = o.refine ? "the .area file's bounds" : "the regions' bounds";
    if (!o.area_limit) return regional;
    const std::string global = fmt::format("-a{}", o.max_area);
    return regional.empty() ? global : global + " with " + regional;
}

}  // namespace

MemoryEstimate estimate_memory(const Options& o, const mesh::Mesh& mesh,
                               const refine::RefineSettings& settings,
                               std::uint32_t vertex_attributes) {
    MemoryEstimate e;
    if (!o.area_limit && !o.regional_area) return e;
    const refine::AreaDemand demand = refine::area_demand(mesh, settings.criteria);
    e.known = true;
    e.triangles = demand.estimate;
    // -S caps the Steiner points, and each adds about two triangles.
    if (o.steiner_limit)
        e.triangles = std::min(e.triangles, double(demand.triangles) + 2.0 * double(o.max_steiner));
    const bool neighbours =
        o.write_neighbours || o.write_edges || o.write_voronoi || o.write_off || o.order == 2;
    double per_triangle = neighbours ? bytes_per_triangle_with_neighbours : bytes_per_triangle;
    if (vertex_attributes > 0) per_triangle += 0.5 * 16.0 * vertex_attributes;
    e.bytes = e.triangles * per_triangle;
    return e;
}

void refuse_beyond_memory(const Options& o, const MemoryEstimate& e,
                          std::optional<std::uint64_t> available) {
    if (o.force || !e.known || !available || e.bytes <= double(*available)) return;
    throw ResourceError(fmt::format(
        "{}: {} would make about {} triangles (~{}), more than the {} of memory available",
        o.input.empty() ? "the input" : o.input, bounds_text(o), about(e.triangles),
        bytes_text(e.bytes), bytes_text(double(*available))));
}

}  // namespace gpdr::api
