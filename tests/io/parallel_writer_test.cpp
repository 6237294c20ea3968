// Writers on several threads (io/format_threads.hpp): a large file's lines
// are formatted in pieces by any thread and written in order, so every
// writer gives the bytes of one thread, for any thread count, with the
// files of one output stage sharing the threads; a failure on any thread
// reaches the writer and leaves no file.  The columns themselves are
// checked against fmt's own formatting of Triangle's layout.

#include <catch2/catch.hpp>

#include <atomic>
#include <climits>
#include <functional>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gpdr/io.hpp>

#include "io/format_threads.hpp"
#include "io/io_test_support.hpp"

using namespace gpdr;
using gpdr::test::TempDir;

namespace {

using Write =
    std::function<void(io::OutputTransaction&, const std::string&, const io::WriteFormat&)>;

// Writes each of `files` (name, writer) into one transaction of its own as
// write_outputs does: with threads > 1, the files side by side on up to
// `threads` threads, which all help format once no file is left to start;
// with 1, on this thread and no FormatThreads.
void write_files(const TempDir& dir, unsigned threads,
                 const std::vector<std::pair<std::string, Write>>& files, int base = 1) {
    io::WriteFormat format;
    format.base = base;
    format.command = "parallel_writer_test";
    std::vector<io::OutputTransaction> transactions(files.size());
    if (threads == 1) {
        for (std::size_t f = 0; f < files.size(); ++f)
            files[f].second(transactions[f], (dir / files[f].first).string(), format);
    } else {
        io::FormatThreads pool(threads);
        pool.expect_files(files.size());
        format.threads = &pool;
        std::vector<std::exception_ptr> failures(files.size());
        std::atomic<std::size_t> next{0};
        const auto work = [&] {
            for (std::size_t f; (f = next.fetch_add(1)) < files.size();) {
                try {
                    files[f].second(transactions[f], (dir / files[f].first).string(), format);
                } catch (...) {
                    failures[f] = std::current_exception();
                }
                pool.file_done();
            }
            pool.help();
        };
        {
            std::vector<std::jthread> helpers;
            for (unsigned h = 1; h < threads; ++h) helpers.emplace_back(work);
            work();
        }
        for (const auto& f : failures)
            if (f) std::rethrow_exception(f);
    }
    for (auto& t : transactions) t.commit();
}

double coordinate(std::mt19937_64& rng) {
    // Shortest round-trip forms of every length.
    return std::uniform_real_distribution<double>(-1e4, 1e4)(rng) /
           static_cast<double>(1u << (rng() % 20));
}

// Three and a half pieces of lines, or a few lines (one thread's path).
constexpr std::size_t many = 3 * io::detail::lines_per_piece + io::detail::lines_per_piece / 2;

NodeSet nodes_of(std::size_t n, std::uint32_t attributes, std::mt19937_64& rng) {
    NodeSet nodes;
    nodes.attribute_count = attributes;
    for (std::size_t i = 0; i < 2 * n; ++i) nodes.xy.push_back(coordinate(rng));
    for (std::size_t i = 0; i < n * attributes; ++i) nodes.attributes.push_back(coordinate(rng));
    for (std::size_t i = 0; i < n; ++i) nodes.markers.push_back(static_cast<int>(rng() % 7) - 3);
    return nodes;
}

EleSet triangles_of(std::size_t n, std::uint32_t corners, std::uint32_t attributes,
                    std::size_t vertices, std::mt19937_64& rng) {
    EleSet ele;
    ele.corners_per_triangle = corners;
    ele.attribute_count = attributes;
    for (std::size_t i = 0; i < n * corners; ++i)
        ele.corners.push_back(static_cast<std::uint32_t>(rng() % vertices));
    for (std::size_t i = 0; i < n * attributes; ++i) ele.attributes.push_back(coordinate(rng));
    return ele;
}

// Every file each writer makes, for `n` lines.
std::vector<std::pair<std::string, Write>> every_writer(std::size_t n, std::mt19937_64& rng) {
    const std::size_t vertices = std::max<std::size_t>(n, 200000);  // indices of 1 to 6 digits
    auto nodes = std::make_shared<NodeSet>(nodes_of(n, 2, rng));
    auto plain = std::make_shared<NodeSet>(nodes_of(n, 0, rng));
    plain->markers.clear();
    auto ele = std::make_shared<EleSet>(triangles_of(n, 3, 1, vertices, rng));
    auto second_order = std::make_shared<EleSet>(triangles_of(n, 6, 0, vertices, rng));
    auto poly = std::make_shared<PolyFile>();
    poly->nodes = *plain;
    for (std::size_t i = 0; i < 2 * n; ++i)
        poly->segments.endpoints.push_back(static_cast<std::uint32_t>(rng() % n));
    for (std::size_t i = 0; i < n; ++i)
        poly->segments.markers.push_back(static_cast<int>(rng() % 40000) - 20000);
    poly->holes = {0.5, 0.25};
    auto edges = std::make_shared<EdgeSet>();
    edges->endpoints = poly->segments.endpoints;
    edges->markers = poly->segments.markers;
    auto neighbours = std::make_shared<NeighbourSet>();
    for (std::size_t i = 0; i < 3 * n; ++i)
        neighbours->neighbours.push_back(rng() % 4 == 0 ? NeighbourSet::none
                                                        : static_cast<std::uint32_t>(rng() % n));
    auto areas = std::make_shared<AreaSet>();
    for (std::size_t i = 0; i < n; ++i) areas->push_back(i % 3 == 0 ? -1.0 : coordinate(rng));
    auto voronoi = std::make_shared<io::VoronoiEdgeSet>();
    for (std::size_t i = 0; i < n; ++i) {
        voronoi->endpoints.push_back(static_cast<std::uint32_t>(rng() % n));
        voronoi->endpoints.push_back(rng() % 5 == 0 ? io::VoronoiEdgeSet::ray
                                                    : static_cast<std::uint32_t>(rng() % n));
        voronoi->directions.push_back(coordinate(rng));
        voronoi->directions.push_back(coordinate(rng));
    }
    return {
        {"a.node", [=](auto& tx, auto& path, auto& f) { io::write_node(tx, path, *nodes, f); }},
        {"a.ele", [=](auto& tx, auto& path, auto& f) { io::write_ele(tx, path, *ele, f); }},
        {"o2.ele",
         [=](auto& tx, auto& path, auto& f) { io::write_ele(tx, path, *second_order, f); }},
        {"a.poly", [=](auto& tx, auto& path, auto& f) { io::write_poly(tx, path, *poly, f); }},
        {"a.edge", [=](auto& tx, auto& path, auto& f) { io::write_edge(tx, path, *edges, f); }},
        {"a.neigh",
         [=](auto& tx, auto& path, auto& f) { io::write_neigh(tx, path, *neighbours, f); }},
        {"a.area", [=](auto& tx, auto& path, auto& f) { io::write_area(tx, path, *areas, f); }},
        {"a.v.edge",
         [=](auto& tx, auto& path, auto& f) { io::write_voronoi_edge(tx, path, *voronoi, f); }},
        {"a.off",
         [=](auto& tx, auto& path, auto& f) { io::write_off(tx, path, *plain, *ele, 7, f); }},
    };
}

}  // namespace

