#pragma once
// Insertion order for incremental Delaunay: biased randomized insertion
// order (BRIO, Amenta, Choi & Rote 2003) with a Hilbert curve order inside
// each round.
//
// Each point falls in round r with probability 2^-(r+1) (the last rounds
// hold half, a quarter, ... of the points), decided by a hash of its index,
// so the order is reproducible and needs no shuffle.  Rounds are inserted
// from the smallest to the largest; inside a round, points follow a Hilbert
// curve over a 2^16 x 2^16 grid on the bounding box, so each point is found
// by a short walk from the one before.  The randomness between rounds keeps
// the expected O(n log n) bound of randomized insertion; the curve order
// makes the walks short and the memory access local.

#include <cstdint>
#include <span>
#include <vector>

#include "geometry/point.hpp"

namespace gpdr::triangulate {

// Indices 0..n-1 of `points` in insertion order.  Coordinates must be finite.
// On `threads` threads, the same order.
std::vector<std::uint32_t> brio_order(std::span<const geometry::Point> points,
                                      std::uint64_t seed = 0, unsigned threads = 1);

// Position of cell (x, y) of a 2^16 x 2^16 grid along the Hilbert curve.
std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y);

}  // namespace gpdr::triangulate
