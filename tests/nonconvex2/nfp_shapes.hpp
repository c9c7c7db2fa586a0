// Test shapes shared by the no-fit polygon tests (test_nfp.cpp, test_nfp_export.cpp): random
// stars, translated copies and the nesting instances as polygons.
#pragma once

#include <pendepth/polygon.hpp>

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

/// The pieces of a nesting instance (../shared/data/nesting) as polygons.
inline std::vector<pendepth::Polygon> instance(const std::string& file) {
  const auto pieces = polygon2_test::nesting_pieces(file);
  std::vector<pendepth::Polygon> polys;
  for (std::size_t k = 0; k < pieces.size(); ++k) polys.push_back(pendepth::Polygon::simple(pieces[k], file + " " + std::to_string(k)));
  return polys;
}

}  // namespace nonconvex2_test
