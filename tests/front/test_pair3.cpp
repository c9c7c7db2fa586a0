// Front door, 3D (include/pendepth/pendepth.hpp): Pair3 gives minimum_depth / directional_depth
// bit for bit; batches equal single calls bit for bit at 1, 2 and 8 threads; σ ≤ σ_d; the
// overlap decision agrees with the depth; bad poses and directions are named.
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
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
using front_test::same;
using front_test::same_bits;
bool same_bits(const Vec3& a, const Vec3& b) { return front_test::same_bits_v(a, b); }

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

std::vector<Vec3> random_directions(std::mt19937_64& rng, std::size_t n) {
  std::normal_distribution<double> g;
  std::vector<Vec3> ds;
  while (ds.size() < n) {
    Vec3 d(g(rng), g(rng), g(rng));
    if (ds.size() % 5 == 0) d = Vec3(0, 0, 1);
    ds.push_back(d);
  }
  return ds;
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

TEST(Pair3, GivesTheEnginesValues) {
  const auto shapes = test_shapes();
  std::mt19937_64 rng(12);
  for (std::size_t a = 0; a < shapes.size(); ++a)
    for (std::size_t b = 0; b < shapes.size(); b += 2) {
      const Pair3 pair(shapes[a], shapes[b]);
      const double spread = 0.6 * std::sqrt(double(shapes[a].polytope().vertices()[0].squaredNorm())) + 0.5;
      const auto pq = random_poses(rng, 6, spread);
      const auto pp = random_poses(rng, 6, 0.2);
      const auto ds = random_directions(rng, 6);
      for (std::size_t i = 0; i < pq.size(); ++i) {
        const Depth3 m = pair.minimum(pp[i], pq[i]);
        ASSERT_TRUE(same(m, minimum_depth(shapes[a].polytope(), pp[i], shapes[b].polytope(), pq[i])));
        const Depth3 d = pair.along(pp[i], pq[i], ds[i]);
        ASSERT_TRUE(same(d, directional_depth(shapes[a].polytope(), pp[i], shapes[b].polytope(), pq[i], ds[i])));
        ASSERT_EQ(pair.overlapping(pp[i], pq[i]), m.overlapping);
        ASSERT_EQ(d.overlapping, m.overlapping);
        ASSERT_LE(m.depth, d.depth * (1 + 1e-12) + 1e-300);  // σ ≤ σ_d
        const Depth3 s = pair.separation(pp[i], pq[i], ds[i]);
        ASSERT_EQ(s.kind, DepthKind::Separation);
        ASSERT_TRUE(same_bits(s.depth, d.depth));
      }
    }
}

TEST(Pair3, BatchesEqualSingleCallsBitForBitAtAnyThreadCount) {
  const auto shapes = test_shapes();
  std::mt19937_64 rng(13);
  const Pair3 pair(shapes[0], shapes[4]);
  const auto poses = random_poses(rng, 120, 1.2);
  const auto ds = random_directions(rng, poses.size());
  const Pose3 pose_p(random_rotation(rng), Vec3(0.1, -0.2, 0.05));
  for (unsigned threads : {1u, 2u, 8u, 0u}) {
    std::vector<Depth3> m(poses.size()), a(poses.size()), mp(poses.size()), ap(poses.size()), a1(poses.size());
    std::unique_ptr<bool[]> o(new bool[poses.size()]);
    pair.minimum(poses, m, threads);
    pair.along(poses, ds, a, threads);
    pair.along(poses, std::span<const Vec3>(ds.data(), 1), a1, threads);
    pair.minimum(pose_p, poses, mp, threads);
    pair.along(pose_p, poses, ds, ap, threads);
    pair.overlapping(poses, std::span<bool>(o.get(), poses.size()), threads);
    for (std::size_t i = 0; i < poses.size(); ++i) {
      ASSERT_TRUE(same(m[i], pair.minimum(Pose3(), poses[i]))) << "threads " << threads << " query " << i;
      ASSERT_TRUE(same(a[i], pair.along(Pose3(), poses[i], ds[i]))) << "threads " << threads;
      ASSERT_TRUE(same(a1[i], pair.along(Pose3(), poses[i], ds[0]))) << "threads " << threads;
      ASSERT_TRUE(same(mp[i], pair.minimum(pose_p, poses[i]))) << "threads " << threads;
      ASSERT_TRUE(same(ap[i], pair.along(pose_p, poses[i], ds[i]))) << "threads " << threads;
      ASSERT_EQ(o[i], m[i].overlapping);
    }
  }
}

TEST(Pair3, BadInputIsNamed) {
  const auto shapes = test_shapes();
  const Pair3 pair(shapes[0], shapes[1]);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error_of([&] { pair.minimum(Pose3(), Pose3(Vec3(nan, 0, 0))); }).find("pose of Q translation"),
            std::string::npos);
  EXPECT_NE(error_of([&] { pair.minimum(Pose3(Eigen::Quaterniond(0, 0, 0, 0), Vec3::Zero()), Pose3()); })
                .find("pose of P rotation is the zero quaternion"),
            std::string::npos);
  EXPECT_NE(error_of([&] { pair.along(Pose3(), Pose3(), Vec3::Zero()); }).find("direction is zero"), std::string::npos);
  std::vector<Pose3> poses(3);
  poses[1].translation.x() = nan;
  std::vector<Depth3> out(3);
  EXPECT_NE(error_of([&] { pair.minimum(poses, out); }).find("pose 1"), std::string::npos);
  poses[1] = Pose3();
  std::vector<Vec3> ds{Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0, 1, 0)};
  EXPECT_NE(error_of([&] { pair.along(poses, ds, out); }).find("direction 1"), std::string::npos);
  std::vector<Depth3> short_out(2);
  EXPECT_NE(error_of([&] { pair.minimum(poses, short_out); }).find("room for 2"), std::string::npos);
  // Flat input is rejected by name; an unreadable file names the file.
  EXPECT_NE(error_of([] {
              std::vector<Vec3> flat{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
              Shape3::hull(flat, "flat");
            }).find("flat"),
            std::string::npos);
  EXPECT_NE(error_of([] { Shape3::from_file("/nonexistent/a.obj"); }).find("/nonexistent/a.obj"), std::string::npos);
  // A huge direction is the same direction.
  const Pose3 q(Vec3(0.3, 0.1, 0));
  EXPECT_TRUE(same(pair.along(Pose3(), q, Vec3(0x1p1000, 0, 0x1p1000)), pair.along(Pose3(), q, Vec3(1, 0, 1))));
  const Pose3 big(Eigen::Quaterniond(0x1p1000, 0x1p999, 0, 0), Vec3(0.3, 0.1, 0));
  const Pose3 unit(Eigen::Quaterniond(1, 0.5, 0, 0), Vec3(0.3, 0.1, 0));
  EXPECT_TRUE(same(pair.minimum(Pose3(), big), pair.minimum(Pose3(), unit)));
}

}  // namespace
