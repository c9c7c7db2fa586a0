// The filter of the exact σ's line interval (src/mesh3/line_lambda.hpp: detail::lambda_interval,
// the core of mesh_sigma_exact.cpp's line_interval) on constructed constraints a·λ <= b (closed)
// and a·λ < b (open), against GMP rationals (mpq_class over the same input doubles: the exact
// max of λ over a < 0, min over a > 0, emptiness) and against its unfiltered tier. a and b are
// sums of products of doubles (the shape of n·u and c − n·x0), so their enclosures (Interval_nt
// on the same sums, sometimes widened by a few ulps: any enclosure is allowed) are not points.
// The inputs are the filter's hard cases: λ exactly tied between different constraints (the same
// z/x under different factors), λ a few ulps apart (enclosures overlapping the extremum),
// lo = hi exactly and nearly, a = 0 exactly with an enclosure holding 0, a nonzero of uncertain
// sign (a difference of nearly equal products) tied with the extremum, constraints holding the
// line, small integers (point enclosures: a tie touches the bound exactly), magnitudes 2^±300.
// Planted by hand (not committed), each made these tests fail: the extremum taken only over the
// enclosures certainly at the bound (`q.l.inf() >= lo_bound`: near ties dropped), and `>=` / `<=`
// of the selection made strict.
#include "mesh3/line_lambda.hpp"
#include "rational.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <vector>

