// Inputs no one wrote by hand: numbers separated by commas (as Triangle
// reads them), control bytes in a bad field (quoted escaped in the
// message), NUL bytes and endless lines (refused on their line), devices and
// fifos (read as the bytes arrive, in constant memory, with the results and
// the errors of the same bytes in a regular file), and headers that declare
// more than the file holds.

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <gpdr/errors.hpp>
#include <gpdr/io.hpp>

#include "io/fifo_support.hpp"
#include "io/io_test_support.hpp"

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
    dir.write("z.node", "1 2 0 0\n1 0\x01x\x1b[31m\x9b\xff 0\n");
    test::WarningLog log;
    try {
        io::read_node((dir / "z.node").string(), log.sink());
        FAIL("no error");
    } catch (const InputError& e) {
        const std::string what = e.what();
        INFO(what);
        CHECK(what.find("'0\\x01x\\x1b[31m\\x9b\\xff'") != std::string::npos);
        for (const char c : what) {
            CHECK(static_cast<unsigned char>(c) >= 0x20);
            CHECK(static_cast<unsigned char>(c) < 0x7f);
        }
    }
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

namespace {

// Where reading a .node or .poly file stopped: its InputError's line and
// reason, or line 0 and "read" when it read without error.
struct Outcome {
    std::size_t line = 0;
    std::string reason = "read";
};

Outcome read_outcome(const std::string& path) {
    test::WarningLog log;
    try {
        if (path.ends_with(".poly"))
            io::read_poly(path, log.sink());
        else
            io::read_node(path, log.sink());
    } catch (const InputError& e) {
        return {e.line(), e.reason()};
    }
    return {};
}

// Reads `contents` as a regular file and through a fifo, both named `name`
// in folders of their own; returns both outcomes.
std::pair<Outcome, Outcome> both_ways(const std::string& name, const std::string& contents) {
    TempDir file_dir, fifo_dir;
    file_dir.write(name, contents);
    const Outcome from_file = read_outcome((file_dir / name).string());
    REQUIRE(test::feed_fifo(fifo_dir / name, file_dir / name));
    const Outcome from_fifo = read_outcome((fifo_dir / name).string());
    return {from_file, from_fifo};
}

constexpr std::size_t mib = std::size_t{1} << 20;

// A comment line of `length` bytes and its newline.  (Built in place:
// "#" + std::string(n, 'x') trips a false -Wrestrict in GCC 12.)
std::string comment_line(std::size_t length) {
    std::string line(length, 'x');
    line[0] = '#';
    line += '\n';
    return line;
}

}  // namespace

TEST_CASE("a NUL byte anywhere in a file is an error on its line", "[io][hostile]") {
    struct Case {
        const char* what;
        std::string name, contents;
        std::size_t line;
        std::string reason;
    };
    const std::string nul(1, '\0');
    const std::vector<Case> cases = {
        {"in a field", "f.node", "1 2 0 0\n1 0" + nul + "x 0\n", 2, "a NUL byte: not a text file"},
        {"in a comment", "c.node", "3 2 0 0\n# a" + nul + "b\n1 0 0\n2 1 0\n3 0 1\n", 2,
         "a NUL byte: not a text file"},
        {"after the entries read", "a.node", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\nignored\n" + nul + "\n",
         6, "a NUL byte: not a text file"},
        {"after a .poly's last list", "a.poly",
         "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n0\n# end" + nul, 8, "a NUL byte: not a text file"},
        {"as the first byte", "z.node", nul + "3 2 0 0\n", 1, "a NUL byte: not a text file"},
        // Lines are checked in order: an earlier bad line is the one reported.
        {"after a bad field", "b.node", "3 2 0 0\n1 0 x\n2 1 0\n3 0 1" + nul + "\n", 2,
         "y coordinate 'x' is not a number"},
    };
    for (const Case& c : cases) {
        DYNAMIC_SECTION(c.what) {
            const auto [from_file, from_fifo] = both_ways(c.name, c.contents);
            CHECK(from_file.line == c.line);
            CHECK(from_file.reason == c.reason);
            CHECK(from_fifo.line == c.line);
            CHECK(from_fifo.reason == c.reason);
        }
    }
}

