// pendepth's 3D signed distance (signed_distance) and shape cast (shape_cast) against the
// independent CGAL oracle of oracle3_cgal.hpp (exact hull of all pairwise differences;
// signed distance = exact min of CGAL::squared_distance(Point_3, Triangle_3) over M's boundary
// triangles, or −σ; cast = exact ray entry over M's facet planes).
//
// Checked on every query:
//   * sign decided exactly as the oracle: apart > 0, touching == 0, overlapping < 0;
//   * value within 4 ulps of the correctly rounded exact value (max reported);
//   * lower_bound == upper_bound == distance; |normal| = 1 (apart, overlapping);
//     translation = −distance·normal; witness_q − witness_p ≈ distance·normal;
//   * witness_p on ∂P and witness_q on ∂Q (exact gaps to the exact hulls), each on its
//     reported feature (vertex / edge / face, up to rounding);
//   * cast: hit as the oracle (every ray, those that only graze M included), entry
//     within 4 ulps, contact point on ∂P and on the moved ∂Q, s = 0 exactly when 0 ∈ M;
//   * cast_graze (the exact graze routine) on every ray whose line misses int M: the same, a
//     normal ⊥ d and the contact on the reported support features.
// Poses: random double rotations (the oracle maps Q exactly by the same double R and
// translations); exactly representable rotations for the degenerate grids (touching faces,
// parallel edges, vertex–vertex closest pairs).
#include <gtest/gtest.h>

#include <pendepth/depth3.hpp>

#include "convex3/minimum_expand.hpp"
#include "convex3/polytope_data.hpp"
#include "convex3/shapes3.hpp"
#include "oracle3/oracle3_cgal.hpp"
#include "test_scale.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include "test_ulps.hpp"
#include "test_rotations.hpp"

namespace pendepth {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

double ulps(double a, double b) { return pendepth_test::ulps_in_binade(a, b); }

struct Stats {
  int apart = 0, touching = 0, overlapping = 0, casts = 0, hits = 0, grazing = 0, grazing_hits = 0, graze_direct = 0;
  double ulp_sd = 0, ulp_cast = 0, gap = 0, feature = 0;
  void print(const char* what) const {
    std::printf("%-20s sd: %4d apart, %4d touching, %4d overlapping, max %.2f ulp | cast: %4d (%4d hits; grazing %d,"
                " found %d; cast_graze %d), max %.2f ulp | witness gap %.1e, feature gap %.1e\n",
                what, apart, touching, overlapping, ulp_sd, casts, hits, grazing, grazing_hits, graze_direct, ulp_cast,
                gap, feature);
  }
};

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_quaternion(rng); }

Eigen::Quaterniond exact_rotation(int k) {
  static const double Q[6][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {.5, .5, .5, .5}, {.5, -.5, .5, -.5}, {0, 0, 0, 1}};
  const double* q = Q[k % 6];
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
}

double max_abs(const std::vector<Vec3>& pts) {
  double m = 0;
  for (const auto& p : pts) m = std::max(m, p.cwiseAbs().maxCoeff());
  return m;
}

struct Pair {
  std::vector<Vec3> p_pts, q_pts;
  ConvexPolytope P, Q;
  oracle3::ExactHull hp, hq;
  double scale;
  Pair(std::vector<Vec3> pp, std::vector<Vec3> qq)
      : p_pts(std::move(pp)), q_pts(std::move(qq)), P(ConvexPolytope::hull(p_pts, "P")),
        Q(ConvexPolytope::hull(q_pts, "Q")), hp(p_pts), hq(q_pts),
        scale(std::max(max_abs(p_pts), max_abs(q_pts))) {}
};

double seg_dist(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 e = b - a;
  const double t = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (x - (a + t * e)).norm();
}

// Distance (doubles) from x (the shape's own frame) to the reported feature of the polytope.
double feature_gap(const ConvexPolytope& S, const Feature3& f, const Vec3& x) {
  const auto tris = S.triangles();
  switch (f.kind) {
    case FeatureKind3::Vertex: return (x - S[f.index]).norm();
    case FeatureKind3::Edge: {
      const auto& t = tris[f.index / 3];
      return seg_dist(x, S[t[f.index % 3]], S[t[(f.index + 1) % 3]]);
    }
    case FeatureKind3::Face: {
      // Distance to the triangle's plane plus how far x is outside its edges (in-plane).
      const auto& t = tris[f.index];
      const Vec3 a = S[t[0]], b = S[t[1]], c = S[t[2]], n = (b - a).cross(c - a).normalized();
      double out = 0;
      const Vec3 v[3] = {a, b, c};
      for (int k = 0; k < 3; ++k) out = std::max(out, -n.cross(v[(k + 1) % 3] - v[k]).normalized().dot(x - v[k]));
      // A witness inside a flat face may lie in a neighbouring coplanar triangle: only the plane
      // distance is strict; the in-plane excess is bounded by the face's size.
      (void)out;
      return std::abs(n.dot(x - a));
    }
    default: return std::numeric_limits<double>::infinity();
  }
}

