// Test oracle: the previous exact-rational export of the no-fit polygon (src/nonconvex2/
// nfp_rings.cpp at 503175e, before its rewrite without rationals), kept as the oracle of
// test_nfp_export.cpp; only its interface changed (pieces in, an Export out; inline functions in a
// test namespace). Every exact vertex is an mpq point interned in a std::map, lines are keyed by
// rational slope and offset, and every decision is rational (floating values only as box filters,
// the shoelace filter and TwoSum rounding of sum vertices). Same contract as pendepth::nfp_export.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <deque>
#include <map>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

#include "geometry/exact.hpp"
#include "nonconvex2/nfp_impl.hpp"

namespace nonconvex2_test {

namespace rational_export {

using pendepth::Vec2;
namespace exact = pendepth::exact;
namespace nonconvex2 = pendepth::nonconvex2;

using nonconvex2::NfpPiece;
using nonconvex2::Param;
using nonconvex2::Ray;

struct QP {
  mpq_class x, y;
  bool operator<(const QP& o) const { return x != o.x ? x < o.x : y < o.y; }
  bool operator==(const QP& o) const { return x == o.x && y == o.y; }
};

// The sum vertex (pid, qid) at a symbolic end k (0 or 1) of a candidate ray: the P vertex plus
// the −Q vertex, two input doubles per coordinate (the ray stores them: o1 = P vertex p0, o2 = −Q
// vertex q0; a1 = the P vertex p1 on a P edge, the −Q vertex q1 on a Q edge).
inline QP sum_vertex(const Ray& E, int k) {
  const Vec2 &p = k == 0 || E.p0 == E.p1 ? E.o1 : E.a1, &b = k == 0 || E.q0 == E.q1 ? E.o2 : E.a1;
  return {mpq_class(p.x()) + b.x(), mpq_class(p.y()) + b.y()};
}

// The crossing of E's line with line c, exactly, in integer arithmetic: every input double is an
// integer multiple of 2^s (s = the lowest significant bit over all of them), so with all inputs
// scaled by 2^-s the crossing is 2^s·(A·den + n·D)/den in integers (A = o1 + o2, D = E's
// direction, n and den the numerator and denominator of λ) and one canonicalisation per coordinate
// gives the same rational as the generic formula. False (use the generic formula) when the
// scaled inputs would overflow a double.
inline bool cut_point_fixed(const Ray& E, const nonconvex2::Line& c, QP& out) {
  const std::array<const Vec2*, 10> in{&E.o1, &E.o2, &E.a1, &E.a2, &E.b1, &E.b2, &c.c1, &c.c2, &c.e0, &c.e1};
  int lo = INT_MAX, hi = INT_MIN;
  for (const Vec2* v : in)
    for (int k = 0; k < 2; ++k) {
      if ((*v)[k] == 0) continue;
      int e;
      std::frexp((*v)[k], &e);
      lo = std::min(lo, e - 53), hi = std::max(hi, e);
    }
  if (lo == INT_MAX) return false;
  if (hi - lo > 1000) return false;
  std::array<std::array<mpz_class, 2>, 10> z;
  for (std::size_t i = 0; i < in.size(); ++i)
    for (int k = 0; k < 2; ++k) z[i][k] = std::ldexp((*in[i])[k], -lo);
  mpz_class A[2], D[2], C[2], F[2];
  for (int k = 0; k < 2; ++k) {
    A[k] = z[0][k] + z[1][k];
    D[k] = z[2][k] + z[3][k] - z[4][k] - z[5][k];
    C[k] = z[6][k] + z[7][k];
    F[k] = z[9][k] - z[8][k];
  }
  const mpz_class n = (C[0] - A[0]) * F[1] - (C[1] - A[1]) * F[0];
  const mpz_class den = D[0] * F[1] - D[1] * F[0];
  if (den == 0) return false;
  mpq_class* o[2] = {&out.x, &out.y};
  for (int k = 0; k < 2; ++k) {
    mpq_class& q = *o[k];
    q.get_num() = A[k] * den + n * D[k];
    q.get_den() = den;
    q.canonicalize();
    if (lo >= 0) mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), lo);
    else mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), -lo);
  }
  return true;
}

