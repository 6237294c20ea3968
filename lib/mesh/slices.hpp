#pragma once
// Passes over a finished mesh on several threads, a chunk of ids at a time.
// The ids come in chunks (mesh.hpp), and the parallel refiner's lanes leave
// some chunks unclaimed and others nearly empty, so the chunks are handed
// out one by one to whichever thread is free; each chunk keeps its own
// results, and the caller joins them in chunk order, so that what comes out
// does not depend on the threads.  Call these only while no thread is
// changing the mesh.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <thread>
#include <vector>

#include "mesh/mesh.hpp"

namespace gpdr::mesh {

// The chunks of ids [0, end), 2^bits ids each, for which has(c) holds, in
// order.
template <class Has>
std::vector<std::uint32_t> held_chunks(std::uint32_t end, unsigned bits, const Has& has) {
    std::vector<std::uint32_t> held;
    const auto chunks =
        static_cast<std::uint32_t>((std::uint64_t{end} + (std::uint64_t{1} << bits) - 1) >> bits);
    for (std::uint32_t c = 0; c < chunks; ++c)
        if (has(c)) held.push_back(c);
    return held;
}

// The triangle chunks anyone claimed.
inline std::vector<std::uint32_t> triangle_chunks(const Mesh& mesh) {
    return held_chunks(mesh.triangle_end(), Mesh::triangle_chunk_bits,
                       [&mesh](std::uint32_t c) { return mesh.has_triangle_chunk(c); });
}

// The ids of chunk c below `end`: [first, last).
struct ChunkIds {
    std::uint32_t first, last;
};
inline ChunkIds chunk_ids(std::uint32_t c, unsigned bits, std::uint32_t end) {
    const std::uint64_t first = std::uint64_t{c} << bits;
    return {static_cast<std::uint32_t>(std::min<std::uint64_t>(end, first)),
            static_cast<std::uint32_t>(std::min<std::uint64_t>(end, first + (1ull << bits)))};
}

// Calls f(i) for every piece i in [0, pieces) on up to `threads` threads
// (the calling thread one of them), each taking the next piece when it is
// free, and returns when all are done, rethrowing the failure of the first
// piece that failed.
template <class F>
void run_pieces(unsigned threads, std::size_t pieces, const F& f) {
    std::vector<std::exception_ptr> failures(pieces);
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < pieces;) {
            try {
                f(i);
            } catch (...) {
                failures[i] = std::current_exception();
            }
        }
    };
    {
        const auto n =
            static_cast<unsigned>(std::clamp<std::size_t>(pieces, 1, std::max(1u, threads)));
        std::vector<std::jthread> helpers;
        for (unsigned t = 1; t < n; ++t) helpers.emplace_back(work);
        work();
    }
    for (const std::exception_ptr& e : failures)
        if (e) std::rethrow_exception(e);
}

// Index ranges [0, n) cut into pieces of at least 65,536 (at most four a
// thread; one on one thread): calls f(k, first, last) for piece k on up to
// `threads` threads.  Returns the number of pieces.
template <class F>
std::size_t run_index_pieces(unsigned threads, std::size_t n, const F& f) {
    const std::size_t pieces =
        threads <= 1 ? 1 : std::clamp<std::size_t>(n >> 16, 1, 4 * std::size_t{threads});
    run_pieces(threads, pieces,
               [&](std::size_t k) { f(k, k * n / pieces, (k + 1) * n / pieces); });
    return pieces;
}

}  // namespace gpdr::mesh
