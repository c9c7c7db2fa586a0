// Two lower-dimensional convex sets whose dimensions sum to 3 or more (a segment and a polygon,
// two polygons): their signed distance (convex3::flat_flat_distance, src/convex3/flat3.cpp; the
// cores of rounded shapes) against the independent CGAL oracle (oracle3_cgal.hpp: the exact hull
// of every difference a − b', b' = R b + tb − ta exactly; correctly rounded signed distance of 0
// to it), on random poses and on integer grids with exact quarter turns (touching exactly: a
// segment ending on a square, through its edges, squares crossing at their edges). Checked: the
// state (overlapping / touching / apart) exactly, the value within 4 ulps, the witnesses and the
// translation (moving B by it leaves the pair touching). Then Pair3 on rounded shapes with such
// cores — a rounded triangle against a capsule, two rounded squares — against the oracle's core
// distance minus the radii, closed forms, and properties: σ <= σ_d, the σ_d move separates
// (1e-9 less does not), the cast's bracket and move, the cast from the far side equals σ_d.
#include <gtest/gtest.h>

#include <pendepth/pendepth.hpp>

#include "convex3/flat3.hpp"
#include "oracle3/oracle3_cgal.hpp"

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include "test_ulps.hpp"
#include "test_rotations.hpp"

namespace pendepth {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

double ulps(double a, double b) { return pendepth_test::ulps_in_binade(a, b); }

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_quaternion(rng); }

// The core distance of A (pose pa) and B (pose pb) by the CGAL oracle; NaN when the differences
// do not span a solid (the oracle's hull is flat: checked by the closed forms below instead).
double oracle_sd(const std::vector<Vec3>& a, const Pose3& pa, const std::vector<Vec3>& b, const Pose3& pb) {
  const Eigen::Matrix3d Ra = pa.matrix(), Rb = pb.matrix();
  const oracle3::ExactDifference M(a, b, Ra.transpose() * Rb, Ra.transpose() * pb.translation,
                                   Ra.transpose() * pa.translation, true);
  return M.hull().solid() ? M.signed_distance() : std::numeric_limits<double>::quiet_NaN();
}

struct Count {
  int overlapping = 0, touching = 0, apart = 0, flat = 0;
  double worst = 0;
};

void check(const std::vector<Vec3>& a, const Pose3& pa, const std::vector<Vec3>& b, const Pose3& pb, Count& n,
           const std::string& what) {
  const convex3::FlatShape3 A = convex3::flat_shape(a, "A"), B = convex3::flat_shape(b, "B");
  ASSERT_GE(A.dim + B.dim, 3) << what;
  const double o = oracle_sd(a, pa, b, pb);
  const Distance3 r = convex3::flat_flat_distance(A, pa, B, pb);
  ASSERT_TRUE(std::isfinite(r.distance)) << what;
  if (std::isnan(o)) {  // a flat M has no interior
    ++n.flat;
    EXPECT_FALSE(r.overlapping) << what;
    EXPECT_GE(r.distance, 0) << what;
    return;
  }
  const double scale = 2 + pa.translation.norm() + pb.translation.norm();
  ASSERT_EQ(r.overlapping, o < 0) << what << ": " << r.distance << " exact " << o;
  if (o == 0) {
    ++n.touching;
    EXPECT_EQ(r.distance, 0) << what;
    return;
  }
  ASSERT_EQ(r.distance > 0, o > 0) << what << ": " << r.distance << " exact " << o;
  const double e = ulps(r.distance, o);
  n.worst = std::max(n.worst, e);
  EXPECT_LE(e, 4) << what << ": " << r.distance << " exact " << o;
  EXPECT_EQ(r.lower_bound, r.distance) << what;
  EXPECT_EQ(r.upper_bound, r.distance) << what;
  EXPECT_NEAR(r.normal.norm(), 1, 8 * kEps) << what;
  EXPECT_LE((r.translation + r.distance * r.normal).norm(), 8 * kEps * std::abs(r.distance)) << what;
  EXPECT_LE((r.witness_q - r.witness_p - r.distance * r.normal).norm(), 1e-12 * scale) << what;
  // Moving B by the translation leaves the pair touching (a tiny residue of the rounding).
  Pose3 moved = pb;
  moved.translation += r.translation;
  EXPECT_LE(std::abs(convex3::flat_flat_distance(A, pa, B, moved).distance), 1e-12 * scale) << what;
  ++(o < 0 ? n.overlapping : n.apart);
}

