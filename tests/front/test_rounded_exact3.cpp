// Exact decisions and certified brackets of rounded pairs (src/primitives/rounded3.cpp,
// convex3/distance_compare.hpp): overlap of spheres and of a box and a sphere at ±1, ±2 ulps of
// touching, where the exact answer is known (integer centres at distance 5; a face at an exactly
// representable distance); σ_d and cast brackets against the quadratic formula in long double
// (lower <= the exit / entry <= upper, a few ulps wide); the moves by the upper bound leave the
// pair apart (σ_d) or in contact (cast) by the exact test; grazing casts decided exactly.
#include <gtest/gtest.h>

#include <pendepth/pendepth.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace pendepth {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kInf = std::numeric_limits<double>::infinity();
using LD = long double;

double step(double x, int k) {  // x moved by k ulps
  for (; k > 0; --k) x = std::nextafter(x, kInf);
  for (; k < 0; ++k) x = std::nextafter(x, -kInf);
  return x;
}

// Sphere–sphere with centres at distance exactly 5 ((0,0,0)–(3,4,0), and a rotated Q, whose
// rotation does not move its centre): overlap ⇔ 5 < r1 + r2, decided on the exact sum.
TEST(RoundedExact3, SpheresAtUlpsOfTouching) {
  for (double r1 : {2.0, 2.5, 1.0 / 3}) {
    for (int k = -2; k <= 2; ++k) {
      const double r2 = step(5 - r1, k);
      const LD sum = static_cast<LD>(r1) + static_cast<LD>(r2);  // exact in long double
      const bool overlap = sum > 5, touch = sum == 5;
      const Pair3 pair(Shape3::sphere(r1), Shape3::sphere(r2));
      const Eigen::Quaterniond rot(0.6, 0.0, 0.8, 0.0);
      // (P unrotated: a rotated P's frame would round Q's centre, as in every 3D engine, whose
      // exactness is that of the relative pose Rpᵀ·(tq − tp) computed in doubles.)
      for (int pose = 0; pose < 4; pose += 2) {
        const Pose3 pp;
        const Pose3 pq = pose & 2 ? Pose3(rot.conjugate(), Vec3(3, 4, 0)) : Pose3(Vec3(3, 4, 0));
        const std::string what = "r1 " + std::to_string(r1) + " step " + std::to_string(k) + " pose " + std::to_string(pose);
        EXPECT_EQ(pair.overlapping(pp, pq), overlap) << what;
        const Distance3 sd = pair.signed_distance(pp, pq);
        EXPECT_EQ(sd.overlapping, overlap) << what;
        EXPECT_EQ(sd.distance < 0, overlap) << what;
        EXPECT_EQ(sd.distance == 0, touch) << what;
        EXPECT_EQ(sd.distance > 0, !overlap && !touch) << what;
        EXPECT_LE(std::abs(static_cast<LD>(sd.distance) - (5 - sum)), 4 * kEps * 5) << what;
        const Depth3 m = pair.minimum(pp, pq);
        EXPECT_EQ(m.overlapping, overlap) << what;
        EXPECT_EQ(m.depth > 0, overlap) << what;
        // σ_d along the line of centres: the exit is r − 5 exactly, inside the bracket.
        const Depth3 a = pair.along(pp, pq, Vec3(3, 4, 0));
        EXPECT_EQ(a.overlapping, overlap) << what;
        if (overlap) {
          EXPECT_LE(static_cast<LD>(a.lower_bound), sum - 5) << what;
          EXPECT_GE(static_cast<LD>(a.upper_bound), sum - 5) << what;
          EXPECT_EQ(a.depth, a.upper_bound) << what;
        }
        // The cast from distance 15 along the line of centres enters at 15 − r.
        Pose3 far = pq;
        far.translation = Vec3(9, 12, 0);  // distance 15
        const Cast3 c = pair.cast(pp, far, Vec3(-3, -4, 0));
        ASSERT_TRUE(c.hit) << what;
        EXPECT_GE(static_cast<LD>(c.distance), 15 - sum) << what;
        EXPECT_LE(static_cast<LD>(c.distance), (15 - sum) * (1 + 8 * static_cast<LD>(kEps))) << what;
        // From the pose itself towards P: 0 when in contact, else the gap 5 − r (an ulp or two)
        // — the upper end of the entry's bracket, within a few ulps of it.
        const Cast3 c0 = pair.cast(pp, pq, Vec3(-3, -4, 0));
        EXPECT_TRUE(c0.hit) << what;
        EXPECT_EQ(c0.overlapping, overlap) << what;
        if (overlap || touch) {
          EXPECT_EQ(c0.distance, 0) << what;
        } else {
          EXPECT_GE(static_cast<LD>(c0.distance), 5 - sum) << what;
          EXPECT_LE(static_cast<LD>(c0.distance), (5 - sum) * (1 + 8 * static_cast<LD>(kEps))) << what;
        }
        EXPECT_EQ(pair.cast(pp, pq, Vec3(3, 4, 0)).hit, overlap || touch) << what;
      }
    }
  }
}

