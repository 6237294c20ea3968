// The picture's PNG encoder and base64, against the standards' own
// examples: RFC 4648's base64 test vectors, PNG's IEND chunk (whose CRC
// every PNG file ends with), and a small image taken apart by hand.

#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "io/png_image.hpp"

using gpdr::io::base64;
using gpdr::io::indexed_png;

namespace {

std::uint32_t be32(const std::string& s, std::size_t at) {
    return std::uint32_t{static_cast<std::uint8_t>(s[at])} << 24 |
           std::uint32_t{static_cast<std::uint8_t>(s[at + 1])} << 16 |
           std::uint32_t{static_cast<std::uint8_t>(s[at + 2])} << 8 |
           static_cast<std::uint8_t>(s[at + 3]);
}

}  // namespace

TEST_CASE("base64 follows RFC 4648's test vectors", "[io][png]") {
    CHECK(base64("") == "");
    CHECK(base64("f") == "Zg==");
    CHECK(base64("fo") == "Zm8=");
    CHECK(base64("foo") == "Zm9v");
    CHECK(base64("foob") == "Zm9vYg==");
    CHECK(base64("fooba") == "Zm9vYmE=");
    CHECK(base64("foobar") == "Zm9vYmFy");
    CHECK(base64(std::string("\xff\xfe\x00", 3)) == "//4A");
}

TEST_CASE("an indexed PNG has its chunks, rows and checksums in place", "[io][png]") {
    // 3 x 2 pixels, palette of two colours.
    const std::vector<std::array<std::uint8_t, 3>> palette = {{255, 255, 255}, {10, 20, 30}};
    const std::vector<std::uint8_t> pixels = {0, 1, 0, 1, 1, 0};
    const std::string png = indexed_png(3, 2, palette, pixels);

    REQUIRE(png.substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8));
    // IHDR: length 13, then width 3, height 2, depth 8, colour type 3.
    CHECK(be32(png, 8) == 13);
    CHECK(png.substr(12, 4) == "IHDR");
    CHECK(be32(png, 16) == 3);
    CHECK(be32(png, 20) == 2);
    CHECK(png.substr(24, 5) == std::string("\x08\x03\x00\x00\x00", 5));
    // PLTE: the two colours.
    const std::size_t plte = 8 + 12 + 13;
    CHECK(be32(png, plte) == 6);
    CHECK(png.substr(plte + 4, 4) == "PLTE");
    CHECK(png.substr(plte + 8, 6) == std::string("\xff\xff\xff\x0a\x14\x1e", 6));
    // IDAT: a zlib header, one final stored block of 2 rows of (filter 0 +
    // 3 pixels), then the Adler-32 of those 8 bytes.
    const std::size_t idat = plte + 12 + 6;
    CHECK(png.substr(idat + 4, 4) == "IDAT");
    const std::string z = png.substr(idat + 8, be32(png, idat));
    const std::string raw("\x00\x00\x01\x00\x00\x01\x01\x00", 8);
    CHECK(z == std::string("\x78\x01\x01\x08\x00\xf7\xff", 7) + raw + z.substr(z.size() - 4));
    // Adler-32 by its definition: s1 = 1 + sum, s2 = sum of the s1s.
    std::uint32_t s1 = 1, s2 = 0;
    for (char c : raw) {
        s1 += static_cast<std::uint8_t>(c);
        s2 += s1;
    }
    CHECK(be32(z, z.size() - 4) == (s2 << 16 | s1));
    // IEND, with the CRC every PNG ends with.
    CHECK(png.substr(png.size() - 12) == std::string("\x00\x00\x00\x00IEND\xae\x42\x60\x82", 12));
}
