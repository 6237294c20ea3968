// Every bad input gives gpdr::InputError with the right file, line and
// reason (the table in bad_input_cases.hpp, shared with the CLI tests), and
// the harmless oddities Triangle accepts give warnings that name file and
// line.

#include <catch2/catch.hpp>

#include <filesystem>

#include <gpdr/errors.hpp>
#include <gpdr/io.hpp>

#include "io/bad_input_cases.hpp"
#include "io/io_test_support.hpp"

using namespace gpdr;
using gpdr::test::TempDir;

namespace {

void write_files(const TempDir& dir,
                 const std::vector<std::pair<std::string, std::string>>& files) {
    for (const auto& [name, contents] : files) dir.write(name, contents);
}

}  // namespace

TEST_CASE("every bad input gives InputError with file and line", "[io][bad-input]") {
    for (const auto& c : test::bad_input_cases()) {
        SECTION(c.name) {
            TempDir dir;
            write_files(dir, c.files);
            test::WarningLog log;
            try {
                test::read_as_cli(dir, c.input, log.sink());
                FAIL("no error for: " << c.name);
            } catch (const InputError& e) {
                INFO("what(): " << e.what());
                CHECK(std::filesystem::path(e.file()).filename() == c.file);
                CHECK(e.line() == c.line);
                CHECK_THAT(e.reason(), Catch::Contains(c.reason_contains));
                const std::string where =
                    c.line == 0 ? e.file() + ": " : e.file() + ":" + std::to_string(c.line) + ": ";
                CHECK(std::string(e.what()).rfind(where, 0) == 0);
            }
            // No temporary or output file appears from reading.
            CHECK(dir.files().size() == c.files.size());
        }
    }
}

TEST_CASE("bad .edge, .neigh and .v.edge files", "[io][bad-input]") {
    TempDir dir;
    const auto edge = (dir / "m.edge").string();
    const auto neigh = (dir / "m.neigh").string();
    const auto vedge = (dir / "m.v.edge").string();
    auto expect_error = [&](auto&& read, std::size_t line, const std::string& reason) {
        try {
            read();
            FAIL("no error, expected: " << reason);
        } catch (const InputError& e) {
            INFO(e.what());
            CHECK(e.line() == line);
            CHECK_THAT(e.reason(), Catch::Contains(reason));
        }
    };
    dir.write("m.edge", "2 1\n1 1 2 0\n2 2 5 1\n");
    expect_error([&] { io::read_edge(edge, 1, 4, ignore_warning); }, 3, "out of range");
    dir.write("m.edge", "2 2\n1 1 2 0\n2 2 3 1\n");
    expect_error([&] { io::read_edge(edge, 1, 4, ignore_warning); }, 1, "must be 0 or 1");
    dir.write("m.neigh", "2 3\n0 1 -1 -1\n1 0 2 -1\n");
    expect_error([&] { io::read_neigh(neigh, 0, 2, ignore_warning); }, 3, "numbered 0 to 1");
    dir.write("m.neigh", "2 4\n0 1 -1 -1\n1 0 -1 -1\n");
    expect_error([&] { io::read_neigh(neigh, 0, 2, ignore_warning); }, 1, "must be 3");
    dir.write("m.neigh", "3 3\n0 1 -1 -1\n1 0 -1 -1\n");
    expect_error([&] { io::read_neigh(neigh, 0, 2, ignore_warning); }, 1, "the .ele file has 2");
    dir.write("m.v.edge", "2 0\n0 0 1\n1 1 -1 0.5\n");
    expect_error([&] { io::read_voronoi_edge(vedge, 0, 2, ignore_warning); }, 3,
                 "ray direction y is missing");
    dir.write("m.v.edge", "1 0\n0 0 -1 0 0\n");
    expect_error([&] { io::read_voronoi_edge(vedge, 0, 2, ignore_warning); }, 2, "zero");
}

