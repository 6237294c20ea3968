// Point location against a boundary (see edge_strips.hpp).

#include "geometry/edge_strips.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/constructions.hpp"
#include "geometry/predicates.hpp"

namespace gpdr::geometry {

EdgeStrips::EdgeStrips(std::vector<Point> ends) : ends_(std::move(ends)) {
    const std::size_t edges = ends_.size() / 2;
    if (edges == 0) {
        offsets_.assign(2, 0);
        return;
    }
    lo_ = hi_ = ends_[0].y;
    for (const Point& p : ends_) {
        lo_ = std::min(lo_, p.y);
        hi_ = std::max(hi_, p.y);
    }
    strips_ = hi_ > lo_ ? std::min<std::size_t>(edges, std::size_t{1} << 24) : 1;
    height_ = hi_ > lo_ ? (hi_ - lo_) / static_cast<double>(strips_) : 1.0;
    offsets_.assign(strips_ + 1, 0);
    const auto span_of = [&](std::size_t e) {
        const double y0 = std::min(ends_[2 * e].y, ends_[2 * e + 1].y);
        const double y1 = std::max(ends_[2 * e].y, ends_[2 * e + 1].y);
        return std::pair{strip(y0), strip(y1)};
    };
    for (std::size_t e = 0; e < edges; ++e) {
        const auto [s0, s1] = span_of(e);
        for (std::size_t s = s0; s <= s1; ++s) ++offsets_[s + 1];
    }
    for (std::size_t s = 0; s < strips_; ++s) offsets_[s + 1] += offsets_[s];
    members_.resize(offsets_[strips_]);
    std::vector<std::size_t> fill(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t e = 0; e < edges; ++e) {
        const auto [s0, s1] = span_of(e);
        for (std::size_t s = s0; s <= s1; ++s) members_[fill[s]++] = static_cast<std::uint32_t>(e);
    }
}

std::size_t EdgeStrips::strip(double y) const {
    const double s = std::floor((y - lo_) / height_);
    return s <= 0                              ? 0
           : s >= static_cast<double>(strips_) ? strips_ - 1
                                               : static_cast<std::size_t>(s);
}

EdgeStrips::Where EdgeStrips::locate(const Point& p) const {
    if (ends_.empty() || !(p.y >= lo_ && p.y <= hi_)) return Where::outside;
    const std::size_t s = strip(p.y);
    bool odd = false;
    for (std::size_t k = offsets_[s]; k < offsets_[s + 1]; ++k) {
        const std::uint32_t e = members_[k];
        const Point &u = ends_[2 * std::size_t{e}], &w = ends_[2 * std::size_t{e} + 1];
        if (p.y < std::min(u.y, w.y) || p.y > std::max(u.y, w.y)) continue;
        const double side = orient2d(u, w, p);
        if (side == 0 && p.x >= std::min(u.x, w.x) && p.x <= std::max(u.x, w.x))
            return Where::on_edge;
        if (u.y <= p.y && p.y < w.y && side > 0)
            odd = !odd;  // upward, p on its left
        else if (w.y <= p.y && p.y < u.y && side < 0)
            odd = !odd;  // downward, p on its right
    }
    return odd ? Where::inside : Where::outside;
}

bool EdgeStrips::crossed(const Point& a, const Point& b, double margin) const {
    if (ends_.empty()) return false;
    const double y0 = std::min(a.y, b.y), y1 = std::max(a.y, b.y);
    if (y1 < lo_ || y0 > hi_) return false;
    for (std::size_t s = strip(y0), last = strip(y1); s <= last; ++s)
        for (std::size_t k = offsets_[s]; k < offsets_[s + 1]; ++k) {
            const std::uint32_t e = members_[k];
            const Point &u = ends_[2 * std::size_t{e}], &w = ends_[2 * std::size_t{e} + 1];
            const double su = orient2d(a, b, u), sw = orient2d(a, b, w);
            if (!((su < 0 && sw > 0) || (su > 0 && sw < 0))) continue;
            const double sa = orient2d(u, w, a), sb = orient2d(u, w, b);
            if (!((sa < 0 && sb > 0) || (sa > 0 && sb < 0))) continue;
            if (margin <= 0) return true;
            const Point x = segment_intersection(a, b, u, w);
            const double m2 = margin * margin;
            if (squared_distance(x, a) > m2 && squared_distance(x, b) > m2) return true;
        }
    return false;
}

}  // namespace gpdr::geometry
