#pragma once
// The mesh: vertex store, triangle store and subsegment side table.
//
// Everything is addressed by ids (ids.hpp) into never-moving storage
// (reserved_table.hpp).  Triangles are created and destroyed only through a Pool
// (pool.hpp), which a thread owns; Mesh itself only hands out fresh chunks and
// takes back what a finished pool did not use.  Vertices are never removed;
// their ids are claimed in ranges (several threads may claim at once).
//
// Sizes: a triangle is 32 bytes (triangle.hpp); a vertex is 16 bytes of
// coordinates plus 1 byte of kind.  Attributes and markers of vertices live in
// side arrays owned by the caller, indexed by VertexId.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "geometry/point.hpp"
#include "mesh/ids.hpp"
#include "mesh/reserved_table.hpp"
#include "mesh/subsegments.hpp"
#include "mesh/triangle.hpp"
#include "mesh/vertex_attributes.hpp"

namespace gpdr::mesh {

using geometry::Point;

// What a vertex is.  `unused` marks ids claimed but never filled (a pool's
// unfinished block) and is what a fresh slot reads as.
enum class VertexKind : std::uint8_t {
    unused = 0,
    input,      // an input vertex in the triangulation
    duplicate,  // an input vertex equal to another one, left out of the triangulation
    segment,    // a Steiner point on a segment
    free,       // a Steiner point in the interior
};

class Mesh {
public:
    // Ids are claimed in chunks of 1024: a lane of the parallel refiner
    // claims chunks of its own every round, and leaves the end of its last
    // one unused (reserved_table.hpp).
    static constexpr unsigned triangle_chunk_bits = 10;  // 32 KiB of triangles per chunk
    static constexpr unsigned vertex_chunk_bits = 10;    // 16 KiB of points per chunk
    using TriangleTable =
        ReservedTable<Triangle, triangle_chunk_bits, (max_triangles >> triangle_chunk_bits)>;
    using PointTable = ReservedTable<Point, vertex_chunk_bits, (1u << (32 - vertex_chunk_bits))>;
    using KindTable =
        ReservedTable<VertexKind, vertex_chunk_bits, (1u << (32 - vertex_chunk_bits))>;

    Mesh();
    Mesh(Mesh&& other) noexcept;
    Mesh& operator=(Mesh&& other) noexcept;
    Mesh(const Mesh&) = delete;
    Mesh& operator=(const Mesh&) = delete;
    ~Mesh();

    // ---- vertices ----------------------------------------------------------
    // Claims `count` consecutive vertex ids and returns the first; their kind
    // reads `unused` until set.  Thread-safe.  Throws gpdr::CapacityError past
    // 2^32-2.
    VertexId claim_vertices(std::uint32_t count);
    // Appends points with consecutive ids (the first is returned).
    VertexId add_vertices(std::span<const Point> points, VertexKind kind);
    VertexId add_vertex(const Point& p, VertexKind kind) { return add_vertices({&p, 1}, kind); }

    const Point& point(VertexId v) const { return points_[index(v)]; }
    void set_point(VertexId v, const Point& p) { points_[index(v)] = p; }
    VertexKind kind(VertexId v) const { return kinds_[index(v)]; }
    void set_kind(VertexId v, VertexKind k) { kinds_[index(v)] = k; }
    // Gives back the memory of the points of ids below `end` (whole
    // granules of the table: some just below it may stay), or of all
    // points: for a mesh whose points were copied out and are never read
    // again (api::ArrayChoices::free_points_of).  Reading one of those
    // points afterwards faults.
    void discard_points_below(std::uint32_t end) {
        points_.discard_below(end >> vertex_chunk_bits);
    }
    void discard_points() {
        constexpr std::uint32_t g = PointTable::granule_chunks;
        points_.discard_below((vertex_chunks_claimed() + g - 1) / g * g);
    }
    // One past the largest vertex id claimed so far.
    std::uint32_t vertex_end() const { return vertex_end_.load(std::memory_order_acquire); }

    // Each vertex's attributes (vertex_attributes.hpp); width 0 unless the
    // input has attributes.
    VertexAttributes& attributes() { return attributes_; }
    const VertexAttributes& attributes() const { return attributes_; }

    // ---- triangles ---------------------------------------------------------
    Triangle& triangle(TriangleId t) { return triangles_[index(t)]; }
    const Triangle& triangle(TriangleId t) const { return triangles_[index(t)]; }
    // The neighbour reference across edge e (EdgeRef::none() on the hull).
    EdgeRef neighbour(EdgeRef e) const { return triangle(e.triangle()).n[e.edge()]; }
    // Makes a and b neighbours of each other; either may be none.
    void link(EdgeRef a, EdgeRef b) {
        if (!a.is_none()) triangle(a.triangle()).n[a.edge()] = b;
        if (!b.is_none()) triangle(b.triangle()).n[b.edge()] = a;
    }
    // Edge e runs from origin to destination; apex is the corner opposite.
    VertexId origin(EdgeRef e) const { return triangle(e.triangle()).v[next3(e.edge())]; }
    VertexId destination(EdgeRef e) const { return triangle(e.triangle()).v[prev3(e.edge())]; }
    VertexId apex(EdgeRef e) const { return triangle(e.triangle()).v[e.edge()]; }

    // One past the largest triangle id ever handed out; ids below it are
    // live or dead slots (Triangle::live()).
    std::uint32_t triangle_end() const {
        return triangle_chunks_.load(std::memory_order_acquire) << triangle_chunk_bits;
    }
    // Live triangles, counted by a pass over the store (O(slots)).
    std::size_t count_triangles() const;

