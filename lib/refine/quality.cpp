// The quality tests of quality.hpp, in Triangle's order.

#include "refine/quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "refine/segments.hpp"

namespace gpdr::refine {

using geometry::Point;

QualityTest::QualityTest(const QualityCriteria& criteria, SegmentEnds segments)
    : criteria_(criteria), segments_(segments) {
    if (UserFunction* const* f = criteria_.user_test.target<UserFunction*>()) user_function_ = *f;
    angle_test_ = criteria_.min_angle_degrees > 0;
    if (angle_test_) {
        const double s = std::sin(criteria_.min_angle_degrees * std::numbers::pi / 180.0);
        rho_bar_ = 1.0 / (2.0 * s);
        rho_bar_squared_ = rho_bar_ * rho_bar_;
    } else {
        rho_bar_ = std::numeric_limits<double>::infinity();
        rho_bar_squared_ = rho_bar_;
    }
    // Diametral lenses of angle 180 - 2 theta (segments.hpp, encroaches()),
    // as Triangle has them: not for conforming Delaunay (-D: circles); above
    // 45 degrees the lens would exceed the circle, so the circle is kept;
    // without an angle bound the lens is empty (theta = 0: cos 0 = 1), so
    // that refining by size alone splits a subsegment only when a Steiner
    // point lies on it or beyond it.
    if (!criteria_.diametral_circles)
        lens_ = angle_test_ ? std::max(0.0, std::cos(2.0 * criteria_.min_angle_degrees *
                                                     std::numbers::pi / 180.0))
                            : 1.0;
    bool regional = false;
    for (double a : criteria_.region_max_area) regional = regional || a > 0;
    area_test_ = criteria_.max_area > 0 || regional || criteria_.area_field != nullptr;
}

namespace {

// call_user_test for corners with attributes, kept out of line so that the
// common case pays for no stack frame of its own.
[[gnu::noinline]] int call_user_test_with_attributes(const UserTest& test, const mesh::Mesh& mesh,
                                                     const mesh::Triangle& r, double area,
                                                     std::uint32_t width) {
    constexpr std::uint32_t on_stack = 2 + 6;
    double small[3 * on_stack];
    double* record = small;
    if (width > on_stack) {
        thread_local std::vector<double> large;
        large.resize(3 * std::size_t{width});
        record = large.data();
    }
    for (int k = 0; k < 3; ++k) {
        double* corner = record + k * width;
        const Point& p = mesh.point(r.v[k]);
        corner[0] = p.x;
        corner[1] = p.y;
        const auto row = mesh.attributes().row(r.v[k]);
        std::copy(row.begin(), row.end(), corner + 2);
    }
    return test(record, record + width, record + 2 * width, area);
}

// Each corner as Triangle's vertex record: x, y, then the attributes.
// Without attributes (the common case, and a call for every new triangle
// under -u), six numbers on the stack: copying through the general path
// cost about 100 instructions a call, 6% of the graded pipe's refinement.
// Inlined into assess(), which calls it for every triangle classified.
// `function`, when not null, is `test`'s own plain function.
[[gnu::always_inline]] inline int user_test_says(const UserTest& test, UserFunction* function,
                                                 const mesh::Mesh& mesh, const mesh::Triangle& r,
                                                 double area) {
    const std::uint32_t attributes = mesh.attributes().width();
    if (attributes != 0) return call_user_test_with_attributes(test, mesh, r, area, 2 + attributes);
    const Point& a = mesh.point(r.v[0]);
    const Point& b = mesh.point(r.v[1]);
    const Point& c = mesh.point(r.v[2]);
    double record[6] = {a.x, a.y, b.x, b.y, c.x, c.y};
    if (function != nullptr) return function(record, record + 2, record + 4, area);
    return test(record, record + 2, record + 4, area);
}

}  // namespace

int call_user_test(const UserTest& test, const mesh::Mesh& mesh, const mesh::Triangle& r,
                   double area) {
    return user_test_says(test, nullptr, mesh, r, area);
}

Poorness QualityTest::assess(const mesh::Mesh& mesh, mesh::TriangleId t, const TriangleMeasures& m,
                             bool* protected_angle) const {
    if (protected_angle) *protected_angle = false;
    const mesh::Triangle& r = mesh.triangle(t);
    if (area_test_) {
        if (criteria_.max_area > 0 && m.area > criteria_.max_area) return Poorness::too_big;
        if (r.region < criteria_.region_max_area.size()) {
            const double bound = criteria_.region_max_area[r.region];
            if (bound > 0 && m.area > bound) return Poorness::too_big;
        }
        if (criteria_.area_field != nullptr) {
            const Point centre =
                geometry::centroid(mesh.point(r.v[0]), mesh.point(r.v[1]), mesh.point(r.v[2]));
            if (m.area > criteria_.area_field->at(centre).area) return Poorness::too_big;
        }
    }
    if (criteria_.user_test != nullptr) {
        if (user_test_says(criteria_.user_test, user_function_, mesh, r, m.area) != 0)
            return Poorness::unsuitable;
    }
    if (bad_shape(m)) {
        // Leave alone a triangle whose small angle an input angle forces.
        if (small_angle_protected(mesh, t, m.shortest.edge, segments_)) {
            if (protected_angle) *protected_angle = true;
            return Poorness::good;
        }
        return Poorness::bad_angle;
    }
    return Poorness::good;
}

}  // namespace gpdr::refine
