#pragma once
// Helpers shared by the mesh and triangulate tests: building a mesh from an
// explicit triangle list, a canonical form for comparing meshes, and random
// point sets.

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "geometry/point.hpp"
#include "mesh/mesh.hpp"
#include "mesh/pool.hpp"
#include "mesh/traverse.hpp"

namespace gpdr::mesh::testing {

using Tri = std::array<std::uint32_t, 3>;

// A mesh with these points (ids = indices) and triangles (counter-clockwise
// corner indices); neighbours are linked through shared edges.
inline Mesh mesh_from_triangles(const std::vector<Point>& points,
                                const std::vector<Tri>& triangles) {
    Mesh mesh;
    mesh.add_vertices(points, VertexKind::input);
    Pool pool(mesh);
    std::map<std::pair<std::uint32_t, std::uint32_t>, EdgeRef>
        by_edge;  // directed edge -> its triangle edge
    for (const Tri& t : triangles) {
        const TriangleId id = pool.create(VertexId{t[0]}, VertexId{t[1]}, VertexId{t[2]});
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t from = t[static_cast<std::size_t>(next3(k))];
            const std::uint32_t to = t[static_cast<std::size_t>(prev3(k))];
            by_edge[{from, to}] = EdgeRef(id, k);
            if (auto it = by_edge.find({to, from}); it != by_edge.end())
                mesh.link(EdgeRef(id, k), it->second);
        }
    }
    return mesh;
}

// Each live triangle rotated to start at its smallest vertex; sorted.
inline std::vector<Tri> canonical(const Mesh& mesh) {
    std::vector<Tri> out;
    for_each_triangle(mesh, [&](TriangleId, const Triangle& t) {
        Tri r{index(t.v[0]), index(t.v[1]), index(t.v[2])};
        std::rotate(r.begin(), std::min_element(r.begin(), r.end()), r.end());
        out.push_back(r);
    });
    std::sort(out.begin(), out.end());
    return out;
}

inline std::vector<Point> uniform_points(std::size_t n, std::uint32_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Point> p(n);
    for (auto& q : p) q = {u(rng), u(rng)};
    return p;
}

// The triangle of `mesh` whose corner set is {a, b, c}, or no_triangle.
inline TriangleId find_triangle(const Mesh& mesh, std::uint32_t a, std::uint32_t b,
                                std::uint32_t c) {
    TriangleId found = no_triangle;
    for_each_triangle(mesh, [&](TriangleId id, const Triangle& t) {
        std::array<std::uint32_t, 3> x{index(t.v[0]), index(t.v[1]), index(t.v[2])}, y{a, b, c};
        std::sort(x.begin(), x.end());
        std::sort(y.begin(), y.end());
        if (x == y) found = id;
    });
    return found;
}

// The edge of live triangle `t` from vertex a to vertex b.
inline EdgeRef edge_of(const Mesh& mesh, TriangleId t, std::uint32_t a, std::uint32_t b) {
    const Triangle& r = mesh.triangle(t);
    for (int k = 0; k < 3; ++k)
        if (index(r.v[next3(k)]) == a && index(r.v[prev3(k)]) == b) return EdgeRef(t, k);
    return EdgeRef::none();
}

}  // namespace gpdr::mesh::testing
