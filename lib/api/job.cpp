// One run of gpdr: read -> triangulate -> refine -> write, timing each stage
// and collecting what -V and -C report.  Each stage takes the data of the
// one before and hands its result on; none reaches back.

#include <optional>

#include <fmt/format.h>

#include <gpdr/errors.hpp>
#include <gpdr/file_names.hpp>
#include <gpdr/job.hpp>
#include <gpdr/memory_job.hpp>

#include "api/job_stages.hpp"
#include "api/run_stamp.hpp"
#include "check/checker.hpp"
#include "check/input_check.hpp"
#include "mesh/traverse.hpp"
#include "parallel/refine_parallel.hpp"
#include "parallel/stopwatch.hpp"
#include "refine/quality.hpp"
#include "refine/refine.hpp"

namespace gpdr {
namespace {

using parallel::Stopwatch;

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
    std::optional<api::Refinement> refinement;  // when the switches ask for it
    api::MeshArrays arrays;
    std::vector<std::string> quality;
};

// -C: the mesh on its own (topology, orientation, constrained Delaunay),
// then against the input geometry and the bounds asked for (those refinement
// was asked to meet and did not give up on; none when a limit stopped it).
// An angle bound out of reach (above 34 degrees) is a problem in itself.
std::vector<std::string> check(const Options& options, int base,
                               const mesh::InputGeometry& geometry, const api::Triangulated& tri,
                               const std::optional<api::Refinement>& refinement) {
    mesh::CheckOptions own;
    own.base = base;
    own.threads = parallel::thread_count(options.threads);
    std::vector<std::string> problems = mesh::check_mesh(tri.mesh, own);
    mesh::InputCheckOptions against;
    against.base = base;
    using Stop = refine::RefineReport::Stop;
    // The mesh handed back for a bound out of reach is held to the bound it
    // was refined to.
    const bool out_of_reach =
        refinement && refinement->report.refine.stopped == Stop::not_converging;
    if (out_of_reach)
        problems.push_back(fmt::format(
            "the minimum angle of {} degrees was not met: refinement did not converge, and the "
            "mesh reached {:.1f} degrees",
            options.min_angle, refinement->report.refine.angle_reached));
    if (refinement && (refinement->report.refine.stopped == Stop::none || out_of_reach)) {
        const refine::RefineReport& refined = refinement->report.refine;
        const refine::UserTest& user_test = refinement->user_test;
        against.min_angle = !options.quality ? 0
                            : out_of_reach   ? refined.angle_refined
                                             : options.min_angle;
        against.max_area = options.area_limit ? options.max_area : 0;
        against.regional_area = options.regional_area && !options.refine;
        against.area_field = true;  // when the input had an .area file
        against.exempt = refined.given_up_triangles;
        if (user_test)
            against.unsuitable = [&](mesh::TriangleId t) {
                const mesh::Triangle& r = tri.mesh.triangle(t);
                const double area =
                    0.5 * geometry::orient2d(tri.mesh.point(r.v[0]), tri.mesh.point(r.v[1]),
                                             tri.mesh.point(r.v[2]));
                return refine::call_user_test(user_test, tri.mesh, r, area) != 0;
            };
    }
    against.region_attributes = options.region_attributes && options.poly && !options.refine;
    against.attribute_of_region = tri.region_attributes;
    std::vector<std::string> more = mesh::check_against_input(tri.mesh, geometry, against);
    problems.insert(problems.end(), more.begin(), more.end());
    return problems;
}

// The finished mesh as arrays, and the counts of `result` they give.  The
// triangles are materialised with `materialise`, else only when an output
// derives from them.  With `free_points`, the mesh's points are given back
// as they are copied (ArrayChoices::free_points_of): the caller reads only
// the arrays from then on.  With `counts_only`, no arrays: only the
// counts.  Takes the vertices out of `input`.
void to_arrays(const Options& options, api::Input& input, bool materialise, bool free_points,
               bool counts_only, Meshed& m, JobResult& result) {
    if (counts_only) {
        // A run that writes no file and prints no statistics: the counts
        // alone (numbering the vertices and triangles and copying the points
        // would be a tenth of a -QNEP Delaunay run).
        const api::MeshCounts counts = api::count_mesh(m.tri.mesh, result.input_vertices,
                                                       parallel::thread_count(options.threads));
        result.vertices = counts.nodes - m.tri.duplicates;
        result.triangles = counts.triangles;
        result.hull_edges = counts.hull_edges;
        result.edges = (3 * result.triangles + result.hull_edges) / 2;
        result.segments = m.tri.mesh.subsegments().size();
        return;
    }
    // Neighbours cost 12 bytes per triangle: only the outputs that are
    // derived from them get them.
    const bool neighbours = options.write_neighbours || options.write_edges ||
                            options.write_voronoi || options.write_off || options.order == 2;
    api::ArrayChoices choices;
    choices.neighbours = neighbours;
    choices.materialise = materialise || neighbours || options.jettison;
    // A node's mesh vertex: for the edge markers of .edge and -o2, and for
    // jettisoning (write_outputs.cpp).
    choices.mesh_ids = options.write_edges || options.order == 2 || options.jettison;
    choices.threads = parallel::thread_count(options.threads);
    if (free_points) choices.free_points_of = &m.tri.mesh;
    m.arrays =
        api::mesh_to_arrays(m.tri.mesh, std::move(input.nodes.data), result.input_vertices,
                            m.tri.triangle_attribute_count, m.tri.region_attributes, choices);
    result.vertices = m.arrays.nodes.size() - m.tri.duplicates;
    result.triangles = m.arrays.triangle_count;
    result.hull_edges = m.arrays.hull_edge_count;
    result.edges =
        (3 * result.triangles + result.hull_edges) / 2;  // each edge has two sides but the hull's
    result.segments = m.tri.mesh.subsegments().size();
}

// The stages from the input to the arrays: triangulate, refine, check (-C),
// to arrays, and -V's quality statistics; fills in `result`'s counts and the
// stages' times.
Meshed make_mesh(const Options& options, api::Input& input, const WarningSink& warn,
                 const JobPlugins& plugins, bool materialise, bool free_points, bool counts_only,
                 JobResult& result, Stopwatch& clock, Progress* progress = nullptr) {
    Meshed m;
    if (progress != nullptr) progress->enter(Progress::Stage::triangulating);
    // -C compares the mesh with the input as read, not as the stages saw it.
    std::optional<mesh::InputGeometry> geometry;
    if (options.check) geometry = api::input_geometry(options, input);
    m.tri = api::triangulate_input(options, input, warn);  // takes the coordinates
    result.triangulate_seconds = clock.lap();

    if (api::wants_refinement(options))
        m.refinement = api::refine_stage(options, plugins, input, m.tri, warn, progress);
    result.refine_seconds = clock.lap();
    if (progress != nullptr) progress->enter(Progress::Stage::preparing);

    if (options.check) {
        result.checked = true;
        result.check_problems = check(options, input.nodes.base, *geometry, m.tri, m.refinement);
    }
    to_arrays(options, input, materialise, free_points, counts_only, m, result);
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
    const refine::RefineReport none;
    result.statistics =
        summary_lines(result, options, m.refinement.has_value(),
                      m.refinement ? m.refinement->report.refine : none, m.tri.steiner_points);
    // The schedule and the threads' times are -V's detail (libtriangle
    // prints the rest without it).
    if (options.verbosity > 0 && m.refinement) {
        const std::vector<std::string> lines = api::refinement_lines(*m.refinement);
        result.statistics.insert(result.statistics.end(), lines.begin(), lines.end());
    }
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

    // The files are written from the arrays and the mesh's triangles and
    // subsegments (write_outputs.cpp): never from its points.  A run that
    // writes none (and without -V) needs no arrays at all.
    const bool writes = api::writes_files(options, names, options.convex_hull);
    const bool counts_only = !writes && options.verbosity == 0;
    Meshed m =
        make_mesh(options, input, warn, plugins, false, true, counts_only, result, clock, progress);

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
    if (writes && (!result.checked || result.check_problems.empty()))
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

    Meshed m = make_mesh(options, in, warn, plugins, true, false, false, result, clock);
    out.mesh = api::output_in_memory(options, m.tri.mesh, m.arrays);
    result.write_seconds += clock.lap();

    add_statistics(result, options, m);
    return out;
}

}  // namespace gpdr
