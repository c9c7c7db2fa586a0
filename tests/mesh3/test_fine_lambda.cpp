// The head-and-tail λ filter of the exact σ (src/mesh3/fine_lambda.hpp: the parameter where a
// plane meets the line of two planes, from the exact planes rounded once) against GMP rationals:
// every enclosure holds the exact λ = (c − n·x0)/(n·u) (x0, u of the line as the exact σ builds
// them), and is within a few ulps of it where the inputs are in range. Planes are built as the
// exact σ's are — normals cross products of double edges, offsets dot products with a double
// vertex (degree 2 and 3 in the input doubles, exact PlaneNumbers) — and the cases are its close
// calls: a plane nearly parallel to the line (its normal turned by 1e-13 to 1e-5 rad out of the
// plane ⟂ u), the line's planes nearly parallel to each other, a plane nearly through the line's
// point x0, magnitudes 2^±40, and out-of-range inputs (no enclosure, never a wrong one); and the
// order of two planes' λ (fine_compare) at exact and near ties.
// Planted by hand (not committed), each made these tests fail: a product's residual dropped from
// its tail (the enclosure tests and the order), fine_compare's sign not flipped when a_p and a_q
// differ in sign (the order test).
#include "mesh3/fine_lambda.hpp"
#include "rational.hpp"

#include <CGAL/FPU.h>
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

