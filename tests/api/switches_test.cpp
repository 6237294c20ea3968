// parse_switches(): a table of switch strings and the Options they give,
// covering every Triangle 1.6 letter, the numbers after q, a, S, o2, gpdr's
// numbered j, g, P, and the errors gpdr adds (unknown letters, values out of
// range).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <fmt/format.h>

#include <gpdr/errors.hpp>
#include <gpdr/switches.hpp>

using gpdr::Options;
using gpdr::Placement;

namespace {

// Every field, so that a row checks that nothing else changed either.
std::string describe(const Options& o) {
    return fmt::format(
        "p{} r{} q{} angle{} alimit{} area{} aregion{} u{} A{} c{} D{} jet{} e{} v{} n{} off{} "
        "B{} P{} N{} E{} I{} O{} X{} z{} o{} Y{} Slimit{} S{} i{} F{} l{} s{} C{} Q{} V{} h{} "
        "threads{} gran{} place{} lib'{}' in'{}'",
        o.poly, o.refine, o.quality, o.min_angle, o.area_limit, o.max_area, o.regional_area,
        o.user_test, o.region_attributes, o.convex_hull, o.conforming_delaunay, o.jettison,
        o.write_edges, o.write_voronoi, o.write_neighbours, o.write_off, o.no_boundary_markers,
        o.no_poly_output, o.no_node_output, o.no_ele_output, o.no_iteration_numbers, o.ignore_holes,
        o.no_exact, o.zero_based, o.order, o.no_segment_splitting, o.steiner_limit, o.max_steiner,
        o.incremental, o.sweepline, o.vertical_cuts, o.split_segments, o.check, o.quiet,
        o.verbosity, o.help, o.threads, o.granularity, static_cast<int>(o.placement),
        o.unsuitable_library, o.input);
}

Options parse(const std::vector<std::string>& clusters) {
    Options o;
    for (const auto& c : clusters) gpdr::parse_switches(c, o);
    return o;
}

struct Row {
    std::vector<std::string> clusters;
    void (*expect)(Options&);  // turns default Options into the expected ones
};

}  // namespace

