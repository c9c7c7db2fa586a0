// Private: exact cutting of a sum edge by open sums, shared by PairDepth2::minimum (σ) and the
// no-fit polygon builder (nfp_build.cpp). An edge is a symbolic Ray E (from one sum vertex to the
// next, μ ∈ [0, 1]); a parameter μ on it is 0, 1, the crossing with a line, the projection of a
// point t, or an exact double. Covers are the open intervals of μ inside other open sums
// (sum_interval); the uncovered closed pieces are swept in exact entry order.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "geometry/exact.hpp"
#include "nonconvex2/pair_sums.hpp"

namespace pendepth::nonconvex2 {

// A parameter μ on an edge ray E (point o + μ·dir): 0, 1, the crossing with a line, or the
// orthogonal projection of t.
struct Param {
  enum Kind { Zero, One, Cut, Proj, Value } kind = Zero;
  Line line;
  double value = 0;  // Value: μ = value (an exact double)
};

template <class L>
auto param_nd(const Param& p, const Ray& E, const Vec2& t, L lift) {
  using T = decltype(lift(0.0));
  switch (p.kind) {
    case Param::Zero:
      return std::pair<T, T>{lift(0.0), lift(1.0)};
    case Param::One:
      return std::pair<T, T>{lift(1.0), lift(1.0)};
    case Param::Cut:
      return std::pair<T, T>{line_num(p.line, E, lift), line_den(p.line, E, lift)};
    case Param::Value:
      return std::pair<T, T>{lift(p.value), lift(1.0)};
    default: {
      auto dx = ray_dx(E, lift), dy = ray_dy(E, lift);
      auto wx = lift(t.x()) - lift(E.o1.x()) - lift(E.o2.x()), wy = lift(t.y()) - lift(E.o1.y()) - lift(E.o2.y());
      return std::pair<T, T>{wx * dx + wy * dy, dx * dx + dy * dy};
    }
  }
}

// A cut through the edge's start or end vertex is the symbolic parameter 0 or 1.
inline Param normalised(const Param& p, const Ray& E) {
  if (p.kind != Param::Cut) return p;
  const int k = known_lambda(p.line, E);
  return k < 0 ? p : Param{k == 0 ? Param::Zero : Param::One, {}};
}

inline int compare_params(const Param& a_in, const Param& b_in, const Ray& E, const Vec2& t) {
  const Param a = normalised(a_in, E), b = normalised(b_in, E);
  if (a.kind == Param::Cut && b.kind == Param::Cut) return compare_lines(a.line, b.line, E);
  auto fixed = [](const Param& p) { return p.kind == Param::Zero ? 0 : p.kind == Param::One ? 1 : -1; };
  if (fixed(a) >= 0 && fixed(b) >= 0) return (fixed(a) > fixed(b)) - (fixed(a) < fixed(b));
  const int sa = exact::exact_sign([&](auto L) { return param_nd(a, E, t, L).second; });
  const int sb = exact::exact_sign([&](auto L) { return param_nd(b, E, t, L).second; });
  const int s = exact::exact_sign([&](auto L) {
    auto [na, da] = param_nd(a, E, t, L);
    auto [nb, db] = param_nd(b, E, t, L);
    return na * db - nb * da;
  });
  return s * sa * sb;
}

// Candidate nearest point: on edge E at parameter `at` (a point of the edge).
struct Cand {
  Ray E;
  Param at;
  Line edge;
};

// Squared distance from t to the candidate as num / den (den > 0).
template <class L>
auto sq_dist(const Cand& c, const Vec2& t, L lift) {
  auto [n, dd] = param_nd(c.at, c.E, t, lift);
  auto dx = ray_dx(c.E, lift), dy = ray_dy(c.E, lift);
  auto x = (lift(c.E.o1.x()) + lift(c.E.o2.x()) - lift(t.x())) * dd + n * dx;
  auto y = (lift(c.E.o1.y()) + lift(c.E.o2.y()) - lift(t.y())) * dd + n * dy;
  return std::pair{x * x + y * y, dd * dd};
}

inline double seg_dist(const Vec2& t, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a, at = t - a;
  const double l2 = ab.squaredNorm();
  const double u = l2 > 0 ? std::clamp(at.dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (at - u * ab).norm();
}

// Floating filter: both points lie in int S by a margin far above every rounding involved (the
// points themselves are within ~2^-50 relative of exact points of the edge, the sum vertices and
// the cross products within a few ulps), so the closed segment between them is certified inside.
inline bool surely_inside(const Sum& S, const Vec2& c0, const Vec2& c1, double scale) {
  const double margin = scale * 0x1p-36;
  for (const Line& c : S.e) {
    const Vec2 e = c.e1 - c.e0, v = c.c1 + c.c2;
    const double len = std::abs(e.x()) + std::abs(e.y());
    for (const Vec2* p : {&c0, &c1}) {
      const Vec2 w = *p - v;
      if (e.x() * w.y() - e.y() * w.x() <= margin * len) return false;
    }
  }
  return true;
}

// Floating filter: both points lie strictly outside one edge line of S by the same margin, so the
// segment between them misses S (and cannot be covered by it).
inline bool surely_outside(const Sum& S, const Vec2& c0, const Vec2& c1, double scale) {
  const double margin = scale * 0x1p-36;
  for (const Line& c : S.e) {
    const Vec2 e = c.e1 - c.e0, v = c.c1 + c.c2;
    const double len = std::abs(e.x()) + std::abs(e.y());
    const Vec2 w0 = c0 - v, w1 = c1 - v;
    if (e.x() * w0.y() - e.y() * w0.x() < -margin * len && e.x() * w1.y() - e.y() * w1.x() < -margin * len) return true;
  }
  return false;
}

/// One coordinate (axis 0: x, 1: y) of the vector from t to the point at parameter p of E, as
/// num / den (den: param_nd's); t = 0 gives the point's own coordinate.
template <class L>
auto point_nd(const Param& p, const Ray& E, const Vec2& t, int axis, L lift) {
  auto [n, dd] = param_nd(p, E, t, lift);
  auto o = axis == 0 ? lift(E.o1.x()) + lift(E.o2.x()) - lift(t.x()) : lift(E.o1.y()) + lift(E.o2.y()) - lift(t.y());
  auto dv = axis == 0 ? ray_dx(E, lift) : ray_dy(E, lift);
  return std::pair{o * dd + n * dv, dd};
}

/// One coordinate (axis 0: x, 1: y) of the vector from t to the candidate point, to a few ulps.
inline double cand_coord(const Cand& c, const Vec2& t, int axis) {
  return exact::accurate_ratio_of([&](auto L) { return point_nd(c.at, c.E, t, axis, L); });
}

/// The vector from t to the candidate point, each coordinate to a few ulps.
inline Vec2 cand_translation(const Cand& c, const Vec2& t) {
  const Ray& E = c.E;
  auto coord = [&](int axis) { return cand_coord(c, t, axis); };
  // The projection on an axis-parallel edge has one coordinate exactly t's: decided exactly (cheap
  // for equal input doubles) rather than by the rational fallback a zero forces on accurate_ratio.
  if (c.at.kind == Param::Proj) {
    if (exact::exact_sign([&](auto L) { return ray_dx(E, L); }) == 0) return Vec2(coord(0), 0);
    if (exact::exact_sign([&](auto L) { return ray_dy(E, L); }) == 0) return Vec2(0, coord(1));
  }
  return Vec2(coord(0), coord(1));
}

/// One geometric line: symbolically (same_line), or parallel with c1 + c2 of m on l (exact, degree
/// 2; collinear edges from parallel edges of P and Q are common on real pieces, and their equality
/// is an exact zero no floating filter can certify).
inline bool collinear(const Line& l, const Line& m) {
  if (same_line(l, m)) return true;
  if (exact::exact_sign([&](auto L) {
        return (L(l.e1.x()) - L(l.e0.x())) * (L(m.e1.y()) - L(m.e0.y())) - (L(l.e1.y()) - L(l.e0.y())) * (L(m.e1.x()) - L(m.e0.x()));
      }) != 0)
    return false;
  return exact::exact_sign([&](auto L) {
           auto x = L(m.c1.x()) + L(m.c2.x()) - L(l.c1.x()) - L(l.c2.x()), y = L(m.c1.y()) + L(m.c2.y()) - L(l.c1.y()) - L(l.c2.y());
           return (L(l.e1.x()) - L(l.e0.x())) * y - (L(l.e1.y()) - L(l.e0.y())) * x;
         }) == 0;
}

/// Symbolic identity of two candidate points (the same sum vertex, or the crossing of the same two
/// symbolic lines); false when not provable this way (the caller then compares exactly).
inline bool same_point(const Cand& a, const Cand& b) {
  auto fixed = [](const Cand& c, std::uint32_t& p, std::uint32_t& q) {
    const int k = c.at.kind == Param::Zero ? 0 : c.at.kind == Param::One ? 1 : c.at.kind == Param::Cut ? known_lambda(c.at.line, c.E) : -1;
    if (k < 0) return false;
    p = k == 0 ? c.E.p0 : c.E.p1;
    q = k == 0 ? c.E.q0 : c.E.q1;
    return c.E.sym;
  };
  auto through = [](const Line& l, std::uint32_t p, std::uint32_t q) { return (l.p0 == p && l.q0 == q) || (l.p1 == p && l.q1 == q); };
  // The sum vertex at end k of c (c's fixed point) lies on line l: exact, degree 2.
  auto vertex_on = [](const Cand& c, int k, const Line& l) {
    return exact::exact_sign([&](auto L) {
             auto x = L(c.E.o1.x()) + L(c.E.o2.x()) - L(l.c1.x()) - L(l.c2.x());
             auto y = L(c.E.o1.y()) + L(c.E.o2.y()) - L(l.c1.y()) - L(l.c2.y());
             if (k == 1) {
               x = x + ray_dx(c.E, L);
               y = y + ray_dy(c.E, L);
             }
             return (L(l.e1.x()) - L(l.e0.x())) * y - (L(l.e1.y()) - L(l.e0.y())) * x;
           }) == 0;
  };
  // A cut point of b whose cut line passes through a's vertex V is V iff V lies on b's edge line
  // (collinear candidates from parallel edges of P and Q are common on real pieces).
  auto end_of = [](const Cand& c) { return c.at.kind == Param::Zero ? 0 : c.at.kind == Param::One ? 1 : known_lambda(c.at.line, c.E); };
  auto cut_at_vertex = [&](const Cand& a, std::uint32_t p, std::uint32_t q, const Cand& b) {
    if (b.at.kind != Param::Cut) return false;
    const int k = end_of(a);
    return (through(b.at.line, p, q) || vertex_on(a, k, b.at.line)) && (through(b.edge, p, q) || vertex_on(a, k, b.edge));
  };
  std::uint32_t pa = 0, qa = 0, pb = 0, qb = 0;  // set when fa / fb
  const bool fa = fixed(a, pa, qa), fb = fixed(b, pb, qb);
  if (fa && fb) {
    if (pa == pb && qa == qb) return true;
    // Two sum vertices with equal coordinates (an edge of P equal to one of −Q): exact, degree 1.
    const int ka = end_of(a), kb = end_of(b);
    for (int axis = 0; axis < 2; ++axis)
      if (exact::exact_sign([&](auto L) {
            auto va = axis == 0 ? L(a.E.o1.x()) + L(a.E.o2.x()) : L(a.E.o1.y()) + L(a.E.o2.y());
            auto vb = axis == 0 ? L(b.E.o1.x()) + L(b.E.o2.x()) : L(b.E.o1.y()) + L(b.E.o2.y());
            if (ka == 1) va = va + (axis == 0 ? ray_dx(a.E, L) : ray_dy(a.E, L));
            if (kb == 1) vb = vb + (axis == 0 ? ray_dx(b.E, L) : ray_dy(b.E, L));
            return va - vb;
          }) != 0)
        return false;
    return true;
  }
  if (fa) return cut_at_vertex(a, pa, qa, b);
  if (fb) return cut_at_vertex(b, pb, qb, a);
  if (a.at.kind == Param::Cut && b.at.kind == Param::Cut)
    return (same_line(a.at.line, b.edge) && collinear(b.at.line, a.edge)) || (same_line(b.at.line, a.edge) && collinear(a.at.line, b.edge));
  // Projections of t on one geometric line (collinear candidates) are one point.
  if (a.at.kind == Param::Proj && b.at.kind == Param::Proj) return collinear(a.edge, b.edge);
  return false;
}

/// Which end of its edge the candidate point is (0 start, 1 end, -1 neither), decided exactly.
inline int cand_end(const Cand& c, const Vec2& t) {
  if (compare_params(c.at, Param{Param::Zero, {}}, c.E, t) == 0) return 0;
  if (compare_params(c.at, Param{Param::One, {}}, c.E, t) == 0) return 1;
  return -1;
}

/// The open interval of μ that another open sum covers on the edge.
struct Cover {
  Line entry, exit;
};

/// Sorts `covers` by exact entry and calls emit(lo, hi) for every uncovered closed piece [lo, hi]
/// of [lo_end, hi_end] (zero-length pieces included: a point between two covers that only touch).
template <class Emit>
void uncovered_pieces(std::vector<Cover>& covers, const Ray& E, const Vec2& t, const Param& lo_end, const Param& hi_end,
                      Emit&& emit) {
  std::sort(covers.begin(), covers.end(), [&](const Cover& x, const Cover& y) { return compare_lines(x.entry, y.entry, E) < 0; });
  Param s = lo_end;
  for (const Cover& cv : covers) {
    const Param a{Param::Cut, cv.entry}, bq{Param::Cut, cv.exit};
    if (compare_params(a, s, E, t) >= 0) {
      emit(s, a);
      s = bq;
    } else if (compare_params(bq, s, E, t) > 0) {
      s = bq;
    }
    if (compare_params(s, hi_end, E, t) > 0) return;
  }
  emit(s, hi_end);
}

}  // namespace pendepth::nonconvex2
