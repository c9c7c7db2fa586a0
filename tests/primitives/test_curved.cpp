// Curved primitives (cylinder, cone, ellipsoid; src/primitives/support3.cpp) against an
// independent oracle: NESTED TESSELLATIONS. Each curved shape C gets an inscribed polytope
// I ⊆ C and a circumscribed one O ⊇ C (double coordinates; both containments verified here with
// the closed-form support function / implicit equation and a margin far above their rounding),
// and the existing exact polytope engines answer the polytope pairs: by monotonicity of M in
// each shape, σ(I) <= σ(C) <= σ(O), σ_d likewise, sd(O) <= sd(C) <= sd(I). The certified
// bracket [lower_bound, upper_bound] must meet that bracket, and stay in it when the
// tessellation is refined. Plus properties: the reported move separates, σ <= σ_d, a cast from
// the far side gives σ_d, sd is continuous through contact, ellipsoid(R,R,R) = sphere(R), the
// cylinder–box closed form, degenerate sizes rejected, huge and tiny pairs through the scaling.
#include <gtest/gtest.h>

#include <pendepth/pendepth.hpp>

#include "primitives/ball3.hpp"
#include "primitives/coaxial3.hpp"
#include "primitives/directed.hpp"
#include "primitives/tessellation.hpp"

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

