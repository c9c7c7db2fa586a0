// Shared by the 3D programs on the real game hulls (bench_convex3.cpp and the output identity
// dumps sigma_identity.cpp, distance_identity.cpp, which replay its draws): the hulls, the draws
// of random poses, a hull's centroid and radius, and the integer test solids (boxes, prisms,
// bipyramids) of the identity dumps. One definition, so the identity dumps' inputs
// stay the benchmark's bit for bit.
#pragma once

#include <pendepth/polytope.hpp>

#include "convex3/shapes3.hpp"  // tests/: the shared hull files

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace pendepth::bench {

/// The hulls of the shared hull files (tests/convex3/shapes3.hpp: every .obj of
/// PENDEPTH_SHARED_DATA/hulls in file-name order, each named by its file).
using test3::shared_hulls;

/// A uniformly random rotation: a normalised quaternion of four standard normal draws.
inline Eigen::Quaterniond random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  return q.normalized();
}

/// A uniformly random point of the ball of radius r about the origin (rejection from the cube).
inline Vec3 random_in_ball(std::mt19937_64& rng, double r) {
  std::uniform_real_distribution<double> U(-1, 1);
  for (;;) {
    Vec3 v(U(rng), U(rng), U(rng));
    if (v.squaredNorm() <= 1) return r * v;
  }
}

/// The mean of the vertices.
inline Vec3 centroid(const ConvexPolytope& S) {
  Vec3 x = Vec3::Zero();
  for (const Vec3& v : S.vertices()) x += v / double(S.size());
  return x;
}

/// The largest distance of a vertex from the centroid.
inline double radius(const ConvexPolytope& S) {
  double r = 0;
  const Vec3 cs = centroid(S);
  for (const Vec3& v : S.vertices()) r = std::max(r, (v - cs).norm());
  return r;
}

/// The box [−x, x] × [−y, y] × [−z, z].
inline ConvexPolytope box(double x, double y, double z) {
  std::vector<Vec3> v;
  for (int s = 0; s < 8; ++s) v.emplace_back(s & 1 ? x : -x, s & 2 ? y : -y, s & 4 ? z : -z);
  return ConvexPolytope::hull(v);
}

/// A prism over a regular n-gon of radius r with vertices rounded to integers, z ∈ [−h, h].
inline ConvexPolytope prism(int n, double r, double h) {
  std::vector<Vec3> v;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * k / n;
    v.emplace_back(std::round(r * std::cos(t)), std::round(r * std::sin(t)), -h);
    v.emplace_back(std::round(r * std::cos(t)), std::round(r * std::sin(t)), h);
  }
  return ConvexPolytope::hull(v);
}

/// A bipyramid over the same rounded n-gon, apexes at z = ±h.
inline ConvexPolytope bipyramid(int n, double r, double h) {
  std::vector<Vec3> v = {Vec3(0, 0, -h), Vec3(0, 0, h)};
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * k / n;
    v.emplace_back(std::round(r * std::cos(t)), std::round(r * std::sin(t)), 0);
  }
  return ConvexPolytope::hull(v);
}

}  // namespace pendepth::bench
