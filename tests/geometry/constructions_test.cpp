// Tests of lib/geometry/constructions: circumcircle, ratios on known
// triangles, selection disk, Ungor's off-centre and segment intersection.

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "geometry/constructions.hpp"

namespace {

using namespace gpdr::geometry;

double distance(const Point& p, const Point& q) { return std::sqrt(squared_distance(p, q)); }

// A random non-degenerate triangle around (ox, oy) of size about `size`.
struct TriangleMaker {
    std::mt19937_64 rng{11};
    std::uniform_real_distribution<double> unit{-1.0, 1.0};

    std::array<Point, 3> operator()(double ox, double oy, double size) {
        for (;;) {
            const Point a{ox + size * unit(rng), oy + size * unit(rng)};
            const Point b{ox + size * unit(rng), oy + size * unit(rng)};
            const Point c{ox + size * unit(rng), oy + size * unit(rng)};
            if (std::abs(orient2d(a, b, c)) > 1e-3 * size * size) return {a, b, c};
        }
    }
};

}  // namespace

TEST_CASE("circumcircle is equidistant from the corners", "[geometry][constructions]") {
    TriangleMaker make;
    for (const auto& [ox, oy, size] : {std::array{0.0, 0.0, 1.0}, std::array{1e7, -1e7, 1.0},
                                       std::array{0.0, 0.0, 1e-10}, std::array{5e9, 5e9, 1e10}}) {
        for (int i = 0; i < 200; ++i) {
            const auto [a, b, c] = make(ox, oy, size);
            const Circle circle = circumcircle(a, b, c);
            const double r = std::sqrt(circle.radius_squared);
            INFO("origin " << ox << " size " << size);
            REQUIRE(std::abs(distance(circle.centre, a) - r) <= 1e-6 * r);
            REQUIRE(std::abs(distance(circle.centre, b) - r) <= 1e-6 * r);
            REQUIRE(std::abs(distance(circle.centre, c) - r) <= 1e-6 * r);
            // The orientation of the corners does not matter.
            const Circle reversed = circumcircle(a, c, b);
            REQUIRE(std::abs(reversed.radius_squared - circle.radius_squared) <=
                    1e-9 * circle.radius_squared);
        }
    }
}

TEST_CASE("ratios, areas and shortest edges of known triangles", "[geometry][constructions]") {
    const Point o{0, 0};
    // Equilateral: circumradius 1/sqrt(3) of the side.
    const Point e1{1, 0}, e2{0.5, std::sqrt(3.0) / 2};
    CHECK(radius_edge_ratio(o, e1, e2) == Approx(1 / std::sqrt(3.0)).epsilon(1e-12));
    CHECK(circumradius_squared(o, e1, e2) == Approx(1.0 / 3).epsilon(1e-12));

    // Right isosceles (legs 1): r = sqrt(2)/2, shortest edge 1, centre at the
    // hypotenuse's midpoint.
    const Point x{1, 0}, y{0, 1};
    CHECK(radius_edge_ratio(o, x, y) == Approx(std::sqrt(2.0) / 2).epsilon(1e-12));
    CHECK(circumcentre(o, x, y).x == Approx(0.5));
    CHECK(circumcentre(o, x, y).y == Approx(0.5));
    CHECK(signed_area(o, x, y) == 0.5);
    CHECK(signed_area(o, y, x) == -0.5);

    // Smallest angle 30 degrees: ratio 1 / (2 sin 30) = 1.
    const Point p{0, 0}, q{1, 0}, apex{0.5, 0.5 / std::tan(M_PI / 12)};
    CHECK(radius_edge_ratio(p, q, apex) == Approx(1.0).epsilon(1e-12));

    // Shortest edge: edge i is opposite corner i.
    const Point a{0, 0}, b{10, 0}, c{10, 1};
    CHECK(shortest_edge(a, b, c).edge == 0);  // bc, length 1
    CHECK(shortest_edge(a, b, c).length_squared == 1.0);
    CHECK(shortest_edge(b, c, a).edge == 2);  // bc again, now opposite the third
    CHECK(shortest_edge(c, a, b).edge == 1);
    // A thin triangle: ratio grows like (long side / short side) / 2.
    CHECK(radius_edge_ratio(a, b, c) > 5.0);
}

TEST_CASE("selection disk", "[geometry][constructions]") {
    // Equilateral triangle: r - sqrt(2) l < 0, the disk is empty.
    const Point o{0, 0}, e1{1, 0}, e2{0.5, std::sqrt(3.0) / 2};
    CHECK(selection_disk(o, e1, e2).radius < 0);
    // A skinny triangle: r = |apex - centre|, l = 1.
    const Point p{0, 0}, q{1, 0}, apex{0.5, 20};
    const Disk disk = selection_disk(p, q, apex);
    const Circle circle = circumcircle(p, q, apex);
    CHECK(disk.centre == circle.centre);
    CHECK(disk.radius == Approx(std::sqrt(circle.radius_squared) - std::sqrt(2.0)));
}

