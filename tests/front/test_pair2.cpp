// Front door, 2D (include/pendepth/pendepth.hpp): Pair2 gives the values of the engine it picks,
// bit for bit; the polygon × convex role swap both ways; every query for every pair; batches
// equal to single calls bit for bit at 1, 2 and 8 threads; errors at the boundary.
#include <pendepth/depth2_polygon_polygon.hpp>
#include <pendepth/depth2_polygon_convex.hpp>
#include <pendepth/nfp2.hpp>
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "front/common.hpp"
#include "nonconvex2/nfp_shapes.hpp"
#include "polygon2/shapes.hpp"

namespace {

using namespace pendepth;
using front_test::error_of;
using front_test::same;
using front_test::same_bits;
bool same_bits(const Vec2& a, const Vec2& b) { return front_test::same_bits_v(a, b); }

std::vector<Vec2> ring_of(const ConvexPolygon& C) { return {C.vertices().begin(), C.vertices().end()}; }

Shape2 shape_of(const Polygon& P) {
  std::vector<std::vector<Vec2>> holes;
  for (std::size_t k = 1; k < P.ring_count(); ++k) holes.emplace_back(P.ring(k).begin(), P.ring(k).end());
  return Shape2(std::vector<Vec2>(P.ring(0).begin(), P.ring(0).end()), holes, P.name());
}

// Placements spread over the overlap region's box and a little beyond, plus exact vertices of
// P − vertices of Q (touching placements on ∂M happen there).
std::vector<Vec2> placements(std::mt19937_64& rng, const Shape2& P, const Shape2& Q, int count) {
  Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const auto& r : P.rings())
    for (const Vec2& p : r) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  Vec2 qlo(1e300, 1e300), qhi(-1e300, -1e300);
  for (const auto& r : Q.rings())
    for (const Vec2& q : r) qlo = qlo.cwiseMin(q), qhi = qhi.cwiseMax(q);
  const Vec2 a = lo - qhi, b = hi - qlo;
  std::uniform_real_distribution<double> u(-0.1, 1.1);
  std::vector<Vec2> ts;
  for (int k = 0; k < count; ++k) ts.emplace_back(a.x() + u(rng) * (b.x() - a.x()), a.y() + u(rng) * (b.y() - a.y()));
  const auto pr = P.rings()[0], qr = Q.rings()[0];
  for (int k = 0; k < count / 8; ++k) ts.push_back(pr[rng() % pr.size()] - qr[rng() % qr.size()]);
  return ts;
}

std::vector<Vec2> directions(std::mt19937_64& rng, std::size_t count) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec2> ds;
  while (ds.size() < count) {
    Vec2 d(u(rng), u(rng));
    if (rng() % 4 == 0) d = Vec2(double(int(rng() % 3) - 1), double(int(rng() % 3) - 1));  // axis-parallel
    if (d.x() != 0 || d.y() != 0) ds.push_back(d);
  }
  return ds;
}

// ---- engine choice ----

TEST(Pair2, ChoosesTheEngineByTheShapesAndPrepare) {
  std::mt19937_64 rng(1);
  const Shape2 C1(ring_of(polygon2_test::random_convex(rng, 6, 3, false)), {}, "C1");
  const Shape2 C2(ring_of(polygon2_test::random_convex(rng, 5, 2, false)), {}, "C2");
  const Shape2 N1 = shape_of(polygon2_test::random_polygon(rng, 12, 1, false));
  const Shape2 N2 = shape_of(polygon2_test::random_polygon(rng, 9, 0, false));
  ASSERT_TRUE(C1.is_convex());
  ASSERT_FALSE(N1.is_convex());
  EXPECT_EQ(Pair2(C1, C2).engine(), Engine2::Convex);
  EXPECT_EQ(Pair2(N1, C2).engine(), Engine2::PolygonConvex);
  EXPECT_EQ(Pair2(C1, N2).engine(), Engine2::PolygonConvexSwapped);
  EXPECT_EQ(Pair2(N1, N2).engine(), Engine2::NoFitPolygon);  // small: Auto builds the no-fit polygon
  EXPECT_EQ(Pair2(N1, N2, Prepare::Queries).engine(), Engine2::PairPerQuery);
  EXPECT_EQ(Pair2(N1, N2, Prepare::Full).engine(), Engine2::NoFitPolygon);
  const Shape2 big = shape_of(Polygon::simple(polygon2_test::comb_ring(70, 1, 1, 10, 2)));
  ASSERT_GT(big.size() * big.size(), Pair2::kNfpAutoLimit);
  EXPECT_EQ(Pair2(big, big).engine(), Engine2::PairPerQuery);
  EXPECT_STREQ(to_string(Engine2::NoFitPolygon), "no-fit-polygon");
}

