#pragma once
// Leaf: the unit of refinement work (GPDR paper §3, Fig. 4).  A leaf owns
//   - its poor triangles, in slots ordered by (level, bin), taken lowest
//     first (see the order below);
//   - the queue of subsegments to split (encroached, or in the way of a
//     Steiner point).
// Entries carry the triangle's generation; an entry whose triangle died
// since (or whose slot holds another triangle now) is stale and skipped when
// popped: nothing is ever searched for and removed.
//
// The order is refine/order.hpp's: the slots carry it out.  The key of a
// triangle is the squared length of its shortest edge l², in bins a factor
// √2 wide (edge_bin), the bin of the shortest edges first, first in, first
// out within a bin.  Triangles poor only by size wait, where the rules let
// them (PoorKind::size), in a last-in-first-out size bin after every other
// bin of their level; where not, by their shortest edge (PoorKind::
// size_edges): in a flat leaf in the same edge bins, in a quadtree leaf in
// size edge bins of their own, taken in the same order as the edge bins
// but only within the leaf's own levels, as the size bin is.
//
// A flat leaf (the sequential refiner, Leaf::flat) has no σ levels: its
// level is the top bits of the bin number, so the order is exactly the one
// above over the whole mesh.  A quadtree leaf of side ℓ (the parallel
// layer) files each triangle under its σ = ⌊log2(ℓ / r)⌋ (r the
// circumradius), which decides which triangles one run of the leaf takes
// (a window of levels) and when the leaf splits; within a σ level by the
// bin of l², counted from the longest edge the level can hold
// (l² < 4 r² <= 4 ℓ² 4^-σ): bin_count bins, the first of which also takes
// every shorter edge.  A run takes its window in the order above across
// levels (first_slot), so that the order is Triangle's within the window.
// Levels are allocated on first use, and the table of them grows only as
// far as the deepest level used (a quadtree leaf sees a handful of levels;
// -g1 makes hundreds of thousands of leaves).
//
// The sequential refiner is one flat leaf.  The parallel layer owns many
// leaves and runs refine_leaf on them from worker threads; a leaf is
// touched by one thread at a time.  Its owned box says whether a Steiner
// point or split point belongs to this leaf; what does not is handed off
// (handed_off_*) for the scheduler to route.  With no box, everything
// belongs to the leaf.
//
// σ is clamped to [0, bucket_count - 2]: σ < 0 (r > ℓ) never happens under
// the paper's relation (9) and σ > 125 means r < ℓ 2^-125; clamping only
// merges priorities at the extremes.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "geometry/point.hpp"
#include "mesh/ids.hpp"
#include "refine/order.hpp"

namespace gpdr::refine {

struct QueuedTriangle {
    mesh::TriangleId id;
    std::uint32_t generation;
    // Where in the leaf that queued it the point deciding its leaf lies
    // (Leaf::where), so that a split can hand it to a child without looking
    // at the mesh; 0: unknown.
    std::uint32_t where = 0;
    // The leaf's count of pushes when it was queued (Leaf::push_poor): a
    // quadtree leaf keeps a triangle's edge bin in its σ level, and takes the
    // heads of equal edge bins of two levels in this order, so that an edge
    // bin is first in, first out across the levels as a flat leaf's is.
    std::uint32_t order = 0;
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

// Where a poor triangle waits in a leaf: lower levels first, then lower
// bins (Leaf::slot).
struct PoorSlot {
    int level = 0;
    int bin = 0;
};

class Leaf {
public:
    static constexpr int bucket_count = 128;  // levels
    static constexpr int bin_count = 64;      // first-in-first-out bins per level
    // The bin of a level that holds the triangles poor only by size (last
    // in, first out, after every other bin of the level).
    static constexpr int size_bin = bin_count;
    // PoorSlot::bin of a quadtree leaf's size edge bin 0 (PoorKind::
    // size_edges); size edge bin i stands for the same edges as edge bin i.
    static constexpr int size_edges_base = size_bin + 1;

    // A quadtree leaf of side `side` (levels by σ).
    explicit Leaf(double side = 1.0)
        : side_squared_(side * side), side_(side), top_bin_(edge_bin(side * side) + 4) {}
    // The sequential refiner's leaf: no σ levels, the bins over the whole
    // range of doubles.
    static Leaf flat() {
        Leaf leaf(1.0);
        leaf.flat_ = true;
        return leaf;
    }
    bool is_flat() const { return flat_; }

