#pragma once
// The quadtree that overlays the mesh during parallel refinement (GPDR paper
// §3; docs/architecture.md, "Parallel refinement").
//
// Conventions (written down once, used everywhere in parallel/):
//   - A node is a square cell: level k has side ℓ_k = ℓ_root 2^-k and cell
//     coordinates (ix, iy) in [0, 2^k); child q of a cell has quadrant bits
//     q = (x half) | (y half) << 1.  Squares are half-open [x0, x0+ℓ).
//   - The LEVEL of a triangle with circumradius r is the k with
//     4r < ℓ_k <= 8r.  A triangle is COUNTED in each level-k cell its closed
//     circumdisk meets (at most 2 x 2 cells, since its diameter is below
//     ℓ_k / 2).  Node::count is that number; it is the paper's Counter_i
//     with i = σ = ⌊log2(ℓ/r)⌋ in {2} (we use the shifted convention
//     4 <= ℓ/r < 8 inclusive of the right boundary: r >= ℓ/8 and r < ℓ/4).
//   - Relation (9) for a leaf L is "every triangle whose circumdisk meets L
//     has r < ℓ(L)/4"; it holds exactly when no triangle is counted in a
//     strict ancestor of L.  A leaf may split when its own count is 0: then
//     every triangle meeting a child has r < ℓ(L)/8 = ℓ(child)/4.
//   - Cells below leaves are materialised as SHADOW nodes when a triangle is
//     counted there, so a child's count is exact the moment it becomes a
//     leaf (no rescan of the mesh on a split).  Only counts at most one
//     level below a leaf are ever read before the leaf splits, so a triangle
//     two or more levels below the leaf that holds it is not counted yet but
//     listed in that leaf, and counted when splits bring a leaf within one
//     level of it (Worker::flush_pending); most of the final mesh is never
//     counted.
//   - A triangle counted in an INTERNAL node breaks (9) for the leaves under
//     it (a Bowyer-Watson triangle can be larger than the cavity it came
//     from when the new vertex is nearly on a cavity edge).  Such counts are
//     atomic; the scheduler then uses the EFFECTIVE side ℓe(L) = the side of
//     the largest ancestor-or-self with a count, for which "every triangle
//     meeting L has r < ℓe(L)/4" holds again, and buffer zones grow to match.
//
// Concurrency: a node's count, children and state are written only by the
// worker whose buffer zone holds the leaf at or above it (plain relaxed
// loads and stores); internal nodes never change except their counts
// (atomic read-modify-write).  `kind` changes only on the master thread
// (release), and workers descend through internal nodes with acquire loads.

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/point.hpp"
#include "mesh/store.hpp"

namespace gpdr::parallel {

using geometry::Point;
using NodeId = std::uint32_t;
inline constexpr NodeId no_node = 0xFFFFFFFFu;
// Deepest level (cell coordinates fit the 26 bits they have in a CellRecord).
inline constexpr int max_level = 26;

enum class NodeKind : std::uint8_t { shadow = 0, leaf = 1, internal = 2 };

struct LeafState;

// Node::owner of a leaf that lies in the buffer zones of two or more leaves
// of the round.
inline constexpr std::int32_t shared_owner = -1;

struct Node {
    // All-zero is an unused shadow node without children (the store is
    // zero-filled); ids are stored plus one so that 0 means "none".
    std::atomic<std::uint8_t> kind;
    std::uint8_t level;
    std::uint32_t ix, iy;
    std::uint32_t parent_plus1;
    std::uint32_t child_plus1[4];
    std::atomic<std::int32_t> count;
    // While a round runs: entry + 1 of the one leaf of the round whose
    // buffer zone holds this leaf, shared_owner when two or more zones hold
    // it, 0 when none does (scheduler.hpp).
    std::atomic<std::int32_t> owner;
    LeafState* state;                 // leaves: the refinement work

    NodeKind get_kind() const {
        return static_cast<NodeKind>(kind.load(std::memory_order_acquire));
    }
    NodeId child(int q) const { return child_plus1[q] - 1; }
    NodeId parent() const { return parent_plus1 - 1; }
};

struct Square {
    double x0, y0, side;
    bool contains(const Point& p) const {
        return p.x >= x0 && p.x < x0 + side && p.y >= y0 && p.y < y0 + side;
    }
};

// The squared Euclidean distance between two squares (0 when they touch or
// overlap).
double squared_distance(const Square& a, const Square& b);
// Whether the closed disk (centre c, radius r) meets the square.
inline bool disk_meets(const Square& s, const Point& c, double r) {
    const double dx = std::max({0.0, s.x0 - c.x, c.x - (s.x0 + s.side)});
    const double dy = std::max({0.0, s.y0 - c.y, c.y - (s.y0 + s.side)});
    // A hair of slack: counting a cell the disk only grazes is safe (it can
    // only delay a split), missing one is not.
    const double rr = r * (1.0 + 0x1p-30);
    return dx * dx + dy * dy <= rr * rr;
}

// Node ids for one thread: blocks claimed from the tree with one atomic add.
struct NodeAllocator {
    NodeId next = 0, end = 0;
};

class Quadtree {
public:
    // The root square (x0, y0, side); the root starts as the only leaf.
    Quadtree(double x0, double y0, double side);

