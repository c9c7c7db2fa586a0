// Run-time ISA dispatch (src/geometry/isa.hpp): the x86-64-v3 clones of σ by expansion and of
// the signed distance (the whole call tree inlined and compiled with AVX2 + FMA) answer every
// field bit for bit as the baseline build (libm's fma, SSE2) — on the shared game hulls at random
// poses (overlapping and apart), on touching placements and ±1–2 ulps around them, and on random
// and integer boxes under quarter turns and generic rotations. Skipped where the processor (or
// the build) has no x86-64-v3 clones.
#include <gtest/gtest.h>

#include <pendepth/depth3.hpp>

#include "convex3/shapes3.hpp"
#include "geometry/isa.hpp"
#include "test_rotations.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <random>
#include <string>
#include <vector>

namespace pendepth {
namespace {

// The doubles of a result, in field order, for a bitwise comparison.
std::vector<std::uint64_t> bits(std::initializer_list<double> x) {
  std::vector<std::uint64_t> b;
  for (double v : x) b.push_back(std::bit_cast<std::uint64_t>(v));
  return b;
}
std::vector<std::uint64_t> bits(const Depth3& d) {
  auto b = bits({d.depth, d.lower_bound, d.upper_bound, d.translation[0], d.translation[1], d.translation[2],
                 d.normal[0], d.normal[1], d.normal[2], d.facet_normal[0], d.facet_normal[1], d.facet_normal[2],
                 d.witness_p[0], d.witness_p[1], d.witness_p[2], d.witness_q[0], d.witness_q[1], d.witness_q[2]});
  for (std::uint64_t x : {std::uint64_t(d.candidates), std::uint64_t(d.overlapping), std::uint64_t(d.feature_p.kind),
                          std::uint64_t(d.feature_p.index), std::uint64_t(d.feature_q.kind), std::uint64_t(d.feature_q.index)})
    b.push_back(x);
  return b;
}
std::vector<std::uint64_t> bits(const Distance3& d) {
  auto b = bits({d.distance, d.lower_bound, d.upper_bound, d.translation[0], d.translation[1], d.translation[2],
                 d.normal[0], d.normal[1], d.normal[2], d.witness_p[0], d.witness_p[1], d.witness_p[2],
                 d.witness_q[0], d.witness_q[1], d.witness_q[2]});
  for (std::uint64_t x : {std::uint64_t(d.overlapping), std::uint64_t(d.feature_p.kind), std::uint64_t(d.feature_p.index),
                          std::uint64_t(d.feature_q.kind), std::uint64_t(d.feature_q.index)})
    b.push_back(x);
  return b;
}

// Sets isa::use_v3() for one query, restores it after.
struct Isa {
  bool saved = isa::use_v3();
  explicit Isa(bool v3) { isa::use_v3() = v3; }
  ~Isa() { isa::use_v3() = saved; }
};

struct Tally {
  int queries = 0, overlapping = 0, apart = 0, mismatches = 0;
};

// σ and the signed distance of one placement on both paths; returns the baseline distance.
Distance3 check(const ConvexPolytope& P, const Pose3& pp, const ConvexPolytope& Q, const Pose3& pq, Tally& t,
                const std::string& what) {
  Depth3 s[2];
  Distance3 d[2];
  for (int v3 = 0; v3 < 2; ++v3) {
    const Isa isa(v3 == 1);
    s[v3] = minimum_depth(P, pp, Q, pq);
    d[v3] = signed_distance(P, pp, Q, pq);
  }
  ++t.queries;
  t.overlapping += s[0].overlapping;
  t.apart += d[0].distance > 0;
  if (bits(s[0]) != bits(s[1]) || bits(d[0]) != bits(d[1])) {
    ++t.mismatches;
    ADD_FAILURE() << what << ": σ " << std::hexfloat << s[0].depth << " (baseline) vs " << s[1].depth
                  << " (v3), distance " << d[0].distance << " vs " << d[1].distance;
  }
  return d[0];
}

// Q's pose putting its box centre at P's box centre + `scale`·(the two half-diagonals)·u.
Pose3 placed(const ConvexPolytope& P, const ConvexPolytope& Q, const Eigen::Quaterniond& rot, const Vec3& u,
             double scale) {
  auto mid = [](const ConvexPolytope& S) {
    Eigen::AlignedBox3d b;
    for (const Vec3& v : S.vertices()) b.extend(v);
    return std::pair(Vec3(b.center()), 0.5 * b.diagonal().norm());
  };
  const auto [cp, rp] = mid(P);
  const auto [cq, rq] = mid(Q);
  return Pose3(rot, cp - rot.toRotationMatrix() * cq + scale * (rp + rq) * u);
}

class IsaDispatch : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!isa::v3_available()) GTEST_SKIP() << "no x86-64-v3 clones on this build or processor";
  }
};

