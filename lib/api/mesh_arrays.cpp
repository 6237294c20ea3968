// Output-stage derivations on a finished mesh in array form (see
// mesh_arrays.hpp).  Everything here is linear in the mesh size and touches
// each triangle a constant number of times.

#include "api/mesh_arrays.hpp"

#include <algorithm>
#include <cmath>

namespace gpdr::api {
namespace {

constexpr std::uint32_t none = NeighbourSet::none;

std::uint32_t corner(const MeshArrays& m, std::size_t t, int k) {
    return m.triangles.corners[t * m.triangles.corners_per_triangle + static_cast<std::size_t>(k)];
}

std::uint32_t neighbour(const MeshArrays& m, std::size_t t, int k) {
    return m.neighbours.neighbours[t * 3 + static_cast<std::size_t>(k)];
}

// Edge k of triangle t is listed by t itself when it is on the boundary or
// when t has the smaller index of the two triangles sharing it.
bool lists_edge(const MeshArrays& m, std::size_t t, int k) {
    const std::uint32_t n = neighbour(m, t, k);
    return n == none || n > t;
}

double x_of(const MeshArrays& m, std::uint32_t v) { return m.nodes.xy[2 * std::size_t{v}]; }
double y_of(const MeshArrays& m, std::uint32_t v) { return m.nodes.xy[2 * std::size_t{v} + 1]; }

// The circumcentre of triangle abc written as a + xi (b - a) + eta (c - a),
// which also gives the weights for interpolating attributes there.
struct Circumcentre {
    double x, y, xi, eta;
};

Circumcentre circumcentre_of(const MeshArrays& m, std::size_t t) {
    const auto a = corner(m, t, 0), b = corner(m, t, 1), c = corner(m, t, 2);
    const double xdo = x_of(m, b) - x_of(m, a), ydo = y_of(m, b) - y_of(m, a);
    const double xao = x_of(m, c) - x_of(m, a), yao = y_of(m, c) - y_of(m, a);
    const double dodist = xdo * xdo + ydo * ydo, aodist = xao * xao + yao * yao;
    const double denominator = 2.0 * (xdo * yao - xao * ydo);
    const double dx = (yao * dodist - ydo * aodist) / denominator;
    const double dy = (xdo * aodist - xao * dodist) / denominator;
    // Solve [xdo xao; ydo yao] (xi, eta) = (dx, dy) by Cramer's rule; the
    // determinant is denominator / 2.
    const double det = denominator / 2.0;
    return {x_of(m, a) + dx, y_of(m, a) + dy, (dx * yao - dy * xao) / det,
            (xdo * dy - ydo * dx) / det};
}

}  // namespace

io::EleSource triangle_source(const MeshArrays& mesh) {
    if (mesh.stream) return mesh.stream();
    const EleSet& ele = mesh.triangles;
    const std::uint32_t nc = ele.corners_per_triangle, na = ele.attribute_count;
    return {ele.size(), nc, na,
            [&ele, nc, na, t = std::size_t{0}](std::uint32_t* corners, double* attributes) mutable {
                std::copy_n(&ele.corners[t * nc], nc, corners);
                std::copy_n(ele.attributes.data() + t * na, na, attributes);
                ++t;
            },
            [&ele, nc, na](std::size_t first, std::size_t n, std::uint32_t* corners,
                           double* attributes) {
                std::copy_n(&ele.corners[first * nc], n * nc, corners);
                std::copy_n(ele.attributes.data() + first * na, n * na, attributes);
            }};
}

EdgeSet edges_of(const MeshArrays& mesh, const EdgeMarker& marker) {
    EdgeSet edges;
    const EdgeCounts counts = count_edges(mesh);
    edges.endpoints.reserve(2 * counts.edges);
    edges.markers.reserve(counts.edges);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            if (!lists_edge(mesh, t, k)) continue;
            const auto a = corner(mesh, t, (k + 1) % 3), b = corner(mesh, t, (k + 2) % 3);
            edges.endpoints.push_back(a);
            edges.endpoints.push_back(b);
            edges.markers.push_back(marker(a, b, neighbour(mesh, t, k) == none));
        }
    }
    return edges;
}

EdgeCounts count_edges(const MeshArrays& mesh) {
    EdgeCounts counts;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            if (!lists_edge(mesh, t, k)) continue;
            ++counts.edges;
            if (neighbour(mesh, t, k) == none) ++counts.boundary;
        }
    }
    return counts;
}

