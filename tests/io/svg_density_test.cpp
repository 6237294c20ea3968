// The picture of a large mesh (write_svg.cpp), read back from the file:
// the pixels its triangles cover are drawn, fine triangles and triangles
// many pixels wide alike, and holes, the outside and a vertex that no
// triangle uses are blank; the legend's density range is the mesh's own.

#include <catch2/catch.hpp>

#include <cstdint>
#include <functional>
#include <regex>
#include <string>
#include <vector>

#include <gpdr/io.hpp>
#include <gpdr/mesh_formats.hpp>

#include "io/io_test_support.hpp"

using namespace gpdr;
using gpdr::test::TempDir;

namespace {

// n x n square cells over [x0, x0 + size] x [y0, y0 + size], two triangles
// each, leaving out the cells (i, j) where `left_out` says so.
void add_grid(NodeSet& nodes, EleSet& ele, double x0, double y0, double size, std::uint32_t n,
              const std::function<bool(std::uint32_t, std::uint32_t)>& left_out) {
    const auto first = static_cast<std::uint32_t>(nodes.size());
    for (std::uint32_t j = 0; j <= n; ++j)
        for (std::uint32_t i = 0; i <= n; ++i) {
            nodes.xy.push_back(x0 + size * i / n);
            nodes.xy.push_back(y0 + size * j / n);
        }
    const auto at = [first, n](std::uint32_t i, std::uint32_t j) {
        return first + j * (n + 1) + i;
    };
    for (std::uint32_t j = 0; j < n; ++j)
        for (std::uint32_t i = 0; i < n; ++i) {
            if (left_out(i, j)) continue;
            ele.corners.insert(ele.corners.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            ele.corners.insert(ele.corners.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
}

io::MeshExport exported(const NodeSet& nodes, const EleSet& ele) {
    io::MeshExport m;
    m.nodes = &nodes;
    m.triangle_count = ele.size();
    m.triangles = [&ele] {
        return io::EleSource{ele.size(), 3, 0,
                             [&ele, t = std::size_t{0}](std::uint32_t* c, double*) mutable {
                                 for (int k = 0; k < 3; ++k) c[k] = ele.corners[3 * t + k];
                                 ++t;
                             }};
    };
    return m;
}

std::string from_base64(const std::string& text) {
    static const std::string digits =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::uint32_t bits = 0;
    int held = 0;
    for (const char ch : text) {
        if (ch == '=') break;
        bits = bits << 6 | static_cast<std::uint32_t>(digits.find(ch));
        held += 6;
        if (held >= 8) {
            held -= 8;
            out.push_back(static_cast<char>((bits >> held) & 0xff));
        }
    }
    return out;
}

std::uint32_t be32(const std::string& s, std::size_t at) {
    return std::uint32_t{static_cast<std::uint8_t>(s[at])} << 24 |
           std::uint32_t{static_cast<std::uint8_t>(s[at + 1])} << 16 |
           std::uint32_t{static_cast<std::uint8_t>(s[at + 2])} << 8 |
           static_cast<std::uint8_t>(s[at + 3]);
}

// The picture as written: the file, its density image's palette indices
// (0 is blank) and the two ends of the legend's density scale.
struct Picture {
    std::string text;
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> pixels;
    double low = 0, high = 0;
    std::uint8_t at(std::uint32_t x, std::uint32_t y) const { return pixels[y * width + x]; }
};

Picture draw(const NodeSet& nodes, const EleSet& ele) {
    TempDir dir;
    io::OutputTransaction tx;
    io::WriteFormat format;
    format.command = "gpdr --svg m.poly";
    io::write_svg(tx, (dir / "m.svg").string(), exported(nodes, ele), format);
    tx.commit();
    Picture p;
    p.text = dir.read("m.svg");
    const std::string prefix = "data:image/png;base64,";
    const std::size_t start = p.text.find(prefix);
    REQUIRE(start != std::string::npos);
    const std::size_t end = p.text.find('"', start);
    const std::string png =
        from_base64(p.text.substr(start + prefix.size(), end - start - prefix.size()));
    // The chunks: IHDR's size; IDAT's zlib stream of stored blocks, rows
    // led by their filter byte.
    std::string raw;
    for (std::size_t at = 8; at < png.size();) {
        const std::uint32_t length = be32(png, at);
        const std::string kind = png.substr(at + 4, 4);
        const std::string data = png.substr(at + 8, length);
        if (kind == "IHDR") {
            p.width = be32(data, 0);
            p.height = be32(data, 4);
        } else if (kind == "IDAT") {
            for (std::size_t b = 2; b + 4 < data.size();) {
                const std::size_t n = static_cast<std::uint8_t>(data[b + 1]) |
                                      std::size_t{static_cast<std::uint8_t>(data[b + 2])} << 8;
                raw += data.substr(b + 5, n);
                b += 5 + n;
            }
        }
        at += 12 + length;
    }
    REQUIRE(raw.size() == std::size_t{p.height} * (p.width + 1));
    for (std::uint32_t y = 0; y < p.height; ++y)
        for (std::uint32_t x = 0; x < p.width; ++x)
            p.pixels.push_back(static_cast<std::uint8_t>(raw[y * (p.width + 1) + 1 + x]));
    // The legend (after the image: std::regex would recurse through it all):
    // the scale's caption, then its low and its high end.
    const std::string legend = p.text.substr(end);
    std::smatch m;
    REQUIRE(std::regex_search(
        legend, m,
        std::regex("vertices per unit area[^<]*</text>\n<text[^>]*>([^<]*)</text>\n<rect[^>]*>\n"
                   "<text[^>]*>([^<]*)</text>")));
    p.low = std::stod(m[1].str());
    p.high = std::stod(m[2].str());
    return p;
}

// Every pixel of columns x0..x1 and rows y0..y1 drawn, or every one blank.
bool all_drawn(const Picture& p, std::uint32_t x0, std::uint32_t x1, std::uint32_t y0,
               std::uint32_t y1) {
    for (std::uint32_t y = y0; y <= y1; ++y)
        for (std::uint32_t x = x0; x <= x1; ++x)
            if (p.at(x, y) == 0) return false;
    return true;
}
bool all_blank(const Picture& p, std::uint32_t x0, std::uint32_t x1, std::uint32_t y0,
               std::uint32_t y1) {
    for (std::uint32_t y = y0; y <= y1; ++y)
        for (std::uint32_t x = x0; x <= x1; ++x)
            if (p.at(x, y) != 0) return false;
    return true;
}

}  // namespace

TEST_CASE("a large mesh's picture shows where its triangles are", "[io][svg]") {
    // In [0, 10]^2, drawn 1000 pixels wide (100 per unit, y down): a fine
    // grid over [0, 1]^2 whose triangles are under half a pixel wide, and a
    // coarse one over [7, 10]^2 of 100-pixel cells with the middle cell left
    // out, a vertex that no triangle uses in its middle.
    NodeSet nodes;
    EleSet ele;
    add_grid(nodes, ele, 0, 0, 1, 300, [](std::uint32_t, std::uint32_t) { return false; });
    add_grid(nodes, ele, 7, 7, 3, 3,
             [](std::uint32_t i, std::uint32_t j) { return i == 1 && j == 1; });
    nodes.xy.insert(nodes.xy.end(), {8.5, 8.5});
    REQUIRE(ele.size() == 2 * 300 * 300 + 2 * 8);

    const Picture p = draw(nodes, ele);
    REQUIRE(p.width == 1000);
    REQUIRE(p.height == 1000);
    CHECK(p.text.find("<polygon") == std::string::npos);
    CHECK(all_drawn(p, 1, 98, 901, 998));     // the fine grid
    CHECK(all_drawn(p, 701, 798, 1, 298));    // the coarse grid's left column of cells
    CHECK(all_drawn(p, 801, 898, 1, 98));     // and the cell above the hole
    CHECK(all_blank(p, 802, 897, 102, 197));  // the hole, its lone vertex included
    CHECK(all_blank(p, 150, 650, 350, 850));  // between the grids
    // The fine grid has 9 vertices per square pixel, 90000 per unit area:
    // the top of the scale, within what the pixel edges, which fall on grid
    // lines, shift from one pixel to the next (and the grid's last lines
    // into the picture's last row and column).  The coarse cells hold no
    // vertex within 3 pixels: shown as 1 in the 7 x 7 pixels, 10000 / 49 per
    // unit area, the bottom.
    CHECK(p.high == Approx(90000).epsilon(0.15));
    CHECK(p.low == Approx(10000.0 / 49).epsilon(0.01));
    // The same mesh, the same picture.
    CHECK(draw(nodes, ele).text == p.text);
}

TEST_CASE("a large uniform mesh's picture is one colour inside", "[io][svg]") {
    // 150 x 150 cells over [0, 1]^2: 45000 triangles, cells 6.7 pixels wide,
    // so most pixels hold no vertex and are drawn for the triangles over
    // them.  The density shown is the grid's throughout its inside, and the
    // scale spans a factor of 10 around it.
    NodeSet nodes;
    EleSet ele;
    add_grid(nodes, ele, 0, 0, 1, 150, [](std::uint32_t, std::uint32_t) { return false; });
    const Picture p = draw(nodes, ele);
    REQUIRE(p.width == 1000);
    CHECK(all_drawn(p, 0, 999, 0, 999));
    const double density = 151.0 * 151.0;  // per unit area
    CHECK(p.low < density);
    CHECK(p.high > density);
    CHECK(p.high / p.low == Approx(10).epsilon(0.01));
}