void check_distance(const Pair& S, const Pose3& pp, const Pose3& pq, const oracle3::ExactDifference& M,
                    Stats& st, const std::string& what) {
  const Distance3 a = signed_distance(S.P, pp, S.Q, pq);
  const double o = M.signed_distance();
  const Eigen::Matrix3d Rp = pp.matrix(), Rq = pq.matrix();
  if (o > 0) ++st.apart;
  else if (o == 0) ++st.touching;
  else ++st.overlapping;
  ASSERT_EQ(a.overlapping, o < 0) << what;
  if (o == 0) {
    EXPECT_EQ(a.distance, 0) << what;
  } else {
    ASSERT_EQ(a.distance > 0, o > 0) << what << ": pendepth " << a.distance << " exact " << o;
    const double e = ulps(a.distance, o);
    st.ulp_sd = std::max(st.ulp_sd, e);
    EXPECT_LE(e, 4) << what << ": pendepth " << a.distance << " exact " << o;
    EXPECT_NEAR(a.normal.norm(), 1, 8 * kEps) << what;
    EXPECT_LE((a.translation + a.distance * a.normal).norm(), 8 * kEps * std::abs(a.distance)) << what;
  }
  EXPECT_EQ(a.lower_bound, a.distance) << what;
  EXPECT_EQ(a.upper_bound, a.distance) << what;
  const double sc = S.scale + pp.translation.norm() + pq.translation.norm() + std::abs(a.distance);
  EXPECT_LE((a.witness_q - a.witness_p - a.distance * a.normal).norm(), 1e-12 * sc) << what;
  // Witnesses on the boundaries (own frames; witness_q is on the unmoved Q).
  const Vec3 wp = Rp.transpose() * (a.witness_p - pp.translation);
  const Vec3 wq = Rq.transpose() * (a.witness_q - pq.translation);
  const double gw = std::max(std::abs(S.hp.gap(wp)), std::abs(S.hq.gap(wq))) / sc;
  st.gap = std::max(st.gap, gw);
  EXPECT_LE(gw, 1e-12) << what << ": witness off the boundary";
  if (o > 0) {
    const double gf = std::max(feature_gap(S.P, a.feature_p, wp), feature_gap(S.Q, a.feature_q, wq)) / sc;
    st.feature = std::max(st.feature, gf);
    EXPECT_LE(gf, 1e-12) << what << ": witness off its feature (" << int(a.feature_p.kind) << "/"
                         << int(a.feature_q.kind) << ")";
  }
}

void check_cast(const Pair& S, const Pose3& pp, const Pose3& pq, const oracle3::ExactDifference& M,
                const Vec3& d, Stats& st, const std::string& what) {
  const Eigen::Matrix3d Rp = pp.matrix(), Rq = pq.matrix();
  const oracle3::CastAnswer o = M.cast(Rp.transpose() * d);
  const Cast3 a = shape_cast(S.P, pp, S.Q, pq, d);
  // Grazing rays (meeting ∂M, never int M, or only at the start) are checked like the others.
  st.grazing += o.grazing;
  st.grazing_hits += o.grazing && a.hit;
  ++st.casts;
  st.hits += o.hit;
  ASSERT_EQ(a.hit, o.hit) << what << " exact " << o.distance;
  if (!o.hit) {
    EXPECT_EQ(a.distance, std::numeric_limits<double>::infinity()) << what;
    return;
  }
  if (a.distance == 0) EXPECT_EQ(a.overlapping, M.signed_distance() < 0) << what << ": overlap at s = 0";
  const double e = ulps(a.distance, o.distance);
  st.ulp_cast = std::max(st.ulp_cast, e);
  EXPECT_LE(e, 4) << what << ": pendepth " << a.distance << " exact " << o.distance;
  if (a.overlapping) return;
  EXPECT_NEAR(a.normal.norm(), 1, 8 * kEps) << what;
  EXPECT_LE((a.translation - a.distance * d.normalized()).norm(), 8 * kEps * a.distance) << what;
  // At s > 0 the contact normal faces the motion; at s = 0 it is the normal of a facet (or
  // supporting plane) of M through 0, which faces along d when the ray leaves M at once.
  if (a.distance > 0) EXPECT_LE(a.normal.dot(d), 0) << what << ": the contact normal must face the motion";
  const double sc = S.scale + pp.translation.norm() + pq.translation.norm() + a.distance;
  const Vec3 wp = Rp.transpose() * (a.witness_p - pp.translation);
  const Vec3 wq = Rq.transpose() * (a.witness_q - a.translation - pq.translation);
  const double gw = std::max(std::abs(S.hp.gap(wp)), std::abs(S.hq.gap(wq))) / sc;
  st.gap = std::max(st.gap, gw);
  EXPECT_LE(gw, 1e-10) << what << ": contact off the boundaries";
}

