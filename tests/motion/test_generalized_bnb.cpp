// PD_g in 2D, the branch and bound over angle intervals (src/motion/generalized_depth2.cpp,
// free_space2.cpp): certified bounds against an independent oracle of the exact best motion at a
// fixed angle.
//
// Oracle, per angle θ of a fine grid: Q.rotated(θ) (the coordinates users get), the exact no-fit
// polygon of P and it (NoFitPolygon2: rings, slits, isolated points of ∂O — a different
// construction from the branch and bound's union of eroded part sums), and the minimum of the
// farthest-point cost max_k |T + R_θ q_k − q_k − t| (q_k Q's hull vertices) over the free placements
// T: the smallest enclosing circle's centre of the no-move points when it is free, else the
// smallest value on ∂O (ternary search per boundary segment, every isolated point). Its minimum
// over the grid is (to rounding) the cost of a real motion, so lower ≤ it; when converged the
// upper bound is within the tolerance of it. Inputs: L-shapes, combs, a bar in a slot of its own
// width (exact fit at a quarter turn: PD_g known in closed form), a frame with a hole, random
// stars, nesting pieces. Pinned seeds.
#include <pendepth/nfp2.hpp>
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <numbers>
#include <random>

#include "motion_shapes.hpp"

namespace {

using namespace pendepth;
using namespace pendepth::motion_test;

// Smallest enclosing circle by brute force over pairs and triples (small point sets).
std::pair<Vec2, double> min_circle(const std::vector<Vec2>& z) {
  Vec2 best_c = z[0];
  double best_r = std::numeric_limits<double>::infinity();
  auto consider = [&](const Vec2& c) {
    double r = 0;
    for (const Vec2& p : z) r = std::max(r, (p - c).norm());
    if (r < best_r) best_r = r, best_c = c;
  };
  for (std::size_t i = 0; i < z.size(); ++i)
    for (std::size_t j = i + 1; j < z.size(); ++j) {
      consider(0.5 * (z[i] + z[j]));
      for (std::size_t k = j + 1; k < z.size(); ++k) {
        const Vec2 ab = z[j] - z[i], ac = z[k] - z[i];
        const double d = 2 * (ab.x() * ac.y() - ab.y() * ac.x());
        if (d == 0) continue;
        consider(z[i] + Vec2(ac.y() * ab.squaredNorm() - ab.y() * ac.squaredNorm(),
                             ab.x() * ac.squaredNorm() - ac.x() * ab.squaredNorm()) / d);
      }
    }
  if (z.size() == 1) best_r = 0;
  return {best_c, best_r};
}

// The exact best motion's cost at `deg` (see the file comment); +inf if the rotated copy is invalid.
double best_at_angle(const Shape2& P, const Shape2& Q, const Vec2& t, double deg) {
  std::optional<Shape2> Qr;
  try {
    Qr.emplace(Q.rotated(deg));
  } catch (const InvalidInput&) {
    return std::numeric_limits<double>::infinity();
  }
  const ConvexPolygon h = ConvexPolygon::hull(Q.rings().front());
  std::vector<Vec2> z;
  for (const Vec2& q : h.vertices()) z.push_back(t + q - turned(q, deg));
  auto f = [&](const Vec2& T) {
    double v = 0;
    for (const Vec2& p : z) v = std::max(v, (T - p).norm());
    return v;
  };
  const NoFitPolygon2 nfp(P.polygon(), Qr->polygon());
  const auto [centre, radius] = min_circle(z);
  if (!nfp.overlapping(centre)) return radius;
  double best = std::numeric_limits<double>::infinity();
  auto segment = [&](const Vec2& a, const Vec2& b) {
    double lo = 0, hi = 1;
    for (int it = 0; it < 100; ++it) {
      const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      if (f(a + m1 * (b - a)) <= f(a + m2 * (b - a))) hi = m2;
      else lo = m1;
    }
    best = std::min({best, f(a), f(b), f(a + 0.5 * (lo + hi) * (b - a))});
  };
  for (const auto& poly : nfp.polygons())
    for (const auto& ring : poly)
      for (std::size_t i = 0; i < ring.size(); ++i) segment(ring[i], ring[i + 1 == ring.size() ? 0 : i + 1]);
  for (const auto& s : nfp.slits()) segment(s[0], s[1]);
  for (const Vec2& p : nfp.points()) best = std::min(best, f(p));
  return best;
}

struct Grid {
  double best = std::numeric_limits<double>::infinity(), angle = 0;
};
Grid grid_best(const Shape2& P, const Shape2& Q, const Vec2& t, int n) {
  Grid g;
  for (int i = 0; i < n; ++i) {
    const double deg = -180 + 360.0 * i / n;
    const double v = best_at_angle(P, Q, t, deg);
    if (v < g.best) g.best = v, g.angle = deg;
  }
  return g;
}

// The contract: lower ≤ the oracle's minimum over the grid (a real motion's cost, up to the
// rounding of the no-fit polygon's vertices), upper verified, converged ⇒ upper within the
// tolerance of the grid minimum, PD_g ≤ σ.
void check(const Shape2& P, const Shape2& Q, const Vec2& t, const GeneralizedDepth2& r, int n) {
  ASSERT_TRUE(r.overlapping);
  EXPECT_LE(r.lower_bound, r.upper_bound);
  EXPECT_LE(r.upper_bound, r.sigma * (1 + 1e-12));
  if (P.is_convex() && Q.is_convex()) {  // the theorem: σ, with σ's own (touching) translation
    EXPECT_EQ(r.lower_bound, r.sigma);
    EXPECT_EQ(r.upper_bound, r.sigma);
  } else {
    EXPECT_FALSE(Pair2(P, Q.rotated(r.angle)).overlapping(t + r.translation));
  }
  const Grid g = grid_best(P, Q, t, n);
  EXPECT_LE(r.lower_bound, g.best * (1 + 1e-9)) << "grid minimum at " << g.angle;
  // The exact best motion at the reported angle is no worse than the reported one.
  EXPECT_LE(best_at_angle(P, Q, t, r.angle), r.upper_bound * (1 + 1e-9));
  if (r.converged) {
    EXPECT_LE(r.upper_bound - r.lower_bound, 1e-6 * r.upper_bound);
    EXPECT_LE(r.upper_bound, g.best * (1 + 1e-6 + 1e-9));
  }
}

TEST(GeneralizedBnb, BarInSlotOfItsWidthFitsAtAQuarterTurn) {
  // A block with a slot 0.5 wide ([−0.25, 0.25] × [−4, 4], open at the top) and a bar 0.5 × 2
  // lying across it at depth 2: it overlaps both walls; pulling it out costs ≥ 3.25. Turned by ±90°
  // about its centre it fits the slot exactly (a slit of touching placements, exact coordinates):
  // the corners (±1, ±0.25) travel |R₉₀q − q| = √(1.25² + 0.75²) = √2.125 — and no other
  // placement of a vertical bar in the slot is cheaper, nor any other angle (the bar fits no
  // tilted slot). An isolated exact fit at a non-zero angle.
  const Shape2 P({Vec2(-3, -5), Vec2(3, -5), Vec2(3, 4), Vec2(0.25, 4), Vec2(0.25, -4), Vec2(-0.25, -4),
                  Vec2(-0.25, 4), Vec2(-3, 4)},
                 {}, "slot");
  const Shape2 Q({Vec2(-1, -0.25), Vec2(1, -0.25), Vec2(1, 0.25), Vec2(-1, 0.25)}, {}, "bar");
  const Vec2 t(0, -2);
  const GeneralizedDepth2 r = generalized_depth(P, Q, t);
  const double exact = std::sqrt(2.125);
  EXPECT_TRUE(r.converged) << r.lower_bound << " " << r.upper_bound;
  EXPECT_LE(r.lower_bound, exact);
  EXPECT_GE(r.upper_bound, exact);
  EXPECT_LE(r.upper_bound, exact * (1 + 1e-12));
  EXPECT_EQ(std::abs(r.angle), 90);
  EXPECT_TRUE(r.rotation_exact);
  EXPECT_GT(r.sigma, 3);  // out through the bottom: 3.25
  check(P, Q, t, r, 360);
}

TEST(GeneralizedBnb, LShapesAndCombsConverge) {
  std::mt19937_64 rng(1818);
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  int n = 0, converged = 0;
  for (int k = 0; k < 10; ++k) {
    const Shape2 P = k % 2 ? l_shape(1.0, Vec2(-1, -1), "L") : comb(4, 0.3, 1.0, Vec2(-1, 0), "comb");
    const Shape2 Q = k % 3 == 0 ? l_shape(0.6, Vec2(-0.4, -0.3), "l")
                     : k % 3 == 1 ? comb(3, 0.2, 0.7, Vec2(-0.5, 0.2), "c")
                                  : l_shape(0.4, Vec2(-0.2, -0.6), "l2");
    const Vec2 t(u(rng), u(rng));
    if (!Pair2(P, Q).overlapping(t)) continue;
    ++n;
    const GeneralizedDepth2 r = generalized_depth(P, Q, t);
    SCOPED_TRACE("case " + std::to_string(k));
    check(P, Q, t, r, 360);
    converged += r.converged;
    EXPECT_TRUE(r.converged) << r.lower_bound << " " << r.upper_bound << " after " << r.intervals << " intervals";
  }
  EXPECT_GE(n, 6);
  RecordProperty("converged", converged);
}

TEST(GeneralizedBnb, HolesConverge) {
  // P a frame (its convex parts are the triangles of a polygon with a hole), Q an L across the
  // hole's rim at random placements.
  const Shape2 P({Vec2(-1.5, -1.5), Vec2(1.5, -1.5), Vec2(1.5, 1.5), Vec2(-1.5, 1.5)},
                 {{Vec2(-0.6, -0.5), Vec2(-0.6, 0.5), Vec2(0.6, 0.5), Vec2(0.6, -0.5)}}, "frame");
  const Shape2 Q = l_shape(0.25, Vec2(-0.3, -0.3), "l");
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-0.9, 0.9);
  int n = 0;
  for (int k = 0; k < 6; ++k) {
    const Vec2 t(u(rng), u(rng));
    if (!Pair2(P, Q).overlapping(t)) continue;
    ++n;
    const GeneralizedDepth2 r = generalized_depth(P, Q, t);
    SCOPED_TRACE("placement " + std::to_string(k));
    check(P, Q, t, r, 180);
    EXPECT_TRUE(r.converged) << r.lower_bound << " " << r.upper_bound << " after " << r.intervals;
  }
  EXPECT_GE(n, 4);
}

