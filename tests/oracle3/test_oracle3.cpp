// pendepth's 3D σ (minimum_depth) and σ_d (directional_depth) against the independent CGAL
// oracle of oracle3_cgal.hpp (exact hull of all pairwise differences from the raw point sets).
//
// Checked on every query:
//   * overlap decided exactly as the oracle (touching = not overlapping, depth 0);
//   * depth within 8 ulps of the correctly rounded exact value (max reported);
//   * lower_bound == upper_bound == depth; translation = depth·normal; |normal| = 1;
//     σ_d: normal = d̂;
//   * facet_normal = the rounded unit normal of a facet of M attaining the exact optimum;
//   * the move ends on ∂M: the exact gap of the moved placement to ∂M is ≈ 0 (relative to the
//     move), and the witness lies on ∂P and on the moved ∂Q (exact gaps to the exact hulls);
//   * σ ≤ σ_d.
// Poses: Q (and sometimes P) rotated by random double quaternions; the oracle maps Q's points
// exactly by the same double R = R_Pᵀ R_Q and translations as depth3.hpp documents (computed
// here by the same expressions). Placements that must be exact (touching) use identity or
// exactly representable rotations (the tetrahedral group: quaternions with entries 0, ±½, ±1).
// Suites: random hulls 4…300 vertices, the shared hulls, face–face, parallel edges,
// vertex–face, identical shapes, touching (on exactly representable points of ∂M), thin plates
// (flat in one axis after rotation), 10⁶ offsets, nearly coplanar facets, shapes rebuilt with
// new coordinates between queries (σ_d's per-thread caches).
#include <gtest/gtest.h>

#include <pendepth/depth3.hpp>

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
  int sigma = 0, sigma_over = 0, sigma_d = 0, sigma_d_over = 0, touching = 0;
  double ulp_sigma = 0, ulp_sigma_d = 0;  ///< max |pendepth − exact| in ulps
  double gap_move = 0;     ///< max |gap of the moved placement to ∂M| / |move|
  double gap_witness = 0;  ///< max |gap of the witness to ∂P, ∂Q'| / scale
  double normal_err = 0;   ///< max |facet_normal − nearest optimal facet normal|
  void add(const Stats& o) {
    sigma += o.sigma, sigma_over += o.sigma_over, sigma_d += o.sigma_d, sigma_d_over += o.sigma_d_over;
    touching += o.touching;
    ulp_sigma = std::max(ulp_sigma, o.ulp_sigma), ulp_sigma_d = std::max(ulp_sigma_d, o.ulp_sigma_d);
    gap_move = std::max(gap_move, o.gap_move), gap_witness = std::max(gap_witness, o.gap_witness);
    normal_err = std::max(normal_err, o.normal_err);
  }
  void print(const char* what) const {
    std::printf(
        "%-22s σ: %5d queries (%5d overlapping), max %.2f ulp | σ_d: %5d queries (%5d overlapping), max %.2f ulp"
        " | touching %d | move gap %.1e, witness gap %.1e, normal %.1e\n",
        what, sigma, sigma_over, ulp_sigma, sigma_d, sigma_d_over, ulp_sigma_d, touching, gap_move, gap_witness,
        normal_err);
  }
};

Stats& total() {
  static Stats s;
  return s;
}

class Summary : public ::testing::Environment {
 public:
  void TearDown() override { total().print("oracle3 total"); }
};
[[maybe_unused]] auto* const kSummary = ::testing::AddGlobalTestEnvironment(new Summary);

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_quaternion(rng); }

// Rotations whose double matrix is exact: the 12 of the tetrahedral group.
Eigen::Quaterniond exact_rotation(int k) {
  static const double Q[12][4] = {{1, 0, 0, 0},         {0, 1, 0, 0},          {0, 0, 1, 0},
                                  {0, 0, 0, 1},         {.5, .5, .5, .5},      {.5, -.5, -.5, -.5},
                                  {.5, .5, -.5, .5},    {.5, -.5, .5, -.5},    {.5, .5, .5, -.5},
                                  {.5, -.5, -.5, .5},   {.5, -.5, .5, .5},     {.5, .5, -.5, -.5}};
  const double* q = Q[k % 12];
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
}

