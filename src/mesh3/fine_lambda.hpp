// Private: a sub-ulp enclosure of the parameter λ where a plane meets a line, from the exact
// plane and the exact line rounded once — the filter between the double enclosures and the exact
// λ of the exact mesh σ (mesh_sigma_exact.cpp, refine_ends; issue 17 item 4; docs/benchmarks.md
// "Exact mesh σ: a head-and-tail filter for λ").
//
// The line x0 + λu (the exact σ's exact x0 and u of plane(f) ∩ plane(g)) meets the plane n·x = c
// at λ = b/a, b = c − n·x0, a = n·u, whose cancellation (a plane nearly parallel to the line, or
// nearly through x0: the rounded symmetric faces of a torus) is what leaves the double enclosures
// wide. Rounding the exact coefficients once (x0, u per line; n, c per plane) keeps that
// cancellation out of the inputs: each is known to ~2⁻¹⁰⁶ of itself however nearly parallel f and
// g are (an enclosure from the planes' roundings instead loses half its bits in u = n_f × n_g).
//
// Numbers are held as h + t ∋ the exact value (Ht): h a double, t an interval (Interval_nt<false>
// under the caller's upward rounding guard) enclosing the residual. Every operation computes a new
// head (any double) and a tail that is an outward-rounded interval expression of the exact
// residual — for a product, h1·h2 − p is enclosed by two fused multiply-adds rounded upward
// (fma(h1, h2, −p) and −fma(−h1, h2, p): one rounding each, so an upper and a lower bound, exact
// when the residual is a double); for a sum, h1 + h2 − s = small − (s − big) in intervals (exact,
// a point, when s − big is: Fast2Sum's lemma) — so the enclosure is sound by construction, with
// no error constant to prove, whatever the rounding of the heads or underflow do; they only decide
// how tight it is (~2⁻¹⁰⁰ of the terms without underflow: double-double precision). λ = q +
// (b − q·a)/a with q = h_b / h_a: the residual b − q·a is computed to the same precision, so λ's
// enclosure is within an ulp or two of q, not the ~4 ulps of an interval quotient.
// Range: every head of the inputs finite and at most 2²⁰⁰ (checked: no product can overflow);
// else, or when a's enclosure holds 0, no enclosure (nullopt: the caller takes the exact λ).
// Cost: 6 roundings of exact numbers per line (FineLine, once), 3 per plane (FinePlane, once),
// ~12 head-and-tail operations per λ; no allocation. Tested against GMP rationals
// (tests/mesh3/test_fine_lambda.cpp).
#pragma once

#include "mesh3/plane_number.hpp"

#include <CGAL/Interval_nt.h>

#include <array>
#include <cmath>
#include <optional>

