// generalized_depth in 3D on mesh pairs (src/motion/generalized_depth3.cpp; issue 18 item 2).
//
// Shapes: polycubes written as OBJ / OFF text and read back (io::parse_mesh, Mesh3::validate), some
// on a non-uniform grid (cell boundaries mapped to chosen coordinates: the faces stay planar).
// Oracles, independent of the search:
//   - the motion: Pair3::overlapping (the exact overlap test) at the returned pose, and that pose
//     equals the documented recomposition of rotation and translation;
//   - its cost: DISP of Q's hull vertices between the two poses in GMP rationals (the poses'
//     rotation matrices as doubles), upper² ≥ DISP² exactly and upper within 1e-12 of DISP;
//   - the lower bound: random separating motions (random rotations with the σ translation at the
//     rotated pose, verified by the overlap test) all cost at least lower_bound (exact DISP);
//   - a bar stuck diagonally between two blocks: turning it back costs 2 sin(φ/2)·r, far below σ,
//     and the search finds at most 1.05 times that.
#include <pendepth/mesh3.hpp>
#include <pendepth/motion.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh3/mesh_gen.hpp"

#include "mesh3/mesh_pair.hpp"
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cmath>
#include <iostream>
#include <random>

namespace {

using namespace pendepth;
using namespace mesh3_test;

// A polycube whose grid line k on axis a sits at coordinate grid[a][k - lo[a]] (monotone).
Gen mapped(const std::set<Voxel>& v, const std::array<std::vector<double>, 3>& grid, const std::array<int, 3>& lo) {
  Gen g = polycube(v);
  for (Vec3& p : g.points)
    for (int a = 0; a < 3; ++a) p[a] = grid[a].at(static_cast<std::size_t>(static_cast<int>(p[a]) - lo[a]));
  return g;
}

Shape3 from_text(const Gen& g, bool obj, const std::string& name) {
  const std::string text = obj ? write_obj(g) : write_off(g);
  return Shape3::from_mesh(Mesh3::validate(io::parse_mesh(text, obj ? io::MeshFormat::Obj : io::MeshFormat::Off, name), name));
}

mpq_class q(double x) { return mpq_class(x); }

// DISP² of Q's hull vertices from pose a to pose b, exactly (the poses' matrices as doubles).
mpq_class disp2(const Shape3& Q, const Pose3& a, const Pose3& b) {
  const Eigen::Matrix3d A = a.matrix(), B = b.matrix();
  mpq_class worst = 0;
  for (const Vec3& x : Q.polytope().vertices()) {
    mpq_class s = 0;
    for (int i = 0; i < 3; ++i) {
      mpq_class c = q(b.translation[i]) - q(a.translation[i]);
      for (int j = 0; j < 3; ++j) c += (q(B(i, j)) - q(A(i, j))) * q(x[j]);
      s += c * c;
    }
    if (s > worst) worst = s;
  }
  return worst;
}

// Every contract check on one answer; returns the exact DISP² of its motion.
mpq_class check_answer(const Shape3& P, const Pose3& pp, const Shape3& Q, const Pose3& pq, const GeneralizedDepth3& r,
                       const std::string& what, double tolerance = 1e-9) {
  const Pair3 pair(P, Q);
  const Depth3 s = pair.minimum(pp, pq);
  const double pair_lower = [&] {  // σ's bounds' lower end (the pairs' max σ_ij): PD_g's lower bound
    const mesh3::SigmaBoundsOnly bounds_only;
    return pair.minimum(pp, pq).lower_bound;
  }();
  EXPECT_EQ(r.overlapping, s.overlapping) << what;
  if (!s.overlapping) return 0;
  EXPECT_EQ(r.sigma, s.depth) << what;
  EXPECT_LE(r.lower_bound, r.upper_bound) << what;
  EXPECT_EQ(r.depth, r.upper_bound) << what;
  EXPECT_LE(r.upper_bound, s.upper_bound * (1 + 1e-12)) << what;  // rotation only helps
  EXPECT_EQ(r.converged, r.upper_bound - pair_lower <= tolerance * r.upper_bound) << what;
  EXPECT_EQ(r.lower_bound, std::min(pair_lower, r.upper_bound)) << what;
  // The pose is the documented recomposition, and it separates.
  const bool identity = r.rotation.coeffs() == Eigen::Quaterniond::Identity().coeffs();
  const Eigen::Quaterniond qn = pq.rotation.normalized();
  const Eigen::Quaterniond rot = identity ? pq.rotation : Eigen::Quaterniond(r.rotation * qn);
  EXPECT_TRUE(r.pose.rotation.coeffs() == rot.coeffs()) << what;
  EXPECT_TRUE(r.pose.translation == pq.translation + r.translation) << what;
  EXPECT_FALSE(pair.overlapping(pp, r.pose)) << what;
  // The cost: a certified upper bound of the motion's exact DISP, tight to 1e-12.
  const mpq_class d2 = disp2(Q, pq, r.pose);
  EXPECT_GE(q(r.upper_bound) * q(r.upper_bound), d2) << what;
  const double d = std::sqrt(d2.get_d());
  EXPECT_LE(r.upper_bound, d * (1 + 1e-12) + 1e-300) << what;
  EXPECT_NEAR(r.rotation.norm(), 1.0, 1e-15) << what;
  return d2;
}

// P: a wall (z in [-2, -1]) with block A on its left above y = 1 and block B on its right below
// y = -1 (z in [-1, 3]); Q: a bar [-6, 6] x [-1, 1] x [0, 2] (convex), its reference point the middle of its bottom.
// Q turned by φ about z has its left end in A and its right end in B.
struct StuckBar {
  Shape3 P, Q;
  explicit StuckBar(bool obj, double k = 1) : P(make_p(obj, k)), Q(make_q(obj, k)) {}
  static std::vector<double> times(std::vector<double> v, double k) {
    for (double& x : v) x *= k;
    return v;
  }
  static Shape3 make_p(bool obj, double k) {
    std::set<Voxel> v;
    for (int x = 0; x < 3; ++x)
      for (int y = 0; y < 3; ++y) v.insert({x, y, 0});
    v.insert({0, 2, 1});  // A
    v.insert({2, 0, 1});  // B
    return from_text(mapped(v, {times({-7, -2, 2, 7}, k), times({-3, -1, 1, 3}, k), times({-2, -1, 3}, k)}, {0, 0, 0}),
                     obj, "P");
  }
  static Shape3 make_q(bool obj, double k) {
    return from_text(mapped({{0, 0, 0}}, {times({-6, 6}, k), times({-1, 1}, k), times({0, 2}, k)}, {0, 0, 0}), !obj, "Q");
  }
};

TEST(Generalized3Mesh, StuckBarTurnsFreeFarBelowSigma) {
  for (double phi : {-0.1, -0.05, -0.2}) {
      const StuckBar s(phi != -0.05);
      ASSERT_FALSE(s.P.is_convex());
      const Pose3 pp, pq(Eigen::Quaterniond(Eigen::AngleAxisd(phi, Vec3::UnitZ())), Vec3(0, 0, 0));
      const GeneralizedDepth3 r = generalized_depth(s.P, pp, s.Q, pq);
      const std::string what = "phi " + std::to_string(phi);
      ASSERT_TRUE(r.overlapping) << what;
      check_answer(s.P, pp, s.Q, pq, r, what);
      // Turning back by φ frees it (the bar then touches A and B): DISP = 2 sin(|φ|/2)·|(6, 1)|.
      const double turn = 2 * std::sin(std::abs(phi) / 2) * std::sqrt(37.0);
      EXPECT_FALSE(Pair3(s.P, s.Q).overlapping(pp, Pose3()));
      EXPECT_LE(r.upper_bound, 1.05 * turn) << what;
      EXPECT_LT(r.upper_bound, 0.5 * r.sigma) << what;  // strictly below σ's upper bound
      EXPECT_FALSE(r.converged) << what;
      EXPECT_GT(r.probes, 0u);
    }
}

TEST(Generalized3Mesh, RandomPolycubesBoundsMotionsAndLowerBoundAgainstRandomMotions) {
  std::mt19937_64 rng(18);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int pairs = 0;
  for (int attempt = 0; pairs < 4 && attempt < 60; ++attempt) {
    Shape3 P = Shape3::hull(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), Q = P;
    try {
      P = from_text(polycube(random_polycube(rng, 6)), attempt % 2, "P");
      Q = from_text(polycube(random_polycube(rng, 4)), attempt % 2 == 0, "Q");
    } catch (const InvalidInput&) {
      continue;  // a non-manifold union: not a valid mesh
    }
    if (P.is_convex() && Q.is_convex()) continue;
    const Pose3 pp(Eigen::Quaterniond(1, 0.1 * g(rng), 0.1 * g(rng), 0.1 * g(rng)), Vec3(0.3 * u(rng), 0.3 * u(rng), 0));
    const Pose3 pq(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)), Vec3(0.5 + u(rng), 0.5 + u(rng), 0.5 * u(rng)));
    const Pair3 pair(P, Q);
    const Depth3 s = pair.minimum(pp, pq);
    if (!s.overlapping) continue;
    ++pairs;
    GeneralizedOptions3 o;
    o.max_probes = 12;
    const GeneralizedDepth3 r = generalized_depth(P, pp, Q, pq, o);
    const std::string what = "attempt " + std::to_string(attempt);
    check_answer(P, pp, Q, pq, r, what);
    EXPECT_LE(r.probes, o.max_probes) << what;
    // The certified lower bound against separating motions found independently: random rotations
    // about Q's reference point with the σ translation there, kept when the exact test verifies them.
    const mpq_class lower2 = q(r.lower_bound * (1 - 1e-12)) * q(r.lower_bound * (1 - 1e-12));
    int verified = 0;
    for (int i = 0; i < 12; ++i) {
      Eigen::Quaterniond w(1, 0.2 * g(rng), 0.2 * g(rng), 0.2 * g(rng));
      if (i % 3 == 0) w = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng));
      w.normalize();
      const Pose3 turned(w * pq.rotation.normalized(), pq.translation);
      const Depth3 d = pair.minimum(pp, turned);
      const Pose3 moved(turned.rotation, pq.translation + d.translation * (1 + 0x1p-40));
      if (pair.overlapping(pp, moved)) continue;
      ++verified;
      EXPECT_GE(disp2(Q, pq, moved), lower2) << what << " motion " << i;
    }
    EXPECT_GE(verified, 6) << what;
  }
  EXPECT_EQ(pairs, 4);
}