// ---- the front door gives the engines' values ----

TEST(Pair2, ConvexPairsGiveTheConvexEnginesValues) {
  std::mt19937_64 rng(2);
  for (int trial = 0; trial < 40; ++trial) {
    const ConvexPolygon A = polygon2_test::random_convex(rng, 3 + int(rng() % 60), 3, trial % 2 == 0);
    const ConvexPolygon B = polygon2_test::random_convex(rng, 3 + int(rng() % 40), 2, trial % 2 == 0);
    const Shape2 P(A), Q(B);
    const Pair2 queries(P, Q, Prepare::Queries), full(P, Q, Prepare::Full), automatic(P, Q);
    const DepthField field(A, B);
    const auto ts = placements(rng, P, Q, 40);
    const auto ds = directions(rng, ts.size());
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const Depth2 merge = minimum_depth(A, B, ts[i]);
      ASSERT_TRUE(same(queries.minimum(ts[i]), merge));
      ASSERT_TRUE(same(automatic.minimum(ts[i]), A.size() + B.size() > Pair2::kFieldAutoSize ? field.minimum(ts[i]) : merge));
      ASSERT_TRUE(same(full.minimum(ts[i]), field.minimum(ts[i])));
      // The depth field and the merge give the same depth (on ties they may name another edge).
      ASSERT_TRUE(same_bits(field.minimum(ts[i]).depth, merge.depth)) << "trial " << trial << " placement " << i;
      ASSERT_TRUE(same(automatic.along(ts[i], ds[i]), directional_depth(A, B, ts[i], ds[i])));
      ASSERT_TRUE(same(automatic.separation(ts[i], ds[i]), separation_depth(A, B, ts[i], ds[i])));
      ASSERT_EQ(automatic.overlapping(ts[i]), merge.overlapping);
    }
  }
}

TEST(Pair2, PolygonConvexPairsGivePolygonDepth2sValues) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 12; ++trial) {
    const Polygon A = polygon2_test::random_polygon(rng, 8 + int(rng() % 20), int(rng() % 3), trial % 2 == 0);
    const ConvexPolygon B = polygon2_test::random_convex(rng, 3 + int(rng() % 8), 1.5, trial % 2 == 0);
    const Shape2 P = shape_of(A), Q(B);
    ASSERT_FALSE(P.is_convex());
    const Pair2 pair(P, Q);
    const PolygonDepth2 engine(A, B);
    const auto ts = placements(rng, P, Q, 30);
    const auto ds = directions(rng, ts.size());
    for (std::size_t i = 0; i < ts.size(); ++i) {
      ASSERT_TRUE(same(pair.minimum(ts[i]), engine.minimum(ts[i])));
      ASSERT_TRUE(same(pair.along(ts[i], ds[i]), engine.along(ts[i], ds[i])));
      ASSERT_TRUE(same(pair.separation(ts[i], ds[i]), engine.separation(ts[i], ds[i])));
      ASSERT_EQ(pair.overlapping(ts[i]), engine.overlapping(ts[i]));
    }
  }
}

