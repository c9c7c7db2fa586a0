// σ for one placement in O(n + m): merge the edges of P and −Q in slope order (DHS §3,
// Theorem 3.1) and take the nearest edge line of M. For t ∈ int M, dist(t, ∂M) is the minimum
// over edges of the distance to the edge's line, and the foot of that line lies on the edge.
//
// One fused pass, no allocation after the first call: each edge of M is produced by the merge
// (exact angle order) and its distance estimated in double with a proven error bound. An edge
// whose numerator is certainly negative proves t ∉ M (depth 0, exact). Pass 2 re-evaluates
// accurately every edge whose lower bound is below the smallest upper bound, so the minimum is
// certified and its value is within a few ulps.
#include <pendepth/depth2.hpp>

#include <cmath>
#include <limits>

#include "convex2/minkowski_sum.hpp"
#include "geometry/exact.hpp"

namespace pendepth {

namespace {

struct Candidate {
  convex2::MEdge edge;
  double lower;  // certified lower bound of the edge's signed distance
};

// Exact angle order of edge vectors (a1 − a0) and (b1 − b0), with the cross product's static
// filter inlined (the common case); predicates::compare_angle decides the rest exactly.
inline int angle_order(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  const double ax = a1.x() - a0.x(), ay = a1.y() - a0.y(), bx = b1.x() - b0.x(), by = b1.y() - b0.y();
  const int ha = (a1.y() < a0.y() || (a1.y() == a0.y() && a1.x() < a0.x()));
  const int hb = (b1.y() < b0.y() || (b1.y() == b0.y() && b1.x() < b0.x()));
  if (ha != hb) return ha < hb ? -1 : 1;
  const double p1 = ax * by, p2 = ay * bx, c = p1 - p2;
  const double bound = exact::kCrossBound * (std::abs(p1) + std::abs(p2)) + exact::kTiny;
  if (c > bound) return -1;
  if (c < -bound) return 1;
  return predicates::compare_angle(a0, a1, b0, b1);
}

}  // namespace

Depth2 minimum_depth(const ConvexPolygon& P, const ConvexPolygon& Q, const Vec2& t) {
  convex2::require_finite(t, "placement t");
  const std::span<const Vec2> p = P.vertices(), q = Q.vertices();
  const std::size_t n = p.size(), m = q.size(), top = Q.top();
  thread_local std::vector<Candidate> cand;
  cand.clear();
  double best_hi = std::numeric_limits<double>::infinity();
  const double atx = std::abs(t.x()), aty = std::abs(t.y());

  std::size_t i = 0, j = 0;
  while (i < n || j < m) {
    const std::size_t ia = i < n ? i : i - n, iq0 = top + j, iq = iq0 < m ? iq0 : iq0 - m;
    const std::size_t ia1 = ia + 1 < n ? ia + 1 : 0, iq1 = iq + 1 < m ? iq + 1 : 0;
    const Vec2 &a = p[ia], &a1 = p[ia1], &qv = q[iq], &qv1 = q[iq1];
    int c = i == n ? 1 : (j == m ? -1 : angle_order(a, a1, -qv, -qv1));
    convex2::MEdge e{static_cast<std::uint32_t>(ia), static_cast<std::uint32_t>(iq), convex2::EdgeSource::P};
    double ex, ey;
    if (c < 0) {
      ++i;
      ex = a1.x() - a.x(), ey = a1.y() - a.y();
    } else if (c > 0) {
      e.src = convex2::EdgeSource::Q;
      ++j;
      ex = qv.x() - qv1.x(), ey = qv.y() - qv1.y();
    } else {
      e.src = convex2::EdgeSource::Both;
      ++i, ++j;
      ex = a1.x() - a.x(), ey = a1.y() - a.y();
    }
    // numerator cross(e, t − a + q): > 0 inside. |error| <= 6u·(|ex|·Sy + |ey|·Sx), S the sums
    // of the absolute values of the three terms of each coordinate of t − a + q.
    const double rx = t.x() - a.x() + qv.x(), ry = t.y() - a.y() + qv.y();
    const double num = ex * ry - ey * rx;
    const double bound = 6 * exact::kUnit *
                             (std::abs(ex) * (aty + std::abs(a.y()) + std::abs(qv.y())) +
                              std::abs(ey) * (atx + std::abs(a.x()) + std::abs(qv.x()))) +
                         exact::kTiny;
    if (num < -bound) return Depth2{};  // t strictly outside this edge's half-plane: t ∉ M
    const double inv = 1 / std::sqrt(ex * ex + ey * ey);
    const double val = num * inv, err = bound * inv * (1 + 8 * exact::kUnit) + std::abs(val) * 8 * exact::kUnit;
    if (val + err < best_hi) best_hi = val + err;
    if (val - err <= best_hi) cand.push_back({e, val - err});
  }

  double best = std::numeric_limits<double>::infinity();
  convex2::MEdge best_edge{};
  for (const Candidate& k : cand) {
    if (!(k.lower <= best_hi)) continue;
    const double d = convex2::edge_distance(p, q, k.edge, t);
    if (d < best) best = d, best_edge = k.edge;
  }
  if (best < 0) return Depth2{};
  if (best == 0) {
    // Rounded to zero: decide overlap exactly. Edges outside the candidate set are certainly
    // farther than best_hi >= σ, so t ∈ int M iff every candidate's exact side is positive; the
    // depth is then below the double range (subnormal-scale placements) and reported as 0.
    for (const Candidate& k : cand)
      if (k.lower <= best_hi && convex2::edge_side(p, q, k.edge, t) <= 0) return Depth2{};
  }
  return convex2::edge_result(p, q, best_edge, t, best);
}

std::vector<Vec2> minkowski_difference(const ConvexPolygon& P, const ConvexPolygon& Q) {
  const convex2::MinkowskiSum M(P, Q);
  std::vector<Vec2> out(M.size());
  for (std::size_t k = 0; k < M.size(); ++k) out[k] = M.vertex(k);
  return out;
}

}  // namespace pendepth
