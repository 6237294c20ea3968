#pragma once
// One refinement thread of the parallel refiner (GPDR paper Fig. 4): its
// pool, its LeafRefiner, the upkeep of the quadtree counters for every
// triangle it creates or kills, routing of work that belongs to other
// leaves, and splitting its leaf.
//
// What a worker touches while it refines leaf L (the contract the master's
// buffer zones guarantee; see scheduler.hpp for the proof): triangles in the
// cavities of points in L and their neighbours' links, the quadtree nodes at
// and below the leaves of L's zone, and those leaves' buckets.  The only
// shared writes outside that are atomic: the Steiner count, the node and
// triangle-slot allocators, and counts of internal nodes (relation (9)
// exceptions, quadtree.hpp).

#include <algorithm>
#include <cstdint>
#include <deque>
#include <vector>

#include "mesh/pool.hpp"
#include "parallel/cell_record.hpp"
#include "parallel/deferred_list.hpp"
#include "parallel/quadtree.hpp"
#include "parallel/refine_parallel.hpp"
#include "refine/refine.hpp"

namespace gpdr::parallel {

// Ownership: a point belongs to the leaf whose half-open square holds it;
// the leaves on the root's border also own everything beyond it (as
// Quadtree::leaf_at finds them), so that every point has exactly one owner
// (a Steiner point outside the domain, never inserted, is still taken by
// some leaf, which splits the hull subsegment in its way).
using refine::OwnedBox;
OwnedBox owned_box(const Quadtree& tree, NodeId leaf);

// Work for a leaf outside the routing worker's zone, sent to the master.
struct Routed {
    bool is_triangle = true;
    refine::QueuedTriangle triangle{};
    refine::QueuedSubsegment subsegment{};
    Point at;                     // the point that decides the leaf
    double radius_squared = 0;    // triangles: for the target leaf's slot,
    double shortest_squared = 0;  // with the shortest edge²
    refine::PoorKind kind{};      // and refine::poor_kind
};

// Puts routed work into a leaf's lists (the worker for its own zone, the
// master for the rest).
inline void push(refine::Leaf& work, const Routed& r) {
    if (r.is_triangle) {
        refine::QueuedTriangle q = r.triangle;
        q.where = work.where(r.at);
        work.push_poor(q, work.slot(r.radius_squared, r.shortest_squared, r.kind));
    } else {
        work.push_subsegment(r.subsegment);
    }
}

// The scheduler's bookkeeping for a leaf (scheduler.hpp), kept by the
// calling thread between rounds; no lane touches it.
struct MasterInfo {
    bool queued = false;        // waiting for the next round (offered once)
    std::vector<Routed> inbox;  // work that arrived while it was held
};

// Splitting where the work is (Worker::refine_own_levels).  A run that has
// made its round's split budget of triangles splits its leaf as soon as the
// work left lies 2 + early_split_granularity σ levels below it, instead of
// refining all its own levels (1 + g) first: where the mesh is densest, the
// leaves go a level deeper than the granularity alone would take them, so
// that fewer runs make much more than the budget and more runs share a
// round; elsewhere a leaf's run never reaches the budget and the tree stays
// as coarse as g makes it.  Counted in triangles created, so that the
// rounds stay the same on any number of threads.  At -g5 a full run makes
// about 60,000 triangles.
//
// The budget of a round is the work of the round before (its runs'
// triangles) over budget_share, within [least_split_budget, split_budget]:
// a round waits for its largest run, so a run above its round's work / 32
// keeps the rounds below work / span 32.  Where many leaves share the
// rounds (most of the work) that is split_budget; while the tree is still
// coarse and few leaves have work, and at the end, the runs are cut to
// what the rounds' work allows.  Smaller budgets throughout cost two
// threads more than they give: 10,000 for every round took work / span to
// 38 on the graded pipe and the square, but -j2 1.16 times as long
// (smaller leaves: their work is handed to children that run later, out of
// the cache).  Early splits also grow some uniform meshes a little: this
// rule up to +0.6% on the samples (docs/performance.md).
inline constexpr std::uint64_t split_budget = 40000;
inline constexpr std::uint64_t least_split_budget = 10000;
inline constexpr std::uint64_t budget_share = 32;
inline constexpr int early_split_granularity = 3;
constexpr std::uint64_t round_split_budget(std::uint64_t work_of_round_before) {
    return std::clamp(work_of_round_before / budget_share, least_split_budget, split_budget);
}
// Entries a run takes between two looks at its budget.
inline constexpr std::uint64_t budget_slice = 256;

// Everything a leaf has beyond its quadtree node (Node::state); made by the
// worker that splits its parent.
struct LeafState {
    LeafState(const Square& square, const OwnedBox& b) : work(square.side), box(b) {
        work.set_owned_box(b);
        work.set_corner({square.x0, square.y0});
    }

