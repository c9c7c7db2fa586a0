// σ_d for two convex polygons in O(log n + log m) without building M (DHS §3; docs/algorithms.md
// §R2.7).
//
// Notation: A = P, B = −Q (normal form of −Q starts at Q's top vertex), t the placement of Q,
// d the direction. X(v) = cross(d, v − t). Front edges of a polygon are those with
// cross(d, e) > 0; they form one contiguous range in angle order (found by binary search over the
// angle-sorted edges) along which X strictly increases. The front chain of M is the merge of the
// front chains of A and B in slope order (ties: A first); the ray t + s·d̂ leaves M where X of the
// merge path crosses 0. Simultaneous prune-and-search on the two median edges finds that crossing
// in O(log p + log q) steps; every decision is an exact predicate on input coordinates.
#include <pendepth/depth2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "convex2/convex_cast.hpp"
#include "convex2/minkowski_sum.hpp"
#include "geometry/exact.hpp"

namespace pendepth {
namespace {

using predicates::compare_angle;

// One polygon seen as A (= P) or B (= −Q): vertex k of its normal form is poly[(base + k) mod n]
// (negated for B, whose normal form starts at Q's top vertex).
struct Side {
  const ConvexPolygon& poly;
  bool negated;
  std::size_t size() const { return poly.size(); }
  std::size_t base() const { return negated ? poly.top() : 0; }
  std::size_t input(std::size_t k) const {  // index into poly's normal form
    std::size_t i = base() + k, n = poly.size();
    while (i >= n) i -= n;
    return i;
  }
  Vec2 v(std::size_t k) const {
    const Vec2& p = poly.vertex_cached(input(k));
    return negated ? Vec2(-p) : p;
  }
};

// A split point in [lo, hi) near the middle. On large ranges it is moved back to the start of a
// 64-vertex block of the polygon (index base + k ≡ 0 mod 64), whose vertices k and k+1 live in
// ConvexPolygon's compact sample array: the searches' first steps then stay in cache. Any split
// point keeps the searches correct; this one keeps them O(log n).
std::size_t split(std::size_t lo, std::size_t hi, std::size_t base, std::size_t n) {
  const std::size_t mid = lo + (hi - lo - 1) / 2;
  if (hi - lo < 2 * ConvexPolygon::kBlock) return mid;
  return mid - (base + mid) % n % ConvexPolygon::kBlock;
}

// First index in [lo, hi) where pred is true (pred monotone false...true); hi if none.
template <class F>
std::size_t partition_point(const Side& S, std::size_t start, std::size_t lo, std::size_t hi, F&& pred) {
  while (lo < hi) {
    std::size_t mid = split(lo, hi, S.base() + start, S.size());
    if (pred(mid)) hi = mid;
    else lo = mid + 1;
  }
  return lo;
}

// Front chain for d: start vertex index s (normal form) and number of edges p >= 1.
struct Chain {
  std::size_t start, edges;
};
struct Chains {
  Chain forward, backward;  // front chains for d and for −d
};

// Edges are angle-sorted in [0, 2π). The front chain for d holds the edges with angle in
// (θ, θ + π), θ = angle(d). One lower_bound per direction serves both d and −d: at most one
// edge is parallel to each (strict convexity), and upper_bound = lower_bound + that edge.
Chains front_chains(const Side& S, const Vec2& d) {
  const std::size_t n = S.size();
  const Vec2 zero(0, 0), nd = -d;
  auto lower = [&](const Vec2& x, std::size_t& lb, std::size_t& ub) {
    lb = partition_point(S, 0, 0, n, [&](std::size_t i) { return compare_angle(S.v(i), S.v(i + 1), zero, x) >= 0; });
    ub = lb + (lb < n && compare_angle(S.v(lb), S.v(lb + 1), zero, x) == 0);
  };
  std::size_t ld, ud, lnd, und;
  lower(d, ld, ud);
  lower(nd, lnd, und);
  auto make = [&](std::size_t s, std::size_t f) {
    s %= n;
    return Chain{s, (f + n - s) % n};
  };
  return {make(ud, lnd), make(und, ld)};
}

struct Exit {
  bool crosses = false;   // the line through t along d crosses int M
  std::size_t ia = 0, iq = 0;     // path vertex u (X < 0) as P index, Q index (normal forms)
  bool edge_from_p = true;        // the exit edge u->w is P's edge ia, else Q's edge iq (reversed)
  bool at_vertex = false;         // the line passes exactly through w
  std::size_t wa = 0, wq = 0;     // vertex w as P index, Q index
  int s_sign = 0;                 // sign of the exit parameter s
  Vec2 ua, ub;                    // u = ua + ub (P vertex, −Q vertex)
  Vec2 e0, e1;                    // exit edge vector e = e1 − e0 (input coordinates, exact)
};

// cross(u − t, e): its sign is the sign of the exit parameter, its value the numerator of s.
template <class L>
auto exit_numerator(L lift, const Exit& ex, const Vec2& t) {
  auto rx = lift(ex.ua.x()) + lift(ex.ub.x()) - lift(t.x());
  auto ry = lift(ex.ua.y()) + lift(ex.ub.y()) - lift(t.y());
  return rx * (lift(ex.e1.y()) - lift(ex.e0.y())) - ry * (lift(ex.e1.x()) - lift(ex.e0.x()));
}

Exit find_exit(const Side& A, const Side& B, const Chain& ca, const Chain& cb, const Vec2& t, const Vec2& d) {
  const std::size_t p = ca.edges, q = cb.edges;
  auto av = [&](std::size_t i) { return A.v(ca.start + i); };
  auto bv = [&](std::size_t j) { return B.v(cb.start + j); };
  // sign of X at merge-path point (i, j): cross(d, a_i + b_j − t)
  auto X = [&](std::size_t i, std::size_t j) {
    const Vec2 a = av(i), b = bv(j);
    // Fast filter: sums of three doubles then two products and a difference; the error is at
    // most 4u·(|d.x|·Sy + |d.y|·Sx) with S the sums of absolute values (see docs/algorithms.md).
    const double sx = a.x() + b.x() - t.x(), sy = a.y() + b.y() - t.y();
    const double Sx = std::abs(a.x()) + std::abs(b.x()) + std::abs(t.x());
    const double Sy = std::abs(a.y()) + std::abs(b.y()) + std::abs(t.y());
    const double bound = 5 * exact::kUnit * (std::abs(d.x()) * Sy + std::abs(d.y()) * Sx) + exact::kTiny;
    return exact::exact_sign_filtered(d.x() * sy - d.y() * sx, bound, [&](auto L) {
      return L(d.x()) * (L(a.y()) + L(b.y()) - L(t.y())) - L(d.y()) * (L(a.x()) + L(b.x()) - L(t.x()));
    });
  };
  // A-edge k precedes B-edge l in slope order (ties: A first).
  auto before = [&](std::size_t k, std::size_t l) {
    return predicates::cross_edges(av(k), av(k + 1), bv(l), bv(l + 1)) >= 0;
  };

  Exit ex;
  if (X(0, 0) >= 0 || X(p, q) <= 0) return ex;  // the line misses int M (or is tangent)
  ex.crosses = true;

  std::size_t ilo = 0, ihi = p, jlo = 0, jhi = q;
  while (ilo < ihi && jlo < jhi) {
    std::size_t k = split(ilo, ihi, A.base() + ca.start, A.size());
    std::size_t l = split(jlo, jhi, B.base() + cb.start, B.size());
    if (before(k, l)) {
      if (X(k + 1, l) < 0) ilo = k + 1;
      else jhi = l;
    } else {
      if (X(k, l + 1) < 0) jlo = l + 1;
      else ihi = k;
    }
  }
  // Finish along the one remaining row/column, clamped to the part of it the merge path visits
  // (the clamp searches run inside [jlo, jhi] / [ilo, ihi], which is all the answer can use).
  std::size_t i, j;
  if (ilo == ihi) {
    i = ilo;
    auto in_b = [&](std::size_t lo, std::size_t hi, auto&& pred) { return partition_point(B, cb.start, lo, hi, pred); };
    std::size_t lo = i == 0 ? jlo : in_b(jlo, jhi, [&](std::size_t l) { return before(i - 1, l); });
    std::size_t hi = i == p ? jhi : in_b(jlo, jhi, [&](std::size_t l) { return before(i, l); });
    j = in_b(lo, std::max(lo, hi) + 1, [&](std::size_t jj) { return X(i, jj) >= 0; });
  } else {
    j = jlo;
    auto in_a = [&](std::size_t lo, std::size_t hi, auto&& pred) { return partition_point(A, ca.start, lo, hi, pred); };
    std::size_t lo = j == 0 ? ilo : in_a(ilo, ihi, [&](std::size_t k) { return !before(k, j - 1); });
    std::size_t hi = j == q ? ihi : in_a(ilo, ihi, [&](std::size_t k) { return !before(k, j); });
    i = in_a(lo, std::max(lo, hi) + 1, [&](std::size_t ii) { return X(ii, j) >= 0; });
  }
  // Predecessor on the merge path: the last traversed edge is the later of A-edge i−1, B-edge j−1.
  std::size_t ui = i, uj = j;
  bool from_a;
  if (i > 0 && j > 0) from_a = !before(i - 1, j - 1);
  else from_a = i > 0;
  if (from_a) ui = i - 1;
  else uj = j - 1;

  ex.ia = A.input(ca.start + ui);
  ex.iq = B.input(cb.start + uj);
  ex.edge_from_p = from_a;
  ex.at_vertex = X(i, j) == 0;
  ex.wa = A.input(ca.start + i);
  ex.wq = B.input(cb.start + j);
  // sign of s = sign of cross(u − t, e) where e is the exit edge vector.
  ex.ua = av(ui);
  ex.ub = bv(uj);
  ex.e0 = from_a ? av(ui) : bv(uj);
  ex.e1 = from_a ? av(ui + 1) : bv(uj + 1);
  ex.s_sign = exact::exact_sign([&](auto L) { return exit_numerator(L, ex, t); });
  return ex;
}

Depth2 none(DepthKind kind) {
  Depth2 r;
  r.kind = kind;
  return r;
}

void check_query(const Vec2& t, const Vec2& d) {
  convex2::require_finite(t, "placement t");
  convex2::require_finite(d, "direction d");
  if (d.x() == 0 && d.y() == 0) throw InvalidInput("direction d is the zero vector");
}

}  // namespace

namespace {
// d scaled by a power of two (exact, same direction) so that its largest component is in [1, 2):
// |d|, d·d and the cross products neither underflow nor overflow for any finite non-zero d.
Vec2 normalized_scale(const Vec2& d) {
  const int e = std::ilogb(std::max(std::abs(d.x()), std::abs(d.y())));
  return Vec2(std::ldexp(d.x(), -e), std::ldexp(d.y(), -e));
}
}  // namespace

namespace {

// The result of moving Q from t along d̂ to the exit point of `ex` (s > 0).
Depth2 exit_result(const ConvexPolygon& P, const ConvexPolygon& Q, const Exit& ex, const Vec2& t, const Vec2& d,
                   DepthKind kind, bool overlapping) {
  // s = |d| · cross(u − t, e) / cross(d, e), numerator and denominator accurate.
  const Vec2 e0 = ex.e0, e1 = ex.e1;
  double ratio = exact::accurate_ratio(
      [&](auto L) { return exit_numerator(L, ex, t); },
      [&](auto L) { return L(d.x()) * (L(e1.y()) - L(e0.y())) - L(d.y()) * (L(e1.x()) - L(e0.x())); });
  const double dn = std::sqrt(exact::accurate_value([&](auto L) { return L(d.x()) * L(d.x()) + L(d.y()) * L(d.y()); }));
  Depth2 r;
  r.kind = kind;
  r.overlapping = overlapping;
  r.depth = std::max(ratio * dn, 0.0);
  r.normal = d / dn;
  r.translation = r.depth * r.normal;
  const Vec2 f = t + r.translation;
  if (ex.at_vertex) {
    r.feature_p = {FeatureKind::Vertex, int(ex.wa)};
    r.feature_q = {FeatureKind::Vertex, int(ex.wq)};
    r.witness_p = r.witness_q = P[ex.wa];
  } else if (ex.edge_from_p) {
    r.feature_p = {FeatureKind::Edge, int(ex.ia)};
    r.feature_q = {FeatureKind::Vertex, int(ex.iq)};
    r.witness_q = r.witness_p = Q[ex.iq] + f;
  } else {
    r.feature_p = {FeatureKind::Vertex, int(ex.ia)};
    r.feature_q = {FeatureKind::Edge, int(ex.iq)};
    r.witness_q = r.witness_p = P[ex.ia];
  }
  return r;
}

}  // namespace

Depth2 directional_depth(const ConvexPolygon& P, const ConvexPolygon& Q, const Vec2& t, const Vec2& d_in) {
  check_query(t, d_in);
  const Vec2 d = normalized_scale(d_in);
  const Side A{P, false}, B{Q, true};
  const Chains ca = front_chains(A, d), cb = front_chains(B, d);
  const Exit ex = find_exit(A, B, ca.forward, cb.forward, t, d);
  if (!ex.crosses || ex.s_sign <= 0) return none(DepthKind::Directional);
  // t must also lie strictly after the entry: the exit along −d, on the back chains.
  const Exit en = find_exit(A, B, ca.backward, cb.backward, t, Vec2(-d));
  if (!en.crosses || en.s_sign <= 0) return none(DepthKind::Directional);
  return exit_result(P, Q, ex, t, d, DepthKind::Directional, true);
}

Depth2 separation_depth(const ConvexPolygon& P, const ConvexPolygon& Q, const Vec2& t, const Vec2& d_in) {
  check_query(t, d_in);
  const Vec2 d = normalized_scale(d_in);
  const Side A{P, false}, B{Q, true};
  const Chains ca = front_chains(A, d), cb = front_chains(B, d);
  // M is convex, so the ray meets int M in one interval: Q is free for good once past its end.
  const Exit ex = find_exit(A, B, ca.forward, cb.forward, t, d);
  if (!ex.crosses || ex.s_sign <= 0) return none(DepthKind::Separation);
  const Exit en = find_exit(A, B, ca.backward, cb.backward, t, Vec2(-d));
  return exit_result(P, Q, ex, t, d, DepthKind::Separation, en.crosses && en.s_sign > 0);
}

}  // namespace pendepth

