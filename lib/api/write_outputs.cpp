// The output stage: every file the switches ask for, all or none, so that a
// failure leaves no partial result and no earlier result clobbered.  With
// several threads (-jN) the files are formatted and written side by side,
// and a thread with no file left to start formats pieces of the large files
// still being written (io/format_threads.hpp): formatting numbers is most of
// the stage, and the .ele file of a large mesh alone costs more than the
// .node beside it.

#include <atomic>
#include <exception>
#include <functional>
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

std::vector<std::string> write_outputs(const OutputRequest& request, const mesh::Mesh& mesh,
                                       MeshArrays& arrays) {
    const Options& o = *request.options;
    const FileNames& names = *request.names;
    if (request.progress != nullptr) request.progress->enter(Progress::Stage::writing);
    io::FormatThreads threads(parallel::thread_count(o.threads));
    const io::WriteFormat format{request.base, !o.no_boundary_markers,
                                 o.command.empty() ? std::string("gpdr") : o.command, request.stamp,
                                 threads.threads() > 1 ? &threads : nullptr};

    const bool want_poly =
        (o.poly || request.write_hull_poly) && !o.no_poly_output && !names.out_poly.empty();
    const PreparedOutputs prepared = prepare_outputs(o, mesh, arrays);
    const EdgeSet& edges = prepared.edges;
    const VoronoiDiagram& voronoi = prepared.voronoi;
    const std::uint64_t edge_count = prepared.edge_count;
    const bool for_others = o.write_vtk || o.write_gmsh || o.write_svg;
    static const SegmentSet no_segments;
    const SegmentSet& segments =
        want_poly || o.write_gmsh || o.write_svg ? arrays.segments : no_segments;
    // What the files for other programs read: the arrays, and the
    // triangles once per pass they make (a fresh source each time).
    io::MeshExport exported;
    if (for_others) {
        const io::EleSource first = triangle_source(arrays);
        exported.nodes = &arrays.nodes;
        exported.triangle_count = first.count;
        exported.corners_per_triangle = first.corners_per_triangle;
        exported.attribute_count = first.attribute_count;
        exported.triangles = [&arrays] { return triangle_source(arrays); };
        exported.segments = &segments;
    }

    // Each job keeps what it needs by value or refers to data that stays
    // put until write_all returns; all of it is only read.
    std::vector<FileJob> jobs;
    const auto add = [&](const std::string& target,
                         std::function<void(io::OutputTransaction&)> write) {
        jobs.push_back({target, std::move(write)});
    };
    if (!o.no_node_output)
        add(names.out_node, [&](io::OutputTransaction& out) {
            io::write_node(out, names.out_node, arrays.nodes, format);
        });
    if (!o.no_ele_output)
        add(names.out_ele, [&](io::OutputTransaction& out) {
            io::write_ele(out, names.out_ele, triangle_source(arrays), format);
        });
    if (want_poly) {
        add(names.out_poly, [&](io::OutputTransaction& out) {
            PolyFile poly;
            poly.nodes_from_node_file = true;  // Triangle's output .poly refers to the .node
            poly.nodes.attribute_count = arrays.nodes.attribute_count;
            // write_poly() takes the header's marker column from nodes.markers.
            if (arrays.nodes.has_markers()) poly.nodes.markers.assign(1, 0);
            poly.segments = segments;
            if (request.poly) {
                poly.holes = request.poly->holes;
                poly.regions = request.poly->regions;
            }
            io::write_poly(out, names.out_poly, poly, format);
        });
    }
    if (o.write_edges)
        add(names.out_edge, [&](io::OutputTransaction& out) {
            io::write_edge(out, names.out_edge, edges, format);
        });
    if (o.write_voronoi) {
        io::WriteFormat plain = format;
        plain.markers = false;
        add(names.out_v_node, [&voronoi, &names, plain](io::OutputTransaction& out) {
            io::write_node(out, names.out_v_node, voronoi.vertices, plain);
        });
        add(names.out_v_edge, [&voronoi, &names, plain](io::OutputTransaction& out) {
            io::write_voronoi_edge(out, names.out_v_edge, voronoi.edges, plain);
        });
    }
    if (o.write_neighbours)
        add(names.out_neigh, [&](io::OutputTransaction& out) {
            io::write_neigh(out, names.out_neigh, arrays.neighbours, format);
        });
    if (o.write_off)
        add(names.out_off, [&](io::OutputTransaction& out) {
            io::write_off(out, names.out_off, arrays.nodes, arrays.triangles, edge_count, format);
        });
    if (o.write_vtk)
        add(names.out_vtu, [&](io::OutputTransaction& out) {
            io::write_vtu(out, names.out_vtu, exported, format);
        });
    if (o.write_gmsh)
        add(names.out_msh, [&](io::OutputTransaction& out) {
            io::write_msh(out, names.out_msh, exported, format);
        });
    if (request.progress != nullptr) request.progress->set_files(jobs.size());
    if (o.write_svg)
        add(names.out_svg, [&](io::OutputTransaction& out) {
            io::write_svg(out, names.out_svg, exported, format);
        });
    write_all(jobs, threads, request.progress);
    std::vector<std::string> written;
    for (const FileJob& j : jobs) written.push_back(j.target);
    return written;
}

}  // namespace gpdr::api
