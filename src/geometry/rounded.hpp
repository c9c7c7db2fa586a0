// Private: correctly rounded values of ratios of polynomials in the input doubles (issue 19 item 1).
//
// rounded_ratio_of(f) returns RN(num / den), the exact real num/den rounded to the nearest double
// (ties to even), for a formula f(lift) → {num, den} written once over a lift as in exact.hpp.
// Being a function of the exact value only, the answer does not depend on how it was found: a
// double-double evaluation whose rigorous error bound keeps the quotient strictly inside one
// rounding cell is returned as is; otherwise (the exact value within ~2⁻⁹⁶ relative of a midpoint
// between two doubles — exact ties included — or magnitudes outside [2⁻⁸⁰⁰, 2⁸⁰⁰]) exact
// rationals decide. So a fast path and an exact path that both ask for RN(·) agree bit for bit,
// and `exact_only` (the rationals alone) is the oracle the tests compare the fast tier with.
//
// Error bounds (u = 2⁻⁵³; exact.hpp's DD carries an absolute bound e on |exact − (hi + lo)|):
//   dd_div(a, b) for DD values a, b (taken exact): q1 = RN(a.hi / b.hi) is within 3.1u of a/b;
//   r = a − q1·b in double-double is −η·a (η the relative error of q1, |η| ≤ 3.1u) plus the
//   product's error (≤ 9u²·|q1·b.hi|) and the subtraction's (≤ 64u² of its operands, exact.hpp's
//   kUnitDD), ≤ 137u²·|a| in all; q2 = RN(r.hi / b.hi) adds ≤ 10u²·|a/b|; q1 + q2 (fast two-sum,
//   exact) is within 147u² < 2⁻⁹⁸ relative of a/b. With inputs off by e_a, e_b (absolute), the
//   quotient is off by at most (e_a/|a| + e_b/|b|)·(1 + 2⁻⁴⁰) + 2⁻⁹⁸ relative (e ≪ |a|, |b|).
//   kDivBound = 2⁻⁹⁷ is used (2× margin).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <gmpxx.h>

#include "geometry/exact.hpp"