TEST(Generalized3Mesh, ConvexPairsStayAtSigmaEvenWhenSearched) {
  // Convex meshes (boxes on the grid) and hulls: the theorem's answer; with the search forced,
  // nothing beats σ (the theorem) and the search's motion is verified.
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g;
  for (int k = 0; k < 6; ++k) {
    std::vector<Vec3> a, b;
    for (int i = 0; i < 10 + k; ++i) a.emplace_back(g(rng), g(rng), 0.6 * g(rng));
    for (int i = 0; i < 8 + k; ++i) b.emplace_back(0.7 * g(rng) + 0.2, 0.5 * g(rng), g(rng));
    const Shape3 P = Shape3::hull(a, "P"), Q = Shape3::hull(b, "Q");
    const Pose3 pp, pq(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)), Vec3(0.1, 0.2, -0.1));
    const Depth3 s = Pair3(P, Q).minimum(pp, pq);
    if (!s.overlapping) continue;
    const GeneralizedDepth3 t = generalized_depth(P, pp, Q, pq);
    EXPECT_EQ(t.depth, s.depth);
    EXPECT_TRUE(t.converged);
    EXPECT_EQ(t.probes, 0u);
    EXPECT_TRUE(t.pose.translation == pq.translation + s.translation);
    GeneralizedOptions3 o;
    o.convex_theorem = false;
    o.max_probes = 24;
    o.tolerance = 0;  // σ's bounds meet: search anyway
    const GeneralizedDepth3 r = generalized_depth(P, pp, Q, pq, o);
    check_answer(P, pp, Q, pq, r, "convex " + std::to_string(k), 0);
    EXPECT_GE(r.upper_bound, s.depth * (1 - 1e-9)) << k;  // PD_g = σ
    EXPECT_LE(r.upper_bound, s.depth * (1 + 1e-9)) << k;
    EXPECT_GT(r.probes, 0u) << k;
  }
}