double radius_of(const std::vector<Vec3>& pts, Vec3* centre = nullptr) {
  Vec3 c = Vec3::Zero();
  for (const auto& p : pts) c += p;
  c /= double(pts.size());
  double r = 0;
  for (const auto& p : pts) r = std::max(r, (p - c).norm());
  if (centre) *centre = c;
  return r;
}

double max_abs(const std::vector<Vec3>& pts) {
  double m = 0;
  for (const auto& p : pts) m = std::max(m, p.cwiseAbs().maxCoeff());
  return m;
}

// One shape pair: pendepth polytopes and exact hulls built once, queried at many poses.
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

// The result's geometric consistency against the oracle (see the header).
void check_result(const Pair& S, const Pose3& pp, const Pose3& pq, const oracle3::ExactDifference& M,
                  const oracle3::Answer& o, const Depth3& a, double& max_ulp, Stats& st, const std::string& what) {
  const Eigen::Matrix3d Rp = pp.matrix(), Rq = pq.matrix();
  ASSERT_EQ(a.overlapping, o.overlapping) << what;
  if (!o.overlapping) {
    EXPECT_EQ(a.depth, 0) << what;
    EXPECT_EQ(a.lower_bound, 0) << what;
    EXPECT_EQ(a.upper_bound, 0) << what;
    st.touching += o.on_boundary;
    return;
  }
  double e = ulps(a.depth, o.depth);
  max_ulp = std::max(max_ulp, e);
  EXPECT_LE(e, 8) << what << ": pendepth " << a.depth << " exact " << o.depth;
  EXPECT_EQ(a.lower_bound, a.depth) << what;
  EXPECT_EQ(a.upper_bound, a.depth) << what;
  EXPECT_NEAR(a.normal.norm(), 1, 8 * kEps) << what;
  EXPECT_LE((a.translation - a.depth * a.normal).norm(), 8 * kEps * a.depth) << what;
  // Facet normal: one of the optimal facets of M (P's frame).
  Vec3 fn = Rp.transpose() * a.facet_normal;
  double best = std::numeric_limits<double>::infinity();
  for (const auto& n : o.normals) best = std::min(best, (fn - n).norm());
  st.normal_err = std::max(st.normal_err, best);
  EXPECT_LE(best, 1e-9) << what << ": facet normal is not an optimal facet of M";
  // The move ends on ∂M: M shifts by −v (v = the move in P's frame).
  Vec3 v = Rp.transpose() * a.translation;
  double g = std::abs(M.hull().gap(v)) / std::max(v.norm(), std::numeric_limits<double>::min());
  st.gap_move = std::max(st.gap_move, g);
  EXPECT_LE(g, 1e-12) << what << ": the move does not end on ∂M";
  // Witness on ∂P and on the moved ∂Q (each shape's own frame).
  const double sc = S.scale + a.witness_p.norm() + pp.translation.norm() + pq.translation.norm() + a.depth;
  Vec3 wp = Rp.transpose() * (a.witness_p - pp.translation);
  Vec3 wq = Rq.transpose() * (a.witness_q - a.translation - pq.translation);
  double gw = std::max(std::abs(S.hp.gap(wp)), std::abs(S.hq.gap(wq))) / sc;
  st.gap_witness = std::max(st.gap_witness, gw);
  EXPECT_LE(gw, 1e-10) << what << ": witness not on both boundaries (P gap " << S.hp.gap(wp) << ", Q gap "
                       << S.hq.gap(wq) << ", features " << int(a.feature_p.kind) << "/" << int(a.feature_q.kind)
                       << ", witness " << a.witness_p.transpose() << ", move " << a.translation.transpose()
                       << ", Q at " << pq.translation.transpose() << ")";
}

