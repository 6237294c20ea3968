// From the live mesh to the arrays Triangle's files hold: vertices numbered
// input first then the added ones in id order (skipping ids claimed but never
// used), triangles in id order with dead slots skipped, neighbours
// renumbered to match, vertex attributes as the mesh keeps them (interpolated
// where refinement added the vertex) and markers set by Triangle's rules.

#include <algorithm>
#include <string>
#include <tuple>

#include <gpdr/errors.hpp>

#include "api/job_stages.hpp"
#include "mesh/traverse.hpp"

namespace gpdr::api {

EdgeMarker edge_markers(const mesh::Mesh& mesh) {
    return [&mesh](std::uint32_t a, std::uint32_t b, bool boundary) {
        if (const auto* s = mesh.subsegments().find(mesh::VertexId{a}, mesh::VertexId{b});
            s && s->marker != 0)
            return s->marker;
        return boundary ? 1 : 0;
    };
}

namespace {

constexpr std::uint32_t none = NeighbourSet::none;

// An edge of the mesh by its ends' mesh vertex ids (not node numbers).
struct MeshEdge {
    std::uint32_t from = 0, to = 0;
    bool hull = false;  // no triangle on the other side
};

// Numbers by id, for the ids of some chunks only.  Parallel refinement
// claims vertex ids and triangle slots in chunks by a fixed rule
// (mesh/pool.hpp), so ids reach far past the vertices and triangles, with
// whole chunks nobody claimed between: an array over every id would cost
// several times the mesh's count (and as many page faults).  So only the
// chunks that hold ids have numbers (none until set).
template <unsigned Bits>
class ChunkedNumbers {
public:
    static constexpr unsigned bits = Bits;
    static constexpr std::uint32_t mask = (1u << bits) - 1;

