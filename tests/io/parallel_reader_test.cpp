// The vertex lines of a .node or .poly read on several threads give what
// one thread gives: the same values, numbering base, warnings (with their
// lines), content hash, and the same first error with its line.  The files
// are cut into slices of any size here (min_slice_bytes 0), so a few lines
// already fall into many slices, and every line of a file in turn gets the
// fault under test, which puts it in the first slice, in later ones and on
// their edges.

#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <fmt/format.h>
#include <gpdr/errors.hpp>
#include <gpdr/io.hpp>

#include "io/io_test_support.hpp"
#include "io/read_settings.hpp"

using namespace gpdr;
using namespace std::string_literals;
using gpdr::test::TempDir;

namespace {

// Everything a read gives, as text: the values' bits, the base, the hash,
// the warnings, or the error message.
template <class Read>
std::string outcome(const Read& read) {
    test::WarningLog log;
    std::string s;
    try {
        const auto r = read(log.sink());
        const NodeSet& n = r.nodes;
        s += fmt::format("base {} hash {}\n", r.base, r.hash);
        for (const double v : n.xy) s += fmt::format("{:x} ", std::bit_cast<std::uint64_t>(v));
        s += fmt::format("\nattributes {}:", n.attribute_count);
        for (const double v : n.attributes)
            s += fmt::format(" {:x}", std::bit_cast<std::uint64_t>(v));
        s += "\nmarkers:";
        for (const int m : n.markers) s += fmt::format(" {}", m);
        s += fmt::format("\nrest {}\n", r.rest);
    } catch (const InputError& e) {
        s += std::string("error ") + e.what() + "\n";
    }
    for (const Warning& w : log.warnings)
        s += fmt::format("warning {}:{}: {}\n", w.file, w.line, w.message);
    return s;
}

struct Read {
    NodeSet nodes;
    int base = 0;
    std::uint64_t hash = 0;
    std::string rest;  // a .poly's segments, holes and regions, in short
};

Read read_node(const std::string& path, unsigned threads, const WarningSink& warn) {
    const auto r = io::detail::read_node_with(path, warn, 1, {threads, 0});
    return {r.data, r.base, r.content_hash, {}};
}

Read read_poly(const std::string& path, unsigned threads, const WarningSink& warn) {
    const auto r = io::detail::read_poly_with(path, warn, 1, nullptr, {threads, 0});
    std::string rest;
    for (const auto e : r.data.segments.endpoints) rest += std::to_string(e) + " ";
    for (const int m : r.data.segments.markers) rest += fmt::format("m{} ", m);
    rest += fmt::format("holes {} regions {}", r.data.holes.size(), r.data.regions.size());
    return {r.data.nodes, r.base, r.content_hash, rest};
}

// Reads `text` as `name` on 1, 2, 3 and 8 threads; all must agree.
std::string check_threads(const std::string& name, const std::string& text) {
    TempDir dir;
    dir.write(name, text);
    const std::string path = (dir / name).string();
    const bool poly = name.ends_with(".poly");
    const auto read_on = [&](unsigned threads) {
        return outcome([&](const WarningSink& warn) {
            return poly ? read_poly(path, threads, warn) : read_node(path, threads, warn);
        });
    };
    const std::string one = read_on(1);
    for (const unsigned threads : {2u, 3u, 8u}) {
        INFO(name << " on " << threads << " threads:\n" << text);
        CHECK(read_on(threads) == one);
    }
    return one;
}

// A .node with comments, blank lines, CRLF line ends, attributes and
// markers, and no newline at its end.
const std::string mixed_node =
    "# points\n"
    "7 2 2 1  # header\r\n"
    "\n"
    "1 0.0 0.0 1.5 -2 3\r\n"
    "   # a comment line\n"
    "2 1.0 0.0 2.5 1e3 0\r\n"
    "3 1.0 1.0, 3.5, 7, 1\n"
    "\t\r\n"
    "4 0.0 1.0 4.5 # no second attribute, no marker\n"
    "5 0.5 0.5 5.5 6 -7\n"
    "6 0.25 0.75 6.5 7 8\n"
    "7 0.75 0.25 7.5 8 9";

// The lines of `text`, with their ends.
std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find('\n', begin);
        end = end == std::string::npos ? text.size() : end + 1;
        lines.push_back(text.substr(begin, end - begin));
        begin = end;
    }
    return lines;
}

// `text` with line `i` (0-based) changed by `change`.
template <class Change>
std::string with_line(const std::string& text, std::size_t i, const Change& change) {
    std::vector<std::string> lines = lines_of(text);
    lines[i] = change(lines[i]);
    std::string out;
    for (const std::string& l : lines) out += l;
    return out;
}

}  // namespace

