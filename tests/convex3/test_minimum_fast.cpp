// σ by certified expansion (src/convex3/minimum_expand.cpp) against the exact O(n·m) reference
// (min over every implicit facet normal of M, src/convex3/minkowski_facets.cpp): random hulls of
// 4…2,000 vertices, the 60 shared hulls, integer spheres / prisms / bipyramids / cubes (massive
// coplanarity, face–face, edge–edge parallel, vertex–face, touching), identical shapes (also
// rotated boxes: exact coincidences), 1e6 offsets, nearly coplanar facets (near-90° rotations,
// tiny rotations, perturbed faces), slivers.
// Every overlapping case also checks: bounds coincide, the features lie on the supporting planes
// of P and Q' for the returned normal, the witnesses coincide on them, and (for a subset) moving
// Q by the translation separates while a slightly shorter move does not.
#include <gtest/gtest.h>

#include <pendepth/depth3.hpp>

#include "convex3/minimum_expand.hpp"
#include "convex3/minkowski_facets.hpp"
#include "convex3/polytope_data.hpp"
#include "shapes3.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include "test_rotations.hpp"

namespace pendepth {
namespace {

using convex3::RelativePose;

// Q in P's frame, formed exactly as depth3.cpp does.
RelativePose relative_pose(const Pose3& pp, const Pose3& pq) {
  Eigen::Matrix3d Rp = pp.matrix(), Rq = pq.matrix();
  RelativePose r;
  r.R = Rp.transpose() * Rq;
  r.tq = Rp.transpose() * pq.translation;
  r.tp = Rp.transpose() * pp.translation;
  return r;
}

struct Ref {
  bool overlapping = true;
  double sigma = std::numeric_limits<double>::infinity();
};

// The O(n·m) exact method: σ = min over all facet normals of M, 0 ∉ int M iff some h_M(u) <= 0.
Ref reference(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel) {
  Ref r;
  for (const auto& k : convex3::minkowski_facets(P, Q, rel, std::nullopt)) {
    if (k.sign <= 0) return Ref{false, 0};
    r.sigma = std::min(r.sigma, k.distance);
  }
  return r;
}

struct Stats {
  int cases = 0, overlapping = 0;
  double max_ulps = 0;
  std::size_t supports = 0;
  void print(const char* what) const {
    std::printf("%s: %d cases, %d overlapping, max error %.2f ulp, %.1f support queries per case\n", what, cases,
                overlapping, max_ulps, cases ? double(supports) / cases : 0.0);
  }
};

std::vector<Vec3> feature_vertices(const ConvexPolytope& S, const Feature3& f) {
  const auto& L = convex3::data_of(S).levels[0];
  switch (f.kind) {
    case FeatureKind3::Vertex: return {S[f.index]};
    case FeatureKind3::Edge: return {S[L.origin(f.index)], S[L.target(f.index)]};
    case FeatureKind3::Face: {
      auto t = S.triangles()[f.index];
      return {S[t[0]], S[t[1]], S[t[2]]};
    }
    default: return {};
  }
}

// Compares minimum_depth with the reference; checks bounds, features, witnesses, and (if
// `move`) that the translation separates while a shorter one does not.
void check(const ConvexPolytope& P, const Pose3& pp, const ConvexPolytope& Q, const Pose3& pq, Stats& st,
           const std::string& what, bool move = false) {
  SCOPED_TRACE(what);
  RelativePose rel = relative_pose(pp, pq);
  Ref ref = reference(P, Q, rel);
  Depth3 d = minimum_depth(P, pp, Q, pq);
  Depth3 direct = convex3::minimum_depth_expand(P, Q, rel, pp.matrix(), pp.translation);
  ++st.cases;
  st.supports += d.candidates;
  EXPECT_EQ(d.depth, direct.depth);  // the public query is this method
  ASSERT_EQ(d.overlapping, ref.overlapping);
  if (!ref.overlapping) {
    EXPECT_EQ(d.depth, 0);
    EXPECT_EQ(d.translation, Vec3::Zero());
    EXPECT_EQ(d.feature_p.kind, FeatureKind3::None);
    return;
  }
  ++st.overlapping;
  EXPECT_EQ(d.lower_bound, d.depth);
  EXPECT_EQ(d.upper_bound, d.depth);
  ASSERT_GT(d.depth, 0);
  double ulps = std::abs(d.depth - ref.sigma) / (ref.sigma * 0x1p-52);
  st.max_ulps = std::max(st.max_ulps, ulps);
  EXPECT_LE(ulps, 8) << "depth " << d.depth << " reference " << ref.sigma;
  EXPECT_NEAR(d.normal.norm(), 1, 1e-15);
  EXPECT_NEAR((d.translation - d.depth * d.normal).norm(), 0, 1e-15 * d.depth);

  // In P's frame: the features lie on the supporting planes of P (max n·p) and Q' (min n·q'),
  // and the witnesses on both planes (after the move) at the same point.
  Eigen::Matrix3d Rp = pp.matrix();
  Vec3 n = Rp.transpose() * d.normal;
  double hp = -std::numeric_limits<double>::infinity(), hq = std::numeric_limits<double>::infinity(), scale = 0;
  for (const Vec3& p : P.vertices()) hp = std::max(hp, n.dot(p)), scale = std::max(scale, p.norm());
  for (const Vec3& q : Q.vertices()) hq = std::min(hq, n.dot(rel.place(q))), scale = std::max(scale, q.norm());
  scale += rel.tq.norm() + rel.tp.norm();
  const double tol = 1e-12 * scale;
  EXPECT_NEAR(hp - hq, d.depth, tol);
  auto kinds = std::make_pair(d.feature_p.kind, d.feature_q.kind);
  EXPECT_TRUE(kinds == std::make_pair(FeatureKind3::Face, FeatureKind3::Vertex) ||
              kinds == std::make_pair(FeatureKind3::Vertex, FeatureKind3::Face) ||
              kinds == std::make_pair(FeatureKind3::Edge, FeatureKind3::Edge));
  for (const Vec3& p : feature_vertices(P, d.feature_p)) EXPECT_NEAR(n.dot(p), hp, tol);
  for (const Vec3& q : feature_vertices(Q, d.feature_q)) EXPECT_NEAR(n.dot(rel.place(q)), hq, tol);
  Vec3 wp = Rp.transpose() * (d.witness_p - pp.translation);
  EXPECT_NEAR(n.dot(wp), hp, tol);
  EXPECT_NEAR((d.witness_p - d.witness_q).norm(), 0, tol);

  if (move) {
    Pose3 moved = pq, short_of = pq;
    moved.translation += d.translation * (1 + 1e-9);
    short_of.translation += d.translation * (1 - 1e-6);
    EXPECT_FALSE(minimum_depth(P, pp, Q, moved).overlapping);
    EXPECT_TRUE(minimum_depth(P, pp, Q, short_of).overlapping);
  }
}

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_unit_quaternion(rng); }

Vec3 centroid(const ConvexPolytope& S) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& v : S.vertices()) c += v / double(S.size());
  return c;
}

