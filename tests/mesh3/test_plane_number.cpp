// The exact σ's number type (src/mesh3/plane_number.hpp: unreduced quotients of exact binary
// floats) against GMP rationals (mpq_class, an independent exact field): random expressions of
// the shapes the exact σ evaluates — products and sums of doubles of mixed magnitudes (plane
// normals and offsets), quotients by sums of squares (feet, line points: a shared denominator),
// differences of such quotients, quotients of those (λ on a line) — every result equal to the
// rational, every comparison and sign equal, to_interval enclosing it, to_double its nearest
// double.
#include "mesh3/plane_number.hpp"
#include "rational.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <mpfr.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using mesh3_test::rational;
using pendepth::mesh3::PlaneNumber;

double nearest(const mpq_class& q) {  // the double nearest q (one rounding)
  mpfr_t r;
  mpfr_init2(r, 53);
  mpfr_set_q(r, q.get_mpq_t(), MPFR_RNDN);
  const double d = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  return d;
}

struct Both {
  PlaneNumber p;
  mpq_class q;
};

void check(const Both& v) {
  ASSERT_EQ(rational(v.p), v.q);
  EXPECT_EQ(sign(v.p), v.q > 0 ? CGAL::POSITIVE : v.q < 0 ? CGAL::NEGATIVE : CGAL::ZERO);
  EXPECT_EQ(is_zero(v.p), v.q == 0);
  const auto [lo, hi] = to_interval(v.p);
  EXPECT_LE(mpq_class(lo), v.q);
  EXPECT_GE(mpq_class(hi), v.q);
  EXPECT_EQ(to_double(v.p), nearest(v.q));
}

TEST(PlaneNumber, EqualsRationalsOnPlaneExpressions) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> U(-1, 1);
  std::uniform_int_distribution<int> E(-30, 30), op(0, 6);
  auto leaf = [&]() -> Both {
    double x = std::ldexp(U(rng), E(rng));
    if (op(rng) == 0) x = std::round(x * 4) / 4;  // small integers and quarters: ties, zeros
    return {PlaneNumber(x), mpq_class(x)};
  };
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Both> v;
    for (int k = 0; k < 6; ++k) v.push_back(leaf());
    // A plane (n, c) and a point x0 = X / w with w = |u|² > 0 (the line point's shape).
    const Both w{v[0].p * v[0].p + v[1].p * v[1].p + PlaneNumber(1e-300), v[0].q * v[0].q + v[1].q * v[1].q + mpq_class(1e-300)};
    const Both inv{PlaneNumber(1) / w.p, mpq_class(1) / w.q};
    const Both x{inv.p * v[2].p, inv.q * v[2].q}, y{inv.p * v[3].p, inv.q * v[3].q};  // shared denominator
    const Both dotp{v[4].p * x.p + v[5].p * y.p, v[4].q * x.q + v[5].q * y.q};
    const Both b{v[1].p - dotp.p, v[1].q - dotp.q};
    const Both w2{v[4].p * v[4].p + PlaneNumber(3), v[4].q * v[4].q + 3};  // another denominator
    const Both z{v[5].p / w2.p, v[5].q / w2.q};
    std::vector<Both> all{v[0], w, inv, x, y, dotp, b, z};
    if (v[2].q - v[3].q * v[4].q != 0)  // λ = b / a
      all.push_back({b.p / (v[2].p - v[3].p * v[4].p), b.q / (v[2].q - v[3].q * v[4].q)});
    all.push_back({-b.p, -b.q});
    all.push_back({abs(b.p), abs(b.q)});
    all.push_back({square(x.p) + b.p * b.p, x.q * x.q + b.q * b.q});
    all.push_back({x.p - x.p, 0});  // exact zero through the shared-denominator path
    for (const Both& a : all) check(a);
    for (const Both& a : all)
      for (const Both& c : all) {
        EXPECT_EQ(a.p < c.p, a.q < c.q);
        EXPECT_EQ(a.p == c.p, a.q == c.q);
        EXPECT_EQ(a.p >= c.p, a.q >= c.q);
        EXPECT_EQ(compare(a.p, c.p), a.q < c.q ? CGAL::SMALLER : a.q > c.q ? CGAL::LARGER : CGAL::EQUAL);
        check({a.p + c.p, a.q + c.q});
        check({a.p - c.p, a.q - c.q});
        check({a.p * c.p, a.q * c.q});
      }
  }
}

// Denominators with one binary exponent and different odd mantissas (3, 5): not shared.
TEST(PlaneNumber, DistinctDenominatorsOfOneExponent) {
  const PlaneNumber a = PlaneNumber(1) / PlaneNumber(3), b = PlaneNumber(1) / PlaneNumber(5);
  check({a + b, mpq_class(8, 15)});
  check({a - b, mpq_class(2, 15)});
  EXPECT_TRUE(b < a);
  EXPECT_FALSE(a == b);
}

// Magnitudes far from 1 (the σ of meshes scaled by 1e±100): exact, enclosed, rounded once.
TEST(PlaneNumber, ExtremeMagnitudes) {
  for (double s : {1e-150, 1e-100, 1e100, 1e150}) {
    const PlaneNumber a(3 * s), b(7 * s), c(0.1);
    const mpq_class qa(3 * s), qb(7 * s), qc(0.1);
    check({a * b / (a + c), qa * qb / (qa + qc)});
    check({(a - b) / (b * b), (qa - qb) / (qb * qb)});
    check({c / b - c / a, qc / qb - qc / qa});
  }
}

}  // namespace
