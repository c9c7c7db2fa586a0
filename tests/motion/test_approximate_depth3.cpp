// approximate_minimum_depth (src/motion/approximate_depth3.cpp) against the exact σ of the full
// hulls (ConvexPolytope::hull + minimum_depth, the certified expansion): the bounds bracket the
// exact σ, upper ≤ (1+δ)·lower, the returned move separates; random point sets on spheres and
// ellipsoids (every point a vertex) and random clouds, 10³–10⁵ points, δ = 1e-1, 1e-2, 1e-3;
// degenerate pairs (separated, touching boxes, identical shapes, boxes); input validation.
#include <gtest/gtest.h>

#include <pendepth/approximate.hpp>
#include <pendepth/depth3.hpp>
#include <pendepth/polytope.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace pendepth {
namespace {

// minimum_depth's value is a few ulps from the exact σ; the approximate bounds are certified on
// the exact σ: comparing the two allows those few ulps (2^-44 relative), nothing more.
constexpr double kUlps = 0x1p-44;

std::vector<Vec3> ellipsoid(std::size_t n, const Vec3& radii, std::uint32_t seed) {
  std::mt19937_64 g(seed);
  std::normal_distribution<double> N;
  std::vector<Vec3> pts;
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 v(N(g), N(g), N(g));
    pts.push_back(v.normalized().cwiseProduct(radii));
  }
  return pts;
}

std::vector<Vec3> cloud(std::size_t n, double r, std::uint32_t seed) {  // uniform in a ball
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> U(-r, r);
  std::vector<Vec3> pts;
  while (pts.size() < n) {
    Vec3 v(U(g), U(g), U(g));
    if (v.norm() <= r) pts.push_back(v);
  }
  return pts;
}

std::vector<Vec3> box(std::size_t n, const Vec3& lo, const Vec3& hi, std::uint32_t seed) {  // corners + interior
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<Vec3> pts;
  for (int c = 0; c < 8; ++c) pts.emplace_back(c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(), c & 4 ? hi.z() : lo.z());
  while (pts.size() < n) pts.push_back(lo + (hi - lo).cwiseProduct(Vec3(U(g), U(g), U(g))));
  return pts;
}

Pose3 random_pose(std::mt19937_64& g, double shift) {
  std::normal_distribution<double> N;
  std::uniform_real_distribution<double> U(-shift, shift);
  return Pose3(Eigen::Quaterniond(N(g), N(g), N(g), N(g)), Vec3(U(g), U(g), U(g)));
}

double exact_sigma(const ConvexPolytope& P, const Pose3& pp, const ConvexPolytope& Q, const Pose3& pq) {
  return minimum_depth(P, pp, Q, pq).depth;
}

// The bounds bracket the exact σ; converged means upper ≤ (1+δ)·lower; moving Q by the result
// leaves (up to the rounding of the move itself) no overlap.
void check(const std::vector<Vec3>& Pp, const Pose3& pp, const std::vector<Vec3>& Qp, const Pose3& pq,
           double delta, const ConvexPolytope& HP, const ConvexPolytope& HQ) {
  const double sigma = exact_sigma(HP, pp, HQ, pq);
  const ApproxDepth3 r = approximate_minimum_depth(Pp, pp, Qp, pq, delta);
  ASSERT_TRUE(r.converged) << "delta " << delta << " sigma " << sigma << " lower " << r.lower_bound << " upper "
                           << r.upper_bound;
  EXPECT_LE(r.lower_bound, sigma * (1 + kUlps));
  EXPECT_GE(r.upper_bound, sigma * (1 - kUlps));
  EXPECT_LE(r.upper_bound, (1 + delta) * r.lower_bound);
  EXPECT_EQ(r.depth, r.upper_bound);
  EXPECT_EQ(r.overlapping, sigma > 0);
  EXPECT_GE(r.lower_bound, 0);
  EXPECT_LE(r.kernel_p, Pp.size());
  EXPECT_LE(r.kernel_q, Qp.size());
  if (sigma > 0) {
    EXPECT_NEAR(r.normal.norm(), 1, 1e-12);
    Pose3 moved = pq;
    moved.translation += r.translation;
    const double size = std::max(HP.vertices()[0].norm(), 1.0) + pq.translation.norm();
    // Touching after the move, up to the rounding of translation and of the poses.
    EXPECT_LE(exact_sigma(HP, pp, HQ, moved), 0x1p-40 * size);
    // A move shorter by the factor (1+δ)^-1 · (1 − 1e-3) cannot separate along any direction.
    Pose3 shorter = pq;
    shorter.translation += r.translation * (1.0 / (1 + delta) * (1 - 1e-3));
    if (r.lower_bound > 0) EXPECT_GT(exact_sigma(HP, pp, HQ, shorter), 0);
  } else {
    EXPECT_EQ(r.upper_bound, 0);
    EXPECT_EQ(r.lower_bound, 0);
  }
}

