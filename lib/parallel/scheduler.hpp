#pragma once
// The rounds' scheduling decisions, in one place: which leaves a round
// refines, and what happens when they return (docs/architecture.md,
// "Parallel refinement").
//
// Buffer zones.  BUF(L) = { L' != L : dist(L, L') < (ℓe(L) + ℓe(L'))/2 },
// Z(L) = {L} ∪ BUF(L) (quadtree.hpp for ℓe; ℓe = ℓ while relation (9)
// holds), U(L) the open ℓe(L)/2-neighbourhood of L.  A leaf is handed out
// only when it lies in no zone held, i.e. when M ∉ Z(L) for every leaf M
// refined in the same round (BUF is symmetric).  The zones themselves may
// share leaves, the leaves between L and M; the paper asks them to be
// disjoint, which takes about twice as many rounds (two leaves of a uniform
// grid run side by side when three apart, not two) for nothing the proof
// below needs.
//
// Why that is enough (the invariants the workers rely on):
//   (a) Reach.  For p in L, every triangle t in p's cavity has p inside its
//       circumdisk, so the disk meets L and r(t) < ℓe(L)/4: all of the closed
//       disk lies within 2r < ℓe(L)/2 of p.  So the cavity lies in U(L), and
//       so do the new triangles (they fill the cavity).  A triangle created
//       larger than (9) allows (an "exception") still lies in U(L) as a
//       point set, and a later cavity of the same worker can only reach it
//       from inside U(L).  Everything else a run reads of the mesh (the
//       walk to p, the poor triangle, a subsegment's neighbours) meets U(L).
//   (b) Disjointness.  A point x in U(L) ∩ U(M) would give dist(L, M) <=
//       dist(L, x) + dist(x, M) < (ℓe(L) + ℓe(M))/2, so M ∈ Z(L).  So two
//       workers' cavities and new triangles never share a triangle, and a
//       triangle one of them reads (it meets U(L)) is never in the other's
//       cavity.
//   (c) Neighbour links.  A triangle next to L's cavity gets only the link
//       across a cavity edge rewritten, and that edge lies in U(L).  Another
//       worker reads the links of such a triangle only for its own cavity
//       edges (in U(M)) or for edges at its own vertices (in U(M)): other
//       fields.  Nothing else of it is written.
//   (d) Counters and buckets.  A triangle of circumradius r counted in cell
//       C at level k (ℓ_k > 4r) whose disk contains p ∈ L lies within 2r of
//       p; if C is at or below a leaf Y then ℓ(Y) >= ℓ_k > 4r, so
//       dist(L, Y) < ℓ(Y)/2 and Y ∈ Z(L).  A worker so writes counts only in
//       its zone and in internal nodes, all by atomic adds: a leaf that two
//       zones share is counted by both (and the shadow nodes below it are
//       made by whichever comes first, Quadtree::child), but its count is
//       read by no run of the round, and L's own count by L's run alone (L
//       lies in no other zone).  A leaf's queues are written by the run of
//       the one zone that holds it (Node::owner); work for any other leaf,
//       a shared one included, goes through the master.
//   (e) Stale queue entries are recognised by the slot's generation alone,
//       read atomically, before anything else of a slot that another worker
//       may be reusing is read (mesh/triangle.hpp).
// A triangle larger than the root allows (never, while (9) holds for the
// root) would void (a); every round then refines one leaf.

#include <cstdint>
#include <string>
#include <vector>

#include "parallel/quadtree.hpp"
#include "parallel/refine_parallel.hpp"
#include "parallel/worker.hpp"

namespace gpdr::parallel {

class Scheduler {
public:
    Scheduler(Quadtree& tree, ParallelReport& report, bool checked)
        : tree_(tree), report_(report), checked_(checked) {}

