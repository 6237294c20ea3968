#pragma once
// Refinement on the schedule the options chose (schedule.hpp): the
// sequential refiner (refine::refine_mesh), or parallel Delaunay refinement
// in rounds (GPDR paper §3; rounds.hpp).  For rounds the mesh is overlaid by
// a quadtree (quadtree.hpp); each round the calling thread picks leaves
// none of which lies in another's buffer zone (scheduler.hpp), and the
// threads refine them side by side, each running the paper's Fig. 4 on its leaf
// (refine::LeafRefiner, through Worker), updating the buckets and counters
// of its zone and splitting the leaf while relation (9) allows.
//
// Guarantees: those of refine::refine_mesh (same quality criteria, limits,
// placement strategies, small-angle protection; a valid constrained
// Delaunay mesh).  The rounds give the same mesh, vertex ids and triangle
// ids for any number of threads and from run to run.  A user
// triunsuitable() or placement strategy is called from several threads at
// once and must be thread-safe.

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "parallel/round_record.hpp"
#include "parallel/schedule.hpp"
#include "refine/refine.hpp"

namespace gpdr::parallel {

// Where one thread's time went (the paper's Fig. 5, right).
struct ThreadTimes {
    double refining = 0;  // refining leaves (Fig. 4 lines 1-12; includes the counters' upkeep)
    double managing = 0;  // scheduling, routing work between leaves, splitting leaves
    double waiting = 0;   // idle: waiting for work or for a worker
};

struct ParallelReport {
    refine::RefineReport refine;       // merged over all lanes, as refine_mesh reports it
    unsigned threads = 0;              // threads that refined (1: the calling thread alone)
    unsigned granularity = 0;          // the g used
    ThreadTimes master;                // the calling thread between rounds
    std::vector<ThreadTimes> workers;  // by thread

    std::uint64_t assignments = 0;        // leaves refined, over all rounds
    std::uint64_t splits = 0;             // leaf splits
    std::uint64_t balance_splits = 0;     // of them, idle leaves split beside the leaf refined
                                          // (Scheduler::take_balance_candidates)
    std::uint64_t leaves = 0;             // leaves at the end
    int depth = 0;                        // deepest leaf level
    unsigned most_concurrent = 0;         // most leaves in one round
    std::uint64_t handed_off_local = 0;   // work routed by a lane into its own buffer zone
    std::uint64_t handed_off_master = 0;  // work routed through the calling thread
    // Triangles created larger than relation (9) allows for some leaf (the
    // scheduler widened the buffer zones for them; see quadtree.hpp).
    std::uint64_t relation9_exceptions = 0;
    bool serialised = false;  // a triangle outgrew the root: the rest ran one leaf at a time
    // For each round (rounds.hpp), the work of each leaf refined in it (the
    // triangles its run created), in the round's order.  Empty for the
    // sequential schedule.
    std::vector<std::vector<std::uint64_t>> rounds;
    // With Schedule::record: each round's leaves, their triangles and the
    // buffer zones of the leaves it refined, with their work (as in
    // `rounds`).  Empty otherwise.
    ScheduleRecord record;
    // Checked mode: the invariant checks that failed (empty when all held).
    std::vector<std::string> problems;
    std::uint64_t checks = 0;  // quadtree verifications run (checked mode)
};

// Refines `mesh` (the input refine::refine_mesh takes) on `schedule`.
// Throws what refine_mesh throws; a thread's exception is rethrown on the
// calling thread after all threads have stopped.
void refine_parallel(mesh::Mesh& mesh, const refine::RefineSettings& settings,
                     const Schedule& schedule, ParallelReport& report);

// Rounds on `threads` threads (0: one per hardware thread) at granularity
// `granularity` (0: the default).
inline void refine_parallel(mesh::Mesh& mesh, const refine::RefineSettings& settings,
                            unsigned threads, unsigned granularity, ParallelReport& report) {
    refine_parallel(mesh, settings,
                    Schedule::rounds(thread_count(threads),
                                     granularity != 0 ? granularity : refine::default_granularity),
                    report);
}

}  // namespace gpdr::parallel
