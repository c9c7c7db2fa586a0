// σ_d by the directional phase of the certified expansion (Phase D of minimum_expand.cpp, behind
// convex3::directional_depth_expand and, for small pairs, pendepth::directional_depth) against
// two independent exact methods: the minimum over ALL implicit facet normals of M
// (directional_depth_facets, O(n·m)) and Compute-Depth-3D on the DK hierarchies
// (directional_depth_dk). Random hulls 4…300 vertices with rotations, the 60 shared hulls,
// integer spheres / prisms / bipyramids / cubes / boxes (coplanar faces, face–face, parallel
// edges), axis-aligned and diagonal directions, rays through vertices and edges of M, touching
// placements (depth 0), exact fits (identical shapes, a box in a box), 1e6 offsets, tiny and
// huge |d|. Every query: overlap decided as both references, depth within 8 ulps of both,
// lower = upper = depth, σ ≤ σ_d, translation = depth·d̂, the facet normal faces d, features
// exist, the witnesses lie on P's supporting plane and coincide.
#include <gtest/gtest.h>

#include <pendepth/depth3.hpp>

#include "convex3/minimum_expand.hpp"
#include "convex3/minkowski_facets.hpp"
#include "shapes3.hpp"

#include <cmath>
#include <limits>
#include <string>
#include "test_rotations.hpp"

namespace pendepth::convex3 {
Depth3 directional_depth_facets(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                                const Pose3& pose_q, const Vec3& d);
}  // namespace pendepth::convex3

