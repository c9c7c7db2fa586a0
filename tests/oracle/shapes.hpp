// Random convex shapes, placements and directions for the oracle tests (pinned seeds at the
// call sites). Shapes are raw point sets: pendepth hulls them with ConvexPolygon::hull, the oracle
// with CGAL, so the two never share a normal form.
#pragma once

#include <pendepth/polygon.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "oracle/exact_oracle.hpp"

namespace oracle_tests {

using pendepth::ConvexPolygon;
using pendepth::Vec2;
using Rng = std::mt19937_64;

inline double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
inline int uniform_int(Rng& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

enum class ShapeKind { Cloud, Ellipse, Grid5, Grid3, Dyadic };
inline const char* name(ShapeKind k) {
  switch (k) {
    case ShapeKind::Cloud: return "cloud";
    case ShapeKind::Ellipse: return "ellipse";
    case ShapeKind::Grid5: return "grid5";
    case ShapeKind::Grid3: return "grid3";
    case ShapeKind::Dyadic: return "dyadic";
  }
  return "?";
}

/// n points of one kind. Cloud: uniform doubles in a random box (few hull vertices). Ellipse:
/// random angles on a rotated ellipse (all points extreme, so n hull vertices). Grid5/Grid3:
/// integer points of [-5,5]² / [-3,3]² (many parallel edges, exact sums). Dyadic: multiples of
/// 2^-20 in [-1,1]² (exact under offsets up to 2^31).
inline std::vector<Vec2> points(Rng& rng, ShapeKind kind, int n, double scale = 1) {
  std::vector<Vec2> pts;
  pts.reserve(n);
  switch (kind) {
    case ShapeKind::Cloud: {
      double w = scale * uniform(rng, 0.1, 10), h = scale * uniform(rng, 0.1, 10);
      Vec2 c(uniform(rng, -5, 5) * scale, uniform(rng, -5, 5) * scale);
      for (int i = 0; i < n; ++i) pts.emplace_back(c.x() + uniform(rng, -w, w), c.y() + uniform(rng, -h, h));
      break;
    }
    case ShapeKind::Ellipse: {
      double a = scale * uniform(rng, 0.2, 10), b = a * uniform(rng, 0.05, 1), phi = uniform(rng, 0, std::numbers::pi);
      Vec2 c(uniform(rng, -5, 5) * scale, uniform(rng, -5, 5) * scale);
      for (int i = 0; i < n; ++i) {
        double th = uniform(rng, 0, 2 * std::numbers::pi);
        Vec2 e(a * std::cos(th), b * std::sin(th));
        pts.emplace_back(c.x() + std::cos(phi) * e.x() - std::sin(phi) * e.y(),
                         c.y() + std::sin(phi) * e.x() + std::cos(phi) * e.y());
      }
      break;
    }
    case ShapeKind::Grid5:
    case ShapeKind::Grid3: {
      int R = kind == ShapeKind::Grid5 ? 5 : 3;
      for (int i = 0; i < n; ++i) pts.emplace_back(uniform_int(rng, -R, R), uniform_int(rng, -R, R));
      break;
    }
    case ShapeKind::Dyadic:
      for (int i = 0; i < n; ++i)
        pts.emplace_back(std::ldexp(uniform_int(rng, -(1 << 20), 1 << 20), -20),
                         std::ldexp(uniform_int(rng, -(1 << 20), 1 << 20), -20));
      break;
  }
  return pts;
}

/// A shape: its raw points and pendepth's hull of them. Re-draws collinear sets.
struct Shape {
  std::vector<Vec2> pts;
  std::optional<ConvexPolygon> poly;
  std::string label;
};

inline Shape shape(Rng& rng, ShapeKind kind, int n, double scale = 1) {
  for (;;) {
    Shape s;
    s.pts = points(rng, kind, n, scale);
    try {
      s.poly.emplace(ConvexPolygon::hull(s.pts));
    } catch (const pendepth::InvalidInput&) {
      continue;  // all points collinear (small grids): draw again
    }
    s.label = std::string(name(kind)) + "(" + std::to_string(n) + " pts, " + std::to_string(s.poly->size()) + " hull)";
    return s;
  }
}

inline ShapeKind random_kind(Rng& rng, int n) {
  // Grids have at most ~40 hull vertices, clouds ~O(log n); ellipses give large hulls.
  if (n > 200) return uniform_int(rng, 0, 3) == 0 ? ShapeKind::Cloud : ShapeKind::Ellipse;
  switch (uniform_int(rng, 0, 4)) {
    case 0: return ShapeKind::Cloud;
    case 1: return ShapeKind::Ellipse;
    case 2: return ShapeKind::Grid5;
    case 3: return ShapeKind::Grid3;
    default: return ShapeKind::Dyadic;
  }
}

inline Vec2 rot90(const Vec2& v) { return Vec2(-v.y(), v.x()); }  // exact

/// Placements: random in M's (slightly enlarged) box, exact boundary points of M, points one
/// ulp inside ∂M (nextafter towards the box centre), and the origin.
inline std::vector<Vec2> placements(Rng& rng, const oracle::ExactDifference& M, int random_count, int boundary_count) {
  std::vector<Vec2> out;
  const Vec2 lo = M.box_lo(), hi = M.box_hi(), c = (lo + hi) / 2, half = (hi - lo) * 0.55;
  for (int i = 0; i < random_count; ++i)
    out.emplace_back(c.x() + uniform(rng, -half.x(), half.x()), c.y() + uniform(rng, -half.y(), half.y()));
  std::vector<Vec2> b = M.boundary_doubles();
  for (int i = 0; i < boundary_count && !b.empty(); ++i) {
    const Vec2 p = b[std::uniform_int_distribution<std::size_t>(0, b.size() - 1)(rng)];
    out.push_back(p);
    const Vec2 in(std::nextafter(p.x(), c.x()), std::nextafter(p.y(), c.y()));
    out.push_back(in);
    out.emplace_back(in.x(), p.y());
    out.emplace_back(p.x(), in.y());
  }
  out.emplace_back(0, 0);
  return out;
}

/// Directions: random at three scales, edges of P and Q (exact double differences, scaled by
/// powers of two so parallelism stays exact), axis directions, edges of M (rounded).
inline Vec2 direction(Rng& rng, const ConvexPolygon& P, const ConvexPolygon& Q, const oracle::ExactDifference& M) {
  const double pow2[] = {1.0, 0x1p-27, 0x1p27};  // ~1e-8 and ~1e8
  const double dec[] = {1.0, 1e-8, 1e8};
  const int scale = uniform_int(rng, 0, 2);
  auto edge = [&](const ConvexPolygon& S) {
    std::size_t i = std::uniform_int_distribution<std::size_t>(0, S.size() - 1)(rng);
    return Vec2(S.at_cyclic(i + 1) - S[i]);
  };
  Vec2 d;
  switch (uniform_int(rng, 0, 5)) {
    case 0: {
      double a = uniform(rng, 0, 2 * std::numbers::pi);
      return Vec2(std::cos(a), std::sin(a)) * dec[scale];
    }
    case 1: d = edge(P); break;
    case 2: d = edge(Q); break;
    case 3: d = -edge(uniform_int(rng, 0, 1) ? P : Q); break;
    case 4: {
      const Vec2 axes[] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, 1}};
      d = axes[uniform_int(rng, 0, 5)];
      break;
    }
    default: {
      std::size_t k = std::uniform_int_distribution<std::size_t>(0, M.size() - 1)(rng);
      d = M.vertex((k + 1) % M.size()) - M.vertex(k);
      break;
    }
  }
  if (d.x() == 0 && d.y() == 0) d = Vec2(1, 0);
  return d * pow2[scale];
}

}  // namespace oracle_tests
