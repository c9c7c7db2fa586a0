// The free-space minimum of the PD_g branch and bound (src/motion/free_space2.hpp), against a
// dense sampling: random convex parts, random weighted farthest-point costs (pinned seeds).
// Oracle: a 240 × 240 grid over the region, each point's membership in U decided by the exact
// inside() and its cost evaluated directly. Properties: when the certification of
// generalized_depth2.cpp applies (the cost's sampled minimiser lies in U and costs less than the
// bound), no free sample costs less than the bound; the bound is tight — within the sampling's
// resolution of the best free sample — and the best point found lies on ∂C (free points next to it).
#include "motion/free_space2.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace pendepth;

TEST(FreeSpace, BoundBelowEveryFreeSampleAndTight) {
  std::mt19937_64 rng(2718);
  std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
  int certified = 0;
  for (int trial = 0; trial < 24; ++trial) {
    auto part = [&](double r, const Vec2& c) {
      std::vector<Vec2> pts;
      for (int i = 0; i < 7; ++i) pts.push_back(c + r * Vec2(u(rng), u(rng)));
      return ConvexPolygon::hull(pts);
    };
    std::vector<ConvexPolygon> A;
    for (int i = 0; i < 3; ++i) A.push_back(part(0.8, Vec2(0.8 * u(rng), 0.8 * u(rng))));
    std::vector<std::vector<Vec2>> E;
    for (int j = 0; j < 2; ++j) {
      const ConvexPolygon e = part(0.5, Vec2(0.3 * u(rng), 0.3 * u(rng)));
      E.emplace_back(e.vertices().begin(), e.vertices().end());
    }
    const motion::FreeSpace fs(A, E);
    motion::FarthestCost f;
    for (int k = 0; k < 4; ++k) f.z.push_back(Vec2(0.4 * u(rng), 0.4 * u(rng))), f.r.push_back(0.1 * w(rng));
    auto cost = [&](const Vec2& x) {
      double v = -1e300;
      for (std::size_t k = 0; k < f.z.size(); ++k) v = std::max(v, (x - f.z[k]).norm() - f.r[k]);
      return v;
    };
    const motion::FreeMinimum fm = fs.minimum(f, std::numeric_limits<double>::infinity());
    ASSERT_TRUE(fm.found);
    EXPECT_LE(fm.lower, fm.value);
    EXPECT_NEAR(fm.lower, fm.value, 1e-9);
    constexpr int n = 240;
    constexpr double lo = -3, hi = 3, step = (hi - lo) / (n - 1);
    double best_free = 1e300, best_all = 1e300;
    Vec2 arg_all(0, 0);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const Vec2 x(lo + i * step, lo + j * step);
        const double c = cost(x);
        if (c < best_all) best_all = c, arg_all = x;
        if (!fs.inside(x)) best_free = std::min(best_free, c);
      }
    ASSERT_LT(best_free, 1e300);
    // Tight: the bound is the minimum over Γ ⊇ ∂C; the sampled free minimum is at most one grid
    // diagonal above the true one, and the true one is ≥ the bound when certified.
    if (cost(arg_all) < fm.lower && fs.inside(arg_all)) {
      ++certified;
      EXPECT_LE(fm.lower, best_free) << "trial " << trial;
      EXPECT_GE(fm.lower, best_free - step * std::sqrt(2.0) - 1e-12) << "trial " << trial;
    }
    // The best point lies on ∂C: free points exist arbitrarily close to it (64 directions at 1e-9;
    // C's corners are wedges of positive angle for random parts).
    bool free_near = false;
    for (int d = 0; d < 64 && !free_near; ++d) {
      const double a = 2 * M_PI * d / 64;
      free_near = !fs.inside(fm.argmin + 1e-9 * Vec2(std::cos(a), std::sin(a)));
    }
    EXPECT_TRUE(free_near) << "trial " << trial;
  }
  EXPECT_GE(certified, 12);
}

}  // namespace
