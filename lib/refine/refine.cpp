// The refinement loop of one leaf and the sequential driver (see
// refine.hpp for the algorithm, its limits and its termination guards).

#include "refine/refine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <gpdr/errors.hpp>

#include "geometry/predicates.hpp"
#include "mesh/locate.hpp"
#include "mesh/slices.hpp"
#include "mesh/split_subsegment.hpp"
#include "mesh/traverse.hpp"
#include "refine/area_demand.hpp"
#include "refine/convergence.hpp"
#include "refine/segments.hpp"

namespace gpdr::refine {

using geometry::Point;
using mesh::EdgeRef;
using mesh::TriangleId;
using mesh::VertexId;

namespace {

constexpr std::uint8_t reason_no_split = 0;
constexpr std::uint8_t reason_precision = 1;

// 2^-40: below this fraction of the domain's diameter an edge is "too small
// for double precision" (about 12 significant bits are left for the
// constructions), and a Steiner point this close (relative to the
// circumradius) to a vertex makes no progress.
constexpr double tiny_fraction = 0x1p-40;

bool finite(const Point& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Where a walk from a triangle toward p ended.
struct Walk {
    enum class Kind : std::uint8_t { located, blocked, lost } kind = Kind::lost;
    mesh::LocateResult where;
    EdgeRef blocking;  // blocked: the subsegment or hull edge in the way
};

// The remembering stochastic walk of mesh/locate.cpp, except that it never
// crosses a subsegment or leaves the mesh: when p lies beyond such an edge
// and no other edge leads on, the walk reports that edge.
Walk walk_to(const mesh::Mesh& mesh, TriangleId start, const Point& p,
             std::uint32_t& random_state) {
    TriangleId t = start;
    int from = -1;
    for (std::uint64_t steps = 0; steps < 4ull * mesh.triangle_end() + 64; ++steps) {
        const mesh::Triangle& r = mesh.triangle(t);
        const Point* corner[3] = {&mesh.point(r.v[0]), &mesh.point(r.v[1]), &mesh.point(r.v[2])};
        random_state = random_state * 1664525u + 1013904223u;
        const int first = static_cast<int>((random_state >> 16) % 3u);
        double o[3] = {1, 1, 1};
        int blocked = -1;
        bool moved = false;
        for (int i = 0; i < 3 && !moved; ++i) {
            const int k = (first + i) % 3;
            if (k == from) continue;
            o[k] = geometry::orient2d(*corner[mesh::next3(k)], *corner[mesh::prev3(k)], p);
            if (o[k] >= 0) continue;
            if (r.n[k].is_none() || r.is_subsegment(k)) {
                blocked = k;
                continue;
            }
            from = r.n[k].edge();
            t = r.n[k].triangle();
            moved = true;
        }
        if (moved) continue;
        Walk w;
        if (blocked >= 0) {
            w.kind = Walk::Kind::blocked;
            w.blocking = EdgeRef(t, blocked);
            return w;
        }
        w.kind = Walk::Kind::located;
        const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
        if (zeros == 0)
            w.where = {t, mesh::Location::inside, 0};
        else if (zeros == 1)
            w.where = {t, mesh::Location::on_edge, o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2};
        else
            w.where = {t, mesh::Location::on_vertex, o[0] != 0 ? 0 : o[1] != 0 ? 1 : 2};
        return w;
    }
    return {};
}

}  // namespace

// ---- RefineRun ---------------------------------------------------------------

RefineRun::RefineRun(const mesh::Mesh& mesh, const RefineSettings& settings)
    : steiner_used(settings.steiner_counter != nullptr ? *settings.steiner_counter
                                                       : own_steiner_used_),
      settings_(settings),
      quality_(settings_.criteria, SegmentEnds{settings_.segment_ends}),
      order_(order_rules(quality_)),
      strategy_(
          settings_.strategy != nullptr
              ? settings_.strategy
              : &builtin_placement(settings_.placement, settings_.criteria.min_angle_degrees)) {
    double min_x = std::numeric_limits<double>::infinity(), max_x = -min_x, min_y = min_x,
           max_y = -min_x;
    std::uint64_t triangles = 0;
    double expected = 0;  // triangles the area bounds alone call for
    const QualityCriteria& c = settings_.criteria;
    mesh::for_each_triangle(mesh, [&](TriangleId, const mesh::Triangle& t) {
        ++triangles;
        for (VertexId v : t.v) {
            const Point& p = mesh.point(v);
            min_x = std::min(min_x, p.x);
            max_x = std::max(max_x, p.x);
            min_y = std::min(min_y, p.y);
            max_y = std::max(max_y, p.y);
        }
        const double bound = area_bound(c, mesh, t);
        if (std::isfinite(bound))
            expected +=
                geometry::signed_area(mesh.point(t.v[0]), mesh.point(t.v[1]), mesh.point(t.v[2])) /
                bound;
    });
    const double diameter = triangles == 0 ? 0.0 : std::hypot(max_x - min_x, max_y - min_y);
    tiny_length_squared_ = (diameter * tiny_fraction) * (diameter * tiny_fraction);
    if (settings_.watch_convergence) cascade_floor_squared_ = refine::cascade_floor_squared(mesh);

    // The safety budget: far above what a terminating refinement needs (an
    // area bound needs about 2 area/bound triangles, one vertex per two
    // triangles; an angle bound a multiple of the input's size for sane
    // inputs), far below what the mesh can hold.  A user test can ask for
    // anything, so it only gets the mesh's capacity.
    constexpr double capacity = double(mesh::max_triangles / 2 - 16);
    double limit = settings_.safety_limit > 0 ? double(settings_.safety_limit)
                   : c.user_test != nullptr
                       ? capacity
                       : double(1u << 20) + 64.0 * (double(triangles) + expected);
    safety_limit_ = static_cast<std::uint64_t>(std::min(limit, capacity));
}

// ---- LeafRefiner ---------------------------------------------------------------

LeafRefiner::LeafRefiner(RefineRun& run, mesh::Pool& pool, RefineReport& report)
    : run_(run),
      settings_(run.settings()),
      quality_(run.quality()),
      pool_(pool),
      mesh_(pool.mesh()),
      report_(report) {}

void LeafRefiner::classify(Leaf& leaf, TriangleId t) {
    const mesh::Triangle& r = mesh_.triangle(t);
    classify(leaf, t,
             QualityTest::measure(mesh_.point(r.v[0]), mesh_.point(r.v[1]), mesh_.point(r.v[2])));
}

void LeafRefiner::classify(Leaf& leaf, TriangleId t, const TriangleMeasures& m) {
    mesh::Triangle& r = mesh_.triangle(t);
    const Point& a = mesh_.point(r.v[0]);
    const Point& b = mesh_.point(r.v[1]);
    const Point& c = mesh_.point(r.v[2]);
    bool protected_angle = false;
    const Poorness poorness = quality_.assess(mesh_, t, m, &protected_angle);
    // Remembered for the final count (count_left): a triangle's assessment
    // depends on nothing but the triangle, so it holds until the triangle dies.
    r.flags =
        static_cast<std::uint8_t>(protected_angle ? r.flags | mesh::Triangle::small_angle_bit
                                                  : r.flags & ~mesh::Triangle::small_angle_bit);
    if (poorness != Poorness::good) {
        const QueuedTriangle q{t, r.generation, leaf.where(m.circle.centre)};
        // Poor triangles are routed by their circumcentre; the Steiner point
        // itself is checked again before it is inserted.
        if (leaf.owns(m.circle.centre)) {
            const PoorSlot at =
                leaf.slot(m.circle.radius_squared, m.shortest.length_squared, kind(m));
            if (holding_size_only_ && at.bin == Leaf::size_bin) {
                // Member by member: a record built whole on the stack was
                // copied with loads that straddle its smaller stores (a
                // store-forwarding stall, a third of this function's time).
                SizeOnly& e = size_only_.emplace_back();
                e.q.id = q.id;
                e.q.generation = q.generation;
                e.q.where = q.where;
                e.at = at;
                e.shortest_squared = m.shortest.length_squared;
            } else
                leaf.push_poor(q, at);
        } else
            leaf.handed_off_triangles.push_back(q);
    }
    if ((r.flags & 7u) == 0) return;
    const Point* corner[3] = {&a, &b, &c};
    for (int k = 0; k < 3; ++k)
        if (r.is_subsegment(k) && encroaches(*corner[mesh::next3(k)], *corner[mesh::prev3(k)],
                                             *corner[k], quality_.encroachment_lens()))
            leaf.push_subsegment({EdgeRef(t, k), r.generation, false});
}

void LeafRefiner::classify_all(Leaf& leaf) {
    mesh::for_each_triangle(mesh_,
                            [&](TriangleId id, const mesh::Triangle&) { classify(leaf, id); });
}

void LeafRefiner::classify_created(Leaf& leaf) {
    report_.triangles_created += buffer_.created.size();
    if (observer_ != nullptr) observer_->tagged_triangles_gone(buffer_.tagged_gone);
    buffer_.tagged_gone.clear();  // (told once)
    holding_size_only_ = run_.order().sort_size_only;
    for (TriangleId id : buffer_.created) {
        const mesh::Triangle& r = mesh_.triangle(id);
        const TriangleMeasures m =
            QualityTest::measure(mesh_.point(r.v[0]), mesh_.point(r.v[1]), mesh_.point(r.v[2]));
        if (observer_ != nullptr) observer_->triangle_created(id, r.generation, m.circle);
        classify(leaf, id, m);
    }
    holding_size_only_ = false;
    queue_size_only(leaf);
}

// The size bin is last in, first out: the triangles one insertion made
// would be taken newest first, in the order the cavity's walk happened to
// list them.  Queued with the longest shortest edge first, they are taken
// shortest first, as Triangle's edge bins would take them (order.hpp, rule
// 2: with -a or -u alone or up to 26 degrees, OrderRules::sort_size_only).
void LeafRefiner::queue_size_only(Leaf& leaf) {
    if (size_only_.empty()) return;
    // Equal edges keep the order they were made in (the sort is stable).
    const auto longer = [](const SizeOnly& a, const SizeOnly& b) {
        return a.shortest_squared > b.shortest_squared;
    };
    if (size_only_.size() <= 16) {
        // An insertion makes a handful: no call, no buffer.
        for (std::size_t i = 1; i < size_only_.size(); ++i)
            for (std::size_t k = i; k > 0 && longer(size_only_[k], size_only_[k - 1]); --k)
                std::swap(size_only_[k], size_only_[k - 1]);
    } else {
        std::stable_sort(size_only_.begin(), size_only_.end(), longer);
    }
    for (const SizeOnly& e : size_only_) leaf.push_poor(e.q, e.at);
    size_only_.clear();
}

bool LeafRefiner::may_split(EdgeRef e) const {
    if (settings_.no_segment_splitting >= 2) return false;
    if (settings_.no_segment_splitting == 1) return !mesh_.neighbour(e).is_none();
    return true;
}

void LeafRefiner::count_steiner_point() {
    // With -S every point is published at once (the limit is exact on one
    // thread); otherwise in batches, so that threads do not fight over the
    // counter's cache line for a safety limit that need not be exact.
    if (settings_.steiner_limit) {
        run_.steiner_used.fetch_add(1, std::memory_order_relaxed);
        return;
    }
    if (++unpublished_steiner_ == 256) publish_steiner_points();
}

void LeafRefiner::publish_steiner_points() {
    run_.steiner_used.fetch_add(unpublished_steiner_, std::memory_order_relaxed);
    unpublished_steiner_ = 0;
}

bool LeafRefiner::budget_left() {
    if (report_.stopped != RefineReport::Stop::none) return false;
    const std::uint64_t used =
        run_.steiner_used.load(std::memory_order_relaxed) + unpublished_steiner_;
    if (settings_.steiner_limit && used >= settings_.max_steiner) {
        report_.stopped = RefineReport::Stop::steiner_limit;
        return false;
    }
    if (used >= run_.safety_limit()) {
        report_.stopped = RefineReport::Stop::safety_limit;
        report_.safety_limit = run_.safety_limit();
        return false;
    }
    return true;
}

bool LeafRefiner::refine_leaf(Leaf& leaf) {
    split_queued_subsegments(leaf);
    if (report_.stopped != RefineReport::Stop::none) return false;
    const int lowest = leaf.lowest_level();
    if (lowest < 0) return true;
    return refine_levels(leaf, lowest + static_cast<int>(settings_.granularity));
}

bool LeafRefiner::refine_levels(Leaf& leaf, int last_level, int last_size_level,
                                std::uint64_t* takes_left) {
    split_queued_subsegments(leaf);
    if (report_.stopped != RefineReport::Stop::none) return false;
    const int last = std::min(last_level, Leaf::bucket_count - 1);
    // Always the first entry of the lowest slot: a split's new triangles
    // may land in a lower slot than the one being emptied.
    for (PoorSlot at; leaf.first_slot(last, at, last_size_level);) {
        if (takes_left != nullptr) {
            if (*takes_left == 0) break;
            --*takes_left;
        }
        QueuedTriangle q;
        leaf.pop_poor(at, q);
        // The next entry's record is a cache miss more often than not
        // (queued long ago): asked for now, it arrives while q is refined.
        // (Asking for the one after it too, or for the next one's
        // neighbours, makes refinement slower: docs/performance.md.)
        if (const QueuedTriangle* next = leaf.next_in(at))
            __builtin_prefetch(&mesh_.triangle(next->id));
        const mesh::Triangle& r = mesh_.triangle(q.id);
        if (r.load_generation() != q.generation || !r.live())
            continue;  // stale (generation first: see Triangle)
        // Its neighbours are the first records the walk to the Steiner
        // point and the cavity search read: asked for while the point is
        // chosen.  (A hull edge's none names the table's last slot, which
        // no id reaches: a prefetch of it is harmless.)
        for (const mesh::EdgeRef e : r.n) __builtin_prefetch(&mesh_.triangle(e.triangle()));
        if (report_.stopped != RefineReport::Stop::none) {
            leaf.push_poor(q, at);
            return false;
        }
        refine_triangle(leaf, q, at);
        split_queued_subsegments(leaf);
    }
    return report_.stopped == RefineReport::Stop::none;
}

std::uint64_t LeafRefiner::split_queued_subsegments(Leaf& leaf) {
    const std::uint64_t splits = report_.segment_splits;
    QueuedSubsegment s;
    while (leaf.pop_subsegment(s)) {
        const mesh::Triangle& r = mesh_.triangle(s.edge.triangle());
        if (r.load_generation() != s.generation || !r.live())
            continue;  // stale: its new triangles were classified
        const bool flagged = r.is_subsegment(s.edge.edge());
        if (!flagged && !r.n[s.edge.edge()].is_none()) continue;
        if (!s.forced && !subsegment_encroached(mesh_, s.edge, quality_.encroachment_lens()))
            continue;
        if (!may_split(s.edge) || !budget_left()) continue;  // counted by the final pass
        split_subsegment(leaf, s.edge);
    }
    return report_.segment_splits - splits;
}

bool LeafRefiner::split_subsegment(Leaf& leaf, EdgeRef e) {
    const VertexId a = mesh_.origin(e), b = mesh_.destination(e);
    const Point pa = mesh_.point(a), pb = mesh_.point(b);
    const double length_squared = geometry::squared_distance(pa, pb);
    const Point p =
        geometry::point_on_segment(pa, pb, split_parameter(mesh_, e, quality_.encroachment_lens()));
    if (length_squared < run_.tiny_length_squared() || p == pa || p == pb)
        return false;  // too short
    if (!leaf.owns(p)) {
        leaf.handed_off_subsegments.push_back({e, mesh_.triangle(e.triangle()).generation, true});
        return false;
    }
    mesh::InsertResult result;
    try {
        result = mesh::split_subsegment(pool_, e, p, mesh::VertexKind::segment, buffer_);
    } catch (const SubsegmentSplitError&) {
        return false;  // degenerate surroundings: the mesh is unchanged, leave the subsegment
    }
    count_steiner_point();
    ++report_.steiner_points;
    ++report_.segment_splits;
    const Point pv = mesh_.point(result.vertex);
    if (mesh_.attributes().width() > 0)
        mesh::interpolate_on_segment(
            mesh_, result.vertex, a, b,
            ((pv.x - pa.x) * (pb.x - pa.x) + (pv.y - pa.y) * (pb.y - pa.y)) / length_squared);
    classify_created(leaf);
    return true;
}

// refine_triangle's steps.  Each either finishes with the triangle (gives
// it up, hands it off, splits subsegments instead, or requeues it) and
// returns nothing, or returns what the next step needs.

// The Steiner point of t from the placement strategy, or nothing when t is
// too small for double precision (given up) or the point belongs to another
// leaf (handed off).
std::optional<Point> LeafRefiner::choose_point(Leaf& leaf, QueuedTriangle q,
                                               const PoorTriangle& t) {
    if (t.shortest_length * t.shortest_length < run_.tiny_length_squared()) {
        give_up(q, reason_precision);
        return std::nullopt;
    }
    const Point p = run_.strategy().place(t, scratch_);
    if (settings_.checked && !admissible_point(t, p))
        throw InternalError(
            std::string("refine: placement strategy '") + run_.strategy().name() +
            "' returned a point outside the selection disk (or, where that is empty, the "
            "circumdisk)");
    if (!finite(p)) {
        give_up(q, reason_precision);
        return std::nullopt;
    }
    if (!leaf.owns(p)) {
        leaf.handed_off_triangles.push_back(q);
        return std::nullopt;
    }
    return p;
}

bool LeafRefiner::alive(QueuedTriangle q) const {
    const mesh::Triangle& r = mesh_.triangle(q.id);
    return r.load_generation() == q.generation && r.live();
}

// The subsegments queued in t's way split, then t goes back to the tail of
// its bin if it survived (Triangle's order).  When one of them belongs to
// another leaf (its split point lies outside), t goes with it instead of
// back into this leaf, which would take it again at once (parallel layer;
// never without a hook).  When none could be split (too short for double
// precision, or a degenerate neighbourhood) and no limit stopped
// refinement, nothing changed and nothing will: t is given up rather than
// queued again.
void LeafRefiner::split_queued_then_requeue(Leaf& leaf, QueuedTriangle q, PoorSlot at) {
    const std::size_t handed = leaf.handed_off_subsegments.size();
    const std::uint64_t splits = split_queued_subsegments(leaf);
    if (!alive(q)) return;
    if (leaf.handed_off_subsegments.size() != handed)
        leaf.handed_off_triangles.push_back(q);
    else if (splits == 0 && report_.stopped == RefineReport::Stop::none)
        give_up(q, reason_precision);
    else
        leaf.push_poor(q, at);  // (a limit stopped it: counted as left by the budget)
}

// Subsegment e is split instead of t (p encroaches it or lies on it); t is
// given up when -Y/-YY forbid that.
void LeafRefiner::split_instead(Leaf& leaf, QueuedTriangle q, PoorSlot at, EdgeRef e) {
    if (!may_split(e)) {
        give_up(q, reason_no_split);
        return;
    }
    leaf.push_subsegment({e, mesh_.triangle(e.triangle()).generation, true});
    split_queued_then_requeue(leaf, q, at);
}

// Where p lies, seen from t without crossing subsegments, or nothing when
// p is lost, on a vertex (given up), beyond a subsegment or on one or on
// the hull (split instead).
std::optional<mesh::LocateResult> LeafRefiner::locate_point(Leaf& leaf, QueuedTriangle q,
                                                            PoorSlot at, const Point& p) {
    const Walk walk = walk_to(mesh_, q.id, p, buffer_.random_state);
    if (walk.kind == Walk::Kind::lost || walk.where.where == mesh::Location::on_vertex) {
        give_up(q, reason_precision);
        return std::nullopt;
    }
    if (walk.kind == Walk::Kind::blocked) {
        split_instead(leaf, q, at, walk.blocking);
        return std::nullopt;
    }
    const mesh::LocateResult where = walk.where;
    if (where.where == mesh::Location::on_edge) {
        const mesh::Triangle& r = mesh_.triangle(where.triangle);
        if (r.is_subsegment(where.index) || r.n[where.index].is_none()) {
            split_instead(leaf, q, at, EdgeRef(where.triangle, where.index));
            return std::nullopt;
        }
    }
    return where;
}

// The cavity of p, found once: searched for the subsegments on its boundary
// that p encroaches (into blocking_) and for its nearest vertex; left marked
// for commit_cavity.  Returns the squared distance to that vertex.
double LeafRefiner::survey_cavity(const Point& p, const mesh::LocateResult& where) {
    mesh::find_cavity(mesh_, p, where.triangle, buffer_);
    blocking_.clear();
    double nearest = std::numeric_limits<double>::infinity();
    for (const TriangleId id : buffer_.killed) {
        const mesh::Triangle& r = mesh_.triangle(id);
        for (int k = 0; k < 3; ++k) {
            nearest = std::min(nearest, geometry::squared_distance(mesh_.point(r.v[k]), p));
            if (r.is_subsegment(k) &&
                encroaches(mesh_.point(r.v[mesh::next3(k)]), mesh_.point(r.v[mesh::prev3(k)]), p,
                           quality_.encroachment_lens()))
                blocking_.push_back(EdgeRef(id, k));
        }
    }
    return nearest;
}

// Fills the surveyed cavity with p (commit_cavity, without a second
// search).
void LeafRefiner::insert_steiner_point(Leaf& leaf, const Point& p,
                                       const mesh::LocateResult& where) {
    const mesh::Triangle& host = mesh_.triangle(where.triangle);
    const VertexId host_corners[3] = {host.v[0], host.v[1], host.v[2]};

    const VertexId v = pool_.new_vertex(p, mesh::VertexKind::free);
    const mesh::InsertResult result = mesh::commit_cavity(pool_, v, where, buffer_);
    if (result.status != mesh::InsertStatus::inserted)
        throw InternalError("refine: a located Steiner point was refused by insertion (vertex " +
                            std::to_string(mesh::index(v)) + ")");
    count_steiner_point();
    ++report_.steiner_points;
    mesh::interpolate_in_triangle(mesh_, v, host_corners);
    classify_created(leaf);
}

void LeafRefiner::refine_triangle(Leaf& leaf, QueuedTriangle q, PoorSlot at) {
    const PoorTriangle t = describe_poor_triangle(mesh_, q.id, quality_);
    // Far below the starting mesh's shortest edge, a triangle poor by its
    // angle means refinement is cascading (convergence.hpp): stop, t kept.
    const double shortest_squared = t.shortest_length * t.shortest_length;
    if (shortest_squared < run_.cascade_floor_squared() &&
        t.circle.radius_squared > t.rho_bar * t.rho_bar * shortest_squared) {
        report_.stopped = RefineReport::Stop::not_converging;
        leaf.push_poor(q, at);
        return;
    }
    const std::optional<Point> p = choose_point(leaf, q, t);
    if (!p) return;
    const std::optional<mesh::LocateResult> where = locate_point(leaf, q, at, *p);
    if (!where) return;

    const double nearest = survey_cavity(*p, *where);
    const bool too_close = nearest <= t.circle.radius_squared * (tiny_fraction * tiny_fraction);
    const bool insert = blocking_.empty() && !too_close && budget_left();
    if (!insert) mesh::abandon_cavity(mesh_, buffer_);

    if (!blocking_.empty()) {  // p encroaches subsegments: split them instead
        bool any = false;
        for (EdgeRef e : blocking_)
            if (may_split(e)) {
                leaf.push_subsegment({e, mesh_.triangle(e.triangle()).generation, true});
                any = true;
            }
        if (!any) {
            give_up(q, reason_no_split);
            return;
        }
        split_queued_then_requeue(leaf, q, at);
        return;
    }
    if (too_close) {
        give_up(q, reason_precision);
        return;
    }
    if (!insert) {  // the budget ran out
        leaf.push_poor(q, at);
        return;
    }
    insert_steiner_point(leaf, *p, *where);
    if (alive(q)) leaf.push_poor(q, at);  // p's cavity missed t (only through rounding): again
}

namespace {

// The reason of the newest give-up of triangle (id, generation) in
// `given_up` (sorted by slot, each slot's entries in the order given), or
// 0xFF when it was never given up.
std::uint8_t give_up_reason(std::span<const LeafRefiner::GivenUp> given_up, TriangleId id,
                            std::uint32_t generation) {
    auto it =
        std::upper_bound(given_up.begin(), given_up.end(), mesh::index(id),
                         [](std::uint32_t x, const auto& g) { return x < mesh::index(g.id); });
    while (it != given_up.begin()) {
        --it;
        if (it->id != id) break;
        if (it->generation == generation) return it->reason;
    }
    return 0xFF;
}

// The final pass over triangle slots [first, end).  FULL assesses every
// triangle again, and so also finds what was left poor for no reason
// (left_other) and what a limit left (left_budget); otherwise it reads the
// small-angle mark classification left on each triangle, and the give-ups
// are counted apart (count_given_up).
void count_left_in(const mesh::Mesh& mesh, const RefineRun& run,
                   std::span<const LeafRefiner::GivenUp> given_up, std::uint32_t first,
                   std::uint32_t end, bool full, RefineReport& report) {
    const QualityTest& quality = run.quality();
    mesh::for_each_triangle_in(mesh, first, end, [&](TriangleId id, const mesh::Triangle& t) {
        // Encroached subsegments, each seen from its triangle of lower id
        // (as mesh::for_each_edge does).
        for (int k = 0; k < 3; ++k) {
            if (!t.is_subsegment(k)) continue;
            const EdgeRef across = t.n[k];
            if (!across.is_none() && mesh::index(across.triangle()) < mesh::index(id)) continue;
            if (subsegment_encroached(mesh, EdgeRef(id, k), quality.encroachment_lens()))
                ++report.encroached_left;
        }
        if (!full) {
            report.left_small_input_angle += t.small_angle_protected() ? 1 : 0;
            return;
        }
        const TriangleMeasures m =
            QualityTest::measure(mesh.point(t.v[0]), mesh.point(t.v[1]), mesh.point(t.v[2]));
        bool protected_angle = false;
        if (quality.assess(mesh, id, m, &protected_angle) == Poorness::good) {
            report.left_small_input_angle += protected_angle ? 1 : 0;
            return;
        }
        const std::uint8_t reason = give_up_reason(given_up, id, t.generation);
        if (reason == reason_no_split || reason == reason_precision)
            report.given_up_triangles.push_back(id);
        if (reason == reason_no_split)
            ++report.left_no_split;
        else if (reason == reason_precision)
            ++report.left_precision;
        else if (report.stopped != RefineReport::Stop::none)
            ++report.left_budget;
        else
            ++report.left_other;
    });
}

// Outside full counting: the give-ups whose triangles are still alive (a
// triangle given up is poor, and stays so while it lives).
void count_given_up(const mesh::Mesh& mesh, std::span<const LeafRefiner::GivenUp> given_up,
                    RefineReport& report) {
    for (std::size_t j = 0; j < given_up.size(); ++j) {
        if (j + 1 < given_up.size() && given_up[j + 1].id == given_up[j].id)
            continue;  // once per slot
        const mesh::Triangle& t = mesh.triangle(given_up[j].id);
        if (!t.live()) continue;
        const std::uint8_t reason =
            give_up_reason(given_up.first(j + 1), given_up[j].id, t.generation);
        if (reason == reason_no_split || reason == reason_precision)
            report.given_up_triangles.push_back(given_up[j].id);
        if (reason == reason_no_split)
            ++report.left_no_split;
        else if (reason == reason_precision)
            ++report.left_precision;
    }
}

}  // namespace

void count_left(const mesh::Mesh& mesh, const RefineRun& run,
                std::vector<LeafRefiner::GivenUp> given_up, RefineReport& report,
                unsigned threads) {
    std::stable_sort(given_up.begin(), given_up.end(), [](const auto& x, const auto& y) {
        return mesh::index(x.id) < mesh::index(y.id);
    });
    // Full counting in checked mode, and when a limit stopped the run.
    const bool full = run.settings().checked || report.stopped != RefineReport::Stop::none;
    // A part of the count per triangle chunk, joined in chunk order.
    const std::vector<std::uint32_t> chunks = mesh::triangle_chunks(mesh);
    const std::uint32_t end = mesh.triangle_end();
    std::vector<RefineReport> parts(chunks.size());
    for (RefineReport& p : parts) p.stopped = report.stopped;
    mesh::run_pieces(threads, chunks.size(), [&](std::size_t i) {
        const auto ids = mesh::chunk_ids(chunks[i], mesh::Mesh::triangle_chunk_bits, end);
        count_left_in(mesh, run, given_up, ids.first, ids.last, full, parts[i]);
    });
    for (const RefineReport& p : parts) {
        report.left_small_input_angle += p.left_small_input_angle;
        report.left_no_split += p.left_no_split;
        report.left_precision += p.left_precision;
        report.left_budget += p.left_budget;
        report.left_other += p.left_other;
        report.encroached_left += p.encroached_left;
        report.given_up_triangles.insert(report.given_up_triangles.end(),
                                         p.given_up_triangles.begin(), p.given_up_triangles.end());
    }
    if (!full) count_given_up(mesh, given_up, report);
}

// ---- the sequential driver ---------------------------------------------------

void refine_mesh(mesh::Mesh& mesh, const RefineSettings& settings, RefineReport& report) {
    RefineRun run(mesh, settings);

    // One flat leaf: Triangle's order over the whole mesh (leaf.hpp).
    Leaf leaf = Leaf::flat();

    {
        mesh::Pool pool(mesh);
        LeafRefiner refiner(run, pool, report);
        refiner.classify_all(leaf);
        while (!leaf.idle())
            if (!refiner.refine_leaf(leaf)) break;

        count_left(mesh, run, refiner.given_up(), report);
    }
}

}  // namespace gpdr::refine
