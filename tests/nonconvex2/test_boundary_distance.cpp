// Signed distance and shape cast of 2D pairs (src/nonconvex2/boundary_distance.cpp through
// Pair2, every engine) against the exact CGAL oracles: the brute-force boundary distance and
// first contact (oracle_distance.hpp) for non-overlapping placements, PairOracle's exact σ and
// overlap test for overlapping ones. Random pairs (fixed seeds), degenerate ones (parallel edges
// touching, vertices on edges, exact fits in slots, holes, placements exactly on ∂M) and real
// nesting pieces.
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "nfp_shapes.hpp"
#include "oracle.hpp"
#include "oracle_distance.hpp"
#include "polygon2/shapes.hpp"

namespace {

using namespace pendepth;
using namespace nonconvex2_test;

constexpr double kTol = 8 * 0x1p-52;  // relative: both sides a few ulps from the exact value

Shape2 shape_of(const Polygon& P) {
  std::vector<std::vector<Vec2>> holes;
  for (std::size_t k = 1; k < P.ring_count(); ++k) holes.emplace_back(P.ring(k).begin(), P.ring(k).end());
  return Shape2(std::vector<Vec2>(P.ring(0).begin(), P.ring(0).end()), holes, P.name());
}

bool close(double a, double b) {
  if (a == b) return true;
  return std::abs(a - b) <= kTol * std::max(std::abs(a), std::abs(b));
}

std::string fmt(const Vec2& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", v.x(), v.y());
  return buf;
}

// Placements over the box of M and a little beyond, exact touching placements (vertex of P −
// vertex of Q), and those nudged by a tiny step.
std::vector<Vec2> placements(std::mt19937_64& rng, const Polygon& P, const Polygon& Q, int count) {
  Vec2 lo(1e300, 1e300), hi(-1e300, -1e300), qlo(1e300, 1e300), qhi(-1e300, -1e300);
  for (const Vec2& p : P.vertices()) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  for (const Vec2& q : Q.vertices()) qlo = qlo.cwiseMin(q), qhi = qhi.cwiseMax(q);
  const Vec2 a = lo - qhi, b = hi - qlo;
  std::uniform_real_distribution<double> u(-0.3, 1.3);
  std::vector<Vec2> ts;
  for (int k = 0; k < count; ++k) ts.emplace_back(a.x() + u(rng) * (b.x() - a.x()), a.y() + u(rng) * (b.y() - a.y()));
  const auto pv = P.vertices(), qv = Q.vertices();
  for (int k = 0; k < count / 4; ++k) {
    const Vec2 t = pv[rng() % pv.size()] - qv[rng() % qv.size()];
    ts.push_back(t);
    ts.push_back(t + Vec2(std::ldexp(1.0, -20), 0));
  }
  // Support placements: P's extreme vertex along u minus Q's along −u (outer rings touch).
  std::uniform_real_distribution<double> w(-1, 1);
  for (int k = 0; k < count / 4; ++k) {
    const Vec2 dir(w(rng), w(rng));
    auto extreme = [&](std::span<const Vec2> vs, const Vec2& v) {
      std::size_t best = 0;
      for (std::size_t i = 1; i < vs.size(); ++i)
        if (vs[i].dot(v) > vs[best].dot(v)) best = i;
      return vs[best];
    };
    ts.push_back(extreme(pv, dir) - extreme(qv, Vec2(0, 0) - dir));
  }
  return ts;
}

struct Counts {
  int overlapping = 0, touching = 0, apart = 0, hits = 0, misses = 0;
};

// Every query of `pair` at t against the oracles.
void check(const Pair2& pair, const PairOracle& oracle, const Vec2& t, const Vec2& d, Counts& n) {
  const Polygon &P = pair.P().polygon(), &Q = pair.Q().polygon();
  const std::string where = std::string(to_string(pair.engine())) + " " + P.name() + " / " + Q.name() + " t=" + fmt(t);
  const Distance2 sd = pair.signed_distance(t);
  const bool inside = oracle.inside(t);
  ASSERT_EQ(sd.overlapping, inside) << where;
  if (inside) {
    ++n.overlapping;
    EXPECT_TRUE(close(-sd.distance, oracle.minimum(t))) << where << " sd " << sd.distance << " σ " << oracle.minimum(t);
    EXPECT_LT(sd.distance, 0) << where;
  } else {
    const ExactDistance ex = exact_boundary_distance(P, Q, t);
    EXPECT_EQ(sd.distance == 0, ex.touching) << where;
    EXPECT_TRUE(close(sd.distance, ex.distance)) << where << " sd " << sd.distance << " exact " << ex.distance;
    // witness_q − witness_p = distance·normal, translation = −distance·normal.
    const double scale = 1 + std::max(std::abs(t.x()), std::abs(t.y())) + 1e3;
    EXPECT_NEAR((sd.witness_q - sd.witness_p - sd.distance * sd.normal).norm(), 0, 1e-12 * scale) << where;
    EXPECT_EQ(sd.translation, Vec2(0, 0) - sd.distance * sd.normal) << where;
    if (ex.touching) {
      ++n.touching;
      EXPECT_EQ(sd.normal, Vec2(0, 0)) << where;
    } else {
      ++n.apart;
      EXPECT_NEAR(sd.normal.norm(), 1, 1e-15) << where;
    }
  }
  const Cast2 c = pair.cast(t, d);
  if (inside) {
    EXPECT_TRUE(c.hit && c.overlapping && c.distance == 0) << where;
    return;
  }
  const ExactCast ec = exact_cast(P, Q, t, d);
  ASSERT_EQ(c.hit, ec.hit) << where << " d=" << fmt(d);
  if (!ec.hit) {
    ++n.misses;
    EXPECT_EQ(c.distance, std::numeric_limits<double>::infinity()) << where;
    return;
  }
  ++n.hits;
  EXPECT_TRUE(close(c.distance, ec.distance)) << where << " d=" << fmt(d) << " cast " << c.distance << " exact " << ec.distance;
  EXPECT_EQ(c.distance == 0, ec.distance == 0) << where;
  EXPECT_NEAR(c.normal.norm(), 1, 1e-15) << where;
}

// Every engine the shapes allow (Queries and Full), each placement with a random or an
// axis-parallel direction; prints the counts so a run shows what was covered.
Counts run_pair(const Polygon& P, const Polygon& Q, std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  const PairOracle oracle(P, Q);
  const auto ts = placements(rng, P, Q, count);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec2> ds;
  for (std::size_t k = 0; k < ts.size(); ++k) {
    if (k % 3 == 0) ds.push_back(k % 2 ? Vec2(0, -1) : Vec2(1, 0));
    else ds.emplace_back(u(rng), u(rng));
  }
  Counts n;
  for (Prepare prep : {Prepare::Queries, Prepare::Full}) {
    const Pair2 pair(shape_of(P), shape_of(Q), prep);
    for (std::size_t k = 0; k < ts.size(); ++k) {
      check(pair, oracle, ts[k], ds[k], n);
      if (::testing::Test::HasFatalFailure()) return n;
    }
  }
  return n;
}

void add(Counts& all, const Counts& n) {
  all.overlapping += n.overlapping, all.touching += n.touching, all.apart += n.apart, all.hits += n.hits,
      all.misses += n.misses;
}

void expect_coverage(const Counts& n, bool touching = true) {
  std::printf("  overlapping %d, touching %d, apart %d, cast hits %d, misses %d\n", n.overlapping, n.touching, n.apart,
              n.hits, n.misses);
  EXPECT_GT(n.overlapping, 0);
  EXPECT_GT(n.apart, 0);
  EXPECT_GT(n.hits, 0);
  if (touching) EXPECT_GT(n.touching, 0);
}

}  // namespace

