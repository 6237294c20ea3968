#pragma once
// Error-free floating-point transformations and arithmetic on expansions,
// following Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast
// Robust Geometric Predicates" (DCG 18, 1997), sections 2.3-2.8.  Written from
// the paper's mathematics.
//
// INCLUDE THIS HEADER ONLY FROM predicates*.cpp: those files are compiled with
// -ffp-contract=off.  A fused multiply-add turns `x - a*b` into one rounding
// and silently breaks every identity below.
//
// Vocabulary (from the paper).  An expansion is an array of doubles e[0..n)
// whose exact sum is the value it represents.  Components are nonoverlapping
// (the lowest set bit of e[i+1] lies above the highest set bit of e[i]),
// ordered by increasing magnitude, and, after "zero elimination", nonzero; a
// length of 0 represents the value 0.  All routines assume IEEE double
// arithmetic rounding to nearest, ties to even (the x86-64/SSE2 default), and
// no overflow or underflow.
//
// Facts used (the paper's theorems):
//  * two_sum / two_diff / two_product return (x, y) with x = fl(x op y) and
//    x + y exact; with ties-to-even the pair is nonadjacent, hence strongly
//    nonoverlapping.
//  * expansion_sum of two strongly nonoverlapping expansions is a strongly
//    nonoverlapping expansion of the exact sum (Fast-Expansion-Sum, Thm 13).
//  * scale_expansion of a strongly nonoverlapping expansion by a double is a
//    strongly nonoverlapping expansion of the exact product (Thm 19).
//  * For any nonoverlapping expansion, sum_{i<n-1} |e[i]| < lowest set bit of
//    e[n-1] <= |e[n-1]| (induction on the nonoverlapping property), so the
//    sign of a nonzero expansion is the sign of its largest component.

#include <cmath>
#include <cstdlib>

namespace gpdr::geometry::exact {

// u: the unit roundoff, half an ulp of 1 (Shewchuk's epsilon).
inline constexpr double kUnitRoundoff = 0x1p-53;

// 2^27 + 1: Dekker/Veltkamp split of a 53-bit significand into two halves of
// at most 26 bits each (one sign bit absorbs the 53rd), so that products of
// halves are exact.
inline constexpr double kSplitter = 0x1p27 + 1.0;

// x + y == a + b exactly, x = fl(a + b).  Knuth's branch-free form.
inline void two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    const double b_virtual = x - a;
    const double a_virtual = x - b_virtual;
    const double b_round = b - b_virtual;
    const double a_round = a - a_virtual;
    y = a_round + b_round;
}

// The same when |a| >= |b| (or a == 0): Dekker's cheaper form.
inline void fast_two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    y = b - (x - a);
}

// The rounding error of x = fl(a - b): (a - b) - x, exactly.
inline double two_diff_tail(double a, double b, double x) {
    const double b_virtual = a - x;
    const double a_virtual = x + b_virtual;
    const double b_round = b_virtual - b;
    const double a_round = a - a_virtual;
    return a_round + b_round;
}

inline void two_diff(double a, double b, double& x, double& y) {
    x = a - b;
    y = two_diff_tail(a, b, x);
}

// a == hi + lo exactly, each half fitting in 26 bits.
inline void split(double a, double& hi, double& lo) {
    const double c = kSplitter * a;
    const double a_big = c - a;
    hi = c - a_big;
    lo = a - hi;
}

// x + y == a * b exactly, x = fl(a * b) (Dekker's product: the four partial
// products of the halves are exact and are subtracted from x largest first).
inline void two_product(double a, double b, double& x, double& y) {
    x = a * b;
    double a_hi, a_lo, b_hi, b_lo;
    split(a, a_hi, a_lo);
    split(b, b_hi, b_lo);
    const double err1 = x - a_hi * b_hi;
    const double err2 = err1 - a_lo * b_hi;
    const double err3 = err2 - a_hi * b_lo;
    y = a_lo * b_lo - err3;
}

// The expansion (tail, head) of a two_sum/two_diff/two_product result, with
// zero elimination.  Returns its length.
inline int make_pair(double head, double tail, double* h) {
    int n = 0;
    if (tail != 0.0) h[n++] = tail;
    if (head != 0.0) h[n++] = head;
    return n;
}

// h = e + f (Fast-Expansion-Sum with zero elimination): merge the components
// by increasing magnitude into g, then carry a running sum Q through g, each
// step emitting the rounding error as an output component.  h may not alias
// e or f.  Returns the length of h (<= ne + nf).
inline int expansion_sum(int ne, const double* e, int nf, const double* f, double* h) {
    if (ne == 0) {
        for (int i = 0; i < nf; ++i) h[i] = f[i];
        return nf;
    }
    if (nf == 0) {
        for (int i = 0; i < ne; ++i) h[i] = e[i];
        return ne;
    }
    int i = 0;
    int j = 0;
    // next(): the merged component of smaller magnitude.
    auto next = [&]() {
        if (j >= nf || (i < ne && std::abs(e[i]) < std::abs(f[j]))) return e[i++];
        return f[j++];
    };
    int n = 0;
    double q = next();
    double g = next();
    double x, y;
    fast_two_sum(g, q, x, y);  // |g| >= |q| by the merge order
    q = x;
    if (y != 0.0) h[n++] = y;
    while (i < ne || j < nf) {
        g = next();
        two_sum(q, g, x, y);
        q = x;
        if (y != 0.0) h[n++] = y;
    }
    if (q != 0.0) h[n++] = q;
    return n;
}

