// Test shapes shared by the no-fit polygon tests (test_nfp.cpp, test_nfp_export.cpp): random
// stars, translated copies and the nesting instances as polygons.
#pragma once

#include <pendepth/polygon.hpp>

#include <algorithm>
#include <pendepth/geometry.hpp>
#include <random>
#include <string>
#include <vector>

#include "polygon2/shapes.hpp"

namespace nonconvex2_test {

/// A random simple star polygon (retried until valid).
inline pendepth::Polygon star(std::mt19937_64& rng, int n, double rmin, double rmax, bool grid) {
  for (;;) {
    try {
      return pendepth::Polygon::simple(polygon2_test::star_ring(rng, n, pendepth::Vec2(0, 0), rmin, rmax, grid), "star");
    } catch (const pendepth::InvalidInput&) {
    }
  }
}

/// S with every vertex mapped by f (rings kept).
template <class F>
pendepth::Polygon mapped(const pendepth::Polygon& S, F&& f) {
  std::vector<std::vector<pendepth::Vec2>> rings;
  for (std::size_t k = 0; k < S.ring_count(); ++k) {
    rings.emplace_back();
    for (const pendepth::Vec2& p : S.ring(k)) rings.back().push_back(f(p));
  }
  return pendepth::Polygon(rings, S.name());
}

/// S translated by o.
inline pendepth::Polygon shifted(const pendepth::Polygon& S, const pendepth::Vec2& o) {
  return mapped(S, [&](const pendepth::Vec2& p) { return pendepth::Vec2(p + o); });
}

/// Convex hull of random integer points (exact: orient2d), counter-clockwise.
inline pendepth::Polygon convex_hull(std::mt19937_64& rng, int n, int span) {
  for (;;) {
    std::vector<pendepth::Vec2> pts;
    for (int k = 0; k < n; ++k) pts.emplace_back(double(int(rng() % span)), double(int(rng() % span)));
    std::sort(pts.begin(), pts.end(), [](const pendepth::Vec2& a, const pendepth::Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    std::vector<pendepth::Vec2> h;
    for (int pass = 0; pass < 2; ++pass) {
      const std::size_t base = h.size();
      for (const pendepth::Vec2& p : pts) {
        while (h.size() >= base + 2 && pendepth::predicates::orient2d(h[h.size() - 2], h.back(), p) <= 0) h.pop_back();
        h.push_back(p);
      }
      h.pop_back();
      std::reverse(pts.begin(), pts.end());
    }
    if (h.size() >= 3) return pendepth::Polygon::simple(h, "hull");
  }
}

/// Every edge split at its midpoint (exact for grid coordinates): straight vertices everywhere,
/// where the candidate rule admits edges whose angle may lie on either side.
inline pendepth::Polygon subdivided(const pendepth::Polygon& S) {
  std::vector<std::vector<pendepth::Vec2>> rings;
  for (std::size_t k = 0; k < S.ring_count(); ++k) {
    rings.emplace_back();
    const auto r = S.ring(k);
    for (std::size_t i = 0; i < r.size(); ++i) {
      rings.back().push_back(r[i]);
      rings.back().push_back(0.5 * (r[i] + r[(i + 1) % r.size()]));
    }
  }
  return pendepth::Polygon(rings, S.name());
}

/// The pieces of a nesting instance (../shared/data/nesting) as polygons.
inline std::vector<pendepth::Polygon> instance(const std::string& file) {
  const auto pieces = polygon2_test::nesting_pieces(file);
  std::vector<pendepth::Polygon> polys;
  for (std::size_t k = 0; k < pieces.size(); ++k) polys.push_back(pendepth::Polygon::simple(pieces[k], file + " " + std::to_string(k)));
  return polys;
}

// A random rectilinear histogram: columns [i, i + 1] × [0, h_i], h_i in [1, hmax]; equal
// neighbouring heights leave a straight vertex on the top (kept): many antiparallel edge pairs
// between two such shapes, chains of collinear edges, exact fits of columns into gaps.
inline pendepth::Polygon histogram(std::mt19937_64& rng, int k, int hmax) {
  std::vector<double> h(k);
  for (auto& x : h) x = 1 + double(rng() % hmax);
  std::vector<pendepth::Vec2> r{{0, 0}, {double(k), 0}};
  for (int i = k - 1; i >= 0; --i) {
    r.emplace_back(i + 1, h[i]);
    if (i == 0 || h[i - 1] != h[i]) r.emplace_back(i, h[i]);
  }
  return pendepth::Polygon::simple(r, "histogram");
}

}  // namespace nonconvex2_test
