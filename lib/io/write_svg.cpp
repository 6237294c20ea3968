// The picture of a mesh (.svg), for a person rather than a program: what
// Triangle's showme shows, in a file any browser opens.
//
// A mesh of up to vector_limit triangles is drawn triangle by triangle, one
// <polygon> each, filled by the triangle's smallest angle (a fixed scale
// from 0 to 60 degrees, so that pictures compare), or by region when the
// triangles have attributes (-A) that tell two regions apart.  Holes and
// the outside are left blank.  The segments are drawn over the triangles,
// heavier, one <path> each.
//
// A larger mesh cannot be drawn edge by edge in a file of a few MB, and its
// edges would be far below a pixel anyway.  It is shaded instead by its
// local density, the vertices per unit area around each pixel (a planar
// triangulation has about twice as many triangles as vertices, so this
// shows the triangles' density too), on a logarithmic scale: where the mesh
// is graded, the grading shows.  Each vertex counts in the pixel it lies
// in; a pixel is covered by the mesh when a vertex lies in it or a triangle
// covers its centre.  A pixel's density is the vertices counted in the
// square of 7 x 7 pixels around it over the pixels covered in that square;
// pixels not covered (holes, the outside) are left blank.  The image is an
// embedded PNG (png_image.hpp); the segments are drawn over it as
// polylines through chains of segments, leaving out points closer than a
// fraction of a pixel to the last one kept.
//
// Both end with a legend: the counts, the range of the mesh's angles, and
// the colour scale.  The density image is made of integer counts and
// marks, which do not depend on the order they are taken in, and the angle
// range of exact minima and maxima: the same mesh gives the same bytes.

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fmt/compile.h>
#include <fmt/format.h>
#include <gpdr/errors.hpp>
#include <gpdr/mesh_formats.hpp>

#include "io/format_threads.hpp"
#include "io/output_file.hpp"
#include "io/png_image.hpp"