TEST_CASE("every writer gives one thread's bytes on any number of threads", "[parallel]") {
    for (const std::size_t n : {std::size_t{100}, many}) {
        for (const int base : {0, 1}) {
            std::mt19937_64 rng(n + base);
            const auto files = every_writer(n, rng);
            TempDir one;
            write_files(one, 1, files, base);
            for (const unsigned threads : {2u, 3u, 8u}) {
                INFO(n << " lines, base " << base << ", " << threads << " threads");
                TempDir several;
                write_files(several, threads, files, base);
                REQUIRE(several.files() == one.files());
                for (const auto& [name, write] : files) {
                    INFO(name);
                    CHECK(several.read(name) == one.read(name));
                }
            }
        }
    }
}

TEST_CASE("a triangle source read in order is written in order on several threads", "[parallel]") {
    std::mt19937_64 rng(7);
    const EleSet ele = triangles_of(many, 3, 2, 1000000, rng);
    const auto from_source = [&ele](io::OutputTransaction& tx, const std::string& path,
                                    const io::WriteFormat& f) {
        std::size_t t = 0;
        const io::EleSource source{ele.size(), 3, 2, [&](std::uint32_t* c, double* a) {
                                       std::copy_n(&ele.corners[3 * t], 3, c);
                                       std::copy_n(&ele.attributes[2 * t], 2, a);
                                       ++t;
                                   }};
        io::write_ele(tx, path, source, f);
        REQUIRE(t == ele.size());  // next() was called exactly count times
    };
    TempDir one, three;
    write_files(one, 1, {{"s.ele", from_source}});
    write_files(three, 3, {{"s.ele", from_source}});
    const std::string text = one.read("s.ele");
    CHECK(three.read("s.ele") == text);

    // Triangle's columns, as fmt writes "{:4}" and "{}".
    std::string expected = fmt::format("{}  3  2\n", ele.size());
    for (std::size_t t = 0; t < ele.size(); ++t)
        expected += fmt::format("{:4}    {:4}  {:4}  {:4}  {}  {}\n", t + 1, ele.corners[3 * t] + 1,
                                ele.corners[3 * t + 1] + 1, ele.corners[3 * t + 2] + 1,
                                ele.attributes[2 * t], ele.attributes[2 * t + 1]);
    REQUIRE(text.size() > expected.size());
    CHECK(text.substr(0, expected.size()) == expected);
    CHECK(text.substr(expected.size()).starts_with("# Generated by parallel_writer_test"));
}

