// σ and σ_d of convex polytopes vs the explicit reference M = hull{p − q'} (all pairwise
// differences, O(nm log nm)) with the exact ray exit / plane distance per facet; analytic
// cases; properties (σ ≤ σ_d, move by the result ⇒ touching, shorter ⇒ overlapping, invariance).
#include <gtest/gtest.h>

#include <pendepth/depth3.hpp>

#include "shapes3.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include "test_rotations.hpp"

namespace pendepth {
namespace {

struct Ref {
  bool overlapping = false;
  double sigma = 0;
};

// Q' vertices in P's frame as the library defines them (R, t as doubles; q' rounded here).
std::vector<Vec3> placed(const ConvexPolytope& Q, const Pose3& pose) {
  std::vector<Vec3> out;
  Eigen::Matrix3d R = pose.matrix();
  for (const auto& q : Q.vertices()) out.push_back(R * q + pose.translation);
  return out;
}

// Explicit M; σ (d empty) or σ_d. Overlap decided exactly on the explicit M's facets.
Ref reference(const ConvexPolytope& P, const std::vector<Vec3>& Qw, const Vec3* d) {
  std::vector<Vec3> diff;
  for (const auto& p : P.vertices())
    for (const auto& q : Qw) diff.push_back(p - q);
  auto M = ConvexPolytope::hull(diff, "M");
  Ref r;
  r.overlapping = true;
  r.sigma = std::numeric_limits<double>::infinity();
  for (const auto& t : M.triangles()) {
    if (predicates::orient3d(M[t[0]], M[t[1]], M[t[2]], Vec3::Zero()) >= 0) return Ref{};
    Vec3 n = (M[t[1]] - M[t[0]]).cross(M[t[2]] - M[t[0]]);
    double h = n.dot(M[t[0]]);
    if (!d) r.sigma = std::min(r.sigma, h / n.norm());
    else if (n.dot(*d) > 0) r.sigma = std::min(r.sigma, h / n.dot(d->normalized()));
  }
  return r;
}

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_unit_quaternion(rng); }

std::vector<Vec3> random_dirs(std::mt19937_64& rng, int k) {
  std::normal_distribution<double> g;
  std::vector<Vec3> d{{1, 0, 0}, {0, 0, -1}};
  while (static_cast<int>(d.size()) < k) d.emplace_back(g(rng), g(rng), g(rng));
  return d;
}

struct Stats {
  int cases = 0, overlapping = 0;
  double max_err = 0;
};

void compare(const ConvexPolytope& P, const ConvexPolytope& Q, const Pose3& pq, std::mt19937_64& rng,
             double scale, Stats& st, const std::string& what) {
  SCOPED_TRACE(what);
  const double tol = 1e-12 * scale;
  auto Qw = placed(Q, pq);
  Depth3 s = minimum_depth(P, Pose3(), Q, pq);
  Ref rs = reference(P, Qw, nullptr);
  ++st.cases;
  ASSERT_EQ(s.overlapping, rs.overlapping);
  if (!rs.overlapping) {
    EXPECT_EQ(s.depth, 0);
    return;
  }
  ++st.overlapping;
  EXPECT_NEAR(s.depth, rs.sigma, tol);
  st.max_err = std::max(st.max_err, std::abs(s.depth - rs.sigma) / scale);
  EXPECT_EQ(s.lower_bound, s.upper_bound);
  EXPECT_NEAR(s.translation.norm(), s.depth, tol);
  for (const Vec3& d : random_dirs(rng, 6)) {
    Depth3 a = directional_depth(P, Pose3(), Q, pq, d);
    Ref ra = reference(P, Qw, &d);
    ASSERT_TRUE(a.overlapping);
    EXPECT_NEAR(a.depth, ra.sigma, tol) << "d = " << d.transpose();
    st.max_err = std::max(st.max_err, std::abs(a.depth - ra.sigma) / scale);
    EXPECT_LE(s.depth, a.depth + tol);  // σ ≤ σ_d
  }
}

TEST(Depth3, RandomHullsVsExplicitMinkowski) {
  std::mt19937_64 rng(314);
  Stats st;
  std::uniform_real_distribution<double> U(-0.8, 0.8);
  for (int it = 0; it < 40; ++it) {
    int n = 4 + static_cast<int>(rng() % 40), m = 4 + static_cast<int>(rng() % 40);
    auto P = ConvexPolytope::hull(it % 2 ? test3::random_sphere(rng, n) : test3::random_ball(rng, n + 10));
    auto Q = ConvexPolytope::hull(test3::random_sphere(rng, m, 0.5));
    Pose3 pq(it % 3 ? random_rotation(rng) : Eigen::Quaterniond::Identity(), Vec3(U(rng), U(rng), U(rng)));
    compare(P, Q, pq, rng, 1.0, st, "random " + std::to_string(it));
  }
  EXPECT_GT(st.overlapping, 25);
  std::printf("random: %d cases, %d overlapping, max rel err %.3g\n", st.cases, st.overlapping, st.max_err);
}

TEST(Depth3, IntegerDegenerateShapes) {
  // Integer coordinates: p − q' exact, so the reference facets are exact too.
  std::mt19937_64 rng(2718);
  Stats st;
  std::vector<ConvexPolytope> S;
  for (int N : {3, 9, 11}) S.push_back(ConvexPolytope::hull(test3::integer_sphere(N)));
  S.push_back(ConvexPolytope::hull(test3::prism(25, 2)));
  S.push_back(ConvexPolytope::hull(test3::bipyramid(25)));
  S.push_back(ConvexPolytope::hull(test3::grid(3)));
  std::uniform_int_distribution<int> t(-4, 4);
  for (std::size_t i = 0; i < S.size(); ++i)
    for (std::size_t j = 0; j < S.size(); ++j)
      for (int k = 0; k < 3; ++k)  // integer offsets: face–face, edge–edge parallel, touching
        compare(S[i], S[j], Pose3(Vec3(t(rng), t(rng), t(rng))), rng, 10.0, st,
                "int " + std::to_string(i) + "," + std::to_string(j));
  EXPECT_GT(st.overlapping, 40);
  std::printf("integer: %d cases, %d overlapping, max rel err %.3g\n", st.cases, st.overlapping, st.max_err);
}

TEST(Depth3, SharedHullPairs) {
  auto files = test3::shared_hull_files();
  std::mt19937_64 rng(42);
  Stats st;
  for (std::size_t i = 0; i + 1 < files.size(); i += 3) {
    auto P = ConvexPolytope::hull(read_obj_vertices(files[i]));
    auto Q = ConvexPolytope::hull(read_obj_vertices(files[i + 1]));
    if (P.size() * Q.size() > 6000) continue;
    // Put Q's centroid near P's centroid so that they overlap.
    Vec3 cp = Vec3::Zero(), cq = Vec3::Zero();
    for (const auto& v : P.vertices()) cp += v / double(P.size());
    for (const auto& v : Q.vertices()) cq += v / double(Q.size());
    double scale = 0;
    for (const auto& v : P.vertices()) scale = std::max(scale, (v - cp).norm());
    auto rot = random_rotation(rng);
    Pose3 pq(rot, cp - rot.toRotationMatrix() * cq);
    compare(P, Q, pq, rng, scale, st, files[i]);
  }
  EXPECT_GT(st.overlapping, 8);
  std::printf("shared hulls: %d cases, %d overlapping, max rel err %.3g\n", st.cases, st.overlapping, st.max_err);
}

TEST(Depth3, AnalyticCubes) {
  auto C = ConvexPolytope::hull(test3::grid(2));  // unit cube [0,1]^3
  // Identical shapes: σ = width = 1; σ_d along a diagonal = 1 (exit through a vertex region).
  Depth3 s = minimum_depth(C, Pose3(), C, Pose3());
  ASSERT_TRUE(s.overlapping);
  EXPECT_EQ(s.depth, 1.0);
  EXPECT_EQ(directional_depth(C, Pose3(), C, Pose3(), Vec3(1, 1, 1)).depth, std::sqrt(3.0));
  // Face–face overlap 0.25 along x.
  s = minimum_depth(C, Pose3(), C, Pose3(Vec3(0.75, 0.1, 0.2)));
  EXPECT_DOUBLE_EQ(s.depth, 0.25);
  EXPECT_EQ(s.normal, Vec3(1, 0, 0));
  // Touching (face, edge, vertex contacts) and separated: depth 0, not overlapping.
  for (Vec3 t : {Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(1, 1, 1), Vec3(1, 0.5, 0.5), Vec3(3, 0, 0)}) {
    EXPECT_FALSE(minimum_depth(C, Pose3(), C, Pose3(t)).overlapping) << t.transpose();
    EXPECT_EQ(directional_depth(C, Pose3(), C, Pose3(t), Vec3(0, 1, 0)).depth, 0);
  }
  // Cube rotated 45° about z: edge into face; σ = 1 − (√2/2 − 0.5)... computed from geometry.
  Eigen::Quaterniond rz(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()));
  Pose3 pq(rz, Vec3(1.2, 0.5, 0));  // Q's footprint: the square (1.2,0.5) (1.907,1.207) (1.2,1.914) (0.493,1.207)
  s = minimum_depth(C, Pose3(), C, pq);
  ASSERT_TRUE(s.overlapping);
  // P's edge x = y = 1 pierces Q's face x + y = 1.7: push Q along (1,1)/√2 by 0.3/√2.
  EXPECT_NEAR(s.depth, 0.3 / std::sqrt(2.0), 1e-14);
  EXPECT_NEAR((s.normal - Vec3(1, 1, 0).normalized()).norm(), 0, 1e-14);
  EXPECT_EQ(s.feature_q.kind, FeatureKind3::Face);
  EXPECT_EQ(s.feature_p.kind, FeatureKind3::Vertex);
}

