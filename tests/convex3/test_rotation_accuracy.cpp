// Accuracy of Pose3::matrix (src/convex3/depth3.cpp: one division s = 2/|q|², no square root)
// against the exact rotation of the double quaternion, evaluated in 50-digit binary floating point
// (Boost.Multiprecision cpp_bin_float_50: an oracle independent of the double formula), and
// against the conversion it replaced (normalise q, then Eigen's toRotationMatrix) on the same
// inputs. Errors are absolute (every entry lies in [−1, 1]), in ε = 2^−52 (one ulp of 1):
//   entry : max |R_ij − R*_ij| over the nine entries, R* the exact rotation of q/|q|;
//   orth  : max |(RᵀR − I)_ij|, RᵀR evaluated exactly enough from the double R.
// Inputs (a pinned RNG): random quaternions (four standard normals) and adversarial families —
// magnitudes 2^−1074 … 2^1023, near-180° rotations (|w| ≪ |(x, y, z)|, w = ±0 included), one
// dominant coefficient (near-identity when it is w), coefficients of independent magnitudes.
// PENDEPTH_ROTATION_SAMPLES=N runs N quaternions per family (default 20 000; docs/benchmarks.md
// quotes N = 10⁶) and prints the old and new maxima.
//
// A priori (u = 2^−53 = ε/2, exact power-of-two prescaling): |q|² to (1 + 3u), s to (1 + 4u),
// each term a·(b·s) to (1 + 6u); an off-diagonal entry s·(ab ± cd) with s·(|ab| + |cd|) ≤ 1
// is within 7u = 3.5 ε, a diagonal one 1 − s·(a² + b²), s·(a² + b²) ≤ 2, within 15u = 7.5 ε.
#include <gtest/gtest.h>

#include <pendepth/depth3.hpp>

#include "test_rotations.hpp"

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace pendepth {
namespace {

using Big = boost::multiprecision::cpp_bin_float_50;

struct Errors {
  double entry = 0, orth = 0;  // in ε
};

// The exact rotation of q = (x, y, z, w) ≠ 0, to 50 digits: I + (2/|q|²)·[quadratic terms].
void exact_rotation(const Eigen::Vector4d& c, Big R[3][3]) {
  const Big x = c[0], y = c[1], z = c[2], w = c[3];
  const Big s = 2 / (x * x + y * y + z * z + w * w);
  R[0][0] = 1 - s * (y * y + z * z), R[0][1] = s * (x * y - w * z), R[0][2] = s * (x * z + w * y);
  R[1][0] = s * (x * y + w * z), R[1][1] = 1 - s * (x * x + z * z), R[1][2] = s * (y * z - w * x);
  R[2][0] = s * (x * z - w * y), R[2][1] = s * (y * z + w * x), R[2][2] = 1 - s * (x * x + y * y);
}

void accumulate(const Eigen::Matrix3d& R, const Big exact[3][3], Errors& e) {
  const double eps = 0x1p-52;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      e.entry = std::max(e.entry, static_cast<double>(abs(Big(R(i, j)) - exact[i][j])) / eps);
      Big dot = 0;  // (RᵀR)_ij: products of doubles, exact in 50 digits
      for (int k = 0; k < 3; ++k) dot += Big(R(k, i)) * Big(R(k, j));
      e.orth = std::max(e.orth, static_cast<double>(abs(dot - (i == j ? 1 : 0))) / eps);
    }
}

// The conversion Pose3::matrix made before (kept as the reference of the old accuracy): the same
// exact prescaling, then q/|q| (a square root, four divisions) and Eigen's toRotationMatrix.
Eigen::Matrix3d normalise_first(const Eigen::Quaterniond& rotation) {
  const Eigen::Vector4d c = rotation.coeffs();
  const int e = std::ilogb(c.cwiseAbs().maxCoeff());
  Eigen::Quaterniond q;
  for (int k = 0; k < 4; ++k) q.coeffs()[k] = std::ldexp(c[k], -e);
  return q.normalized().toRotationMatrix();
}

int samples() {
  const char* env = std::getenv("PENDEPTH_ROTATION_SAMPLES");
  return env ? std::max(1, std::atoi(env)) : 20000;
}

double normal_nonzero(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;)
    if (const double v = g(rng); v != 0) return v;
}

using Family = std::function<Eigen::Vector4d(std::mt19937_64&)>;