TEST(Pair2, TwoPolygonsGivePairDepth2OrTheNoFitPolygonsValues) {
  std::mt19937_64 rng(4);
  for (int trial = 0; trial < 10; ++trial) {
    const Polygon A = polygon2_test::random_polygon(rng, 8 + int(rng() % 14), int(rng() % 2), trial % 2 == 0);
    const Polygon B = polygon2_test::random_polygon(rng, 6 + int(rng() % 8), 0, trial % 2 == 0);
    const Shape2 P = shape_of(A), Q = shape_of(B);
    ASSERT_FALSE(Q.is_convex());
    const Pair2 per_query(P, Q, Prepare::Queries), full(P, Q, Prepare::Full);
    const PairDepth2 pd(A, B);
    const NoFitPolygon2 nfp(A, B);
    const auto ts = placements(rng, P, Q, 24);
    const auto ds = directions(rng, ts.size());
    for (std::size_t i = 0; i < ts.size(); ++i) {
      ASSERT_TRUE(same(per_query.minimum(ts[i]), pd.minimum(ts[i])));
      ASSERT_TRUE(same(per_query.along(ts[i], ds[i]), pd.along(ts[i], ds[i])));
      ASSERT_TRUE(same(per_query.separation(ts[i], ds[i]), pd.separation(ts[i], ds[i])));
      ASSERT_EQ(per_query.overlapping(ts[i]), pd.overlapping(ts[i]));
      ASSERT_TRUE(same(full.minimum(ts[i]), nfp.minimum(ts[i])));
      ASSERT_TRUE(same(full.along(ts[i], ds[i]), nfp.along(ts[i], ds[i])));
      // The no-fit polygon has no separation of its own: the pair answers it with PairDepth2.
      ASSERT_TRUE(same(full.separation(ts[i], ds[i]), pd.separation(ts[i], ds[i])));
      ASSERT_EQ(full.overlapping(ts[i]), nfp.overlapping(ts[i]));
      // The two engines agree on the decision and, to a few ulps, on the value.
      ASSERT_EQ(per_query.overlapping(ts[i]), full.overlapping(ts[i]));
      const double a = per_query.minimum(ts[i]).depth, b = full.minimum(ts[i]).depth;
      ASSERT_NEAR(a, b, 1e-12 * (1 + std::abs(a)));
    }
    const auto& e = full.no_fit_polygon();
    EXPECT_EQ(e.polygons, nfp.polygons());
    EXPECT_EQ(e.slits, nfp.slits());
    EXPECT_EQ(e.points, nfp.points());
    EXPECT_EQ(per_query.no_fit_polygon().polygons, nfp.polygons());  // built on demand
  }
}

TEST(Pair2, RealNestingPiecesEveryEngineAgrees) {
  const auto pieces = nonconvex2_test::instance("trousers.json");
  std::mt19937_64 rng(5);
  for (std::size_t a = 0; a < pieces.size() && a < 8; ++a)
    for (std::size_t b = 0; b < pieces.size() && b < 8; b += 3) {
      const Shape2 P = shape_of(pieces[a]), Q = shape_of(pieces[b]);
      const Pair2 x(P, Q, Prepare::Queries), y(P, Q, Prepare::Full);
      for (const Vec2& t : placements(rng, P, Q, 16)) {
        const Depth2 rx = x.minimum(t), ry = y.minimum(t);
        ASSERT_EQ(rx.overlapping, ry.overlapping);
        ASSERT_NEAR(rx.depth, ry.depth, 1e-12 * (1 + rx.depth));
        ASSERT_EQ(x.overlapping(t), rx.overlapping);
      }
    }
}

// ---- role swap ----

