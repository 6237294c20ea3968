#pragma once
// Strong index types of the mesh and the packed neighbour reference.
//
// A triangle is addressed by a TriangleId; one of its three edges by an
// EdgeRef, which packs the triangle id and the edge index 0..2 in one 32-bit
// word (id * 4 + edge), so a neighbour link costs four bytes and following
// it needs no second lookup to know which edge of the neighbour faces back.
// Ids are slot numbers in the never-moving store (store.hpp): they stay
// valid while other threads allocate.

#include <cstdint>

namespace gpdr::mesh {

enum class VertexId : std::uint32_t {};
enum class TriangleId : std::uint32_t {};

constexpr std::uint32_t index(VertexId v) { return static_cast<std::uint32_t>(v); }
constexpr std::uint32_t index(TriangleId t) { return static_cast<std::uint32_t>(t); }

// No vertex at all (an unset field).
inline constexpr VertexId no_vertex{0xFFFFFFFFu};
// The symbolic vertex "at infinity" that ghost triangles share while a point
// set is being triangulated (triangulate/delaunay.cpp).  It has no
// coordinates; the insertion code recognises it.  A finished mesh never
// contains it.
inline constexpr VertexId ghost_vertex{0xFFFFFFFEu};
inline constexpr TriangleId no_triangle{0xFFFFFFFFu};

// Largest number of triangle slots: the packed reference keeps 30 bits.
inline constexpr std::uint32_t max_triangles = 1u << 30;

// Edge index arithmetic.  Edge k of a triangle is opposite its corner k and
// runs from corner k+1 to corner k+2 (indices mod 3), counter-clockwise.
constexpr int next3(int k) { return k == 2 ? 0 : k + 1; }
constexpr int prev3(int k) { return k == 0 ? 2 : k - 1; }

// Edge `edge` of triangle `triangle`, packed; `none` is the outside of the
// mesh (a hull edge's missing neighbour).
class EdgeRef {
public:
    constexpr EdgeRef() = default;
    constexpr EdgeRef(TriangleId t, int edge)
        : bits_(index(t) * 4u + static_cast<std::uint32_t>(edge)) {}

    static constexpr EdgeRef none() { return EdgeRef(); }
    static constexpr EdgeRef from_bits(std::uint32_t bits) {
        EdgeRef r;
        r.bits_ = bits;
        return r;
    }

    constexpr bool is_none() const { return bits_ == none_bits; }
    constexpr TriangleId triangle() const { return TriangleId{bits_ >> 2}; }
    constexpr int edge() const { return static_cast<int>(bits_ & 3u); }
    constexpr std::uint32_t bits() const { return bits_; }
    // The next / previous edge of the same triangle (counter-clockwise).
    constexpr EdgeRef next() const { return EdgeRef(triangle(), next3(edge())); }
    constexpr EdgeRef prev() const { return EdgeRef(triangle(), prev3(edge())); }

    friend constexpr bool operator==(EdgeRef, EdgeRef) = default;

private:
    static constexpr std::uint32_t none_bits = 0xFFFFFFFFu;
    std::uint32_t bits_ = none_bits;
};

static_assert(EdgeRef(TriangleId{5}, 2).triangle() == TriangleId{5});
static_assert(EdgeRef(TriangleId{5}, 2).edge() == 2);
static_assert(EdgeRef(TriangleId{5}, 2).next().edge() == 0);
static_assert(EdgeRef::none().is_none() && !EdgeRef(TriangleId{0}, 0).is_none());

}  // namespace gpdr::mesh
