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
// threads; a leaf is touched by one thread at a time.  Its `owns` hook says
// whether a Steiner point or split point belongs to this leaf; what does
// not is handed off (handed_off_*) for the scheduler to route.  With no
// hook, everything belongs to the leaf.
//
// Bucket σ is clamped to [0, bucket_count - 1]: σ < 0 (r > ℓ) never happens
// under the paper's relation (9) and σ > 127 means r < ℓ 2^-127; clamping
// only merges priorities at the extremes.

#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/point.hpp"
#include "mesh/ids.hpp"

namespace gpdr::refine {

struct QueuedTriangle {
    mesh::TriangleId id;
    std::uint32_t generation;
};

struct QueuedSubsegment {
    mesh::EdgeRef edge;        // an edge of a live triangle when queued
    std::uint32_t generation;  // of edge.triangle() when queued
    bool forced;               // split even if no apex encroaches (a rejected point did)
};

class Leaf {
public:
    static constexpr int bucket_count = 128;
    using OwnsPoint = bool (*)(const void* context, const geometry::Point& p);

    explicit Leaf(double side = 1.0) : side_squared_(side * side), side_(side) {}

    double side() const { return side_; }
    // σ = ⌊log2(ℓ / r)⌋ from r², clamped (see above).
    int sigma(double radius_squared) const {
        const double ratio = side_squared_ / radius_squared;
        if (!(ratio >= 1.0)) return 0;  // r >= ℓ, or not a number
        const int s = std::ilogb(ratio) >> 1;  // ⌊log2(ℓ²/r²)⌋ / 2, floored
        return s < bucket_count ? s : bucket_count - 1;
    }

    void set_owner(OwnsPoint owns, const void* context) {
        owns_ = owns;
        owns_context_ = context;
    }
    bool owns(const geometry::Point& p) const { return owns_ == nullptr || owns_(owns_context_, p); }

    // ---- poor triangles ------------------------------------------------------
    void push_poor(QueuedTriangle q, int level) {
        buckets_[level].push_back(q);
        if (level < lowest_) lowest_ = level;
        ++poor_entries_;
    }
    // The lowest non-empty level, or -1.  (Stale entries count as entries.)
    int lowest_level() {
        while (lowest_ < bucket_count && buckets_[lowest_].empty()) ++lowest_;
        return lowest_ < bucket_count ? lowest_ : -1;
    }
    // Takes the newest entry of level j.  Within a level the order is free
    // (Miller's bound needs only the level order); last in, first out
    // refines triangles while they are still in the cache.
    bool pop_poor(int j, QueuedTriangle& q) {
        std::vector<QueuedTriangle>& b = buckets_[j];
        if (b.empty()) return false;
        q = b.back();
        b.pop_back();
        --poor_entries_;
        return true;
    }
    std::size_t poor_entries() const { return poor_entries_; }

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

    // Work that belongs to other leaves (parallel layer); always empty for a
    // leaf without an `owns` hook.
    std::vector<QueuedTriangle> handed_off_triangles;
    std::vector<QueuedSubsegment> handed_off_subsegments;

private:
    double side_squared_;
    double side_;
    std::vector<QueuedTriangle> buckets_[bucket_count];
    int lowest_ = bucket_count;
    std::size_t poor_entries_ = 0;
    std::vector<QueuedSubsegment> subsegments_;
    OwnsPoint owns_ = nullptr;
    const void* owns_context_ = nullptr;
};

}  // namespace gpdr::refine