namespace gpdr::io {
namespace {

using File = OutputTransaction::File;
using Out = std::back_insert_iterator<fmt::memory_buffer>;
using Colour = std::array<std::uint8_t, 3>;

constexpr std::size_t vector_limit = 20000;  // triangles drawn one by one, at most
constexpr double drawing_size = 1000;        // the drawing's longer side, in pixels
constexpr double margin = 12;
constexpr double legend_height = 78;
constexpr double legend_width = 460;  // the least picture width that fits the legend

// Mesh coordinates -> picture coordinates (y down).
struct Frame {
    double min_x = 0, max_y = 0, scale = 1;
    double width = 1, height = 1;  // of the drawing, in pixels
    double x(double mx) const { return margin + (mx - min_x) * scale; }
    double y(double my) const { return margin + (max_y - my) * scale; }
};

Frame frame_of(const NodeSet& nodes) {
    double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
    for (std::size_t v = 0; v < nodes.size(); ++v) {
        const double x = nodes.xy[2 * v], y = nodes.xy[2 * v + 1];
        if (v == 0) {
            min_x = max_x = x;
            min_y = max_y = y;
        }
        min_x = std::min(min_x, x);
        max_x = std::max(max_x, x);
        min_y = std::min(min_y, y);
        max_y = std::max(max_y, y);
    }
    Frame f;
    f.min_x = min_x;
    f.max_y = max_y;
    const double longer = std::max(max_x - min_x, max_y - min_y);
    f.scale = longer > 0 ? drawing_size / longer : 1;
    f.width = std::max(1.0, std::ceil((max_x - min_x) * f.scale));
    f.height = std::max(1.0, std::ceil((max_y - min_y) * f.scale));
    return f;
}

// A colour scale from dark violet through blue and green to yellow, in the
// manner of the perceptually even scales of plotting programs.
Colour ramp(double t) {
    static constexpr std::array<Colour, 5> stops = {Colour{68, 1, 84}, Colour{59, 82, 139},
                                                    Colour{33, 145, 140}, Colour{94, 201, 98},
                                                    Colour{253, 231, 37}};
    t = std::clamp(t, 0.0, 1.0) * (stops.size() - 1);
    const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(t), stops.size() - 2);
    const double f = t - static_cast<double>(i);
    Colour c;
    for (int k = 0; k < 3; ++k)
        c[k] = static_cast<std::uint8_t>(
            std::lround(stops[i][k] + f * (stops[i + 1][k] - stops[i][k])));
    return c;
}

// Regions: colours that are easy to tell apart.
Colour region_colour(std::size_t rank) {
    static constexpr std::array<Colour, 10> colours = {
        Colour{141, 211, 199}, Colour{255, 255, 179}, Colour{190, 186, 218}, Colour{251, 128, 114},
        Colour{128, 177, 211}, Colour{253, 180, 98},  Colour{179, 222, 105}, Colour{252, 205, 229},
        Colour{217, 217, 217}, Colour{188, 128, 189}};
    return colours[rank % colours.size()];
}

std::string hex(const Colour& c) { return fmt::format("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]); }

// The smallest and largest angle of the mesh, kept as cotangents (no
// trigonometry per triangle): the cotangent of a triangle's angle at a
// corner is the dot product of the two edges there over their cross
// product, twice the triangle's area, which is the same at every corner.
// The smallest angle has the largest cotangent.
struct AngleRange {
    double largest_cot = -std::numeric_limits<double>::infinity();  // of smallest angles
    double smallest_cot = std::numeric_limits<double>::infinity();  // of largest angles
    // Returns the square of the triangle's longest edge.
    double add(const double* a, const double* b, const double* c) {
        const double abx = b[0] - a[0], aby = b[1] - a[1];
        const double bcx = c[0] - b[0], bcy = c[1] - b[1];
        const double cax = a[0] - c[0], cay = a[1] - c[1];
        const double at_a = -(abx * cax + aby * cay);
        const double at_b = -(bcx * abx + bcy * aby);
        const double at_c = -(cax * bcx + cay * bcy);
        const double cross = std::abs(abx * cay - aby * cax);
        // A degenerate triangle counts as right-angled, as a cotangent of 0.
        const double most = cross > 0 ? std::max({at_a, at_b, at_c}) / cross : 0;
        const double least = cross > 0 ? std::min({at_a, at_b, at_c}) / cross : 0;
        largest_cot = std::max(largest_cot, most);
        smallest_cot = std::min(smallest_cot, least);
        return std::max({abx * abx + aby * aby, bcx * bcx + bcy * bcy, cax * cax + cay * cay});
    }
    void merge(const AngleRange& other) {
        largest_cot = std::max(largest_cot, other.largest_cot);
        smallest_cot = std::min(smallest_cot, other.smallest_cot);
    }
    static double degrees(double cot) { return std::atan2(1.0, cot) * 180 / std::numbers::pi; }
    bool empty() const { return largest_cot == -std::numeric_limits<double>::infinity(); }
};

const double* corner(const NodeSet& nodes, std::uint32_t v) {
    return nodes.xy.data() + 2 * std::size_t{v};
}

// The segments as chains: maximal paths through vertices that join exactly
// two segments (closed loops included), each a list of vertices.
std::vector<std::vector<std::uint32_t>> segment_chains(const SegmentSet& segments) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;  // (vertex, segment)
    for (std::uint32_t s = 0; s < segments.size(); ++s) {
        const std::uint32_t a = segments.endpoints[2 * s], b = segments.endpoints[2 * s + 1];
        if (a == b) continue;
        ends.emplace_back(a, s);
        ends.emplace_back(b, s);
    }
    std::sort(ends.begin(), ends.end());
    const auto at = [&ends](std::uint32_t v) {
        const auto first = std::lower_bound(ends.begin(), ends.end(), std::make_pair(v, 0u));
        auto last = first;
        while (last != ends.end() && last->first == v) ++last;
        return std::make_pair(first, last);
    };
    std::vector<bool> used(segments.size(), false);
    std::vector<std::vector<std::uint32_t>> chains;
    const auto walk = [&](std::uint32_t v, std::uint32_t s) {
        std::vector<std::uint32_t> chain{v};
        for (;;) {
            used[s] = true;
            const std::uint32_t a = segments.endpoints[2 * s];
            const std::uint32_t w = a == v ? segments.endpoints[2 * s + 1] : a;
            chain.push_back(w);
            const auto [first, last] = at(w);
            if (last - first != 2) break;
            const std::uint32_t next = first->second == s ? (first + 1)->second : first->second;
            if (used[next]) break;  // a loop, closed
            v = w;
            s = next;
        }
        chains.push_back(std::move(chain));
    };
    for (std::size_t i = 0; i < ends.size();) {
        const auto [first, last] = at(ends[i].first);
        if (last - first != 2)
            for (auto e = first; e != last; ++e)
                if (!used[e->second]) walk(e->first, e->second);
        i = static_cast<std::size_t>(last - ends.begin());
    }
    for (const auto& [v, s] : ends)
        if (!used[s]) walk(v, s);
    return chains;
}

void put_header(Out out, double width, double height) {
    fmt::format_to(out,
                   "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                   "<svg xmlns=\"http://www.w3.org/2000/svg\" "
                   "xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"{0}\" height=\"{1}\" "
                   "viewBox=\"0 0 {0} {1}\">\n"
                   "<rect width=\"{0}\" height=\"{1}\" fill=\"#ffffff\"/>\n",
                   width, height);
}

// The legend's first lines: counts and angles.
void put_counts(Out out, const MeshExport& mesh, std::size_t segments, const AngleRange& angles,
                double top) {
    fmt::format_to(
        out,
        "<g id=\"legend\" font-family=\"sans-serif\" font-size=\"13\" fill=\"#000000\">\n"
        "<text x=\"{}\" y=\"{}\">{} triangles, {} vertices, {} segments</text>\n",
        margin, top + 14, mesh.triangle_count, mesh.nodes->size(), segments);
    if (!angles.empty())
        fmt::format_to(out,
                       "<text x=\"{}\" y=\"{}\">angles from {:.2f}\u00b0 to {:.2f}\u00b0</text>\n",
                       margin, top + 32, AngleRange::degrees(angles.largest_cot),
                       AngleRange::degrees(angles.smallest_cot));
}

// A colour bar of the ramp with a caption and its two end labels.
void put_ramp_bar(Out out, double top, const std::string& caption, const std::string& low,
                  const std::string& high) {
    fmt::format_to(out, "<defs><linearGradient id=\"scale\">");
    for (int i = 0; i <= 8; ++i)
        fmt::format_to(out, "<stop offset=\"{}\" stop-color=\"{}\"/>", i / 8.0, hex(ramp(i / 8.0)));
    fmt::format_to(out,
                   "</linearGradient></defs>\n"
                   "<text x=\"{0}\" y=\"{1}\">{2}</text>\n"
                   "<text x=\"{0}\" y=\"{3}\">{4}</text>\n"
                   "<rect x=\"{5}\" y=\"{6}\" width=\"200\" height=\"12\" fill=\"url(#scale)\"/>\n"
                   "<text x=\"{7}\" y=\"{3}\">{8}</text>\n",
                   margin, top + 52, caption, top + 70, low, margin + 60, top + 60, margin + 266,
                   high);
}

void put_segments(File& file, const Frame& frame, const NodeSet& nodes, const SegmentSet& segments,
                  bool simplify) {
    Out out(file.buffer());
    fmt::format_to(out,
                   "<g id=\"segments\" stroke=\"#000000\" stroke-width=\"{}\" "
                   "stroke-linecap=\"round\" stroke-linejoin=\"round\" fill=\"none\">\n",
                   simplify ? 1.2 : 1.6);
    if (!simplify) {
        for (std::size_t s = 0; s < segments.size(); ++s) {
            const double* a = corner(nodes, segments.endpoints[2 * s]);
            const double* b = corner(nodes, segments.endpoints[2 * s + 1]);
            fmt::format_to(out, FMT_COMPILE("<path d=\"M{:.2f} {:.2f}L{:.2f} {:.2f}\"/>\n"),
                           frame.x(a[0]), frame.y(a[1]), frame.x(b[0]), frame.y(b[1]));
            file.flush_if_full();
        }
    } else {
        constexpr double keep = 0.7;  // pixels between points kept
        for (const auto& chain : segment_chains(segments)) {
            double last_x = 0, last_y = 0;
            for (std::size_t i = 0; i < chain.size(); ++i) {
                const double* p = corner(nodes, chain[i]);
                const double x = frame.x(p[0]), y = frame.y(p[1]);
                if (i > 0 && i + 1 < chain.size() && std::hypot(x - last_x, y - last_y) < keep)
                    continue;
                fmt::format_to(out, FMT_COMPILE("{}{:.1f} {:.1f}"), i == 0 ? "<path d=\"M" : "L", x,
                               y);
                last_x = x;
                last_y = y;
            }
            fmt::format_to(out, "\"/>\n");
            file.flush_if_full();
        }
    }
    fmt::format_to(out, "</g>\n");
}

// The small mesh, triangle by triangle.
void draw_triangles(File& file, const Frame& frame, const MeshExport& mesh, AngleRange& angles,
                    std::map<double, std::size_t>& regions) {
    const NodeSet& nodes = *mesh.nodes;
    if (mesh.attribute_count > 0) {
        EleSource source = mesh.triangles();
        std::vector<double> attributes(source.attribute_count);
        std::uint32_t c[6];
        for (std::size_t t = 0; t < source.count; ++t) {
            source.next(c, attributes.data());
            regions.emplace(attributes[0], 0);
        }
        std::size_t rank = 0;
        for (auto& [value, r] : regions) r = rank++;
    }
    const bool by_region = regions.size() > 1;
    Out out(file.buffer());
    fmt::format_to(out,
                   "<g id=\"triangles\" stroke=\"#303030\" stroke-width=\"0.3\" "
                   "stroke-linejoin=\"round\">\n");
    EleSource source = mesh.triangles();
    std::vector<double> attributes(std::max<std::uint32_t>(source.attribute_count, 1), 0.0);
    std::uint32_t c[6];
    for (std::size_t t = 0; t < source.count; ++t) {
        source.next(c, attributes.data());
        const double* a = corner(nodes, c[0]);
        const double* b = corner(nodes, c[1]);
        const double* d = corner(nodes, c[2]);
        angles.add(a, b, d);
        const Colour fill = by_region ? region_colour(regions.at(attributes[0]))
                                      : ramp(smallest_angle_degrees(a, b, d) / 60);
        fmt::format_to(out,
                       FMT_COMPILE("<polygon points=\"{:.2f},{:.2f} {:.2f},{:.2f} {:.2f},{:.2f}\" "
                                   "fill=\"{}\"/>\n"),
                       frame.x(a[0]), frame.y(a[1]), frame.x(b[0]), frame.y(b[1]), frame.x(d[0]),
                       frame.y(d[1]), hex(fill));
        file.flush_if_full();
    }
    fmt::format_to(out, "</g>\n");
}

// Replaces each value of the w x h image by the sum over the square of
// (2 smoothing + 1) pixels around it (clipped at the edges): two passes of
// running sums, rows then columns.  Integers, so that the sums are exact.
constexpr int smoothing = 3;
void box_sum(std::vector<std::uint32_t>& image, std::uint32_t w, std::uint32_t h) {
    std::vector<std::uint32_t> line;
    const auto pass = [&](std::size_t count, std::size_t length, std::size_t step,
                          std::size_t stride) {
        line.resize(length + 1);
        for (std::size_t l = 0; l < count; ++l) {
            std::uint32_t* p = image.data() + l * stride;
            line[0] = 0;
            for (std::size_t i = 0; i < length; ++i) line[i + 1] = line[i] + p[i * step];
            for (std::size_t i = 0; i < length; ++i) {
                const std::size_t a = i >= smoothing ? i - smoothing : 0;
                const std::size_t b = std::min(length, i + smoothing + 1);
                p[i * step] = line[b] - line[a];
            }
        }
    };
    pass(h, w, 1, w);  // each row
    pass(w, h, w, 1);  // each column
}

// What the density image is made of, per pixel: the vertices of the mesh
// in it, and whether the mesh covers it (such a vertex lies in it or a
// triangle covers its centre).  Counts and marks only: the image does not
// depend on the order in which vertices and triangles are taken.
//
// A planar triangulation has about twice as many triangles as vertices, so
// the vertices' density shows the triangles' and costs a sequential read of
// the coordinates.  The triangles, read in any case for the angle range,
// mark the vertices they use (a vertex in a hole, or a duplicate, belongs to
// no triangle and is not drawn) and, where they are not much smaller than
// a pixel, the pixel centres they cover.
struct DensityCounts {
    std::uint32_t w = 0, h = 0;
    std::vector<std::uint32_t> vertices;
    std::vector<std::uint8_t> covered;
    std::vector<std::uint8_t> used;  // per vertex

    DensityCounts(std::uint32_t width, std::uint32_t height, std::size_t vertex_count)
        : w(width),
          h(height),
          vertices(std::size_t{w} * h, 0),
          covered(std::size_t{w} * h, 0),
          used(vertex_count, 0) {}

    // Marks a pixel or a vertex.  Threads may mark the same one at once
    // (all write 1).
    static void mark(std::uint8_t& m) {
        std::atomic_ref<std::uint8_t>(m).store(1, std::memory_order_relaxed);
    }

    // Mesh coordinates -> pixels (x right, y down, from the drawing's
    // corner: never negative).
    static double px(const Frame& frame, double mx) { return (mx - frame.min_x) * frame.scale; }
    static double py(const Frame& frame, double my) { return (frame.max_y - my) * frame.scale; }

    // The vertices that the triangles use (after the CoverPass).
    void count_vertices(const Frame& frame, const NodeSet& nodes) {
        for (std::size_t v = 0; v < nodes.size(); ++v) {
            if (used[v] == 0) continue;
            const auto i = std::min(static_cast<std::uint32_t>(px(frame, nodes.xy[2 * v])), w - 1);
            const auto j =
                std::min(static_cast<std::uint32_t>(py(frame, nodes.xy[2 * v + 1])), h - 1);
            const std::size_t at = std::size_t{j} * w + i;
            ++vertices[at];
            covered[at] = 1;
        }
    }

    // One triangle, its corners in pixels: marks the pixel centres
    // (i + 0.5, j + 0.5) it covers, edges included.  Its bounding box holds
    // none, mostly, for a triangle smaller than a pixel.
    void cover(const double* x, const double* y) {
        const auto [i0, i1] =
            centres(std::min({x[0], x[1], x[2]}), std::max({x[0], x[1], x[2]}), w);
        if (i0 > i1) return;
        const auto [j0, j1] =
            centres(std::min({y[0], y[1], y[2]}), std::max({y[0], y[1], y[2]}), h);
        if (j0 > j1) return;
        // Twice the signed area; negative as y points down.
        const double twice = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
        if (twice == 0) return;
        const double sign = twice > 0 ? 1 : -1;
        for (std::int64_t j = j0; j <= j1; ++j) {
            for (std::int64_t i = i0; i <= i1; ++i) {
                const double cx = static_cast<double>(i) + 0.5, cy = static_cast<double>(j) + 0.5;
                bool inside = true;
                for (int k = 0; k < 3 && inside; ++k) {
                    const int k1 = (k + 1) % 3;
                    inside =
                        sign * ((x[k1] - x[k]) * (cy - y[k]) - (y[k1] - y[k]) * (cx - x[k])) >= 0;
                }
                if (inside)
                    mark(covered[static_cast<std::size_t>(j) * w + static_cast<std::size_t>(i)]);
            }
        }
    }

    // The k whose pixel centre k + 0.5 lies in [lo, hi] (0 <= lo <= hi),
    // as the first and last, up to n - 1: floor(v + 0.5) is the number of
    // centres up to v.
    static std::pair<std::int64_t, std::int64_t> centres(double lo, double hi, std::uint32_t n) {
        auto first = static_cast<std::int64_t>(lo + 0.5);
        if (first > 0 && static_cast<double>(first) - 0.5 == lo) --first;  // a centre on lo
        const auto last = static_cast<std::int64_t>(hi + 0.5) - 1;
        return {first, std::min<std::int64_t>(last, std::int64_t{n} - 1)};
    }
};

// The pass over the triangles: the angle range, the vertices used, and the
// pixel centres that the triangles cover.  Only a triangle with an edge of
// half a pixel or more is drawn: a pixel centre in a smaller one is closer
// than half a pixel to each of its corners, which lie in that pixel then,
// and the vertices have marked it.
//
// The pass waits on memory: a triangle's corners are anywhere in the vertex
// array.  So the triangles come in batches: the corners of a whole batch are
// asked for ahead (prefetch), then each triangle is taken.  With several
// threads and a source that reads runs of triangles from anywhere, pieces of
// the pass run on all of them: the marks are the same whichever thread makes
// them, and each piece's angle range is merged after (minima and maxima, so
// exact), so the picture does not change.
class CoverPass {
public:
    CoverPass(const Frame& frame, const MeshExport& mesh, DensityCounts& counts)
        : nodes_(*mesh.nodes),
          counts_(counts),
          frame_(frame),
          per_triangle_(mesh.corners_per_triangle),
          half_pixel_squared_(0.25 / (frame.scale * frame.scale)) {}  // in the mesh's units

    AngleRange run(const MeshExport& mesh, FormatThreads* threads) {
        const EleSource source = mesh.triangles();
        const std::size_t pieces = (source.count + piece - 1) / piece;
        if (threads == nullptr || threads->threads() < 2 || pieces < 2 || !source.read) {
            AngleRange angles;
            Batch batch(source);
            for (std::size_t first = 0; first < source.count; first += read_batch) {
                const std::size_t n = std::min(read_batch, source.count - first);
                for (std::size_t t = 0; t < n; ++t)
                    source.next(&batch.corners[per_triangle_ * t], batch.attributes.data());
                take(batch.corners.data(), n, angles);
            }
            return angles;
        }
        std::vector<AngleRange> angles(pieces);
        FormatThreads::Pieces work;
        work.count = pieces;
        work.format = [&](std::size_t p, std::size_t, fmt::memory_buffer&) {
            Batch batch(source);
            const std::size_t end = std::min(source.count, (p + 1) * piece);
            for (std::size_t first = p * piece; first < end; first += read_batch) {
                const std::size_t n = std::min(read_batch, end - first);
                source.read(first, n, batch.corners.data(), batch.attributes.data());
                take(batch.corners.data(), n, angles[p]);
            }
        };
        threads->run_pieces(work);
        AngleRange all;
        for (const AngleRange& a : angles) all.merge(a);
        return all;
    }

private:
    // Triangles read at once (a multiple of them starts where the mesh's
    // stream reads from without a walk), and per piece of the pass.
    static constexpr std::size_t read_batch = 4096;
    static constexpr std::size_t piece = 16 * read_batch;
    // Triangles whose corners are asked for ahead at once.
    static constexpr std::size_t ahead = 256;

    struct Batch {
        std::vector<std::uint32_t> corners;
        std::vector<double> attributes;
        explicit Batch(const EleSource& source)
            : corners(read_batch * source.corners_per_triangle),
              attributes(read_batch * source.attribute_count) {}
    };

    // n triangles, their corners `per_triangle_` apart in `corners`.
    void take(const std::uint32_t* corners, std::size_t n, AngleRange& angles) {
        for (std::size_t first = 0; first < n; first += ahead) {
            const std::size_t m = std::min(ahead, n - first);
            const std::uint32_t* c = corners + first * per_triangle_;
            for (std::size_t b = 0; b < m; ++b)
                for (int k = 0; k < 3; ++k) {
                    __builtin_prefetch(corner(nodes_, c[per_triangle_ * b + k]));
                    DensityCounts::mark(counts_.used[c[per_triangle_ * b + k]]);
                }
            for (std::size_t b = 0; b < m; ++b) {
                const std::uint32_t* t = c + per_triangle_ * b;
                const double* p[3] = {corner(nodes_, t[0]), corner(nodes_, t[1]),
                                      corner(nodes_, t[2])};
                if (angles.add(p[0], p[1], p[2]) < half_pixel_squared_) continue;
                double x[3], y[3];
                for (int k = 0; k < 3; ++k) {
                    x[k] = DensityCounts::px(frame_, p[k][0]);
                    y[k] = DensityCounts::py(frame_, p[k][1]);
                }
                counts_.cover(x, y);
            }
        }
    }

    const NodeSet& nodes_;
    DensityCounts& counts_;
    const Frame& frame_;
    std::size_t per_triangle_;
    double half_pixel_squared_;
};

// The large mesh: the density image.  Returns the density range, in
// vertices per unit area of the mesh, of the pixels drawn.
std::pair<double, double> draw_density(File& file, const Frame& frame, const MeshExport& mesh,
                                       AngleRange& angles, FormatThreads* threads) {
    const auto w = static_cast<std::uint32_t>(frame.width);
    const auto h = static_cast<std::uint32_t>(frame.height);
    DensityCounts counts(w, h, mesh.nodes->size());
    angles = CoverPass(frame, mesh, counts).run(mesh, threads);
    counts.count_vertices(frame, *mesh.nodes);
    // A few vertices per pixel are noise: the density shown is that of the
    // square of (2 smoothing + 1) pixels around each, the vertices in it
    // over the pixels covered in it.  Inside triangles larger than the
    // square, it may hold none: it is then shown as holding one, the least
    // density the square can tell.
    std::vector<std::uint32_t> received = std::move(counts.vertices);
    std::vector<std::uint32_t> area(counts.covered.begin(), counts.covered.end());
    box_sum(received, w, h);
    box_sum(area, w, h);
    std::vector<double> density(received.size(), 0.0);
    const std::vector<std::uint8_t>& drawn = counts.covered;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < received.size(); ++i) {
        if (drawn[i] == 0) continue;  // (then area[i] > 0)
        const double vertices = std::max<std::uint32_t>(received[i], 1);
        density[i] = std::log10(vertices / area[i]);  // per square pixel
        lo = std::min(lo, density[i]);
        hi = std::max(hi, density[i]);
    }
    // At least a factor of 10 from one end of the scale to the other, so
    // that a uniform mesh looks uniform rather than its small variations
    // filling the scale.
    if (hi - lo < 1) {
        const double middle = (hi + lo) / 2;
        lo = middle - 0.5;
        hi = middle + 0.5;
    }
    std::vector<std::uint8_t> image(received.size(), 0);
    for (std::size_t i = 0; i < received.size(); ++i) {
        if (drawn[i] == 0) continue;
        const double f = hi > lo ? (density[i] - lo) / (hi - lo) : 0.5;
        image[i] = static_cast<std::uint8_t>(1 + std::lround(f * 254));
    }
    std::vector<Colour> palette(256);
    palette[0] = {255, 255, 255};
    for (int i = 1; i < 256; ++i) palette[i] = ramp((i - 1) / 254.0);
    const std::string png = indexed_png(w, h, palette, image);
    Out out(file.buffer());
    fmt::format_to(out,
                   "<image x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" "
                   "style=\"image-rendering:pixelated\" xlink:href=\"data:image/png;base64,",
                   margin, margin, w, h);
    file.flush_if_full();
    const std::string text = base64(png);
    file.append(text.data(), text.size());
    fmt::format_to(out, "\"/>\n");
    if (lo > hi) return {0, 0};
    // Per square pixel -> per unit area of the mesh.
    const double per_unit = frame.scale * frame.scale;
    return {std::pow(10.0, lo) * per_unit, std::pow(10.0, hi) * per_unit};
}

}  // namespace

