// Refinement on its schedule: the sequential refiner, or the rounds' set-up
// (root square, lanes, first leaf), the rounds, and the merged report.  See
// refine_parallel.hpp.

#include "parallel/refine_parallel.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <memory>

#include "geometry/constructions.hpp"
#include "mesh/traverse.hpp"
#include "parallel/rounds.hpp"
#include "parallel/scheduler.hpp"
#include "parallel/segment_labels.hpp"
#include "parallel/stopwatch.hpp"
#include "parallel/worker.hpp"

namespace gpdr::parallel {

namespace {

// The root square: it holds every circumdisk of the mesh (so every Steiner
// point, and by the Bowyer-Watson containment every later circumdisk, lies
// in it) and has side > 4 r_max, so relation (9) holds for it from the start.
Square root_square(const mesh::Mesh& mesh) {
    double min_x = std::numeric_limits<double>::infinity(), min_y = min_x, max_x = -min_x,
           max_y = -min_x, r_max = 0;
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId, const mesh::Triangle& t) {
        const geometry::Circle c =
            geometry::circumcircle(mesh.point(t.v[0]), mesh.point(t.v[1]), mesh.point(t.v[2]));
        const double r = std::sqrt(c.radius_squared);
        if (!std::isfinite(r)) return;
        min_x = std::min(min_x, c.centre.x - r);
        max_x = std::max(max_x, c.centre.x + r);
        min_y = std::min(min_y, c.centre.y - r);
        max_y = std::max(max_y, c.centre.y + r);
        r_max = std::max(r_max, r);
    });
    if (!(max_x >= min_x)) return {0, 0, 1};
    double side = std::max({max_x - min_x, max_y - min_y, 4.0 * r_max});
    side = side * (1.0 + 0x1p-20) + std::numeric_limits<double>::min();
    return {0.5 * (min_x + max_x) - 0.5 * side, 0.5 * (min_y + max_y) - 0.5 * side, side};
}

void merge(refine::RefineReport& into, refine::RefineReport& from) {
    into.steiner_points += from.steiner_points;
    into.segment_splits += from.segment_splits;
    into.triangles_created += from.triangles_created;
    if (into.stopped == refine::RefineReport::Stop::none) {
        into.stopped = from.stopped;
        into.safety_limit = from.safety_limit;
    }
}

// One flat leaf in Triangle's order (refine::refine_mesh).  Labelled here
// too: without labels the small-angle rule walks a subsegment's chain (up to
// 256 steps each way) every time it is asked, which long chains, as -D's
// splits make on a -r mesh's boundary, turn into most of the run.
void refine_sequential(mesh::Mesh& mesh, refine::RefineSettings settings, ParallelReport& report) {
    Stopwatch clock;
    SegmentLabels labels(mesh, settings.segment_ends);
    settings.segment_ends = labels.ends();
    refine::refine_mesh(mesh, settings, report.refine);
    labels.restore();
    report.workers.assign(1, ThreadTimes{clock.lap(), 0, 0});
    report.leaves = 1;
}

// The lanes of the rounds (rounds.hpp), whose pools claim ids by their own
// rule, made in order (mesh::Lane).
std::vector<std::unique_ptr<Worker>> make_lanes(mesh::Mesh& mesh, refine::RefineRun& run,
                                                Quadtree& tree, bool checked) {
    std::vector<std::unique_ptr<Worker>> lanes;
    const mesh::Lane first = mesh::Lane::first(mesh, lane_count);
    for (unsigned l = 0; l < lane_count; ++l) {
        mesh::Lane lane = first;
        lane.index = l;
        lanes.push_back(std::make_unique<Worker>(mesh, run, tree, lane, checked));
    }
    return lanes;
}

// The first leaf: the root, every triangle counted and classified by lane 0.
void seed_root(const mesh::Mesh& mesh, const refine::RefineRun& run, Quadtree& tree, Worker& lane) {
    Node& root = tree.node(Quadtree::root());
    root.state = lane.new_leaf_state(Quadtree::root());
    lane.count_all();
    lane.refiner().classify_all(root.state->work);
    // Everything lies in the root; anything handed off (a centre on the
    // root's far edge) stays with it.
    refine::Leaf& w = root.state->work;
    for (auto q : w.handed_off_triangles) {
        const mesh::Triangle& t = mesh.triangle(q.id);
        const refine::TriangleMeasures m = refine::QualityTest::measure(
            mesh.point(t.v[0]), mesh.point(t.v[1]), mesh.point(t.v[2]));
        q.where = w.where(m.circle.centre);
        w.push_poor(q, w.slot(m.circle.radius_squared, m.shortest.length_squared,
                              refine::poor_kind(run.order(), run.quality(), m)));
    }
    w.handed_off_triangles.clear();
}

