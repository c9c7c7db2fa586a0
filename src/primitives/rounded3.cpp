// pendepth — rounded shapes in 3D: spheres, capsules and any convex core ⊕ a ball (issue 16 item
// 5; docs/design.md "Primitives"; survey §3 on rounded shapes: GJK engines treat the margin of
// a sphere-swept core exactly this way).
//
// Contract (rounded3.hpp): P = C_P ⊕ B(r_P), Q = C_Q ⊕ B(r_Q), r = r_P + r_Q > 0. Then
// M = P ⊕ (−Q) = M_C ⊕ B(r) with M_C = C_P ⊕ (−C_Q), and the signed distance function of M is
// that of M_C minus r (for a convex set the offset by r moves every boundary point along its
// normal by r, inside and out):
//   sd = sd_C − r,  overlap ⇔ sd < 0,  σ = max(0, −sd),  normal and features those of the cores,
//   witness_p = w_P + r_P·n (P's surface point), witness_q = witness_p + sd·n.
// Every decision is exact (convex3/distance_compare.hpp; exact for the relative pose computed in
// doubles, as in every 3D engine here): overlap ⇔ dist(C_P, C_Q) < r ⇔ the
// exact squared core distance (a ratio of polynomials in the input doubles, on the final simplex
// of the exact GJK) < r²; touching ⇔ equality, and then sd = 0 exactly. The value sd = sd_C − r
// is one rounding further than sd_C (few ulps), its sign always the exact one.
// σ_d and the cast are certified brackets. Along the ray x(λ) = λ·d (Q moved by λ·d; the point
// never rounded: the comparison keeps λ·d as a polynomial; d is replaced by d̂ when |d| and d/|d|
// are exact), g(λ) = dist(x(λ), M_C) is convex, so {λ : g(λ) < r} is an open interval (a, b);
// σ_d = b·|d| when a < 0 < b, the cast a·|d| when 0 <= a. Newton's method on
// φ(s) = sd_C(s·d̂) − r in doubles (derivative n(s)·d̂, n the core answer's normal: one step on a
// facet piece of the offset, quadratic on a cylinder or sphere piece) only proposes λ. The
// bracket (λ_lo, λ_hi] is certified by exact tests — σ_d: g(λ_lo) < r <= g(λ_hi); cast: λ_lo
// before the entry (g(λ_lo) > r and g'(λ_lo) < 0, the exact sign of the derivative), λ_hi not —
// and shrunk by bisection to 2 ulps (at most 200 steps; a proposal that falls short is walked
// forward by doubling steps first). The lengths λ·|d| are rounded outward (|d| as a double-double;
// the product's residual by FMA), so lower_bound <= the exit <= upper_bound = depth, and the cast
// distance is the upper end of its bracket [lower_bound, upper_bound] (Cast3's bounds): the move by λ_hi·d certainly ends overlap (σ_d) /
// certainly touches (cast), except on a ray that only grazes M (below). The translation vector
// λ_hi·d is rounded per component (exact when d is an axis or λ_hi·d_k is a double).
// The cast's hit is exact: it misses when g does not decrease at 0 (convex g) or when the line
// stays farther than r from M_C (exact line comparison: distance_compare.hpp — for the line's
// direction Rpᵀ·d rounded when P's pose rotates, exact otherwise); otherwise the
// entry exists and the bracket holds it, also for a ray that only grazes M (line at distance
// exactly r: the touching point is the first where g stops decreasing, and λ_hi may then be a few
// ulps past it, without contact there).
// Cost: Newton 1–6 core distances, then ~3–8 exact comparisons (one exact GJK each).
#include "primitives/rounded3.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pendepth::primitives {