struct Case {
  std::vector<Vec3> P, Q;
};

TEST(ApproximateDepth3, RandomEllipsoidsAndCloudsAllDeltas) {
  std::mt19937_64 g(20261126);
  const std::size_t sizes[] = {1000, 10000};
  int k = 0;
  for (std::size_t n : sizes) {
    for (int shape = 0; shape < 3; ++shape, ++k) {
      Case c;
      if (shape == 0) c = {ellipsoid(n, Vec3(1, 1, 1), 11 + k), ellipsoid(n / 2, Vec3(0.7, 0.7, 0.7), 12 + k)};
      if (shape == 1) c = {ellipsoid(n, Vec3(2, 1, 0.5), 13 + k), ellipsoid(n, Vec3(0.3, 1.5, 0.8), 14 + k)};
      if (shape == 2) c = {cloud(n, 1.0, 15 + k), ellipsoid(n, Vec3(1.2, 0.4, 0.9), 16 + k)};
      const ConvexPolytope HP = ConvexPolytope::hull(c.P), HQ = ConvexPolytope::hull(c.Q);
      for (int pose = 0; pose < 2; ++pose) {
        const Pose3 pp = random_pose(g, 0.5), pq = random_pose(g, 0.8);
        for (double delta : {1e-1, 1e-2, 1e-3}) {
          SCOPED_TRACE(testing::Message() << "n " << n << " shape " << shape << " pose " << pose);
          check(c.P, pp, c.Q, pq, delta, HP, HQ);
        }
      }
    }
  }
}

// 10⁵ points: the working sets are the column-grid kernels (W ≠ X), the full sets are scanned
// only to certify.
TEST(ApproximateDepth3, HundredThousandPointsUseTheColumnKernel) {
  std::mt19937_64 g(7);
  const std::vector<Vec3> P = ellipsoid(100000, Vec3(1.5, 1, 1.2), 21), Q = cloud(100000, 1.0, 22);
  const ConvexPolytope HP = ConvexPolytope::hull(P), HQ = ConvexPolytope::hull(Q);
  const Pose3 pp = random_pose(g, 0.3), pq = random_pose(g, 0.6);
  for (double delta : {1e-1, 1e-2, 1e-3}) {
    check(P, pp, Q, pq, delta, HP, HQ);
    const ApproxDepth3 r = approximate_minimum_depth(P, pp, Q, pq, delta);
    EXPECT_LT(r.working_p, P.size());
    EXPECT_LT(r.working_q, Q.size());
    EXPECT_LT(r.kernel_p, r.working_p);
  }
}

// Beyond the exact hull's reach in a test (3·10⁵ points, W a column kernel, repairs possible):
// the certificates checked directly on the full sets in long double. upper = h_M(normal) (the
// exact support value along the returned normal); lower ≤ h_M(u) for every u, probed on random
// directions and on directions near the returned normal (where an overestimated lower bound
// would show). Long double evaluation errors are below 1e-15 here; 1e-12 is the slack.
long double support_gap(const std::vector<Vec3>& P, const std::vector<Vec3>& Q, const Pose3& pq, const Vec3& u) {
  const Eigen::Matrix3d R = pq.matrix();
  long double hp = -1e300L, mq = 1e300L;
  for (const Vec3& p : P) hp = std::max(hp, (long double)u.x() * p.x() + (long double)u.y() * p.y() + (long double)u.z() * p.z());
  for (const Vec3& q : Q) {
    long double v = 0;
    for (int k = 0; k < 3; ++k) {
      long double c = pq.translation[k];
      for (int l = 0; l < 3; ++l) c += (long double)R(k, l) * q[l];
      v += (long double)u[k] * c;
    }
    mq = std::min(mq, v);
  }
  return (hp - mq) / std::sqrt((long double)u.squaredNorm());
}