    // ---- subsegments -------------------------------------------------------
    SubsegmentTable& subsegments() { return subsegments_; }
    const SubsegmentTable& subsegments() const { return subsegments_; }

    // Bytes held by the vertex and triangle stores (not the side table).
    std::size_t triangle_store_bytes() const { return triangles_.bytes(); }
    std::size_t vertex_store_bytes() const { return points_.bytes() + kinds_.bytes(); }

    // ---- ids by a fixed rule (Pool's lanes) -------------------------------
    // The deterministic parallel refiner gives each of its lanes chunks of
    // ids by a rule that depends on the lane alone (pool.hpp), so that the
    // ids a lane hands out never depend on which thread claimed first.  Ids
    // then have holes: whole chunks nobody claimed (they read as dead
    // triangles and unused vertices: reserved_table.hpp), and the unused end of each
    // lane's last chunk.
    //
    // The first triangle chunk and the first vertex chunk above every id
    // claimed so far.
    std::uint32_t triangle_chunks_claimed() const {
        return triangle_chunks_.load(std::memory_order_acquire);
    }
    std::uint32_t vertex_chunks_claimed() const {
        return static_cast<std::uint32_t>((std::uint64_t{vertex_end()} + PointTable::chunk_mask) >>
                                          vertex_chunk_bits);
    }
    // The holes: the chunks below the first above every id claimed that no
    // one claimed, ascending, as found by the last refresh_holes() (which
    // must not run while a pool claims ids).  The lanes of the next round
    // claim them first (pool.hpp).
    void refresh_holes();
    std::span<const std::uint32_t> triangle_holes() const { return triangle_holes_; }
    std::span<const std::uint32_t> vertex_holes() const { return vertex_holes_; }
    struct SpareSlots;
    // Claims triangle chunk c (its slots, as claim_triangle_chunk gives them)
    // or vertex chunk c (its ids; the first is returned).  Thread-safe;
    // throws gpdr::CapacityError past the limits on ids.
    SpareSlots claim_triangle_chunk_at(std::uint32_t c);
    VertexId claim_vertex_chunk_at(std::uint32_t c);
    // Whether chunk c holds ids anyone claimed (a pass over all ids may skip
    // the others).
    bool has_triangle_chunk(std::uint32_t c) const { return triangles_.has_chunk(c); }
    bool has_vertex_chunk(std::uint32_t c) const { return kinds_.has_chunk(c); }
    // How many ids of chunk c, from its first, were ever handed out, as far
    // as the mesh knows: the whole chunk, unless the pool that held its end
    // gave that end back unused and nobody took it again (each lane's last
    // chunks).  Passes over the ids stop there: on many lanes, those unused
    // ends are millions of slots.  Read them only while no pool is being
    // destroyed.
    std::uint32_t triangle_chunk_used(std::uint32_t c) const {
        return TriangleTable::chunk_size - (c < triangle_tails_.size() ? triangle_tails_[c] : 0);
    }
    std::uint32_t vertex_chunk_used(std::uint32_t c) const {
        return PointTable::chunk_size - (c < vertex_tails_.size() ? vertex_tails_[c] : 0);
    }

    // ---- for Pool only -----------------------------------------------------
    // Triangle slots a pool owns and has not used: an intrusive free list
    // (linked through n[0] of dead slots) and a fresh range [fresh, fresh_end).
    struct SpareSlots {
        std::uint32_t free_head = index(no_triangle);
        std::uint32_t fresh = 0;
        std::uint32_t fresh_end = 0;
    };
    // Claims a fresh chunk of triangle slots.  Thread-safe, lock-free.
    SpareSlots claim_triangle_chunk();
    // A finished pool gives back what it did not use; a new pool takes it.
    // (Mutex: called once per pool lifetime, never in the hot path.)
    void give_back(const SpareSlots& spare);
    bool take_back(SpareSlots& spare);
    // A finished pool returns the unused tail [next, end) of its vertex
    // block; it is taken back only if it is still the last block claimed.
    // Otherwise, when the tail ends its chunk, the chunk's used part
    // (vertex_chunk_used) ends at `next`.
    void give_back_vertices(std::uint32_t next, std::uint32_t end);

private:
    // Gives the tables their address ranges, at the first claim of an id:
    // an empty mesh (a placeholder, moved into later) holds none.
    void reserve_tables() {
        std::call_once(*reserve_once_, [this] { reserve_tables_now(); });
    }
    void reserve_tables_now();

    TriangleTable triangles_;
    PointTable points_;
    KindTable kinds_;
    VertexAttributes attributes_;
    std::atomic<std::uint32_t> triangle_chunks_{0};
    std::atomic<std::uint32_t> vertex_end_{0};
    SubsegmentTable subsegments_;
    std::unique_ptr<std::once_flag> reserve_once_;
    std::unique_ptr<std::mutex> spare_mutex_;
    std::vector<SpareSlots> spares_;
    // Per chunk, the ids at its end that no pool used (0 where unknown),
    // written under spare_mutex_: triangle_chunk_used, vertex_chunk_used.
    std::vector<std::uint32_t> triangle_tails_;
    std::vector<std::uint32_t> vertex_tails_;
    // The holes, and the chunk their lists were complete up to.
    std::vector<std::uint32_t> triangle_holes_, vertex_holes_;
    std::uint32_t triangle_holes_end_ = 0, vertex_holes_end_ = 0;
};

}  // namespace gpdr::mesh
