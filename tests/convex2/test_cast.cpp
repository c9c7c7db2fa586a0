// The localised convex distance (convex_nearest_vertex + BoundaryPair2::distance_near) against
// the exact squared distance to the explicit M (rationals) and against the full boundary search. The convex shape cast (src/convex2/convex_cast.hpp: the ray's entry into M by prune-and-search
// on the back chains) against the exact rational brute force on the explicit M (the ray clipped
// by every half-plane of M, closed) and against the second algorithm, the first boundary contact
// (src/nonconvex2/boundary_distance): hit or miss, the distance a few ulps from the exact value,
// 0 exactly when t is on ∂M; degenerate families (grids with parallel edges, identical shapes,
// edge-parallel and axis directions, placements on vertices and edges of M).
#include <pendepth/polygon.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>

#include "brute_force.hpp"
#include "convex2/convex_cast.hpp"
#include "nonconvex2/boundary_distance.hpp"
#include "random_shapes.hpp"

namespace {

using namespace pendepth;
using brute::QPt;

// Exact entry parameter (units of d) of the ray t + s·d into the closed M, or nullopt.
std::optional<mpq_class> exact_entry(const std::vector<QPt>& M, const Vec2& tv, const Vec2& dv) {
  const QPt t = brute::lift(tv), d = brute::lift(dv);
  mpq_class lo = 0;
  std::optional<mpq_class> hi;
  for (std::size_t k = 0; k < M.size(); ++k) {
    const QPt e = brute::sub(M[(k + 1) % M.size()], M[k]);
    const mpq_class c0 = brute::cross(e, brute::sub(t, M[k])), c1 = brute::cross(e, d);  // inside: c0 + s·c1 >= 0
    if (sgn(c1) == 0) {
      if (sgn(c0) < 0) return std::nullopt;
    } else if (sgn(c1) > 0) {
      const mpq_class s = -c0 / c1;
      if (s > lo) lo = s;
    } else {
      const mpq_class s = -c0 / c1;
      if (!hi || s < *hi) hi = s;
    }
  }
  if (hi && *hi < lo) return std::nullopt;
  return lo;
}

}  // namespace

TEST(ConvexCast, AgainstExactEntryAndTheBoundaryContact) {
  std::mt19937_64 rng(2024);
  int hits = 0, misses = 0, zeros = 0, tangent = 0;
  double worst = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const auto [P, Q] = shapes::random_pair(rng, trial);
    const auto M = brute::minkowski_difference(P, Q);
    const Polygon PP = Polygon::simple(P.vertices()), QQ = Polygon::simple(Q.vertices());
    const nonconvex2::BoundaryPair2 boundary(PP, QQ);
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const auto& v : M) {
      x0 = std::min(x0, v.x.get_d()), x1 = std::max(x1, v.x.get_d());
      y0 = std::min(y0, v.y.get_d()), y1 = std::max(y1, v.y.get_d());
    }
    std::uniform_real_distribution<double> ux(2 * x0 - x1, 2 * x1 - x0), uy(2 * y0 - y1, 2 * y1 - y0);
    for (int k = 0; k < 40; ++k) {
      const Vec2 t = k % 2 ? shapes::placement(rng, P, Q, M, k / 2) : Vec2(ux(rng), uy(rng));
      if (brute::inside(M, t)) continue;  // the precondition: not overlapping
      const Vec2 d = shapes::direction(rng, P, Q, k);
      const std::optional<Cast2> c = convex2::convex_cast(P, Q, t, d);
      const Cast2 b = boundary.cast(t, d);
      const auto ex = exact_entry(M, t, d);
      char where[200];
      std::snprintf(where, sizeof where, "trial %d t=(%.17g, %.17g) d=(%.17g, %.17g)", trial, t.x(), t.y(), d.x(), d.y());
      ASSERT_EQ(b.hit, ex.has_value()) << where;
      if (!c) {
        ++tangent;
        continue;
      }
      ASSERT_EQ(c->hit, ex.has_value()) << where;
      if (!ex) {
        ++misses;
        EXPECT_EQ(c->distance, std::numeric_limits<double>::infinity());
        continue;
      }
      ++hits;
      const double exact = ex->get_d() * std::hypot(d.x(), d.y());
      EXPECT_EQ(c->distance == 0, sgn(*ex) == 0) << where;
      if (sgn(*ex) == 0) ++zeros;
      const double err = exact == 0 ? 0 : std::abs(c->distance - exact) / exact;
      worst = std::max(worst, err);
      EXPECT_LE(err, 8 * 0x1p-52) << where << " cast " << c->distance << " exact " << exact;
      EXPECT_LE(std::abs(c->distance - b.distance), 16 * 0x1p-52 * exact) << where;
      EXPECT_NEAR(c->normal.norm(), 1, 1e-15);
    }
  }
  std::printf("  hits %d (at 0: %d), misses %d, tangent lines left to the boundaries %d, worst %.2f ulps\n", hits,
              zeros, misses, tangent, worst / 0x1p-52);
  EXPECT_GT(hits, 500);
  EXPECT_GT(misses, 300);
  EXPECT_GT(zeros, 20);
}

