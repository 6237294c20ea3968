#pragma once
// The point type every layer shares: plain doubles, no invariants.

namespace gpdr::geometry {

struct Point {
    double x = 0;
    double y = 0;

    friend constexpr bool operator==(const Point&, const Point&) = default;
};

}  // namespace gpdr::geometry