TEST_CASE("a failure while formatting on several threads reaches the writer", "[parallel]") {
    std::mt19937_64 rng(11);
    const NodeSet nodes = nodes_of(many, 0, rng);
    for (const unsigned threads : {2u, 3u}) {
        INFO(threads << " threads");
        TempDir dir;
        std::size_t read = 0;
        const Write failing = [&](io::OutputTransaction& tx, const std::string& path,
                                  const io::WriteFormat& f) {
            const io::EleSource source{many, 3, 0, [&](std::uint32_t* c, double*) {
                                           if (++read > 2 * io::detail::lines_per_piece + 5)
                                               throw std::runtime_error("source failed");
                                           c[0] = c[1] = c[2] = 1;
                                       }};
            io::write_ele(tx, path, source, f);
        };
        const Write node = [&](io::OutputTransaction& tx, const std::string& path,
                               const io::WriteFormat& f) { io::write_node(tx, path, nodes, f); };
        CHECK_THROWS_WITH(write_files(dir, threads, {{"f.ele", failing}, {"f.node", node}}),
                          "source failed");
        // The transactions were destroyed without a commit: nothing is left.
        CHECK(dir.files().empty());
    }
}

TEST_CASE("segment columns are fmt's, negative markers and wide numbers included", "[parallel]") {
    std::mt19937_64 rng(5);
    PolyFile poly;
    poly.nodes_from_node_file = true;
    poly.nodes.markers.assign(1, 0);
    const std::size_t n = 2 * io::detail::lines_per_piece + 3;
    // Every length of number, both signs, the extremes; then random ones.
    const std::vector<std::uint32_t> ends{0,      9,       10,       99,        100,
                                          999,    1000,    9999,     10000,     99999,
                                          100000, 1234567, 99999999, 100000000, 4294967295u};
    const std::vector<int> markers{0,     -1,     9,       -9,      10,      -10,
                                   99,    -99,    100,     -100,    999,     -999,
                                   1000,  -1000,  9999,    -9999,   10000,   -10000,
                                   12345, -12345, INT_MAX, INT_MIN, INT_MAX, INT_MIN + 1};
    for (std::size_t s = 0; s < n; ++s) {
        poly.segments.endpoints.push_back(
            s < ends.size() ? ends[s] : static_cast<std::uint32_t>(rng() % 3000000));
        poly.segments.endpoints.push_back(static_cast<std::uint32_t>(rng() % 30));
        poly.segments.markers.push_back(
            s < markers.size() ? markers[s] : static_cast<int>(rng() % 200001) - 100000);
    }
    const Write write = [&](io::OutputTransaction& tx, const std::string& path,
                            const io::WriteFormat& f) { io::write_poly(tx, path, poly, f); };
    std::string expected = fmt::format("0  2  0  1\n{}  1\n", n);
    for (std::size_t s = 0; s < n; ++s)
        expected += fmt::format("{:4}    {:4}  {:4}    {:4}\n", s, poly.segments.endpoints[2 * s],
                                poly.segments.endpoints[2 * s + 1], poly.segments.markers[s]);
    expected += "0\n";
    for (const unsigned threads : {1u, 2u}) {
        TempDir dir;
        write_files(dir, threads, {{"m.poly", write}}, 0);
        const std::string text = dir.read("m.poly");
        REQUIRE(text.size() > expected.size());
        CHECK(text.substr(0, expected.size()) == expected);
    }
}
