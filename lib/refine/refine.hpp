#pragma once
// Guaranteed-quality Delaunay refinement (Ruppert 1995, Shewchuk 1997/2002,
// with Triangle's shortest-edge-first order and the GPDR paper's selection
// disks).
//
// The loop of one leaf (refine_leaf, the paper's Fig. 4):
//   0. Split every subsegment in the queue: encroached ones (a vertex
//      strictly inside the diametral lens, or circle with -D; without an
//      angle bound no vertex encroaches, segments.hpp), re-tested when
//      popped, and "forced" ones that a rejected Steiner point encroached
//      or that stood between a poor triangle and its Steiner point.  Split
//      points are midpoints or concentric-shell points (segments.hpp).
//      Every split's new triangles are classified, which queues any
//      subsegment the new vertex encroaches, so this runs until no
//      subsegment is encroached.
//   1. While the leaf's lowest slot (leaf.hpp: the bin of the shortest
//      edges; a quadtree leaf first by σ level, up to i_min + granularity)
//      holds a poor triangle: take the first, t, and p = f(t) from the
//      placement strategy (the circumcentre when the selection disk is
//      empty);
//        - walk from t to p without crossing a subsegment; a subsegment (or
//          hull edge) in the way is split instead (p lies outside the part
//          of the domain t sees, or on the subsegment), and t goes back to
//          the tail of its bin if it survives;
//        - search p's cavity; if p encroaches a subsegment on its boundary
//          (Triangle's rule), p is not inserted: those subsegments are
//          split instead (step 0), and t goes back to the tail of its bin
//          if it survives;
//        - otherwise p is inserted (Bowyer-Watson) and the new triangles
//          are classified: poor ones queued in their slots, encroached
//          subsegments queued.
//      Step 0 runs after every poor triangle.
//
// Limits (Triangle's behaviour): -Y leaves boundary subsegments (one
// triangle only) unsplit, -YY every subsegment; -S n stops after n Steiner
// points.  A subsegment that may not be split is left, and a Steiner point
// that would split it is not inserted: the triangle stays as it is and is
// counted in the report.
//
// Termination.  Below about 20.7° (rho_bar >= sqrt 2) the selection disk
// theory guarantees it, except near small input angles, where the
// small-angle rule (segments.hpp) leaves the forced triangles alone; in
// practice, in this order, it ends up to 34° and beyond.  Whatever the
// bound, refinement always ends: every step inserts a vertex or splits a
// subsegment, or gives the triangle up.  A triangle whose shortest edge is
// below 2^-40 of the domain's diameter, whose Steiner point would land on
// (or within 2^-40 r of) an existing vertex, or whose Steiner point is
// rejected for subsegments none of which can be split (too short for
// double precision, or a degenerate neighbourhood), is left and counted as
// "precision" instead of being queued again; and a safety budget
// of Steiner points derived from the input (RefineSettings::safety_limit)
// stops the run with a valid mesh.  Either way the result is a valid
// constrained Delaunay mesh and the report says what is left poor and why.
//
// Threads: a LeafRefiner belongs to one thread (it owns the Pool, the
// InsertBuffer and all scratch); the settings, QualityTest and strategy are
// shared read-only.  No globals: several threads may each run a LeafRefiner
// on different leaves of the same mesh (the parallel layer guarantees that
// their cavities' neighbourhoods are disjoint).  The subsegment side table is shared:
// it is split into shards, each with its own lock (mesh/subsegments.hpp).

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <gpdr/options.hpp>

#include "mesh/insert.hpp"
#include "mesh/mesh.hpp"
#include "mesh/pool.hpp"
#include "refine/leaf.hpp"
#include "refine/order.hpp"
#include "refine/placement.hpp"
#include "refine/quality.hpp"

namespace gpdr::refine {

struct RefineSettings {
    QualityCriteria criteria;
    // The placement: `strategy` if set (a user's), else the built-in `placement`.
    Placement placement = Placement::off_centre;
    const PlacementStrategy* strategy = nullptr;
    int no_segment_splitting = 0;   // -Y: 1 (boundary subsegments), -YY: 2 (all)
    bool steiner_limit = false;     // -S given
    std::uint64_t max_steiner = 0;  // -S<n>: what is left of the budget for this stage
    // Optional: where the run counts the Steiner points its threads add (in
    // batches), for a caller that watches the count from another thread
    // while refinement runs (the progress line).  It must start at 0.
    std::atomic<std::uint64_t>* steiner_counter = nullptr;
    // Safety net against non-termination (angle bounds above ~34°): at most
    // this many Steiner points; 0 derives it from the input (see refine.cpp).
    std::uint64_t safety_limit = 0;
    // Verify every strategy's point is inside the selection disk (throws
    // gpdr::Error naming the strategy if not).
#ifdef NDEBUG
    bool checked = false;
#else
    bool checked = true;
#endif
    // Input segment ends by SubsegmentInfo::segment, 2 per segment (optional;
    // speeds up the small-angle rule, see segments.hpp).
    std::span<const mesh::VertexId> segment_ends;
    // Levels refined per refine_leaf call beyond i_min (Fig. 4's g; a flat
    // leaf's order does not depend on it).
    unsigned granularity = default_granularity;
    // Stop a run that cascades (convergence.hpp): api::refine_stage's runs
    // above 34 degrees.
    bool watch_convergence = false;
};

struct RefineReport {
    // not_converging: above 34 degrees, a cascade of ever smaller poor
    // triangles (convergence.hpp).
    enum class Stop : std::uint8_t { none, steiner_limit, safety_limit, not_converging };

