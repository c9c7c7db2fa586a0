// Private: filtered exact evaluation of polynomials in the input doubles.
//
// A formula is written once as a generic lambda `f(c)` where `c(x)` lifts an input double into
// the number type. It is evaluated first with `Fl` (double value + rigorous forward error bound),
// then, when that bound cannot decide, with `DD` (double-double, ~106-bit, with its own error
// bound), then exactly with `Ex` (Shewchuk's floating-point expansions: sums of non-overlapping
// doubles, exact while no product underflows or overflows and the length stays under a cap), and
// only when that cannot decide either with exact rationals (mpq_set_d is exact). Exact zeros of
// non-integer data (collinear points with decimal coordinates) end in the Ex tier, several times
// cheaper than GMP (no allocation, no gcd; docs/benchmarks.md).
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
struct Fl {
  double v = 0, e = 0;
};
inline Fl operator+(Fl a, Fl b) {
  double v = a.v + b.v;
  return {v, a.e + b.e + std::abs(v) * kUnit};
}
inline Fl operator-(Fl a, Fl b) {
  double v = a.v - b.v;
  return {v, a.e + b.e + std::abs(v) * kUnit};
}
inline Fl operator*(Fl a, Fl b) {
  double v = a.v * b.v;
  return {v, std::abs(a.v) * b.e + std::abs(b.v) * a.e + a.e * b.e + std::abs(v) * kUnit + kTiny};
}
inline Fl operator-(Fl a) { return {-a.v, a.e}; }

/// Double that knows whether every operation so far was exact (TwoSum / FMA checks). Used only
/// when the Fl filter cannot decide: for integer-like coordinates the degenerate (zero) cases are
/// then certified without the rational fallback.
struct FlX {
  double v = 0;
  bool exact = true;
};
inline constexpr double kExactFloor = 0x1p-960;  // below this a product's error may be unrepresentable
inline FlX operator+(FlX a, FlX b) {
  double v = a.v + b.v;
  bool ex = a.exact && b.exact;
  if (ex) {
    double bv = v - a.v, av = v - bv;
    ex = (a.v - av) + (b.v - bv) == 0;
  }
  return {v, ex};
}
inline FlX operator-(FlX a) { return {-a.v, a.exact}; }
inline FlX operator-(FlX a, FlX b) { return a + (-b); }
inline FlX operator*(FlX a, FlX b) {
  double v = a.v * b.v;
  bool ex = a.exact && b.exact && (std::abs(v) > kExactFloor || a.v == 0 || b.v == 0) &&
            std::isfinite(v) && std::fma(a.v, b.v, -v) == 0;
  return {v, ex};
}
struct LiftFlX {
  FlX operator()(double x) const { return {x, true}; }
};

/// Exact sign of a·b − c·d for a, b, c, d taken as exact values (e.g. FlX sums known exact), or 2
/// when undecided (a product overflowed, or its rounding error may be unrepresentable). Rounding
/// is monotone, so fl(a·b) ≠ fl(c·d) orders the exact products; equal roundings p compare the
/// products' exact errors (FMA): a·b − c·d = (p + e1) − (p + e2) = e1 − e2. For integer-like data
/// this decides the frequent exact zeros that floating filters cannot, at the cost of one filter.
inline int sign_ab_minus_cd(double a, double b, double c, double d) {
  const double p = a * b, q = c * d;
  if (!std::isfinite(p) || !std::isfinite(q)) return 2;
  if (p != q) return p > q ? 1 : -1;
  auto err = [](double x, double y, double r, double& e) {
    if (x == 0 || y == 0) {
      e = 0;  // r = x·y = 0 exactly
      return true;
    }
    if (!(std::abs(r) >= 0x1p-900)) return false;  // every bit of x·y lies above 2⁻¹⁰⁰⁶ otherwise
    e = std::fma(x, y, -r);
    return true;
  };
  double e1, e2;
  if (!err(a, b, p, e1) || !err(c, d, q, e2)) return 2;
  return (e1 > e2) - (e1 < e2);
}
/// The same for a·b − c·d with FlX operands: 2 unless all four are exact.
inline int sign_ab_minus_cd(FlX a, FlX b, FlX c, FlX d) {
  return a.exact && b.exact && c.exact && d.exact ? sign_ab_minus_cd(a.v, b.v, c.v, d.v) : 2;
}