    ChunkedNumbers() = default;
    // Chunks 0 .. chunks - 1, those for which has(c) holds.
    template <class Has>
    ChunkedNumbers(std::size_t chunks, const Has& has) : first_(chunks, absent) {
        std::size_t next = 0;
        for (std::uint32_t c = 0; c < chunks; ++c)
            if (has(c)) {
                first_[c] = next;
                next += std::size_t{1} << bits;
            }
        numbers_.assign(next, none);
    }
    // Whether chunk c has numbers.
    bool has_chunk(std::uint32_t c) const { return c < first_.size() && first_[c] != absent; }
    std::uint32_t& operator[](std::uint32_t id) { return numbers_[at(id)]; }
    std::uint32_t operator[](std::uint32_t id) const { return numbers_[at(id)]; }
    const std::uint32_t* address(std::uint32_t id) const { return &numbers_[at(id)]; }

private:
    static constexpr std::size_t absent = ~std::size_t{0};
    std::size_t at(std::uint32_t id) const { return first_[id >> bits] + (id & mask); }
    std::vector<std::size_t> first_;  // per chunk: where its numbers start
    std::vector<std::uint32_t> numbers_;
};

// Mesh vertex id -> node number (the claimed chunks, and the input's).
using VertexNumbers = ChunkedNumbers<mesh::Mesh::vertex_chunk_bits>;
VertexNumbers vertex_numbers(const mesh::Mesh& mesh, std::size_t input_count) {
    const std::size_t chunks = std::max<std::size_t>(
        mesh.vertex_chunks_claimed(), (input_count + VertexNumbers::mask) >> VertexNumbers::bits);
    return VertexNumbers(chunks, [&](std::uint32_t c) {
        return mesh.has_vertex_chunk(c) || (std::size_t{c} << VertexNumbers::bits) < input_count;
    });
}

// Triangle slot -> triangle number (the claimed chunks).
using TriangleNumbers = ChunkedNumbers<mesh::Mesh::triangle_chunk_bits>;
TriangleNumbers triangle_numbers(const mesh::Mesh& mesh) {
    return TriangleNumbers(mesh.triangle_chunks_claimed(),
                           [&](std::uint32_t c) { return mesh.has_triangle_chunk(c); });
}

// Vertex numbers: the input vertices keep theirs (duplicates included, as
// Triangle writes them); added vertices follow, in id order, skipping ids
// claimed but never used.  Fills the coordinates in `nodes` and `mesh_ids`;
// returns each mesh vertex's number (none for the skipped).
VertexNumbers number_vertices(const mesh::Mesh& mesh, std::size_t input_count, NodeSet& nodes,
                              std::vector<std::uint32_t>& mesh_ids) {
    const std::uint32_t vertex_end = mesh.vertex_end();
    nodes.xy.resize(2 * input_count);
    for (std::uint32_t v = 0; v < input_count; ++v) {
        const auto& p = mesh.point(mesh::VertexId{v});
        nodes.xy[2 * std::size_t{v}] = p.x;
        nodes.xy[2 * std::size_t{v} + 1] = p.y;
    }
    VertexNumbers number = vertex_numbers(mesh, input_count);
    mesh_ids.reserve(input_count);
    for (std::uint32_t v = 0; v < input_count; ++v) {
        number[v] = v;
        mesh_ids.push_back(v);
    }
    for (std::uint32_t v = static_cast<std::uint32_t>(input_count); v < vertex_end; ++v) {
        if ((v & VertexNumbers::mask) == 0 && !number.has_chunk(v >> VertexNumbers::bits)) {
            v |= VertexNumbers::mask;  // the whole chunk (the loop's ++v goes past it)
            continue;
        }
        if (mesh.kind(mesh::VertexId{v}) == mesh::VertexKind::unused) continue;
        number[v] = static_cast<std::uint32_t>(mesh_ids.size());
        mesh_ids.push_back(v);
        const auto& p = mesh.point(mesh::VertexId{v});
        nodes.xy.push_back(p.x);
        nodes.xy.push_back(p.y);
    }
    return number;
}

// The added vertices' attributes, as the mesh keeps them (interpolated where
// each was inserted); the input vertices' stay as read.
void copy_added_attributes(const mesh::Mesh& mesh, std::size_t input_count,
                           const std::vector<std::uint32_t>& mesh_ids, NodeSet& nodes) {
    const std::uint32_t na = nodes.attribute_count;
    nodes.attributes.resize(nodes.size() * na, 0.0);
    if (na == 0 || mesh.attributes().width() != na) return;
    for (std::size_t n = input_count; n < mesh_ids.size(); ++n) {
        const mesh::VertexId v{mesh_ids[n]};
        if (!mesh.attributes().has_row(v))
            throw InternalError("output: vertex " + std::to_string(mesh_ids[n]) +
                                " was added without its attributes");
        const auto row = mesh.attributes().row(v);
        std::copy(row.begin(), row.end(),
                  nodes.attributes.begin() + static_cast<std::ptrdiff_t>(n * na));
    }
}

// The one walk over the triangles that the output needs: it counts the
// live triangles, keeps every `stride`-th live triangle's slot in `slot_of`
// (for the stream below) and, with neighbours, each slot's number (compact,
// in id order) in `triangle_number`, and lists the edges that the markers
// and the segments come from: the hull's in `hull` and the subsegments in
// `subsegments`, each once, in the order of mesh::for_each_edge.
constexpr std::uint32_t stride = 4096;
std::uint32_t walk_triangles(const mesh::Mesh& mesh, bool with_neighbours,
                             TriangleNumbers& triangle_number, std::vector<std::uint32_t>& slot_of,
                             std::vector<MeshEdge>& hull, std::vector<MeshEdge>& subsegments) {
    std::uint32_t count = 0;
    if (with_neighbours) triangle_number = triangle_numbers(mesh);
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId id, const mesh::Triangle& t) {
        if (count % stride == 0) slot_of.push_back(index(id));
        if (with_neighbours) triangle_number[index(id)] = count;
        ++count;
        for (int k = 0; k < 3; ++k) {
            const mesh::EdgeRef across = t.n[k];
            const bool on_hull = across.is_none();
            // The edge is listed from its triangle with the lower id.
            if (!on_hull && index(across.triangle()) < index(id)) continue;
            if (!on_hull && !t.is_subsegment(k)) continue;
            const MeshEdge e{index(t.v[mesh::next3(k)]), index(t.v[mesh::prev3(k)]), on_hull};
            if (on_hull) hull.push_back(e);
            if (t.is_subsegment(k)) subsegments.push_back(e);
        }
    });
    return count;
}

// A triangle's attributes are its region's (0 past the table).
double region_attribute(std::span<const double> region_attributes, std::size_t at) {
    return at < region_attributes.size() ? region_attributes[at] : 0.0;
}

