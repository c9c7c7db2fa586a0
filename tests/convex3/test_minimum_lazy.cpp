// σ's lazy refinement in Phase B (src/convex3/minimum_expand.cpp: the cutoff of a new best facet
// is upper_key(), a rigorous bound from the rounded values, and refine() runs once, on the
// answer's facet) against the path before it (each new best facet refined at once,
// convex3::minimum_depth_expand_eager): every field of the answer equal bit for bit, on random
// hulls, the shared real hulls, integer spheres at integer offsets (exact ties on many planes),
// cubes and prisms (coplanar faces, face–face contact), slivers, touching and disjoint pairs, and
// warm starts. The certificate itself: on every facet of the final K, upper_key() >= the exact
// (h/|n|)² >= lower_key() (rationals) — a bound that lost a margin fails here.
#include <gtest/gtest.h>

#include <pendepth/depth3.hpp>

#include "convex3/minimum_expand.hpp"
#include "shapes3.hpp"

#include <cstring>
#include <random>
#include <string>
#include <vector>
#include "test_rotations.hpp"

namespace pendepth {
namespace {

using convex3::RelativePose;

RelativePose relative_pose(const Pose3& pp, const Pose3& pq) {
  Eigen::Matrix3d Rp = pp.matrix(), Rq = pq.matrix();
  RelativePose r;
  r.R = Rp.transpose() * Rq;
  r.tq = Rp.transpose() * pq.translation;
  r.tp = Rp.transpose() * pp.translation;
  return r;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(const Vec3& a, const Vec3& b) {
  return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()) && same_bits(a.z(), b.z());
}

struct Tally {
  int cases = 0, overlapping = 0, facets = 0;
};

// The lazy and the eager path on one placement (cold and from a seed), and the keys of K.
void compare(const ConvexPolytope& P, const ConvexPolytope& Q, const Pose3& pq, Tally& t, const std::string& what) {
  SCOPED_TRACE(what);
  const Pose3 pp;
  const RelativePose rel = relative_pose(pp, pq);
  const Eigen::Matrix3d Rp = pp.matrix();
  const Depth3 a = convex3::minimum_depth_expand(P, Q, rel, Rp, pp.translation);
  const Depth3 b = convex3::minimum_depth_expand_eager(P, Q, rel, Rp, pp.translation);
  ++t.cases;
  t.overlapping += a.overlapping;
  EXPECT_EQ(a.overlapping, b.overlapping);
  EXPECT_TRUE(same_bits(a.depth, b.depth)) << a.depth << " vs " << b.depth;
  EXPECT_TRUE(same_bits(a.lower_bound, b.lower_bound));
  EXPECT_TRUE(same_bits(a.upper_bound, b.upper_bound));
  EXPECT_TRUE(same_bits(a.translation, b.translation));
  EXPECT_TRUE(same_bits(a.normal, b.normal));
  EXPECT_TRUE(same_bits(a.facet_normal, b.facet_normal));
  EXPECT_TRUE(same_bits(a.witness_p, b.witness_p));
  EXPECT_TRUE(same_bits(a.witness_q, b.witness_q));
  EXPECT_EQ(a.feature_p.kind, b.feature_p.kind);
  EXPECT_EQ(a.feature_p.index, b.feature_p.index);
  EXPECT_EQ(a.feature_q.kind, b.feature_q.kind);
  EXPECT_EQ(a.feature_q.index, b.feature_q.index);
  EXPECT_EQ(a.candidates, b.candidates);  // the same supports: only the refinements moved
  if (a.overlapping) {
    // Warm (seeded by the answer itself, at the same pose) = cold, on both paths.
    convex3::ExpandSeed s1, s2;
    (void)convex3::minimum_depth_expand(P, Q, rel, Rp, pp.translation, &s1);
    (void)convex3::minimum_depth_expand_eager(P, Q, rel, Rp, pp.translation, &s2);
    const Depth3 wa = convex3::minimum_depth_expand(P, Q, rel, Rp, pp.translation, &s1);
    const Depth3 wb = convex3::minimum_depth_expand_eager(P, Q, rel, Rp, pp.translation, &s2);
    EXPECT_TRUE(same_bits(wa.depth, a.depth));
    EXPECT_TRUE(same_bits(wb.depth, a.depth));
    EXPECT_TRUE(same_bits(wa.normal, a.normal) && same_bits(wa.witness_p, a.witness_p));
    EXPECT_TRUE(same_bits(wb.normal, a.normal) && same_bits(wb.witness_p, a.witness_p));
    int checked = 0;
    EXPECT_EQ(convex3::minimum_expand_key_violations(P, Q, rel, checked), 0);
    t.facets += checked;
  }
}

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_unit_quaternion(rng); }

Vec3 centroid(const ConvexPolytope& S) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& v : S.vertices()) c += v / double(S.size());
  return c;
}

