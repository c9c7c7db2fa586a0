// pendepth — ball pairs in closed form: the second pre-step of the certified support-function
// engine (support3.cpp; issue 16 item 5; docs/algorithms.md §R4.8 "Ball pairs").
//
// Why. A sphere on the axis of a cone has a whole ring of nearest points: EPA's inner polytope
// cuts one facet of that continuum per support and its bracket only shrinks as 1/k² (7e-7 after
// 4,800 supports, docs/robustness.md). But a ball makes M simple: for Q = B(c, r),
// M = P ⊕ (−Q) = (P ⊕ B(r)) − c, so sd_M(0) = sd_P(c) − r — the signed distance of ONE POINT
// from P. For a solid of revolution that is a 2D problem in the meridian plane through c.
//
// Notation. Body A = the non-ball shape (cone(R, H), cylinder(R, H) or the spheroid
// ellipsoid(A, A, C), ⊕ B(r_A)), in its own frame, axis z; x the ball's centre in A's frame; r the ball's radius; ρ = |x_xy|.
// Contract (ball3.hpp). Facts used, each for convex sets:
//  (1) sd_{A ⊕ B(r)} = sd_A − r, and sd_A is 1-Lipschitz;
//  (2) sd_A(x) = sup over unit u of ⟨u, x⟩ − h_A(u) (inside: minus the distance to ∂A, outside:
//      the distance), so |sd_A − sd_B| <= d_H(A, B) pointwise, and sd is decreasing in the set;
//  (3) for a solid of revolution with meridian section T (convex, symmetric about the axis),
//      sd_A(x) = sd_T(ρ, x_z): a nearest point of A (of ∂A) turned about the axis into x's half
//      plane stays in A (on ∂A) and gets no farther (|x − y|² = ρ² + ρ_y² − 2ρρ_y cos φ + Δz²);
//  (4) sd_T(ρ, z) is convex and even in ρ, so non-decreasing in ρ >= 0: the lower (upper) bound
//      is taken at a lower (upper) bound of ρ.
// The pose. Q ball (P body): Q' = R·B(q0, r) + t is the ellipsoid c + R·B(r), c = R q0 + t, which
// holds B(c, r·σ_min(R)) and lies in B(c, r·σ_max(R)) (σ(R) bracketed by `stretch`), so by (2)
// sd_M(0) ∈ [sd_P(c) − r·σ_max, sd_P(c) − r·σ_min]; c is bracketed componentwise (intervals) and
// replaced by a double point within e of it (1). P ball (Q body): sd_M(0) = sd_{Q'}(p0) − r with
// Q' = R·Q + t; R = R̂·S (polar: R̂ orthogonal, S's eigenvalues σ_i(R)), ‖R − R̂‖₂ <= η =
// max|σ_i − 1|, so d_H(R·Q, R̂·Q) <= η·ρ_Q and sd_{R̂Q+t}(p0) = sd_Q(R̂ᵀ(p0 − t)), which differs
// from sd_Q(Rᵀ(p0 − t)) by <= η|p0 − t| (1): x = Rᵀ(p0 − t) bracketed, e += η(ρ_Q + |p0 − t|).
// The section. T's right half boundary is a polyline V_0 = (0, top), …, V_m = (0, bottom),
// clockwise; edge i (V_i → V_i+1) has the outward normal n_i = (z_i − z_i+1, ρ_i+1 − ρ_i) and the
// line function f_i(p) = ⟨n_i, p − V_i⟩/|n_i| (its mirror edge's is f_i − 2ρ n_iρ/|n_i| <= f_i for
// ρ >= 0, so the right half's edges are all the edges that matter). For p = (ρ, z), ρ >= 0:
//  lower bounds (2): every f_i(p) (u = n̂_i, h_T(n̂_i) = ⟨n̂_i, V_i⟩), and for each vertex V_i the
//    direction u = p − V_i: min over T's vertices w (both halves) of ⟨u, p − w⟩/|u| — equal to
//    |p − V_i| where V_i is nearest (a vertex region);
//  upper bounds: if every f_i(p) <= 0 (certified) p ∈ T and sd_T(p) = max_i f_i(p) (the depth of
//    a point of a convex polygon is its least distance to an edge line); otherwise
//    max(max_i f_i, D) with D the least certified distance from p to a point of T — a vertex,
//    or the foot on edge i when its parameter λ_i ∈ [0, 1] is certified (then the distance is
//    |f_i|) — valid on both sides: inside sd <= max_i f_i, outside sd = dist(p, T) <= D.
// Every quantity is an outward interval (directed.hpp); no decision changes a bound, only which
// valid bound is used. Cost O(1) (a few dozen roundings, no support query). The spheroid's
// ellipse: a certified 1D maximisation ("The spheroid's meridian ellipse" below).
#include "primitives/ball3.hpp"

