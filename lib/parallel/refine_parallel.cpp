// Parallel refinement: set-up (root square, counters, first leaf), the
// master loop with worker threads, the same loop on the calling thread for
// one thread, and the merged report.  See refine_parallel.hpp.

#include "parallel/refine_parallel.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "geometry/constructions.hpp"
#include "mesh/traverse.hpp"
#include "parallel/rounds.hpp"
#include "parallel/scheduler.hpp"
#include "parallel/segment_labels.hpp"
#include "parallel/worker.hpp"

namespace gpdr::parallel {

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

// Leaves a worker may hold at once outside checked mode (run_threads).
constexpr unsigned queue_depth = 3;

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

// The master loop and the worker threads.  Each worker has a short queue of
// assignments (Scheduler entries queue_depth w .. queue_depth w + depth - 1):
// the leaf it refines and, outside checked mode, the next ones, handed out
// while it still refines, so that it goes on at once instead of waiting for
// the master to take its leaf back.  A worker wakes the master only when
// its queue runs low (one leaf left besides the one it starts) or another
// worker has nothing to do: on two cores each wake-up takes a core from a
// worker, and a queue of three lets the master complete two leaves and hand
// out two per wake-up instead of one.  A worker that finds nothing to do
// takes over another's last leaf that has not started yet.
void run_threads(std::vector<std::unique_ptr<Worker>>& workers, Scheduler& scheduler,
                 const ParallelOptions& options, ParallelReport& report,
                 std::exception_ptr& failure, const std::function<void()>& check) {
    struct Task {
        int entry = -1;
        NodeId leaf = no_node;
        std::vector<NodeId> balance;  // Scheduler::take_balance_candidates
    };
    struct Finished {
        int entry;
        bool split, stopped, outgrew_root;
        std::vector<NodeId> balanced;
        std::vector<Routed> outbox;
    };
    // Checked mode checks between leaves, with every worker idle: one leaf each.
    const unsigned depth = options.checked ? 1 : queue_depth;
    struct Slot {
        std::condition_variable cv;
        // tasks[0] is the worker's (it may be refining it); the others wait.
        Task tasks[queue_depth];
        unsigned count = 0;
        std::vector<Finished> finished;
        void push(Task t) { tasks[count++] = std::move(t); }
        void pop_front() {
            for (unsigned i = 1; i < count; ++i) tasks[i - 1] = std::move(tasks[i]);
            tasks[--count] = {};
        }
        bool holds(int entry) const {
            return std::any_of(tasks, tasks + count,
                               [&](const Task& t) { return t.entry == entry; }) ||
                   std::any_of(finished.begin(), finished.end(),
                               [&](const Finished& f) { return f.entry == entry; });
        }
    };
    const auto threads = static_cast<unsigned>(workers.size());
    std::mutex mutex;
    std::condition_variable master_cv;
    std::vector<Slot> slots(threads);
    bool quit = false;
    std::vector<std::thread> pool;
    for (unsigned w = 0; w < threads; ++w) {
        pool.emplace_back([&, w] {
            Worker& worker = *workers[w];
            Slot& slot = slots[w];
            std::unique_lock lock(mutex);
            bool tell_master = false;  // of results left in slot.finished
            for (;;) {
                const auto t0 = Clock::now();
                if (tell_master && slot.count == 0) {
                    // (Told with the mutex free, as below.)
                    lock.unlock();
                    master_cv.notify_one();
                    tell_master = false;
                    lock.lock();
                }
                slot.cv.wait(lock, [&] { return quit || slot.count != 0; });
                worker.times.waiting += seconds(t0, Clock::now());
                if (quit) return;
                const Task task = std::move(slot.tasks[0]);
                lock.unlock();
                // The master is woken only now that the mutex is free: woken
                // while the worker held it, it would find it taken and sleep
                // again at once (two more context switches on a machine whose
                // cores the workers keep busy).
                if (tell_master) master_cv.notify_one();
                tell_master = false;
                bool split = false;
                try {
                    split = worker.run(task.leaf, task.entry + 1, task.balance);
                } catch (...) {
                    lock.lock();
                    if (!failure) failure = std::current_exception();
                    lock.unlock();
                    worker.stopped = true;
                }
                lock.lock();
                slot.finished.push_back({task.entry, split, worker.stopped, worker.outgrew_root,
                                         std::move(worker.balanced), std::move(worker.outbox)});
                worker.balanced.clear();
                worker.outbox.clear();
                slot.pop_front();
                // Otherwise the result waits for the next wake-up (the
                // master takes every worker's results each time).
                tell_master = slot.count <= 1 || worker.stopped ||
                              std::any_of(slots.begin(), slots.end(),
                                          [](const Slot& s) { return s.count == 0; });
            }
        });
    }
    {
        std::unique_lock lock(mutex);
        unsigned busy = 0;  // assignments not completed
        bool stop = false, need_check = false;
        std::vector<Finished> done;
        struct Planned {
            unsigned w;
            Task task;
        };
        std::vector<Planned> planned;
        std::vector<Slot*> wake;  // workers given a leaf to start
        // What each worker held when the results were taken (entries in use).
        std::vector<std::vector<int>> held(threads);
        for (;;) {
            const auto t0 = Clock::now();
            // Take the results and what each worker holds, then let go of
            // the lock while scheduling (the scheduler is the master's
            // alone), so that finishing workers never wait for it.
            for (unsigned w = 0; w < threads; ++w) {
                Slot& slot = slots[w];
                for (Finished& f : slot.finished) done.push_back(std::move(f));
                slot.finished.clear();
                held[w].clear();
                for (unsigned i = 0; i < slot.count; ++i) held[w].push_back(slot.tasks[i].entry);
            }
            const bool failed = failure != nullptr;
            lock.unlock();
            for (Finished& f : done) {
                --busy;
                scheduler.complete(f.entry, f.split, f.balanced, f.outbox, f.outgrew_root);
                if (f.stopped) stop = true;
                need_check = options.checked;
            }
            done.clear();
            if (need_check && busy == 0) {  // (every worker waits for a leaf)
                check();
                need_check = false;
            }
            planned.clear();
            // Idle workers first, then one more leaf for each worker in
            // turn, until the queues are full or no leaf can be handed out.
            bool none_left = stop || failed || need_check;
            for (unsigned round = 0; round < depth && !none_left; ++round) {
                for (unsigned w = 0; w < threads && !none_left; ++w) {
                    if (held[w].size() != round) continue;
                    int entry = static_cast<int>(queue_depth * w);
                    while (std::find(held[w].begin(), held[w].end(), entry) != held[w].end())
                        ++entry;
                    const NodeId leaf = scheduler.assign(entry, busy);
                    if (leaf == no_node) {
                        none_left = true;
                        break;
                    }
                    ++busy;
                    held[w].push_back(entry);
                    planned.push_back({w, {entry, leaf, scheduler.take_balance_candidates(entry)}});
                }
            }
            lock.lock();
            for (Planned& p : planned) {
                // A worker that finished meanwhile starts it at once.
                Slot& slot = slots[p.w];
                if (slot.count == 0) wake.push_back(&slot);
                slot.push(std::move(p.task));
            }
            // A worker still idle takes over another's last leaf that has
            // not started (under the lock: its worker may start it any
            // moment), under an entry it does not use (its unprocessed
            // results may).
            for (unsigned w = 0; w < threads && !stop && !failure && !need_check; ++w) {
                Slot& slot = slots[w];
                if (slot.count != 0) continue;
                const auto donor = std::max_element(
                    slots.begin(), slots.end(),
                    [](const Slot& a, const Slot& b) { return a.count < b.count; });
                if (donor->count < 2) break;
                int entry = static_cast<int>(queue_depth * w);
                while (entry < static_cast<int>(queue_depth * (w + 1)) && slot.holds(entry))
                    ++entry;
                if (entry == static_cast<int>(queue_depth * (w + 1)))
                    continue;  // all await completion
                Task moved = std::move(donor->tasks[--donor->count]);
                donor->tasks[donor->count] = {};
                scheduler.move_assignment(moved.entry, entry);
                slot.push({entry, moved.leaf, std::move(moved.balance)});
                wake.push_back(&slot);
            }
            if (!wake.empty()) {
                // With the mutex free (see the workers' loop).
                lock.unlock();
                for (Slot* slot : wake) slot->cv.notify_one();
                wake.clear();
                lock.lock();
            }
            const auto t1 = Clock::now();
            report.master.managing += seconds(t0, t1);
            if (busy == 0) break;
            master_cv.wait(lock, [&] {
                return std::any_of(slots.begin(), slots.end(),
                                   [](const Slot& s) { return !s.finished.empty(); });
            });
            report.master.waiting += seconds(t1, Clock::now());
        }
        quit = true;
        for (auto& s : slots) s.cv.notify_one();
    }
    for (auto& t : pool) t.join();
}

}  // namespace

