#pragma once
// A stable counting sort on several threads, for orders that must not
// depend on the thread count (the BRIO rounds, the points of each band).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/slices.hpp"

namespace gpdr::mesh {

// Items 0 .. n-1, item i with key key(i) < keys <= 256: calls place(i, at)
// once for each item, `at` its position when the items are ordered by key
// and by index within a key, and returns where each key's items start
// (keys + 1 entries, the last n).  On `threads` threads: the items are cut
// into pieces, each piece counts its items per key, and a piece's items of
// a key go after those of the pieces before it, so the positions are those
// of one pass in index order.  key and place are called from several
// threads at once (place with distinct positions).
template <class Key, class Place>
std::vector<std::size_t> sort_by_key(unsigned threads, std::size_t n, std::uint32_t keys,
                                     const Key& key, const Place& place) {
    const std::size_t most_pieces = 4 * std::size_t{std::max(1u, threads)};
    std::vector<std::uint8_t> keyed(n);
    std::vector<std::vector<std::size_t>> next(most_pieces, std::vector<std::size_t>(keys, 0));
    const std::size_t pieces =
        run_index_pieces(threads, n, [&](std::size_t k, std::size_t first, std::size_t last) {
            for (std::size_t i = first; i < last; ++i) {
                keyed[i] = static_cast<std::uint8_t>(key(i));
                ++next[k][keyed[i]];
            }
        });
    std::vector<std::size_t> start(std::size_t{keys} + 1, 0);
    for (std::uint32_t r = 0; r < keys; ++r) {
        std::size_t at = start[r];
        for (std::size_t k = 0; k < pieces; ++k) {
            const std::size_t count = next[k][r];
            next[k][r] = at;
            at += count;
        }
        start[r + 1] = at;
    }
    run_index_pieces(threads, n, [&](std::size_t k, std::size_t first, std::size_t last) {
        std::vector<std::size_t>& at = next[k];
        for (std::size_t i = first; i < last; ++i) place(i, at[keyed[i]]++);
    });
    return start;
}

}  // namespace gpdr::mesh