namespace {

// Exact squared distance from t to the closed explicit M (t outside): min over M's edges.
mpq_class exact_squared_distance(const std::vector<QPt>& M, const Vec2& tv) {
  const QPt t = brute::lift(tv);
  std::optional<mpq_class> best;
  for (std::size_t k = 0; k < M.size(); ++k) {
    const QPt a = M[k], e = brute::sub(M[(k + 1) % M.size()], a), w = brute::sub(t, a);
    const mpq_class ee = e.x * e.x + e.y * e.y, we = w.x * e.x + w.y * e.y;
    mpq_class d2;
    if (sgn(we) <= 0) d2 = w.x * w.x + w.y * w.y;
    else if (we >= ee) {
      const QPt u = brute::sub(t, M[(k + 1) % M.size()]);
      d2 = u.x * u.x + u.y * u.y;
    } else {
      const mpq_class c = brute::cross(e, w);
      d2 = c * c / ee;
    }
    if (!best || d2 < *best) best = d2;
  }
  return *best;
}

}  // namespace

TEST(ConvexDistance, LocalisedSearchAgainstExactMAndTheBoundarySearch) {
  std::mt19937_64 rng(77);
  int localised = 0, fallback = 0;
  double worst = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const auto [P, Q] = shapes::random_pair(rng, trial);
    const auto M = brute::minkowski_difference(P, Q);
    const Polygon PP = Polygon::simple(P.vertices()), QQ = Polygon::simple(Q.vertices());
    const nonconvex2::BoundaryPair2 boundary(PP, QQ);
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const auto& v : M) {
      x0 = std::min(x0, v.x.get_d()), x1 = std::max(x1, v.x.get_d());
      y0 = std::min(y0, v.y.get_d()), y1 = std::max(y1, v.y.get_d());
    }
    const double w = x1 - x0, h = y1 - y0;
    std::uniform_real_distribution<double> ux(x0 - 3 * w, x1 + 3 * w), uy(y0 - 3 * h, y1 + 3 * h);
    std::uniform_real_distribution<double> nx(x0 - 0.1 * w, x1 + 0.1 * w), ny(y0 - 0.1 * h, y1 + 0.1 * h);
    for (int k = 0; k < 60; ++k) {
      Vec2 t = k % 3 == 0 ? Vec2(ux(rng), uy(rng)) : k % 3 == 1 ? Vec2(nx(rng), ny(rng)) : shapes::placement(rng, P, Q, M, k);
      if (k % 3 == 2) t += Vec2(std::ldexp(1.0, -30) * (1 + std::abs(t.x())), 0);  // just off ∂M
      if (brute::inside(M, t)) continue;
      const mpq_class d2 = exact_squared_distance(M, t);
      if (sgn(d2) == 0) continue;  // touching: not this path's case
      const auto v = convex2::convex_nearest_vertex(P, Q, t);
      char where[160];
      std::snprintf(where, sizeof where, "trial %d t=(%.17g, %.17g)", trial, t.x(), t.y());
      const Distance2 full = boundary.distance(t);
      if (!v) {
        ++fallback;
        continue;
      }
      ++localised;
      const Distance2 near = boundary.distance_near(t, (*v)[0], (*v)[1]);
      // Both the exact minimum, each a few ulps from it (equal minima through different pairs,
      // e.g. parallel edges, may round differently).
      ASSERT_LE(std::abs(near.distance - full.distance), 8 * 0x1p-52 * full.distance) << where;
      const double exact = std::sqrt(d2.get_d());
      const double err = std::abs(near.distance - exact) / exact;
      worst = std::max(worst, err);
      EXPECT_LE(err, 4 * 0x1p-52) << where;
      EXPECT_NEAR((near.witness_q - near.witness_p).norm(), near.distance, 1e-12 * (1 + t.norm() + near.witness_p.norm())) << where;
    }
  }
  std::printf("  localised %d, left to the boundary search %d, worst %.2f ulps\n", localised, fallback, worst / 0x1p-52);
  EXPECT_GT(localised, 3000);
}