// The lanes' reports merged into `report`, and the final count of what is
// left poor (refine_mesh's).
void merge_lanes(mesh::Mesh& mesh, const refine::RefineRun& run,
                 std::vector<std::unique_ptr<Worker>>& lanes, bool checked, unsigned threads,
                 ParallelReport& report) {
    std::vector<refine::LeafRefiner::GivenUp> given_up;
    for (auto& w : lanes) {
        merge(report.refine, w->report);
        const auto& g = w->refiner().given_up();
        given_up.insert(given_up.end(), g.begin(), g.end());
        report.handed_off_local += w->handed_off_local;
        report.relation9_exceptions += w->relation9_exceptions;
        if (w->zone_escapes != 0 && checked)
            report.problems.push_back(
                "a worker counted a triangle in a leaf outside its buffer zone");
    }
    lanes.clear();  // the pools give their spare slots back
    refine::count_left(mesh, run, std::move(given_up), report.refine, threads);
}

// Schedule::record: before each round runs, its leaves, their triangles and
// its buffer zones go to report.record (round_record.hpp).
std::function<void(const std::vector<NodeId>&)> round_recorder(const mesh::Mesh& mesh,
                                                               const Quadtree& tree,
                                                               const Scheduler& scheduler,
                                                               ParallelReport& report) {
    // (The objects, not this function's references to them, are captured.)
    return [m = &mesh, t = &tree, s = &scheduler, r = &report](const std::vector<NodeId>& round) {
        r->record.push_back(
            record_round(*m, *t, round, [s](std::size_t i) -> const std::vector<NodeId>& {
                return s->zone(static_cast<int>(i));
            }));
    };
}

// The recorded runs' work, from the rounds' own record of it.
void record_work(ParallelReport& report) {
    for (std::size_t i = 0; i < report.record.size() && i < report.rounds.size(); ++i) {
        std::vector<RecordedRun>& runs = report.record[i].runs;
        for (std::size_t j = 0; j < runs.size() && j < report.rounds[i].size(); ++j)
            runs[j].work = report.rounds[i][j];
    }
}

// Rounds over the quadtree on schedule.threads threads.
void refine_in_rounds(mesh::Mesh& mesh, refine::RefineSettings settings, const Schedule& schedule,
                      ParallelReport& report) {
    Stopwatch clock;
    SegmentLabels labels(mesh, settings.segment_ends);
    settings.segment_ends = labels.ends();
    refine::RefineRun run(mesh, settings);
    const Square root = root_square(mesh);
    Quadtree tree(root.x0, root.y0, root.side);
    std::vector<std::unique_ptr<Worker>> lanes = make_lanes(mesh, run, tree, schedule.checked);
    seed_root(mesh, run, tree, *lanes[0]);
    Scheduler scheduler(tree, report, schedule.checked);
    if (lanes[0]->outgrew_root) scheduler.set_serial();
    scheduler.offer(Quadtree::root());
    report.master.managing += clock.lap();

    std::exception_ptr failure;
    const std::function<void()> check = [&] {
        verify_quadtree(mesh, tree, report.problems);
        ++report.checks;
        for (const auto& w : lanes)
            if (w->zone_escapes != 0)
                report.problems.push_back(
                    "a worker counted a triangle in a leaf outside its buffer zone");
    };
    const auto record = schedule.record ? round_recorder(mesh, tree, scheduler, report)
                                        : std::function<void(const std::vector<NodeId>&)>{};
    run_rounds(lanes, scheduler, schedule.threads, schedule.checked, report, failure, check,
               record);
    if (failure) std::rethrow_exception(failure);
    if (schedule.record) record_work(report);

    clock.lap();
    report.serialised = scheduler.serial();
    std::vector<NodeId> leaves;
    tree.leaves(leaves);
    report.leaves = leaves.size();
    merge_lanes(mesh, run, lanes, schedule.checked, schedule.threads, report);
    labels.restore();
    report.master.managing += clock.lap();
}

}  // namespace

void refine_parallel(mesh::Mesh& mesh, const refine::RefineSettings& settings,
                     const Schedule& schedule, ParallelReport& report) {
    report.threads = schedule.threads;
    report.granularity = schedule.granularity;
    refine::RefineSettings s = settings;
    s.granularity = schedule.granularity;
    if (schedule.kind == Schedule::Kind::sequential)
        refine_sequential(mesh, std::move(s), report);
    else
        refine_in_rounds(mesh, std::move(s), schedule, report);
}

}  // namespace gpdr::parallel
