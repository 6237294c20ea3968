// The quadtree's geometry, cell lookup and buffer zones (see quadtree.hpp
// for the conventions and the concurrency rules).

#include "parallel/quadtree.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include <gpdr/errors.hpp>

namespace gpdr::parallel {

double squared_distance(const Square& a, const Square& b) {
    const double gx = std::max({0.0, a.x0 - (b.x0 + b.side), b.x0 - (a.x0 + a.side)});
    const double gy = std::max({0.0, a.y0 - (b.y0 + b.side), b.y0 - (a.y0 + a.side)});
    return gx * gx + gy * gy;
}

Quadtree::Quadtree(double x0, double y0, double side)
    : x0_(x0),
      y0_(y0),
      side_(side),
      shrunk_side_squared_over_16_(side * side / 16 * (1 - 0x1p-30)),
      rounding_margin_(0x1p-40 * (std::abs(x0) + std::abs(y0) + 4 * side)) {
    for (int k = 0; k <= max_level + 1; ++k) {
        sides_[k] = std::ldexp(side, -k);
        inverse_sides_[k] = 1.0 / sides_[k];
    }
    // level_of reads k off the exponent of q = ℓ_root²(1 - 2^-30)/16r².  A
    // radius² below S / 4^(m+2) by a relative 2^-40 (far beyond the
    // division's rounding) gives q >= 4^(m+2), so k >= m + 2; one above
    // S / 4^(max_level+1) by as much gives q < 4^(max_level+1), so k <=
    // max_level.  (For m + 2 > max_level no triangle qualifies: limit 0.)
    const double s = shrunk_side_squared_over_16_;
    for (int m = 0; m <= max_level + 1; ++m)
        deferrable_below_[m] =
            m + 2 <= max_level ? std::ldexp(s, -2 * (m + 2)) * (1 - 0x1p-40) : 0.0;
    smallest_counted_ = std::ldexp(s, -2 * (max_level + 1)) * (1 + 0x1p-40);
    NodeAllocator a;
    const NodeId root = allocate(a);
    Node& n = node(root);
    n.kind.store(static_cast<std::uint8_t>(NodeKind::leaf), std::memory_order_release);
    // The rest of the block is left unused (ids are cheap).
}

NodeId Quadtree::allocate(NodeAllocator& alloc) {
    if (alloc.next == alloc.end) {
        constexpr std::uint32_t block = 64;
        const std::uint32_t first = next_.fetch_add(block, std::memory_order_acq_rel);
        if (std::uint64_t{first} + block > (std::uint64_t{1} << 32) - 2)
            throw CapacityError("parallel: quadtree too large");
        const std::uint32_t last = first + block - 1;
        for (std::uint32_t c = first >> 12; c <= last >> 12; ++c)
            if (!nodes_.ensure(c, true)) throw CapacityError("parallel: quadtree too large");
        alloc.next = first;
        alloc.end = first + block;
    }
    return alloc.next++;
}

NodeId Quadtree::child(NodeId id, int q, NodeAllocator& alloc) {
    Node& n = node(id);
    std::atomic_ref<std::uint32_t> slot(n.child_plus1[q]);
    if (const std::uint32_t c = slot.load(std::memory_order_acquire); c != 0) return c - 1;
    const NodeId c = allocate(alloc);
    Node& m = node(c);
    m.level = static_cast<std::uint8_t>(n.level + 1);
    m.ix = n.ix * 2 + (q & 1);
    m.iy = n.iy * 2 + (q >> 1);
    m.parent_plus1 = id + 1;
    std::uint32_t made = 0;
    if (slot.compare_exchange_strong(made, c + 1, std::memory_order_acq_rel,
                                     std::memory_order_acquire))
        return c;
    // Another lane made it first: a shadow node below a leaf that two zones
    // share, which both count in (scheduler.hpp, (d)).  Ours goes back
    // unused, all zeros again, to be handed out next.
    m.level = 0;
    m.ix = m.iy = 0;
    m.parent_plus1 = 0;
    --alloc.next;
    return made - 1;
}

NodeId Quadtree::cell(NodeId from, int level, std::uint32_t ix, std::uint32_t iy,
                      NodeAllocator* alloc, NodeId& leaf) {
    NodeId id = from;
    leaf = no_node;
    for (;;) {
        Node& n = node(id);
        const NodeKind k = n.get_kind();
        if (k == NodeKind::leaf) leaf = id;
        if (n.level == level) return id;
        const int shift = level - n.level - 1;
        const int q = static_cast<int>(((ix >> shift) & 1u) | (((iy >> shift) & 1u) << 1));
        // (Atomic: below a leaf two zones share, another lane may be making
        // the child: see child.)
        const std::uint32_t c =
            std::atomic_ref<std::uint32_t>(n.child_plus1[q]).load(std::memory_order_acquire);
        if (c == 0) {
            if (alloc == nullptr) return no_node;
            id = child(id, q, *alloc);
        } else {
            id = c - 1;
        }
    }
}

NodeId Quadtree::leaf_below(NodeId from, const Point& p) const {
    NodeId id = from;
    for (;;) {
        const Node& n = node(id);
        if (n.get_kind() != NodeKind::internal) return id;
        const double half = side_at(n.level + 1);
        const Square s = square(id);
        const int q = (p.x >= s.x0 + half ? 1 : 0) | (p.y >= s.y0 + half ? 2 : 0);
        id = n.child(q);
    }
}

double Quadtree::effective_side(NodeId leaf) const {
    double side = side_at(node(leaf).level);
    for (NodeId a = node(leaf).parent(); a != no_node; a = node(a).parent())
        if (node(a).count.load(std::memory_order_relaxed) != 0) side = side_at(node(a).level);
    return side;
}

void Quadtree::leaves(std::vector<NodeId>& out) const {
    out.clear();
    std::vector<NodeId> stack{root()};
    while (!stack.empty()) {
        const NodeId id = stack.back();
        stack.pop_back();
        const Node& n = node(id);
        if (n.get_kind() != NodeKind::internal) {
            out.push_back(id);
            continue;
        }
        for (int q = 3; q >= 0; --q) stack.push_back(n.child(q));
    }
}

}  // namespace gpdr::parallel