namespace pendepth {
namespace {

using namespace curved_test;

struct Case {
  Curved c;
  Shape3 other;
  bool other_curved = false;
  Curved oc{};
};

std::vector<Case> cases() {
  std::vector<Case> r;
  const Curved cyl{K::Cyl, 0.1, 0.2, 0}, cone{K::Cone, 0.12, 0.15, 0}, ell{K::Ell, 0.1, 0.2, 0.15};
  const Shape3 box = Shape3::box(0.1, 0.08, 0.12), sph = Shape3::sphere(0.1), cap = Shape3::capsule(0.05, 0.1);
  const std::vector<Vec3> pts{Vec3(0.1, 0, 0), Vec3(-0.05, 0.09, 0.02), Vec3(-0.05, -0.08, 0.03), Vec3(0, 0.01, 0.15),
                              Vec3(0.01, 0, -0.12)};
  const Shape3 hull = Shape3::hull(pts);
  for (const Curved& c : {cyl, cone, ell}) {
    r.push_back({c, box});
    r.push_back({c, sph});
    r.push_back({c, cap});
    r.push_back({c, hull});
    r.push_back({c, Shape3::rounded(hull, 0.02)});
  }
  r.push_back({cyl, ell.shape(), true, ell});
  r.push_back({cone, cyl.shape(), true, cyl});
  r.push_back({ell, cone.shape(), true, cone});
  return r;
}


// The oracle pair for C (and the other shape's tessellation when it is curved too).
Pair3 oracle_pair(const Case& k, int n, bool outer) {
  const Shape3 a = tessellation(k.c, n, outer);
  const Shape3 b = k.other_curved ? tessellation(k.oc, n, outer) : k.other;
  return Pair3(a, b);
}

TEST(Curved, NestedTessellationsBracketEveryQuery) {
  std::mt19937_64 rng(20261126);
  int checked_min = 0, checked_sd = 0, checked_dir = 0;
  double worst_gap = 0;
  for (const Case& k : cases()) {
    const Shape3 in = tessellation(k.c, 32, false), out = tessellation(k.c, 32, true);
    verify_nesting(k.c, in, out);
    if (k.other_curved) verify_nesting(k.oc, tessellation(k.oc, 32, false), tessellation(k.oc, 32, true));
    const Pair3 pair(k.c.shape(), k.other);
    const Pair3 inner = oracle_pair(k, 32, false), outer = oracle_pair(k, 32, true);
    for (int it = 0; it < 8; ++it) {
      const Pose3 pp = random_pose(rng, 0.05), pq = random_pose(rng, 0.25);
      const Distance3 s = pair.signed_distance(pp, pq);
      const Distance3 si = inner.signed_distance(pp, pq), so = outer.signed_distance(pp, pq);
      ASSERT_LE(s.lower_bound, s.upper_bound);
      ASSERT_LE(s.lower_bound, s.distance);
      ASSERT_LE(s.distance, s.upper_bound);
      // sd(O) <= sd <= sd(I): the brackets meet.
      EXPECT_LE(s.lower_bound, si.distance + 1e-15) << it;
      EXPECT_GE(s.upper_bound, so.distance - 1e-15) << it;
      // The contract: relative gap 1e-12, or the rounding floor of the support evaluations
      // (docs/robustness.md "Curved primitives": about 16u times the pair's size).
      const double floor = 48 * 0x1p-53 * 0.8;
      EXPECT_LE(s.upper_bound - s.lower_bound, 1e-12 * std::abs(s.distance) + floor) << it;
      worst_gap = std::max(worst_gap, (s.upper_bound - s.lower_bound) / std::max(std::abs(s.distance), 1e-3));
      ++checked_sd;
      const Depth3 m = pair.minimum(pp, pq);
      const Depth3 mi = inner.minimum(pp, pq), mo = outer.minimum(pp, pq);
      EXPECT_LE(m.lower_bound, mo.depth + 1e-15);
      EXPECT_GE(m.upper_bound, mi.depth - 1e-15);
      EXPECT_EQ(m.overlapping, s.overlapping);
      if (!m.overlapping) continue;
      ++checked_min;
      EXPECT_LE(m.upper_bound - m.lower_bound, 1e-12 * m.depth + floor);
      // The reported move lengthened by 1e-9 separates, certified: along its direction u,
      // h_M(u) <= U (σ's upper end) and the move is U·u·(1 + 1e-9), so sd >= 1e-9·U up to the
      // rounding of the poses, far above the bracket's floor (the near-contact ridges that kept
      // ~1e-11 wide brackets close since GJK's triangle solve, test_near_contact.cpp).
      Pose3 moved = pq;
      moved.translation += m.translation * (1 + 1e-9);
      EXPECT_GT(pair.signed_distance(pp, moved).lower_bound, 0) << it << " " << k.other.name() << " depth " << m.depth;
      // σ_d along a random direction: bracketed by the tessellations, σ <= σ_d.
      std::normal_distribution<double> g;
      const Vec3 d(g(rng), g(rng), g(rng));
      const Depth3 a = pair.along(pp, pq, d), ai = inner.along(pp, pq, d), ao = outer.along(pp, pq, d);
      ASSERT_TRUE(a.overlapping);
      EXPECT_LE(a.lower_bound, ao.depth + 1e-15);
      EXPECT_GE(a.upper_bound, ai.depth - 1e-15);
      EXPECT_LE(m.lower_bound, a.upper_bound);
      EXPECT_LE(a.upper_bound - a.lower_bound, 1e-11 * a.depth + 16 * floor);
      Pose3 moved_d = pq;
      moved_d.translation += a.translation * (1 + 1e-9);  // likewise (the exit plane of σ_d's upper end)
      EXPECT_GT(pair.signed_distance(pp, moved_d).lower_bound, 0) << it;
      ++checked_dir;
    }
  }
  std::printf("checked: sd %d, sigma %d, sigma_d %d; worst relative sd gap %.3g\n", checked_sd, checked_min,
              checked_dir, worst_gap);
  EXPECT_GT(checked_min, 20);
  EXPECT_GT(checked_sd - checked_min, 20);
}

TEST(Curved, RefiningTheTessellationNarrowsAroundTheAnswer) {
  const Curved ell{K::Ell, 0.1, 0.2, 0.15};
  const Shape3 box = Shape3::box(0.1, 0.08, 0.12);
  const Pair3 pair(ell.shape(), box);
  const Pose3 pp, pq(Eigen::Quaterniond(0.9, 0.1, 0.3, -0.2), Vec3(0.15, 0.1, 0.05));
  const Depth3 m = pair.minimum(pp, pq);
  ASSERT_TRUE(m.overlapping);
  double width = 1;
  for (int n : {8, 16, 32, 64}) {
    const double lo = Pair3(tessellation(ell, n, false), box).minimum(pp, pq).depth;
    const double hi = Pair3(tessellation(ell, n, true), box).minimum(pp, pq).depth;
    EXPECT_LE(lo, m.lower_bound + 1e-15);
    EXPECT_GE(hi, m.upper_bound - 1e-15);
    EXPECT_LT(hi - lo, width) << n;
    width = hi - lo;
  }
  EXPECT_LT(width, 1e-2 * m.depth);
}

TEST(Curved, EllipsoidWithEqualAxesIsTheSphere) {
  std::mt19937_64 rng(7);
  const Pair3 exact(Shape3::sphere(0.1), Shape3::box(0.05, 0.1, 0.07));
  const Pair3 curved(Shape3::ellipsoid(0.1, 0.1, 0.1), Shape3::box(0.05, 0.1, 0.07));
  for (int it = 0; it < 40; ++it) {
    const Pose3 pp = random_pose(rng, 0.02), pq = random_pose(rng, 0.2);
    const Distance3 e = exact.signed_distance(pp, pq), c = curved.signed_distance(pp, pq);
    const double tol = 1e-15;  // the exact engine's value is a few ulps from the true one
    EXPECT_LE(c.lower_bound, e.distance + tol) << it;
    EXPECT_GE(c.upper_bound, e.distance - tol) << it;
    EXPECT_EQ(c.overlapping, e.overlapping);
  }
}

TEST(Curved, CylinderAgainstBoxClosedForm) {
  const double R = 0.1, H = 0.2, X = 0.15, Y = 0.05, Z = 0.1;
  const Pair3 pair(Shape3::cylinder(R, H), Shape3::box(X, Y, Z));
  for (double ox : {0.0, 0.03, 0.1, 0.14}) {
    // Q at (ox, 0, 0): M = (box ⊕ disc) × [−H−Z, H+Z]; σ = min(X + R − |ox|, Y + R, H + Z).
    const Depth3 m = pair.minimum(Pose3(), Pose3(Vec3(ox, 0, 0)));
    const double want = std::min({X + R - ox, Y + R, H + Z});
    EXPECT_LE(m.lower_bound, want * (1 + 1e-15));
    EXPECT_GE(m.upper_bound, want * (1 - 1e-15));
    EXPECT_LE(m.upper_bound - m.lower_bound, 1e-12 * want);
    // σ_d along x: the exit at X + R − ox.
    const Depth3 a = pair.along(Pose3(), Pose3(Vec3(ox, 0, 0)), Vec3(1, 0, 0));
    EXPECT_LE(a.lower_bound, (X + R - ox) * (1 + 1e-15));
    EXPECT_GE(a.upper_bound, (X + R - ox) * (1 - 1e-15));
  }
  // Apart along the diagonal corner region: distance from the box corner's circle.
  const Distance3 s = pair.signed_distance(Pose3(), Pose3(Vec3(0.4, 0.3, 0)));
  const double want = std::hypot(0.4 - X, 0.3 - Y) - R;
  EXPECT_LE(s.lower_bound, want * (1 + 1e-15));
  EXPECT_GE(s.upper_bound, want * (1 - 1e-15));
}

TEST(Curved, CastFromTheFarSideGivesSigmaD) {
  std::mt19937_64 rng(11);
  const Pair3 pair(Shape3::cone(0.1, 0.15), Shape3::ellipsoid(0.05, 0.08, 0.1));
  int hits = 0;
  for (int it = 0; it < 12; ++it) {
    const Pose3 pp = random_pose(rng, 0.0), pq = random_pose(rng, 0.05);
    std::normal_distribution<double> g;
    const Vec3 d = Vec3(g(rng), g(rng), g(rng)).normalized();
    const Depth3 a = pair.along(pp, pq, d);
    if (!a.overlapping) continue;
    const double far = 1.0;  // beyond the exit: Q at pq + far·d, cast back along −d
    Pose3 start = pq;
    start.translation += far * d;
    const Cast3 c = pair.cast(pp, start, -d);
    ASSERT_TRUE(c.hit);
    EXPECT_NEAR(far - c.distance, a.depth, 1e-11) << it;
    ++hits;
  }
  EXPECT_GT(hits, 5);
  // A ray that misses: far off to the side, moving away.
  const Cast3 miss = pair.cast(Pose3(), Pose3(Vec3(1, 0, 0)), Vec3(1, 0, 0));
  EXPECT_FALSE(miss.hit);
  EXPECT_TRUE(std::isinf(miss.distance));
}

TEST(Curved, SignedDistanceIsContinuousThroughContact) {
  const Pair3 pair(Shape3::cylinder(0.1, 0.2), Shape3::ellipsoid(0.1, 0.05, 0.08));
  const Vec3 dir = Vec3(1, 0.3, 0.2).normalized();
  double prev = 0;
  bool first = true;
  const int steps = 400;
  for (int i = 0; i <= steps; ++i) {
    const double s = 0.1 + 0.2 * i / steps;
    const Distance3 d = pair.signed_distance(Pose3(), Pose3(s * dir));
    if (!first) EXPECT_LE(std::abs(d.distance - prev), 0.2 / steps * 1.0000001) << s;
    prev = d.distance, first = false;
  }
}

TEST(Curved, TangentContactIsReportedAsTouchingWithItsBracket) {
  // Two equal spheres-as-ellipsoids exactly tangent along x: sd = 0 exactly, undecidable in
  // floating point; the answer is touching (distance 0, not overlapping) with a bracket around 0.
  const Pair3 pair(Shape3::ellipsoid(0.5, 0.5, 0.5), Shape3::ellipsoid(0.5, 0.5, 0.5));
  const Distance3 d = pair.signed_distance(Pose3(), Pose3(Vec3(1, 0, 0)));
  EXPECT_LE(d.lower_bound, 0);
  EXPECT_GE(d.upper_bound, 0);
  EXPECT_LE(d.upper_bound - d.lower_bound, 1e-13);
  EXPECT_FALSE(d.overlapping);
  EXPECT_EQ(d.distance, 0);
  EXPECT_FALSE(pair.overlapping(Pose3(), Pose3(Vec3(1, 0, 0))));
  // Off by far more than the rounding floor: decided.
  EXPECT_TRUE(pair.overlapping(Pose3(), Pose3(Vec3(1 - 1e-9, 0, 0))));
  EXPECT_FALSE(pair.overlapping(Pose3(), Pose3(Vec3(1 + 1e-12, 0, 0))));
  EXPECT_GT(pair.signed_distance(Pose3(), Pose3(Vec3(1 + 1e-12, 0, 0))).lower_bound, 0);
}

TEST(Curved, LowerDimensionalAndRoundedShapesClosedForms) {
  // A point Q: the signed distance field of the curved shape.
  const Pair3 ball(Shape3::ellipsoid(0.5, 0.5, 0.5), Shape3::point(Vec3::Zero()));
  const Pair3 cyl(Shape3::cylinder(0.5, 1.0), Shape3::point(Vec3::Zero()));
  const Pair3 soft(Shape3::rounded(Shape3::cylinder(0.5, 1.0), 0.25), Shape3::segment(Vec3(0, 0, -1), Vec3(0, 0, 1)));
  auto brackets = [](const Distance3& d, double want) {
    EXPECT_LE(d.lower_bound, want + 1e-15);
    EXPECT_GE(d.upper_bound, want - 1e-15);
    EXPECT_LE(d.upper_bound - d.lower_bound, 1e-12 * std::abs(want) + 1e-15);
  };
  brackets(ball.signed_distance(Pose3(), Pose3(Vec3(0.3, 0.4, 1.2))), std::sqrt(0.09 + 0.16 + 1.44) - 0.5);
  brackets(ball.signed_distance(Pose3(), Pose3(Vec3(0.1, 0.2, 0.2))), -0.2);
  brackets(cyl.signed_distance(Pose3(), Pose3(Vec3(0.3, 0.0, 0.1))), -0.2);      // nearest: the side
  brackets(cyl.signed_distance(Pose3(), Pose3(Vec3(0.0, 0.1, 0.9))), -0.1);      // nearest: the top
  brackets(cyl.signed_distance(Pose3(), Pose3(Vec3(3.0, 4.0, 0.0))), 4.5);       // beside the side
  brackets(soft.signed_distance(Pose3(), Pose3(Vec3(2.0, 0.0, 0.5))), 1.25);     // segment ∥ the axis
  // Concentric cylinder and rounded cylinder: M = cylinder(2, 2) ⊕ B(0.5): σ = 2.5, attained on
  // the whole side and top of M — a continuum of curved nearest points, which EPA's inner
  // polytope cannot approximate (its bracket stays ~1.7e-4 wide); the coaxial pre-step sums the
  // parallel components exactly (src/primitives/coaxial3.cpp): σ = 2.5 with lower = upper.
  const Depth3 c = Pair3(Shape3::cylinder(1, 1), Shape3::rounded(Shape3::cylinder(1, 1), 0.5)).minimum(Pose3(), Pose3());
  EXPECT_LE(c.lower_bound, 2.5 * (1 + 1e-15));
  EXPECT_GE(c.upper_bound, 2.5 * (1 - 1e-15));
  EXPECT_LE(c.upper_bound - c.lower_bound, 1e-12 * 2.5);
  EXPECT_EQ(c.lower_bound, 2.5);
  EXPECT_EQ(c.upper_bound, 2.5);
}

TEST(Curved, BatchesEqualSinglesBitForBit) {
  std::mt19937_64 rng(3);
  const Pair3 pair(Shape3::cone(0.2, 0.3), Shape3::ellipsoid(0.1, 0.2, 0.15));
  std::vector<Pose3> poses;
  for (int i = 0; i < 24; ++i) poses.push_back(random_pose(rng, 0.3));
  std::vector<Depth3> m(poses.size());
  std::vector<Distance3> d(poses.size());
  pair.minimum(poses, m, 2);
  pair.signed_distance(poses, d, 2);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Depth3 a = pair.minimum(Pose3(), poses[i]);
    EXPECT_EQ(m[i].depth, a.depth);
    EXPECT_EQ(m[i].lower_bound, a.lower_bound);
    EXPECT_EQ(d[i].distance, pair.signed_distance(Pose3(), poses[i]).distance);
  }
}

TEST(Curved, DegenerateSizesAreInvalidInput) {
  EXPECT_THROW(Shape3::cylinder(0, 1), InvalidInput);
  EXPECT_THROW(Shape3::cylinder(1, 0), InvalidInput);
  EXPECT_THROW(Shape3::cone(-1, 1), InvalidInput);
  EXPECT_THROW(Shape3::ellipsoid(1, NAN, 1), InvalidInput);
  EXPECT_THROW(Shape3::ellipsoid(1, 1, INFINITY), InvalidInput);
  try {
    Shape3::cone(1, 0, "tip");
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "tip: half height 0 must be finite and positive");
  }
  EXPECT_THROW(Shape3::cylinder(1, 1).polytope(), InvalidInput);
}

