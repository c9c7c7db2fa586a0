// Warm start of 3D σ (Pair3::minimum with a WarmStart3, Pair3::trajectory; survey §3.3): the
// warm answer equals the cold one bit for bit in every field but `candidates`, on trajectories
// with small steps, large jumps and separated poses, at exact ties (boxes face to face,
// identical cubes in place, symmetric shapes at quarter turns), for pairs the numeric domain
// scales (2^±300), and for arbitrary seeds at the engine (any seed, even a meaningless one,
// gives the canonical answer). The warm start is exercised: it does fewer support queries.
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "convex3/minimum_expand.hpp"
#include "convex3/shapes3.hpp"
#include "front/common.hpp"

namespace {

using namespace pendepth;
using front_test::same;
using front_test::same_bits_v;

// Every field, facet_normal included; not `candidates` (the work).
::testing::AssertionResult identical(const Depth3& a, const Depth3& b) {
  auto r = same(a, b);
  if (!r) return r;
  if (!same_bits_v(a.facet_normal, b.facet_normal)) return ::testing::AssertionFailure() << "facet_normal differs";
  return ::testing::AssertionSuccess();
}

std::vector<Vec3> box(double x, double y, double z) {
  std::vector<Vec3> v;
  for (int k = 0; k < 8; ++k) v.emplace_back(k & 1 ? x : -x, k & 2 ? y : -y, k & 4 ? z : -z);
  return v;
}

std::vector<Shape3> shapes() {
  std::mt19937_64 rng(5);
  std::vector<Shape3> s;
  s.push_back(Shape3::hull(test3::random_sphere(rng, 40, 1.0), "sphere40"));
  s.push_back(Shape3::hull(test3::integer_sphere(25), "isphere25"));
  s.push_back(Shape3::hull(test3::prism(25, 2), "prism25"));
  s.push_back(Shape3::hull(box(1, 0.5, 0.75), "box"));
  const auto files = test3::shared_hull_files();
  for (std::size_t k = 0; k < files.size(); k += 12) s.push_back(Shape3::from_file(files[k], files[k]));
  return s;
}

Eigen::Quaterniond small_turn(std::mt19937_64& rng, double angle) {
  std::normal_distribution<double> g;
  Vec3 axis(g(rng), g(rng), g(rng));
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

// A random walk of Q around P: steps of `step` (translation) and `turn` radians, kept near P.
std::vector<Pose3> walk(std::mt19937_64& rng, std::size_t n, double step, double turn, double radius) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Pose3> poses;
  Pose3 p(Vec3(u(rng), u(rng), u(rng)) * 0.5 * radius);
  for (std::size_t k = 0; k < n; ++k) {
    p.translation += step * Vec3(u(rng), u(rng), u(rng));
    if (p.translation.norm() > radius) p.translation *= 0.5;
    p.rotation = (small_turn(rng, turn * u(rng)) * p.rotation).normalized();
    poses.push_back(p);
  }
  return poses;
}

// Warm along the poses vs a cold call per pose; returns (warm, cold) support queries.
std::pair<std::size_t, std::size_t> compare(const Pair3& pair, const Pose3& pp, const std::vector<Pose3>& poses,
                                            const std::string& what) {
  WarmStart3 warm;
  std::size_t sw = 0, sc = 0;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Depth3 a = pair.minimum(pp, poses[i], warm), b = pair.minimum(pp, poses[i]);
    EXPECT_TRUE(identical(a, b)) << what << " pose " << i;
    EXPECT_EQ(warm.valid(), b.overlapping);
    sw += a.candidates, sc += b.candidates;
  }
  return {sw, sc};
}

TEST(WarmStart3, SmallStepsEqualColdAndSaveSupports) {
  const auto S = shapes();
  std::mt19937_64 rng(31);
  std::size_t sw = 0, sc = 0;
  for (std::size_t a = 0; a < S.size(); ++a)
    for (std::size_t b = a; b < S.size(); b += 2) {
      const Pair3 pair(S[a], S[b]);
      const Pose3 pp(small_turn(rng, 0.7), Vec3(0.1, -0.2, 0.05));
      auto [w, c] = compare(pair, pp, walk(rng, 60, 0.01, 0.02, 1.0), S[a].name() + " / " + S[b].name());
      sw += w, sc += c;
    }
  // The warm start is used: at most 3/4 of the cold starts' support queries (measured: 0.65).
  EXPECT_LT(sw * 4, sc * 3) << "warm " << sw << " cold " << sc;
  std::printf("[ stats    ] small steps: %zu support queries warm, %zu cold\n", sw, sc);
}

