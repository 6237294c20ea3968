// A 64-bit hash of bytes for the run stamp (see content_hash.hpp).

#include "io/content_hash.hpp"

#include <bit>
#include <cstring>

namespace gpdr::io {
namespace {

constexpr std::uint64_t fnv_prime = 0x100000001b3ull;

std::uint64_t step(std::uint64_t h, std::uint64_t word) noexcept {
    h = (h ^ word) * fnv_prime;
    return h ^ (h >> 29);
}

// MurmurHash3's fmix64: every input bit reaches every output bit.
std::uint64_t finalise(std::uint64_t h) noexcept {
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ull;
    h ^= h >> 33;
    return h;
}

std::uint64_t little_endian_word(const unsigned char* p, std::size_t n) noexcept {
    std::uint64_t w = 0;
    for (std::size_t i = 0; i < n; ++i) w |= std::uint64_t{p[i]} << (8 * i);
    return w;
}

}  // namespace

std::uint64_t hash_bytes(std::string_view bytes, std::uint64_t h) noexcept {
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
    std::size_t n = bytes.size();
    for (; n >= 8; p += 8, n -= 8) {
        std::uint64_t w;
        std::memcpy(&w, p, 8);
        if constexpr (std::endian::native == std::endian::big) w = __builtin_bswap64(w);
        h = step(h, w);
    }
    h = step(h, little_endian_word(p, n));
    return finalise(step(h, bytes.size()));
}

std::uint64_t hash_number(std::uint64_t n, std::uint64_t h) noexcept {
    // The state is mixed before n joins it, so that chaining depends on the
    // order: (h ^ n) alone would not tell hash_number(a, b) from (b, a).
    return finalise(step(finalise(h), n));
}

}  // namespace gpdr::io
