// The read stage of a run: which files the switches name, read and checked
// in full before any meshing starts.

#include <gpdr/io.hpp>

#include "api/job_stages.hpp"
#include "io/content_hash.hpp"
#include "parallel/schedule.hpp"

namespace gpdr::api {

Input read_input(const Options& options, const FileNames& names, const WarningSink& warn) {
    const int default_base = options.zero_based ? 0 : 1;
    // -jN reads the vertex lines of a large .node or .poly on N threads.
    const unsigned threads = parallel::thread_count(options.threads);
    Input in;
    if (options.poly && !options.refine) {
        auto poly = io::read_poly(names.in_poly, warn, default_base, nullptr, threads);
        in.nodes.base = poly.base;
        in.nodes.data = std::move(poly.data.nodes);
        in.node_file = poly.data.nodes_from_node_file ? names.in_node : names.in_poly;
        in.poly_file = names.in_poly;
        poly.data.nodes = {};
        in.poly = std::move(poly.data);
        in.content_hash = poly.content_hash;
        return in;
    }
    in.nodes = io::read_node(names.in_node, warn, default_base, threads);
    in.node_file = names.in_node;
    in.content_hash = in.nodes.content_hash;
    if (options.refine) {
        const int base = in.nodes.base;
        auto ele = io::read_ele(names.in_ele, base, in.nodes.data.size(), warn);
        in.ele_file = names.in_ele;
        in.content_hash = io::hash_number(in.content_hash, ele.content_hash);
        if (options.poly) {
            // The .poly of a mesh written by gpdr or Triangle has no vertices
            // of its own (count 0): they are those of the .node just read,
            // which is not read twice (a pipe could not be).
            const io::KnownNodes known{in.nodes.data.size(), in.nodes.base, in.nodes.content_hash};
            auto poly = io::read_poly(names.in_poly, warn, default_base, &known, threads);
            poly.data.nodes = {};
            in.poly_file = names.in_poly;
            in.poly = std::move(poly.data);
            in.content_hash = io::hash_number(in.content_hash, poly.content_hash);
        }
        if (options.regional_area) {
            auto areas = io::read_area(names.in_area, base, ele.data.size(), warn);
            in.content_hash = io::hash_number(in.content_hash, areas.content_hash);
            in.areas = std::move(areas.data);
        }
        in.triangles = std::move(ele.data);
    }
    return in;
}

}  // namespace gpdr::api