namespace {
constexpr int kMaxNewton = 200;
constexpr int kMaxBisect = 200;
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kInf = std::numeric_limits<double>::infinity();

// |d| as a double-double hi + lo (relative error < 2^-100), and whether hi alone is exact (d·d's
// products and sums exact, its root exact: axis-aligned and Pythagorean directions).
struct Norm {
  double v = 0, lo = 0;
  bool exact = true;
};
Norm norm_of(const Vec3& d) {
  Norm n;
  double s = 0, e = 0;  // d·d = s + e (e: the products' and sums' rounding errors, summed)
  for (int k = 0; k < 3; ++k) {
    const double p = d[k] * d[k], pe = std::fma(d[k], d[k], -p), t = s + p;
    const double bb = t - s, te = (s - (t - bb)) + (p - bb);  // TwoSum
    if (pe != 0 || te != 0) n.exact = false;
    e += pe + te;
    s = t;
  }
  n.v = std::sqrt(s);
  const double r = std::fma(-n.v, n.v, s);
  if (r != 0) n.exact = false;
  n.lo = (r + e) / (2 * n.v);
  if (n.exact) n.lo = 0;
  return n;
}
// The ray's direction for λ: d̂ itself when |d| and every d_k/|d| are exact (then λ is the
// length), else d (λ·|d| is the length).
struct Ray {
  Vec3 dir;
  Norm len;
};
Ray ray_of(const Vec3& d) {
  const Norm n = norm_of(d);
  if (n.exact) {
    const Vec3 u = d / n.v;
    bool exact = true;
    for (int k = 0; k < 3; ++k) exact = exact && std::fma(u[k], n.v, -d[k]) == 0;
    if (exact) return {u, Norm{1.0, 0.0, true}};
  }
  return {d, n};
}

// λ·|d| rounded outward. x = fl(λ·hi); the true λ·|d| = x + e with e = (λ·hi − x) + λ·lo, the
// first term exact by FMA, known to far better than x's half ulp; where it cannot be told from 0
// (|e| below 2^-90·x, a bound on lo's own error) the result steps outward anyway.
double length_up(double lam, const Norm& nd) {
  const double x = lam * nd.v, e = std::fma(lam, nd.v, -x) + lam * nd.lo;
  if (nd.exact) return e > 0 ? std::nextafter(x, kInf) : x;
  return e < -0x1p-90 * std::abs(x) ? x : std::nextafter(x, kInf);
}
double length_down(double lam, const Norm& nd) {
  const double x = lam * nd.v, e = std::fma(lam, nd.v, -x) + lam * nd.lo;
  if (nd.exact) return e < 0 ? std::nextafter(x, 0.0) : x;
  return std::max(0.0, e > 0x1p-90 * std::abs(x) ? x : std::nextafter(x, 0.0));
}

// Shrinks (lo, hi) — good(hi) and not good(lo), the boundary between — by bisection until the
// two are at most 2 ulps apart (or adjacent doubles); at most kMaxBisect steps.
template <class Good>
void bisect(double& lo, double& hi, Good&& good) {
  for (int k = 0; k < kMaxBisect; ++k) {
    if (!(hi - lo > 2 * (std::nextafter(hi, kInf) - hi))) break;
    const double mid = lo + (hi - lo) / 2;
    if (!(mid > lo && mid < hi)) break;
    (good(mid) ? hi : lo) = mid;
  }
}

// Newton on φ(s) = sd_C(s·d̂) − r from s0 (a proposal in s units; see the file comment).
double newton(const CoreDistance& core, double r, const Vec3& dh, double s, Distance3 c, bool exit) {
  for (int k = 0; k < kMaxNewton; ++k) {
    const double slope = c.normal.dot(dh);
    if (exit ? !(slope > 0) : !(slope < 0)) break;
    const double next = s - (c.distance - r) / slope;
    if (exit ? !(next < s) : !(next > s)) break;
    const Distance3 cn = core(next * dh, nullptr);
    s = next, c = cn;
    if (!(c.distance > r)) break;
  }
  return s;
}

}  // namespace

