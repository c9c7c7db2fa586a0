// Independent exact oracle for the signed distance and the shape cast of two polygons
// (src/nonconvex2/boundary_distance.hpp), with CGAL's exact kernel (Epeck), by brute force:
//   * the distance of the boundaries of P and Q + t: the minimum of CGAL::squared_distance over
//     every pair of boundary segments (P's segments against Q's translated exactly by t);
//   * the cast: the first contact along the ray, the minimum over every vertex of Q + t moving
//     along d against every edge of P and every vertex of P moving along −d against every edge of
//     Q + t, each hit found by CGAL::intersection(Ray_2, Segment_2).
// Both are exact rationals, converted once at the end.
#pragma once

#include <pendepth/polygon.hpp>

namespace nonconvex2_test {

struct ExactDistance {
  double distance = 0;  ///< sqrt of the exact squared distance rounded to nearest (0 iff they touch)
  bool touching = false;
};
ExactDistance exact_boundary_distance(const pendepth::Polygon& P, const pendepth::Polygon& Q, const pendepth::Vec2& t);

/// The smallest s >= 0 (a length, |d| = 1 units) with the boundaries of P and Q + t + s·d̂
/// meeting, from the exact ray parameter rounded once and multiplied by |d| (rounded); +inf when
/// none. `hit` false when none.
struct ExactCast {
  double distance = 0;
  bool hit = false;
};
ExactCast exact_cast(const pendepth::Polygon& P, const pendepth::Polygon& Q, const pendepth::Vec2& t,
                     const pendepth::Vec2& d);

}  // namespace nonconvex2_test
