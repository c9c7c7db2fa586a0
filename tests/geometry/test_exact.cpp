// The tiers of src/geometry/exact.hpp, in particular the expansion tier Ex, against exact
// rationals (GMP) on random polynomials of the shapes the library evaluates (sums of products of
// differences of input doubles), with exact zeros built in, mixed magnitudes, and the cases where
// Ex must give up (underflowing products, overflow, too many components) and the rational tier
// takes over. Pinned seeds.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "geometry/exact.hpp"

namespace ex = pendepth::exact;

namespace {

// A random double of the kind found in real data: integers, decimals (not exact in binary),
// values at many scales, and near neighbours of each other (to make cancellation likely).
double random_double(std::mt19937_64& rng, int kind) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> small(-1000, 1000), expo(-60, 60);
  switch (kind % 4) {
    case 0:
      return small(rng);
    case 1:
      return small(rng) / 10.0;
    case 2:
      return std::ldexp(u(rng), expo(rng));
    default:
      return 1e6 + small(rng) * 0.1;
  }
}

}  // namespace

// cross(b − a, d − c)·(e − f) + (g + h)·(a − e) − (b − g)·(c + h)·(d − f), its Ex value and sign
// against GMP, and the same value minus itself rearranged (an exact zero by construction).
TEST(Exact, ExpansionTierMatchesRationals) {
  std::mt19937_64 rng(20261121);
  int zeros = 0, checked = 0, gave_up = 0;
  for (int it = 0; it < 20000; ++it) {
    double v[8];
    const int kind = it % 5;
    for (double& x : v) x = random_double(rng, kind == 4 ? static_cast<int>(rng() % 4) : kind);
    auto f = [&](auto L) {
      auto a = L(v[0]), b = L(v[1]), c = L(v[2]), d = L(v[3]), e = L(v[4]), g = L(v[6]), h = L(v[7]), ff = L(v[5]);
      return ((b - a) * (L(v[3]) - c) - (L(v[1]) - L(v[0])) * (d + c)) * (e - ff) + (g + h) * (a - e) - (b - g) * (c + h) * (d - ff);
    };
    // The same polynomial expanded differently: f − f2 is exactly zero.
    auto f2 = [&](auto L) {
      auto a = L(v[0]), b = L(v[1]), c = L(v[2]), d = L(v[3]), e = L(v[4]), g = L(v[6]), h = L(v[7]), ff = L(v[5]);
      return (b - a) * (d - c) * e - (b - a) * (d - c) * ff - (b - a) * (d + c) * e + (b - a) * (d + c) * ff + g * a - g * e + h * a -
             h * e - (b * c * d - b * c * ff + b * h * d - b * h * ff - g * c * d + g * c * ff - g * h * d + g * h * ff);
    };
    const mpq_class q = f(ex::LiftQ{}).v;
    const ex::Ex e = f(ex::LiftEx{});
    if (!e.ok) {
      ++gave_up;
    } else {
      ASSERT_EQ(ex::ex_sign(e), sgn(q)) << it;
      const double want = q.get_d();
      const double got = ex::ex_value(e);
      ASSERT_LE(std::abs(got - want), std::abs(want) * 0x1p-51) << it;
      ++checked;
    }
    const ex::Ex z = [&] {
      auto d = [&](auto L) { return f(L) - f2(L); };
      return d(ex::LiftEx{});
    }();
    if (z.ok) {
      ASSERT_EQ(ex::ex_sign(z), 0) << it;
      ++zeros;
    }
    ASSERT_EQ(ex::exact_sign([&](auto L) { return f(L) - f2(L); }), 0) << it;
    ASSERT_EQ(ex::exact_sign(f), sgn(q)) << it;
  }
  EXPECT_GT(checked, 19000);
  EXPECT_GT(zeros, 19000);
  std::cout << "Ex: " << checked << " values and " << zeros << " exact zeros match GMP; gave up " << gave_up << "\n";
}

// Near-degenerate orientation of points on a line with decimal coordinates: the Fl and DD
// tiers cannot certify these zeros, the expansion tier must.
TEST(Exact, CollinearDecimalPointsAreExactZeros) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> k(-500, 500);
  for (int it = 0; it < 5000; ++it) {
    // p, p + t·w, p + s·w with t, s small integers: exactly collinear only if each coordinate is
    // exact, so build points whose coordinates are exact doubles by construction.
    const double px = k(rng) * 0.1, py = k(rng) * 0.1, wx = k(rng) * 0.25, wy = k(rng) * 0.25;
    const double ax = px + wx, ay = py + wy, bx = px + 2 * wx, by = py + 2 * wy;
    auto orient = [&](auto L) { return (L(ax) - L(px)) * (L(by) - L(py)) - (L(ay) - L(py)) * (L(bx) - L(px)); };
    const mpq_class q = orient(ex::LiftQ{}).v;
    const ex::Ex e = orient(ex::LiftEx{});
    ASSERT_TRUE(e.ok);
    ASSERT_EQ(ex::ex_sign(e), sgn(q)) << it;
    ASSERT_EQ(ex::exact_sign(orient), sgn(q)) << it;
  }
}

