#pragma once
// The rounds, recorded for a simulation of refinement across machines
// (docs/scaling.md).  With Schedule::record set (tests only), each round,
// once its leaves are chosen and before they run, records every leaf of the
// quadtree with the triangles it holds (by centroid) and each leaf the round
// refines with its buffer zone; the leaves' work (triangles created) comes
// from ParallelReport::rounds when the rounds end.  Off, it costs one test
// per round.
//
// simulate_ranks() reads a record as R ranks of a distributed memory machine
// would run the same rounds: each round one superstep, the leaves owned by
// ranks in ranges of their Morton order that hold equal numbers of
// triangles, each leaf of the round refined by the rank that owns it, which
// must first fetch the triangles of its buffer zone owned by other ranks.
// Per round it gives the share of the buffer zones' triangles owned by
// another rank (what crosses the network) and the balance, the largest
// rank's work over the mean.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "mesh/mesh.hpp"
#include "parallel/quadtree.hpp"

namespace gpdr::parallel {

// A quadtree cell and its position on the Z curve: the Morton code of its
// lowest corner at max_level, so that cells of any level order along one
// curve (a cell's descendants follow it, before its next sibling).
struct Cell {
    std::uint8_t level = 0;
    std::uint32_t ix = 0, iy = 0;
    std::uint64_t morton() const;
};

struct RecordedLeaf {
    Cell cell;
    std::uint64_t triangles = 0;  // live triangles whose centroid it holds
};

// A leaf the round refined.
struct RecordedRun {
    std::uint32_t leaf = 0;           // index into RecordedRound::leaves
    std::vector<std::uint32_t> zone;  // Z(leaf), the leaf included: indices, ascending
    std::uint64_t work = 0;           // triangles its run created
};

struct RecordedRound {
    std::vector<RecordedLeaf> leaves;  // every leaf as the round starts, in Morton order
    std::vector<RecordedRun> runs;     // the round's leaves, in the round's order
    // The ids claimed as the round starts (Mesh::triangle_end, vertex_end):
    // the lanes' rule leaves holes (mesh/pool.hpp), which these show.
    std::uint32_t triangle_end = 0, vertex_end = 0;
};

using ScheduleRecord = std::vector<RecordedRound>;

// The round about to run: `round` the leaves Scheduler::plan_round chose,
// zone(i) the buffer zone it holds for round[i] (node ids).  One pass over
// the mesh; call it while no lane runs.
RecordedRound record_round(const mesh::Mesh& mesh, const Quadtree& tree,
                           const std::vector<NodeId>& round,
                           const std::function<const std::vector<NodeId>&(std::size_t)>& zone);

// ---- the simulation ---------------------------------------------------------

// Which of `ranks` ranks owns each leaf of the round: ranges of the Morton
// order, each holding about 1/ranks of the triangles (a leaf goes to the
// rank in whose share the middle of its triangles falls).
std::vector<std::uint32_t> morton_owners(const RecordedRound& round, unsigned ranks);

struct RankRound {
    std::uint64_t work = 0;              // the round's: every run's
    std::uint64_t largest = 0;           // the work of the rank with the most
    double balance = 1;                  // largest / (work / ranks); 1 for a round without work
    std::uint64_t zone_triangles = 0;    // in the runs' buffer zones, their leaves left out
    std::uint64_t remote_triangles = 0;  // of them, in leaves another rank owns than the run's
    double share = 0;                    // remote / zone triangles; 0 without zone triangles
    // Triangles in leaves whose rank is not the one the round before gave
    // their part of the Morton order (the ranges follow the triangles).
    std::uint64_t moved_triangles = 0;
};
std::vector<RankRound> simulate_ranks(const ScheduleRecord& record, unsigned ranks);

// A distribution over rounds: the median, the mean weighted by the rounds'
// work, and the largest.
struct RoundStatistic {
    double median = 0, weighted = 0, worst = 0;
};
struct RankSummary {
    RoundStatistic share, balance;
    std::uint64_t work = 0;
    std::uint64_t remote = 0;  // triangles fetched from other ranks, over all rounds
    std::uint64_t moved = 0;   // triangles that changed ranks between rounds
    // work / the sum over rounds of the largest rank's work: the speed-up
    // the supersteps allow the ranks, communication aside.
    double speedup = 1;
};
RankSummary summarise(const std::vector<RankRound>& rounds);

}  // namespace gpdr::parallel
