#pragma once
// Leaf: the unit of refinement work (GPDR paper §3, Fig. 4).  A leaf of the
// quadtree of side ℓ owns
//   - PoorTriangles_i: poor triangles bucketed by σ = ⌊log2(ℓ / r)⌋ (r the
//     circumradius), so the refiner takes the largest triangles first
//     (smallest σ; Miller's order);
//   - the queue of subsegments to split (encroached, or in the way of a
//     Steiner point).
// Entries carry the triangle's generation; an entry whose triangle died
// since (or whose slot holds another triangle now) is stale and skipped when
// popped: nothing is ever searched for and removed.
//
// The sequential refiner is one leaf that never splits (refine.hpp).  The
// parallel layer owns many leaves and runs refine_leaf on them from worker
// threads; a leaf is touched by one thread at a time.  Its owned box says
// whether a Steiner point or split point belongs to this leaf; what does
// not is handed off (handed_off_*) for the scheduler to route.  With no
// box, everything belongs to the leaf.
//
// Bucket σ is clamped to [0, bucket_count - 1]: σ < 0 (r > ℓ) never happens
// under the paper's relation (9) and σ > 127 means r < ℓ 2^-127; clamping
// only merges priorities at the extremes.
//
// Within one σ level the order is free as far as Miller's bound goes, and it
// matters a great deal for the size of the mesh above 25 degrees: the worst
// shaped triangles first (Triangle's order) gives meshes within a few
// percent of Triangle's up to 30 degrees, where plain last-in-first-out gave
// up to four times as many triangles at 33 degrees.  So each level holds
// rank_count stacks by shape rank (QualityTest::shape_rank, 0 = worst).
// Within a stack the newest goes first: it was just created, so it is still
// in the cache (first-in-first-out was 1.6 times slower, for 1% fewer
// triangles at 20 degrees).  Levels are allocated on first use, and the
// table of them grows only as far as the deepest level used (a quadtree leaf
// sees a handful of levels; -g1 makes hundreds of thousands of leaves).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/point.hpp"
#include "mesh/ids.hpp"

namespace gpdr::refine {

struct QueuedTriangle {
    mesh::TriangleId id;
    std::uint32_t generation;
    // Where in the leaf that queued it the point deciding its leaf lies
    // (Leaf::where), so that a split can hand it to a child without looking
    // at the mesh; 0: unknown.
    std::uint32_t where = 0;
};

// The points a leaf owns (parallel layer): the half-open box
// [x_lo, x_hi) x [y_lo, y_hi), whose sides may be infinite.  (A plain box,
// not a callback: the test is made for every poor triangle a worker finds.)
struct OwnedBox {
    double x_lo, y_lo, x_hi, y_hi;
    bool contains(const geometry::Point& p) const {
        return p.x >= x_lo && p.x < x_hi && p.y >= y_lo && p.y < y_hi;
    }
};

struct QueuedSubsegment {
    mesh::EdgeRef edge;        // an edge of a live triangle when queued
    std::uint32_t generation;  // of edge.triangle() when queued
    bool forced;               // split even if no apex encroaches (a rejected point did)
};

class Leaf {
public:
    static constexpr int bucket_count = 128;
    static constexpr int rank_count = 64;

    explicit Leaf(double side = 1.0) : side_squared_(side * side), side_(side) {}

    double side() const { return side_; }
    // σ = ⌊log2(ℓ / r)⌋ from r², clamped (see above).
    int sigma(double radius_squared) const {
        const double ratio = side_squared_ / radius_squared;
        if (!(ratio >= 1.0)) return 0;         // r >= ℓ, or not a number
        const int s = std::ilogb(ratio) >> 1;  // ⌊log2(ℓ²/r²)⌋ / 2, floored
        return s < bucket_count ? s : bucket_count - 1;
    }