Distance3 rounded_distance(const CoreDistance& core, const CoreCompare& cmp, double rp, double rq) {
  Vec3 touch = Vec3::Zero();
  const Distance3 c = core(Vec3::Zero(), &touch);
  const double r = rp + rq;
  const int sign = cmp.at(Vec3::Zero(), 0.0, rp, rq, nullptr);  // exact: dist(C_P, C_Q) vs r
  // (+ 0: a −0 component, from rotating an axis vector, prints as 0)
  const Vec3 n = ((c.distance == 0 && !c.overlapping) ? touch : c.normal) + Vec3::Zero();
  Distance3 out;
  const double v = c.distance - r;  // few ulps; its sign made the exact one
  const double tiny = std::numeric_limits<double>::denorm_min();
  out.distance = sign == 0 ? 0.0 : sign > 0 ? std::max(v, tiny) : std::min(v, -tiny);
  out.lower_bound = out.upper_bound = out.distance;
  out.overlapping = sign < 0;
  out.feature_p = c.feature_p, out.feature_q = c.feature_q;
  out.witness_p = c.witness_p + rp * n;
  if (out.distance == 0) {  // touching: the contact point; normal and translation 0 by convention
    out.witness_q = out.witness_p;
    return out;
  }
  out.normal = n;
  out.translation = -out.distance * n + Vec3::Zero();
  out.witness_q = out.witness_p + out.distance * n;
  return out;
}

Depth3 rounded_minimum(const CoreDistance& core, const CoreCompare& cmp, double rp, double rq) {
  const Distance3 s = rounded_distance(core, cmp, rp, rq);
  Depth3 r;
  r.kind = DepthKind::Minimum;
  if (!s.overlapping) return r;
  r.overlapping = true;
  r.depth = r.lower_bound = r.upper_bound = -s.distance;
  r.translation = s.translation;
  r.normal = r.facet_normal = s.normal;
  r.witness_p = r.witness_q = s.witness_p;
  r.feature_p = s.feature_p, r.feature_q = s.feature_q;
  return r;
}

Depth3 rounded_along(const CoreDistance& core, const CoreCompare& cmp, double rp, double rq, const Vec3& d0) {
  const double r = rp + rq;
  Depth3 out;
  out.kind = DepthKind::Directional;
  // lo: Q moved by lo·d overlaps (g(lo) < r); hi: it does not (g(hi) >= r, so hi >= the exit,
  // equal when the exit is a double and the move touches).
  const Ray ray = ray_of(d0);
  const Vec3& d = ray.dir;
  const Norm& nd = ray.len;
  auto out_of = [&](double lam) { return cmp.at(d, lam, rp, rq, nullptr) >= 0; };
  if (out_of(0)) return out;  // touching or apart (exact)
  const Vec3 dh = d0.normalized();
  // A proposal: Newton from a point beyond the exit (doubling from r; φ(s) >= s − |far| − r).
  double s = r;
  Distance3 c = core(s * dh, nullptr);
  for (int k = 0; k < 2100 && !(c.distance > r); ++k) s *= 2, c = core(s * dh, nullptr);
  const double guess = newton(core, r, dh, s, c, true) / nd.v;
  // The certified bracket around the proposal.
  double lo = 0, hi = kInf;
  for (double w : {0.0, 4 * kEps, 64 * kEps, 0x1p-30, 0x1p-10, 1.0}) {
    const double t = guess * (1 + w);
    if (!(t > lo && t < kInf)) continue;
    if (out_of(t)) {
      hi = t;
      break;
    }
    lo = t;
  }
  for (int k = 0; k < 2100 && !(hi < kInf); ++k) {  // (guard: Newton's proposal far off)
    const double t = std::max(2 * lo, r / nd.v);
    (out_of(t) ? hi : lo) = t;
  }
  if (const double t = guess * (1 - 4 * kEps); t > lo && t < hi) (out_of(t) ? hi : lo) = t;
  bisect(lo, hi, out_of);
  out.overlapping = true;
  out.lower_bound = length_down(lo, nd);
  out.depth = out.upper_bound = length_up(hi, nd);
  out.normal = dh;
  out.translation = hi * d + Vec3::Zero();
  c = core(out.translation, nullptr);
  out.facet_normal = c.normal;
  // The contact after the move: P's surface point over the core witness.
  out.witness_p = out.witness_q = c.witness_p + rp * c.normal;
  out.feature_p = c.feature_p, out.feature_q = c.feature_q;
  out.candidates = 0;
  return out;
}