TEST_CASE("off-centre", "[geometry][constructions]") {
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> stretch(1.01, 60.0);  // keeps pq shortest
    int moved = 0, at_circumcentre = 0;
    for (double rho : {1.0, std::numbers::sqrt2, 2.0}) {
        for (double origin : {0.0, 1e6}) {
            for (int i = 0; i < 300; ++i) {
                // Random triangles from fat to very skinny, random orientation.
                const Point p{origin + unit(rng), origin + unit(rng)};
                const double angle = M_PI * unit(rng);
                const double len = 0.1 + std::abs(unit(rng));
                const Point q{p.x + len * std::cos(angle), p.y + len * std::sin(angle)};
                const double along = 0.5 + 0.4 * unit(rng), height = len * stretch(rng);
                const Point r{p.x + along * (q.x - p.x) - height * (q.y - p.y) / len,
                              p.y + along * (q.y - p.y) + height * (q.x - p.x) / len};
                const auto corners = (i % 2) ? std::array{p, q, r} : std::array{q, p, r};
                const auto [a, b, c] = corners;
                const double ratio = radius_edge_ratio(a, b, c);
                const Point off = off_centre(a, b, c, rho);
                const Circle circle = circumcircle(a, b, c);
                INFO("rho " << rho << " ratio " << ratio);

                // The shortest edge pq (the construction's premise here).
                REQUIRE(shortest_edge(p, q, r).edge == 2);
                if (ratio <= rho * (1 - 1e-9)) {
                    // Not poor: the circumcentre is nearer than the off-centre.
                    REQUIRE(off == circle.centre);
                }
                if (off == circle.centre) {
                    ++at_circumcentre;
                } else {
                    ++moved;
                    // New triangle p q off has ratio exactly rho, off is on the
                    // bisector of pq on the circumcentre's side, nearer to pq.
                    REQUIRE(radius_edge_ratio(p, q, off) == Approx(rho).epsilon(1e-9));
                    REQUIRE(distance(off, p) == Approx(distance(off, q)).epsilon(1e-9));
                    REQUIRE(orient2d(p, q, off) * orient2d(p, q, r) > 0);
                    const Point m{(p.x + q.x) / 2, (p.y + q.y) / 2};
                    REQUIRE(distance(m, off) < distance(m, circle.centre));
                }
                // For rho >= sqrt(2) and a poor triangle, the off-centre lies in
                // the selection disk (GPDR: off-centres are a valid choice).
                if (rho >= std::numbers::sqrt2 && ratio > rho * (1 + 1e-9)) {
                    const Disk disk = selection_disk(a, b, c);
                    REQUIRE(disk.radius > 0);
                    REQUIRE(distance(off, disk.centre) < disk.radius);
                }
            }
        }
    }
    REQUIRE(moved > 200);
    REQUIRE(at_circumcentre > 50);
}

TEST_CASE("segment intersection and points on segments", "[geometry][constructions]") {
    const Point x = segment_intersection({0, 0}, {2, 2}, {0, 2}, {2, 0});
    CHECK(x.x == 1.0);
    CHECK(x.y == 1.0);
    // One end of ab on cd: that end, exactly.
    const Point a{0.1, 0.7}, b{3.3, -1.9};
    CHECK(segment_intersection(a, b, {0.1, -5}, {0.1, 5}) == a);
    CHECK(point_on_segment(a, b, 0.0) == a);
    CHECK(point_on_segment(a, b, 1.0) == b);
    const Point mid = point_on_segment(a, b, 0.5);
    CHECK(mid.x == Approx(1.7));
    CHECK(mid.y == Approx(-0.6));

    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int checked = 0;
    for (double origin : {0.0, 1e7}) {
        while (checked < (origin == 0 ? 300 : 600)) {
            const Point p{origin + unit(rng), origin + unit(rng)},
                q{origin + unit(rng), origin + unit(rng)},
                r{origin + unit(rng), origin + unit(rng)},
                s{origin + unit(rng), origin + unit(rng)};
            // Proper crossings only.
            if (orient2d(r, s, p) * orient2d(r, s, q) >= 0) continue;
            if (orient2d(p, q, r) * orient2d(p, q, s) >= 0) continue;
            const Point y = segment_intersection(p, q, r, s);
            // On both lines (distance relative to the segment lengths), and
            // inside both bounding boxes.
            const double tol = 1e-9 * (origin == 0 ? 1 : 1e7);
            REQUIRE(std::abs(orient2d(p, q, y)) / distance(p, q) <= tol);
            REQUIRE(std::abs(orient2d(r, s, y)) / distance(r, s) <= tol);
            REQUIRE(y.x >= std::min(p.x, q.x));
            REQUIRE(y.x <= std::max(p.x, q.x));
            REQUIRE(y.x >= std::min(r.x, s.x) - tol);
            REQUIRE(y.x <= std::max(r.x, s.x) + tol);
            ++checked;
        }
    }
    REQUIRE(checked == 600);
}