void refine_parallel(mesh::Mesh& mesh, const refine::RefineSettings& settings_in,
                     const ParallelOptions& options, ParallelReport& report) {
    const unsigned threads = thread_count(options.threads);
    const unsigned granularity =
        options.granularity != 0 ? options.granularity : default_granularity;
    report.threads = threads;
    report.granularity = granularity;
    refine::RefineSettings settings = settings_in;
    settings.granularity = granularity;

    if (threads == 1 && options.one_leaf_for_one_thread) {
        const auto t0 = Clock::now();
        // Labelled here too: without labels the small-angle rule walks a
        // subsegment's chain (up to 256 steps each way) every time it is
        // asked, which long chains, as -D's splits make on a -r mesh's
        // boundary, turn into most of the run.
        SegmentLabels labels(mesh, settings.segment_ends);
        settings.segment_ends = labels.ends();
        refine::refine_mesh(mesh, settings, report.refine);
        labels.restore();
        report.workers.assign(1, ThreadTimes{seconds(t0, Clock::now()), 0, 0});
        report.leaves = 1;
        return;
    }

    const auto start = Clock::now();
    SegmentLabels labels(mesh, settings.segment_ends);
    settings.segment_ends = labels.ends();
    refine::RefineRun run(mesh, settings);
    const Square root = root_square(mesh);
    Quadtree tree(root.x0, root.y0, root.side);
    // The workers: one per thread, or the deterministic schedule's lanes,
    // whose pools claim ids by their own rule (made in order: mesh::Lane).
    std::vector<std::unique_ptr<Worker>> workers;
    const mesh::Lane first_lane = mesh::Lane::first(mesh, lane_count);
    for (unsigned w = 0; w < (options.deterministic ? lane_count : threads); ++w) {
        std::optional<mesh::Lane> lane;
        if (options.deterministic) {
            lane = first_lane;
            lane->index = w;
        }
        workers.push_back(std::make_unique<Worker>(mesh, run, tree, options, lane));
    }

    // The first leaf: the root, every triangle counted and classified.
    Node& root_node = tree.node(Quadtree::root());
    root_node.state = workers[0]->new_leaf_state(Quadtree::root());
    workers[0]->count_all();
    workers[0]->refiner().classify_all(root_node.state->work);
    {
        // Everything lies in the root; anything handed off (a centre on the
        // root's far edge) stays with it.
        refine::Leaf& w = root_node.state->work;
        for (auto q : w.handed_off_triangles) {
            const mesh::Triangle& t = mesh.triangle(q.id);
            const refine::TriangleMeasures m = refine::QualityTest::measure(
                mesh.point(t.v[0]), mesh.point(t.v[1]), mesh.point(t.v[2]));
            q.where = w.where(m.circle.centre);
            w.push_poor(q, w.slot(m.circle.radius_squared, m.shortest.length_squared,
                                  refine::poor_kind(run.quality(), m)));
        }
        w.handed_off_triangles.clear();
    }

    Scheduler scheduler(tree, report, options.checked, options.deterministic);
    if (workers[0]->outgrew_root) scheduler.set_serial();
    scheduler.offer(Quadtree::root());
    report.master.managing += seconds(start, Clock::now());

    std::exception_ptr failure;
    const std::function<void()> check = [&] {
        verify_quadtree(mesh, tree, report.problems);
        ++report.checks;
        for (const auto& w : workers)
            if (w->zone_escapes != 0)
                report.problems.push_back(
                    "a worker counted a triangle in a leaf outside its buffer zone");
    };

    if (options.deterministic) {
        run_rounds(workers, scheduler, threads, options, report, failure, check);
    } else if (threads == 1) {
        // The same schedule on the calling thread: no master, no worker threads.
        Worker& worker = *workers[0];
        for (;;) {
            const auto t0 = Clock::now();
            const NodeId leaf = scheduler.assign(0, 0);
            if (leaf == no_node) break;
            const auto t1 = Clock::now();
            report.master.managing += seconds(t0, t1);
            const bool split = worker.run(leaf, 1, scheduler.take_balance_candidates(0));
            const auto t2 = Clock::now();
            scheduler.complete(0, split, worker.balanced, worker.outbox, worker.outgrew_root);
            if (options.checked) check();
            report.master.managing += seconds(t2, Clock::now());
            if (worker.stopped) break;
        }
    } else {
        run_threads(workers, scheduler, options, report, failure, check);
    }
    if (failure) std::rethrow_exception(failure);

    // The merged report, and the final count of what is left (refine_mesh's).
    const auto t_end = Clock::now();
    std::vector<refine::LeafRefiner::GivenUp> given_up;
    for (auto& w : workers) {
        merge(report.refine, w->report);
        const auto& g = w->refiner().given_up();
        given_up.insert(given_up.end(), g.begin(), g.end());
        if (!options.deterministic) report.workers.push_back(w->times);  // (else by thread)
        report.handed_off_local += w->handed_off_local;
        report.relation9_exceptions += w->relation9_exceptions;
        if (w->zone_escapes != 0 && options.checked)
            report.problems.push_back(
                "a worker counted a triangle in a leaf outside its buffer zone");
    }
    report.serialised = scheduler.serial();
    std::vector<NodeId> leaves;
    tree.leaves(leaves);
    report.leaves = leaves.size();
    workers.clear();  // the pools give their spare slots back
    refine::count_left(mesh, run, std::move(given_up), report.refine, threads);
    labels.restore();
    report.master.managing += seconds(t_end, Clock::now());
}

}  // namespace gpdr::parallel