TEST_CASE("parallel reading: comments, blank lines, CRLF, attributes, markers",
          "[io][parallel_read]") {
    const std::string one = check_threads("mixed.node", mixed_node);
    CHECK(one.find("error") == std::string::npos);
    CHECK(one.find("warning") == std::string::npos);
}

TEST_CASE("parallel reading: a bad number on any line", "[io][parallel_read]") {
    const std::size_t count = lines_of(mixed_node).size();
    for (std::size_t i = 0; i < count; ++i) {
        // The first field that starts with a digit becomes "1x".
        const std::string text = with_line(mixed_node, i, [](std::string line) {
            const std::size_t d = line.find_first_of("0123456789");
            if (d != std::string::npos && line.find('#') > d)
                line = line.substr(0, d + 1) + 'x' + line.substr(d + 1);
            return line;
        });
        const std::string one = check_threads("bad.node", text);
        if (i >= 3 && i != 4 && i != 7) CHECK(one.find("error") != std::string::npos);
    }
}

TEST_CASE("parallel reading: a NUL byte or an overlong line in any line", "[io][parallel_read]") {
    const std::size_t count = lines_of(mixed_node).size();
    for (std::size_t i = 0; i < count; ++i) {
        const std::string nul = with_line(mixed_node, i, [](std::string line) {
            line.insert(line.size() / 2, 1, '\0');
            return line;
        });
        CHECK(check_threads("nul.node", nul).find("NUL byte") != std::string::npos);
        if (i < 2) continue;
        const std::string long_line = with_line(mixed_node, i, [](std::string line) {
            return fmt::format("# {}{}", std::string(std::size_t{1} << 20, ' '), line);
        });
        CHECK(check_threads("long.node", long_line).find("longer than") != std::string::npos);
    }
}

TEST_CASE("parallel reading: a wrong vertex count, ids that jump", "[io][parallel_read]") {
    // More vertices announced than there are; fewer (the rest is ignored,
    // but still checked for NUL bytes).
    for (const char* header : {"8 2 2 1", "9 2 2 1", "3 2 2 1", "6 2 2 1", "1 2 2 1", "0 2 2 1"}) {
        std::string text = mixed_node;
        text.replace(text.find("7 2 2 1"), 7, header);
        check_threads("count.node", text);
        check_threads("count_nul.node", text + "\n8 1 1\n9 \0 2\n"s);
        check_threads("count_bad.node", text + "\n8 1 x\n");
    }
    // A jump in the numbering on any line, a first number of 0 or 5.
    const std::size_t count = lines_of(mixed_node).size();
    for (std::size_t i = 3; i < count; ++i) {
        const std::string text = with_line(mixed_node, i, [](std::string line) {
            const std::size_t d = line.find_first_of("0123456789");
            if (d != std::string::npos && line.find('#') > d)
                line = line.substr(0, d) + '4' + line.substr(d);
            return line;
        });
        check_threads("jump.node", text);
    }
    for (const char* first : {"0", "5", "2"}) {
        std::string text = mixed_node;
        text.replace(text.find("\n1 0.0") + 1, 1, first);
        check_threads("first.node", text);
    }
}

TEST_CASE("parallel reading: fewer lines than slices", "[io][parallel_read]") {
    check_threads("one.node", "1 2 0 0\n1 0.5 0.5\n");
    check_threads("two.node", "2\n0 1 2\n1 3 4");
    check_threads("none.node", "3 2 0 0\n");
    check_threads("short.node", "3 2 0 0\n1 1 1\n");
    check_threads("blank.node", "2 2 0 0\n\n\n#\n\n1 0 0\n\n2 1 1\n\n");
}

TEST_CASE("parallel reading: a .poly goes on after its vertices", "[io][parallel_read]") {
    const std::string poly =
        "5 2 1 1\n"
        "1 0 0 0.5 1\n"
        "2 4 0 0.5 1\n"
        "# between\n"
        "3 4 4 0.5 1\n"
        "4 0 4 0.5 1\n"
        "5 2 2 0.5 0\n"
        "4 1\n"
        "1 1 2 7\n"
        "2 2 3 7\n"
        "3 3 4 7\n"
        "4 4 1 7\n"
        "1\n"
        "1 2.5 2.5\n"
        "1\n"
        "1 1 1 3 0.1\n";
    CHECK(check_threads("box.poly", poly).find("error") == std::string::npos);
    const std::size_t count = lines_of(poly).size();
    for (std::size_t i = 0; i < count; ++i) {
        check_threads("bad.poly", with_line(poly, i, [](std::string line) {
                          return line.substr(0, line.size() - 1) + " x\n";
                      }));
        check_threads("nul.poly", with_line(poly, i, [](std::string line) {
                          return line.substr(0, 1) + std::string(1, '\0') + line.substr(1);
                      }));
        check_threads("cut.poly", poly.substr(0, poly.find('\n', i * 5)));
    }
}