TEST(Generalized3Mesh, ApartZeroProbesAndScaling) {
  const StuckBar s(true);
  // Apart: nothing to do.
  const Pose3 far(Vec3(0, 0, 10));
  const GeneralizedDepth3 a = generalized_depth(s.P, Pose3(), s.Q, far);
  EXPECT_FALSE(a.overlapping);
  EXPECT_EQ(a.depth, 0);
  EXPECT_TRUE(a.pose.translation == far.translation);
  // No probes: the translational answer, verified.
  const Pose3 pq(Eigen::Quaterniond(Eigen::AngleAxisd(-0.1, Vec3::UnitZ())), Vec3(0, 0, 0));
  GeneralizedOptions3 o;
  o.max_probes = 0;
  const GeneralizedDepth3 t = generalized_depth(s.P, Pose3(), s.Q, pq, o);
  check_answer(s.P, Pose3(), s.Q, pq, t, "no probes");
  EXPECT_EQ(t.probes, 0u);
  EXPECT_TRUE(t.rotation.coeffs() == Eigen::Quaterniond::Identity().coeffs());
  EXPECT_NEAR(t.upper_bound, t.sigma, 1e-12 * t.sigma);
  // Huge and tiny copies (the numeric domain): the same search, lengths scaled.
  const GeneralizedDepth3 r = generalized_depth(s.P, Pose3(), s.Q, pq);
  for (int e : {-300, 200}) {
    const StuckBar big(true, std::ldexp(1.0, e));
    const Shape3 &P = big.P, &Q = big.Q;
    const Pose3 pqs(pq.rotation, std::ldexp(1.0, e) * pq.translation);
    const GeneralizedDepth3 g = generalized_depth(P, Pose3(), Q, pqs);
    check_answer(P, Pose3(), Q, pqs, g, "scale 2^" + std::to_string(e));
    EXPECT_NEAR(g.upper_bound, std::ldexp(r.upper_bound, e), 1e-9 * std::ldexp(r.upper_bound, e)) << e;
    EXPECT_NEAR(g.lower_bound, std::ldexp(r.lower_bound, e), 1e-9 * std::ldexp(r.lower_bound, e)) << e;
  }
}