namespace {

using mesh3_test::rational;
using pendepth::mesh3::PlaneNumber;
namespace d = pendepth::mesh3::detail;

struct V {
  PlaneNumber x, y, z;
};
using D3 = std::array<double, 3>;
V lift(const D3& a) { return {a[0], a[1], a[2]}; }
V cross(const V& a, const V& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
PlaneNumber dot(const V& a, const V& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V sub(const V& a, const V& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

// A plane through the double points p, q, r: n = (q − p) × (r − p), c = n·p (exact).
struct Plane {
  V n;
  PlaneNumber c;
};
Plane through(const D3& p, const D3& q, const D3& r) {
  const V n = cross(sub(lift(q), lift(p)), sub(lift(r), lift(p)));
  return {n, dot(n, lift(p))};
}

// The line plane(f) ∩ plane(g) as the exact σ builds it: u = n_f × n_g, x0 = X / |u|².
struct Line {
  V u, x0;
};
Line line_of(const Plane& f, const Plane& g) {
  const V u = cross(f.n, g.n);
  const PlaneNumber s = PlaneNumber(1) / dot(u, u);
  const V gu = cross(g.n, u), uf = cross(u, f.n);
  return {u, {s * (f.c * gu.x + g.c * uf.x), s * (f.c * gu.y + g.c * uf.y), s * (f.c * gu.z + g.c * uf.z)}};
}
mpq_class exact_lambda(const Line& L, const Plane& p) {
  return rational(p.c - dot(p.n, L.x0)) / rational(dot(p.n, L.u));
}

struct Outcome {
  bool given = false, sharp = false;
};
// The filter's enclosure of λ for (f, g, p) holds the exact λ; given unless out of range or
// n·u = 0 (`may_refuse`: also when n·u's enclosure may hold 0).
Outcome check(const Plane& f, const Plane& g, const Plane& p, bool may_refuse = false) {
  const Line L = line_of(f, g);
  const d::FineLine fl = d::fine_line(L.u, L.x0);
  const d::FinePlane fp = d::fine_plane(p.n, p.c);
  std::optional<std::pair<double, double>> l;
  {
    CGAL::Protect_FPU_rounding<true> up;
    l = d::fine_lambda(fl, fp);
  }
  const bool parallel = is_zero(dot(p.n, L.u));
  if (parallel) EXPECT_FALSE(l.has_value());
  else if (!may_refuse) EXPECT_TRUE(l.has_value());
  if (!l) return {};
  const mpq_class x = exact_lambda(L, p);
  EXPECT_LE(mpq_class(l->first), x);
  EXPECT_GE(mpq_class(l->second), x);
  return {true, l->second - l->first <= 0x1p-50 * std::max(std::abs(l->first), std::abs(l->second))};
}

D3 rnd(std::mt19937_64& g, double s) {
  std::uniform_real_distribution<double> u(-s, s);
  return {u(g), u(g), u(g)};
}
D3 add(const D3& a, const D3& b, double t = 1) { return {a[0] + t * b[0], a[1] + t * b[1], a[2] + t * b[2]}; }
D3 crossd(const D3& a, const D3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

TEST(FineLambda, RandomPlanesAreEnclosedWithinAFewUlps) {
  std::mt19937_64 gen(17);
  int sharp = 0, n = 0;
  for (int k = 0; k < 2000; ++k) {
    const double s = std::ldexp(1.0, static_cast<int>(gen() % 81) - 40);  // 2^-40 .. 2^40
    const Plane f = through(rnd(gen, s), rnd(gen, s), rnd(gen, s)), g = through(rnd(gen, s), rnd(gen, s), rnd(gen, s)),
                p = through(rnd(gen, s), rnd(gen, s), rnd(gen, s));
    const Outcome o = check(f, g, p);
    n += 1, sharp += o.sharp;
  }
  EXPECT_EQ(sharp, n);  // a few ulps
}

// The close calls of the exact σ: p's normal nearly ⟂ u (p nearly parallel to the line), turned by
// 1e-13 .. 1e-5 rad; f and g nearly parallel; p nearly through the line's point.
TEST(FineLambda, CloseCallsAreEnclosed) {
  std::mt19937_64 gen(23);
  int sharp = 0, n = 0;
  for (int k = 0; k < 3000; ++k) {
    const double turn = std::pow(10.0, -5.0 - 8.0 * static_cast<double>(gen() % 1000) / 1000.0);
    const D3 a = rnd(gen, 1), b = rnd(gen, 1), c = rnd(gen, 1), e = rnd(gen, 1);
    const Plane f = through(a, b, c);
    Plane g = through(a, b, e), p;
    const D3 dir = add(b, a, -1);  // the line f ∩ g runs along a–b
    switch (k % 3) {
      case 0: {  // p holds a direction turned by `turn` from the line's: nearly parallel to it
        const D3 q = rnd(gen, 1), w = rnd(gen, 1);
        p = through(q, add(q, add(dir, w, turn)), add(q, crossd(dir, w)));
        break;
      }
      case 1: {  // g nearly parallel to f: e just off f's plane
        const D3 off = add(add(a, add(c, a, -1), 0.37), add(b, a, -1), 0.21);
        g = through(a, b, add(off, rnd(gen, 1), turn));
        p = through(rnd(gen, 1), rnd(gen, 1), rnd(gen, 1));
        break;
      }
      default:  // p nearly through a (a point of the line) and nearly holding the line
        p = through(add(a, rnd(gen, 1), turn), add(b, rnd(gen, 1), turn), rnd(gen, 1));
        break;
    }
    const Outcome o = check(f, g, p, true);
    n += 1, sharp += o.sharp;
  }
  EXPECT_EQ(sharp, n);  // given and a few ulps wide: the inputs carry no cancellation
}

// fine_compare: the order of two planes' λ on a line, against the exact λ — exact ties (both
// planes through a vertex of the line: the same λ exactly) and near ties (one of them through a
// point 1e-13 .. 1e-5 off that vertex): never a wrong sign; every near tie ordered; exact ties
// found equal or left undecided (the exact σ then takes the exact numbers).
TEST(FineLambda, ComparesTiesAndNearTies) {
  std::mt19937_64 gen(29);
  int near = 0, near_decided = 0, ties = 0;
  for (int k = 0; k < 3000; ++k) {
    const D3 a = rnd(gen, 1), b = rnd(gen, 1);
    const Plane f = through(a, b, rnd(gen, 1)), g = through(a, b, rnd(gen, 1));
    const double off = k % 2 ? 0.0 : std::pow(10.0, -5.0 - 8.0 * static_cast<double>(gen() % 1000) / 1000.0);
    const Plane p = through(a, rnd(gen, 1), rnd(gen, 1)), q = through(add(a, rnd(gen, 1), off), rnd(gen, 1), rnd(gen, 1));
    const Line L = line_of(f, g);
    if (is_zero(dot(p.n, L.u)) || is_zero(dot(q.n, L.u))) continue;
    const d::FineLine fl = d::fine_line(L.u, L.x0);
    const d::FinePlane fp = d::fine_plane(p.n, p.c), fq = d::fine_plane(q.n, q.c);
    std::optional<int> r;
    {
      CGAL::Protect_FPU_rounding<true> up;
      r = d::fine_compare(fl, fp, fq);
    }
    const int want = cmp(exact_lambda(L, p), exact_lambda(L, q));
    (want == 0 ? ties : near) += 1;
    if (!r) continue;
    near_decided += want != 0;
    EXPECT_EQ(*r, want < 0 ? -1 : want > 0 ? 1 : 0) << k;  // a tie: 0 (its residuals vanished) or undecided
  }
  EXPECT_EQ(near_decided, near);  // every near tie ordered (1e-13 off: far above 2⁻¹⁰⁰)
  EXPECT_GT(ties, 1000);
}

// Exactly parallel to the line: n·u = 0 — no enclosure (refused, the exact path decides).
TEST(FineLambda, ParallelPlaneIsRefused) {
  const Plane f = through({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), g = through({0, 0, 0}, {1, 0, 0}, {0, 0, 1}),
              p = through({0, 2, 3}, {1, 2, 3}, {0, 5, 7});
  EXPECT_FALSE(check(f, g, p).given);
}

// Out of range (a head above 2^200: products could overflow): no enclosure, never a wrong one.
TEST(FineLambda, OutOfRangeIsRefused) {
  const double s = 0x1p70;
  const Plane f = through({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), g = through({0, 0, 0}, {1, 0, 0}, {0, 0, 1}),
              p = through({s, s, s}, {s, 0, s}, {0, s, 2 * s});  // c ~ 2^210
  EXPECT_FALSE(d::fine_plane(p.n, p.c).ok);
  EXPECT_FALSE(check(f, g, p, true).given);
}

}  // namespace
