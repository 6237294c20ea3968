#pragma once
// The order of refinement: which poor triangle is split next.
//
// Above 25 degrees the size of a quality mesh depends on this order more
// than on anything else: with the same Steiner points, encroachment rules
// and quality test, one order can make several times the triangles of
// another at 33 degrees, or never end at 34.  Every rule that decides the
// order lives here; Leaf (leaf.hpp) is the data structure that carries it
// out, QualityTest (quality.hpp) only says whether a triangle is poor.  How
// much each rule gives or costs is measured in docs/refinement-order.md.
//
// 1. Triangle's order, the base of everything.  A poor triangle's key is the
//    squared length of its shortest edge, in bins a factor √2 wide
//    (Leaf::edge_bin); the bin of the shortest edges is taken first, and a
//    bin is first in, first out.  A triangle whose split was put off (its
//    Steiner point encroached a subsegment, or one stood in the way) goes
//    back to the tail of its bin.  It makes the smallest meshes known, and
//    it is the order in which refinement ends near 34 degrees.
//
// 2. Triangles poor only by size (an area bound or the user's test, no bad
//    angle; PoorKind) may wait apart.  Up to 30 degrees
//    (OrderRules::stack_size_only) they wait in a last-in, first-out size
//    bin after the other bins of their level: the newest was just made and
//    is still in the cache, and the mesh stays within a few percent of
//    Triangle's order.  Up to 26 degrees (OrderRules::sort_size_only) the
//    ones one insertion makes are pushed shortest edge last, so that the
//    stack takes them shortest first, which brings the mesh back to the
//    edge bins' size.  Above 30 degrees their order decides the mesh as
//    much as the others' does, and they wait by their shortest edge: in a
//    flat leaf in the same edge bins, in a quadtree leaf in size edge bins
//    of their own, taken in the same order.
//
// 3. The parallel order.  A quadtree leaf of side ℓ files each triangle
//    under its σ level, ⌊log2(ℓ / r)⌋, and one run of the leaf takes a
//    window of levels in the order above: its own levels (1 + g, the
//    granularity) for every kind, and order_levels_beyond_split levels more
//    for the triangles poor by their angle, which brings the parallel
//    order's meshes to those of Triangle's order.  Size-only triangles stay
//    in the leaf's own levels: taken further, they keep a leaf from
//    splitting and slow area-bound runs down for no smaller mesh.
//
// 4. A leaf that cannot split (its count of large triangles is not 0, so
//    relation (9) would not hold for its children) takes its triangles poor
//    by their angle over all its levels, in Triangle's order, looking at its
//    count again after every blocked_batch of them: otherwise its window
//    would take the large triangles first and leave the small ones near the
//    input's features to children it cannot have yet.
//
// 5. Above max_quadtree_angle the leaves' windows cannot keep Triangle's
//    order across leaves well enough for refinement to end with meshes of
//    its size, and every thread count refines in order 1 on one thread
//    (the schedule, parallel/schedule.hpp, asks quadtree_keeps_order).
//    Above 34 degrees the star placement (star_placement.hpp) keeps the
//    rounds' meshes near one thread's where a try ends, but a try that does
//    not end grows in the rounds instead of cascading, and the cascade
//    watch (convergence.hpp) catches it only late: one thread there too
//    (docs/refinement-order.md, "Above 34 degrees").
//
// The rules are decided once per run (order_rules) and read as plain flags
// where triangles are classified.

#include <cstdint>

#include "refine/quality.hpp"

namespace gpdr::refine {

// How a poor triangle waits in a leaf (Leaf::slot).
enum class PoorKind : std::uint8_t {
    angle,  // poor by its angle: by its shortest edge, in the edge bins
    // Poor only by size, where such triangles may wait apart
    // (OrderRules::stack_size_only): the size bin, last in, first out.
    size,
    // Poor only by size, where they may not: by the shortest edge like the
    // others.  A flat leaf files them in the edge bins; a quadtree leaf in
    // size edge bins of their own, which its runs take in the same order
    // as the edge bins but only within the leaf's own levels (first_slot's
    // last_size_level), so that the size of the mesh does not hold a leaf
    // back from splitting.
    size_edges,
};

// Rule 2's largest angle bound for sorting, in degrees (the one for the
// stack, 30 degrees, is order_rules' ρ̄ >= 1).
inline constexpr double size_sort_max_angle = 26.0;
// Rule 3: a leaf's own levels are 1 + g, g the granularity (-g; this when
// none is given, the same for any thread count, since the rounds and so the
// mesh depend on it) ...
inline constexpr unsigned default_granularity = 5;
// ... and the triangles poor by their angle get this many σ levels more.
inline constexpr int order_levels_beyond_split = 4;
// Rule 4: entries a blocked leaf takes between two looks at its count.  A
// look costs the counting of what the batch made; 4,096 entries are a few
// milliseconds of refinement, so a leaf whose count falls to 0 goes on to
// its window (and its split) soon after.
inline constexpr std::uint64_t blocked_batch = 4096;
// Rule 5: the largest angle bound the quadtree refines, in degrees.
inline constexpr double max_quadtree_angle = 33.0;

// Rule 2 for one run's quality test.
struct OrderRules {
    // Size-only triangles wait in the size bin (PoorKind::size), not by
    // their shortest edge (PoorKind::size_edges).
    bool stack_size_only = true;
    // The size-only triangles of one insertion are pushed shortest edge
    // last (LeafRefiner::queue_size_only).
    bool sort_size_only = true;
};
OrderRules order_rules(const QualityTest& quality);

// Rule 5: whether the quadtree may refine with this angle bound (0: none).
bool quadtree_keeps_order(double min_angle_degrees);

// How a poor triangle with measures m waits (Leaf::slot).
inline PoorKind poor_kind(const OrderRules& rules, const QualityTest& quality,
                          const TriangleMeasures& m) {
    if (quality.bad_shape(m)) return PoorKind::angle;
    return rules.stack_size_only ? PoorKind::size : PoorKind::size_edges;
}

}  // namespace gpdr::refine
