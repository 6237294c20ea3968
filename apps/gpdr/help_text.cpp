// gpdr's usage, help and version texts.  The switch list follows the order
// of Triangle 1.6's help so that its users find each letter where they expect
// it; the wording is gpdr's own.  man/gpdr.1 says the same at more length.
//
// tests/cli/switch_reference_test.cpp checks the help's switch reference
// against the parser: it runs from "Switches:" through every block (an
// unindented header and the indented lines under it) whose first indented
// line is an entry, and an entry is a line starting with two spaces and a
// dash that names its switches separated by ", " ("  -jN, --threads N").
// Every switch letter and long option the parser accepts needs an entry.
#include "help_text.hpp"

#include <fmt/format.h>

#ifndef GPDR_VERSION
#define GPDR_VERSION "unknown"
#endif

namespace gpdr::app {

std::string version_text() { return fmt::format("gpdr {}\n", GPDR_VERSION); }

std::string usage_text() {
    return "Usage: gpdr [-prq__a__uAcDjevngBPNEIOXzo_YS__iFlsCQVh] [--threads N]\n"
           "            [--granularity N] [--placement NAME] [--unsuitable LIB.so] [--force]\n"
           "            [--vtk] [--gmsh] [--svg] input_file\n"
           "\n"
           "Meshes input_file (.node, or .poly with -p; -r refines a .node/.ele mesh) and\n"
           "writes the result as input.1.node, input.1.ele, ...  Numbers follow their\n"
           "switch with no space: -pq30a0.1.\n"
           "\n"
           "  gpdr -pq box.poly     quality mesh of a PSLG, no angle below 20 degrees\n"
           "  gpdr -h               every switch, the files, and the exit status\n";
}

std::string help_text() {
    return version_text() +
           "A parallel two-dimensional quality mesh generator and Delaunay triangulator,\n"
           "and a drop-in replacement for Triangle 1.6: the same switches, the same files.\n"
           "\n"
           "Usage: gpdr [-prq__a__uAcDjevngBPNEIOXzo_YS__iFlsCQVh] [long options] input_file\n"
           "\n"
           "Letters may be grouped (-pq30a0.1 is -p -q30 -a0.1) and are read left to\n"
           "right; a number follows its letter with no space.  An unknown letter is an\n"
           "error.  The input is a .node file, a .poly file with -p, or with -r a mesh\n"
           "given by its .node and .ele files (and .poly, .area when -p, -a ask for them).\n"
           "The extension may be left off; .poly implies -p, .ele implies -r, and .area\n"
           "implies -r and -a.\n"
           "\n"
           "Switches:\n"
           "  -p        Read a planar straight line graph (.poly): vertices, segments,\n"
           "            holes, regions.  Triangulate it keeping every segment; without -c,\n"
           "            remove the triangles outside the segments and in holes.\n"
           "  -r        Refine the mesh in input.node and input.ele (a previous output).\n"
           "  -q[ANGLE] Quality mesh: no angle below ANGLE degrees (default 20; at most\n"
           "            about 34 is practical, and below 60 is required).  Also keeps the\n"
           "            largest angle below 180 - 2 ANGLE.\n"
           "  -a[AREA]  With a number: no triangle larger than AREA (above zero; 1e-5 style\n"
           "            exponents allowed).  Bare: area bounds per region from the .poly,\n"
           "            or per triangle from input.area with -r (each bound holds where its\n"
           "            triangle lies, for the triangles whose centroid is there).  Both\n"
           "            may be given: -aa0.5.\n"
           "  -u        Refine triangles that the user's triunsuitable() rejects.\n"
           "  -A        Give each triangle the attribute of the region holding it (-p).\n"
           "  -c        Enclose the convex hull with segments and mesh all of it.\n"
           "  -D        Conforming Delaunay: make every triangle Delaunay, not only\n"
           "            constrained Delaunay.\n"
           "  -j        Jettison vertices that no triangle uses from the output .node.\n"
           "  -e        Also write the edges (.edge).\n"
           "  -v        Also write the Voronoi diagram (.v.node and .v.edge).\n"
           "  -n        Also write each triangle's neighbours (.neigh).\n"
           "  -g        Also write the mesh as an Object File Format file (.off).\n"
           "  -B        Write no boundary markers.\n"
           "  -P        Write no .poly file.\n"
           "  -N        Write no .node file.\n"
           "  -E        Write no .ele file.\n"
           "  -I        No iteration number in output names (box.node, not box.1.node);\n"
           "            not with -r, and no .poly is written.\n"
           "  -O        Ignore the holes of the .poly file.\n"
           "  -X        Accepted for Triangle's sake; gpdr's arithmetic is always exact.\n"
           "  -z        Number items from zero (the input's first index still decides).\n"
           "  -o2       Write six-node (second-order) triangles.\n"
           "  -Y        Add no vertices on the boundary segments.  -YY: on any segment.\n"
           "  -S[N]     Add at most N Steiner vertices (bare: none); vertices where\n"
           "            segments cross are always added and count against N.\n"
           "  -i        Incremental insertion (Triangle's algorithm choice; accepted, no effect:\n"
           "            gpdr always inserts incrementally in Hilbert-curve order).\n"
           "  -F        Fortune's sweepline (accepted, no effect, as -i).\n"
           "  -l        Vertical cuts only (accepted, no effect, as -i).\n"
           "  -s        Segments by splitting (accepted, no effect: gpdr always inserts\n"
           "            segments by constrained retriangulation).\n"
           "  -C        Check the final mesh: topology, orientation, constrained Delaunay,\n"
           "            and against the input (segments covered, boundary, vertices, holes,\n"
           "            regions, bounds).  On a problem nothing is written (status 4).\n"
           "  -Q        Quiet: print no \"Wrote\" lines, no warnings, no progress line.\n"
           "  -V        Verbose: print statistics; repeat (-VV, -VVV) for more.\n"
           "  -h, -H, -?\n"
           "            Print this help and exit; the rest of the command line is not read.\n"
           "\n"
           "gpdr's own (a digit right after j, g or P; bare they mean the above):\n"
           "  -jN, --threads N       Refine on N threads (0: one per hardware thread), in\n"
           "                         rounds of quadtree leaves chosen from the mesh alone: the\n"
           "                         files are the same, to the byte, for every N >= 2 and\n"
           "                         every run.  -j1 refines on the calling thread alone in\n"
           "                         Triangle's order (a mesh of its own), as does -S (its\n"
           "                         limit is exact only there), and so does every N with\n"
           "                         -q above 33 degrees (there the order decides whether\n"
           "                         refinement ends).  At most 64 threads refine.\n"
           "                         With -V, the rounds and where each thread's time went.\n"
           "                         The output files are written, and -V's statistics\n"
           "                         taken, on up to N threads.\n"
           "  -gN, --granularity N   How many sigma levels a worker refines in a quadtree leaf\n"
           "                         before the leaf splits (0: the default, 5; a leaf k\n"
           "                         levels below the root, at most k); smaller makes\n"
           "                         more, smaller leaves: more to share among many\n"
           "                         threads (-g4, -g3), more upkeep on few.\n"
           "  -PN, --placement NAME  Where Steiner points go: 0 circumcentre,\n"
           "                         1 off-centre (the default, as Triangle),\n"
           "                         2 optimisation (the GPDR paper's point).\n"
           "  --unsuitable LIB.so    Load triunsuitable() from a shared object (implies -u; it\n"
           "                         replaces one linked into gpdr).\n"
           "  --force                Refine even when the mesh the area bounds call for is\n"
           "                         estimated to need more memory than is available (gpdr\n"
           "                         refuses such a run otherwise, writing nothing).\n"
           "  --vtk                  Also write the mesh for ParaView and meshio (.vtu: VTK\n"
           "                         XML, binary): markers, attributes, each triangle's\n"
           "                         smallest angle and area.  Numbered from 0.\n"
           "  --gmsh                 Also write the mesh for gmsh and its solvers (.msh,\n"
           "                         MSH 4.1): regions and segment markers as physical\n"
           "                         groups.  Numbered from 1.\n"
           "  --svg                  Also write a picture of the mesh (.svg): triangles shaded\n"
           "                         by smallest angle or region, segments, a legend; above\n"
           "                         20000 triangles, shaded by mesh density instead.\n"
           "  --help                 The same as -h.\n"
           "  --version              Print the version and exit.\n"
           "\n"
           "Files (input box.poly; outputs box.1.*, or box.2.* when refining box.1):\n"
           "  .node .poly .ele .area     inputs, the same formats as Triangle's\n"
           "  .node .ele .poly           outputs (unless -N, -E, -P)\n"
           "  .edge .neigh .v.node .v.edge .off   outputs with -e, -n, -v, -g\n"
           "  .vtu .msh .svg             outputs with --vtk, --gmsh, --svg\n"
           "\n"
           "Messages: \"Wrote FILE\" lines and statistics on standard output; warnings\n"
           "and errors as \"gpdr: ...\" on standard error, where a terminal also gets a\n"
           "progress line during runs longer than a second.  Exit status: 0 on success (and\n"
           "for -h and for no input), 1 on any error, 2 out of memory, 3 an internal\n"
           "error (a bug in gpdr), 4 when -C found problems (no file written), 128 + n\n"
           "when killed by signal n.\n"
           "See gpdr(1) for the file formats and the few deliberate differences from\n"
           "Triangle.  --nondeterministic is refused: the files are the same for every\n"
           "thread count from 2 up, and -j1 refines on one thread in Triangle's order.\n";
}

}  // namespace gpdr::app