void write_svg(OutputTransaction& tx, const std::string& path, const MeshExport& mesh,
               const WriteFormat& format) {
    const NodeSet& nodes = *mesh.nodes;
    if (nodes.xy.size() % 2 != 0 ||
        (mesh.corners_per_triangle != 3 && mesh.corners_per_triangle != 6))
        throw OutputError("cannot write " + path + ": inconsistent data");
    static const SegmentSet no_segments;
    const SegmentSet& segments = mesh.segments != nullptr ? *mesh.segments : no_segments;
    const Frame frame = frame_of(nodes);
    const bool small = mesh.triangle_count <= vector_limit;
    const double width = std::max(2 * margin + frame.width, legend_width);
    const double legend_top = 2 * margin + frame.height;
    const double height = legend_top + legend_height;

    File& file = tx.begin_file(path);
    put_header(Out(file.buffer()), width, height);
    AngleRange angles;
    std::map<double, std::size_t> regions;
    std::pair<double, double> density{0, 0};
    if (small)
        draw_triangles(file, frame, mesh, angles, regions);
    else
        density = draw_density(file, frame, mesh, angles, format.threads);
    put_segments(file, frame, nodes, segments, !small);

    Out out(file.buffer());
    put_counts(out, mesh, segments.size(), angles, legend_top);
    if (!small) {
        put_ramp_bar(out, legend_top,
                     "vertices per unit area (too many triangles to draw one by one)",
                     fmt::format("{:.3g}", density.first), fmt::format("{:.3g}", density.second));
    } else if (regions.size() > 1) {
        double x = margin;
        std::size_t shown = 0;
        for (const auto& [value, rank] : regions) {
            if (++shown > 6) {
                fmt::format_to(out, "<text x=\"{}\" y=\"{}\">and {} more</text>\n", x,
                               legend_top + 52, regions.size() - 6);
                break;
            }
            const std::string label = fmt::format("region {}", value);
            fmt::format_to(out,
                           "<rect x=\"{}\" y=\"{}\" width=\"12\" height=\"12\" fill=\"{}\" "
                           "stroke=\"#303030\" stroke-width=\"0.5\"/>\n"
                           "<text x=\"{}\" y=\"{}\">{}</text>\n",
                           x, legend_top + 42, hex(region_colour(rank)), x + 16, legend_top + 52,
                           label);
            x += 16 + 8.0 * static_cast<double>(label.size()) + 12;
        }
    } else {
        put_ramp_bar(out, legend_top, "each triangle's smallest angle", "0\u00b0", "60\u00b0");
    }
    fmt::format_to(out, "</g>\n</svg>\n");
    file.finish(format.command, format.stamp, File::Closing::xml_comment);
}

}  // namespace gpdr::io