TEST(ApproximateDepth3, LargeSetsCertificatesOnTheFullSets) {
  std::mt19937_64 g(81);
  const std::vector<Vec3> P = ellipsoid(300000, Vec3(1.5, 1, 1.2), 82), Q = cloud(300000, 1.0, 83);
  const Pose3 pq(Eigen::Quaterniond(1, 0.2, 0.3, 0.1), Vec3(0.2, 0.1, 0));
  for (double delta : {1e-2, 1e-3}) {
    const ApproxDepth3 r = approximate_minimum_depth(P, Pose3(), Q, pq, delta);
    ASSERT_TRUE(r.converged);
    EXPECT_LE(r.upper_bound, (1 + delta) * r.lower_bound);
    EXPECT_LT(r.working_p, P.size());
    const long double h = support_gap(P, Q, pq, r.normal);
    EXPECT_NEAR(double(h), r.upper_bound, 1e-12 * r.upper_bound);
    EXPECT_GE(r.upper_bound, double(h));
    std::normal_distribution<double> N;
    for (int i = 0; i < 120; ++i) {
      const double spread = i < 40 ? 1.0 : i < 80 ? 1e-2 : 1e-3;
      const Vec3 u = (r.normal + spread * Vec3(N(g), N(g), N(g))).normalized();
      EXPECT_GE(double(support_gap(P, Q, pq, u)), r.lower_bound * (1 - 1e-12)) << i;
    }
  }
}

TEST(ApproximateDepth3, SmallerDeltaNeverLooser) {
  const std::vector<Vec3> P = ellipsoid(5000, Vec3(1, 1, 1), 31), Q = ellipsoid(5000, Vec3(1, 1, 1), 32);
  const Pose3 pq(Vec3(0.3, 0.1, -0.2));
  const ApproxDepth3 a = approximate_minimum_depth(P, Pose3(), Q, pq, 1e-1);
  const ApproxDepth3 b = approximate_minimum_depth(P, Pose3(), Q, pq, 1e-3);
  EXPECT_LE(b.upper_bound - b.lower_bound, 1e-3 * b.lower_bound);
  EXPECT_LE(b.upper_bound, (1 + 1e-1) * a.lower_bound);  // both bracket the same σ
  EXPECT_LE(a.lower_bound, b.upper_bound);
  EXPECT_GE(b.kernel_p + b.kernel_q, a.kernel_p + a.kernel_q);
}

TEST(ApproximateDepth3, SeparatedAndTouchingAreCertifiedZero) {
  const std::vector<Vec3> A = box(2000, Vec3(0, 0, 0), Vec3(1, 2, 3), 41), B = box(2000, Vec3(0, 0, 0), Vec3(2, 1, 1), 42);
  const ConvexPolytope HA = ConvexPolytope::hull(A), HB = ConvexPolytope::hull(B);
  // Separated by a gap along x, along a diagonal, and far away with a rotation.
  check(A, Pose3(), B, Pose3(Vec3(1.5, 0, 0)), 1e-2, HA, HB);
  check(A, Pose3(), B, Pose3(Vec3(-2.25, -1.25, -1.5)), 1e-2, HA, HB);
  check(A, Pose3(), B, Pose3(Eigen::Quaterniond(1, 2, 3, 4), Vec3(50, -40, 30)), 1e-2, HA, HB);
  // Touching face to face (x = 1), edge to edge and corner to corner: σ = 0 exactly.
  for (const Vec3& t : {Vec3(1, 0.5, 1), Vec3(1, 2, 0.25), Vec3(1, 2, 3), Vec3(-2, -1, -1)}) {
    SCOPED_TRACE(testing::Message() << "t " << t.transpose());
    const ApproxDepth3 r = approximate_minimum_depth(A, Pose3(), B, Pose3(t), 1e-2);
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(r.lower_bound, 0);
    EXPECT_EQ(r.upper_bound, 0);
    EXPECT_FALSE(r.overlapping);
    EXPECT_EQ(exact_sigma(HA, Pose3(), HB, Pose3(t)), 0);
  }
}

