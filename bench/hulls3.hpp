// Shared by the 3D programs on the real game hulls (bench_convex3.cpp and the output identity
// dumps sigma_identity.cpp, distance_identity.cpp, which replay its draws): the hulls, the draws
// of random poses, a hull's centroid and radius. One definition, so the identity dumps' inputs
// stay the benchmark's bit for bit.
#pragma once

#include <pendepth/polytope.hpp>

#include "convex3/shapes3.hpp"  // tests/: the shared hull files

#include <algorithm>
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

}  // namespace pendepth::bench
