// Adaptive exact orient2d and incircle, in the manner of Shewchuk, "Adaptive
// Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates"
// (DCG 18, 1997), section 4: a floating-point filter with a proven error bound
// decides almost every call; behind it, the determinant of the rounded
// coordinate differences is computed exactly (stage B), and only when that
// cannot decide, the determinant of the exact differences (stage D).
// Written from the paper's mathematics; the error bounds are derived below.
// What differs from the paper: no stage C (the first-order tail correction)
// -- stage D is reached only by inputs degenerate to within a few ulps whose
// coordinate differences are not exact, and its cost there is irrelevant;
// stage B's test carries its own rigorous bound on the error of the estimate
// instead of relying on the structure of the expansion.
//
// Compiled with -ffp-contract=off (lib/CMakeLists.txt): see expansion.hpp.
//
// Error analysis conventions.  u = 2^-53.  Every rounding satisfies both
// fl(x op y) = (x op y)(1 + d) and (x op y) = fl(x op y)(1 + d') with
// |d|, |d'| <= u (no overflow or underflow).  Rounding to nearest preserves
// sign, and fl(a - b) == 0 exactly when a == b.
//
// Range: exact provided no intermediate value overflows or underflows; this
// holds when every coordinate is zero or of magnitude within [1e-50, 1e50].

#include "geometry/predicates.hpp"

#include <cmath>

#include "geometry/expansion.hpp"