std::vector<Vec3> random_polygon(std::mt19937_64& rng, int k) {
  std::uniform_real_distribution<double> A(0, 2 * M_PI), U(-0.5, 0.5);
  std::vector<double> ang(k);
  for (auto& x : ang) x = A(rng);
  std::sort(ang.begin(), ang.end());
  const double z = U(rng);
  std::vector<Vec3> p;
  for (double x : ang) p.emplace_back(0.8 * std::cos(x), 0.5 * std::sin(x), z);
  return p;
}
std::vector<Vec3> random_segment(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(-1, 1);
  return {Vec3(U(rng), U(rng), U(rng)), Vec3(U(rng), U(rng), U(rng))};
}

TEST(FlatFlatOracle, RandomSegmentsAndPolygons) {
  std::mt19937_64 rng(2417);
  std::uniform_real_distribution<double> U(-1, 1);
  Count n;
  for (int trial = 0; trial < 240; ++trial) {
    const int kind = trial % 3;  // segment–polygon, polygon–segment, polygon–polygon
    const std::vector<Vec3> a = kind == 0 ? random_segment(rng) : random_polygon(rng, 3 + trial % 4);
    const std::vector<Vec3> b = kind == 1 ? random_segment(rng) : random_polygon(rng, 3 + trial / 3 % 4);
    const Pose3 pa = trial % 2 ? Pose3(random_rotation(rng), 0.3 * Vec3(U(rng), U(rng), U(rng))) : Pose3();
    const Pose3 pb(random_rotation(rng), (0.1 + 0.4 * (trial % 4)) * Vec3(U(rng), U(rng), U(rng)));
    check(a, pa, b, pb, n, "trial " + std::to_string(trial));
  }
  std::printf("random: %d overlapping, %d touching, %d apart, worst %.2f ulps\n", n.overlapping, n.touching, n.apart,
              n.worst);
  EXPECT_GT(n.overlapping, 15);  // a segment must pierce a polygon, or two polygons cross
  EXPECT_GT(n.apart, 60);
}

// A square in z = 0 and vertical segments / squares on an integer grid, with exact quarter turns
// of B: ends on the square, through its edges and corners, crossing squares — exactly touching.
TEST(FlatFlatOracle, DegenerateGrids) {
  const std::vector<Vec3> square = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)};
  const std::vector<Vec3> stick = {Vec3(0, 0, 0), Vec3(0, 0, 2)};
  const std::vector<Vec3> wall = {Vec3(0, -1, -1), Vec3(0, 1, -1), Vec3(0, 1, 1), Vec3(0, -1, 1)};
  const Eigen::Quaterniond rots[] = {Eigen::Quaterniond(1, 0, 0, 0), Eigen::Quaterniond(0, 1, 0, 0),
                                     Eigen::Quaterniond(0.5, 0.5, 0.5, 0.5)};
  Count n;
  for (const auto* b : {&stick, &wall})
    for (const auto& rot : rots)
      for (double x : {-2.0, -1.0, 0.0, 1.5})
        for (double y : {-1.0, 0.5})
          for (double z : {-3.0, -2.0, -1.0, 0.0, 0.5}) {
            const std::string what = std::string(b == &stick ? "stick" : "wall") + " at " + std::to_string(x) + "," +
                                     std::to_string(y) + "," + std::to_string(z);
            check(square, Pose3(), *b, Pose3(rot, Vec3(x, y, z)), n, what);
            check(*b, Pose3(rot, Vec3(x, y, z)), square, Pose3(), n, what + " (swapped)");
          }
  std::printf("grids: %d overlapping, %d touching, %d apart, %d flat, worst %.2f ulps\n", n.overlapping, n.touching,
              n.apart, n.flat, n.worst);
  EXPECT_GT(n.touching, 40);
  EXPECT_GT(n.overlapping, 20);
  EXPECT_GT(n.apart, 40);
}

