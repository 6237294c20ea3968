// One run of gpdr: read -> triangulate -> (refine) -> write, timing each
// stage and collecting what -V and -C report.  Each stage takes the data of
// the one before and hands its result on; none reaches back.

#include <chrono>

#include <fmt/format.h>

#include <gpdr/errors.hpp>
#include <gpdr/file_names.hpp>
#include <gpdr/io.hpp>
#include <gpdr/job.hpp>

#include "api/job_stages.hpp"
#include "mesh/checker.hpp"
#include "mesh/traverse.hpp"
#include "triangulate/delaunay.hpp"

namespace gpdr {
namespace {

class Stopwatch {
public:
    // Seconds since the last call (or since construction).
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(now - last_).count();
        last_ = now;
        return s;
    }

private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// Triangle's -C treats the hull of a point set as its boundary; -c makes the
// hull edges segments, so they appear in the output .poly with marker 1.
void make_hull_segments(mesh::Mesh& mesh) {
    std::vector<mesh::EdgeView> hull;
    mesh::for_each_hull_edge(mesh, [&](const mesh::EdgeView& e) { hull.push_back(e); });
    for (const auto& e : hull) {
        mesh.triangle(e.edge.triangle()).set_subsegment(e.edge.edge(), true);
        mesh.subsegments().set(e.from, e.to, mesh::SubsegmentInfo{1, mesh::SubsegmentInfo::no_segment});
    }
}

// Duplicate vertices: one warning naming them (Triangle prints one per copy).
void warn_duplicates(const triangulate::DelaunayReport& report, const std::string& file, int base,
                     const WarningSink& warn) {
    if (report.duplicates.empty()) return;
    constexpr std::size_t shown = 8;
    std::string list;
    for (std::size_t i = 0; i < report.duplicates.size() && i < shown; ++i) {
        const auto [dup, kept] = report.duplicates[i];
        list += fmt::format("{}{} (same as {})", i ? ", " : "", dup + base, kept + base);
    }
    if (report.duplicates.size() > shown) list += fmt::format(", and {} more", report.duplicates.size() - shown);
    warn(Warning{file, 0,
                 fmt::format("{} duplicate vert{} left out of the mesh: {}", report.duplicates.size(),
                             report.duplicates.size() == 1 ? "ex" : "ices", list)});
}

std::string ms(double seconds) { return fmt::format("{:.0f}", seconds * 1000); }

}  // namespace

JobResult run_job(const Options& given, const WarningSink& warn) {
    Options options = given;
    apply_input_name(options);
    api::refuse_unimplemented(options);
    const FileNames names = file_names(options);
    JobResult result;
    Stopwatch clock;

    // Read.
    const int default_base = options.zero_based ? 0 : 1;
    auto input = io::read_node(names.in_node, warn, default_base);
    result.input_vertices = input.data.size();
    result.read_seconds = clock.lap();

    // Triangulate.
    std::vector<geometry::Point> points(input.data.size());
    for (std::size_t i = 0; i < points.size(); ++i) points[i] = {input.data.xy[2 * i], input.data.xy[2 * i + 1]};
    triangulate::DelaunayReport report;
    mesh::Mesh mesh = [&] {
        try {
            return triangulate::delaunay(points, report);
        } catch (const GeometryError& e) {
            throw InputError(names.in_node, 0, e.what());
        }
    }();
    points = {};
    warn_duplicates(report, names.in_node, input.base, warn);
    if (options.convex_hull) make_hull_segments(mesh);
    result.triangulate_seconds = clock.lap();

    if (options.check) {
        result.checked = true;
        result.check_problems = mesh::check_mesh(mesh);
    }

    // Write.
    api::MeshArrays arrays = api::mesh_to_arrays(mesh, std::move(input.data));
    const api::EdgeCounts edges = api::count_edges(arrays);
    result.vertices = arrays.nodes.size() - report.duplicates.size();
    result.triangles = arrays.triangles.size();
    result.edges = edges.edges;
    result.hull_edges = edges.boundary;
    result.segments = mesh.subsegments().size();
    if (options.verbosity > 0) {
        // Computed before -o2 turns the triangles into six-node ones.
        result.statistics = api::quality_statistics(arrays);
    }
    api::OutputRequest request;
    request.options = &options;
    request.names = &names;
    request.base = input.base;
    request.write_hull_poly = options.convex_hull;
    result.files_written = api::write_outputs(request, mesh, arrays);
    result.write_seconds = clock.lap();

    // -V: Triangle's timing and count lines, then the quality block.
    std::vector<std::string> lines{
        fmt::format("Read milliseconds:  {}", ms(result.read_seconds)),
        fmt::format("Delaunay milliseconds:  {}", ms(result.triangulate_seconds)),
        fmt::format("Output milliseconds:  {}", ms(result.write_seconds)),
        fmt::format("Total running milliseconds:  {}",
                    ms(result.read_seconds + result.triangulate_seconds + result.write_seconds)),
        "",
        "Statistics:",
        "",
        fmt::format("  Input vertices: {}", result.input_vertices),
        "",
        fmt::format("  Mesh vertices: {}", result.vertices),
        fmt::format("  Mesh triangles: {}", result.triangles),
        fmt::format("  Mesh edges: {}", result.edges),
        fmt::format("  Mesh exterior boundary edges: {}", result.hull_edges),
    };
    if (options.convex_hull) lines.push_back(fmt::format("  Mesh subsegments (constrained edges): {}", result.segments));
    if (!result.statistics.empty()) lines.emplace_back();
    result.statistics.insert(result.statistics.begin(), lines.begin(), lines.end());
    return result;
}

}  // namespace gpdr
