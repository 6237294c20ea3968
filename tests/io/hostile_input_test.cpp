// Inputs no one wrote by hand: numbers separated by commas (as Triangle
// reads them), control bytes in a bad field (quoted escaped in the
// message), and files that are not regular files (read up to a cap).

#include <catch2/catch.hpp>

#include <cstdlib>
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
