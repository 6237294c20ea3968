// One run of gpdr: read -> triangulate -> refine -> write, timing each stage
// and collecting what -V and -C report.  Each stage takes the data of the
// one before and hands its result on; none reaches back.

#include <atomic>
#include <chrono>
#include <optional>

#include <fmt/format.h>

#include <gpdr/errors.hpp>
#include <gpdr/file_names.hpp>
#include <gpdr/job.hpp>
#include <gpdr/memory_job.hpp>

#include "api/job_stages.hpp"
#include "api/memory_available.hpp"
#include "api/memory_estimate.hpp"
#include "api/run_stamp.hpp"
#include "check/checker.hpp"
#include "check/input_check.hpp"
#include "mesh/traverse.hpp"
#include "parallel/refine_parallel.hpp"
#include "refine/quality.hpp"
#include "refine/refine.hpp"

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

std::string ms(double seconds) { return fmt::format("{:.0f}", seconds * 1000); }

// -V: Triangle's timing and count lines, before the quality block.
std::vector<std::string> summary_lines(const JobResult& r, const Options& options, bool refining,
                                       const refine::RefineReport& refined,
                                       std::uint64_t conforming_points) {
    std::vector<std::string> lines{
        fmt::format("Read milliseconds:  {}", ms(r.read_seconds)),
        fmt::format("{} milliseconds:  {}", options.poly || options.refine ? "Mesh" : "Delaunay",
                    ms(r.triangulate_seconds)),
        fmt::format("Quality milliseconds:  {}", ms(r.refine_seconds)),
        fmt::format("Output milliseconds:  {}", ms(r.write_seconds)),
        fmt::format("Total running milliseconds:  {}", ms(r.read_seconds + r.triangulate_seconds +
                                                          r.refine_seconds + r.write_seconds)),
        "",
        "Statistics:",
        "",
        fmt::format("  Input vertices: {}", r.input_vertices),
        "",
        fmt::format("  Mesh vertices: {}", r.vertices),
        fmt::format("  Mesh triangles: {}", r.triangles),
        fmt::format("  Mesh edges: {}", r.edges),
        fmt::format("  Mesh exterior boundary edges: {}", r.hull_edges),
    };
    if (options.poly || options.convex_hull || refining)
        lines.push_back(fmt::format("  Mesh subsegments (constrained edges): {}", r.segments));
    if (refining || conforming_points)
        lines.push_back(fmt::format("  Steiner points added: {} ({} by refinement, {} on segments)",
                                    refined.steiner_points + conforming_points,
                                    refined.steiner_points,
                                    refined.segment_splits + conforming_points));
    if (refining)
        lines.push_back(
            fmt::format("  Triangles below the angle bound because of small input angles: {}",
                        refined.left_small_input_angle));
    return lines;
}

// The stages every run shares: from the input, read and checked, to the
// finished mesh as arrays and its -V quality statistics.
struct Meshed {
    api::Triangulated tri;
    api::MeshArrays arrays;
    bool refining = false;
    refine::RefineReport refined;
    std::vector<std::string> parallel_lines;
    std::vector<std::string> quality;
    refine::UserTest user_test;  // -u: the test refinement met, for -C
};

// -C: the mesh on its own (topology, orientation, constrained Delaunay),
// then against the input geometry and the bounds asked for (those refinement
// was asked to meet and did not give up on; none when a limit stopped it).
std::vector<std::string> check(const Options& options, int base,
                               const mesh::InputGeometry& geometry, const api::Triangulated& tri,
                               const Meshed& m) {
    mesh::CheckOptions own;
    own.base = base;
    own.threads = parallel::thread_count(options.threads);
    std::vector<std::string> problems = mesh::check_mesh(tri.mesh, own);
    mesh::InputCheckOptions against;
    against.base = base;
    if (m.refining && m.refined.stopped == refine::RefineReport::Stop::none) {
        against.min_angle = options.quality ? options.min_angle : 0;
        against.max_area = options.area_limit ? options.max_area : 0;
        against.regional_area = options.regional_area && !options.refine;
        against.area_field = true;  // when the input had an .area file
        against.exempt = m.refined.given_up_triangles;
        if (m.user_test)
            against.unsuitable = [&](mesh::TriangleId t) {
                const mesh::Triangle& r = tri.mesh.triangle(t);
                const double area =
                    0.5 * geometry::orient2d(tri.mesh.point(r.v[0]), tri.mesh.point(r.v[1]),
                                             tri.mesh.point(r.v[2]));
                return refine::call_user_test(m.user_test, tri.mesh, r, area) != 0;
            };
    }
    against.region_attributes = options.region_attributes && options.poly && !options.refine;
    against.attribute_of_region = tri.region_attributes;
    std::vector<std::string> more = mesh::check_against_input(tri.mesh, geometry, against);
    problems.insert(problems.end(), more.begin(), more.end());
    return problems;
}

