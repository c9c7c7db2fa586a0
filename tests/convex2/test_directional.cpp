// σ_d (O(log n + log m) prune-and-search) against the exact brute force over the explicit M.
#include <pendepth/depth2.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <random>

#include "convex2/brute_force.hpp"
#include "convex2/random_shapes.hpp"
#include "test_scale.hpp"

using pendepth::ConvexPolygon;
using pendepth::Vec2;

namespace {

// σ_d to within a few ulps of |d|·s_exact (s_exact rational).
void expect_directional(const ConvexPolygon& P, const ConvexPolygon& Q, const std::vector<brute::QPt>& M,
                        const Vec2& t, const Vec2& d, double& worst_ulps) {
  pendepth::Depth2 r = pendepth::directional_depth(P, Q, t, d);
  mpq_class s = brute::exit_param(M, t, d);
  ASSERT_TRUE(std::isfinite(r.depth));
  if (sgn(s) == 0) {
    ASSERT_EQ(r.depth, 0.0) << "t=" << t.transpose() << " d=" << d.transpose();
    ASSERT_FALSE(r.overlapping);
    return;
  }
  ASSERT_TRUE(r.overlapping) << "t=" << t.transpose() << " d=" << d.transpose();
  double want = s.get_d() * std::sqrt(d.x() * d.x() + d.y() * d.y());
  double u = brute::ulps(r.depth, want);
  worst_ulps = std::max(worst_ulps, u);
  ASSERT_LE(u, 8) << "got " << r.depth << " want " << want << " t=" << t.transpose() << " d=" << d.transpose();
  // The translation is along d̂ and has the reported length.
  ASSERT_NEAR(r.translation.norm(), r.depth, 1e-15 * r.depth);
  ASSERT_GT(r.translation.dot(d), 0);
  // Moving Q by slightly less keeps the interiors overlapping; slightly more separates them
  // The moved placements t + (1 ± 1e-9)·depth·d/|d| are formed exactly along the exact d, so rays
  // grazing an edge of M that is parallel to d are judged correctly.
  const double f = r.depth / d.norm();
  ASSERT_TRUE(brute::inside(M, brute::moved(t, d, f * (1 - 1e-9))))
      << std::setprecision(17) << "t=" << t.transpose() << " d=" << d.transpose() << " depth " << r.depth;
  ASSERT_FALSE(brute::inside(M, brute::moved(t, d, f * (1 + 1e-9))));
}

}  // namespace