TEST(Depth3, MoveByResultTouchesAndInvariance) {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> U(-0.5, 0.5);
  for (int it = 0; it < 20; ++it) {
    auto P = ConvexPolytope::hull(test3::random_sphere(rng, 30));
    auto Q = ConvexPolytope::hull(test3::random_ball(rng, 40, 0.6));
    Pose3 pq(random_rotation(rng), Vec3(U(rng), U(rng), U(rng)));
    Depth3 s = minimum_depth(P, Pose3(), Q, pq);
    ASSERT_TRUE(s.overlapping);
    Pose3 moved = pq, short_of = pq;
    moved.translation += s.translation * (1 + 1e-9);
    short_of.translation += s.translation * (1 - 1e-6);
    EXPECT_FALSE(minimum_depth(P, Pose3(), Q, moved).overlapping);
    EXPECT_TRUE(minimum_depth(P, Pose3(), Q, short_of).overlapping);
    // Witness: on P's boundary-plane of the facet and on moved Q (both the same contact point).
    EXPECT_NEAR((s.witness_p - s.witness_q).norm(), 0, 1e-12);
    // Rigid motion of the whole scene and a 1e6 offset of both: same depth.
    auto g = random_rotation(rng);
    Vec3 off(1e6, -1e6, 5e5);
    Pose3 gp(g, off), gq(g * pq.rotation, g.toRotationMatrix() * pq.translation + off);
    Depth3 s2 = minimum_depth(P, gp, Q, gq);
    EXPECT_NEAR(s2.depth, s.depth, 1e-9);
    EXPECT_NEAR((s2.normal - g.toRotationMatrix() * s.normal).norm(), 0, 1e-6);
    Vec3 d(U(rng), U(rng), 1);
    EXPECT_NEAR(directional_depth(P, gp, Q, gq, g.toRotationMatrix() * d).depth,
                directional_depth(P, Pose3(), Q, pq, d).depth, 1e-9);
  }
}

