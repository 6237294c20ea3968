// Inputs no one wrote by hand: numbers separated by commas (as Triangle
// reads them), control bytes in a bad field (quoted escaped in the
// message), and files that are not regular files (read up to a cap).

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gpdr/errors.hpp>
#include <gpdr/io.hpp>

#include "io/io_test_support.hpp"
#include "io/text_reader.hpp"

using namespace gpdr;
using gpdr::test::TempDir;

TEST_CASE("a field may end with a comma, as Triangle reads it", "[io][hostile]") {
    TempDir dir;
    dir.write("c.node", "3, 2, 1, 1\n1, 0, 0, 7, 2\n2, 1.5, 0, 8, 0\n3, 0, 1e1, 9, 1\n");
    test::WarningLog log;
    const auto nodes = io::read_node((dir / "c.node").string(), log.sink());
    REQUIRE(nodes.data.size() == 3);
    CHECK(nodes.data.xy == std::vector<double>{0, 0, 1.5, 0, 0, 10});
    CHECK(nodes.data.attributes == std::vector<double>{7, 8, 9});
    CHECK(nodes.data.markers == std::vector<int>{2, 0, 1});
}

TEST_CASE("a comma inside a field is not a separator", "[io][hostile]") {
    TempDir dir;
    dir.write("c.node", "2 2 0 0\n1 0,5 0\n2 1 1\n");
    test::WarningLog log;
    try {
        io::read_node((dir / "c.node").string(), log.sink());
        FAIL("'0,5' was read as a number");
    } catch (const InputError& e) {
        CHECK(e.line() == 2);
        CHECK(e.reason().find("'0,5'") != std::string::npos);
    }
}

TEST_CASE("control bytes in a bad field are quoted escaped", "[io][hostile]") {
    TempDir dir;
    dir.write("z.node", std::string("1 2 0 0\n1 0\0x\x1b[31m 0\n", 21));
    test::WarningLog log;
    try {
        io::read_node((dir / "z.node").string(), log.sink());
        FAIL("no error");
    } catch (const InputError& e) {
        const std::string what = e.what();
        INFO(what);
        CHECK(what.find("'0\\x00x\\x1b[31m'") != std::string::npos);
        for (const char c : what) CHECK(static_cast<unsigned char>(c) >= 0x20);
    }
}

TEST_CASE("a file that is not regular is read up to a cap", "[io][hostile]") {
    // The readers' cap is FileText::max_unsized_bytes (1 GiB); 1 MiB here.
    try {
        const io::detail::FileText text("/dev/zero", "", std::size_t{1} << 20);
        FAIL("/dev/zero was read");
    } catch (const InputError& e) {
        CHECK(e.line() == 0);
        CHECK(e.reason().find("not a regular file") != std::string::npos);
    }
    // A pipe's bytes are read whole.
    TempDir dir;
    dir.write("p.node", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n");
    const std::string fifo = (dir / "fifo").string();
    REQUIRE(std::system(("mkfifo '" + fifo + "' && (cat '" + (dir / "p.node").string() + "' > '" +
                         fifo + "' &)")
                            .c_str()) == 0);
    const io::detail::FileText text(fifo, "");
    CHECK(std::string(text.data(), text.size()) == dir.read("p.node"));
}

TEST_CASE("a header may declare no more attribute values than the file holds", "[io][hostile]") {
    TempDir dir;
    test::WarningLog log;
    // A 42-byte file declaring 333,333 attributes per vertex: a million
    // values, every one stored, interpolated and written out if accepted.
    dir.write("big.node", "3 2 333333 0\n1 0 0 # 3 points\n2 1 0\n3 0 1\n");
    REQUIRE(std::filesystem::file_size(dir / "big.node") == 42);
    try {
        io::read_node((dir / "big.node").string(), log.sink());
        FAIL("accepted");
    } catch (const InputError& e) {
        CHECK(e.line() == 1);
        CHECK_THAT(e.reason(), Catch::Contains("vertex attribute count 333333 is impossible"));
    }

    // Every value takes two bytes or more: the 12 bytes after the header
    // hold at most 6 values (the last needs no separator), missing ones
    // reading as 0 as in Triangle.
    dir.write("six.node", "1 2 6 0\n1 0 0 5 6 7");
    const auto six = io::read_node((dir / "six.node").string(), log.sink());
    CHECK(six.data.attributes == std::vector<double>{5, 6, 7, 0, 0, 0});
    dir.write("seven.node", "1 2 7 0\n1 0 0 5 6 7");
    CHECK_THROWS_AS(io::read_node((dir / "seven.node").string(), log.sink()), InputError);

    // The same for a .poly's vertices and an .ele's triangles.
    dir.write("big.poly", "3 2 1000 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n");
    CHECK_THROWS_AS(io::read_poly((dir / "big.poly").string(), log.sink()), InputError);
    dir.write("big.ele", "1 3 50\n1 1 2 3\n");
    CHECK_THROWS_AS(io::read_ele((dir / "big.ele").string(), 1, 3, log.sink()), InputError);
}
