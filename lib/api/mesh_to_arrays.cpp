// From the live mesh to the arrays Triangle's files hold: vertices numbered
// input first then the added ones in id order (skipping ids claimed but never
// used), triangles in id order with dead slots skipped, neighbours
// renumbered to match, vertex attributes as the mesh keeps them (interpolated
// where refinement added the vertex) and markers set by Triangle's rules.

#include <algorithm>
#include <memory>
#include <string>
#include <tuple>

#include <gpdr/errors.hpp>

#include "api/job_stages.hpp"
#include "mesh/slices.hpp"
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
// chunks that hold ids have numbers.  They start unset: the passes that
// fill them (on several threads, a chunk at a time) set every id of the
// chunks they cover, `none` where an id has no number.
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
        numbers_ = std::make_unique_for_overwrite<std::uint32_t[]>(next);
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
    std::unique_ptr<std::uint32_t[]> numbers_;
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

// The vertex id chunks that have numbers (the claimed ones, and the
// input's), each up to its used part (mesh.hpp; the numbers of the ids past
// it are never read), and which ids are written as nodes: the input
// vertices (duplicates included, as Triangle writes them) and the vertices
// added, not the ids claimed but never used.
struct VertexChunks {
    const mesh::Mesh& mesh;
    std::size_t input_count;
    std::uint32_t end;
    std::vector<std::uint32_t> chunks;

    VertexChunks(const mesh::Mesh& m, std::size_t input)
        : mesh(m),
          input_count(input),
          end(static_cast<std::uint32_t>(std::max<std::size_t>(m.vertex_end(), input))),
          chunks(mesh::held_chunks(end, VertexNumbers::bits, [&](std::uint32_t c) {
              return m.has_vertex_chunk(c) || (std::size_t{c} << VertexNumbers::bits) < input;
          })) {}
    mesh::ChunkIds ids_of(std::size_t i) const {
        mesh::ChunkIds ids = mesh::chunk_ids(chunks[i], VertexNumbers::bits, end);
        ids.last = std::min(ids.last, ids.first + mesh.vertex_chunk_used(chunks[i]));
        return ids;
    }
    bool written(std::uint32_t v) const {
        return v < input_count || mesh.kind(mesh::VertexId{v}) != mesh::VertexKind::unused;
    }
    // The nodes before each chunk (chunks.size() + 1 entries, the last the
    // node count), on `threads` threads.
    std::vector<std::uint32_t> nodes_before(unsigned threads) const {
        std::vector<std::uint32_t> first(chunks.size() + 1, 0);
        mesh::run_pieces(threads, chunks.size(), [&](std::size_t i) {
            const mesh::ChunkIds ids = ids_of(i);
            std::uint32_t n = 0;
            for (std::uint32_t v = ids.first; v < ids.last; ++v) n += written(v) ? 1 : 0;
            first[i + 1] = n;
        });
        for (std::size_t i = 0; i < chunks.size(); ++i) first[i + 1] += first[i];
        return first;
    }
};

// ArrayChoices::free_points_of: the coordinates in id order, appended to
// storage reserved untouched, each granule of the point table given back
// once copied, so that they are held about once, not twice, at any moment.
void copy_freeing_points(const VertexChunks& vertices, std::size_t count, mesh::Mesh& mesh,
                         NodeSet& nodes) {
    std::vector<double>().swap(nodes.xy);
    nodes.xy.reserve(2 * count);
    for (std::size_t i = 0; i < vertices.chunks.size(); ++i) {
        const mesh::ChunkIds ids = vertices.ids_of(i);
        for (std::uint32_t v = ids.first; v < ids.last; ++v) {
            if (!vertices.written(v)) continue;
            const auto& p = mesh.point(mesh::VertexId{v});
            nodes.xy.push_back(p.x);
            nodes.xy.push_back(p.y);
        }
        mesh.discard_points_below(ids.last);
    }
    mesh.discard_points();
}