TEST(MinimumLazy, RandomHulls) {
  std::mt19937_64 rng(0x51a7);
  std::uniform_real_distribution<double> U(-1, 1);
  Tally t;
  for (int n : {4, 6, 10, 20, 40, 64, 200}) {
    const ConvexPolytope P = ConvexPolytope::hull(test3::random_sphere(rng, n), "P");
    const ConvexPolytope Q = ConvexPolytope::hull(test3::random_sphere(rng, n, 0.7), "Q");
    for (int k = 0; k < 40; ++k)
      compare(P, Q, Pose3(random_rotation(rng), 1.2 * Vec3(U(rng), U(rng), U(rng))), t, "n=" + std::to_string(n));
  }
  std::printf("random hulls: %d cases, %d overlapping, %d facets' keys checked\n", t.cases, t.overlapping, t.facets);
  EXPECT_GT(t.overlapping, 150);
}

TEST(MinimumLazy, SharedHulls) {
  const auto files = test3::shared_hull_files();
  ASSERT_GE(files.size(), 8u);
  std::vector<ConvexPolytope> H;
  for (const auto& f : files) H.push_back(ConvexPolytope::hull(read_obj_vertices(f), f));
  std::mt19937_64 rng(0x6a12);
  std::uniform_real_distribution<double> U(-0.3, 0.3);
  Tally t;
  for (std::size_t i = 0; i < H.size(); ++i) {
    const ConvexPolytope &P = H[i], &Q = H[(i + 7) % H.size()];
    double r = 0;
    const Vec3 cp = centroid(P);
    for (const Vec3& v : P.vertices()) r = std::max(r, (v - cp).norm());
    for (int k = 0; k < 6; ++k) {
      const auto rot = random_rotation(rng);
      const Vec3 off = r * Vec3(U(rng), U(rng), U(rng));
      compare(P, Q, Pose3(rot, cp - rot.toRotationMatrix() * centroid(Q) + off), t, files[i]);
      // The same pair without rotation: the hulls' axis-aligned faces become parallel.
      compare(P, Q, Pose3(cp - centroid(Q) + off), t, files[i] + " unrotated");
    }
  }
  std::printf("shared hulls: %d cases, %d overlapping, %d facets' keys checked\n", t.cases, t.overlapping, t.facets);
  EXPECT_GT(t.overlapping, 400);
}

TEST(MinimumLazy, DegenerateFamilies) {
  std::mt19937_64 rng(0xde9e);
  std::uniform_int_distribution<int> I(-4, 4);
  Tally t;
  // Integer spheres at integer offsets: exact ties between facets of M on different planes.
  for (int N : {3, 11, 25, 50}) {
    const ConvexPolytope P = ConvexPolytope::hull(test3::integer_sphere(N), "P");
    const ConvexPolytope Q = ConvexPolytope::hull(test3::integer_sphere(N == 3 ? 2 : 3), "Q");
    for (int k = 0; k < 30; ++k) compare(P, Q, Pose3(Vec3(I(rng), I(rng), I(rng))), t, "isphere" + std::to_string(N));
  }
  // Cubes and prisms: coplanar faces, face–face contact; identical shapes; touching (offset =
  // the sum of half-widths) and disjoint.
  const ConvexPolytope cube = ConvexPolytope::hull(test3::grid(2), "cube");
  for (double x : {0.0, 0.25, 0.5, 1.0, 1.5, 2.0}) compare(cube, cube, Pose3(Vec3(x, 0.5 * x, 0)), t, "cube");
  const ConvexPolytope prism = ConvexPolytope::hull(test3::prism(25), "prism");
  const ConvexPolytope bip = ConvexPolytope::hull(test3::bipyramid(65), "bipyramid");
  for (int k = 0; k < 30; ++k) {
    compare(prism, bip, Pose3(Vec3(I(rng), I(rng), 2 * I(rng))), t, "prism-bipyramid");
    compare(prism, prism, Pose3(Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())), Vec3(I(rng), I(rng), 0)),
            t, "prism quarter turn");
  }
  compare(prism, prism, Pose3(Vec3(0, 0, 14)), t, "prisms touching");
  // Slivers: a flattened ellipsoid (10⁻⁶ thick) against small random hulls.
  std::vector<Vec3> sl = test3::random_sphere(rng, 300);
  for (auto& p : sl) p.z() *= 1e-6;
  const ConvexPolytope sliver = ConvexPolytope::hull(sl, "sliver");
  const ConvexPolytope small = ConvexPolytope::hull(test3::random_sphere(rng, 24, 0.3), "small");
  std::uniform_real_distribution<double> U(-0.6, 0.6);
  for (int k = 0; k < 40; ++k) compare(sliver, small, Pose3(random_rotation(rng), Vec3(U(rng), U(rng), 0.1 * U(rng))), t, "sliver");
  std::printf("degenerate: %d cases, %d overlapping, %d facets' keys checked\n", t.cases, t.overlapping, t.facets);
  EXPECT_GT(t.overlapping, 100);
  EXPECT_LT(t.overlapping, t.cases);  // disjoint and touching placements were met too
}

}  // namespace
}  // namespace pendepth
