// File names: a table of input names and switches and the names Triangle 1.6
// would read and write for them (extensions stripped and their implied
// switches, iteration numbers, -I, paths with folders and dots).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <gpdr/errors.hpp>
#include <gpdr/file_names.hpp>
#include <gpdr/switches.hpp>

#include "api/job_stages.hpp"

using gpdr::Options;

TEST_CASE("input names: extensions stripped and the switches they imply", "[api][file_names]") {
    struct Row {
        std::string input, base;
        bool poly, refine, regional_area;
    };
    const std::vector<Row> rows = {
        {"box", "box", false, false, false},
        {"box.node", "box", false, false, false},
        {"box.poly", "box", true, false, false},
        {"box.1.ele", "box.1", false, true, false},
        {"box.1.area", "box.1", false, true, true},
        {"a.poly.node", "a", true, false, false},  // Triangle strips .node, then .poly
        {"a.node.poly", "a.node", true, false, false},
        {"./dir.v2/box.poly", "./dir.v2/box", true, false, false},
        {"box.POLY", "box.POLY", false, false, false},  // case matters, as in Triangle
        {"box.edge", "box.edge", false, false, false},
    };
    for (const Row& row : rows) {
        INFO("input: " << row.input);
        const auto name = gpdr::split_input_name(row.input);
        CHECK(name.base == row.base);
        CHECK(name.poly == row.poly);
        CHECK(name.refine == row.refine);
        CHECK(name.regional_area == row.regional_area);
    }
}

TEST_CASE("output bases carry the next iteration number", "[api][file_names]") {
    const std::vector<std::pair<std::string, std::string>> rows = {
        {"box", "box.1"},
        {"box.1", "box.2"},
        {"box.9", "box.10"},
        {"box.09", "box.10"},  // Triangle's %d drops leading zeros
        {"box.0", "box.1"},
        {"box.99999999999999999999", "box.100000000000000000000"},  // no overflow
        {"box.1a", "box.1a.1"},
        {"box.", "box..1"},  // a final '.' does not count
        {".5", ".5.1"},      // nor does a '.' first in the name
        {"dir/.5", "dir/.6"},
        {"./box", "./box.1"},
        {"../box", "../box.1"},
        {"./dir.v2/box", "./dir.v2/box.1"},
        {"dir.2/box", "dir.2/box.1"},
        {"./dir.v2/box.3", "./dir.v2/box.4"},
        {"my mesh.12", "my mesh.13"},
    };
    for (const auto& [base, out] : rows) {
        INFO("base: " << base);
        CHECK(gpdr::next_output_base(base) == out);
    }
}

TEST_CASE("file_names lists every input and output name", "[api][file_names]") {
    Options o;
    o.input = "box.poly";
    const auto f = gpdr::file_names(o);
    CHECK(f.input_base == "box");
    CHECK(f.output_base == "box.1");
    CHECK(f.in_node == "box.node");
    CHECK(f.in_poly == "box.poly");
    CHECK(f.in_ele == "box.ele");
    CHECK(f.in_area == "box.area");
    CHECK(f.out_node == "box.1.node");
    CHECK(f.out_ele == "box.1.ele");
    CHECK(f.out_poly == "box.1.poly");
    CHECK(f.out_edge == "box.1.edge");
    CHECK(f.out_neigh == "box.1.neigh");
    CHECK(f.out_v_node == "box.1.v.node");
    CHECK(f.out_v_edge == "box.1.v.edge");
    CHECK(f.out_off == "box.1.off");
}

TEST_CASE("refining box.1 writes box.2", "[api][file_names]") {
    for (const std::string input : {"box.1", "box.1.ele", "box.1.node", "box.1.area"}) {
        INFO("input: " << input);
        Options o;
        o.refine = true;
        o.poly = true;
        o.input = input;
        const auto f = gpdr::file_names(o);
        CHECK(f.input_base == "box.1");
        CHECK(f.in_ele == "box.1.ele");
        CHECK(f.in_poly == "box.1.poly");
        CHECK(f.out_node == "box.2.node");
        CHECK(f.out_poly == "box.2.poly");
    }
}

TEST_CASE("switch -I drops the iteration number and never writes .poly", "[api][file_names]") {
    Options o;
    o.no_iteration_numbers = true;
    o.input = "./dir.v2/box.poly";
    const auto f = gpdr::file_names(o);
    CHECK(f.output_base == "./dir.v2/box");
    CHECK(f.out_node == "./dir.v2/box.node");
    CHECK(f.out_ele == "./dir.v2/box.ele");
    CHECK(f.out_edge == "./dir.v2/box.edge");
    CHECK(f.out_v_edge == "./dir.v2/box.v.edge");
    CHECK(f.out_poly.empty());  // it would replace the input .poly
}

TEST_CASE("switch -I is refused when refining, as Triangle refuses it", "[api][file_names]") {
    Options o;
    o.no_iteration_numbers = true;
    o.input = "box.1";
    o.refine = true;
    CHECK_THROWS_AS(gpdr::file_names(o), gpdr::UsageError);
    CHECK_THROWS_WITH(gpdr::apply_input_name(o), Catch::Contains("-I"));

    Options implied;  // -r implied by the .ele or .area extension
    implied.no_iteration_numbers = true;
    implied.input = "box.1.ele";
    CHECK_THROWS_AS(gpdr::file_names(implied), gpdr::UsageError);
    implied.input = "box.1.area";
    CHECK_THROWS_AS(gpdr::apply_input_name(implied), gpdr::UsageError);
    implied.input = "box.1.node";
    CHECK_NOTHROW(gpdr::file_names(implied));
}

TEST_CASE("apply_input_name turns the extension into switches", "[api][file_names]") {
    Options o;
    o.input = "box.1.area";
    gpdr::apply_input_name(o);
    CHECK(o.refine);
    CHECK(o.regional_area);
    CHECK_FALSE(o.poly);
    CHECK_FALSE(o.quality);          // .area asks for refinement by area, not an angle bound
    CHECK(o.input == "box.1.area");  // the name as given stays
    gpdr::apply_input_name(o);       // a second call changes nothing
    CHECK(o.refine);
    CHECK(gpdr::file_names(o).output_base == "box.2");

    Options p;
    p.input = "box.poly";
    gpdr::apply_input_name(p);
    CHECK(p.poly);
    CHECK_FALSE(p.refine);

    Options none;
    CHECK_THROWS_AS(gpdr::apply_input_name(none), gpdr::UsageError);
    CHECK_THROWS_AS(gpdr::file_names(none), gpdr::UsageError);
}

TEST_CASE("whether a run writes any file", "[api][file_names]") {
    struct Row {
        std::string input, switches;
        bool vtk, writes;
    };
    const std::vector<Row> rows = {
        {"box.node", "", false, true},       {"box.node", "NEP", false, false},
        {"box.poly", "pNE", false, true},    // the output .poly
        {"box.poly", "pNEP", false, false},  {"box.node", "NEPc", false, false},
        {"box.node", "NEPe", false, true},   {"box.node", "NEPn", false, true},
        {"box.node", "NEPv", false, true},   {"box.node", "NEPg", false, true},
        {"box.node", "NEP", true, true},
    };
    for (const Row& row : rows) {
        INFO(row.input << " -" << row.switches << (row.vtk ? " --vtk" : ""));
        Options options;
        options.input = row.input;
        if (!row.switches.empty()) gpdr::parse_switches(row.switches, options);
        options.write_vtk = row.vtk;
        gpdr::apply_input_name(options);
        CHECK(gpdr::api::writes_files(options, gpdr::file_names(options), options.convex_hull) ==
              row.writes);
    }
}
