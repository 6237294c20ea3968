// gpdr -j1, -j2, -j3 and -j8 read a large .node or .poly alike: the same
// output files, byte for byte, and the same error message (with the same
// line number) whether the fault lies in the first slice of the vertex
// lines or in a later one.  The files are a few MiB, so that -jN cuts
// them into several slices (smaller files are read on one thread).

#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "cli/cli_support.hpp"

using namespace gpdr::test;

namespace {

constexpr std::size_t vertex_count = 120000;

// The vertex lines of a random point set with an attribute and a marker,
// with comments, blank lines and CRLF line ends among them; line k + 2 of
// the file (the header is line 1) is vertex k + 1's.
std::vector<std::string> vertex_lines() {
    std::vector<std::string> lines;
    std::uint64_t state = 42;
    const auto next = [&state] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) / double(std::uint64_t{1} << 53);
    };
    for (std::size_t k = 0; k < vertex_count; ++k) {
        std::string line =
            fmt::format("{} {:.17g} {:.17g} {:.3f} {}", k + 1, next(), next(), next(), k % 3);
        if (k % 1000 == 7) line += "  # a comment after the values";
        line += k % 5 == 0 ? "\r\n" : "\n";
        lines.push_back(line);
    }
    return lines;
}

std::string node_file(const std::vector<std::string>& lines, std::size_t count = vertex_count) {
    std::string text = fmt::format("{} 2 1 1\n", count);
    for (const std::string& l : lines) text += l;
    return text;
}

// Runs gpdr with `switches` on `name` (written with `text`) at -j1, -j2,
// -j3 and -j8; checks that every run gives the same status, messages and
// files as -j1, and returns -j1's stderr.
std::string same_on_any_threads(const std::string& name, const std::string& text,
                                const std::string& switches) {
    std::string first_err;
    std::vector<std::pair<std::string, std::string>> first_files;
    int first_status = 0;
    for (const int threads : {1, 2, 3, 8}) {
        TempDir dir;
        dir.write(name, text);
        const RunResult r = run_gpdr(dir, fmt::format("-Q{}j{} {}", switches, threads, name));
        std::vector<std::pair<std::string, std::string>> files;
        for (const std::string& f : dir.files())
            if (f != name) files.emplace_back(f, dir.read(f));
        INFO(name << " -" << switches << " -j" << threads);
        if (threads == 1) {
            first_err = r.err;
            first_files = files;
            first_status = r.status;
            continue;
        }
        CHECK(r.status == first_status);
        CHECK(r.err == first_err);
        CHECK(files.size() == first_files.size());
        CHECK(files == first_files);
    }
    return first_err;
}

}  // namespace

TEST_CASE("a large .node gives the same files on any number of threads", "[cli][parallel_read]") {
    const std::string err = same_on_any_threads("points.node", node_file(vertex_lines()), "");
    CHECK(err.empty());
}

TEST_CASE("an error in the first or a later slice is reported alike", "[cli][parallel_read]") {
    const std::vector<std::string> lines = vertex_lines();
    // A bad number near the start (first slice) and near the end (last).
    for (const std::size_t k : {std::size_t{3}, vertex_count / 2, vertex_count - 10}) {
        std::vector<std::string> bad = lines;
        bad[k] = fmt::format("{} 0.5 0.5x 1 0\n", k + 1);
        const std::string err = same_on_any_threads("bad.node", node_file(bad), "");
        CHECK(err ==
              fmt::format("gpdr: bad.node:{}: y coordinate '0.5x' is not a number\n", k + 2));
    }
    // A NUL byte in a later slice.
    std::vector<std::string> nul = lines;
    nul[vertex_count * 3 / 4][2] = '\0';
    CHECK(
        same_on_any_threads("nul.node", node_file(nul), "") ==
        fmt::format("gpdr: nul.node:{}: a NUL byte: not a text file\n", vertex_count * 3 / 4 + 2));
    // A header announcing one vertex more than there are: reported on the
    // line after the last.
    CHECK(same_on_any_threads("count.node", node_file(lines, vertex_count + 1), "") ==
          fmt::format("gpdr: count.node:{}: expected {} vertices, found {}\n", vertex_count + 2,
                      vertex_count + 1, vertex_count));
    // A jump in the numbering is a warning, on its line (-Q silences it,
    // so look at the files and at a run without -Q below).
    std::vector<std::string> jump = lines;
    jump[vertex_count - 5] = fmt::format("{} 0.25 0.75 1 0\n", vertex_count + 7);
    same_on_any_threads("jump.node", node_file(jump), "");
}

TEST_CASE("a large .poly reads its vertices in slices and the rest in order",
          "[cli][parallel_read]") {
    const std::vector<std::string> lines = vertex_lines();
    std::string poly = node_file(lines);
    poly += "# the segments: a chain through the first vertices\n3 1\n1 1 2 5\n2 2 3 5\n3 3 4 5\n";
    poly += "0\n";
    CHECK(same_on_any_threads("chain.poly", poly, "p").empty());
    // An error after the vertex list, and one in it.
    const std::size_t at = poly.find("2 2 3 5");
    const std::string bad_segment = poly.substr(0, at) + "2 2 x 5" + poly.substr(at + 7);
    CHECK(same_on_any_threads("segment.poly", bad_segment, "p")
              .find(fmt::format("segment.poly:{}: segment endpoint 'x'", vertex_count + 5)) !=
          std::string::npos);
    std::vector<std::string> bad = lines;
    bad[vertex_count - 1] = fmt::format("{} 0.5\n", vertex_count);
    CHECK(same_on_any_threads("vertex.poly", node_file(bad) + "0 0\n0\n", "p") ==
          fmt::format("gpdr: vertex.poly:{}: y coordinate is missing\n", vertex_count + 1));
}

TEST_CASE("a numbering jump is reported on its line on any number of threads",
          "[cli][parallel_read]") {
    std::vector<std::string> lines = vertex_lines();
    lines[vertex_count - 5] = fmt::format("{} 0.25 0.75 1 0\n", vertex_count + 7);
    const std::string text = node_file(lines);
    for (const int threads : {1, 2, 8}) {
        TempDir dir;
        dir.write("jump.node", text);
        const RunResult r = run_gpdr(dir, fmt::format("-NEPj{} jump.node", threads));
        INFO("-j" << threads << ": " << r.err);
        CHECK(r.status == 0);
        CHECK(r.err.find(fmt::format(
                  "jump.node:{}: warning: vertex number {} where {} was expected", vertex_count - 3,
                  vertex_count + 7, vertex_count - 4)) != std::string::npos);
    }
}
