// 3D primitives on the front door (Shape3::box / sphere / capsule / rounded; src/primitives/
// rounded3.cpp) against closed forms: sphere–sphere (distance of the centres; the ray's exit and
// entry of a ball by the quadratic formula), box–sphere (the box's signed distance field),
// capsule–capsule (the segments' distance by an independent long-double minimisation), and
// rounded hulls against the core pair's exact answer minus the radii. Properties: σ <= σ_d,
// moving Q by σ's or σ_d's translation or the cast's leaves the pair touching, the cast from the
// far side equals the exit, batch = single, errors.
#include <gtest/gtest.h>

#include <pendepth/pendepth.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include "test_rotations.hpp"

namespace pendepth {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_unit_quaternion(rng); }

// |a − b| within `ulps` ulps of the larger magnitude `scale` (absolute: closed forms are evaluated
// in doubles too, so both sides carry rounding of the coordinates' size).
void expect_close(double a, double b, double scale, const std::string& what, double ulps = 16) {
  EXPECT_LE(std::abs(a - b), ulps * kEps * std::max({scale, std::abs(a), std::abs(b)})) << what << ": " << a << " vs " << b;
}

// Checks shared by every primitive pair at one pose: σ <= σ_d, the moves touch, the cast from the
// far side is the exit, sd continuous through contact (sign of sd agrees with overlapping).
void properties(const Pair3& pair, const Pose3& pq, const Vec3& d, double scale, const std::string& what) {
  const Pose3 pp;
  const Distance3 sd = pair.signed_distance(pp, pq);
  const Depth3 m = pair.minimum(pp, pq);
  EXPECT_EQ(m.overlapping, sd.distance < 0) << what;
  EXPECT_EQ(pair.overlapping(pp, pq), m.overlapping) << what;
  if (m.overlapping) {
    expect_close(m.depth, -sd.distance, scale, what + " σ = −sd", 1);
    Pose3 moved = pq;
    moved.translation += m.translation;
    EXPECT_LE(std::abs(pair.signed_distance(pp, moved).distance), 64 * kEps * scale) << what << ": σ move";
    const Depth3 a = pair.along(pp, pq, d);
    ASSERT_TRUE(a.overlapping) << what;
    EXPECT_LE(m.depth, a.depth * (1 + 16 * kEps)) << what << ": σ > σ_d";
    moved = pq;
    moved.translation += a.translation;
    EXPECT_LE(std::abs(pair.signed_distance(pp, moved).distance), 64 * kEps * scale) << what << ": σ_d move";
    // From the far side, the cast enters where the exit was.
    const double far = a.depth + scale;
    Pose3 start = pq;
    start.translation += far * d.normalized();
    const Cast3 c = pair.cast(pp, start, -d);
    ASSERT_TRUE(c.hit) << what;
    expect_close(c.distance, far - a.depth, scale, what + " cast from the far side", 64);
  } else {
    const Cast3 c = pair.cast(pp, pq, d);
    if (c.hit && c.distance > 0) {
      Pose3 moved = pq;
      moved.translation += c.translation;
      EXPECT_LE(std::abs(pair.signed_distance(pp, moved).distance), 64 * kEps * scale) << what << ": cast move";
      EXPECT_LE(c.normal.dot(d), 1e-12) << what;
    }
  }
}