TEST(Curved, HugeAndTinyPairsGoThroughTheScaling) {
  const Pair3 unit(Shape3::ellipsoid(1, 2, 1.5), Shape3::cylinder(1, 0.5));
  const Pose3 pq(Eigen::Quaterniond(0.8, 0.2, 0.1, 0.3), Vec3(1.25, 0.5, 0.25));
  const Depth3 u = unit.minimum(Pose3(), pq);
  ASSERT_TRUE(u.overlapping);
  for (int e : {-300, 300}) {
    const double s = std::ldexp(1.0, e);
    const Pair3 big(Shape3::ellipsoid(s, 2 * s, 1.5 * s), Shape3::cylinder(s, 0.5 * s));
    const Depth3 b = big.minimum(Pose3(), Pose3(pq.rotation, pq.translation * s));
    ASSERT_TRUE(b.overlapping) << e;
    EXPECT_EQ(b.lower_bound, std::ldexp(u.lower_bound, e));
    EXPECT_EQ(b.upper_bound, std::ldexp(u.upper_bound, e));
  }
}


// ---- coaxial pairs: the closed-form pre-step (src/primitives/coaxial3.cpp) -------------------
// A shape of the disk ⊕ axial segment ⊕ ball family with its sizes (own frame, axis z).
struct Axial {
  Shape3 shape;
  double disk = 0, seg = 0, ball = 0;
};

Axial random_axial(std::mt19937_64& rng, bool solid) {
  std::uniform_real_distribution<double> size(0.05, 0.6);
  const double a = size(rng), b = size(rng), c = size(rng);
  switch (std::uniform_int_distribution<int>(0, solid ? 4 : 6)(rng)) {
    case 0: return {Shape3::cylinder(a, b), a, b, 0};
    case 1: return {Shape3::rounded(Shape3::cylinder(a, b), c), a, b, c};
    case 2: return {Shape3::sphere(c), 0, 0, c};
    case 3: return {Shape3::capsule(c, b), 0, b, c};
    case 4: return {Shape3::ellipsoid(c, c, c), 0, 0, c};
    case 5: return {Shape3::point(Vec3::Zero()), 0, 0, 0};
    default: return {Shape3::segment(Vec3(0, 0, -b), Vec3(0, 0, b)), 0, b, 0};
  }
}

// Q's rotations that keep z ↦ ±z exactly in doubles: about z by any angle (x = y = 0 in the
// quaternion), and the exact half turns (signed permutations).
Eigen::Quaterniond axial_rotation(std::mt19937_64& rng) {
  const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
  if (kind == 0) return Eigen::Quaterniond(0, 1, 0, 0);  // half turn about x: z ↦ −z
  if (kind == 1) return Eigen::Quaterniond(0, 0, 0, 1);  // half turn about z
  const double phi = std::uniform_real_distribution<double>(-kPi, kPi)(rng);
  return Eigen::Quaterniond(std::cos(phi / 2), 0, 0, std::sin(phi / 2));
}

// The independent oracle: sd of t from cylinder(R, H) ⊕ B(r), in 100 digits, by clamping t to
// the core (outside) or the nearer of side and cap (inside).
using Big = boost::multiprecision::cpp_bin_float_100;
Big oracle_sd(const Big& R, const Big& H, const Big& r, const Vec3& t) {
  const Big rho = boost::multiprecision::sqrt(Big(t[0]) * t[0] + Big(t[1]) * t[1]), z = boost::multiprecision::abs(Big(t[2]));
  if (rho <= R && z <= H) return -r - (R - rho < H - z ? R - rho : H - z);
  const Big dr = rho > R ? Big(rho - R) : Big(0), dz = z > H ? Big(z - H) : Big(0);
  return boost::multiprecision::sqrt(dr * dr + dz * dz) - r;
}

// [σ_min, σ_max] of the double 2×2 block A of Q's rotation (exact eigenvalues of AᵀA in 100
// digits): the double rotation stretches Q's disk and ball by at most these.
std::array<Big, 2> stretch_oracle(const Eigen::Matrix3d& R) {
  const Big a = R(0, 0), b = R(0, 1), c = R(1, 0), d = R(1, 1);
  const Big p = a * a + c * c, q = a * b + c * d, s = b * b + d * d;
  const Big mid = (p + s) / 2, rad = boost::multiprecision::sqrt(((p - s) / 2) * ((p - s) / 2) + q * q);
  return {boost::multiprecision::sqrt(mid - rad), boost::multiprecision::sqrt(mid + rad)};
}

// σ and the signed distance at Q's pose pq with the closed forms (coaxial, ball) switched off
// (EPA alone); the switches are restored on exit.
struct EpaAlone {
  Depth3 minimum;
  Distance3 distance;
};
EpaAlone without_closed_form(const Pair3& pair, const Pose3& pq) {
  struct Off {
    Off() { primitives::coaxial_enabled = primitives::ball_enabled = false; }
    ~Off() { primitives::coaxial_enabled = primitives::ball_enabled = true; }
  } off;
  return {pair.minimum(Pose3(), pq), pair.signed_distance(Pose3(), pq)};
}

TEST(Curved, CoaxialPairsAgainstHighPrecisionOracle) {
  // P at the identity, Q rotated about z or by a half turn: the relative pose is Q's own (exact),
  // so the oracle sees the engine's R and t. sd lies in [sd(largest sizes), sd(smallest)].
  std::mt19937_64 rng(16005);
  std::uniform_real_distribution<double> off(-1.2, 1.2);
  int exact_pairs = 0, overlapping = 0, apart = 0;
  for (int it = 0; it < 3000; ++it) {
    const bool p_solid = it % 2 == 0;
    const Axial P = random_axial(rng, p_solid), Q = random_axial(rng, !p_solid);
    if (!P.shape.curved() && !Q.shape.curved()) continue;  // the rounded engine's pair (exact, not here)
    const Pose3 pq(axial_rotation(rng), Vec3(off(rng), off(rng), off(rng)) * (it % 3 == 0 ? 0.25 : 1.0));
    const Eigen::Matrix3d R = pq.matrix();
    ASSERT_TRUE(R(0, 2) == 0 && R(1, 2) == 0 && R(2, 0) == 0 && R(2, 1) == 0 && std::abs(R(2, 2)) == 1);
    const auto [smin, smax] = stretch_oracle(R);
    const Big one = 1, bmin = smin < one ? smin : one, bmax = smax > one ? smax : one;
    const Big sd_lo = oracle_sd(Big(P.disk) + Big(Q.disk) * smax, Big(P.seg) + Q.seg, Big(P.ball) + Big(Q.ball) * bmax, pq.translation);
    const Big sd_hi = oracle_sd(Big(P.disk) + Big(Q.disk) * smin, Big(P.seg) + Q.seg, Big(P.ball) + Big(Q.ball) * bmin, pq.translation);
    const Pair3 pair(P.shape, Q.shape);
    const Distance3 s = pair.signed_distance(Pose3(), pq);
    ASSERT_LE(s.lower_bound, s.upper_bound) << it;
    EXPECT_LE(Big(s.lower_bound), sd_hi) << it;  // the brackets meet (the true value is in both)
    EXPECT_GE(Big(s.upper_bound), sd_lo) << it;
    const double scale = 1 + pq.translation.norm();
    EXPECT_LE(s.upper_bound - s.lower_bound, 1e-12 * std::abs(s.distance) + 64 * 0x1p-53 * scale) << it;
    if (smin == 1 && smax == 1) {  // an exact isometry: the oracle is one value, inside the bracket
      ++exact_pairs;
      EXPECT_LE(Big(s.lower_bound), sd_lo) << it;
      EXPECT_GE(Big(s.upper_bound), sd_lo) << it;
    }
    const Depth3 m = pair.minimum(Pose3(), pq);
    EXPECT_EQ(m.overlapping, s.overlapping) << it;
    if (s.lower_bound > 0) {
      ++apart;
      EXPECT_FALSE(s.overlapping);
    }
    if (!m.overlapping) continue;
    ++overlapping;
    EXPECT_LE(Big(m.lower_bound), -sd_lo) << it;
    EXPECT_GE(Big(m.upper_bound), -sd_hi) << it;
    EXPECT_LE(m.upper_bound - m.lower_bound, 1e-12 * m.depth + 64 * 0x1p-53 * scale) << it;
    // The move separates to touching: Q moved by it is at sd 0 within the rounding (of the
    // unit normal and its product with σ).
    Pose3 moved = pq;
    moved.translation += m.translation;
    EXPECT_LE(std::abs(pair.signed_distance(Pose3(), moved).distance), 4e-14 * scale) << it;
  }
  std::printf("coaxial: %d overlapping, %d apart, %d exact isometries\n", overlapping, apart, exact_pairs);
  EXPECT_GT(overlapping, 500);
  EXPECT_GT(apart, 500);
  EXPECT_GT(exact_pairs, 500);
}

