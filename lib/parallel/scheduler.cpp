// The rounds' scheduling (see scheduler.hpp for the rule and its proof)
// and the checked mode's quadtree verification.

#include "parallel/scheduler.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>

#include <fmt/format.h>

#include "geometry/constructions.hpp"
#include "mesh/traverse.hpp"
#include "parallel/morton.hpp"

namespace gpdr::parallel {

bool Scheduler::has_work(NodeId leaf) const {
    const Node& n = tree_.node(leaf);
    return n.state != nullptr && !n.state->work.idle();
}

// Subsegments first, as refine_leaf's step 0 comes first: a poor triangle
// whose Steiner point waits for a subsegment that another leaf must split
// would otherwise be taken again and again.  Then the absolute size class
// of the leaf's lowest σ level.
long Scheduler::key(NodeId leaf) const {
    const Node& n = tree_.node(leaf);
    if (n.state->work.subsegment_entries() != 0) return long(n.level) - 4096;
    const int lowest = n.state->work.lowest_level();
    return long(n.level) + std::max(lowest, 0);
}

void Scheduler::offer(NodeId leaf) {
    // Every change to a leaf's work is followed by an offer; the next round
    // sorts its candidates afresh, so a leaf waits once, unsorted.
    Info& i = info(leaf);
    if (held(leaf) || tree_.node(leaf).get_kind() != NodeKind::leaf || !has_work(leaf)) return;
    if (!i.queued) waiting_.push_back(leaf);
    i.queued = true;
}

void Scheduler::deliver(const Routed& r, NodeId near) {
    const NodeId x = tree_.leaf_at(r.at, near);
    ++report_.handed_off_master;
    if (held(x)) {
        to_inbox(x, r);  // its zone is being refined: later
        return;
    }
    push(tree_.node(x).state->work, r);
    offer(x);
}

void Scheduler::flush_inbox(NodeId leaf) {
    if (!flag(leaf, inbox_flag)) return;
    set_flag(leaf, inbox_flag, false);
    std::vector<Routed> items;
    items.swap(info(leaf).inbox);
    for (const Routed& r : items) {
        const NodeId x = tree_.leaf_at(r.at, leaf);  // the leaf may have split meanwhile
        if (held(x) && x != leaf) {
            to_inbox(x, r);
            continue;
        }
        push(tree_.node(x).state->work, r);
    }
}

void Scheduler::hold(int entry, NodeId chosen) {
    if (checked_) {
        // The rule, checked independently of the hold counts: the new leaf
        // in no zone of the round so far, and no leaf taken in its zone.
        for (const Active& a : active_) {
            if (a.leaf == no_node) continue;
            if (std::find(a.zone.begin(), a.zone.end(), chosen) != a.zone.end() ||
                std::find(zone_scratch_.begin(), zone_scratch_.end(), a.leaf) !=
                    zone_scratch_.end())
                report_.problems.push_back(
                    fmt::format("buffer zones: leaf {} handed out beside leaf {}", chosen, a.leaf));
        }
    }
    Active& a = active_[entry];
    a.leaf = chosen;
    a.zone = zone_scratch_;
    set_flag(chosen, taken_flag, true);
    for (NodeId z : a.zone) {
        hold_leaf(z);
        flush_inbox(z);
    }
    ++report_.assignments;
}

// Once the round is chosen: a zone's leaves that no other zone of the round
// holds are the lane's alone (Node::owner is its tag), the others are
// shared (shared_owner: the lanes route work for them through the calling
// thread and leave their queues alone); the lane may split the exclusive
// ones that are large and idle (take_balance_candidates).
void Scheduler::mark_owners(std::size_t entries) {
    for (std::size_t e = 0; e < entries; ++e) {
        Active& a = active_[e];
        a.balance.clear();
        const int level = tree_.node(a.leaf).level;
        for (NodeId z : a.zone) {
            const bool exclusive = holds_[z] == 1;
            tree_.node(z).owner.store(exclusive ? static_cast<std::int32_t>(e + 1) : shared_owner,
                                      std::memory_order_relaxed);
            if (exclusive && tree_.node(z).level + 2 <= level) a.balance.push_back(z);
        }
    }
}

void Scheduler::plan_round(std::vector<NodeId>& round) {
    round.clear();
    struct Candidate {
        long key;
        int level;
        std::uint64_t cell;
        NodeId leaf;
    };
    std::vector<Candidate> candidates;
    candidates.reserve(waiting_.size());
    for (const NodeId x : waiting_) {
        Info& i = info(x);
        i.queued = false;
        if (tree_.node(x).get_kind() != NodeKind::leaf || held(x) || !has_work(x)) continue;
        const Node& n = tree_.node(x);
        candidates.push_back({key(x), n.level, morton(n.ix, n.iy), x});
    }
    waiting_.clear();
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
        return std::tie(a.key, a.level, a.cell) < std::tie(b.key, b.level, b.cell);
    });
    for (const Candidate& c : candidates) {
        if (serial_ && !round.empty()) break;
        if (held(c.leaf)) continue;  // in a zone taken: offered again when it completes
        // No leaf taken lies in its zone (BUF is symmetric: none can, once
        // the leaf lies in no zone taken; the search stops if one did).
        const NodeId taken = tree_.zone_until(c.leaf, zone_scratch_,
                                              [&](NodeId z) { return flag(z, taken_flag); });
        if (taken != no_node) continue;
        const int entry = static_cast<int>(round.size());
        if (active_.size() <= static_cast<std::size_t>(entry)) active_.resize(entry + 1);
        hold(entry, c.leaf);
        round.push_back(c.leaf);
    }
    mark_owners(round.size());
    report_.most_concurrent =
        std::max(report_.most_concurrent, static_cast<unsigned>(round.size()));
    // The others wait for the next round.
    for (const Candidate& c : candidates) offer(c.leaf);
}

