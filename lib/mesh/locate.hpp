#pragma once
// Point location by walking (Devillers, Pion & Teillaud, "Walking in a
// triangulation", 2002: the remembering stochastic visibility walk).
//
// From the hint, step into the neighbour across any edge that has p strictly
// on its far side (exact orient2d), testing the edges in a random rotation and
// skipping the edge just crossed.  The randomness makes the walk terminate on
// any triangulation, Delaunay or not, whatever the degeneracies; after an
// absurd number of steps it also stops skipping the edge it came through,
// which is the plain stochastic walk, proven to terminate with probability 1.

#include <cstdint>

#include "mesh/mesh.hpp"

namespace gpdr::mesh {

enum class Location : std::uint8_t {
    inside,     // strictly inside `triangle`
    on_edge,    // in the relative interior of edge `index` of `triangle`
    on_vertex,  // equal to corner `index` of `triangle`
    outside,    // beyond edge `index` of `triangle`: that edge has no neighbour
                // (a hull edge), or `triangle` is a ghost and `index` its real edge
};

struct LocateResult {
    TriangleId triangle = no_triangle;
    Location where = Location::inside;
    int index = 0;
};

// Finds where p lies, walking from `hint` (any live triangle, ghosts
// included).  `random_state` is the caller's (per thread) generator state.
LocateResult locate(const Mesh& mesh, const Point& p, TriangleId hint, std::uint32_t& random_state);

}  // namespace gpdr::mesh