TEST(BoundaryDistance, RandomStarsAgainstExactOracle) {
  Counts all;
  for (int k = 0; k < 6; ++k) {
    std::mt19937_64 rng(100 + k);
    const Polygon P = star(rng, 8 + k, 40, 100, k % 2 == 0), Q = star(rng, 6 + k, 20, 50, k % 2 == 0);
    add(all, run_pair(P, Q, 200 + k, 40));
  }
  expect_coverage(all);
}

TEST(BoundaryDistance, ConvexAndMixedEnginesAgainstExactOracle) {
  for (int k = 0; k < 4; ++k) {
    std::mt19937_64 rng(300 + k);
    const Polygon A = convex_hull(rng, 12 + 4 * k, 100), B = convex_hull(rng, 8 + k, 40);
    const Polygon S = star(rng, 10, 30, 80, k % 2 == 1);
    EXPECT_EQ(Pair2(shape_of(A), shape_of(B)).engine(), Engine2::Convex);
    expect_coverage(run_pair(A, B, 400 + k, 40));
    EXPECT_EQ(Pair2(shape_of(S), shape_of(B)).engine(), Engine2::PolygonConvex);
    expect_coverage(run_pair(S, B, 500 + k, 40));
    EXPECT_EQ(Pair2(shape_of(B), shape_of(S)).engine(), Engine2::PolygonConvexSwapped);
    expect_coverage(run_pair(B, S, 600 + k, 40));
  }
}

