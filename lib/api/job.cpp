// One run of gpdr: read -> triangulate -> (refine) -> write, timing each
// stage and collecting what -V and -C report.  Each stage takes the data of
// the one before and hands its result on; none reaches back.

#include <chrono>
#include <optional>

#include <fmt/format.h>

#include <gpdr/errors.hpp>
#include <gpdr/file_names.hpp>
#include <gpdr/io.hpp>
#include <gpdr/job.hpp>

#include "api/job_stages.hpp"
#include "mesh/checker.hpp"
#include "mesh/traverse.hpp"
#include "refine/refine.hpp"
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

// Everything the input files say, read and validated before anything else
// happens, so that a malformed file is reported by file and line whatever
// the switches ask for.
struct Input {
    io::ReadResult<NodeSet> nodes;
    std::string node_file;             // where the vertices came from
    std::optional<PolyFile> poly;      // -p
    std::optional<EleSet> triangles;   // -r
    std::optional<AreaSet> areas;      // -r with bare -a
};

Input read_input(const Options& options, const FileNames& names, const WarningSink& warn) {
    const int default_base = options.zero_based ? 0 : 1;
    Input in;
    if (options.poly && !options.refine) {
        auto poly = io::read_poly(names.in_poly, warn, default_base);
        in.nodes.base = poly.base;
        in.nodes.data = std::move(poly.data.nodes);
        in.node_file = poly.data.nodes_from_node_file ? names.in_node : names.in_poly;
        poly.data.nodes = {};
        in.poly = std::move(poly.data);
        return in;
    }
    in.nodes = io::read_node(names.in_node, warn, default_base);
    in.node_file = names.in_node;
    if (options.refine) {
        const int base = in.nodes.base;
        auto ele = io::read_ele(names.in_ele, base, in.nodes.data.size(), warn);
        if (options.poly) {
            auto poly = io::read_poly(names.in_poly, warn, default_base);
            poly.data.nodes = {};
            in.poly = std::move(poly.data);
        }
        if (options.regional_area) in.areas = io::read_area(names.in_area, base, ele.data.size(), warn).data;
        in.triangles = std::move(ele.data);
    }
    return in;
}

}  // namespace

JobResult run_job(const Options& given, const WarningSink& warn, const JobPlugins& plugins) {
    Options options = given;
    apply_input_name(options);
    const FileNames names = file_names(options);
    JobResult result;
    Stopwatch clock;

    // Read.
    Input input = read_input(options, names, warn);
    api::refuse_unimplemented(options);
    result.input_vertices = input.nodes.data.size();
    result.read_seconds = clock.lap();

    // Triangulate.
    std::vector<geometry::Point> points(input.nodes.data.size());
    for (std::size_t i = 0; i < points.size(); ++i) points[i] = {input.nodes.data.xy[2 * i], input.nodes.data.xy[2 * i + 1]};
    triangulate::DelaunayReport report;
    mesh::Mesh mesh = [&] {
        try {
            return triangulate::delaunay(points, report);
        } catch (const GeometryError& e) {
            throw InputError(input.node_file, 0, e.what());
        }
    }();
    points = {};
    warn_duplicates(report, input.node_file, input.nodes.base, warn);
    // Triangle treats the hull of a point set as segments: -c writes them
    // to the .poly, and refinement keeps its Steiner points inside them.
    const bool refining = api::wants_refinement(options);
    if (options.convex_hull || refining) make_hull_segments(mesh);
    result.triangulate_seconds = clock.lap();

    // Refine.
    refine::RefineReport refined;
    if (refining) {
        const refine::RefineSettings settings =
            api::refine_settings(options, plugins, input.poly ? &*input.poly : nullptr);
        api::warn_before_refinement(options, warn);
        refine::refine_mesh(mesh, settings, refined);
        api::warn_after_refinement(refined, warn);
    }
    result.refine_seconds = clock.lap();

    if (options.check) {
        result.checked = true;
        result.check_problems = mesh::check_mesh(mesh);
    }

    // Write.
    api::MeshArrays arrays = api::mesh_to_arrays(mesh, std::move(input.nodes.data), refined.new_vertices);
    refined.new_vertices = {};
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
    request.base = input.nodes.base;
    request.write_hull_poly = options.convex_hull;
    result.files_written = api::write_outputs(request, mesh, arrays);
    result.write_seconds = clock.lap();

    // -V: Triangle's timing and count lines, then the quality block.
    std::vector<std::string> lines{
        fmt::format("Read milliseconds:  {}", ms(result.read_seconds)),
        fmt::format("Delaunay milliseconds:  {}", ms(result.triangulate_seconds)),
        fmt::format("Quality milliseconds:  {}", ms(result.refine_seconds)),
        fmt::format("Output milliseconds:  {}", ms(result.write_seconds)),
        fmt::format("Total running milliseconds:  {}", ms(result.read_seconds + result.triangulate_seconds +
                                                          result.refine_seconds + result.write_seconds)),
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
    if (options.convex_hull || refining)
        lines.push_back(fmt::format("  Mesh subsegments (constrained edges): {}", result.segments));
    if (refining) {
        lines.push_back(fmt::format("  Steiner points added: {} ({} on segments)", refined.steiner_points,
                                    refined.segment_splits));
    }
    if (!result.statistics.empty()) lines.emplace_back();
    result.statistics.insert(result.statistics.begin(), lines.begin(), lines.end());
    return result;
}

}  // namespace gpdr
