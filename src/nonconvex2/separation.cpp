// Complete separation along d of two simple polygons (DHS §6, last paragraphs): the smallest s ≥ 0
// with Q + t + s'·d̂ interior-disjoint from P for all s' ≥ s.
//
// Frame: u(x) = d·x (along the motion), w(x) = d × x (across it); an orientation-preserving
// similarity, never computed: every decision is an exact polynomial sign in the input doubles.
// For each level w, int P's slice ends at E_P(w) (largest u) and int(Q + t)'s slice starts at
// e_Q(w); at level w the overlapping shifts have supremum E_P(w) − e_Q(w), so the answer is
// max(0, sup_w (E_P − e_Q)) over the open common w-range. E_P is the upper envelope of the edges
// of P's outer ring with d × e > 0 (interior on their −u side: holes and other edges are never
// rightmost), e_Q the lower envelope of Q's outer-ring edges with d × e < 0 — the "visibility
// profile from the point at infinity" of the paper, each built in linear time by the visibility
// walk of envelope.cpp. Both are linear between merged breakpoints, so the supremum is the largest
// one-sided limit at a breakpoint: for each elementary open interval, (P's envelope edge − Q's
// envelope edge) evaluated at both ends. Zero-width contacts (edges parallel to d, touching
// envelopes) do not count because only open intervals are used.
//
// Cost: O(n + m) per query (two envelope walks, one linear merge), as in the paper; plus the overlap
// test whose answer the result reports. The previous divide-and-conquer envelope (O(n log n)) is
// kept as the tests' oracle (tests/nonconvex2/envelope_dc.hpp).
#include <algorithm>
#include <cmath>

#include "geometry/exact.hpp"
#include "nonconvex2/envelope.hpp"
#include "nonconvex2/query.hpp"

