// Symbolic M = P ⊕ (−Q) for convex polygons (DHS §3, Theorem 3.1) and its certified distances.
#include "convex2/minkowski_sum.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "geometry/exact.hpp"

namespace pendepth::convex2 {

void require_finite(const Vec2& v, const char* what) {
  if (!std::isfinite(v.x()) || !std::isfinite(v.y()))
    throw InvalidInput(std::string(what) + " has a non-finite coordinate");
}

MinkowskiSum::MinkowskiSum(const ConvexPolygon& P, const ConvexPolygon& Q)
    : own_p_(P.vertices().begin(), P.vertices().end()), own_q_(Q.vertices().begin(), Q.vertices().end()) {
  p_ = own_p_;
  q_ = own_q_;
  merge(Q.top());
  build_fan();
}

void MinkowskiSum::assign_view(const ConvexPolygon& P, const ConvexPolygon& Q) {
  own_p_.clear();
  own_q_.clear();
  p_ = P.vertices();
  q_ = Q.vertices();
  merge(Q.top());
  build_fan();
}

void MinkowskiSum::build_fan() {
  fan_.clear();
  for (std::size_t k = 0; k < edges_.size(); k += kFanBlock) fan_.push_back({p_[edges_[k].ia], q_[edges_[k].iq]});
}

void MinkowskiSum::merge(std::size_t top) {
  const std::size_t n = p_.size(), m = q_.size();
  edges_.clear();
  edges_.reserve(n + m);
  std::size_t i = 0, j = 0;
  while (i < n || j < m) {
    const std::size_t ia = i % n, iq = (top + j) % m;
    MEdge e{static_cast<std::uint32_t>(ia), static_cast<std::uint32_t>(iq), EdgeSource::P};
    int c;
    if (i == n) c = 1;
    else if (j == m) c = -1;
    else {
      // A edge: P[ia] -> P[ia+1]; B edge: -Q[iq] -> -Q[iq+1].
      Vec2 b0 = -q_[iq], b1 = -q_[(iq + 1) % m];
      c = predicates::compare_angle(p_[ia], p_[(ia + 1) % n], b0, b1);
    }
    if (c < 0) { e.src = EdgeSource::P; ++i; }
    else if (c > 0) { e.src = EdgeSource::Q; ++j; }
    else { e.src = EdgeSource::Both; ++i; ++j; }
    edges_.push_back(e);
  }
}

Vec2 MinkowskiSum::vertex(std::size_t k) const {
  const MEdge& e = edges_[k % edges_.size()];
  return p_[e.ia] - q_[e.iq];
}

void edge_points(std::span<const Vec2> p, std::span<const Vec2> q, const MEdge& e, Vec2& from, Vec2& to) {
  if (e.src == EdgeSource::Q) {
    from = -q[e.iq];
    to = -q[(e.iq + 1) % q.size()];
  } else {
    from = p[e.ia];
    to = p[(e.ia + 1) % p.size()];
  }
}

void MinkowskiSum::edge_points(std::size_t k, Vec2& from, Vec2& to) const {
  convex2::edge_points(p_, q_, edges_[k], from, to);
}

Vec2 MinkowskiSum::outward_normal(std::size_t k) const {
  Vec2 a, b;
  edge_points(k, a, b);
  Vec2 e = b - a;
  return Vec2(e.y(), -e.x()) / e.norm();
}

namespace {
// cross(E, t − (P[ia] − Q[iq])) with E = to − from: > 0 inside.
template <class L>
auto numerator(L lift, const Vec2& from, const Vec2& to, const Vec2& a, const Vec2& q, const Vec2& t) {
  auto ex = lift(to.x()) - lift(from.x()), ey = lift(to.y()) - lift(from.y());
  auto rx = lift(t.x()) - lift(a.x()) + lift(q.x());
  auto ry = lift(t.y()) - lift(a.y()) + lift(q.y());
  return ex * ry - ey * rx;
}
template <class L>
auto length2(L lift, const Vec2& from, const Vec2& to) {
  auto ex = lift(to.x()) - lift(from.x()), ey = lift(to.y()) - lift(from.y());
  return ex * ex + ey * ey;
}
}  // namespace

int edge_side(std::span<const Vec2> p, std::span<const Vec2> q, const MEdge& e, const Vec2& t) {
  Vec2 a, b;
  edge_points(p, q, e, a, b);
  const Vec2 &pa = p[e.ia], &qq = q[e.iq];
  return exact::exact_sign([&](auto L) { return numerator(L, a, b, pa, qq, t); });
}

int MinkowskiSum::side(std::size_t k, const Vec2& t) const { return edge_side(p_, q_, edges_[k], t); }

double edge_distance(std::span<const Vec2> p, std::span<const Vec2> q, const MEdge& e, const Vec2& t) {
  Vec2 a, b;
  edge_points(p, q, e, a, b);
  const Vec2 &pa = p[e.ia], &qq = q[e.iq];
  double num = exact::accurate_value([&](auto L) { return numerator(L, a, b, pa, qq, t); });
  double len = std::sqrt(exact::accurate_value([&](auto L) { return length2(L, a, b); }));
  return num / len;
}

double MinkowskiSum::distance(std::size_t k, const Vec2& t) const { return edge_distance(p_, q_, edges_[k], t); }

void MinkowskiSum::distance_estimate(std::size_t k, const Vec2& t, double& value, double& error) const {
  Vec2 a, b;
  edge_points(k, a, b);
  const Vec2 &pa = p_[edges_[k].ia], &qq = q_[edges_[k].iq];
  exact::Fl r = numerator(exact::LiftFl{}, a, b, pa, qq, t);
  double len = (b - a).norm();
  value = r.v / len;
  error = exact::safe_bound(r.e) / len * (1 + 8 * exact::kUnit) + std::abs(value) * 8 * exact::kUnit;
  if (!std::isfinite(value) || !std::isfinite(error)) error = std::numeric_limits<double>::infinity();
}

bool MinkowskiSum::contains_interior(const Vec2& t) const {
  // Fan from vertex 0 = P[ia0] − Q[iq0]: sign of cross(v_k − v_0, t − v_0), symbolic vertices.
  const std::size_t N = edges_.size();
  const Vec2 &a0 = p_[edges_[0].ia], &q0 = q_[edges_[0].iq];
  const double wx = t.x() - a0.x() + q0.x(), wy = t.y() - a0.y() + q0.y();
  const double Swx = std::abs(t.x()) + std::abs(a0.x()) + std::abs(q0.x());
  const double Swy = std::abs(t.y()) + std::abs(a0.y()) + std::abs(q0.y());
  auto orient_pq = [&](const Vec2& ak, const Vec2& qk) {
    // Static filter: sums of 4 and 3 doubles, two products, one difference: error at most
    // 8u·(Sux·Swy + Suy·Swx) with S the sums of absolute values of the terms.
    const double ux = ak.x() - qk.x() - a0.x() + q0.x(), uy = ak.y() - qk.y() - a0.y() + q0.y();
    const double Sux = std::abs(ak.x()) + std::abs(qk.x()) + std::abs(a0.x()) + std::abs(q0.x());
    const double Suy = std::abs(ak.y()) + std::abs(qk.y()) + std::abs(a0.y()) + std::abs(q0.y());
    const double bound = 8 * exact::kUnit * (Sux * Swy + Suy * Swx) + exact::kTiny;
    return exact::exact_sign_filtered(ux * wy - uy * wx, bound, [&](auto L) {
      auto vx = L(ak.x()) - L(qk.x()) - L(a0.x()) + L(q0.x());
      auto vy = L(ak.y()) - L(qk.y()) - L(a0.y()) + L(q0.y());
      return vx * (L(t.y()) - L(a0.y()) + L(q0.y())) - vy * (L(t.x()) - L(a0.x()) + L(q0.x()));
    });
  };
  auto orient = [&](std::size_t k) {
    const MEdge& ek = edges_[k % N];
    return orient_pq(p_[ek.ia], q_[ek.iq]);
  };
  if (orient(1) <= 0 || orient(N - 1) >= 0) return false;
  // Last k in [1, N-1) with orient(k) > 0: t lies in the wedge (v0, v_k, v_{k+1}). While the
  // range is long, split at multiples of kFanBlock, whose vertices sit in the compact fan_
  // array (cache-friendly on huge M); then finish in the edge array.
  std::size_t lo = 1, hi = N - 1;
  while (hi - lo > 2 * kFanBlock) {
    const std::size_t mid = (lo + hi) / 2 / kFanBlock * kFanBlock;  // in (lo, hi): range > 2 blocks
    const auto& f = fan_[mid / kFanBlock];
    if (orient_pq(f[0], f[1]) > 0) lo = mid;
    else hi = mid;
  }
  while (hi - lo > 1) {
    std::size_t mid = (lo + hi) / 2;
    if (orient(mid) > 0) lo = mid;
    else hi = mid;
  }
  return side(lo, t) > 0;
}

Depth2 edge_result(std::span<const Vec2> p_, std::span<const Vec2> q_, const MEdge& e, const Vec2& t, double dist) {
  Depth2 r;
  r.kind = DepthKind::Minimum;
  r.overlapping = true;
  r.depth = dist;
  Vec2 from, to;
  edge_points(p_, q_, e, from, to);
  const Vec2 ev = to - from;
  r.normal = Vec2(ev.y(), -ev.x()) / ev.norm();
  r.translation = dist * r.normal;
  const std::size_t n = p_.size(), m = q_.size();
  const Vec2 f = t + r.translation;  // Q's final placement, on ∂M
  auto q_vertex_on_p_edge = [&](std::size_t iq) {
    r.witness_q = q_[iq] + f;
    r.witness_p = r.witness_q;
  };
  auto p_vertex_on_q_edge = [&](std::size_t ia) {
    r.witness_p = p_[ia];
    r.witness_q = p_[ia];
  };
  switch (e.src) {
    case EdgeSource::P:
      r.feature_p = {FeatureKind::Edge, int(e.ia)};
      r.feature_q = {FeatureKind::Vertex, int(e.iq)};
      q_vertex_on_p_edge(e.iq);
      break;
    case EdgeSource::Q:
      r.feature_p = {FeatureKind::Vertex, int(e.ia)};
      r.feature_q = {FeatureKind::Edge, int(e.iq)};
      p_vertex_on_q_edge(e.ia);
      break;
    case EdgeSource::Both: {
      // Collinear pieces: P's edge (Q vertex iq fixed), then −Q's edge (P vertex ia+1 fixed).
      r.feature_p = {FeatureKind::Edge, int(e.ia)};
      r.feature_q = {FeatureKind::Edge, int(e.iq)};
      Vec2 ep = p_[(e.ia + 1) % n] - p_[e.ia];
      Vec2 v0 = p_[e.ia] - q_[e.iq];
      if ((f - v0).dot(ep) <= ep.squaredNorm()) q_vertex_on_p_edge(e.iq);
      else p_vertex_on_q_edge((e.ia + 1) % n);
      (void)m;
      break;
    }
  }
  return r;
}

Depth2 MinkowskiSum::result_for_edge(std::size_t k, const Vec2& t, double dist) const {
  return edge_result(p_, q_, edges_[k], t, dist);
}

Nearest nearest_edge(const MinkowskiSum& M, const Vec2& t, const std::size_t* first, const std::size_t* last) {
  // Pass 1: double estimates with rigorous error bounds; the true minimiser's lower bound is
  // <= the smallest upper bound. Pass 2: re-evaluate those candidates accurately.
  const bool all = first == nullptr;
  const std::size_t count = all ? M.size() : std::size_t(last - first);
  auto index = [&](std::size_t s) { return all ? s : first[s]; };
  double best_hi = std::numeric_limits<double>::infinity();
  thread_local std::vector<double> lo, val;
  lo.resize(count);
  val.resize(count);
  for (std::size_t s = 0; s < count; ++s) {
    double v, e;
    M.distance_estimate(index(s), t, v, e);
    val[s] = v;
    lo[s] = v - e;
    best_hi = std::min(best_hi, v + e);
  }
  Nearest best{index(0), std::numeric_limits<double>::infinity()};
  for (std::size_t s = 0; s < count; ++s) {
    if (!(lo[s] <= best_hi)) continue;
    std::size_t k = index(s);
    double d = M.distance(k, t);
    if (d < best.distance) best = {k, d};
  }
  return best;
}

}  // namespace pendepth::convex2
