// Test shapes for polygon2: random star-shaped polygons (optionally with holes), combs with deep
// pockets, spirals, squares with a grid of square holes, random convex Q, nesting pieces from
// ../shared/data. Fixed seeds are chosen by the callers.
#pragma once

#include <pendepth/polygon.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace polygon2_test {

using pendepth::Vec2;
using Rings = std::vector<std::vector<Vec2>>;

inline constexpr double kPi = 3.14159265358979323846;

/// Star-shaped ring around c with n vertices, radii in [rmin, rmax]; coordinates rounded to
/// integers when `grid` (which may make it non-simple: callers validate and retry).
inline std::vector<Vec2> star_ring(std::mt19937_64& rng, int n, Vec2 c, double rmin, double rmax, bool grid) {
  std::uniform_real_distribution<double> ua(0, 2 * kPi), ur(rmin, rmax);
  std::vector<double> ang(n);
  for (auto& a : ang) a = ua(rng);
  std::sort(ang.begin(), ang.end());
  std::vector<Vec2> r;
  for (double a : ang) {
    double rad = ur(rng);
    Vec2 p = c + rad * Vec2(std::cos(a), std::sin(a));
    if (grid) p = Vec2(std::round(p.x()), std::round(p.y()));
    r.push_back(p);
  }
  return r;
}

/// A random valid polygon: star-shaped outer ring (radius ~100) with `holes` star-shaped holes
/// (each inside its own disjoint disk well inside the outer ring's minimum radius).
inline pendepth::Polygon random_polygon(std::mt19937_64& rng, int n, int holes, bool grid) {
  for (;;) {
    Rings rings{star_ring(rng, n, Vec2(0, 0), 60, 100, grid)};
    for (int k = 0; k < holes; ++k) {
      double a = 2 * kPi * k / std::max(holes, 1);
      Vec2 c = holes == 1 ? Vec2(0, 0) : Vec2(35 * std::cos(a), 35 * std::sin(a));
      if (grid) c = Vec2(std::round(c.x()), std::round(c.y()));
      double rmax = holes == 1 ? 30 : std::min(14.0, 35 * std::sin(kPi / holes) - 2);
      rings.push_back(star_ring(rng, 3 + static_cast<int>(rng() % 6), c, rmax / 2, rmax, grid));
      if (rng() % 2) std::reverse(rings.back().begin(), rings.back().end());
    }
    try {
      return pendepth::Polygon(rings, "random");
    } catch (const pendepth::InvalidInput&) {
    }
  }
}

/// Comb: base [0, W] x [0, base], `teeth` teeth of width tw separated by gaps of width gw and
/// height h (pockets open upwards, each exactly gw wide).
inline std::vector<Vec2> comb_ring(int teeth, double tw, double gw, double h, double base) {
  std::vector<Vec2> r;
  double W = teeth * tw + (teeth - 1) * gw;
  r.push_back({0, 0});
  r.push_back({W, 0});
  for (int k = teeth - 1; k >= 0; --k) {
    double x0 = k * (tw + gw), x1 = x0 + tw;
    r.push_back({x1, base + h});
    r.push_back({x0, base + h});
    if (k > 0) {
      r.push_back({x0, base});
      r.push_back({x0 - gw, base});
    }
  }
  // Right edge of the last tooth goes up from (W, 0): vertex (W, base + h) already pushed first.
  return r;
}

/// Random convex polygon (hull of a star ring of m points, radius in [scale/2, scale]).
inline pendepth::ConvexPolygon random_convex(std::mt19937_64& rng, int m, double scale, bool grid) {
  for (;;) {
    auto pts = star_ring(rng, m, Vec2(0, 0), scale / 2, scale, grid);
    try {
      return pendepth::ConvexPolygon::hull(pts, "Q");
    } catch (const pendepth::InvalidInput&) {
    }
  }
}

/// A thick Archimedean spiral: centre line r = a + b·θ for θ in [0, turns·2π], half-width w
/// (w < π·b keeps the arms apart), `steps` samples per side: a long, deep, winding pocket.
inline std::vector<Vec2> spiral_ring(double a, double b, double w, double turns, int steps) {
  std::vector<Vec2> outer, inner;
  for (int k = 0; k <= steps; ++k) {
    const double th = turns * 2 * kPi * k / steps, r = a + b * th;
    const Vec2 u(std::cos(th), std::sin(th));
    outer.push_back((r + w) * u);
    inner.push_back((r - w) * u);
  }
  std::vector<Vec2> ring(inner.begin(), inner.end());
  ring.insert(ring.end(), outer.rbegin(), outer.rend());
  return ring;
}

/// Square [0, k·(h + g) + g]² with a k×k grid of square holes of side h, gaps g, shifted by o.
inline Rings holes_grid(int k, double h, double g, Vec2 o) {
  const double W = k * (h + g) + g;
  Rings r{{o + Vec2(0, 0), o + Vec2(W, 0), o + Vec2(W, W), o + Vec2(0, W)}};
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const Vec2 c = o + Vec2(g + i * (h + g), g + j * (h + g));
      r.push_back({c, c + Vec2(0, h), c + Vec2(h, h), c + Vec2(h, 0)});
    }
  return r;
}

/// Pieces of a nesting instance (items[].shape.data, closing vertex repeated).
inline std::vector<std::vector<Vec2>> nesting_pieces(const std::string& file) {
  std::ifstream in(std::string(PENDEPTH_SHARED_DATA) + "/nesting/" + file);
  nlohmann::json j;
  in >> j;
  std::vector<std::vector<Vec2>> out;
  for (const auto& item : j["items"]) {
    std::vector<Vec2> r;
    for (const auto& p : item["shape"]["data"]) r.push_back({p[0].get<double>(), p[1].get<double>()});
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace polygon2_test
