// Seeded random convex pairs, placements and directions for the convex2 tests, covering the
// degenerate families the issue names: parallel edges (small integer grids), triangles,
// identical shapes, large offsets, directions parallel to edges, placements exactly on ∂M.
#pragma once

#include <pendepth/polygon.hpp>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "convex2/brute_force.hpp"

namespace shapes {

using pendepth::ConvexPolygon;
using pendepth::Vec2;

inline ConvexPolygon grid_hull(std::mt19937_64& rng, int R, int count, Vec2 offset = {0, 0}) {
  std::uniform_int_distribution<int> c(-R, R);
  for (;;) {
    std::vector<Vec2> pts;
    for (int k = 0; k < count; ++k) pts.emplace_back(c(rng) + offset.x(), c(rng) + offset.y());
    try {
      return ConvexPolygon::hull(pts);
    } catch (const pendepth::InvalidInput&) {
    }
  }
}

inline ConvexPolygon ellipse(std::mt19937_64& rng, int count, double scale, Vec2 center = {0, 0}) {
  std::uniform_real_distribution<double> a(0, 2 * M_PI), s(0.2, 1.0);
  double sx = scale * s(rng), sy = scale * s(rng);
  for (;;) {
    std::vector<Vec2> pts;
    for (int k = 0; k < count; ++k) {
      double th = a(rng);
      pts.emplace_back(center.x() + sx * std::cos(th), center.y() + sy * std::sin(th));
    }
    try {
      return ConvexPolygon::hull(pts);
    } catch (const pendepth::InvalidInput&) {
    }
  }
}

/// Family chosen by trial index: grids (parallel edges), ellipses, triangles, identical shapes,
/// shapes offset by 1e6.
inline std::pair<ConvexPolygon, ConvexPolygon> random_pair(std::mt19937_64& rng, int trial) {
  std::uniform_int_distribution<int> sz(3, 40);
  switch (trial % 6) {
    case 0: return {grid_hull(rng, 3, sz(rng)), grid_hull(rng, 3, sz(rng))};
    case 1: return {grid_hull(rng, 20, sz(rng)), grid_hull(rng, 5, sz(rng), {3, -2})};
    case 2: return {ellipse(rng, sz(rng), 2.0), ellipse(rng, sz(rng), 1.0, {0.3, 0.1})};
    case 3: return {grid_hull(rng, 50, 3), grid_hull(rng, 50, 3)};  // triangles (mostly)
    case 4: {
      ConvexPolygon A = ellipse(rng, sz(rng), 1.0);
      return {A, A};  // identical shapes
    }
    default: return {ellipse(rng, sz(rng), 1.0, {1e6, -1e6}), ellipse(rng, sz(rng), 0.5, {1e6, -1e6})};
  }
}

/// A placement: random in M's bounding box, an exact vertex of M (on ∂M), an edge midpoint of
/// M, or M's vertex nudged by one ulp.
inline Vec2 placement(std::mt19937_64& rng, const ConvexPolygon&, const ConvexPolygon&,
                      const std::vector<brute::QPt>& M, int k) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const auto& v : M) {
    x0 = std::min(x0, v.x.get_d()); x1 = std::max(x1, v.x.get_d());
    y0 = std::min(y0, v.y.get_d()); y1 = std::max(y1, v.y.get_d());
  }
  std::uniform_int_distribution<std::size_t> pick(0, M.size() - 1);
  const brute::QPt& v = M[pick(rng)];
  const brute::QPt& w = M[(&v - M.data() + 1) % M.size()];
  switch (k % 6) {
    case 0: return {v.x.get_d(), v.y.get_d()};  // exact when representable (grid families)
    case 1: {
      mpq_class mx = (v.x + w.x) / 2, my = (v.y + w.y) / 2;
      return {mx.get_d(), my.get_d()};
    }
    case 2: return {std::nextafter(v.x.get_d(), (x0 + x1) / 2), std::nextafter(v.y.get_d(), (y0 + y1) / 2)};
    default: {
      std::uniform_real_distribution<double> ux(x0, x1), uy(y0, y1);
      return {ux(rng), uy(rng)};
    }
  }
}

/// A direction: random, axis-aligned, or parallel to an edge of P or of Q (exact edge vector).
inline Vec2 direction(std::mt19937_64& rng, const ConvexPolygon& P, const ConvexPolygon& Q, int k) {
  std::uniform_int_distribution<std::size_t> ip(0, P.size() - 1), iq(0, Q.size() - 1);
  std::normal_distribution<double> g;
  switch (k % 5) {
    case 0: { std::size_t i = ip(rng); return P.at_cyclic(i + 1) - P[i]; }
    case 1: { std::size_t i = iq(rng); return Q[i] - Q.at_cyclic(i + 1); }
    case 2: { Vec2 axes[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}}; return axes[k % 4]; }
    case 3: return Vec2(g(rng), g(rng)) * 1e-8;
    default: return Vec2(g(rng), g(rng)) * (k % 2 ? 1e8 : 1.0);
  }
}

}  // namespace shapes