TEST(MinimumFast, RandomHulls) {
  std::mt19937_64 rng(1001);
  Stats st;
  std::uniform_real_distribution<double> U(-0.7, 0.7);
  const int nsizes[] = {4, 5, 6, 8, 12, 20, 40, 100, 300};
  for (int it = 0; it < 90; ++it) {
    int n = nsizes[it % 9], m = nsizes[(it / 9 + it) % 9];
    auto P = ConvexPolytope::hull(it % 3 ? test3::random_sphere(rng, n) : test3::random_ball(rng, n + 6));
    auto Q = ConvexPolytope::hull(it % 4 ? test3::random_sphere(rng, m, 0.6) : test3::random_ball(rng, m + 6, 0.6));
    Pose3 pq(it % 5 ? random_rotation(rng) : Eigen::Quaterniond::Identity(), Vec3(U(rng), U(rng), U(rng)));
    Pose3 pp = it % 7 == 0 ? Pose3(random_rotation(rng), Vec3(U(rng), U(rng), U(rng))) : Pose3();
    check(P, pp, Q, pq, st, "random " + std::to_string(it), it % 10 == 0);
  }
  // 2,000 vertices against small hulls (the reference is O(n·m)).
  auto big = ConvexPolytope::hull(test3::random_sphere(rng, 2000));
  for (int it = 0; it < 4; ++it) {
    auto Q = ConvexPolytope::hull(test3::random_sphere(rng, 12 + 10 * it, 0.4));
    check(big, Pose3(), Q, Pose3(random_rotation(rng), Vec3(U(rng), U(rng), U(rng))), st, "2000 " + std::to_string(it),
          true);
  }
  EXPECT_GT(st.overlapping, 70);
  st.print("random hulls");
}