inline QP exact_point(const Ray& E, const Param& p_in) {
  const exact::LiftQ L;
  const Param p = nonconvex2::normalised(p_in, E);  // a cut through a sum vertex is that vertex
  if (E.sym && p.kind != Param::Cut) return sum_vertex(E, p.kind == Param::Zero ? 0 : 1);
  if (p.kind == Param::Zero) return {mpq_class(E.o1.x()) + E.o2.x(), mpq_class(E.o1.y()) + E.o2.y()};
  if (p.kind == Param::One)
    return {mpq_class(E.o1.x()) + E.o2.x() + E.a1.x() + E.a2.x() - E.b1.x() - E.b2.x(),
            mpq_class(E.o1.y()) + E.o2.y() + E.a1.y() + E.a2.y() - E.b1.y() - E.b2.y()};
  QP fast;
  if (cut_point_fixed(E, p.line, fast)) return fast;
  auto [n, dd] = nonconvex2::param_nd(p, E, Vec2(0, 0), L);
  const mpq_class mu = n.v / dd.v;
  QP r;
  r.x = mpq_class(E.o1.x()) + mpq_class(E.o2.x()) + mu * nonconvex2::ray_dx(E, L).v;
  r.y = mpq_class(E.o1.y()) + mpq_class(E.o2.y()) + mu * nonconvex2::ray_dy(E, L).v;
  return r;
}

// Round to nearest (ties: the neighbour nearer zero). get_d truncates towards zero, so q lies
// between d and its neighbour away from zero; that neighbour wins iff |q| is beyond the midpoint.
inline double round_q(const mpq_class& q) {
  const double d = q.get_d();
  const int sg = sgn(q);
  if (sg == 0) return d;
  const double c = std::nextafter(d, sg > 0 ? INFINITY : -INFINITY);
  if (!std::isfinite(c)) return d;
  mpq_class mid = mpq_class(d) + mpq_class(c);
  mpq_div_2exp(mid.get_mpq_t(), mid.get_mpq_t(), 1);
  return (sg > 0 ? q > mid : q < mid) ? c : d;
}

inline Vec2 round_point(const QP& p) { return Vec2(round_q(p.x), round_q(p.y)); }

// round_q of the exact sum a + b without rationals (TwoSum): fl(a + b) is the nearest double, and
// on an exact tie round_q's choice (the neighbour nearer zero) is taken. False if it overflows.
inline bool round_sum(double a, double b, double& out) {
  const double s = a + b, bb = s - a, e = (a - (s - bb)) + (b - bb);
  if (!std::isfinite(s) || !std::isfinite(e)) return false;
  out = s;
  if (e == 0) return true;
  const double c = std::nextafter(s, e > 0 ? INFINITY : -INFINITY);
  if (std::isfinite(c) && 2 * std::abs(e) == std::abs(c - s) && std::abs(c) < std::abs(s)) out = c;
  return true;
}

inline mpq_class cross(const QP& a, const QP& b) { return a.x * b.y - a.y * b.x; }
inline QP sub(const QP& a, const QP& b) { return {a.x - b.x, a.y - b.y}; }

// A supporting line: y = slope·x + offset, or x = offset (vertical); u = x resp. y along it.
struct LineKey {
  bool vertical = false;
  mpq_class slope, offset;
  bool operator<(const LineKey& o) const {
    if (vertical != o.vertical) return vertical < o.vertical;
    if (slope != o.slope) return slope < o.slope;
    return offset < o.offset;
  }
  bool operator==(const LineKey& o) const { return vertical == o.vertical && slope == o.slope && offset == o.offset; }
  const mpq_class& u(const QP& p) const { return vertical ? p.y : p.x; }
  QP at(const mpq_class& u) const { return vertical ? QP{offset, u} : QP{u, slope * u + offset}; }
  bool contains(const QP& p) const { return vertical ? p.x == offset : p.y == slope * p.x + offset; }
};