namespace gpdr::geometry {

namespace {

using namespace exact;

constexpr double u = kUnitRoundoff;

// orient2d, stage A.  Let acx = fl(ax - cx) etc. (computed), detleft =
// fl(acx bcy), detright = fl(acy bcx), X = detleft - detright (exact) and
// det = fl(X), which has the sign of X.  The true value is
// T = (ax - cx)(by - cy) - (ay - cy)(bx - cx) = acx bcy (1+a1)(1+a2) - ...,
// while X = acx bcy (1+d1) - acy bcx (1+d2); so
//   |X - T| <= ((1+u)^2 - 1 + u) P',  P' = |acx bcy| + |acy bcx|,
// and P' <= (|detleft| + |detright|) / (1-u) <= detsum / (1-u)^2 with
// detsum = fl(|detleft| + |detright|).  The sign of det is right when
// |X| > |X - T|; as |X| >= |det| / (1+u), it suffices that
//   |det| > (3u + u^2)(1+u)(1-u)^-2 detsum = (3u + 10u^2 + O(u^3)) detsum,
// and errbound = fl(k detsum) >= k detsum (1-u) costs another 3u^2.  So
// k = (3 + 16u) u (exactly representable) holds with room to spare; it is
// also Shewchuk's constant.
constexpr double kOrientBoundA = (3.0 + 16.0 * u) * u;
static_assert(kOrientBoundA == detail::orient_bound_a);

// orient2d, stage B.  B = acx bcy - acy bcx computed exactly; T differs from
// it only through the rounding of the four differences:
//   |T - B| <= ((1+u)^2 - 1) P' <= (2u + u^2)(1+u)^2 detsum
//           =  (2u + 5u^2 + O(u^3)) detsum.
constexpr double kOrientBoundB = (2.0 + 8.0 * u) * u;

// incircle, stage A.  With adx = fl(ax - dx) etc., the computed det is
// fl(fl(ta + tb) + tc), ta = fl(alift * fl(bdxcdy - cdxbdy)), alift =
// fl(fl(adx adx) + fl(ady ady)), bdxcdy = fl(bdx cdy), ...  Expanded, T' (the
// exact determinant of the computed differences) is a sum of 12 degree-4
// monomials m_i, and X = fl(ta + tb) + tc (det before its last rounding,
// same sign as det) is sum m_i (1 + t_i) with each t_i a product of at most 6
// factors (1 + d): |X - T'| <= ((1+u)^6 - 1) P', P' = sum |m_i|.  The true
// determinant T carries each difference's rounding, 4 per monomial:
// |T' - T| <= ((1+u)^4 - 1) P'.  The computed permanent is sum |m_i| times at
// most 7 factors (1 + d) each, so P' <= permanent / (1-u)^7.  The sign is
// right when |X| > |X - T|, and |X| >= |det| / (1+u); so it suffices that
//   |det| > (1+u)(1-u)^-7 ((1+u)^6 + (1+u)^4 - 2) permanent
//         = (10u + 111u^2 + O(u^3)) permanent,
// plus u^2 terms for rounding errbound itself: k = (10 + 128u) u suffices.
// (Shewchuk proves 96 with a finer accounting; the difference is immaterial.)
constexpr double kIncircleBoundA = (10.0 + 128.0 * u) * u;
static_assert(kIncircleBoundA == detail::incircle_bound_a);

// incircle, stage B.  B = T' computed exactly; |T - B| <= ((1+u)^4 - 1) P'
// <= (4u + 6u^2 + O(u^3)) (1-u)^-7 permanent = (4u + 34u^2 + O(u^3)) permanent.
constexpr double kIncircleBoundB = (4.0 + 48.0 * u) * u;

// h = a b - c d exactly (<= 4 components).
int cross_difference(double a, double b, double c, double d, double* h) {
    double p[2], q[2];
    double x, y;
    two_product(a, b, x, y);
    const int np = make_pair(x, y, p);
    two_product(c, d, x, y);
    const int nq = make_pair(x, y, q);
    negate(nq, q);
    return expansion_sum(np, p, nq, q, h);
}

// h = (dx^2 + dy^2) * e exactly, for doubles dx, dy and ne <= 4 (so h has
// <= 8 ne <= 32 components).
int lift_times(double dx, double dy, int ne, const double* e, double* h) {
    double t1[8], t2[16], s1[8], s2[16];
    const int n_t1 = scale_expansion(ne, e, dx, t1);
    const int n_t2 = scale_expansion(n_t1, t1, dx, t2);
    const int n_s1 = scale_expansion(ne, e, dy, s1);
    const int n_s2 = scale_expansion(n_s1, s1, dy, s2);
    return expansion_sum(n_t2, t2, n_s2, s2, h);
}

// h = (dx^2 + dy^2) * (b_x c_y - c_x b_y) exactly (<= 512 components).
int lifted_cross(const Diff& dx, const Diff& dy, const Diff& bx, const Diff& by, const Diff& cx,
                 const Diff& cy, double* h) {
    double xx[8], yy[8], lift[16], cross[16], scratch[512 + 32];
    double scratch_small[12];
    const int n_xx = expansion_product(dx.n, dx.c, dx.n, dx.c, xx, scratch_small);
    const int n_yy = expansion_product(dy.n, dy.c, dy.n, dy.c, yy, scratch_small);
    const int n_lift = expansion_sum(n_xx, xx, n_yy, yy, lift);
    const int n_cross = cross_difference(bx, cy, cx, by, cross);
    return expansion_product(n_lift, lift, n_cross, cross, h, scratch);
}

double orient2d_exact_diffs(const Point& a, const Point& b, const Point& c) {
    const Diff acx = exact_diff(a.x, c.x);
    const Diff acy = exact_diff(a.y, c.y);
    const Diff bcx = exact_diff(b.x, c.x);
    const Diff bcy = exact_diff(b.y, c.y);
    double det[16];
    const int n = cross_difference(acx, bcy, acy, bcx, det);
    return approximate(n, det);
}

double incircle_exact_diffs(const Point& a, const Point& b, const Point& c, const Point& d) {
    const Diff adx = exact_diff(a.x, d.x);
    const Diff ady = exact_diff(a.y, d.y);
    const Diff bdx = exact_diff(b.x, d.x);
    const Diff bdy = exact_diff(b.y, d.y);
    const Diff cdx = exact_diff(c.x, d.x);
    const Diff cdy = exact_diff(c.y, d.y);
    double ta[512], tb[512], tc[512], tab[1024], det[1536];
    const int n_a = lifted_cross(adx, ady, bdx, bdy, cdx, cdy, ta);
    const int n_b = lifted_cross(bdx, bdy, cdx, cdy, adx, ady, tb);
    const int n_c = lifted_cross(cdx, cdy, adx, ady, bdx, bdy, tc);
    const int n_ab = expansion_sum(n_a, ta, n_b, tb, tab);
    const int n = expansion_sum(n_ab, tab, n_c, tc, det);
    return approximate(n, det);
}

}  // namespace

// Stages B and D of orient2d; detsum is stage A's (see kOrientBoundA).
double detail::orient2d_adapt(const Point& a, const Point& b, const Point& c, double detsum) {
    const double acx = a.x - c.x;
    const double bcx = b.x - c.x;
    const double acy = a.y - c.y;
    const double bcy = b.y - c.y;

    double det_b[4];
    const int n_b = cross_difference(acx, bcy, acy, bcx, det_b);

    // Differences all exact: B is the true determinant.
    if (two_diff_tail(a.x, c.x, acx) == 0.0 && two_diff_tail(b.x, c.x, bcx) == 0.0 &&
        two_diff_tail(a.y, c.y, acy) == 0.0 && two_diff_tail(b.y, c.y, bcy) == 0.0)
        return approximate(n_b, det_b);

    // |B| >= |est| - est.error > |T - B| decides T's sign as est's.
    const Estimate est = estimate(n_b, det_b);
    if (std::abs(est.value) > widen(est.error + kOrientBoundB * detsum)) return est.value;

    return orient2d_exact_diffs(a, b, c);
}

// Stages B and D of incircle; permanent is stage A's (see kIncircleBoundA).
double detail::incircle_adapt(const Point& a, const Point& b, const Point& c, const Point& d,
                              double permanent) {
    const double adx = a.x - d.x;
    const double bdx = b.x - d.x;
    const double cdx = c.x - d.x;
    const double ady = a.y - d.y;
    const double bdy = b.y - d.y;
    const double cdy = c.y - d.y;

    double bc[4], ca[4], ab[4];
    const int n_bc = cross_difference(bdx, cdy, cdx, bdy, bc);
    const int n_ca = cross_difference(cdx, ady, adx, cdy, ca);
    const int n_ab = cross_difference(adx, bdy, bdx, ady, ab);
    double ta[32], tb[32], tc[32], tab[64], det_b[96];
    const int n_ta = lift_times(adx, ady, n_bc, bc, ta);
    const int n_tb = lift_times(bdx, bdy, n_ca, ca, tb);
    const int n_tc = lift_times(cdx, cdy, n_ab, ab, tc);
    const int n_tab = expansion_sum(n_ta, ta, n_tb, tb, tab);
    const int n_b = expansion_sum(n_tab, tab, n_tc, tc, det_b);

    if (two_diff_tail(a.x, d.x, adx) == 0.0 && two_diff_tail(b.x, d.x, bdx) == 0.0 &&
        two_diff_tail(c.x, d.x, cdx) == 0.0 && two_diff_tail(a.y, d.y, ady) == 0.0 &&
        two_diff_tail(b.y, d.y, bdy) == 0.0 && two_diff_tail(c.y, d.y, cdy) == 0.0)
        return approximate(n_b, det_b);

    const Estimate est = estimate(n_b, det_b);
    if (std::abs(est.value) > widen(est.error + kIncircleBoundB * permanent)) return est.value;

    return incircle_exact_diffs(a, b, c, d);
}

double orient2d_exact(const Point& a, const Point& b, const Point& c) {
    return orient2d_exact_diffs(a, b, c);
}

double incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
    return incircle_exact_diffs(a, b, c, d);
}

}  // namespace gpdr::geometry