// The shared hulls: pairs (i, i + 7) and (i, i + 13), random rotations, centre distances from
// deep overlap to apart; each apart placement also moved to touching and ±1–2 ulps around it.
TEST_F(IsaDispatch, SharedHullsBitForBit) {
  const std::vector<ConvexPolytope> H = test3::shared_hulls();
  ASSERT_GE(H.size(), 8u);
  std::mt19937_64 rng(0x15a3);
  std::uniform_real_distribution<double> U(0.0, 0.9);
  std::normal_distribution<double> N;
  Tally t;
  for (int q = 0; q < 3000; ++q) {
    const ConvexPolytope &P = H[q % H.size()], &Q = H[(q + (q % 2 ? 7 : 13)) % H.size()];
    const Eigen::Quaterniond rot = pendepth_test::random_unit_quaternion(rng);
    const Vec3 u = Vec3(N(rng), N(rng), N(rng)).normalized();
    const Pose3 pp = q % 4 == 3 ? Pose3(pendepth_test::random_unit_quaternion(rng), Vec3(0.1, -0.2, 0.3)) : Pose3();
    Pose3 pq = placed(P, Q, rot, u, U(rng));
    pq.translation = pp.matrix() * pq.translation + pp.translation;
    const Distance3 d = check(P, pp, Q, pq, t, "hulls " + std::to_string(q));
    if (d.distance > 0 && q % 3 == 0)
      for (int k = -2; k <= 2; ++k) {
        Vec3 tr = pq.translation + d.translation;
        for (int c = 0; c < 3; ++c)
          for (int s = 0; s < std::abs(k); ++s) tr[c] = std::nextafter(tr[c], k > 0 ? HUGE_VAL : -HUGE_VAL);
        check(P, pp, Q, Pose3(rot, tr), t, "hulls touching " + std::to_string(q) + " k " + std::to_string(k));
      }
  }
  EXPECT_EQ(t.mismatches, 0);
  EXPECT_GT(t.overlapping, t.queries / 4);
  EXPECT_GT(t.apart, t.queries / 4);
  std::printf("shared hulls: %d placements (%d overlapping, %d apart), %d differ\n", t.queries, t.overlapping,
              t.apart, t.mismatches);
}

// Boxes: random real extents and integer extents, quarter turns (parallel faces and edges,
// coplanar supports) and generic rotations, integer, half-integer and random offsets.
TEST_F(IsaDispatch, BoxesBitForBit) {
  auto box = [](const Vec3& h) {
    std::vector<Vec3> v;
    for (int k = 0; k < 8; ++k) v.emplace_back(k & 1 ? h[0] : -h[0], k & 2 ? h[1] : -h[1], k & 4 ? h[2] : -h[2]);
    return ConvexPolytope::hull(v, "box");
  };
  std::mt19937_64 rng(0xb0c5);
  std::uniform_real_distribution<double> E(0.05, 2.0), O(-3, 3);
  std::uniform_int_distribution<int> I(1, 4), T(0, 3);
  Tally t;
  for (int q = 0; q < 2000; ++q) {
    const bool integer = q % 2 == 0;
    const ConvexPolytope P = integer ? box(Vec3(I(rng), I(rng), I(rng))) : box(Vec3(E(rng), E(rng), E(rng)));
    const ConvexPolytope Q = integer ? box(Vec3(I(rng), I(rng), I(rng))) : box(Vec3(E(rng), E(rng), E(rng)));
    Eigen::Quaterniond rot = pendepth_test::random_unit_quaternion(rng);
    if (q % 3 != 2) {  // a quarter turn about a coordinate axis: exact components 0, ±1/√2, ±1
      const int a = T(rng) % 3, n = T(rng);
      rot = Eigen::Quaterniond(Eigen::AngleAxisd(n * M_PI / 2, Vec3::Unit(a)));
      if (n == 0) rot = Eigen::Quaterniond::Identity();
    }
    Vec3 off(O(rng), O(rng), O(rng));
    if (integer) off = 0.5 * (2 * off).array().round().matrix();
    check(P, Pose3(), Q, Pose3(rot, off), t, "boxes " + std::to_string(q));
  }
  EXPECT_EQ(t.mismatches, 0);
  EXPECT_GT(t.overlapping, t.queries / 10);
  EXPECT_GT(t.apart, t.queries / 10);
  std::printf("boxes: %d placements (%d overlapping, %d apart), %d differ\n", t.queries, t.overlapping, t.apart,
              t.mismatches);
}

}  // namespace
}  // namespace pendepth