    // The leaf's square's lower left corner (parallel layer): from then on
    // `where` locates points in it.
    void set_corner(const geometry::Point& corner) {
        corner_ = corner;
        cells_per_side_ = double(1u << where_levels) / side_;
        has_corner_ = true;
    }
    // The quadrants that hold p on the way down from this leaf's square, for
    // where_levels levels: the cell of p in a grid of 2^where_levels cells a
    // side, its column in bits 31-18 and its row in bits 17-4 (the first
    // split's half is the top bit of each), and in bits 3-0 how many levels
    // are left (0: unknown, as for a leaf without a corner).  A point
    // outside the square counts as in its nearest cell.  (Column and row
    // side by side rather than interleaved: `where` is computed for every
    // poor triangle a worker queues, and read only for those a split finds.)
    static constexpr std::uint32_t where_levels = 14;
    std::uint32_t where(const geometry::Point& p) const {
        if (!has_corner_) return 0;
        constexpr double last = double((1u << where_levels) - 1);
        const auto cell = [&](double f) {
            // std::max(0.0, NaN) is 0.0: a point that is not a number lands in cell 0.
            return static_cast<std::uint32_t>(
                static_cast<std::int64_t>(std::min(std::max(0.0, f), last)));
        };
        return (cell((p.x - corner_.x) * cells_per_side_) << column_shift) |
               (cell((p.y - corner_.y) * cells_per_side_) << row_shift) | where_levels;
    }
    // The first quadrant of `where`, and `where` as seen from that child.
    static int first_quadrant(std::uint32_t where) {
        return static_cast<int>((where >> 31) |
                                (((where >> (row_shift + where_levels - 1)) & 1u) << 1));
    }
    static std::uint32_t in_child(std::uint32_t where) {
        constexpr std::uint32_t field = (1u << where_levels) - 1;
        const std::uint32_t column = ((where >> column_shift) << 1) & field;
        const std::uint32_t row = ((where >> row_shift) << 1) & field;
        return (column << column_shift) | (row << row_shift) | ((where & 15u) - 1);
    }
    // Whether no level is left in `where` (or it was never known).
    static bool path_used_up(std::uint32_t where) { return (where & 15u) == 0; }

    void set_owned_box(const OwnedBox& box) {
        box_ = box;
        has_box_ = true;
    }
    bool owns(const geometry::Point& p) const { return !has_box_ || box_.contains(p); }

    // ---- poor triangles ------------------------------------------------------
    // Queues q at σ level `level` with shape rank `rank` (0 = worst shape).
    void push_poor(QueuedTriangle q, int level, int rank = 0) {
        stack(level, rank).push_back(q);
        note_pushed(level, rank, 1);
    }
    // The lowest non-empty level, or -1.  (Stale entries count as entries.)
    int lowest_level() {
        const int used = static_cast<int>(levels_.size());
        while (lowest_ < used && (!levels_[lowest_] || levels_[lowest_]->entries == 0)) ++lowest_;
        if (lowest_ < used) return lowest_;
        lowest_ = bucket_count;
        return -1;
    }
    // Takes from level j the newest entry of the worst shape rank (stored in
    // *rank when asked).
    bool pop_poor(int j, QueuedTriangle& q, int* rank = nullptr) {
        if (j < 0 || static_cast<std::size_t>(j) >= levels_.size()) return false;
        Level* l = levels_[static_cast<std::size_t>(j)].get();
        if (!l || l->entries == 0) return false;
        while (l->ranks[l->lowest_rank].empty()) ++l->lowest_rank;
        if (rank != nullptr) *rank = l->lowest_rank;
        std::vector<QueuedTriangle>& stack = l->ranks[l->lowest_rank];
        q = stack.back();
        stack.pop_back();
        if (--l->entries == 0) l->lowest_rank = rank_count;
        --poor_entries_;
        return true;
    }
    std::size_t poor_entries() const { return poor_entries_; }

