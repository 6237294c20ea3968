// Passes over a mesh a chunk of ids at a time (mesh/slices.hpp): the held
// chunks in order, each chunk's ids below the end, and run_pieces runs
// every piece once, on the threads asked for, and reports the first
// piece's failure.

#include <catch2/catch.hpp>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "mesh/slices.hpp"

using namespace gpdr;

TEST_CASE("the held chunks and their ids", "[slices]") {
    // Chunks of 16 ids; ids end inside chunk 9.
    const std::uint32_t end = 9 * 16 + 5;
    const auto held = mesh::held_chunks(end, 4, [](std::uint32_t c) { return c % 3 != 1; });
    CHECK(held == std::vector<std::uint32_t>{0, 2, 3, 5, 6, 8, 9});
    CHECK(mesh::held_chunks(0, 4, [](std::uint32_t) { return true; }).empty());
    const mesh::ChunkIds middle = mesh::chunk_ids(3, 4, end);
    CHECK(middle.first == 48);
    CHECK(middle.last == 64);
    const mesh::ChunkIds last = mesh::chunk_ids(9, 4, end);
    CHECK(last.first == 144);
    CHECK(last.last == end);
    // The last chunk of 32-bit ids does not wrap around.
    const mesh::ChunkIds top = mesh::chunk_ids(0xFFFF, 16, 0xFFFFFFFF);
    CHECK(top.first == 0xFFFF0000u);
    CHECK(top.last == 0xFFFFFFFFu);
}

TEST_CASE("run_pieces runs every piece once and rethrows the first failure", "[slices]") {
    for (const unsigned threads : {1u, 2u, 4u}) {
        INFO(threads << " threads");
        std::vector<std::atomic<int>> ran(37);
        std::mutex mutex;
        std::set<std::thread::id> seen;
        mesh::run_pieces(threads, ran.size(), [&](std::size_t i) {
            ran[i] += 1;
            const std::lock_guard lock(mutex);
            seen.insert(std::this_thread::get_id());
        });
        for (const auto& r : ran) CHECK(r == 1);
        CHECK(seen.size() <= threads);
    }
    mesh::run_pieces(3, 0, [](std::size_t) { FAIL("no piece to run"); });
    const auto failing = [](std::size_t i) {
        if (i % 5 == 2) throw std::runtime_error("piece " + std::to_string(i));
    };
    CHECK_THROWS_WITH(mesh::run_pieces(4, 20, failing), "piece 2");
}
