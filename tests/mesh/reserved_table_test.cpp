// ReservedTable: one reserved range, made writable a granule at a time;
// pages nobody wrote read as zeros; a chunk beyond the reservation is
// refused as memory that ran out.

#include <catch2/catch.hpp>

#include <cstdint>
#include <new>
#include <thread>
#include <vector>

#include "mesh/reserved_table.hpp"

namespace gpdr::mesh {
namespace {

struct Cell {
    std::uint32_t a, b;
};

// 64 chunks of 256 cells (2 KiB each): 1024 chunks to a 2 MiB granule is
// more than the table holds, so a granule here is the whole table...
using Small = ReservedTable<Cell, 8, 64>;
// ... and here 2 MiB hold 32 chunks of 8192 cells (64 KiB each).
using Large = ReservedTable<Cell, 13, 128>;
static_assert(Large::granule_chunks == 32);

}  // namespace

TEST_CASE("a reserved table holds what was written and zeros elsewhere", "[mesh][store]") {
    Large table;
    CHECK_FALSE(table.has_chunk(0));
    table.reserve(Large::max_chunks);
    CHECK(table.bytes() < Large::chunk_bytes);  // the flags alone
    REQUIRE(table.ensure(33));
    CHECK(table.has_chunk(33));
    CHECK_FALSE(table.has_chunk(32));  // in the same granule, not claimed
    CHECK(table.bytes() >= Large::granule_chunks * Large::chunk_bytes);
    const std::uint32_t first = 33 * Large::chunk_size;
    for (std::uint32_t i = 0; i < Large::chunk_size; ++i) table[first + i] = {i, ~i};
    CHECK(table[first + 7].a == 7);
    CHECK(table[first + 7].b == ~7u);
    // Chunks never claimed, in and beyond the granule, read as zeros.
    CHECK(table[first - 1].a == 0);
    CHECK(table[100 * Large::chunk_size + 5].b == 0);

    Large moved(std::move(table));
    CHECK(moved.has_chunk(33));
    CHECK(moved[first + Large::chunk_size - 1].a == Large::chunk_size - 1);
}

TEST_CASE("a reserved table refuses chunks beyond its range", "[mesh][store]") {
    Large table;
    table.reserve(40);  // rounded up to whole granules: 64 chunks
    CHECK(table.ensure(63));
    CHECK_THROWS_AS(table.ensure(64), std::bad_alloc);
    CHECK_FALSE(table.ensure(Large::max_chunks));  // past the table itself
    table.reserve(128);                            // a second reservation does nothing
    CHECK_THROWS_AS(table.ensure(64), std::bad_alloc);
}

TEST_CASE("threads claim chunks of a reserved table at once", "[mesh][store]") {
    Small table;
    table.reserve(Small::max_chunks);
    std::vector<std::thread> threads;
    for (std::uint32_t t = 0; t < 8; ++t)
        threads.emplace_back([&table, t] {
            for (std::uint32_t c = t % 2; c < Small::max_chunks; c += 2) {
                table.ensure(c);
                table[c * Small::chunk_size + t].a = t + 1;
            }
        });
    for (std::thread& t : threads) t.join();
    for (std::uint32_t c = 0; c < Small::max_chunks; ++c) {
        CHECK(table.has_chunk(c));
        for (std::uint32_t t = c % 2; t < 8; t += 2)
            CHECK(table[c * Small::chunk_size + t].a == t + 1);
    }
    CHECK(table.bytes() == Small::max_chunks * Small::chunk_bytes + Small::max_chunks + 1);
}

}  // namespace gpdr::mesh