// Polygons with exactly parallel edges and chords (a hexagon whose long diagonals are parallel to
// edges, a rectangle): the scans skip those known ties (FlatShape3::chord_dir); random poses.
TEST(FlatFlatOracle, ParallelEdgesAndChords) {
  const std::vector<Vec3> hexagon = {Vec3(0.5, 0, 0),     Vec3(0.25, 0.5, 0),  Vec3(-0.25, 0.5, 0),
                                     Vec3(-0.5, 0, 0),    Vec3(-0.25, -0.5, 0), Vec3(0.25, -0.5, 0)};
  const std::vector<Vec3> rect = {Vec3(-0.75, -0.25, 0.125), Vec3(0.75, -0.25, 0.125), Vec3(0.75, 0.25, 0.125),
                                  Vec3(-0.75, 0.25, 0.125)};
  const convex3::FlatShape3 h = convex3::flat_shape(hexagon, "hexagon");
  ASSERT_EQ(h.edge_dir, (std::vector<int>{0, 1, 2, 0, 1, 2}));
  EXPECT_EQ(h.chord_dir[0 * 6 + 3], 1);   // the long diagonal v0–v3 ∥ edges 1 and 4
  EXPECT_EQ(h.chord_dir[4 * 6 + 1], 2);   // v1–v4 ∥ edges 2 and 5
  EXPECT_EQ(h.chord_dir[1 * 6 + 5], -1);  // v1–v5 is vertical: no edge
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> U(-1, 1);
  Count n;
  for (int trial = 0; trial < 120; ++trial) {
    const std::vector<Vec3>& a = trial % 2 ? hexagon : rect;
    const std::vector<Vec3> b = trial % 3 == 0 ? random_segment(rng) : trial % 3 == 1 ? rect : hexagon;
    const Pose3 pa = trial % 4 ? Pose3() : Pose3(random_rotation(rng), 0.2 * Vec3(U(rng), U(rng), U(rng)));
    const Pose3 pb(random_rotation(rng), (0.1 + 0.3 * (trial % 3)) * Vec3(U(rng), U(rng), U(rng)));
    check(a, pa, b, pb, n, "parallel trial " + std::to_string(trial));
  }
  std::printf("parallel: %d overlapping, %d touching, %d apart, worst %.2f ulps\n", n.overlapping, n.touching, n.apart,
              n.worst);
  EXPECT_GT(n.overlapping, 15);
  EXPECT_GT(n.apart, 30);
}

// Coplanar or parallel lower-dimensional sets: M is flat (no interior), so never overlapping;
// 0 when they meet, else the distance.
TEST(FlatFlat, FlatDifferencesNeverOverlap) {
  const convex3::FlatShape3 sq = convex3::flat_shape(
      std::vector<Vec3>{Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)}, "square");
  const convex3::FlatShape3 tri =
      convex3::flat_shape(std::vector<Vec3>{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, "triangle");
  const convex3::FlatShape3 seg = convex3::flat_shape(std::vector<Vec3>{Vec3(-3, 0, 0), Vec3(3, 0, 0)}, "segment");
  Vec3 n = Vec3::Zero();
  for (const Vec3& t : {Vec3(0, 0, 0), Vec3(0.5, 0.25, 0), Vec3(1, 1, 0)}) {
    const Distance3 r = convex3::flat_flat_distance(sq, Pose3(), tri, Pose3(t), &n);
    EXPECT_FALSE(r.overlapping);
    EXPECT_EQ(r.distance, 0);
    EXPECT_NEAR(std::abs(n.z()), 1, 1e-15);  // the supporting plane is the common one
    EXPECT_EQ(convex3::flat_flat_distance(sq, Pose3(), seg, Pose3(t)).distance, 0);
  }
  EXPECT_EQ(convex3::flat_flat_distance(sq, Pose3(), tri, Pose3(Vec3(3, 0, 0))).distance, 2);
  EXPECT_EQ(convex3::flat_flat_distance(sq, Pose3(), tri, Pose3(Vec3(0, 0, 0.5))).distance, 0.5);
  EXPECT_EQ(convex3::flat_flat_distance(sq, Pose3(), seg, Pose3(Vec3(0, 0, -2))).distance, 2);
  EXPECT_EQ(convex3::flat_flat_distance(seg, Pose3(), sq, Pose3(Vec3(0, 3, 0))).distance, 2);
}

// Rounded shapes with such cores through Pair3.
TEST(FlatFlatRounded, ClosedForms) {
  const std::vector<Vec3> sq = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)};
  const Pair3 pair(Shape3::rounded(Shape3::flat(sq), 0.25), Shape3::capsule(0.5, 1));
  // The capsule's segment through the square at x = 0.5: core σ = 0.5, sd = −0.5 − 0.75.
  const Distance3 in = pair.signed_distance(Pose3(), Pose3(Vec3(0.5, 0, 0)));
  EXPECT_TRUE(in.overlapping);
  EXPECT_EQ(in.distance, -1.25);
  EXPECT_EQ(pair.minimum(Pose3(), Pose3(Vec3(0.5, 0, 0))).depth, 1.25);
  EXPECT_EQ(pair.signed_distance(Pose3(), Pose3(Vec3(3, 0, 0))).distance, 1.25);   // cores 2 apart
  EXPECT_EQ(pair.signed_distance(Pose3(), Pose3(Vec3(1.75, 0, 0))).distance, 0);   // cores 0.75 apart
  EXPECT_TRUE(pair.overlapping(Pose3(), Pose3(Vec3(0, 0, 1.5))));                   // the end 0.5 above
  EXPECT_EQ(pair.signed_distance(Pose3(), Pose3(Vec3(0, 0, 2.75))).distance, 1);    // end 1.75 above
  const Cast3 c = pair.cast(Pose3(), Pose3(Vec3(0, 0, 6)), Vec3(0, 0, -1));         // falls onto the square
  ASSERT_TRUE(c.hit);
  EXPECT_LE(c.lower_bound, 4.25);
  EXPECT_GE(c.upper_bound, 4.25);
  EXPECT_LE(c.upper_bound - c.lower_bound, 8 * kEps * 4.25);
  const Depth3 up = pair.along(Pose3(), Pose3(Vec3(0.5, 0, 0)), Vec3(0, 0, 1));  // out upwards: 1 + 0.75
  EXPECT_LE(up.lower_bound, 1.75);
  EXPECT_GE(up.upper_bound, 1.75);
}