    double side_at(int level) const { return sides_[level]; }
    Square square(NodeId id) const {
        const Node& n = node(id);
        const double s = side_at(n.level);
        return {x0_ + s * n.ix, y0_ + s * n.iy, s};
    }
    Square cell_square(int level, std::uint32_t ix, std::uint32_t iy) const {
        const double s = side_at(level);
        return {x0_ + s * ix, y0_ + s * iy, s};
    }
    Node& node(NodeId id) const { return nodes_[id]; }
    static constexpr NodeId root() { return 0; }
    std::uint32_t node_end() const { return next_.load(std::memory_order_acquire); }

    // Cell coordinate of x at `level`, clamped into the root.  (The hot
    // path of the counters: a truncation, no library call.)
    std::uint32_t cell_x(double x, int level) const {
        return cell_coordinate((x - x0_) * inverse_sides_[level], level);
    }
    std::uint32_t cell_y(double y, int level) const {
        return cell_coordinate((y - y0_) * inverse_sides_[level], level);
    }
    // The level a triangle of circumradius r = sqrt(radius_squared) is
    // counted at (see above): k = ⌊log2(ℓ_root / 4r)⌋, read off the exponent
    // of ℓ_root² / 16r² (halved), that quotient shrunk by 2^-30 first so that
    // rounding never breaks ℓ_k > 4r (it may give the level above, whose
    // cells are larger: only ever conservative).  -1 when r >= ℓ_root / 4 (up
    // to that margin), max_level + 1 when the triangle is too small to matter
    // (or r is not a positive number).
    int level_of(double radius_squared) const {
        if (!(radius_squared > 0)) return max_level + 1;
        const double q = shrunk_side_squared_over_16_ / radius_squared;
        if (!(q > 1.0)) return -1;
        if (!(q < 0x1p+60)) return max_level + 1;  // deeper than max_level (or infinite)
        // q is normal and in (1, 2^60): floor(log2 q) is its biased exponent - 1023.
        const int e = static_cast<int>((std::bit_cast<std::uint64_t>(q) >> 52) & 0x7FF) - 1023;
        const int k = e >> 1;  // 4^k <= q < true ℓ²/16r², so ℓ_k > 4r
        return k > max_level ? max_level + 1 : k;
    }

    // The node of cell (level, ix, iy), descending from `from` (an
    // ancestor-or-self of it).  Missing shadow nodes below leaves are made
    // with `alloc`; with alloc == nullptr, no_node is returned instead.
    // `leaf` receives the leaf on the way down (no_node when the cell is
    // an internal node).
    NodeId cell(NodeId from, int level, std::uint32_t ix, std::uint32_t iy, NodeAllocator* alloc,
                NodeId& leaf);
    // The nearest ancestor-or-self of node `from` whose square holds cell
    // (level, ix, iy): where cell() may start instead of the root.
    NodeId ancestor_holding(NodeId from, int level, std::uint32_t ix, std::uint32_t iy) const {
        const Node* n = &node(from);
        while (n->level > level || (ix >> (level - n->level)) != n->ix ||
               (iy >> (level - n->level)) != n->iy) {
            from = n->parent();
            n = &node(from);
        }
        return from;
    }
    // The child q of node id, made if missing.
    NodeId child(NodeId id, int q, NodeAllocator& alloc);
    // The leaf whose square holds p (p clamped into the root).
    NodeId leaf_at(const Point& p) const { return leaf_below(root(), p); }
    // The same leaf, found from node `near` (most points asked for lie in
    // it or beside it): the descent starts at near's nearest
    // ancestor-or-self whose square holds p with the rounding margin to
    // spare on every side, which the descent from the root passes through
    // too (its comparisons with the split lines above that node cannot go
    // the other way), so that the answer is leaf_at's, bit for bit.
    NodeId leaf_at(const Point& p, NodeId near) const {
        while (near != root() && !holds_with_margin(square(near), p)) near = node(near).parent();
        return leaf_below(near, p);
    }

    // Whether a triangle of circumradius² radius_squared is at least two
    // levels below a leaf of level leaf_level (level_of(radius_squared) >=
    // leaf_level + 2) and not too small to be counted at all (<= max_level);
    // conservative near the limits.  Two comparisons, no division: it is
    // asked of every triangle a worker creates.  (leaf_level may be
    // max_level + 1, a child of the deepest leaves: nothing qualifies.)
    bool two_levels_below(double radius_squared, int leaf_level) const {
        return two_levels_below(leaf_level).holds(radius_squared);
    }
    // The same test with its two limits taken out, for a caller that asks
    // it of many triangles and one leaf level.
    struct RadiusBand {
        double most, least;  // of the circumradius²
        bool holds(double radius_squared) const {
            return radius_squared <= most && radius_squared >= least;
        }
    };
    RadiusBand two_levels_below(int leaf_level) const {
        return {deferrable_below_[leaf_level], smallest_counted_};
    }