namespace pendepth {
namespace {

using test3::ulps;

struct Stats {
  int queries = 0, overlapping = 0, failures = 0;
  double max_ulps_facets = 0, max_ulps_dk = 0;
  std::size_t supports = 0;
  void print(const char* what) const {
    std::printf("%s: %d queries, %d overlapping, %d failures, max error %.2f ulp (facets) %.2f ulp (DK), "
                "%.1f support queries per query\n",
                what, queries, overlapping, failures, max_ulps_facets, max_ulps_dk,
                queries ? double(supports) / queries : 0.0);
  }
};

// One query: the expansion against the facet reference and the DK path; `sigma` (if >= 0) is σ.
void check(const ConvexPolytope& P, const Pose3& pp, const ConvexPolytope& Q, const Pose3& pq, const Vec3& d,
           Stats& st, const std::string& what) {
  SCOPED_TRACE(what + " d = (" + std::to_string(d.x()) + ", " + std::to_string(d.y()) + ", " +
               std::to_string(d.z()) + ")");
  Depth3 a = convex3::directional_depth_expand(P, pp, Q, pq, d);
  Depth3 r = convex3::directional_depth_facets(P, pp, Q, pq, d);
  Depth3 k = convex3::directional_depth_dk(P, pp, Q, pq, d);
  ++st.queries;
  st.supports += a.candidates;
  auto failed_parts = [] { return ::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count(); };
  const int failures = failed_parts();
  EXPECT_EQ(a.kind, DepthKind::Directional);
  ASSERT_EQ(a.overlapping, r.overlapping);
  ASSERT_EQ(a.overlapping, k.overlapping);
  if (!a.overlapping) {
    EXPECT_EQ(a.depth, 0);
    EXPECT_EQ(a.translation, Vec3::Zero());
    EXPECT_EQ(a.feature_p.kind, FeatureKind3::None);
    return;
  }
  ++st.overlapping;
  const double ef = ulps(a.depth, r.depth), ek = ulps(a.depth, k.depth);
  st.max_ulps_facets = std::max(st.max_ulps_facets, ef);
  st.max_ulps_dk = std::max(st.max_ulps_dk, ek);
  EXPECT_LE(ef, 8) << a.depth << " vs facets " << r.depth;
  EXPECT_LE(ek, 8) << a.depth << " vs DK " << k.depth;
  EXPECT_TRUE(std::isfinite(a.depth) && a.depth > 0);
  EXPECT_EQ(a.lower_bound, a.depth);
  EXPECT_EQ(a.upper_bound, a.depth);
  const Vec3 dn = d.normalized();
  EXPECT_LE((a.normal - dn).norm(), 1e-15);
  EXPECT_LE((a.translation - a.depth * dn).norm(), 1e-15 * a.depth);
  Depth3 s = minimum_depth(P, pp, Q, pq);
  EXPECT_TRUE(s.overlapping);
  EXPECT_LE(s.depth, a.depth * (1 + 1e-15)) << "σ > σ_d";
  // The exit facet faces d and its plane supports M at the exit point: h_P(u) − min u·q' = u·v
  // (u = facet_normal, v = translation; a tie on an edge of M may pick either facet, so the
  // normal itself is not compared). Features exist; the witnesses lie on P's support plane and
  // coincide (world frame).
  const Vec3 u = a.facet_normal;
  EXPECT_NEAR(u.norm(), 1, 1e-15);
  EXPECT_GT(u.dot(d), 0);
  EXPECT_NE(a.feature_p.kind, FeatureKind3::None);
  EXPECT_NE(a.feature_q.kind, FeatureKind3::None);
  double hp = -std::numeric_limits<double>::infinity(), hq = std::numeric_limits<double>::infinity(), scale = 1;
  for (const Vec3& p : P.vertices()) {
    const Vec3 w = pp.apply(p);
    hp = std::max(hp, u.dot(w)), scale = std::max(scale, w.norm());
  }
  for (const Vec3& q : Q.vertices()) {
    const Vec3 w = pq.apply(q);
    hq = std::min(hq, u.dot(w)), scale = std::max(scale, w.norm());
  }
  const double tol = 1e-12 * scale;
  EXPECT_NEAR(hp - hq, u.dot(a.translation), tol) << "the facet plane does not support M at the exit";
  EXPECT_NEAR(u.dot(a.witness_p), hp, tol);
  EXPECT_LE((a.witness_p - a.witness_q).norm(), tol);
  if (failed_parts() != failures) ++st.failures;
}

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_unit_quaternion(rng); }

std::vector<Vec3> directions(std::mt19937_64& rng, int k) {
  std::normal_distribution<double> g;
  std::vector<Vec3> d{{1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {1, 1, 0}, {1, -1, 1}};
  while (static_cast<int>(d.size()) < k) d.emplace_back(g(rng), g(rng), g(rng));
  return d;
}

// Points of ∂M in P's frame for Q placed by pq (P at the identity): m(u) = support_P(u) −
// support_Q'(−u), a vertex of M for a generic u; the sum of two such points for nearby u (on an
// edge or facet of M, often an edge). As directions from 0 they aim rays at vertices and edges of M.
std::vector<Vec3> boundary_directions(const ConvexPolytope& P, const ConvexPolytope& Q, const Pose3& pq,
                                      std::mt19937_64& rng, int k) {
  std::normal_distribution<double> g;
  const Eigen::Matrix3d R = pq.matrix();
  auto m = [&](const Vec3& u) {
    int i = P.support(u), j = Q.support(-(R.transpose() * u));
    return Vec3(P[i] - (R * Q[j] + pq.translation));
  };
  std::vector<Vec3> d;
  while (static_cast<int>(d.size()) < k) {
    Vec3 u(g(rng), g(rng), g(rng));
    Vec3 a = m(u), b = m(u + 0.3 * Vec3(g(rng), g(rng), g(rng)));
    if (a != Vec3::Zero()) d.push_back(a);
    if (a + b != Vec3::Zero()) d.push_back(a + b);
  }
  return d;
}

TEST(DirectionalExpand, RandomHulls) {
  std::mt19937_64 rng(31337);
  std::uniform_real_distribution<double> U(-0.7, 0.7);
  Stats st;
  const int sizes[] = {4, 5, 6, 8, 12, 16, 24, 32, 48, 64, 100, 300};
  for (int it = 0; it < 96; ++it) {
    const int n = sizes[it % 12], m = sizes[(it / 12 + it) % 12];
    auto P = ConvexPolytope::hull(it % 3 ? test3::random_sphere(rng, n) : test3::random_ball(rng, n + 6));
    auto Q = ConvexPolytope::hull(it % 4 ? test3::random_sphere(rng, m, 0.6) : test3::random_ball(rng, m + 6, 0.6));
    Pose3 pq(it % 5 ? random_rotation(rng) : Eigen::Quaterniond::Identity(), Vec3(U(rng), U(rng), U(rng)));
    Pose3 pp = it % 7 == 0 ? Pose3(random_rotation(rng), Vec3(U(rng), U(rng), U(rng))) : Pose3();
    for (const Vec3& d : directions(rng, 8)) check(P, pp, Q, pq, d, st, "random " + std::to_string(it));
    if (pp.translation == Vec3::Zero())
      for (const Vec3& d : boundary_directions(P, Q, pq, rng, 4)) check(P, pp, Q, pq, d, st, "random ∂M " + std::to_string(it));
  }
  st.print("random hulls");
  EXPECT_EQ(st.failures, 0);
  EXPECT_GT(st.overlapping, 500);
}

TEST(DirectionalExpand, SharedHulls) {
  auto files = test3::shared_hull_files();
  ASSERT_EQ(files.size(), 60u);
  std::vector<ConvexPolytope> H;
  for (const auto& f : files) H.push_back(ConvexPolytope::hull(read_obj_vertices(f), f));
  std::mt19937_64 rng(606060);
  std::uniform_real_distribution<double> U(-0.3, 0.3);
  Stats st;
  for (std::size_t i = 0; i < H.size(); ++i) {
    const auto &P = H[i], &Q = H[(i + 11) % H.size()];
    Vec3 cp = Vec3::Zero(), cq = Vec3::Zero();
    double r = 0;
    for (const auto& v : P.vertices()) cp += v / double(P.size());
    for (const auto& v : Q.vertices()) cq += v / double(Q.size());
    for (const auto& v : P.vertices()) r = std::max(r, (v - cp).norm());
    auto rot = random_rotation(rng);
    Pose3 pq(rot, cp - rot.toRotationMatrix() * cq + r * Vec3(U(rng), U(rng), U(rng)));
    for (const Vec3& d : directions(rng, 6)) check(P, Pose3(), Q, pq, d, st, files[i]);
    for (const Vec3& d : boundary_directions(P, Q, pq, rng, 4)) check(P, Pose3(), Q, pq, d, st, files[i] + " ∂M");
    check(P, Pose3(), P, Pose3(), Vec3(0.3, -0.5, 0.8), st, files[i] + " identical");
  }
  st.print("shared hulls");
  EXPECT_EQ(st.failures, 0);
  EXPECT_GT(st.overlapping, 500);
}

TEST(DirectionalExpand, IntegerDegenerateShapes) {
  // Integer coordinates and offsets, identity or quarter-turn rotations (exact for the doubles
  // of the rounded matrix): face–face, parallel edges, vertex–face, identical shapes, touching;
  // axis and diagonal directions run along faces and edges of M; rays aimed at vertices and
  // edges of M.
  std::vector<std::pair<std::string, ConvexPolytope>> S;
  for (int N : {3, 9, 11}) S.push_back({"sphere" + std::to_string(N), ConvexPolytope::hull(test3::integer_sphere(N))});
  S.push_back({"prism25", ConvexPolytope::hull(test3::prism(25, 2))});
  S.push_back({"bipyramid25", ConvexPolytope::hull(test3::bipyramid(25))});
  S.push_back({"cube2", ConvexPolytope::hull(test3::grid(2))});
  S.push_back({"cube3", ConvexPolytope::hull(test3::grid(3))});
  S.push_back({"box", ConvexPolytope::hull(std::vector<Vec3>{{0, 0, 0}, {3, 0, 0}, {0, 1, 0}, {3, 1, 0}, {0, 0, 2},
                                                              {3, 0, 2}, {0, 1, 2}, {3, 1, 2}})});
  const std::vector<Vec3> dirs{{1, 0, 0},  {0, 1, 0},  {0, 0, -1}, {1, 1, 0},  {1, 0, -1},
                               {1, 1, 1},  {2, -1, 0}, {1, 2, 3},  {-1, -1, 1}};
  const Eigen::Quaterniond rots[] = {Eigen::Quaterniond::Identity(), Eigen::Quaterniond(1, 0, 0, 1),
                                     Eigen::Quaterniond(0, 1, 0, 0)};
  std::mt19937_64 rng(4711);
  std::uniform_int_distribution<int> t(-3, 3);
  auto ext = [](const ConvexPolytope& C, int axis, double sign) {
    double e = -INFINITY;
    for (const auto& v : C.vertices()) e = std::max(e, sign * v[axis]);
    return sign * e;
  };
  Stats st;
  int touching = 0;
  for (std::size_t i = 0; i < S.size(); ++i)
    for (std::size_t j = 0; j < S.size(); ++j)
      for (int k = 0; k < 6; ++k) {
        // k = 0: same placement; 1..3: random integer offsets (rotated for k = 2, 3); 4, 5: Q
        // pushed against P along +x (then shifted by 1 in y) or −z: touching by construction.
        const auto &P = S[i].second, &Q = S[j].second;
        Vec3 off = k == 0 ? Vec3::Zero() : Vec3(t(rng), t(rng), t(rng));
        if (k == 4) off = Vec3(ext(P, 0, 1) - ext(Q, 0, -1), 1, 0);
        if (k == 5) off = Vec3(0, 0, ext(P, 2, -1) - ext(Q, 2, 1));
        Pose3 pq(k == 2 || k == 3 ? rots[(i + j + k) % 3] : Eigen::Quaterniond::Identity(), off);
        const std::string what = S[i].first + " vs " + S[j].first + " " + std::to_string(k);
        const int before = st.overlapping;
        for (const Vec3& d : dirs) check(P, Pose3(), Q, pq, d, st, what);
        touching += k >= 4 && st.overlapping == before;
        for (const Vec3& d : boundary_directions(P, Q, pq, rng, 4)) check(P, Pose3(), Q, pq, d, st, what + " ∂M");
      }
  st.print("integer degenerate");
  std::printf("  of which %d placements pushed into contact have depth 0\n", touching);
  EXPECT_EQ(st.failures, 0);
  EXPECT_GT(st.overlapping, 1000);
  EXPECT_GT(touching, 50);
}

TEST(DirectionalExpand, AnalyticCubesAndFits) {
  auto C = ConvexPolytope::hull(test3::grid(2));  // [0,1]³
  auto run = [&](const Pose3& pq, const Vec3& d) { return convex3::directional_depth_expand(C, Pose3(), C, pq, d); };
  EXPECT_EQ(run(Pose3(), Vec3(1, 0, 0)).depth, 1.0);
  EXPECT_EQ(run(Pose3(), Vec3(1, 1, 1)).depth, std::sqrt(3.0));
  EXPECT_EQ(run(Pose3(), Vec3(0, 2, 0)).depth, 1.0);
  EXPECT_EQ(run(Pose3(Vec3(0.75, 0.125, 0.25)), Vec3(1, 0, 0)).depth, 0.25);
  EXPECT_EQ(run(Pose3(Vec3(0.75, 0.125, 0.25)), Vec3(-1, 0, 0)).depth, 1.75);
  // Touching along a face, an edge, a vertex; separated: 0 whatever the direction.
  for (Vec3 t : {Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(1, 1, 1), Vec3(0, 0.5, 1), Vec3(3, 0, 0)})
    for (Vec3 d : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 1), Vec3(-1, -1, -1)}) {
      Depth3 r = run(Pose3(t), d);
      EXPECT_FALSE(r.overlapping) << t.transpose() << " / " << d.transpose();
      EXPECT_EQ(r.depth, 0);
      EXPECT_EQ(r.kind, DepthKind::Directional);
    }
  // Along a face of the overlap (d parallel to the contact faces); through an edge of M.
  Depth3 r = run(Pose3(Vec3(0.5, 0, 0)), Vec3(0, 1, 0));
  EXPECT_TRUE(r.overlapping);
  EXPECT_EQ(r.depth, 1.0);
  EXPECT_EQ(r.facet_normal, Vec3(0, 1, 0));
  EXPECT_EQ(run(Pose3(Vec3(0.5, 0.5, 0)), Vec3(1, 1, 0)).depth, std::sqrt(0.5));
  // Exact fit: a 1×1×1 cube in a 1×1×2 box shifted by 0.5 (Q exactly inside P, sliding along z).
  auto B = ConvexPolytope::hull(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 2},
                                                  {1, 0, 2}, {0, 1, 2}, {1, 1, 2}});
  Depth3 fit = convex3::directional_depth_expand(B, Pose3(), C, Pose3(Vec3(0, 0, 0.5)), Vec3(0, 0, 1));
  EXPECT_EQ(fit.depth, 1.5);
  fit = convex3::directional_depth_expand(B, Pose3(), C, Pose3(Vec3(0, 0, 0.5)), Vec3(1, 0, 0));
  EXPECT_EQ(fit.depth, 1.0);
  // Tiny and huge |d|: scaled exactly, the same answer.
  EXPECT_EQ(run(Pose3(Vec3(0.5, 0, 0)), Vec3(1e-300, 0, 0)).depth, 0.5);
  EXPECT_EQ(run(Pose3(Vec3(0.5, 0, 0)), Vec3(1e300, 0, 0)).depth, 0.5);
  EXPECT_EQ(run(Pose3(Vec3(0.5, 0, 0)), Vec3(4e-320, 0, 0)).depth, 0.5);  // subnormal
  EXPECT_THROW(run(Pose3(), Vec3::Zero()), InvalidInput);
  EXPECT_THROW(run(Pose3(), Vec3(NAN, 0, 1)), InvalidInput);
  EXPECT_THROW(run(Pose3(), Vec3(INFINITY, 0, 1)), InvalidInput);
}