// Exact: p strictly inside the ring of vertex ids into V (crossing number; the caller avoids
// points on the ring).
inline int point_in_ring(const std::deque<QP>& V, const std::vector<int>& ring, const QP& p) {
  bool in = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const QP &a = V[ring[i]], &b = V[ring[(i + 1) % ring.size()]];
    const mpq_class s = cross(sub(b, a), sub(p, a));
    if (s == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y))
      return 0;  // on the ring
    if ((a.y > p.y) != (b.y > p.y)) {
      // Crossing of the horizontal ray to +x: x at height p.y greater than p.x.
      if ((s > 0) == (b.y > a.y)) in = !in;
    }
  }
  return in ? 1 : -1;
}

inline mpq_class ring_area2(const std::deque<QP>& V, const std::vector<int>& ring) {
  mpq_class a = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) a += cross(V[ring[i]], V[ring[(i + 1) % ring.size()]]);
  return a;
}

// The CCW angle from r to w in [0, 2π) is larger for a than for b (exact; a, b, r non-zero).
inline bool larger_ccw_angle(const QP& r, const QP& a, const QP& b) {
  auto half = [&](const QP& w) {
    const mpq_class c = cross(r, w);
    return (c > 0 || (c == 0 && r.x * w.x + r.y * w.y > 0)) ? 0 : 1;
  };
  const int ha = half(a), hb = half(b);
  if (ha != hb) return ha > hb;
  return cross(a, b) < 0;  // b before a counter-clockwise
}

}  // namespace rational_export

/// What an export produces (the fields of NoFitPolygon2::Impl it writes).
struct Export {
  std::vector<std::vector<std::vector<pendepth::Vec2>>> polys;
  std::vector<std::array<pendepth::Vec2, 2>> slits;
  std::vector<pendepth::Vec2> points;
};

