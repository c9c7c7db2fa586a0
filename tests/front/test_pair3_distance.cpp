// Front door, 3D signed distance and shape cast (Pair3::signed_distance / cast): the engines'
// values bit for bit; batches equal single calls bit for bit at any thread count; huge and tiny
// scales give the unit-size bits; bad input named. Properties (exact oracles are in
// tests/oracle3/test_distance3.cpp):
//   * sd < 0 ⇔ overlapping(), and then sd = −σ bit for bit;
//   * moving Q by `translation` brings it into contact (|sd| tiny after the move);
//   * continuity through contact: sd at the cast's contact is ≈ 0, and sd >= 0 before it;
//   * the cast never beats the straight-line distance (s >= sd), and moving away along the
//     distance normal never hits;
//   * the cast from the far side equals σ_d: for an overlapping placement t, the ray from
//     t + L·d̂ along −d enters M at L − σ_d(t).
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "convex3/shapes3.hpp"
#include "front/common.hpp"
#include "test_rotations.hpp"

namespace {

using namespace pendepth;
using front_test::error_of;
using front_test::same_bits;
using front_test::same_bits_v;

::testing::AssertionResult same(const Distance3& a, const Distance3& b) {
  if (same_bits(a.distance, b.distance) && same_bits_v(a.translation, b.translation) &&
      same_bits_v(a.normal, b.normal) && same_bits_v(a.witness_p, b.witness_p) &&
      same_bits_v(a.witness_q, b.witness_q) && a.feature_p == b.feature_p && a.feature_q == b.feature_q &&
      same_bits(a.lower_bound, b.lower_bound) && same_bits(a.upper_bound, b.upper_bound) &&
      a.overlapping == b.overlapping)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "distance " << a.distance << " vs " << b.distance;
}

::testing::AssertionResult same(const Cast3& a, const Cast3& b) {
  if (same_bits(a.distance, b.distance) && same_bits_v(a.translation, b.translation) &&
      same_bits_v(a.normal, b.normal) && same_bits_v(a.witness_p, b.witness_p) &&
      same_bits_v(a.witness_q, b.witness_q) && a.feature_p == b.feature_p && a.feature_q == b.feature_q &&
      a.hit == b.hit && a.overlapping == b.overlapping && same_bits(a.lower_bound, b.lower_bound) &&
      same_bits(a.upper_bound, b.upper_bound))
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "cast " << a.distance << " vs " << b.distance;
}

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_quaternion(rng); }

std::vector<Pose3> random_poses(std::mt19937_64& rng, std::size_t n, double spread) {
  std::uniform_real_distribution<double> u(-spread, spread);
  std::vector<Pose3> poses;
  for (std::size_t k = 0; k < n; ++k) {
    Pose3 p(Vec3(u(rng), u(rng), u(rng)));
    if (k % 3 != 0) p.rotation = random_rotation(rng);
    poses.push_back(p);
  }
  return poses;
}

std::vector<Shape3> test_shapes() {
  std::mt19937_64 rng(11);
  std::vector<Shape3> s;
  s.push_back(Shape3::hull(test3::random_sphere(rng, 40, 1.0), "sphere40"));
  s.push_back(Shape3::hull(test3::integer_sphere(25), "isphere25"));
  s.push_back(Shape3::hull(test3::prism(25, 2), "prism25"));
  const auto files = test3::shared_hull_files();
  for (std::size_t k = 0; k < files.size() && k < 4; ++k) s.push_back(Shape3::from_file(files[k], files[k]));
  return s;
}

double extent(const Shape3& s) {
  double m = 0;
  for (const Vec3& v : s.polytope().vertices()) m = std::max(m, v.norm());
  return m;
}

TEST(Pair3Distance, GivesTheEnginesValues) {
  const auto shapes = test_shapes();
  std::mt19937_64 rng(21);
  std::normal_distribution<double> g;
  for (std::size_t a = 0; a < shapes.size(); ++a)
    for (std::size_t b = 1; b < shapes.size(); b += 2) {
      const Pair3 pair(shapes[a], shapes[b]);
      const double spread = 1.5 * (extent(shapes[a]) + extent(shapes[b]));
      const auto pq = random_poses(rng, 6, spread);
      const auto pp = random_poses(rng, 6, 0.2);
      for (std::size_t i = 0; i < pq.size(); ++i) {
        const Vec3 d(g(rng), g(rng), g(rng));
        ASSERT_TRUE(same(pair.signed_distance(pp[i], pq[i]),
                         signed_distance(shapes[a].polytope(), pp[i], shapes[b].polytope(), pq[i])));
        ASSERT_TRUE(same(pair.cast(pp[i], pq[i], d), shape_cast(shapes[a].polytope(), pp[i], shapes[b].polytope(), pq[i], d)));
      }
    }
}

