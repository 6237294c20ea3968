// The output stage: every file the switches ask for, all or none, so that a
// failure leaves no partial result and no earlier result clobbered.  With
// several threads (-jN) the files are formatted and written side by side,
// and a thread with no file left to start formats pieces of the large files
// still being written (io/format_threads.hpp): formatting numbers is most of
// the stage, and the .ele file of a large mesh alone costs more than the
// .node beside it.

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <iterator>
#include <memory>
#include <thread>
#include <vector>

#include <gpdr/io.hpp>
#include <gpdr/mesh_formats.hpp>

#include "api/job_stages.hpp"
#include "io/format_threads.hpp"
#include "io/temporary_files.hpp"
#include "mesh/traverse.hpp"
#include "parallel/refine_parallel.hpp"

namespace gpdr::api {
namespace {

// One output file: its name and the call that writes it into a transaction.
struct FileJob {
    std::string target;
    std::function<void(io::OutputTransaction&)> write;
};

// Writes every job into a transaction of its own, on the threads of
// `threads` (jobs are taken in order, so the first, largest files start
// first; a thread with no job left helps format the files being written),
// then renames all of them into place in job order, only when all were
// written.  A failure rethrows the first failing job's error (in job
// order, whatever the timing), and the transactions' destructors remove
// every temporary file.
void write_all(const std::vector<FileJob>& jobs, io::FormatThreads& threads, Progress* progress) {
    const std::size_t n = jobs.size();
    const auto transactions = std::make_unique<io::OutputTransaction[]>(n);
    std::vector<std::exception_ptr> failures(n);
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t j; (j = next.fetch_add(1)) < n;) {
            try {
                jobs[j].write(transactions[j]);
                if (progress != nullptr) progress->file_done();
            } catch (...) {
                failures[j] = std::current_exception();
            }
            threads.file_done();
        }
        threads.help();
    };
    threads.expect_files(n);
    {
        // This thread and threads - 1 helpers.
        std::vector<std::jthread> helpers;
        for (unsigned h = 1; h < threads.threads() && n > 0; ++h) helpers.emplace_back(work);
        work();
    }
    for (const std::exception_ptr& f : failures)
        if (f) std::rethrow_exception(f);
    // All files or none: a SIGINT, SIGTERM or SIGHUP waits for the renames.
    const io::detail::SignalsHeld held;
    for (std::size_t j = 0; j < n; ++j) transactions[j].commit();
}

}  // namespace

PreparedOutputs prepare_outputs(const Options& o, const mesh::Mesh& mesh, MeshArrays& arrays) {
    PreparedOutputs p;
    if (o.jettison) jettison_unused_vertices(arrays);
    // Node indices -> mesh vertex ids (what follows does not change them).
    const std::vector<std::uint32_t>& mesh_id = arrays.mesh_ids;

    // Edge markers are known by mesh vertex ids; the arrays may be renumbered.
    p.mesh_marker = edge_markers(mesh);
    const EdgeMarker marker = [&p, &mesh_id](std::uint32_t a, std::uint32_t b, bool boundary) {
        return p.mesh_marker(mesh_id[a], mesh_id[b], boundary);
    };

    // Computed before -o2 changes the triangles to six nodes.
    if (o.write_edges) p.edges = edges_of(arrays, marker);
    if (o.write_voronoi) p.voronoi = voronoi_of(arrays);
    if (o.write_off) p.edge_count = count_edges(arrays).edges;
    if (o.order == 2) make_second_order(arrays, marker);
    return p;
}