TEST(GeneralizedBnb, RotationHelpsAndTheBoundsMeet) {
  // A bar 0.5 × 6 turned by a few degrees in a slot 0.52 wide: it pokes into both walls, σ pulls
  // it through a wall or out of the slot, turning back is much cheaper; the bounds must meet.
  const Shape2 P({Vec2(-3, -5), Vec2(3, -5), Vec2(3, 4), Vec2(0.26, 4), Vec2(0.26, -4), Vec2(-0.26, -4),
                  Vec2(-0.26, 4), Vec2(-3, 4)},
                 {}, "slot");
  for (double deg : {3.0, -2.0}) {
    std::vector<Vec2> rr;
    for (const Vec2& p : {Vec2(-0.25, -3), Vec2(0.25, -3), Vec2(0.25, 3), Vec2(-0.25, 3)}) rr.push_back(turned(p, deg));
    const Shape2 Q(rr, {}, "bar");
    const Vec2 t(0.0, 0.0);
    ASSERT_TRUE(Pair2(P, Q).overlapping(t));
    const GeneralizedDepth2 r = generalized_depth(P, Q, t);
    SCOPED_TRACE("turned " + std::to_string(deg));
    check(P, Q, t, r, 720);
    EXPECT_TRUE(r.converged) << r.lower_bound << " " << r.upper_bound;
    EXPECT_LT(r.depth, 0.25 * r.sigma);
    EXPECT_LT(r.angle * deg, 0);  // turned back
  }
}