TEST_CASE("parse_switches reads every switch as Triangle does", "[api][switches]") {
    const std::vector<Row> rows = {
        {{""}, [](Options&) {}},
        {{"-p"}, [](Options& o) { o.poly = true; }},
        {{"p"}, [](Options& o) { o.poly = true; }},  // the leading '-' is optional
        {{"-r"}, [](Options& o) { o.refine = true; }},
        {{"-q"},
         [](Options& o) {
             o.quality = true;
             o.min_angle = 20;
         }},
        {{"-q30"},
         [](Options& o) {
             o.quality = true;
             o.min_angle = 30;
         }},
        {{"-q32.5"},
         [](Options& o) {
             o.quality = true;
             o.min_angle = 32.5;
         }},
        {{"-q.5"},
         [](Options& o) {
             o.quality = true;
             o.min_angle = 0.5;
         }},
        {{"-q0"},
         [](Options& o) {
             o.quality = true;
             o.min_angle = 0;
         }},
        {{"-q30q"},
         [](Options& o) {
             o.quality = true;
             o.min_angle = 20;
         }},  // last one wins
        {{"-q1e1"},
         [](Options& o) {
             o.quality = true;
             o.min_angle = 10;
         }},
        {{"-a"}, [](Options& o) { o.regional_area = true; }},
        {{"-a0.5"},
         [](Options& o) {
             o.area_limit = true;
             o.max_area = 0.5;
         }},
        {{"-a.25"},
         [](Options& o) {
             o.area_limit = true;
             o.max_area = 0.25;
         }},
        {{"-aa0.5"},
         [](Options& o) {
             o.regional_area = true;
             o.area_limit = true;
             o.max_area = 0.5;
         }},
        {{"-a0.5a"},
         [](Options& o) {
             o.regional_area = true;
             o.area_limit = true;
             o.max_area = 0.5;
         }},
        {{"-a1a2"},
         [](Options& o) {
             o.area_limit = true;
             o.max_area = 2;
         }},
        {{"-a1e-5"},
         [](Options& o) {
             o.area_limit = true;
             o.max_area = 1e-5;
         }},
        {{"-a1e+2"},
         [](Options& o) {
             o.area_limit = true;
             o.max_area = 100;
         }},
        {{"-a2.5e3"},
         [](Options& o) {
             o.area_limit = true;
             o.max_area = 2500;
         }},
        {{"-a1e"},
         [](Options& o) {
             o.area_limit = true;
             o.max_area = 1;
             o.write_edges = true;
         }},
        {{"-a1ep"},
         [](Options& o) {
             o.area_limit = true;
             o.max_area = 1;
             o.write_edges = true;
             o.poly = true;
         }},
        {{"-u"}, [](Options& o) { o.user_test = true; }},
        {{"-A"}, [](Options& o) { o.region_attributes = true; }},
        {{"-c"}, [](Options& o) { o.convex_hull = true; }},
        {{"-D"}, [](Options& o) { o.conforming_delaunay = true; }},
        {{"-j"}, [](Options& o) { o.jettison = true; }},
        {{"-jq"},
         [](Options& o) {
             o.jettison = true;
             o.quality = true;
         }},
        {{"-j4"}, [](Options& o) { o.threads = 4; }},
        {{"-j0"}, [](Options& o) { o.threads = 0; }},
        {{"-j4j"},
         [](Options& o) {
             o.threads = 4;
             o.jettison = true;
         }},
        {{"-e"}, [](Options& o) { o.write_edges = true; }},
        {{"-v"}, [](Options& o) { o.write_voronoi = true; }},
        {{"-n"}, [](Options& o) { o.write_neighbours = true; }},
        {{"-g"}, [](Options& o) { o.write_off = true; }},
        {{"-g64"}, [](Options& o) { o.granularity = 64; }},
        {{"-g64g"},
         [](Options& o) {
             o.granularity = 64;
             o.write_off = true;
         }},
        {{"-B"}, [](Options& o) { o.no_boundary_markers = true; }},
        {{"-P"}, [](Options& o) { o.no_poly_output = true; }},
        {{"-P0"}, [](Options& o) { o.placement = Placement::circumcentre; }},
        {{"-P1"}, [](Options& o) { o.placement = Placement::off_centre; }},
        {{"-P2"}, [](Options& o) { o.placement = Placement::optimisation; }},
        {{"-P2P"},
         [](Options& o) {
             o.placement = Placement::optimisation;
             o.no_poly_output = true;
         }},
        {{"-N"}, [](Options& o) { o.no_node_output = true; }},
        {{"-E"}, [](Options& o) { o.no_ele_output = true; }},
        {{"-I"}, [](Options& o) { o.no_iteration_numbers = true; }},
        {{"-O"}, [](Options& o) { o.ignore_holes = true; }},
        {{"-X"}, [](Options& o) { o.no_exact = true; }},
        {{"-z"}, [](Options& o) { o.zero_based = true; }},
        {{"-o2"}, [](Options& o) { o.order = 2; }},
        {{"-Y"}, [](Options& o) { o.no_segment_splitting = 1; }},
        {{"-YY"}, [](Options& o) { o.no_segment_splitting = 2; }},
        {{"-Y", "-Y"}, [](Options& o) { o.no_segment_splitting = 2; }},
        {{"-YYY"}, [](Options& o) { o.no_segment_splitting = 2; }},
        {{"-S"},
         [](Options& o) {
             o.steiner_limit = true;
             o.max_steiner = 0;
         }},
        {{"-S500"},
         [](Options& o) {
             o.steiner_limit = true;
             o.max_steiner = 500;
         }},
        {{"-S500S"},
         [](Options& o) {
             o.steiner_limit = true;
             o.max_steiner = 0;
         }},
        {{"-S10000000000"},
         [](Options& o) {
             o.steiner_limit = true;
             o.max_steiner = 10000000000ull;
         }},
        {{"-i"}, [](Options& o) { o.incremental = true; }},
        {{"-F"}, [](Options& o) { o.sweepline = true; }},
        {{"-l"}, [](Options& o) { o.vertical_cuts = true; }},
        {{"-s"}, [](Options& o) { o.split_segments = true; }},
        {{"-C"}, [](Options& o) { o.check = true; }},
        {{"-Q"}, [](Options& o) { o.quiet = true; }},
        {{"-V"}, [](Options& o) { o.verbosity = 1; }},
        {{"-VVV"}, [](Options& o) { o.verbosity = 3; }},
        {{"-V", "-VV"}, [](Options& o) { o.verbosity = 3; }},
        {{"-h"}, [](Options& o) { o.help = true; }},
        {{"-H"}, [](Options& o) { o.help = true; }},
        {{"-ph"},
         [](Options& o) {
             o.poly = true;
             o.help = true;
         }},
        {{"-hk"}, [](Options& o) { o.help = true; }},  // Triangle stops at h
        {{"-pq30a0.1"},
         [](Options& o) {
             o.poly = o.quality = o.area_limit = true;
             o.min_angle = 30;
             o.max_area = 0.1;
         }},
        {{"-p", "-q30", "-a0.1"},
         [](Options& o) {
             o.poly = o.quality = o.area_limit = true;
             o.min_angle = 30;
             o.max_area = 0.1;
         }},
        {{"-pq33.5a.001DYYS100o2zAevngBPNEIOXilsCQV"},
         [](Options& o) {
             o.poly = o.quality = o.area_limit = true;
             o.min_angle = 33.5;
             o.max_area = 0.001;
             o.conforming_delaunay = true;
             o.no_segment_splitting = 2;
             o.steiner_limit = true;
             o.max_steiner = 100;
             o.order = 2;
             o.zero_based = o.region_attributes = o.write_edges = o.write_voronoi = true;
             o.write_neighbours = o.write_off = o.no_boundary_markers = o.no_poly_output = true;
             o.no_node_output = o.no_ele_output = o.no_iteration_numbers = o.ignore_holes = true;
             o.no_exact = o.incremental = o.vertical_cuts = o.split_segments = true;
             o.check = o.quiet = true;
             o.verbosity = 1;
         }},
        {{"-rpj2g8P0uc"},
         [](Options& o) {
             o.refine = o.poly = o.user_test = o.convex_hull = true;
             o.threads = 2;
             o.granularity = 8;
             o.placement = Placement::circumcentre;
         }},
    };
    for (const Row& row : rows) {
        INFO("switches: " << fmt::format("{}", fmt::join(row.clusters, " ")));
        Options expected;
        row.expect(expected);
        CHECK(describe(parse(row.clusters)) == describe(expected));
    }
}

