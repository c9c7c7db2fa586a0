// Exact signed distance of two posed convex polytopes: GJK (Gilbert–Johnson–Keerthi 1988; van den
// Bergen 2003; Ericson, Real-Time Collision Detection §9.5) on the implicit M = P ⊕ (−Q') with
// every decision an exact sign, then σ (minimum_expand.cpp) when 0 ∈ M. The same exact pair
// machinery also serves the shape cast's fast path (shape_cast_certified, at the end of this
// file; cast3.cpp): a GJK ray cast in doubles whose answer is certified exactly.
//
// Contract (include/pendepth/depth3.hpp, Distance3): dist(0, M) when 0 ∉ M — the Euclidean
// distance of P and Q' — with witnesses and the features that define it; 0 when 0 ∈ ∂M
// (touching); −σ when 0 ∈ int M.
//
// Notation as in minimum_expand.cpp: P fixed, Q' = R Q + tq − tp (exact semantics for the double
// R, tq, tp), a point of M kept symbolically as a pair (i, j): m = p_i − q'_j. The simplex X holds
// at most 4 affinely independent pairs and the closest point w of conv(X) to 0, written
// w = Σ_{k∈S} λ_k m_k with λ > 0 on the subset S.
//
// Why the answer is exact:
//  * Closest point of conv(X) (Johnson's sub-algorithm, exact): a subset S of X is accepted iff
//    its barycentric coordinates of the projection of 0 onto aff(S) are all > 0 (exact signs of
//    dets: λ_a ∝ n·(b × c) for a triangle, λ_b ∝ −a·(b − a) for a segment) and every other point
//    y of X satisfies w_S·(y − a) ≥ 0. Then w_S ∈ conv(X) and conv(X) lies in the half-space
//    {w_S·x ≥ |w_S|²}: w_S is the closest point. Exactly one S passes (the face whose relative
//    interior holds the closest point). If w_S = 0 exactly (0 on aff(S) inside conv(S), or 0
//    inside the tetrahedron) then 0 ∈ M: σ (minimum_expand.cpp) tells overlap (−σ) from touching
//    (0). The direction U is a polynomial positive multiple of w_S: m_a (vertex),
//    |e|² a − (a·e) e (segment, e = b − a), ±n with n = (b − a) × (c − a) (triangle, the sign of
//    n·a).
//  * Support: i minimising U·p over P and j maximising U·q' over Q' (so m_ij minimises U·m over
//    M). Hill climbing in doubles from the previous answer proposes (i, j); if m_ij is strictly
//    closer than the plane (exact sign of U·(m_ij − a) < 0) it joins X — the distance strictly
//    decreases, so no simplex repeats and the loop ends. Otherwise (i, j) is certified by an
//    exact climb: on a convex polytope a vertex with no strictly better neighbour (exact signs
//    over the level-0 adjacency, flat-facet diagonals included) is a global optimum. If the
//    certified pair is still not strictly closer, then M ⊂ {U·x ≥ U·w_S}: dist(0, M) ≥ |w_S|,
//    and w_S ∈ conv(X) ⊂ M gives equality.
//  * Value: |w_S| = |m_a|, |e × a|/|e| or |n·a|/|n|, every polynomial (coordinates of m_a,
//    e × a, e, n, and n·a) evaluated to ~1 ulp (double-double, exact tiers when its bound fails),
//    norms by stableNorm, one division: within ~3 ulps (1 ulp measured against CGAL).
// Predicates: each sign is first evaluated from the simplex points cached as doubles with a
// rigorous error bound (exact::Fl), then exact::exact_sign (double-double, expansions, GMP).
//
// Fast path (gjk_fast, tried first): the loop in plain doubles (supports by a linear scan of
// shapes of ≤ 64 vertices), then one filtered certificate of its final simplex that also proves
// it non-degenerate (support faces exactly S's vertices), so the exact loop could only have
// ended on the same S; the value is computed by the same code on S in canonical order: the same
// bits (see gjk_fast). Uncertified → the exact loop. The value's double-double evaluation
// resolves the structural zeros of its components (FlX / FlZ) as the general per-component
// evaluation would, without its exact tiers (SignedDistancePath::quick_value; tests compare).
//
// Result: witnesses = Σ λ_k p_{i_k} and Σ λ_k q'_{j_k} (λ rounded), normal = −U/|U| (from P
// towards Q), features = the distinct P (Q) vertices of S: one vertex, an edge (a level-0
// half-edge; a flat-facet diagonal is reported as a face), or a face (a level-0 triangle in
// the support plane containing the witness, up to rounding).
// Complexity: O(k·(c + 1)) for k GJK iterations (a handful on real hulls; at most the number of
// simplices of M in theory) and c the climb lengths (O(1) from warm starts). DEPARTURE from the
// O(log n · log m) DK separation of DHS §5: GJK is output-sensitive like σ's expansion, and an
// order of magnitude faster on hulls of up to hundreds of vertices (docs/benchmarks.md).
#include <pendepth/depth3.hpp>

#include "convex3/distance_compare.hpp"
#include "convex3/minimum_expand.hpp"
#include "convex3/polytope_data.hpp"
#include "geometry/exact.hpp"
#include "geometry/isa.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <limits>
#include <optional>
#include <cmath>
#include <type_traits>