TEST(MinimumFast, SharedHullPairs) {
  auto files = test3::shared_hull_files();
  ASSERT_EQ(files.size(), 60u);
  std::vector<ConvexPolytope> H;
  for (const auto& f : files) H.push_back(ConvexPolytope::hull(read_obj_vertices(f)));
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> U(-0.3, 0.3);
  Stats st;
  for (std::size_t i = 0; i < H.size(); ++i) {
    const auto &P = H[i], &Q = H[(i + 17) % H.size()];
    double scale = 0;
    Vec3 cp = centroid(P);
    for (const Vec3& v : P.vertices()) scale = std::max(scale, (v - cp).norm());
    auto rot = random_rotation(rng);
    Vec3 off = scale * Vec3(U(rng), U(rng), U(rng));
    Pose3 pq(rot, cp + off - rot.toRotationMatrix() * centroid(Q));
    check(P, Pose3(), Q, pq, st, files[i], i % 6 == 0);
  }
  // Identical shapes at the same place: σ is the width of the shape.
  for (std::size_t i = 0; i < H.size(); i += 6) check(H[i], Pose3(), H[i], Pose3(), st, "identical " + files[i]);
  EXPECT_GT(st.overlapping, 55);
  st.print("shared hulls");
}

TEST(MinimumFast, IntegerCoplanarShapes) {
  // Integer coordinates and offsets, identity or exact axis rotations: face–face, edge–edge
  // parallel, vertex–face, identical shapes and touching contacts (exact zeros everywhere).
  std::vector<std::pair<std::string, ConvexPolytope>> S;
  for (int N : {3, 9, 11, 27}) S.push_back({"sphere" + std::to_string(N), ConvexPolytope::hull(test3::integer_sphere(N))});
  S.push_back({"prism25", ConvexPolytope::hull(test3::prism(25, 2))});
  S.push_back({"prism65", ConvexPolytope::hull(test3::prism(65, 3))});
  S.push_back({"bipyramid25", ConvexPolytope::hull(test3::bipyramid(25))});
  S.push_back({"cube3", ConvexPolytope::hull(test3::grid(3))});
  S.push_back({"cube2", ConvexPolytope::hull(test3::grid(2))});
  std::mt19937_64 rng(2719);
  std::uniform_int_distribution<int> t(-5, 5);
  // Rotations by multiples of 90° about an axis, given by unnormalised quaternions: R is the
  // rounded matrix (nearly, not exactly, a permutation) — nearly coplanar facets.
  const Eigen::Quaterniond rots[] = {Eigen::Quaterniond::Identity(), Eigen::Quaterniond(1, 0, 0, 1),
                                     Eigen::Quaterniond(0, 1, 0, 0), Eigen::Quaterniond(1, 1, 0, 0)};
  Stats st;
  for (std::size_t i = 0; i < S.size(); ++i)
    for (std::size_t j = 0; j < S.size(); ++j) {
      check(S[i].second, Pose3(), S[j].second, Pose3(), st, S[i].first + " vs " + S[j].first + " at 0");
      for (int k = 0; k < 4; ++k) {
        Pose3 pq(rots[(i + j + k) % 4], Vec3(t(rng), t(rng), t(rng)));
        check(S[i].second, Pose3(), S[j].second, pq, st, S[i].first + " vs " + S[j].first + " " + std::to_string(k),
              k == 0);
      }
    }
  EXPECT_GT(st.overlapping, 200);
  st.print("integer coplanar shapes");
}