TEST_CASE("harmless oddities are accepted with a warning naming file and line", "[io][warnings]") {
    TempDir dir;
    test::WarningLog log;
    SECTION("non-consecutive vertex ids") {
        dir.write("a.node", "3 2 0 0\n1 0 0\n2 1 0\n5 0 1\n");
        const auto r = io::read_node((dir / "a.node").string(), log.sink());
        CHECK(r.data.size() == 3);
        CHECK(r.base == 1);
        REQUIRE(log.warnings.size() == 1);
        CHECK(log.warnings[0].line == 4);
        CHECK(std::filesystem::path(log.warnings[0].file).filename() == "a.node");
        CHECK_THAT(log.warnings[0].message, Catch::Contains("not consecutive"));
    }
    SECTION("a segment with equal endpoints") {
        dir.write("a.poly", "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n2 0\n0 0 1\n1 2 2\n0\n");
        const auto r = io::read_poly((dir / "a.poly").string(), log.sink());
        CHECK(r.base == 0);
        CHECK(r.data.segments.size() == 2);
        REQUIRE(log.warnings.size() == 1);
        CHECK(log.warnings[0].line == 7);
        CHECK_THAT(log.warnings[0].message, Catch::Contains("both endpoints"));
    }
    SECTION("a first vertex number other than 0 or 1 keeps the default base") {
        dir.write("a.node", "2 2 0 0\n7 0 0\n8 1 0\n");
        CHECK(io::read_node((dir / "a.node").string(), log.sink(), 0).base == 0);
        CHECK(io::read_node((dir / "a.node").string(), log.sink(), 1).base == 1);
        CHECK(log.warnings.size() == 2);
        CHECK(log.warnings[0].line == 2);
    }
}

TEST_CASE("Triangle's defaults for values a line leaves out", "[io][defaults]") {
    TempDir dir;
    // Header without dimension/attributes/markers; integral reals as ids;
    // comments and blank lines anywhere; CRLF line ends; '+' and exponents.
    dir.write("a.node", "# c\r\n3\r\n\r\n1.0 0 0 # x\r\n2 +1.5 1e-5\r\n3 0 1\r\n");
    const auto n = io::read_node((dir / "a.node").string(), ignore_warning);
    CHECK(n.base == 1);
    CHECK(n.data.attribute_count == 0);
    CHECK_FALSE(n.data.has_markers());
    CHECK(n.data.xy == std::vector<double>{0, 0, 1.5, 1e-5, 0, 1});

    // Missing attributes and markers are 0.
    dir.write("b.node", "2 2 2 1\n0 0 0 7\n1 1 0 3 4 9\n");
    const auto b = io::read_node((dir / "b.node").string(), ignore_warning);
    CHECK(b.base == 0);
    CHECK(b.data.attributes == std::vector<double>{7, 0, 3, 4});
    CHECK(b.data.markers == std::vector<int>{0, 9});

    // A region with one value after x y uses it as attribute and area bound;
    // a missing segment marker is 0; no region section at all is fine.
    dir.write(
        "c.poly",
        "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n2 1\n1 1 2\n2 2 3 4\n0\n2\n1 0.2 0.2 5\n2 0.1 0.1 6 -1\n");
    const auto c = io::read_poly((dir / "c.poly").string(), ignore_warning);
    CHECK(c.data.segments.markers == std::vector<int>{0, 4});
    REQUIRE(c.data.regions.size() == 2);
    CHECK(c.data.regions[0].attribute == 5);
    CHECK(c.data.regions[0].max_area == 5);
    CHECK(c.data.regions[1].max_area == -1);
    dir.write("d.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n0\n");
    CHECK(io::read_poly((dir / "d.poly").string(), ignore_warning).data.regions.empty());

    // .ele header without corners and attributes: 3 and 0; missing
    // attribute 0; .area line without a value: no bound (-1).
    dir.write("e.ele", "2\n1 1 2 3\n2 3 2 1\n");
    const auto e = io::read_ele((dir / "e.ele").string(), 1, 3, ignore_warning);
    CHECK(e.data.corners_per_triangle == 3);
    CHECK(e.data.corners == std::vector<std::uint32_t>{0, 1, 2, 2, 1, 0});
    dir.write("f.ele", "1 3 2\n0 0 1 2 8\n");
    const auto f = io::read_ele((dir / "f.ele").string(), 0, 3, ignore_warning);
    CHECK(f.base == 0);
    CHECK(f.data.attributes == std::vector<double>{8, 0});
    dir.write("g.area", "2\n1\n2 0.5\n");
    CHECK(io::read_area((dir / "g.area").string(), 1, 2, ignore_warning).data ==
          std::vector<double>{-1, 0.5});
}

TEST_CASE(".poly with vertex count 0 takes the .node file of the same name", "[io][poly]") {
    TempDir dir;
    dir.write("m.node", "3 2 1 1\n0 0 0 10 1\n1 1 0 11 1\n2 0 1 12 0\n");
    dir.write("m.poly", "0 2 1 1\n1 1\n0 2 0 9\n0\n");
    const auto r = io::read_poly((dir / "m.poly").string(), ignore_warning);
    CHECK(r.data.nodes_from_node_file);
    CHECK(r.base == 0);
    CHECK(r.data.nodes.size() == 3);
    CHECK(r.data.nodes.attributes == std::vector<double>{10, 11, 12});
    CHECK(r.data.segments.endpoints == std::vector<std::uint32_t>{2, 0});
    CHECK(r.data.segments.markers == std::vector<int>{9});
}