namespace pendepth {

namespace convex3 {

namespace {

using exact::exact_sign;
using exact::Fl;
using exact::LiftFl;

template <class T>
using V3 = std::array<T, 3>;
template <class L>
using Num = decltype(std::declval<L>()(0.0));

template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
V3<T> sub(const V3<T>& a, const V3<T>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class T>
V3<T> scale(const T& s, const V3<T>& a) {
  return {s * a[0], s * a[1], s * a[2]};
}

// FlX (exact doubles) that also knows a product with an exact zero factor is exactly 0: proves
// the structural zeros of the value's polynomials (axis-aligned edges) without the exact tiers.
// `exact` means: the formula's real value is exactly v.
struct FlZ {
  double v = 0;
  bool exact = true;
};
inline FlZ operator+(FlZ a, FlZ b) {
  const exact::FlX r = exact::FlX{a.v, a.exact} + exact::FlX{b.v, b.exact};
  return {r.v, r.exact};
}
inline FlZ operator-(FlZ a) { return {-a.v, a.exact}; }
inline FlZ operator-(FlZ a, FlZ b) { return a + (-b); }
inline FlZ operator*(FlZ a, FlZ b) {
  if ((a.exact && a.v == 0) || (b.exact && b.v == 0)) return {0.0, true};
  const exact::FlX r = exact::FlX{a.v, a.exact} * exact::FlX{b.v, b.exact};
  return {r.v, r.exact};
}
struct LiftFlZ {
  FlZ operator()(double x) const { return {x, true}; }
};

// Plain doubles: the rounded guess of Johnson's sub-algorithm (verified exactly afterwards).
struct LiftD {
  double operator()(double x) const { return x; }
};

// The first operations on input doubles — lift(a)·lift(b), lift(a) − lift(b), lift(a)·x (mul,
// diff, mul_x) — for the filter's Fl and the double-double DD (the value, and exact_sign's DD
// tier; DV: DD's hi and lo alone, by the same operations) without the terms of a lifted
// double's zero error and lo parts, which their operators compute (IEEE arithmetic cannot fold
// x·0): the value and the bound e bit for bit — the dropped terms add +0 to a sum of
// non-negative terms, or ±0 to a nonzero error term — DD's lo up to the sign of a zero. A
// zero's sign reaches no nonzero result (x + ±0 = x, ±0·y = ±0, no division in these
// polynomials); non-finite stays non-finite in both. The identity dumps
// (scripts/distance_identity.sha256, sigma_identity.sha256: hashed with the lifted operators)
// keep their hashes on both paths. Other lifts: their own operations.
namespace plain {

template <class L>
Num<L> mul(L lift, double a, double b) {
  if constexpr (std::is_same_v<L, LiftFl>) {
    const double v = a * b;
    return {v, std::abs(v) * exact::kUnit + exact::kTiny};
  } else if constexpr (std::is_same_v<L, exact::LiftDV>) {
    const double p = a * b;
    exact::DV r;
    exact::quick_two_sum(p, std::fma(a, b, -p), r.hi, r.lo);
    return r;
  } else if constexpr (std::is_same_v<L, exact::LiftDD>) {
    const exact::DV v = mul(exact::LiftDV{}, a, b);
    const double ma = std::abs(a) * (1 + 0x1p-50), mb = std::abs(b) * (1 + 0x1p-50);
    return {v.hi, v.lo, ma * mb * exact::kUnitDD + exact::kTiny};
  } else {
    return lift(a) * lift(b);
  }
}
template <class L>
Num<L> diff(L lift, double a, double b) {
  if constexpr (std::is_same_v<L, LiftFl>) {
    const double v = a - b;
    return {v, std::abs(v) * exact::kUnit};
  } else if constexpr (std::is_same_v<L, exact::LiftDV>) {
    exact::DV r;
    exact::two_sum(a, -b, r.hi, r.lo);  // the exact difference: DD's renormalisations keep it
    return r;
  } else if constexpr (std::is_same_v<L, exact::LiftDD>) {
    const exact::DV v = diff(exact::LiftDV{}, a, b);
    return {v.hi, v.lo, (std::abs(a) + std::abs(b)) * exact::kUnitDD};
  } else {
    return lift(a) - lift(b);
  }
}
template <class L>
Num<L> mul_x(L lift, double a, const Num<L>& x) {
  if constexpr (std::is_same_v<L, LiftFl>) {
    const double v = a * x.v;
    return {v, std::abs(a) * x.e + std::abs(v) * exact::kUnit + exact::kTiny};
  } else if constexpr (std::is_same_v<L, exact::LiftDV>) {
    const double p = a * x.hi;
    const double err = std::fma(a, x.hi, -p) + a * x.lo;
    exact::DV r;
    exact::quick_two_sum(p, err, r.hi, r.lo);
    return r;
  } else if constexpr (std::is_same_v<L, exact::LiftDD>) {
    const exact::DV v = mul_x(exact::LiftDV{}, a, exact::DV{x.hi, x.lo});
    const double ma = std::abs(a) * (1 + 0x1p-50), mb = std::abs(x.hi) * (1 + 0x1p-50);
    return {v.hi, v.lo, ma * x.e + ma * mb * exact::kUnitDD + exact::kTiny};
  } else {
    return lift(a) * x;
  }
}

}  // namespace plain

struct PairId {
  int i = -1, j = -1;
  friend bool operator==(const PairId&, const PairId&) = default;
};

// A simplex point: its pair, and its coordinates as Fl (value + rigorous error bound).
struct Member {
  PairId id;
  V3<Fl> fl;
};

struct Ctx {
  const PolytopeData& P;
  const PolytopeData& Q;
  const RelativePose& rel;
  /// When set: every point is mapped by the linear projection π(v) = (d·d)v − (v·d)d along d
  /// (0 ∈ π(M) ⇔ the line s·d meets M; used to certify that a cast's line misses M).
  const Vec3* proj = nullptr;
  /// When set: Q is moved further by lam·od (world frame), kept exact in P's frame as
  /// Σ_l RpT(k, l)·od_l·lam (distance_compare: the points of a ray, never rounded).
  const Eigen::Matrix3d* RpT = nullptr;
  Vec3 od{0, 0, 0};
  double lam = 0;
  Vec3 off_approx{0, 0, 0};  ///< the same offset rounded (proposals only)

  template <class L>
  V3<Num<L>> project(L lift, const V3<Num<L>>& v) const {
    if (!proj) return v;
    const V3<Num<L>> d{lift((*proj)[0]), lift((*proj)[1]), lift((*proj)[2])};
    return sub(scale(dot(d, d), v), scale(dot(v, d), d));
  }
  Vec3 project(const Vec3& v) const { return proj ? Vec3(proj->squaredNorm() * v - v.dot(*proj) * *proj) : v; }

  template <class L>
  V3<Num<L>> qplaced(L lift, int j) const {
    const Vec3& q = Q.v[j];
    V3<Num<L>> r;
    for (int k = 0; k < 3; ++k)
      r[k] = plain::mul(lift, rel.R(k, 0), q[0]) + plain::mul(lift, rel.R(k, 1), q[1]) +
             plain::mul(lift, rel.R(k, 2), q[2]) + plain::diff(lift, rel.tq[k], rel.tp[k]);
    if (RpT)
      for (int k = 0; k < 3; ++k)
        r[k] = r[k] + lift(lam) * (lift((*RpT)(k, 0)) * lift(od[0]) + lift((*RpT)(k, 1)) * lift(od[1]) +
                                   lift((*RpT)(k, 2)) * lift(od[2]));
    return project(lift, r);
  }
  template <class L>
  V3<Num<L>> pvec(L lift, int i) const {
    return project(lift, V3<Num<L>>{lift(P.v[i][0]), lift(P.v[i][1]), lift(P.v[i][2])});
  }
  template <class L>
  V3<Num<L>> m(L lift, PairId s) const {
    return sub(pvec(lift, s.i), qplaced(lift, s.j));
  }
  // A member's point: the cached Fl in the first tier, recomputed in the others.
  template <class L>
  V3<Num<L>> pt(L lift, const Member& x) const {
    if constexpr (std::is_same_v<L, LiftFl>)
      return x.fl;
    else if constexpr (std::is_same_v<L, LiftD>)
      return {x.fl[0].v, x.fl[1].v, x.fl[2].v};
    else
      return m(lift, x.id);
  }
  // m_x − m_y written structurally: p_x − p_y (same j), −R(q_x − q_y) (same i), or both; the
  // same exact value with a smaller degree and tighter filter bounds.
  template <class L>
  V3<Num<L>> dm(L lift, PairId x, PairId y) const {
    V3<Num<L>> r{lift(0.0), lift(0.0), lift(0.0)};
    if (x.i != y.i)
      for (int k = 0; k < 3; ++k) r[k] = plain::diff(lift, P.v[x.i][k], P.v[y.i][k]);
    if (x.j != y.j) {
      const Vec3 &qa = Q.v[x.j], &qb = Q.v[y.j];
      const Num<L> d0 = plain::diff(lift, qa[0], qb[0]), d1 = plain::diff(lift, qa[1], qb[1]),
                   d2 = plain::diff(lift, qa[2], qb[2]);
      for (int k = 0; k < 3; ++k)
        r[k] = r[k] - (plain::mul_x(lift, rel.R(k, 0), d0) + plain::mul_x(lift, rel.R(k, 1), d1) +
                       plain::mul_x(lift, rel.R(k, 2), d2));
    }
    return project(lift, r);
  }
  Member member(PairId s) const { return {s, m(LiftFl{}, s)}; }
  Vec3 approx_p(int i) const { return project(P.v[i]); }
  Vec3 approx_q(int j) const { return project(Vec3(rel.R * Q.v[j] + (rel.tq - rel.tp) + off_approx)); }
};

// The search direction of a subset S (size 1–3, S[0] = a): a polynomial positive multiple of
// the closest point w_S of aff(S) to 0 (tri_sign = sign of n·a for a triangle).
struct Dir {
  const Ctx* c;
  int size = 1;
  Member s[3];
  int tri_sign = 1;

  template <class L>
  V3<Num<L>> operator()(L lift) const {
    auto a = c->pt(lift, s[0]);
    if (size == 1) return a;
    auto e = c->dm(lift, s[1].id, s[0].id);
    if (size == 2) return sub(scale(dot(e, e), a), scale(dot(a, e), e));
    auto n = cross(e, c->dm(lift, s[2].id, s[0].id));
    return tri_sign > 0 ? n : V3<Num<L>>{-n[0], -n[1], -n[2]};
  }
};

// Exact sign of U·(x − y) given lazily: f(lift) returns the vector x − y. `zero`, asked only
// when the floating filter fails, may prove the value exactly 0 (else the exact tiers decide).
template <class F, class Z>
int dir_sign(const Dir& U, const V3<Fl>& Ufl, F&& diff, Z&& zero) {
  const int s = exact::certified_sign(dot(Ufl, diff(LiftFl{})));
  if (s != 2) return s;
  if (zero()) return 0;
  return exact_sign([&](auto L) { return dot(U(L), diff(L)); });
}
template <class F>
int dir_sign(const Dir& U, const V3<Fl>& Ufl, F&& diff) {
  return dir_sign(U, Ufl, std::forward<F>(diff), [] { return false; });
}

// Rounded steepest ascent of u·v from v (a proposal; certified later).
int climb_rounded(const PolytopeData& d, const VertexAdjacency& a, const Vec3& u, int v) {
  double bv = u.dot(d.v[v]);
  for (;;) {
    int next = -1;
    for (int e = a.start[v]; e < a.start[v + 1]; ++e)
      if (double s = u.dot(d.v[a.nbr[e]]); s > bv) bv = s, next = a.nbr[e];
    if (next < 0) return v;
    v = next;
  }
}

// Result of the closest-point step on X ∪ {new}.
struct Reduced {
  bool contact = false;  // 0 ∈ conv(S): 0 ∈ M
  int size = 0;
  Member s[4];
  int tri_sign = 1;
};

// Number of set bits of a 4-bit mask (a nibble table: std::popcount is a library call without
// -mpopcnt).
inline int bits4(int mask) { return static_cast<int>((0x4332322132212110ull >> (4 * mask)) & 0xF); }

// Exact sign of the barycentric numerators and the tests of Johnson's sub-algorithm.
class Johnson {
 public:
  explicit Johnson(const Ctx& c) : c_(c) {}

  // The closest point of conv(X) to 0 for affinely independent X (size 1–4, X[last] newest).
  Reduced reduce(const Member* X, int n) const {
    // Subsets as bit masks, those holding the newest point first, smallest first.
    const int all = (1 << n) - 1, newest = 1 << (n - 1);
    // A guess in doubles, verified exactly; the exact enumeration only when the guess fails.
    for (int size = 1; size <= n; ++size)
      for (int mask = 1; mask <= all; ++mask) {
        if (bits4(mask) != size || !(mask & newest)) continue;
        Reduced r;
        if (accept<false>(X, n, mask, r)) {
          if (accept<true>(X, n, mask, r)) return r;
          size = n + 1;
          break;
        }
      }
    for (int pass = 0; pass < 2; ++pass)
      for (int size = 1; size <= n; ++size)
        for (int mask = 1; mask <= all; ++mask) {
          if (bits4(mask) != size) continue;
          if (((mask & newest) != 0) != (pass == 0)) continue;
          Reduced r;
          if (accept<true>(X, n, mask, r)) return r;
        }
    // Unreachable for affinely independent X (exactly one face holds the closest point).
    Reduced r;
    r.size = 1;
    r.s[0] = X[n - 1];
    return r;
  }

 private:
  const Ctx& c_;

  template <bool kExact, class F>
  static int sgn(F&& f) {
    if constexpr (kExact) {
      return exact_sign(std::forward<F>(f));
    } else {
      const double v = f(LiftD{});
      return (v > 0) - (v < 0);
    }
  }

  template <bool kExact>
  bool accept(const Member* X, int nx, int mask, Reduced& r) const {
    int idx[4] = {}, k = 0, out[4] = {}, o = 0;
    for (int b = 0; b < nx; ++b) (mask >> b & 1 ? idx[k++] : out[o++]) = b;
    const Member* S[4] = {};
    for (int t = 0; t < k; ++t) S[t] = &X[idx[t]];
    r.size = k;
    for (int t = 0; t < k; ++t) r.s[t] = *S[t];
    auto P = [&](auto L, const Member* x) { return c_.pt(L, *x); };
    auto D = [&](auto L, const Member* x, const Member* y) { return c_.dm(L, x->id, y->id); };
    if (k == 4) {  // 0 inside the tetrahedron (closed): contact
      auto D = [&](auto L, int replace) {
        V3<Num<decltype(L)>> p[4];
        for (int t = 0; t < 4; ++t)
          p[t] = t == replace ? V3<Num<decltype(L)>>{L(0.0), L(0.0), L(0.0)} : P(L, S[t]);
        return dot(cross(sub(p[1], p[0]), sub(p[2], p[0])), sub(p[3], p[0]));
      };
      const int v = sgn<kExact>([&](auto L) { return D(L, -1); });
      if (v == 0) return false;  // never for affinely independent X (guard)
      for (int t = 0; t < 4; ++t)
        if (sgn<kExact>([&](auto L) { return D(L, t); }) * v < 0) return false;
      r.contact = true;
      return true;
    }
    if (k == 1) {
      auto a = [&](auto L) { return P(L, S[0]); };
      bool zero = true;
      for (int t = 0; t < 3 && zero; ++t) zero = sgn<kExact>([&](auto L) { return a(L)[t]; }) == 0;
      if (zero) return r.contact = true;
      for (int t = 0; t < o; ++t)
        if (sgn<kExact>([&](auto L) { return dot(a(L), D(L, &X[out[t]], S[0])); }) < 0) return false;
      return true;
    }
    if (k == 2) {
      // λ_a ∝ b·(b − a), λ_b ∝ −a·(b − a).
      if (sgn<kExact>([&](auto L) { return dot(P(L, S[1]), D(L, S[1], S[0])); }) <= 0) return false;
      if (sgn<kExact>([&](auto L) { return dot(P(L, S[0]), D(L, S[1], S[0])); }) >= 0) return false;
      bool zero = true;  // 0 on the segment's line: e × a = 0
      for (int t = 0; t < 3 && zero; ++t)
        zero = sgn<kExact>([&](auto L) { return cross(D(L, S[1], S[0]), P(L, S[0]))[t]; }) == 0;
      if (zero) return r.contact = true;
      Dir U{&c_, 2, {*S[0], *S[1], {}}, 1};
      for (int t = 0; t < o; ++t)
        if (sgn<kExact>([&](auto L) { return dot(U(L), D(L, &X[out[t]], S[0])); }) < 0) return false;
      return true;
    }
    // k == 3: λ_a ∝ n·(b × c), λ_b ∝ n·(c × a), λ_c ∝ n·(a × b).
    auto n = [&](auto L) { return cross(D(L, S[1], S[0]), D(L, S[2], S[0])); };
    for (int t = 0; t < 3; ++t)
      if (sgn<kExact>([&](auto L) { return dot(n(L), cross(P(L, S[(t + 1) % 3]), P(L, S[(t + 2) % 3]))); }) <= 0)
        return false;
    const int h = sgn<kExact>([&](auto L) { return dot(n(L), P(L, S[0])); });
    if (h == 0) return r.contact = true;
    r.tri_sign = h;
    for (int t = 0; t < o; ++t)
      if (h * sgn<kExact>([&](auto L) { return dot(n(L), D(L, &X[out[t]], S[0])); }) < 0) return false;
    return true;
  }
};

// f's value within ~1 ulp: double-double first (the formulas here are of high degree, so the
// plain floating tier of exact::accurate_value almost never certifies), then exact tiers.
template <class F>
double accurate_dd(F&& f) {
  const exact::DD r = f(exact::LiftDD{});
  if (exact::dd_finite(r) && exact::safe_bound(r.e) <= std::abs(r.hi) * 0x1p-54) return r.hi;
  const exact::FlX x = f(exact::LiftFlX{});  // exact zeros of float-like data (axis-aligned faces)
  if (x.exact) return x.v;
  return exact::accurate_value(std::forward<F>(f));
}

// The value of the final simplex V (vertex: dist = |a|, U = a; segment: dist = |e × a|/|e|,
// U = (e·e)a − (a·e)e; triangle: dist = |n·a|/|n|, U = ±n, n = e1 × e2; e_k = m_k − m_0,
// a = m_0) from double-doubles without their running error bounds (exact::DV), checked against
// bounds proven in advance from the inputs' magnitudes instead. Returns false (dist, u
// untouched) unless every check passes; the caller then runs the quick value with running
// bounds (exact::DD). Same bits: DV computes hi and lo by DD's operations, and each bound here
// is never smaller than the running bound DD computes for the same value, so a pass here is a
// pass of `ok` there and both report the hi of the same double-doubles.
//
// Proof (u = kUnitDD, τ = kTiny, g = 1 + 2⁻⁵⁰). DD's running bound is e = a.e + b.e +
// (|a.hi| + |b.hi|)·u for a sum or difference and g|a.hi|·b.e + g|b.hi|·a.e + a.e·b.e +
// g²|a.hi||b.hi|·u + τ for a product (plain::mul, diff, mul_x: the same with a.e = 0 or lo = 0);
// every result has |hi| ≤ g·(|a.hi| + |b.hi|) (sums) or ≤ g·|a.hi||b.hi| + 2⁻¹⁰⁷⁰ (products).
// Inputs: Lp, Lq the largest |coordinate| of V's P and Q vertices, Rm the largest |R_kl|, Lt the
// largest |tq_k| + |tp_k|. By induction along dm and m (each constant below is one more than
// the derivation's, and one τ more: that covers the g factors, the floating evaluation of both
// bounds and the absolute terms of underflow):
//   dm: diff(q) ≤ 2Lq·u; mul_x ≤ 4RmLq·u + τ; their sum ≤ 22RmLq·u + 3τ, |hi| ≤ 6RmLq; minus
//       diff(p) (≤ 2Lp·u, |hi| ≤ 2Lp):  e(e_k) ≤ (4Lp + 28RmLq)·u + 3τ            < Ee
//   m:  three mul ≤ RmLq·u + τ, then diff(t) ≤ Lt·u: ≤ 11RmLq·u + 2Lt·u + 3τ, |hi| ≤ 3RmLq + Lt;
//       p minus it:                     e(a_k) ≤ (Lp + 14RmLq + 3Lt)·u + 3τ         < Em
// Then, for operands whose components have |hi| ≤ H1, H2 (the largest measured) and running
// bounds ≤ E1, E2 (apriori_product, _cross, _dot; g ≤ 2, each product's |hi| ≤ 2H1H2, the
// dot's partial sum ≤ 5H1H2; the dot's constant is 12):
//   product: gH1E2 + gH2E1 + E1E2 + g²H1H2·u + τ ≤ P = 2(H1E2 + H2E1 + E1E2 + H1H2·u + τ)
//   cross component x − y: ≤ 2P + (|x.hi| + |y.hi|)·u ≤ 2P + 4H1H2·u
//   dot (x + y) + z: ≤ 3P + (|x.hi| + |y.hi|)·u + (|(x + y).hi| + |z.hi|)·u ≤ 3P + 11H1H2·u
// and the segment's U_k = s1·a_k − s2·e_k (s1 = e·e, s2 = a·e, measured |hi|) by two products
// and one difference likewise. A non-finite input makes a hi or lo non-finite or a bound
// infinite: no pass.
double apriori_product(double H1, double E1, double H2, double E2) {
  return 2 * (H1 * E2 + H2 * E1 + E1 * E2 + H1 * H2 * exact::kUnitDD + exact::kTiny);
}
double apriori_cross(double H1, double E1, double H2, double E2) {
  return 2 * apriori_product(H1, E1, H2, E2) + 4 * H1 * H2 * exact::kUnitDD;
}
double apriori_dot(double H1, double E1, double H2, double E2) {
  return 3 * apriori_product(H1, E1, H2, E2) + 12 * H1 * H2 * exact::kUnitDD;
}
double max_hi(const V3<exact::DV>& x) {
  return std::max({std::abs(x[0].hi), std::abs(x[1].hi), std::abs(x[2].hi)});
}
// DD's `ok` with a bound proven in advance: finite, and the bound below 2⁻⁵⁴|hi|.
bool apriori_pass(const exact::DV& x, double bound) {
  return exact::dv_finite(x) && exact::safe_bound(bound) <= std::abs(x.hi) * 0x1p-54;
}
bool apriori_pass(const V3<exact::DV>& x, double bound) {
  return apriori_pass(x[0], bound) && apriori_pass(x[1], bound) && apriori_pass(x[2], bound);
}
Vec3 hi3(const V3<exact::DV>& x) { return {x[0].hi, x[1].hi, x[2].hi}; }

bool value_a_priori(const Ctx& c, const Reduced& V, double& dist, Vec3& u) {
  constexpr double uu = exact::kUnitDD, tau = exact::kTiny;
  double Lp = 0, Lq = 0, Rm = 0, Lt = 0;
  for (int k = 0; k < V.size; ++k)
    for (int l = 0; l < 3; ++l) {
      Lp = std::max(Lp, std::abs(c.P.v[V.s[k].id.i][l]));
      Lq = std::max(Lq, std::abs(c.Q.v[V.s[k].id.j][l]));
    }
  for (int k = 0; k < 3; ++k) {
    for (int l = 0; l < 3; ++l) Rm = std::max(Rm, std::abs(c.rel.R(k, l)));
    Lt = std::max(Lt, std::abs(c.rel.tq[k]) + std::abs(c.rel.tp[k]));
  }
  const double RLq = Rm * Lq;
  const double Ee = (5 * Lp + 29 * RLq) * uu + 4 * tau;
  const double Em = (2 * Lp + 15 * RLq + 4 * Lt) * uu + 4 * tau;
  const exact::LiftDV D;
  const V3<exact::DV> a = c.m(D, V.s[0].id);
  const double Ha = max_hi(a);
  if (V.size == 1) {
    if (!apriori_pass(a, Em)) return false;
    u = hi3(a);
    dist = u.stableNorm();
    return true;
  }
  const V3<exact::DV> e1 = c.dm(D, V.s[1].id, V.s[0].id);
  const double He1 = max_hi(e1);
  if (V.size == 2) {
    const V3<exact::DV> x = cross(e1, a);
    const exact::DV s1 = dot(e1, e1), s2 = dot(a, e1);
    const V3<exact::DV> U = sub(scale(s1, a), scale(s2, e1));
    const double Hs1 = std::abs(s1.hi), Hs2 = std::abs(s2.hi);
    const double Es1 = apriori_dot(He1, Ee, He1, Ee), Es2 = apriori_dot(Ha, Em, He1, Ee);
    const double EU = apriori_product(Hs1, Es1, Ha, Em) + apriori_product(Hs2, Es2, He1, Ee) +
                      2 * (Hs1 * Ha + Hs2 * He1) * uu;
    const double Ex = apriori_cross(He1, Ee, Ha, Em);
    if (!(apriori_pass(x, Ex) && apriori_pass(e1, Ee) && apriori_pass(U, EU))) return false;
    u = hi3(U);
    dist = hi3(x).stableNorm() / hi3(e1).stableNorm();
    return true;
  }
  const V3<exact::DV> e2 = c.dm(D, V.s[2].id, V.s[0].id);
  const V3<exact::DV> n = cross(e1, e2);
  const exact::DV na = dot(n, a);
  const double En = apriori_cross(He1, Ee, max_hi(e2), Ee);
  if (!(apriori_pass(na, apriori_dot(max_hi(n), En, Ha, Em)) && apriori_pass(n, En))) return false;
  const Vec3 nv = hi3(n);
  u = V.tri_sign > 0 ? nv : Vec3(-nv);
  dist = std::abs(na.hi) / nv.stableNorm();
  return true;
}

// Ascending order of n ≤ 3 ints by insertion (std::sort's general case, inlined into the
// flattened x86-64-v3 clone, draws false -Warray-bounds warnings there).
void sort_small(int* a, int n) {
  for (int k = 1; k < n; ++k)
    for (int l = k; l > 0 && a[l] < a[l - 1]; --l) std::swap(a[l], a[l - 1]);
}

// The feature of one side spanned by the distinct vertices vs (1–3) of S on that side, all on
// the side's support plane for U: a vertex; a true edge (its two triangles not coplanar); else
// the true face containing them (the support set is then that face), reported as its level-0
// triangle around vs — one whose plane holds every vertex of vs (exact orient3d on the
// polytope's own vertices) — that best contains `wit` (the side's witness in its own frame;
// rounded barycentric coordinates). O(Σ degrees of vs); no outer hierarchy needed.
// `simple`: vs is known to be the whole support set (the fast path's certificate (c)), so two
// vertices are a true edge and three a level-0 triangle — the answers of the general search,
// without its orientation tests.
Feature3 feature_of(const ConvexPolytope& S, const int* vs, int nv, const Vec3& wit, bool simple = false) {
  const PolytopeData& D = data_of(S);
  if (nv == 1) return {FeatureKind3::Vertex, vs[0]};
  const DKLevel& L0 = D.levels[0];
  auto around = [&](int v, auto&& f) {
    const int h0 = D.vertex_he[v];
    int h = h0;
    do {
      f(h);
      h = L0.ccw(h);
    } while (h != h0);
  };
  if (simple) {
    int found = -1;
    around(vs[0], [&](int h) {
      if (nv == 2 && L0.target(h) == vs[1]) found = h;
      if (nv == 3) {
        const auto& T = D.tris[h / 3];
        auto has = [&](int x) { return T[0] == x || T[1] == x || T[2] == x; };
        if (has(vs[1]) && has(vs[2])) found = h / 3;
      }
    });
    if (found >= 0) return {nv == 2 ? FeatureKind3::Edge : FeatureKind3::Face, found};
  }
  if (nv == 2) {
    int edge = -1;
    around(vs[0], [&](int h) {
      if (L0.target(h) == vs[1]) edge = h;
    });
    if (edge >= 0) {
      const auto& T = D.tris[edge / 3];
      const int tw = L0.twin[edge];
      const int far = L0.fv[3 * (tw / 3) + (tw % 3 + 2) % 3];
      if (predicates::orient3d(D.v[T[0]], D.v[T[1]], D.v[T[2]], D.v[far]) != 0) return {FeatureKind3::Edge, edge};
    }
  }
  int best = -1;
  double best_score = 0;
  for (int k = 0; k < nv; ++k)
    around(vs[k], [&](int h) {
      const int t = h / 3;
      const auto& T = D.tris[t];
      for (int l = 0; l < nv; ++l)
        if (vs[l] != T[0] && vs[l] != T[1] && vs[l] != T[2] &&
            predicates::orient3d(D.v[T[0]], D.v[T[1]], D.v[T[2]], D.v[vs[l]]) != 0)
          return;
      const Vec3 a = D.v[T[0]], b = D.v[T[1]], c = D.v[T[2]];
      const Vec3 n = (b - a).cross(c - a);
      const double score =
          std::min({n.dot((b - wit).cross(c - wit)), n.dot((c - wit).cross(a - wit)), n.dot((a - wit).cross(b - wit))}) /
          n.squaredNorm();
      if (best < 0 || score > best_score) best = t, best_score = score;
    });
  return {FeatureKind3::Face, best};
}

}  // namespace

// Signed distance in P's frame for Q placed by rel; result in the world frame of (Rp, tp_world).
// The exact GJK loop (see the file comment) on c's points: the final simplex reduced to S,
// with contact = 0 ∈ conv(S). U and Ufl: S's direction.
struct GjkResult {
  Reduced X;
  bool contact = false;
};
// Out of line: the rare path (the fast path's certificate failed), kept out of the flattened
// x86-64-v3 clone below (it would multiply the clone's size and compile time; geometry/isa.hpp).
[[gnu::noinline]] GjkResult gjk_loop(const Ctx& c, const VertexAdjacency& aP, const VertexAdjacency& aQ) {
  const PolytopeData& PD = c.P;
  const PolytopeData& QD = c.Q;
  const RelativePose& rel = c.rel;
  const Johnson johnson(c);
  // First direction: from Q' towards P (centroids).
  Vec3 v = c.project(Vec3(aP.centroid - (rel.R * aQ.centroid + (rel.tq - rel.tp) + c.off_approx)));
  if (!v.allFinite() || v == Vec3::Zero()) v = Vec3::UnitX();
  // Support of M minimising v·m: P minimises v·p, Q' maximises v·q' = (Rᵀ v)·q.
  auto support = [&](const Vec3& u0, int i0, int j0) {
    const Vec3 u = c.project(u0);  // u0·π(m) = π(u0)·m
    const Vec3 uq = rel.R.transpose() * u;
    return PairId{climb_rounded(PD, aP, -u, i0 >= 0 ? i0 : seed_vertex(aP, -u)),
                  climb_rounded(QD, aQ, uq, j0 >= 0 ? j0 : seed_vertex(aQ, uq))};
  };
  PairId s = support(v, -1, -1);
  Reduced X;
  X.size = 1;
  X.s[0] = c.member(s);
  {
    Reduced r = johnson.reduce(X.s, 1);
    X = r;
  }
  Dir U{};
  V3<Fl> Ufl{};
  auto set_dir = [&]() {
    U = Dir{&c, X.size, {X.s[0], X.size > 1 ? X.s[1] : Member{}, X.size > 2 ? X.s[2] : Member{}}, X.tri_sign};
    Ufl = U(LiftFl{});
  };
  bool contact = X.contact;
  while (!contact) {
    set_dir();
    const Vec3 u(Ufl[0].v, Ufl[1].v, Ufl[2].v);
    s = support(u, s.i, s.j);
    const Member& a = X.s[0];
    // Pairs on the plane through X by construction: members, and the fourth corner
    // m_x + m_y − m_z of a parallelogram of members (x.i = s.i, y.j = s.j, z = (y.i, x.j)).
    auto member = [&](int i, int j) {
      for (int k = 0; k < X.size; ++k)
        if (X.s[k].id.i == i && X.s[k].id.j == j) return true;
      return false;
    };
    auto on_plane = [&](PairId x) {
      for (int u = 0; u < X.size; ++u)
        for (int v = 0; v < X.size; ++v)
          if (X.s[u].id.i == x.i && X.s[v].id.j == x.j && member(X.s[v].id.i, X.s[u].id.j)) return true;
      return false;
    };
    // U·(p_k − p_i) = U·(m_(k,j') − m_(i,j')) is 0 when both pairs are on the plane (same for Q).
    auto p_zero = [&](int k, int i) {
      for (int u = 0; u < X.size; ++u)
        if (on_plane({k, X.s[u].id.j}) && on_plane({i, X.s[u].id.j})) return true;
      return false;
    };
    auto q_zero = [&](int k, int j) {
      for (int u = 0; u < X.size; ++u)
        if (on_plane({X.s[u].id.i, k}) && on_plane({X.s[u].id.i, j})) return true;
      return false;
    };
    // A triangle of one side's vertices (all members share j, or all share i; plain points, no
    // projection or ray offset): U = ±(e₁ × e₂) with e the P edge vectors, or U = ±(R e₁ × R e₂)
    // with e the Q edge vectors, and (R a × R b)·(R d) = det(R)·(a × b)·d for any matrix R
    // (adjugate identity). So U·(x − y) on that side is exactly 0 whenever x and y both lie in
    // the triangle's plane (orient3d of the shape's own vertices: a flat facet of the hull) —
    // exact zeros known without the expansion tiers, asked only when the floating filter fails
    // (every other sign as before).
    const bool plain = !c.proj && !c.RpT && X.size == 3;
    const int side = !plain ? 0
                     : X.s[0].id.j == X.s[1].id.j && X.s[1].id.j == X.s[2].id.j ? 1
                     : X.s[0].id.i == X.s[1].id.i && X.s[1].id.i == X.s[2].id.i ? 2
                                                                                 : 0;
    auto coplanar = [&](const std::vector<Vec3>& pts, int x, bool p_side) {
      const int v0 = p_side ? X.s[0].id.i : X.s[0].id.j, v1 = p_side ? X.s[1].id.i : X.s[1].id.j,
                v2 = p_side ? X.s[2].id.i : X.s[2].id.j;
      return x == v0 || x == v1 || x == v2 || predicates::orient3d(pts[v0], pts[v1], pts[v2], pts[x]) == 0;
    };
    auto flat_zero_p = [&](int k, int i) { return side == 1 && coplanar(PD.v, k, true) && coplanar(PD.v, i, true); };
    auto flat_zero_q = [&](int k, int j) { return side == 2 && coplanar(QD.v, k, false) && coplanar(QD.v, j, false); };
    auto improves = [&](PairId x) {
      for (int k = 0; k < X.size; ++k)
        if (X.s[k].id == x) return false;
      if (on_plane(x)) return false;  // structurally on the plane
      return dir_sign(U, Ufl, [&](auto L) { return c.dm(L, x, a.id); }, [&] {
               return (x.j == a.id.j && flat_zero_p(x.i, a.id.i)) || (x.i == a.id.i && flat_zero_q(x.j, a.id.j));
             }) < 0;
    };
    if (!improves(s)) {
      // Certify (i, j) exactly: no neighbour strictly better.
      for (bool moved = true; moved;) {
        moved = false;
        for (int e = aP.start[s.i]; e < aP.start[s.i + 1] && !moved; ++e) {
          const int k = aP.nbr[e], i = s.i;
          if (p_zero(k, i)) continue;
          if (dir_sign(U, Ufl, [&](auto L) { return sub(c.pvec(L, k), c.pvec(L, i)); },
                       [&] { return flat_zero_p(k, i); }) < 0)
            s.i = k, moved = true;
        }
      }
      for (bool moved = true; moved;) {
        moved = false;
        for (int e = aQ.start[s.j]; e < aQ.start[s.j + 1] && !moved; ++e) {
          const int k = aQ.nbr[e], j = s.j;
          if (q_zero(k, j)) continue;
          if (dir_sign(U, Ufl, [&](auto L) { return c.dm(L, PairId{0, k}, PairId{0, j}); },
                       [&] { return flat_zero_q(k, j); }) < 0)
            s.j = k, moved = true;
        }
      }
      if (!improves(s)) break;  // certified: M ⊂ {U·x ≥ U·w}
    }
    Member Y[4];
    for (int k = 0; k < X.size; ++k) Y[k] = X.s[k];
    Y[X.size] = c.member(s);
    X = johnson.reduce(Y, X.size + 1);
    contact = X.contact;
  }

  return {X, contact};
}

// ---- Fast path: GJK in doubles, its final simplex certified once ---------------------------------

// Closest point of the triangle (m[x], m[y], m[z]) to 0 in doubles (Ericson §5.1.5): the point
// and the vertices of the face holding it (indices into m).
static void closest_tri_double(const Vec3* m, int x, int y, int z, Vec3& out, int* ks, int& nk) {
  const Vec3 &a = m[x], &b = m[y], &c = m[z];
  const Vec3 ab = b - a, ac = c - a;
  const double d1 = -ab.dot(a), d2 = -ac.dot(a);
  if (d1 <= 0 && d2 <= 0) return out = a, ks[0] = x, nk = 1, void();
  const double d3 = -ab.dot(b), d4 = -ac.dot(b);
  if (d3 >= 0 && d4 <= d3) return out = b, ks[0] = y, nk = 1, void();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return out = a + (d1 / (d1 - d3)) * ab, ks[0] = x, ks[1] = y, nk = 2, void();
  const double d5 = -ab.dot(c), d6 = -ac.dot(c);
  if (d6 >= 0 && d5 <= d6) return out = c, ks[0] = z, nk = 1, void();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return out = a + (d2 / (d2 - d6)) * ac, ks[0] = x, ks[1] = z, nk = 2, void();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return out = b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b), ks[0] = y, ks[1] = z, nk = 2, void();
  const double den = 1 / (va + vb + vc);
  out = a + (vb * den) * ab + (vc * den) * ac;
  ks[0] = x, ks[1] = y, ks[2] = z, nk = 3;
}

// Closest point v of conv(m[0..n)) to 0 in doubles (n ≤ 4; Ericson, Real-Time Collision
// Detection §5.1.5–5.1.6), the simplex reduced to the vertices of the face holding it. False,
// with the simplex untouched, when 0 seems inside a tetrahedron or the tetrahedron is flat.
static bool closest_simplex_double(PairId* id, Vec3* m, int& n, Vec3& v) {
  auto keep = [&](std::initializer_list<int> ks) {
    PairId i2[4];
    Vec3 m2[4];
    int k = 0;
    for (int x : ks) i2[k] = id[x], m2[k] = m[x], ++k;
    for (int x = 0; x < k; ++x) id[x] = i2[x], m[x] = m2[x];
    n = k;
  };
  if (n == 1) {
    v = m[0];
    return true;
  }
  if (n == 2) {
    const Vec3 ab = m[1] - m[0];
    const double t = -m[0].dot(ab), l = ab.squaredNorm();
    if (t <= 0) return keep({0}), v = m[0], true;
    if (t >= l) return keep({1}), v = m[1], true;
    v = m[0] + (t / l) * ab;
    return true;
  }
  int ks[3], nk = 0;
  if (n == 3) {
    closest_tri_double(m, 0, 1, 2, v, ks, nk);
  } else {
    const int F[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};  // face, opposite vertex
    double best = std::numeric_limits<double>::infinity();
    for (const auto& f : F) {
      const Vec3 nf = (m[f[1]] - m[f[0]]).cross(m[f[2]] - m[f[0]]);
      const double so = -nf.dot(m[f[0]]), sd = nf.dot(m[f[3]] - m[f[0]]);
      if (!(sd != 0)) return false;  // flat (or NaN)
      if (!(so * sd < 0)) continue;   // 0 on the tetrahedron's side of this face
      Vec3 x;
      int k2[3] = {0, 0, 0}, n2;  // initialised: the flattened v3 clone warns otherwise
      closest_tri_double(m, f[0], f[1], f[2], x, k2, n2);
      if (x.squaredNorm() < best) best = x.squaredNorm(), v = x, nk = n2, std::copy(k2, k2 + 3, ks);
    }
    if (nk == 0) return false;  // 0 inside: contact
  }
  if (nk == 1) keep({ks[0]});
  if (nk == 2) keep({ks[0], ks[1]});
  if (nk == 3) keep({ks[0], ks[1], ks[2]});
  return true;
}

// The loop of gjk_loop with every decision in plain doubles (supports by scans or rounded
// climbs, the closest point of the simplex by Ericson's region tests, improvement by the double
// sign with a 2⁻⁴⁰ relative margin; a flat tetrahedron proposes its triangle): no error bounds
// until the end — its proposals need not be right, only certified. Its final simplex S is then accepted only by one certificate whose
// every sign is a filtered one (exact::Fl: value and a rigorous bound of its error, or for the
// edge signs of (c) a bound derived for that formula; `margin` scales the bounds: 1 in the
// library, 0 only in the test showing that the tests catch an unsound certificate):
//  (a) S is non-degenerate: its distinct P vertices S_P and Q vertices S_Q have sizes
//      (1,1), (2,1), (1,2) with |S| = |S_P| + |S_Q| − 1, or (3,1), (1,3), (2,2) with |S| = 3
//      (so the members form a connected pattern: all S_P at one level of U·p, all S_Q at one
//      level of U·q');
//  (b) the projection w of 0 onto aff(S) lies in conv(S)'s relative interior (every barycentric
//      numerator certified > 0), w ≠ 0 (a component of m_a, e × a, or n·a certified ≠ 0: 0 ∉ M),
//      and for (2,2) not on the other diagonal of the parallelogram (n·(m_D × m_O) ≠ 0, D the
//      fourth corner, O its opposite);
//  (c) every neighbour k ∉ S_P of every s ∈ S_P has U·(p_k − p_s) certified > 0, and every
//      neighbour k ∉ S_Q of every t ∈ S_Q has U·(q'_t − q'_k) certified > 0.
// (c) makes each s a local, hence global (convexity, level-0 adjacency), minimiser of U·p and
// S_P exactly the minimising face P_U (a larger face would have a boundary edge leaving S_P at
// the same level); the same for Q'. So M ⊂ {U·x ≥ U·w}, w ∈ conv(S) ⊂ M: w is the closest point,
// and the face of M it lies on is F = P_U ⊕ (−Q'_U) with vertex sets S_P, S_Q. With (a), (b) the
// exact loop can only end on the same set S (a segment or triangle F holds w in its relative
// interior only as itself; a parallelogram F holds it in the interior of triangles only, all with
// normal ±(e_P × e_Q), the value's canonical form in signed_distance_gjk), so both paths give the
// same bits. Any failed test (a sign the filter cannot certify, a coplanar or parallel feature,
// contact, no convergence in 48 steps) returns nullopt: the exact loop answers.
std::optional<Reduced> gjk_fast(const Ctx& c, const VertexAdjacency& aP, const VertexAdjacency& aQ, double margin) {
  if (c.proj || c.RpT) return std::nullopt;  // plain signed distance only
  const PolytopeData& PD = c.P;
  const PolytopeData& QD = c.Q;
  const RelativePose& rel = c.rel;
  auto fsign = [margin](Fl x) {
    const double b = exact::safe_bound(x.e) * margin;
    return x.v > b ? 1 : x.v < -b ? -1 : 0;  // 0: not certified (or NaN)
  };
  const Vec3 tqp = rel.tq - rel.tp;
  auto approx = [&](PairId s) { return Vec3(PD.v[s.i] - (rel.R * QD.v[s.j] + tqp)); };
  Vec3 v = aP.centroid - (rel.R * aQ.centroid + tqp);
  if (!v.allFinite() || v == Vec3::Zero()) v = Vec3::UnitX();
  // Supports: a linear scan for up to 64 vertices (as Bullet; measured faster than climbing on
  // such hulls), else rounded hill climbing from the previous answer. Proposals only: the
  // certificate decides.
  auto scan = [](const PolytopeData& d, const Vec3& u) {
    const Vec3* x = d.v.data();
    double best = -std::numeric_limits<double>::infinity();
    int bi = 0;
    for (int k = 0, n = static_cast<int>(d.v.size()); k < n; ++k) {
      const double s = u[0] * x[k][0] + u[1] * x[k][1] + u[2] * x[k][2];
      if (s > best) best = s, bi = k;
    }
    return bi;
  };
  auto support = [&](const Vec3& u, int i0, int j0) {
    const Vec3 uq = rel.R.transpose() * u;
    return PairId{PD.v.size() <= 64 ? scan(PD, -u) : climb_rounded(PD, aP, -u, i0 >= 0 ? i0 : seed_vertex(aP, -u)),
                  QD.v.size() <= 64 ? scan(QD, uq) : climb_rounded(QD, aQ, uq, j0 >= 0 ? j0 : seed_vertex(aQ, uq))};
  };
  PairId s = support(v, -1, -1);
  PairId ids[4] = {s};
  Vec3 ms[4] = {approx(s)};
  int n = 1;
  v = ms[0];
  for (int iter = 0;; ++iter) {
    if (iter == 48 || !v.allFinite() || (v[0] == 0 && v[1] == 0 && v[2] == 0)) return std::nullopt;
    s = support(v, s.i, s.j);
    bool dup = false;
    for (int k = 0; k < n; ++k) dup = dup || ids[k] == s;
    if (dup) break;
    const Vec3 x = approx(s);
    // Not closer than the plane through v by more than rounding (2⁻⁴⁰ relative): converged; a
    // rounding-level cycle would otherwise run to the cap.
    if (!(x.dot(v) < v.squaredNorm() * (1 - 0x1p-40))) break;
    ids[n] = s, ms[n] = x, ++n;
    if (!closest_simplex_double(ids, ms, n, v)) {
      // A flat tetrahedron (the new point on the triangle's plane: a parallelogram or polygon
      // face of M, no progress) or a seeming contact; the simplex is untouched: propose the
      // previous triangle (the certificate below rejects it unless it is the answer).
      n = 3;
      break;
    }
  }
  // (a) the pattern of S = ids[0..n).
  int sp[3], sq[3], np = 0, nq = 0;
  for (int k = 0; k < n; ++k) {
    if (std::find(sp, sp + np, ids[k].i) == sp + np) sp[np++] = ids[k].i;
    if (std::find(sq, sq + nq, ids[k].j) == sq + nq) sq[nq++] = ids[k].j;
  }
  const bool ok_pattern =
      n == 3 ? (np == 3 && nq == 1) || (np == 1 && nq == 3) || (np == 2 && nq == 2) : np + nq - 1 == n;
  if (!ok_pattern) return std::nullopt;
  // (b) with the members' filtered coordinates.
  Reduced R;
  R.size = n;
  for (int k = 0; k < n; ++k) R.s[k] = c.member(ids[k]);
  const LiftFl F;
  const V3<Fl> a = R.s[0].fl;
  auto nonzero3 = [&](const V3<Fl>& x) { return fsign(x[0]) != 0 || fsign(x[1]) != 0 || fsign(x[2]) != 0; };
  V3<Fl> Ufl;  // S's direction U (Dir's polynomials, from the values at hand)
  if (R.size == 1) {
    if (!nonzero3(a)) return std::nullopt;
    Ufl = a;
  } else if (R.size == 2) {
    const V3<Fl> e = c.dm(F, R.s[1].id, R.s[0].id);
    if (fsign(dot(R.s[1].fl, e)) != 1 || fsign(dot(a, e)) != -1 || !nonzero3(cross(e, a))) return std::nullopt;
    Ufl = sub(scale(dot(e, e), a), scale(dot(a, e), e));
  } else {
    const V3<Fl> n = cross(c.dm(F, R.s[1].id, R.s[0].id), c.dm(F, R.s[2].id, R.s[0].id));
    for (int t = 0; t < 3; ++t)
      if (fsign(dot(n, cross(R.s[(t + 1) % 3].fl, R.s[(t + 2) % 3].fl))) != 1) return std::nullopt;
    const int h = fsign(dot(n, a));
    if (h == 0) return std::nullopt;
    R.tri_sign = h;
    Ufl = h > 0 ? n : V3<Fl>{-n[0], -n[1], -n[2]};
    if (np == 2) {  // the other diagonal: from the missing corner D to its opposite O
      PairId D{-1, -1};
      for (int x = 0; x < 2; ++x)
        for (int y = 0; y < 2; ++y) {
          bool in = false;
          for (int k = 0; k < 3; ++k) in = in || R.s[k].id == PairId{sp[x], sq[y]};
          if (!in) D = {sp[x], sq[y]};
        }
      const PairId O{D.i == sp[0] ? sp[1] : sp[0], D.j == sq[0] ? sq[1] : sq[0]};
      if (fsign(dot(n, cross(c.m(F, D), c.m(F, O)))) == 0) return std::nullopt;
    }
  }
  // (c) the supporting plane, strictly, at every vertex of S_P and S_Q. U enclosed by Fl once; in
  // Q's frame W = Rᵀ U (R as the doubles it holds: exact semantics). Each sign is then
  // w·d for d = x − y the rounded edge vector of the adjacency (d_c = (x_c − y_c)(1 + θ),
  // |θ| ≤ u): |w·(x − y) − fl(w_v·d)| ≤ γ₃ S + 1.01u S + (1 + 1.01u) E with S = Σ|w_v,c d_c| and
  // E = Σ e_c |d_c| (e: the Fl bound of w); bounded by 8u·S + (1 + 4u)·E, inflated by (1 + 16u)
  // for its own rounding plus an underflow term (exact::kTiny).
  V3<Fl> Wfl;
  for (int k = 0; k < 3; ++k)
    Wfl[k] = plain::mul_x(F, rel.R(0, k), Ufl[0]) + plain::mul_x(F, rel.R(1, k), Ufl[1]) +
               plain::mul_x(F, rel.R(2, k), Ufl[2]);
  auto edge_sign = [margin](const V3<Fl>& w, double dx, double dy, double dz) {
    const double val = w[0].v * dx + w[1].v * dy + w[2].v * dz;
    const double S = std::abs(w[0].v * dx) + std::abs(w[1].v * dy) + std::abs(w[2].v * dz);
    const double E = w[0].e * std::abs(dx) + w[1].e * std::abs(dy) + w[2].e * std::abs(dz);
    const double b = ((8 * exact::kUnit) * S + (1 + 4 * exact::kUnit) * E) * (1 + 16 * exact::kUnit) * margin +
                     exact::kTiny * margin;
    return val > b ? 1 : val < -b ? -1 : 0;
  };
  auto in = [](const int* vs, int nv, int x) { return vs[0] == x || (nv > 1 && vs[1] == x) || (nv > 2 && vs[2] == x); };
  for (int x = 0; x < np; ++x)  // U·(p_k − p_s) > 0
    for (int e = aP.start[sp[x]]; e < aP.start[sp[x] + 1]; ++e) {
      if (in(sp, np, aP.nbr[e])) continue;
      if (edge_sign(Ufl, aP.dx[e], aP.dy[e], aP.dz[e]) != 1) return std::nullopt;
    }
  for (int y = 0; y < nq; ++y)  // U·(q'_t − q'_k) = W·(q_t − q_k) > 0
    for (int e = aQ.start[sq[y]]; e < aQ.start[sq[y] + 1]; ++e) {
      if (in(sq, nq, aQ.nbr[e])) continue;
      if (edge_sign(Wfl, aQ.dx[e], aQ.dy[e], aQ.dz[e]) != -1) return std::nullopt;
    }
  return R;
}

LineTouch line_touch_gjk(const ConvexPolytope& Pp, const ConvexPolytope& Qp, const RelativePose& rel, const Vec3& d) {
  const PolytopeData& PD = data_of(Pp);
  const PolytopeData& QD = data_of(Qp);
  Ctx cp{PD, QD, rel};
  cp.proj = &d;
  const GjkResult g = gjk_loop(cp, vertex_adjacency(PD), vertex_adjacency(QD));
  LineTouch r;
  r.touch = g.contact;
  if (!r.touch) return r;
  r.size = g.X.size;
  for (int k = 0; k < g.X.size; ++k) r.i[k] = g.X.s[k].id.i, r.j[k] = g.X.s[k].id.j;
  return r;
}

Distance3 signed_distance_gjk(const ConvexPolytope& Pp, const ConvexPolytope& Qp, const RelativePose& rel,
                              const Eigen::Matrix3d& Rp, const Vec3& tp_world) {
  return signed_distance_gjk(Pp, Qp, rel, Rp, tp_world, SignedDistancePath{}, nullptr);
}

namespace {

Distance3 signed_distance_body(const ConvexPolytope& Pp, const ConvexPolytope& Qp, const RelativePose& rel,
                               const Eigen::Matrix3d& Rp, const Vec3& tp_world, const SignedDistancePath& path,
                               bool* fast_used) {
  const PolytopeData& PD = data_of(Pp);
  const PolytopeData& QD = data_of(Qp);
  const VertexAdjacency& aP = vertex_adjacency(PD);
  const VertexAdjacency& aQ = vertex_adjacency(QD);
  const Ctx c{PD, QD, rel};

  std::optional<Reduced> fast;
  if (path.fast) fast = gjk_fast(c, aP, aQ, path.margin);
  if (fast_used) *fast_used = fast.has_value();
  GjkResult g;
  if (!fast) g = gjk_loop(c, aP, aQ);
  Reduced X = fast ? *fast : g.X;
  const bool contact = !fast && g.contact;
  // Apart: S in a canonical order (by (i, j)), so that every path ending on the same set S gives
  // the same bits; V: the simplex the value and normal are computed on — S itself, except on a
  // parallelogram face of M (two P and two Q vertices: an edge–edge closest pair) where any
  // triangle of three corners may hold w, all with the normal ±(e_P × e_Q): the corners
  // (i1, j1), (i1, j2), (i2, j1) (i1 < i2, j1 < j2) are used (the triangle need not hold w).
  bool edge_edge = false;
  Reduced V = X;
  if (!contact) {
    int swaps = 0;
    for (int k = 1; k < X.size; ++k)  // insertion sort by (i, j)
      for (int l = k; l > 0 && std::pair(X.s[l].id.i, X.s[l].id.j) < std::pair(X.s[l - 1].id.i, X.s[l - 1].id.j); --l)
        std::swap(X.s[l], X.s[l - 1]), ++swaps;
    V = X;
    if (X.size == 3) {
      const int i1 = X.s[0].id.i, i2 = X.s[2].id.i;
      int j1 = X.s[0].id.j, j2 = j1;
      for (int k = 0; k < 3; ++k) j1 = std::min(j1, X.s[k].id.j), j2 = std::max(j2, X.s[k].id.j);
      const int ni = 1 + (X.s[1].id.i != i1) + (i2 != X.s[1].id.i);
      const int nj = 1 + (X.s[0].id.j != X.s[1].id.j && X.s[1].id.j != X.s[2].id.j && X.s[0].id.j != X.s[2].id.j
                              ? 2
                              : X.s[0].id.j != X.s[1].id.j || X.s[1].id.j != X.s[2].id.j);
      edge_edge = ni == 2 && nj == 2;
      if (edge_edge) V.s[0] = c.member({i1, j1}), V.s[1] = c.member({i1, j2}), V.s[2] = c.member({i2, j1});
      // n·a = ((b − a) × (c − a))·a = det(a, b, c): alternating, so the fast path's certified
      // sign carries over with the parity of the sort.
      X.tri_sign = fast ? (swaps % 2 ? -fast->tri_sign : fast->tri_sign) : exact_sign([&](auto L) {
        return dot(cross(c.dm(L, X.s[1].id, X.s[0].id), c.dm(L, X.s[2].id, X.s[0].id)), c.pt(L, X.s[0]));
      });
      V.tri_sign = !edge_edge ? X.tri_sign : exact_sign([&](auto L) {
        return dot(cross(c.dm(L, V.s[1].id, V.s[0].id), c.dm(L, V.s[2].id, V.s[0].id)), c.pt(L, V.s[0]));
      });
    }
  }
  Distance3 r;
  // Barycentric weights (rounded) of the closest point (or of 0) on S.
  std::array<double, 4> lam{1, 0, 0, 0};
  {
    Vec3 m[4];
    for (int k = 0; k < X.size; ++k) m[k] = c.approx_p(X.s[k].id.i) - c.approx_q(X.s[k].id.j);
    if (X.size == 2) {
      const Vec3 e = m[1] - m[0];
      double t = e.squaredNorm() > 0 ? std::clamp(-m[0].dot(e) / e.squaredNorm(), 0.0, 1.0) : 0.0;
      lam = {1 - t, t, 0, 0};
    } else if (X.size == 3) {
      const Vec3 n = (m[1] - m[0]).cross(m[2] - m[0]);
      double l[3], sum = 0;
      for (int k = 0; k < 3; ++k) sum += l[k] = std::max(0.0, n.dot(m[(k + 1) % 3].cross(m[(k + 2) % 3])));
      for (int k = 0; k < 3; ++k) lam[k] = sum > 0 ? l[k] / sum : 1.0 / 3;
    } else if (X.size == 4) {
      auto det = [](const Vec3& a, const Vec3& b, const Vec3& cc) { return a.dot(b.cross(cc)); };
      double V = det(m[1] - m[0], m[2] - m[0], m[3] - m[0]), sum = 0;
      double l[4];
      const Vec3 z = Vec3::Zero();
      for (int k = 0; k < 4; ++k) {
        Vec3 p[4] = {m[0], m[1], m[2], m[3]};
        p[k] = z;
        sum += l[k] = std::max(0.0, det(p[1] - p[0], p[2] - p[0], p[3] - p[0]) / V);
      }
      for (int k = 0; k < 4; ++k) lam[k] = sum > 0 ? l[k] / sum : 0.25;
    }
  }
  Vec3 wp = Vec3::Zero(), wq = Vec3::Zero();
  for (int k = 0; k < X.size; ++k) wp += lam[k] * c.approx_p(X.s[k].id.i), wq += lam[k] * c.approx_q(X.s[k].id.j);
  if (edge_edge) {  // the closest points of the two edges (rounded), whichever triangle S is
    const Vec3 p1 = c.approx_p(V.s[0].id.i), ep = c.approx_p(V.s[2].id.i) - p1;
    const Vec3 q1 = c.approx_q(V.s[0].id.j), eq = c.approx_q(V.s[1].id.j) - q1;
    const Vec3 w0 = p1 - q1;
    const double A = ep.dot(ep), B = ep.dot(eq), C = eq.dot(eq), D = ep.dot(w0), E = eq.dot(w0);
    const double den = A * C - B * B;
    double sp = den > 0 ? std::clamp((B * E - C * D) / den, 0.0, 1.0) : 0.0;
    const double tq = C > 0 ? std::clamp((B * sp + E) / C, 0.0, 1.0) : 0.0;
    sp = A > 0 ? std::clamp((B * tq - D) / A, 0.0, 1.0) : 0.0;
    wp = p1 + sp * ep, wq = q1 + tq * eq;
  }

  if (contact) {
    // 0 ∈ M: σ decides overlap (−σ) or touching (0).
    const Depth3 d = minimum_depth_expand(Pp, Qp, rel, Rp, tp_world);
    if (d.overlapping) {
      r.overlapping = true;
      r.distance = -d.depth;
      r.lower_bound = -d.upper_bound;
      r.upper_bound = -d.lower_bound;
      r.translation = d.translation;
      r.normal = d.normal;
      r.witness_p = d.witness_p;
      r.witness_q = d.witness_q - d.translation;
      r.feature_p = d.feature_p;
      r.feature_q = d.feature_q;
      return r;
    }
    r.witness_p = Rp * wp + tp_world;
    r.witness_q = Rp * wq + tp_world;
    if (X.size == 4) X.size = 3;  // 0 on a face of the tetrahedron: report its first three pairs
  } else {
    // Distance |w_S| from accurately evaluated polynomials, one square root (on V: S, or the
    // canonical triangle of an edge–edge parallelogram).
    const Member& a = V.s[0];
    // Each factor from accurately evaluated polynomials of low degree (no squares, so tiny
    // distances do not underflow), norms by Eigen's stableNorm: within ~3 ulps.
    auto acc3 = [&](auto&& f) {
      const auto v = f(exact::LiftDD{});
      Vec3 r;
      for (int k = 0; k < 3; ++k)
        r[k] = exact::dd_finite(v[k]) && exact::safe_bound(v[k].e) <= std::abs(v[k].hi) * 0x1p-54
                   ? v[k].hi
                   : accurate_dd([&](auto L) { return f(L)[k]; });
      return r;
    };
    // First the double-double values each used once (the same operations as below, so the same
    // bits when every bound holds); the general evaluation (exact tiers) otherwise.
    double dist = 0;
    Vec3 u;
    bool done = false;
    if (path.quick_value && path.a_priori_value) done = value_a_priori(c, V, dist, u);
    if (path.quick_value && !done) {
      const exact::LiftDD D;
      auto ok = [](const exact::DD& x) {
        return exact::dd_finite(x) && exact::safe_bound(x.e) <= std::abs(x.hi) * 0x1p-54;
      };
      // Each component as the general evaluation below (acc3, accurate_dd) would give it: the
      // double-double's hi when its bound holds; else the exact-double value (FlX) when exact;
      // else +0 when FlZ proves the value exactly 0 (a zero factor: axis-aligned edges of the
      // identity-posed shape), which is what the exact tiers return for an exact zero; else the
      // general evaluation runs (done = false). `zf`: f's components in FlZ, possibly from
      // another formula of the same real value that shows more zeros.
      auto pick_z = [&](const V3<exact::DD>& x, auto&& f, Vec3& out, auto&& zf) {
        std::optional<V3<exact::FlX>> fx;
        std::optional<V3<FlZ>> fz;
        for (int k = 0; k < 3; ++k) {
          if (ok(x[k])) {
            out[k] = x[k].hi;
            continue;
          }
          if (!fx) fx = f(exact::LiftFlX{});
          if ((*fx)[k].exact) {
            out[k] = (*fx)[k].v;
            continue;
          }
          if (!fz) fz = zf(LiftFlZ{});
          if (!(*fz)[k].exact || (*fz)[k].v != 0) return false;
          out[k] = 0.0;
        }
        return true;
      };
      auto pick = [&](const V3<exact::DD>& x, auto&& f, Vec3& out) { return pick_z(x, f, out, f); };
      const Dir UV{&c, V.size, {V.s[0], V.size > 1 ? V.s[1] : Member{}, V.size > 2 ? V.s[2] : Member{}}, V.tri_sign};
      auto fU = [&](auto L) { return UV(L); };
      const V3<exact::DD> aD = c.pt(D, a);
      if (V.size == 1) {
        done = pick(aD, fU, u);
        dist = u.stableNorm();
      } else if (V.size == 2) {
        const V3<exact::DD> eD = c.dm(D, V.s[1].id, a.id);
        const V3<exact::DD> UD = sub(scale(dot(eD, eD), aD), scale(dot(aD, eD), eD));
        Vec3 x, e;
        // U = (e·e)a − (a·e)e is also e × (a × e) (the same polynomial): in that form FlZ sees the
        // zero components of an axis-aligned edge's U (a product with an exact zero factor), which
        // the first form hides in cancelling products — 2 % of the benchmark's placements (vertex
        // against an axis-aligned edge of the identity-posed P) fell to the expansion tiers there.
        auto zU = [&](LiftFlZ L) {
          V3<FlZ> r = fU(L);
          const V3<FlZ> eZ = c.dm(L, V.s[1].id, a.id), t = cross(eZ, cross(c.pt(L, a), eZ));
          for (int k = 0; k < 3; ++k)
            if (!r[k].exact || r[k].v != 0) r[k] = t[k];
          return r;
        };
        done = pick(cross(eD, aD), [&](auto L) { return cross(c.dm(L, V.s[1].id, a.id), c.pt(L, a)); }, x) &&
               pick(eD, [&](auto L) { return c.dm(L, V.s[1].id, a.id); }, e) && pick_z(UD, fU, u, zU);
        dist = x.stableNorm() / e.stableNorm();
      } else {
        auto fn = [&](auto L) { return cross(c.dm(L, V.s[1].id, a.id), c.dm(L, V.s[2].id, a.id)); };
        const V3<exact::DD> nD = fn(D);
        const exact::DD naD = dot(nD, aD);
        const V3<exact::DD> UD = V.tri_sign > 0 ? nD : V3<exact::DD>{-nD[0], -nD[1], -nD[2]};
        Vec3 nv;
        done = ok(naD) && pick(nD, fn, nv) && pick(UD, fU, u);
        dist = std::abs(naD.hi) / nv.stableNorm();
      }
    }
    if (!done) {
      if (X.size == 1) {
        dist = acc3([&](auto L) { return c.pt(L, a); }).stableNorm();
      } else if (X.size == 2) {
        const Member& b = V.s[1];
        dist = acc3([&](auto L) { return cross(c.dm(L, b.id, a.id), c.pt(L, a)); }).stableNorm() /
               acc3([&](auto L) { return c.dm(L, b.id, a.id); }).stableNorm();
      } else {
        auto n = [&](auto L) { return cross(c.dm(L, V.s[1].id, a.id), c.dm(L, V.s[2].id, a.id)); };
        dist = std::abs(accurate_dd([&](auto L) { return dot(n(L), c.pt(L, a)); })) / acc3(n).stableNorm();
      }
      // normal = −U/|U|, U evaluated accurately per component.
      const Dir U{&c, V.size, {V.s[0], V.size > 1 ? V.s[1] : Member{}, V.size > 2 ? V.s[2] : Member{}}, V.tri_sign};
      const auto ud = U(exact::LiftDD{});
      for (int k = 0; k < 3; ++k)
        u[k] = exact::dd_finite(ud[k]) && exact::safe_bound(ud[k].e) <= std::abs(ud[k].hi) * 0x1p-54
                   ? ud[k].hi
                   : accurate_dd([&](auto L) { return U(L)[k]; });
    }
    r.distance = r.lower_bound = r.upper_bound = dist;
    const Vec3 nl = -u.stableNormalized();
    r.normal = Rp * nl;
    r.translation = Vec3::Zero() - r.distance * r.normal;  // as in 2D: no -0 components
    r.witness_p = Rp * wp + tp_world;
    r.witness_q = Rp * wq + tp_world;
  }
  // Features: the distinct vertices of each side in S (ascending when apart).
  int vp[3], vq[3], np = 0, nq = 0;
  for (int k = 0; k < X.size; ++k) {
    if (std::find(vp, vp + np, X.s[k].id.i) == vp + np) vp[np++] = X.s[k].id.i;
    if (std::find(vq, vq + nq, X.s[k].id.j) == vq + nq) vq[nq++] = X.s[k].id.j;
  }
  if (!contact) sort_small(vp, np), sort_small(vq, nq);
  const Vec3 wq_own = rel.R.transpose() * (wq - (rel.tq - rel.tp));
  r.feature_p = feature_of(Pp, vp, np, wp, fast.has_value());
  r.feature_q = feature_of(Qp, vq, nq, wq_own, fast.has_value());
  return r;
}

#if PENDEPTH_V3_CLONES
// The same call tree (the fast path, the exact loop, the value) compiled for x86-64-v3
// (geometry/isa.hpp); the same bits.
PENDEPTH_V3_CLONE Distance3 signed_distance_v3(const ConvexPolytope& Pp, const ConvexPolytope& Qp,
                                               const RelativePose& rel, const Eigen::Matrix3d& Rp,
                                               const Vec3& tp_world, const SignedDistancePath& path,
                                               bool* fast_used) {
  return signed_distance_body(Pp, Qp, rel, Rp, tp_world, path, fast_used);
}
#endif

}  // namespace

Distance3 signed_distance_gjk(const ConvexPolytope& Pp, const ConvexPolytope& Qp, const RelativePose& rel,
                              const Eigen::Matrix3d& Rp, const Vec3& tp_world, const SignedDistancePath& path,
                              bool* fast_used) {
#if PENDEPTH_V3_CLONES
  if (isa::use_v3()) return signed_distance_v3(Pp, Qp, rel, Rp, tp_world, path, fast_used);
#endif
  return signed_distance_body(Pp, Qp, rel, Rp, tp_world, path, fast_used);
}


// ---- Shape cast: GJK ray cast in doubles, certified exactly (cast3.cpp's fast path) -----------
namespace {

// Closest point of conv(pts) to 0 in doubles (brute force over the ≤ 15 faces): the subset mask,
// its weights and the point. A proposal only.
struct Closest {
  int mask = 0;
  double lam[4] = {0, 0, 0, 0};
  Vec3 v{0, 0, 0};
};
Closest closest_double_lu(const Vec3* pts, int n) {
  Closest best;
  double best_d = std::numeric_limits<double>::infinity();
  for (int mask = 1; mask < (1 << n); ++mask) {
    int idx[4], k = 0;
    for (int b = 0; b < n; ++b)
      if (mask >> b & 1) idx[k++] = b;
    double lam[4] = {1, 0, 0, 0};
    if (k > 1) {
      Eigen::Matrix3d G = Eigen::Matrix3d::Identity();
      Vec3 rhs = Vec3::Zero();
      for (int a = 1; a < k; ++a) {
        rhs[a - 1] = -pts[idx[0]].dot(pts[idx[a]] - pts[idx[0]]);
        for (int b = 1; b < k; ++b) G(a - 1, b - 1) = (pts[idx[a]] - pts[idx[0]]).dot(pts[idx[b]] - pts[idx[0]]);
      }
      using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;  // no heap
      using SmallV = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
      const Small gm = G.topLeftCorner(k - 1, k - 1);
      const double det = gm.determinant();
      if (!(std::abs(det) > 0)) continue;
      const SmallV mu = gm.fullPivLu().solve(SmallV(rhs.head(k - 1)));
      lam[0] = 1;
      for (int a = 1; a < k; ++a) lam[a] = mu[a - 1], lam[0] -= mu[a - 1];
    }
    bool inside = true;
    for (int a = 0; a < k; ++a) inside = inside && lam[a] >= 0;
    if (!inside) continue;
    Vec3 v = Vec3::Zero();
    for (int a = 0; a < k; ++a) v += lam[a] * pts[idx[a]];
    const double dv = v.squaredNorm();
    if (dv < best_d) {
      best_d = dv, best.mask = mask, best.v = v;
      for (int a = 0; a < 4; ++a) best.lam[a] = 0;
      for (int a = 0; a < k; ++a) best.lam[idx[a]] = lam[a];
    }
  }
  return best;
}

// The same by Ericson's region tests (§5.1.5–5.1.6; closest_tri_double): a few dozen flops
// instead of up to 15 small LU solves; a flat tetrahedron goes to closest_double_lu.
Closest closest_double(const Vec3* pts, int n) {
  Closest r;
  if (n == 1) {
    r.mask = 1, r.lam[0] = 1, r.v = pts[0];
    return r;
  }
  if (n == 2) {
    const Vec3 ab = pts[1] - pts[0];
    const double t = -pts[0].dot(ab), l = ab.squaredNorm();
    if (t <= 0) return r.mask = 1, r.lam[0] = 1, r.v = pts[0], r;
    if (t >= l) return r.mask = 2, r.lam[1] = 1, r.v = pts[1], r;
    r.mask = 3, r.lam[1] = t / l, r.lam[0] = 1 - r.lam[1], r.v = pts[0] + r.lam[1] * ab;
    return r;
  }
  int ks[3], nk = 0;
  if (n == 3) {
    closest_tri_double(pts, 0, 1, 2, r.v, ks, nk);
  } else {
    const int F[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};  // face, opposite vertex
    double best = std::numeric_limits<double>::infinity();
    for (const auto& f : F) {
      const Vec3 nf = (pts[f[1]] - pts[f[0]]).cross(pts[f[2]] - pts[f[0]]);
      const double so = -nf.dot(pts[f[0]]), sd = nf.dot(pts[f[3]] - pts[f[0]]);
      if (!(sd != 0)) return closest_double_lu(pts, n);  // flat (or NaN)
      if (!(so * sd < 0)) continue;
      Vec3 x;
      int k2[3], n2;
      closest_tri_double(pts, f[0], f[1], f[2], x, k2, n2);
      if (x.squaredNorm() < best) best = x.squaredNorm(), r.v = x, nk = n2, std::copy(k2, k2 + 3, ks);
    }
    if (nk == 0) {  // 0 inside: the whole tetrahedron, weights by signed volumes
      auto det = [](const Vec3& a, const Vec3& b, const Vec3& c) { return a.dot(b.cross(c)); };
      const double V = det(pts[1] - pts[0], pts[2] - pts[0], pts[3] - pts[0]);
      for (int k = 0; k < 4; ++k) {
        Vec3 p[4] = {pts[0], pts[1], pts[2], pts[3]};
        p[k] = Vec3::Zero();
        r.lam[k] = det(p[1] - p[0], p[2] - p[0], p[3] - p[0]) / V;
      }
      r.mask = 15, r.v = Vec3::Zero();
      return r;
    }
  }
  for (int k = 0; k < nk; ++k) r.mask |= 1 << ks[k];
  return r;
}

}  // namespace

std::optional<Cast3> shape_cast_certified(const ConvexPolytope& Pp, const ConvexPolytope& Qp, const RelativePose& rel,
                                          const Vec3& d, const Eigen::Matrix3d& Rp, const Vec3& tp_world) {
  const PolytopeData& PD = data_of(Pp);
  const PolytopeData& QD = data_of(Qp);
  const VertexAdjacency& aP = vertex_adjacency(PD);
  const VertexAdjacency& aQ = vertex_adjacency(QD);
  const Ctx c{PD, QD, rel};
  const Vec3 t = rel.tq - rel.tp;
  auto approx = [&](PairId x) { return Vec3(PD.v[x.i] - (rel.R * QD.v[x.j] + t)); };
  // Support of M maximising u·m: P maximises u·p, Q' minimises u·q'.
  PairId s{seed_vertex(aP, d), seed_vertex(aQ, -(rel.R.transpose() * d))};
  auto support = [&](const Vec3& u) {
    s = {climb_rounded(PD, aP, u, s.i), climb_rounded(QD, aQ, -(rel.R.transpose() * u), s.j)};
    return s;
  };
  const double scale = std::max(aP.extent.maxCoeff(), aQ.extent.maxCoeff()) + t.norm();
  // van den Bergen's GJK ray cast (2004) on the ray λ·d.
  double lambda = 0;
  Vec3 v = -approx(support(-d));  // x − (a point of M), x = 0
  Vec3 nlast = Vec3::Zero();      // the plane of the last advance of λ
  PairId Y[4];
  int ny = 0;
  bool hit = false;
  for (int iter = 0; iter < 64; ++iter) {
    if (v.squaredNorm() <= std::pow(0x1p-40 * scale, 2)) {
      hit = true;
      break;
    }
    const PairId p = support(v);
    const Vec3 x = lambda * d, w = x - approx(p);
    bool advanced = false;
    if (v.dot(w) > 0) {
      if (v.dot(d) >= 0) break;  // a proposed miss: certified below
      lambda -= v.dot(w) / v.dot(d);
      nlast = v;
      advanced = true;
    }
    bool dup = false;
    for (int k = 0; k < ny; ++k) dup = dup || Y[k] == p;
    if (!dup && ny < 4) Y[ny++] = p;
    Vec3 pts[4];
    for (int k = 0; k < ny; ++k) pts[k] = lambda * d - approx(Y[k]);
    const Closest cl = closest_double(pts, ny);
    if (cl.mask == 0) return std::nullopt;
    int m = 0;
    for (int k = 0; k < ny; ++k)
      if (cl.mask >> k & 1) Y[m++] = Y[k];
    ny = m;
    v = cl.v;
    if (dup && !advanced && v.squaredNorm() > std::pow(0x1p-40 * scale, 2)) {  // no progress
      hit = v.squaredNorm() <= std::pow(0x1p-26 * scale, 2);  // converged up to rounding: propose Y
      break;
    }
  }
  // Exact certificates. Lifted d for the predicates.
  auto dl = [&](auto L) { return V3<Num<decltype(L)>>{L(d[0]), L(d[1]), L(d[2])}; };
  if (!hit) {
    // Miss, certified by the double vectors as exact directions: v with v·d >= 0 excludes the
    // ray beyond h_M(v)/(v·d) (all of it when v·d = 0 and h_M(v) < 0, or when h_M(v) < 0 and no
    // advance happened); the last advance plane n (n·d < 0) excludes s < h_M(n)/(n·d). Miss iff
    // these cover s >= 0: h_M(v)·(n·d) > h_M(n)·(v·d) (both denominators' signs known).
    // Failing that: the line itself misses M, certified by the exact GJK on the projection
    // along d (0 ∉ π(M)).
    auto line_misses = [&]() {
      Ctx cp{PD, QD, rel};
      cp.proj = &d;
      return !gjk_loop(cp, aP, aQ).contact;
    };
    auto miss = []() {
      Cast3 r;
      r.distance = std::numeric_limits<double>::infinity();
      return r;
    };
    if (!v.allFinite() || v == Vec3::Zero() || !nlast.allFinite()) return line_misses() ? std::optional(miss()) : std::nullopt;
    auto exact_support = [&](const Vec3& u) {  // maximiser of u·m over M, exact
      auto ul = [&](auto L) { return V3<Num<decltype(L)>>{L(u[0]), L(u[1]), L(u[2])}; };
      PairId q = support(u);
      for (bool moved = true; moved;) {
        moved = false;
        for (int e = aP.start[q.i]; e < aP.start[q.i + 1] && !moved; ++e) {
          const int k = aP.nbr[e], i = q.i;
          if (exact_sign([&](auto L) { return dot(ul(L), sub(c.pvec(L, k), c.pvec(L, i))); }) > 0) q.i = k, moved = true;
        }
      }
      for (bool moved = true; moved;) {
        moved = false;
        for (int e = aQ.start[q.j]; e < aQ.start[q.j + 1] && !moved; ++e) {
          const int k = aQ.nbr[e], j = q.j;
          if (exact_sign([&](auto L) { return dot(ul(L), c.dm(L, PairId{0, k}, PairId{0, j})); }) > 0)
            q.j = k, moved = true;
        }
      }
      return q;
    };
    auto lift = [](const Vec3& u) {
      return [u](auto L) { return V3<Num<decltype(L)>>{L(u[0]), L(u[1]), L(u[2])}; };
    };
    const auto vl = lift(v), nl = lift(nlast);
    const PairId qv = exact_support(v);
    const int vd = exact_sign([&](auto L) { return dot(vl(L), dl(L)); });
    if (vd < 0) return line_misses() ? std::optional(miss()) : std::nullopt;
    if (nlast == Vec3::Zero() || vd == 0) {
      if (exact_sign([&](auto L) { return dot(vl(L), c.m(L, qv)); }) >= 0) return line_misses() ? std::optional(miss()) : std::nullopt;
    } else {
      if (exact_sign([&](auto L) { return dot(nl(L), dl(L)); }) >= 0) return line_misses() ? std::optional(miss()) : std::nullopt;
      const PairId qn = exact_support(nlast);
      if (exact_sign([&](auto L) {
            return dot(vl(L), c.m(L, qv)) * dot(nl(L), dl(L)) - dot(nl(L), c.m(L, qn)) * dot(vl(L), dl(L));
          }) <= 0)
        return line_misses() ? std::optional(miss()) : std::nullopt;
    }
    Cast3 r;
    r.distance = std::numeric_limits<double>::infinity();
    return r;
  }
  if (ny == 4) {  // x on a facet of the tetrahedron (up to rounding): keep that facet
    Vec3 pts[4];
    for (int k = 0; k < 4; ++k) pts[k] = lambda * d - approx(Y[k]);
    const Closest cl = closest_double(pts, 4);
    int drop = 0;
    for (int k = 1; k < 4; ++k)
      if (cl.lam[k] < cl.lam[drop]) drop = k;
    for (int k = drop; k < 3; ++k) Y[k] = Y[k + 1];
    ny = 3;
  }
  // The entry certificate for a triangle of pairs (see the file comment of cast3.cpp).
  auto certify = [&](PairId ya, PairId yb, PairId yc) -> std::optional<Cast3> {
  const Member A = c.member(ya), B = c.member(yb), C = c.member(yc);
  auto n = [&](auto L) { return cross(c.dm(L, B.id, A.id), c.dm(L, C.id, A.id)); };
  const int nd = exact_sign([&](auto L) { return dot(n(L), dl(L)); });
  if (nd == 0) return std::nullopt;
  const int sigma = -nd;  // n' = sigma·n faces against d: outward at the entry
  // The line s·d crosses the closed triangle: [d, a, b], [d, b, c], [d, c, a] of one sign.
  const Member* T[3] = {&A, &B, &C};
  int pos = 0, neg = 0;
  for (int k = 0; k < 3; ++k) {
    const int sg =
        exact_sign([&](auto L) { return dot(dl(L), cross(c.pt(L, *T[k]), c.pt(L, *T[(k + 1) % 3]))); });
    pos += sg > 0, neg += sg < 0;
  }
  if (pos && neg) return std::nullopt;
  // Entry at s >= 0: n'·a <= 0.
  const int ha = sigma * exact_sign([&](auto L) { return dot(n(L), c.pt(L, A)); });
  if (ha > 0) return std::nullopt;
  // n'·m is maximal over M at the triangle: P maximises n'·p at A.i, Q' minimises n'·q' at A.j
  // (neighbours on the plane by construction skipped).
  Reduced X;
  X.size = 3;
  X.s[0] = A, X.s[1] = B, X.s[2] = C;
  auto member = [&](int i, int j) {
    for (int k = 0; k < 3; ++k)
      if (X.s[k].id.i == i && X.s[k].id.j == j) return true;
    return false;
  };
  auto on_plane = [&](PairId x) {
    for (int u = 0; u < 3; ++u)
      for (int w = 0; w < 3; ++w)
        if (X.s[u].id.i == x.i && X.s[w].id.j == x.j && member(X.s[w].id.i, X.s[u].id.j)) return true;
    return false;
  };
  for (int e = aP.start[A.id.i]; e < aP.start[A.id.i + 1]; ++e) {
    const int k = aP.nbr[e];
    bool zero = false;
    for (int u = 0; u < 3 && !zero; ++u) zero = on_plane({k, X.s[u].id.j}) && on_plane({A.id.i, X.s[u].id.j});
    if (!zero && sigma * exact_sign([&](auto L) { return dot(n(L), sub(c.pvec(L, k), c.pvec(L, A.id.i))); }) > 0)
      return std::nullopt;
  }
  for (int e = aQ.start[A.id.j]; e < aQ.start[A.id.j + 1]; ++e) {
    const int k = aQ.nbr[e];
    bool zero = false;
    for (int u = 0; u < 3 && !zero; ++u) zero = on_plane({X.s[u].id.i, k}) && on_plane({X.s[u].id.i, A.id.j});
    // n'·(q'_k − q'_j) < 0 ⇔ n'·dm((·,k), (·,j)) > 0 (dm = −R(q_k − q_j))
    if (!zero && sigma * exact_sign([&](auto L) { return dot(n(L), c.dm(L, PairId{0, k}, PairId{0, A.id.j})); }) > 0)
      return std::nullopt;
  }
  // Certified: the entry is at s = (n·a)/(n·d) (in units of d), on the triangle.
  Cast3 r;
  r.hit = true;
  const double na = accurate_dd([&](auto L) { return dot(n(L), c.pt(L, A)); });
  const double ndv = accurate_dd([&](auto L) { return dot(n(L), dl(L)); });
  const double sp = ha == 0 ? 0.0 : na / ndv;
  r.distance = sp * d.norm();
  const Vec3 dir = d.normalized();
  r.translation = Rp * (r.distance * dir);
  Vec3 nn;
  {
    const auto v3 = n(exact::LiftDD{});
    for (int k = 0; k < 3; ++k) nn[k] = v3[k].hi;
  }
  r.normal = Rp * (sigma * nn).stableNormalized();
  // Contact: the entry point's weights on the triangle (rounded), its P part.
  const Vec3 x = sp * d, a = approx(A.id), b = approx(B.id), cc = approx(C.id);
  const Vec3 nr = (b - a).cross(cc - a);
  double l[3] = {nr.dot((b - x).cross(cc - x)), nr.dot((cc - x).cross(a - x)), nr.dot((a - x).cross(b - x))};
  double sum = 0;
  for (double& z : l) sum += z = std::max(0.0, z);
  Vec3 wp = Vec3::Zero();
  for (int k = 0; k < 3; ++k) wp += (sum > 0 ? l[k] / sum : 1.0 / 3) * PD.v[T[k]->id.i];
  r.witness_p = r.witness_q = Rp * wp + tp_world;
  int vp[3], vq[3], np = 0, nq = 0;
  Vec3 wq = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    wq += (sum > 0 ? l[k] / sum : 1.0 / 3) * QD.v[T[k]->id.j];
    if (std::find(vp, vp + np, T[k]->id.i) == vp + np) vp[np++] = T[k]->id.i;
    if (std::find(vq, vq + nq, T[k]->id.j) == vq + nq) vq[nq++] = T[k]->id.j;
  }
  r.feature_p = feature_of(Pp, vp, np, wp);
  r.feature_q = feature_of(Qp, vq, nq, wq);
  return r;
  };
  if (ny == 3)
    if (auto r = certify(Y[0], Y[1], Y[2])) return r;
  // Entry through an edge of M (the ray cast ends on an edge, or its triangle's plane contains
  // d): the triangles of the candidate facets of M around each edge of the final simplex — the
  // faces of P (Q) at a P (Q) edge, the parallelograms with the other side's neighbours.
  auto third = [](const PolytopeData& D, const VertexAdjacency& A, int u, int w, std::vector<int>& out) {
    for (int e = A.start[u]; e < A.start[u + 1]; ++e)
      if (A.nbr[e] == w) {
        const int h = A.he[e], tw = D.levels[0].twin[h];
        out.push_back(D.levels[0].fv[3 * (h / 3) + (h % 3 + 2) % 3]);
        out.push_back(D.levels[0].fv[3 * (tw / 3) + (tw % 3 + 2) % 3]);
      }
  };
  auto complete = [&](PairId ya, PairId yb) -> std::optional<Cast3> {
    std::vector<PairId> cand;
    std::vector<int> t;
    if (ya.j == yb.j) {
      third(PD, aP, ya.i, yb.i, t);
      for (int v : t) cand.push_back({v, ya.j});
      for (int e = aQ.start[ya.j]; e < aQ.start[ya.j + 1]; ++e) cand.push_back({ya.i, aQ.nbr[e]}), cand.push_back({yb.i, aQ.nbr[e]});
    } else if (ya.i == yb.i) {
      third(QD, aQ, ya.j, yb.j, t);
      for (int v : t) cand.push_back({ya.i, v});
      for (int e = aP.start[ya.i]; e < aP.start[ya.i + 1]; ++e) cand.push_back({aP.nbr[e], ya.j}), cand.push_back({aP.nbr[e], yb.j});
    } else {
      cand = {{ya.i, yb.j}, {yb.i, ya.j}};
    }
    for (const PairId& yc : cand)
      if (!(yc == ya) && !(yc == yb))
        if (auto r = certify(ya, yb, yc)) return r;
    return std::nullopt;
  };
  if (ny == 2)
    if (auto r = complete(Y[0], Y[1])) return r;
  if (ny == 3)
    for (int k = 0; k < 3; ++k)
      if (auto r = complete(Y[k], Y[(k + 1) % 3])) return r;
  return std::nullopt;
}

// ---- Exact comparison of a distance with a radius (rounded shapes; distance_compare.hpp) -------

CorePoints::CorePoints(const ConvexPolytope& S) : data_(&data_of(S)), adj_(&vertex_adjacency(*data_)) {}

CorePoints::CorePoints(const FlatShape3& F) {
  auto d = std::make_shared<PolytopeData>();
  d->v = F.v;
  auto a = std::make_shared<VertexAdjacency>();
  const int k = static_cast<int>(F.v.size());
  a->start.assign(1, 0);
  for (int v = 0; v < k; ++v) {
    if (k == 2) a->nbr.push_back(1 - v);
    if (k >= 3) a->nbr.push_back((v + k - 1) % k), a->nbr.push_back((v + 1) % k);
    a->start.push_back(static_cast<int>(a->nbr.size()));
  }
  Vec3 lo = F.v[0], hi = F.v[0], sum = Vec3::Zero();
  for (const Vec3& p : F.v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p), sum += p;
  a->extent = hi - lo;
  a->centroid = sum / k;
  a->cube_k = 1;
  a->cube.assign(6, 0);
  own_data_ = d, own_adj_ = a;
  data_ = d.get(), adj_ = a.get();
}

namespace {

// sign(dist(0, conv of c's points)² − T) for T = thr(L) (a polynomial), on the exact GJK's final
// simplex; −1 on contact (T > 0 by the callers). `slope` (if non-null, no contact): −sign(U·dir(L)).
template <class Thr, class DirF>
int compare_on(const Ctx& c, const VertexAdjacency& aP, const VertexAdjacency& aQ, Thr&& thr, DirF&& dir,
               int* slope) {
  const GjkResult g = gjk_loop(c, aP, aQ);
  if (g.contact) return -1;
  const Reduced& X = g.X;
  const Member& a = X.s[0];
  int s;
  if (X.size == 1) {
    s = exact_sign([&](auto L) {
      const auto v = c.pt(L, a);
      return dot(v, v) - thr(L);
    });
  } else if (X.size == 2) {
    s = exact_sign([&](auto L) {
      const auto e = c.dm(L, X.s[1].id, a.id);
      const auto x = cross(e, c.pt(L, a));
      return dot(x, x) - thr(L) * dot(e, e);
    });
  } else {
    s = exact_sign([&](auto L) {
      const auto n = cross(c.dm(L, X.s[1].id, a.id), c.dm(L, X.s[2].id, a.id));
      const auto h = dot(n, c.pt(L, a));
      return h * h - thr(L) * dot(n, n);
    });
  }
  if (slope) {
    const Dir U{&c, X.size, {X.s[0], X.size > 1 ? X.s[1] : Member{}, X.size > 2 ? X.s[2] : Member{}}, X.tri_sign};
    *slope = -exact_sign([&](auto L) { return dot(U(L), dir(L)); });
  }
  return s;
}

}  // namespace

int distance_compare(const CorePoints& P, const Pose3& pp, const CorePoints& Q, const Pose3& pq, const Vec3& d,
                     double lambda, double rp, double rq, int* slope) {
  Eigen::Matrix3d Rp;
  const RelativePose rel = relative_pose(pp, pq, &Rp);
  const Eigen::Matrix3d RpT = Rp.transpose();
  Ctx c{P.data(), Q.data(), rel};
  c.RpT = &RpT, c.od = d, c.lam = lambda;
  c.off_approx = RpT * (lambda * d);
  // g(λ) = dist(λd, M) has g'(λ) = (λd − c)/|λd − c|·d, and w = c − λd ∝ U (P's frame): the sign
  // is −U·(Rpᵀ d), Rpᵀ d kept exact as a polynomial.
  return compare_on(
      c, P.adjacency(), Q.adjacency(), [&](auto L) { return (L(rp) + L(rq)) * (L(rp) + L(rq)); },
      [&](auto L) {
        V3<Num<decltype(L)>> v;
        for (int k = 0; k < 3; ++k) v[k] = L(RpT(k, 0)) * L(d[0]) + L(RpT(k, 1)) * L(d[1]) + L(RpT(k, 2)) * L(d[2]);
        return v;
      },
      slope);
}

int line_distance_compare(const CorePoints& P, const Pose3& pp, const CorePoints& Q, const Pose3& pq, const Vec3& d,
                          double rp, double rq) {
  Eigen::Matrix3d Rp;
  const RelativePose rel = relative_pose(pp, pq, &Rp);
  const Vec3 dp = Rp.transpose() * d;
  Ctx c{P.data(), Q.data(), rel};
  c.proj = &dp;
  // π(v) = |d|²·(v's component across d): compare with ((rp + rq)·|d|²)².
  return compare_on(c, P.adjacency(), Q.adjacency(),
                    [&](auto L) {
                      const auto dd = L(dp[0]) * L(dp[0]) + L(dp[1]) * L(dp[1]) + L(dp[2]) * L(dp[2]);
                      return (L(rp) + L(rq)) * (L(rp) + L(rq)) * dd * dd;
                    },
                    [](auto L) { return V3<Num<decltype(L)>>{L(0.0), L(0.0), L(0.0)}; }, nullptr);
}

Distance3 signed_distance_path(const ConvexPolytope& P, const Pose3& pp, const ConvexPolytope& Q, const Pose3& pq,
                               const SignedDistancePath& path, bool* fast_used) {
  Eigen::Matrix3d Rp;
  const RelativePose rel = relative_pose(pp, pq, &Rp);
  return signed_distance_gjk(P, Q, rel, Rp, pp.translation, path, fast_used);
}

}  // namespace convex3

Distance3 signed_distance(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q, const Pose3& pose_q) {
  Eigen::Matrix3d Rp;
  const convex3::RelativePose rel = convex3::relative_pose(pose_p, pose_q, &Rp);
  return convex3::signed_distance_gjk(P, Q, rel, Rp, pose_p.translation);
}

}  // namespace pendepth