    // A square as disk_inside reads it: its centre, and how far from the
    // centre a disk may reach in x and in y, less twice the rounding margin.
    struct Room {
        double x, y, reach;
    };
    Room room(const Square& s) const {
        const double half = 0.5 * s.side;
        return {s.x0 + half, s.y0 + half, half - 2 * rounding_margin_};
    }
    // Whether the closed disk (centre c, radius² radius_squared) lies inside
    // the square of `room` with room to spare: then every cell, at any level,
    // that the counters would give the disk (cell_record) lies inside the
    // square, whatever the rounding of its cell coordinates.  Conservative:
    // a disk that only just fits is reported as not inside.  (Asked of
    // every triangle a worker creates: no square root, no branch; the
    // distances from the centre to the nearer sides are compared squared.
    // The rounding of the centre's offset is far below the margin, the
    // second one taken off the reach.)
    bool disk_inside(const Room& room, const Point& c, double radius_squared) const {
        const double gx = room.reach - std::abs(c.x - room.x);
        const double gy = room.reach - std::abs(c.y - room.y);
        const double rr = radius_squared * (1.0 + 0x1p-40);
        // (NaN anywhere makes a comparison false.)
        return (gx > 0) & (gy > 0) & (gx * gx > rr) & (gy * gy > rr);
    }

    // ℓe(leaf) (see above).
    double effective_side(NodeId leaf) const;
    // BUF(leaf) ∪ {leaf}: the leaves L' with dist(leaf, L') < (ℓe(leaf) + ℓe(L'))/2.
    void zone(NodeId leaf, std::vector<NodeId>& out) const {
        zone_until(leaf, out, [](NodeId) { return false; });
    }
    // The same search, stopped at the first zone leaf for which stop(leaf)
    // holds: that leaf, or no_node when none does (then `out` is the zone).
    // The master asks "is any leaf of the zone held?" for every candidate
    // leaf, and most are blocked: stopping early halves their cost.
    template <class Stop>
    NodeId zone_until(NodeId leaf, std::vector<NodeId>& out, Stop&& stop) const {
        out.clear();
        return zone_search(root(), square(leaf), effective_side(leaf), 0.0, out, stop);
    }
    // Every leaf, in depth-first order.
    void leaves(std::vector<NodeId>& out) const;

private:
    static std::uint32_t cell_coordinate(double f, int level) {
        const double top = double((std::uint32_t{1} << level) - 1);
        // std::max(0.0, NaN) is 0.0: a coordinate that is not a number lands in cell 0.
        return static_cast<std::uint32_t>(
            static_cast<std::int64_t>(std::min(std::max(0.0, f), top)));
    }
    NodeId allocate(NodeAllocator& alloc);
    template <class Stop>
    NodeId zone_search(NodeId id, const Square& target, double target_side, double above,
                       std::vector<NodeId>& out, Stop& stop) const {
        const Node& n = node(id);
        const Square s = square(id);
        // Every leaf below has ℓe <= max(ℓ(n), above): prune when even that is too far.
        const double reach = 0.5 * (target_side + std::max(s.side, above));
        if (squared_distance(target, s) >= reach * reach) return no_node;
        if (n.get_kind() != NodeKind::internal) {
            out.push_back(id);
            return stop(id) ? id : no_node;
        }
        const double below =
            n.count.load(std::memory_order_relaxed) != 0 ? std::max(above, s.side) : above;
        for (int q = 0; q < 4; ++q)
            if (const NodeId found = zone_search(n.child(q), target, target_side, below, out, stop);
                found != no_node)
                return found;
        return no_node;
    }

    double x0_, y0_, side_;
    double shrunk_side_squared_over_16_;      // ℓ_root² / 16 (1 - 2^-30)
    double deferrable_below_[max_level + 2];  // two_levels_below's limits
    double smallest_counted_;
    // Far above the rounding error of a cell coordinate (cell_x of a disk's
    // extreme x or y, computed from coordinates of the root's magnitude).
    double rounding_margin_;

    bool holds_with_margin(const Square& s, const Point& p) const {
        const double m = rounding_margin_;
        return p.x >= s.x0 + m && p.x < s.x0 + s.side - m && p.y >= s.y0 + m &&
               p.y < s.y0 + s.side - m;
    }
    // leaf_at's descent from `from`, which the descent from the root passes.
    NodeId leaf_below(NodeId from, const Point& p) const;
    double sides_[max_level + 2];          // ℓ_k
    double inverse_sides_[max_level + 2];  // 1 / ℓ_k
    // 2^28 nodes at most (the graded pipe needs about 400 thousand): the
    // table of chunk pointers, zeroed up front, stays at 512 KiB.
    mutable mesh::ChunkTable<Node, 12, (1u << 16)> nodes_;
    std::atomic<std::uint32_t> next_{0};
};

}  // namespace gpdr::parallel