TEST(DirectionalExpand, RotatedSymmetricShapesAndOffsets) {
  // Identical boxes / integer balls under random rotations (exactly coplanar quadruples of
  // pairs), both shapes posed and moved 1e6 away; the scene rotated as a whole.
  std::mt19937_64 rng(8128);
  std::uniform_real_distribution<double> U(-0.6, 0.6);
  Stats st;
  auto box = ConvexPolytope::hull(test3::grid(2));
  auto ball = ConvexPolytope::hull(test3::integer_sphere(50));
  auto rs = ConvexPolytope::hull(test3::random_sphere(rng, 40));
  const Vec3 off(1e6, -1e6, 5e5);
  for (int it = 0; it < 24; ++it) {
    Pose3 pq(random_rotation(rng), Vec3(U(rng), U(rng), U(rng)));
    auto g = random_rotation(rng);
    Pose3 gp(g, off), gq(g * pq.rotation, g.toRotationMatrix() * pq.translation + off);
    for (const Vec3& d : directions(rng, 6)) {
      check(box, Pose3(), box, pq, d, st, "box " + std::to_string(it));
      check(ball, Pose3(), ball, Pose3(pq.rotation, 6 * pq.translation), d, st, "ball " + std::to_string(it));
      check(rs, gp, rs, gq, g.toRotationMatrix() * d, st, "posed 1e6 " + std::to_string(it));
    }
  }
  st.print("rotated symmetric / offsets");
  EXPECT_EQ(st.failures, 0);
  EXPECT_GT(st.overlapping, 300);
}