namespace pendepth::exact {

inline constexpr double kDivBound = 0x1p-97;

/// a / b in double-double (b.hi ≠ 0); the result's `e` is left 0 (the caller bounds it).
inline DD dd_div(const DD& a, const DD& b) {
  const double q1 = a.hi / b.hi;
  const DD r = a - DD{q1, 0, 0} * b;
  const double q2 = r.hi / b.hi;
  DD q;
  quick_two_sum(q1, q2, q.hi, q.lo);
  return q;
}

/// True when every real within R of hi + lo rounds to nearest to hi: the interval lies strictly
/// inside hi's rounding cell (the smaller of the two half gaps is used, so powers of two are safe;
/// no tie can occur). Magnitudes outside [2⁻⁸⁰⁰, 2⁸⁰⁰] (or NaN) are refused.
inline bool rounds_to(double hi, double lo, double R) {
  const double a = std::abs(hi);
  if (!(a >= 0x1p-800 && a <= 0x1p800)) return false;
  // The gap to the next double towards zero (a is normal: one less in the last bit), exact
  // (Sterbenz); ≤ the gap above.
  const double gap = a - std::bit_cast<double>(std::bit_cast<std::uint64_t>(a) - 1);
  return (std::abs(lo) + R) * (1 + 0x1p-50) < 0.5 * gap;
}

/// The rational q rounded to the nearest double, ties to even (mpq_get_d truncates).
inline double round_nearest(const mpq_class& q) {
  const double d = q.get_d();
  if (!std::isfinite(d)) return d;
  const mpq_class qd(d);
  if (qd == q) return d;
  const int s = sgn(q);
  const double away = std::nextafter(d, s > 0 ? INFINITY : -INFINITY);
  // The midpoint between d and the next double away from zero (2¹⁰²⁴ past the largest double).
  const double step = std::isfinite(away) ? away - d : d - std::nextafter(d, 0.0);
  const mpq_class mid = qd + mpq_class(step) / 2;
  const int c = cmp(abs(q), abs(mid));
  if (c < 0) return d;
  if (c > 0) return away;
  return (std::bit_cast<std::uint64_t>(d) & 1) == 0 ? d : away;
}

/// Double-double evaluation of num / den with a rigorous absolute error bound: false when the
/// components are not finite, not in range, or the denominator's sign is not certain.
template <class F>
bool dd_ratio(F&& f, double& hi, double& lo, double& bound, int* den_sign = nullptr) {
  const auto r = f(LiftDD{});
  const DD &n = r.first, &d = r.second;
  if (!dd_finite(n) || !dd_finite(d)) return false;
  const double an = std::abs(n.hi), ad = std::abs(d.hi);
  if (!(an >= 0x1p-700 && an <= 0x1p700 && ad >= 0x1p-700 && ad <= 0x1p700)) return false;
  const double en = safe_bound(n.e), ed = safe_bound(d.e);
  if (!(en <= an * 0x1p-60 && ed <= ad * 0x1p-60)) return false;
  const DD q = dd_div(n, d);
  const double rel = (en / an + ed / ad) * (1 + 0x1p-40) + kDivBound;
  hi = q.hi, lo = q.lo, bound = rel * std::abs(q.hi) * (1 + 0x1p-40);
  if (den_sign) *den_sign = d.hi > 0 ? 1 : -1;
  return true;
}

/// When the bound b around hi + lo holds one midpoint m between hi and its neighbour on lo's side
/// (b below a quarter of the smaller gap at hi, |lo| ≤ half the gap on its side as hi + lo is
/// normalised): the exact value lies strictly between the midpoints beyond hi and beyond the
/// neighbour, so RN is hi or the neighbour by the exact sign of num/den − m = (num − m·den)/den
/// (exact.hpp's tiers: exact zeros of sums of a few input doubles — frequent ties, e.g. a vertex
/// o1 + o2 − t with one bit too many — end in the expansion tier, not in rationals); a tie goes
/// to the even one. False when b is too wide.
template <class F>
bool round_near_midpoint(F&& f, double hi, double lo, double b, int den_sign, double& out) {
  const double a = std::abs(hi);
  if (!(a >= 0x1p-800 && a <= 0x1p800) || lo == 0) return false;
  const double gmin = a - std::nextafter(a, 0.0);
  if (!(b * (1 + 0x1p-50) < 0.25 * gmin)) return false;
  const double nb = std::nextafter(hi, lo > 0 ? INFINITY : -INFINITY);
  const double half = 0.5 * (nb - hi);  // exact: the gap is a power of two ≥ 2⁻⁸⁰¹
  const int s = den_sign * exact_sign([&](auto L) {
                  const auto r = f(L);
                  return r.first - (L(hi) + L(half)) * r.second;
                });
  const int side = lo > 0 ? 1 : -1;  // X − m has sign s; X beyond m (on lo's side) iff s == side
  if (s == side) out = nb;
  else if (s == -side) out = hi;
  else out = (std::bit_cast<std::uint64_t>(hi) & 1) == 0 ? hi : nb;
  return true;
}

/// RN(num / den) (den ≠ 0): the certified double-double tier, else exact rationals;
/// `exact_only` skips the double-double tier (the tests' oracle).
template <class F>
double rounded_ratio_of(F&& f, bool exact_only = false) {
  if (!exact_only) {
    double hi, lo, b, v;
    int sd;
    if (dd_ratio(f, hi, lo, b, &sd)) {
      if (rounds_to(hi, lo, b)) return hi;
      if (round_near_midpoint(f, hi, lo, b, sd, v)) return v;
    }
  }
  const auto r = f(LiftQ{});
  return round_nearest(mpq_class(r.first.v / r.second.v));
}

}  // namespace pendepth::exact
