#pragma once
// An independent check of a mesh written by gpdr or Triangle against the
// PSLG it was made from (through ExactDomain, never through gpdr's own
// checker).  A mesh is right when:
//  - its triangles are counter-clockwise (exact orient2d) and no two share a
//    directed edge, and no two vertices that triangles use coincide;
//  - its area equals the domain's, each region's area carries the region's
//    attribute (with -A), and no hole point lies inside a triangle;
//  - every boundary edge and every output segment lies on an input segment
//    (or, with -c, on an edge of the convex hull);
//  - every input vertex of the domain is a mesh vertex, and every edge of
//    the domain's arrangement is covered by a chain of mesh edges;
//  - with a minimum angle, every angle below it is at a vertex where input
//    segments meet at less than 60 degrees, or opposite an edge whose ends
//    lie on two input segments that meet at less than 60 degrees, at equal
//    distances from where they meet (Ruppert's algorithm, as Triangle runs
//    it, leaves both), except in as many
//    triangles as the mesher reported it left because of floating-point
//    precision.
// "Lies on" allows rounding: a vertex is on a segment when its distance from
// it is at most 16 machine epsilons of the input's largest coordinate, which
// holds a correctly rounded crossing point or a rounded split point and is
// far below any distance between distinct points of these inputs.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <gpdr/files.hpp>

#include "stress/exact_domain.hpp"

namespace gpdr::stress {

struct WrittenMesh {
    std::vector<double> xy;                // x0, y0, x1, y1, ...
    std::vector<std::uint32_t> triangles;  // 3 corners per triangle, 0-based
    std::vector<double> attributes;        // first triangle attribute, or empty
    std::vector<std::uint32_t> segments;   // 2 per output segment, 0-based
};

// Reads stem.node, stem.ele and, when it exists, stem.poly.  Throws
// gpdr::InputError when a file is malformed.
WrittenMesh read_written_mesh(const std::string& stem);

struct CheckSettings {
    double min_angle = 0;  // degrees; 0: no angle bound
    std::size_t left_by_precision = 0;
    bool attributes = false;  // -A: check region attributes
    // Excuse small angles opposite an edge that spans a sharp input angle
    // (see above); false counts them as wrong.
    bool excuse_spanning_edges = true;
};

// The problems found, one sentence each (at most a few per kind); empty when
// the mesh is right.
std::vector<std::string> check_mesh(const PolyFile& input, const ExactDomain& domain,
                                    const WrittenMesh& mesh, const CheckSettings& settings);

}  // namespace gpdr::stress
