// A 64-bit hash of bytes for the run stamp (see content_hash.hpp).

#include "io/content_hash.hpp"

#include <algorithm>
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

// Steps `h` over the whole 8-byte words at p; returns the bytes consumed.
std::size_t whole_words(std::uint64_t& h, const unsigned char* p, std::size_t n) noexcept {
    const std::size_t whole = n - n % 8;
    for (std::size_t i = 0; i < whole; i += 8) {
        std::uint64_t w;
        std::memcpy(&w, p + i, 8);
        if constexpr (std::endian::native == std::endian::big) w = __builtin_bswap64(w);
        h = step(h, w);
    }
    return whole;
}

// The end of every hash: the zero-padded tail (possibly empty), the length.
std::uint64_t finish(std::uint64_t h, const unsigned char* tail, std::size_t tail_size,
                     std::uint64_t length) noexcept {
    h = step(h, little_endian_word(tail, tail_size));
    return finalise(step(h, length));
}

}  // namespace

std::uint64_t hash_bytes(std::string_view bytes, std::uint64_t h) noexcept {
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
    const std::size_t whole = whole_words(h, p, bytes.size());
    return finish(h, p + whole, bytes.size() - whole, bytes.size());
}

std::uint64_t hash_number(std::uint64_t n, std::uint64_t h) noexcept {
    // The state is mixed before n joins it, so that chaining depends on the
    // order: (h ^ n) alone would not tell hash_number(a, b) from (b, a).
    return finalise(step(finalise(h), n));
}

void ContentHasher::add(std::string_view bytes) noexcept {
    if (bytes.empty()) return;  // its data() may be null, which memcpy must not see
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
    std::size_t n = bytes.size();
    length_ += n;
    if (pending_size_ > 0) {
        // Complete the word that the previous piece left open.
        const std::size_t take = std::min(n, 8 - pending_size_);
        std::memcpy(pending_ + pending_size_, p, take);
        pending_size_ += take;
        p += take;
        n -= take;
        if (pending_size_ < 8) return;
        whole_words(h_, pending_, 8);
        pending_size_ = 0;
    }
    const std::size_t whole = whole_words(h_, p, n);
    pending_size_ = n - whole;
    if (pending_size_ > 0) std::memcpy(pending_, p + whole, pending_size_);
}

std::uint64_t ContentHasher::value() const noexcept {
    return finish(h_, pending_, pending_size_, length_);
}

}  // namespace gpdr::io
