// Private: filtered exact evaluation of polynomials in the input doubles.
//
// A formula is written once as a generic lambda `f(c)` where `c(x)` lifts an input double into
// the number type. It is evaluated first with `Fl` (double value + rigorous forward error bound),
// and only when the bound cannot decide with `mpq_class` (exact rationals; mpq_set_d is exact).
//   exact_sign(f)      : exact sign of the polynomial
//   accurate_value(f)  : the value to within ~1 ulp (relative), exact fallback when needed
#pragma once

#include <cmath>
#include <cstdint>
#include <gmpxx.h>

namespace pendepth::exact {

inline constexpr double kUnit = 0x1p-53;       // unit roundoff
inline constexpr double kTiny = 0x1p-1000;     // absolute slack covering underflow in products

/// Double with an absolute error bound: |exact - v| <= e for the real-number formula.
/// e == 0 means every operation so far was exact (checked with TwoSum / FMA), so v is the exact
/// value and even a zero sign is certified without the rational fallback — the common case for
/// integer-like coordinates, where degenerate (zero) predicates are frequent.
struct Fl {
  double v = 0, e = 0;
};
inline constexpr double kExactFloor = 0x1p-960;  // below this a product's error may be unrepresentable
inline Fl operator+(Fl a, Fl b) {
  double v = a.v + b.v;
  if (a.e == 0 && b.e == 0) {
    double bv = v - a.v, av = v - bv;
    if ((a.v - av) + (b.v - bv) == 0) return {v, 0};
  }
  return {v, a.e + b.e + std::abs(v) * kUnit};
}
inline Fl operator-(Fl a, Fl b) { return a + Fl{-b.v, b.e}; }
inline Fl operator*(Fl a, Fl b) {
  double v = a.v * b.v;
  if (a.e == 0 && b.e == 0 && (std::abs(v) > kExactFloor || a.v == 0 || b.v == 0) &&
      std::fma(a.v, b.v, -v) == 0)
    return {v, 0};
  return {v, std::abs(a.v) * b.e + std::abs(b.v) * a.e + a.e * b.e + std::abs(v) * kUnit + kTiny};
}
inline Fl operator-(Fl a) { return {-a.v, a.e}; }

/// Exact rational evaluated eagerly (gmpxx's expression templates would dangle when returned
/// from the generic formula lambdas).
struct Rat {
  mpq_class v;
};
inline Rat operator+(const Rat& a, const Rat& b) { return {mpq_class(a.v + b.v)}; }
inline Rat operator-(const Rat& a, const Rat& b) { return {mpq_class(a.v - b.v)}; }
inline Rat operator*(const Rat& a, const Rat& b) { return {mpq_class(a.v * b.v)}; }
inline Rat operator-(const Rat& a) { return {mpq_class(-a.v)}; }

struct LiftFl {
  Fl operator()(double x) const { return {x, 0}; }
};
struct LiftQ {
  Rat operator()(double x) const { return {mpq_class(x)}; }
};

/// Inflates a computed bound to cover the rounding of the bound computation itself.
inline double safe_bound(double e) { return e * (1 + 16 * kUnit) + kTiny; }

/// The sign of `r` if the bound certifies it, else 2 (undecided; NaN/inf also undecided).
inline int certified_sign(Fl r) {
  double b = safe_bound(r.e);
  if (r.v > b) return 1;
  if (r.v < -b) return -1;
  if (r.e == 0) return (r.v > 0) - (r.v < 0);  // every operation was exact
  return 2;
}

template <class F>
int exact_sign(F&& f) {
  int s = certified_sign(f(LiftFl{}));
  if (s != 2) return s;
  Rat q = f(LiftQ{});
  return sgn(q.v);
}

/// The value of f to within ~2 ulps relative (exact rational, then rounded, when needed).
template <class F>
double accurate_value(F&& f) {
  Fl r = f(LiftFl{});
  if (std::isfinite(r.v) && (r.e == 0 || safe_bound(r.e) <= std::abs(r.v) * 0x1p-52)) return r.v;
  Rat q = f(LiftQ{});
  return q.v.get_d();
}

/// num/den to within a few ulps, both evaluated accurately. Requires den != 0.
template <class N, class D>
double accurate_ratio(N&& num, D&& den) {
  Fl rn = num(LiftFl{}), rd = den(LiftFl{});
  bool ok = std::isfinite(rn.v) && std::isfinite(rd.v) &&
            safe_bound(rn.e) <= std::abs(rn.v) * 0x1p-52 && safe_bound(rd.e) <= std::abs(rd.v) * 0x1p-52;
  if (ok) return rn.v / rd.v;
  mpq_class q = num(LiftQ{}).v / den(LiftQ{}).v;
  return q.get_d();
}

}  // namespace pendepth::exact
