// Test oracle: exact rational brute force, independent of pendepth's searches.
// M = hull of all pairwise differences p_i − q_j (exact), then every edge is examined.
#pragma once

#include <pendepth/polygon.hpp>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace brute {

struct QPt {
  mpq_class x, y;
};
inline mpq_class cross(const QPt& a, const QPt& b) { return a.x * b.y - a.y * b.x; }
inline QPt sub(const QPt& a, const QPt& b) { return {a.x - b.x, a.y - b.y}; }

/// Exact convex hull (CCW, no collinear points) of P ⊕ (−Q).
inline std::vector<QPt> minkowski_difference(const pendepth::ConvexPolygon& P, const pendepth::ConvexPolygon& Q) {
  std::vector<QPt> pts;
  for (const auto& p : P.vertices())
    for (const auto& q : Q.vertices()) pts.push_back({mpq_class(p.x()) - mpq_class(q.x()), mpq_class(p.y()) - mpq_class(q.y())});
  std::sort(pts.begin(), pts.end(), [](const QPt& a, const QPt& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<QPt> h(2 * pts.size() + 1);
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && sgn(cross(sub(h[k - 1], h[k - 2]), sub(pts[i], h[k - 2]))) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && sgn(cross(sub(h[k - 1], h[k - 2]), sub(pts[i], h[k - 2]))) <= 0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);
  return h;
}

inline QPt lift(const pendepth::Vec2& v) { return {mpq_class(v.x()), mpq_class(v.y())}; }

/// Is t strictly inside M?
inline bool inside(const std::vector<QPt>& M, const QPt& t) {
  for (std::size_t k = 0; k < M.size(); ++k)
    if (sgn(cross(sub(M[(k + 1) % M.size()], M[k]), sub(t, M[k]))) <= 0) return false;
  return true;
}
inline bool inside(const std::vector<QPt>& M, const pendepth::Vec2& tv) { return inside(M, lift(tv)); }

/// Exact point t + f·v for doubles t, v and factor f (no rounding of the moved placement).
inline QPt moved(const pendepth::Vec2& t, const pendepth::Vec2& v, double f) {
  mpq_class F(f);
  return {mpq_class(t.x()) + F * mpq_class(v.x()), mpq_class(t.y()) + F * mpq_class(v.y())};
}

/// σ_d / |d|: exact exit parameter of t + s·d (d not normalised), or 0 if t ∉ int M.
inline mpq_class exit_param(const std::vector<QPt>& M, const pendepth::Vec2& tv, const pendepth::Vec2& dv) {
  if (!inside(M, tv)) return 0;
  QPt t = lift(tv), d = lift(dv);
  std::optional<mpq_class> best;
  for (std::size_t k = 0; k < M.size(); ++k) {
    QPt e = sub(M[(k + 1) % M.size()], M[k]);
    mpq_class den = cross(d, e);
    if (sgn(den) <= 0) continue;
    mpq_class s = cross(sub(M[k], t), e) / den;
    if (!best || s < *best) best = s;
  }
  return *best;
}

/// Complete separation / |d|: the end of the line's open interval in int M if the ray reaches it
/// (end > 0), else 0 — for the line t + s·d, s ∈ ℝ, through convex M.
inline mpq_class separation_param(const std::vector<QPt>& M, const pendepth::Vec2& tv, const pendepth::Vec2& dv) {
  QPt t = lift(tv), d = lift(dv);
  std::optional<mpq_class> entry, exit;
  for (std::size_t k = 0; k < M.size(); ++k) {
    QPt e = sub(M[(k + 1) % M.size()], M[k]);
    mpq_class den = cross(d, e);
    if (sgn(den) == 0) {
      if (sgn(cross(e, sub(t, M[k]))) <= 0) return 0;  // the line runs outside or along this edge
      continue;
    }
    mpq_class s = cross(sub(M[k], t), e) / den;
    if (sgn(den) > 0) { if (!exit || s < *exit) exit = s; }
    else if (!entry || s > *entry) entry = s;
  }
  if (!(*entry < *exit) || sgn(*exit) <= 0) return 0;
  return *exit;
}

/// σ² exactly (0 if t ∉ int M).
inline mpq_class min_depth_squared(const std::vector<QPt>& M, const pendepth::Vec2& tv) {
  if (!inside(M, tv)) return 0;
  QPt t = lift(tv);
  std::optional<mpq_class> best;
  for (std::size_t k = 0; k < M.size(); ++k) {
    QPt e = sub(M[(k + 1) % M.size()], M[k]);
    mpq_class c = cross(e, sub(t, M[k]));
    mpq_class d2 = c * c / (e.x * e.x + e.y * e.y);
    if (!best || d2 < *best) best = d2;
  }
  return *best;
}

/// Relative difference in units of 2^-52 (ulps of 1.0 relative), for reporting.
inline double ulps(double got, double want) {
  if (got == want) return 0;
  return std::abs(got - want) / (std::max(std::abs(want), 1e-300) * 0x1p-52);
}

}  // namespace brute
