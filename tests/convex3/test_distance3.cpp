// Engine-level checks of signed_distance and shape_cast (include/pendepth/depth3.hpp) without
// CGAL (the exact CGAL oracle is tests/oracle3/test_distance3.cpp):
//   * a second, independent algorithm: brute force in doubles over every feature pair (P
//     triangle × Q vertex, P vertex × Q triangle, P edge × Q edge, world frame) agrees with the
//     distance of disjoint pairs to 1e-12 relative, and the reported witnesses are that far apart;
//   * swapping the shapes: sd(P, Q) = sd(Q, P) within 4 ulps, witnesses swapped, normal negated;
//     cast(P, Q, d) = cast(Q, P, −d) (same hit, distance within 4 ulps). Rotations with exact
//     matrices (the tetrahedral group), so that both frames pose the same exact problem (with
//     general double rotations R_Pᵀ R_Q and R_Qᵀ R_P round differently: different exact inputs);
//   * integer boxes touching exactly give distance 0 and a cast of 0; boxes a gap g apart give g.
#include <gtest/gtest.h>

#include <pendepth/depth3.hpp>

#include "convex3/shapes3.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>
#include "test_ulps.hpp"
#include "test_rotations.hpp"

namespace pendepth {
namespace {

double ulps(double a, double b) { return pendepth_test::ulps_in_binade(a, b); }

Vec3 closest_on_segment(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 e = b - a;
  const double t = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return a + t * e;
}

// Point–triangle distance (Ericson, Real-Time Collision Detection §5.1.5), doubles.
double point_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const Vec3 q = p - n * (n.dot(p - a) / n.squaredNorm());
  const bool inside = n.dot((b - a).cross(q - a)) >= 0 && n.dot((c - b).cross(q - b)) >= 0 &&
                      n.dot((a - c).cross(q - c)) >= 0;
  if (inside) return (p - q).norm();
  return std::min({(p - closest_on_segment(p, a, b)).norm(), (p - closest_on_segment(p, b, c)).norm(),
                   (p - closest_on_segment(p, c, a)).norm()});
}

// Segment–segment distance (Ericson §5.1.9), doubles.
double segment_segment(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r), c = d1.dot(r), b = d1.dot(d2);
  const double den = a * e - b * b;
  double s = den > 1e-300 ? std::clamp((b * f - c * e) / den, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0) t = 0, s = std::clamp(-c / a, 0.0, 1.0);
  else if (t > 1) t = 1, s = std::clamp((b - c) / a, 0.0, 1.0);
  return ((p1 + s * d1) - (p2 + t * d2)).norm();
}

std::vector<Vec3> posed(const ConvexPolytope& S, const Pose3& pose) {
  std::vector<Vec3> v;
  for (const Vec3& x : S.vertices()) v.push_back(pose.apply(x));
  return v;
}

double brute_distance(const ConvexPolytope& P, const Pose3& pp, const ConvexPolytope& Q, const Pose3& pq) {
  const auto vp = posed(P, pp), vq = posed(Q, pq);
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : P.triangles())
    for (const Vec3& x : vq) best = std::min(best, point_triangle(x, vp[t[0]], vp[t[1]], vp[t[2]]));
  for (const auto& t : Q.triangles())
    for (const Vec3& x : vp) best = std::min(best, point_triangle(x, vq[t[0]], vq[t[1]], vq[t[2]]));
  for (const auto& s : P.triangles())
    for (int i = 0; i < 3; ++i)
      for (const auto& t : Q.triangles())
        for (int j = 0; j < 3; ++j)
          best = std::min(best, segment_segment(vp[s[i]], vp[s[(i + 1) % 3]], vq[t[j]], vq[t[(j + 1) % 3]]));
  return best;
}

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_quaternion(rng); }

TEST(Distance3, BruteForceFeaturePairsAgree) {
  std::mt19937_64 rng(31);
  std::normal_distribution<double> g;
  int apart = 0;
  for (int k = 0; k < 12; ++k) {
    const ConvexPolytope P = ConvexPolytope::hull(test3::random_ball(rng, 6 + 3 * k), "P");
    const ConvexPolytope Q = ConvexPolytope::hull(test3::random_sphere(rng, 5 + 2 * k), "Q");
    for (int j = 0; j < 8; ++j) {
      const Pose3 pp(random_rotation(rng), Vec3(g(rng), g(rng), g(rng)) * 0.2);
      const Pose3 pq(random_rotation(rng), pp.translation + (1.2 + 0.3 * j) * Vec3(g(rng), g(rng), g(rng)).normalized());
      const Distance3 r = signed_distance(P, pp, Q, pq);
      if (r.overlapping || r.distance == 0) continue;
      ++apart;
      const double b = brute_distance(P, pp, Q, pq);
      EXPECT_NEAR(r.distance, b, 1e-12 * (1 + b)) << k << "/" << j;
      EXPECT_NEAR((r.witness_q - r.witness_p).norm(), r.distance, 1e-12 * (1 + b));
    }
  }
  EXPECT_GT(apart, 40);
}

