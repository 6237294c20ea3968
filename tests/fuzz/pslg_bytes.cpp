// Decoding the pipeline fuzz target's bytes (pslg_bytes.hpp).

#include "fuzz/pslg_bytes.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace gpdr::fuzz {
namespace {

// A cursor that reads 0 past the end.
class Bytes {
public:
    explicit Bytes(std::span<const std::uint8_t> b) : b_(b) {}
    std::uint8_t next() { return at_ < b_.size() ? b_[at_++] : 0; }
    std::size_t left() const { return b_.size() - at_; }
    std::span<const std::uint8_t> rest() const { return b_.subspan(at_); }

private:
    std::span<const std::uint8_t> b_;
    std::size_t at_ = 0;
};

// Grid to coordinates.  The first is exact; the others give the inexact
// crossings of digitised and generated data, near-collinear triples after
// rounding, and tiny or huge magnitudes.
double grid_map(int map, std::int8_t g) {
    const double v = g;
    switch (map & 7) {
        case 0:
            return v;
        case 1:
            return v * 0.1;
        case 2:
            return v * 0.001;
        case 3:
            return v * 0.1 + 1e6;
        case 4:
            return v / 3 + 7;
        case 5:
            return v * 1e5;
        case 6:
            return v * 1e-9 + 1;
        default:
            return v * 0.37 - 11.3;
    }
}

double coordinate(Bytes& in, int map) { return grid_map(map, static_cast<std::int8_t>(in.next())); }

}  // namespace

PipelineCase decode_pipeline_case(std::span<const std::uint8_t> bytes) {
    Bytes in(bytes);
    const std::uint8_t b0 = in.next(), b1 = in.next();
    const std::size_t n = std::min<std::size_t>(in.next(), max_vertices);
    std::size_t m = std::min<std::size_t>(in.next(), max_segments);
    const std::uint8_t b4 = in.next();
    const int map = (b1 >> 3) & 7;

    PipelineCase c;
    MeshInput& input = c.input;
    input.name = "fuzz";
    const std::size_t vertices = std::min(n, in.left() / 2);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (std::size_t v = 0; v < 2 * vertices; ++v) {
        const double x = coordinate(in, map);
        input.nodes.xy.push_back(x);
        lo[v % 2] = std::min(lo[v % 2], x);
        hi[v % 2] = std::max(hi[v % 2], x);
    }
    if (vertices > 0) c.box_area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
    if (vertices == 0) m = 0;
    m = std::min(m, in.left() / 2);
    for (std::size_t s = 0; s < 2 * m; ++s)
        input.segments.endpoints.push_back(static_cast<std::uint32_t>(in.next() % vertices));
    for (std::size_t h = b4 & 3; h > 0 && in.left() >= 2; --h) {
        input.holes.push_back(coordinate(in, map));
        input.holes.push_back(coordinate(in, map));
    }
    for (std::size_t r = (b4 >> 2) & 3; r > 0 && in.left() >= 4; --r) {
        Region region;
        region.x = coordinate(in, map);
        region.y = coordinate(in, map);
        region.attribute = in.next();
        const std::uint8_t area = in.next();
        region.max_area = area == 0 || c.box_area <= 0 ? -1 : c.box_area / area;
        input.regions.push_back(region);
    }
    c.area_bytes = in.rest();

    Options& o = c.options;
    const int mode = b0 & 3;
    o.poly = mode != 3 && m > 0;
    o.quality = mode == 1 || mode == 3;
    o.convex_hull = mode == 2;
    o.conforming_delaunay = (b0 >> 2) & 1;
    if (((b0 >> 3) & 1) && c.box_area > 0) {
        o.area_limit = true;
        o.max_area = std::ldexp(c.box_area, -int(b4 >> 4) - 1);
        o.regional_area = true;
    }
    if (((b0 >> 4) & 3) != 3) o.placement = static_cast<Placement>((b0 >> 4) & 3);
    o.no_segment_splitting = (b0 >> 6) & 1;
    o.region_attributes = (b0 >> 7) & 1;
    static constexpr std::array<double, 8> angles = {20, 25, 30, 33, 0, 10, 15, 34};
    o.min_angle = angles[b1 & 7];
    o.jettison = (b1 >> 6) & 1;
    o.order = (b1 >> 7) & 1 ? 2 : 1;
    o.steiner_limit = true;
    o.max_steiner = steiner_budget;
    o.threads = 1;
    o.check = true;
    o.quiet = true;

    if (mode == 3) {
        c.refine = true;
        c.first = Options{};
        c.first.poly = m > 0;
        c.first.steiner_limit = true;
        c.first.max_steiner = steiner_budget;
        c.first.threads = 1;
        c.first.check = true;
        c.first.quiet = true;
        o.refine = true;
        o.poly = m > 0;
    }
    return c;
}

AreaSet triangle_area_bounds(const PipelineCase& c, std::size_t triangles) {
    AreaSet areas(triangles, -1.0);
    if (c.area_bytes.empty() || c.box_area <= 0) return areas;
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint8_t k = c.area_bytes[t % c.area_bytes.size()];
        if (k != 0) areas[t] = c.box_area / k;
    }
    return areas;
}

}  // namespace gpdr::fuzz
