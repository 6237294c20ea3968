#pragma once
// The 2-2 edge flip (Lawson): replace the diagonal of a convex quadrilateral
// by the other one.  Used by Lawson's algorithm (triangulate/lawson.hpp) and
// by the repairs after a subsegment split (split_subsegment.hpp);
// Bowyer–Watson insertion does not need it.
//
/*
            c                         c
           /|\                       / \
          / | \                     /   \
         /  |  \                   /  u  \
        / t | u \                 /       \
       a    |    d      ==>      a---------d
        \   |   /                 \       /
         \  |  /                   \  t  /
          \ | /                     \   /
           \|/                       \ /
            b                         b
*/
//
// Before: t = (a, b, c) in some rotation, and e is its edge b -> c (opposite
// a); u is the triangle across e, apex d.  After: t = (a, b, d) and
// u = (d, c, a), stored with those corners at indices 0, 1, 2, so the new
// diagonal a-d is edge 1 of both.  The four outer edges keep their
// neighbours and subsegment flags; both triangles keep their ids and region
// and get a new generation (queues must treat them as new triangles).
//
// Requires: e has a neighbour, e is not a subsegment, neither triangle is a
// ghost, and abdc is strictly convex (flippable() checks this exactly).

#include "mesh/mesh.hpp"

namespace gpdr::mesh {

// Whether edge e can be flipped (see the contract above).
bool flippable(const Mesh& mesh, EdgeRef e);

// Flips edge e; returns the new diagonal as an edge of the old e.triangle()
// (edge 1, from d to a).
EdgeRef flip(Mesh& mesh, EdgeRef e);

}  // namespace gpdr::mesh