// σ and σ_d for every direction at one pose.
void check_pose(const Pair& S, const Pose3& pp, const Pose3& pq, const std::vector<Vec3>& dirs, Stats& st,
                const std::string& what) {
  // The relative pose exactly as depth3 forms it (double R, t; exact semantics afterwards).
  const Eigen::Matrix3d Rp = pp.matrix(), Rq = pq.matrix();
  const Eigen::Matrix3d R = Rp.transpose() * Rq;
  const Vec3 tq = Rp.transpose() * pq.translation, tp = Rp.transpose() * pp.translation;
  oracle3::ExactDifference M(S.p_pts, S.q_pts, R, tq, tp);
  Depth3 s = minimum_depth(S.P, pp, S.Q, pq);
  oracle3::Answer os = M.sigma();
  ++st.sigma;
  st.sigma_over += os.overlapping;
  check_result(S, pp, pq, M, os, s, st.ulp_sigma, st, what + " σ");
  for (const auto& d : dirs) {
    Depth3 a = directional_depth(S.P, pp, S.Q, pq, d);
    const Vec3 dl = Rp.transpose() * d;
    oracle3::Answer o = M.sigma_d(dl);
    ++st.sigma_d;
    st.sigma_d_over += o.overlapping;
    std::string w = what + " σ_d d=(" + std::to_string(d.x()) + "," + std::to_string(d.y()) + "," +
                    std::to_string(d.z()) + ")";
    check_result(S, pp, pq, M, o, a, st.ulp_sigma_d, st, w);
    if (o.overlapping) {
      EXPECT_LE((a.normal - d.normalized()).norm(), 8 * kEps) << w;
      EXPECT_LE(s.depth, a.depth * (1 + 16 * kEps)) << w << ": σ > σ_d";
    }
  }
}

std::vector<Vec3> random_dirs(std::mt19937_64& rng, int k) {
  std::normal_distribution<double> g;
  std::vector<Vec3> d;
  while (static_cast<int>(d.size()) < k) {
    Vec3 v(g(rng), g(rng), g(rng));
    if (v.norm() > 1e-3) d.push_back(v);
  }
  return d;
}

std::vector<Vec3> axis_dirs() {
  return {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {1, 1, 0}, {-1, 0, 1}, {1, 1, 1}, {2, -1, 0}};
}

std::vector<Vec3> ellipsoid(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> A(0.6, 1.4);
  Vec3 ax(A(rng), A(rng), A(rng));
  auto p = test3::random_sphere(rng, n);
  for (auto& x : p) x = x.cwiseProduct(ax);
  return p;
}

void finish(const Stats& st, const char* what) {
  st.print(what);
  total().add(st);
}

TEST(Oracle3, RandomHulls) {
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> U(-1, 1);
  Stats st;
  const std::pair<int, int> sizes[] = {{4, 4},   {4, 9},   {5, 5},   {6, 8},     {8, 8},    {12, 5},
                                       {20, 20}, {30, 12}, {50, 50}, {100, 40}, {150, 150}, {300, 300}};
  for (const auto& [n, m] : sizes) {
    const int pairs = n * m >= 20000 ? 1 : pendepth_test::scaled(n * m >= 2000 ? 3 : 8);
    for (int k = 0; k < pairs; ++k) {
      Pair S(k % 2 ? ellipsoid(rng, n) : test3::random_ball(rng, n), k % 3 ? ellipsoid(rng, m) : test3::random_ball(rng, m));
      const int poses = n * m >= 20000 ? 2 : pendepth_test::scaled(6);
      for (int j = 0; j < poses; ++j) {
        Pose3 pq(random_rotation(rng), 0.8 * Vec3(U(rng), U(rng), U(rng)));
        Pose3 pp = j % 3 == 2 ? Pose3(random_rotation(rng), Vec3(U(rng), U(rng), U(rng))) : Pose3();
        if (j % 3 == 2) pq.translation += pp.translation;
        auto dirs = random_dirs(rng, 3);
        dirs.push_back(Vec3::Unit(j % 3));
        check_pose(S, pp, pq, dirs, st, "random " + std::to_string(n) + "x" + std::to_string(m));
      }
    }
  }
  finish(st, "random hulls");
  EXPECT_GT(st.sigma_over, st.sigma / 3);
}