    // Marks a leaf that may have work (calling thread only, leaf not held):
    // the next round considers it.
    void offer(NodeId leaf);
    // One ROUND of leaves refined side by side (rounds.hpp).  Every leaf
    // with work is looked at in a fixed order, its key (below), then level,
    // then the cell's Morton code (never node ids: which thread made a node
    // decides its id), and taken when its zone shares no leaf with the
    // zones taken before it in this round.  The leaves, in that order, are
    // held under entries 0, 1, ... (`round` receives them; none when no
    // leaf has work): Node::owner of the zone's leaves is entry + 1 while
    // the round runs, the tag the lane refines under.  The caller completes
    // them in the same order once all have run.  So the rounds, and what
    // each leaf finds, depend on the mesh alone, never on timing.
    void plan_round(std::vector<NodeId>& round);
    // The leaves of the zone of entry's leaf two or more levels above it,
    // handed over once: the lane splits those that are idle with a count
    // of 0 when its run ends (Worker::run).
    //
    // Why.  A leaf without work is never refined, so it never splits: a
    // large one (empty space between the domain and the root's sides, or a
    // finished region) stays large, and then it lies in the zone of every
    // small leaf near it, so that no two of those can be refined in one
    // round.  Split while they lie in a zone, such leaves shrink towards
    // the size of the leaves being refined beside them
    // (docs/performance.md, "Parallel refinement").
    std::vector<NodeId> take_balance_candidates(int entry) {
        return std::move(active_[entry].balance);
    }
    // The lane refining entry's leaf returned it (split or not, and
    // `balanced`: the balance candidates it split too): frees its zone,
    // applies the splits, takes the work it routed out of its zone.
    void complete(int entry, bool split, const std::vector<NodeId>& balanced,
                  std::vector<Routed>& outbox, bool outgrew_root);
    // Work for a leaf outside the sender's zone; `near`, a node near its
    // point (the sender's leaf), is where the search for its leaf starts.
    void deliver(const Routed& r, NodeId near);
    // The buffer zone held for entry's leaf while the round runs (Schedule::record).
    const std::vector<NodeId>& zone(int entry) const { return active_[entry].zone; }
    bool serial() const { return serial_; }
    void set_serial() { serial_ = true; }

private:
    using Info = MasterInfo;
    struct Active {
        NodeId leaf = no_node;
        std::vector<NodeId> zone;
        std::vector<NodeId> balance;  // until take_balance_candidates
    };
    // Holds `chosen` under `entry`: its zone (zone_scratch_).
    void hold(int entry, NodeId chosen);
    void mark_owners(std::size_t entries);
    // Publishes a split its lane made: children first, then the parent.
    void publish_split(NodeId leaf);
    Info& info(NodeId id) { return tree_.node(id).state->master; }
    // Per-node flags, kept here by node id rather than in the leaf's state:
    // the zone searches read the held flag of every leaf they meet, and
    // holding or freeing a zone looks at every zone leaf's inbox, while the
    // states lie wherever their workers allocated them (a cache miss each).
    enum : std::uint8_t {
        taken_flag = 1,  // refined in the round
        inbox_flag = 2,  // MasterInfo::inbox is not empty
    };
    bool flag(NodeId x, std::uint8_t f) const { return x < flags_.size() && (flags_[x] & f) != 0; }
    void set_flag(NodeId x, std::uint8_t f, bool on) {
        if (x >= flags_.size()) flags_.resize(tree_.node_end());
        flags_[x] = static_cast<std::uint8_t>(on ? flags_[x] | f : flags_[x] & ~f);
    }
    // In how many zones of the round a leaf lies (a large leaf beside many
    // small ones may lie in dozens).
    bool held(NodeId x) const { return x < holds_.size() && holds_[x] != 0; }
    void hold_leaf(NodeId x) {
        if (x >= holds_.size()) holds_.resize(tree_.node_end());
        ++holds_[x];
    }
    void release_leaf(NodeId x) {
        if (--holds_[x] == 0) tree_.node(x).owner.store(0, std::memory_order_relaxed);
    }
    void to_inbox(NodeId x, const Routed& r) {
        info(x).inbox.push_back(r);
        set_flag(x, inbox_flag, true);
    }
    bool has_work(NodeId leaf) const;
    // Subsegments to split first, anywhere, then larger triangles first
    // across the whole tree (Miller's order, as far as leaves allow).
    long key(NodeId leaf) const;
    void flush_inbox(NodeId leaf);

    Quadtree& tree_;
    ParallelReport& report_;
    bool checked_;
    bool serial_ = false;
    std::vector<Active> active_;  // by entry
    // The leaves offered since the last round, each once (MasterInfo::queued).
    std::vector<NodeId> waiting_;
    std::vector<NodeId> zone_scratch_;
    std::vector<std::uint8_t> flags_;   // by node id (flag())
    std::vector<std::uint32_t> holds_;  // by node id (held())
};

// Checked mode: the quadtree invariants on a quiescent mesh (no worker
// busy): exact counters, relation (9) with effective sides for
// every leaf, leaves tiling the root.  Problems are appended to `problems`.
void verify_quadtree(const mesh::Mesh& mesh, Quadtree& tree, std::vector<std::string>& problems);

}  // namespace gpdr::parallel