// Distance from x to the boundary of the shape S placed at o.
double boundary_distance(const Shape2& S, const Vec2& x, const Vec2& o) {
  double best = 1e300;
  for (const auto& r : S.rings())
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Vec2 a = r[i] + o, b = r[(i + 1) % r.size()] + o;
      const double u = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      best = std::min(best, (a + u * (b - a) - x).norm());
    }
  return best;
}

// Q the polygon, P convex: the pair answers as if the polygon were fixed and maps back. Checked
// against the direct problem (the polygon fixed, the convex shape at −t) and by properties in the
// user's frame: after the move the shapes touch, each witness lies on its own shape's boundary,
// and a shorter move overlaps.
TEST(Pair2, RoleSwapBothWays) {
  std::mt19937_64 rng(6);
  int nonconvex = 0;
  for (int trial = 0; trial < 16; ++trial) {
    const Polygon A = polygon2_test::random_polygon(rng, 8 + int(rng() % 16), int(rng() % 2), trial % 2 == 0);
    const ConvexPolygon B = polygon2_test::random_convex(rng, 3 + int(rng() % 6), 1.5, trial % 2 == 0);
    const Shape2 N = shape_of(A), C(B);
    if (N.is_convex()) continue;  // a convex star: no polygon engine
    ++nonconvex;
    const Pair2 direct(N, C), swapped(C, N);
    ASSERT_EQ(swapped.engine(), Engine2::PolygonConvexSwapped);
    const auto ts = placements(rng, C, N, 30);
    const auto ds = directions(rng, ts.size());
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const Vec2 t = ts[i];
      const Depth2 s = swapped.minimum(t), r = direct.minimum(-t);
      ASSERT_EQ(swapped.overlapping(t), direct.overlapping(-t));
      ASSERT_EQ(s.overlapping, r.overlapping);
      ASSERT_TRUE(same_bits(s.depth, r.depth));
      ASSERT_EQ(s.translation, Vec2(-r.translation));
      ASSERT_EQ(s.feature_p, r.feature_q);
      ASSERT_EQ(s.feature_q, r.feature_p);
      const double eps = 1e-9 * (1 + t.norm() + s.depth);
      if (s.overlapping) {
        // After the move Q touches P: the depth there is 0 up to the rounding of t + v (σ is
        // 1-Lipschitz in t), the witnesses coincide, lie on P's boundary and on the moved Q's,
        // and any shorter move along v still overlaps (the open disk of radius σ lies in O).
        ASSERT_LE(swapped.minimum(t + s.translation).depth, eps) << "trial " << trial << " i " << i;
        ASSERT_LE((s.witness_p - s.witness_q).norm(), eps);
        ASSERT_LE(boundary_distance(C, s.witness_p, Vec2(0, 0)), eps);
        ASSERT_LE(boundary_distance(N, s.witness_q, Vec2(t + s.translation)), eps);
        if (s.depth > 1e-6) ASSERT_TRUE(swapped.overlapping(t + 0.99 * s.translation));
      }
      const Depth2 a = swapped.along(t, ds[i]), b = direct.along(-t, -ds[i]);
      ASSERT_TRUE(same_bits(a.depth, b.depth));
      ASSERT_EQ(a.translation, Vec2(-b.translation));
      if (a.overlapping) {
        ASSERT_LE(boundary_distance(C, a.witness_p, Vec2(0, 0)), eps);
        ASSERT_LE(boundary_distance(N, a.witness_q, Vec2(t + a.translation)), eps);
        if (a.depth > 1e-6) ASSERT_TRUE(swapped.overlapping(t + 0.99 * a.translation));
      }
      const Depth2 c = swapped.separation(t, ds[i]), e = direct.separation(-t, -ds[i]);
      ASSERT_TRUE(same_bits(c.depth, e.depth));
      ASSERT_EQ(c.translation, Vec2(-e.translation));
      // σ ≤ σ_d ≤ complete separation.
      ASSERT_LE(s.depth, a.depth * (1 + 1e-12) + 1e-300);
      ASSERT_LE(a.depth, c.depth * (1 + 1e-12) + 1e-300);
    }
  }
  EXPECT_GE(nonconvex, 10);
}

