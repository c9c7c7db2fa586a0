// Independent oracle for the complete separation of two simple polygons (issue 5 item 1): the
// previous O(n log n) construction, kept only for tests and benchmarks. Each envelope (the
// visibility profile of the outer ring from infinity along d) is built by divide and conquer over
// the edges: two envelopes of non-crossing segments merge in linear time, per elementary level
// interval the larger of the two segments, compared exactly at the interval's midpoint level. The
// separation merges P's right envelope with Q's left envelope and takes the largest one-sided limit
// of the gap, exactly as the library did before the linear-time walk (src/nonconvex2/envelope.cpp).
// It shares no code with the walk; only the input validation (check_and_scale) and |d|
// (norm_accurate) come from the library.
#pragma once

#include <pendepth/depth2.hpp>
#include <pendepth/polygon.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/exact.hpp"
#include "nonconvex2/query.hpp"

namespace nonconvex2_test {
namespace oracle {
using namespace pendepth;
using pendepth::exact::exact_sign;

struct Piece {
  std::uint32_t lo, hi, edge;  // levels of vertices lo < hi; edge g from g to next(g)
};

// Upper envelope (largest u = dir·x) of the outer-ring edges of `shape` with dir × e > 0, as a
// function of the level w = dir × x. Pieces sorted by level.
class Envelope {
 public:
  Envelope(const Polygon& shape, const Vec2& dir) : S_(shape), V_(shape.vertices()), dir_(dir) {}

  int cmp_level(std::uint32_t a, std::uint32_t b) const {
    const Vec2 &p = V_[a], &q = V_[b], &d = dir_;
    return exact_sign([&](auto L) { return L(d.x()) * (L(p.y()) - L(q.y())) - L(d.y()) * (L(p.x()) - L(q.x())); });
  }

  // Sign of u_a − u_b at the level midway between z0 and z1 (edges a, b span that open interval).
  int cmp_edges(std::uint32_t a, std::uint32_t b, std::uint32_t z0, std::uint32_t z1) const {
    const Vec2 &a0 = V_[a], &a1 = V_[S_.next(a)], &b0 = V_[b], &b1 = V_[S_.next(b)];
    const Vec2 &y0 = V_[z0], &y1 = V_[z1], &d = dir_;
    return exact_sign([&](auto L) {
      auto cr = [&](const Vec2& p) { return L(d.x()) * L(p.y()) - L(d.y()) * L(p.x()); };
      auto dt = [&](const Vec2& p) { return L(d.x()) * L(p.x()) + L(d.y()) * L(p.y()); };
      auto cre = [&](const Vec2& p, const Vec2& q) { return cr(q) - cr(p); };
      auto dte = [&](const Vec2& p, const Vec2& q) { return dt(q) - dt(p); };
      auto Da = cre(a0, a1), Db = cre(b0, b1);
      auto W = cr(y0) + cr(y1);
      auto ua = (L(2.0) * dt(a0) * Da + (W - L(2.0) * cr(a0)) * dte(a0, a1)) * Db;
      auto ub = (L(2.0) * dt(b0) * Db + (W - L(2.0) * cr(b0)) * dte(b0, b1)) * Da;
      return ua - ub;
    });
  }

  std::vector<Piece> build() const {
    std::vector<std::vector<Piece>> parts;
    const std::size_t n = S_.ring(0).size();
    for (std::uint32_t g = 0; g < n; ++g) {
      const std::uint32_t h = static_cast<std::uint32_t>(S_.next(g));
      if (cmp_level(g, h) < 0) parts.push_back({{g, h, g}});
    }
    while (parts.size() > 1) {
      std::vector<std::vector<Piece>> next;
      for (std::size_t k = 0; k + 1 < parts.size(); k += 2) next.push_back(merge(parts[k], parts[k + 1]));
      if (parts.size() % 2) next.push_back(std::move(parts.back()));
      parts = std::move(next);
    }
    return parts.empty() ? std::vector<Piece>{} : parts[0];
  }

 private:
  std::vector<Piece> merge(const std::vector<Piece>& A, const std::vector<Piece>& B) const {
    auto less = [&](std::uint32_t a, std::uint32_t b) { return cmp_level(a, b) < 0; };
    std::vector<std::uint32_t> la, lb, lv;
    for (const Piece& p : A) la.insert(la.end(), {p.lo, p.hi});
    for (const Piece& p : B) lb.insert(lb.end(), {p.lo, p.hi});
    std::merge(la.begin(), la.end(), lb.begin(), lb.end(), std::back_inserter(lv), less);
    std::vector<Piece> out;
    std::size_t ia = 0, ib = 0;
    for (std::size_t k = 0; k + 1 < lv.size(); ++k) {
      const std::uint32_t x = lv[k], y = lv[k + 1];
      if (cmp_level(x, y) >= 0) continue;  // equal levels: no open interval between them
      while (ia < A.size() && cmp_level(A[ia].hi, x) <= 0) ++ia;
      while (ib < B.size() && cmp_level(B[ib].hi, x) <= 0) ++ib;
      const bool ha = ia < A.size() && cmp_level(A[ia].lo, x) <= 0;
      const bool hb = ib < B.size() && cmp_level(B[ib].lo, x) <= 0;
      if (!ha && !hb) continue;
      std::uint32_t e = ha ? A[ia].edge : B[ib].edge;
      if (ha && hb && cmp_edges(A[ia].edge, B[ib].edge, x, y) < 0) e = B[ib].edge;
      if (!out.empty() && out.back().edge == e && cmp_level(out.back().hi, x) == 0) out.back().hi = y;
      else out.push_back({x, y, e});
    }
    return out;
  }

  const Polygon& S_;
  std::span<const Vec2> V_;
  Vec2 dir_;
};

// A breakpoint level: a vertex of P (q = false) or of Q + t.
struct Level {
  std::uint32_t v;
  bool q;
};

inline Depth2 oracle_separation(const Polygon& P, const Polygon& Q, const Vec2& t, const Vec2& d_in, bool overlapping_t) {
  const Vec2 d = pendepth::nonconvex2::check_and_scale(t, d_in);
  const auto VP = P.vertices(), VQ = Q.vertices();
  const std::vector<Piece> ep = Envelope(P, d).build();
  std::vector<Piece> eq = Envelope(Q, -d).build();  // max of −u over levels −w: reverse to increasing w
  std::reverse(eq.begin(), eq.end());
  for (Piece& p : eq) std::swap(p.lo, p.hi);

  auto point = [&](const Level& l) -> const Vec2& { return l.q ? VQ[l.v] : VP[l.v]; };
  const Vec2 zero(0, 0);
  auto shift = [&](const Level& l) -> const Vec2& { return l.q ? t : zero; };
  auto cmp = [&](const Level& a, const Level& b) {
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
  auto better = [&](const Cand& x, const Cand& y) {  // λ(x) > λ(y)
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
  r.overlapping = overlapping_t;
  if (!found || exact_sign([&](auto L) { return ND(best, L).first; }) * den_sign(best) <= 0) return r;

  const double dn = pendepth::nonconvex2::norm_accurate(d);
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


}  // namespace oracle

}  // namespace nonconvex2_test
