// σ_d by Compute-Depth-3D (directional3.cpp, convex3::directional_depth_dk) and by the public
// pendepth::directional_depth (the expansion of minimum_expand.cpp within its work budget, else
// Compute-Depth-3D; its own tests: test_directional_expand.cpp), each against two
// independent references: the minimum over ALL implicit facet normals of M (minkowski_facets,
// O(n·m)) and, for small shapes, the explicit M = hull of all differences with an exact ray exit.
// Random hulls 4…2000 vertices, the 60 shared hulls, degenerate integer suites (face–face,
// parallel edges, vertex–face, identical, touching, directions along faces and edges), 1e6
// offsets, random rotations; σ ≤ σ_d; bad directions.
#include <gtest/gtest.h>

#include <pendepth/depth3.hpp>

#include "convex3/minkowski_facets.hpp"
#include "shapes3.hpp"

#include <cmath>
#include <limits>
#include "test_rotations.hpp"

namespace pendepth::convex3 {
Depth3 directional_depth_dk(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                            const Pose3& pose_q, const Vec3& d);
Depth3 directional_depth_facets(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                                const Pose3& pose_q, const Vec3& d);
}  // namespace pendepth::convex3

namespace pendepth {
namespace {

struct Stats {
  int queries = 0, overlapping = 0, failures = 0;
  double max_ulps = 0;  ///< |σ_d − reference| in units of the reference's ulp
  void print(const char* what) const {
    std::printf("%s: %d queries, %d overlapping, %d failures, max error %.1f ulp\n", what, queries, overlapping,
                failures, max_ulps);
  }
};

using test3::ulps;

// 0 ∈ ∂M exactly: P and Q' touch without overlapping (every facet has h ≥ 0, one has h = 0).
bool touching(const ConvexPolytope& P, const ConvexPolytope& Q, const Pose3& pq) {
  convex3::RelativePose rel;
  rel.R = pq.matrix();
  rel.tq = pq.translation;
  int zero = 0;
  for (const auto& k : convex3::minkowski_facets(P, Q, rel, std::nullopt)) {
    if (k.sign < 0) return false;
    zero += k.sign == 0;
  }
  return zero > 0;
}

// σ (min over all facet normals) from the same enumeration, for σ ≤ σ_d.
double sigma_reference(const ConvexPolytope& P, const Pose3& pp, const ConvexPolytope& Q, const Pose3& pq) {
  Eigen::Matrix3d Rp = pp.matrix(), Rq = pq.matrix();
  convex3::RelativePose rel;
  rel.R = Rp.transpose() * Rq;
  rel.tq = Rp.transpose() * pq.translation;
  rel.tp = Rp.transpose() * pp.translation;
  double s = std::numeric_limits<double>::infinity();
  for (const auto& k : convex3::minkowski_facets(P, Q, rel, std::nullopt)) {
    if (k.sign <= 0) return 0;
    s = std::min(s, k.distance);
  }
  return s;
}

// One query against the facet reference; `tol_ulps` allows for the two roundings of each side.
void check_one(const Depth3& a, const Depth3& r, const ConvexPolytope& P, const Pose3& pp, const Vec3& d,
               Stats& st, const std::string& what, double sigma);

// The public query (the expansion, or DK beyond its work budget) and the DK path itself.
void check(const ConvexPolytope& P, const Pose3& pp, const ConvexPolytope& Q, const Pose3& pq, const Vec3& d,
           Stats& st, const std::string& what, double sigma = -1) {
  Depth3 r = convex3::directional_depth_facets(P, pp, Q, pq, d);
  check_one(directional_depth(P, pp, Q, pq, d), r, P, pp, d, st, what, sigma);
  check_one(convex3::directional_depth_dk(P, pp, Q, pq, d), r, P, pp, d, st, what + " (DK)", sigma);
}

void check_one(const Depth3& a, const Depth3& r, const ConvexPolytope& P, const Pose3& pp, const Vec3& d,
               Stats& st, const std::string& what, double sigma) {
  ++st.queries;
  bool ok = a.overlapping == r.overlapping;
  double e = ulps(a.depth, r.depth);
  if (ok && r.overlapping) {
    ++st.overlapping;
    ok = e <= 8;
    st.max_ulps = std::max(st.max_ulps, e);
    ok = ok && a.lower_bound == a.depth && a.upper_bound == a.depth && std::isfinite(a.depth);
    ok = ok && std::abs(a.translation.norm() - a.depth) <= 1e-12 * (1 + a.depth);
    if (sigma >= 0) ok = ok && sigma <= a.depth * (1 + 1e-12);  // σ ≤ σ_d
    // The exit facet faces d, and its features exist on level 0 of each shape.
    ok = ok && std::abs(a.facet_normal.norm() - 1) < 1e-12 && a.facet_normal.dot(d) > 0;
    ok = ok && a.feature_p.kind != FeatureKind3::None && a.feature_q.kind != FeatureKind3::None;
    ok = ok && a.feature_p.index >= 0 && a.feature_q.index >= 0;
    // The witness lies on the facet plane through P's feature (world frame).
    Vec3 on_p = a.feature_p.kind == FeatureKind3::Vertex ? P[a.feature_p.index]
                : a.feature_p.kind == FeatureKind3::Face  ? P[P.triangles()[a.feature_p.index][0]]
                                                          : P[P.triangles()[a.feature_p.index / 3][a.feature_p.index % 3]];
    Vec3 wp = pp.matrix() * on_p + pp.translation;
    double scale = 1 + wp.norm() + a.witness_p.norm();
    ok = ok && std::abs(a.facet_normal.dot(a.witness_p - wp)) <= 1e-9 * scale;
  } else if (ok) {
    ok = a.depth == 0 && a.translation == Vec3::Zero();
  }
  if (!ok) {
    ++st.failures;
    ADD_FAILURE() << what << ": d = " << d.transpose() << " got " << a.overlapping << " " << a.depth << " ref "
                  << r.overlapping << " " << r.depth << " (" << e << " ulp)";
  }
}

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_unit_quaternion(rng); }

std::vector<Vec3> directions(std::mt19937_64& rng, int k) {
  std::normal_distribution<double> g;
  std::vector<Vec3> d{{1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {1, 1, 0}, {1, -1, 1}};
  while (static_cast<int>(d.size()) < k) d.emplace_back(g(rng), g(rng), g(rng));
  return d;
}

TEST(Directional3, RandomHullsVsFacetReference) {
  std::mt19937_64 rng(5150);
  std::uniform_real_distribution<double> U(-0.7, 0.7);
  Stats st;
  for (int it = 0; it < 60; ++it) {
    int n = 4 + static_cast<int>(rng() % (it < 40 ? 40 : 300)), m = 4 + static_cast<int>(rng() % 60);
    auto P = ConvexPolytope::hull(it % 2 ? test3::random_sphere(rng, n) : test3::random_ball(rng, n + 10));
    auto Q = ConvexPolytope::hull(test3::random_sphere(rng, m, 0.5));
    Pose3 pq(it % 3 ? random_rotation(rng) : Eigen::Quaterniond::Identity(), Vec3(U(rng), U(rng), U(rng)));
    Pose3 pp = it % 4 == 1 ? Pose3(random_rotation(rng), Vec3(U(rng), U(rng), U(rng))) : Pose3();
    double sigma = sigma_reference(P, pp, Q, pq);
    for (const Vec3& d : directions(rng, 7)) check(P, pp, Q, pq, d, st, "random " + std::to_string(it), sigma);
  }
  st.print("random 4..310");
  EXPECT_GT(st.overlapping, 200);
}

TEST(Directional3, LargeHullsVsFacetReference) {
  // 300…2000 vertices against 8…300: the O(n·m) reference stays affordable.
  std::mt19937_64 rng(2000);
  Stats st;
  const int sizes[][2] = {{2000, 8}, {2000, 40}, {800, 150}, {300, 300}};
  for (const auto& s : sizes) {
    auto P = ConvexPolytope::hull(test3::random_sphere(rng, s[0]));
    auto Q = ConvexPolytope::hull(test3::random_sphere(rng, s[1], 0.4));
    Pose3 pq(random_rotation(rng), Vec3(0.5, -0.3, 0.4));
    for (const Vec3& d : directions(rng, 6)) check(P, Pose3(), Q, pq, d, st, "large " + std::to_string(s[0]));
  }
  st.print("large");
  EXPECT_GT(st.overlapping, 20);
}

TEST(Directional3, SharedHulls) {
  auto files = test3::shared_hull_files();
  ASSERT_EQ(files.size(), 60u);
  std::mt19937_64 rng(60);
  Stats st;
  std::vector<ConvexPolytope> H;
  for (const auto& f : files) H.push_back(ConvexPolytope::hull(read_obj_vertices(f), f));
  for (std::size_t i = 0; i < H.size(); ++i) {
    const auto& P = H[i];
    const auto& Q = H[(i + 7) % H.size()];
    Vec3 cp = Vec3::Zero(), cq = Vec3::Zero();
    for (const auto& v : P.vertices()) cp += v / double(P.size());
    for (const auto& v : Q.vertices()) cq += v / double(Q.size());
    auto rot = random_rotation(rng);
    Pose3 pq(rot, cp - rot.toRotationMatrix() * cq + 0.1 * (P[0] - cp));
    for (const Vec3& d : directions(rng, 6)) check(P, Pose3(), Q, pq, d, st, files[i]);
  }
  st.print("shared hulls");
  EXPECT_GT(st.overlapping, 300);
}

TEST(Directional3, IntegerDegenerateSuites) {
  // Integer coordinates and offsets: face–face, parallel edges, vertex–face, identical and
  // touching contacts; axis and diagonal directions run along faces and edges of M.
  std::vector<ConvexPolytope> S;
  for (int N : {3, 9, 11}) S.push_back(ConvexPolytope::hull(test3::integer_sphere(N)));
  S.push_back(ConvexPolytope::hull(test3::prism(25, 2)));
  S.push_back(ConvexPolytope::hull(test3::bipyramid(25)));
  S.push_back(ConvexPolytope::hull(test3::grid(2)));
  S.push_back(ConvexPolytope::hull(test3::grid(3)));
  std::vector<Vec3> dirs{{1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {1, 1, 0}, {1, 0, -1}, {1, 1, 1}, {2, -1, 0}, {1, 2, 3}};
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<int> t(-4, 4);
  Stats st;
  int touch = 0;  // touching placements among them (checked to give 0 like the reference)
  for (std::size_t i = 0; i < S.size(); ++i)
    for (std::size_t j = 0; j < S.size(); ++j)
      for (int k = 0; k < 6; ++k) {
        // k = 0: same placement; 1..3: random integer offsets; 4, 5: Q pushed against P along
        // +x (then shifted by 1 in y) or −z: touching by construction (integer coordinates).
        Vec3 off = k == 0 ? Vec3::Zero() : Vec3(t(rng), t(rng), t(rng));
        auto ext = [](const ConvexPolytope& S, int axis, double sign) {
          double e = -INFINITY;
          for (const auto& v : S.vertices()) e = std::max(e, sign * v[axis]);
          return sign * e;
        };
        if (k == 4) off = Vec3(ext(S[i], 0, 1) - ext(S[j], 0, -1), 1, 0);
        if (k == 5) off = Vec3(0, 0, ext(S[i], 2, -1) - ext(S[j], 2, 1));
        Pose3 pq(off);
        for (const Vec3& d : dirs) check(S[i], Pose3(), S[j], pq, d, st, "int " + std::to_string(i) + "," + std::to_string(j));
        touch += touching(S[i], S[j], pq);
      }
  st.print("integer degenerate");
  EXPECT_GT(st.overlapping, 500);
  std::printf("  of which %d placements touch\n", touch);
  EXPECT_GT(touch, 80);
}

TEST(Directional3, LargeDegenerateAndHighDegree) {
  // Massive coplanarity (integer spheres, prism caps) and hub vertices of degree ~800
  // (bipyramid apexes: the walks' restarts give up on them and walk from the top instead).
  std::vector<Vec3> bip;
  for (int i = 0; i < 800; ++i) {
    double t = 2 * M_PI * i / 800;
    bip.emplace_back(std::cos(t), std::sin(t), 0);
  }
  bip.emplace_back(0, 0, 1.5);
  bip.emplace_back(0, 0, -0.5);
  std::vector<ConvexPolytope> S{ConvexPolytope::hull(test3::integer_sphere(1105)), ConvexPolytope::hull(test3::prism(5525, 30)),
                                ConvexPolytope::hull(test3::bipyramid(5525)), ConvexPolytope::hull(bip, "bipyramid800")};
  auto small = ConvexPolytope::hull(test3::integer_sphere(9));
  std::mt19937_64 rng(1105);
  std::uniform_int_distribution<int> t(-20, 20);
  Stats st;
  std::vector<Vec3> dirs{{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {1, 1, 0}, {1, 2, 5}, {-3, 1, 1}};
  for (std::size_t i = 0; i < S.size(); ++i) {
    double sc = i == 3 ? 0.05 : 1;  // the bipyramid has unit size
    for (int k = 0; k < 2; ++k) {
      Pose3 pq(Vec3(t(rng), t(rng), t(rng)) * sc);
      for (const Vec3& d : dirs) check(S[i], Pose3(), small, pq, d, st, "degenerate " + std::to_string(i));
      // Self pairs under a rotation (not for the 802-vertex bipyramid: seconds a query for the reference).
      Pose3 rq(random_rotation(rng), Vec3(t(rng), t(rng), t(rng)) * sc * 0.5);
      const auto& Q = i == 3 ? small : S[i];
      for (const Vec3& d : dirs) check(S[i], Pose3(), Q, rq, d, st, "pair " + std::to_string(i));
    }
  }
  st.print("large degenerate");
  EXPECT_GT(st.overlapping, 80);
}

TEST(Directional3, AnalyticCubes) {
  auto C = ConvexPolytope::hull(test3::grid(2));  // [0,1]³
  EXPECT_EQ(directional_depth(C, Pose3(), C, Pose3(), Vec3(1, 0, 0)).depth, 1.0);
  EXPECT_EQ(directional_depth(C, Pose3(), C, Pose3(), Vec3(1, 1, 1)).depth, std::sqrt(3.0));
  EXPECT_EQ(directional_depth(C, Pose3(), C, Pose3(), Vec3(0, 2, 0)).depth, 1.0);
  EXPECT_DOUBLE_EQ(directional_depth(C, Pose3(), C, Pose3(Vec3(0.75, 0.1, 0.2)), Vec3(1, 0, 0)).depth, 0.25);
  EXPECT_DOUBLE_EQ(directional_depth(C, Pose3(), C, Pose3(Vec3(0.75, 0.1, 0.2)), Vec3(-1, 0, 0)).depth, 1.75);
  // Touching along a face, an edge, a vertex; separated: 0 whatever the direction.
  for (Vec3 t : {Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(1, 1, 1), Vec3(0, 0.5, 1), Vec3(3, 0, 0)})
    for (Vec3 d : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 1), Vec3(-1, -1, -1)}) {
      Depth3 r = directional_depth(C, Pose3(), C, Pose3(t), d);
      EXPECT_FALSE(r.overlapping) << t.transpose() << " / " << d.transpose();
      EXPECT_EQ(r.depth, 0);
    }
  // Moving along a face of the overlap (d parallel to the contact faces).
  Depth3 r = directional_depth(C, Pose3(), C, Pose3(Vec3(0.5, 0, 0)), Vec3(0, 1, 0));
  EXPECT_TRUE(r.overlapping);
  EXPECT_EQ(r.depth, 1.0);
  EXPECT_EQ(r.facet_normal, Vec3(0, 1, 0));
}

TEST(Directional3, OffsetsAndRigidMotions) {
  // Translating and rotating the whole scene, or offsetting both shapes by 1e6, keeps σ_d;
  // each answer is also checked against the reference under its own (rounded) poses.
  std::mt19937_64 rng(1e6);
  std::uniform_real_distribution<double> U(-0.5, 0.5);
  Stats st;
  for (int it = 0; it < 12; ++it) {
    auto P = ConvexPolytope::hull(test3::random_sphere(rng, 40));
    auto Q = ConvexPolytope::hull(test3::random_ball(rng, 60, 0.6));
    Pose3 pq(random_rotation(rng), Vec3(U(rng), U(rng), U(rng)));
    auto g = random_rotation(rng);
    Vec3 off(1e6, -1e6, 5e5);
    Pose3 gp(g, off), gq(g * pq.rotation, g.toRotationMatrix() * pq.translation + off);
    Pose3 sp(off), sq(pq.rotation, pq.translation + off);
    for (const Vec3& d : directions(rng, 5)) {
      Vec3 gd = g.toRotationMatrix() * d;
      Depth3 a = directional_depth(P, Pose3(), Q, pq, d);
      Depth3 b = directional_depth(P, gp, Q, gq, gd);
      Depth3 c = directional_depth(P, sp, Q, sq, d);
      EXPECT_EQ(a.overlapping, b.overlapping);
      EXPECT_NEAR(a.depth, b.depth, 1e-9);
      EXPECT_NEAR(a.depth, c.depth, 1e-9);
      check(P, gp, Q, gq, gd, st, "rotated+offset");
      check(P, sp, Q, sq, d, st, "offset 1e6");
    }
  }
  st.print("offsets 1e6 / rotations");
  EXPECT_GT(st.overlapping, 60);
}

TEST(Directional3, MoveByResultSeparates) {
  // Moving Q by σ_d·d̂ makes it touch: slightly more separates, slightly less still overlaps.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-0.4, 0.4);
  for (int it = 0; it < 10; ++it) {
    auto P = ConvexPolytope::hull(test3::random_sphere(rng, 3000));
    auto Q = ConvexPolytope::hull(test3::random_sphere(rng, 3000, 0.6));
    Pose3 pq(random_rotation(rng), Vec3(U(rng), U(rng), U(rng)));
    for (const Vec3& d : directions(rng, 6)) {
      Depth3 r = directional_depth(P, Pose3(), Q, pq, d);
      ASSERT_TRUE(r.overlapping);
      Pose3 beyond = pq, short_of = pq;
      beyond.translation += r.translation * (1 + 1e-9);
      short_of.translation += r.translation * (1 - 1e-6);
      EXPECT_FALSE(directional_depth(P, Pose3(), Q, beyond, d).overlapping);
      Depth3 rest = directional_depth(P, Pose3(), Q, short_of, d);
      EXPECT_TRUE(rest.overlapping);
      EXPECT_NEAR(rest.depth, 1e-6 * r.depth, 1e-12);
    }
  }
}

TEST(Directional3, InvalidDirection) {
  auto C = ConvexPolytope::hull(test3::grid(2));
  EXPECT_THROW(directional_depth(C, Pose3(), C, Pose3(), Vec3::Zero()), InvalidInput);
  EXPECT_THROW(directional_depth(C, Pose3(), C, Pose3(), Vec3(NAN, 0, 1)), InvalidInput);
  EXPECT_THROW(directional_depth(C, Pose3(), C, Pose3(), Vec3(INFINITY, 0, 1)), InvalidInput);
  EXPECT_THROW(directional_depth(C, Pose3(Vec3(NAN, 0, 0)), C, Pose3(), Vec3(1, 0, 0)), InvalidInput);
  EXPECT_THROW(directional_depth(C, Pose3(), C, Pose3(Eigen::Quaterniond(0, 0, 0, 0), Vec3::Zero()), Vec3(1, 0, 0)),
               InvalidInput);
  // Tiny and huge directions are scaled exactly: same answer as the unit direction.
  EXPECT_DOUBLE_EQ(directional_depth(C, Pose3(), C, Pose3(Vec3(0.5, 0, 0)), Vec3(1e-300, 0, 0)).depth, 0.5);
  EXPECT_DOUBLE_EQ(directional_depth(C, Pose3(), C, Pose3(Vec3(0.5, 0, 0)), Vec3(1e300, 0, 0)).depth, 0.5);
}

}  // namespace
}  // namespace pendepth