Cast3 rounded_cast(const CoreDistance& core, const CoreCompare& cmp, double rp, double rq, const Vec3& d0) {
  const double r = rp + rq;
  Cast3 out;
  const Ray ray = ray_of(d0);
  const Vec3& d = ray.dir;
  const Norm& nd = ray.len;
  int slope0 = 0;
  const int s0 = cmp.at(d, 0.0, rp, rq, &slope0);
  if (s0 <= 0) {  // overlapping or touching at s = 0 (exact)
    Vec3 touch = Vec3::Zero();
    const Distance3 c = core(Vec3::Zero(), &touch);
    out.hit = true;
    out.overlapping = s0 < 0;
    if (!out.overlapping) {
      const Vec3 n = (c.distance == 0 && !c.overlapping) ? touch : c.normal;
      out.normal = n;
      out.witness_p = out.witness_q = c.witness_p + rp * n;
      out.feature_p = c.feature_p, out.feature_q = c.feature_q;
    }
    return out;
  }
  auto miss = [&]() {
    out.distance = out.lower_bound = out.upper_bound = std::numeric_limits<double>::infinity();
    return out;
  };
  // g(0) > r: the ray meets M only where g decreases (convex g), and only if the line does.
  if (slope0 >= 0) return miss();
  const int line = cmp.line(d, rp, rq);
  if (line > 0) return miss();
  const Vec3 dh = d0.normalized();
  const Distance3 c0 = core(Vec3::Zero(), nullptr);
  const double guess = newton(core, r, dh, 0.0, c0, false) / nd.v;
  // The entry a = inf{λ : g(λ) <= r} (finite: the line comes within r and g decreases at 0).
  // A point t is before the entry iff g(t) > r and g'(t) < 0 (convex g: after a point where g
  // does not decrease and exceeds r, it never comes down to r): an exact, monotone test.
  auto before = [&](double lam) {
    int slope = 0;
    return cmp.at(d, lam, rp, rq, &slope) > 0 && slope < 0;
  };
  double lo = 0, hi = kInf;  // before(lo), !before(hi): a ∈ (lo, hi]
  for (double w : {0.0, 4 * kEps, 64 * kEps, 0x1p-30, 0x1p-20, 0x1p-10}) {
    const double t = guess * (1 + w);
    if (!(t > lo && t < kInf)) continue;
    if (!before(t)) {
      hi = t;
      break;
    }
    lo = t;
  }
  // Newton's proposal fell short (a ray that only grazes, or rounding at a near contact):
  // steps doubling from an ulp of the problem's scale.
  double step = kEps * std::max({lo, guess, std::max(c0.distance, r) / nd.v});
  for (int k = 0; k < 2200 && !(hi < kInf) && step < kInf; ++k, step *= 2) {
    const double t = lo + step;
    (before(t) ? lo : hi) = t;
  }
  if (!(hi < kInf)) return miss();  // (guard: unreachable for a finite entry)
  if (const double t = guess * (1 - 4 * kEps); t > lo && t < hi) (before(t) ? lo : hi) = t;
  bisect(lo, hi, [&](double t) { return !before(t); });
  // hi: Q moved by hi·d touches or overlaps P, except on a ray that only grazes M, where hi may
  // lie a few ulps past the touching point (the entry is still in (lo, hi]).
  out.distance = out.upper_bound = length_up(hi, nd);
  out.lower_bound = length_down(lo, nd);
  out.translation = hi * d + Vec3::Zero();
  Distance3 c;
  out.hit = true;
  c = core(out.translation, nullptr);
  out.normal = c.normal;
  out.witness_p = out.witness_q = c.witness_p + rp * c.normal;
  out.feature_p = c.feature_p, out.feature_q = c.feature_q;
  return out;
}

}  // namespace pendepth::primitives