void Scheduler::publish_split(NodeId leaf) {
    // Children before the parent turns internal: a worker that sees
    // "internal" (acquire) finds the children's kinds set.
    Node& n = tree_.node(leaf);
    for (int q = 0; q < 4; ++q) {
        Node& c = tree_.node(n.child(q));
        c.kind.store(static_cast<std::uint8_t>(NodeKind::leaf), std::memory_order_release);
        c.owner.store(0, std::memory_order_relaxed);
    }
    n.kind.store(static_cast<std::uint8_t>(NodeKind::internal), std::memory_order_release);
    ++report_.splits;
    report_.depth = std::max(report_.depth, int(n.level) + 1);
}

void Scheduler::complete(int entry, bool split, const std::vector<NodeId>& balanced,
                         std::vector<Routed>& outbox, bool outgrew_root) {
    Active& a = active_[entry];
    const NodeId leaf = a.leaf;
    if (split) publish_split(leaf);
    for (NodeId b : balanced) publish_split(b);
    report_.balance_splits += balanced.size();
    set_flag(leaf, taken_flag, false);
    for (NodeId z : a.zone) release_leaf(z);
    // A leaf another zone of the round still holds is offered when that
    // one completes.
    for (NodeId z : a.zone) {
        if (held(z)) continue;
        flush_inbox(z);
        if (tree_.node(z).get_kind() == NodeKind::leaf) {
            offer(z);
        } else {
            const Node& n = tree_.node(z);
            for (int q = 0; q < 4; ++q) offer(n.child(q));
        }
    }
    a.leaf = no_node;
    a.zone.clear();
    for (const Routed& r : outbox) deliver(r, leaf);
    outbox.clear();
    if (outgrew_root) serial_ = true;
}

// ---- checked mode ---------------------------------------------------------------