namespace {

// What the writers of the table below read: the request, the arrays and
// what was derived from them.  Everything stays put until write_all returns.
struct OutputContext {
    const Options& options;
    const FileNames& names;
    const OutputRequest& request;
    const MeshArrays& arrays;
    const PreparedOutputs& prepared;
    const io::WriteFormat& format;
    const io::MeshExport& exported;  // for the files other programs read
    const SegmentSet& segments;      // the .poly's, the .msh's and the .svg's
    bool want_poly;                  // -p (or -c on a point set), not -P
};

// Which files the switches ask for: the options, and whether an output
// .poly is wanted (-p, or -c on a point set, and not -P).
struct Wants {
    const Options& options;
    bool want_poly;
};

// One row of the output table: when the switches ask for the file, where it
// goes, and how it is written.
struct OutputFile {
    bool (*wanted)(const Wants&);
    std::string FileNames::*path;
    void (*write)(io::OutputTransaction&, const std::string& path, const OutputContext&);
};

bool wants_poly(const Options& o, const FileNames& names, bool write_hull_poly) {
    return (o.poly || write_hull_poly) && !o.no_poly_output && !names.out_poly.empty();
}

// Triangle's output .poly: the segments (and the input's holes and
// regions), its vertices in the .node beside it.
void write_output_poly(io::OutputTransaction& out, const std::string& path,
                       const OutputContext& c) {
    PolyFile poly;
    poly.nodes_from_node_file = true;
    poly.nodes.attribute_count = c.arrays.nodes.attribute_count;
    // write_poly() takes the header's marker column from nodes.markers.
    if (c.arrays.nodes.has_markers()) poly.nodes.markers.assign(1, 0);
    poly.segments = c.segments;
    if (c.request.poly) {
        poly.holes = c.request.poly->holes;
        poly.regions = c.request.poly->regions;
    }
    io::write_poly(out, path, poly, c.format);
}

// The Voronoi diagram's files carry no markers.
io::WriteFormat without_markers(const io::WriteFormat& format) {
    io::WriteFormat plain = format;
    plain.markers = false;
    return plain;
}

// Every file gpdr writes, in the order they are written and renamed into
// place (the largest first: they take longest to format).
constexpr OutputFile output_files[] = {
    {[](const Wants& c) { return !c.options.no_node_output; }, &FileNames::out_node,
     [](io::OutputTransaction& out, const std::string& path, const OutputContext& c) {
         io::write_node(out, path, c.arrays.nodes, c.format);
     }},
    {[](const Wants& c) { return !c.options.no_ele_output; }, &FileNames::out_ele,
     [](io::OutputTransaction& out, const std::string& path, const OutputContext& c) {
         io::write_ele(out, path, triangle_source(c.arrays), c.format);
     }},
    {[](const Wants& c) { return c.want_poly; }, &FileNames::out_poly, write_output_poly},
    {[](const Wants& c) { return c.options.write_edges; }, &FileNames::out_edge,
     [](io::OutputTransaction& out, const std::string& path, const OutputContext& c) {
         io::write_edge(out, path, c.prepared.edges, c.format);
     }},
    {[](const Wants& c) { return c.options.write_voronoi; }, &FileNames::out_v_node,
     [](io::OutputTransaction& out, const std::string& path, const OutputContext& c) {
         io::write_node(out, path, c.prepared.voronoi.vertices, without_markers(c.format));
     }},
    {[](const Wants& c) { return c.options.write_voronoi; }, &FileNames::out_v_edge,
     [](io::OutputTransaction& out, const std::string& path, const OutputContext& c) {
         io::write_voronoi_edge(out, path, c.prepared.voronoi.edges, without_markers(c.format));
     }},
    {[](const Wants& c) { return c.options.write_neighbours; }, &FileNames::out_neigh,
     [](io::OutputTransaction& out, const std::string& path, const OutputContext& c) {
         io::write_neigh(out, path, c.arrays.neighbours, c.format);
     }},
    {[](const Wants& c) { return c.options.write_off; }, &FileNames::out_off,
     [](io::OutputTransaction& out, const std::string& path, const OutputContext& c) {
         io::write_off(out, path, c.arrays.nodes, c.arrays.triangles, c.prepared.edge_count,
                       c.format);
     }},
    {[](const Wants& c) { return c.options.write_vtk; }, &FileNames::out_vtu,
     [](io::OutputTransaction& out, const std::string& path, const OutputContext& c) {
         io::write_vtu(out, path, c.exported, c.format);
     }},
    {[](const Wants& c) { return c.options.write_gmsh; }, &FileNames::out_msh,
     [](io::OutputTransaction& out, const std::string& path, const OutputContext& c) {
         io::write_msh(out, path, c.exported, c.format);
     }},
    {[](const Wants& c) { return c.options.write_svg; }, &FileNames::out_svg,
     [](io::OutputTransaction& out, const std::string& path, const OutputContext& c) {
         io::write_svg(out, path, c.exported, c.format);
     }},
};

// What the files for other programs read: the arrays, and the triangles
// once per pass they make (a fresh source each time).
io::MeshExport exported_mesh(const MeshArrays& arrays, const SegmentSet& segments) {
    io::MeshExport exported;
    const io::EleSource first = triangle_source(arrays);
    exported.nodes = &arrays.nodes;
    exported.triangle_count = first.count;
    exported.corners_per_triangle = first.corners_per_triangle;
    exported.attribute_count = first.attribute_count;
    exported.triangles = [&arrays] { return triangle_source(arrays); };
    exported.segments = &segments;
    return exported;
}

}  // namespace

bool writes_files(const Options& options, const FileNames& names, bool write_hull_poly) {
    const Wants wants{options, wants_poly(options, names, write_hull_poly)};
    return std::any_of(std::begin(output_files), std::end(output_files),
                       [&](const OutputFile& file) { return file.wanted(wants); });
}

std::vector<std::string> write_outputs(const OutputRequest& request, const mesh::Mesh& mesh,
                                       MeshArrays& arrays) {
    const Options& o = *request.options;
    const FileNames& names = *request.names;
    if (request.progress != nullptr) request.progress->enter(Progress::Stage::writing);
    io::FormatThreads threads(parallel::thread_count(o.threads));
    const io::WriteFormat format{request.base, !o.no_boundary_markers,
                                 o.command.empty() ? std::string("gpdr") : o.command, request.stamp,
                                 threads.threads() > 1 ? &threads : nullptr};

    const bool want_poly = wants_poly(o, names, request.write_hull_poly);
    const PreparedOutputs prepared = prepare_outputs(o, mesh, arrays);
    static const SegmentSet no_segments;
    const SegmentSet& segments =
        want_poly || o.write_gmsh || o.write_svg ? arrays.segments : no_segments;
    const bool for_others = o.write_vtk || o.write_gmsh || o.write_svg;
    const io::MeshExport exported = for_others ? exported_mesh(arrays, segments) : io::MeshExport{};
    const OutputContext context{o,      names,    request,  arrays,   prepared,
                                format, exported, segments, want_poly};

    std::vector<FileJob> jobs;
    for (const OutputFile& file : output_files) {
        if (!file.wanted(Wants{o, want_poly})) continue;
        const std::string& path = names.*file.path;
        jobs.push_back({path, [&context, &file, &path](io::OutputTransaction& out) {
                            file.write(out, path, context);
                        }});
    }
    if (request.progress != nullptr) request.progress->set_files(jobs.size());
    write_all(jobs, threads, request.progress);
    std::vector<std::string> written;
    for (const FileJob& j : jobs) written.push_back(j.target);
    return written;
}

}  // namespace gpdr::api