// The first live triangle slot at or after `slot` (there must be one),
// passing over whole chunks nobody claimed (mesh.hpp).
std::uint32_t live_from(const mesh::Mesh& mesh, std::uint32_t slot) {
    constexpr std::uint32_t bits = mesh::Mesh::triangle_chunk_bits;
    constexpr std::uint32_t mask = mesh::Mesh::TriangleTable::chunk_mask;
    for (;; ++slot) {
        while ((slot & mask) == 0 && !mesh.has_triangle_chunk(slot >> bits)) slot += mask + 1;
        if (mesh.triangle(mesh::TriangleId{slot}).live()) return slot;
    }
}

// The triangles as a stream that walks the mesh's slots on each pass;
// `number` and `slot_of` (slot_of[k]: the slot of triangle k * stride, so
// that a run of triangles can be read from anywhere without walking the
// slots before it) are shared by the passes (the -V statistics and each
// file).  Its read() starts at the slot of the triangle `stride` * k before
// the first one asked for, so threads can read runs of triangles at once.
std::function<io::EleSource()> triangle_stream(const mesh::Mesh& mesh, VertexNumbers number,
                                               std::vector<std::uint32_t> slot_of,
                                               std::uint32_t count, std::uint32_t attribute_count,
                                               std::span<const double> region_attributes) {
    struct Shared {
        VertexNumbers number;
        std::vector<std::uint32_t> slot_of;
    };
    auto shared = std::make_shared<Shared>(Shared{std::move(number), std::move(slot_of)});
    // Fills triangle `t`'s corners and attributes.
    const auto put = [shared, attribute_count, region_attributes](
                         const mesh::Triangle& t, std::uint32_t* corners, double* attributes) {
        for (int k = 0; k < 3; ++k) corners[k] = shared->number[index(t.v[k])];
        const std::size_t row = std::size_t{t.region} * attribute_count;
        for (std::uint32_t i = 0; i < attribute_count; ++i)
            attributes[i] = region_attribute(region_attributes, row + i);
    };
    return [&mesh, shared, put, count, attribute_count] {
        return io::EleSource{
            count, 3, attribute_count,
            [&mesh, put, slot = std::uint32_t{0}](std::uint32_t* corners,
                                                  double* attributes) mutable {
                slot = live_from(mesh, slot);
                put(mesh.triangle(mesh::TriangleId{slot++}), corners, attributes);
            },
            [&mesh, shared, put, attribute_count](std::size_t first, std::size_t n,
                                                  std::uint32_t* corners, double* attributes) {
                if (n == 0) return;
                std::uint32_t slot = shared->slot_of[first / stride];
                for (std::size_t skip = first % stride;; ++slot) {
                    slot = live_from(mesh, slot);
                    if (skip-- == 0) break;
                }
                // A run waits on memory: the triangles' corners are
                // numbered through a table as large as the vertices.  So a
                // batch of triangles is found first and their numbers
                // asked for ahead (prefetch), then each is taken.
                constexpr std::size_t batch = 64;
                std::uint32_t slots[batch];
                for (std::size_t done = 0; done < n;) {
                    const std::size_t m = std::min(batch, n - done);
                    for (std::size_t i = 0; i < m; ++i, ++slot) {
                        slot = live_from(mesh, slot);
                        slots[i] = slot;
                        for (const mesh::VertexId v : mesh.triangle(mesh::TriangleId{slot}).v)
                            __builtin_prefetch(shared->number.address(index(v)));
                    }
                    for (std::size_t i = 0; i < m; ++i, ++done)
                        put(mesh.triangle(mesh::TriangleId{slots[i]}), corners + 3 * done,
                            attributes + done * attribute_count);
                }
            }};
    };
}