TEST(Oracle3, SharedHulls) {
  auto files = test3::shared_hull_files();
  ASSERT_GE(files.size(), 2u);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  Stats st;
  const int pairs = std::min<int>(pendepth_test::scaled(10), static_cast<int>(files.size()) - 1);
  for (int k = 0; k < pairs; ++k) {
    const auto& fp = files[(3 * k) % files.size()];
    const auto& fq = files[(3 * k + 7) % files.size()];
    Pair S(read_obj_vertices(fp), read_obj_vertices(fq));
    Vec3 cp, cq;
    double rp = radius_of(S.p_pts, &cp), rq = radius_of(S.q_pts, &cq);
    for (int j = 0; j < 3; ++j) {
      Pose3 pq(random_rotation(rng), Vec3::Zero());
      // Centre Q's centre near P's centre (both in P's frame: P at the identity).
      pq.translation = cp - pq.matrix() * cq + 0.4 * std::min(rp, rq) * Vec3(g(rng), g(rng), g(rng)).normalized();
      check_pose(S, Pose3(), pq, random_dirs(rng, 4), st, fp + " / " + fq);
    }
  }
  finish(st, "shared hulls");
  EXPECT_GT(st.sigma_over, 0);
}

std::vector<Vec3> box(Vec3 lo, Vec3 hi) {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  return p;
}

// Integer / half-integer translation grids: coincident faces, edges and vertices galore.
void grid_suite(const Pair& S, const std::vector<double>& coords, const Eigen::Quaterniond& rot, Stats& st,
                const std::string& what, int stride = 1) {
  int i = 0;
  for (double x : coords)
    for (double y : coords)
      for (double z : coords) {
        if (i++ % stride) continue;
        check_pose(S, Pose3(), Pose3(rot, Vec3(x, y, z)), axis_dirs(), st, what);
      }
}

TEST(Oracle3, FaceFaceEdgeEdgeVertexFace) {
  Stats st;
  {  // face–face: cubes with interior and on-face points in the input
    auto p = test3::grid(3);  // [0,2]³ with 27 points
    Pair S(p, box({0, 0, 0}, {1, 1, 1}));
    grid_suite(S, {-1, -0.5, 0, 0.5, 1, 1.5, 2}, exact_rotation(0), st, "cube/cube", pendepth_test::scaled(8) == 1 ? 8 : 1);
    grid_suite(S, {-0.5, 0.5, 1.5}, exact_rotation(4), st, "cube/cube rot120");
  }
  {  // parallel edges: prisms over the same integer polygon, Q turned upside down (exact)
    Pair S(test3::prism(25, 3), test3::prism(25, 2));
    grid_suite(S, {-4, 0, 3, 5}, exact_rotation(1), st, "prism/prism", pendepth_test::scaled(4) == 1 ? 4 : 1);
    Pair O({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}, box({-1, -1, -1}, {1, 1, 1}));
    grid_suite(O, {-1, 0, 0.5, 1, 2}, exact_rotation(5), st, "octahedron/cube", pendepth_test::scaled(2) == 1 ? 2 : 1);
  }
  {  // vertex–face: a tetrahedron against an octahedron and a bipyramid
    Pair S({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}}, {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}});
    grid_suite(S, {-1, 0, 1, 2, 3}, exact_rotation(0), st, "tet/octahedron", pendepth_test::scaled(2) == 1 ? 2 : 1);
    Pair B(test3::bipyramid(25), {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}});
    grid_suite(B, {-5, -1, 0, 3}, exact_rotation(7), st, "bipyramid/tet", pendepth_test::scaled(2) == 1 ? 2 : 1);
  }
  finish(st, "face/edge/vertex");
  EXPECT_GT(st.touching, 20);
}

TEST(Oracle3, IdenticalShapes) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> U(-0.3, 0.3);
  Stats st;
  for (int k = 0; k < pendepth_test::scaled(6); ++k) {
    auto pts = k % 2 ? test3::random_sphere(rng, 10 + 8 * k) : test3::integer_sphere(k < 3 ? 50 : 65);
    Pair S(pts, pts);
    for (int j = 0; j < 4; ++j) {
      auto rot = random_rotation(rng);
      Vec3 t = j == 0 ? Vec3::Zero() : Vec3(U(rng), U(rng), U(rng));
      // Same rotation on both: Q' = P exactly up to the translation (R = R_Pᵀ R_P in doubles).
      check_pose(S, Pose3(rot, Vec3::Zero()), Pose3(rot, t), random_dirs(rng, 3), st, "identical");
      check_pose(S, Pose3(), Pose3(exact_rotation(j), t), axis_dirs(), st, "identical exact rot");
    }
  }
  finish(st, "identical");
}