TEST(WarmStart3, LargeJumpsAndSeparatedPosesEqualCold) {
  const auto S = shapes();
  std::mt19937_64 rng(32);
  for (std::size_t a = 0; a < S.size(); ++a) {
    const Pair3 pair(S[a], S[(a + 3) % S.size()]);
    compare(pair, Pose3(), walk(rng, 80, 1.5, 3.0, 2.5), S[a].name());
  }
}

TEST(WarmStart3, ExactTiesEqualCold) {
  // Boxes face to face, identical cubes in place (six facets of M at distance σ), symmetric
  // shapes at quarter turns: exact ties between facets of M and polygonal facets that K
  // triangulates differently from every start.
  const Shape3 cube = Shape3::hull(test3::grid(2), "cube"), B = Shape3::hull(box(1, 1, 0.5), "slab");
  const Shape3 ball = Shape3::hull(test3::integer_sphere(25), "isphere"), prism = Shape3::hull(test3::prism(8, 2), "prism8");
  const Eigen::Quaterniond quarter(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()));
  std::vector<Pose3> poses;
  for (double x : {0.0, 0.25, 0.5, -0.5, 0.75})
    for (double y : {0.0, 0.5, -0.25})
      for (double z : {0.0, 0.5, 0.125}) {
        poses.emplace_back(Vec3(x, y, z));
        poses.emplace_back(quarter, Vec3(z, x, y));
      }
  const std::vector<std::pair<Shape3, Shape3>> pairs{{cube, cube}, {B, B}, {cube, B}, {ball, ball}, {prism, prism}, {ball, cube}};
  for (const auto& [P, Q] : pairs) {
    const Pair3 pair(P, Q);
    compare(pair, Pose3(), poses, P.name() + " / " + Q.name());
    // Every pose warm-started from every other one: each start gives the cold answer.
    for (std::size_t i = 0; i < poses.size(); i += 5)
      for (std::size_t j = 0; j < poses.size(); j += 3) {
        WarmStart3 w;
        pair.minimum(Pose3(), poses[j], w);
        EXPECT_TRUE(identical(pair.minimum(Pose3(), poses[i], w), pair.minimum(Pose3(), poses[i])))
            << P.name() << " / " << Q.name() << " pose " << i << " from " << j;
      }
  }
  // The identical cubes in place: σ = 1, the least features (P's face with the least triangle
  // id and Q's least vertex on the opposite face).
  const Depth3 d = Pair3(cube, cube).minimum(Pose3(), Pose3());
  EXPECT_EQ(d.depth, 1.0);
  EXPECT_EQ(d.feature_p.kind, FeatureKind3::Face);
  EXPECT_EQ(d.feature_q.kind, FeatureKind3::Vertex);
}

TEST(WarmStart3, AnySeedGivesTheCanonicalAnswer) {
  // At the engine: seeds of arbitrary (valid or out-of-range) pairs build any first K.
  const auto S = shapes();
  std::mt19937_64 rng(33);
  for (std::size_t a = 0; a < S.size(); ++a) {
    const ConvexPolytope &P = S[a].polytope(), &Q = S[(a + 1) % S.size()].polytope();
    std::uniform_int_distribution<int> ip(-1, static_cast<int>(P.size())), iq(-1, static_cast<int>(Q.size()));
    for (const Pose3& pq : walk(rng, 30, 0.5, 1.0, 1.0)) {
      const Depth3 cold = minimum_depth(P, Pose3(), Q, pq);
      for (int k = 0; k < 6; ++k) {
        convex3::ExpandSeed seed;
        seed.valid = true;
        seed.count = 3 + k;
        for (int& x : seed.pairs) x = (&x - seed.pairs.data()) % 2 == 0 ? ip(rng) : iq(rng);
        const Depth3 warm = convex3::minimum_depth_seeded(P, Pose3(), Q, pq, &seed);
        EXPECT_TRUE(identical(warm, cold)) << S[a].name();
        EXPECT_EQ(seed.valid, cold.overlapping);
      }
    }
  }
}