// Rotations whose double matrix is exact: the 12 of the tetrahedral group.
Eigen::Quaterniond exact_rotation(int k) {
  static const double Q[12][4] = {{1, 0, 0, 0},      {0, 1, 0, 0},       {0, 0, 1, 0},      {0, 0, 0, 1},
                                  {.5, .5, .5, .5},  {.5, -.5, -.5, -.5}, {.5, .5, -.5, .5}, {.5, -.5, .5, -.5},
                                  {.5, .5, .5, -.5}, {.5, -.5, -.5, .5}, {.5, -.5, .5, .5}, {.5, .5, -.5, -.5}};
  const double* q = Q[k % 12];
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
}

TEST(Distance3, SwappingTheShapes) {
  std::mt19937_64 rng(32);
  std::normal_distribution<double> g;
  int casts = 0;
  for (int k = 0; k < 10; ++k) {
    const ConvexPolytope P = ConvexPolytope::hull(test3::random_ball(rng, 10 + 4 * k), "P");
    const ConvexPolytope Q = ConvexPolytope::hull(test3::random_ball(rng, 8 + 3 * k), "Q");
    for (int j = 0; j < 10; ++j) {
      const Pose3 pp(exact_rotation(k + j), Vec3(g(rng), g(rng), g(rng)) * 0.3);
      const Pose3 pq(exact_rotation(3 * k + 5 * j + 1), Vec3(g(rng), g(rng), g(rng)) * (0.5 + 0.3 * j));
      const Distance3 a = signed_distance(P, pp, Q, pq), b = signed_distance(Q, pq, P, pp);
      ASSERT_EQ(a.overlapping, b.overlapping);
      EXPECT_LE(ulps(a.distance, b.distance), 4) << a.distance << " vs " << b.distance;
      if (!a.overlapping && a.distance > 0) {
        EXPECT_LE((a.normal + b.normal).norm(), 1e-12);
        EXPECT_LE((a.witness_p - b.witness_q).norm(), 1e-9);
        EXPECT_LE((a.witness_q - b.witness_p).norm(), 1e-9);
      }
      const Vec3 d(g(rng), g(rng), g(rng));
      const Cast3 c = shape_cast(P, pp, Q, pq, d), e = shape_cast(Q, pq, P, pp, -d);
      ASSERT_EQ(c.hit, e.hit);
      if (c.hit) {
        ++casts;
        EXPECT_LE(ulps(c.distance, e.distance), 4) << c.distance << " vs " << e.distance;
      }
    }
  }
  EXPECT_GT(casts, 20);
}

TEST(Distance3, IntegerBoxesTouchOrAreAGapApart) {
  std::vector<Vec3> unit;
  for (int i = 0; i < 8; ++i) unit.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const ConvexPolytope B = ConvexPolytope::hull(unit, "box");
  for (const Vec3& t : {Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(1, 1, 1), Vec3(1, 0.5, 0.25), Vec3(-1, 0.5, 0)}) {
    const Distance3 r = signed_distance(B, Pose3(), B, Pose3(t));
    EXPECT_EQ(r.distance, 0) << t.transpose();
    EXPECT_FALSE(r.overlapping);
    const Cast3 c = shape_cast(B, Pose3(), B, Pose3(t), -t);
    EXPECT_TRUE(c.hit && c.distance == 0 && !c.overlapping) << t.transpose();
  }
  for (double gap : {0.5, 0x1p-30, 3.0}) {
    const Distance3 r = signed_distance(B, Pose3(), B, Pose3(Vec3(1 + gap, 0.25, 0)));
    EXPECT_EQ(r.distance, gap);
    EXPECT_EQ(r.normal, Vec3(1, 0, 0));
    // Face–face: any closest pair is valid; the witnesses lie on the two facing faces and the
    // features (edges or faces of the GJK simplex) contain them.
    EXPECT_EQ(r.witness_p.x(), 1);
    EXPECT_EQ(r.witness_q.x(), 1 + gap);
    EXPECT_NE(r.feature_p.kind, FeatureKind3::None);
    EXPECT_NE(r.feature_q.kind, FeatureKind3::None);
    const Cast3 c = shape_cast(B, Pose3(), B, Pose3(Vec3(1 + gap, 0.25, 0)), Vec3(-3, 0, 0));
    EXPECT_TRUE(c.hit);
    EXPECT_EQ(c.distance, gap);
    EXPECT_EQ(c.normal, Vec3(1, 0, 0));
  }
  // Vertex–vertex: the corner (1, 1, 1) against the corner of a box at (2, 3, 4).
  const Distance3 v = signed_distance(B, Pose3(), B, Pose3(Vec3(2, 3, 4)));
  EXPECT_LE(ulps(v.distance, std::sqrt(1.0 + 4.0 + 9.0)), 2);
  EXPECT_EQ(v.feature_p, (Feature3{FeatureKind3::Vertex, v.feature_p.index}));
  EXPECT_EQ(B[v.feature_p.index], Vec3(1, 1, 1));
  EXPECT_EQ(B[v.feature_q.index], Vec3(0, 0, 0));
}

}  // namespace
}  // namespace pendepth