#include "primitives/directed.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace pendepth::primitives {

namespace {
using namespace directed;

// A ball: the centre (own frame) and its radius bracketed (an ellipsoid's axis + a rounding).
struct Ball {
  Vec3 centre = Vec3::Zero();
  Interval r;
};
std::optional<Ball> ball_of(const Support3& s) {
  if (s.kind == Support3::Kind::Points && s.points.size() == 1) return Ball{s.points[0], iv(s.radius)};
  if (s.kind == Support3::Kind::Ellipsoid && s.a == s.b && s.b == s.c) return Ball{Vec3::Zero(), iv(s.a) + iv(s.radius)};
  return std::nullopt;
}

// The right half of a body's meridian section (see the header), top to bottom, or (ellipse) the
// spheroid's meridian ellipse of semi-axes a along ρ and c along z; nullopt for a body this file
// does not answer.
struct Section {
  std::array<Vec2, 4> v{};
  int n = 0;  // polygon vertices
  bool ellipse = false;
  double a = 0, c = 0;
};
std::optional<Section> section_of(const Support3& s) {
  const double R = s.a, H = s.b;
  if (s.kind == Support3::Kind::Cone) return Section{{Vec2(0, H), Vec2(R, -H), Vec2(0, -H)}, 3};
  if (s.kind == Support3::Kind::Cylinder) return Section{{Vec2(0, H), Vec2(R, H), Vec2(R, -H), Vec2(0, -H)}, 4};
  if (s.kind == Support3::Kind::Ellipsoid && s.a == s.b) return Section{{}, 0, true, s.a, s.c};
  return std::nullopt;
}

struct Interval2 {
  Interval x, y;
};
Interval2 minus(const Vec2& p, const Vec2& v) { return {iv(p[0]) - iv(v[0]), iv(p[1]) - iv(v[1])}; }
Interval dot(const Interval2& a, const Interval2& b) { return a.x * b.x + a.y * b.y; }
Interval norm(const Interval2& a) { return hypot(a.x, a.y); }

// The bracket of sd_T at p (ρ = p[0] >= 0 a double), by the bounds of the header.
Interval section_sd(const Section& T, const Vec2& p) {
  double lower = -kInf, max_f_hi = -kInf, dist_hi = kInf;
  for (int i = 0; i + 1 < T.n; ++i) {
    const Vec2 &a = T.v[i], &b = T.v[i + 1];
    const Interval2 n{iv(a[1]) - iv(b[1]), iv(b[0]) - iv(a[0])}, d{n.y, -n.x}, pa = minus(p, a);  // d = b − a
    const Interval nn = norm(n), dd = dot(d, d);
    if (!(nn.lo > 0 && dd.lo > 0)) {  // (an underflowed edge: no line bound; the sd stays valid)
      max_f_hi = kInf;
      continue;
    }
    const Interval f = dot(n, pa) / nn;
    lower = std::max(lower, f.lo), max_f_hi = std::max(max_f_hi, f.hi);
    const Interval lam = dot(pa, d) / dd;
    if (lam.lo >= 0 && lam.hi <= 1) dist_hi = std::min(dist_hi, f.mag());
  }
  for (int i = 0; i < T.n; ++i) {
    const Interval2 pv = minus(p, T.v[i]);
    dist_hi = std::min(dist_hi, norm(pv).hi);
    const Vec2 u = p - T.v[i];
    if (!(u.squaredNorm() > 0)) continue;
    const Interval2 ui{iv(u[0]), iv(u[1])};
    double least = kInf;
    for (int j = 0; j < T.n; ++j)
      for (const double side : {1.0, -1.0})
        least = std::min(least, dot(ui, minus(p, Vec2(side * T.v[j][0], T.v[j][1]))).lo);
    if (const Interval nu = norm(ui); nu.lo > 0) lower = std::max(lower, (Interval{least, least} / nu).lo);
  }
  return {lower, max_f_hi <= 0 ? max_f_hi : std::max(max_f_hi, dist_hi)};
}

// The nearest boundary point of T to p and the outward unit normal there (doubles, not
// certified: the reported move and witnesses).
struct Foot {
  Vec2 y = Vec2::Zero(), n = Vec2(1, 0);
};
Foot section_foot(const Section& T, const Vec2& p) {
  Foot best;
  double best_d = kInf, best_f = -kInf;
  bool inside = true;
  Vec2 inner_n(1, 0);
  for (int i = 0; i + 1 < T.n; ++i) {
    const Vec2 &a = T.v[i], &b = T.v[i + 1], d = b - a;
    const Vec2 n = Vec2(-d[1], d[0]).normalized();
    const double f = n.dot(p - a);
    if (f > 0) inside = false;
    if (f > best_f) best_f = f, inner_n = n;
    const double lam = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const Vec2 y = a + lam * d;
    if (const double dist = (p - y).norm(); dist < best_d) best_d = dist, best.y = y, best.n = dist > 0 ? Vec2((p - y) / dist) : n;
  }
  if (inside) best.y = p - best_f * inner_n, best.n = inner_n;
  return best;
}

// ---- The spheroid's meridian ellipse E (semi-axes a along ρ, c along z) -------------------------
// sd_E(p) = max over unit u of ⟨u, p⟩ − h_E(u), h_E(u) = |(a·u_ρ, c·u_z)| (fact (2)), both inside
// and outside; with p in the closed first quadrant (z replaced by |z|: E is symmetric) a maximiser
// lies in the closed first quadrant too (turning a component of u to p's sign raises ⟨u, p⟩ and
// keeps h_E). That quadrant is covered by u = (1, s) and u = (s, 1), s ∈ [0, 1] (unnormalised: the
// value is G(s) = (⟨u, p⟩ − h_E(u))/|u|, h_E 1-homogeneous). So sd_E(p) = max of G over the two
// halves, a 1D maximisation, certified in three steps:
//  (a) the maximiser in doubles (not certified, only where to look): per half, G on a 9-point grid,
//    then safeguarded Newton on G' = 0 in the grid cell around the best point (a step leaving the
//    bracket where G' changes sign bisects instead), or the grid's end when G' does not change
//    sign there; s*_k the result in half k;
//  (b) lower: G at any s (an outward interval's lower end) — a supporting line; taken at s*_k and at
//    every expansion point below, the best is the lower bound;
//  (c) upper: each half's [0, 1] is covered by boxes S (at first [0, s* − w], [s* − w, s* + w],
//    [s* + w, 1], w = 1/4, the empty ones left out); on S with an expansion point e ∈ S
//    (s* when in S, else S's end nearest s*) and T = S − e, for every s ∈ S Taylor's theorem with
//    the Lagrange remainder gives G(s) = G(e) + G'(e)(s − e) + ½G''(ξ)(s − e)², ξ between e and s
//    (G is C² on [0, 1]: S > 0, W > 0 below), so on each side of e, with t = |s − e| ∈ [0, w_±],
//    b = G'(e)'s upper (right) or minus its lower (left) end and c = G''(S)'s upper end,
//    G(s) <= G(e) + b·t + ½c·t² <= G(e) + quadratic_rise(b, c, w_±) (proved at that function);
//    and the mean value theorem gives G(S) ⊆ G(e) + G'(S)·T; the box's upper end is the lesser of
//    the two, G'(S), G''(S) naive interval enclosures. Near the maximiser G'(e) ~ 0 and G''(S) < 0
//    (a non-degenerate maximum), so the box [s* ± w] closes at once: its upper end is G(e) +
//    min(|G'(e)|·w, G'(e)²/2|c|); away from it G falls and a few splits suffice. Boxes whose upper end falls below the lower bound cannot hold the
//    maximum and are dropped; until the gap meets the target, the box of the largest upper end
//    is halved (each half keeps an expansion point by the rule above); the upper bound is the
//    largest upper end of the kept boxes (together they cover both halves).
// (a) only chooses the boxes and expansion points, so a wrong s* costs boxes, never validity.
// In one half's own names, u = (1, s) with p = (p_f, p_v) and semi-axes (k_f, k_v) along them
// (the other half swaps ρ and z): N = p_f + p_v·s − S, S = √(k_f² + k_v² s²), W = √(1 + s²),
// G = N/W, G' = N'/W − N·s/W³, G'' = N''/W − 2N'·s/W³ + N·(2s² − 1)/W⁵ with N' = p_v − k_v² s/S,
// N'' = −k_f² k_v²/S³ (S' = k_v² s/S, S'' = k_v²/S − k_v⁴ s²/S³ = k_f² k_v²/S³; (1/W)' = −s/W³,
// (1/W)'' = (2s² − 1)/W⁵).
// On the spheroid's axis with the centre inside (a ring of nearest points in 3D) the maximiser is
// an end of a half: no continuum in the meridian plane.
// Cost: the target is a 2⁻⁴⁶ relative gap (or 2⁻⁵² of the scale at a contact, or G's own rounding
// at the top box's expansion point); measured over 20,000 random spheroids and points: 4–10 boxes
// for 86 %, mean 7.8, 99th percentile 22, worst 84 (deep inside, where G is flat); each box one G,
// G' at a point and one G', G'' over the box (docs/benchmarks.md "Ball pairs against spheroids");
// at most kMaxEllipseBoxes (the caller then intersects with EPA).
constexpr int kMaxEllipseBoxes = 2000;

// One half's terms, in doubles for step (a) and in outward intervals for (b), (c) — the same
// formulas (header): Num = double (rounded to nearest) or Interval (the products with a factor
// >= 0 and the quotients by one > 0 by directed.hpp's mul_nonneg and div_pos; each result an
// enclosure over the interval s ⊆ [0, 1]).
double mul_nonneg(double a, double b) { return a * b; }
double div_pos(double a, double b) { return a / b; }
double root_of(double x) { return std::sqrt(x); }
Interval root_of(const Interval& x) { return sqrt(x); }
template <class Num>
Num lift(double x) {
  if constexpr (std::is_same_v<Num, double>) return x;
  else return iv(x);
}
template <class Num>
struct Half {
  Num pf, pv;  // (both >= 0)
  Num kf2, kv2, kfkv2;  // k_f², k_v², k_f² k_v²
  Half(const Num& f, const Num& v, double kf, double kv) : pf(f), pv(v) {
    kf2 = lift<Num>(kf) * lift<Num>(kf), kv2 = lift<Num>(kv) * lift<Num>(kv), kfkv2 = kf2 * kv2;
  }
};
template <class Num>
struct Terms {
  Num s, s2, S, W2, W, W3, N, N1;
};
template <class Num>
Terms<Num> half_terms(const Half<Num>& h, const Num& s) {
  Terms<Num> t;
  t.s = s, t.s2 = mul_nonneg(s, s), t.S = root_of(h.kf2 + mul_nonneg(h.kv2, t.s2));
  t.W2 = lift<Num>(1) + t.s2, t.W = root_of(t.W2), t.W3 = mul_nonneg(t.W2, t.W);
  t.N = h.pf + mul_nonneg(h.pv, s) - t.S, t.N1 = h.pv - div_pos(mul_nonneg(h.kv2, s), t.S);
  return t;
}
template <class Num>
Num value(const Terms<Num>& t) {
  return div_pos(t.N, t.W);
}
template <class Num>
Num slope(const Terms<Num>& t) {
  return div_pos(t.N1, t.W) - div_pos(mul_nonneg(t.N, t.s), t.W3);
}
template <class Num>
Num curvature(const Half<Num>& h, const Terms<Num>& t) {
  const Num N2 = -div_pos(h.kfkv2, mul_nonneg(mul_nonneg(t.S, t.S), t.S));
  return div_pos(N2, t.W) - div_pos(mul_nonneg(mul_nonneg(t.N1, t.s), lift<Num>(2)), t.W3) +
         div_pos(t.N * (lift<Num>(2) * t.s2 - lift<Num>(1)), mul_nonneg(t.W3, t.W2));
}

// Step (a) in doubles: G, G', G'' at s.
struct HalfD {
  Half<double> h;
  double g(double s) const { return value(half_terms(h, s)); }
  double d1(double s) const { return slope(half_terms(h, s)); }
  double d2(double s) const { return curvature(h, half_terms(h, s)); }
};
double half_argmax(const HalfD& h) {
  constexpr int kGrid = 8;
  int best = 0;
  double best_g = -kInf;
  for (int i = 0; i <= kGrid; ++i)
    if (const double v = h.g(double(i) / kGrid); v > best_g) best_g = v, best = i;
  double lo = std::max(0, best - 1) / double(kGrid), hi = std::min(kGrid, best + 1) / double(kGrid);
  const bool rising = h.d1(lo) > 0, falling = h.d1(hi) < 0;
  if (!rising || !falling) return !rising && best == 0 ? 0.0 : !falling && best == kGrid ? 1.0 : best / double(kGrid);
  double s = best / double(kGrid);
  for (int it = 0; it < 40; ++it) {  // the bracket [lo, hi] keeps G'(lo) > 0 > G'(hi)
    const double d = h.d1(s);
    if (d == 0 || !(std::isfinite(d))) break;
    (d > 0 ? lo : hi) = s;
    const double dd = h.d2(s), next = dd < 0 ? s - d / dd : lo + (hi - lo) / 2;
    const double step = next > lo && next < hi ? next : lo + (hi - lo) / 2;
    if (step == s || hi - lo <= 0x1p-50) break;
    s = step;
  }
  return s;
}

// An upper bound of b·t + ½c·t² over t ∈ [0, w] (rounded up): 0 when b <= 0 and c <= 0; for
// c < 0 both b·w (the quadratic term is <= 0) and b²/(2|c|) (the parabola's vertex value); for
// c >= 0, b·w + ½c·w² (each term at t = w is its largest, b > 0 or not: max with 0 at t = 0).
double quadratic_rise(double b, double c, double w) {
  if (!(std::isfinite(b) && std::isfinite(c))) return kInf;  // (no bound: the mean value form's stands)
  if (b <= 0 && c <= 0) return 0;
  if (c < 0) return std::min(mul(b, w, +1), quot(mul(b, b, +1), mul(2, -c, -1), +1));
  return std::max(0.0, add(mul(b, w, +1), mul(mul(0.5, c, +1), mul(w, w, +1), +1), +1));
}

struct EllipseSd {
  Interval sd;
  Foot foot;
};
EllipseSd ellipse_sd(const Section& E, const Interval& rho, double z0) {
  const double z = std::abs(z0);
  const std::array<Half<Interval>, 2> halves{Half<Interval>{rho, iv(z), E.a, E.c}, Half<Interval>{iv(z), rho, E.c, E.a}};
  const double rho_mid = rho.lo + (rho.hi - rho.lo) / 2;
  const bool seeded = ellipse_seed >= 0 && ellipse_seed <= 1;
  const std::array<double, 2> star =
      seeded ? std::array<double, 2>{ellipse_seed, ellipse_seed}
             : std::array<double, 2>{half_argmax({Half<double>{rho_mid, z, E.a, E.c}}), half_argmax({Half<double>{z, rho_mid, E.c, E.a}})};
  struct Box {
    int half;
    double s0, s1, up, at;  // at: G(e)'s upper end
  };
  std::vector<Box> boxes;
  boxes.reserve(16);
  const double scale = rho.hi + z + std::max(E.a, E.c);
  double lower = -kInf;
  int best_half = 0;
  double best_s = 0;
  const auto note = [&](int k, double s, const Interval& v) {
    if (v.lo > lower) lower = v.lo, best_half = k, best_s = s;
  };
  const auto push = [&](int k, double s0, double s1) {  // step (c) on [s0, s1]
    const double s = star[k], e = s >= s0 && s <= s1 ? s : s < s0 ? s0 : s1;
    const Terms<Interval> at = half_terms(halves[k], iv(e)), over = half_terms(halves[k], Interval{s0, s1});
    const Interval g = value(at), d1 = slope(at), box_d1 = slope(over), box_d2 = curvature(halves[k], over);
    note(k, e, g);
    const Interval T{sub(s0, e, -1), sub(s1, e, +1)};
    const double rise = std::max(quadratic_rise(d1.hi, box_d2.hi, T.hi), quadratic_rise(-d1.lo, box_d2.hi, -T.lo));
    const double taylor = add(g.hi, rise, +1), mean_value = (g + box_d1 * T).hi;
    boxes.push_back({k, s0, s1, std::min(taylor, mean_value), g.hi});
  };
  constexpr double kW = 1.0 / 4;
  for (int k = 0; k < 2; ++k) {
    const double s = star[k], a = std::max(0.0, s - kW), b = std::min(1.0, s + kW);
    if (a > 0) push(k, 0, a);
    push(k, a, b);
    if (b < 1) push(k, b, 1);
  }
  for (int n = int(boxes.size()); n < kMaxEllipseBoxes; n += 2) {
    std::erase_if(boxes, [&](const Box& b) { return b.up < lower; });
    const auto top = std::max_element(boxes.begin(), boxes.end(), [](const Box& x, const Box& y) { return x.up < y.up; });
    // The target, or the floor; or the top box's upper end is within it of G at its own
    // expansion point (the rest of the gap is G's rounding there, which no split narrows).
    if (top->up - std::max(lower, top->at) <= std::max(0x1p-46 * std::abs(lower), 0x1p-52 * scale)) break;
    const Box b = *top;
    const double m = b.s0 + (b.s1 - b.s0) / 2;
    if (!(m > b.s0 && m < b.s1)) break;  // (the rounding floor: s cannot be split further)
    boxes.erase(top);
    push(b.half, b.s0, m), push(b.half, m, b.s1);
  }
  double upper = -kInf;
  for (const Box& b : boxes) upper = std::max(upper, b.up);
  // The foot along the best direction: the boundary point with outward normal u (∇h_E(u)).
  const Vec2 u = (best_half == 0 ? Vec2(1, best_s) : Vec2(best_s, 1)).normalized();
  const double h = std::hypot(E.a * u[0], E.c * u[1]), sz = z0 < 0 ? -1.0 : 1.0;
  return {{lower, std::max(upper, lower)}, Foot{Vec2(E.a * E.a * u[0] / h, sz * E.c * E.c * u[1] / h), Vec2(u[0], sz * u[1])}};
}

// The body's signed distance at a point x known to within e (its own frame), the normal and the
// point of ∂A nearest x (rounding included).
struct BodySd {
  Interval sd;
  Vec3 normal = Vec3::UnitX(), surface = Vec3::Zero();
};
BodySd body_sd(const Support3& A, const Section& T, const Vec3& x, double e) {
  const double rho_lo = hypot_dir(x[0], x[1], -1), rho_hi = hypot_dir(x[0], x[1], +1);
  BodySd out;
  // (4): monotone in ρ; (1): e and the rounding radius shift both ends.
  const double rho = std::hypot(x[0], x[1]);
  EllipseSd es;
  if (T.ellipse) es = ellipse_sd(T, Interval{rho_lo, rho_hi}, x[2]);
  const double lo = T.ellipse ? es.sd.lo : section_sd(T, Vec2(rho_lo, x[2])).lo;
  const double hi = T.ellipse ? es.sd.hi : section_sd(T, Vec2(rho_hi, x[2])).hi;
  out.sd = {sub(sub(lo, e, -1), A.radius, -1), sub(add(hi, e, +1), A.radius, +1)};
  const Vec3 radial = rho > 0 ? Vec3(x[0] / rho, x[1] / rho, 0) : Vec3::UnitX();
  const Foot f = T.ellipse ? es.foot : section_foot(T, Vec2(rho, x[2]));
  out.normal = (f.n[0] * radial + Vec3(0, 0, f.n[1])).normalized();
  out.surface = f.y[0] * radial + Vec3(0, 0, f.y[1]) + A.radius * out.normal;
  return out;
}

// A 3-vector bracketed componentwise: a double point within e of every point of the box.
struct Fuzzy {
  Vec3 x = Vec3::Zero();
  double e = 0;
};
Fuzzy fuzzy(const std::array<Interval, 3>& b) {
  Fuzzy f;
  double sq = 0;
  for (int k = 0; k < 3; ++k) {
    f.x[k] = b[k].lo + (b[k].hi - b[k].lo) / 2;
    const double w = std::max(sub(f.x[k], b[k].lo, +1), sub(b[k].hi, f.x[k], +1));
    sq = add(sq, mul(w, w, +1), +1);
  }
  f.e = root(sq, +1);
  return f;
}

// M's signed distance when Q is the ball (P the body): c = R q0 + t.
BallSd ball_q(const Support3& P, const Section& T, const Ball& q, const Eigen::Matrix3d& R, const Vec3& t) {
  std::array<Interval, 3> c;
  for (int k = 0; k < 3; ++k) c[k] = iv(R(k, 0)) * iv(q.centre[0]) + iv(R(k, 1)) * iv(q.centre[1]) + iv(R(k, 2)) * iv(q.centre[2]) + iv(t[k]);
  const Fuzzy x = fuzzy(c);  // (q0 = 0: x = t exactly, e = 0)
  const Interval r = q.r * stretch(R);
  const BodySd b = body_sd(P, T, x.x, x.e);
  BallSd out;
  out.lo = sub(b.sd.lo, r.hi, -1), out.hi = sub(b.sd.hi, r.lo, +1);
  out.normal = b.normal;
  out.touch_p = b.surface, out.touch_q = x.x - q.r.lo * b.normal;
  return out;
}

// M's signed distance when P is the ball (Q the body): x = Rᵀ(p0 − t) in Q's frame, widened by the
// distance from R to an orthogonal matrix (header).
BallSd ball_p(const Ball& p, const Support3& Q, const Section& T, const Eigen::Matrix3d& R, const Vec3& t) {
  std::array<Interval, 3> y, c;
  for (int k = 0; k < 3; ++k) y[k] = iv(p.centre[k]) - iv(t[k]);
  for (int k = 0; k < 3; ++k) c[k] = iv(R(0, k)) * y[0] + iv(R(1, k)) * y[1] + iv(R(2, k)) * y[2];
  Fuzzy x = fuzzy(c);
  const Interval s = stretch(R);
  const double eta = std::max(sub(1, s.lo, +1), sub(s.hi, 1, +1));
  if (eta > 0) {
    x.e = add(x.e, mul(eta, add(Q.rho, norm_up(y[0], y[1], y[2]), +1), +1), +1);
  }
  const BodySd b = body_sd(Q, T, x.x, x.e);
  BallSd out;
  out.lo = sub(b.sd.lo, p.r.hi, -1), out.hi = sub(b.sd.hi, p.r.lo, +1);
  out.normal = -(R * b.normal).normalized();
  out.touch_q = R * b.surface + t, out.touch_p = p.centre + p.r.lo * out.normal;
  return out;
}

}  // namespace

std::optional<BallSd> ball_signed_distance(const Support3& P, const Support3& Q, const Eigen::Matrix3d& R, const Vec3& t) {
  if (!ball_enabled) return std::nullopt;
  if (const auto q = ball_of(Q)) {
    if (const auto T = section_of(P)) return ball_q(P, *T, *q, R, t);
  }
  if (const auto p = ball_of(P)) {
    if (const auto T = section_of(Q)) return ball_p(*p, Q, *T, R, t);
  }
  return std::nullopt;
}

}  // namespace pendepth::primitives