TEST(Curved, CoaxialExactInputsGiveEqualBounds) {
  // Sizes and offsets exact in binary: every operation of the closed form is exact.
  const Pair3 a(Shape3::cylinder(1, 1), Shape3::capsule(0.25, 0.5));
  const Depth3 m = a.minimum(Pose3(), Pose3(Vec3(0.5, 0, 0.25)));  // side: 1.25 − 0.5
  EXPECT_EQ(m.lower_bound, 0.75);
  EXPECT_EQ(m.upper_bound, 0.75);
  EXPECT_EQ(m.translation, Vec3(0.75, 0, 0));
  // 3-4-5 from the rim of the core cylinder(1, 1.5), minus 0.25.
  const Distance3 d = a.signed_distance(Pose3(), Pose3(Vec3(1 + 3, 0, 1.5 + 4)));
  EXPECT_EQ(d.lower_bound, 4.75);
  EXPECT_EQ(d.upper_bound, 4.75);
  EXPECT_EQ(d.distance, 4.75);
  // Touching exactly: sd = 0, not overlapping, bracket [0, 0].
  const Distance3 t = a.signed_distance(Pose3(), Pose3(Vec3(0, 0, 1.75)));
  EXPECT_EQ(t.lower_bound, 0);
  EXPECT_EQ(t.upper_bound, 0);
  EXPECT_FALSE(t.overlapping);
  EXPECT_FALSE(a.overlapping(Pose3(), Pose3(Vec3(0, 0, 1.75))));
  // Huge and tiny pairs (through the scaling by a power of two): the same bits, scaled.
  for (int e : {-300, 300}) {
    const double s = std::ldexp(1.0, e);
    const Pair3 big(Shape3::cylinder(s, s), Shape3::capsule(0.25 * s, 0.5 * s));
    const Depth3 b = big.minimum(Pose3(), Pose3(Vec3(0.5 * s, 0, 0.25 * s)));
    EXPECT_EQ(b.lower_bound, 0.75 * s) << e;
    EXPECT_EQ(b.upper_bound, 0.75 * s) << e;
  }
}

TEST(Curved, CoaxialPairsInsideTheNestedTessellationsAndTheEpaBracket) {
  // Two independent references: the polygon prisms I ⊆ cylinder ⊆ O through the exact engines
  // (rounded hulls for the rounded cylinders), and EPA itself (the pre-step switched off).
  std::mt19937_64 rng(27);
  std::uniform_real_distribution<double> off(-0.5, 0.5);
  const Curved cp{K::Cyl, 0.3, 0.2, 0}, cq{K::Cyl, 0.15, 0.35, 0};
  verify_nesting(cp, tessellation(cp, 48, false), tessellation(cp, 48, true));
  verify_nesting(cq, tessellation(cq, 48, false), tessellation(cq, 48, true));
  const double r = 0.05;
  const Pair3 pair(cp.shape(), Shape3::rounded(cq.shape(), r));
  const Pair3 inner(tessellation(cp, 48, false), Shape3::rounded(tessellation(cq, 48, false), r));
  const Pair3 outer(tessellation(cp, 48, true), Shape3::rounded(tessellation(cq, 48, true), r));
  int checked = 0;
  for (int it = 0; it < 60; ++it) {
    const Pose3 pq(axial_rotation(rng), Vec3(off(rng), off(rng), off(rng)));
    const Distance3 s = pair.signed_distance(Pose3(), pq);
    EXPECT_LE(s.lower_bound, inner.signed_distance(Pose3(), pq).distance + 1e-15) << it;
    EXPECT_GE(s.upper_bound, outer.signed_distance(Pose3(), pq).distance - 1e-15) << it;
    const Depth3 m = pair.minimum(Pose3(), pq);
    EXPECT_GE(m.upper_bound, inner.minimum(Pose3(), pq).depth - 1e-15) << it;
    EXPECT_LE(m.lower_bound, outer.minimum(Pose3(), pq).depth + 1e-15) << it;
    const auto [em, e] = without_closed_form(pair, pq);
    EXPECT_LE(s.lower_bound, e.upper_bound) << it;
    EXPECT_GE(s.upper_bound, e.lower_bound) << it;
    EXPECT_LE(s.upper_bound - s.lower_bound, e.upper_bound - e.lower_bound + 1e-16) << it;
    if (!m.overlapping) continue;
    ++checked;
    EXPECT_LE(m.lower_bound, em.upper_bound) << it;
    EXPECT_GE(m.upper_bound, em.lower_bound) << it;
    // σ <= σ_d along random directions (σ_d: EPA along the ray, unchanged).
    std::normal_distribution<double> g;
    const Depth3 a = pair.along(Pose3(), pq, Vec3(g(rng), g(rng), g(rng)));
    EXPECT_LE(m.lower_bound, a.upper_bound) << it;
  }
  EXPECT_GT(checked, 10);
}

TEST(Curved, NearCoaxialPairsTakeTheTiltBoundWhenNarrower) {
  // The centred cylinder in a rounded cylinder tilted by ε: σ still on a near-continuum, EPA's
  // bracket ~1e-5–1e-4 wide at 600 supports (at 1e-6 its longer budget closes it); the closed
  // form of the untilted sum widened by ‖R − R0‖·ρ_C is certified (it must meet EPA's bracket)
  // and ~ε wide, and it narrows the answer.
  const Pair3 pair(Shape3::cylinder(1, 1), Shape3::rounded(Shape3::cylinder(1, 1), 0.5));
  for (double eps : {1e-6, 1e-9, 1e-12}) {
    const Pose3 pq(Eigen::Quaterniond(Eigen::AngleAxisd(eps, Vec3(0.6, 0.8, 0))), Vec3::Zero());
    const Depth3 m = pair.minimum(Pose3(), pq);
    const Depth3 e = without_closed_form(pair, pq).minimum;
    ASSERT_TRUE(m.overlapping && e.overlapping);
    EXPECT_LE(m.lower_bound, e.upper_bound) << eps;
    EXPECT_GE(m.upper_bound, e.lower_bound) << eps;
    EXPECT_LE(m.upper_bound - m.lower_bound, 4 * eps * 2.5) << eps;  // ρ_Q ≈ 1.9, both sides
    EXPECT_LT(m.upper_bound - m.lower_bound, e.upper_bound - e.lower_bound) << eps;
    Pose3 moved = pq;  // the move separates (to touching, within rounding)
    moved.translation += m.translation * (1 + 1e-12);
    EXPECT_GE(pair.signed_distance(Pose3(), moved).upper_bound, 0) << eps;
  }
}

TEST(Curved, NonParallelPairsFallThroughToEpaBitForBit) {
  // Tilted axes (z not mapped to ±z exactly), cones against non-balls, general ellipsoids, polytopes,
  // off-centre segments: the answers are EPA's, bit for bit (a ball against a cone, cylinder or
  // spheroid: the ball closed form, "Ball pairs" below) — except a near-coaxial tilt (1e-9 rad),
  // where the closed form widened by the tilt bound is kept when its bracket is narrower (it must meet EPA's).
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> off(-0.3, 0.3);
  const std::vector<std::pair<Shape3, Shape3>> pairs{
      {Shape3::cylinder(0.3, 0.2), Shape3::rounded(Shape3::cylinder(0.2, 0.3), 0.05)},
      {Shape3::cylinder(0.3, 0.2), Shape3::cylinder(0.2, 0.1)},
      {Shape3::cylinder(0.3, 0.2), Shape3::capsule(0.1, 0.2)},
      {Shape3::cone(0.3, 0.2), Shape3::capsule(0.1, 0.05)},
      {Shape3::ellipsoid(0.3, 0.25, 0.2), Shape3::sphere(0.1)},
      {Shape3::cylinder(0.3, 0.2), Shape3::box(0.1, 0.1, 0.1)},
      {Shape3::cylinder(0.3, 0.2), Shape3::segment(Vec3(0.01, 0, 0), Vec3(0.01, 0, 0.1))}};
  int n = 0, narrower = 0;
  for (const auto& [P, Q] : pairs) {
    const Pair3 pair(P, Q);
    for (int it = 0; it < 6; ++it, ++n) {
      // Nearly coaxial (a tilt of 1e-9 rad) every other time, else a random pose.
      const Pose3 pq = it % 2 ? random_pose(rng, 0.3)
                              : Pose3(Eigen::Quaterniond(1, 0.5e-9, 0, 0), Vec3(off(rng), off(rng), off(rng)));
      const Depth3 m = pair.minimum(Pose3(), pq);
      const Distance3 d = pair.signed_distance(Pose3(), pq);
      const auto [em, ed] = without_closed_form(pair, pq);
      if (it % 2 == 0 && m.upper_bound - m.lower_bound < em.upper_bound - em.lower_bound) {
        EXPECT_LE(m.lower_bound, em.upper_bound) << n;
        EXPECT_GE(m.upper_bound, em.lower_bound) << n;
        EXPECT_LE(d.lower_bound, ed.upper_bound) << n;
        EXPECT_GE(d.upper_bound, ed.lower_bound) << n;
        ++narrower;
        continue;
      }
      EXPECT_EQ(m.lower_bound, em.lower_bound) << n;
      EXPECT_EQ(m.upper_bound, em.upper_bound) << n;
      EXPECT_EQ(m.translation, em.translation) << n;
      EXPECT_EQ(m.candidates, em.candidates) << n;
      EXPECT_EQ(d.lower_bound, ed.lower_bound) << n;
      EXPECT_EQ(d.upper_bound, ed.upper_bound) << n;
      EXPECT_EQ(d.witness_p, ed.witness_p) << n;
    }
  }
  EXPECT_LT(narrower, n / 4);  // off-centre tilted pairs have isolated nearest points: EPA closes
}


