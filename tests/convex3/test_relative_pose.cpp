// The poses' shortcuts (src/convex3/depth3.cpp) against the formulas they replace, bit for bit:
// Pose3::matrix scales the quaternion by one product x·2^−e instead of ldexp(x, −e) (e from the
// exponent bits), and relative_pose skips the products by P's rotation when it is exactly I
// (each coefficient of Iᵀ·x: x_i, or a zero whose sign follows all three terms). Inputs: random
// and axis-aligned quaternions (exact zeros of both signs in the matrix), quaternions scaled to
// 2^±1000 and into the subnormals, translations with ±0 components.
#include <gtest/gtest.h>

#include <pendepth/depth3.hpp>

#include "convex3/minkowski_facets.hpp"
#include "test_rotations.hpp"

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace pendepth {
namespace {

bool same_bits(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Pose3::matrix written plainly: ldexp for every coefficient, I for x = y = z = +0.
Eigen::Matrix3d matrix_reference(const Pose3& p) {
  const Eigen::Vector4d c = p.rotation.coeffs();
  if (c[0] == 0 && !std::signbit(c[0]) && c[1] == 0 && !std::signbit(c[1]) && c[2] == 0 && !std::signbit(c[2]))
    return Eigen::Matrix3d::Identity();
  return pendepth_test::scaled_rotation_matrix(p.rotation);
}

std::vector<Pose3> poses() {
  std::vector<Pose3> out;
  const double vals[] = {0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 0.7071067811865476};
  const double trans[] = {0.0, -0.0, 1.5, -2.25, 1e-300};
  int t = 0;
  for (double w : vals)
    for (double x : vals)
      for (double y : vals)
        for (double z : {0.0, -0.0, 1.0, -0.5}) {
          if (w == 0 && x == 0 && y == 0 && z == 0) continue;
          const Vec3 tr(trans[t % 5], trans[(t / 5) % 5], trans[(t / 25) % 5]);
          ++t;
          out.emplace_back(Eigen::Quaterniond(w, x, y, z), tr);
        }
  std::mt19937_64 rng(7);
  std::normal_distribution<double> N;
  for (int k = 0; k < 300; ++k) {
    const double s = std::ldexp(1.0, static_cast<int>(rng() % 2080) - 1060);  // 2^-1060 … 2^1019
    Eigen::Quaterniond q(N(rng) * s, N(rng) * s, N(rng) * s, N(rng) * s);
    out.emplace_back(q, Vec3(N(rng), k % 3 ? N(rng) : -0.0, N(rng)));
  }
  return out;
}

TEST(RelativePose, MatrixMatchesLdexpScaling) {
  int n = 0;
  for (const Pose3& p : poses()) {
    if (!p.rotation.coeffs().allFinite() || p.rotation.coeffs().cwiseAbs().maxCoeff() == 0) continue;
    EXPECT_TRUE(same_bits(p.matrix(), matrix_reference(p))) << p.rotation.coeffs().transpose();
    ++n;
  }
  EXPECT_GT(n, 1000);
}

TEST(RelativePose, IdentityRotationOfPMatchesTheProducts) {
  const std::vector<Pose3> ps = poses();
  int n = 0;
  for (const Pose3& pq : ps)
    for (const Vec3& tp : {Vec3(0.0, 0.0, 0.0), Vec3(-0.0, -0.0, -0.0), Vec3(-0.0, 3.0, -0.0), Vec3(1e-310, -2.0, 0.0)}) {
      if (pq.rotation.coeffs().cwiseAbs().maxCoeff() == 0) continue;
      const Pose3 pp(tp);
      const Eigen::Matrix3d Rp = matrix_reference(pp), Rq = matrix_reference(pq);
      ASSERT_TRUE(Rp == Eigen::Matrix3d::Identity());
      Eigen::Matrix3d Rp_out;
      const convex3::RelativePose r = convex3::relative_pose(pp, pq, &Rp_out);
      EXPECT_TRUE(same_bits(Rp_out, Rp));
      const Eigen::Matrix3d R = Rp.transpose() * Rq;
      const Vec3 tq = Rp.transpose() * pq.translation, tpl = Rp.transpose() * pp.translation;
      EXPECT_TRUE(same_bits(r.R, R)) << pq.rotation.coeffs().transpose();
      EXPECT_TRUE(same_bits(r.tq, tq)) << pq.translation.transpose();
      EXPECT_TRUE(same_bits(r.tp, tpl)) << tp.transpose();
      ++n;
    }
  EXPECT_GT(n, 4000);
}

// Every pose of P (unrotated with any w, zeros of both signs, rotated, 2^±1000 scales) against
// the products by its matrix: the quaternion test of the unrotated P and the matrix comparison
// after it must together give the products' bits.
TEST(RelativePose, AnyRotationOfPMatchesTheProducts) {
  const std::vector<Pose3> ps = poses();
  int n = 0, unrotated = 0;
  for (std::size_t a = 0; a < ps.size(); a += 3)
    for (std::size_t b = 1; b < ps.size(); b += 7) {
      const Pose3 &pp = ps[a], &pq = ps[b];
      if (pp.rotation.coeffs().cwiseAbs().maxCoeff() == 0 || pq.rotation.coeffs().cwiseAbs().maxCoeff() == 0) continue;
      const Eigen::Matrix3d Rp = matrix_reference(pp), Rq = matrix_reference(pq);
      Eigen::Matrix3d Rp_out;
      const convex3::RelativePose r = convex3::relative_pose(pp, pq, &Rp_out);
      EXPECT_TRUE(same_bits(Rp_out, Rp)) << pp.rotation.coeffs().transpose();
      EXPECT_TRUE(same_bits(r.R, Eigen::Matrix3d(Rp.transpose() * Rq))) << pp.rotation.coeffs().transpose();
      EXPECT_TRUE(same_bits(r.tq, Vec3(Rp.transpose() * pq.translation))) << pp.rotation.coeffs().transpose();
      EXPECT_TRUE(same_bits(r.tp, Vec3(Rp.transpose() * pp.translation))) << pp.rotation.coeffs().transpose();
      unrotated += Rp == Eigen::Matrix3d::Identity();
      ++n;
    }
  EXPECT_GT(n, 20000);
  EXPECT_GT(unrotated, 1000);
}

}  // namespace
}  // namespace pendepth