TEST(Oracle3, Touching) {
  std::mt19937_64 rng(5);
  Stats st;
  std::vector<std::pair<std::vector<Vec3>, std::vector<Vec3>>> shapes = {
      {test3::integer_sphere(25), test3::integer_sphere(9)},
      {test3::prism(25), test3::bipyramid(25)},
      {box({0, 0, 0}, {2, 1, 3}), test3::grid(2)},
      {test3::random_sphere(rng, 12), test3::random_sphere(rng, 9)},
  };
  int placed = 0;
  for (auto& [p, q] : shapes) {
    Pair S(p, q);
    for (int r = 0; r < 3; ++r) {
      auto rot = exact_rotation(3 * r + 1);
      // ∂M(0) points that are doubles: translating Q there makes the shapes touch exactly.
      oracle3::ExactDifference M0(S.p_pts, S.q_pts, Pose3(rot, Vec3::Zero()).matrix(), Vec3::Zero(), Vec3::Zero());
      auto pts = M0.boundary_doubles();
      const int stride = std::max<int>(1, static_cast<int>(pts.size()) / pendepth_test::scaled(24));
      for (std::size_t i = 0; i < pts.size(); i += stride) {
        Stats one;
        check_pose(S, Pose3(), Pose3(rot, pts[i]), axis_dirs(), one, "touching");
        EXPECT_EQ(one.sigma_over + one.sigma_d_over, 0);
        EXPECT_EQ(one.touching, one.sigma + one.sigma_d) << "oracle: not on the boundary";
        st.add(one);
        ++placed;
      }
    }
  }
  finish(st, "touching");
  EXPECT_GT(placed, 40);
}

TEST(Oracle3, ThinPlatesAfterRotation) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-0.5, 0.5);
  Stats st;
  for (double h : {1e-3, 1e-7, 1e-11}) {
    auto plate = box({-1, -1, -h}, {1, 1, h});
    plate.push_back({0, 0, 0});  // interior point, dropped
    Pair S(plate, ellipsoid(rng, 20));
    Pair T(S.q_pts, S.p_pts);
    for (int j = 0; j < pendepth_test::scaled(6); ++j) {
      // The plate (P) rotated arbitrarily, or exactly so that it is flat in x or y.
      Pose3 pp(j % 2 ? random_rotation(rng) : exact_rotation(4 + j), Vec3(U(rng), U(rng), U(rng)));
      Pose3 pq(random_rotation(rng), pp.translation + Vec3(U(rng), U(rng), U(rng)));
      check_pose(S, pp, pq, random_dirs(rng, 3), st, "thin plate");
      // Q thin instead.
      check_pose(T, Pose3(), Pose3(j % 2 ? random_rotation(rng) : exact_rotation(j), Vec3(U(rng), U(rng), U(rng))),
                 axis_dirs(), st, "thin plate as Q");
    }
  }
  finish(st, "thin plates");
}