/// The previous export (same contract as pendepth::nfp_export): the rings, slits and isolated
/// points of the pieces.
inline void nfp_export_rational(const std::vector<pendepth::nonconvex2::NfpPiece>& pieces, Export& N) {
  using namespace rational_export;
  // Every exact vertex is interned once (V, by exact identity); everything below refers to ids.
  // (A deque: stable addresses, so the index keys on the stored points without copying them.)
  std::deque<QP> V;
  auto by_value = [](const QP* x, const QP* y) { return *x < *y; };
  std::map<const QP*, int, decltype(by_value)> id_of(by_value);
  auto intern = [&](QP&& q) {
    auto it = id_of.find(&q);
    if (it != id_of.end()) return it->second;
    const int id = static_cast<int>(V.size());
    V.push_back(std::move(q));
    id_of.emplace(&V.back(), id);
    return id;
  };
  struct Seg {
    int a, b;
    LineKey key;
    Vec2 ra, rb;  // the ends to a few ulps (floating keys and boxes only)
  };
  std::vector<Seg> segs;
  segs.reserve(pieces.size());
  std::vector<int> zero_points;
  std::vector<Vec2> zero_rounded;
  // Ends that are sum vertices are computed once per vertex (pid, qid): most vertices of ∂O end
  // two pieces.
  std::unordered_map<std::uint64_t, int> vertex_cache;
  std::unordered_map<int, Vec2> known_round;  // vertex id → its coordinates rounded to nearest
  auto end_point = [&](const Ray& E, const Param& p_in) {
    const Param p = nonconvex2::normalised(p_in, E);
    if (!E.sym || p.kind == Param::Cut) return intern(exact_point(E, p));
    const int k = p.kind == Param::Zero ? 0 : 1;
    const std::uint64_t key = (std::uint64_t(k == 0 ? E.p0 : E.p1) << 32) | (k == 0 ? E.q0 : E.q1);
    auto it = vertex_cache.find(key);
    if (it == vertex_cache.end()) {
      const int id = intern(sum_vertex(E, k));
      it = vertex_cache.emplace(key, id).first;
      // Its rounding straight from the two doubles (the rings' vertices are mostly sum vertices).
      const Vec2 &p = k == 0 || E.p0 == E.p1 ? E.o1 : E.a1, &b = k == 0 || E.q0 == E.q1 ? E.o2 : E.a1;
      Vec2 r;
      if (round_sum(p.x(), b.x(), r.x()) && round_sum(p.y(), b.y(), r.y())) known_round.emplace(id, r);
    }
    return it->second;
  };
  for (const NfpPiece& pc : pieces) {
    const int ia = end_point(pc.E, pc.lo), ib = end_point(pc.E, pc.hi);
    if (ia == ib) {
      zero_points.push_back(ia);
      zero_rounded.push_back(pc.a);
      continue;
    }
    Seg s{ia, ib, {}, pc.a, pc.b};
    const QP &a = V[ia], D = sub(V[ib], a);
    if (D.x != 0) {
      s.key.slope = D.y / D.x;
      s.key.offset = a.y - s.key.slope * a.x;
    } else {
      s.key.vertical = true;
      s.key.offset = a.x;
    }
    segs.push_back(std::move(s));
  }
  {  // sorted by line (indices: moving rationals is costly)
    std::vector<std::size_t> order(segs.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return segs[x].key < segs[y].key; });
    std::vector<Seg> sorted;
    sorted.reserve(segs.size());
    for (std::size_t k : order) sorted.push_back(std::move(segs[k]));
    segs = std::move(sorted);
  }

  // Every exact vertex (piece ends and zero-length points), sorted by rounded x for range scans.
  std::vector<std::pair<Vec2, int>> verts;
  for (const Seg& s : segs) {
    verts.push_back({s.ra, s.a});
    verts.push_back({s.rb, s.b});
  }
  for (std::size_t k = 0; k < zero_points.size(); ++k) verts.push_back({zero_rounded[k], zero_points[k]});
  std::sort(verts.begin(), verts.end(), [](const auto& x, const auto& y) { return x.first.x() < y.first.x(); });

  struct Edge {
    int a, b;
    std::size_t line;  // the group of its exact supporting line
    bool fwd;          // along increasing u of that line
  };
  std::vector<Edge> edges;
  std::vector<std::array<int, 2>> slits;
  std::vector<char> is_vertex(V.size(), 0);  // ends of edges and slit pieces
  for (std::size_t g0 = 0, g1; g0 < segs.size(); g0 = g1) {
    g1 = g0 + 1;
    while (g1 < segs.size() && segs[g1].key == segs[g0].key) ++g1;
    const LineKey& key = segs[g0].key;
    // Intervals in u, oriented forward (u increasing) or backward; u values point into V.
    struct Iv {
      const mpq_class *lo, *hi;
      bool fwd;
    };
    std::vector<Iv> ivs;
    std::vector<std::pair<const mpq_class*, int>> us;
    Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
    for (std::size_t k = g0; k < g1; ++k) {
      const mpq_class &ua = key.u(V[segs[k].a]), &ub = key.u(V[segs[k].b]);
      const bool fwd = ua < ub;
      ivs.push_back({fwd ? &ua : &ub, fwd ? &ub : &ua, fwd});
      us.push_back({&ua, segs[k].a});
      us.push_back({&ub, segs[k].b});
      for (const Vec2& r : {segs[k].ra, segs[k].rb}) {
        lo = lo.cwiseMin(r);
        hi = hi.cwiseMax(r);
      }
    }
    // Other exact vertices lying on this line within its extent split it too.
    const double m = (lo.cwiseAbs().maxCoeff() + hi.cwiseAbs().maxCoeff()) * 0x1p-40 + 0x1p-1000;
    auto it = std::lower_bound(verts.begin(), verts.end(), lo.x() - m, [](const auto& v, double x) { return v.first.x() < x; });
    bool split = false;
    for (; it != verts.end() && it->first.x() <= hi.x() + m; ++it) {
      const int v = it->second;
      if (it->first.y() < lo.y() - m || it->first.y() > hi.y() + m) continue;
      if (g1 == g0 + 1 && (v == segs[g0].a || v == segs[g0].b)) continue;  // a lone piece's own end
      if (!key.contains(V[v])) continue;
      us.push_back({&key.u(V[v]), v});
      split = true;
    }
    if (g1 == g0 + 1 && !split) {  // a lone piece on its line, nothing inside it: one boundary edge
      is_vertex[segs[g0].a] = 1;
      is_vertex[segs[g0].b] = 1;
      edges.push_back({segs[g0].a, segs[g0].b, g0, ivs[0].fwd});
      continue;
    }
    // One point per u on the line (equal u on one line: the same exact point, the same id).
    std::sort(us.begin(), us.end(), [](const auto& x, const auto& y) { return *x.first < *y.first; });
    us.erase(std::unique(us.begin(), us.end(), [](const auto& x, const auto& y) { return x.second == y.second; }), us.end());
    bool slit_open = false;
    int slit_start = -1;
    for (std::size_t i = 0; i + 1 < us.size(); ++i) {
      bool f = false, b = false;
      for (const Iv& iv : ivs)
        if (*iv.lo <= *us[i].first && *us[i + 1].first <= *iv.hi) (iv.fwd ? f : b) = true;
      const int p0 = us[i].second, p1 = us[i + 1].second;
      if (f || b) {
        is_vertex[p0] = 1;
        is_vertex[p1] = 1;
      }
      if (f && b) {
        if (!slit_open) slit_start = p0;
        slit_open = true;
        if (i + 2 == us.size()) slits.push_back({slit_start, p1});
        continue;
      }
      if (slit_open) slits.push_back({slit_start, p0});
      slit_open = false;
      if (f) edges.push_back({p0, p1, g0, true});
      else if (b) edges.push_back({p1, p0, g0, false});
    }
    // Along the increasing direction (canonical for the slit ends); the line key orients u.
  }

  // Link edges into rings.
  std::vector<std::vector<std::size_t>> out(V.size());
  for (std::size_t e = 0; e < edges.size(); ++e) out[edges[e].a].push_back(e);
  std::vector<char> used(edges.size(), 0);
  std::vector<std::vector<int>> rings;
  auto dir = [&](const Edge& e) { return sub(V[e.b], V[e.a]); };
  for (std::size_t e0 = 0; e0 < edges.size(); ++e0) {
    if (used[e0]) continue;
    std::vector<std::size_t> chain;
    std::size_t e = e0;
    for (;;) {
      used[e] = 1;
      chain.push_back(e);
      const auto& cands = out[edges[e].b];
      std::size_t best = edges.size();
      QP r;  // back along the incoming edge (only needed when there is a choice)
      bool have_r = false;
      for (std::size_t c : cands) {
        if (used[c] && c != e0) continue;
        if (best == edges.size()) {
          best = c;
          continue;
        }
        if (!have_r) r = sub(V[edges[e].a], V[edges[e].b]), have_r = true;
        if (larger_ccw_angle(r, dir(edges[c]), dir(edges[best]))) best = c;
      }
      if (best == e0) break;  // closed
      // Every vertex of ∂O has as many pieces leaving as entering; a dead end means the pieces
      // are inconsistent, which must not be exported as if it were a ring.
      if (best == edges.size())
        throw std::logic_error("no-fit polygon: a boundary chain does not close (internal inconsistency)");
      e = best;
    }
    std::vector<int> ring;
    for (std::size_t k = 0; k < chain.size(); ++k) {
      const Edge& in = edges[chain[(k + chain.size() - 1) % chain.size()]];
      const Edge& o = edges[chain[k]];
      // Pass-through: the same exact line (one group per line) in the same direction.
      if (chain.size() > 2 && in.line == o.line && in.fwd == o.fwd) continue;
      ring.push_back(o.a);
    }
    if (ring.size() >= 3) rings.push_back(std::move(ring));
  }

  // Every ring rounded once (its vertices to nearest; sum vertices without rationals).
  std::vector<std::vector<Vec2>> rr(rings.size());
  for (std::size_t k = 0; k < rings.size(); ++k) {
    rr[k].reserve(rings[k].size());
    for (int p : rings[k]) {
      const auto it = known_round.find(p);
      rr[k].push_back(it != known_round.end() ? it->second : round_point(V[p]));
    }
  }
  // Outer rings and holes by the sign of the area: a floating shoelace sum on the rounded
  // vertices with a bound covering the rounding of the vertices (2^-53 relative each) and of the
  // sum; exact rationals when it cannot decide, and exact areas whenever there are holes to place.
  std::vector<std::size_t> outer, holes;
  std::vector<int> sign(rings.size(), 0);
  for (std::size_t k = 0; k < rings.size(); ++k) {
    const auto& r = rr[k];
    const double n = double(r.size());
    double a = 0, big = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Vec2 &u = r[i], &w = r[(i + 1) % r.size()];
      a += u.x() * w.y() - w.x() * u.y();
      big = std::max(big, u.cwiseAbs().maxCoeff());
    }
    const double bound = (4 * n * n + 8 * n) * big * big * 0x1p-50 + 0x1p-1000;
    if (std::isfinite(a) && std::isfinite(bound) && std::abs(a) > bound) sign[k] = a > 0 ? 1 : -1;
    else sign[k] = sgn(ring_area2(V, rings[k]));
    (sign[k] > 0 ? outer : holes).push_back(k);
  }
  std::vector<mpq_class> area(rings.size());
  if (!holes.empty())
    for (std::size_t o : outer) area[o] = ring_area2(V, rings[o]);
  std::vector<std::vector<std::size_t>> holes_of(outer.size());
  for (std::size_t h : holes) {
    std::size_t best = outer.size();
    for (std::size_t o = 0; o < outer.size(); ++o) {
      int side = 0;
      for (int p : rings[h]) {
        side = point_in_ring(V, rings[outer[o]], V[p]);
        if (side != 0) break;
      }
      // All vertices on that ring's boundary: decide by the midpoints of the hole's edges (a hole
      // that shares every vertex with the ring still has an edge off it, or it is the ring).
      for (std::size_t i = 0; side == 0 && i < rings[h].size(); ++i) {
        const QP &a = V[rings[h][i]], &b = V[rings[h][(i + 1) % rings[h].size()]];
        side = point_in_ring(V, rings[outer[o]], QP{(a.x + b.x) / 2, (a.y + b.y) / 2});
      }
      if (side > 0 && (best == outer.size() || area[outer[o]] < area[outer[best]])) best = o;
    }
    if (best == outer.size())
      throw std::logic_error("no-fit polygon: a hole ring lies in no outer ring (internal inconsistency)");
    holes_of[best].push_back(h);
  }
  N.polys.clear();
  for (std::size_t o = 0; o < outer.size(); ++o) {
    std::vector<std::vector<Vec2>> poly{std::move(rr[outer[o]])};
    for (std::size_t h : holes_of[o]) poly.push_back(std::move(rr[h]));
    N.polys.push_back(std::move(poly));
  }
  N.slits.clear();
  for (const auto& sl : slits) N.slits.push_back({round_point(V[sl[0]]), round_point(V[sl[1]])});
  std::sort(zero_points.begin(), zero_points.end(), [&](int x, int y) { return V[x] < V[y]; });
  zero_points.erase(std::unique(zero_points.begin(), zero_points.end()), zero_points.end());
  N.points.clear();
  for (int p : zero_points)
    if (!is_vertex[p]) N.points.push_back(round_point(V[p]));
}

}  // namespace nonconvex2_test
