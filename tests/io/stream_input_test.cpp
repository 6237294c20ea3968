// A file read from a fifo, as its bytes arrive, gives exactly what the same
// bytes give from a regular file: the values, the numbering base, the
// warnings and the content hash behind the run stamp.  The inputs span
// several of the stream reader's buffers, with lines cut across reads, a
// long comment that makes the buffer grow, and Windows line endings.

#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <vector>

#include <gpdr/io.hpp>

#include "io/fifo_support.hpp"
#include "io/io_test_support.hpp"

using namespace gpdr;
using gpdr::test::TempDir;

namespace {

namespace fs = std::filesystem;

// The warnings as "line: message" strings, for comparing two runs.
std::vector<std::string> lines_of(const test::WarningLog& log) {
    std::vector<std::string> out;
    for (const Warning& w : log.warnings) out.push_back(std::to_string(w.line) + ": " + w.message);
    return out;
}

void check_same(const NodeSet& a, const NodeSet& b) {
    CHECK(test::same_bits(a.xy, b.xy));
    CHECK(a.attribute_count == b.attribute_count);
    CHECK(test::same_bits(a.attributes, b.attributes));
    CHECK(a.markers == b.markers);
}

void check_same(const PolyFile& a, const PolyFile& b) {
    check_same(a.nodes, b.nodes);
    CHECK(a.nodes_from_node_file == b.nodes_from_node_file);
    CHECK(a.segments.endpoints == b.segments.endpoints);
    CHECK(a.segments.markers == b.segments.markers);
    CHECK(test::same_bits(a.holes, b.holes));
    REQUIRE(a.regions.size() == b.regions.size());
    for (std::size_t i = 0; i < a.regions.size(); ++i) {
        const Region &p = a.regions[i], &q = b.regions[i];
        CHECK(test::same_bits({p.x, p.y, p.attribute, p.max_area},
                              {q.x, q.y, q.attribute, q.max_area}));
    }
}

void check_same(const EleSet& a, const EleSet& b) {
    CHECK(a.corners_per_triangle == b.corners_per_triangle);
    CHECK(a.corners == b.corners);
    CHECK(a.attribute_count == b.attribute_count);
    CHECK(test::same_bits(a.attributes, b.attributes));
}

// Copies the files `names` from `from` into two folders, as regular files
// in one and as fifos fed from the copies in the other, and calls
// `read(folder, log)` on each; `read` returns its content hash.
template <typename Read>
void read_both_ways(const fs::path& from, const std::vector<std::string>& names, Read read) {
    TempDir file_dir, fifo_dir;
    for (const std::string& name : names) {
        fs::copy_file(from / name, file_dir / name);
        REQUIRE(test::feed_fifo(fifo_dir / name, file_dir / name));
    }
    test::WarningLog file_log, fifo_log;
    const auto from_file = read(file_dir, file_log);
    const auto from_fifo = read(fifo_dir, fifo_log);
    CHECK(from_file.base == from_fifo.base);
    CHECK(from_file.content_hash == from_fifo.content_hash);
    check_same(from_file.data, from_fifo.data);
    CHECK(lines_of(file_log) == lines_of(fifo_log));
}

// A .node file of some megabytes: 40,000 vertices with two attributes (one
// line in seven leaves them out) and markers, comments between them, a
// 300 kB comment line, CRLF line endings on some lines, and an id jump
// (a warning), without a final newline.
std::string large_node_file() {
    std::string text = "# made by stream_input_test.cpp\n40000 2 2 1\n";
    // Appended piece by piece: "literal" + std::string trips a false
    // -Wrestrict in GCC 12.
    for (int k = 1; k <= 40000; ++k) {
        const int id = k < 20000 ? k : k + 1;
        text += std::to_string(id);
        text += ' ';
        text += std::to_string(k * 0.001);
        text += ' ';
        text += std::to_string((k * 7919 % 40000) * 0.0125);
        if (k % 7 != 0) {
            text += ' ';
            text += std::to_string(k);
            text += " 1e-3";
        }
        text += ' ';
        text += std::to_string(k % 3);
        text += k % 5 == 0 ? "\r\n" : "\n";
        if (k % 1000 == 0) {
            text += "# vertex ";
            text += std::to_string(k);
            text += '\n';
        }
        if (k == 25000) {
            text += '#';
            text.append(300000, '-');
            text += '\n';
        }
    }
    text += "# the end, without a newline";
    return text;
}

}  // namespace

TEST_CASE("a .node or .poly read from a fifo gives what the regular file gives",
          "[io][hostile][stream]") {
    const auto node = [](const std::string& name) {
        return [name](const TempDir& dir, test::WarningLog& log) {
            return io::read_node((dir / name).string(), log.sink());
        };
    };
    const auto poly = [](const std::string& name) {
        return [name](const TempDir& dir, test::WarningLog& log) {
            return io::read_poly((dir / name).string(), log.sink());
        };
    };
    SECTION("samples") {
        read_both_ways(test::project_samples(), {"points.node"}, node("points.node"));
        read_both_ways(test::project_samples(), {"pipe.poly"}, poly("pipe.poly"));
        read_both_ways(test::project_samples(), {"flow.poly"}, poly("flow.poly"));
        // Vertex count 0: the vertices come from the .node beside it.
        read_both_ways(test::test_data(), {"nested_hex3.poly", "nested_hex3.node"},
                       poly("nested_hex3.poly"));
    }
    SECTION("a large file cut across many reads") {
        TempDir source;
        source.write("large.node", large_node_file());
        read_both_ways(source.path(), {"large.node"}, node("large.node"));
    }
}

TEST_CASE("an .ele and an .area read from a fifo give what the regular files give",
          "[io][hostile][stream]") {
    TempDir source;
    const std::string ele = "# two triangles\n2 3 1\n1 1 2 3 0.5\n2 1 3 4\n";
    const std::string area = "2\n1 0.25\n2\n# no bound on the second\n";
    source.write("s.ele", ele);
    read_both_ways(source.path(), {"s.ele"}, [](const TempDir& dir, test::WarningLog& log) {
        return io::read_ele((dir / "s.ele").string(), 1, 4, log.sink());
    });
    TempDir file_dir, fifo_dir;
    file_dir.write("s.area", area);
    REQUIRE(test::feed_fifo(fifo_dir / "s.area", file_dir / "s.area"));
    test::WarningLog log;
    const auto from_file = io::read_area((file_dir / "s.area").string(), 1, 2, log.sink());
    const auto from_fifo = io::read_area((fifo_dir / "s.area").string(), 1, 2, log.sink());
    CHECK(test::same_bits(from_file.data, from_fifo.data));
    CHECK(from_file.content_hash == from_fifo.content_hash);
}