// Where Ex must give up: a product whose error term would be subnormal, an overflow, and a value
// spread over more than Ex::kCap components. exact_sign still answers exactly (rationals).
TEST(Exact, ExpansionGivesUpAndRationalsTakeOver) {
  {
    // The product is 2^-1100·(1 + 2^-52), below the smallest subnormal 2^-1074 (which is what it
    // is compared with): its rounding error cannot be represented.
    auto f = [](auto L) { return L(0x1p-600) * L(0x1.0000000000001p-500) - L(0x1p-1074); };
    EXPECT_FALSE(f(ex::LiftEx{}).ok);
    EXPECT_EQ(sgn(f(ex::LiftQ{}).v), -1);
    EXPECT_EQ(ex::exact_sign(f), -1);
  }
  {
    auto f = [](auto L) { return L(0x1p600) * L(0x1p600) - L(1.0); };
    EXPECT_FALSE(f(ex::LiftEx{}).ok);
  }
  {
    // x = Σ 2^(60k − 900), k = 0..30: 31 components 60 bits apart (none merge); x·(1/3) needs up
    // to 62 components before compression, more than Ex::kCap.
    auto x = [](auto L) {
      auto s = L(std::ldexp(1.0, -900));
      for (int k = 1; k <= 30; ++k) s = s + L(std::ldexp(1.0, 60 * k - 900));
      return s;
    };
    EXPECT_TRUE(x(ex::LiftEx{}).ok);
    EXPECT_EQ(x(ex::LiftEx{}).n, 31);
    auto f = [&](auto L) { return x(L) * L(1.0 / 3.0) - L(1.0); };
    EXPECT_FALSE(f(ex::LiftEx{}).ok);
    EXPECT_EQ(ex::exact_sign(f), 1);
    EXPECT_EQ(ex::exact_sign([&](auto L) { return x(L) * L(1.0 / 3.0) * L(3.0) - x(L) * L(3.0) * L(1.0 / 3.0); }), 0);
  }
  {
    // accurate_value and accurate_ratio of an exact zero and of a cancellation.
    const double a = 0.1, b = 0.2, c = 0.3;
    EXPECT_EQ(ex::accurate_value([&](auto L) { return (L(a) + L(b)) * L(c) - L(a) * L(c) - L(b) * L(c); }), 0.0);
    const double r = ex::accurate_ratio([&](auto L) { return L(a) + L(b) - L(c); }, [&](auto L) { return L(1.0) + L(0.0); });
    EXPECT_EQ(r, mpq_class(mpq_class(a) + mpq_class(b) - mpq_class(c)).get_d());
  }
}

// sign_ab_minus_cd (exact products by rounding monotonicity and FMA errors) against GMP: random
// doubles of every kind, products made equal on purpose (a·b = c·d exactly, and equal roundings
// of different products: ties the filter alone cannot order), zeros, products near underflow and
// overflow (where it must answer 2 or the true sign, never a wrong one); and the FlX overload
// answers 2 unless all four operands are exact.
TEST(Exact, SignOfExactProductDifference) {
  std::mt19937_64 rng(8811);
  auto sgn = [](const mpq_class& q) { return (q > 0) - (q < 0); };
  auto check = [&](double a, double b, double c, double d) {
    const int s = ex::sign_ab_minus_cd(a, b, c, d);
    const int truth = sgn(mpq_class(a) * b - mpq_class(c) * d);
    if (std::isfinite(a * b) && std::isfinite(c * d) && std::abs(a * b) >= 0x1p-900 && std::abs(c * d) >= 0x1p-900) {
      EXPECT_NE(s, 2) << a << " " << b << " " << c << " " << d;
    }
    if (s != 2) {
      EXPECT_EQ(s, truth) << a << " " << b << " " << c << " " << d;
    }
    return s;
  };
  int ties = 0, decided_ties = 0;
  for (int it = 0; it < 200000; ++it) {
    const double a = random_double(rng, int(rng() % 4)), b = random_double(rng, int(rng() % 4));
    double c = random_double(rng, int(rng() % 4)), d = random_double(rng, int(rng() % 4));
    switch (it % 5) {
      case 0:  // the same product, factors swapped or scaled by powers of two
        c = std::ldexp(b, 3), d = std::ldexp(a, -3);
        break;
      case 1:  // neighbours: equal roundings of different exact products are likely
        c = std::nextafter(a, INFINITY), d = b;
        break;
      case 2:
        c = a, d = std::nextafter(b, -INFINITY);
        break;
      default:
        break;
    }
    if (a * b == c * d) {
      ++ties;
      decided_ties += check(a, b, c, d) != 2;
    } else {
      check(a, b, c, d);
    }
  }
  EXPECT_GT(ties, 40000);
  EXPECT_GT(decided_ties, ties * 9 / 10);
  // Zeros, underflow and overflow.
  check(0, 5, 0, -3);
  check(0, 5, 1, -3);
  EXPECT_EQ(check(0x1p-600, 0x1p-500, 0x1p-600, 0x1.0000000000001p-500), 2);  // errors below 2⁻¹⁰⁷⁴
  EXPECT_EQ(check(0x1p600, 0x1p500, 1, 1), 2);                                // overflow
  check(0x1p-500, 0x1p-500, 0, 1);
  // FlX operands: inexact ones leave it undecided.
  const ex::FlX e3{3, true}, e5{5, true}, i3{3, false};
  EXPECT_EQ(ex::sign_ab_minus_cd(e3, e5, e5, e3), 0);
  EXPECT_EQ(ex::sign_ab_minus_cd(e3, e5, e5, i3), 2);
}

