// σ by the O(n + m) merge against the exact brute force; σ ≤ σ_d; σ_d along σ's normal = σ.
#include <pendepth/depth2.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "convex2/brute_force.hpp"
#include "convex2/random_shapes.hpp"
#include "test_scale.hpp"

using pendepth::ConvexPolygon;
using pendepth::Vec2;

TEST(Minimum, AnalyticSquares) {
  ConvexPolygon P({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  ConvexPolygon Q({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  auto m = pendepth::minimum_depth(P, Q, {0.25, 0.5});
  EXPECT_EQ(m.depth, 1.25);
  EXPECT_EQ(m.normal, Vec2(-1, 0));
  EXPECT_EQ(m.translation, Vec2(-1.25, 0));
  EXPECT_EQ(m.witness_p.x(), 0.0);
  EXPECT_EQ(m.feature_p.kind, pendepth::FeatureKind::Edge);  // P's left edge, parallel to Q's right edge
  EXPECT_EQ(m.feature_q.kind, pendepth::FeatureKind::Edge);
  EXPECT_EQ(pendepth::minimum_depth(P, Q, {2, 0.5}).depth, 0.0);   // touching along x = 2
  EXPECT_EQ(pendepth::minimum_depth(P, Q, {-1, -1}).depth, 0.0);   // corner contact
  EXPECT_EQ(pendepth::minimum_depth(P, Q, {5, 5}).depth, 0.0);     // apart
  EXPECT_THROW(pendepth::minimum_depth(P, Q, {NAN, 0}), pendepth::InvalidInput);
}

TEST(Minimum, RandomPairsAgainstExactBruteForce) {
  std::mt19937_64 rng(99);
  double worst = 0;
  int checked = 0, overlapping = 0;
  for (int trial = 0; trial < pendepth_test::scaled(1500); ++trial) {
    auto [P, Q] = shapes::random_pair(rng, trial);
    auto M = brute::minkowski_difference(P, Q);
    for (int k = 0; k < 8; ++k) {
      Vec2 t = shapes::placement(rng, P, Q, M, k);
      auto r = pendepth::minimum_depth(P, Q, t);
      mpq_class d2 = brute::min_depth_squared(M, t);
      ++checked;
      if (sgn(d2) == 0) {
        ASSERT_EQ(r.depth, 0.0) << trial << " t=" << t.transpose();
        ASSERT_FALSE(r.overlapping);
        continue;
      }
      ++overlapping;
      double want = std::sqrt(d2.get_d());
      double u = brute::ulps(r.depth, want);
      worst = std::max(worst, u);
      ASSERT_LE(u, 8) << "got " << r.depth << " want " << want << " trial " << trial;
      ASSERT_NEAR(r.translation.norm(), r.depth, 1e-15 * r.depth);
      ASSERT_TRUE(brute::inside(M, brute::moved(t, r.translation, 1 - 1e-9)));
      ASSERT_FALSE(brute::inside(M, brute::moved(t, r.translation, 1 + 1e-9)));
      // σ_d along σ's own direction equals σ; σ ≤ σ_d for random d.
      auto along = pendepth::directional_depth(P, Q, t, r.normal);
      ASSERT_LE(brute::ulps(along.depth, r.depth), 64) << along.depth << " vs " << r.depth;
      for (int j = 0; j < 4; ++j) {
        Vec2 d = shapes::direction(rng, P, Q, j);
        ASSERT_GE(pendepth::directional_depth(P, Q, t, d).depth, r.depth * (1 - 1e-15));
      }
    }
  }
  std::printf("minimum: %d queries (%d overlapping), worst %.2f ulps\n", checked, overlapping, worst);
}

TEST(Minimum, MinOverManyDirectionsApproachesSigma) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < pendepth_test::scaled(60); ++trial) {
    auto [P, Q] = shapes::random_pair(rng, trial);
    auto M = brute::minkowski_difference(P, Q);
    Vec2 t = shapes::placement(rng, P, Q, M, 3);
    auto r = pendepth::minimum_depth(P, Q, t);
    if (!r.overlapping) continue;
    const int K = 720;
    double best = INFINITY;
    for (int k = 0; k < K; ++k) {
      double a = 2 * M_PI * k / K;
      best = std::min(best, pendepth::directional_depth(P, Q, t, {std::cos(a), std::sin(a)}).depth);
    }
    ASSERT_GE(best, r.depth * (1 - 1e-15));
    ASSERT_LE(best, r.depth / std::cos(M_PI / K) * (1 + 1e-12));
  }
}