// ---- ball pairs: the closed form of src/primitives/ball3.cpp --------------------------------
// A ball Q = B(c, r) against a cone: sd_M(0) = sd_cone(c) − r. The independent oracle, in 100
// digits: inside the triangle section (both line functions <= 0) the larger line function, else
// the least distance to its two right-half edges, each by clamped projection.
Big segment_distance(const Big& pr, const Big& pz, const Big& ar, const Big& az, const Big& br, const Big& bz) {
  const Big dr = br - ar, dz = bz - az;
  Big lam = ((pr - ar) * dr + (pz - az) * dz) / (dr * dr + dz * dz);
  if (lam < 0) lam = 0;
  if (lam > 1) lam = 1;
  const Big er = pr - ar - lam * dr, ez = pz - az - lam * dz;
  return boost::multiprecision::sqrt(er * er + ez * ez);
}
Big oracle_cone_sd(double R0, double H0, const Vec3& x) {
  const Big R = R0, H = H0, z = x[2];
  const Big rho = boost::multiprecision::sqrt(Big(x[0]) * x[0] + Big(x[1]) * x[1]);
  const Big fs = (2 * H * rho + R * z - R * H) / boost::multiprecision::sqrt(4 * H * H + R * R), fb = -z - H;
  if (fs <= 0 && fb <= 0) return fs > fb ? fs : fb;
  const Big a = segment_distance(rho, z, 0, H, R, -H), b = segment_distance(rho, z, R, -H, 0, -H);
  return a < b ? a : b;
}

// The spheroid ellipsoid(A, A, C): sd of its meridian ellipse, the max over θ ∈ [0, π/2] of
// ⟨u, p⟩ − h(u), u = (cos θ, sin θ), p = (ρ, |z|) — a 256-point grid, then golden sections
// around each grid local maximum, in 100 digits (the max is smooth or at an end: ~1e-40 in θ).
Big oracle_spheroid_sd(double A0, double C0, const Vec3& x) {
  const Big A = A0, C = C0, z = boost::multiprecision::abs(Big(x[2]));
  const Big rho = boost::multiprecision::sqrt(Big(x[0]) * x[0] + Big(x[1]) * x[1]);
  const Big half_pi = boost::multiprecision::acos(Big(0));
  const auto g = [&](const Big& th) {
    const Big c = boost::multiprecision::cos(th), s = boost::multiprecision::sin(th);
    return rho * c + z * s - boost::multiprecision::sqrt(A * A * c * c + C * C * s * s);
  };
  constexpr int kGrid = 256;
  std::vector<Big> v(kGrid + 1);
  for (int i = 0; i <= kGrid; ++i) v[i] = g(half_pi * i / kGrid);
  Big best = v[0];
  const Big phi = (boost::multiprecision::sqrt(Big(5)) - 1) / 2;
  for (int i = 0; i <= kGrid; ++i) {  // every grid local maximum refined (two near-equal maxima)
    if ((i > 0 && v[i] < v[i - 1]) || (i < kGrid && v[i] < v[i + 1])) continue;
    Big lo = half_pi * std::max(0, i - 1) / kGrid, hi = half_pi * std::min(kGrid, i + 1) / kGrid;
    for (int it = 0; it < 120; ++it) {
      const Big m1 = hi - phi * (hi - lo), m2 = lo + phi * (hi - lo);
      if (g(m1) < g(m2)) lo = m1;
      else hi = m2;
    }
    const Big m = g((lo + hi) / 2);
    best = std::max({best, v[i], m});
  }
  return best;
}

// The bracket holds the oracle and is at most 1e-12 relative wide (64 ulps of the scale at a
// contact, where sd ~ 0).
void expect_certified(const Distance3& s, const Big& ref, double scale, const std::string& what) {
  EXPECT_LE(Big(s.lower_bound), ref) << what;
  EXPECT_GE(Big(s.upper_bound), ref) << what;
  EXPECT_LE(s.upper_bound - s.lower_bound, std::max(1e-12 * std::abs(s.distance), 64 * 0x1p-53 * scale)) << what;
}

TEST(Curved, SphereOnConeAxisAgainstHighPrecisionOracle) {
  // The exact continuum (a ring of nearest points) EPA could not close (7e-7 after 4,800
  // supports): inside, near the apex, near the base, touching the apex and the base, apart.
  // P at the identity, Q translated only: the engine's relative pose is exact, the oracle one value.
  for (const auto& [R, H, r] : {std::array<double, 3>{1, 1, 0.2}, {0.6, 0.7, 0.1}, {0.12, 0.15, 0.01}}) {
    const Pair3 pair(Shape3::cone(R, H), Shape3::sphere(r)), swapped(Shape3::sphere(r), Shape3::cone(R, H));
    for (const double f : {-1.2, -0.999, -0.95, -0.3, 0.0, 0.5, 0.9, 0.999, 1.0, 1.2, 1.3}) {
      const double z = f * H + (f == 1.2 ? r - 0.2 * H : f == -1.2 ? 0.2 * H - r : 0.0);  // ±1.2: touching
      const Vec3 c(0, 0, z);
      const Big ref = oracle_cone_sd(R, H, c) - Big(r);
      const std::string what = "cone(" + std::to_string(R) + ", " + std::to_string(H) + ") z = " + std::to_string(z);
      const Distance3 s = pair.signed_distance(Pose3(), Pose3(c));
      expect_certified(s, ref, 1 + R + H, what);
      // The roles swapped: the ball at the identity, the cone moved by −c (an exact negation).
      expect_certified(swapped.signed_distance(Pose3(), Pose3(-c)), ref, 1 + R + H, what + " swapped");
      const Depth3 m = pair.minimum(Pose3(), Pose3(c));
      if (ref < 0) {
        ASSERT_TRUE(m.overlapping) << what;
        EXPECT_LE(Big(m.lower_bound), -ref) << what;
        EXPECT_GE(Big(m.upper_bound), -ref) << what;
        EXPECT_LE(m.upper_bound - m.lower_bound, std::max(1e-12 * m.depth, 64 * 0x1p-53 * (1 + R + H))) << what;
        Pose3 moved(c);  // the move separates, to touching within rounding
        moved.translation += m.translation;
        EXPECT_LE(std::abs(pair.signed_distance(Pose3(), moved).distance), 1e-14 * (1 + R + H)) << what;
      } else {
        EXPECT_FALSE(m.overlapping) << what;
      }
    }
  }
}

TEST(Curved, SphereOnSpheroidAxisAgainstHighPrecisionOracle) {
  // The same continuum on a spheroid's axis (prolate: the ring at the equator's height; oblate:
  // the poles nearest): inside, near the pole, touching, apart; either role.
  for (const auto& [A, C, r] : {std::array<double, 3>{1, 1.5, 0.2}, {1.5, 1, 0.2}, {0.3, 0.5, 0.05}}) {
    const Pair3 pair(Shape3::ellipsoid(A, A, C), Shape3::sphere(r)), swapped(Shape3::sphere(r), Shape3::ellipsoid(A, A, C));
    for (const double f : {0.0, 0.2, -0.5, 0.9, 0.999, 1.0, 1.1, 1.5}) {
      const Vec3 c(0, 0, f * C);
      const Big ref = oracle_spheroid_sd(A, C, c) - Big(r);
      const std::string what = "spheroid(" + std::to_string(A) + ", " + std::to_string(C) + ") z = " + std::to_string(c[2]);
      expect_certified(pair.signed_distance(Pose3(), Pose3(c)), ref, 1 + A + C, what);
      expect_certified(swapped.signed_distance(Pose3(), Pose3(-c)), ref, 1 + A + C, what + " swapped");
      const Depth3 m = pair.minimum(Pose3(), Pose3(c));
      EXPECT_EQ(m.overlapping, ref < 0) << what;
      if (!m.overlapping) continue;
      EXPECT_LE(Big(m.lower_bound), -ref) << what;
      EXPECT_GE(Big(m.upper_bound), -ref) << what;
      Pose3 moved(c);  // the move separates, to touching within rounding
      moved.translation += m.translation;
      EXPECT_LE(std::abs(pair.signed_distance(Pose3(), moved).distance), 1e-14 * (1 + A + C)) << what;
    }
  }
}

