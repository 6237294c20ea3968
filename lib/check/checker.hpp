#pragma once
// The invariant checker (docs/architecture.md: tests run it after every operation in
// small cases; -C runs it on the result, as Triangle's -C does).  The check
// layer sits just above mesh, so that the tests of every layer that makes
// meshes can run it; it keeps the namespace of what it checks, gpdr::mesh.
//
// It checks, for every live triangle:
//   topology     corners are distinct stored vertices (no ghost), neighbour
//                links are symmetric, point at live triangles, and the shared
//                edge has the same two vertices (reversed) on both sides;
//   orientation  corners strictly counter-clockwise (exact orient2d);
//   Delaunay     every edge that is not a subsegment is locally Delaunay:
//                the opposite apex is not strictly inside the circumcircle
//                (exact incircle), which makes the mesh constrained Delaunay;
//   subsegments  the flag agrees on both sides of an edge and, optionally,
//                the flagged edges are exactly the side table's entries.
// Segment conformity (every input segment is a union of subsegments) needs
// the input segments and belongs to the CDT's checks.
//
// It never prints and never throws on a broken mesh: it returns the problems
// found, each a sentence naming triangles and vertices (at most
// `max_problems`, then one line saying how many more).

#include <cstddef>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace gpdr::mesh {

struct CheckOptions {
    bool delaunay = true;
    bool subsegment_table = true;
    std::size_t max_problems = 100;
    int base = 0;          // added to triangle and vertex ids in the problems
    unsigned threads = 1;  // slices of the triangles checked side by side
};

std::vector<std::string> check_mesh(const Mesh& mesh, const CheckOptions& options = {});

}  // namespace gpdr::mesh