// The triangles copied into out.triangles (and, with neighbours, their
// neighbours renumbered by `triangle_number` into out.neighbours).
void copy_triangles(const mesh::Mesh& mesh, const VertexNumbers& number,
                    const TriangleNumbers& triangle_number, bool with_neighbours,
                    std::span<const double> region_attributes, MeshArrays& out) {
    const std::uint32_t count = static_cast<std::uint32_t>(out.triangle_count);
    const std::uint32_t attribute_count = out.triangles.attribute_count;
    out.triangles.corners.reserve(3 * std::size_t{count});
    out.triangles.attributes.reserve(std::size_t{attribute_count} * count);
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId, const mesh::Triangle& t) {
        for (int k = 0; k < 3; ++k) {
            out.triangles.corners.push_back(number[index(t.v[k])]);
            if (with_neighbours)
                out.neighbours.neighbours.push_back(
                    t.n[k].is_none() ? none : triangle_number[index(t.n[k].triangle())]);
        }
        const std::size_t row = std::size_t{t.region} * attribute_count;
        for (std::uint32_t i = 0; i < attribute_count; ++i)
            out.triangles.attributes.push_back(region_attribute(region_attributes, row + i));
    });
}

// Markers: keep non-zero input markers; otherwise a subsegment's marker,
// then 1 for any boundary vertex.
void set_vertex_markers(const mesh::Mesh& mesh, const VertexNumbers& number,
                        const std::vector<MeshEdge>& hull, NodeSet& nodes) {
    nodes.markers.resize(nodes.size(), 0);
    std::vector<bool> fixed(nodes.size());
    for (std::size_t v = 0; v < nodes.size(); ++v) fixed[v] = nodes.markers[v] != 0;
    // Where two subsegments with different markers meet, the one of the
    // earlier input segment wins, as in Triangle (then the one whose ends
    // have the smaller numbers): not the table's own order, which depends
    // on the order in which threads filled it.
    struct Marked {
        std::uint32_t segment;
        std::uint32_t a, b;  // numbers of the ends, a < b
        int marker;
    };
    std::vector<Marked> marked;
    mesh.subsegments().for_each(
        [&](mesh::VertexId a, mesh::VertexId b, const mesh::SubsegmentInfo& s) {
            if (s.marker == 0) return;
            const std::uint32_t x = number[index(a)], y = number[index(b)];
            marked.push_back({s.segment, std::min(x, y), std::max(x, y), s.marker});
        });
    std::sort(marked.begin(), marked.end(), [](const Marked& x, const Marked& y) {
        return std::tie(x.segment, x.a, x.b) < std::tie(y.segment, y.a, y.b);
    });
    for (const Marked& m : marked)
        for (const auto v : {m.a, m.b})
            if (!fixed[v]) {
                nodes.markers[v] = m.marker;
                fixed[v] = true;
            }
    for (const MeshEdge& e : hull)
        for (const auto v : {number[e.from], number[e.to]})
            if (!fixed[v]) nodes.markers[v] = 1;
}

}  // namespace

MeshArrays mesh_to_arrays(const mesh::Mesh& mesh, NodeSet nodes, std::size_t input_count,
                          std::uint32_t attribute_count, std::span<const double> region_attributes,
                          bool with_neighbours, bool materialise) {
    MeshArrays out;
    VertexNumbers number = number_vertices(mesh, input_count, nodes, out.mesh_ids);
    copy_added_attributes(mesh, input_count, out.mesh_ids, nodes);

    TriangleNumbers triangle_number;
    std::vector<std::uint32_t> slot_of;
    std::vector<MeshEdge> hull, subsegments;
    const std::uint32_t count =
        walk_triangles(mesh, with_neighbours, triangle_number, slot_of, hull, subsegments);
    out.hull_edge_count = hull.size();
    if (with_neighbours) out.neighbours.neighbours.reserve(3 * std::size_t{count});
    out.triangle_count = count;
    out.triangles.corners_per_triangle = 3;
    out.triangles.attribute_count = attribute_count;
    set_vertex_markers(mesh, number, hull, nodes);
    const EdgeMarker marker = edge_markers(mesh);
    out.segments.endpoints.reserve(2 * subsegments.size());
    out.segments.markers.reserve(subsegments.size());
    for (const MeshEdge& e : subsegments) {
        out.segments.endpoints.push_back(number[e.from]);
        out.segments.endpoints.push_back(number[e.to]);
        out.segments.markers.push_back(marker(e.from, e.to, e.hull));
    }
    if (materialise)
        copy_triangles(mesh, number, triangle_number, with_neighbours, region_attributes, out);
    else
        out.stream = triangle_stream(mesh, std::move(number), std::move(slot_of), count,
                                     attribute_count, region_attributes);
    out.nodes = std::move(nodes);
    return out;
}

}  // namespace gpdr::api
