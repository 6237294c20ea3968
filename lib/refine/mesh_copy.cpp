// A copy of a mesh (see mesh_copy.hpp).

#include "refine/mesh_copy.hpp"

#include <vector>

namespace gpdr::refine {

namespace {

void copy_vertices(const mesh::Mesh& from, mesh::Mesh& to) {
    const std::uint32_t end = from.vertex_end();
    const std::uint32_t chunks = from.vertex_chunks_claimed();
    for (std::uint32_t c = 0; c < chunks; ++c) {
        if (!from.has_vertex_chunk(c)) continue;
        const std::uint32_t first = mesh::index(to.claim_vertex_chunk_at(c));
        const std::uint32_t last = std::min(end, first + mesh::Mesh::PointTable::chunk_size);
        for (std::uint32_t i = first; i < last; ++i) {
            const mesh::VertexId v{i};
            to.set_point(v, from.point(v));
            to.set_kind(v, from.kind(v));
        }
    }
    // The last chunk was claimed whole: its ids past `end` go back.
    to.give_back_vertices(end, to.vertex_end());

    const mesh::VertexAttributes& rows = from.attributes();
    if (rows.width() == 0) return;
    to.attributes() = mesh::VertexAttributes(rows.width());
    for (std::uint32_t i = 0; i < end; ++i) {
        const mesh::VertexId v{i};
        if (!rows.has_row(v)) continue;
        const auto row = rows.row(v);
        const auto into = to.attributes().write(v);
        for (std::size_t k = 0; k < row.size(); ++k) into[k] = row[k];
    }
}

void copy_triangles(const mesh::Mesh& from, mesh::Mesh& to) {
    constexpr std::uint32_t size = mesh::Mesh::TriangleTable::chunk_size;
    const std::uint32_t chunks = from.triangle_chunks_claimed();
    for (std::uint32_t c = 0; c < chunks; ++c) {
        if (!from.has_triangle_chunk(c)) continue;
        to.claim_triangle_chunk_at(c);  // its slots come with the spares below
        for (std::uint32_t i = c * size; i < (c + 1) * size; ++i)
            to.triangle(mesh::TriangleId{i}) = from.triangle(mesh::TriangleId{i});
    }
    from.subsegments().for_each(
        [&](mesh::VertexId a, mesh::VertexId b, const mesh::SubsegmentInfo& info) {
            to.subsegments().set(a, b, info);
        });
}

}  // namespace

mesh::Mesh copy_mesh(mesh::Mesh& from) {
    mesh::Mesh to;
    copy_vertices(from, to);
    copy_triangles(from, to);
    // The spare slots the next pool takes, in the same order in both (a
    // pool takes the newest first).
    std::vector<mesh::Mesh::SpareSlots> spares;
    for (mesh::Mesh::SpareSlots s; from.take_back(s);) spares.push_back(s);
    for (auto s = spares.rbegin(); s != spares.rend(); ++s) {
        from.give_back(*s);
        to.give_back(*s);
    }
    return to;
}

}  // namespace gpdr::refine