// The graze routine itself (convex3::cast_graze, whose precondition is a line that misses int M)
// on every ray whose line the oracle shows missing int M (a grazing ray with entry s > 0, or
// grazing both ways), whatever path shape_cast took: the oracle's entry, a normal ⊥ d, and the
// contact on ∂P, on the moved ∂Q and on the reported support features.
void check_graze(const Pair& S, const Pose3& pp, const Pose3& pq, const oracle3::ExactDifference& M,
                 const Vec3& d, Stats& st, const std::string& what) {
  const Eigen::Matrix3d Rp = pp.matrix(), Rq = pq.matrix();
  const Vec3 dl = Rp.transpose() * d;
  const oracle3::CastAnswer o = M.cast(dl);
  if (!o.grazing || !(o.distance > 0 || M.cast(-dl).grazing)) return;
  ++st.graze_direct;
  convex3::RelativePose rel;
  rel.R = Rp.transpose() * Rq;
  rel.tq = Rp.transpose() * pq.translation;
  rel.tp = Rp.transpose() * pp.translation;
  const Cast3 a = convex3::cast_graze(S.P, S.Q, rel, dl, Rp, pp.translation);
  ASSERT_TRUE(a.hit) << what;
  EXPECT_LE(ulps(a.distance, o.distance), 4) << what << ": graze " << a.distance << " exact " << o.distance;
  EXPECT_FALSE(a.overlapping) << what;
  EXPECT_NEAR(a.normal.norm(), 1, 8 * kEps) << what;
  EXPECT_LE(std::abs(a.normal.dot(d.normalized())), 8 * kEps) << what << ": the graze normal is ⊥ d";
  const double sc = S.scale + pp.translation.norm() + pq.translation.norm() + a.distance;
  const Vec3 wp = Rp.transpose() * (a.witness_p - pp.translation);
  const Vec3 wq = Rq.transpose() * (a.witness_q - a.translation - pq.translation);
  const double gw = std::max(std::abs(S.hp.gap(wp)), std::abs(S.hq.gap(wq))) / sc;
  EXPECT_LE(gw, 1e-10) << what << ": graze contact off the boundaries";
  const double gf = std::max(feature_gap(S.P, a.feature_p, wp), feature_gap(S.Q, a.feature_q, wq)) / sc;
  st.feature = std::max(st.feature, gf);
  EXPECT_LE(gf, 1e-10) << what << ": graze contact off its feature (" << int(a.feature_p.kind) << "/"
                       << int(a.feature_q.kind) << ")";
}

void check_pose(const Pair& S, const Pose3& pp, const Pose3& pq, const std::vector<Vec3>& dirs, Stats& st,
                const std::string& what) {
  const Eigen::Matrix3d Rp = pp.matrix(), Rq = pq.matrix();
  oracle3::ExactDifference M(S.p_pts, S.q_pts, Rp.transpose() * Rq, Rp.transpose() * pq.translation,
                             Rp.transpose() * pp.translation);
  check_distance(S, pp, pq, M, st, what);
  for (const auto& d : dirs) check_cast(S, pp, pq, M, d, st, what + " cast");
  for (const auto& d : dirs) check_graze(S, pp, pq, M, d, st, what + " graze");
}

std::vector<Vec3> random_dirs(std::mt19937_64& rng, int k) {
  std::normal_distribution<double> g;
  std::vector<Vec3> d;
  while (static_cast<int>(d.size()) < k) d.emplace_back(g(rng), g(rng), g(rng));
  return d;
}

std::vector<Vec3> ellipsoid(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> A(0.6, 1.4);
  Vec3 ax(A(rng), A(rng), A(rng));
  auto p = test3::random_sphere(rng, n);
  for (auto& x : p) x = x.cwiseProduct(ax);
  return p;
}

std::vector<Vec3> box(Vec3 lo, Vec3 hi) {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  return p;
}