// Triangulates, refines, checks (-C) and turns the mesh into arrays,
// filling in `result`'s counts and the triangulate and refine times.  The
// triangles are always materialised with `materialise`, else only when an
// output derives from them.  Takes the vertices out of `input`.
Meshed make_mesh(const Options& options, api::Input& input, const WarningSink& warn,
                 const JobPlugins& plugins, bool materialise, JobResult& result, Stopwatch& clock,
                 Progress* progress = nullptr) {
    Meshed m;
    if (progress != nullptr) progress->enter(Progress::Stage::triangulating);
    // -C compares the mesh with the input as read, not as the stages saw it.
    std::optional<mesh::InputGeometry> geometry;
    if (options.check) geometry = api::input_geometry(options, input);
    api::Triangulated& tri = m.tri;
    tri = api::triangulate_input(options, input, warn);  // takes the coordinates
    result.triangulate_seconds = clock.lap();

    m.refining = api::wants_refinement(options);
    if (m.refining) {
        refine::RefineSettings settings =
            api::refine_settings(options, plugins, input.poly ? &*input.poly : nullptr);
        settings.criteria.area_field = tri.area_field.get();
        m.user_test = settings.criteria.user_test;
        settings.criteria.diametral_circles = options.conforming_delaunay;
        settings.segment_ends = tri.segment_ends;
        // -S counts every vertex gpdr adds, as Triangle's does: those -D
        // added, and those where segments cross.
        const std::uint64_t added = tri.steiner_points + tri.cdt_report.new_vertices.size();
        if (settings.steiner_limit)
            settings.max_steiner = settings.max_steiner > added ? settings.max_steiner - added : 0;
        api::warn_before_refinement(options, warn);
        api::refuse_beyond_memory(
            options,
            api::estimate_memory(options, tri.mesh, settings, input.nodes.data.attribute_count),
            api::memory_available());
        std::atomic<std::uint64_t> steiner_counter{0};
        if (progress != nullptr) {
            progress->enter(Progress::Stage::refining);
            // The refining threads count the vertices they add in one
            // atomic, in batches: reading it from the program's thread
            // costs them nothing.  (The mesh's vertex ids are no count:
            // parallel refinement claims them in chunks by a fixed rule,
            // with holes.)
            settings.steiner_counter = &steiner_counter;
            progress->watch([&steiner_counter, before = std::uint64_t{tri.mesh.vertex_end()}] {
                return before + steiner_counter.load(std::memory_order_relaxed);
            });
        }
        struct Unwatch {
            Progress* p;
            ~Unwatch() {
                if (p != nullptr) p->unwatch();
            }
        } unwatch{progress};
        m.parallel_lines = api::refine(tri.mesh, settings, options, m.refined);
        api::warn_after_refinement(m.refined, warn);
    }
    result.refine_seconds = clock.lap();
    if (progress != nullptr) progress->enter(Progress::Stage::preparing);

    if (options.check) {
        result.checked = true;
        result.check_problems = check(options, input.nodes.base, *geometry, tri, m);
    }

    // Neighbours cost 12 bytes per triangle: only the outputs that are
    // derived from them get them.
    const bool neighbours = options.write_neighbours || options.write_edges ||
                            options.write_voronoi || options.write_off || options.order == 2;
    // The triangle array itself only for what is derived from it.
    materialise = materialise || neighbours || options.jettison;
    m.arrays = api::mesh_to_arrays(tri.mesh, std::move(input.nodes.data), result.input_vertices,
                                   tri.triangle_attribute_count, tri.region_attributes, neighbours,
                                   materialise, parallel::thread_count(options.threads));
    result.vertices = m.arrays.nodes.size() - tri.duplicates;
    result.triangles = m.arrays.triangle_count;
    result.hull_edges = m.arrays.hull_edge_count;
    result.edges =
        (3 * result.triangles + result.hull_edges) / 2;  // each edge has two sides but the hull's
    result.segments = tri.mesh.subsegments().size();
    if (options.verbosity > 0) {
        // Before -o2 changes the triangles; not counted as output time (as
        // in Triangle, whose "Output milliseconds" are the writing alone).
        const double before = clock.lap();
        m.quality = api::quality_statistics(m.arrays, parallel::thread_count(options.threads));
        clock.lap();
        result.write_seconds += before;
    }
    return m;
}

