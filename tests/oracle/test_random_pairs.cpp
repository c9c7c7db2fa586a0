// Thousands of random convex pairs, n and m from 3 to 10^4, against the exact oracle: σ_d by
// directional_depth / separation_depth / DepthQuery2, σ by minimum_depth (merge) / DepthField /
// DepthQuery2, at random placements, exact points of ∂M, points one ulp inside ∂M, and rays through
// vertices of M; directions random, parallel to edges of P, Q and M, axis-aligned, at scales 1,
// ~1e-8 and ~1e8. The oracle's own constructions of M are cross-checked on the way.
#include <pendepth/depth2.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "oracle/checks.hpp"
#include "oracle/exact_oracle.hpp"
#include "oracle/shapes.hpp"

namespace oracle_tests {
namespace {

#ifdef NDEBUG
constexpr int kSpeed = 1;  // Release: full counts
#else
constexpr int kSpeed = 8;  // Debug / sanitizers: an eighth of the pairs (same generators and seeds)
#endif

struct SizeClass {
  const char* name;
  std::uint64_t seed;
  int pairs;         // Release count
  int lo, hi;        // n and m drawn log-uniformly from [lo, hi]
  int random_t, boundary_t, directions;
};

int log_uniform(Rng& rng, int lo, int hi) {
  return std::clamp(int(std::lround(std::exp(uniform(rng, std::log(lo), std::log(hi))))), lo, hi);
}

void run(const SizeClass& sc) {
  const auto start = std::chrono::steady_clock::now();
  Rng rng(sc.seed);
  Stats stats;
  const int pairs = std::max(2, sc.pairs / kSpeed);
  long oracle_cross_checks = 0;
  std::size_t largest_n = 0, largest_m = 0;  // hull sizes of the pair with the largest n·m
  for (int trial = 0; trial < pairs && stats.failures < kMaxFailures; ++trial) {
    const int n = log_uniform(rng, sc.lo, sc.hi), m = log_uniform(rng, sc.lo, sc.hi);
    // Q at a comparable or a very different scale; both near the origin so M covers it often.
    const double qscale = uniform_int(rng, 0, 3) == 0 ? uniform(rng, 0.01, 0.2) : 1.0;
    Shape P = shape(rng, random_kind(rng, n), n);
    Shape Q = shape(rng, random_kind(rng, m), m, qscale);
    const oracle::ExactDifference M(P.pts, Q.pts);
    if (P.poly->size() * Q.poly->size() > largest_n * largest_m) {
      largest_n = P.poly->size();
      largest_m = Q.poly->size();
    }
    const std::string context = sc.name + std::string(" trial ") + std::to_string(trial) + " P:" + P.label +
                                " Q:" + Q.label;

    // The oracle's constructions agree with each other, and pendepth's explicit M rounds the
    // exact vertices correctly (each vertex is one rounded subtraction of input doubles).
    if (P.poly->size() * Q.poly->size() <= 4096) {
      const oracle::ExactDifference merged(P.pts, Q.pts, oracle::Construction::Merge);
      ASSERT_TRUE(M.same_polygon(merged)) << context;
      if (trial % 16 == 0) {
        const oracle::ExactDifference cgal(P.pts, Q.pts, oracle::Construction::CgalMinkowskiSum);
        ASSERT_TRUE(M.same_polygon(cgal)) << context;
      }
      ++oracle_cross_checks;
    } else if (trial % 25 == 0) {  // large n·m: the merge against CGAL's Minkowski sum
      const oracle::ExactDifference cgal(P.pts, Q.pts, oracle::Construction::CgalMinkowskiSum);
      ASSERT_TRUE(M.same_polygon(cgal)) << context;
      ++oracle_cross_checks;
    }
    const std::vector<Vec2> md = pendepth::minkowski_difference(*P.poly, *Q.poly);
    ASSERT_EQ(md.size(), M.size()) << context;
    for (std::size_t k = 0; k < md.size(); ++k) ASSERT_EQ(md[k], M.vertex(k)) << context << " vertex " << k;

    PairChecker check(*P.poly, *Q.poly, M, stats, context);
    for (const Vec2& t : placements(rng, M, sc.random_t, sc.boundary_t)) {
      if (!check.minimum(t)) break;
      for (int k = 0; k < sc.directions; ++k)
        if (!check.directional(t, direction(rng, *P.poly, *Q.poly, M))) break;
    }
    // Rays through a vertex of M: t halfway along a chord, d along the chord.
    for (int k = 0; k < 2; ++k) {
      const std::size_t i = std::uniform_int_distribution<std::size_t>(0, M.size() - 1)(rng);
      const std::size_t j = (i + M.size() / 2) % M.size();
      const Vec2 a = M.vertex(i), b = M.vertex(j), t = (a + b) / 2;
      check.minimum(t);
      check.directional(t, b - a);
      check.directional(t, a - b);
    }
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.print(sc.name);
  std::printf("[%s] %d pairs (largest %zu x %zu vertices), %ld oracle cross-checks of M, %.1f s\n", sc.name, pairs,
              largest_n, largest_m, oracle_cross_checks, secs);
  EXPECT_EQ(stats.failures, 0);
  EXPECT_LE(stats.worst_directional, kDepthTol);
  EXPECT_LE(stats.worst_minimum, kDepthTol);
}

TEST(OracleRandomPairs, Small) { run({"small", 0x5eed0001, 2400, 3, 40, 6, 3, 3}); }
TEST(OracleRandomPairs, Medium) { run({"medium", 0x5eed0002, 250, 40, 1000, 4, 2, 3}); }
TEST(OracleRandomPairs, Large) { run({"large", 0x5eed0003, 16, 1000, 10000, 3, 1, 2}); }

}  // namespace
}  // namespace oracle_tests