TEST(Primitives3, SphereSphereClosedForm) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(-1, 1), R(0.1, 0.8);
  for (int k = 0; k < 300; ++k) {
    const double r1 = R(rng), r2 = R(rng);
    const Pair3 pair(Shape3::sphere(r1), Shape3::sphere(r2));
    const Vec3 w(U(rng), U(rng), U(rng)), d(U(rng), U(rng), U(rng));
    const Pose3 pq(random_rotation(rng), w);
    const std::string what = "sphere–sphere " + std::to_string(k);
    const double r = r1 + r2;
    expect_close(pair.signed_distance(Pose3(), pq).distance, w.norm() - r, 2, what + " sd", 4);
    const Vec3 dh = d.normalized();
    const double b = w.dot(dh), disc = b * b - w.squaredNorm() + r * r;
    const Depth3 a = pair.along(Pose3(), pq, d);
    if (w.norm() < r) {
      expect_close(a.depth, -b + std::sqrt(disc), 2, what + " σ_d");
      expect_close(pair.minimum(Pose3(), pq).depth, r - w.norm(), 2, what + " σ");
    }
    const Cast3 c = pair.cast(Pose3(), pq, d);
    const bool hit = w.norm() <= r || (disc > 1e-9 && b < 0);
    if (disc > 1e-9 || w.norm() <= r) {  // away from grazing rays
      ASSERT_EQ(c.hit, hit) << what;
      if (hit && w.norm() > r) expect_close(c.distance, -b - std::sqrt(disc), 2, what + " cast");
    }
    properties(pair, pq, d, 2, what);
  }
}

double box_sd(const Vec3& p, const Vec3& h) {
  const Vec3 q = p.cwiseAbs() - h;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

TEST(Primitives3, BoxSphereClosedForm) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> U(-1.5, 1.5), H(0.2, 1), R(0.05, 0.5);
  for (int k = 0; k < 300; ++k) {
    const Vec3 h(H(rng), H(rng), H(rng));
    const double r = R(rng);
    const Pair3 pair(Shape3::box(h.x(), h.y(), h.z()), Shape3::sphere(r));
    const Pair3 swapped(Shape3::sphere(r), Shape3::box(h.x(), h.y(), h.z()));
    const Vec3 c(U(rng), U(rng), U(rng)), d(U(rng), U(rng), U(rng));
    const std::string what = "box–sphere " + std::to_string(k);
    const double sd = box_sd(c, h) - r;
    expect_close(pair.signed_distance(Pose3(), Pose3(c)).distance, sd, 3, what + " sd", 8);
    expect_close(swapped.signed_distance(Pose3(), Pose3(-c)).distance, sd, 3, what + " sd swapped", 8);
    properties(pair, Pose3(random_rotation(rng), c), d, 3, what);
    properties(swapped, Pose3(random_rotation(rng), -c), d, 3, what + " swapped");
  }
  // Touching exactly: a sphere resting on a face, on an edge (45°: not exact), at a corner.
  const Pair3 pair(Shape3::box(1, 1, 1), Shape3::sphere(0.5));
  EXPECT_EQ(pair.signed_distance(Pose3(), Pose3(Vec3(0, 0, 1.5))).distance, 0);
  EXPECT_FALSE(pair.overlapping(Pose3(), Pose3(Vec3(0.25, -0.5, 1.5))));
  EXPECT_EQ(pair.minimum(Pose3(), Pose3(Vec3(0, 0, 1.25))).depth, 0.25);
  EXPECT_EQ(pair.along(Pose3(), Pose3(Vec3(0, 0, 1.25)), Vec3(0, 0, 3)).depth, 0.25);
  EXPECT_EQ(pair.cast(Pose3(), Pose3(Vec3(0, 0, 4)), Vec3(0, 0, -1)).distance, 2.5);
}