// The -V lines, once every stage has been timed.
void add_statistics(JobResult& result, const Options& options, const Meshed& m) {
    result.statistics = summary_lines(result, options, m.refining, m.refined, m.tri.steiner_points);
    // The threads' times are -V's detail (libtriangle prints the rest
    // without it).
    if (options.verbosity > 0)
        result.statistics.insert(result.statistics.end(), m.parallel_lines.begin(),
                                 m.parallel_lines.end());
    if (!m.quality.empty()) {
        result.statistics.emplace_back();
        result.statistics.insert(result.statistics.end(), m.quality.begin(), m.quality.end());
    }
}

}  // namespace

JobResult run_job(const Options& given, const WarningSink& warn, const JobPlugins& plugins,
                  Progress* progress) {
    Options options = given;
    apply_input_name(options);
    const FileNames names = file_names(options);
    JobResult result;
    Stopwatch clock;

    // Read (every input is checked before anything else happens).
    if (progress != nullptr) progress->enter(Progress::Stage::reading);
    api::Input input = api::read_input(options, names, warn);
    result.input_vertices = input.nodes.data.size();
    if (progress != nullptr) progress->set_input_vertices(result.input_vertices);
    result.read_seconds = clock.lap();

    Meshed m = make_mesh(options, input, warn, plugins, false, result, clock, progress);

    api::OutputRequest request;
    request.options = &options;
    request.names = &names;
    request.base = input.nodes.base;
    request.poly = input.poly ? &*input.poly : nullptr;
    request.write_hull_poly = options.convex_hull;
    request.progress = progress;
    request.stamp = api::run_stamp(options.command.empty() ? "gpdr" : options.command,
                                   input.content_hash, result.vertices, result.triangles);
    // A mesh -C found wrong is not written: no file is made or replaced.
    if (!result.checked || result.check_problems.empty())
        result.files_written = api::write_outputs(request, m.tri.mesh, m.arrays);
    result.write_seconds += clock.lap();
    if (progress != nullptr) progress->enter(Progress::Stage::finished);

    add_statistics(result, options, m);
    return result;
}

MemoryJobResult run_job_in_memory(const Options& given, MeshInput input, const WarningSink& warn,
                                  const JobPlugins& plugins) {
    Options options = given;
    options.write_off = false;  // -g makes only a file
    if (options.help) throw UsageError("-h: there is no help text to print in library mode");
    MemoryJobResult out;
    JobResult& result = out.report;
    Stopwatch clock;

    api::Input in = api::input_from_memory(options, std::move(input));
    result.input_vertices = in.nodes.data.size();
    result.read_seconds = clock.lap();

    Meshed m = make_mesh(options, in, warn, plugins, true, result, clock);
    out.mesh = api::output_in_memory(options, m.tri.mesh, m.arrays);
    result.write_seconds += clock.lap();

    add_statistics(result, options, m);
    return out;
}

}  // namespace gpdr
