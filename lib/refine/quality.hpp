#pragma once
// Quality criteria: when is a triangle "poor" and must be refined (Triangle's
// -q, -a, bare -a with regions or an .area file, -u).
//
// The tests, in Triangle's order (its documentation: the user test comes
// after the area checks, and the angle test last):
//   1. global area bound      area > max_area                      (-a<A>)
//   2. regional area bound    area > region_max_area[t.region]     (-a with .poly regions)
//   3. .area field            area > the field at its centroid      (-ra with an .area file)
//   4. user test              triunsuitable(org, dest, apex, area) != 0   (-u)
//   5. angle bound            r / l > rho_bar = 1 / (2 sin theta), compared as squares
//                             (r circumradius, l shortest edge), unless a small input
//                             angle forces the small angle (small_angle.hpp).
// A bound <= 0 means "no bound"; theta = 0 means no angle test.
//
// Thread safety: QualityTest is immutable after construction and may be
// shared by threads.  The user test is called from several threads at once
// when refinement runs in parallel: it must be thread-safe (a pure function
// of its arguments is).

#include <cstdint>
#include <functional>
#include <vector>

#include "geometry/area_field.hpp"
#include "geometry/constructions.hpp"
#include "mesh/mesh.hpp"
#include "refine/segments.hpp"

namespace gpdr::refine {

// Triangle's triunsuitable() prototype: each pointer addresses x, y and then
// the vertex attributes of one corner (corners counter-clockwise: org, dest,
// apex), as Triangle's vertex records do; area > 0.  gpdr passes copies, so
// a test that writes through them changes nothing.  Non-zero: the triangle is too big / unsuitable,
// refine it.  A function object, so that a library caller's test can carry its own data.
using UserFunction = int(double* org, double* dest, double* apex, double area);
using UserTest = std::function<UserFunction>;

// Calls `test` on triangle r of the mesh (area > 0) with each corner as
// Triangle's vertex record: x, y, then the vertex's attributes.
int call_user_test(const UserTest& test, const mesh::Mesh& mesh, const mesh::Triangle& r,
                   double area);

struct QualityCriteria {
    double min_angle_degrees = 0;  // -q; 0: no angle test
    double max_area = -1;          // -a<A>; <= 0: no bound
    // Indexed by Triangle::region (the CDT numbers region i of the .poly as
    // i + 1 and leaves 0 for "no region"); an entry <= 0 or an index past
    // the end: no bound.
    std::vector<double> region_max_area;
    // -ra: the bounds of an .area file as a field over the plane, each
    // triangle held to it at its centroid (geometry/area_field.hpp).  Not
    // owned; nullptr: none.
    const geometry::AreaField* area_field = nullptr;
    UserTest user_test = nullptr;  // -u
    // Encroachment by diametral circles instead of lenses (-D: every
    // subsegment must end up Delaunay).
    bool diametral_circles = false;
};

// Why a triangle is poor (several may hold; the first in test order is kept).
enum class Poorness : std::uint8_t { good, too_big, unsuitable, bad_angle };

// The measures every caller needs anyway, computed once.
struct TriangleMeasures {
    geometry::Circle circle;        // circumcircle
    geometry::EdgeLength shortest;  // shortest edge (index = opposite corner)
    double area = 0;
};

class QualityTest {
public:
    // `segments`: the input segments' ends, for the small-input-angle rule
    // (may be empty, see segments.hpp).
    explicit QualityTest(const QualityCriteria& criteria, SegmentEnds segments = {});

    const QualityCriteria& criteria() const { return criteria_; }
    // rho_bar = 1 / (2 sin theta); +infinity when there is no angle test.
    double rho_bar() const { return rho_bar_; }
    bool has_angle_test() const { return angle_test_; }
    // The `lens` argument of encroaches() (segments.hpp): cos(2 theta) for
    // diametral lenses, 0 for diametral circles, 1 (nothing encroaches)
    // without an angle bound.
    double encroachment_lens() const { return lens_; }
    bool has_area_test() const { return area_test_; }

    // Inline: its caller for every new triangle (LeafRefiner::classify_created)
    // copies the circle on, and a copy loaded back from a returned record
    // whose parts were stored one by one waits for the stores to retire.
    static TriangleMeasures measure(const geometry::Point& a, const geometry::Point& b,
                                    const geometry::Point& c) {
        const double orientation =
            geometry::orient2d(a, b, c);  // once: the circle and the area share it
        return {geometry::circumcircle(a, b, c, orientation), geometry::shortest_edge(a, b, c),
                0.5 * orientation};
    }

    // Tests 1-5 on live triangle t (measures from measure()).  The angle test
    // leaves a triangle alone when a small input angle forces its angle
    // (`protected_angle` is then set, and the result is good).
    Poorness assess(const mesh::Mesh& mesh, mesh::TriangleId t, const TriangleMeasures& m,
                    bool* protected_angle = nullptr) const;

    // Only the shape: r^2 > rho_bar^2 l^2.
    bool bad_shape(const TriangleMeasures& m) const {
        return angle_test_ &&
               m.circle.radius_squared > rho_bar_squared_ * m.shortest.length_squared;
    }

private:
    QualityCriteria criteria_;
    SegmentEnds segments_;
    double rho_bar_ = 0;
    double rho_bar_squared_ = 0;
    bool angle_test_ = false;
    double lens_ = 0.0;
    bool area_test_ = false;
    // The user test when it is a plain function (a triunsuitable() from a
    // plugin or linked in): called directly, without std::function's
    // second indirection.
    UserFunction* user_function_ = nullptr;
};

}  // namespace gpdr::refine