TEST(Directional, AnalyticSquares) {
  ConvexPolygon P({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  ConvexPolygon Q({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  EXPECT_EQ(pendepth::directional_depth(P, Q, {0.5, 0.5}, {1, 0}).depth, 1.5);
  EXPECT_EQ(pendepth::directional_depth(P, Q, {0.5, 0.5}, {-1, 0}).depth, 1.5);
  EXPECT_DOUBLE_EQ(pendepth::directional_depth(P, Q, {0.5, 0.5}, {1, 1}).depth, 1.5 * std::sqrt(2.0));
  // Touching along an edge: depth 0 in every direction.
  for (Vec2 d : {Vec2(1, 0), Vec2(-1, 0), Vec2(0, 1), Vec2(1, -3)})
    EXPECT_EQ(pendepth::directional_depth(P, Q, {2, 0.5}, d).depth, 0.0);
  auto r = pendepth::directional_depth(P, Q, {0.5, 0.25}, {0, -1});
  EXPECT_EQ(r.depth, 1.25);
  EXPECT_EQ(r.translation, Vec2(0, -1.25));
  EXPECT_EQ(r.witness_p.y(), 0.0);  // Q (now at y = -1) touches P from below along y = 0
}

TEST(Directional, DirectionScaleDoesNotMatter) {
  // Subnormal and huge directions: same answer as the unit direction, never NaN or inf.
  ConvexPolygon P({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  ConvexPolygon Q({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const Vec2 t(0.25, 0.5);
  for (Vec2 unit : {Vec2(1, 0), Vec2(1, 1), Vec2(-3, 1)}) {
    const auto ref = pendepth::directional_depth(P, Q, t, unit);
    for (double scale : {5e-324, 1e-310, 1e-300, 1e-8, 1e8, 1e300, 1.7e308}) {
      const Vec2 d = unit * scale;
      if ((d.x() == 0 && d.y() == 0) || !d.allFinite()) continue;
      const bool exact_multiple = d.x() / scale == unit.x() && d.y() / scale == unit.y();
      auto r = pendepth::directional_depth(P, Q, t, d);
      ASSERT_TRUE(std::isfinite(r.depth) && r.translation.allFinite() && r.normal.allFinite()) << scale;
      if (exact_multiple) {
        ASSERT_LE(brute::ulps(r.depth, ref.depth), 4) << scale;  // same direction, other rounding
      } else {
        ASSERT_NEAR(r.depth, ref.depth, 1e-6) << scale;  // d rounded (subnormal), direction perturbed
      }
    }
  }
}

TEST(Directional, InvalidDirection) {
  ConvexPolygon P({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  EXPECT_THROW(pendepth::directional_depth(P, P, {0, 0}, {0, 0}), pendepth::InvalidInput);
  EXPECT_THROW(pendepth::directional_depth(P, P, {0, 0}, {NAN, 1}), pendepth::InvalidInput);
  EXPECT_THROW(pendepth::directional_depth(P, P, {INFINITY, 0}, {1, 1}), pendepth::InvalidInput);
}

TEST(Directional, RandomPairsAgainstExactBruteForce) {
  std::mt19937_64 rng(20261121);
  double worst = 0;
  int checked = 0;
  for (int trial = 0; trial < pendepth_test::scaled(1500); ++trial) {
    auto [P, Q] = shapes::random_pair(rng, trial);
    auto M = brute::minkowski_difference(P, Q);
    for (int k = 0; k < 12; ++k) {
      Vec2 t = shapes::placement(rng, P, Q, M, k);
      Vec2 d = shapes::direction(rng, P, Q, k);
      expect_directional(P, Q, M, t, d, worst);
      ++checked;
      if (HasFatalFailure()) return;
    }
  }
  RecordProperty("worst_ulps", std::to_string(worst));
  std::printf("directional: %d queries, worst %.2f ulps\n", checked, worst);
}

TEST(Directional, SeparationAgainstExactBruteForce) {
  // Equals σ_d whenever the interiors overlap; from outside it is the end of the ray's interval
  // in int M (positive if the ray meets P later), 0 if the ray never meets int M.
  std::mt19937_64 rng(5);
  int outside_positive = 0;
  for (int trial = 0; trial < pendepth_test::scaled(1500); ++trial) {
    auto [P, Q] = shapes::random_pair(rng, trial);
    auto M = brute::minkowski_difference(P, Q);
    for (int k = 0; k < 6; ++k) {
      Vec2 t = shapes::placement(rng, P, Q, M, k), d = shapes::direction(rng, P, Q, k);
      if (k == 5) t -= d / d.norm() * 3.0;  // often before the entry: the ray crosses M later
      auto a = pendepth::directional_depth(P, Q, t, d);
      auto s = pendepth::separation_depth(P, Q, t, d);
      ASSERT_EQ(s.kind, pendepth::DepthKind::Separation);
      ASSERT_EQ(s.overlapping, a.overlapping);
      if (a.overlapping) ASSERT_EQ(s.depth, a.depth);
      mpq_class want = brute::separation_param(M, t, d);
      if (sgn(want) == 0) {
        ASSERT_EQ(s.depth, 0.0) << "t=" << t.transpose() << " d=" << d.transpose();
        continue;
      }
      if (!a.overlapping) ++outside_positive;
      double w = want.get_d() * d.norm();
      ASSERT_LE(brute::ulps(s.depth, w), 8) << s.depth << " vs " << w << " t=" << t.transpose() << " d=" << d.transpose();
    }
  }
  EXPECT_GT(outside_positive, 100);  // the from-outside case really is exercised
}
