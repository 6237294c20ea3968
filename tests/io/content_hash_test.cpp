// The hash behind the run stamp: a function of the bytes alone, and one that
// every changed bit, and every added byte, changes.

#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "io/content_hash.hpp"

using namespace gpdr;

TEST_CASE("the content hash tells byte strings apart", "[io][stamp]") {
    std::string text = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n# a square\n";
    const std::uint64_t h = io::hash_bytes(text);
    CHECK(io::hash_bytes(std::string(text)) == h);

    // Every single-bit change anywhere, the tail beyond the last whole
    // 8-byte word included, gives a hash not seen before.
    std::set<std::uint64_t> seen{h};
    for (std::size_t i = 0; i < text.size(); ++i) {
        for (int bit = 0; bit < 8; ++bit) {
            std::string changed = text;
            changed[i] = static_cast<char>(changed[i] ^ (1 << bit));
            CHECK(seen.insert(io::hash_bytes(changed)).second);
        }
    }
    // Zero bytes appended, or a prefix: not the same bytes, not the same hash.
    for (std::size_t n = 0; n < 17; ++n) {
        CHECK(seen.insert(io::hash_bytes(text + std::string(n + 1, '\0'))).second);
        CHECK(seen.insert(io::hash_bytes(text.substr(0, n))).second);
    }
    // Chaining depends on the order of what is chained.
    const std::uint64_t a = io::hash_bytes("a"), b = io::hash_bytes("b");
    CHECK(io::hash_number(a, b) != io::hash_number(b, a));
    CHECK(io::hash_number(1, h) != io::hash_number(2, h));
}

TEST_CASE("the content hash of bytes in pieces is the hash of the whole", "[io][stamp]") {
    std::string text;
    for (int i = 0; i < 300; ++i) text += static_cast<char>(i * 37 % 256);
    const std::uint64_t whole = io::hash_bytes(text);
    // Every cut into two pieces, and pieces of every size up to 17 (words
    // completed across several pieces, empty pieces between them).
    for (std::size_t cut = 0; cut <= text.size(); ++cut) {
        io::ContentHasher h;
        h.add(std::string_view(text).substr(0, cut));
        h.add(std::string_view(text).substr(cut));
        CHECK(h.value() == whole);
    }
    for (std::size_t piece = 1; piece <= 17; ++piece) {
        io::ContentHasher h;
        for (std::size_t at = 0; at < text.size(); at += piece) {
            h.add(std::string_view(text).substr(at, piece));
            h.add({});
        }
        CHECK(h.value() == whole);
    }
    CHECK(io::ContentHasher().value() == io::hash_bytes(""));
}
