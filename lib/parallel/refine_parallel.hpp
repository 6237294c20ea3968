#pragma once
// Parallel Delaunay refinement (GPDR paper §3): the mesh is overlaid by a
// quadtree (quadtree.hpp); one master thread keeps the queue of leaves with
// work and hands a leaf to a worker only when its buffer zone shares no leaf
// with the buffer zone of any leaf being refined or handed out (a busy
// worker is given its next leaves ahead, so it seldom waits for the master
// between leaves); each worker runs the
// paper's Fig. 4 on its leaf (refine::LeafRefiner::refine_leaf: σ levels
// i_min .. i_min + g), updates the buckets and counters of its zone, and
// splits the leaf while relation (9) allows.
//
// Guarantees: those of refine::refine_mesh (same quality criteria, limits,
// placement strategies, small-angle protection; a valid constrained
// Delaunay mesh).  With the deterministic schedule (the default,
// rounds.hpp) the mesh, its vertex ids and its triangle ids are the same
// for any number of threads and from run to run; otherwise they depend on
// the thread schedule.  A user triunsuitable() or placement strategy is
// called from several threads at once and must be thread-safe.
//
// threads == 1 runs the quadtree schedule on the calling thread (the same
// rounds as -jN, one leaf at a time; without the deterministic schedule,
// one leaf at a time with no master thread), unless
// ParallelOptions::one_leaf_for_one_thread asks for the sequential
// refiner's single leaf that never splits (refine::refine_mesh).

#include <algorithm>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "mesh/mesh.hpp"
#include "refine/refine.hpp"

namespace gpdr::parallel {

// Where one thread's time went (the paper's Fig. 5, right).
struct ThreadTimes {
    double refining = 0;  // refining leaves (Fig. 4 lines 1-12; includes the counters' upkeep)
    double managing = 0;  // scheduling, routing work between leaves, splitting leaves
    double waiting = 0;   // idle: waiting for work or for a worker
};

struct ParallelReport {
    refine::RefineReport refine;  // merged over all workers, as refine_mesh reports it
    unsigned threads = 0;         // worker threads used (1: on the calling thread)
    unsigned granularity = 0;     // the g used
    ThreadTimes master;
    std::vector<ThreadTimes> workers;

    std::uint64_t assignments = 0;        // leaves handed to workers
    std::uint64_t splits = 0;             // leaf splits
    std::uint64_t balance_splits = 0;     // of them, idle leaves split beside the leaf refined
                                          // (Scheduler::take_balance_candidates)
    std::uint64_t leaves = 0;             // leaves at the end
    int depth = 0;                        // deepest leaf level
    unsigned most_concurrent = 0;         // most leaves held at once (refined or handed out next)
    std::uint64_t handed_off_local = 0;   // work routed by a worker into its own buffer zone
    std::uint64_t handed_off_master = 0;  // work routed through the master
    // Triangles created larger than relation (9) allows for some leaf (the
    // scheduler widened the buffer zones for them; see quadtree.hpp).
    std::uint64_t relation9_exceptions = 0;
    bool serialised = false;  // a triangle outgrew the root: the rest ran one leaf at a time
    // The deterministic schedule (rounds.hpp): for each round, the work of
    // each leaf refined in it (the triangles its run created), in the
    // round's order.  Empty for the other schedules.
    std::vector<std::vector<std::uint64_t>> rounds;
    // Checked mode: the invariant checks that failed (empty when all held).
    std::vector<std::string> problems;
    std::uint64_t checks = 0;  // quadtree verifications run (checked mode)
};

// The threads a -jN asks for: N, or for 0 one per hardware thread (at
// least one).  Refinement and the output stage both use it.
inline unsigned thread_count(unsigned requested) {
    return requested != 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
}

struct ParallelOptions {
    unsigned threads = 0;      // 0: thread_count(0)
    unsigned granularity = 0;  // 0: default_granularity
    // Verify the quadtree (relation (9) for every leaf, exact counters,
    // leaves tiling the root) after every leaf refinement (the master waits
    // until no worker is busy first), and buffer-zone exclusivity at every
    // assignment.  Failures go to ParallelReport::problems.  Slow: tests.
    bool checked = false;
    bool one_leaf_for_one_thread = false;
    // The deterministic schedule (rounds.hpp): the same mesh, ids and all,
    // for any number of threads.  Otherwise the master hands leaves out as
    // workers come free, and the mesh depends on their timing.
    bool deterministic = true;
};

// Granularity when none is given, the same for any number of threads (the
// deterministic schedule's rounds, and so the mesh, depend on it), by
// measurement (docs/performance.md, "Parallel refinement").
inline constexpr unsigned default_granularity = 5;

// How many σ levels below the split threshold (2 + g: Worker::should_split)
// a leaf refines triangles poor by their angle before it splits, in the
// leaf's order (shortest edges first; docs/refinement-order.md).  The
// windows of σ levels make meshes larger than one thread's, up to several
// times at 33-34 degrees and by up to 14% at 20-25; with four more levels
// (and equal edge bins first in, first out across the levels) -j2 gives
// -j1's counts on the models of bench-quality.sh and stays within 1.1% of
// them up to 30 degrees on meshes of 100,000 triangles, 7% at 32-34, for no
// measurable time (the graded pipe and a uniformly refined square, -j2).
// (Triangles in the size bin stay in the leaf's own levels: taking them
// further made area-bound runs 1.2-1.6 times slower for the same counts.)
inline constexpr int order_levels_beyond_split = 4;

// How many entries a leaf whose count keeps it from splitting takes, in
// Triangle's order over all its levels, between two looks at its count
// (Worker::refine_while_blocked).  A look costs the counting of what the
// batch made; 4,096 entries are a few milliseconds of refinement, so a
// leaf whose count falls to 0 goes on to its window (and its split) soon
// after.
inline constexpr std::uint64_t blocked_batch = 4096;

// The largest angle bound (-q) the quadtree refines; above it every thread
// count runs the sequential refiner, in Triangle's order.  Near 34 degrees
// the order decides whether refinement ends at all, and the leaves' windows
// cannot keep Triangle's order across leaves: at 33.5 degrees -j2 made up
// to 1.21 times -j1's triangles on the generated models under -a, and at
// 34 up to 3.5 times, or 75 times (flow under -a, 100,000 triangles by the
// bound), where the safety stop ends it.  Up to 33 degrees: 0.96-1.14
// times, refined about twice as fast as one thread on meshes of millions
// of triangles.  docs/refinement-order.md.
inline constexpr double max_quadtree_angle = 33.0;

// Refines `mesh` (the input refine::refine_mesh takes) in parallel.  Throws
// what refine_mesh throws; a worker's exception is rethrown on the calling
// thread after all threads have stopped.
void refine_parallel(mesh::Mesh& mesh, const refine::RefineSettings& settings,
                     const ParallelOptions& options, ParallelReport& report);

// The job pipeline's entry: threads 0 = hardware threads, granularity 0 =
// default_granularity.
inline void refine_parallel(mesh::Mesh& mesh, const refine::RefineSettings& settings,
                            unsigned threads, unsigned granularity, ParallelReport& report) {
    ParallelOptions o;
    o.threads = threads;
    o.granularity = granularity;
    refine_parallel(mesh, settings, o, report);
}

}  // namespace gpdr::parallel