// σ_d and the cast of a sphere against a box against the exit / entry of the ray from the
// rounded box, found by bisection in long double on the convex sd_box(c + s·d̂) − r (an oracle
// independent of pendepth's Newton iteration): within 8 ulps of the scale where the ray crosses
// ∂M transversally (|sd slope| > 0.05).
TEST(Primitives3, BoxSphereRayAgainstBisection) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(-1.5, 1.5), H(0.2, 1), R(0.05, 0.5);
  using LV = Eigen::Matrix<long double, 3, 1>;
  auto box_sd_l = [](const LV& p, const LV& h) {
    const LV q = p.cwiseAbs() - h;
    return q.cwiseMax(0.0L).norm() + std::min(q.maxCoeff(), 0.0L);
  };
  int exits = 0, entries = 0;
  for (int k = 0; k < 300; ++k) {
    const Vec3 h(H(rng), H(rng), H(rng));
    const double r = R(rng);
    const Pair3 pair(Shape3::box(h.x(), h.y(), h.z()), Shape3::sphere(r));
    const Vec3 c(U(rng), U(rng), U(rng)), d(U(rng), U(rng), U(rng));
    const LV cl = c.cast<long double>(), dl = d.cast<long double>().normalized(), hl = h.cast<long double>();
    auto f = [&](long double s) { return box_sd_l(cl + s * dl, hl) - r; };
    auto root = [&](long double lo, long double hi) {  // f(lo), f(hi) of opposite signs
      const bool up = f(lo) < 0;
      for (int i = 0; i < 200; ++i) {
        const long double mid = (lo + hi) / 2;
        ((f(mid) < 0) == up ? lo : hi) = mid;
      }
      return (lo + hi) / 2;
    };
    auto slope = [&](long double s) { return (f(s + 1e-7L) - f(s - 1e-7L)) / 2e-7L; };
    const std::string what = "box–sphere ray " + std::to_string(k);
    if (f(0) < 0) {
      const long double s = root(0, 10);
      if (std::abs(slope(s)) < 0.05L) continue;
      ++exits;
      expect_close(pair.along(Pose3(), Pose3(c), d).depth, static_cast<double>(s), 4, what + " σ_d", 8);
    } else if (f(0) > 0) {
      long double lo = 0, hi = 10;  // the minimiser of the convex f, golden section
      for (int i = 0; i < 200; ++i) {
        const long double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        (f(m1) < f(m2) ? hi : lo) = f(m1) < f(m2) ? m2 : m1;
      }
      const Cast3 cast = pair.cast(Pose3(), Pose3(c), d);
      if (f(lo) > 1e-6L) {
        EXPECT_FALSE(cast.hit) << what;
        continue;
      }
      if (f(lo) > -1e-6L) continue;  // nearly grazing
      const long double s = root(0, lo);
      if (std::abs(slope(s)) < 0.05L) continue;
      ++entries;
      ASSERT_TRUE(cast.hit) << what;
      expect_close(cast.distance, static_cast<double>(s), 4, what + " cast", 8);
    }
  }
  EXPECT_GT(exits, 50);
  EXPECT_GT(entries, 30);
}

// Distance of segments [a0, a1] and [b0, b1] by nested golden-section searches in long double
// (the distance is convex in both parameters): an algorithm independent of pendepth's.
long double seg_seg(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  using V = Eigen::Matrix<long double, 3, 1>;
  const V A0 = a0.cast<long double>(), A1 = a1.cast<long double>(), B0 = b0.cast<long double>(), B1 = b1.cast<long double>();
  auto inner = [&](long double s) {  // exact closest point on segment B to A(s)
    const V p = A0 + s * (A1 - A0), e = B1 - B0;
    const long double t = std::clamp((p - B0).dot(e) / e.squaredNorm(), 0.0L, 1.0L);
    return (p - (B0 + t * e)).norm();
  };
  long double lo = 0, hi = 1;
  for (int k = 0; k < 200; ++k) {
    const long double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (inner(m1) < inner(m2)) hi = m2;
    else lo = m1;
  }
  return std::min({inner(lo), inner(0), inner(1)});
}