Shape2 star(std::mt19937_64& rng, int n, double radius, std::string_view name) {
  std::uniform_real_distribution<double> rr(0.35, 1.0);
  std::vector<Vec2> r;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * (i + 0.3 * rr(rng)) / n, l = radius * rr(rng);
    r.emplace_back(l * std::cos(a), l * std::sin(a));
  }
  return Shape2(r, {}, name);
}

TEST(GeneralizedBnb, RandomStarsBracketTheOracle) {
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  int n = 0, converged = 0;
  for (int k = 0; k < 12; ++k) {
    const Shape2 P = star(rng, 6 + k % 4, 1.0, "P"), Q = star(rng, 5 + k % 5, 0.7, "Q");
    const Vec2 t(u(rng), u(rng));
    if (!Pair2(P, Q).overlapping(t)) continue;
    ++n;
    const GeneralizedDepth2 r = generalized_depth(P, Q, t);
    SCOPED_TRACE("star pair " + std::to_string(k));
    check(P, Q, t, r, 360);
    converged += r.converged;
  }
  EXPECT_GE(n, 5);
  EXPECT_EQ(converged, n);
}

TEST(GeneralizedBnb, NestingPiecesConverge) {
  // Deep overlaps (Q's box centre near P's) and shallow ones (Q's box corner near P's): every pair
  // of the first three pieces of each instance.
  std::mt19937_64 rng(77);
  int n = 0;
  for (const char* file : {"albano.json", "trousers.json", "shirts.json"}) {
    const auto pieces = nesting(file);
    ASSERT_GE(pieces.size(), 4u) << file;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        const Shape2 &P = pieces[i], &Q = pieces[j];
        if (P.is_convex() && Q.is_convex()) continue;
        Vec2 plo(1e300, 1e300), phi(-1e300, -1e300), qlo = plo, qhi = phi;
        const auto pr = P.rings(), qr = Q.rings();
        for (const Vec2& p : pr[0]) plo = plo.cwiseMin(p), phi = phi.cwiseMax(p);
        for (const Vec2& q : qr[0]) qlo = qlo.cwiseMin(q), qhi = qhi.cwiseMax(q);
        std::uniform_real_distribution<double> u(-0.2, 0.2);
        const Vec2 deep = 0.5 * (plo + phi - qlo - qhi) + Vec2(u(rng) * (phi - plo).x(), u(rng) * (phi - plo).y());
        const Vec2 shallow = phi - qlo - 0.15 * (phi - plo).cwiseMin(qhi - qlo);
        for (const Vec2& t : {deep, shallow}) {
          if (!Pair2(P, Q).overlapping(t)) continue;
          ++n;
          const GeneralizedDepth2 r = generalized_depth(P, Q, t);
          SCOPED_TRACE(std::string(file) + " pieces " + std::to_string(i) + ", " + std::to_string(j));
          EXPECT_TRUE(r.converged) << r.lower_bound << " " << r.upper_bound << " after " << r.intervals;
          check(P, Q, t, r, 36);
        }
      }
  }
  EXPECT_GE(n, 12);
}

TEST(GeneralizedBnb, BudgetReportsTheGapHonestly) {
  // With a budget of one interval the search stops early: the bounds still bracket, converged says
  // whether they meet.
  const Shape2 P = comb(4, 0.3, 1.0, Vec2(-1, 0), "comb"), Q = l_shape(0.6, Vec2(-0.4, -0.3), "l");
  const Vec2 t(0.1, 0.3);
  ASSERT_TRUE(Pair2(P, Q).overlapping(t));
  GeneralizedOptions2 o;
  o.max_intervals = 1;
  const GeneralizedDepth2 small = generalized_depth(P, Q, t, o);
  const GeneralizedDepth2 full = generalized_depth(P, Q, t);
  EXPECT_LE(small.lower_bound, full.upper_bound);
  EXPECT_LE(full.lower_bound, small.upper_bound);
  EXPECT_LE(small.intervals, 64u);  // the initial intervals, then the budget stops the search
  EXPECT_EQ(small.converged, small.upper_bound - small.lower_bound <= 1e-6 * small.upper_bound);
  EXPECT_TRUE(full.converged);
}

}  // namespace