TEST(Depth3, LargeHullProperties) {
  // 2000 vertices vs 20: no explicit oracle (40 000 differences); properties only.
  std::mt19937_64 rng(2000);
  auto P = ConvexPolytope::hull(test3::random_sphere(rng, 2000));
  auto Q = ConvexPolytope::hull(test3::random_sphere(rng, 20, 0.3));
  Pose3 pq(random_rotation(rng), Vec3(0.5, -0.3, 0.4));
  Depth3 s = minimum_depth(P, Pose3(), Q, pq);
  ASSERT_TRUE(s.overlapping);
  for (const Vec3& d : random_dirs(rng, 4)) EXPECT_LE(s.depth, directional_depth(P, Pose3(), Q, pq, d).depth);
  Pose3 moved = pq, short_of = pq;
  moved.translation += s.translation * (1 + 1e-9);
  short_of.translation += s.translation * (1 - 1e-6);
  EXPECT_FALSE(minimum_depth(P, Pose3(), Q, moved).overlapping);
  EXPECT_TRUE(minimum_depth(P, Pose3(), Q, short_of).overlapping);
}

TEST(Depth3, InvalidInput) {
  auto C = ConvexPolytope::hull(test3::grid(2));
  EXPECT_THROW(directional_depth(C, Pose3(), C, Pose3(), Vec3::Zero()), InvalidInput);
  EXPECT_THROW(directional_depth(C, Pose3(), C, Pose3(), Vec3(NAN, 0, 1)), InvalidInput);
  EXPECT_THROW(minimum_depth(C, Pose3(), C, Pose3(Eigen::Quaterniond(0, 0, 0, 0), Vec3::Zero())), InvalidInput);
  EXPECT_THROW(minimum_depth(C, Pose3(Vec3(INFINITY, 0, 0)), C, Pose3()), InvalidInput);
}

// Pose3::matrix returns I directly for x = y = z = +0: the same bits as the general path (scale
// by a power of two, one division s = 2/|q|², the quadratic terms; test_rotations.hpp writes it
// out as the reference), for w of every sign and magnitude; quaternions with a −0 component take
// the general path.
TEST(Depth3, IdentityRotationMatrixIsTheGeneralOne) {
  auto general = [](const Eigen::Quaterniond& q) { return pendepth_test::scaled_rotation_matrix(q); };
  auto same_bits = [](const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
    return std::memcmp(a.data(), b.data(), sizeof(double) * 9) == 0;
  };
  std::mt19937_64 rng(16);
  std::vector<double> ws = {1, -1, 0.5, 3, -7.25, 0x1p-1000, -0x1p1000, 0x1p-1074, 1.7976931348623157e308};
  for (int k = 0; k < 1000; ++k)
    ws.push_back(std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng), int(rng() % 2000) - 1000));
  for (double w : ws) {
    if (w == 0) continue;
    for (int z = 0; z < 8; ++z) {  // each of x, y, z is +0 or −0
      const Eigen::Quaterniond q(w, z & 1 ? -0.0 : 0.0, z & 2 ? -0.0 : 0.0, z & 4 ? -0.0 : 0.0);
      const Eigen::Matrix3d R = Pose3(q, Vec3::Zero()).matrix();
      EXPECT_TRUE(same_bits(R, general(q))) << "w = " << w << ", zeros " << z;
      if (z == 0) EXPECT_TRUE(same_bits(R, Eigen::Matrix3d::Identity())) << "w = " << w;
    }
  }
}

}  // namespace
}  // namespace pendepth