TEST(Oracle3, MillionOffsets) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> U(-0.5, 0.5);
  Stats st;
  const Vec3 off(1e6, -1e6, 1e6);
  for (int k = 0; k < pendepth_test::scaled(4); ++k) {
    // Offsets in the coordinates themselves ...
    auto p = ellipsoid(rng, 8 + 10 * k), q = test3::random_ball(rng, 6 + 7 * k);
    auto po = p, qo = q;
    for (auto& x : po) x += off;
    for (auto& x : qo) x += off;
    Pair S(po, qo);
    for (int j = 0; j < 3; ++j) {
      Pose3 pq(j ? random_rotation(rng) : exact_rotation(k), Vec3(U(rng), U(rng), U(rng)));
      if (j) pq.translation = off - pq.matrix() * off + Vec3(U(rng), U(rng), U(rng));  // rotate about the offset
      check_pose(S, Pose3(), pq, random_dirs(rng, 3), st, "offset coordinates");
    }
    // ... and in the poses.
    Pair T(p, q);
    for (int j = 0; j < 3; ++j) {
      Pose3 pp(random_rotation(rng), off + Vec3(U(rng), U(rng), U(rng)));
      Pose3 pq(random_rotation(rng), pp.translation + Vec3(U(rng), U(rng), U(rng)));
      check_pose(T, pp, pq, random_dirs(rng, 3), st, "offset poses");
    }
  }
  finish(st, "1e6 offsets");
  EXPECT_GT(st.sigma_over, 0);
}

// A 7×7 grid lifted onto a paraboloid of curvature κ (tiny: facets nearly coplanar) over an apex.
std::vector<Vec3> flat_cap(double kappa, double apex) {
  std::vector<Vec3> p;
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y) p.emplace_back(x, y, kappa * (x * x + y * y));
  p.emplace_back(0.25, 0.5, apex);
  return p;
}

TEST(Oracle3, NearlyCoplanarFacets) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> U(-1, 1);
  Stats st;
  for (double kappa : {1e-4, 1e-9, 1e-13}) {
    Pair S(flat_cap(kappa, -2), flat_cap(-kappa, 2));
    for (int j = 0; j < pendepth_test::scaled(8); ++j) {
      // Q's base pushed below P's (both bases lie near z = 0): mostly overlapping.
      Pose3 pq(j % 2 ? random_rotation(rng) : exact_rotation(j), Vec3(0.5 * U(rng), 0.5 * U(rng), -0.5 + 0.3 * U(rng)));
      auto dirs = random_dirs(rng, 3);
      dirs.push_back({0, 0, 1});
      dirs.push_back({1e-3, 0, 1});
      check_pose(S, Pose3(), pq, dirs, st, "nearly coplanar k=" + std::to_string(kappa));
    }
  }
  finish(st, "nearly coplanar");
  EXPECT_GT(st.sigma_over, 0);
}

// σ_d keeps per-thread caches of caps and top levels keyed by the shape's address and validated
// against their inputs: shapes freed and rebuilt (likely at the same address) with the same
// topology but other coordinates, and poses alternating between rotations, must not see stale
// data.
TEST(Oracle3, RebuiltShapesAndChangingPoses) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> U(-0.4, 0.4);
  const std::vector<Vec3> bases_p[2] = {ellipsoid(rng, 40), ellipsoid(rng, 40)};
  const std::vector<Vec3> bases_q[2] = {test3::random_ball(rng, 30), test3::random_ball(rng, 30)};
  const auto r1 = random_rotation(rng), r2 = random_rotation(rng);
  const auto dirs = random_dirs(rng, 4);
  Stats st;
  for (int k = 0; k < pendepth_test::scaled(16); ++k) {
    // Another point set every other time; otherwise the same hull structure with other
    // coordinates (anisotropic scaling and a shift).
    auto p = bases_p[(k / 2) % 2], q = bases_q[(k / 2) % 2];
    const double f = 1 + 0.3 * (k % 2);
    const Vec3 shift = 2.0 * (k % 3) * Vec3(1, -0.5, 0.25);  // both shapes: M only scales
    for (auto& x : p) x = Vec3(f * x.x(), x.y() / f, x.z()) + shift;
    for (auto& x : q) x = Vec3(x.x(), f * x.y(), x.z() / f) + shift;
    Pair S(p, q);
    for (int j = 0; j < 3; ++j) {  // Q rotated about the shift point
      Pose3 pq((k + j) % 2 ? r1 : r2, Vec3(U(rng), U(rng), U(rng)));
      pq.translation += shift - pq.matrix() * shift;
      check_pose(S, Pose3(), pq, dirs, st, "rebuilt");
    }
  }
  finish(st, "rebuilt shapes");
  EXPECT_GT(st.sigma_d_over, 0);
}

}  // namespace
}  // namespace pendepth