TEST(Curved, BallPairsAgainstHighPrecisionOracleAtRandomPlacements) {
  // Spheres, points ⊕ balls and points around a cone or a spheroid (either role), P at the identity and Q
  // translated (exact relative pose), plus rotated poses of Q (the ball's radius then within the
  // stretch of the double rotation: the oracle's bracket [ref − r·1e-15, ref + r·1e-15]).
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> size(0.05, 0.6), off(-1.0, 1.0);
  int overlapping = 0, apart = 0;
  for (int it = 0; it < 1200; ++it) {
    const double R = size(rng), H = size(rng), r = it % 5 == 0 ? 0.0 : size(rng) * 0.5;
    const bool cone = it % 4 < 2;  // else the spheroid ellipsoid(R, R, H)
    const Shape3 body = cone ? Shape3::cone(R, H) : Shape3::ellipsoid(R, R, H);
    const Vec3 q0 = it % 3 == 0 ? Vec3(Vec3(off(rng), off(rng), off(rng)) * 0.1) : Vec3(Vec3::Zero());
    const Shape3 ball = it % 5 == 0 ? Shape3::point(q0) : Shape3::rounded(Shape3::point(q0), r);
    const bool rotated = it % 2 == 1;
    const Pose3 pq(rotated ? random_pose(rng, 0).rotation.normalized() : Eigen::Quaterniond::Identity(),
                   Vec3(off(rng), off(rng), off(rng)) * (it % 4 < 2 ? 0.4 : 1.0));
    const Vec3 c = pq.apply(q0);  // the centre; rounded when rotated (the oracle's slack below)
    const Big ref = (cone ? oracle_cone_sd(R, H, c) : oracle_spheroid_sd(R, H, c)) - Big(r);
    const Big slack = rotated ? Big(1e-15) * (1 + c.norm()) : Big(q0 == Vec3::Zero() ? 0 : 1e-15);
    const std::string what = "it " + std::to_string(it);
    const Distance3 s = Pair3(body, ball).signed_distance(Pose3(), pq);
    EXPECT_LE(Big(s.lower_bound), ref + slack) << what;
    EXPECT_GE(Big(s.upper_bound), ref - slack) << what;
    EXPECT_LE(s.upper_bound - s.lower_bound, std::max(1e-12 * std::abs(s.distance), 64 * 0x1p-53 * (1 + c.norm()))) << what;
    // Swapped roles: the ball at the identity, the cone at the inverse pose.
    const Pose3 inv(pq.rotation.conjugate(), -(pq.rotation.conjugate() * pq.translation));
    const Distance3 w = Pair3(ball, body).signed_distance(Pose3(), inv);
    const Big slack_w = Big(1e-15) * (1 + c.norm());
    EXPECT_LE(Big(w.lower_bound), ref + slack_w) << what;
    EXPECT_GE(Big(w.upper_bound), ref - slack_w) << what;
    // (At a contact the floor is the double rotation's distance from an orthogonal one, η <=
    // 24u + max row sum of |R̃ᵀR̃ − I| (directed.hpp stretch), times the body's size and the
    // offset: 512 ulps here.)
    EXPECT_LE(w.upper_bound - w.lower_bound, std::max(1e-12 * std::abs(w.distance), 512 * 0x1p-53 * (1 + c.norm()))) << what;
    (ref < 0 ? overlapping : apart) += 1;
  }
  EXPECT_GT(overlapping, 200);
  EXPECT_GT(apart, 200);
}
TEST(Curved, SpheroidOffAxisBallsAgainstHighPrecisionOracle) {
  // The spheroid's maximiser found in doubles, then certified (ball3.cpp "The spheroid's meridian
  // ellipse"): random off-axis centres around oblate, prolate, flat (C/A down to 0.02), needle-like
  // and near-spherical (|C/A − 1| = 1e-3) spheroids — deep inside, near the surface (±1e-9 to ±0.1
  // of the size along the normal), apart — spheres and points, either role. P at the identity and
  // Q translated only: the relative pose is exact, the oracle one 100-digit value. Then the same
  // cases with the maximiser replaced by a wrong one (s = 0, 1/2, 1 in both halves): only the
  // certified boxes then stand between a wrong answer and the bracket.
  struct Case {
    double A, C, r;
    Vec3 c;
    Big ref;
  };
  std::vector<Case> cases;
  std::mt19937_64 rng(20261128);
  std::uniform_real_distribution<double> unit(0.0, 1.0), off(-1.0, 1.0);
  int inside = 0, outside = 0, near_surface = 0;
  for (int it = 0; it < 300; ++it) {
    const double A = 0.05 + unit(rng);
    const double C = it % 5 == 0 ? A * (it % 2 ? 1 + 1e-3 : 1 - 1e-3) : A * std::exp(std::log(0.02) + unit(rng) * 2 * std::log(50.0));
    const double r = it % 4 == 0 ? 0.0 : 0.3 * A * unit(rng);
    Vec3 c;
    if (it % 2 == 0) {  // a surface point (θ off the poles) moved along its normal
      const double th = 0.05 + unit(rng) * (kPi - 0.1), ph = unit(rng) * 2 * kPi;
      const Vec3 y(A * std::sin(th) * std::cos(ph), A * std::sin(th) * std::sin(ph), C * std::cos(th));
      const Vec3 n = Vec3(y[0] / (A * A), y[1] / (A * A), y[2] / (C * C)).normalized();
      const double d = std::array<double, 6>{1e-9, -1e-9, 1e-4, -1e-4, 0.1, -0.1}[it / 2 % 6] * std::max(A, C);
      c = y + (d + r) * n;
      ++near_surface;
    } else {  // anywhere in the box around it, off the axis
      c = Vec3(off(rng) * 1.5 * A, off(rng) * 1.5 * A, off(rng) * 1.5 * C);
    }
    ASSERT_GT(std::hypot(c[0], c[1]), 0) << it;
    cases.push_back({A, C, r, c, oracle_spheroid_sd(A, C, c) - Big(r)});
    (cases.back().ref < 0 ? inside : outside) += 1;
  }
  EXPECT_GT(inside, 90);
  EXPECT_GT(outside, 90);
  EXPECT_EQ(near_surface, 150);
  for (const double seed : {-1.0, 0.0, 0.5, 1.0}) {
    primitives::ellipse_seed = seed;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const auto& [A, C, r, c, ref] = cases[i];
      const Shape3 body = Shape3::ellipsoid(A, A, C), ball = r == 0 ? Shape3::point(Vec3::Zero()) : Shape3::sphere(r);
      const std::string what = "case " + std::to_string(i) + " seed " + std::to_string(seed) + " spheroid(" + std::to_string(A) + ", " +
                               std::to_string(C) + ")";
      const double scale = 1 + A + C + c.norm();
      expect_certified(Pair3(body, ball).signed_distance(Pose3(), Pose3(c)), ref, scale, what);
      expect_certified(Pair3(ball, body).signed_distance(Pose3(), Pose3(Vec3(-c))), ref, scale, what + " swapped");
    }
  }
  primitives::ellipse_seed = -1;
}

