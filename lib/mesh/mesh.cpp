// Mesh: the chunked stores' bookkeeping (claiming vertex ranges and triangle
// chunks, taking back what finished pools did not use).

#include "mesh/mesh.hpp"
#include "mesh/traverse.hpp"

#include <string>
#include <utility>

#include <sys/mman.h>

#include <gpdr/errors.hpp>

namespace gpdr::mesh {

Mesh::Mesh()
    : reserve_once_(std::make_unique<std::once_flag>()),
      spare_mutex_(std::make_unique<std::mutex>()) {}

// The tables' address ranges: all of them (100 GiB, none of it memory until
// used) when the process may map that much.  Under a limit on address space
// (`ulimit -v`, valgrind) the mesh takes half of the largest range that can
// be mapped, leaving the rest to everything else, shared by what a vertex
// costs: two triangles (64 bytes), its point (16) and its kind (1).
void Mesh::reserve_tables_now() {
    constexpr std::size_t full =
        std::size_t{TriangleTable::max_chunks} * TriangleTable::chunk_bytes +
        std::size_t{PointTable::max_chunks} * PointTable::chunk_bytes +
        std::size_t{KindTable::max_chunks} * KindTable::chunk_bytes;
    auto can_map = [](std::size_t length) {
        void* p =
            mmap(nullptr, length, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
        if (p == MAP_FAILED) return false;
        munmap(p, length);
        return true;
    };
    std::uint32_t triangle_chunks = TriangleTable::max_chunks;
    std::uint32_t vertex_chunks = PointTable::max_chunks;
    if (!can_map(full)) {
        std::size_t largest = full / 2;
        while (largest > (std::size_t{1} << 20) && !can_map(largest)) largest /= 2;
        const std::size_t vertices = largest / 2 / (2 * sizeof(Triangle) + sizeof(Point) + 1);
        triangle_chunks = static_cast<std::uint32_t>(((2 * vertices) >> triangle_chunk_bits) + 1);
        vertex_chunks = static_cast<std::uint32_t>((vertices >> vertex_chunk_bits) + 1);
    }
    triangles_.reserve(triangle_chunks);
    points_.reserve(vertex_chunks);
    kinds_.reserve(vertex_chunks);
}

Mesh::~Mesh() = default;

Mesh::Mesh(Mesh&& other) noexcept
    : triangles_(std::move(other.triangles_)),
      points_(std::move(other.points_)),
      kinds_(std::move(other.kinds_)),
      attributes_(std::move(other.attributes_)),
      triangle_chunks_(other.triangle_chunks_.load()),
      vertex_end_(other.vertex_end_.load()),
      subsegments_(std::move(other.subsegments_)),
      reserve_once_(std::move(other.reserve_once_)),
      spare_mutex_(std::move(other.spare_mutex_)),
      spares_(std::move(other.spares_)),
      triangle_tails_(std::move(other.triangle_tails_)),
      vertex_tails_(std::move(other.vertex_tails_)),
      triangle_holes_(std::move(other.triangle_holes_)),
      vertex_holes_(std::move(other.vertex_holes_)),
      triangle_holes_end_(std::exchange(other.triangle_holes_end_, 0)),
      vertex_holes_end_(std::exchange(other.vertex_holes_end_, 0)) {
    other.triangle_chunks_ = 0;
    other.vertex_end_ = 0;
}

Mesh& Mesh::operator=(Mesh&& other) noexcept {
    if (this != &other) {
        triangles_ = std::move(other.triangles_);
        points_ = std::move(other.points_);
        kinds_ = std::move(other.kinds_);
        attributes_ = std::move(other.attributes_);
        triangle_chunks_ = other.triangle_chunks_.load();
        vertex_end_ = other.vertex_end_.load();
        subsegments_ = std::move(other.subsegments_);
        reserve_once_ = std::move(other.reserve_once_);
        spare_mutex_ = std::move(other.spare_mutex_);
        spares_ = std::move(other.spares_);
        triangle_tails_ = std::move(other.triangle_tails_);
        vertex_tails_ = std::move(other.vertex_tails_);
        triangle_holes_ = std::move(other.triangle_holes_);
        vertex_holes_ = std::move(other.vertex_holes_);
        triangle_holes_end_ = std::exchange(other.triangle_holes_end_, 0);
        vertex_holes_end_ = std::exchange(other.vertex_holes_end_, 0);
        other.triangle_chunks_ = 0;
        other.vertex_end_ = 0;
    }
    return *this;
}

VertexId Mesh::claim_vertices(std::uint32_t count) {
    // Two ids are reserved (ghost_vertex, no_vertex).
    constexpr std::uint64_t limit = index(ghost_vertex);
    std::uint32_t first = vertex_end_.load(std::memory_order_relaxed);
    do {
        if (std::uint64_t{first} + count > limit)
            throw CapacityError("mesh: more than " + std::to_string(limit) + " vertices");
    } while (!vertex_end_.compare_exchange_weak(first, first + count, std::memory_order_acq_rel));
    if (count > 0) {
        reserve_tables();
        const std::uint32_t last = first + count - 1;
        for (std::uint32_t c = first >> vertex_chunk_bits; c <= last >> vertex_chunk_bits; ++c) {
            points_.ensure(c);
            kinds_.ensure(c);
        }
    }
    return VertexId{first};
}

VertexId Mesh::add_vertices(std::span<const Point> points, VertexKind kind) {
    if (points.size() > index(ghost_vertex))
        throw CapacityError("mesh: more than " + std::to_string(index(ghost_vertex)) + " vertices");
    const VertexId first = claim_vertices(static_cast<std::uint32_t>(points.size()));
    std::uint32_t v = index(first);
    for (const Point& p : points) {
        points_[v] = p;
        kinds_[v] = kind;
        ++v;
    }
    return first;
}

std::size_t Mesh::count_triangles() const {
    std::size_t live = 0;
    for_each_triangle(*this, [&live](TriangleId, const Triangle&) { ++live; });
    return live;
}

Mesh::SpareSlots Mesh::claim_triangle_chunk() {
    const std::uint32_t c = triangle_chunks_.fetch_add(1, std::memory_order_acq_rel);
    if (c >= TriangleTable::max_chunks) {
        triangle_chunks_.fetch_sub(1, std::memory_order_acq_rel);
        throw CapacityError("mesh: more than " + std::to_string(max_triangles) + " triangles");
    }
    reserve_tables();
    triangles_.ensure(c);
    SpareSlots s;
    s.fresh = c << triangle_chunk_bits;
    s.fresh_end = s.fresh + TriangleTable::chunk_size;
    return s;
}

namespace {

// Raises `end` to at least `value`.
void raise_to(std::atomic<std::uint32_t>& end, std::uint32_t value) {
    std::uint32_t now = end.load(std::memory_order_relaxed);
    while (now < value && !end.compare_exchange_weak(now, value, std::memory_order_acq_rel)) {}
}

}  // namespace

Mesh::SpareSlots Mesh::claim_triangle_chunk_at(std::uint32_t c) {
    if (c >= TriangleTable::max_chunks)
        throw CapacityError("mesh: more than " + std::to_string(max_triangles) + " triangles");
    reserve_tables();
    triangles_.ensure(c);
    raise_to(triangle_chunks_, c + 1);
    SpareSlots s;
    s.fresh = c << triangle_chunk_bits;
    s.fresh_end = s.fresh + TriangleTable::chunk_size;
    return s;
}

VertexId Mesh::claim_vertex_chunk_at(std::uint32_t c) {
    // The last chunk holds the two reserved ids (ghost_vertex, no_vertex).
    constexpr std::uint64_t limit = index(ghost_vertex);
    const std::uint64_t end = (std::uint64_t{c} + 1) << vertex_chunk_bits;
    if (end > limit) throw CapacityError("mesh: more than " + std::to_string(limit) + " vertices");
    reserve_tables();
    points_.ensure(c);
    kinds_.ensure(c);
    raise_to(vertex_end_, static_cast<std::uint32_t>(end));
    return VertexId{c << vertex_chunk_bits};
}

namespace {

// The holes below `end` among chunks for which claimed(c) tells: those of
// `holes` still unclaimed, then the unclaimed ones from `scanned` on.
template <class Claimed>
void refresh(std::vector<std::uint32_t>& holes, std::uint32_t& scanned, std::uint32_t end,
             const Claimed& claimed) {
    std::erase_if(holes, claimed);
    for (std::uint32_t c = scanned; c < end; ++c)
        if (!claimed(c)) holes.push_back(c);
    if (end > scanned) scanned = end;
}

}  // namespace

void Mesh::refresh_holes() {
    refresh(triangle_holes_, triangle_holes_end_, triangle_chunks_claimed(),
            [this](std::uint32_t c) { return triangles_.has_chunk(c); });
    refresh(vertex_holes_, vertex_holes_end_, vertex_chunks_claimed(),
            [this](std::uint32_t c) { return kinds_.has_chunk(c); });
}

namespace {

// Records that the last `tail` ids of chunk c were never used (0: none
// known), growing the table as needed.
void set_tail(std::vector<std::uint32_t>& tails, std::uint32_t c, std::uint32_t tail) {
    if (c >= tails.size()) {
        if (tail == 0) return;
        tails.resize(std::size_t{c} + 1, 0);
    }
    tails[c] = tail;
}

}  // namespace

void Mesh::give_back(const SpareSlots& spare) {
    if (spare.free_head == index(no_triangle) && spare.fresh == spare.fresh_end) return;
    std::lock_guard lock(*spare_mutex_);
    spares_.push_back(spare);
    // A fresh range runs to the end of its chunk (claim_triangle_chunk).
    if (spare.fresh < spare.fresh_end && (spare.fresh_end & TriangleTable::chunk_mask) == 0)
        set_tail(triangle_tails_, spare.fresh >> triangle_chunk_bits,
                 spare.fresh_end - spare.fresh);
}

bool Mesh::take_back(SpareSlots& spare) {
    std::lock_guard lock(*spare_mutex_);
    if (spares_.empty()) return false;
    spare = spares_.back();
    spares_.pop_back();
    // Its fresh slots may be used again.
    if (spare.fresh < spare.fresh_end)
        set_tail(triangle_tails_, spare.fresh >> triangle_chunk_bits, 0);
    return true;
}

void Mesh::give_back_vertices(std::uint32_t next, std::uint32_t end) {
    if (next >= end) return;
    std::uint32_t expected = end;
    if (vertex_end_.compare_exchange_strong(expected, next, std::memory_order_acq_rel)) return;
    // Ids below vertex_end_ are never claimed again: a tail that ends its
    // chunk stays unused.
    const std::uint32_t c = next >> vertex_chunk_bits;
    if ((end & PointTable::chunk_mask) == 0 && ((end - 1) >> vertex_chunk_bits) == c) {
        std::lock_guard lock(*spare_mutex_);
        set_tail(vertex_tails_, c, end - next);
    }
}

}  // namespace gpdr::mesh
