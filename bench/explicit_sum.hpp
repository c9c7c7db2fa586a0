// Shared by the 2D non-convex benchmarks (bench_polygon2, bench_nonconvex2): an explicit
// Minkowski sum as a peer (CGAL, Clipper) builds it, kept as flat segment arrays, and the peers'
// per-query "scan": even-odd point location (straddles decided by the exact orientation
// predicate), then the nearest edge (σ) or the first edge along the ray (σ_d), in double.
#pragma once

#include <pendepth/geometry.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace pendepth::bench {

// Crossing number on one ring, the straddle decided by the exact orientation predicate.
inline int crossings(const std::vector<Vec2>& ring, const Vec2& p) {
  int c = 0;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 &a = ring[j], &b = ring[i];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const int o = pendepth::predicates::orient2d(a, b, p);
      if ((b.y() > a.y()) ? o > 0 : o < 0) ++c;
    }
  }
  return c;
}

// ---- an explicit sum and its scans ----

// Rings of an explicit sum (outer boundaries and holes, any orientation) as flat segment arrays.
class ExplicitSum {
 public:
  void add_ring(const std::vector<Vec2>& ring) {
    if (ring.size() < 3) return;
    rings_.push_back(ring);
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      ax_.push_back(ring[j].x()), ay_.push_back(ring[j].y());
      ex_.push_back(ring[i].x() - ring[j].x()), ey_.push_back(ring[i].y() - ring[j].y());
    }
  }
  std::size_t vertices() const { return ax_.size(); }
  std::size_t rings() const { return rings_.size(); }

  // Even-odd over all rings: CGAL and Clipper give outer boundaries and holes as nested rings.
  bool inside(const Vec2& t) const {
    int c = 0;
    for (const auto& r : rings_) c += crossings(r, t);
    return c % 2 == 1;
  }
  double sigma(const Vec2& t) const {
    if (!inside(t)) return 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < ax_.size(); ++k) {
      const double wx = t.x() - ax_[k], wy = t.y() - ay_[k];
      const double len2 = ex_[k] * ex_[k] + ey_[k] * ey_[k];
      const double s = std::clamp((wx * ex_[k] + wy * ey_[k]) / len2, 0.0, 1.0);
      const double dx = wx - s * ex_[k], dy = wy - s * ey_[k];
      best = std::min(best, dx * dx + dy * dy);
    }
    return std::sqrt(best);
  }
  // d a unit vector: the first boundary point along the ray (t inside).
  double sigma_d(const Vec2& t, const Vec2& d) const {
    if (!inside(t)) return 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < ax_.size(); ++k) {
      const double den = d.x() * ey_[k] - d.y() * ex_[k];
      if (den == 0) continue;
      const double wx = ax_[k] - t.x(), wy = ay_[k] - t.y();
      const double s = (wx * ey_[k] - wy * ex_[k]) / den;  // along the ray
      const double u = (wx * d.y() - wy * d.x()) / den;    // along the edge
      if (s >= 0 && u >= 0 && u <= 1) best = std::min(best, s);
    }
    return best == std::numeric_limits<double>::infinity() ? 0 : best;
  }

 private:
  std::vector<std::vector<Vec2>> rings_;
  std::vector<double> ax_, ay_, ex_, ey_;
};

}  // namespace pendepth::bench