TEST(Primitives3, CapsuleCapsuleAgainstSegmentDistance) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1, 1), R(0.05, 0.4), H(0.1, 0.8);
  for (int k = 0; k < 200; ++k) {
    const double r1 = R(rng), r2 = R(rng), h1 = H(rng), h2 = H(rng);
    const Pair3 pair(Shape3::capsule(r1, h1), Shape3::capsule(r2, h2));
    const Pose3 pp = k % 2 ? Pose3(random_rotation(rng), Vec3(U(rng), U(rng), U(rng)) * 0.2) : Pose3();
    const Pose3 pq(random_rotation(rng), Vec3(U(rng), U(rng), U(rng)));
    const Vec3 a0 = pp.apply(Vec3(0, 0, -h1)), a1 = pp.apply(Vec3(0, 0, h1));
    const Vec3 b0 = pq.apply(Vec3(0, 0, -h2)), b1 = pq.apply(Vec3(0, 0, h2));
    const double expect = static_cast<double>(seg_seg(a0, a1, b0, b1)) - (r1 + r2);
    const std::string what = "capsule–capsule " + std::to_string(k);
    EXPECT_NEAR(pair.signed_distance(pp, pq).distance, expect, 1e-13) << what;
    if (k % 2 == 0) properties(pair, pq, Vec3(U(rng), U(rng), U(rng)), 3, what);
  }
  // Parallel capsules side by side (touching along a segment) and crossing at right angles.
  const Pair3 pair(Shape3::capsule(0.5, 1), Shape3::capsule(0.25, 2));
  EXPECT_EQ(pair.signed_distance(Pose3(), Pose3(Vec3(0.75, 0, 0.5))).distance, 0);
  EXPECT_EQ(pair.signed_distance(Pose3(), Pose3(Vec3(1, 0, 0.5))).distance, 0.25);
  EXPECT_EQ(pair.minimum(Pose3(), Pose3(Vec3(0.5, 0, 3))).depth, 0.25);  // the caps' ends 0.5 apart
  const Eigen::Quaterniond quarter(std::sqrt(0.5), std::sqrt(0.5), 0, 0);  // axis z → −y
  const double cross = pair.signed_distance(Pose3(), Pose3(quarter, Vec3(2, 0, 0))).distance;
  EXPECT_NEAR(cross, 2 - 0.75, 4 * kEps);
}

TEST(Primitives3, RoundedHullsAreCoreMinusRadius) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> U(-1, 1), R(0.01, 0.3);
  for (int k = 0; k < 60; ++k) {
    std::vector<Vec3> a, b;
    for (int i = 0; i < 10; ++i) a.emplace_back(U(rng), U(rng), U(rng)), b.emplace_back(U(rng), U(rng), 0.5 * U(rng));
    const Shape3 A = Shape3::hull(a), B = k % 3 == 0 ? Shape3::flat(std::vector<Vec3>{b[0], b[1], b[2]}) : Shape3::hull(b);
    const double ra = R(rng), rb = k % 2 ? R(rng) : 0.0;
    const Pair3 core(A, B), rounded(Shape3::rounded(A, ra), Shape3::rounded(B, rb));
    const Pose3 pq(random_rotation(rng), 2.5 * Vec3(U(rng), U(rng), U(rng)));
    const Vec3 d(U(rng), U(rng), U(rng));
    const Distance3 c = core.signed_distance(Pose3(), pq), s = rounded.signed_distance(Pose3(), pq);
    const std::string what = "rounded " + std::to_string(k);
    EXPECT_EQ(s.distance, c.distance - (ra + rb)) << what;  // one rounding from the exact core value
    if (s.distance != 0) {
      EXPECT_NEAR(s.normal.norm(), 1, 8 * kEps) << what;
      EXPECT_LE((s.witness_q - s.witness_p - s.distance * s.normal).norm(), 1e-12) << what;
    }
    properties(rounded, pq, d, 4, what);
  }
}

TEST(Primitives3, BatchScaleAndErrors) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  for (double sc : {1.0, 0x1p-300, 0x1p200}) {
    const Pair3 pair(Shape3::capsule(0.3 * sc, 0.5 * sc), Shape3::box(0.2 * sc, 0.4 * sc, 0.3 * sc));
    const Pair3 unit(Shape3::capsule(0.3, 0.5), Shape3::box(0.2, 0.4, 0.3));
    std::vector<Pose3> poses;
    for (int i = 0; i < 30; ++i) poses.emplace_back(random_rotation(rng), sc * Vec3(U(rng), U(rng), U(rng)));
    std::vector<Depth3> out(poses.size());
    std::vector<Distance3> dout(poses.size());
    pair.minimum(poses, out, 2);
    pair.signed_distance(poses, dout, 2);
    for (std::size_t i = 0; i < poses.size(); ++i) {
      EXPECT_EQ(out[i].depth, pair.minimum(Pose3(), poses[i]).depth);
      EXPECT_EQ(dout[i].distance, pair.signed_distance(Pose3(), poses[i]).distance);
      const Pose3 pu(poses[i].rotation, poses[i].translation / sc);
      EXPECT_EQ(dout[i].distance, sc * unit.signed_distance(Pose3(), pu).distance);
    }
  }
  EXPECT_THROW(Shape3::sphere(0), InvalidInput);
  EXPECT_THROW(Shape3::sphere(-1), InvalidInput);
  EXPECT_THROW(Shape3::capsule(1, NAN), InvalidInput);
  EXPECT_THROW(Shape3::box(1, 0, 1), InvalidInput);
  EXPECT_THROW(Shape3::rounded(Shape3::sphere(1), 1), InvalidInput);
  const std::vector<Vec3> tri = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  EXPECT_NO_THROW(Pair3(Shape3::rounded(Shape3::flat(tri), 0.1), Shape3::capsule(1, 1)));  // cores 2 + 1
  EXPECT_NO_THROW(Pair3(Shape3::rounded(Shape3::flat(tri), 0.1), Shape3::sphere(1)));
  EXPECT_EQ(Shape3::sphere(2).dimension(), 3);
  EXPECT_EQ(Shape3::sphere(2).radius(), 2);
  EXPECT_EQ(Shape3::sphere(2).core().dimension(), 0);
}

