// The shape cast's certified fast path (src/convex3/signed_distance3.cpp, shape_cast_certified:
// GJK ray cast in doubles, its entry triangle or miss certified exactly) on disjoint game-hull
// pairs, the benchmark's placements (docs/benchmarks.md, issue 16): it answers (almost) every
// query itself — the Compute-Depth-3D fallback stays rare — and each answer agrees with the
// fallback's own (the reversed line's DK descent, line_exit_dk, as in src/convex3/cast3.cpp):
// the same hit or miss, the same time of impact within 4 ulps, normals within 1e-12.
#include <gtest/gtest.h>

#include <pendepth/depth3.hpp>
#include <pendepth/io.hpp>

#include "convex3/minimum_expand.hpp"
#include "convex3/shapes3.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>
#include "test_ulps.hpp"
#include "test_rotations.hpp"

namespace pendepth {
namespace {

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_unit_quaternion(rng); }
Vec3 random_in_ball(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(-1, 1);
  for (;;)
    if (Vec3 v(U(rng), U(rng), U(rng)); v.norm() <= 1) return v;
}
double ulps(double a, double b) { return pendepth_test::ulps_in_binade(a, b); }

TEST(CastFast, SharedHullsFastPathAgreesWithDescent) {
  const std::vector<ConvexPolytope> H = test3::shared_hulls();
  ASSERT_GE(H.size(), 8u);
  auto centroid = [](const ConvexPolytope& S) {
    Vec3 x = Vec3::Zero();
    for (const Vec3& v : S.vertices()) x += v / double(S.size());
    return x;
  };
  auto radius = [&](const ConvexPolytope& S) {
    double r = 0;
    for (const Vec3& v : S.vertices()) r = std::max(r, (v - centroid(S)).norm());
    return r;
  };
  std::mt19937_64 rng(0xca57);
  std::uniform_real_distribution<double> U(0.6, 1.6);
  int queries = 0, fast = 0, hits = 0, compared = 0;
  double worst_ulps = 0;
  for (int a = 0; queries < 600 && a < 100000; ++a) {
    const ConvexPolytope &P = H[a % H.size()], &Q = H[(a + 7) % H.size()];
    const Eigen::Quaterniond rot = random_rotation(rng);
    const Vec3 dir = random_in_ball(rng);
    if (dir.norm() < 1e-3) continue;
    const Pose3 pose(rot, centroid(P) - rot.toRotationMatrix() * centroid(Q) +
                              (radius(P) + radius(Q)) * U(rng) * dir.normalized());
    if (!(signed_distance(P, Pose3(), Q, pose).distance > 0)) continue;
    const Vec3 d = (centroid(P) - pose.translation).normalized() + 0.5 * random_in_ball(rng);
    if (d.norm() < 1e-3) continue;
    ++queries;
    convex3::RelativePose rel;
    rel.R = pose.matrix(), rel.tq = pose.translation, rel.tp = Vec3::Zero();
    const auto f = convex3::shape_cast_certified(P, Q, rel, d, Eigen::Matrix3d::Identity(), Vec3::Zero());
    const Cast3 full = shape_cast(P, Pose3(), Q, pose, d);
    if (!f) continue;
    ++fast;
    hits += f->hit;
    // The fallback's answer for apart shapes: the entry of the line by the reversed descent.
    const convex3::LineExit in = convex3::line_exit_dk(P, Q, rel, -d);
    if (!in.hit) continue;  // a graze: decided by cast_graze, not compared here
    ++compared;
    const bool hit = in.h_sign < 0;
    ASSERT_EQ(f->hit, hit) << "query " << queries;
    EXPECT_EQ(full.hit, hit);
    if (!hit) continue;
    const double s = -in.exit;
    worst_ulps = std::max(worst_ulps, ulps(f->distance, s));
    EXPECT_LE(ulps(f->distance, s), 4) << "query " << queries << ": " << f->distance << " vs " << s;
    EXPECT_LE((f->normal - in.unit).norm(), 1e-12) << "query " << queries;
  }
  EXPECT_EQ(queries, 600);
  EXPECT_GE(fast, queries * 98 / 100) << fast << " of " << queries;
  EXPECT_GT(hits, queries / 3);
  std::printf("cast: %d queries, fast path %d (%d hits), %d compared with the descent, worst %.1f ulps\n", queries,
              fast, hits, compared, worst_ulps);
}

}  // namespace
}  // namespace pendepth
