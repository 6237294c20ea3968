// crossing_point(), correctly rounded through expansion arithmetic (see
// crossing.hpp).  Named predicates_* so that it is compiled, as the
// predicates are, without fused multiply-adds (expansion.hpp).
//
// With oa = orient(c, d, a) and ob = orient(c, d, b), the lines meet at
// a + oa / (oa - ob) (b - a), whose coordinates are the rationals
//   x = (oa b.x - ob a.x) / (oa - ob),   y = (oa b.y - ob a.y) / (oa - ob).
// Numerator N and denominator D are exact expansions.  A first guess q
// (their approximate quotient) is within a few ulps; it is then moved one
// ulp at a time until the exact value lies between the midpoints to q's
// neighbours: the sign of x - m for a midpoint m = (q + q') / 2 is the sign
// of (2N - (q + q') D) / D, an expansion again.

#include <cmath>
#include <limits>

#include "geometry/crossing.hpp"
#include "geometry/expansion.hpp"

namespace gpdr::geometry {
namespace {

using namespace exact;

// An expansion in a fixed buffer (large enough for everything below).
struct Expansion {
    double c[256];
    int n = 0;
};

int sign(const Expansion& e) { return e.n == 0 ? 0 : (e.c[e.n - 1] > 0 ? 1 : -1); }

// orient(p, q, r) exactly: (p.x - r.x)(q.y - r.y) - (p.y - r.y)(q.x - r.x).
Expansion orient(const Point& p, const Point& q, const Point& r) {
    Expansion e;
    e.n = cross_difference(exact_diff(p.x, r.x), exact_diff(q.y, r.y), exact_diff(p.y, r.y),
                           exact_diff(q.x, r.x), e.c);
    return e;
}

// s * e + t * f exactly.
Expansion combine(const Expansion& e, double s, const Expansion& f, double t) {
    Expansion se, tf, out;
    se.n = scale_expansion(e.n, e.c, s, se.c);
    tf.n = scale_expansion(f.n, f.c, t, tf.c);
    out.n = expansion_sum(se.n, se.c, tf.n, tf.c, out.c);
    return out;
}

// The sign of n / d - (q + r) / 2, for doubles q, r.
int compare_with_midpoint(const Expansion& two_n, const Expansion& d, double q, double r) {
    Expansion qd, rd, sum, diff;
    qd.n = scale_expansion(d.n, d.c, q, qd.c);
    rd.n = scale_expansion(d.n, d.c, r, rd.c);
    sum.n = expansion_sum(qd.n, qd.c, rd.n, rd.c, sum.c);
    negate(sum.n, sum.c);
    diff.n = expansion_sum(two_n.n, two_n.c, sum.n, sum.c, diff.c);
    return sign(diff) * sign(d);
}

bool even(double q) {
    int exponent = 0;
    const double m = std::frexp(q, &exponent);  // q = m 2^e, 0.5 <= |m| < 1: 53 bits
    const double scaled = std::ldexp(m, 53);
    return std::fmod(scaled, 2.0) == 0;
}

// n / d correctly rounded (d != 0).
double rounded_quotient(const Expansion& n, const Expansion& d) {
    if (n.n == 0) return 0.0;
    Expansion two_n;
    two_n.n = scale_expansion(n.n, n.c, 2.0, two_n.c);
    double q = approximate(n.n, n.c) / approximate(d.n, d.c);
    constexpr double inf = std::numeric_limits<double>::infinity();
    // The guess is within a few ulps; the bound only guards against a bug.
    for (int step = 0; step < 64; ++step) {
        const double up = std::nextafter(q, inf), down = std::nextafter(q, -inf);
        const int above = compare_with_midpoint(two_n, d, q, up);
        if (above > 0) {
            q = up;
            continue;
        }
        if (above == 0) return even(q) ? q : up;
        const int below = compare_with_midpoint(two_n, d, down, q);
        if (below < 0) {
            q = down;
            continue;
        }
        if (below == 0) return even(q) ? q : down;
        break;
    }
    return q;
}

}  // namespace

Point crossing_point(const Point& a, const Point& b, const Point& c, const Point& d) {
    const Expansion oa = orient(c, d, a);
    Expansion ob = orient(c, d, b);
    Expansion denominator;
    {
        Expansion minus_ob = ob;
        negate(minus_ob.n, minus_ob.c);
        denominator.n = expansion_sum(oa.n, oa.c, minus_ob.n, minus_ob.c, denominator.c);
    }
    const Expansion x = combine(oa, b.x, ob, -a.x);
    const Expansion y = combine(oa, b.y, ob, -a.y);
    return {rounded_quotient(x, denominator), rounded_quotient(y, denominator)};
}

}  // namespace gpdr::geometry
