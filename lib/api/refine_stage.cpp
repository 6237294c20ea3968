// The refinement stage of a run: switches -> refine::RefineSettings, the
// refiner itself, and what its report means to the user (warnings).

#include <cmath>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <fmt/format.h>

#include <gpdr/errors.hpp>

#include "api/job_stages.hpp"
#include "parallel/refine_parallel.hpp"
#include "parallel/rounds.hpp"
#include "refine/refine.hpp"

namespace gpdr::api {

bool wants_refinement(const Options& o) {
    // Triangle refines for -q, -a (either form) and -u alike; -D alone only
    // conforms (triangulate/conforming).
    return o.quality || o.area_limit || o.regional_area || o.user_test;
}

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
    s.placement = o.placement;
    s.no_segment_splitting = o.no_segment_splitting;
    s.steiner_limit = o.steiner_limit;
    s.max_steiner = o.max_steiner;
    s.granularity = o.granularity == 0 ? 1 : o.granularity;
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

std::vector<std::string> refine(mesh::Mesh& mesh, const refine::RefineSettings& settings,
                                const Options& o, refine::RefineReport& report) {
    parallel::ParallelOptions p;
    p.threads = o.threads;
    p.granularity = o.granularity;
    // -j1 runs the sequential refiner (one leaf, no quadtree, Triangle's
    // order).  So does -S, whose limit is exact only on one thread, and so
    // does an angle bound above 33 degrees (max_quadtree_angle).  -j0 on a
    // machine with one hardware thread runs the rounds on it: the same mesh
    // as -j0 anywhere else.
    const bool high_angle = o.quality && o.min_angle > parallel::max_quadtree_angle;
    p.one_leaf_for_one_thread = o.threads == 1 || o.steiner_limit || high_angle;
    p.deterministic = !o.nondeterministic;
    if (o.steiner_limit || high_angle) p.threads = 1;
    parallel::ParallelReport r;
    parallel::refine_parallel(mesh, settings, p, r);
#if defined(__GLIBC__)
    // The refiners' queues, lists and quadtree are freed now, much of it in
    // the worker threads' own malloc arenas, which keep freed memory
    // mapped.  The output arrays come next and would be mapped on top of
    // it, raising the peak by what refinement had in use (about 140 MB on
    // the graded pipe with -j2): give it back first.
    malloc_trim(0);
#endif
    report = std::move(r.refine);
    std::vector<std::string> lines;
    if (high_angle && o.threads != 1) {
        lines.emplace_back();
        lines.push_back(fmt::format(
            "Refinement on one thread, in Triangle's order: the angle bound is above {} degrees",
            parallel::max_quadtree_angle));
    }
    if (r.threads <= 1 && r.rounds.empty()) return lines;
    // The GPDR paper's Fig. 5 (right): where each thread's time went.
    const auto line = [](const char* who, unsigned i, const parallel::ThreadTimes& t) {
        return fmt::format("  {}{}: refining {:.0f} ms, managing {:.0f} ms, waiting {:.0f} ms", who,
                           i, t.refining * 1000, t.managing * 1000, t.waiting * 1000);
    };
    lines.emplace_back();
    if (r.rounds.empty()) {
        lines.push_back(fmt::format(
            "Parallel refinement: {} worker threads, granularity {}, {} leaves, {} assignments",
            r.threads, r.granularity, r.leaves, r.assignments));
        lines.push_back(fmt::format("  master: managing {:.0f} ms, waiting {:.0f} ms",
                                    r.master.managing * 1000, r.master.waiting * 1000));
        for (std::size_t w = 0; w < r.workers.size(); ++w)
            lines.push_back(line("worker ", unsigned(w + 1), r.workers[w]));
        return lines;
    }
    // The deterministic schedule: its rounds, and what they allow.
    const parallel::ScheduleShape s = parallel::schedule_shape(r.rounds);
    lines.push_back(fmt::format(
        "Parallel refinement: {} threads, granularity {}, {} leaves, {} rounds refining {} leaves",
        r.threads, r.granularity, r.leaves, s.rounds, s.runs));
    lines.push_back(fmt::format("  leaves per round: {} fewest, {} median, {} most", s.fewest,
                                s.median, s.most));
    lines.push_back(fmt::format(
        "  work {} triangles made, span {} (the largest leaf's of each round): work / span {:.1f}",
        s.work, s.span, s.parallelism()));
    lines.push_back(fmt::format(
        "  speed-up the rounds allow: {:.1f} on 4 threads, {:.1f} on 16, "
        "{:.1f} on 64",
        parallel::predicted_speedup(r.rounds, 4), parallel::predicted_speedup(r.rounds, 16),
        parallel::predicted_speedup(r.rounds, 64)));
    lines.push_back(
        fmt::format("  between rounds (the calling thread): {:.0f} ms", r.master.managing * 1000));
    for (std::size_t w = 0; w < r.workers.size(); ++w)
        lines.push_back(line("thread ", unsigned(w + 1), r.workers[w]));
    return lines;
}

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

}  // namespace gpdr::api
