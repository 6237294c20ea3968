#pragma once
// Every setting a Triangle-style command line can make.  Options holds only
// what the user asked for; mesh state lives elsewhere (as in Triangle, where
// `struct behavior` and `struct mesh` are kept apart).

#include <cstdint>
#include <string>

namespace gpdr {

// Where a Steiner point goes inside the selection disk of a poor triangle.
enum class Placement : int {
    circumcentre = 0,
    off_centre = 1,    // Üngör's off-centre; Triangle's default
    optimisation = 2,  // the GPDR paper's point on the arc Γ minimising F
};

struct Options {
    // Triangle 1.6 switches, in the order of its help text.
    bool poly = false;                 // -p  read a PSLG (.poly)
    bool refine = false;               // -r  refine a previous mesh
    bool quality = false;              // -q  quality refinement
    double min_angle = 20.0;           //     -q<deg>, degrees
    bool area_limit = false;           // -a<area> given
    double max_area = -1.0;            //     the global bound (> 0 when area_limit)
    bool regional_area = false;        // bare -a: bounds from .poly regions or .area
    bool user_test = false;            // -u  triunsuitable()
    bool region_attributes = false;    // -A
    bool convex_hull = false;          // -c
    bool conforming_delaunay = false;  // -D
    bool jettison = false;             // -j  (bare)
    bool write_edges = false;          // -e
    bool write_voronoi = false;        // -v
    bool write_neighbours = false;     // -n
    bool write_off = false;            // -g  (bare)
    bool no_boundary_markers = false;  // -B
    bool no_poly_output = false;       // -P  (bare)
    bool no_node_output = false;       // -N
    bool no_ele_output = false;        // -E
    bool no_iteration_numbers = false; // -I
    bool ignore_holes = false;         // -O
    bool no_exact = false;             // -X  (accepted; gpdr is always exact)
    bool zero_based = false;           // -z
    int order = 1;                     // -o2 gives 2: six-node triangles
    int no_segment_splitting = 0;      // -Y: 1 boundary segments, -YY: 2 all segments
    bool steiner_limit = false;        // -S given
    std::uint64_t max_steiner = 0;     //     -S<n>; bare -S means 0
    bool incremental = false;          // -i  (algorithm choice, accepted)
    bool sweepline = false;            // -F  (algorithm choice, accepted)
    bool vertical_cuts = false;        // -l  (algorithm choice, accepted)
    bool split_segments = false;       // -s
    bool check = false;                // -C
    bool quiet = false;                // -Q
    int verbosity = 0;                 // -V, repeatable

    // gpdr's own.
    unsigned threads = 0;              // -jN / --threads; 0: hardware threads
    unsigned granularity = 0;          // -gN / --granularity; 0: built-in default
    Placement placement = Placement::off_centre;  // -PN / --placement
    std::string unsuitable_library;    // --unsuitable PATH.so

    // The input name as given on the command line (last one wins).
    std::string input;
};

}  // namespace gpdr