// generalized_depth takes σ and the pairs' max σ_ij from one query (mesh3::SigmaKeepBounds): the
// kept answer must be, bit for bit, what the query returns on the bounds alone (a SigmaBoundsOnly
// guard), also through Pair3's numeric-domain scaling; on some poses the query's own answer must be
// the exact σ (another lower bound), so that the kept one is not just a copy of it.
TEST(Generalized3Mesh, KeptBoundsAreTheBoundsOnlyAnswer) {
  int refined = 0, compared = 0;
  for (int e : {0, -300, 200}) {
    const StuckBar s(e % 2 == 0, std::ldexp(1.0, e));
    const Pair3 pair(s.P, s.Q);
    for (double phi : {-0.05, -0.1, -0.2}) {
      const Pose3 pq(Eigen::Quaterniond(Eigen::AngleAxisd(phi, Vec3::UnitZ())), std::ldexp(1.0, e) * Vec3(0.25, -0.125, 0.5));
      mesh3::SigmaKeepBounds keep;
      const Depth3 x = pair.minimum(Pose3(), pq);
      const Depth3 b = [&] {
        const mesh3::SigmaBoundsOnly bounds_only;
        return pair.minimum(Pose3(), pq);
      }();
      const std::string what = "2^" + std::to_string(e) + " phi " + std::to_string(phi);
      ASSERT_TRUE(keep.bounds.has_value()) << what;
      const Depth3& k = *keep.bounds;
      EXPECT_TRUE(k.overlapping == b.overlapping && k.depth == b.depth && k.lower_bound == b.lower_bound &&
                  k.upper_bound == b.upper_bound && k.translation == b.translation && k.normal == b.normal)
          << what << ": kept " << k.lower_bound << " " << k.upper_bound << " vs " << b.lower_bound << " " << b.upper_bound;
      ++compared, refined += x.lower_bound != b.lower_bound;
    }
  }
  EXPECT_EQ(compared, 9);
  EXPECT_GT(refined, 0);  // the exact σ ran on some poses
  std::cout << "[generalized3] kept bounds compared on " << compared << " poses, " << refined << " with the exact σ\n";
}

TEST(Generalized3Mesh, BadInput) {
  const StuckBar s(false);
  EXPECT_THROW(generalized_depth(s.P, Pose3(), s.Q, Pose3(Vec3(NAN, 0, 0))), InvalidInput);
  EXPECT_THROW(generalized_depth(s.P, Pose3(Vec3(0, INFINITY, 0)), s.Q, Pose3()), InvalidInput);
  EXPECT_THROW(generalized_depth(s.P, Pose3(), s.Q, Pose3(Eigen::Quaterniond(0, 0, 0, 0), Vec3::Zero())), InvalidInput);
  EXPECT_THROW(generalized_depth(s.P, Pose3(Eigen::Quaterniond(NAN, 0, 0, 1), Vec3::Zero()), s.Q, Pose3()), InvalidInput);
  GeneralizedOptions3 o;
  o.tolerance = -1;
  EXPECT_THROW(generalized_depth(s.P, Pose3(), s.Q, Pose3(), o), InvalidInput);
  o.tolerance = NAN;
  EXPECT_THROW(generalized_depth(s.P, Pose3(), s.Q, Pose3(), o), InvalidInput);
}

}  // namespace