    std::uint64_t steiner_points = 0;  // all vertices added
    std::uint64_t segment_splits = 0;  // of those, on subsegments
    std::uint64_t triangles_created = 0;
    Stop stopped = Stop::none;
    std::uint64_t safety_limit = 0;  // the limit that stopped it, when stopped == safety_limit

    // Poor triangles left at the end (refine_mesh counts them in a final
    // pass), by reason.  A triangle given up for several reasons is counted
    // under the last.
    std::uint64_t left_small_input_angle = 0;  // the small-angle rule protects it
    std::uint64_t left_no_split = 0;           // its point would split a subsegment -Y/-YY protects
    std::uint64_t left_precision = 0;          // too small for double precision, or no progress
    std::uint64_t left_budget = 0;  // still queued when -S or the safety limit stopped it
    std::uint64_t left_other = 0;   // poor for no recorded reason (a bug if non-zero)
    // Encroached subsegments left unsplit (-Y/-YY, budget, too short).
    std::uint64_t encroached_left = 0;
    // The triangles counted in left_no_split and left_precision, by id.
    std::vector<mesh::TriangleId> given_up_triangles;

    // Set by whoever tries several bounds (api::refine_stage above 34
    // degrees) when the asked one was out of reach: the bound of the mesh
    // handed back, and its smallest angle apart from small input angles.
    // (stopped is then not_converging.)
    double angle_refined = 0;
    double angle_reached = 0;
    // Each try of such a run, in order (-V lists them).
    struct Try {
        double angle = 0;
        const char* placement = "";
        Stop stopped = Stop::none;
        std::uint64_t steiner_points = 0;
        std::uint64_t left_precision = 0;
        double seconds = 0;
    };
    std::vector<Try> tries;
};

// The shared, read-only part of a run (one per refinement, all threads).
class RefineRun {
public:
    // `mesh` is read to derive the safety limit and the precision threshold.
    RefineRun(const mesh::Mesh& mesh, const RefineSettings& settings);

    const RefineSettings& settings() const { return settings_; }
    const QualityTest& quality() const { return quality_; }
    const OrderRules& order() const { return order_; }
    const PlacementStrategy& strategy() const { return *strategy_; }
    double tiny_length_squared() const { return tiny_length_squared_; }
    std::uint64_t safety_limit() const { return safety_limit_; }
    // Below this squared length a split of a triangle poor by its angle
    // stops the run as not converging (convergence.hpp; 0: not watched).
    double cascade_floor_squared() const { return cascade_floor_squared_; }

    // Steiner points added by all threads (for -S and the safety limit):
    // settings().steiner_counter when given, else a counter of the run's.
    std::atomic<std::uint64_t>& steiner_used;

private:
    std::atomic<std::uint64_t> own_steiner_used_{0};
    RefineSettings settings_;
    QualityTest quality_;
    OrderRules order_;
    const PlacementStrategy* strategy_;
    double tiny_length_squared_ = 0;
    std::uint64_t safety_limit_ = 0;
    double cascade_floor_squared_ = 0;
};

// Told of every change refinement makes to the mesh (the parallel layer
// keeps its quadtree counters with it).  For each insertion or split:
// first the tagged triangles that died or that a flip changed, as they were
// (mesh::InsertBuffer::tagged_gone; their slots may already be reused by the
// triangles that follow), then each new triangle, or one a flip changed in
// place, with its slot's generation and the circumcircle classification
// computes for it anyway.
class MeshObserver {
public:
    virtual ~MeshObserver() = default;
    virtual void tagged_triangles_gone(std::span<const mesh::TaggedTriangle> gone) = 0;
    virtual void triangle_created(mesh::TriangleId t, std::uint32_t generation,
                                  const geometry::Circle& circumcircle) = 0;
};

// One thread's refiner: owns the pool, insertion buffer and scratch.
class LeafRefiner {
public:
    LeafRefiner(RefineRun& run, mesh::Pool& pool, RefineReport& report);
    // Counts its last Steiner points in the run's (the run outlives it).
    ~LeafRefiner() { publish_steiner_points(); }
    LeafRefiner(const LeafRefiner&) = delete;
    LeafRefiner& operator=(const LeafRefiner&) = delete;