VoronoiDiagram voronoi_of(const MeshArrays& mesh) {
    VoronoiDiagram v;
    const std::size_t triangles = mesh.triangles.size();
    const std::uint32_t attributes = mesh.nodes.attribute_count;
    v.vertices.xy.resize(2 * triangles);
    v.vertices.attribute_count = attributes;
    v.vertices.attributes.resize(triangles * attributes);
    for (std::size_t t = 0; t < triangles; ++t) {
        const Circumcentre c = circumcentre_of(mesh, t);
        v.vertices.xy[2 * t] = c.x;
        v.vertices.xy[2 * t + 1] = c.y;
        for (std::uint32_t i = 0; i < attributes; ++i) {
            const auto at = [&](int k) {
                return mesh.nodes.attributes[std::size_t{corner(mesh, t, k)} * attributes + i];
            };
            v.vertices.attributes[t * attributes + i] =
                at(0) + c.xi * (at(1) - at(0)) + c.eta * (at(2) - at(0));
        }
    }
    const EdgeCounts counts = count_edges(mesh);
    v.edges.endpoints.reserve(2 * counts.edges);
    v.edges.directions.reserve(2 * counts.edges);
    for (std::size_t t = 0; t < triangles; ++t) {
        for (int k = 0; k < 3; ++k) {
            if (!lists_edge(mesh, t, k)) continue;
            const std::uint32_t n = neighbour(mesh, t, k);
            v.edges.endpoints.push_back(static_cast<std::uint32_t>(t));
            if (n != none) {
                v.edges.endpoints.push_back(n);
                v.edges.directions.insert(v.edges.directions.end(), {0.0, 0.0});
            } else {
                // The edge a->b is counter-clockwise around t, so the domain
                // is on its left and (dy, -dx) points out of it.
                const auto a = corner(mesh, t, (k + 1) % 3), b = corner(mesh, t, (k + 2) % 3);
                v.edges.endpoints.push_back(io::VoronoiEdgeSet::ray);
                v.edges.directions.push_back(y_of(mesh, b) - y_of(mesh, a));
                v.edges.directions.push_back(x_of(mesh, a) - x_of(mesh, b));
            }
        }
    }
    return v;
}

void make_second_order(MeshArrays& mesh, const EdgeMarker& marker) {
    const std::size_t triangles = mesh.triangles.size();
    const std::uint32_t attributes = mesh.nodes.attribute_count;
    std::vector<std::uint32_t> six(triangles * 6);
    NodeSet& nodes = mesh.nodes;
    const bool markers = nodes.has_markers();
    for (std::size_t t = 0; t < triangles; ++t) {
        for (int k = 0; k < 3; ++k) six[t * 6 + static_cast<std::size_t>(k)] = corner(mesh, t, k);
    }
    for (std::size_t t = 0; t < triangles; ++t) {
        for (int k = 0; k < 3; ++k) {
            if (!lists_edge(mesh, t, k)) continue;
            const auto a = corner(mesh, t, (k + 1) % 3), b = corner(mesh, t, (k + 2) % 3);
            const auto mid = static_cast<std::uint32_t>(nodes.size());
            nodes.xy.push_back((x_of(mesh, a) + x_of(mesh, b)) / 2);
            nodes.xy.push_back((y_of(mesh, a) + y_of(mesh, b)) / 2);
            for (std::uint32_t i = 0; i < attributes; ++i) {
                nodes.attributes.push_back((nodes.attributes[std::size_t{a} * attributes + i] +
                                            nodes.attributes[std::size_t{b} * attributes + i]) /
                                           2);
            }
            const std::uint32_t n = neighbour(mesh, t, k);
            if (markers) nodes.markers.push_back(marker(a, b, n == none));
            six[t * 6 + 3 + static_cast<std::size_t>(k)] = mid;
            if (n != none) {
                // The same edge seen from the neighbour: find which of its
                // corners is opposite it.
                for (int j = 0; j < 3; ++j) {
                    if (neighbour(mesh, n, j) == t && corner(mesh, n, (j + 1) % 3) == b) {
                        six[std::size_t{n} * 6 + 3 + static_cast<std::size_t>(j)] = mid;
                    }
                }
            }
        }
    }
    mesh.triangles.corners = std::move(six);
    mesh.triangles.corners_per_triangle = 6;
}

std::vector<std::uint32_t> jettison_unused_vertices(MeshArrays& mesh) {
    NodeSet& nodes = mesh.nodes;
    std::vector<std::uint32_t> renumber(nodes.size(), none);
    for (const std::uint32_t v : mesh.triangles.corners) renumber[v] = 0;
    const std::uint32_t attributes = nodes.attribute_count;
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < renumber.size(); ++v) {
        if (renumber[v] == none) continue;
        renumber[v] = next;
        nodes.xy[2 * std::size_t{next}] = nodes.xy[2 * v];
        nodes.xy[2 * std::size_t{next} + 1] = nodes.xy[2 * v + 1];
        std::copy_n(
            nodes.attributes.begin() + static_cast<std::ptrdiff_t>(v * attributes), attributes,
            nodes.attributes.begin() + static_cast<std::ptrdiff_t>(std::size_t{next} * attributes));
        if (nodes.has_markers()) nodes.markers[next] = nodes.markers[v];
        ++next;
    }
    nodes.xy.resize(2 * std::size_t{next});
    nodes.attributes.resize(std::size_t{next} * attributes);
    if (nodes.has_markers()) nodes.markers.resize(next);
    for (std::uint32_t& v : mesh.triangles.corners) v = renumber[v];
    // Segments join corners of triangles, which all keep their vertices.
    for (std::uint32_t& v : mesh.segments.endpoints) v = renumber[v];
    for (std::size_t v = 0; v < renumber.size() && v < mesh.mesh_ids.size(); ++v)
        if (renumber[v] != none) mesh.mesh_ids[renumber[v]] = mesh.mesh_ids[v];
    if (mesh.mesh_ids.size() > next) mesh.mesh_ids.resize(next);
    return renumber;
}

}  // namespace gpdr::api
