#pragma once
// Pool: the allocator one thread owns (docs/architecture.md, "The mesh", paper §3.1).
//
// Triangles: a pool hands out slots from its own intrusive free list (dead
// slots linked through n[0]) and, when that is empty, from a fresh chunk it
// claimed from the mesh with one atomic increment.  So the hot path never
// calls the system allocator and never takes a lock; a chunk (1024 slots)
// is claimed once per 1024 net creations.  Destroying a triangle bumps its
// generation, so (id, generation) pairs held in queues go stale.
//
// Vertices: ids come from a block the pool claimed from the mesh; at the
// end, the unused tail of the block is returned if nobody claimed after it
// (always so with one thread), otherwise those ids stay `unused` holes.
// The unused ends of a lane pool's last chunks, triangles' and vertices',
// are recorded by the mesh when the pool is destroyed, so that passes over
// the finished mesh stop where each chunk's used part ends.
//
// A pool on a LANE (the deterministic parallel refiner's) claims by a fixed
// rule instead: lane k of n takes the chunks at places k, n + k, 2n + k, ...
// of a list fixed when the lanes were set (move_to_lane: before every round,
// n being the lanes the round uses): first the holes, the chunks below
// every id claimed that no one claimed (the rounds before left them: their
// lanes claim unevenly), then the chunks above every id claimed, in order.
// The ids it hands out then depend only on the lanes' settings and the
// sequence of creations and destructions asked of it, whatever other lanes
// do at the same time and whichever thread runs it.
//
// A pool must not outlive its mesh.  When destroyed it gives its unused slots
// back to the mesh, and the next pool created starts from them.

#include <cstdint>
#include <span>

#include "mesh/mesh.hpp"

namespace gpdr::mesh {

struct Lane {
    std::uint32_t index = 0;           // k
    std::uint32_t count = 1;           // n
    std::uint32_t triangle_chunk = 0;  // the bases: the first chunks above every id claimed
    std::uint32_t vertex_chunk = 0;
    // The holes below the bases, ascending (the mesh's lists: they stay put
    // until the next Lane::first).
    std::span<const std::uint32_t> triangle_holes;
    std::span<const std::uint32_t> vertex_holes;

    // The lanes' list for lanes made on `mesh` now.  Not thread-safe: call
    // it while no pool claims ids.
    static Lane first(Mesh& mesh, std::uint32_t count) {
        mesh.refresh_holes();
        return {0,
                count,
                mesh.triangle_chunks_claimed(),
                mesh.vertex_chunks_claimed(),
                mesh.triangle_holes(),
                mesh.vertex_holes()};
    }
    // The chunk at place p of the list: a hole, or a chunk above the base.
    static std::uint32_t at(std::span<const std::uint32_t> holes, std::uint32_t base,
                            std::uint32_t p) {
        return p < holes.size() ? holes[p] : base + (p - static_cast<std::uint32_t>(holes.size()));
    }
};

class Pool {
public:
    explicit Pool(Mesh& mesh, std::uint32_t vertex_block = 256);
    Pool(Mesh& mesh, const Lane& lane);
    ~Pool();
    Pool(const Pool&) = delete;
    Pool& operator=(const Pool&) = delete;

    Mesh& mesh() const { return *mesh_; }

    // A live triangle (a, b, c) with no neighbours, no flags, region 0; its
    // generation is the slot's current one.  Corners must be counter-clockwise.
    TriangleId create(VertexId a, VertexId b, VertexId c) {
        if (spare_.free_head == index(no_triangle) && spare_.fresh == spare_.fresh_end) refill();
        TriangleId t;
        if (spare_.free_head != index(no_triangle)) {
            t = TriangleId{spare_.free_head};
            spare_.free_head = mesh_->triangle(t).n[0].bits();
        } else {
            t = TriangleId{spare_.fresh++};
        }
        Triangle& r = mesh_->triangle(t);
        r.v[0] = a;
        r.v[1] = b;
        r.v[2] = c;
        r.n[0] = r.n[1] = r.n[2] = EdgeRef::none();
        r.region = 0;
        r.flags = Triangle::live_bit;
        r.user_tag = 0;
        return t;
    }

    // Kills triangle t: bumps its generation and keeps the slot for reuse.
    // Its neighbours' links to it are the caller's business.
    // Destroying a dead slot would corrupt the free list: refused (throws
    // gpdr::InternalError; a bug in the caller, checked because it is one
    // branch).
    void destroy(TriangleId t) {
        Triangle& r = mesh_->triangle(t);
        if (!r.live()) [[unlikely]]
            destroyed_twice(t);
        r.bump_generation();
        r.flags = 0;
        r.n[0] = EdgeRef::from_bits(spare_.free_head);
        spare_.free_head = index(t);
    }

    // A new vertex at p.
    VertexId new_vertex(const Point& p, VertexKind kind);

    // A lane pool's claims from now on follow `lane` (its own chunks from
    // lane.triangle_chunk and lane.vertex_chunk on); the slots and ids it
    // holds stay its own.
    void move_to_lane(const Lane& lane) {
        lane_ = lane;
        lane_triangle_chunks_ = 0;
        lane_vertex_chunks_ = 0;
    }

private:
    void refill();
    [[noreturn]] static void destroyed_twice(TriangleId t);

    Mesh* mesh_;
    Mesh::SpareSlots spare_;
    std::uint32_t vertex_block_;
    std::uint32_t vertex_next_ = 0;
    std::uint32_t vertex_end_ = 0;
    bool on_lane_ = false;
    Lane lane_;
    std::uint32_t lane_triangle_chunks_ = 0;  // claimed so far on the lane
    std::uint32_t lane_vertex_chunks_ = 0;
};

}  // namespace gpdr::mesh