    // Assesses live triangle t and queues it in `leaf` if poor; queues its
    // encroached subsegments.
    void classify(Leaf& leaf, mesh::TriangleId t);
    void classify(Leaf& leaf, mesh::TriangleId t, const TriangleMeasures& m);
    // classify() for every live triangle of the mesh (a fresh leaf that covers
    // the whole mesh).
    void classify_all(Leaf& leaf);
    // Fig. 4 of the paper on `leaf`: step 0, then levels i_min .. i_min + g.
    // Returns false when a limit stopped refinement (report().stopped).
    bool refine_leaf(Leaf& leaf);
    // The same for levels i_min .. last_level, size bins only up to
    // last_size_level (none when last_level < i_min, but step 0 always
    // runs).  With takes_left, at most that many entries (stale ones
    // included), counted off it.
    bool refine_levels(Leaf& leaf, int last_level, int last_size_level = Leaf::bucket_count,
                       std::uint64_t* takes_left = nullptr);
    // Splits queued subsegments until none is left (step 0); returns how
    // many it split.
    std::uint64_t split_queued_subsegments(Leaf& leaf);

    // The triangles given up (id, generation, reason), for the final count.
    struct GivenUp {
        mesh::TriangleId id;
        std::uint32_t generation;
        std::uint8_t reason;  // 0 no_split, 1 precision
    };
    const std::vector<GivenUp>& given_up() const { return given_up_; }
    // Adds this refiner's Steiner points not yet counted in
    // RefineRun::steiner_used (they are published in batches).
    void publish_steiner_points();
    // Optional (nullptr: none); not owned.
    void set_observer(MeshObserver* observer) { observer_ = observer; }
    const QualityTest& quality() const { return quality_; }

private:
    // Splits q's triangle, taken from slot `at` (where it goes back if its
    // split is put off).
    void refine_triangle(Leaf& leaf, QueuedTriangle q, PoorSlot at);
    // Its steps (refine.cpp).
    std::optional<geometry::Point> choose_point(Leaf& leaf, QueuedTriangle q,
                                                const PoorTriangle& t);
    std::optional<mesh::LocateResult> locate_point(Leaf& leaf, QueuedTriangle q, PoorSlot at,
                                                   const geometry::Point& p);
    double survey_cavity(const geometry::Point& p, const mesh::LocateResult& where);
    void insert_steiner_point(Leaf& leaf, const geometry::Point& p,
                              const mesh::LocateResult& where);
    void split_instead(Leaf& leaf, QueuedTriangle q, PoorSlot at, mesh::EdgeRef e);
    void split_queued_then_requeue(Leaf& leaf, QueuedTriangle q, PoorSlot at);
    bool alive(QueuedTriangle q) const;
    PoorKind kind(const TriangleMeasures& m) const { return poor_kind(run_.order(), quality_, m); }
    bool split_subsegment(Leaf& leaf, mesh::EdgeRef e);
    bool may_split(mesh::EdgeRef e) const;
    bool budget_left();
    void count_steiner_point();
    // Classifies the triangles of buffer_.created; the ones poor only by
    // size that go to a size bin are queued together at the end, the one
    // with the shortest edge last (queue_size_only).
    void classify_created(Leaf& leaf);
    void queue_size_only(Leaf& leaf);
    void give_up(QueuedTriangle q, std::uint8_t reason) {
        given_up_.push_back({q.id, q.generation, reason});
    }

    RefineRun& run_;
    const RefineSettings& settings_;
    const QualityTest& quality_;
    mesh::Pool& pool_;
    mesh::Mesh& mesh_;
    RefineReport& report_;
    mesh::InsertBuffer buffer_;
    PlacementScratch scratch_;
    std::vector<mesh::EdgeRef> blocking_;
    std::vector<GivenUp> given_up_;
    MeshObserver* observer_ = nullptr;
    std::uint64_t unpublished_steiner_ = 0;
    // Size-bin entries held back while classify_created runs.
    struct SizeOnly {
        QueuedTriangle q;
        PoorSlot at;
        double shortest_squared;
    };
    std::vector<SizeOnly> size_only_;
    bool holding_size_only_ = false;
};

// The final pass of a run: counts the poor triangles left in `mesh` by
// reason (the give-ups of all threads' refiners) and the encroached
// subsegments left, into `report`, on `threads` threads, each over a slice
// of the triangle slots.  In checked mode, and when a limit stopped the
// run, it assesses every triangle again (and so also finds triangles left
// poor for no reason: left_other); otherwise it reads the small-angle mark
// classification left on each triangle and counts the give-ups whose
// triangles still live, about a tenth of a one-thread refinement less.
void count_left(const mesh::Mesh& mesh, const RefineRun& run,
                std::vector<LeafRefiner::GivenUp> given_up, RefineReport& report,
                unsigned threads = 1);

// The sequential refiner: one leaf that never splits, on the calling thread.
// Requires a constrained Delaunay mesh without ghosts whose boundary edges
// are subsegments (the CDT's output; a point set's Delaunay triangulation
// with its hull edges flagged).  Throws gpdr::Error if a placement strategy
// leaves the selection disk in checked mode, or the mesh is broken.
void refine_mesh(mesh::Mesh& mesh, const RefineSettings& settings, RefineReport& report);

}  // namespace gpdr::refine