TEST(DirectionalExpand, NearlyCoplanarAndSlivers) {
  std::mt19937_64 rng(7331);
  std::uniform_real_distribution<double> U(-0.3, 0.3);
  Stats st;
  // A cube with points pushed out of its faces by 1e-13…1e-9; a hull against itself rotated by
  // a tiny angle; slivers (thickness 1e-6).
  std::vector<Vec3> bumpy = test3::grid(2);
  std::uniform_real_distribution<double> F(0.1, 0.9);
  for (int k = 0; k < 24; ++k) {
    const int ax = k % 3;
    Vec3 p(F(rng), F(rng), F(rng));
    p[ax] = (k / 3) % 2 ? 1 + std::pow(10.0, -13 + k % 5) : -std::pow(10.0, -13 + k % 5);
    bumpy.push_back(p);
  }
  auto B = ConvexPolytope::hull(bumpy), C = ConvexPolytope::hull(test3::grid(2));
  for (int it = 0; it < 8; ++it)
    for (const Vec3& d : directions(rng, 6)) {
      check(B, Pose3(), C, Pose3(Vec3(0.6 + U(rng), U(rng), U(rng))), d, st, "bumpy " + std::to_string(it));
      Vec3 axis = Vec3(U(rng), U(rng), U(rng)).normalized();
      auto P = ConvexPolytope::hull(test3::random_sphere(rng, 30));
      check(P, Pose3(), P, Pose3(Eigen::Quaterniond(Eigen::AngleAxisd(std::pow(10.0, -12 + it), axis)),
                                 Vec3(U(rng), U(rng), U(rng))),
            d, st, "tiny rotation " + std::to_string(it));
      auto a = test3::random_sphere(rng, 40);
      for (auto& p : a) p.z() *= 1e-6;
      auto S = ConvexPolytope::hull(a), Q = ConvexPolytope::hull(test3::random_sphere(rng, 25, 0.7));
      check(S, Pose3(), Q, Pose3(random_rotation(rng), Vec3(U(rng), U(rng), 1e-7 * U(rng))), d, st,
            "sliver " + std::to_string(it));
      check(Q, Pose3(), S, Pose3(random_rotation(rng), Vec3(U(rng), U(rng), U(rng))), d, st,
            "sliver moving " + std::to_string(it));
    }
  st.print("nearly coplanar / slivers");
  EXPECT_EQ(st.failures, 0);
  EXPECT_GT(st.overlapping, 100);
}