// ---- shape cast (src/convex2/convex_cast.hpp): the entry of the ray into the closed M ----


namespace pendepth::convex2 {

std::optional<Cast2> convex_cast(const ConvexPolygon& P, const ConvexPolygon& Q, const Vec2& t, const Vec2& d_in) {
  const Vec2 d = normalized_scale(d_in);
  const Side A{P, false}, B{Q, true};
  const Chains ca = front_chains(A, d), cb = front_chains(B, d);
  // X = cross(d, x − t) increases along the front chains from M's extreme vertex on one side of
  // the line to the other: the line meets the closed M iff X(start) <= 0 <= X(end).
  auto X = [&](const Vec2& a, const Vec2& b) {
    return exact::exact_sign([&](auto L) {
      return L(d.x()) * (L(a.y()) + L(b.y()) - L(t.y())) - L(d.y()) * (L(a.x()) + L(b.x()) - L(t.x()));
    });
  };
  const int lo = X(A.v(ca.forward.start), B.v(cb.forward.start));
  const int hi = X(A.v(ca.forward.start + ca.forward.edges), B.v(cb.forward.start + cb.forward.edges));
  Cast2 r;
  if (lo > 0 || hi < 0) {  // the line misses M
    r.distance = std::numeric_limits<double>::infinity();
    return r;
  }
  if (lo == 0 || hi == 0) return std::nullopt;  // tangent: contact on ∂M only
  // The line crosses int M: it enters where it leaves M along −d (λ along −d, s = −λ).
  Exit en = find_exit(A, B, ca.backward, cb.backward, t, Vec2(-d));
  bool zero = en.s_sign == 0;
  if (en.s_sign > 0) {
    // The entry is behind t, which is not in int M: t is on ∂M at the exit (touching) or past M.
    const Exit ex = find_exit(A, B, ca.forward, cb.forward, t, d);
    if (ex.s_sign < 0) {
      r.distance = std::numeric_limits<double>::infinity();
      return r;
    }
    en = ex;
    zero = true;
  }
  double s = 0;
  if (!zero)
    s = exact::accurate_ratio([&](auto L) { return exit_numerator(L, en, t); },
                              [&](auto L) {
                                return L(d.x()) * (L(en.e1.y()) - L(en.e0.y())) - L(d.y()) * (L(en.e1.x()) - L(en.e0.x()));
                              });
  const double dn = std::sqrt(exact::accurate_value([&](auto L) { return L(d.x()) * L(d.x()) + L(d.y()) * L(d.y()); }));
  r.hit = true;
  r.distance = s * dn;
  r.translation = s * d;
  // M's edge at the contact, counter-clockwise (P's edge, or −Q's): outward normal (e.y, −e.x).
  const Vec2 e(exact::accurate_value([&](auto L) { return L(en.e1.x()) - L(en.e0.x()); }),
               exact::accurate_value([&](auto L) { return L(en.e1.y()) - L(en.e0.y()); }));
  r.normal = Vec2(e.y(), 0 - e.x()) / std::hypot(e.x(), e.y());
  const Vec2 f = t + r.translation;
  if (en.at_vertex) {
    r.feature_p = {FeatureKind::Vertex, int(en.wa)};
    r.feature_q = {FeatureKind::Vertex, int(en.wq)};
    r.witness_p = r.witness_q = P[en.wa];
  } else if (en.edge_from_p) {
    r.feature_p = {FeatureKind::Edge, int(en.ia)};
    r.feature_q = {FeatureKind::Vertex, int(en.iq)};
    r.witness_q = r.witness_p = Q[en.iq] + f;
  } else {
    r.feature_p = {FeatureKind::Vertex, int(en.ia)};
    r.feature_q = {FeatureKind::Edge, int(en.iq)};
    r.witness_q = r.witness_p = P[en.ia];
  }
  return r;
}

// ---- distance, localised (convex_cast.hpp: convex_nearest_vertex) ----

namespace {

// front_chains for the direction of the edge x0 → x1 (an edge of A or B, not a Vec2 direction).
Chains edge_chains(const Side& S, const Vec2& x0, const Vec2& x1) {
  const std::size_t n = S.size();
  auto lower = [&](const Vec2& y0, const Vec2& y1, std::size_t& lb, std::size_t& ub) {
    lb = partition_point(S, 0, 0, n, [&](std::size_t i) { return compare_angle(S.v(i), S.v(i + 1), y0, y1) >= 0; });
    ub = lb + (lb < n && compare_angle(S.v(lb), S.v(lb + 1), y0, y1) == 0);
  };
  std::size_t ld, ud, lnd, und;
  lower(x0, x1, ld, ud);
  lower(x1, x0, lnd, und);
  auto make = [&](std::size_t s, std::size_t f) {
    s %= n;
    return Chain{s, (f + n - s) % n};
  };
  return {make(ud, lnd), make(und, ld)};
}

}  // namespace

std::optional<std::array<std::size_t, 2>> convex_nearest_vertex(const ConvexPolygon& P, const ConvexPolygon& Q,
                                                                const Vec2& t) {
  const Side A{P, false}, B{Q, true};
  // A point well inside M: the centroid of three vertices of each shape (rounding only moves it
  // slightly; the crossing test below is exact for the direction actually used).
  auto inner = [](const Side& S) {
    const std::size_t n = S.size();
    return Vec2((S.v(0) + S.v(n / 3) + S.v(2 * n / 3)) / 3);
  };
  Vec2 d = inner(A) + inner(B) - t;
  if (!d.allFinite() || (d.x() == 0 && d.y() == 0)) return std::nullopt;
  d = normalized_scale(d);
  const Chains ca = front_chains(A, d), cb = front_chains(B, d);
  auto X = [&](const Vec2& a, const Vec2& b) {
    return exact::exact_sign([&](auto L) {
      return L(d.x()) * (L(a.y()) + L(b.y()) - L(t.y())) - L(d.y()) * (L(a.x()) + L(b.x()) - L(t.x()));
    });
  };
  if (X(A.v(ca.forward.start), B.v(cb.forward.start)) >= 0 ||
      X(A.v(ca.forward.start + ca.forward.edges), B.v(cb.forward.start + cb.forward.edges)) <= 0)
    return std::nullopt;
  const Exit en = find_exit(A, B, ca.backward, cb.backward, t, Vec2(-d));
  if (!en.crosses || en.s_sign >= 0) return std::nullopt;  // t must lie before the entry
  // The entry edge E (x0 → x1, counter-clockwise on M): t is strictly outside its line.
  const Vec2 x0 = en.e0, x1 = en.e1;
  const Chains wa = edge_chains(A, x0, x1), wb = edge_chains(B, x0, x1);
  // outside: t strictly right of the edge line through v; proj: sign of (x1 − x0)·(t − v).
  auto outside = [&](const Vec2& e0, const Vec2& e1, const Vec2& a, const Vec2& b) {
    return exact::exact_sign([&](auto L) {
             return (L(e1.x()) - L(e0.x())) * (L(t.y()) - L(a.y()) - L(b.y())) -
                    (L(e1.y()) - L(e0.y())) * (L(t.x()) - L(a.x()) - L(b.x()));
           }) < 0;
  };
  auto proj = [&](const Vec2& e0, const Vec2& e1, const Vec2& a, const Vec2& b) {
    return exact::exact_sign([&](auto L) {
      return (L(e1.x()) - L(e0.x())) * (L(t.x()) - L(a.x()) - L(b.x())) +
             (L(e1.y()) - L(e0.y())) * (L(t.y()) - L(a.y()) - L(b.y()));
    });
  };
  // "The nearest point is at or before this edge" (start vertex a + b): before the entry edge
  // the edge must face t and t project before its start; from the entry edge on, either.
  auto R = [&](bool after, const Vec2& e0, const Vec2& e1, const Vec2& a, const Vec2& b) {
    const bool out = outside(e0, e1, a, b);
    if (!after && !out) return false;
    if (after && !out) return true;
    return proj(e0, e1, a, b) <= 0;
  };
  // The first edge of a half window (chains ca, cb merged in slope order) where R holds: the path
  // point (A chain index, B chain index) of its start, or nullopt.
  auto first_true = [&](const Chain& ka, const Chain& kb, bool after) -> std::optional<std::array<std::size_t, 2>> {
    const std::size_t p = ka.edges, q = kb.edges;
    auto av = [&](std::size_t i) { return A.v(ka.start + i); };
    auto bv = [&](std::size_t j) { return B.v(kb.start + j); };
    auto before = [&](std::size_t k, std::size_t l) {
      return predicates::cross_edges(av(k), av(k + 1), bv(l), bv(l + 1)) >= 0;
    };
    auto j_of = [&](std::size_t k) {  // B edges before A edge k
      return partition_point(B, kb.start, 0, q, [&](std::size_t l) { return before(k, l); });
    };
    auto i_of = [&](std::size_t l) {  // A edges before B edge l (ties: A first)
      return partition_point(A, ka.start, 0, p, [&](std::size_t k) { return !before(k, l); });
    };
    const std::size_t kA = partition_point(A, ka.start, 0, p, [&](std::size_t k) {
      return R(after, av(k), av(k + 1), av(k), bv(j_of(k)));
    });
    const std::size_t lB = partition_point(B, kb.start, 0, q, [&](std::size_t l) {
      return R(after, bv(l), bv(l + 1), av(i_of(l)), bv(l));
    });
    if (kA == p && lB == q) return std::nullopt;
    if (lB == q || (kA < p && before(kA, lB))) return std::array<std::size_t, 2>{kA, j_of(kA)};
    return std::array<std::size_t, 2>{i_of(lB), lB};
  };
  auto vertex = [&](const Chain& ka, const Chain& kb, std::size_t i, std::size_t j) {
    return std::array<std::size_t, 2>{A.input(ka.start + i), B.input(kb.start + j)};
  };
  // First half: the edges before the entry edge (angles in (θ − π, θ)), the backward chains.
  if (const auto h = first_true(wa.backward, wb.backward, false))
    return vertex(wa.backward, wb.backward, (*h)[0], (*h)[1]);
  // The entry edge's direction (with a parallel edge of the other shape), starting where the
  // first half ends.
  const Vec2 ea = A.v(wa.backward.start + wa.backward.edges), eb = B.v(wb.backward.start + wb.backward.edges);
  if (R(true, x0, x1, ea, eb)) return vertex(wa.backward, wb.backward, wa.backward.edges, wb.backward.edges);
  if (const auto h = first_true(wa.forward, wb.forward, true)) return vertex(wa.forward, wb.forward, (*h)[0], (*h)[1]);
  return std::nullopt;
}

}  // namespace pendepth::convex2