    refine::Leaf work;
    OwnedBox box;
    MasterInfo master;
    // Triangles inside the leaf too small to be counted yet: each lies
    // inside the leaf's square and is at least two levels below it, so no
    // count that anyone reads before the leaf splits includes it.  The list
    // is read only by the worker refining the leaf.  It also holds the
    // entries of triangles that died since they were listed: they are
    // dropped when a split hands the list down, and in a leaf that never
    // splits they are never read at all (Worker::flush_pending).
    DeferredList deferred;
    // The same for triangles small enough, and far enough inside child q's
    // square, to be deferred in that child once the leaf splits: the split
    // gives the child this list as its own, unread.  (Most triangles a leaf
    // makes are several levels below it; on the graded pipe 95% of the
    // live ones a split read went on to a child's list.)
    DeferredList deferred_in_child[4];
};

// How a triangle is counted, kept in its mesh::Triangle::user_tag: 0 not
// counted (too small to matter, pending or deferred), counted_tag counted in
// the cells its CellRecord names.
inline constexpr std::uint8_t counted_tag = 1;

// Computes the record of a triangle with this circumcircle (pure).  It is
// not stored: a counted triangle that dies or flips is uncounted from its
// corners as they were (mesh::TaggedTriangle), whose circumcircle, computed
// by the same function from the same corners in the same order, gives the
// same record bit for bit.
CellRecord cell_record(const Quadtree& tree, const Point& centre, double radius_squared,
                       bool& outgrew_root);

class Worker final : public refine::MeshObserver {
public:
    // The worker's pool claims ids by the lane's rule (rounds.hpp).  In
    // checked mode it also records counts it makes outside its zone.
    Worker(mesh::Mesh& mesh, refine::RefineRun& run, Quadtree& tree, const mesh::Lane& lane,
           bool checked);

    // Counts every live triangle (single-threaded, before refinement starts).
    void count_all();
    // Refines leaf `leaf`, whose zone (`zone`: its leaves) the master holds
    // for this run under `tag` (Node::owner of the zone's leaves that no
    // other zone of the round holds): Fig. 4 lines 1-12, routing of
    // handed-off work, and the split (line 13).  Returns whether the leaf
    // split.  Then splits those of `balance` (leaves of the zone,
    // Scheduler::take_balance_candidates) that are idle and whose count is
    // 0, and lists them in `balanced`.
    bool run(NodeId leaf, std::int32_t tag, const std::vector<NodeId>& zone,
             const std::vector<NodeId>& balance = {});
    // The round's (round_split_budget), set before its runs.
    void set_split_budget(std::uint64_t triangles) { split_budget_ = triangles; }

    void tagged_triangles_gone(std::span<const mesh::TaggedTriangle> gone) override;
    void triangle_created(mesh::TriangleId t, std::uint32_t generation,
                          const geometry::Circle& circumcircle) override;

    LeafState* new_leaf_state(NodeId leaf);