TEST(Curved, BallPairsInsideTheNestedTessellationsAndTheEpaBracket) {
  // Random poses of both shapes (the cone's axis anywhere in the world): the closed form must meet
  // EPA's own bracket (the pre-step switched off) and the polytope brackets I ⊆ cone ⊆ O, and
  // cylinders against off-centre rounded points (the coaxial form declines those) likewise.
  std::mt19937_64 rng(31);
  const Curved cone{K::Cone, 0.3, 0.25, 0}, cyl{K::Cyl, 0.2, 0.3, 0}, spheroid{K::Ell, 0.3, 0.3, 0.2};
  int checked = 0, narrower = 0;
  for (const Curved& k : {cone, cyl, spheroid}) {
    const int n = k.k == K::Ell ? 24 : 64;  // (the ellipsoid's grid has 2n(n − 1) + 2 points)
    const Shape3 in = tessellation(k, n, false), out = tessellation(k, n, true);
    verify_nesting(k, in, out);
    for (const Shape3& ball : {Shape3::sphere(0.1), Shape3::rounded(Shape3::point(Vec3(0.03, -0.02, 0.05)), 0.07),
                               Shape3::point(Vec3(0.01, 0.02, 0))}) {
      for (const bool swap : {false, true}) {
        const Pair3 pair = swap ? Pair3(ball, k.shape()) : Pair3(k.shape(), ball);
        const Pair3 inner = swap ? Pair3(ball, in) : Pair3(in, ball), outer = swap ? Pair3(ball, out) : Pair3(out, ball);
        for (int it = 0; it < 25; ++it) {
          const Pose3 pp = random_pose(rng, 0.3), pq = random_pose(rng, 0.3);
          const Distance3 s = pair.signed_distance(pp, pq);
          const Depth3 m = pair.minimum(pp, pq);
          EXPECT_LE(s.lower_bound, inner.signed_distance(pp, pq).distance + 1e-15) << it;
          EXPECT_GE(s.upper_bound, outer.signed_distance(pp, pq).distance - 1e-15) << it;
          EXPECT_GE(m.upper_bound, inner.minimum(pp, pq).depth - 1e-15) << it;
          EXPECT_LE(m.lower_bound, outer.minimum(pp, pq).depth + 1e-15) << it;
          struct Off {
            Off() { primitives::ball_enabled = false; }
            ~Off() { primitives::ball_enabled = true; }
          };
          Distance3 e;
          Depth3 em;
          {
            const Off off;
            e = pair.signed_distance(pp, pq), em = pair.minimum(pp, pq);
          }
          EXPECT_LE(s.lower_bound, e.upper_bound) << it;
          EXPECT_GE(s.upper_bound, e.lower_bound) << it;
          const double scale = 1 + (pq.translation - pp.translation).norm();
          EXPECT_LE(s.upper_bound - s.lower_bound, std::max(1e-12 * std::abs(s.distance), 512 * 0x1p-53 * scale)) << it;
          narrower += s.upper_bound - s.lower_bound <= e.upper_bound - e.lower_bound;
          EXPECT_EQ(m.overlapping, s.overlapping) << it;
          ++checked;
          if (!m.overlapping || !em.overlapping) continue;
          EXPECT_LE(m.lower_bound, em.upper_bound) << it;
          EXPECT_GE(m.upper_bound, em.lower_bound) << it;
          Pose3 moved = pq;  // the move separates (to touching within rounding)
          moved.translation += m.translation * (1 + 1e-12);
          EXPECT_GE(pair.signed_distance(pp, moved).upper_bound, 0) << it;
        }
      }
    }
  }
  EXPECT_EQ(checked, 3 * 3 * 2 * 25);
  std::printf("ball pairs: the closed form's bracket no wider than EPA's in %d of %d\n", narrower, checked);
}

// ---- near-coaxial pairs to 1e-12 (docs/robustness.md "A continuum of nearest points") ---------
// The centred cylinder(1, 1) in the rounded cylinder(1, 1) ⊕ 0.5, Q tilted by ε about a
// horizontal axis. Oracle: for unit u, h_P(u) = |u_xy| + |u_z| >= 1 and, with w = −R̃ᵀu (R̃ the
// engine's double rotation), h_Q(w) = |w_xy| + |w_z| + 0.5|w| >= 1.5|w| >= 1.5·(1 − η), η >= the
// distance of R̃'s singular values from 1 (bounded here in 100 digits by Σ|R̃ᵀR̃ − I|); a
// horizontal u with ⟨u, R̃e_z⟩ = 0 attains h_P(u) = 1, h_Q(w) <= 1.5·(1 + η). So σ lies in
// [2.5 − 1.5η, 2.5 + 1.5η] (η ~ 1e-16), and the claim is a gap <= 1e-12·σ at every tilt from
// 1e-3 to 1e-12 (the second-order ring bound of coaxial3.cpp for the lower end, the searched upper
// end; before it, ε between ~1.2e-12 and ~3e-7 stayed ~0.8ε wide).
Big stretch_eta(const Eigen::Matrix3d& R) {
  Big eta = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Big g = i == j ? Big(-1) : Big(0);
      for (int k = 0; k < 3; ++k) g += Big(R(k, i)) * R(k, j);
      eta += boost::multiprecision::abs(g);
    }
  return eta;  // |σ_i² − 1| <= η, so |σ_i − 1| <= η
}

TEST(Curved, NearCoaxialCentredPairMeetsTheContract) {
  const Pair3 pair(Shape3::cylinder(1, 1), Shape3::rounded(Shape3::cylinder(1, 1), 0.5));
  std::mt19937_64 rng(1812);
  std::uniform_real_distribution<double> A(0, 2 * kPi);
  for (double eps : {1e-3, 1e-4, 1e-5, 1e-6, 3e-7, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1.2e-12, 1e-12}) {
    for (int k = 0; k < 6; ++k) {
      const double phi = A(rng);
      const Pose3 pq(Eigen::Quaterniond(Eigen::AngleAxisd(eps, Vec3(std::cos(phi), std::sin(phi), 0))), Vec3::Zero());
      const Big eta = stretch_eta(pq.matrix());
      ASSERT_LT(eta, Big(1e-14));
      const Big lo = Big(2.5) - Big(1.5) * eta, hi = Big(2.5) + Big(1.5) * eta;
      const Depth3 m = pair.minimum(Pose3(), pq);
      const Distance3 d = pair.signed_distance(Pose3(), pq);
      ASSERT_TRUE(m.overlapping && d.overlapping) << eps;
      EXPECT_LE(Big(m.lower_bound), hi) << eps << " " << k;
      EXPECT_GE(Big(m.upper_bound), lo) << eps << " " << k;
      EXPECT_LE(Big(d.lower_bound), -lo) << eps << " " << k;
      EXPECT_GE(Big(d.upper_bound), -hi) << eps << " " << k;
      EXPECT_LE(m.upper_bound - m.lower_bound, 1e-12 * m.depth) << eps << " " << k;
      EXPECT_LE(d.upper_bound - d.lower_bound, 1e-12 * -d.distance) << eps << " " << k;
      Pose3 moved = pq;  // the reported move separates (to touching, within rounding)
      moved.translation += m.translation * (1 + 1e-12);
      EXPECT_GE(pair.signed_distance(Pose3(), moved).upper_bound, 0) << eps;
    }
  }
}

TEST(Curved, NearCoaxialCentredRandomPairsAgainstHighPrecisionOracle) {
  // Centred (t = 0) random pairs of cylinders, rounded cylinders and capsules with R <= H (a
  // capsule: R = 0), Q tilted by 10^−U(3, 12) about a random horizontal axis after an axial
  // rotation. Oracle (100 digits, independent of the ring bound's regions): for unit u,
  // |u_xy| + |u_z| >= 1 and R <= H give h_P(u) >= R_P + r_P, and with v = −R̃ᵀu,
  // h_Q(v) >= (R_Q + r_Q)|v| >= (R_Q + r_Q)(1 − η); the horizontal u orthogonal to R̃e_z attains
  // h_P = R_P + r_P and h_Q <= (R_Q + r_Q)(1 + η). So σ ∈ [R_P + r_P + (R_Q + r_Q)(1 ∓ η)]. The
  // bracket must hold that interval's points, meet EPA alone (pre-step off), be <= 1e-12·σ wide,
  // and its move must separate.
  std::mt19937_64 rng(1816);
  std::uniform_real_distribution<double> size(0.05, 0.6), L(3, 12), A(0, 2 * kPi);
  struct Sized {
    Shape3 shape;
    double R, r;
  };
  const auto pick = [&] {
    const double a = size(rng), b = size(rng), c = size(rng);
    const double R = std::min(a, b), H = std::max(a, b);
    switch (std::uniform_int_distribution<int>(0, 2)(rng)) {
      case 0: return Sized{Shape3::cylinder(R, H), R, 0};
      case 1: return Sized{Shape3::rounded(Shape3::cylinder(R, H), c), R, c};
      default: return Sized{Shape3::capsule(c, H), 0, c};
    }
  };
  int checked = 0;
  for (int it = 0; it < 40; ++it) {
    const Sized P = pick(), Q = pick();
    if (!P.shape.curved() && !Q.shape.curved()) continue;  // two capsules: the rounded engine
    const double eps = std::pow(10.0, -L(rng)), phi = A(rng);
    const Eigen::Quaterniond tilt(Eigen::AngleAxisd(eps, Vec3(std::cos(phi), std::sin(phi), 0)));
    const Pose3 pq(tilt * axial_rotation(rng), Vec3::Zero());
    const Pair3 pair(P.shape, Q.shape);
    const Big eta = stretch_eta(pq.matrix());
    const Big base = Big(P.R) + P.r, q = Big(Q.R) + Q.r;
    const Big lo = base + q * (1 - eta), hi = base + q * (1 + eta);
    const Depth3 m = pair.minimum(Pose3(), pq);
    const Distance3 d = pair.signed_distance(Pose3(), pq);
    ASSERT_TRUE(m.overlapping && d.overlapping) << it;
    EXPECT_LE(Big(m.lower_bound), hi) << it << " eps " << eps;
    EXPECT_GE(Big(m.upper_bound), lo) << it << " eps " << eps;
    EXPECT_LE(Big(d.lower_bound), -lo) << it << " eps " << eps;
    EXPECT_GE(Big(d.upper_bound), -hi) << it << " eps " << eps;
    EXPECT_LE(m.upper_bound - m.lower_bound, 1e-12 * m.depth) << it << " eps " << eps << " ends − ref: " << double(Big(m.lower_bound) - lo) << ", " << double(Big(m.upper_bound) - lo);
    EXPECT_LE(d.upper_bound - d.lower_bound, 1e-12 * -d.distance) << it << " eps " << eps;
    if (it % 4 == 0) {  // EPA alone (certified, ~4,800 supports): the brackets meet
      const auto [em, ed] = without_closed_form(pair, pq);
      EXPECT_LE(m.lower_bound, em.upper_bound) << it;
      EXPECT_GE(m.upper_bound, em.lower_bound) << it;
      EXPECT_LE(d.lower_bound, ed.upper_bound) << it;
      EXPECT_GE(d.upper_bound, ed.lower_bound) << it;
    }
    Pose3 moved = pq;
    moved.translation += m.translation * (1 + 1e-12);
    EXPECT_GE(pair.signed_distance(Pose3(), moved).upper_bound, 0) << it;
    ++checked;
  }
  EXPECT_GT(checked, 30);
}

