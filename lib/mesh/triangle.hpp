#pragma once
// The triangle record: 32 bytes, index-based (docs/architecture.md, "The mesh").
//
/*
                 v[2]
                 /\
                /  \
      edge 1   /    \   edge 0          corners counter-clockwise;
   (v2 -> v0) /      \ (v1 -> v2)       edge k is opposite corner k and runs
             /        \                 from v[k+1] to v[k+2];
            /__________\                n[k] is the neighbour across edge k
        v[0]   edge 2   v[1]            (Triangle's .neigh: "neighbour k is
              (v0 -> v1)                 opposite corner k").
*/
// n[k] names the neighbour triangle AND the index of the shared edge in it,
// so the neighbour's link back is n[k].triangle()'s n[n[k].edge()].

#include <atomic>
#include <cstdint>

#include "mesh/ids.hpp"

// An all-zero record is a dead slot with generation 0: fresh chunks come
// zero-filled from the store and need no initialisation pass.

namespace gpdr::mesh {

struct Triangle {
    // Bits of `flags`.
    static constexpr std::uint8_t subsegment_bit0 = 1u << 0;  // edge k is a subsegment: bit k
    static constexpr std::uint8_t live_bit = 1u << 3;         // the slot holds a triangle
    static constexpr std::uint8_t mark_bit = 1u << 4;         // scratch: "in the cavity"
    // Set by refinement when it last assessed the triangle: its small angle
    // is forced by an input angle, so it is left alone (refine/segments.hpp).
    static constexpr std::uint8_t small_angle_bit = 1u << 5;

    VertexId v[3];
    EdgeRef n[3];
    // Bumped each time the slot's triangle dies, so a queue entry
    // (id, generation) taken earlier is recognised as stale.
    std::uint32_t generation;
    // Room for a region index (-A attributes, regional area bounds): set by
    // the CDT later; 0 means "no region".
    std::uint16_t region;
    std::uint8_t flags;
    // A byte for the layers above the mesh (the parallel refiner keeps how
    // the triangle is counted in it): 0 in a new triangle; when an insertion
    // kills the triangle or flips it, the triangle as it was is saved in
    // InsertBuffer::tagged_gone (a flipped one loses its tag).
    std::uint8_t user_tag;

    bool live() const { return (flags & live_bit) != 0; }
    // The generation, read and bumped as a relaxed atomic (a plain move on
    // the usual targets): a parallel worker checks a queue entry for
    // staleness while another thread may be reusing the slot
    // (parallel/scheduler.hpp).  An entry is live exactly when the slot's
    // generation still equals the entry's; nothing else of a slot that may
    // be someone else's is read before that check.
    std::uint32_t load_generation() const {
        return std::atomic_ref<std::uint32_t>(const_cast<std::uint32_t&>(generation))
            .load(std::memory_order_relaxed);
    }
    void bump_generation() {
        std::atomic_ref<std::uint32_t>(generation).store(generation + 1, std::memory_order_relaxed);
    }
    bool marked() const { return (flags & mark_bit) != 0; }
    bool small_angle_protected() const { return (flags & small_angle_bit) != 0; }
    bool is_subsegment(int k) const { return (flags >> k) & 1u; }
    void set_subsegment(int k, bool on) {
        const auto bit = static_cast<std::uint8_t>(subsegment_bit0 << k);
        flags =
            on ? static_cast<std::uint8_t>(flags | bit) : static_cast<std::uint8_t>(flags & ~bit);
    }
    bool is_ghost() const {
        return v[0] == ghost_vertex || v[1] == ghost_vertex || v[2] == ghost_vertex;
    }
    // Corner index of vertex `x`, or -1.
    int corner_of(VertexId x) const { return v[0] == x ? 0 : v[1] == x ? 1 : v[2] == x ? 2 : -1; }
};

static_assert(sizeof(Triangle) == 32, "the triangle record must stay at 32 bytes");

}  // namespace gpdr::mesh