namespace pendepth {

namespace {

using exact::exact_sign;

using Piece = nonconvex2::EnvelopePiece;

// A breakpoint level: a vertex of P (q = false) or of Q + t.
struct Level {
  std::uint32_t v;
  bool q;
};

}  // namespace

Depth2 PairDepth2::separation(const Vec2& t, const Vec2& d_in) const {
  const Vec2 d = nonconvex2::check_and_scale(t, d_in);
  const Polygon &P = impl_->P, &Q = impl_->Q;
  const auto VP = P.vertices(), VQ = Q.vertices();
  const std::vector<Piece> ep = nonconvex2::right_envelope(P, d);
  std::vector<Piece> eq = nonconvex2::right_envelope(Q, -d);  // max of −u over levels −w: reverse to increasing w
  std::reverse(eq.begin(), eq.end());
  for (Piece& p : eq) std::swap(p.lo, p.hi);

  auto point = [&](const Level& l) -> const Vec2& { return l.q ? VQ[l.v] : VP[l.v]; };
  const Vec2 zero(0, 0);
  auto shift = [&](const Level& l) -> const Vec2& { return l.q ? t : zero; };
  auto cmp = [&](const Level& a, const Level& b) {
    if (a.v == b.v && a.q == b.q) return 0;  // one vertex (a shifted one would reach the rational tier)
    const Vec2 &p = point(a), &pt = shift(a), &q = point(b), &qt = shift(b);
    return exact_sign([&](auto L) {
      auto x = L(p.x()) + L(pt.x()) - L(q.x()) - L(qt.x()), y = L(p.y()) + L(pt.y()) - L(q.y()) - L(qt.y());
      return L(d.x()) * y - L(d.y()) * x;
    });
  };

  Depth2 r;
  r.kind = DepthKind::Separation;
  if (ep.empty() || eq.empty()) return r;
  const Level lowP{ep.front().lo, false}, highP{ep.back().hi, false}, lowQ{eq.front().lo, true}, highQ{eq.back().hi, true};
  const Level low = cmp(lowP, lowQ) >= 0 ? lowP : lowQ, high = cmp(highP, highQ) <= 0 ? highP : highQ;
  if (cmp(low, high) >= 0) return r;  // the slabs swept by P and Q + t do not overlap

  std::vector<Level> lv, lp, lq;
  for (const Piece& p : ep) lp.insert(lp.end(), {{p.lo, false}, {p.hi, false}});
  for (const Piece& p : eq) lq.insert(lq.end(), {{p.lo, true}, {p.hi, true}});
  std::merge(lp.begin(), lp.end(), lq.begin(), lq.end(), std::back_inserter(lv),
             [&](const Level& a, const Level& b) { return cmp(a, b) < 0; });

  // Candidate: P envelope edge a, Q envelope edge b, at the level of z. λ = N / (D·|d|²).
  struct Cand {
    std::uint32_t a, b;
    Level z;
  };
  auto ND = [&](const Cand& c, auto L) {
    const Vec2 &a0 = VP[c.a], &a1 = VP[P.next(c.a)], &b0 = VQ[c.b], &b1 = VQ[Q.next(c.b)];
    const Vec2 &z = point(c.z), &zt = shift(c.z);
    auto cr = [&](auto x, auto y) { return L(d.x()) * y - L(d.y()) * x; };
    auto dt = [&](auto x, auto y) { return L(d.x()) * x + L(d.y()) * y; };
    auto eax = L(a1.x()) - L(a0.x()), eay = L(a1.y()) - L(a0.y());
    auto ebx = L(b1.x()) - L(b0.x()), eby = L(b1.y()) - L(b0.y());
    auto Da = cr(eax, eay), Db = cr(ebx, eby);
    auto N = dt(L(a0.x()) - L(b0.x()) - L(t.x()), L(a0.y()) - L(b0.y()) - L(t.y())) * Da * Db +
             cr(L(z.x()) + L(zt.x()) - L(a0.x()), L(z.y()) + L(zt.y()) - L(a0.y())) * dt(eax, eay) * Db -
             cr(L(z.x()) + L(zt.x()) - L(b0.x()) - L(t.x()), L(z.y()) + L(zt.y()) - L(b0.y()) - L(t.y())) * dt(ebx, eby) * Da;
    return std::pair{N, Da * Db};
  };
  auto den_sign = [&](const Cand& c) { return exact_sign([&](auto L) { return ND(c, L).second; }); };
  // Edges g and h of S pass through one point at the level of z: the same edge, or two edges
  // sharing an endpoint on that level (a continuous envelope at a breakpoint).
  auto meet_at = [&](const Polygon& S, bool q, std::uint32_t g, std::uint32_t h, const Level& z) {
    if (g == h) return true;
    const std::uint32_t gn = static_cast<std::uint32_t>(S.next(g)), hn = static_cast<std::uint32_t>(S.next(h));
    const std::uint32_t v = gn == h ? h : hn == g ? g : UINT32_MAX;
    return v != UINT32_MAX && cmp({v, q}, z) == 0;
  };
  auto better = [&](const Cand& x, const Cand& y) {  // λ(x) > λ(y)
    // The one-sided limits on both sides of a continuous breakpoint are equal: skip the exact
    // (rational) evaluation of that tie.
    if (cmp(x.z, y.z) == 0 && meet_at(P, false, x.a, y.a, x.z) && meet_at(Q, true, x.b, y.b, x.z)) return false;
    const int s = exact_sign([&](auto L) {
      auto [nx, dx] = ND(x, L);
      auto [ny, dy] = ND(y, L);
      return nx * dy - ny * dx;
    });
    return s * den_sign(x) * den_sign(y) > 0;
  };

  Cand best{};
  bool found = false;
  std::size_t ia = 0, ib = 0;
  for (std::size_t k = 0; k + 1 < lv.size(); ++k) {
    const Level x = lv[k], y = lv[k + 1];
    if (cmp(x, y) >= 0 || cmp(x, low) < 0 || cmp(y, high) > 0) continue;
    while (ia < ep.size() && cmp({ep[ia].hi, false}, x) <= 0) ++ia;
    while (ib < eq.size() && cmp({eq[ib].hi, true}, x) <= 0) ++ib;
    // Inside the common open range both envelopes cover (x, y); the guard only protects indices.
    if (ia == ep.size() || ib == eq.size()) break;
    if (cmp({ep[ia].lo, false}, x) > 0 || cmp({eq[ib].lo, true}, x) > 0) continue;
    for (const Level& z : {x, y}) {
      const Cand c{ep[ia].edge, eq[ib].edge, z};
      if (!found || better(c, best)) {
        best = c;
        found = true;
      }
    }
  }
  r.overlapping = overlapping(t);
  if (!found || exact_sign([&](auto L) { return ND(best, L).first; }) * den_sign(best) <= 0) return r;

  const double dn = nonconvex2::norm_accurate(d);
  const double lambda = exact::accurate_ratio([&](auto L) { return ND(best, L).first; }, [&](auto L) {
    return ND(best, L).second * (L(d.x()) * L(d.x()) + L(d.y()) * L(d.y()));
  });
  r.depth = lambda * dn;
  r.normal = d / dn;
  r.translation = r.depth * r.normal;
  // The contact at level z: P's envelope edge a meets Q's envelope edge b there.
  const std::uint32_t a0 = best.a, a1 = static_cast<std::uint32_t>(P.next(best.a));
  const std::uint32_t b0 = best.b, b1 = static_cast<std::uint32_t>(Q.next(best.b));
  if (cmp({a0, false}, best.z) == 0) r.feature_p = {FeatureKind::Vertex, int(a0)};
  else if (cmp({a1, false}, best.z) == 0) r.feature_p = {FeatureKind::Vertex, int(a1)};
  else r.feature_p = {FeatureKind::Edge, int(a0)};
  if (cmp({b0, true}, best.z) == 0) r.feature_q = {FeatureKind::Vertex, int(b0)};
  else if (cmp({b1, true}, best.z) == 0) r.feature_q = {FeatureKind::Vertex, int(b1)};
  else r.feature_q = {FeatureKind::Edge, int(b0)};
  if (r.feature_p.kind == FeatureKind::Vertex) {
    r.witness_p = VP[r.feature_p.index];
  } else if (r.feature_q.kind == FeatureKind::Vertex) {
    r.witness_p = VQ[r.feature_q.index] + t + r.translation;
  } else {
    const Vec2 &p0 = VP[a0], &p1 = VP[a1], &z = point(best.z), &zt = shift(best.z);
    const double alpha = exact::accurate_ratio(
        [&](auto L) {
          return L(d.x()) * (L(z.y()) + L(zt.y()) - L(p0.y())) - L(d.y()) * (L(z.x()) + L(zt.x()) - L(p0.x()));
        },
        [&](auto L) { return L(d.x()) * (L(p1.y()) - L(p0.y())) - L(d.y()) * (L(p1.x()) - L(p0.x())); });
    r.witness_p = p0 + alpha * (p1 - p0);
  }
  r.witness_q = r.witness_p;
  return r;
}

}  // namespace pendepth