TEST_CASE("parse_switches rejects what Triangle would misread", "[api][switches]") {
    struct Bad {
        std::string cluster;
        std::string message_part;  // the message must say this
    };
    const std::vector<Bad> rows = {
        {"-k", "unknown switch -k"},
        {"-pqk", "-pqk"},
        {"-x", "did you mean -X?"},
        {"-d", "did you mean -D?"},
        {"-L", "-D"},
        {"-w", "weighted"},
        {"-5", "number must follow"},
        {"-p-q", "write switches together"},
        {"-a1e-p", "unknown switch '-'"},  // 'e' then '-' and no digit: not an exponent
        {"-", "standard input"},
        {"-threads", "did you mean --threads?"},
        {"-version", "did you mean --version?"},
        // Every long option gets suggested (gpdr::long_option_names; -svg
        // is -s -v -g, three switches).
        {"-vtk", "did you mean --vtk?"},
        {"-gmsh", "did you mean --gmsh?"},
        {"-force", "did you mean --force?"},
        {"-unsuitable", "did you mean --unsuitable?"},
        {"-placement", "--placement"},
        {"-q70", "-q70"},
        {"-q60", "below 60"},
        {"-q-5", "-q-5"},
        {"-q3.2.1", "not a number"},
        {"-q.", "not a number"},
        {"-a0", "greater than zero"},
        {"-a0.0", "greater than zero"},
        {"-a-1", "-a-1"},
        {"-a1..", "not a number"},
        {"-a1e999", "out of range"},
        {"-o", "-o: write -o2"},
        {"-o3", "-o in -o3: write -o2"},
        {"-P3", "placement"},
        {"-P12", "-P12"},
        {"-S99999999999999999999999", "too large"},
        {"-j99999999999", "too large"},
        {"-g99999999999", "too large"},
        {"-p\x01", "byte 0x01"},
    };
    for (const Bad& bad : rows) {
        INFO("switches: " << bad.cluster);
        Options o;
        try {
            gpdr::parse_switches(bad.cluster, o);
            FAIL("no UsageError");
        } catch (const gpdr::UsageError& e) {
            CHECK_THAT(e.what(), Catch::Contains(bad.message_part));
        }
    }
}