// ---- batches ----

template <class F>
void expect_batches_equal_singles(const Pair2& pair, const std::vector<Vec2>& ts, const std::vector<Vec2>& ds,
                                  F&& label) {
  for (unsigned threads : {1u, 2u, 8u, 0u}) {
    std::vector<Depth2> m(ts.size()), a(ts.size()), s(ts.size()), a1(ts.size());
    std::unique_ptr<bool[]> o(new bool[ts.size()]);
    pair.minimum(ts, m, threads);
    pair.along(ts, ds, a, threads);
    pair.along(ts, std::span<const Vec2>(ds.data(), 1), a1, threads);  // one direction for all
    pair.separation(ts, ds, s, threads);
    pair.overlapping(ts, std::span<bool>(o.get(), ts.size()), threads);
    for (std::size_t i = 0; i < ts.size(); ++i) {
      ASSERT_TRUE(same(m[i], pair.minimum(ts[i]))) << label() << " threads " << threads << " query " << i;
      ASSERT_TRUE(same(a[i], pair.along(ts[i], ds[i]))) << label() << " threads " << threads;
      ASSERT_TRUE(same(a1[i], pair.along(ts[i], ds[0]))) << label() << " threads " << threads;
      ASSERT_TRUE(same(s[i], pair.separation(ts[i], ds[i]))) << label() << " threads " << threads;
      ASSERT_EQ(o[i], pair.overlapping(ts[i])) << label() << " threads " << threads;
    }
  }
}

TEST(Pair2, BatchesEqualSingleCallsBitForBitAtAnyThreadCount) {
  std::mt19937_64 rng(7);
  const Shape2 C1(ring_of(polygon2_test::random_convex(rng, 12, 3, false)), {}, "C1");
  const Shape2 C2(ring_of(polygon2_test::random_convex(rng, 7, 2, false)), {}, "C2");
  const Shape2 N1 = shape_of(polygon2_test::random_polygon(rng, 16, 1, false));
  const Shape2 N2 = shape_of(polygon2_test::random_polygon(rng, 10, 0, false));
  const std::vector<std::pair<Shape2, Shape2>> pairs{{C1, C2}, {N1, C2}, {C1, N2}, {N1, N2}};
  for (const auto& [P, Q] : pairs)
    for (Prepare prep : {Prepare::Auto, Prepare::Queries, Prepare::Full}) {
      const Pair2 pair(P, Q, prep);
      const auto ts = placements(rng, P, Q, 200);
      const auto ds = directions(rng, ts.size());
      expect_batches_equal_singles(pair, ts, ds, [&] { return std::string(to_string(pair.engine())); });
    }
}

// ---- errors at the boundary ----