/// Double-double (hi + lo, |lo| <= ulp(hi)/2) with an absolute error bound e. Error bounds are
/// taken relative to the operands' magnitudes (not the result's), so they stay valid under
/// cancellation. Unit: 2^-100 covers the ~2^-104 rounding of each double-double operation with
/// a margin.
struct DD {
  double hi = 0, lo = 0, e = 0;
};
inline constexpr double kUnitDD = 0x1p-100;
inline void two_sum(double a, double b, double& s, double& err) {
  s = a + b;
  double bb = s - a;
  err = (a - (s - bb)) + (b - bb);
}
inline void quick_two_sum(double a, double b, double& s, double& err) {
  s = a + b;
  err = b - (s - a);
}
/// The value parts (hi, lo) of the double-double sum and product, shared by DD (which adds its
/// running bound e) and DV (none: callers that bound the error a priori).
inline void dd_sum_value(double ahi, double alo, double bhi, double blo, double& hi, double& lo) {
  double s, e1, t, e2;
  two_sum(ahi, bhi, s, e1);
  two_sum(alo, blo, t, e2);
  e1 += t;
  quick_two_sum(s, e1, s, e1);
  e1 += e2;
  quick_two_sum(s, e1, hi, lo);
}
inline void dd_product_value(double ahi, double alo, double bhi, double blo, double& hi, double& lo) {
  double p = ahi * bhi;
  double err = std::fma(ahi, bhi, -p);
  err += ahi * blo + alo * bhi;
  quick_two_sum(p, err, hi, lo);
}
inline DD operator+(const DD& a, const DD& b) {
  DD r;
  dd_sum_value(a.hi, a.lo, b.hi, b.lo, r.hi, r.lo);
  r.e = a.e + b.e + (std::abs(a.hi) + std::abs(b.hi)) * kUnitDD;
  return r;
}
inline DD operator-(const DD& a) { return {-a.hi, -a.lo, a.e}; }
inline DD operator-(const DD& a, const DD& b) { return a + (-b); }
inline DD operator*(const DD& a, const DD& b) {
  DD r;
  dd_product_value(a.hi, a.lo, b.hi, b.lo, r.hi, r.lo);
  double ma = std::abs(a.hi) * (1 + 0x1p-50), mb = std::abs(b.hi) * (1 + 0x1p-50);
  r.e = ma * b.e + mb * a.e + a.e * b.e + ma * mb * kUnitDD + kTiny;
  return r;
}
struct LiftDD {
  DD operator()(double x) const { return {x, 0, 0}; }
};
inline bool dd_finite(const DD& r) { return std::isfinite(r.hi) && std::isfinite(r.lo) && std::isfinite(r.e); }

/// A double-double value without an error bound: hi and lo exactly as DD computes them from the
/// same operations (the shared value parts above), for formulas whose bound is proven in advance
/// from their inputs' magnitudes (signed_distance3.cpp: the distance of a triangle).
struct DV {
  double hi = 0, lo = 0;
};
inline DV operator+(const DV& a, const DV& b) {
  DV r;
  dd_sum_value(a.hi, a.lo, b.hi, b.lo, r.hi, r.lo);
  return r;
}
inline DV operator-(const DV& a) { return {-a.hi, -a.lo}; }
inline DV operator-(const DV& a, const DV& b) { return a + (-b); }
inline DV operator*(const DV& a, const DV& b) {
  DV r;
  dd_product_value(a.hi, a.lo, b.hi, b.lo, r.hi, r.lo);
  return r;
}
struct LiftDV {
  DV operator()(double x) const { return {x, 0}; }
};
inline bool dv_finite(const DV& r) { return std::isfinite(r.hi) && std::isfinite(r.lo); }