namespace {

// The problems of one verification, at most 20 (more say nothing new).
class QuadtreeProblems {
public:
    explicit QuadtreeProblems(std::vector<std::string>& problems)
        : problems_(problems), before_(problems.size()) {}
    void add(std::string s) {
        if (problems_.size() - before_ < 20) problems_.push_back(std::move(s));
    }

private:
    std::vector<std::string>& problems_;
    std::size_t before_;
};

// Where a live deferred entry is deferred: the leaf's square, or its
// child's for the lists of the children.
struct DeferredIn {
    NodeId leaf;
    int level;
    Square square;
};
using DeferredMap = std::unordered_map<std::uint32_t, DeferredIn>;

// The live entries of every leaf's deferred lists, by triangle slot.
DeferredMap deferred_entries(const mesh::Mesh& mesh, const Quadtree& tree,
                             const std::vector<NodeId>& leaves, QuadtreeProblems& problems) {
    DeferredMap deferred_in;
    for (NodeId l : leaves) {
        if (tree.node(l).state == nullptr) continue;
        const Node& n = tree.node(l);
        const auto list_in = [&](const DeferredList& list, const DeferredIn& in) {
            list.for_each([&](const DeferredTriangle& e) {
                if (mesh.triangle(e.t).load_generation() != e.generation) return;
                if (!deferred_in.emplace(mesh::index(e.t), in).second)
                    problems.add(fmt::format("triangle {} is deferred twice", mesh::index(e.t)));
            });
        };
        list_in(n.state->deferred, {l, n.level, tree.square(l)});
        for (int q = 0; q < 4; ++q)
            list_in(n.state->deferred_in_child[q],
                    {l, n.level + 1,
                     tree.cell_square(n.level + 1, 2 * n.ix + (q & 1), 2 * n.iy + (q >> 1))});
    }
    return deferred_in;
}

// Triangle i (circumcircle c, cell record `record`) is either counted, or
// deferred, or too small to be counted, and deferred only where it may be.
void check_counted_or_deferred(const Quadtree& tree, std::uint32_t i, const mesh::Triangle& t,
                               const geometry::Circle& c, CellRecord record,
                               const DeferredMap& deferred_in, QuadtreeProblems& problems) {
    const bool counted = t.user_tag == counted_tag;
    const auto listed = deferred_in.find(i);
    if (listed != deferred_in.end()) {
        // Deferred (Worker::flush_pending): not counted, listed in a leaf
        // whose square (or its child's, for a child's list) holds it with
        // room to spare, two or more levels above it.
        const DeferredIn& in = listed->second;
        const int k = tree.level_of(c.radius_squared);
        if (counted || !record.counted() || k < in.level + 2 ||
            !tree.disk_inside(tree.room(in.square), c.centre, c.radius_squared))
            problems.add(
                fmt::format("triangle {} (level {}, tag {}) is deferred in leaf {} for level {}", i,
                            k, int(t.user_tag), in.leaf, in.level));
    } else if (!counted) {
        if (record.counted())
            problems.add(fmt::format("triangle {} is neither counted nor deferred", i));
    } else if (!record.counted()) {
        problems.add(fmt::format("triangle {} is counted although too small to be", i));
    }
}

// A counted triangle adds one to the counter of each cell its record names.
void expect_counts(Quadtree& tree, std::uint32_t i, CellRecord record,
                   std::unordered_map<NodeId, std::int32_t>& expected, QuadtreeProblems& problems) {
    record.for_each_cell([&](std::uint32_t ix, std::uint32_t iy) {
        NodeId leaf;
        const NodeId n = tree.cell(Quadtree::root(), record.level(), ix, iy, nullptr, leaf);
        if (n == no_node)
            problems.add(fmt::format("triangle {}: its counter cell was never made", i));
        else
            ++expected[n];
    });
}

// Relation (9), with effective sides, for every leaf the circumdisk of
// triangle i meets.  A triangle larger than the root allows is exempt: it
// is counted at the root, and the scheduler then hands out one leaf at a
// time (cell_record's outgrew_root).  `stack` is scratch.
void check_relation_9(const Quadtree& tree, std::uint32_t i, const geometry::Circle& c,
                      std::vector<NodeId>& stack, QuadtreeProblems& problems) {
    if (tree.level_of(c.radius_squared) < 0) return;
    const double r = std::sqrt(c.radius_squared);
    stack.assign(1, Quadtree::root());
    while (!stack.empty()) {
        const NodeId n = stack.back();
        stack.pop_back();
        if (!disk_meets(tree.square(n), c.centre, r)) continue;
        if (tree.node(n).get_kind() == NodeKind::internal) {
            for (int q = 0; q < 4; ++q) stack.push_back(tree.node(n).child(q));
            continue;
        }
        if (!(r < tree.effective_side(n) / 4))
            problems.add(fmt::format(
                "relation (9) fails: triangle {} (r = {}) meets leaf {} of effective side {}", i, r,
                n, tree.effective_side(n)));
    }
}

// Every node's counter holds what the counted triangles expect of it.
void check_counters(const Quadtree& tree, const std::unordered_map<NodeId, std::int32_t>& expected,
                    QuadtreeProblems& problems) {
    for (NodeId n = 0; n < tree.node_end(); ++n) {
        const auto it = expected.find(n);
        const std::int32_t want = it == expected.end() ? 0 : it->second;
        const std::int32_t have = tree.node(n).count.load(std::memory_order_relaxed);
        if (want != have)
            problems.add(fmt::format("quadtree node {}: count {}, expected {}", n, have, want));
    }
}

// The leaves have work lists, none is held, and together they tile the root.
void check_leaves(const Quadtree& tree, const std::vector<NodeId>& leaves,
                  QuadtreeProblems& problems) {
    double area = 0;
    for (NodeId l : leaves) {
        const Square s = tree.square(l);
        area += s.side * s.side;
        if (tree.node(l).get_kind() != NodeKind::leaf || tree.node(l).state == nullptr)
            problems.add(
                fmt::format("quadtree node {} is neither internal nor a leaf with work lists", l));
        if (tree.node(l).owner.load(std::memory_order_relaxed) != 0)
            problems.add(fmt::format("leaf {} is still held while no worker is busy", l));
    }
    const Square root = tree.square(Quadtree::root());
    if (std::abs(area - root.side * root.side) > 1e-9 * root.side * root.side)
        problems.add("the leaves do not tile the root square");
}

}  // namespace

void verify_quadtree(const mesh::Mesh& mesh, Quadtree& tree, std::vector<std::string>& problems) {
    QuadtreeProblems found(problems);
    std::vector<NodeId> leaves;
    tree.leaves(leaves);
    const DeferredMap deferred_in = deferred_entries(mesh, tree, leaves, found);
    std::unordered_map<NodeId, std::int32_t> expected;
    bool outgrew = false;
    std::vector<NodeId> stack;
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId id, const mesh::Triangle& t) {
        const geometry::Circle c =
            geometry::circumcircle(mesh.point(t.v[0]), mesh.point(t.v[1]), mesh.point(t.v[2]));
        const CellRecord record = cell_record(tree, c.centre, c.radius_squared, outgrew);
        const std::uint32_t i = mesh::index(id);
        check_counted_or_deferred(tree, i, t, c, record, deferred_in, found);
        if (t.user_tag == counted_tag && record.counted())
            expect_counts(tree, i, record, expected, found);
        check_relation_9(tree, i, c, stack, found);
    });
    check_counters(tree, expected, found);
    check_leaves(tree, leaves, found);
}

}  // namespace gpdr::parallel