// Touching along the skew plane x + y + z = 1 (P the unit corner tetrahedron with interior points,
// Q its mirror image sharing the face e1 e2 e3): certified σ = 0; then shifted into P by
// 1e-9·(1, 1, 1) and 1e-3·(1, 1, 1) (σ = √3·shift: tiny depths keep their relative guarantee).
TEST(ApproximateDepth3, SkewTouchingAndShallowOverlap) {
  std::mt19937_64 g(5);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<Vec3> P{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, Q{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2. / 3, 2. / 3, 2. / 3}};
  while (P.size() < 3000) {
    const Vec3 v(U(g), U(g), U(g));
    if (v.sum() < 1) P.push_back(v);
  }
  const ConvexPolytope HP = ConvexPolytope::hull(P), HQ = ConvexPolytope::hull(Q);
  for (double shift : {0.0, 1e-9, -1e-9, -1e-3}) {
    SCOPED_TRACE(testing::Message() << "shift " << shift);
    check(P, Pose3(), Q, Pose3(Vec3(shift, shift, shift)), 1e-2, HP, HQ);
  }
  const ApproxDepth3 r = approximate_minimum_depth(P, Pose3(), Q, Pose3(), 1e-3);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.upper_bound, 0);
  EXPECT_NEAR(std::abs(r.normal.dot(Vec3(1, 1, 1).normalized())), 1, 1e-12);  // the separating plane
}

TEST(ApproximateDepth3, BoxesMatchTheAnalyticDepth) {
  // Axis-aligned boxes: σ = the smallest overlap of the coordinate intervals, exactly.
  const std::vector<Vec3> A = box(3000, Vec3(0, 0, 0), Vec3(4, 3, 2), 51), B = box(3000, Vec3(0, 0, 0), Vec3(1, 1, 1), 52);
  const ConvexPolytope HA = ConvexPolytope::hull(A), HB = ConvexPolytope::hull(B);
  for (const Vec3& t : {Vec3(0.5, 0.5, 0.5), Vec3(3.75, 1, 0.5), Vec3(-0.5, 2.5, 1.5), Vec3(1.5, 1, 0.125)}) {
    double want = std::numeric_limits<double>::infinity();
    const Vec3 hiA(4, 3, 2);
    for (int k = 0; k < 3; ++k) want = std::min({want, hiA[k] - t[k], t[k] + 1});
    for (double delta : {1e-1, 1e-3}) {
      const ApproxDepth3 r = approximate_minimum_depth(A, Pose3(), B, Pose3(t), delta);
      EXPECT_TRUE(r.converged);
      EXPECT_LE(r.lower_bound, want);
      EXPECT_GE(r.upper_bound, want);
      EXPECT_LE(r.upper_bound, (1 + delta) * r.lower_bound);
      check(A, Pose3(), B, Pose3(t), delta, HA, HB);
    }
  }
}