/// Exact floating-point expansion (Shewchuk 1997, "Adaptive precision floating-point arithmetic
/// and fast robust geometric predicates"): the value is the exact sum of c[0..n), non-overlapping,
/// increasing magnitude, no zeros; kept compressed, so n stays near (bit span of the value) / 53.
/// `ok` turns false, and stays false, when exactness cannot be guaranteed: an overflow, a product
/// whose rounding error may be below the subnormal range, or more than kCap components. Callers
/// then use rationals.
struct Ex {
  static constexpr int kCap = 40;
  int n = 0;
  bool ok = true;
  double c[kCap];
};
namespace detail {
inline constexpr double kExFloor = 0x1p-900;  // products below this may lose their error term
inline bool ex_push(Ex& h, double v) {
  if (v == 0) return true;
  if (h.n == Ex::kCap || !std::isfinite(v)) return h.ok = false;
  h.c[h.n++] = v;
  return true;
}
// Shewchuk's COMPRESS: the same value, non-adjacent components (as short as it gets).
inline void ex_compress(Ex& e) {
  if (e.n <= 1) return;
  double g[Ex::kCap];
  int bottom = e.n - 1;
  double Q = e.c[e.n - 1];
  for (int i = e.n - 2; i >= 0; --i) {
    double Qn, q;
    quick_two_sum(Q, e.c[i], Qn, q);
    if (q != 0) {
      g[bottom--] = Qn;
      Q = q;
    } else {
      Q = Qn;
    }
  }
  g[bottom] = Q;
  int top = 0;
  for (int i = bottom + 1; i < e.n; ++i) {
    double Qn, q;
    quick_two_sum(g[i], Q, Qn, q);
    if (q != 0) e.c[top++] = q;
    Q = Qn;
  }
  e.c[top++] = Q;
  e.n = top;
  if (e.n == 1 && e.c[0] == 0) e.n = 0;
  if (e.n > 0 && !std::isfinite(e.c[e.n - 1])) e.ok = false;
}
// h += b (Shewchuk's GROW-EXPANSION with zero elimination).
inline void ex_grow(Ex& h, double b) {
  Ex out;
  double Q = b;
  for (int i = 0; i < h.n; ++i) {
    double s, e;
    two_sum(Q, h.c[i], s, e);
    Q = s;
    if (!ex_push(out, e)) break;
  }
  ex_push(out, Q);
  out.ok = out.ok && h.ok;
  h = out;
}
// e·b (Shewchuk's SCALE-EXPANSION with zero elimination; products by FMA).
inline Ex ex_scale(const Ex& e, double b) {
  Ex h;
  h.ok = e.ok;
  if (b == 0 || e.n == 0) return h;
  auto prod = [&](double x, double& p, double& err) {
    p = x * b;
    err = std::fma(x, b, -p);
    if (!std::isfinite(p) || std::abs(p) < kExFloor) h.ok = false;
  };
  double Q, t0;
  prod(e.c[0], Q, t0);
  ex_push(h, t0);
  for (int i = 1; i < e.n && h.ok; ++i) {
    double T, t, s, r;
    prod(e.c[i], T, t);
    two_sum(Q, t, s, r);
    ex_push(h, r);
    quick_two_sum(T, s, Q, r);
    ex_push(h, r);
  }
  ex_push(h, Q);
  return h;
}
}  // namespace detail
inline Ex operator+(const Ex& a, const Ex& b) {
  Ex h = a.n >= b.n ? a : b;
  const Ex& o = a.n >= b.n ? b : a;
  h.ok = a.ok && b.ok;
  for (int j = 0; j < o.n && h.ok; ++j) detail::ex_grow(h, o.c[j]);
  detail::ex_compress(h);
  return h;
}
inline Ex operator-(const Ex& a) {
  Ex r = a;
  for (int i = 0; i < r.n; ++i) r.c[i] = -r.c[i];
  return r;
}
inline Ex operator-(const Ex& a, const Ex& b) { return a + (-b); }
inline Ex operator*(const Ex& a, const Ex& b) {
  const Ex& big = a.n >= b.n ? a : b;
  const Ex& small = a.n >= b.n ? b : a;
  Ex acc;
  acc.ok = a.ok && b.ok;
  for (int j = 0; j < small.n && acc.ok; ++j) acc = acc + detail::ex_scale(big, small.c[j]);
  return acc;
}
struct LiftEx {
  Ex operator()(double x) const {
    Ex r;
    if (!std::isfinite(x)) r.ok = false;
    else if (x != 0) r.c[r.n++] = x;
    return r;
  }
};
inline int ex_sign(const Ex& e) { return e.n == 0 ? 0 : (e.c[e.n - 1] > 0 ? 1 : -1); }
/// The value to within ~1 ulp (the components summed from the smallest).
inline double ex_value(const Ex& e) {
  double v = 0;
  for (int i = 0; i < e.n; ++i) v += e.c[i];
  return v;
}

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