TEST(Pair2, BadQueriesAreNamed) {
  const Shape2 P(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}, "P");
  const Shape2 Q(std::vector<Vec2>{{0, 0}, {2, 0}, {1, 2}}, {}, "Q");
  const Pair2 pair(P, Q);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_NE(error_of([&] { pair.minimum(Vec2(nan, 0)); }).find("placement"), std::string::npos);
  EXPECT_NE(error_of([&] { pair.along(Vec2(1, 1), Vec2(0, 0)); }).find("direction is zero"), std::string::npos);
  EXPECT_NE(error_of([&] { pair.separation(Vec2(1, 1), Vec2(inf, 0)); }).find("not finite"), std::string::npos);
  std::vector<Vec2> ts{{1, 1}, {2, 2}, {inf, 3}};
  std::vector<Depth2> out(3), short_out(2);
  EXPECT_NE(error_of([&] { pair.minimum(ts, out); }).find("placement 2"), std::string::npos);
  ts[2] = Vec2(3, 3);
  EXPECT_NE(error_of([&] { pair.minimum(ts, short_out); }).find("room for 2"), std::string::npos);
  std::vector<Vec2> ds{{1, 0}, {0, 0}, {1, 1}};
  EXPECT_NE(error_of([&] { pair.along(ts, ds, out); }).find("direction 1"), std::string::npos);
  ds.pop_back();
  EXPECT_NE(error_of([&] { pair.along(ts, ds, out); }).find("2 directions for 3"), std::string::npos);
  // Nothing was written by a rejected batch.
  for (const Depth2& r : out) EXPECT_EQ(r.depth, 0);
  // Huge and tiny directions are the same direction (no overflow to NaN, no underflow to zero).
  const Depth2 a = pair.along(Vec2(1, 1), Vec2(0x1p1000, 0x1p1000)), b = pair.along(Vec2(1, 1), Vec2(0x1p-1060, 0x1p-1060));
  EXPECT_TRUE(same(a, pair.along(Vec2(1, 1), Vec2(1, 1))));
  EXPECT_TRUE(same(a, b));
  EXPECT_TRUE(std::isfinite(a.depth) && a.depth > 0);
}

TEST(Shape2, ValidationNamesTheShapeRingAndVertex) {
  EXPECT_NE(error_of([] { Shape2(std::vector<Vec2>{{0, 0}, {1, 0}}, {}, "tiny"); }).find("tiny"), std::string::npos);
  // A bow tie is neither convex nor simple: the polygon's error.
  const std::string bow = error_of([] { Shape2(std::vector<Vec2>{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}, "bow"); });
  EXPECT_NE(bow.find("bow"), std::string::npos);
  EXPECT_NE(bow.find("intersect"), std::string::npos) << bow;
  const std::string hole = error_of([] {
    Shape2(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{5, 5}, {6, 5}, {6, 6}}}, "plate");
  });
  EXPECT_NE(hole.find("plate"), std::string::npos);
  EXPECT_NE(hole.find("hole"), std::string::npos) << hole;
  const std::string nan = error_of([] {
    Shape2(std::vector<Vec2>{{0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0}, {0, 1}}, {}, "n");
  });
  EXPECT_NE(nan.find("finite"), std::string::npos) << nan;
  const std::string wkt = error_of([] { Shape2::from_wkt("POLYGON ((0 0, 1 0, 1 1, 0 0)", "text"); });
  EXPECT_EQ(wkt.rfind("text:", 0), 0u) << wkt;
  EXPECT_NE(error_of([] { Shape2::from_file("/nonexistent/x.wkt"); }).find("cannot read"), std::string::npos);
}

TEST(Shape2, KindsRingsAndInputVertices) {
  // Given clockwise with a collinear vertex: convex, normal form drops it; input_vertex maps back.
  const Shape2 sq(std::vector<Vec2>{{0, 0}, {0, 2}, {2, 2}, {2, 1}, {2, 0}}, {}, "sq");
  ASSERT_TRUE(sq.is_convex());
  EXPECT_EQ(sq.size(), 4u);
  EXPECT_EQ(sq.hole_count(), 0u);
  for (std::size_t i = 0; i < sq.size(); ++i) {
    const auto [ring, k] = sq.input_vertex(i);
    EXPECT_EQ(ring, 0u);
    const Vec2 given[] = {{0, 0}, {0, 2}, {2, 2}, {2, 1}, {2, 0}};
    EXPECT_EQ(given[k], sq.convex()[i]);
  }
  EXPECT_EQ(sq.polygon().size(), 4u);
  const Shape2 plate = Shape2::from_wkt("POLYGON ((0 0, 6 0, 6 6, 0 6), (2 2, 2 4, 4 4, 4 2))");
  EXPECT_FALSE(plate.is_convex());
  EXPECT_EQ(plate.hole_count(), 1u);
  EXPECT_EQ(plate.rings().size(), 2u);
  EXPECT_EQ(plate.input_vertex(5), (std::array<std::size_t, 2>{1, 1}));
  EXPECT_THROW(plate.convex(), std::logic_error);
  EXPECT_THROW(plate.input_vertex(8), InvalidInput);
  // Copies share the validated data.
  const Shape2 copy = plate;
  EXPECT_EQ(&copy.polygon(), &plate.polygon());
}