    // A split (parallel layer): moves every poor triangle to the child its
    // `where` names, at the σ level one down (the sides halve; σ is clamped
    // at both ends) with the same shape rank, and empties this leaf's
    // levels.  An entry whose path is used up goes to used_up(q) instead,
    // to be placed afresh.  Each stack is copied straight onto the
    // children's, newest first, so that they come out as popping this one
    // and pushing each entry would leave them (the parallel refiner's order
    // before: copying oldest first made the pipe's mesh 0.5% larger).
    // (Popping and pushing entry by entry took about 15 ns an entry, 120 ms
    // of the graded pipe's -j2 run, whose splits move 7.8 million;
    // cachegrind at c = 1e-3: about 50 million fewer instructions.  Reserving
    // each child's share first raised the pipe's peak by 25 MiB.)
    template <class UsedUp>
    void move_poor_to_children(Leaf* const children[4], UsedUp&& used_up) {
        std::vector<std::unique_ptr<Level>> levels;
        levels.swap(levels_);
        lowest_ = bucket_count;
        poor_entries_ = 0;
        for (std::size_t j = 0; j < levels.size(); ++j) {
            Level* l = levels[j].get();
            if (!l || l->entries == 0) continue;
            const int jj = static_cast<int>(j);
            const int child_level = jj == 0 || jj == bucket_count - 1 ? jj : jj - 1;
            for (int r = l->lowest_rank; r < rank_count; ++r) {
                const std::vector<QueuedTriangle>& stack = l->ranks[r];
                if (stack.empty()) continue;
                std::vector<QueuedTriangle>* into[4] = {nullptr, nullptr, nullptr, nullptr};
                std::size_t moved[4] = {0, 0, 0, 0};
                for (auto it = stack.rbegin(); it != stack.rend(); ++it) {
                    QueuedTriangle q = *it;
                    if (path_used_up(q.where)) {
                        used_up(q);
                        continue;
                    }
                    const int c = first_quadrant(q.where);
                    q.where = in_child(q.where);
                    if (into[c] == nullptr) into[c] = &children[c]->stack(child_level, r);
                    into[c]->push_back(q);
                    ++moved[c];
                }
                for (int c = 0; c < 4; ++c)
                    if (moved[c] != 0) children[c]->note_pushed(child_level, r, moved[c]);
            }
        }
    }

    // ---- subsegments -----------------------------------------------------------
    void push_subsegment(QueuedSubsegment q) { subsegments_.push_back(q); }
    bool pop_subsegment(QueuedSubsegment& q) {
        if (subsegments_.empty()) return false;
        q = subsegments_.back();
        subsegments_.pop_back();
        return true;
    }
    std::size_t subsegment_entries() const { return subsegments_.size(); }

    bool idle() const { return poor_entries_ == 0 && subsegments_.empty(); }

    // Frees the queues' storage (a leaf that split and handed its work to
    // its children keeps its node, but never queues anything again).  Any
    // entries left are dropped.
    void release() {
        std::vector<std::unique_ptr<Level>>().swap(levels_);
        lowest_ = bucket_count;
        poor_entries_ = 0;
        std::vector<QueuedSubsegment>().swap(subsegments_);
        std::vector<QueuedTriangle>().swap(handed_off_triangles);
        std::vector<QueuedSubsegment>().swap(handed_off_subsegments);
    }

    // Work that belongs to other leaves (parallel layer); always empty for a
    // leaf without an `owns` hook.
    std::vector<QueuedTriangle> handed_off_triangles;
    std::vector<QueuedSubsegment> handed_off_subsegments;

private:
    double side_squared_;
    double side_;
    static constexpr int row_shift = 4, column_shift = row_shift + where_levels;
    geometry::Point corner_{};
    double cells_per_side_ = 0;  // 2^where_levels / ℓ
    bool has_corner_ = false;
    struct Level {
        std::array<std::vector<QueuedTriangle>, rank_count> ranks;
        int lowest_rank = rank_count;
        std::size_t entries = 0;
    };
    // Level `level`'s stack for `rank`, made if missing; entries pushed
    // straight onto it are then counted by note_pushed.
    std::vector<QueuedTriangle>& stack(int level, int rank) {
        if (static_cast<std::size_t>(level) >= levels_.size())
            levels_.resize(static_cast<std::size_t>(level) + 1);
        auto& l = levels_[static_cast<std::size_t>(level)];
        if (!l) l = std::make_unique<Level>();
        return l->ranks[rank];
    }
    void note_pushed(int level, int rank, std::size_t n) {
        Level& l = *levels_[static_cast<std::size_t>(level)];
        l.entries += n;
        if (rank < l.lowest_rank) l.lowest_rank = rank;
        if (level < lowest_) lowest_ = level;
        poor_entries_ += n;
    }
    std::vector<std::unique_ptr<Level>> levels_;  // by σ level, up to the deepest used
    int lowest_ = bucket_count;
    std::size_t poor_entries_ = 0;
    std::vector<QueuedSubsegment> subsegments_;
    OwnedBox box_{};
    bool has_box_ = false;
};

}  // namespace gpdr::refine
