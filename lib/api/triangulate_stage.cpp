// The triangulation stage of a run: the Delaunay triangulation of a point
// set, the constrained Delaunay triangulation of a .poly (-p), or the mesh of
// an .ele rebuilt (-r); then -D's conforming splits.  What the library
// reports about the input (duplicates, crossings) becomes warnings here.

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include <gpdr/errors.hpp>

#include "api/job_stages.hpp"
#include "mesh/pool.hpp"
#include "mesh/traverse.hpp"
#include "parallel/schedule.hpp"
#include "triangulate/conforming.hpp"
#include "triangulate/constrained.hpp"
#include "triangulate/delaunay.hpp"
#include "triangulate/from_triangles.hpp"
#include "triangulate/lawson.hpp"

namespace gpdr::api {
namespace {

// A list of at most `shown` items, then "and N more".
template <class T, class F>
std::string list_some(const std::vector<T>& items, F&& describe, std::size_t shown = 8) {
    std::string s;
    for (std::size_t i = 0; i < items.size() && i < shown; ++i)
        s += (i ? ", " : "") + describe(items[i]);
    if (items.size() > shown) s += fmt::format(", and {} more", items.size() - shown);
    return s;
}

void warn_duplicates(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& duplicates,
                     const std::string& file, int base, const WarningSink& warn) {
    if (duplicates.empty()) return;
    warn(Warning{file, 0,
                 fmt::format("{} duplicate vert{} left out of the mesh: {}", duplicates.size(),
                             duplicates.size() == 1 ? "ex" : "ices",
                             list_some(duplicates, [&](const auto& d) {
                                 return fmt::format("{} (same as {})", d.first + base,
                                                    d.second + base);
                             }))});
}

// The vertices as Points.  The NodeSet gives its coordinates up: the mesh
// keeps them from here on, and mesh_to_arrays() takes them back for output.
std::vector<geometry::Point> take_points(NodeSet& nodes) {
    std::vector<geometry::Point> points(nodes.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        points[i] = {nodes.xy[2 * i], nodes.xy[2 * i + 1]};
    nodes.xy = {};
    return points;
}

// The input vertices' attributes, copied beside the mesh (whose vertex ids
// are the input's), where refinement and the output find them.
void keep_input_attributes(const NodeSet& nodes, mesh::Mesh& mesh) {
    const std::uint32_t na = nodes.attribute_count;
    if (na == 0) return;
    mesh::VertexAttributes& table = mesh.attributes() = mesh::VertexAttributes(na);
    const std::size_t count = nodes.attributes.size() / na;
    for (std::size_t v = 0; v < count; ++v) {
        const std::span<double> row = table.write(mesh::VertexId{static_cast<std::uint32_t>(v)});
        std::copy_n(nodes.attributes.begin() + static_cast<std::ptrdiff_t>(v * na), na,
                    row.begin());
    }
}

// Triangle's hull-as-segments: -c writes the hull to the .poly, and
// refinement keeps its Steiner points inside it.
void make_hull_segments(mesh::Mesh& mesh) {
    std::vector<mesh::EdgeView> hull;
    mesh::for_each_hull_edge(mesh, [&](const mesh::EdgeView& e) {
        if (!e.subsegment) hull.push_back(e);
    });
    for (const auto& e : hull) {
        mesh.triangle(e.edge.triangle()).set_subsegment(e.edge.edge(), true);
        mesh.subsegments().set(e.from, e.to,
                               mesh::SubsegmentInfo{1, mesh::SubsegmentInfo::no_segment});
    }
}

void triangulate_points(const Options& options, Input& in, Triangulated& out,
                        const WarningSink& warn) {
    triangulate::DelaunayReport report;
    try {
        triangulate::DelaunayOptions delaunay_options;
        delaunay_options.threads = parallel::thread_count(options.threads);
        out.mesh = triangulate::delaunay(take_points(in.nodes.data), report, delaunay_options);
    } catch (const GeometryError& e) {
        throw InputError(in.node_file, 0, e.what());
    }
    keep_input_attributes(in.nodes.data, out.mesh);
    warn_duplicates(report.duplicates, in.node_file, in.nodes.base, warn);
    out.duplicates = report.duplicates.size();
    if (options.convex_hull || wants_refinement(options)) make_hull_segments(out.mesh);
}

// What the CDT did about the input's segments, as warnings on the .poly:
// duplicates left out, overlaps kept once, a vertex added at each crossing.
void warn_about_segments(const triangulate::CdtReport& report, const mesh::Mesh& mesh,
                         const std::string& poly_file, int base, const WarningSink& warn) {
    if (!report.duplicate_segments.empty())
        warn(Warning{poly_file, 0,
                     fmt::format("duplicate segments left out: {}",
                                 list_some(report.duplicate_segments, [&](const auto& d) {
                                     return fmt::format("{} (same as {})", d.first + base,
                                                        d.second + base);
                                 }))});
    if (!report.overlapping_segments.empty())
        warn(Warning{poly_file, 0,
                     fmt::format("segments overlap; each shared stretch was kept once: {}",
                                 list_some(report.overlapping_segments, [&](const auto& d) {
                                     return fmt::format("segments {} and {}", d.first + base,
                                                        d.second + base);
                                 }))});
    std::vector<triangulate::NewSegmentVertex> crossings;
    for (const auto& v : report.new_vertices)
        if (v.other_segment != triangulate::NewSegmentVertex::no_segment) crossings.push_back(v);
    if (!crossings.empty())
        warn(Warning{poly_file, 0,
                     fmt::format("segments cross; a vertex was added at each crossing: {}",
                                 list_some(crossings, [&](const auto& v) {
                                     const auto& p = mesh.point(v.vertex);
                                     return fmt::format("segments {} and {} at ({}, {})",
                                                        v.segment + base, v.other_segment + base,
                                                        p.x, p.y);
                                 }))});
}

void triangulate_pslg(const Options& options, Input& in, Triangulated& out,
                      const WarningSink& warn) {
    const PolyFile& poly = *in.poly;
    // The vertices were moved from the PolyFile into in.nodes.
    triangulate::Pslg& pslg = out.pslg.emplace(triangulate::pslg_from(poly));
    pslg.points = take_points(in.nodes.data);
    triangulate::CdtOptions cdt;
    cdt.convex_hull = options.convex_hull;
    cdt.ignore_holes = options.ignore_holes;
    triangulate::CdtReport& report = out.cdt_report;
    try {
        out.mesh = triangulate::constrained_delaunay(pslg, cdt, report);
    } catch (const GeometryError& e) {
        throw InputError(in.poly_file, 0, e.what());
    }
    const int base = in.nodes.base;
    warn_duplicates(report.duplicate_vertices, in.node_file, base, warn);
    out.duplicates = report.duplicate_vertices.size();
    warn_about_segments(report, out.mesh, in.poly_file, base, warn);
    // Attributes of the new vertices: interpolated along their segment.
    keep_input_attributes(in.nodes.data, out.mesh);
    for (const auto& v : report.new_vertices) {
        if (v.segment == triangulate::NewSegmentVertex::no_segment) continue;
        mesh::interpolate_on_segment(
            out.mesh, v.vertex, mesh::VertexId{pslg.segments[2 * std::size_t{v.segment}]},
            mesh::VertexId{pslg.segments[2 * std::size_t{v.segment} + 1]}, v.t);
    }
    // Refinement sees the pieces: a segment cut at a crossing is two
    // segments meeting at an input vertex, as in Triangle.
    out.segment_ends.reserve(2 * report.pieces.size());
    for (const triangulate::SegmentPiece& piece : report.pieces) {
        out.segment_ends.push_back(mesh::VertexId{piece.a});
        out.segment_ends.push_back(mesh::VertexId{piece.b});
    }
    if (options.region_attributes) {
        out.triangle_attribute_count = 1;
        out.region_attributes.assign(poly.regions.size() + 1, 0.0);
        for (std::size_t r = 0; r < poly.regions.size(); ++r)
            out.region_attributes[r + 1] = poly.regions[r].attribute;
    }
}

void rebuild_mesh(const Options& options, Input& in, Triangulated& out) {
    const EleSet& ele = *in.triangles;
    const std::vector<geometry::Point> points = take_points(in.nodes.data);
    // The .area file's bounds belong to the triangles as read, before the
    // flips below make the mesh Delaunay.
    if (in.areas)
        out.area_field = std::make_unique<geometry::AreaField>(points, ele.corners,
                                                               ele.corners_per_triangle, *in.areas);
    triangulate::TriangleMeshInput input;
    input.points = points;
    input.corners = ele.corners;
    input.corners_per_triangle = ele.corners_per_triangle;
    input.index_base = in.nodes.base;
    if (in.poly) {
        input.segments = in.poly->segments.endpoints;
        input.segment_markers = in.poly->segments.markers;
    }
    triangulate::TriangleMeshReport report;
    try {
        out.mesh = triangulate::from_triangles(input, report);
    } catch (const GeometryError& e) {
        throw InputError(in.ele_file, 0, e.what());
    }
    keep_input_attributes(in.nodes.data, out.mesh);
    // Triangle attributes ride on the region field, which every later stage
    // passes from a triangle to the ones that replace it: region r + 1 is
    // the r-th distinct attribute tuple.
    const std::uint32_t na = ele.attribute_count;
    if (na > 0) {
        out.triangle_attribute_count = na;
        out.region_attributes.assign(na, 0.0);  // region 0: none
        std::map<std::vector<double>, std::uint16_t> index;
        for (std::size_t t = 0; t < ele.size(); ++t) {
            std::vector<double> tuple(
                ele.attributes.begin() + static_cast<std::ptrdiff_t>(t * na),
                ele.attributes.begin() + static_cast<std::ptrdiff_t>((t + 1) * na));
            auto [it, fresh] =
                index.try_emplace(tuple, static_cast<std::uint16_t>(index.size() + 1));
            if (fresh) {
                if (index.size() > 65534)
                    throw NotImplemented(fmt::format(
                        "{}: more than 65534 distinct triangle attribute values", in.ele_file));
                out.region_attributes.insert(out.region_attributes.end(), tuple.begin(),
                                             tuple.end());
            }
            out.mesh.triangle(mesh::TriangleId{static_cast<std::uint32_t>(t)}).region = it->second;
        }
    }
    if (in.poly) {
        out.segment_ends.reserve(in.poly->segments.endpoints.size());
        for (const std::uint32_t v : in.poly->segments.endpoints)
            out.segment_ends.push_back(mesh::VertexId{v});
    }
    // Refinement and -D insert with Bowyer-Watson, which needs a constrained
    // Delaunay mesh; a mesh read back need not be one.
    if (wants_refinement(options) || options.conforming_delaunay)
        triangulate::make_constrained_delaunay(out.mesh);
}

}  // namespace

Triangulated triangulate_input(const Options& options, Input& in, const WarningSink& warn) {
    Triangulated out;
    if (options.refine)
        rebuild_mesh(options, in, out);
    else if (in.poly)
        triangulate_pslg(options, in, out, warn);
    else
        triangulate_points(options, in, out, warn);

    // -D: split subsegments until every triangle is Delaunay.  (On a point
    // set the Delaunay triangulation already is.)
    if (options.conforming_delaunay && (options.poly || options.refine)) {
        triangulate::ConformingReport report;
        {
            mesh::Pool pool(out.mesh);
            triangulate::make_conforming(pool, triangulate::conforming_options(options), report);
        }
        out.steiner_points += report.points_added;
        for (const auto& s : report.splits)
            mesh::interpolate_on_segment(out.mesh, s.vertex, s.from, s.to, s.t);
        if (report.encroached_left)
            warn(Warning{
                "", 0,
                fmt::format("{} subsegments are still encroached ({}), so the mesh is not "
                            "conforming Delaunay everywhere",
                            report.encroached_left,
                            report.stopped == triangulate::ConformingReport::Stop::steiner_limit
                                ? "the -S limit was reached"
                                : "-Y/-YY forbids splitting them, or they are too short")});
    }
    return out;
}

}  // namespace gpdr::api
