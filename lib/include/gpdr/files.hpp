#pragma once
// In-memory forms of Triangle's files.  Indices are always stored 0-based;
// the numbering base a file used (0 or 1) is kept beside the data so that
// output can use it again, as Triangle does.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gpdr {

// A list of vertices: .node, or the vertex section of .poly.
struct NodeSet {
    std::vector<double> xy;  // x0, y0, x1, y1, ...
    std::uint32_t attribute_count = 0;
    std::vector<double> attributes;  // size() * attribute_count
    std::vector<int> markers;        // empty: the file had no markers

    std::size_t size() const noexcept { return xy.size() / 2; }
    bool has_markers() const noexcept { return !markers.empty(); }
};

// Segments of a .poly, or edges of an .edge file.
struct SegmentSet {
    std::vector<std::uint32_t> endpoints;  // 2 per segment, 0-based
    std::vector<int> markers;              // empty: no markers

    std::size_t size() const noexcept { return endpoints.size() / 2; }
    bool has_markers() const noexcept { return !markers.empty(); }
};
using EdgeSet = SegmentSet;

// A region line of a .poly: a point inside the region, its attribute, and
// its area bound (negative: no bound).
struct Region {
    double x = 0, y = 0;
    double attribute = 0;
    double max_area = -1;
};

struct PolyFile {
    NodeSet nodes;                      // read from the .node file when the .poly's count is 0
    bool nodes_from_node_file = false;  // ... as it was then (output: write the count 0)
    SegmentSet segments;
    std::vector<double> holes;  // x0, y0, x1, y1, ...
    std::vector<Region> regions;
};

// Triangles of an .ele file.
struct EleSet {
    std::uint32_t corners_per_triangle = 3;  // 3 or 6
    std::vector<std::uint32_t> corners;      // corners_per_triangle per triangle, 0-based
    std::uint32_t attribute_count = 0;
    std::vector<double> attributes;  // size() * attribute_count

    std::size_t size() const noexcept {
        return corners_per_triangle == 0 ? 0 : corners.size() / corners_per_triangle;
    }
};

// Neighbours of a .neigh file: 3 per triangle, neighbour k opposite corner k.
struct NeighbourSet {
    static constexpr std::uint32_t none = 0xffffffffu;  // written as -1
    std::vector<std::uint32_t> neighbours;              // 3 per triangle, 0-based
    std::size_t size() const noexcept { return neighbours.size() / 3; }
};

// Per-triangle area bounds of an .area file (<= 0: no bound).
using AreaSet = std::vector<double>;

}  // namespace gpdr