/// f(l) out of line, for the exact tiers (Ex, Rat): rarely run and large once inlined; a call
/// keeps them out of their callers — in particular out of the flattened x86-64-v3 clones
/// (geometry/isa.hpp), which would otherwise inline every one at every use (compile time).
template <class F, class L>
[[gnu::noinline, gnu::cold]] auto cold_eval(F& f, L l) {
  return f(l);
}

/// Inflates a computed bound to cover the rounding of the bound computation itself.
inline double safe_bound(double e) { return e * (1 + 16 * kUnit) + kTiny; }

/// The sign of `r` if the bound certifies it, else 2 (undecided; NaN/inf also undecided).
inline int certified_sign(Fl r) {
  double b = safe_bound(r.e);
  if (r.v > b) return 1;
  if (r.v < -b) return -1;
  return 2;
}

/// The tiers of exact_sign after the floating and exact-double ones: double-double, expansions,
/// rationals.
template <class F>
int exact_sign_beyond_flx(F&& f) {
  DD d = f(LiftDD{});
  if (dd_finite(d)) {
    double b = safe_bound(d.e);
    if (d.hi > b) return 1;  // |lo| <= ulp(hi)/2, so hi beyond the bound fixes the sign
    if (d.hi < -b) return -1;
  }
  const Ex e = cold_eval(f, LiftEx{});
  if (e.ok) return ex_sign(e);
  Rat q = cold_eval(f, LiftQ{});
  return sgn(q.v);
}

/// Exact sign of a polynomial in input doubles, written once as a generic lambda over a lift:
/// a floating value with a running error bound, then exact doubles, double-double, expansions,
/// rationals — each only when the previous cannot decide.
template <class F>
int exact_sign(F&& f) {
  int s = certified_sign(f(LiftFl{}));
  if (s != 2) return s;
  FlX x = f(LiftFlX{});
  if (x.exact) return (x.v > 0) - (x.v < 0);
  return exact_sign_beyond_flx(f);
}

/// exact_sign for a polynomial whose floating filter has just failed elsewhere (a point found on
/// a line by a filter with a wider margin, say): the value is most likely an exact zero, which
/// the Fl tier cannot certify, so the exact-double tier runs first (integer-like data ends
/// there), then the usual tiers.
template <class F>
int exact_sign_tie_likely(F&& f) {
  const FlX x = f(LiftFlX{});
  if (x.exact) return (x.v > 0) - (x.v < 0);
  const int s = certified_sign(f(LiftFl{}));
  if (s != 2) return s;
  return exact_sign_beyond_flx(f);
}

/// exact_sign with a caller-supplied fast filter: `approx` is the formula evaluated in plain
/// double and `bound` a proven bound on its error (derived per formula, Shewchuk-style). Only if
/// it cannot decide does the generic tiered evaluation run (skipping the redundant Fl tier).
template <class F>
int exact_sign_filtered(double approx, double bound, F&& f) {
  if (approx > bound) return 1;
  if (approx < -bound) return -1;
  FlX x = f(LiftFlX{});
  if (x.exact) return (x.v > 0) - (x.v < 0);
  DD d = f(LiftDD{});
  if (dd_finite(d)) {
    double b = safe_bound(d.e);
    if (d.hi > b) return 1;
    if (d.hi < -b) return -1;
  }
  const Ex e = cold_eval(f, LiftEx{});
  if (e.ok) return ex_sign(e);
  Rat q = cold_eval(f, LiftQ{});
  return sgn(q.v);
}