TEST(Shape2, RotatedByQuarterTurnsIsExactAndOtherAnglesRoundOnce) {
  const Shape2 plate = Shape2::from_wkt("POLYGON ((0 0, 6 0, 6 6, 0 6), (2 2, 2 4, 4 4, 4 2))", "plate");
  const Shape2 L = Shape2::from_wkt("POLYGON ((0 0, 3 0, 3 1, 1 1, 1 2, 0 2))", "L");
  for (const double deg : {90.0, -270.0, 450.0}) EXPECT_TRUE(Shape2::rotation_is_exact(deg));
  for (const double deg : {45.0, 1e-300, 89.999}) EXPECT_FALSE(Shape2::rotation_is_exact(deg));
  // A quarter turn maps (x, y) to (−y, x) exactly: the rings as a set of points.
  const Shape2 L90 = L.rotated(90);
  EXPECT_EQ(L90.name(), "L@90");
  auto points = [](const Shape2& s) {
    std::vector<std::array<double, 2>> out;
    for (const auto& r : s.rings())
      for (const Vec2& p : r) out.push_back({p.x(), p.y()});
    std::sort(out.begin(), out.end());
    return out;
  };
  std::vector<std::array<double, 2>> expected;
  for (const auto& r : L.rings())
    for (const Vec2& p : r) expected.push_back({-p.y(), p.x()});
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(points(L90), expected);
  EXPECT_EQ(points(L.rotated(90).rotated(270)), points(L));
  EXPECT_EQ(points(L.rotated(-90)), points(L.rotated(270)));
  // Rotating the whole scene by a quarter turn: the same depths, bit for bit, every engine.
  const Shape2 sq(std::vector<Vec2>{{0, 0}, {2, 0}, {2, 1}, {0, 1}}, {}, "sq");
  std::mt19937_64 rng(7);
  for (const auto& [P, Q] : {std::pair{plate, sq}, std::pair{L, sq}, std::pair{L, plate}, std::pair{sq, L}}) {
    const Pair2 a(P, Q), b(P.rotated(90), Q.rotated(90));
    for (const Vec2& t : placements(rng, P, Q, 40)) {
      const Vec2 t90(-t.y(), t.x());
      EXPECT_TRUE(same_bits(a.minimum(t).depth, b.minimum(t90).depth)) << P.name() << " " << Q.name() << " t " << t.transpose();
      EXPECT_EQ(a.overlapping(t), b.overlapping(t90));
    }
  }
  // Another angle: each coordinate rotated once with the rounded cos and sin.
  const double rad = 30.0 * std::numbers::pi / 180.0, c = std::cos(rad), s = std::sin(rad);
  const auto r30 = L.rotated(30).rings()[0], r0 = L.rings()[0];
  ASSERT_EQ(r30.size(), r0.size());
  std::vector<std::array<double, 2>> want;
  for (const Vec2& p : r0) want.push_back({c * p.x() - s * p.y(), s * p.x() + c * p.y()});
  std::vector<std::array<double, 2>> got;
  for (const Vec2& p : r30) got.push_back({p.x(), p.y()});
  std::sort(want.begin(), want.end()), std::sort(got.begin(), got.end());
  EXPECT_EQ(got, want);
  EXPECT_NE(error_of([&] { L.rotated(std::numeric_limits<double>::quiet_NaN()); }).find("L: rotation angle is not finite"),
            std::string::npos);
  EXPECT_THROW(L.rotated(std::numeric_limits<double>::infinity()), InvalidInput);
}

}  // namespace