    refine::RefineReport report;
    std::vector<Routed> outbox;    // handed to the master after each run
    std::vector<NodeId> balanced;  // (see run)
    ThreadTimes times;
    std::uint64_t handed_off_local = 0;
    std::uint64_t relation9_exceptions = 0;
    std::uint64_t zone_escapes = 0;
    // Queue storage given back to the allocator since the master last
    // looked (run_rounds returns it to the system once it adds up).
    std::uint64_t released_bytes = 0;
    bool outgrew_root = false;
    bool stopped = false;
    mesh::Pool& pool() { return pool_; }
    refine::LeafRefiner& refiner() { return refiner_; }

private:
    void count(mesh::TriangleId t, const geometry::Circle& circumcircle);
    // (Out of line: triangle_created's fast path stays free of it.)
    [[gnu::noinline]] void count_now(mesh::TriangleId t, const geometry::Circle& circumcircle);
    void uncount(const mesh::TaggedTriangle& was);
    // Counts the triangles created since the last call that are still
    // alive and were not listed as deferred (below).  Most triangles a run
    // creates die within the same run (each insertion kills about four),
    // and nobody reads a count of this worker's zone before the run ends
    // but the worker itself, so their counting is put off until the run
    // ends or the worker needs its leaf's count, and a triangle that died
    // meanwhile is never counted at all.  (The master reads only internal
    // nodes' counts while a worker runs, and may read them before any
    // increment anyway.)
    //
    // Most triangles a run creates (93% on the graded pipe) are far smaller
    // than the leaf (the leaf stops refining about g levels above its
    // finest triangles), and their cells' counts matter only once the leaf
    // has split down to one level above them.  So a triangle two or more
    // levels below the leaf being refined, inside its square, is not
    // counted but listed in the leaf soon after it is made (sort_created):
    // in the list for the child whose square holds it when it is also two
    // levels below that child (LeafState::deferred_in_child; most are),
    // else in the leaf's own (LeafState::deferred).  A split gives each
    // child its list unread, and hands the own list down: entries of
    // triangles that died are dropped, the triangles now only one level
    // below a child (or that straddle two children) are counted, the
    // others listed in a child.
    // Nothing but a sweep looks at an entry before that: a listed triangle
    // that dies costs its 8 bytes until a split reads the list, or until
    // the run that ends with the list doubled since its last sweep drops it
    // (sweep_deferred; the batch below keeps many out from the start), and
    // most of the final mesh is never counted.
    // (On the pipe the hand-downs read 3.8 million entries and pass 11.7
    // million on unread.  One list per leaf, all of it read at a split,
    // read 22 million, and 95% of its live entries went on to a child's
    // list; holding new triangles without their circles in the pending
    // list until the run ended, to list only the survivors, and sweeping
    // dead entries out of growing lists read 39 and 31 million more.)
    // Invariant: a live triangle is counted, pending (or in the batch of
    // new ones, below; both are emptied when a run ends), or listed in
    // one leaf L: in L's own list when L's square holds it with room to
    // spare (Quadtree::disk_inside) and it is at least two levels below L,
    // or in L's list for child q when the square of L's child q does and
    // it is at least two levels below that child.
    void flush_pending();
    // A new triangle waits, with its circumcircle, in a batch of the last
    // created_batch ones the run made.  When the batch is full, and before
    // the leaf's count is read or the run ends, the ones still alive are
    // sorted: listed (deferral_list) or left pending.  Each insertion kills
    // about four triangles, many of them made a few insertions before, and
    // a listed dead triangle holds its 8 bytes until a split reads it; the
    // dead ones in the batch cost a generation check, no test.  (Sorting
    // at creation, through a ring of 256 deferrable triangles that listed
    // only those alive when they left it, executed 121 instructions per
    // triangle against 18 + 60 now; the batch is 8 KiB, which stays in the
    // first-level cache, where 1024 missed it 30% more often.)
    void sort_created();
    // Where a triangle with this circumcircle may be deferred in leaf
    // `leaf` (whose geometry `at` describes): the list for the child its
    // centre lies in, the leaf's own, or none (it must be counted).
    struct DeferralTargets {
        Quadtree::RadiusBand band, child_band;  // two levels below the leaf, below a child
        Quadtree::Room room;
        Quadtree::Room child_rooms[4];
        Point middle;  // where the children's squares meet
    };
    DeferralTargets deferral_targets(NodeId leaf) const;
    DeferredList* deferral_list(const geometry::Circle& circumcircle, const DeferralTargets& at,
                                LeafState& leaf) const;
    // Whether e's triangle is the one listed (its slot's generation has not moved on).
    bool alive(DeferredTriangle e) const {
        return mesh_.triangle(e.t).load_generation() == e.generation;
    }
    // alive() and prefetch() as DeferredList::sweep asks them.
    struct Liveness {
        const Worker* worker;
        bool operator()(DeferredTriangle e) const { return worker->alive(e); }
        void ahead(DeferredTriangle e) const { worker->prefetch(e.t); }
    };
    Liveness liveness() const { return {this}; }
    // Asks for triangle t's slot ahead of reading it (deferred_list.hpp: look_ahead).
    void prefetch(mesh::TriangleId t) const { __builtin_prefetch(&mesh_.triangle(t)); }
    // The same for the points of e's corners, if e is alive (its corners are
    // read only then: the slot of a dead one may be another worker's now).
    void prefetch_corners(DeferredTriangle e) const {
        if (!alive(e)) return;
        for (const mesh::VertexId v : mesh_.triangle(e.t).v) __builtin_prefetch(&mesh_.point(v));
    }
    void hand_down_deferred(NodeId leaf);
    void apply(CellRecord record, int delta, bool check_zone);
    // Where the work item should go: a leaf of this worker's zone (pushed
    // there) or the master's outbox.
    void route_triangle(refine::QueuedTriangle q, bool steiner_point_if_centre_inside,
                        const OwnedBox& inside, NodeId splitting);
    void route_subsegment(refine::QueuedSubsegment s, NodeId splitting);
    void deliver(const Routed& r, NodeId splitting);
    bool should_split(const Node& n, LeafState& state);
    bool refine_while_blocked(const Node& n, LeafState& state);
    bool refine_own_levels(const Node& n, LeafState& state, int last_level, int last_size_level,
                           bool& split_now);
    bool may_split_early(const Node& n, LeafState& state);
    // run()'s steps.
    bool refine_window(const Node& n, LeafState& state);
    void route_handed_off(LeafState& state);
    void split_balance_candidates(const std::vector<NodeId>& balance);
    void release_idle_queues(LeafState& state);
    void sweep_deferred(LeafState& state);
    int granularity_at(const Node& n) const;
    void split(NodeId leaf);