TEST_CASE("a line longer than 1 MiB is an error on its line", "[io][hostile]") {
    const std::string header = "3 2 0 0\n1 0 0\n";
    const std::string rest = "2 1 0\n3 0 1\n";
    SECTION("a comment of 1 MiB is read") {
        const std::string line = comment_line(mib);
        const auto [from_file, from_fifo] = both_ways("l.node", header + line + rest);
        CHECK(from_file.reason == "read");
        CHECK(from_fifo.reason == "read");
    }
    SECTION("one byte more is refused") {
        const std::string line = comment_line(mib + 1);
        const auto [from_file, from_fifo] = both_ways("l.node", header + line + rest);
        CHECK(from_file.line == 3);
        CHECK(from_file.reason == "line longer than 1 MiB");
        CHECK(from_fifo.line == 3);
        CHECK(from_fifo.reason == "line longer than 1 MiB");
    }
    SECTION("an endless run of blanks, with no newline, is refused") {
        const auto [from_file, from_fifo] =
            both_ways("l.node", header + rest + std::string(3 * mib, ' '));
        CHECK(from_file.line == 5);
        CHECK(from_file.reason == "line longer than 1 MiB");
        CHECK(from_fifo.line == 5);
        CHECK(from_fifo.reason == "line longer than 1 MiB");
    }
    SECTION("within a line, the first offence is reported") {
        // A NUL within the first 1 MiB of a long line: the NUL; past it, the length.
        std::string early = comment_line(2 * mib), late = early;
        early[mib - 1] = '\0';
        late[mib + 1] = '\0';
        const auto [early_file, early_fifo] = both_ways("e.node", header + early + rest);
        CHECK(early_file.reason == "a NUL byte: not a text file");
        CHECK(early_fifo.reason == "a NUL byte: not a text file");
        const auto [late_file, late_fifo] = both_ways("l.node", header + late + rest);
        CHECK(late_file.reason == "line longer than 1 MiB");
        CHECK(late_fifo.reason == "line longer than 1 MiB");
    }
}

TEST_CASE("/dev/zero and /dev/urandom are refused at their first lines", "[io][hostile]") {
    // Named as inputs: read as the bytes arrive, and refused after the
    // first read instead of after a gigabyte.
    const Outcome zero = read_outcome("/dev/zero");
    CHECK(zero.line == 1);
    CHECK(zero.reason == "a NUL byte: not a text file");
    // Random bytes: a NUL byte or a field that is not a number, on one of
    // the first lines (a line that starts with '#' is a comment).
    test::WarningLog log;
    try {
        io::read_poly("/dev/urandom", log.sink());
        FAIL("/dev/urandom was read");
    } catch (const InputError& e) {
        INFO(e.what());
        CHECK(e.line() >= 1);
        CHECK(e.line() < 100);
    }
    // Through fifos.
    TempDir dir;
    REQUIRE(test::feed_fifo(dir / "zero.node", "/dev/zero"));
    const Outcome zero_fifo = read_outcome((dir / "zero.node").string());
    CHECK(zero_fifo.line == 1);
    CHECK(zero_fifo.reason == "a NUL byte: not a text file");
    REQUIRE(test::feed_fifo(dir / "noise.poly", "/dev/urandom"));
    const Outcome noise_fifo = read_outcome((dir / "noise.poly").string());
    INFO(noise_fifo.reason);
    CHECK(noise_fifo.line >= 1);
    CHECK(noise_fifo.line < 100);
}

TEST_CASE("from a stream, a header's counts are checked as the bytes arrive", "[io][hostile]") {
    SECTION("too many attributes for the file: the same error, once the stream has ended") {
        const auto [from_file, from_fifo] =
            both_ways("big.node", "3 2 333333 0\n1 0 0 # 3 points\n2 1 0\n3 0 1\n");
        CHECK(from_file.line == 1);
        CHECK_THAT(from_file.reason,
                   Catch::Contains("vertex attribute count 333333 is impossible"));
        CHECK(from_fifo.line == from_file.line);
        CHECK(from_fifo.reason == from_file.reason);
        const auto [six_file, six_fifo] = both_ways("six.node", "1 2 6 0\n1 0 0 5 6 7");
        CHECK(six_file.reason == "read");
        CHECK(six_fifo.reason == "read");
        const auto [seven_file, seven_fifo] = both_ways("seven.node", "1 2 7 0\n1 0 0 5 6 7");
        CHECK(seven_file.line == 1);
        CHECK(seven_fifo.line == 1);
        CHECK(seven_fifo.reason == seven_file.reason);
    }
    SECTION("values left out beyond what the bytes read pay for: refused while reading") {
        // 100 vertices of 100,000 attributes, every one left out: 80 MB of
        // zeros from a 700-byte stream if they were stored.
        std::string text = "100 2 100000 0\n";
        for (int k = 1; k <= 100; ++k) text += std::to_string(k) + " 0 0\n";
        const auto [from_file, from_fifo] = both_ways("wide.node", text);
        CHECK(from_file.line == 1);
        CHECK_THAT(from_file.reason, Catch::Contains("is impossible"));
        // The 11th vertex brings the values left out past 1,048,576 plus
        // half the bytes read.
        CHECK(from_fifo.line == 12);
        CHECK_THAT(from_fifo.reason, Catch::Contains("values left out of their lines"));
    }
    SECTION("a count the file cannot hold: refused up front, or where the stream ends") {
        const auto [from_file, from_fifo] = both_ways("many.node", "4000000000 2 0 0\n1 0 0\n");
        CHECK(from_file.line == 1);
        CHECK_THAT(from_file.reason, Catch::Contains("vertex count 4000000000 is impossible"));
        CHECK(from_fifo.line == 3);
        CHECK(from_fifo.reason == "expected 4000000000 vertices, found 1");
    }
}
