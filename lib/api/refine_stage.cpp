// The refinement stage of a run: switches -> refine::RefineSettings, the
// budget and the memory check, the refiner on the schedule the options
// choose (parallel/schedule.hpp), and what its report means to the user
// (warnings, -V lines).

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include <gpdr/errors.hpp>

#include "api/job_stages.hpp"
#include "api/memory_available.hpp"
#include "api/memory_estimate.hpp"
#include "parallel/freed_memory.hpp"
#include "parallel/refine_parallel.hpp"
#include "parallel/rounds.hpp"
#include "parallel/stopwatch.hpp"
#include "refine/convergence.hpp"
#include "refine/mesh_copy.hpp"
#include "refine/refine.hpp"
#include "refine/star_placement.hpp"

namespace gpdr::api {

bool wants_refinement(const Options& o) {
    // Triangle refines for -q, -a (either form) and -u alike; -D alone only
    // conforms (triangulate/conforming).
    return o.quality || o.area_limit || o.regional_area || o.user_test;
}

namespace {

// The settings the switches ask for (throws UsageError for -u with no
// function).
refine::RefineSettings refine_settings(const Options& o, const JobPlugins& plugins,
                                       const PolyFile* poly) {
    refine::RefineSettings s;
    if (o.quality) s.criteria.min_angle_degrees = o.min_angle;
    if (o.area_limit) s.criteria.max_area = o.max_area;
    if (o.regional_area && poly && !o.refine) {
        // The CDT numbers region i of the .poly as i + 1; 0 is "no region".
        // With -r the triangles carry the .ele's attributes instead, and a
        // bare -a means the .area file (Triangle ignores the regions too).
        s.criteria.region_max_area.assign(poly->regions.size() + 1, -1.0);
        for (std::size_t i = 0; i < poly->regions.size(); ++i)
            s.criteria.region_max_area[i + 1] = poly->regions[i].max_area;
    }
    if (o.user_test) {
        if (!plugins.triunsuitable && !plugins.unsuitable)
            throw UsageError(
                "-u needs a triunsuitable() function: load one with --unsuitable PATH.so "
                "(built with 'cc -shared -fPIC -O2 -o PATH.so yours.c'), or link it into gpdr "
                "(cmake "
                "-DGPDR_TRIUNSUITABLE=yours.c; see README, \"Grading with triunsuitable()\")");
        if (plugins.unsuitable)
            s.criteria.user_test = plugins.unsuitable;
        else
            s.criteria.user_test = plugins.triunsuitable;
    }
    s.criteria.diametral_circles = o.conforming_delaunay;
    s.placement = o.placement;
    s.no_segment_splitting = o.no_segment_splitting;
    s.steiner_limit = o.steiner_limit;
    s.max_steiner = o.max_steiner;
    return s;
}

// While it lives, the progress line shows the vertices refinement adds: the
// refining threads count them in one atomic, in batches, so reading it from
// the program's thread costs them nothing.  (The mesh's vertex ids are no
// count: parallel refinement claims them in chunks by a fixed rule, with
// holes.)
class ProgressWatch {
public:
    ProgressWatch(Progress* progress, const mesh::Mesh& mesh, refine::RefineSettings& settings)
        : progress_(progress) {
        if (progress_ == nullptr) return;
        progress_->enter(Progress::Stage::refining);
        settings.steiner_counter = &added_;
        progress_->watch([this, before = std::uint64_t{mesh.vertex_end()}] {
            return before + added_.load(std::memory_order_relaxed);
        });
    }
    ~ProgressWatch() {
        if (progress_ != nullptr) progress_->unwatch();
    }
    ProgressWatch(const ProgressWatch&) = delete;
    ProgressWatch& operator=(const ProgressWatch&) = delete;

private:
    Progress* progress_;
    std::atomic<std::uint64_t> added_{0};
};

void warn_after_refinement(const Options& o, const refine::RefineReport& r,
                           const WarningSink& warn) {
    using Stop = refine::RefineReport::Stop;
    if (r.stopped == Stop::not_converging)
        warn(Warning{"", 0,
                     fmt::format("a minimum angle of {} degrees is out of reach for this input: "
                                 "refinement did not converge (it split ever smaller triangles), "
                                 "so the mesh is the one refined to {} degrees; it reached {:.1f} "
                                 "degrees of {} (apart from small input angles)",
                                 o.min_angle, r.angle_refined, r.angle_reached, o.min_angle)});
    if (r.stopped == Stop::steiner_limit)
        warn(Warning{
            "", 0,
            fmt::format("refinement stopped at the Steiner point limit (-S) after {} points; "
                        "{} triangles still fail the quality bounds",
                        r.steiner_points, r.left_budget)});
    if (r.stopped == Stop::safety_limit)
        warn(Warning{"", 0,
                     fmt::format("refinement stopped at its safety limit of {} Steiner points "
                                 "(2^20, plus 64 per triangle of the input and per triangle the "
                                 "area bounds call for), which a refinement that ends never "
                                 "reaches: the angle bound is out of reach for this input (above "
                                 "about 34 degrees, or next to small input angles); the mesh is "
                                 "valid but {} triangles still fail the bounds",
                                 r.safety_limit, r.left_budget)});
    if (r.left_precision)
        warn(Warning{"", 0,
                     fmt::format("{} triangles were left as they are because refining them further "
                                 "would exhaust floating-point precision",
                                 r.left_precision)});
    if (r.left_no_split)
        warn(Warning{"", 0,
                     fmt::format("{} triangles were left as they are because -Y/-YY forbids "
                                 "splitting the segments they encroach",
                                 r.left_no_split)});
    if (r.left_other)
        warn(Warning{"", 0,
                     fmt::format("{} triangles still fail the quality bounds (please report this)",
                                 r.left_other)});
}

void trim_freed_memory() {
    // The refiners' queues, lists and quadtree are freed now, much of it in
    // the refining threads' own malloc arenas, which keep freed memory
    // mapped.  The output arrays come next and would be mapped on top of
    // it, raising the peak by what refinement had in use (about 140 MB on
    // the graded pipe with -j2): give it back first.
    parallel::return_freed_memory();
}

// ---- above 34 degrees ---------------------------------------------------------
//
// Refinement above 34 degrees may not end (refine/convergence.hpp), and
// whether it ends depends on where the Steiner points go as much as on the
// input.  So the asked bound is tried with each placement of -P1 in turn
// (refine/star_placement.hpp), each on a copy of the constrained Delaunay
// mesh, until one ends with the bound met.  If none does, the bound is out
// of reach, and the mesh handed back is the best one found below it: the
// 34-degree mesh (or, when even that does not end, the largest bound of
// `floor_angles` that ends), then bounds halfway between the best that ended
// and the lowest that did not, down to a step of `angle_step`, each tried
// with every placement within a budget of 10 times the floor mesh's
// triangles.  A try that does not converge stops within thousands of
// Steiner points, so the tries that fail cost little.

constexpr double floor_angles[] = {34.0, 33.0, 32.0, 30.0, 27.0, 24.0, 20.0};
constexpr double angle_step = 0.25;
constexpr std::uint64_t growth_allowed = 10;  // triangles, against the floor mesh's

struct Try {
    mesh::Mesh mesh;
    parallel::ParallelReport report;
    double angle = 0;
    bool ended() const {
        return report.refine.stopped == refine::RefineReport::Stop::none &&
               report.refine.left_precision == 0;
    }
};

// Refines a copy of `cdt` with the bound `angle`, `strategy` (nullptr: the
// built-in one) and at most `budget` Steiner points (0: the safety limit),
// stopping when it cascades unless `watch` is false.  Appends what it did to
// `tries`.
Try try_bound(mesh::Mesh& cdt, refine::RefineSettings s, const parallel::Schedule& schedule,
              double angle, const refine::PlacementStrategy* strategy, std::uint64_t budget,
              std::vector<refine::RefineReport::Try>& tries, bool watch = true) {
    parallel::Stopwatch clock;
    Try t{refine::copy_mesh(cdt), {}, angle};
    s.criteria.min_angle_degrees = angle;
    s.strategy = strategy;
    s.safety_limit = budget;
    s.watch_convergence = watch;
    if (s.steiner_counter != nullptr) s.steiner_counter->store(0, std::memory_order_relaxed);
    parallel::refine_parallel(t.mesh, s, schedule, t.report);
    const refine::RefineReport& r = t.report.refine;
    tries.push_back({angle,
                     strategy != nullptr ? strategy->name()
                                         : refine::builtin_placement(s.placement, angle).name(),
                     r.stopped, r.steiner_points, r.left_precision, clock.lap()});
    return t;
}

// The placements tried for `angle`: each of -P1's above 34 degrees, else
// the one the options ask for.
std::vector<const refine::PlacementStrategy*> placements_for(const Options& o, double angle) {
    if (o.placement == Placement::off_centre && angle > refine::star_placement_above) {
        const auto all = refine::star_placements();
        return {all.begin(), all.end()};
    }
    return {nullptr};
}

// The first try at `angle` that ends with its bound met, with each placement.
std::optional<Try> try_each_placement(const Options& o, mesh::Mesh& cdt,
                                      const refine::RefineSettings& s,
                                      const parallel::Schedule& schedule, double angle,
                                      std::uint64_t budget,
                                      std::vector<refine::RefineReport::Try>& tries) {
    for (const refine::PlacementStrategy* strategy : placements_for(o, angle)) {
        Try t = try_bound(cdt, s, schedule, angle, strategy, budget, tries);
        if (t.ended()) return t;
    }
    return std::nullopt;
}

// The best mesh below the asked bound (see above), its report saying so.
Try best_below(const Options& o, mesh::Mesh& cdt, const refine::RefineSettings& s,
               const parallel::Schedule& schedule, std::vector<refine::RefineReport::Try>& tries) {
    std::optional<Try> best;
    for (const double angle : floor_angles) {
        if (angle >= o.min_angle) continue;
        best = try_each_placement(o, cdt, s, schedule, angle, 0, tries);
        if (best) break;
    }
    if (!best)  // the lowest, unwatched, as below 34 degrees (the safety limit's warning)
        return try_bound(cdt, s, schedule, floor_angles[std::size(floor_angles) - 1], nullptr, 0,
                         tries, false);
    const std::uint64_t floor_triangles = best->mesh.count_triangles();
    const std::uint64_t start = cdt.count_triangles();
    // A vertex inside makes two triangles, one on a segment one: half the
    // allowed growth in Steiner points keeps within it.
    const std::uint64_t budget = std::max<std::uint64_t>(
        1,
        (growth_allowed * floor_triangles - std::min(growth_allowed * floor_triangles, start)) / 2);
    double low = best->angle, high = o.min_angle;
    while (high - low > angle_step) {
        const double middle = std::round((low + high) / 2 * 100) / 100;
        if (std::optional<Try> t = try_each_placement(o, cdt, s, schedule, middle, budget, tries)) {
            best = std::move(t);
            low = middle;
        } else {
            high = middle;
        }
    }
    best->report.refine.stopped = refine::RefineReport::Stop::not_converging;
    best->report.refine.angle_refined = best->angle;
    best->report.refine.angle_reached = refine::smallest_angle_degrees(best->mesh);
    return std::move(*best);
}

// Refinement with a bound above 34 degrees (see above).
void refine_above_34(const Options& o, Triangulated& tri, const refine::RefineSettings& s,
                     Refinement& r) {
    mesh::Mesh cdt = refine::copy_mesh(tri.mesh);
    std::vector<refine::RefineReport::Try> tries;
    std::optional<Try> done = try_each_placement(o, cdt, s, r.schedule, o.min_angle, 0, tries);
    if (!done) done = best_below(o, cdt, s, r.schedule, tries);
    tri.mesh = std::move(done->mesh);
    r.report = std::move(done->report);
    r.report.refine.tries = std::move(tries);
}

// What became of a try, for -V.
std::string try_outcome(const refine::RefineReport::Try& t) {
    using Stop = refine::RefineReport::Stop;
    switch (t.stopped) {
        case Stop::none:
            return t.left_precision == 0 ? "ended, bound met"
                                         : "ended, triangles left for precision";
        case Stop::not_converging:
            return "not converging";
        case Stop::safety_limit:
            return "stopped by its budget";
        case Stop::steiner_limit:
            return "stopped by -S";
    }
    return "";
}

}  // namespace

Refinement refine_stage(const Options& options, const JobPlugins& plugins, const Input& input,
                        Triangulated& tri, const WarningSink& warn, Progress* progress) {
    refine::RefineSettings settings =
        refine_settings(options, plugins, input.poly ? &*input.poly : nullptr);
    settings.criteria.area_field = tri.area_field.get();
    settings.segment_ends = tri.segment_ends;
    // -S counts every vertex gpdr adds, as Triangle's does: those -D added,
    // and those where segments cross.
    const std::uint64_t added = tri.steiner_points + tri.cdt_report.new_vertices.size();
    if (settings.steiner_limit)
        settings.max_steiner = settings.max_steiner > added ? settings.max_steiner - added : 0;
    refuse_beyond_memory(
        options, estimate_memory(options, tri.mesh, settings, input.nodes.data.attribute_count),
        memory_available());

    Refinement r;
    r.schedule = parallel::choose_schedule(options);
    r.user_test = settings.criteria.user_test;
    {
        const ProgressWatch watch(progress, tri.mesh, settings);
        // (-S caps the whole run: one try, as below 34 degrees.)
        if (options.quality && options.min_angle > refine::watched_above && !options.steiner_limit)
            refine_above_34(options, tri, settings, r);
        else
            parallel::refine_parallel(tri.mesh, settings, r.schedule, r.report);
    }
    trim_freed_memory();
    warn_after_refinement(options, r.report.refine, warn);
    return r;
}

std::vector<std::string> refinement_lines(const Refinement& r) {
    std::vector<std::string> lines{"", r.schedule.describe()};
    for (const refine::RefineReport::Try& t : r.report.refine.tries)
        lines.push_back(
            fmt::format("  tried {} degrees, placement {}: {} after {} Steiner points, "
                        "{:.0f} ms",
                        t.angle, t.placement, try_outcome(t), t.steiner_points, t.seconds * 1000));
    const parallel::ParallelReport& p = r.report;
    if (p.rounds.empty()) return lines;
    // The GPDR paper's Fig. 5 (right): where each thread's time went.
    const auto line = [](unsigned i, const parallel::ThreadTimes& t) {
        return fmt::format("  thread {}: refining {:.0f} ms, managing {:.0f} ms, waiting {:.0f} ms",
                           i, t.refining * 1000, t.managing * 1000, t.waiting * 1000);
    };
    // The rounds, and what they allow.
    const parallel::ScheduleShape s = parallel::schedule_shape(p.rounds);
    lines.push_back(
        fmt::format("  {} leaves, {} rounds refining {} leaves", p.leaves, s.rounds, s.runs));
    lines.push_back(fmt::format("  leaves per round: {} fewest, {} median, {} most", s.fewest,
                                s.median, s.most));
    lines.push_back(fmt::format(
        "  work {} triangles made, span {} (the largest leaf's of each round): work / span {:.1f}",
        s.work, s.span, s.parallelism()));
    lines.push_back(fmt::format(
        "  speed-up the rounds allow: {:.1f} on 4 threads, {:.1f} on 16, {:.1f} on 64",
        parallel::predicted_speedup(p.rounds, 4), parallel::predicted_speedup(p.rounds, 16),
        parallel::predicted_speedup(p.rounds, 64)));
    lines.push_back(
        fmt::format("  between rounds (the calling thread): {:.0f} ms", p.master.managing * 1000));
    for (std::size_t w = 0; w < p.workers.size(); ++w)
        lines.push_back(line(unsigned(w + 1), p.workers[w]));
    return lines;
}

}  // namespace gpdr::api