    mesh::Mesh& mesh_;
    refine::RefineRun& run_;
    Quadtree& tree_;
    bool checked_;
    mesh::Pool pool_;
    refine::LeafRefiner refiner_;
    NodeAllocator nodes_;
    std::deque<LeafState> leaf_states_;
    BlockPool deferred_blocks_;
    // A new triangle and the circumcircle it was made with (stale once the
    // triangle died or changed).
    struct Created {
        DeferredTriangle e;
        geometry::Circle circle;
    };
    std::vector<Created> pending_;
    static constexpr std::uint32_t created_batch = 256;
    Created created_[created_batch];
    std::uint32_t created_size_ = 0;
    std::vector<refine::QueuedTriangle> routing_triangles_;
    std::vector<refine::QueuedSubsegment> routing_subsegments_;
    NodeId current_ = no_node;
    DeferralTargets current_targets_{};  // of current_, and its state
    LeafState* current_state_ = nullptr;
    std::int32_t tag_ = 0;  // the zone's Node::owner while a run goes on
    // The zone's leaves while a run goes on (checked mode's in_zone).
    const std::vector<NodeId>* zone_ = &no_zone_;
    static inline const std::vector<NodeId> no_zone_;
    bool in_zone(NodeId leaf) const;
    // Cells found lately: consecutive triangles mostly share cells, and a
    // cell's node never changes (nodes are never freed).
    struct CachedCell {
        std::uint64_t key = 0;
        NodeId node = no_node;
    };
    CachedCell cache_[256];
    refine::PlacementScratch scratch_;
    // report.triangles_created when the current run began (split_budget_).
    std::uint64_t run_start_ = 0;
    std::uint64_t split_budget_ = split_budget;
};

}  // namespace gpdr::parallel
