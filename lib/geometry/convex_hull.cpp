// Andrew's monotone chain (see convex_hull.hpp).

#include "geometry/convex_hull.hpp"

#include <algorithm>
#include <numeric>

#include "geometry/predicates.hpp"

namespace gpdr::geometry {

std::vector<std::uint32_t> convex_hull(std::span<const Point> points) {
    std::vector<std::uint32_t> order(points.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto below = [&](std::uint32_t i, std::uint32_t j) {
        const Point &p = points[i], &q = points[j];
        return p.x < q.x || (p.x == q.x && p.y < q.y);
    };
    std::sort(order.begin(), order.end(), below);
    order.erase(
        std::unique(order.begin(), order.end(),
                    [&](std::uint32_t i, std::uint32_t j) { return points[i] == points[j]; }),
        order.end());
    if (order.size() < 3) return order;

    // Each chain keeps only strict left turns, so collinear points drop out.
    std::vector<std::uint32_t> hull;
    hull.reserve(2 * order.size());
    const auto add = [&](std::uint32_t i, std::size_t floor) {
        while (hull.size() > floor &&
               orient2d(points[hull[hull.size() - 2]], points[hull.back()], points[i]) <= 0)
            hull.pop_back();
        hull.push_back(i);
    };
    for (const std::uint32_t i : order) add(i, 1);  // lower chain, left to right
    const std::size_t lower = hull.size();
    for (std::size_t k = order.size() - 1; k-- > 0;) add(order[k], lower);  // upper chain
    hull.pop_back();                                                        // the first point again
    if (hull.size() < 3) {
        // All collinear: the chains met at the two extreme points.
        return {order.front(), order.back()};
    }
    return hull;
}

}  // namespace gpdr::geometry
