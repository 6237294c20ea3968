// PNG (ISO/IEC 15948) as png_image.hpp describes it: the signature, then
// chunks (length, type, data, CRC-32 of type and data): IHDR, PLTE, one
// IDAT holding a zlib stream (RFC 1950) of stored deflate blocks (RFC 1951)
// with the rows, each led by filter type 0, and IEND.

#include "io/png_image.hpp"

#include <algorithm>

namespace gpdr::io {
namespace {

const std::array<std::uint32_t, 256>& crc_table() {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xedb88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    return table;
}

std::uint32_t crc32(const char* data, std::size_t size) {
    std::uint32_t c = 0xffffffffu;
    const auto& table = crc_table();
    for (std::size_t i = 0; i < size; ++i)
        c = table[(c ^ static_cast<std::uint8_t>(data[i])) & 0xff] ^ (c >> 8);
    return c ^ 0xffffffffu;
}

void put_be32(std::string& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(static_cast<char>((v >> shift) & 0xff));
}

void put_chunk(std::string& out, const char* type, const std::string& data) {
    put_be32(out, static_cast<std::uint32_t>(data.size()));
    const std::size_t start = out.size();
    out.append(type, 4);
    out += data;
    put_be32(out, crc32(out.data() + start, out.size() - start));
}

}  // namespace

std::string indexed_png(std::uint32_t width, std::uint32_t height,
                        const std::vector<std::array<std::uint8_t, 3>>& palette,
                        const std::vector<std::uint8_t>& pixels) {
    std::string png("\x89PNG\r\n\x1a\n", 8);
    std::string header;
    put_be32(header, width);
    put_be32(header, height);
    header +=
        std::string("\x08\x03\x00\x00\x00", 5);  // 8 bits, palette, deflate, filter 0, no interlace
    put_chunk(png, "IHDR", header);
    std::string colours;
    for (const auto& c : palette) colours.append(reinterpret_cast<const char*>(c.data()), 3);
    put_chunk(png, "PLTE", colours);

    // The raw image: each row led by its filter type, 0 (none).
    std::string raw;
    raw.reserve(std::size_t{height} * (width + 1));
    for (std::uint32_t y = 0; y < height; ++y) {
        raw.push_back(0);
        raw.append(reinterpret_cast<const char*>(pixels.data()) + std::size_t{y} * width, width);
    }
    std::string z("\x78\x01", 2);  // deflate, 32K window, no dictionary, fastest
    std::size_t at = 0;
    do {
        const std::size_t n = std::min<std::size_t>(65535, raw.size() - at);
        const bool last = at + n == raw.size();
        z.push_back(last ? 1 : 0);  // BFINAL, BTYPE 00: stored
        z.push_back(static_cast<char>(n & 0xff));
        z.push_back(static_cast<char>(n >> 8));
        z.push_back(static_cast<char>(~n & 0xff));
        z.push_back(static_cast<char>((~n >> 8) & 0xff));
        z.append(raw, at, n);
        at += n;
    } while (at < raw.size());
    std::uint32_t a = 1, b = 0;  // Adler-32
    for (const char ch : raw) {
        a = (a + static_cast<std::uint8_t>(ch)) % 65521;
        b = (b + a) % 65521;
    }
    put_be32(z, (b << 16) | a);
    put_chunk(png, "IDAT", z);
    put_chunk(png, "IEND", "");
    return png;
}

std::string base64(const std::string& bytes) {
    static constexpr char digits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const std::uint32_t v = std::uint32_t{static_cast<std::uint8_t>(bytes[i])} << 16 |
                                std::uint32_t{static_cast<std::uint8_t>(bytes[i + 1])} << 8 |
                                static_cast<std::uint8_t>(bytes[i + 2]);
        out += {digits[v >> 18], digits[(v >> 12) & 63], digits[(v >> 6) & 63], digits[v & 63]};
    }
    if (i < bytes.size()) {
        std::uint32_t v = std::uint32_t{static_cast<std::uint8_t>(bytes[i])} << 16;
        if (i + 1 < bytes.size()) v |= std::uint32_t{static_cast<std::uint8_t>(bytes[i + 1])} << 8;
        out += digits[v >> 18];
        out += digits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

}  // namespace gpdr::io
