// Copies between struct triangulateio and gpdr's in-memory job.  The rules
// for who allocates what follow Triangle 1.6's library (docs/c-api.md): an
// output array whose pointer is NULL is allocated with malloc(), one that is
// set is the caller's and is written in place.
#include "convert.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <new>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <gpdr/errors.hpp>

namespace gpdr::capi {
namespace {

[[noreturn]] void fail(const std::string& reason) { throw InputError(input_name, 0, reason); }

std::size_t count(int n, const char* field) {
    if (n < 0) fail(fmt::format("{} is {}", field, n));
    return static_cast<std::size_t>(n);
}

// `size` values from `values` (which may be NULL only when size is 0).
template <class T>
std::vector<T> copy(const T* values, std::size_t size, const char* field, const char* counted_by) {
    if (size == 0) return {};
    if (!values) fail(fmt::format("{} is NULL, but {} says it holds entries", field, counted_by));
    return std::vector<T>(values, values + size);
}

// Vertex indices numbered from `base`, as 0-based indices; each must name one
// of `vertex_count` vertices.
std::vector<std::uint32_t> indices(const int* values, std::size_t size, int base,
                                   std::size_t vertex_count, const char* field,
                                   const char* counted_by) {
    std::vector<std::uint32_t> out;
    if (size == 0) return out;
    if (!values) fail(fmt::format("{} is NULL, but {} says it holds entries", field, counted_by));
    out.reserve(size);
    for (std::size_t i = 0; i < size; ++i) {
        const std::int64_t v = std::int64_t{values[i]} - base;
        if (v < 0 || static_cast<std::uint64_t>(v) >= vertex_count)
            fail(fmt::format("{}[{}] is {}, but the vertices are numbered {} to {}", field, i,
                             values[i], base, std::int64_t(vertex_count) - 1 + base));
        out.push_back(static_cast<std::uint32_t>(v));
    }
    return out;
}

// A count as the int the structure holds, with room for the numbering base.
int int_count(std::size_t n, const char* what) {
    if (n > static_cast<std::size_t>(INT_MAX - 1))
        fail(fmt::format("the mesh has {} {}, more than an int can number", n, what));
    return static_cast<int>(n);
}

// The fields of the output structures, filled in two steps: first every
// array is allocated (or found given), then, when that has all succeeded,
// the data are copied and the fields set.  Arrays allocated here are freed
// again unless finish() ran.
class Transfer {
public:
    Transfer() { owned_.reserve(16); }
    ~Transfer() {
        for (void* p : owned_) std::free(p);
    }
    Transfer(const Transfer&) = delete;
    Transfer& operator=(const Transfer&) = delete;

    // `values`, converted one by one, into `field`'s array.
    template <class T, class U, class Convert>
    void array(T*& field, const std::vector<U>& values, Convert convert) {
        T* target = claim<T>(field, values.size());
        copies_.push_back([target, &values, convert] {
            std::transform(values.begin(), values.end(), target, convert);
        });
        set(field, target);
    }
    template <class T>
    void array(T*& field, const std::vector<T>& values) {
        array(field, values, [](const T& v) { return v; });
    }

    template <class T>
    void set(T& field, T value) {
        sets_.push_back([&field, value] { field = value; });
    }

    void finish() {
        for (const auto& c : copies_) c();
        for (const auto& s : sets_) s();
        owned_.clear();
    }

private:
    template <class T>
    T* claim(T* given, std::size_t count) {
        if (given) return given;
        if (count == 0) return nullptr;
        if (count > SIZE_MAX / sizeof(T)) throw std::bad_alloc();
        void* p = std::malloc(count * sizeof(T));
        if (!p) throw std::bad_alloc();
        owned_.push_back(p);  // reserved: cannot throw
        return static_cast<T*>(p);
    }

