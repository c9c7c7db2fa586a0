// The signed distance's fast path (src/convex3/signed_distance3.cpp, gjk_fast: GJK in doubles,
// its final simplex accepted by one filtered certificate) against the exact GJK loop it skips:
//   * bit for bit (distance, bounds, normal, translation, witnesses, features, overlap flag) on
//     the shared game hulls at random poses, on random hulls, and on degenerate placements —
//     boxes and prisms touching, apart by ±1–2 ulps, face on face (coplanar supports), parallel
//     edges, a vertex over the edge and face regions' boundary of a rotated box;
//   * the value's quick double-double evaluation (exact zeros proven by FlX / FlZ) equals the
//     general per-component evaluation bit for bit, on both paths, and so does the quick
//     value checked against bounds proven in advance (a_priori_value) against running bounds;
//   * the fast path answers most apart pairs (it is not a path that never runs);
//   * the certificate's margin matters: with the error bounds removed (margin 0, plain floating
//     signs) the same placements give results that differ from the exact path's — so a
//     certificate without its margin fails this test.
#include <gtest/gtest.h>

#include <pendepth/depth3.hpp>
#include <pendepth/io.hpp>

#include "convex3/distance_compare.hpp"
#include "convex3/shapes3.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>
#include "test_rotations.hpp"

