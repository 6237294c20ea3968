// Where a subsegment is split (refine/segments.hpp, split_parameter):
// concentric shells at an input vertex only where another subsegment leaves
// it at an angle small enough for the split points of each to encroach the
// other (below 90 degrees with diametral circles, below twice the angle
// bound with lenses); the midpoint elsewhere, crossing points included.

#include "refine_support.hpp"

namespace gpdr::refine::testing {

namespace {

// The diametral lens encroaches() takes for an angle bound in degrees.
double lens_of(double degrees) { return std::cos(2.0 * degrees * std::numbers::pi / 180.0); }

struct Split {
    double from_corner = 0;  // distance of the split point from `corner`
    double length = 0;       // the subsegment's length
};

// Splits the subsegment corner-far of the CDT of pslg where split_parameter
// puts the point.
Split split_of(const triangulate::Pslg& pslg, std::uint32_t corner, std::uint32_t far,
               double lens) {
    triangulate::CdtReport report;
    const mesh::Mesh m = triangulate::triangulate_segments(pslg, report);
    const mesh::VertexId a{corner}, b{far};
    mesh::EdgeRef found = mesh::EdgeRef::none();
    mesh::for_each_triangle(m, [&](mesh::TriangleId id, const mesh::Triangle& t) {
        for (int k = 0; k < 3; ++k) {
            const mesh::EdgeRef e(id, k);
            const bool ends = (m.origin(e) == a && m.destination(e) == b) ||
                              (m.origin(e) == b && m.destination(e) == a);
            if (ends && t.is_subsegment(k)) found = e;
        }
    });
    REQUIRE_FALSE(found.is_none());
    const Point& o = m.point(m.origin(found));
    const Point& d = m.point(m.destination(found));
    const Point p = geometry::point_on_segment(o, d, split_parameter(m, found, lens));
    return {std::sqrt(geometry::squared_distance(p, m.point(a))),
            std::sqrt(geometry::squared_distance(o, d))};
}

// Two segments of length 1.5 from the origin, `degrees` apart, in a box.
triangulate::Pslg corner(double degrees) {
    triangulate::Pslg p;
    const double a = degrees * std::numbers::pi / 180.0;
    p.points = {{-2, -2},
                {2, -2},
                {2, 2},
                {-2, 2},
                {0, 0},
                {1.5, 0},
                {1.5 * std::cos(a), 1.5 * std::sin(a)}};
    p.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 4, 6};
    return p;
}

}  // namespace

TEST_CASE("concentric shells where a corner's split points can encroach", "[refine][shells]") {
    // 1.5 long: the shell at distance 1 from the corner.
    const Split narrow = split_of(corner(50), 4, 5, lens_of(33));
    CHECK(narrow.from_corner == Approx(1.0));
    CHECK(split_of(corner(50), 4, 5, 0.0).from_corner == Approx(1.0));
    // 75 degrees: within a circle's reach (90), beyond a 33-degree lens's
    // (66), and beyond the reach of a 30-degree one (60).
    CHECK(split_of(corner(75), 4, 5, 0.0).from_corner == Approx(1.0));
    CHECK(split_of(corner(75), 4, 5, lens_of(33)).from_corner == Approx(0.75));
    CHECK(split_of(corner(75), 4, 5, lens_of(30)).from_corner == Approx(0.75));
    CHECK(split_of(corner(62), 4, 5, lens_of(33)).from_corner == Approx(1.0));
    // No vertex encroaches without an angle bound (lens 1): a rejected
    // Steiner point still splits, and the circle's 90 degrees decide.
    CHECK(split_of(corner(75), 4, 5, 1.0).from_corner == Approx(1.0));
    // Wider than 90 degrees: the midpoint for every lens.
    CHECK(split_of(corner(95), 4, 5, 0.0).from_corner == Approx(0.75));
    CHECK(split_of(corner(120), 4, 5, lens_of(20)).from_corner == Approx(0.75));
}

TEST_CASE("a crossing point is a corner of its four pieces", "[refine][shells]") {
    // Segments crossing at 76 and 104 degrees, at 50 and 130: the crossing
    // point is an input vertex where four pieces meet.  A piece from it to
    // a free end, 1.5 long, gets a shell split only where the crossing's
    // acute angle is within the lens's reach.
    for (const double degrees : {76.0, 50.0}) {
        INFO(degrees);
        triangulate::Pslg p;
        const double a = degrees * std::numbers::pi / 180.0;
        const Point x{0.25, 0.5};
        p.points = {{-3, -3},
                    {3, -3},
                    {3, 3},
                    {-3, 3},
                    {x.x - 1.5, x.y},
                    {x.x + 1.5, x.y},
                    {x.x - 1.5 * std::cos(a), x.y - 1.5 * std::sin(a)},
                    {x.x + 1.5 * std::cos(a), x.y + 1.5 * std::sin(a)}};
        p.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 6, 7};
        triangulate::CdtReport report;
        const mesh::Mesh m = triangulate::triangulate_segments(p, report);
        REQUIRE(report.new_vertices.size() == 1);
        const std::uint32_t crossing = index(report.new_vertices.front().vertex);
        const double expected = degrees < 66 ? 1.0 : 0.75;
        CHECK(split_of(p, crossing, 5, lens_of(33)).from_corner == Approx(expected));
        CHECK(split_of(p, crossing, 5, 0.0).from_corner == Approx(1.0));
    }
}

}  // namespace gpdr::refine::testing
