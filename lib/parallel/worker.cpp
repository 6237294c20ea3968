// One refinement thread (see worker.hpp): Fig. 4 of the GPDR paper on a leaf,
// the quadtree counters, routing of handed-off work, leaf splitting.

#include "parallel/worker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/constructions.hpp"
#include "mesh/traverse.hpp"
#include "parallel/stopwatch.hpp"
#include "refine/segments.hpp"

namespace gpdr::parallel {

namespace {

bool finite(const Point& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

CellRecord cell_record(const Quadtree& tree, const Point& centre, double radius_squared,
                       bool& outgrew_root) {
    const int k = tree.level_of(radius_squared);
    if (k > max_level) return {};  // too small to matter for any leaf we may make
    if (k < 0) {
        // Larger than the root allows (cannot happen while relation (9)
        // holds for the root; the scheduler then runs one leaf at a time).
        outgrew_root = true;
        return {0, 1, 0, 0};
    }
    // The disk's diameter is below ℓ_k / 2, so its bounding box spans at
    // most 2 x 2 cells.  A cell beside the centre's (same row or column) is
    // met by the disk whenever the box reaches it; only the diagonal cell of
    // a 2 x 2 box needs the real test.
    const double r = std::sqrt(radius_squared);
    const std::uint32_t x_lo = tree.cell_x(centre.x - r, k), x_hi = tree.cell_x(centre.x + r, k);
    const std::uint32_t y_lo = tree.cell_y(centre.y - r, k), y_hi = tree.cell_y(centre.y + r, k);
    std::uint64_t mask = 1;
    if (x_hi != x_lo) mask |= 2;
    if (y_hi != y_lo) mask |= 4;
    if (mask == 7) {
        // Which corner of the box holds the centre decides the diagonal cell.
        const std::uint32_t cx = tree.cell_x(centre.x, k), cy = tree.cell_y(centre.y, k);
        const unsigned centre_bit = (cx != x_lo ? 1u : 0u) | (cy != y_lo ? 2u : 0u);
        const unsigned diagonal = 3u - centre_bit;
        mask = 15u & ~(1u << diagonal);
        if (disk_meets(tree.cell_square(k, x_lo + (diagonal & 1u), y_lo + (diagonal >> 1)), centre,
                       r))
            mask |= 1u << diagonal;
    }
    return {k, static_cast<unsigned>(mask), x_lo, y_lo};
}

Worker::Worker(mesh::Mesh& mesh, refine::RefineRun& run, Quadtree& tree, const mesh::Lane& lane,
               bool checked)
    : mesh_(mesh),
      run_(run),
      tree_(tree),
      checked_(checked),
      pool_(mesh, lane),
      refiner_(run, pool_, report) {
    refiner_.set_observer(this);
}

OwnedBox owned_box(const Quadtree& tree, NodeId leaf) {
    const Square s = tree.square(leaf);
    const Node& n = tree.node(leaf);
    const std::uint32_t last = (std::uint32_t{1} << n.level) - 1;
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {n.ix == 0 ? -inf : s.x0, n.iy == 0 ? -inf : s.y0, n.ix == last ? inf : s.x0 + s.side,
            n.iy == last ? inf : s.y0 + s.side};
}

LeafState* Worker::new_leaf_state(NodeId leaf) {
    return &leaf_states_.emplace_back(tree_.square(leaf), owned_box(tree_, leaf));
}

// ---- counters ------------------------------------------------------------------

void Worker::apply(CellRecord record, int delta, bool check_zone) {
    const int level = record.level();
    record.for_each_cell([&](std::uint32_t ix, std::uint32_t iy) {
        const std::uint64_t key = (std::uint64_t(level + 1) << 52) | (std::uint64_t(ix) << 26) | iy;
        CachedCell& cached = cache_[(key * 0x9E3779B97F4A7C15ull) >> 56];
        NodeId id = cached.node, leaf = no_node;
        if (cached.key != key || (check_zone && checked_)) {
            // Start at the leaf being refined, or at its nearest ancestor
            // that holds the cell: most counted cells are in the leaf or
            // beside it, a level or two below a common ancestor, where a walk
            // from the root would go down the whole tree.
            const NodeId start = current_ == no_node
                                     ? Quadtree::root()
                                     : tree_.ancestor_holding(current_, level, ix, iy);
            id = tree_.cell(start, level, ix, iy, &nodes_, leaf);
            cached = {key, id};
        }
        // An atomic add everywhere: a leaf that two zones of the round share
        // is counted by both lanes (scheduler.hpp, (d)).
        Node& n = tree_.node(id);
        n.count.fetch_add(delta, std::memory_order_relaxed);
        if (n.get_kind() == NodeKind::internal) {
            // Above a leaf: relation (9) does not hold there (quadtree.hpp).
            if (delta > 0) ++relation9_exceptions;
        } else if (leaf != no_node && check_zone && checked_ && !in_zone(leaf)) {
            ++zone_escapes;
        }
    });
}

bool Worker::in_zone(NodeId leaf) const {
    const std::int32_t owner = tree_.node(leaf).owner.load(std::memory_order_relaxed);
    return owner == tag_ ||
           (owner == shared_owner && std::find(zone_->begin(), zone_->end(), leaf) != zone_->end());
}

void Worker::count(mesh::TriangleId t, const geometry::Circle& c) {
    const CellRecord record = cell_record(tree_, c.centre, c.radius_squared, outgrew_root);
    mesh::Triangle& r = mesh_.triangle(t);
    if (!record.counted()) {
        r.user_tag = 0;
        return;
    }
    r.user_tag = counted_tag;
    apply(record, +1, current_ != no_node);
}

void Worker::count_now(mesh::TriangleId t, const geometry::Circle& c) { count(t, c); }

void Worker::uncount(const mesh::TaggedTriangle& was) {
    const geometry::Circle c =
        geometry::circumcircle(mesh_.point(was.v[0]), mesh_.point(was.v[1]), mesh_.point(was.v[2]));
    apply(cell_record(tree_, c.centre, c.radius_squared, outgrew_root), -1, false);
}

void Worker::flush_pending() {
    if (pending_.empty()) return;
    // Prefetching as DeferredList::drain does for hand_down_deferred, each
    // triangle look_ahead entries early (its corners are not read: the
    // entry keeps the circle the triangle was made with).
    const std::size_t n = pending_.size();
    for (std::size_t i = 0; i < n && i < look_ahead; ++i) prefetch(pending_[i].e.t);
    for (std::size_t i = 0; i < n; ++i) {
        if (i + look_ahead < n) prefetch(pending_[i + look_ahead].e.t);
        const Created& p = pending_[i];
        // Created and killed (or changed by a flip) in this run: never counted.
        if (!alive(p.e)) continue;
        count(p.e.t, p.circle);
    }
    pending_.clear();
}

Worker::DeferralTargets Worker::deferral_targets(NodeId leaf) const {
    // (The squares as Quadtree::square computes them for the nodes, bit for
    // bit: the verifier and later splits test against those.)
    const Node& n = tree_.node(leaf);
    DeferralTargets t;
    t.band = tree_.two_levels_below(n.level);
    t.child_band = tree_.two_levels_below(n.level + 1);
    t.room = tree_.room(tree_.cell_square(n.level, n.ix, n.iy));
    for (int q = 0; q < 4; ++q)
        t.child_rooms[q] =
            tree_.room(tree_.cell_square(n.level + 1, 2 * n.ix + (q & 1), 2 * n.iy + (q >> 1)));
    const Square last = tree_.cell_square(n.level + 1, 2 * n.ix + 1, 2 * n.iy + 1);
    t.middle = {last.x0, last.y0};
    return t;
}

DeferredList* Worker::deferral_list(const geometry::Circle& c, const DeferralTargets& at,
                                    LeafState& leaf) const {
    // The centre picks the child; the room test alone decides (a centre
    // rounded onto the wrong side fails it).  Both tests are asked without
    // a branch: most triangles pass them.
    const int q = (c.centre.x >= at.middle.x ? 1 : 0) | (c.centre.y >= at.middle.y ? 2 : 0);
    if (at.child_band.holds(c.radius_squared) &
        tree_.disk_inside(at.child_rooms[q], c.centre, c.radius_squared))
        return &leaf.deferred_in_child[q];
    if (at.band.holds(c.radius_squared) & tree_.disk_inside(at.room, c.centre, c.radius_squared))
        return &leaf.deferred;
    return nullptr;
}

// Line 13's upkeep of the leaf's own deferred list (its lists for the
// children became theirs unread, see split): each live triangle goes to the
// child whose square holds it, to the list of the grandchild it fits, or is
// counted now.
void Worker::hand_down_deferred(NodeId leaf) {
    const Node& n = tree_.node(leaf);
    DeferralTargets targets[4];
    LeafState* states[4];
    for (int q = 0; q < 4; ++q) {
        targets[q] = deferral_targets(n.child(q));
        states[q] = tree_.node(n.child(q)).state;
    }
    const Point middle = deferral_targets(leaf).middle;
    n.state->deferred.drain(
        [&](const DeferredTriangle& e) {
            if (!alive(e)) return;
            const mesh::Triangle& r = mesh_.triangle(e.t);
            const geometry::Circle c = geometry::circumcircle(
                mesh_.point(r.v[0]), mesh_.point(r.v[1]), mesh_.point(r.v[2]));
            const int q = (c.centre.x >= middle.x ? 1 : 0) | (c.centre.y >= middle.y ? 2 : 0);
            if (DeferredList* list = deferral_list(c, targets[q], *states[q]))
                list->push(e, deferred_blocks_);
            else
                count(e.t, c);
        },
        [&](const DeferredTriangle& e) { prefetch(e.t); },
        [&](const DeferredTriangle& e) { prefetch_corners(e); }, deferred_blocks_);
}

void Worker::count_all() {
    mesh::for_each_triangle(mesh_, [&](mesh::TriangleId id, const mesh::Triangle& r) {
        count(id, geometry::circumcircle(mesh_.point(r.v[0]), mesh_.point(r.v[1]),
                                         mesh_.point(r.v[2])));
    });
}

// The counted triangles that died or flipped, first: uncounted from their
// corners as they were (their slots may be reused by the created triangles
// that follow).  A pending or deferred triangle needs nothing: its entry goes
// stale with the slot's generation, which a death or a flip bumps.
void Worker::tagged_triangles_gone(std::span<const mesh::TaggedTriangle> gone) {
    for (const mesh::TaggedTriangle& was : gone)
        if (was.tag == counted_tag) uncount(was);
}

// A new triangle, or one a flip changed (its tag is 0: see above).
void Worker::triangle_created(mesh::TriangleId t, std::uint32_t generation,
                              const geometry::Circle& circumcircle) {
    if (current_ == no_node) [[unlikely]] {
        count_now(t, circumcircle);
        return;
    }
    created_[created_size_++] = {{t, generation}, circumcircle};
    if (created_size_ == created_batch) [[unlikely]]
        sort_created();
}

void Worker::sort_created() {
    // (A copy: the pushes below cannot change it, so the compiler keeps it
    // in registers.)
    const DeferralTargets at = current_targets_;
    for (std::uint32_t i = 0; i < created_size_; ++i) {
        const Created& c = created_[i];
        if (!alive(c.e)) continue;
        if (DeferredList* list = deferral_list(c.circle, at, *current_state_))
            list->push(c.e, deferred_blocks_);
        else
            pending_.push_back(c);
    }
    created_size_ = 0;
}

// ---- routing ---------------------------------------------------------------------

void Worker::deliver(const Routed& r, NodeId splitting) {
    NodeId x;
    if (splitting != no_node && tree_.node(splitting).state->box.contains(r.at)) {
        const Square s = tree_.square(splitting);
        const double half = 0.5 * s.side;
        const int q = (r.at.x >= s.x0 + half ? 1 : 0) | (r.at.y >= s.y0 + half ? 2 : 0);
        x = tree_.node(splitting).child(q);
    } else {
        x = tree_.leaf_at(r.at, current_ == no_node ? Quadtree::root() : current_);
    }
    Node& n = tree_.node(x);
    if (n.get_kind() != NodeKind::internal && n.state != nullptr &&
        n.owner.load(std::memory_order_relaxed) == tag_) {
        push(n.state->work, r);  // a leaf of this worker's zone (Fig. 4 line 9)
        ++handed_off_local;
    } else {
        outbox.push_back(r);
    }
}

void Worker::route_triangle(refine::QueuedTriangle q, bool steiner_point_if_centre_inside,
                            const OwnedBox& inside, NodeId splitting) {
    const mesh::Triangle& t = mesh_.triangle(q.id);
    if (t.load_generation() != q.generation || !t.live())
        return;  // stale (generation first: mesh/triangle.hpp)
    const refine::TriangleMeasures m =
        refine::QualityTest::measure(mesh_.point(t.v[0]), mesh_.point(t.v[1]), mesh_.point(t.v[2]));
    Routed r;
    r.triangle = q;
    r.at = m.circle.centre;
    r.radius_squared = m.circle.radius_squared;
    r.shortest_squared = m.shortest.length_squared;
    r.kind = refine::poor_kind(run_.order(), run_.quality(), m);
    // Classification routes by circumcentre, refinement by the Steiner
    // point f(t): a triangle handed off although its centre is inside was
    // handed off for its Steiner point, and one kept although its centre is
    // outside was kept for it.
    if (inside.contains(r.at) == steiner_point_if_centre_inside) {
        const refine::PoorTriangle p = refine::describe_poor_triangle(mesh_, q.id, run_.quality());
        // Exactly refine_triangle's choice, so that the leaf it lands in takes it.
        const Point f = run_.strategy().place(p, scratch_);
        if (finite(f)) r.at = f;
    }
    deliver(r, splitting);
}

void Worker::route_subsegment(refine::QueuedSubsegment s, NodeId splitting) {
    const mesh::Triangle& t = mesh_.triangle(s.edge.triangle());
    if (t.load_generation() != s.generation || !t.live()) return;
    const Point& a = mesh_.point(mesh_.origin(s.edge));
    const Point& b = mesh_.point(mesh_.destination(s.edge));
    Routed r;
    r.is_triangle = false;
    r.subsegment = s;
    r.at = geometry::point_on_segment(
        a, b, refine::split_parameter(mesh_, s.edge, refiner_.quality().encroachment_lens()));
    deliver(r, splitting);
}

// ---- one leaf ----------------------------------------------------------------------

void Worker::split(NodeId leaf) {
    // Line 13: the leaf's own count is 0, so (9) holds for each child; the
    // children's counts are exact already (shadow nodes: everything at most
    // one level below the leaf is counted), and the hand-down below counts
    // what is now one level below a child.
    const OwnedBox s = tree_.node(leaf).state->box;
    for (int q = 0; q < 4; ++q) {
        const NodeId c = tree_.child(leaf, q, nodes_);
        Node& n = tree_.node(c);
        n.state = new_leaf_state(c);
        n.owner.store(tag_, std::memory_order_relaxed);
    }
    // The leaf's lists for its children become theirs, unread.
    LeafState& parent = *tree_.node(leaf).state;
    for (int q = 0; q < 4; ++q)
        tree_.node(tree_.node(leaf).child(q)).state->deferred.take(parent.deferred_in_child[q]);
    hand_down_deferred(leaf);
    // The poor triangles go to the child their `where` names (see
    // move_poor_to_children); the mesh is not looked at (stale entries go
    // along and are skipped when popped).  Only an entry whose `where` is
    // used up is measured and routed afresh.
    refine::Leaf& work = tree_.node(leaf).state->work;
    const Node& n = tree_.node(leaf);
    refine::Leaf* const children[4] = {
        &tree_.node(n.child(0)).state->work, &tree_.node(n.child(1)).state->work,
        &tree_.node(n.child(2)).state->work, &tree_.node(n.child(3)).state->work};
    work.move_poor_to_children(
        children, [&](refine::QueuedTriangle q) { route_triangle(q, false, s, leaf); });
    refine::QueuedSubsegment e;
    while (work.pop_subsegment(e)) route_subsegment(e, leaf);
    // The emptied queues would otherwise hold their capacity (tens of
    // megabytes over all split leaves) until refinement ends.
    released_bytes += work.release();
}

// The granularity of a leaf at tree level L: g, but at most L.  Near the
// root a round holds a handful of leaves, whose zones overlap (the root's
// four children are refined one after another), so a leaf there that
// refined g levels before splitting would refine them alone; splitting as
// soon as relation (9) allows hands that work down to levels where many
// leaves share a round (docs/performance.md, "The rounds").  Only size-only
// triangles are bounded by it: the window for triangles poor by their angle
// stays g-wide (refine_window), so a small mesh is still refined by the
// root alone, in -j1's order.
int Worker::granularity_at(const Node& n) const {
    return std::min(static_cast<int>(run_.settings().granularity), static_cast<int>(n.level));
}

// Whether the leaf should split now, before refining further: relation (9)
// holds for its children (its own count is 0) and the work waiting in it is
// for triangles small enough to be the children's (σ >= 2 + g: a leaf
// refines triangles down to r ~ ℓ/2^(2+g) itself, so that larger g makes
// fewer, longer runs).  Splitting later would leave one worker refining a
// large part of the mesh while the others wait for its buffer zone.
bool Worker::should_split(const Node& n, LeafState& state) {
    if (stopped || n.level >= max_level) return false;
    const int lowest = state.work.lowest_level();
    const bool work_is_childrens =
        lowest >= 2 + granularity_at(n) || (lowest < 0 && state.work.subsegment_entries() != 0);
    if (!work_is_childrens) return false;
    // The count must be exact now: the batch may hold triangles to count.
    sort_created();
    flush_pending();
    return n.count.load(std::memory_order_relaxed) == 0;
}

// A leaf whose count is not 0 cannot split: relation (9) would not hold for
// its children.  Its window (refine_window) would take the large triangles
// first and leave those below the window for the children it cannot have
// yet, where Triangle's order takes the small ones near the input's
// features first, and the meshes would grow.  So while its count is not 0,
// the leaf takes its triangles poor by their angle over all its levels, in
// the leaf's order, checking the count after every blocked_batch entries
// (refine/order.hpp, rule 4); then its run goes on as any other.  A leaf
// whose count falls to 0 early (the initial triangulation's few large
// triangles resolved) keeps its parallelism; one that stays blocked refines
// its part of the mesh alone, in -j1's order.  False when a limit stopped
// refinement.
bool Worker::refine_while_blocked(const Node& n, LeafState& state) {
    for (;;) {
        sort_created();
        flush_pending();
        if (n.count.load(std::memory_order_relaxed) == 0) return true;
        std::uint64_t takes_left = refine::blocked_batch;
        if (!refiner_.refine_levels(state.work, refine::Leaf::bucket_count - 1, -1, &takes_left))
            return false;
        if (takes_left != 0) return true;  // none left poor by its angle
    }
}

// Fig. 4 on the levels of the leaf's own triangles, i_min .. 1 + g (the
// leaf splits once its work lies at 2 + g and below: should_split; g as
// granularity_at has it), and, for triangles poor by their angle, down to
// 1 + g + order_levels_beyond_split with the full g, all in the leaf's order
// (refine/order.hpp, rule 3).  Before the window, while the leaf's count
// keeps it from splitting, its triangles poor by their angle at every level
// (rule 4: refine_while_blocked).  Returns whether the leaf should split
// now that its work belongs to its children.
bool Worker::refine_window(const Node& n, LeafState& state) {
    const int own_levels = 1 + granularity_at(n);
    const int last_level =
        1 + static_cast<int>(run_.settings().granularity) + refine::order_levels_beyond_split;
    bool split_now = should_split(n, state);
    if (!split_now && !stopped && n.level < max_level && !state.work.idle()) {
        if (!refine_while_blocked(n, state)) {
            stopped = true;
        } else {
            split_now = should_split(n, state);
        }
    }
    if (!split_now && !state.work.idle()) {
        const int lowest = state.work.lowest_level();
        if (!refine_own_levels(n, state, std::max(lowest, last_level),
                               std::max(lowest, own_levels), split_now)) {
            stopped = true;
        } else if (!split_now) {
            split_now = should_split(n, state);
        }
    }
    sort_created();
    flush_pending();
    return split_now;
}

// The window's levels, in budget_slice entries at a time: once the run has
// made its round's split budget of triangles, the leaf splits as soon as it may
// (may_split_early), leaving the rest of its levels to its children (see
// split_budget).  split_now says whether it stopped for that.  False when a
// limit stopped refinement.
bool Worker::refine_own_levels(const Node& n, LeafState& state, int last_level,
                               int last_size_level, bool& split_now) {
    split_now = false;
    for (;;) {
        std::uint64_t takes_left = budget_slice;
        if (!refiner_.refine_levels(state.work, last_level, last_size_level, &takes_left))
            return false;
        if (takes_left != 0) return true;  // the window is done
        if (report.triangles_created - run_start_ >= split_budget_ && may_split_early(n, state)) {
            split_now = true;
            return true;
        }
    }
}

// should_split's test with early_split_granularity for the leaf's levels:
// the work left is for triangles at least 2 + that many levels below the
// leaf, and its count, made exact, is 0.  Only triangles poor by size alone
// may be left: the window's order across levels for the others (rule 3,
// refine/order.hpp) keeps the meshes small at high angles, and a split
// would cut it short.  The queues are looked at first: they cost nothing,
// where the count costs the counting of the run's batch.
bool Worker::may_split_early(const Node& n, LeafState& state) {
    if (stopped || n.level >= max_level || !state.work.size_bins_only()) return false;
    const int lowest = state.work.lowest_level();
    if (lowest < 2 + std::min(early_split_granularity, granularity_at(n))) return false;
    sort_created();
    flush_pending();
    return n.count.load(std::memory_order_relaxed) == 0;
}

// The work the leaf handed off: to leaves of the zone, or to the outbox.
// (Swapped with the worker's emptied lists: no allocation per run.)
void Worker::route_handed_off(LeafState& state) {
    routing_triangles_.swap(state.work.handed_off_triangles);
    for (const auto& q : routing_triangles_) route_triangle(q, true, state.box, no_node);
    routing_triangles_.clear();
    routing_subsegments_.swap(state.work.handed_off_subsegments);
    for (const auto& s : routing_subsegments_) route_subsegment(s, no_node);
    routing_subsegments_.clear();
}

// The zone's large idle leaves (see Scheduler::take_balance_candidates): the
// same split, allowed by the same rule (a count of 0 lets relation (9) hold
// for the children; the counts are exact now).  A leaf with work waits to
// be refined instead.
void Worker::split_balance_candidates(const std::vector<NodeId>& balance) {
    balanced.clear();
    for (const NodeId e : balance) {
        const Node& b = tree_.node(e);
        if (stopped || b.level >= max_level || !b.state->work.idle() ||
            b.count.load(std::memory_order_relaxed) != 0)
            continue;
        split(e);
        balanced.push_back(e);
    }
}

// A leaf left with nothing to do keeps its emptied queues at the capacity
// its runs grew them to, and most leaves are idle most of the time: over
// the idle leaves that held 160 MiB at the end of the graded pipe's -j2
// refinement, second only to the deferred lists.  Given back at once; a
// leaf that is given work again grows its queues afresh.
void Worker::release_idle_queues(LeafState& state) { released_bytes += state.work.release(); }

// The leaf's deferred lists, swept of stale entries when they have doubled
// since they were last swept (DeferredList::worth_sweeping).  A listed
// triangle that dies stays listed until a split reads the list, and in a
// leaf that never splits again, to the end: most triangles listed die
// later in the run that listed them (refining a level kills triangles the
// levels above it made), after the batch that sorts new triangles has let
// them go (sort_created).  Unswept, the graded pipe's lists held 29 million
// entries at the end of its -j2 refinement, 14.4 million of them live;
// swept at the end of each run that doubled them, 14.5 million.
void Worker::sweep_deferred(LeafState& state) {
    if (state.deferred.worth_sweeping()) state.deferred.sweep(liveness(), deferred_blocks_);
    for (DeferredList& list : state.deferred_in_child)
        if (list.worth_sweeping()) list.sweep(liveness(), deferred_blocks_);
}

bool Worker::run(NodeId leaf, std::int32_t tag, const std::vector<NodeId>& zone,
                 const std::vector<NodeId>& balance) {
    Stopwatch clock;
    zone_ = &zone;
    run_start_ = report.triangles_created;
    current_ = leaf;
    current_targets_ = deferral_targets(leaf);
    current_state_ = tree_.node(leaf).state;
    tag_ = tag;
    const Node& n = tree_.node(leaf);
    LeafState& state = *n.state;
    const bool split_now = refine_window(n, state);
    times.refining += clock.lap();

    route_handed_off(state);
    if (split_now)
        split(leaf);
    else if (state.work.idle())
        release_idle_queues(state);
    if (!split_now) sweep_deferred(state);
    split_balance_candidates(balance);
    current_ = no_node;
    tag_ = 0;
    zone_ = &no_zone_;
    times.managing += clock.lap();
    return split_now;
}

}  // namespace gpdr::parallel