// Awkward inputs stay finite: coincident sphere centres, capsules on one axis (touching cores,
// collinear segments), a tiny sphere on a large box, far placements, grazing casts.
TEST(Primitives3, AwkwardInputsStayFinite) {
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> U(-1, 1);
  auto finite = [](const Vec3& v) { return v.allFinite(); };
  const Pair3 spheres(Shape3::sphere(1), Shape3::sphere(0.5));
  const Distance3 same = spheres.signed_distance(Pose3(), Pose3());
  EXPECT_EQ(same.distance, -1.5);
  EXPECT_NEAR(same.normal.norm(), 1, 8 * kEps);  // any direction: the centres coincide
  const Pair3 caps(Shape3::capsule(0.5, 1), Shape3::capsule(0.5, 1));
  const Depth3 axis = caps.minimum(Pose3(), Pose3(Vec3(0, 0, 1)));  // collinear cores overlapping
  EXPECT_TRUE(axis.overlapping);
  EXPECT_NEAR(axis.depth, 1, 4 * kEps);  // sideways: the radii (1); along z it would be 3
  const Pair3 tiny(Shape3::box(1024, 1024, 1024), Shape3::sphere(0x1p-30));
  EXPECT_EQ(tiny.signed_distance(Pose3(), Pose3(Vec3(0, 0, 1024 + 0x1p-29))).distance, 0x1p-30);  // exact inputs
  // A ray grazing a sphere (tangent): a hit or a miss, never NaN.
  const Cast3 graze = spheres.cast(Pose3(), Pose3(Vec3(5, 1.5, 0)), Vec3(-1, 0, 0));
  EXPECT_FALSE(std::isnan(graze.distance));
  for (const Pair3& pair : {spheres, caps, tiny, Pair3(Shape3::capsule(0.2, 0.3), Shape3::box(0.5, 0.5, 0.5))})
    for (int k = 0; k < 40; ++k) {
      const double far = k % 4 == 3 ? 1e7 : 2;
      const Pose3 pq(random_rotation(rng), far * Vec3(U(rng), U(rng), U(rng)));
      const Vec3 d(U(rng), U(rng), U(rng));
      const Depth3 m = pair.minimum(Pose3(), pq), a = pair.along(Pose3(), pq, d);
      const Distance3 sd = pair.signed_distance(Pose3(), pq);
      const Cast3 c = pair.cast(Pose3(), pq, d);
      ASSERT_TRUE(std::isfinite(m.depth) && finite(m.translation) && finite(m.witness_p));
      ASSERT_TRUE(std::isfinite(a.depth) && finite(a.translation) && finite(a.witness_p));
      ASSERT_TRUE(std::isfinite(sd.distance) && finite(sd.normal) && finite(sd.witness_q));
      ASSERT_TRUE(!std::isnan(c.distance) && finite(c.normal) && finite(c.witness_p));
    }
}

}  // namespace
}  // namespace pendepth