namespace {

using mesh3_test::rational;
using pendepth::mesh3::PlaneNumber;
using pendepth::mesh3::detail::lambda_interval;
using I = CGAL::Interval_nt<true>;

struct Term {
  double x, y;  // x·y
};
// One constraint: a = Σ x·y, b = Σ x·y; `widen` ulps added to each end of both enclosures.
struct Constraint {
  std::vector<Term> a, b;
  bool on_line = false;  // a = b = 0 exactly (the plane holds the line)
  int widen = 0;
};

template <class T>
T eval(const std::vector<Term>& t) {
  T s(0);
  for (const auto& [x, y] : t) s = s + T(x) * T(y);
  return s;
}
I widened(const I& v, int k) {
  double lo = v.inf(), hi = v.sup();
  for (int i = 0; i < k; ++i) lo = std::nextafter(lo, -INFINITY), hi = std::nextafter(hi, INFINITY);
  return {lo, hi};
}

// The Cs of lambda_interval over the constraints.
struct Constraints {
  std::vector<Constraint> v;
  bool on_line(std::size_t p) const { return v[p].on_line; }
  I a_i(std::size_t p) const { return widened(eval<I>(v[p].a), v[p].widen); }
  I b_i(std::size_t p) const { return widened(eval<I>(v[p].b), v[p].widen); }
  PlaneNumber a_e(std::size_t p) const { return eval<PlaneNumber>(v[p].a); }
  PlaneNumber b_e(std::size_t p) const { return eval<PlaneNumber>(v[p].b); }
};

// The oracle: the same set in rationals.
struct Expected {
  bool nonempty = true;
  std::optional<mpq_class> lo, hi;
};
Expected oracle(const Constraints& cs, std::size_t first, bool strict) {
  Expected e;
  for (std::size_t p = first; p < cs.v.size(); ++p) {
    const Constraint& k = cs.v[p];
    const mpq_class a = eval<mpq_class>(k.a), b = eval<mpq_class>(k.b);
    if (k.on_line) {
      EXPECT_TRUE(a == 0 && b == 0);
      if (strict) e.nonempty = false;
      continue;
    }
    if (a == 0) {
      if (strict ? b <= 0 : b < 0) e.nonempty = false;
      continue;
    }
    const mpq_class l = b / a;
    if (a > 0 && (!e.hi || l < *e.hi)) e.hi = l;
    if (a < 0 && (!e.lo || l > *e.lo)) e.lo = l;
  }
  if (e.lo && e.hi && (strict ? *e.lo >= *e.hi : *e.lo > *e.hi)) e.nonempty = false;
  return e;
}

// Both tiers, closed and open, equal the oracle (ends compared only when nonempty).
void check(const Constraints& cs, std::size_t first = 0) {
  for (bool strict : {false, true}) {
    const Expected e = oracle(cs, first, strict);
    for (bool filtered : {true, false}) {
      SCOPED_TRACE(testing::Message() << "strict " << strict << " filtered " << filtered);
      std::optional<PlaneNumber> lo, hi;
      ASSERT_EQ(lambda_interval(cs, first, cs.v.size() - first, strict, filtered, lo, hi), e.nonempty);
      if (!e.nonempty) continue;
      ASSERT_EQ(lo.has_value(), e.lo.has_value());
      ASSERT_EQ(hi.has_value(), e.hi.has_value());
      if (lo) ASSERT_EQ(rational(*lo), *e.lo);
      if (hi) ASSERT_EQ(rational(*hi), *e.hi);
    }
  }
}

// λ = z/x on the side `s` (+1: a > 0, an upper end; −1: a < 0, a lower end), a and b scaled by
// m1 + m2 (two products each: rounded enclosures, the exact ratio unchanged).
Constraint ratio(double z, double x, int s, double m1, double m2, int widen = 0) {
  return {{{s * x, m1}, {s * x, m2}}, {{s * z, m1}, {s * z, m2}}, false, widen};
}

// λ = z/x with a = s·x·t tiny against the rounding of x·y − x·y (t << ulp(x·y)): a's enclosure
// holds 0 although a != 0 — the filter takes a's sign and λ exactly.
Constraint uncertain(double z, double x, int s, double y, double t) {
  return {{{x, y}, {-x, y}, {s * x, t}}, {{z, y}, {-z, y}, {s * z, t}}, false, 0};
}

// A hand case: the lower end's extremum λ = 1 + 2⁻⁵¹ has an enclosure reaching below the bound
// set by a point enclosure at λ = 1 (a near tie overlapping the bound); the upper end is tied
// exactly (λ = 3 twice, point enclosures touching the bound).
TEST(LineLambda, ExtremumInsideAnOverlappingEnclosure) {
  Constraints cs;
  cs.v.push_back(ratio(1, 1, -1, 1, 0));                        // λ⁻ = 1, enclosure [1, 1]
  cs.v.push_back(ratio(1 + 0x1p-51, 1, -1, 1, 0, 4));           // λ⁻ = 1 + 2u, enclosure [1 − u, 1 + 6u]
  cs.v.push_back(ratio(6, 2, 1, 1, 0));                         // λ⁺ = 3, [3, 3]
  cs.v.push_back(ratio(3, 1, 1, 0.5, 0.5));                     // λ⁺ = 3, [3, 3]
  cs.v.push_back(ratio(3 + 0x1p-50, 1, 1, 0.1, 0.7, 3));        // λ⁺ = 3 + 2u', enclosure below 3
  auto lam = [&](std::size_t p) { return cs.b_i(p) / cs.a_i(p); };  // the filter's enclosures
  EXPECT_TRUE(lam(0).is_point() && lam(1).inf() < 1 && lam(1).sup() > 1 + 0x1p-51);
  EXPECT_TRUE(lam(2).is_point() && lam(3).is_point() && lam(4).inf() < 3);
  check(cs);
}

// lo = hi exactly (closed: one point; open: empty) through exactly tied point enclosures.
TEST(LineLambda, PointIntervalOfExactTies) {
  Constraints cs;
  for (int k = 1; k <= 4; ++k) cs.v.push_back(ratio(5 * k, 2 * k, -1, 1, 0));  // λ⁻ = 2.5, exact
  for (int k = 1; k <= 4; ++k) cs.v.push_back(ratio(5 * k, 2 * k, 1, 0.25, 0.75));  // λ⁺ = 2.5
  check(cs);
}

// a = 0 exactly with an enclosure holding 0 (b of every sign), a nonzero of uncertain sign tied
// with the extremum, a constraint holding the line, and a first constraint outside the range.
TEST(LineLambda, ZeroAndUncertainSigns) {
  const double x = 0.1, y = 0.3, t = 0x1p-80;
  for (double bsign : {1.0, 0.0, -1.0}) {
    Constraints cs;
    cs.v.push_back({{{0, 1}}, {{-1, 1}}, false, 0});                       // a = 0, b < 0: outside the range
    cs.v.push_back({{{x, y}, {-x, y}}, {{bsign * 0.7, 0.3}}, false, 0});   // a = 0 exactly, enclosure ∋ 0
    cs.v.push_back(uncertain(0.7, x, -1, y, t));                           // a < 0 tiny, sign uncertain
    cs.v.push_back(ratio(0.7, 0.1, -1, 3, 0.3));                           // λ⁻ = 0.7/0.1 (tied)
    cs.v.push_back(ratio(0.7, 0.1, 1, 0.3, 3, 2));                         // λ⁺ = 0.7/0.1
    for (std::size_t p : {1, 2}) EXPECT_TRUE(cs.a_i(p).inf() < 0 && cs.a_i(p).sup() > 0);  // the exact path
    check(cs, 1);
    cs.v.push_back({{{x, y}, {-x, y}}, {{0.7, 0.3}, {-0.7, 0.3}}, true, 0});  // holds the line
    check(cs, 1);
  }
}

// Random cases built around a lower and an upper target: exact ties, near ties (a few ulps),
// far constraints, the target pair equal, a few ulps apart or far, all at random magnitudes.
TEST(LineLambda, RandomNearTiesEqualRationals) {
  std::mt19937_64 rng(1727);
  std::uniform_real_distribution<double> U(0.5, 1);
  std::uniform_int_distribution<int> kind(0, 9), ulps(-3, 3), wid(0, 3), cnt(2, 8), sgn(0, 1), mag(0, 2);
  auto nudge = [](double v, int k) {
    for (; k > 0; --k) v = std::nextafter(v, INFINITY);
    for (; k < 0; ++k) v = std::nextafter(v, -INFINITY);
    return v;
  };
  auto scale = [&] {  // 1, or 2^±300 (huge / tiny planes), or a non-power-of-two around 1e±30
    const int m = mag(rng);
    return m == 0 ? 1.0 : m == 1 ? std::ldexp(1.0, sgn(rng) ? 300 : -300) : U(rng) * (sgn(rng) ? 1e30 : 1e-30);
  };
  auto scale_of = [&](bool dyadic) { return dyadic ? std::ldexp(1.0, sgn(rng) ? 300 : -300) : scale(); };
  for (int trial = 0; trial < 3000; ++trial) {
    const double lam_scale = std::ldexp(1.0, std::uniform_int_distribution<int>(-40, 40)(rng));
    // A quarter of the trials on dyadic inputs (exact products and quotients: point
    // enclosures, a tie at the extremum touches the certain bound exactly).
    const bool dyadic = trial % 4 == 0;
    auto draw = [&] { return dyadic ? std::ldexp(1.0, -mag(rng)) : U(rng); };
    const double xl = draw(), zl = (sgn(rng) ? 1 : -1) * (dyadic ? cnt(rng) : U(rng)) * lam_scale;
    double xh = draw(), zh;
    switch (kind(rng) % 3) {
      case 0: xh = 2 * xl, zh = 2 * zl; break;  // hi = lo exactly, another a
      case 1: xh = xl, zh = nudge(zl, ulps(rng)); break;  // hi − lo a few ulps
      default: zh = zl + std::abs(zl) * U(rng) * (sgn(rng) ? 1 : -0.01); break;
    }
    Constraints cs;
    auto add_side = [&](double z, double x, int s) {
      const int n = cnt(rng);
      for (int k = 0; k < n; ++k) {
        const double m = scale_of(dyadic);
        double zk = z, xk = x;
        switch (kind(rng)) {
          case 0: case 1: case 2: break;                    // exactly tied
          case 3: case 4: zk = nudge(z, ulps(rng)); break;  // near tie
          case 5: xk = nudge(x, ulps(rng)); break;          // near tie through a
          case 6:  // tied, a of uncertain sign
            cs.v.push_back(uncertain(z, x, s, U(rng) * m, 0x1p-80 * m));
            continue;
          case 7: {  // a = 0 exactly, b > 0 (no constraint) or rarely b <= 0
            const double y = U(rng) * m, b = kind(rng) == 0 ? -U(rng) : U(rng);
            cs.v.push_back({{{x, y}, {-x, y}}, {{b, m}}, false, 0});
            continue;
          }
          case 8: zk = z + s * std::abs(z) * U(rng); break;  // far inside
          default:                                             // holds the line, rarely
            if (kind(rng) == 0) {
              cs.v.push_back({{{x, m}, {-x, m}}, {{z, m}, {-z, m}}, true, 0});
              continue;
            }
        }
        const double m1 = draw() * m;
        cs.v.push_back(ratio(zk, xk, s, m1, sgn(rng) ? 0.0 : draw() * m, dyadic ? 0 : wid(rng)));
      }
    };
    add_side(zl, xl, -1);
    add_side(zh, xh, 1);
    std::shuffle(cs.v.begin(), cs.v.end(), rng);
    SCOPED_TRACE(trial);
    check(cs);
    if (HasFatalFailure()) return;
  }
}

}  // namespace