TEST(BoundaryDistance, HolesAgainstExactOracle) {
  Counts all;
  for (int k = 0; k < 2; ++k) {
    std::mt19937_64 rng(700 + k);
    const Polygon P = polygon2_test::random_polygon(rng, 12, 1 + k, k != 1);
    const Polygon Q = convex_hull(rng, 6, 8 + 4 * k);
    const Polygon R = star(rng, 7, 4, 10, true);
    add(all, run_pair(P, Q, 800 + k, 24));
    add(all, run_pair(P, R, 900 + k, 24));
  }
  expect_coverage(all);
}

// Rectilinear shapes: antiparallel edges touching along segments, vertices on edges, columns
// fitting gaps exactly, casts parallel to edges (collinear contacts).
TEST(BoundaryDistance, DegenerateHistogramsAndSlots) {
  for (int k = 0; k < 4; ++k) {
    std::mt19937_64 rng(1000 + k);
    const Polygon P = histogram(rng, 6 + k, 4), Q = histogram(rng, 3 + k, 3);
    expect_coverage(run_pair(P, Q, 1100 + k, 40));
  }
  // A comb and a bar exactly as wide as its slots: sliding in a slot is touching (distance 0).
  const Polygon comb = Polygon::simple(polygon2_test::comb_ring(4, 3, 2, 5, 1), "comb");
  const Polygon bar = Polygon::simple(std::vector<Vec2>{{0, 0}, {2, 0}, {2, 7}, {0, 7}}, "bar");
  const Pair2 pair(shape_of(comb), shape_of(bar));
  const PairOracle oracle(comb, bar);
  Counts n;
  for (double y : {1.0, 3.5, 6.0, 9.0})
    for (const Vec2& d : {Vec2(0, -1), Vec2(0, 1), Vec2(1, 0), Vec2(1, -1)}) check(pair, oracle, Vec2(3, y), d, n);
  EXPECT_EQ(pair.signed_distance(Vec2(3, 3.5)).distance, 0);
  EXPECT_EQ(pair.cast(Vec2(3, 3.5), Vec2(0, -1)).distance, 0);  // in the slot: touching its walls
  EXPECT_EQ(pair.cast(Vec2(3, 9), Vec2(0, -1)).distance, 3);    // reaches the walls' top corners
  EXPECT_EQ(pair.cast(Vec2(3.5, 9), Vec2(0, -1)).distance, 3);  // lands on a tooth top
  expect_coverage(run_pair(comb, bar, 1200, 60));
}

TEST(BoundaryDistance, NestingPiecesAgainstExactOracle) {
  for (const char* file : {"albano.json", "shirts.json"}) {
    const auto pieces = instance(file);
    std::mt19937_64 rng(1300);
    for (int k = 0; k < 3; ++k) {
      const Polygon& P = pieces[rng() % pieces.size()];
      const Polygon& Q = pieces[rng() % pieces.size()];
      expect_coverage(run_pair(P, Q, 1400 + k, 30), false);
    }
  }
}