TEST(DirectionalExpand, PublicQueryAndWorkBudget) {
  // pendepth::directional_depth runs the expansion within a work budget O(log n · log m) (same
  // bits), Compute-Depth-3D when the budget runs out; the budget is checked as documented.
  std::mt19937_64 rng(12);
  auto P = ConvexPolytope::hull(test3::random_sphere(rng, 40));
  auto Q = ConvexPolytope::hull(test3::random_sphere(rng, 30, 0.6));
  Pose3 pq(random_rotation(rng), Vec3(0.2, 0.1, -0.3));
  convex3::RelativePose rel;
  rel.R = pq.matrix(), rel.tq = pq.translation;
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  for (const Vec3& d : directions(rng, 6)) {
    Depth3 a = directional_depth(P, Pose3(), Q, pq, d), b = convex3::directional_depth_expand(P, Pose3(), Q, pq, d);
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.candidates, b.candidates);
    EXPECT_EQ(a.witness_p, b.witness_p);
    std::size_t work = 0;
    auto full = convex3::directional_depth_expand(P, Q, rel, d, I, Vec3::Zero(), SIZE_MAX, &work);
    ASSERT_TRUE(full.has_value());
    EXPECT_EQ(full->depth, b.depth);
    EXPECT_LT(work, convex3::directional_work_budget(P.size(), Q.size()) / 4);  // typical: far below
    // Exactly the work needed passes; less gives up (before any answer).
    EXPECT_TRUE(convex3::directional_depth_expand(P, Q, rel, d, I, Vec3::Zero(), work).has_value());
    EXPECT_FALSE(convex3::directional_depth_expand(P, Q, rel, d, I, Vec3::Zero(), work / 2).has_value());
    EXPECT_FALSE(convex3::directional_depth_expand(P, Q, rel, d, I, Vec3::Zero(), 0).has_value());
  }
  // A hub vertex of degree 8000 (bipyramid apexes): climbs through it scan 8000 neighbours, so
  // some queries exceed the budget and are answered by Compute-Depth-3D (same bits as
  // directional_depth_dk); the others by the expansion.
  std::vector<Vec3> bip;
  for (int i = 0; i < 8000; ++i) {
    const double a = 2 * M_PI * i / 8000;
    bip.emplace_back(std::cos(a), std::sin(a), 0);
  }
  bip.emplace_back(0, 0, 1.5), bip.emplace_back(0, 0, -0.5);
  auto H = ConvexPolytope::hull(bip, "bipyramid8000");
  auto S = ConvexPolytope::hull(test3::random_sphere(rng, 24, 0.3));
  int fallbacks = 0, direct = 0;
  std::uniform_real_distribution<double> U(-0.5, 0.5);
  for (int it = 0; it < 64 && (fallbacks < 2 || direct < 2); ++it) {
    Pose3 hq(random_rotation(rng), Vec3(U(rng), U(rng), 0.3 * U(rng)));
    Vec3 d = directions(rng, 6).back();
    convex3::RelativePose hr;
    hr.R = hq.matrix(), hr.tq = hq.translation;
    std::size_t work = 0;
    auto e = convex3::directional_depth_expand(H, S, hr, d, I, Vec3::Zero(), SIZE_MAX, &work);
    ASSERT_TRUE(e.has_value());
    Depth3 pub = directional_depth(H, Pose3(), S, hq, d);
    if (work > convex3::directional_work_budget(H.size(), S.size())) {
      ++fallbacks;
      Depth3 k = convex3::directional_depth_dk(H, Pose3(), S, hq, d);
      EXPECT_EQ(pub.depth, k.depth);
      EXPECT_EQ(pub.candidates, k.candidates);
      EXPECT_LE(ulps(pub.depth, e->depth), 8);
    } else {
      ++direct;
      EXPECT_EQ(pub.depth, e->depth);
    }
    EXPECT_EQ(pub.overlapping, e->overlapping);
  }
  std::printf("bipyramid8000: %d queries over budget (DK), %d by the expansion\n", fallbacks, direct);
  EXPECT_GE(fallbacks, 1);
  EXPECT_GE(direct, 1);
  // Budgets grow as log n · log m.
  EXPECT_EQ(convex3::directional_work_budget(1, 1), convex3::kExpandWorkBase + convex3::kExpandWorkPerLog);
  EXPECT_EQ(convex3::directional_work_budget(1023, 1023), convex3::kExpandWorkBase + 100 * convex3::kExpandWorkPerLog);
}

}  // namespace
}  // namespace pendepth