namespace pendepth::mesh3::detail {

using IFine = CGAL::Interval_nt<false>;  // the caller holds CGAL::Protect_FPU_rounding<true>

struct Ht {
  double h = 0;
  IFine t = IFine(0);
};

// Upward rounding (the caller's guard) for every function below but fine_plane.
inline Ht operator*(const Ht& x, const Ht& y) {
  const double p = x.h * y.h;
  const IFine e(-std::fma(-x.h, y.h, p), std::fma(x.h, y.h, -p));  // ∋ x.h·y.h − p
  return {p, e + IFine(x.h) * y.t + IFine(y.h) * x.t + x.t * y.t};
}
inline Ht operator+(const Ht& x, const Ht& y) {
  const double s = x.h + y.h;
  const bool xb = std::abs(x.h) >= std::abs(y.h);
  const double big = xb ? x.h : y.h, small = xb ? y.h : x.h;
  return {s, (IFine(small) - (IFine(s) - IFine(big))) + x.t + y.t};  // ∋ x.h + y.h − s
}
inline Ht operator-(const Ht& x) { return {-x.h, -x.t}; }
inline Ht operator-(const Ht& x, const Ht& y) { return x + -y; }
inline IFine enclose(const Ht& x) { return IFine(x.h) + x.t; }

using Ht3 = std::array<Ht, 3>;
inline Ht dot(const Ht3& a, const Ht3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Round to nearest (no guard needed: PlaneNumber's conversions round on their own): h = RN(x),
// t ∋ x − h exactly (outward; a point 0 when x is a double — Gmpzf's to_interval would widen
// even 0 by 2⁻⁵³ of its exponent's scale).
inline Ht fine_number(const PlaneNumber& x) {
  const double h = to_double(x);
  if (!std::isfinite(h)) return {h, IFine(0)};
  const PlaneNumber r = x - PlaneNumber(h);
  if (is_zero(r)) return {h, IFine(0)};
  const auto [lo, hi] = to_interval(r);
  return {h, IFine(lo, hi)};
}
inline bool in_range(const Ht& v) {
  return std::isfinite(v.h) && std::abs(v.h) <= 0x1p200 && std::isfinite(v.t.inf()) && std::isfinite(v.t.sup());
}
template <class V>
Ht3 fine_vector(const V& v) {
  return {fine_number(v.x), fine_number(v.y), fine_number(v.z)};
}

// A plane n·x <= c, or a line x0 + λu, rounded once: `ok` when every head is finite and at most
// 2²⁰⁰ (the range: no product below can overflow).
struct FinePlane {
  Ht3 n;
  Ht c;
  bool ok = false;
};
template <class V>
FinePlane fine_plane(const V& n, const PlaneNumber& c) {
  FinePlane r{fine_vector(n), fine_number(c), true};
  for (const Ht& v : r.n) r.ok = r.ok && in_range(v);
  r.ok = r.ok && in_range(r.c);
  return r;
}
struct FineLine {
  Ht3 u, x0;
  bool ok = false;
};
template <class V>
FineLine fine_line(const V& u, const V& x0) {
  FineLine r{fine_vector(u), fine_vector(x0), true};
  for (const Ht3* w : {&r.u, &r.x0})
    for (const Ht& v : *w) r.ok = r.ok && in_range(v);
  return r;
}

// Upward rounding (the caller's guard): an enclosure of λ = (c − n·x0)/(n·u) of the plane p on
// L (bounds in Interval_nt<true>'s meaning), or nullopt (out of range, or n·u's sign uncertain).
inline std::optional<std::pair<double, double>> fine_lambda(const FineLine& L, const FinePlane& p) {
  if (!L.ok || !p.ok) return std::nullopt;
  const Ht b = p.c - dot(p.n, L.x0), a = dot(p.n, L.u);
  const IFine ai = enclose(a);
  if (!(ai.inf() > 0 || ai.sup() < 0) || a.h == 0) return std::nullopt;
  const double q = b.h / a.h;
  if (!std::isfinite(q)) return std::nullopt;
  const IFine l = IFine(q) + enclose(b - Ht{q} * a) / ai;
  if (!std::isfinite(l.inf()) || !std::isfinite(l.sup())) return std::nullopt;
  return std::pair{l.inf(), l.sup()};
}

// Upward rounding (the caller's guard): the sign of λ_p − λ_q on L (−1, 0, 1) — of (b_p·a_q −
// b_q·a_p) / (a_p·a_q), the numerator to ~2⁻¹⁰⁰ of its terms, so λ a fraction of an ulp apart are
// ordered and exact ties whose residuals vanish exactly are found equal — or nullopt (out of
// range, a sign of a or of the numerator uncertain).
inline std::optional<int> fine_compare(const FineLine& L, const FinePlane& p, const FinePlane& q) {
  if (!L.ok || !p.ok || !q.ok) return std::nullopt;
  const Ht ap = dot(p.n, L.u), aq = dot(q.n, L.u);
  const IFine api = enclose(ap), aqi = enclose(aq);
  if (!(api.inf() > 0 || api.sup() < 0) || !(aqi.inf() > 0 || aqi.sup() < 0)) return std::nullopt;
  const Ht bp = p.c - dot(p.n, L.x0), bq = q.c - dot(q.n, L.x0);
  const IFine d = enclose(bp * aq - bq * ap);
  const int sd = d.inf() > 0 ? 1 : d.sup() < 0 ? -1 : 0;
  if (sd == 0 && !(d.inf() == 0 && d.sup() == 0)) return std::nullopt;
  return (api.inf() > 0) == (aqi.inf() > 0) ? sd : -sd;
}

}  // namespace pendepth::mesh3::detail
