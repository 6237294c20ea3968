// The refinement stage of a run: switches -> refine::RefineSettings, the
// budget and the memory check, the refiner on the schedule the options
// choose (parallel/schedule.hpp), and what its report means to the user
// (warnings, -V lines).

#include <atomic>
#include <cmath>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <fmt/format.h>

#include <gpdr/errors.hpp>

#include "api/job_stages.hpp"
#include "api/memory_available.hpp"
#include "api/memory_estimate.hpp"
#include "parallel/refine_parallel.hpp"
#include "parallel/rounds.hpp"
#include "refine/refine.hpp"

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

void warn_before_refinement(const Options& o, const WarningSink& warn) {
    if (o.quality && o.min_angle > 34.0)
        warn(Warning{
            "", 0,
            fmt::format("a minimum angle of {} degrees may be out of reach (Triangle's refinement "
                        "usually works up to about 34); gpdr stops with a valid mesh if it is",
                        o.min_angle)});
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

void warn_after_refinement(const refine::RefineReport& r, const WarningSink& warn) {
    using Stop = refine::RefineReport::Stop;
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
#if defined(__GLIBC__)
    // The refiners' queues, lists and quadtree are freed now, much of it in
    // the refining threads' own malloc arenas, which keep freed memory
    // mapped.  The output arrays come next and would be mapped on top of
    // it, raising the peak by what refinement had in use (about 140 MB on
    // the graded pipe with -j2): give it back first.
    malloc_trim(0);
#endif
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
    warn_before_refinement(options, warn);
    refuse_beyond_memory(
        options, estimate_memory(options, tri.mesh, settings, input.nodes.data.attribute_count),
        memory_available());

    Refinement r;
    r.schedule = parallel::choose_schedule(options);
    r.user_test = settings.criteria.user_test;
    {
        const ProgressWatch watch(progress, tri.mesh, settings);
        parallel::refine_parallel(tri.mesh, settings, r.schedule, r.report);
    }
    trim_freed_memory();
    warn_after_refinement(r.report.refine, warn);
    return r;
}

std::vector<std::string> refinement_lines(const Refinement& r) {
    std::vector<std::string> lines{"", r.schedule.describe()};
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
