// Degenerate inputs against the exact oracle: identical shapes, triangles and slivers, squares
// against squares (parallel edges everywhere), touching placements (t exactly on ∂M → 0, not
// overlapping), directions parallel to edges, unit shapes at a 10^6 offset (exact and rounded
// shifts), 10^6 random queries at that offset, and invalid queries.
#include <pendepth/depth2.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "oracle/checks.hpp"
#include "oracle/exact_oracle.hpp"
#include "oracle/shapes.hpp"

namespace oracle_tests {
namespace {

#ifdef NDEBUG
constexpr int kSpeed = 1;
#else
constexpr int kSpeed = 10;  // Debug / sanitizers: a tenth of the repetitions, same seeds
#endif

using pendepth::InvalidInput;

std::vector<Vec2> ring(std::initializer_list<Vec2> v) { return v; }

// All checks of a pair over the given placements, each with the given directions plus
// `edge_dirs` edge vectors of P, −P, Q, −Q or M drawn at random (all of them when negative).
void check_pair(Rng& rng, const std::vector<Vec2>& p_pts, const std::vector<Vec2>& q_pts, const std::vector<Vec2>& ts,
                const std::vector<Vec2>& dirs, int edge_dirs, Stats& stats, const std::string& context) {
  const ConvexPolygon P = ConvexPolygon::hull(p_pts), Q = ConvexPolygon::hull(q_pts);
  const oracle::ExactDifference M(p_pts, q_pts);
  PairChecker check(P, Q, M, stats, context);
  std::vector<Vec2> edges;
  for (const ConvexPolygon* S : {&P, &Q})
    for (std::size_t i = 0; i < S->size(); ++i) {
      edges.push_back(S->at_cyclic(i + 1) - (*S)[i]);
      edges.push_back((*S)[i] - S->at_cyclic(i + 1));
    }
  for (std::size_t k = 0; k < M.size(); ++k) edges.push_back(M.vertex((k + 1) % M.size()) - M.vertex(k));
  std::erase(edges, Vec2(0, 0));  // a rounded edge of M could vanish
  for (const Vec2& t : ts) {
    if (!check.minimum(t)) return;
    std::vector<Vec2> all = dirs;
    if (edge_dirs < 0) all.insert(all.end(), edges.begin(), edges.end());
    for (int k = 0; k < edge_dirs; ++k)
      all.push_back(edges[std::uniform_int_distribution<std::size_t>(0, edges.size() - 1)(rng)]);
    for (const Vec2& d : all)
      if (!check.directional(t, d)) return;
  }
}

std::vector<Vec2> axis_dirs() { return {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {1, -1}, {-2, 1}, {0.3, -0.7}}; }

TEST(OracleDegenerate, IdenticalShapes) {
  Rng rng(0x1de7);
  Stats stats;
  const ShapeKind kinds[] = {ShapeKind::Cloud, ShapeKind::Ellipse, ShapeKind::Grid5, ShapeKind::Grid3, ShapeKind::Dyadic};
  for (int trial = 0; trial < 150 / kSpeed && stats.failures < kMaxFailures; ++trial) {
    const int n = uniform_int(rng, 3, 30);
    Shape S = shape(rng, kinds[trial % 5], n);
    const oracle::ExactDifference M(S.pts, S.pts);
    std::vector<Vec2> ts = placements(rng, M, 4, 3);
    ts.push_back(Vec2(0, 0));  // centre of the symmetric M = S ⊕ (−S): σ is the minimum width of S
    check_pair(rng, S.pts, S.pts, ts, axis_dirs(), 8, stats, "identical " + S.label);
  }
  stats.print("identical");
  EXPECT_EQ(stats.failures, 0);
}

TEST(OracleDegenerate, TrianglesAndSlivers) {
  Rng rng(0x7a1);
  Stats stats;
  for (int trial = 0; trial < 400 / kSpeed && stats.failures < kMaxFailures; ++trial) {
    auto triangle = [&](int kind) -> std::vector<Vec2> {
      for (;;) {
        std::vector<Vec2> t;
        if (kind == 0) t = points(rng, ShapeKind::Cloud, 3);
        else if (kind == 1) t = points(rng, ShapeKind::Grid3, 3);
        else {  // sliver: apex a tiny relative height above the base
          const Vec2 a(uniform(rng, -3, 3), uniform(rng, -3, 3)), b(uniform(rng, -3, 3), uniform(rng, -3, 3));
          const Vec2 mid = (a + b) / 2, up = rot90(b - a) * std::ldexp(1.0, -uniform_int(rng, 10, 40));
          t = {a, b, mid + up};
        }
        if (pendepth::predicates::orient2d(t[0], t[1], t[2]) != 0) return t;
      }
    };
    const std::vector<Vec2> A = triangle(trial % 3), B = triangle((trial / 3) % 3);
    const oracle::ExactDifference M(A, B);
    check_pair(rng, A, B, placements(rng, M, 6, 3), axis_dirs(), 6, stats, "triangles trial " + std::to_string(trial));
  }
  stats.print("triangles");
  EXPECT_EQ(stats.failures, 0);
}

TEST(OracleDegenerate, SquaresAgainstSquares) {
  // Axis-aligned and 45°-turned squares of integer sizes; placements on the half-integer grid,
  // so most of them are vertices of M, on its edges, or exactly half-way between.
  Rng rng(0x5a0a);
  Stats stats;
  auto axis_square = [](int a, Vec2 c) { return ring({c, c + Vec2(a, 0), c + Vec2(a, a), c + Vec2(0, a)}); };
  auto diamond = [](int a, Vec2 c) { return ring({c + Vec2(a, 0), c + Vec2(0, a), c + Vec2(-a, 0), c + Vec2(0, -a)}); };
  int combo = 0;
  for (int a = 1; a <= 3; ++a)
    for (int b = 1; b <= 3; ++b)
      for (int kind = 0; kind < 4; ++kind) {
        if (combo++ % kSpeed != 0) continue;
        const std::vector<Vec2> A = kind & 1 ? diamond(a, {0, 0}) : axis_square(a, {0, 0});
        const std::vector<Vec2> B = kind & 2 ? diamond(b, {1, -1}) : axis_square(b, {-1, 0});
        const oracle::ExactDifference M(A, B);
        std::vector<Vec2> ts;
        for (double x = std::floor(M.box_lo().x()) - 0.5; x <= M.box_hi().x() + 0.5; x += 0.5)
          for (double y = std::floor(M.box_lo().y()) - 0.5; y <= M.box_hi().y() + 0.5; y += 0.5) ts.emplace_back(x, y);
        check_pair(rng, A, B, ts, axis_dirs(), 4, stats,
                   "squares a=" + std::to_string(a) + " b=" + std::to_string(b) + " kind=" + std::to_string(kind));
      }
  stats.print("squares");
  EXPECT_EQ(stats.failures, 0);
  EXPECT_GT(stats.boundary, 1000 / kSpeed);  // the suite does exercise t ∈ ∂M
}

TEST(OracleDegenerate, TouchingPlacementsAreZero) {
  // Every exactly representable point of ∂M (vertices, midpoints, quarter points of edges):
  // depth 0 and not overlapping, in every direction (including along the touching edge).
  Rng rng(0x70c4);
  Stats stats;
  long touching = 0;
  for (int trial = 0; trial < 200 / kSpeed && stats.failures < kMaxFailures; ++trial) {
    const ShapeKind kinds[] = {ShapeKind::Grid5, ShapeKind::Grid3, ShapeKind::Dyadic, ShapeKind::Cloud};
    Shape P = shape(rng, kinds[trial % 4], uniform_int(rng, 3, 20));
    Shape Q = shape(rng, kinds[(trial / 4) % 4], uniform_int(rng, 3, 20));
    const oracle::ExactDifference M(P.pts, Q.pts);
    std::vector<Vec2> ts = M.boundary_doubles();
    for (const Vec2& t : ts) ASSERT_EQ(M.locate(t), oracle::Location::Boundary) << fmt(t);  // the oracle's own claim
    touching += long(ts.size());
    check_pair(rng, P.pts, Q.pts, ts, axis_dirs(), 6, stats, "touching trial " + std::to_string(trial));
  }
  stats.print("touching");
  EXPECT_EQ(stats.failures, 0);
  EXPECT_EQ(stats.boundary, stats.zeros);
  EXPECT_GT(touching, 1000 / kSpeed);
}

TEST(OracleDegenerate, DirectionsParallelToEdgesOfM) {
  // For grid shapes, t on an edge line, one ulp inside it, and at interior grid points, with d
  // along every edge of M exactly: the ray grazes or runs along ∂M.
  Rng rng(0xed6e);
  Stats stats;
  for (int trial = 0; trial < 100 / kSpeed && stats.failures < kMaxFailures; ++trial) {
    Shape P = shape(rng, trial % 2 ? ShapeKind::Grid3 : ShapeKind::Grid5, uniform_int(rng, 3, 12));
    Shape Q = shape(rng, trial % 3 ? ShapeKind::Grid3 : ShapeKind::Grid5, uniform_int(rng, 3, 12));
    const oracle::ExactDifference M(P.pts, Q.pts);
    std::vector<Vec2> ts = placements(rng, M, 0, 6);
    for (int x = -10; x <= 10; x += 2)
      for (int y = -10; y <= 10; y += 3) ts.emplace_back(x, y);
    check_pair(rng, P.pts, Q.pts, ts, {}, -1, stats, "edge-parallel trial " + std::to_string(trial));
  }
  stats.print("edge-parallel");
  EXPECT_EQ(stats.failures, 0);
}

// Unit shapes both translated by c = (1e6, -1e6). With dyadic coordinates (multiples of 2^-20)
// the shift is exact, M is unchanged (the oracle confirms), and the answers must match the
// unshifted scene; with arbitrary doubles the shifted shapes are rounded and are compared with
// the oracle of what was actually built.
TEST(OracleDegenerate, UnitShapesAtLargeOffset) {
  Rng rng(0x0ff5e7);
  Stats stats, shifted_stats;
  const Vec2 c(1e6, -1e6);
  long compared = 0;
  for (int trial = 0; trial < 200 / kSpeed && stats.failures + shifted_stats.failures < kMaxFailures; ++trial) {
    const bool dyadic = trial % 2 == 0;
    const ShapeKind kind = dyadic ? ShapeKind::Dyadic : (trial % 4 == 1 ? ShapeKind::Ellipse : ShapeKind::Cloud);
    Shape P = shape(rng, kind, uniform_int(rng, 3, 16), dyadic ? 1 : 0.1);
    Shape Q = shape(rng, kind, uniform_int(rng, 3, 16), dyadic ? 1 : 0.1);
    std::vector<Vec2> ps, qs;
    for (const Vec2& v : P.pts) ps.push_back(v + c);
    for (const Vec2& v : Q.pts) qs.push_back(v + c);
    const oracle::ExactDifference M(P.pts, Q.pts), Ms(ps, qs);
    if (dyadic) ASSERT_TRUE(M.same_polygon(Ms)) << "an exact shift of both shapes leaves M unchanged";
    const ConvexPolygon Pu = ConvexPolygon::hull(P.pts), Qu = ConvexPolygon::hull(Q.pts);
    const ConvexPolygon Psh = ConvexPolygon::hull(ps), Qsh = ConvexPolygon::hull(qs);
    PairChecker check(Psh, Qsh, Ms, shifted_stats, std::string(dyadic ? "dyadic" : "rounded") + " shift trial " +
                                                       std::to_string(trial));
    for (const Vec2& t : placements(rng, Ms, 6, 3)) {
      check.minimum(t);
      std::vector<Vec2> dirs = axis_dirs();
      for (int k = 0; k < 3; ++k) dirs.push_back(direction(rng, Psh, Qsh, Ms));
      for (const Vec2& d : dirs) {
        check.directional(t, d);
        if (dyadic) {  // same values as the unshifted scene
          ++compared;
          EXPECT_TRUE(oracle::within(pendepth::directional_depth(Psh, Qsh, t, d).depth,
                                     pendepth::directional_depth(Pu, Qu, t, d).depth, kPairTol))
              << check.scene() << " t=" << fmt(t) << " d=" << fmt(d);
        }
      }
      if (dyadic)
        EXPECT_TRUE(oracle::within(pendepth::minimum_depth(Psh, Qsh, t).depth, pendepth::minimum_depth(Pu, Qu, t).depth,
                                   kPairTol))
            << check.scene() << " t=" << fmt(t);
    }
  }
  shifted_stats.print("offset 1e6");
  std::printf("[offset 1e6] %ld σ_d values compared with the unshifted scene\n", compared);
  EXPECT_EQ(shifted_stats.failures, 0);
}

// 10^6 random queries (Release; 5·10^4 in Debug) on unit shapes: P at c = (1e6, -1e6), Q at the
// origin, so placements are t ≈ c. Every query is checked with the oracle's exact point location
// (CGAL, filtered): the overlapping flags of σ, σ_d and the field, σ <= σ_d, and the separating
// move t + (1±ε)v for both translations. One query in 100 is also compared in value with the
// oracle's exact σ and σ_d (10^4 queries) — the full exact distances for all 10^6 would dominate
// the suite's run time.
TEST(OracleDegenerate, MillionQueriesAtLargeOffset) {
  const auto start = std::chrono::steady_clock::now();
  Rng rng(0x1000000);
  const long kQueries = kSpeed == 1 ? 1000000 : 50000;
  const int kPairs = 20;
  const Vec2 c(1e6, -1e6);
  Stats stats;
  long queries = 0, overlapping = 0, moves = 0, skipped = 0, failures = 0;
  for (int pair = 0; pair < kPairs && failures < kMaxFailures; ++pair) {
    const ShapeKind kind = pair % 2 ? ShapeKind::Ellipse : ShapeKind::Dyadic;
    Shape P = shape(rng, kind, uniform_int(rng, 3, 12), 0.2);
    Shape Q = shape(rng, kind, uniform_int(rng, 3, 12), 0.2);
    std::vector<Vec2> ps;
    for (const Vec2& v : P.pts) ps.push_back(v + c);
    const ConvexPolygon Pc = ConvexPolygon::hull(ps);
    const oracle::ExactDifference M(ps, Q.pts);
    PairChecker check(Pc, *Q.poly, M, stats, "offset query pair " + std::to_string(pair));
    const pendepth::DepthField& field = check.query().field();
    const Vec2 lo = M.box_lo(), hi = M.box_hi(), mid = (lo + hi) / 2, half = (hi - lo) * 0.6;
    auto fail = [&](const std::string& why, const Vec2& t, const Vec2& d) {
      ++failures;
      ADD_FAILURE() << why << "\n  " << check.scene() << " P=" << fmt_polygon(Pc) << " Q=" << fmt_polygon(*Q.poly)
                    << "\n  t=" << fmt(t) << " d=" << fmt(d);
    };
    for (long k = 0; k < kQueries / kPairs && failures < kMaxFailures; ++k, ++queries) {
      const Vec2 t(mid.x() + uniform(rng, -half.x(), half.x()), mid.y() + uniform(rng, -half.y(), half.y()));
      const double a = uniform(rng, 0, 2 * std::numbers::pi);
      const Vec2 d(std::cos(a), std::sin(a));
      const pendepth::Depth2 rd = pendepth::directional_depth(Pc, *Q.poly, t, d);
      const pendepth::Depth2 rm = pendepth::minimum_depth(Pc, *Q.poly, t);
      const pendepth::Depth2 rf = field.minimum(t);
      const bool inside = M.locate(t) == oracle::Location::Inside;
      if (k % 100 == 0) {  // the 1% subset: values against the exact oracle
        check.minimum(t);
        check.directional(t, d);
      }
      if (rd.overlapping != inside || rm.overlapping != inside || rf.overlapping != inside)
        fail("overlapping flag differs from the exact location (" + std::string(inside ? "inside" : "not inside") + ")", t, d);
      if (!inside) {
        if (rd.depth != 0 || rm.depth != 0 || rf.depth != 0) fail("non-zero depth outside int M", t, d);
        continue;
      }
      ++overlapping;
      if (!(rm.depth <= rd.depth * (1 + kPairTol * kEps)) || !oracle::within(rf.depth, rm.depth, kPairTol))
        fail("σ > σ_d, or field != merge: σ=" + fmt(rm.depth) + " field=" + fmt(rf.depth) + " σ_d=" + fmt(rd.depth), t, d);
      // Separating moves, ε as in test_properties.cpp (margin ε·σ against rounding ~2^-48 (|t|+|v|)).
      for (const pendepth::Depth2* r : {&rd, &rm}) {
        const double eps = std::max(1e-9, 64 * kEps * (t.norm() + r->translation.norm()) / rm.depth);
        if (eps > 1e-4) {
          ++skipped;
          continue;
        }
        ++moves;
        if (M.locate(t + (1 + eps) * r->translation) == oracle::Location::Inside ||
            M.locate(t + (1 - eps) * r->translation) != oracle::Location::Inside)
          fail(std::string(r == &rd ? "σ_d" : "σ") + " translation does not just separate, ε=" + fmt(eps), t, d);
      }
    }
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[million] %ld queries (%ld overlapping), %ld separating moves checked (%ld too close to ∂M), "
              "%ld/%ld compared with the exact values, %.1f s\n",
              queries, overlapping, moves, skipped, stats.minimum, stats.directional, secs);
  stats.print("million subset");
  EXPECT_EQ(failures, 0);
  EXPECT_EQ(stats.failures, 0);
  EXPECT_EQ(queries, kQueries / kPairs * kPairs);
}

TEST(OracleErrors, InvalidQueriesThrow) {
  const ConvexPolygon P = ConvexPolygon::hull(ring({{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
  const ConvexPolygon Q = ConvexPolygon::hull(ring({{0, 0}, {1, 0}, {0, 1}}));
  const pendepth::DepthQuery2 query(P, Q);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const Vec2 t(0.5, 0.5);
  for (const Vec2& d : {Vec2(0, 0), Vec2(-0.0, 0.0), Vec2(nan, 1), Vec2(1, nan), Vec2(inf, 0), Vec2(0, -inf)}) {
    EXPECT_THROW(pendepth::directional_depth(P, Q, t, d), InvalidInput) << fmt(d);
    EXPECT_THROW(pendepth::separation_depth(P, Q, t, d), InvalidInput) << fmt(d);
    EXPECT_THROW(query.along(t, d), InvalidInput) << fmt(d);
    EXPECT_THROW(query.separation(t, d), InvalidInput) << fmt(d);
  }
  for (const Vec2& bad : {Vec2(nan, 0), Vec2(0, nan), Vec2(inf, 0), Vec2(0, -inf)}) {
    EXPECT_THROW(pendepth::directional_depth(P, Q, bad, Vec2(1, 0)), InvalidInput) << fmt(bad);
    EXPECT_THROW(pendepth::separation_depth(P, Q, bad, Vec2(1, 0)), InvalidInput) << fmt(bad);
    EXPECT_THROW(pendepth::minimum_depth(P, Q, bad), InvalidInput) << fmt(bad);
    EXPECT_THROW(query.field().minimum(bad), InvalidInput) << fmt(bad);
    EXPECT_THROW(query.minimum(bad), InvalidInput) << fmt(bad);
    EXPECT_THROW(query.along(bad, Vec2(0, 1)), InvalidInput) << fmt(bad);
  }
  // Valid queries next to the invalid ones still answer (t outside, on ∂M, inside).
  EXPECT_EQ(pendepth::directional_depth(P, Q, Vec2(5, 5), Vec2(1, 0)).depth, 0.0);
  EXPECT_EQ(pendepth::minimum_depth(P, Q, Vec2(2, 0.5)).depth, 0.0);
  EXPECT_GT(query.minimum(t).depth, 0.0);
}

}  // namespace
}  // namespace oracle_tests