TEST_CASE("an unknown letter is reported wherever it is in the cluster", "[api][switches]") {
    Options o;
    CHECK_THROWS_AS(gpdr::parse_switches("-pq30a0.1Z", o), gpdr::UsageError);
    CHECK_THROWS_WITH(gpdr::parse_switches("-pq30a0.1Z", o),
                      Catch::Contains("-Z") && Catch::Contains("-pq30a0.1Z"));
}

TEST_CASE("parse_placement takes names and numbers", "[api][switches]") {
    using gpdr::parse_placement;
    CHECK(parse_placement("circumcentre") == Placement::circumcentre);
    CHECK(parse_placement("Circumcenter") == Placement::circumcentre);
    CHECK(parse_placement("0") == Placement::circumcentre);
    CHECK(parse_placement("off-centre") == Placement::off_centre);
    CHECK(parse_placement("offcenter") == Placement::off_centre);
    CHECK(parse_placement("1") == Placement::off_centre);
    CHECK(parse_placement("optimisation") == Placement::optimisation);
    CHECK(parse_placement("optimization") == Placement::optimisation);
    CHECK(parse_placement("2") == Placement::optimisation);
    CHECK_THROWS_AS(parse_placement("3"), gpdr::UsageError);
    CHECK_THROWS_AS(parse_placement(""), gpdr::UsageError);
    CHECK_THROWS_WITH(parse_placement("centroid"), Catch::Contains("centroid"));
    for (auto p : {Placement::circumcentre, Placement::off_centre, Placement::optimisation})
        CHECK(parse_placement(gpdr::placement_name(p)) == p);
}

TEST_CASE("the library dialect reads switches as Triangle's library does", "[api][switches]") {
    const auto library = [](const char* text) {
        Options o;
        gpdr::parse_switches(text, o, gpdr::SwitchDialect::library);
        return o;
    };
    const auto program = [](const char* text) {
        Options o;
        gpdr::parse_switches(text, o);
        return o;
    };
    // What is not a switch is skipped, here and only here.
    CHECK(describe(library("Qz{a0.2}")) == describe(program("-Qza0.2")));
    CHECK(describe(library("-p -q")) == describe(program("-pq")));
    CHECK_THROWS_AS(program("-Qz{a0.2}"), gpdr::UsageError);
    // h asks for nothing, and does not stop the reading.
    CHECK(describe(library("phq")) == describe(program("-pq")));
    // L is Triangle's other name for D.
    CHECK(library("pL").conforming_delaunay);
    CHECK_THROWS_AS(program("-pL"), gpdr::UsageError);
    // Weighted triangulations are refused, not skipped.
    CHECK_THROWS_WITH(library("pw"), Catch::Contains("weighted"));
    CHECK_THROWS_WITH(library("pW"), Catch::Contains("weighted"));
    // Numbers: as the program reads them, errors included.
    CHECK(library("a1e-3").max_area == 1e-3);
    CHECK(library("q32.5j4").min_angle == 32.5);
    CHECK(library("q32.5j4").threads == 4);
    CHECK_THROWS_AS(library("q70"), gpdr::UsageError);
}