// exact_sign_tie_likely (exact doubles first) agrees with GMP on cross products of differences of
// random doubles of every kind: exact zeros (collinear by construction), near-zeros, inexact
// decimal data that must fall through to the later tiers.
TEST(Exact, TieLikelySignMatchesRationals) {
  std::mt19937_64 rng(9090);
  int zeros = 0;
  for (int it = 0; it < 100000; ++it) {
    const int kind = int(rng() % 4);
    const double ax = random_double(rng, kind), ay = random_double(rng, kind), bx = random_double(rng, kind), by = random_double(rng, kind);
    double cx = random_double(rng, kind), cy = random_double(rng, kind);
    if (it % 3 == 0) cx = ax + 2 * (bx - ax), cy = ay + 2 * (by - ay);  // on the line when that rounds exactly
    auto f = [&](auto L) { return (L(bx) - L(ax)) * (L(cy) - L(ay)) - (L(by) - L(ay)) * (L(cx) - L(ax)); };
    const mpq_class q = (mpq_class(bx) - ax) * (mpq_class(cy) - ay) - (mpq_class(by) - ay) * (mpq_class(cx) - ax);
    const int truth = (q > 0) - (q < 0);
    zeros += truth == 0;
    ASSERT_EQ(ex::exact_sign_tie_likely(f), truth) << it;
    ASSERT_EQ(ex::exact_sign(f), truth) << it;
  }
  EXPECT_GT(zeros, 10000);
}

// accurate_ratio_of (numerator and denominator from one formula) gives accurate_ratio's double bit
// for bit, through every tier: generic values (double-double tier), exact zeros of the numerator
// and heavy cancellation (expansions), overflowing products (rationals), on a degree-3-over-2
// formula like the queries' (a point on a line through a sum of doubles, over a squared norm).
TEST(Exact, AccurateRatioOfMatchesAccurateRatio) {
  std::mt19937_64 rng(19019);
  std::uniform_real_distribution<double> u(-100, 100);
  auto f = [](const double* x) {
    return [x](auto L) {
      auto dx = L(x[0]) + L(x[1]) - L(x[2]), dy = L(x[3]) - L(x[4]);
      auto num = (L(x[5]) - L(x[6])) * dx * dy + L(x[7]) * dy * dy - L(x[8]) * dx;
      auto den = dx * dx + dy * dy;
      return std::pair{num, den};
    };
  };
  int tested = 0;
  for (int it = 0; it < 20000; ++it) {
    double x[9];
    for (double& v : x) v = u(rng);
    const int kind = it % 5;
    if (kind == 1) x[8] = 0, x[6] = x[5], x[7] = 0;                 // numerator exactly 0
    if (kind == 2) x[5] = 0.1, x[6] = 0.1 + 0x1p-40, x[8] = 1e-300;  // cancellation, a tiny term
    if (kind == 3) x[0] *= 0x1p500, x[1] *= 0x1p500;                // products beyond the double range
    if (kind == 4) x[1] = -x[0] + 0x1p-30, x[2] = 0x1p-30, x[4] = x[3] + 1e-3;  // dx exactly 0
    const auto g = f(x);
    bool zero_den = false;
    try {
      zero_den = ex::exact_sign([&](auto L) { return g(L).second; }) == 0;
    } catch (...) {
    }
    if (zero_den) continue;
    const double want = ex::accurate_ratio([&](auto L) { return g(L).first; }, [&](auto L) { return g(L).second; });
    const double got = ex::accurate_ratio_of(g);
    ASSERT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(want)) << "case " << it << " kind " << kind;
    ++tested;
  }
  EXPECT_GT(tested, 15000);
}
