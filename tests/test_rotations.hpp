// Random rotations for the 3D suites: a quaternion of four standard normal coordinates is uniform on
// the rotation group once normalised. Shared so every suite draws the same rotations from a seed.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace pendepth_test {

/// Not normalised: Pose3 normalises its rotation, and these tests check that it does.
inline Eigen::Quaterniond random_quaternion(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng));
}

/// The same draw, normalised.
inline Eigen::Quaterniond random_unit_quaternion(std::mt19937_64& rng) { return random_quaternion(rng).normalized(); }

/// Pose3::matrix written out plainly, for the tests of its shortcuts (the exponent read from the
/// bits, the identity without arithmetic): each coefficient scaled by ldexp(·, −ilogb(max |c|)),
/// then R = I + (2/|q|²)·[quadratic terms] with one division and Eigen's toRotationMatrix order
/// of terms. Not for zero or non-finite quaternions.
inline Eigen::Matrix3d scaled_rotation_matrix(const Eigen::Quaterniond& rotation) {
  const Eigen::Vector4d c = rotation.coeffs();
  const int e = std::ilogb(c.cwiseAbs().maxCoeff());
  const double x = std::ldexp(c[0], -e), y = std::ldexp(c[1], -e), z = std::ldexp(c[2], -e),
               w = std::ldexp(c[3], -e);
  const double s = 2 / ((x * x + y * y) + (z * z + w * w));
  const double tx = x * s, ty = y * s, tz = z * s;
  Eigen::Matrix3d R;
  R(0, 0) = 1 - (y * ty + z * tz);
  R(0, 1) = x * ty - w * tz;
  R(0, 2) = x * tz + w * ty;
  R(1, 0) = x * ty + w * tz;
  R(1, 1) = 1 - (x * tx + z * tz);
  R(1, 2) = y * tz - w * tx;
  R(2, 0) = x * tz - w * ty;
  R(2, 1) = y * tz + w * tx;
  R(2, 2) = 1 - (x * tx + y * ty);
  return R;
}

}  // namespace pendepth_test