// Vertex numbers: the input vertices keep theirs; added vertices follow, in
// id order (VertexChunks::written).  Fills the coordinates in `nodes` and,
// unless it is null, `mesh_ids`; returns each mesh vertex's number (none for
// the skipped).  On `threads` threads, a chunk of ids at a time: each chunk
// counts its vertices, then numbers them from the count of the chunks
// before it, which gives the numbers one pass in id order gives.
VertexNumbers number_vertices(const mesh::Mesh& mesh, std::size_t input_count, NodeSet& nodes,
                              std::vector<std::uint32_t>* mesh_ids, unsigned threads,
                              mesh::Mesh* free_points) {
    const VertexChunks vertices(mesh, input_count);
    VertexNumbers number = vertex_numbers(mesh, input_count);
    const std::vector<std::uint32_t> first = vertices.nodes_before(threads);
    const bool copy_here = free_points == nullptr;
    if (copy_here) nodes.xy.resize(2 * std::size_t{first.back()});
    if (mesh_ids != nullptr) mesh_ids->resize(first.back());
    mesh::run_pieces(threads, vertices.chunks.size(), [&](std::size_t i) {
        const mesh::ChunkIds ids = vertices.ids_of(i);
        std::uint32_t n = first[i];
        for (std::uint32_t v = ids.first; v < ids.last; ++v) {
            if (!vertices.written(v)) {
                number[v] = none;
                continue;
            }
            number[v] = n;
            if (mesh_ids != nullptr) (*mesh_ids)[n] = v;
            if (copy_here) {
                const auto& p = mesh.point(mesh::VertexId{v});
                nodes.xy[2 * std::size_t{n}] = p.x;
                nodes.xy[2 * std::size_t{n} + 1] = p.y;
            }
            ++n;
        }
    });
    if (!copy_here) copy_freeing_points(vertices, first.back(), *free_points, nodes);
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

// A place to start reading triangles from: triangle number `first` (in
// the output's order) lies at slot `slot`.
struct Anchor {
    std::uint32_t first = 0;
    std::uint32_t slot = 0;
};

// What the walk over the triangles finds (below).
struct TriangleWalk {
    std::uint32_t count = 0;      // live triangles
    std::vector<Anchor> anchors;  // by `first`, none more than `stride` apart
    std::vector<MeshEdge> hull, subsegments;
};

// The one walk over the triangles that the output needs: it counts the
// live triangles, keeps anchors (for the stream below: the first triangle
// of every chunk of slots, and every `stride`-th after it) and, with
// neighbours, each slot's number (compact, in id order) in
// `triangle_number`, and lists the edges that the markers and the segments
// come from: the hull's and the subsegments, each once, in the order of
// mesh::for_each_edge.  On `threads` threads, a chunk of slots at a time,
// joined in slot order; with neighbours a second pass adds to each chunk's
// numbers the triangles before it.
constexpr std::uint32_t stride = 4096;

// The walk over one chunk's slots `ids`: its triangles counted from 0, its
// anchors and edges, and with `numbers` each triangle's number within it.
void walk_chunk(const mesh::Mesh& mesh, mesh::ChunkIds ids, TriangleNumbers* numbers,
                TriangleWalk& part) {
    mesh::for_each_triangle_in(
        mesh, ids.first, ids.last, [&](mesh::TriangleId id, const mesh::Triangle& t) {
            if (part.count % stride == 0) part.anchors.push_back({part.count, index(id)});
            if (numbers != nullptr) (*numbers)[index(id)] = part.count;
            ++part.count;
            for (int k = 0; k < 3; ++k) {
                const mesh::EdgeRef across = t.n[k];
                const bool on_hull = across.is_none();
                // The edge is listed from its triangle with the lower id.
                if (!on_hull && index(across.triangle()) < index(id)) continue;
                if (!on_hull && !t.is_subsegment(k)) continue;
                const MeshEdge e{index(t.v[mesh::next3(k)]), index(t.v[mesh::prev3(k)]), on_hull};
                if (on_hull) part.hull.push_back(e);
                if (t.is_subsegment(k)) part.subsegments.push_back(e);
            }
        });
}

TriangleWalk walk_triangles(const mesh::Mesh& mesh, bool with_neighbours,
                            TriangleNumbers& triangle_number, unsigned threads) {
    constexpr unsigned bits = TriangleNumbers::bits;
    if (with_neighbours) triangle_number = triangle_numbers(mesh);
    const std::vector<std::uint32_t> chunks = mesh::triangle_chunks(mesh);
    const std::uint32_t end = mesh.triangle_end();
    std::vector<TriangleWalk> parts(chunks.size());
    mesh::run_pieces(threads, chunks.size(), [&](std::size_t i) {
        const mesh::ChunkIds ids = mesh::chunk_ids(chunks[i], bits, end);
        TriangleWalk& part = parts[i];
        if (with_neighbours) {
            const std::uint32_t used =
                std::min(ids.last, ids.first + mesh.triangle_chunk_used(chunks[i]));
            for (std::uint32_t id = ids.first; id < used; ++id) triangle_number[id] = none;
        }
        walk_chunk(mesh, ids, with_neighbours ? &triangle_number : nullptr, part);
    });
    TriangleWalk all;
    std::vector<std::uint32_t> before(chunks.size(), 0);  // triangles before each chunk
    for (std::size_t i = 0; i < chunks.size(); ++i) {
        before[i] = all.count;
        for (const Anchor& a : parts[i].anchors)
            all.anchors.push_back({a.first + all.count, a.slot});
        all.hull.insert(all.hull.end(), parts[i].hull.begin(), parts[i].hull.end());
        all.subsegments.insert(all.subsegments.end(), parts[i].subsegments.begin(),
                               parts[i].subsegments.end());
        all.count += parts[i].count;
    }
    if (with_neighbours)
        mesh::run_pieces(threads, chunks.size(), [&](std::size_t i) {
            if (before[i] == 0) return;
            const mesh::ChunkIds ids = mesh::chunk_ids(chunks[i], bits, end);
            mesh::for_each_triangle_in(mesh, ids.first, ids.last,
                                       [&](mesh::TriangleId id, const mesh::Triangle&) {
                                           triangle_number[index(id)] += before[i];
                                       });
        });
    return all;
}

// A triangle's attributes are its region's (0 past the table).
double region_attribute(std::span<const double> region_attributes, std::size_t at) {
    return at < region_attributes.size() ? region_attributes[at] : 0.0;
}

// The first live triangle slot at or after `slot` (there must be one),
// passing over whole chunks nobody claimed and the unused ends of chunks
// (mesh.hpp).
std::uint32_t live_from(const mesh::Mesh& mesh, std::uint32_t slot) {
    constexpr std::uint32_t bits = mesh::Mesh::triangle_chunk_bits;
    constexpr std::uint32_t mask = mesh::Mesh::TriangleTable::chunk_mask;
    for (;;) {
        if ((slot & mask) == 0 && !mesh.has_triangle_chunk(slot >> bits)) {
            slot += mask + 1;
            continue;
        }
        if (mesh.triangle(mesh::TriangleId{slot}).live()) return slot;
        ++slot;
        if ((slot & mask) != 0 && (slot & mask) >= mesh.triangle_chunk_used(slot >> bits))
            slot = (slot | mask) + 1;
    }
}

// The triangles as a stream that walks the mesh's slots on each pass;
// `number` and `anchors` (so that a run of triangles can be read from
// anywhere without walking the slots before it) are shared by the passes
// (the -V statistics and each file).  Its read() starts at the last anchor
// before the first triangle asked for, so threads can read runs of
// triangles at once.
std::function<io::EleSource()> triangle_stream(const mesh::Mesh& mesh, VertexNumbers number,
                                               std::vector<Anchor> anchors, std::uint32_t count,
                                               std::uint32_t attribute_count,
                                               std::span<const double> region_attributes) {
    struct Shared {
        VertexNumbers number;
        std::vector<Anchor> anchors;
    };
    auto shared = std::make_shared<Shared>(Shared{std::move(number), std::move(anchors)});
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
                const auto& anchors = shared->anchors;
                const Anchor& from =
                    *(std::upper_bound(anchors.begin(), anchors.end(), first,
                                       [](std::size_t f, const Anchor& a) { return f < a.first; }) -
                      1);
                std::uint32_t slot = from.slot;
                for (std::size_t skip = first - from.first;; ++slot) {
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
                          const ArrayChoices& choices) {
    const bool with_neighbours = choices.neighbours;
    const unsigned threads = choices.threads;
    MeshArrays out;
    // The added vertices' attributes are copied through the mesh ids.
    const bool copies_attributes =
        nodes.attribute_count != 0 && mesh.attributes().width() == nodes.attribute_count;
    const bool mesh_ids = choices.mesh_ids || copies_attributes;
    if (choices.free_points_of != nullptr && choices.free_points_of != &mesh)
        throw InternalError("output: free_points_of names another mesh");
    VertexNumbers number =
        number_vertices(mesh, input_count, nodes, mesh_ids ? &out.mesh_ids : nullptr, threads,
                        choices.free_points_of);
    copy_added_attributes(mesh, input_count, out.mesh_ids, nodes);
    if (!choices.mesh_ids) std::vector<std::uint32_t>().swap(out.mesh_ids);

    TriangleNumbers triangle_number;
    TriangleWalk walk = walk_triangles(mesh, with_neighbours, triangle_number, threads);
    const std::uint32_t count = walk.count;
    const std::vector<MeshEdge>& hull = walk.hull;
    const std::vector<MeshEdge>& subsegments = walk.subsegments;
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
    if (choices.materialise)
        copy_triangles(mesh, number, triangle_number, with_neighbours, region_attributes, out);
    else
        out.stream = triangle_stream(mesh, std::move(number), std::move(walk.anchors), count,
                                     attribute_count, region_attributes);
    out.nodes = std::move(nodes);
    return out;
}

MeshCounts count_mesh(const mesh::Mesh& mesh, std::size_t input_count, unsigned threads) {
    MeshCounts counts;
    counts.nodes = VertexChunks(mesh, input_count).nodes_before(threads).back();
    // The triangles and hull edges, as the walk that numbers the triangles
    // finds them.
    const std::vector<std::uint32_t> triangle_chunks = mesh::triangle_chunks(mesh);
    const std::uint32_t triangle_end = mesh.triangle_end();
    std::vector<MeshCounts> parts(triangle_chunks.size());
    mesh::run_pieces(threads, triangle_chunks.size(), [&](std::size_t i) {
        const mesh::ChunkIds ids =
            mesh::chunk_ids(triangle_chunks[i], TriangleNumbers::bits, triangle_end);
        mesh::for_each_triangle_in(mesh, ids.first, ids.last,
                                   [&](mesh::TriangleId, const mesh::Triangle& t) {
                                       ++parts[i].triangles;
                                       for (const mesh::EdgeRef e : t.n)
                                           parts[i].hull_edges += e.is_none() ? 1 : 0;
                                   });
    });
    for (const MeshCounts& part : parts) {
        counts.triangles += part.triangles;
        counts.hull_edges += part.hull_edges;
    }
    return counts;
}

}  // namespace gpdr::api