    std::vector<void*> owned_;
    std::vector<std::function<void()>> copies_, sets_;
};

// A 0-based vertex or triangle index as the structures number it, from
// `base`; "none" (a hull side's neighbour) is -1.
struct Numbered {
    int base;
    int operator()(std::uint32_t v) const {
        return v == NeighbourSet::none ? -1 : static_cast<int>(v) + base;
    }
};

// The vertices (unless N): coordinates, attributes, markers (unless B).
void transfer_vertices(Transfer& t, const MeshOutput& mesh, const Options& o, triangulateio& out) {
    t.set(out.numberofpoints, int_count(mesh.nodes.size(), "vertices"));
    t.set(out.numberofpointattributes, static_cast<int>(mesh.nodes.attribute_count));
    if (o.no_node_output) return;
    t.array(out.pointlist, mesh.nodes.xy);
    if (mesh.nodes.attribute_count > 0) t.array(out.pointattributelist, mesh.nodes.attributes);
    if (!o.no_boundary_markers) t.array(out.pointmarkerlist, mesh.nodes.markers);
}

// The triangles (unless E): corners, attributes; and their neighbours (n).
void transfer_triangles(Transfer& t, const MeshOutput& mesh, const Options& o,
                        const Numbered& index, triangulateio& out) {
    t.set(out.numberoftriangles, int_count(mesh.triangles.size(), "triangles"));
    t.set(out.numberofcorners, static_cast<int>(mesh.triangles.corners_per_triangle));
    t.set(out.numberoftriangleattributes, static_cast<int>(mesh.triangles.attribute_count));
    if (!o.no_ele_output) {
        t.array(out.trianglelist, mesh.triangles.corners, index);
        if (mesh.triangles.attribute_count > 0)
            t.array(out.triangleattributelist, mesh.triangles.attributes);
    }
    if (o.write_neighbours) t.array(out.neighborlist, mesh.neighbours.neighbours, index);
}

// The segments (p or c, unless P), with the input's holes and regions.
void transfer_segments(Transfer& t, const MemoryJobResult& result, const Options& o,
                       const Numbered& index, const triangulateio& in, triangulateio& out) {
    // Triangle's count of segments: the subsegments when the run used any
    // (a PSLG, a refined mesh, refinement, the hull as segments), else the
    // hull's edges.
    const bool uses_segments = o.poly || o.refine || o.quality || o.area_limit || o.regional_area ||
                               o.user_test || o.conforming_delaunay || o.convex_hull;
    t.set(out.numberofsegments,
          int_count(uses_segments ? result.report.segments : result.report.hull_edges, "segments"));
    if (!(o.poly || o.convex_hull) || o.no_poly_output) return;
    t.array(out.segmentlist, result.mesh.segments.endpoints, index);
    if (!o.no_boundary_markers) t.array(out.segmentmarkerlist, result.mesh.segments.markers);
    // The holes and regions are the input's own arrays, not copies.
    t.set(out.holelist, o.poly ? in.holelist : nullptr);
    t.set(out.numberofholes, o.poly ? in.numberofholes : 0);
    t.set(out.regionlist, o.poly ? in.regionlist : nullptr);
    t.set(out.numberofregions, o.poly ? in.numberofregions : 0);
}

// The edges (e), with markers (unless B).
void transfer_edges(Transfer& t, const MemoryJobResult& result, const Options& o,
                    const Numbered& index, triangulateio& out) {
    t.set(out.numberofedges, int_count(result.report.edges, "edges"));
    if (!o.write_edges) return;
    t.array(out.edgelist, result.mesh.edges.endpoints, index);
    if (!o.no_boundary_markers) t.array(out.edgemarkerlist, result.mesh.edges.markers);
}

// The Voronoi diagram's counts, and with v its vertices and edges (no
// markers, as in Triangle).
void transfer_voronoi(Transfer& t, const MemoryJobResult& result, const Options& o,
                      const Numbered& index, triangulateio& vorout) {
    const MeshOutput& mesh = result.mesh;
    t.set(vorout.numberofpoints, int_count(mesh.triangles.size(), "triangles"));
    t.set(vorout.numberofpointattributes, static_cast<int>(mesh.nodes.attribute_count));
    t.set(vorout.numberofedges, int_count(result.report.edges, "edges"));
    if (!o.write_voronoi) return;
    t.array(vorout.pointlist, mesh.voronoi_vertices.xy);
    if (mesh.voronoi_vertices.attribute_count > 0)
        t.array(vorout.pointattributelist, mesh.voronoi_vertices.attributes);
    t.set(vorout.pointmarkerlist, static_cast<int*>(nullptr));
    t.array(vorout.edgelist, mesh.voronoi_edges.endpoints, index);
    t.set(vorout.edgemarkerlist, static_cast<int*>(nullptr));
    t.array(vorout.normlist, mesh.voronoi_edges.directions);
}

}  // namespace

MeshInput read_input(const triangulateio& in, const Options& o) {
    const int base = o.zero_based ? 0 : 1;
    MeshInput m;
    m.name = input_name;
    const std::size_t n = count(in.numberofpoints, "numberofpoints");
    m.nodes.xy = copy(in.pointlist, 2 * n, "pointlist", "numberofpoints");
    m.nodes.attribute_count =
        static_cast<std::uint32_t>(count(in.numberofpointattributes, "numberofpointattributes"));
    m.nodes.attributes = copy(in.pointattributelist, n * m.nodes.attribute_count,
                              "pointattributelist", "numberofpointattributes");
    if (in.pointmarkerlist) m.nodes.markers.assign(in.pointmarkerlist, in.pointmarkerlist + n);

    if (o.poly) {
        const std::size_t segments = count(in.numberofsegments, "numberofsegments");
        m.segments.endpoints =
            indices(in.segmentlist, 2 * segments, base, n, "segmentlist", "numberofsegments");
        if (in.segmentmarkerlist)
            m.segments.markers.assign(in.segmentmarkerlist, in.segmentmarkerlist + segments);
        m.holes = copy(in.holelist, 2 * count(in.numberofholes, "numberofholes"), "holelist",
                       "numberofholes");
        const std::vector<double> regions =
            copy(in.regionlist, 4 * count(in.numberofregions, "numberofregions"), "regionlist",
                 "numberofregions");
        for (std::size_t r = 0; r < regions.size(); r += 4)
            m.regions.push_back(Region{regions[r], regions[r + 1], regions[r + 2], regions[r + 3]});
    }
    if (o.refine) {
        const std::size_t triangles = count(in.numberoftriangles, "numberoftriangles");
        const std::size_t corners = count(in.numberofcorners, "numberofcorners");
        if (corners < 3) fail(fmt::format("numberofcorners is {}, fewer than 3", corners));
        m.triangles.corners_per_triangle = static_cast<std::uint32_t>(corners);
        m.triangles.corners = indices(in.trianglelist, triangles * corners, base, n, "trianglelist",
                                      "numberoftriangles");
        m.triangles.attribute_count = static_cast<std::uint32_t>(
            count(in.numberoftriangleattributes, "numberoftriangleattributes"));
        m.triangles.attributes =
            copy(in.triangleattributelist, triangles * m.triangles.attribute_count,
                 "triangleattributelist", "numberoftriangleattributes");
        if (o.regional_area)
            m.areas = copy(in.trianglearealist, triangles, "trianglearealist", "numberoftriangles");
    }
    return m;
}

void write_output(const MemoryJobResult& result, const Options& o, const triangulateio& in,
                  triangulateio& out, triangulateio* vorout) {
    const Numbered index{o.zero_based ? 0 : 1};
    Transfer t;
    transfer_vertices(t, result.mesh, o, out);
    transfer_triangles(t, result.mesh, o, index, out);
    transfer_segments(t, result, o, index, in, out);
    transfer_edges(t, result, o, index, out);
    if (vorout) transfer_voronoi(t, result, o, index, *vorout);
    t.finish();
}

}  // namespace gpdr::capi
