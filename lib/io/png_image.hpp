#pragma once
// A minimal PNG encoder for the picture of a large mesh (write_svg.cpp): an
// 8-bit palette image, its pixel rows stored uncompressed in the zlib
// stream (deflate's "stored" blocks).  That keeps gpdr free of a compression
// library and costs about one byte per pixel, which is small for the
// pictures it makes; the bytes depend on nothing but the pixels.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace gpdr::io {

// The PNG file of a width x height image whose pixel (x, y), y from the top,
// is palette entry pixels[y * width + x].
std::string indexed_png(std::uint32_t width, std::uint32_t height,
                        const std::vector<std::array<std::uint8_t, 3>>& palette,
                        const std::vector<std::uint8_t>& pixels);

// Standard base64 (RFC 4648, with '=' padding), for a data: URL.
std::string base64(const std::string& bytes);

}  // namespace gpdr::io