// A box [−1, 1]³ and a sphere of radius 0.5 at x = 1.5 ± k ulps: the core distance x − 1 is exact
// (Sterbenz), so overlap ⇔ x < 1.5; also with the sphere as P (swapped roles), a capsule and a
// rounded box.
TEST(RoundedExact3, BoxSphereAtUlpsOfTouching) {
  const Pair3 pair(Shape3::box(1, 1, 1), Shape3::sphere(0.5));
  const Pair3 swapped(Shape3::sphere(0.5), Shape3::box(1, 1, 1));
  for (int k = -2; k <= 2; ++k) {
    const double x = step(1.5, k);
    const std::string what = "step " + std::to_string(k);
    for (const Vec3& c : {Vec3(x, 0.3, -0.2), Vec3(0.25, -x, 0.5), Vec3(-0.75, 0.5, x)}) {
      EXPECT_EQ(pair.overlapping(Pose3(), Pose3(c)), k < 0) << what;
      EXPECT_EQ(swapped.overlapping(Pose3(), Pose3(-c)), k < 0) << what;
      const Distance3 sd = pair.signed_distance(Pose3(), Pose3(c));
      EXPECT_EQ(sd.distance == 0, k == 0) << what;
      EXPECT_EQ(sd.distance < 0, k < 0) << what;
      EXPECT_EQ(swapped.signed_distance(Pose3(), Pose3(-c)).distance == 0, k == 0) << what;
    }
    // A capsule (segment core, axis z) beside the face x = 1, and a rounded box (a box core
    // ⊕ 0.25: polytope cores on both sides) at x: core gaps x − 1 and x − 1.25, both exact.
    const Pair3 capsule(Shape3::box(1, 1, 1), Shape3::capsule(0.5, 0.25));
    EXPECT_EQ(capsule.overlapping(Pose3(), Pose3(Vec3(x, 0.3, -0.2))), k < 0) << what;
    EXPECT_EQ(capsule.signed_distance(Pose3(), Pose3(Vec3(x, 0.3, -0.2))).distance == 0, k == 0) << what;
    const Pair3 rounded(Shape3::box(1, 1, 1), Shape3::rounded(Shape3::box(0.25, 0.25, 0.25), 0.25));
    EXPECT_EQ(rounded.overlapping(Pose3(), Pose3(Vec3(x, 0.5, -0.5))), k < 0) << what;
    EXPECT_EQ(rounded.signed_distance(Pose3(), Pose3(Vec3(x, 0.5, -0.5))).distance == 0, k == 0) << what;
  }
}