TEST(WarmStart3, ScaledPairsEqualCold) {
  // Pairs the numeric domain answers on scaled copies (src/front/scale.hpp).
  std::mt19937_64 rng(34);
  for (int e : {300, -300, 100}) {
    auto scaled = [&](std::vector<Vec3> v) {
      for (auto& x : v) x *= std::ldexp(1.0, e);
      return v;
    };
    const Shape3 P = Shape3::hull(scaled(test3::random_sphere(rng, 30, 1.0)), "P");
    const Shape3 Q = Shape3::hull(scaled(box(1, 0.5, 0.75)), "Q");
    const Pair3 pair(P, Q);
    auto poses = walk(rng, 40, 0.02, 0.05, 1.0);
    for (auto& p : poses) p.translation *= std::ldexp(1.0, e);
    compare(pair, Pose3(), poses, "scale 2^" + std::to_string(e));
  }
}

TEST(WarmStart3, RenumberedShapesGiveTheSameAnswer) {
  // The canonical answer depends on the geometry, not on the vertex numbering: the hull of the
  // same points in another order answers the same bits (feature indices aside), ties included.
  std::mt19937_64 rng(36);
  const std::vector<std::vector<Vec3>> clouds{test3::random_sphere(rng, 30, 1.0), box(1, 0.5, 0.75), test3::grid(2),
                                              test3::prism(25, 2)};
  for (const auto& cloud : clouds) {
    auto shuffled = cloud;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    const Pair3 a(Shape3::hull(cloud), Shape3::hull(box(0.5, 0.5, 0.5))), b(Shape3::hull(shuffled), Shape3::hull(box(0.5, 0.5, 0.5)));
    auto poses = walk(rng, 40, 0.3, 0.5, 1.0);
    for (double x : {0.0, 0.25, 0.5}) poses.emplace_back(Vec3(x, 0, 0));
    for (const Pose3& pq : poses) {
      const Depth3 x = a.minimum(Pose3(), pq), y = b.minimum(Pose3(), pq);
      EXPECT_TRUE(front_test::same_bits(x.depth, y.depth) && same_bits_v(x.translation, y.translation) &&
                  same_bits_v(x.normal, y.normal) && same_bits_v(x.witness_p, y.witness_p) &&
                  same_bits_v(x.witness_q, y.witness_q) && x.feature_p.kind == y.feature_p.kind &&
                  x.feature_q.kind == y.feature_q.kind)
          << x.depth << " vs " << y.depth;
    }
  }
}

TEST(WarmStart3, TrajectoryEqualsSingleCalls) {
  const auto S = shapes();
  std::mt19937_64 rng(35);
  const Pair3 pair(S[0], S[4]);
  const Pose3 pp(small_turn(rng, 1.0), Vec3(0.5, 0, 0));
  const auto poses = walk(rng, 50, 0.02, 0.05, 1.0);
  const auto warm = pair.trajectory(pp, poses), cold = pair.trajectory(pp, poses, false);
  ASSERT_EQ(warm.size(), poses.size());
  ASSERT_EQ(cold.size(), poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_TRUE(identical(warm[i], cold[i])) << i;
    EXPECT_TRUE(identical(cold[i], pair.minimum(pp, poses[i]))) << i;
  }
  // A state from another pair is ignored; a bad pose is named with its index.
  WarmStart3 w;
  Pair3(S[1], S[2]).minimum(Pose3(), poses[0], w);
  EXPECT_TRUE(identical(pair.minimum(pp, poses[1], w), pair.minimum(pp, poses[1])));
  auto bad = poses;
  bad[7].translation.x() = std::nan("");
  const std::string msg = front_test::error_of([&] { pair.trajectory(pp, bad); });
  EXPECT_NE(msg.find("7"), std::string::npos) << msg;
  EXPECT_TRUE(pair.trajectory(pp, {}).empty());
}

}  // namespace