std::vector<std::pair<std::string, Family>> families() {
  auto pow2 = [](std::mt19937_64& rng, int lo, int hi) {
    return std::ldexp(1.0, lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1)));
  };
  auto normal4 = [](std::mt19937_64& rng) {
    return Eigen::Vector4d(normal_nonzero(rng), normal_nonzero(rng), normal_nonzero(rng), normal_nonzero(rng));
  };
  return {
      {"random", normal4},
      {"tiny/huge magnitudes",
       [=](std::mt19937_64& rng) {  // the largest coefficient from 2^−1074·… to 2^1023·…
         const double s = pow2(rng, -1072, 1020);
         for (;;)  // a few redraws: subnormal products that all round to 0, an overflow
           if (const Eigen::Vector4d c = normal4(rng) * s; c.allFinite() && c.cwiseAbs().maxCoeff() != 0) return c;
       }},
      {"near 180 degrees (w ~ 0)",
       [=](std::mt19937_64& rng) {
         Eigen::Vector4d c = normal4(rng);
         const int k = static_cast<int>(rng() % 64);
         c[3] = k == 63 ? (rng() & 1 ? 0.0 : -0.0) : c[3] * pow2(rng, -60, 0) * (k < 8 ? 0x1p-1000 : 1);
         return c;
       }},
      {"one dominant coefficient",
       [=](std::mt19937_64& rng) {
         Eigen::Vector4d c = normal4(rng);
         const int big = static_cast<int>(rng() % 4);
         for (int k = 0; k < 4; ++k)
           if (k != big) c[k] *= pow2(rng, -60, -1);
         return c;
       }},
      {"independent magnitudes",
       [=](std::mt19937_64& rng) {
         Eigen::Vector4d c = normal4(rng);
         for (int k = 0; k < 4; ++k) c[k] *= pow2(rng, -30, 30);
         return c;
       }},
  };
}

// The new conversion's measured maxima over the families (N = 10⁶ each: 4.36 ε and 8.72 ε,
// rounded up; the old one measured 5.72 ε and 11.47 ε there), inside the a-priori bound above.
constexpr double kEntryBound = 4.5, kOrthBound = 9.0;

TEST(RotationAccuracy, OneDivisionIsAsCloseAsNormalisingFirst) {
  const int n = samples();
  Errors all_new, all_old;
  std::mt19937_64 rng(2026112816);
  for (const auto& [name, draw] : families()) {
    Errors now, before;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector4d c = draw(rng);
      const Eigen::Quaterniond q(c[3], c[0], c[1], c[2]);
      ASSERT_TRUE(q.coeffs() == c);
      Big exact[3][3];
      exact_rotation(c, exact);
      const Eigen::Matrix3d R = Pose3(q, Vec3::Zero()).matrix();
      accumulate(R, exact, now);
      accumulate(normalise_first(q), exact, before);
      // The shortcuts (exponent from the bits, the identity) change no bit of the plain formula.
      ASSERT_TRUE(R == pendepth_test::scaled_rotation_matrix(q)) << c.transpose();
    }
    std::printf("%-26s new: entry %.3f eps, |RtR - I| %.3f eps   old: entry %.3f eps, |RtR - I| %.3f eps\n",
                name.c_str(), now.entry, now.orth, before.entry, before.orth);
    EXPECT_LE(now.entry, kEntryBound) << name;
    EXPECT_LE(now.orth, kOrthBound) << name;
    all_new.entry = std::max(all_new.entry, now.entry), all_new.orth = std::max(all_new.orth, now.orth);
    all_old.entry = std::max(all_old.entry, before.entry), all_old.orth = std::max(all_old.orth, before.orth);
  }
  std::printf("all (%d per family)          new: entry %.3f eps, |RtR - I| %.3f eps   old: entry %.3f eps, |RtR - I| %.3f eps\n",
              n, all_new.entry, all_new.orth, all_old.entry, all_old.orth);
}

// Exactly representable rotations stay exact: half-turns, quarter turns written (1, 1, 0, 0)
// (|q|² = 2, s = 1 — normalising first rounded 1/√2 and left 2.2e-16 on the diagonal) and the
// axis permutations (±1, ±1, ±1, ±1), at any power-of-two scale, give entries in {0, ±1}.
TEST(RotationAccuracy, SignedPermutationsAreExact) {
  const double vals[] = {0.0, 1.0, -1.0};
  int n = 0;
  for (double scale : {1.0, 0x1p-1000, 0x1p1000, 0x1p-1074, 0.5})
    for (double x : vals)
      for (double y : vals)
        for (double z : vals)
          for (double w : vals) {
            const int nonzero = (x != 0) + (y != 0) + (z != 0) + (w != 0);
            if (nonzero == 0 || nonzero == 3) continue;  // zero; |q|² = 3: s = 2/3 rounds
            const Eigen::Vector4d c(x * scale, y * scale, z * scale, w * scale);
            const Eigen::Quaterniond q(c[3], c[0], c[1], c[2]);
            Big exact[3][3];
            exact_rotation(c, exact);
            const Eigen::Matrix3d R = Pose3(q, Vec3::Zero()).matrix();
            for (int i = 0; i < 3; ++i)
              for (int j = 0; j < 3; ++j) EXPECT_EQ(Big(R(i, j)), exact[i][j]) << c.transpose();
            ++n;
          }
  EXPECT_EQ(n, 5 * (8 + 24 + 16));
}

}  // namespace
}  // namespace pendepth