// h = b * e (Scale-Expansion with zero elimination).  h may not alias e.
// Returns the length of h (<= 2 ne).
inline int scale_expansion(int ne, const double* e, double b, double* h) {
    if (ne == 0 || b == 0.0) return 0;
    int n = 0;
    double q, y;
    two_product(e[0], b, q, y);
    if (y != 0.0) h[n++] = y;
    for (int i = 1; i < ne; ++i) {
        double p_hi, p_lo;
        two_product(e[i], b, p_hi, p_lo);
        double s, s_err;
        two_sum(q, p_lo, s, s_err);
        if (s_err != 0.0) h[n++] = s_err;
        double t, t_err;
        fast_two_sum(p_hi, s, t, t_err);  // |p_hi| >= |s| (paper, Thm 19)
        if (t_err != 0.0) h[n++] = t_err;
        q = t;
    }
    if (q != 0.0) h[n++] = q;
    return n;
}

// h = e * f: the sum over the components of f of the scaled copies of e.
// h must hold 2 ne nf components; scratch must hold 2 ne nf + 2 ne.
inline int expansion_product(int ne, const double* e, int nf, const double* f, double* h,
                             double* scratch) {
    double* scaled = scratch;
    double* acc = scratch + 2 * ne;
    // The running total alternates between acc and h (a sum may not write
    // over its input); it is copied into h at the end if it finished in acc.
    int n = 0;
    double* cur = acc;
    double* other = h;
    for (int k = 0; k < nf; ++k) {
        const int ns = scale_expansion(ne, e, f[k], scaled);
        n = expansion_sum(n, cur, ns, scaled, other);
        double* tmp = cur;
        cur = other;
        other = tmp;
    }
    if (cur != h)
        for (int k = 0; k < n; ++k) h[k] = cur[k];
    return n;
}

inline void negate(int n, double* e) {
    for (int i = 0; i < n; ++i) e[i] = -e[i];
}

// An approximation of an expansion's value with a rigorous error bound:
// |sum(e) - value| <= error.
//
// value is the recursive sum from the smallest component up.  Let r be the
// exact sum of all but the top component t and r^ its computed sum: the
// textbook bound for recursive summation gives |r - r^| <= gamma_{n-2} *
// sum_{i<n-1} |e[i]| < gamma_{n-2} |t| (nonoverlapping, see above), and the
// last addition value = fl(t + r^) errs by at most u |value|.  With
// gamma_k = k u / (1 - k u) <= 1.01 k u for k u < 0.0099 (n stays below a few
// thousand here) and the roundings of this very formula and of the constant
// 1.02 u (4 roundings of nonnegative numbers, far below 1% together) absorbed
// by the factor 1.02:
// error = 1.02 (n u |t| + u |value|).
struct Estimate {
    double value;
    double error;
};

inline Estimate estimate(int n, const double* e) {
    if (n == 0) return {0.0, 0.0};
    double value = e[0];
    for (int i = 1; i < n; ++i) value += e[i];
    const double bound =
        (static_cast<double>(n) * std::abs(e[n - 1]) + std::abs(value)) * (1.02 * kUnitRoundoff);
    return {value, bound};
}

// A double with exactly the sign of the expansion and, unless the expansion's
// estimate is too uncertain, its approximate magnitude.
inline double approximate(int n, const double* e) {
    if (n <= 0) return 0.0;
    const Estimate est = estimate(n, e);
    if (std::abs(est.value) > est.error) return est.value;
    return e[n - 1];  // the sign of a nonzero expansion is that of its top
}

// x * (1 + 8u), rounded: at least x_exact whenever x was computed from
// nonnegative exact quantities by at most 6 roundings, since
// (1 - u)^7 (1 + 8u) >= (1 - 7u)(1 + 8u) = 1 + u - 56u^2 > 1.
inline double widen(double x) { return x * (1.0 + 8.0 * kUnitRoundoff); }

// An exact coordinate difference a - b as an expansion of <= 2 components.
struct Diff {
    double c[2];
    int n;
};

inline Diff exact_diff(double a, double b) {
    Diff d{};
    double x, y;
    two_diff(a, b, x, y);
    d.n = make_pair(x, y, d.c);
    return d;
}

// h = a b - c d exactly for exact differences (<= 16 components).
inline int cross_difference(const Diff& a, const Diff& b, const Diff& c, const Diff& d, double* h) {
    double p[8], q[8], scratch[12];
    const int np = expansion_product(a.n, a.c, b.n, b.c, p, scratch);
    const int nq = expansion_product(c.n, c.c, d.n, d.c, q, scratch);
    negate(nq, q);
    return expansion_sum(np, p, nq, q, h);
}

}  // namespace gpdr::geometry::exact