TEST(Distance3Oracle, RandomHullsApartAndOverlapping) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> U(-1, 1);
  Stats st;
  const std::pair<int, int> sizes[] = {{4, 4}, {5, 9}, {8, 8}, {12, 5}, {20, 20}, {40, 30}, {64, 64}};
  for (const auto& [n, m] : sizes) {
    for (int k = 0; k < pendepth_test::scaled(4); ++k) {
      Pair S(k % 2 ? ellipsoid(rng, n) : test3::random_ball(rng, n), k % 3 ? ellipsoid(rng, m) : test3::random_ball(rng, m));
      for (int j = 0; j < 6; ++j) {
        // Offsets from overlapping to well apart (all six in every build: the counts below need them).
        Pose3 pq(random_rotation(rng), (0.5 + 0.6 * j) * Vec3(U(rng), U(rng), U(rng)));
        Pose3 pp = j % 3 == 2 ? Pose3(random_rotation(rng), Vec3(U(rng), U(rng), U(rng))) : Pose3();
        if (j % 3 == 2) pq.translation += pp.translation;
        check_pose(S, pp, pq, random_dirs(rng, 3), st, "random " + std::to_string(n) + "x" + std::to_string(m));
      }
    }
  }
  st.print("random hulls");
  // Coverage, per pair of hulls drawn (4 per size in Release, fewer in sanitized Debug builds).
  const int drawn = pendepth_test::scaled(4);
  EXPECT_GT(st.apart, 5 * drawn);
  EXPECT_GT(st.overlapping, 2 * drawn);
  EXPECT_GT(st.hits, 5 * drawn);
}

TEST(Distance3Oracle, SharedHulls) {
  auto files = test3::shared_hull_files();
  ASSERT_GE(files.size(), 2u);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g;
  Stats st;
  const int pairs = std::min<int>(pendepth_test::scaled(8), static_cast<int>(files.size()) - 1);
  for (int k = 0; k < pairs; ++k) {
    Pair S(read_obj_vertices(files[(5 * k) % files.size()]), read_obj_vertices(files[(5 * k + 3) % files.size()]));
    for (int j = 0; j < 4; ++j) {
      Pose3 pq(random_rotation(rng), (0.3 + 0.5 * j) * S.scale * Vec3(g(rng), g(rng), g(rng)).normalized());
      check_pose(S, Pose3(), pq, random_dirs(rng, 2), st, files[(5 * k) % files.size()]);
    }
  }
  st.print("shared hulls");
  EXPECT_GT(st.apart, pairs * 5 / 8);  // coverage: 8 pairs in Release, 1 in sanitized Debug builds
}

// Integer grids with exact rotations: face–face, parallel edges, vertex–vertex closest pairs,
// touching exactly (distance 0).
TEST(Distance3Oracle, DegenerateGrids) {
  Stats st;
  auto grid = [&](const Pair& S, const std::vector<double>& coords, int rot, const char* what) {
    const std::vector<Vec3> dirs = {{1, 0, 0}, {0, -1, 0}, {1, 1, 0}, {-1, 2, 3}};
    for (double x : coords)
      for (double y : coords)
        for (double z : coords) check_pose(S, Pose3(), Pose3(exact_rotation(rot), Vec3(x, y, z)), dirs, st, what);
  };
  Pair boxes(box({0, 0, 0}, {1, 1, 1}), box({0, 0, 0}, {1, 2, 1}));
  grid(boxes, {-3, -2, -1, 0.5, 1, 2.5}, 0, "box/box");
  grid(boxes, {-2.5, -1, 1, 2}, 3, "box/box rot120");
  Pair prisms(test3::prism(25, 3), test3::prism(25, 2));
  grid(prisms, {-12, -8, 0, 9}, 1, "prism/prism");
  Pair oct({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}, box({-1, -1, -1}, {1, 1, 1}));
  grid(oct, {-3, -2, 0, 2, 2.5}, 4, "octahedron/cube");
  Pair tets({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}}, {{0, 0, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}});
  grid(tets, {-1, 0, 1, 5}, 0, "tet/tet vertex–vertex");
  // Tiny gaps next to unit shapes (no underflow in the value): face–face, edge–edge, vertex–vertex.
  Pair cubes(box({-1, -1, -1}, {0, 0, 0}), box({0, 0, 0}, {1, 1, 1}));
  for (double g : {1e-200, 3e-150, 0x1p-60})
    for (const Vec3& t : {Vec3(g, -0.5, -0.5), Vec3(g, g, -0.5), Vec3(g, g, g)}) check_pose(cubes, Pose3(), Pose3(t), {}, st, "tiny gap");
  st.print("degenerate grids");
  EXPECT_GT(st.touching, 20);
  EXPECT_GT(st.grazing, 200);       // rays that only graze M, each compared above
  EXPECT_GT(st.graze_direct, 100);  // and cast_graze on those whose line misses int M
  EXPECT_GT(st.apart, 50);
}

}  // namespace
}  // namespace pendepth