// σ_d of sphere pairs: the exit of the ray c + s·d̂ from the ball of radius r by the quadratic
// formula in long double (stable form), inside the certified bracket, at most 8 ulps wide; the
// move by the reported translation (along an axis, when adding it to the pose is exact: then the
// moved pose is the certified point) leaves the pair apart or touching (σ_d) / in contact (cast),
// decided exactly.
TEST(RoundedExact3, SphereRayBracketsContainTheQuadraticRoot) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> U(-1, 1), R(0.2, 0.8);
  int exits = 0, entries = 0, moves = 0;
  for (int k = 0; k < 400; ++k) {
    const double r1 = R(rng), r2 = R(rng);
    const Pair3 pair(Shape3::sphere(r1), Shape3::sphere(r2));
    // Coarse centres and (half the time) axis directions: the moves' sums are often exact.
    const Vec3 c = k % 2 ? Vec3(U(rng), U(rng), U(rng)) : Vec3(std::round(8 * U(rng)) / 8, std::round(8 * U(rng)) / 8, 0.125);
    Vec3 d(U(rng), U(rng), U(rng));
    if (k % 4 == 0) d = Vec3::Unit(k / 4 % 3) * (k % 8 == 0 ? 1.0 : -3.0);
    const std::string what = "case " + std::to_string(k);
    using LV = Eigen::Matrix<LD, 3, 1>;
    const LV cl = c.cast<LD>(), dl = d.cast<LD>().normalized();
    const LD r = static_cast<LD>(r1) + static_cast<LD>(r2);
    const LD b = cl.dot(dl), q = cl.squaredNorm() - r * r, disc = b * b - q;
    const Pose3 pq(c);
    if (q < 0) {  // overlapping: exit s = −b + √disc = −q / (b + √disc) for b >= 0
      ++exits;
      const LD s = b >= 0 ? -q / (b + std::sqrt(disc)) : -b + std::sqrt(disc);
      const Depth3 a = pair.along(Pose3(), pq, d);
      ASSERT_TRUE(a.overlapping) << what;
      EXPECT_LE(static_cast<LD>(a.lower_bound), s * (1 + 0x1p-60L)) << what;
      EXPECT_GE(static_cast<LD>(a.upper_bound), s * (1 - 0x1p-60L)) << what;
      EXPECT_LE(a.upper_bound - a.lower_bound, 8 * kEps * a.upper_bound) << what;
      EXPECT_EQ(a.depth, a.upper_bound) << what;
      // A rotated P (a ball: the same set) moves the exact offset λ·d into P's frame exactly;
      // only the relative pose's rounding (a few ulps) separates the answers.
      const Depth3 ar = pair.along(Pose3(Eigen::Quaterniond(0.6, 0.0, 0.8, 0.0), Vec3::Zero()), pq, d);
      EXPECT_NEAR(ar.depth, a.depth, 64 * kEps * 2) << what;
      EXPECT_LE(ar.upper_bound - ar.lower_bound, 8 * kEps * ar.upper_bound) << what;
      // (along an axis the translation is hi·e exactly, the point the bracket certifies)
      Vec3 moved = c + a.translation;
      bool exact = k % 4 == 0;
      for (int i = 0; i < 3; ++i) exact = exact && moved[i] - c[i] == a.translation[i] && moved[i] - a.translation[i] == c[i];
      if (exact) {
        ++moves;
        EXPECT_FALSE(pair.overlapping(Pose3(), Pose3(moved))) << what;
      }
    } else if (disc > 1e-6L && b < 0) {  // apart, the ray enters: s = −b − √disc = q / (−b + √disc)
      ++entries;
      const LD s = q / (-b + std::sqrt(disc));
      const Cast3 cast = pair.cast(Pose3(), pq, d);
      ASSERT_TRUE(cast.hit) << what;
      EXPECT_GE(static_cast<LD>(cast.distance), s * (1 - 0x1p-60L)) << what;
      EXPECT_LE(cast.distance, static_cast<double>(s) * (1 + 8 * kEps)) << what;
      // The certified bracket (Cast3's bounds): lower <= the entry <= upper = distance, a few ulps wide.
      EXPECT_LE(static_cast<LD>(cast.lower_bound), s * (1 + 0x1p-60L)) << what;
      EXPECT_EQ(cast.upper_bound, cast.distance) << what;
      EXPECT_LE(cast.lower_bound, cast.upper_bound) << what;
      EXPECT_LE(cast.upper_bound - cast.lower_bound, 8 * kEps * cast.upper_bound) << what;
      Vec3 moved = c + cast.translation;
      bool exact = k % 4 == 0;
      for (int i = 0; i < 3; ++i)
        exact = exact && moved[i] - c[i] == cast.translation[i] && moved[i] - cast.translation[i] == c[i];
      if (exact) {
        ++moves;
        EXPECT_LE(pair.signed_distance(Pose3(), Pose3(moved)).distance, 0) << what;  // touching or overlapping
      }
    } else if (disc < -1e-6L || b > 0) {
      const Cast3 miss = pair.cast(Pose3(), pq, d);
      EXPECT_FALSE(miss.hit) << what;
      EXPECT_EQ(miss.lower_bound, kInf) << what;
      EXPECT_EQ(miss.upper_bound, kInf) << what;
    }
  }
  EXPECT_GT(exits, 50);
  EXPECT_GT(entries, 30);
  EXPECT_GT(moves, 20);
}

// Grazing casts: the line of the ray at distance exactly r from the other centre (a hit), r ± 1
// and 2 ulps (hit / miss decided exactly), and the ray moving away (a miss). Never NaN.
TEST(RoundedExact3, GrazingCastsAreDecidedExactly) {
  for (int k = -2; k <= 2; ++k) {
    const double r2 = step(1.75, k);  // r = 1.25 + r2, the line at distance 3
    const LD r = 1.25L + static_cast<LD>(r2);
    const Pair3 pair(Shape3::sphere(1.25), Shape3::sphere(r2));
    const std::string what = "step " + std::to_string(k);
    for (const Vec3& d : {Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(0.75, 0, 0)}) {
      const Cast3 c = pair.cast(Pose3(), Pose3(Vec3(-10, 3, 0)), d);
      EXPECT_EQ(c.hit, r >= 3) << what;
      EXPECT_FALSE(std::isnan(c.distance)) << what;
      if (c.hit) {
        const LD s = 10 - std::sqrt(std::max(r * r - 9, 0.0L));  // entry
        EXPECT_GE(static_cast<LD>(c.distance), s * (1 - 0x1p-60L)) << what;
        EXPECT_LE(static_cast<LD>(c.distance), s * (1 + 8 * static_cast<LD>(kEps))) << what;
      } else {
        EXPECT_EQ(c.distance, kInf) << what;
      }
      EXPECT_FALSE(pair.cast(Pose3(), Pose3(Vec3(-10, 3, 0)), -d).hit) << what;  // moving away
    }
  }
}

}  // namespace
}  // namespace pendepth
