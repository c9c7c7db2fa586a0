// Random rotations for the 3D suites: a quaternion of four standard normal coordinates is uniform on
// the rotation group once normalised. Shared so every suite draws the same rotations from a seed.
#pragma once

#include <Eigen/Geometry>
#include <random>

namespace pendepth_test {

/// Not normalised: Pose3 normalises its rotation, and these tests check that it does.
inline Eigen::Quaterniond random_quaternion(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng));
}

/// The same draw, normalised.
inline Eigen::Quaterniond random_unit_quaternion(std::mt19937_64& rng) { return random_quaternion(rng).normalized(); }

}  // namespace pendepth_test