    // ⌊log_√2(x)⌋ for finite x > 0: 2 e + (m >= √2) where x = m 2^e,
    // 1 <= m < 2 (Triangle's bins); 0 and denormals give edge_bin(DBL_MIN)
    // or below, infinity and NaN give the top bin.  Read off x's bits, not
    // through ilogb and scalbn (a library call each, for every poor
    // triangle): e is its biased exponent less the bias, and m >= √2 (the
    // double nearest it) exactly when x's 52 fraction bits are at least √2's.
    static int edge_bin(double x) {
        if (!(x >= 0x1p-1022)) return x >= 0 ? 2 * -1022 : 2 * 1024;
        if (!(x <= 0x1.fffffffffffffp1023)) return 2 * 1024;
        constexpr std::uint64_t fraction = (std::uint64_t{1} << 52) - 1;
        constexpr std::uint64_t sqrt2_fraction =
            std::bit_cast<std::uint64_t>(1.4142135623730951) & fraction;
        const auto bits = std::bit_cast<std::uint64_t>(x);
        const int e = static_cast<int>(bits >> 52) - 1023;  // x is positive and normal
        return 2 * e + ((bits & fraction) >= sqrt2_fraction ? 1 : 0);
    }

    double side() const { return side_; }
    // σ = ⌊log2(ℓ / r)⌋ from r², clamped (see above).
    int sigma(double radius_squared) const {
        const double ratio = side_squared_ / radius_squared;
        if (!(ratio >= 1.0)) return 0;  // r >= ℓ, or not a number
        // ⌊log2(ℓ²/r²)⌋ / 2, floored: ratio is normal (or infinite, whose
        // exponent field clamps as ilogb's INT_MAX would).
        const int s = (static_cast<int>(std::bit_cast<std::uint64_t>(ratio) >> 52) - 1023) >> 1;
        return s < bucket_count - 1 ? s : bucket_count - 2;
    }
    // The slot of a poor triangle with circumradius² radius_squared and
    // shortest edge² shortest_squared, of the given kind.
    PoorSlot slot(double radius_squared, double shortest_squared, PoorKind kind) const {
        if (flat_) {
            if (kind == PoorKind::size) return {bucket_count - 1, size_bin};
            // Bins -2044 .. 2048 (edge_bin's range), shortest first.
            const int key = edge_bin(shortest_squared) + 2 * 1022;
            return {key / bin_count, key % bin_count};
        }
        const int level = sigma(radius_squared);
        if (kind == PoorKind::size) return {level, size_bin};
        // From the shortest edges (bin 0: bin_count - 1 bins or more below
        // the level's top) to the longest (bin_count - 1).
        const int below_top = top_bin_ - 4 * level - edge_bin(shortest_squared);
        const int b = bin_count - 1 - std::clamp(below_top, 0, bin_count - 1);
        return {level, kind == PoorKind::angle ? b : size_edges_base + b};
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
    void push_poor(QueuedTriangle q, PoorSlot at) {
        q.order = pushes_++;
        bin(at).items.push_back(q);
        note_pushed(at, 1);
    }
    // The lowest non-empty level, or -1.  (Stale entries count as entries.)
    // A bit per level: the flat leaf keeps its size bin on the top level,
    // and a scan up to it after each edge bin's entry cost 1.5% of -j1's
    // instructions.
    int lowest_level() const {
        for (std::size_t w = 0; w < occupied_.size(); ++w)
            if (occupied_[w] != 0) return static_cast<int>(64 * w) + std::countr_zero(occupied_[w]);
        return -1;
    }
    // Takes the first entry of the slot `at` that first_slot gave (the
    // newest of a size bin, the oldest of any other).
    void pop_poor(PoorSlot at, QueuedTriangle& q) {
        Level& l = *levels_[static_cast<std::size_t>(at.level)];
        Bin& b = l.bin(at.bin);
        if (at.bin == size_bin) {
            q = b.items.back();
            b.items.pop_back();
        } else {
            q = b.items[b.head++];
            if (b.head == b.items.size()) {
                b.items.clear();
                b.head = 0;
            } else if (b.head >= 4096 && 2 * b.head >= b.items.size()) {
                // Long-lived bins: drop the taken half (amortised O(1)).
                b.items.erase(b.items.begin(), b.items.begin() + static_cast<long>(b.head));
                b.head = 0;
            }
            --edge_entries_;
        }
        --poor_entries_;
        if (--l.entries == 0) {
            l.lowest_bin = bin_count + 1;
            l.lowest_size_edge = bin_count;
            occupied_[static_cast<std::size_t>(at.level) / 64] &=
                ~(std::uint64_t{1} << (at.level % 64));
        } else if (at.bin <= size_bin) {
            while (l.lowest_bin <= size_bin && l.bins[l.lowest_bin].empty()) ++l.lowest_bin;
        } else {
            while (l.lowest_size_edge < bin_count && (*l.size_edges)[l.lowest_size_edge].empty())
                ++l.lowest_size_edge;
        }
        if (flat_) return;
        if (at.bin <= size_bin || l.entries == 0) note_head(at.level, l);
        if (at.bin > size_bin) note_size_edge_head(at.level, l);
    }
    std::size_t poor_entries() const { return poor_entries_; }
    // The entry pop_poor would take next from slot `at` if nothing is
    // pushed meanwhile, or null: what the refiner will most likely read
    // next, worth asking the memory for while it inserts the one it took.
    const QueuedTriangle* next_in(PoorSlot at) const {
        const Bin& b = levels_[static_cast<std::size_t>(at.level)]->bin(at.bin);
        if (b.empty()) return nullptr;
        return at.bin == size_bin ? &b.items.back() : &b.items[b.head];
    }

    // The slot to take first among levels lowest_level() .. last_level, the
    // size bins and size edge bins only up to last_size_level: a flat
    // leaf's lowest; a quadtree leaf's by shortest edge over the levels
    // (edge bins and size edge bins compared across levels; size bins after
    // every edge bin, lowest level first).  False when those levels hold
    // nothing.
    bool first_slot(int last_level, PoorSlot& at, int last_size_level = bucket_count) {
        const int lowest = lowest_level();
        if (lowest < 0 || lowest > last_level) return false;
        const int last_size = std::min(last_level, last_size_level);
        if (flat_ || (edge_entries_ == 0 && lowest <= last_size)) {
            // (Without edge entries, the lowest level's size bin.)
            at = {lowest, levels_[static_cast<std::size_t>(lowest)]->lowest_bin};
            return true;
        }
        // The least head over the levels (heads_: one word a level, so that
        // a window of many levels costs a short scan, not a visit to each
        // level's bins).
        const int last = std::min(last_level, static_cast<int>(levels_.size()) - 1);
        std::uint64_t best = empty_head;
        int best_level = -1;
        bool best_is_size_edge = false;
        for (int j = lowest; j <= last; ++j) {
            const std::uint64_t h = heads_[static_cast<std::size_t>(j)];
            if (h < best && (h < size_heads || j <= last_size)) {
                best = h;
                best_level = j;
                best_is_size_edge = false;
            }
            if (has_size_edges_ && j <= last_size) {
                const std::uint64_t e = size_edge_heads_[static_cast<std::size_t>(j)];
                if (e < best) {
                    best = e;
                    best_level = j;
                    best_is_size_edge = true;
                }
            }
        }
        if (best_level < 0) return false;
        const Level& l = *levels_[static_cast<std::size_t>(best_level)];
        at = {best_level, best_is_size_edge ? size_edges_base + l.lowest_size_edge : l.lowest_bin};
        return true;
    }

    // A split (parallel layer): moves every poor triangle to the child its
    // `where` names, at the σ level one down (the sides halve; σ is clamped
    // at both ends) in the same bin (the child's level one down has the
    // same top bin), and empties this leaf's levels.  An entry whose path
    // is used up goes to used_up(q) instead, to be placed afresh.  Each bin
    // is copied straight onto the children's in the order it would be
    // taken (the size bins newest first), so that they come out as taking
    // this leaf's entries one by one and pushing each would leave them.
    // (Popping and pushing entry by entry took about 15 ns an entry, 120 ms
    // of the graded pipe's -j2 run, whose splits move 7.8 million;
    // cachegrind at c = 1e-3: about 50 million fewer instructions.  Reserving
    // each child's share first raised the pipe's peak by 25 MiB.)
    template <class UsedUp>
    void move_poor_to_children(Leaf* const children[4], UsedUp&& used_up) {
        std::vector<std::unique_ptr<Level>> levels;
        levels.swap(levels_);
        heads_.clear();
        size_edge_heads_.clear();
        // The entries keep their order: the children count on from it.
        for (int c = 0; c < 4; ++c) children[c]->pushes_ = std::max(children[c]->pushes_, pushes_);
        occupied_ = {};
        poor_entries_ = 0;
        edge_entries_ = 0;
        for (std::size_t j = 0; j < levels.size(); ++j) {
            Level* l = levels[j].get();
            if (!l || l->entries == 0) continue;
            const int jj = static_cast<int>(j);
            const int child_level = jj == 0 || jj == bucket_count - 1 ? jj : jj - 1;
            const auto move_bin = [&](const Bin& b, int r) {
                if (b.empty()) return;
                std::vector<QueuedTriangle>* into[4] = {nullptr, nullptr, nullptr, nullptr};
                std::size_t moved[4] = {0, 0, 0, 0};
                const auto move = [&](QueuedTriangle q) {
                    if (path_used_up(q.where)) {
                        used_up(q);
                        return;
                    }
                    const int c = first_quadrant(q.where);
                    q.where = in_child(q.where);
                    if (into[c] == nullptr) into[c] = &children[c]->bin({child_level, r}).items;
                    into[c]->push_back(q);
                    ++moved[c];
                };
                if (r == size_bin)
                    for (auto it = b.items.rbegin(); it != b.items.rend(); ++it) move(*it);
                else
                    for (std::size_t i = b.head; i < b.items.size(); ++i) move(b.items[i]);
                for (int c = 0; c < 4; ++c)
                    if (moved[c] != 0) children[c]->note_pushed({child_level, r}, moved[c]);
            };
            for (int r = l->lowest_bin; r <= size_bin; ++r) move_bin(l->bins[r], r);
            for (int i = l->lowest_size_edge; i < bin_count; ++i)
                move_bin((*l->size_edges)[i], size_edges_base + i);
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
    // Whether every poor triangle queued waits in a size bin (poor only by
    // size, PoorKind::size): none in the edge bins, whose order across the
    // leaf's levels the mesh's size depends on.  Stale entries count.
    bool size_bins_only() const { return edge_entries_ == 0; }

    bool idle() const { return poor_entries_ == 0 && subsegments_.empty(); }

    // Frees the queues' storage (a leaf that split and handed its work to
    // its children keeps its node, but never queues anything again; an idle
    // one grows them afresh if work comes).  Any entries left are dropped.
    // Returns about how many bytes that gave back to the allocator.
    std::size_t release() {
        const std::size_t bytes = capacity_bytes();
        std::vector<std::unique_ptr<Level>>().swap(levels_);
        std::vector<std::uint64_t>().swap(heads_);
        std::vector<std::uint64_t>().swap(size_edge_heads_);
        occupied_ = {};
        poor_entries_ = 0;
        edge_entries_ = 0;
        std::vector<QueuedSubsegment>().swap(subsegments_);
        std::vector<QueuedTriangle>().swap(handed_off_triangles);
        std::vector<QueuedSubsegment>().swap(handed_off_subsegments);
        return bytes;
    }

    // Work that belongs to other leaves (parallel layer); always empty for a
    // leaf without an `owns` hook.
    std::vector<QueuedTriangle> handed_off_triangles;
    std::vector<QueuedSubsegment> handed_off_subsegments;

private:
    // The storage release() frees.
    std::size_t capacity_bytes() const {
        const auto of = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
        std::size_t bytes = of(levels_) + of(heads_) + of(size_edge_heads_) + of(subsegments_) +
                            of(handed_off_triangles) + of(handed_off_subsegments);
        for (const auto& l : levels_) {
            if (!l) continue;
            bytes += sizeof(Level);
            for (const Bin& b : l->bins) bytes += of(b.items);
            if (l->size_edges)
                for (const Bin& b : *l->size_edges) bytes += sizeof(Bin) + of(b.items);
        }
        return bytes;
    }

    double side_squared_;
    double side_;
    static constexpr int row_shift = 4, column_shift = row_shift + where_levels;
    geometry::Point corner_{};
    double cells_per_side_ = 0;  // 2^where_levels / ℓ
    bool has_corner_ = false;
    bool flat_ = false;
    int top_bin_ = 0;  // edge_bin(4 ℓ²): level 0's longest possible edges
    struct Bin {
        std::vector<QueuedTriangle> items;
        std::size_t head = 0;  // items before it were taken (first-in-first-out bins)
        bool empty() const { return head == items.size(); }
    };
    struct Level {
        std::array<Bin, bin_count + 1> bins;  // the last: the size bin
        // The size edge bins (PoorKind::size_edges in a quadtree leaf), made
        // on first use: up to 30 degrees no leaf has them.
        std::unique_ptr<std::array<Bin, bin_count>> size_edges;
        int lowest_bin = bin_count + 1;    // of bins; bin_count + 1: none
        int lowest_size_edge = bin_count;  // of *size_edges; bin_count: none
        std::size_t entries = 0;
        // PoorSlot::bin's bin.
        const Bin& bin(int b) const {
            if (b <= size_bin) return bins[static_cast<std::size_t>(b)];
            return (*size_edges)[static_cast<std::size_t>(b - size_edges_base)];
        }
        Bin& bin(int b) { return const_cast<Bin&>(std::as_const(*this).bin(b)); }
    };
    // The bin at `at`, made if missing; entries pushed straight into it are
    // then counted by note_pushed.
    Bin& bin(PoorSlot at) {
        if (static_cast<std::size_t>(at.level) >= levels_.size()) {
            levels_.resize(static_cast<std::size_t>(at.level) + 1);
            if (!flat_) heads_.resize(levels_.size(), empty_head);
            if (has_size_edges_) size_edge_heads_.resize(levels_.size(), empty_head);
        }
        auto& l = levels_[static_cast<std::size_t>(at.level)];
        if (!l) l = std::make_unique<Level>();
        if (at.bin > size_bin && !l->size_edges) {
            l->size_edges = std::make_unique<std::array<Bin, bin_count>>();
            if (!has_size_edges_) {
                has_size_edges_ = true;
                size_edge_heads_.resize(levels_.size(), empty_head);
            }
        }
        return l->bin(at.bin);
    }
    void note_pushed(PoorSlot at, std::size_t n) {
        Level& l = *levels_[static_cast<std::size_t>(at.level)];
        l.entries += n;
        if (at.bin > size_bin) {
            if (at.bin - size_edges_base < l.lowest_size_edge) {
                l.lowest_size_edge = at.bin - size_edges_base;
                note_size_edge_head(at.level, l);
            }
        } else if (at.bin < l.lowest_bin) {
            l.lowest_bin = at.bin;
            if (!flat_) note_head(at.level, l);
        }
        occupied_[static_cast<std::size_t>(at.level) / 64] |= std::uint64_t{1} << (at.level % 64);
        if (at.bin != size_bin) edge_entries_ += n;
        poor_entries_ += n;
    }
    std::vector<std::unique_ptr<Level>> levels_;  // by σ level, up to the deepest used
    // A quadtree leaf's summary of each level for first_slot: the key of its
    // lowest non-empty bin (Level::lowest_bin, kept exact) in the high word,
    // the order of that bin's head in the low word, so that the least word
    // is the slot to take first: edge bins by their absolute edge_bin(l²)
    // (bin 0 of a level stands for bin_count - 1 below its top: slot), the
    // older head first where two levels hold the same edge bin, size bins
    // after every edge bin, lowest level first.  empty_head: nothing queued.
    static constexpr std::uint64_t empty_head = ~std::uint64_t{0};
    static constexpr std::int64_t key_offset = 4096;  // keys are above -4096
    static constexpr std::int64_t size_key = std::int64_t{1} << 20;
    static constexpr std::uint64_t size_heads = std::uint64_t(size_key + key_offset) << 32;
    std::vector<std::uint64_t> heads_;
    // The same for each level's size edge bins (while has_size_edges_).
    std::vector<std::uint64_t> size_edge_heads_;
    bool has_size_edges_ = false;
    std::uint64_t edge_head(int j, const Bin& b, int edge_bin_index) const {
        const std::int64_t key = top_bin_ - 4L * j - (bin_count - 1 - edge_bin_index);
        return (std::uint64_t(key + key_offset) << 32) | b.items[b.head].order;
    }
    void note_size_edge_head(int j, const Level& l) {
        const int b = l.lowest_size_edge;
        size_edge_heads_[static_cast<std::size_t>(j)] =
            b >= bin_count ? empty_head : edge_head(j, (*l.size_edges)[b], b);
    }
    void note_head(int j, const Level& l) {
        std::uint64_t& h = heads_[static_cast<std::size_t>(j)];
        const int b = l.lowest_bin;
        if (b > size_bin) {
            h = empty_head;
        } else if (b == size_bin) {
            h = std::uint64_t(size_key + j + key_offset) << 32;
        } else {
            h = edge_head(j, l.bins[b], b);
        }
    }
    std::uint32_t pushes_ = 0;                                        // QueuedTriangle::order
    std::array<std::uint64_t, (bucket_count + 63) / 64> occupied_{};  // bit j: level j has entries
    std::size_t poor_entries_ = 0;
    // Of them, in edge bins: while none, the window's first slot is the
    // lowest level's size bin, found without looking at the other levels.
    std::size_t edge_entries_ = 0;
    std::vector<QueuedSubsegment> subsegments_;
    OwnedBox box_{};
    bool has_box_ = false;
};

}  // namespace gpdr::refine
