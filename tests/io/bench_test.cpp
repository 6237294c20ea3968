// Hidden benchmark ("[.bench]"): write and read back a mesh of 10 million
// triangles over 5 million vertices with random coordinates, as .node +
// .ele, and report the seconds for each step.  Run with
//   build/tests/test_io "[.bench]"
// The triangles are random vertex triples: the files' size and shape match a
// real mesh's, which is all the I/O sees.

#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>

#include <gpdr/io.hpp>

#include "io/io_test_support.hpp"

using namespace gpdr;

TEST_CASE("write and read 10 million triangles", "[.bench][io]") {
    constexpr std::size_t vertex_count = 5'000'000;
    constexpr std::size_t triangle_count = 10'000'000;
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> coord(-1000.0, 1000.0);
    NodeSet nodes;
    nodes.xy.resize(2 * vertex_count);
    for (double& c : nodes.xy) c = coord(rng);
    nodes.markers.assign(vertex_count, 0);
    EleSet ele;
    ele.corners.resize(3 * triangle_count);
    std::uniform_int_distribution<std::uint32_t> vertex(0, vertex_count - 1);
    for (auto& c : ele.corners) c = vertex(rng);

    test::TempDir dir;
    const auto node_path = (dir / "big.node").string();
    const auto ele_path = (dir / "big.ele").string();
    using clock = std::chrono::steady_clock;
    const auto seconds = [](clock::time_point a, clock::time_point b) {
        return std::chrono::duration<double>(b - a).count();
    };

    const auto t0 = clock::now();
    {
        io::OutputTransaction tx;
        io::write_node(tx, node_path, nodes, {1, true, "gpdr bench"});
        const auto t1 = clock::now();
        io::write_ele(tx, ele_path, ele, {1, true, "gpdr bench"});
        const auto t2 = clock::now();
        tx.commit();
        std::printf("write .node: %.2f s (%.0f MB)\n", seconds(t0, t1),
                    std::filesystem::file_size(node_path) / 1e6);
        std::printf("write .ele:  %.2f s (%.0f MB)\n", seconds(t1, t2),
                    std::filesystem::file_size(ele_path) / 1e6);
    }
    const auto t3 = clock::now();
    const auto n = io::read_node(node_path, ignore_warning);
    const auto t4 = clock::now();
    const auto e = io::read_ele(ele_path, n.base, n.data.size(), ignore_warning);
    const auto t5 = clock::now();
    std::printf("read .node:  %.2f s\nread .ele:   %.2f s\n", seconds(t3, t4), seconds(t4, t5));
    CHECK(test::same_bits(n.data.xy, nodes.xy));
    CHECK(e.data.corners == ele.corners);
}
