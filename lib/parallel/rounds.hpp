#pragma once
// Parallel refinement in bulk-synchronous ROUNDS (schedule.hpp), so that
// the mesh and its numbering are the same for any number of threads and
// from run to run.
//
// Each round:
//   1. The calling thread chooses the round's leaves by a rule that reads
//      the mesh and the quadtree alone (Scheduler::plan_round): every leaf
//      with work in a fixed order, taken when its buffer zone is free of the
//      zones taken before it.
//   2. Leaf i of the round is refined on LANE i mod `lanes`, a worker with
//      its own pool, queues and scratch (Worker), and a lane's leaves are
//      refined in the round's order; threads take whole lanes, in any
//      order, and any thread may run any lane.
//   3. After the last lane, the calling thread completes the leaves in the
//      round's order: publishes their splits, frees their zones, delivers
//      the work they routed to other leaves.
// Why that gives the same mesh for any thread count: a leaf's run reads and
// writes only its buffer zone (scheduler.hpp), which no other leaf of the
// round shares, so it finds the same mesh whatever ran before it in the
// round; its lane finds itself in the same state (the same leaves ran on it
// before, in the same order); and a lane's pool hands out ids by a rule of
// its own (mesh/pool.hpp: Lane), so even the ids, and with them the output's
// numbering, do not depend on the threads.  Everything the calling thread
// does between rounds happens in a fixed order.
//
// The number of lanes is fixed (lane_count), not the number of threads:
// more threads than lanes would idle.

#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <vector>

#include "parallel/refine_parallel.hpp"

namespace gpdr::parallel {

class Scheduler;
class Worker;

inline constexpr unsigned lane_count = 64;

// Runs rounds until no leaf has work, a lane stops (a limit) or fails (its
// exception goes to `failure`), on `threads` threads: the calling thread and
// threads - 1 more.  `check` runs after each round when `checked`;
// `record`, when set, with the round's leaves once they are chosen and
// before they run (Schedule::record); its time is left out of the calling
// thread's (the other threads wait meanwhile).
// Records each round's leaves' work in report.rounds.
void run_rounds(std::vector<std::unique_ptr<Worker>>& lanes, Scheduler& scheduler, unsigned threads,
                bool checked, ParallelReport& report, std::exception_ptr& failure,
                const std::function<void()>& check,
                const std::function<void(const std::vector<NodeId>&)>& record = {});

// What the recorded rounds say of the schedule's parallelism, counting a
// leaf's work as the triangles its run created (deterministic, unlike time).
struct ScheduleShape {
    std::uint64_t rounds = 0;
    std::uint64_t runs = 0;                          // leaves refined, over all rounds
    std::uint64_t fewest = 0, median = 0, most = 0;  // leaves per round
    std::uint64_t work = 0;                          // every run's work
    std::uint64_t span = 0;  // the sum over rounds of the round's largest run
    // Work / span: the most any number of workers could speed the rounds up.
    double parallelism() const { return span == 0 ? 0.0 : double(work) / double(span); }
};
ScheduleShape schedule_shape(const std::vector<std::vector<std::uint64_t>>& rounds);

// The speed-up the rounds allow `workers` workers that share each round's
// leaves perfectly: work / sum over rounds of max(the largest run, the
// round's work / workers).  An upper bound (a leaf cannot be shared; lanes
// and barriers cost more), not a measurement.
double predicted_speedup(const std::vector<std::vector<std::uint64_t>>& rounds, unsigned workers);

}  // namespace gpdr::parallel