namespace pendepth {
namespace {

using convex3::SignedDistancePath;

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
bool same_bits(const Vec3& a, const Vec3& b) {
  return same_bits(a[0], b[0]) && same_bits(a[1], b[1]) && same_bits(a[2], b[2]);
}
bool same(const Distance3& a, const Distance3& b) {
  return same_bits(a.distance, b.distance) && same_bits(a.lower_bound, b.lower_bound) &&
         same_bits(a.upper_bound, b.upper_bound) && same_bits(a.normal, b.normal) &&
         same_bits(a.translation, b.translation) && same_bits(a.witness_p, b.witness_p) &&
         same_bits(a.witness_q, b.witness_q) && a.feature_p == b.feature_p && a.feature_q == b.feature_q &&
         a.overlapping == b.overlapping;
}

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_unit_quaternion(rng); }

struct Tally {
  int queries = 0, fast = 0, mismatches = 0, mismatches_margin0 = 0;
};

// Runs one placement through the three paths and counts.
void check(const ConvexPolytope& P, const Pose3& pp, const ConvexPolytope& Q, const Pose3& pq, Tally& t,
           const std::string& what) {
  bool used = false, used0 = false;
  const Distance3 exact = convex3::signed_distance_path(P, pp, Q, pq, SignedDistancePath{false, 1.0});
  const Distance3 fast = convex3::signed_distance_path(P, pp, Q, pq, SignedDistancePath{true, 1.0}, &used);
  const Distance3 fast0 = convex3::signed_distance_path(P, pp, Q, pq, SignedDistancePath{true, 0.0}, &used0);
  const Distance3 front = signed_distance(P, pp, Q, pq);
  // The value's quick double-double evaluation (exact zeros by FlX / FlZ) against the general
  // per-component one, on both paths.
  const Distance3 exact_general = convex3::signed_distance_path(P, pp, Q, pq, SignedDistancePath{false, 1.0, false});
  const Distance3 fast_general = convex3::signed_distance_path(P, pp, Q, pq, SignedDistancePath{true, 1.0, false});
  // The quick value checked against bounds proven in advance (DV) against the running
  // bounds alone (DD), on both paths.
  const Distance3 exact_running =
      convex3::signed_distance_path(P, pp, Q, pq, SignedDistancePath{false, 1.0, true, false});
  const Distance3 fast_running =
      convex3::signed_distance_path(P, pp, Q, pq, SignedDistancePath{true, 1.0, true, false});
  ++t.queries;
  t.fast += used;
  if (!same(exact, exact_running) || !same(fast, fast_running)) {
    ++t.mismatches;
    ADD_FAILURE() << what << ": a priori bounds " << exact.distance << " vs running bounds "
                  << exact_running.distance << " (normal " << exact.normal.transpose() << " vs "
                  << exact_running.normal.transpose() << ")";
  }
  if (!same(exact, exact_general) || !same(fast, fast_general)) {
    ++t.mismatches;
    ADD_FAILURE() << what << ": quick value " << exact.distance << " vs general " << exact_general.distance
                  << " (normal " << exact.normal.transpose() << " vs " << exact_general.normal.transpose() << ")";
  }
  if (!same(exact, fast) || !same(exact, front)) {
    ++t.mismatches;
    ADD_FAILURE() << what << ": fast path (used " << used << ") " << fast.distance << " vs exact " << exact.distance
                  << " (normal " << fast.normal.transpose() << " vs " << exact.normal.transpose() << ", features "
                  << int(fast.feature_p.kind) << ":" << fast.feature_p.index << "/" << int(fast.feature_q.kind) << ":"
                  << fast.feature_q.index << " vs " << int(exact.feature_p.kind) << ":" << exact.feature_p.index << "/"
                  << int(exact.feature_q.kind) << ":" << exact.feature_q.index << ")";
  }
  t.mismatches_margin0 += !same(exact, fast0);
}

Vec3 centroid(const ConvexPolytope& S) {
  Vec3 x = Vec3::Zero();
  for (const Vec3& v : S.vertices()) x += v / double(S.size());
  return x;
}
double radius(const ConvexPolytope& S) {
  double r = 0;
  for (const Vec3& v : S.vertices()) r = std::max(r, (v - centroid(S)).norm());
  return r;
}

// Random poses of the shared hulls, apart and overlapping, plus the same placements pushed to
// touching (Q moved by the exact translation) and ±1–2 ulps around it.
TEST(DistanceFast, SharedHullsBitForBit) {
  const std::vector<ConvexPolytope> H = test3::shared_hulls();
  ASSERT_GE(H.size(), 8u);
  std::mt19937_64 rng(0x5dfa57);
  std::uniform_real_distribution<double> U(0.3, 1.6);
  Tally t, apart;
  for (int q = 0; q < 600; ++q) {
    const ConvexPolytope &P = H[q % H.size()], &Q = H[(q + 7) % H.size()];
    const Eigen::Quaterniond rot = random_rotation(rng);
    Vec3 dir(U(rng) - 0.95, U(rng) - 0.95, U(rng) - 0.95);
    if (dir.norm() < 1e-3) continue;
    const Vec3 off = centroid(P) - rot.toRotationMatrix() * centroid(Q) + (radius(P) + radius(Q)) * U(rng) * dir.normalized();
    const Pose3 pp = q % 4 == 3 ? Pose3(random_rotation(rng), Vec3(0.1, -0.2, 0.3)) : Pose3();
    const Pose3 pq(rot, pp.matrix() * off + pp.translation);
    check(P, pp, Q, pq, t, "shared hull pair " + std::to_string(q));
    const Distance3 d = signed_distance(P, pp, Q, pq);
    if (d.distance > 0) {
      check(P, pp, Q, pq, apart, "apart");
      // Touching and a few ulps either side: Q moved by the translation to contact.
      for (int k = -2; k <= 2; ++k) {
        Vec3 tr = pq.translation + d.translation;
        for (int c = 0; c < 3; ++c)
          for (int s = 0; s < std::abs(k); ++s) tr[c] = std::nextafter(tr[c], k > 0 ? HUGE_VAL : -HUGE_VAL);
        check(P, pp, Q, Pose3(rot, tr), t, "touching±ulps pair " + std::to_string(q) + " k " + std::to_string(k));
      }
    }
  }
  EXPECT_EQ(t.mismatches + apart.mismatches, 0);
  // Most apart placements are answered by the fast path alone.
  EXPECT_GT(apart.fast, apart.queries * 7 / 10) << apart.fast << " of " << apart.queries;
  std::printf("shared hulls: %d placements, fast path on %d of %d apart; margin 0 differs on %d\n", t.queries,
              apart.fast, apart.queries, t.mismatches_margin0);
}

// Boxes and prisms (integer and decimal coordinates) in degenerate placements: face on face
// (coplanar supports), edge parallel to edge, vertex over an edge, touching and ±ulps apart,
// axis-aligned and under small and random rotations.
TEST(DistanceFast, DegeneratePlacementsBitForBit) {
  auto cuboid = [](const Vec3& lo, const Vec3& hi) {
    std::vector<Vec3> v;
    for (int k = 0; k < 8; ++k) v.emplace_back(k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]);
    return ConvexPolytope::hull(v, "cuboid");
  };
  const ConvexPolytope box = cuboid(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  const ConvexPolytope slab = cuboid(Vec3(-0.3, -0.7, -0.1), Vec3(0.9, 0.7, 0.1));
  const ConvexPolytope prism = ConvexPolytope::hull(test3::prism(5, 1.5));
  const ConvexPolytope bip = ConvexPolytope::hull(test3::bipyramid(25));
  const std::vector<const ConvexPolytope*> shapes{&box, &slab, &prism, &bip};
  std::mt19937_64 rng(0xde9e);
  std::uniform_real_distribution<double> U(-1, 1);
  Tally t;
  const std::vector<Vec3> dirs{{1, 0, 0}, {0, 0, 1}, {1, 1, 0}, {1, 1, 1}, {0.5, 0, 1}, {1, 0.25, 0}};
  for (const ConvexPolytope* P : shapes)
    for (const ConvexPolytope* Q : shapes)
      for (const Vec3& dir0 : dirs)
        for (int rot_kind = 0; rot_kind < 3; ++rot_kind) {
          const Eigen::Quaterniond rot = rot_kind == 0   ? Eigen::Quaterniond::Identity()
                                         : rot_kind == 1 ? Eigen::Quaterniond(Eigen::AngleAxisd(1e-9, Vec3(0, 0, 1)))
                                                         : random_rotation(rng);
          const Vec3 dir = dir0.normalized();
          // Far apart, then the exact contact translation, then ±1–2 ulps around it.
          const Pose3 far(rot, 30 * dir + 0.1 * Vec3(U(rng), U(rng), U(rng)) * (rot_kind == 2));
          check(*P, Pose3(), *Q, far, t, "far");
          const Distance3 d = signed_distance(*P, Pose3(), *Q, far);
          ASSERT_GT(d.distance, 0);
          const Vec3 touch = far.translation + d.translation;
          for (int k = -2; k <= 2; ++k) {
            Vec3 tr = touch;
            for (int c = 0; c < 3; ++c)
              for (int s = 0; s < std::abs(k); ++s) tr[c] = std::nextafter(tr[c], k > 0 ? HUGE_VAL : -HUGE_VAL);
            check(*P, Pose3(), *Q, Pose3(rot, tr), t, "near touching k " + std::to_string(k));
          }
          // A gap of one unit exactly along an axis (integer data: exact placements).
          check(*P, Pose3(), *Q, Pose3(rot, touch + 0x1p-20 * dir), t, "gap");
        }
  EXPECT_EQ(t.mismatches, 0);
  std::printf("degenerate: %d placements, fast path on %d; margin 0 differs on %d\n", t.queries, t.fast,
              t.mismatches_margin0);
}

// Random hulls (random points on spheres and in balls), random poses near contact: the closest
// point is often within rounding of an edge of M, where the certificate's λ and strictness tests
// are close calls.
TEST(DistanceFast, RandomHullsNearContactBitForBit) {
  std::mt19937_64 rng(0xfa57);
  std::uniform_real_distribution<double> U(-1, 1);
  Tally t;
  for (int q = 0; q < 300; ++q) {
    const ConvexPolytope P = ConvexPolytope::hull(q % 2 ? test3::random_sphere(rng, 6 + q % 20)
                                                        : test3::random_ball(rng, 8 + q % 30));
    const ConvexPolytope Q = ConvexPolytope::hull(test3::random_sphere(rng, 4 + q % 12, 0.5));
    const Eigen::Quaterniond rot = random_rotation(rng);
    const Vec3 dir = Vec3(U(rng), U(rng), U(rng)).normalized();
    const Pose3 far(rot, 3 * dir);
    check(P, Pose3(), Q, far, t, "random far");
    const Distance3 d = signed_distance(P, Pose3(), Q, far);
    const Vec3 touch = far.translation + d.translation;
    for (double g : {1e-3, 1e-9, 0.0})
      check(P, Pose3(), Q, Pose3(rot, touch - g * d.normal), t, "random near");
  }
  EXPECT_EQ(t.mismatches, 0);
  std::printf("random hulls: %d placements, fast path on %d; margin 0 differs on %d\n", t.queries, t.fast,
              t.mismatches_margin0);
}

// The margin is what makes the certificate sound: without it (plain floating signs) some of the
// placements above are accepted on a sign the rounding got wrong (a coplanar neighbour taken as
// strictly above, a barycentric numerator of 0 taken as positive) and the answer differs from
// the exact one. This test fails if the margin stops mattering, e.g. if the certificate no longer
// reads it — or if every close call were decided some other way, in which case it should go.
TEST(DistanceFast, CertificateWithoutMarginIsDetected) {
  const std::vector<ConvexPolytope> H = test3::shared_hulls();
  ASSERT_GE(H.size(), 8u);
  std::mt19937_64 rng(0x0a12);
  std::uniform_real_distribution<double> U(0.3, 1.6);
  int differ = 0, n = 0;
  for (int q = 0; q < 400; ++q) {
    const ConvexPolytope &P = H[q % H.size()], &Q = H[(q + 3) % H.size()];
    const Eigen::Quaterniond rot = random_rotation(rng);
    const Vec3 dir = Vec3(U(rng) - 0.95, U(rng) - 0.95, U(rng) - 0.95).normalized();
    const Pose3 pq(rot, centroid(P) - rot.toRotationMatrix() * centroid(Q) + 2 * (radius(P) + radius(Q)) * dir);
    const Distance3 exact = convex3::signed_distance_path(P, Pose3(), Q, pq, SignedDistancePath{false, 1.0});
    const Distance3 fast0 = convex3::signed_distance_path(P, Pose3(), Q, pq, SignedDistancePath{true, 0.0});
    for (const Pose3& x : {pq, Pose3(rot, pq.translation + exact.translation)}) {
      const Distance3 e = convex3::signed_distance_path(P, Pose3(), Q, x, SignedDistancePath{false, 1.0});
      const Distance3 f = convex3::signed_distance_path(P, Pose3(), Q, x, SignedDistancePath{true, 0.0});
      ++n;
      differ += !same(e, f);
    }
    (void)fast0;
  }
  EXPECT_GT(differ, 0) << "margin 0 never changed a result on " << n << " placements";
}

}  // namespace
}  // namespace pendepth