TEST(FlatFlatRounded, AgainstTheOracleAndProperties) {
  std::mt19937_64 rng(91);
  std::uniform_real_distribution<double> U(-1, 1);
  std::normal_distribution<double> g;
  int over = 0, apart = 0, far = 0, hits = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const std::vector<Vec3> a = random_polygon(rng, 3 + trial % 3);
    const std::vector<Vec3> b = trial % 2 ? random_segment(rng) : random_polygon(rng, 4);
    const double ra = 0.05 + 0.2 * (U(rng) + 1), rb = 0.05 + 0.1 * (U(rng) + 1), r = ra + rb;
    const Pair3 pair(Shape3::rounded(Shape3::flat(a), ra), Shape3::rounded(Shape3::flat(b), rb));
    const Pose3 pp = trial % 3 ? Pose3() : Pose3(random_rotation(rng), Vec3(U(rng), U(rng), U(rng)) * 0.2);
    const Pose3 pq(random_rotation(rng), (0.3 + 0.8 * (trial % 3)) * Vec3(U(rng), U(rng), U(rng)));
    const std::string what = "trial " + std::to_string(trial);
    const double o = oracle_sd(a, pp, b, pq) - r;  // two roundings from the exact value
    const Distance3 sd = pair.signed_distance(pp, pq);
    EXPECT_LE(std::abs(sd.distance - o), 8 * kEps * std::max(std::abs(o) + r, 1e-300)) << what;
    if (std::abs(o) < 1e-9) continue;  // the state is exact, the oracle's rounded value is not
    ASSERT_EQ(sd.overlapping, o < 0) << what;
    ASSERT_EQ(pair.overlapping(pp, pq), o < 0) << what;
    const Vec3 d(g(rng), g(rng), g(rng));
    if (o < 0) {
      ++over;
      const Depth3 m = pair.minimum(pp, pq), al = pair.along(pp, pq, d);
      EXPECT_EQ(m.depth, -sd.distance) << what;
      EXPECT_LE(m.depth, al.upper_bound * (1 + 4 * kEps)) << what;
      EXPECT_LE(al.lower_bound, al.upper_bound) << what;
      EXPECT_FALSE(pair.overlapping(pp, Pose3(pq.rotation, pq.translation + al.translation * (1 + 1e-9)))) << what;
      EXPECT_TRUE(pair.overlapping(pp, Pose3(pq.rotation, pq.translation + al.translation * (1 - 1e-9)))) << what;
      // The cast from the far side equals σ_d.
      const double L = al.depth + 4;
      const Cast3 c = pair.cast(pp, Pose3(pq.rotation, pq.translation + L * d.normalized()), -d);
      ASSERT_TRUE(c.hit) << what;
      EXPECT_NEAR(c.distance, L - al.depth, 1e-12 * L) << what;
      ++far;
    } else {
      ++apart;
      const Cast3 c = pair.cast(pp, pq, -sd.normal + 0.3 * d);
      if (!c.hit) continue;
      ++hits;
      EXPECT_LE(c.lower_bound, c.upper_bound) << what;
      EXPECT_EQ(c.upper_bound, c.distance) << what;
      EXPECT_GE(c.distance, sd.distance * (1 - 1e-14)) << what;
      EXPECT_LE(std::abs(pair.signed_distance(pp, Pose3(pq.rotation, pq.translation + c.translation)).distance),
                1e-12 * (1 + c.distance))
          << what;
      EXPECT_GT(pair.signed_distance(pp, Pose3(pq.rotation, pq.translation + 0.5 * c.translation)).distance, 0) << what;
    }
  }
  EXPECT_GT(over, 20);
  EXPECT_GT(apart, 20);
  EXPECT_GT(far, 20);
  EXPECT_GT(hits, 10);
}

}  // namespace
}  // namespace pendepth