TEST(Curved, NearCoaxialOffCentrePairsInsideTheNestedTessellations) {
  // Off-centre placements (isolated nearest points) and near-centred ones (|t| ~ 1e-6 … 1e-12,
  // where the ring of almost-nearest directions is broken only by t and the tilt: the ring bound
  // of coaxial3.cpp), tilts 1e-3 … 1e-12: the bracket meets the polygon prisms' (I ⊆ cylinder ⊆ O
  // through the exact engines, 96 segments) and is <= 1e-12·σ.
  const Curved c{K::Cyl, 1, 1, 0};
  const Shape3 in = tessellation(c, 96, false), out = tessellation(c, 96, true);
  verify_nesting(c, in, out);
  const Pair3 pair(c.shape(), Shape3::rounded(c.shape(), 0.5));
  const Pair3 inner(in, Shape3::rounded(in, 0.5)), outer(out, Shape3::rounded(out, 0.5));
  std::mt19937_64 rng(1813);
  std::uniform_real_distribution<double> U(-0.2, 0.2), A(0, 2 * kPi);
  for (double eps : {1e-3, 1e-6, 1e-9, 1e-12}) {
    for (int k = 0; k < 12; ++k) {
      const double phi = A(rng), scale = k < 6 ? 1.0 : std::pow(10.0, -2.0 * k + 6);  // 1e-6 … 1e-16 (× 0.2)
      const Pose3 pq(Eigen::Quaterniond(Eigen::AngleAxisd(eps, Vec3(std::cos(phi), std::sin(phi), 0))),
                     Vec3(U(rng), U(rng), U(rng)) * scale);
      const Depth3 m = pair.minimum(Pose3(), pq);
      ASSERT_TRUE(m.overlapping);
      EXPECT_GE(m.upper_bound, inner.minimum(Pose3(), pq).depth - 1e-15) << eps << " " << k;
      EXPECT_LE(m.lower_bound, outer.minimum(Pose3(), pq).depth + 1e-15) << eps << " " << k;
      EXPECT_LE(m.upper_bound - m.lower_bound, 1e-12 * m.depth) << eps << " " << k;
    }
  }
}

TEST(Curved, NearCoaxialRandomPairsMeetEpaAndTheTiltBound) {
  // Random decomposable pairs, Q tilted by 10^−U(3, 12) about a random horizontal axis after an
  // axial rotation, offsets near and far (past the first 300: |t| ~ 1e-2 … 1e-12, where the ring
  // bound of coaxial3.cpp is what closes the bracket, on every size ratio of the family): the
  // answer (closed form ∩ ring bound ∩ search ∩ EPA) must meet EPA alone (pre-step off; both
  // certified), meet 1e-12 or be no wider than EPA alone, and never be NaN.
  std::mt19937_64 rng(1815);
  std::uniform_real_distribution<double> off(-0.6, 0.6), L(3, 12), A(0, 2 * kPi);
  int overlapping = 0;
  for (int it = 0; it < 450; ++it) {
    const bool p_solid = it % 2 == 0;
    const Axial P = random_axial(rng, p_solid), Q = random_axial(rng, !p_solid);
    if (!P.shape.curved() && !Q.shape.curved()) continue;
    const double eps = std::pow(10.0, -L(rng)), phi = A(rng);
    const Eigen::Quaterniond tilt(Eigen::AngleAxisd(eps, Vec3(std::cos(phi), std::sin(phi), 0)));
    const double offset = it >= 300 ? std::pow(10.0, -2 - it % 11) : it % 3 == 0 ? 0.05 : 1.0;
    const Pose3 pq(tilt * axial_rotation(rng), Vec3(off(rng), off(rng), off(rng)) * offset);
    const Pair3 pair(P.shape, Q.shape);
    const Distance3 s = pair.signed_distance(Pose3(), pq);
    const Depth3 m = pair.minimum(Pose3(), pq);
    const auto [em, e] = without_closed_form(pair, pq);
    ASSERT_FALSE(std::isnan(s.lower_bound) || std::isnan(s.upper_bound) || std::isnan(m.lower_bound) || std::isnan(m.upper_bound)) << it;
    ASSERT_LE(s.lower_bound, s.upper_bound) << it;
    EXPECT_LE(s.lower_bound, e.upper_bound) << it;
    EXPECT_GE(s.upper_bound, e.lower_bound) << it;
    // The contract (1e-12 relative to a few ulps of the pair's size), or no wider than EPA alone
    // (its budget may be longer than the one the near-coaxial path grants it).
    const double scale = 1 + pq.translation.norm();
    const auto target = [&](double lo, double hi) { return 1e-12 * std::max(std::abs(lo), std::abs(hi)) + 64 * 0x1p-53 * scale; };
    EXPECT_LE(s.upper_bound - s.lower_bound, std::max(e.upper_bound - e.lower_bound, target(s.lower_bound, s.upper_bound))) << it;
    if (!m.overlapping || !em.overlapping) continue;
    ++overlapping;
    EXPECT_LE(m.lower_bound, em.upper_bound) << it;
    EXPECT_GE(m.upper_bound, em.lower_bound) << it;
    EXPECT_LE(m.upper_bound - m.lower_bound, std::max(em.upper_bound - em.lower_bound, target(m.lower_bound, m.upper_bound))) << it;
  }
  EXPECT_GT(overlapping, 60);
}

TEST(Curved, NearSphericalEllipsoidClosesPastSixHundredSupports) {
  // A generic near-continuum (no closed form): ellipsoid(1, 1, 1 + 1e-7) ⊕ sphere(0.5) near the
  // centre, where EPA stopped at 600 supports 4e-7 mean / 4e-5 worst wide. Oracle: B(1) ⊆ E ⊆
  // B(1 + 1e-7), so σ lies between the exact sphere pairs' (the rounded engine).
  const Pair3 pair(Shape3::ellipsoid(1, 1, 1 + 1e-7), Shape3::sphere(0.5));
  const Pair3 small(Shape3::sphere(1), Shape3::sphere(0.5)), big(Shape3::sphere(1 + 1e-7), Shape3::sphere(0.5));
  std::mt19937_64 rng(1814);
  std::uniform_real_distribution<double> U(-0.12, 0.12);
  for (int k = 0; k < 40; ++k) {
    const Pose3 pq(random_pose(rng, 1).rotation, Vec3(U(rng), U(rng), U(rng)));
    const Depth3 m = pair.minimum(Pose3(), pq);
    ASSERT_TRUE(m.overlapping);
    EXPECT_GE(m.upper_bound, small.minimum(Pose3(), pq).lower_bound) << k;
    EXPECT_LE(m.lower_bound, big.minimum(Pose3(), pq).upper_bound) << k;
    EXPECT_LE(m.upper_bound - m.lower_bound, 1e-12 * m.depth) << k;
  }
}

}  // namespace
}  // namespace pendepth

// directed.hpp's inline next_dn / next_up (bit steps) against std::nextafter: every special
// value (±0, ±denorm_min, ±min normal, ±max, ±∞, NaN) and 10⁶ random bit patterns.
TEST(Curved, DirectedStepsEqualNextafter) {
  namespace d = pendepth::primitives::directed;
  using L = std::numeric_limits<double>;
  auto same = [](double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) || (a != a && b != b); };
  std::vector<double> xs = {0.0, -0.0, L::denorm_min(), -L::denorm_min(), L::min(), -L::min(), L::max(), -L::max(),
                            L::infinity(), -L::infinity(), L::quiet_NaN(), 1.0, -1.0, 0x1p-1022 - 0x1p-1074};
  std::mt19937_64 rng(20261128);
  for (int i = 0; i < 1000000; ++i) xs.push_back(std::bit_cast<double>(rng()));
  int bad = 0;
  for (double x : xs) {
    if (!same(d::next_dn(x), std::nextafter(x, -L::infinity()))) ++bad;
    if (!same(d::next_up(x), std::nextafter(x, L::infinity()))) ++bad;
  }
  EXPECT_EQ(bad, 0);
}