TEST(MinimumFast, AnalyticContacts) {
  auto C = ConvexPolytope::hull(test3::grid(2));  // unit cube
  // Touching (face, edge, vertex) and separated: depth 0.
  for (Vec3 t : {Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(1, 1, 1), Vec3(0.5, 1, 0.25), Vec3(0, 0, -1), Vec3(2, 0, 0)}) {
    Depth3 d = minimum_depth(C, Pose3(), C, Pose3(t));
    EXPECT_FALSE(d.overlapping) << t.transpose();
    EXPECT_EQ(d.depth, 0);
  }
  // Face–face: σ = 0.25 exactly, P's face and a Q vertex define the facet.
  Depth3 d = minimum_depth(C, Pose3(), C, Pose3(Vec3(0.75, 0.125, 0.5)));
  EXPECT_EQ(d.depth, 0.25);
  EXPECT_EQ(d.normal, Vec3(1, 0, 0));
  EXPECT_EQ(d.feature_p.kind, FeatureKind3::Face);
  EXPECT_EQ(d.feature_q.kind, FeatureKind3::Vertex);
  // Edge–edge: P's ridge (along x, z = 1) and Q's keel (along y, 0.5 below it after the
  // placement) cross; every sideways escape is longer than lifting Q by 0.5.
  std::vector<Vec3> wedge_p{{-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {1, 1, 0}, {-1, 0, 1}, {1, 0, 1}};
  std::vector<Vec3> wedge_q{{-1, -1, 0}, {-1, 1, 0}, {1, -1, 0}, {1, 1, 0}, {0, -1, -1}, {0, 1, -1}};
  auto A = ConvexPolytope::hull(wedge_p), B = ConvexPolytope::hull(wedge_q);
  d = minimum_depth(A, Pose3(), B, Pose3(Vec3(0, 0, 1.5)));
  ASSERT_TRUE(d.overlapping);
  EXPECT_EQ(d.depth, 0.5);
  EXPECT_EQ(d.normal, Vec3(0, 0, 1));
  EXPECT_EQ(d.feature_p.kind, FeatureKind3::Edge);
  EXPECT_EQ(d.feature_q.kind, FeatureKind3::Edge);
  EXPECT_EQ(d.witness_p, Vec3(0, 0, 1));
  // Identical shapes in place: σ = 1 (the cube's width), exactly.
  EXPECT_EQ(minimum_depth(C, Pose3(), C, Pose3()).depth, 1.0);
}

TEST(MinimumFast, LargeOffsets) {
  // Both shapes 1e6 away from the origin (in their poses and in their own coordinates): exact
  // against the reference for the same doubles, and close to the unshifted answer.
  std::mt19937_64 rng(606);
  std::uniform_real_distribution<double> U(-0.6, 0.6);
  Stats st;
  const Vec3 off(1e6, -1e6, 5e5);
  for (int it = 0; it < 24; ++it) {
    auto pts = test3::random_sphere(rng, 10 + 5 * it);
    auto P = ConvexPolytope::hull(pts);
    auto Q = ConvexPolytope::hull(test3::random_sphere(rng, 8 + 3 * it, 0.5));
    Pose3 pq(random_rotation(rng), Vec3(U(rng), U(rng), U(rng)));
    Depth3 base = minimum_depth(P, Pose3(), Q, pq);
    auto g = random_rotation(rng);
    Pose3 gp(g, off), gq(g * pq.rotation, g.toRotationMatrix() * pq.translation + off);
    check(P, gp, Q, gq, st, "posed offset " + std::to_string(it), it % 4 == 0);
    Depth3 d = minimum_depth(P, gp, Q, gq);
    ASSERT_EQ(d.overlapping, base.overlapping);
    EXPECT_NEAR(d.depth, base.depth, 1e-8);
    // Coordinates themselves far away: P's points shifted by off, Q placed accordingly.
    for (auto& p : pts) p += off;
    auto Pfar = ConvexPolytope::hull(pts);
    Pose3 qfar(pq.rotation, pq.translation + off);
    check(Pfar, Pose3(), Q, qfar, st, "coordinate offset " + std::to_string(it));
    EXPECT_NEAR(minimum_depth(Pfar, Pose3(), Q, qfar).depth, base.depth, 1e-8);
  }
  EXPECT_GT(st.overlapping, 30);
  st.print("offsets 1e6");
}

TEST(MinimumFast, NearlyCoplanarAndSlivers) {
  std::mt19937_64 rng(7331);
  std::uniform_real_distribution<double> U(-0.3, 0.3);
  Stats st;
  // A cube whose faces carry points pushed out by 1e-13…1e-9: nearly coplanar facets.
  std::vector<Vec3> bumpy = test3::grid(2);
  std::uniform_real_distribution<double> F(0.1, 0.9);
  for (int k = 0; k < 24; ++k) {
    int ax = k % 3;
    Vec3 p(F(rng), F(rng), F(rng));
    p[ax] = (k / 3) % 2 ? 1 + std::pow(10.0, -13 + k % 5) : -std::pow(10.0, -13 + k % 5);
    bumpy.push_back(p);
  }
  auto B = ConvexPolytope::hull(bumpy);
  auto C = ConvexPolytope::hull(test3::grid(2));
  for (int it = 0; it < 12; ++it) {
    Vec3 t(0.6 + U(rng), U(rng), U(rng));
    check(B, Pose3(), C, Pose3(t), st, "bumpy cube " + std::to_string(it), it % 4 == 0);
    check(B, Pose3(), B, Pose3(Eigen::Quaterniond(1, 0, 0, 1), t), st, "bumpy pair " + std::to_string(it));
  }
  // A hull against itself rotated by a tiny angle: nearly parallel face pairs everywhere.
  for (int it = 0; it < 10; ++it) {
    auto P = ConvexPolytope::hull(test3::random_sphere(rng, 30));
    Vec3 axis = Vec3(U(rng), U(rng), U(rng)).normalized();
    Eigen::Quaterniond tiny(Eigen::AngleAxisd(std::pow(10.0, -12 + it), axis));
    check(P, Pose3(), P, Pose3(tiny, Vec3(U(rng), U(rng), U(rng))), st, "tiny rotation " + std::to_string(it), true);
  }
  // Slivers: flattened random hulls (thickness 1e-6), in every pairing.
  for (int it = 0; it < 10; ++it) {
    auto a = test3::random_sphere(rng, 40), b = test3::random_sphere(rng, 25, 0.7);
    for (auto& p : a) p.z() *= 1e-6;
    auto P = ConvexPolytope::hull(a), Q = ConvexPolytope::hull(b);
    check(P, Pose3(), Q, Pose3(random_rotation(rng), Vec3(U(rng), U(rng), 1e-7 * U(rng))), st,
          "sliver " + std::to_string(it));
    check(Q, Pose3(), P, Pose3(random_rotation(rng), Vec3(U(rng), U(rng), U(rng))), st,
          "sliver moving " + std::to_string(it));
  }
  EXPECT_GT(st.overlapping, 50);
  st.print("nearly coplanar / slivers");
}

TEST(MinimumFast, SymmetricShapesRotated) {
  // Identical centrally symmetric shapes under arbitrary rotations: the pairs (i, ī) span the
  // parallelepiped (I + R)·box, so many exactly coplanar quadruples arise that no symbolic rule
  // sees; they are decided by the exact fallback.
  std::mt19937_64 rng(8128);
  std::uniform_real_distribution<double> U(-0.6, 0.6);
  Stats st;
  auto box = ConvexPolytope::hull(test3::grid(2));
  auto brick = ConvexPolytope::hull(std::vector<Vec3>{{0, 0, 0}, {3, 0, 0}, {0, 1, 0}, {3, 1, 0}, {0, 0, 0.5},
                                                     {3, 0, 0.5}, {0, 1, 0.5}, {3, 1, 0.5}});
  auto ball = ConvexPolytope::hull(test3::integer_sphere(50));
  for (int it = 0; it < 40; ++it) {
    Pose3 pq(random_rotation(rng), Vec3(U(rng), U(rng), U(rng)));
    check(box, Pose3(), box, pq, st, "box " + std::to_string(it), it % 8 == 0);
    check(brick, Pose3(), brick, Pose3(pq.rotation, 2 * pq.translation), st, "brick " + std::to_string(it));
    check(ball, Pose3(), ball, Pose3(pq.rotation, 6 * pq.translation), st, "ball " + std::to_string(it));
  }
  EXPECT_GT(st.overlapping, 70);
  st.print("symmetric shapes rotated");
}

TEST(MinimumFast, AdjacencyMatchesHalfEdges) {
  // The lazily built CSR adjacency lists exactly the level-0 edges around each vertex, and the
  // cube-map seed is a vertex; hill climbing from it reaches the brute-force support value.
  std::mt19937_64 rng(99);
  for (int n : {4, 50, 700}) {
    auto P = ConvexPolytope::hull(test3::random_sphere(rng, n));
    const auto& A = convex3::vertex_adjacency(convex3::data_of(P));
    const auto& L = convex3::data_of(P).levels[0];
    ASSERT_EQ(A.start.back(), static_cast<int>(L.fv.size()));
    for (int v = 0; v < static_cast<int>(P.size()); ++v)
      for (int e = A.start[v]; e < A.start[v + 1]; ++e) {
        EXPECT_EQ(L.origin(A.he[e]), v);
        EXPECT_EQ(L.target(A.he[e]), A.nbr[e]);
        EXPECT_EQ(Vec3(A.dx[e], A.dy[e], A.dz[e]), P[A.nbr[e]] - P[v]);
      }
    std::normal_distribution<double> g;
    for (int k = 0; k < 50; ++k) {
      Vec3 u(g(rng), g(rng), g(rng));
      int s = convex3::seed_vertex(A, u);
      ASSERT_GE(s, 0);
      ASSERT_LT(s, static_cast<int>(P.size()));
    }
    EXPECT_GE(convex3::seed_vertex(A, Vec3::Zero()), 0);
  }
}

}  // namespace
}  // namespace pendepth