// Huge and tiny pairs are answered on copies scaled by a power of two: the analytic σ of two
// boxes scaled by 2^±600 is bracketed, and the bounds are the unit answer's scaled (the scaled
// copies have the same bits whenever the unit pair is scaled to the same exponent).
TEST(ApproximateDepth3, HugeAndTinyPairsAreScaled) {
  const std::vector<Vec3> A = box(300, Vec3(0, 0, 0), Vec3(1.5, 1.25, 1.75), 91), B = box(300, Vec3(0, 0, 0), Vec3(1, 1, 1), 92);
  const Vec3 t(0.5, 0.75, 1.25);  // σ = min(1.5 − .5, .5 + 1, 1.25 − .75, .75 + 1, 1.75 − 1.25, 1.25 + 1) = 0.5
  const Eigen::Quaterniond rot(1, 0.1, -0.2, 0.3);
  const ApproxDepth3 unit = approximate_minimum_depth(A, Pose3(), B, Pose3(t), 1e-3);
  const ApproxDepth3 unit_rot = approximate_minimum_depth(A, Pose3(), B, Pose3(rot, t), 1e-3);
  for (int e : {600, -600, 70, -70}) {
    std::vector<Vec3> As = A, Bs = B;
    for (auto& p : As) p = std::ldexp(1.0, e) * p;
    for (auto& p : Bs) p = std::ldexp(1.0, e) * p;
    const ApproxDepth3 r = approximate_minimum_depth(As, Pose3(), Bs, Pose3(std::ldexp(1.0, e) * t), 1e-3);
    EXPECT_TRUE(r.converged) << e;
    EXPECT_LE(r.lower_bound, std::ldexp(0.5, e)) << e;
    EXPECT_GE(r.upper_bound, std::ldexp(0.5, e)) << e;
    EXPECT_EQ(r.upper_bound, std::ldexp(unit.upper_bound, e)) << e;
    EXPECT_EQ(r.lower_bound, std::ldexp(unit.lower_bound, e)) << e;
    const ApproxDepth3 rr = approximate_minimum_depth(As, Pose3(), Bs, Pose3(rot, std::ldexp(1.0, e) * t), 1e-3);
    EXPECT_TRUE(rr.converged) << e;
    EXPECT_EQ(rr.upper_bound, std::ldexp(unit_rot.upper_bound, e)) << e;
  }
}

TEST(ApproximateDepth3, IdenticalShapes) {
  std::mt19937_64 g(61);
  const std::vector<Vec3> P = ellipsoid(4000, Vec3(1, 0.6, 0.3), 62);
  const ConvexPolytope H = ConvexPolytope::hull(P);
  check(P, Pose3(), P, Pose3(), 1e-2, H, H);
  const Pose3 same = random_pose(g, 1.0);
  check(P, same, P, same, 1e-3, H, H);
  const std::vector<Vec3> B = box(500, Vec3(-1, -1, -1), Vec3(1, 1, 1), 63);
  const ConvexPolytope HB = ConvexPolytope::hull(B);
  const ApproxDepth3 r = approximate_minimum_depth(B, Pose3(), B, Pose3(), 1e-3);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.lower_bound, 2);  // σ = 2 (the cube's width) exactly
  EXPECT_GE(r.upper_bound, 2);
  check(B, Pose3(), B, Pose3(), 1e-3, HB, HB);
}

TEST(ApproximateDepth3, InvalidInput) {
  const std::vector<Vec3> P = cloud(100, 1, 71), flat = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  const std::vector<Vec3> empty, line = {Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2), Vec3(3, 3, 3)};
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (double delta : {0.0, -0.1, 1.0, 2.0, nan, inf, 1e-12})
    EXPECT_THROW(approximate_minimum_depth(P, Pose3(), P, Pose3(), delta), InvalidInput) << delta;
  EXPECT_THROW(approximate_minimum_depth(empty, Pose3(), P, Pose3(), 0.1), InvalidInput);
  EXPECT_THROW(approximate_minimum_depth(P, Pose3(), flat, Pose3(), 0.1), InvalidInput);
  EXPECT_THROW(approximate_minimum_depth(line, Pose3(), P, Pose3(), 0.1), InvalidInput);
  std::vector<Vec3> bad = P;
  bad[17] = Vec3(0, nan, 0);
  EXPECT_THROW(approximate_minimum_depth(bad, Pose3(), P, Pose3(), 0.1), InvalidInput);
  bad[17] = Vec3(0, 0, inf);
  EXPECT_THROW(approximate_minimum_depth(P, Pose3(), bad, Pose3(), 0.1), InvalidInput);
  bad[17] = Vec3(0x1p1020, 0, 0), bad[18] = Vec3(1e-5, 0, 0);  // 1e-5 has no exact value at scale 2^1020
  EXPECT_THROW(approximate_minimum_depth(P, Pose3(), bad, Pose3(), 0.1), InvalidInput);
  EXPECT_THROW(approximate_minimum_depth(P, Pose3(Vec3(nan, 0, 0)), P, Pose3(), 0.1), InvalidInput);
  EXPECT_THROW(approximate_minimum_depth(P, Pose3(), P, Pose3(Eigen::Quaterniond(0, 0, 0, 0), Vec3::Zero()), 0.1),
               InvalidInput);
}

}  // namespace
}  // namespace pendepth