TEST(Pair3Distance, BatchesEqualSingleCallsBitForBitAtAnyThreadCount) {
  const auto shapes = test_shapes();
  std::mt19937_64 rng(22);
  const Pair3 pair(shapes[0], shapes[4]);
  const auto poses = random_poses(rng, 120, 3.0);
  const Pose3 pose_p(random_rotation(rng), Vec3(0.1, -0.2, 0.05));
  for (unsigned threads : {1u, 2u, 8u, 0u}) {
    std::vector<Distance3> s(poses.size()), sp(poses.size());
    pair.signed_distance(poses, s, threads);
    pair.signed_distance(pose_p, poses, sp, threads);
    for (std::size_t i = 0; i < poses.size(); ++i) {
      ASSERT_TRUE(same(s[i], pair.signed_distance(Pose3(), poses[i]))) << "threads " << threads << " query " << i;
      ASSERT_TRUE(same(sp[i], pair.signed_distance(pose_p, poses[i]))) << "threads " << threads << " query " << i;
    }
  }
}

TEST(Pair3Distance, Properties) {
  const auto shapes = test_shapes();
  std::mt19937_64 rng(23);
  std::normal_distribution<double> g;
  int apart = 0, over = 0, hits = 0, far = 0;
  for (std::size_t a = 0; a < shapes.size(); ++a)
    for (std::size_t b = 0; b < shapes.size(); ++b) {
      const Pair3 pair(shapes[a], shapes[b]);
      const double sc = extent(shapes[a]) + extent(shapes[b]);
      for (const Pose3& pq : random_poses(rng, 8, 1.2 * sc)) {
        const Distance3 r = pair.signed_distance(Pose3(), pq);
        const Depth3 m = pair.minimum(Pose3(), pq);
        ASSERT_EQ(r.distance < 0, pair.overlapping(Pose3(), pq));
        ASSERT_EQ(r.overlapping, m.overlapping);
        if (r.overlapping) {
          ++over;
          ASSERT_TRUE(same_bits(r.distance, -m.depth));
        } else {
          ++apart;
        }
        // The translation brings Q into contact.
        Pose3 moved = pq;
        moved.translation += r.translation;
        EXPECT_LE(std::abs(pair.signed_distance(Pose3(), moved).distance), 1e-13 * sc) << a << "/" << b;
        if (r.distance > 0) {
          // Moving away along the normal never touches (+inf, and so are the exact engine's bounds).
          const Cast3 away = pair.cast(Pose3(), pq, r.normal);
          EXPECT_FALSE(away.hit);
          EXPECT_EQ(away.lower_bound, away.distance);
          EXPECT_EQ(away.upper_bound, away.distance);
          // Towards P: a hit no nearer than the distance; sd ≈ 0 at the contact, > 0 halfway.
          const Vec3 d = -r.normal + 0.3 * Vec3(g(rng), g(rng), g(rng));
          const Cast3 c = pair.cast(Pose3(), pq, d);
          if (c.hit) {
            ++hits;
            EXPECT_EQ(c.lower_bound, c.distance);  // an exact engine: the bracket is the answer
            EXPECT_EQ(c.upper_bound, c.distance);
            EXPECT_GE(c.distance, r.distance * (1 - 1e-14));
            Pose3 at = pq, half = pq;
            at.translation += c.translation;
            half.translation += 0.5 * c.translation;
            EXPECT_LE(std::abs(pair.signed_distance(Pose3(), at).distance), 1e-13 * sc);
            EXPECT_GT(pair.signed_distance(Pose3(), half).distance, 0);
          }
        } else if (r.overlapping) {
          const Vec3 d(g(rng), g(rng), g(rng));
          const Cast3 c0 = pair.cast(Pose3(), pq, d);
          EXPECT_TRUE(c0.hit && c0.overlapping && c0.distance == 0);
          // The cast from the far side equals σ_d.
          const double sd = pair.along(Pose3(), pq, d).depth, L = sd + sc;
          Pose3 farp = pq;
          farp.translation += L * d.normalized();
          const Cast3 c = pair.cast(Pose3(), farp, -d);
          ASSERT_TRUE(c.hit);
          EXPECT_NEAR(c.distance, L - sd, 1e-13 * L);
          ++far;
        }
      }
    }
  EXPECT_GT(apart, 50);
  EXPECT_GT(over, 20);
  EXPECT_GT(hits, 20);
  EXPECT_GT(far, 20);
}

