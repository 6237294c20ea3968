#pragma once
// The names of every file one run reads and writes, worked out from the
// input name as Triangle 1.6 does: a known extension is stripped (and may
// imply switches), and the output base carries the next iteration number
// (box.poly -> box.1.*, box.1 -> box.2.*) unless -I.

#include <string>
#include <string_view>

#include <gpdr/options.hpp>

namespace gpdr {

// What the input name says by itself.
struct InputName {
    std::string base;            // the name without .node/.poly/.ele/.area
    bool poly = false;           // it ended in .poly: implies -p
    bool refine = false;         // it ended in .ele or .area: implies -r
    bool regional_area = false;  // it ended in .area: implies bare -a
};

// Strips the extensions Triangle strips, in its order: .node, then .poly,
// then .ele, then .area, each from what the previous step left.
InputName split_input_name(std::string_view input);

// The output base for an input base without -I: if the text after the last
// '.' (not the name's first character, not its last) is all digits N, it
// becomes N+1 ("box.1" -> "box.2", "box.09" -> "box.10"); otherwise ".1" is
// appended ("box" -> "box.1", "dir.v2/box" -> "dir.v2/box.1").
std::string next_output_base(std::string_view input_base);

// Applies the switches options.input's extension implies (.poly: -p; .ele:
// -r; .area: -r and bare -a).  Throws UsageError when options.input is empty
// or -I is combined with refining (Triangle refuses it: the outputs would
// replace the mesh being refined).  Calling it twice changes nothing more.
void apply_input_name(Options& options);

struct FileNames {
    std::string input_base;   // e.g. "box" for box.poly, "box.1" for box.1.ele
    std::string output_base;  // e.g. "box.1", "box.2"; input_base with -I

    // What the run may read (which ones it does read depends on -p, -r, -a).
    std::string in_node, in_poly, in_ele, in_area;

    // What the run may write (which ones depends on -e -v -n -g -N -E -P,
    // --vtk, --gmsh, --svg).
    // out_poly is empty with -I: Triangle never writes a .poly then, so as not
    // to replace the input .poly.
    std::string out_node, out_ele, out_poly, out_edge, out_neigh, out_v_node, out_v_edge, out_off;
    std::string out_vtu, out_msh, out_svg;
};

// Every name for options.input under the given switches (the implied ones
// included whether or not apply_input_name() ran).  Throws UsageError as
// apply_input_name() does.
FileNames file_names(const Options& options);

}  // namespace gpdr