/// Error bound factor for a difference of two products of differences, (a−b)(c−d) − (e−f)(g−h):
/// |computed − exact| <= kCrossBound·(|p1| + |p2|) with p1, p2 the computed products
/// (Shewchuk's ccwerrboundA, rounded up), plus kTiny for underflow.
inline constexpr double kCrossBound = (3.0 + 16.0 * kUnit) * kUnit * (1 + 0x1p-40);

namespace detail {
// The value of f to within ~1 ulp if a floating tier can certify it; false otherwise.
template <class F>
bool floating_value(F&& f, double& out) {
  Fl r = f(LiftFl{});
  if (std::isfinite(r.v) && safe_bound(r.e) <= std::abs(r.v) * 0x1p-53) {
    out = r.v;
    return true;
  }
  DD d = f(LiftDD{});  // exact inputs combined exactly also land here (tiny bound)
  if (dd_finite(d) && safe_bound(d.e) <= std::abs(d.hi) * 0x1p-54) {
    out = d.hi;  // hi = round(hi + lo); the error bound is far below half an ulp of hi
    return true;
  }
  const Ex e = cold_eval(f, LiftEx{});  // exact: zeros and heavy cancellation
  if (e.ok) {
    out = ex_value(e);
    return std::isfinite(out);
  }
  return false;
}
}  // namespace detail

/// The value of f to within ~1 ulp relative (exact rational, then rounded, when needed).
template <class F>
double accurate_value(F&& f) {
  double v;
  if (detail::floating_value(f, v)) return v;
  Rat q = cold_eval(f, LiftQ{});
  return q.v.get_d();
}

/// num/den to within a few ulps, both evaluated accurately. Requires den != 0.
template <class N, class D>
double accurate_ratio(N&& num, D&& den) {
  double a, b;
  if (detail::floating_value(num, a) && detail::floating_value(den, b) && b != 0) {
    double r = a / b;
    if (std::isfinite(r) && (r != 0 || a == 0)) return r;
  }
  mpq_class q = cold_eval(num, LiftQ{}).v / cold_eval(den, LiftQ{}).v;
  return q.get_d();
}

/// accurate_ratio for a formula computing numerator and denominator together, f(lift) returning
/// {num, den}: each tier evaluates the pair once instead of once per component. The same result,
/// bit for bit, as accurate_ratio([&](auto L) { return f(L).first; }, [&](auto L) { return
/// f(L).second; }): each component goes through floating_value's tiers with the same acceptance
/// tests, and a component's value does not depend on its companion being computed.
template <class F>
double accurate_ratio_of(F&& f) {
  double v[2];
  int got[2] = {0, 0};  // 1: accepted, -1: no floating tier can certify it
  {
    const auto r = f(LiftFl{});
    const Fl c[2] = {r.first, r.second};
    for (int k = 0; k < 2; ++k)
      if (std::isfinite(c[k].v) && safe_bound(c[k].e) <= std::abs(c[k].v) * 0x1p-53) v[k] = c[k].v, got[k] = 1;
  }
  if (got[0] != 1 || got[1] != 1) {
    const auto r = f(LiftDD{});
    const DD c[2] = {r.first, r.second};
    for (int k = 0; k < 2; ++k)
      if (got[k] != 1 && dd_finite(c[k]) && safe_bound(c[k].e) <= std::abs(c[k].hi) * 0x1p-54) v[k] = c[k].hi, got[k] = 1;
  }
  if (got[0] != 1 || got[1] != 1) {
    const auto r = cold_eval(f, LiftEx{});
    const Ex* c[2] = {&r.first, &r.second};
    for (int k = 0; k < 2; ++k)
      if (got[k] != 1) {
        if (c[k]->ok) {
          v[k] = ex_value(*c[k]);
          got[k] = std::isfinite(v[k]) ? 1 : -1;
        } else {
          got[k] = -1;
        }
      }
  }
  if (got[0] == 1 && got[1] == 1 && v[1] != 0) {
    const double q = v[0] / v[1];
    if (std::isfinite(q) && (q != 0 || v[0] == 0)) return q;
  }
  const auto r = cold_eval(f, LiftQ{});
  mpq_class q = r.first.v / r.second.v;
  return q.get_d();
}

}  // namespace pendepth::exact