Shape3 hull_scaled(const std::vector<Vec3>& pts, double s) {
  std::vector<Vec3> v = pts;
  for (Vec3& x : v) x *= s;
  return Shape3::hull(v);
}

std::vector<Vec3> box(double a, double b, double c) {
  std::vector<Vec3> v;
  for (double x : {-a, a})
    for (double y : {-b, b})
      for (double z : {-c, c}) v.emplace_back(x, y, z);
  return v;
}

// Every length of the answer times 2^k, every unit vector and feature the same.
template <class R>
bool scaled_same(const R& a, const R& b, int k) {
  auto s = [k](double x) { return std::ldexp(x, k); };
  auto sv = [&](const Vec3& v) { return Vec3(s(v.x()), s(v.y()), s(v.z())); };
  bool ok = same_bits(s(a.distance), b.distance) && same_bits_v(sv(a.translation), b.translation) &&
            same_bits_v(a.normal, b.normal) && same_bits_v(sv(a.witness_p), b.witness_p) &&
            same_bits_v(sv(a.witness_q), b.witness_q) && a.feature_p == b.feature_p && a.feature_q == b.feature_q &&
            a.overlapping == b.overlapping;
  if constexpr (requires { a.lower_bound; })
    ok = ok && same_bits(s(a.lower_bound), b.lower_bound) && same_bits(s(a.upper_bound), b.upper_bound);
  return ok;
}

TEST(Pair3Distance, EveryScaleGivesTheUnitSizeBits) {
  std::mt19937_64 rng(24);
  const std::vector<std::pair<std::vector<Vec3>, std::vector<Vec3>>> pairs{
      {box(1, 1, 1), box(2, 1, 0.5)}, {test3::integer_sphere(27), test3::bipyramid(25)},
      {test3::random_ball(rng, 30), test3::prism(25)}};
  std::uniform_int_distribution<int> u(-64, 64);
  std::normal_distribution<double> g;
  for (const auto& [p, q] : pairs) {
    const Pair3 unit(Shape3::hull(p), Shape3::hull(q));
    for (int k : {-900, -400, -150, 120, 400, 1000}) {
      const double s = std::ldexp(1.0, k);
      const Pair3 big(hull_scaled(p, s), hull_scaled(q, s));
      for (int i = 0; i < 12; ++i) {
        const Vec3 t(u(rng) / 4.0, u(rng) / 4.0, u(rng) / 4.0), d(u(rng) + 0.5, u(rng), u(rng));
        Pose3 pose(t);
        if (i % 2) pose.rotation = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng));
        const Pose3 pose_big(pose.rotation, t * s);
        ASSERT_TRUE(scaled_same(unit.signed_distance(Pose3(), pose), big.signed_distance(Pose3(), pose_big), k))
            << "2^" << k;
        ASSERT_TRUE(scaled_same(unit.cast(Pose3(), pose, d), big.cast(Pose3(), pose_big, d), k)) << "2^" << k;
      }
    }
  }
}

TEST(Pair3Distance, BadInputIsNamed) {
  const auto shapes = test_shapes();
  const Pair3 pair(shapes[0], shapes[1]);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error_of([&] { pair.signed_distance(Pose3(), Pose3(Vec3(nan, 0, 0))); }).find("pose of Q translation"),
            std::string::npos);
  EXPECT_NE(error_of([&] { pair.cast(Pose3(), Pose3(), Vec3::Zero()); }).find("direction is zero"), std::string::npos);
  EXPECT_NE(error_of([&] { pair.cast(Pose3(), Pose3(), Vec3(nan, 1, 0)); }).find("direction"), std::string::npos);
  EXPECT_NE(error_of([&] { pair.cast(Pose3(Eigen::Quaterniond(0, 0, 0, 0), Vec3::Zero()), Pose3(), Vec3(1, 0, 0)); })
                .find("pose of P rotation is the zero quaternion"),
            std::string::npos);
  std::vector<Pose3> poses(3);
  poses[1].translation.x() = nan;
  std::vector<Distance3> out(3), short_out(2);
  EXPECT_NE(error_of([&] { pair.signed_distance(poses, out); }).find("pose 1"), std::string::npos);
  poses[1] = Pose3();
  EXPECT_NE(error_of([&] { pair.signed_distance(poses, short_out); }).find("room for 2"), std::string::npos);
}

}  // namespace
