// PolygonDepth2 (DHS §4, §6): σ_d, complete separation and the overlap test against the exact CGAL
// union oracle (oracle.hpp), and the implicit convolved triangles against the convex-pair code.
// Inputs: random star-shaped polygons with and without holes (integer and real coordinates),
// combs whose pockets Q fits exactly, a polygon with collinear vertices, nesting pieces; placements
// random, on vertices/edges of the R_i and on vertices of ∂M; directions random, axis-parallel,
// parallel to P's and Q's edges. Pinned seeds.
#include <pendepth/depth2.hpp>
#include <pendepth/depth2_polygon_convex.hpp>

#include <gtest/gtest.h>

#include <cmath>

#include "../test_scale.hpp"
#include "oracle.hpp"
#include "polygon2/convolved_triangles.hpp"
#include "shapes.hpp"
#include "test_ulps.hpp"

namespace {

using pendepth::ConvexPolygon;
using pendepth::Polygon;
using pendepth::PolygonDepth2;
using pendepth::Vec2;
using polygon2_test::UnionOracle;

std::vector<std::array<Vec2, 3>> triangles_of(const Polygon& P) {
  std::vector<std::array<Vec2, 3>> out;
  for (const auto& t : pendepth::polygon2::triangulate(P)) out.push_back({P.vertices()[t[0]], P.vertices()[t[1]], P.vertices()[t[2]]});
  return out;
}

struct Stats {
  std::size_t queries = 0, overlapping = 0, positive_sep_outside = 0, slit = 0;
  double max_ulps = 0;
};

// Relative error in units of 2^-52 of `got` against the correctly rounded-ish `want`; an exact
// zero must be reproduced exactly.
double ulps(double a, double b) { return pendepth_test::ulps_of_want(a, b); }

void check_pair(const Polygon& P, const ConvexPolygon& Q, std::mt19937_64& rng, int random_queries, Stats& st,
                const std::string& what) {
  PolygonDepth2 query(P, Q);
  std::vector<Vec2> qv(Q.vertices().begin(), Q.vertices().end());
  UnionOracle oracle(triangles_of(P), qv);

  // Placements.
  std::vector<Vec2> ts;
  Vec2 lo = P.vertices()[0], hi = lo;
  for (const Vec2& p : P.vertices()) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Vec2 qlo = qv[0], qhi = qv[0];
  for (const Vec2& q : qv) {
    qlo = qlo.cwiseMin(q);
    qhi = qhi.cwiseMax(q);
  }
  lo -= qhi;
  hi -= qlo;
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y());
  for (int k = 0; k < random_queries; ++k) {
    Vec2 t(ux(rng), uy(rng));
    if (k % 2) t = Vec2(std::round(t.x()), std::round(t.y()));
    ts.push_back(t);
  }
  for (int k = 0; k < random_queries; ++k) {
    const Vec2& p = P.vertices()[rng() % P.size()];
    const Vec2& q = qv[rng() % qv.size()];
    ts.push_back(p - q);  // a vertex of some R_i
    std::size_t g = rng() % P.size();
    ts.push_back((P.vertices()[g] + P.vertices()[P.next(g)]) / 2 - q);  // on an edge of some R_i
  }
  auto bv = oracle.boundary_vertices();
  for (int k = 0; k < random_queries && !bv.empty(); ++k) ts.push_back(bv[rng() % bv.size()]);

  // Directions.
  std::vector<Vec2> ds{{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  std::uniform_int_distribution<int> ud(-5, 5);
  for (int k = 0; k < 4; ++k) {
    Vec2 d(ud(rng), ud(rng));
    if (d != Vec2(0, 0)) ds.push_back(d);
    std::size_t g = rng() % P.size();
    ds.push_back(P.vertices()[P.next(g)] - P.vertices()[g]);
    std::size_t j = rng() % qv.size();
    ds.push_back(qv[(j + 1) % qv.size()] - qv[j]);
  }
  ds.push_back({std::sqrt(2.0), 1 / 3.0});

  for (const Vec2& t : ts) {
    const bool inside = oracle.inside(t);
    const bool in_union = oracle.inside_union(t);
    ASSERT_TRUE(!inside || in_union) << what;  // O ⊆ int M
    st.slit += in_union && !inside;
    ASSERT_EQ(query.overlapping(t), inside) << what << " t=" << t.transpose();
    for (const Vec2& d : ds) {
      ++st.queries;
      auto r = query.along(t, d);
      ASSERT_EQ(r.overlapping, inside) << what;
      const double want = oracle.along(t, d);
      const double e = ulps(r.depth, want);
      ASSERT_LE(e, 16) << what << " along t=" << t.transpose() << " d=" << d.transpose() << " got " << r.depth
                       << " want " << want;
      st.max_ulps = std::max(st.max_ulps, e);
      st.overlapping += inside;
      if (inside) {
        EXPECT_NEAR(r.translation.norm(), r.depth, 1e-14 * r.depth);
        EXPECT_NEAR(r.normal.dot(d.normalized()), 1, 1e-15);
      }
      auto s = query.separation(t, d);
      const double want_s = oracle.separation(t, d);
      const double es = ulps(s.depth, want_s);
      ASSERT_LE(es, 16) << what << " separation t=" << t.transpose() << " d=" << d.transpose() << " got " << s.depth
                        << " want " << want_s;
      st.max_ulps = std::max(st.max_ulps, es);
      EXPECT_GE(s.depth, r.depth * (1 - 1e-15)) << what;
      st.positive_sep_outside += (!inside && want_s > 0);
    }
  }
}

ConvexPolygon random_convex(std::mt19937_64& rng, int m, double scale, bool grid) {
  for (;;) {
    auto pts = polygon2_test::star_ring(rng, m, Vec2(0, 0), scale / 2, scale, grid);
    try {
      return ConvexPolygon::hull(pts, "Q");
    } catch (const pendepth::InvalidInput&) {
    }
  }
}

TEST(PolygonDepth, RandomPolygonsWithHolesAgainstExactUnion) {
  std::mt19937_64 rng(4242);
  Stats st;
  // Debug/sanitizer builds visit every kDivisor-th case (same seeds and shapes, fewer of them).
  for (int it = 0; it < 24; it += pendepth_test::kDivisor) {
    Polygon P = polygon2_test::random_polygon(rng, 6 + it % 19, it % 4, it % 2 == 0);
    ConvexPolygon Q = random_convex(rng, 3 + it % 8, 5 + it % 30, it % 3 == 0);
    check_pair(P, Q, rng, 12, st, "random " + std::to_string(it));
  }
  std::printf("random: %zu ray queries (%zu overlapping, %zu with separation > 0 from outside), max error %.2f ulps\n",
              st.queries, st.overlapping, st.positive_sep_outside, st.max_ulps);
  EXPECT_GT(st.overlapping, st.queries / 5);
  EXPECT_GT(st.positive_sep_outside, 0u);
}

TEST(PolygonDepth, NestingPiecesAgainstExactUnion) {
  std::mt19937_64 rng(99);
  Stats st;
  for (const char* f : {"albano.json", "shirts.json", "trousers.json"}) {
    auto pieces = polygon2_test::nesting_pieces(f);
    for (std::size_t k = 0; k < pieces.size(); k += 3 * pendepth_test::kDivisor) {
      Polygon P = Polygon::simple(pieces[k], f);
      ConvexPolygon Q = ConvexPolygon::hull(pieces[(k + 1) % pieces.size()], f);
      check_pair(P, Q, rng, 6, st, std::string(f) + " #" + std::to_string(k));
    }
  }
  std::printf("nesting: %zu ray queries (%zu overlapping), max error %.2f ulps\n", st.queries, st.overlapping, st.max_ulps);
}

TEST(PolygonDepth, CombPocketsExactFitAndCollinearVertices) {
  // Pockets 3 wide between teeth 2 wide, base [0, 17] x [0, 2], teeth up to y = 12; Q = [0, 3]^2.
  const Polygon comb = Polygon::simple(polygon2_test::comb_ring(4, 2, 3, 10, 2));
  const ConvexPolygon sq{{0, 0}, {3, 0}, {3, 3}, {0, 3}};
  PolygonDepth2 query(comb, sq);
  for (double y : {2.0, 2.5, 6.0, 9.0, 12.0}) {  // Q fits the slot exactly: touching both sides
    EXPECT_FALSE(query.overlapping({2, y}));
    EXPECT_EQ(query.along({2, y}, {0, 1}).depth, 0);
    EXPECT_EQ(query.along({2, y}, {0, -1}).depth, 0);
    EXPECT_FALSE(query.along({2, y}, {0, 1}).overlapping);
  }
  // Dipping 0.5 into the base: analytic answers.
  EXPECT_EQ(query.along({2, 1.5}, {0, 1}).depth, 0.5);
  EXPECT_EQ(query.along({2, 1.5}, {0, -7}).depth, 4.5);
  EXPECT_EQ(query.along({2, 1.5}, {1, 0}).depth, 15);
  EXPECT_EQ(query.along({2, 1.5}, {-1, 0}).depth, 5);
  // Shifted 0.25 into the right tooth: up the slot the overlap persists to the top of the teeth.
  EXPECT_EQ(query.along({2.25, 5}, {0, 1}).depth, 7);
  EXPECT_EQ(query.along({2.25, 5}, {-1, 0}).depth, 0.25);
  EXPECT_EQ(query.separation({2.25, 5}, {1, 0}).depth, 14.75);
  // From outside, the ray crosses the comb: down the slot (touching only) and through the base
  // until Q is below it; from below, up through the base and tooth 0.
  EXPECT_EQ(query.separation({2, 20}, {0, -1}).depth, 23);
  EXPECT_EQ(query.separation({0.5, -10}, {0, 1}).depth, 22);
  EXPECT_FALSE(query.separation({0.5, -10}, {0, 1}).overlapping);

  std::mt19937_64 rng(7);
  Stats st;
  check_pair(comb, sq, rng, 20, st, "comb/square");
  check_pair(comb, ConvexPolygon{{0, 0}, {3, 0}, {1.5, 2}}, rng, 10, st, "comb/triangle");
  std::vector<Vec2> outer, hole;
  for (int i = 0; i < 10; ++i) outer.push_back({double(i), 0});
  for (int i = 0; i < 10; ++i) outer.push_back({10, double(i)});
  for (int i = 10; i > 0; --i) outer.push_back({double(i), 10});
  for (int i = 10; i > 0; --i) outer.push_back({0, double(i)});
  for (int i = 3; i < 7; ++i) hole.push_back({double(i), 3});
  for (int i = 3; i < 7; ++i) hole.push_back({7, double(i)});
  for (int i = 7; i > 3; --i) hole.push_back({double(i), 7});
  for (int i = 7; i > 3; --i) hole.push_back({3, double(i)});
  const Polygon framed({outer, hole});
  check_pair(framed, sq, rng, 15, st, "collinear frame/square");
  check_pair(framed, ConvexPolygon{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, rng, 15, st, "collinear frame/hole-sized square");
  std::printf("degenerate: %zu ray queries (%zu overlapping), %zu placements in int M touching only, max error %.2f ulps\n",
              st.queries, st.overlapping, st.slit, st.max_ulps);
  EXPECT_GT(st.slit, 0u);
}

// The implicit R_i against the convex-pair code run on the explicit triangle.
TEST(ConvolvedTriangles, MatchConvexDirectionalDepth) {
  std::mt19937_64 rng(31337);
  std::size_t checked = 0;
  for (int it = 0; it < 30; ++it) {
    Polygon P = polygon2_test::random_polygon(rng, 5 + it % 10, it % 3, it % 2 == 0);
    ConvexPolygon Q = random_convex(rng, 3 + it % 12, 10 + it, it % 2 == 1);
    pendepth::polygon2::ConvolvedTriangles R(P, Q);
    for (std::size_t i = 0; i < R.size(); ++i) {
      const auto& id = R.triangle(i);
      ConvexPolygon T{P.vertices()[id[0]], P.vertices()[id[1]], P.vertices()[id[2]]};
      for (int k = 0; k < 6; ++k) {
        // Placements near the triangle, half of them on vertices of R_i.
        Vec2 t = P.vertices()[id[rng() % 3]] - Q[rng() % Q.size()];
        if (k % 2) t += Vec2(double(rng() % 21) - 10, double(rng() % 21) - 10) / 2;
        Vec2 d(double(rng() % 11) - 5, double(rng() % 11) - 5);
        if (d == Vec2(0, 0)) d = Vec2(1, 0);
        auto ref = pendepth::directional_depth(T, Q, t, d);
        ASSERT_EQ(R.contains_interior(i, t), ref.overlapping);
        pendepth::polygon2::Cut en, ex;
        const bool hit = R.line_interval(i, t, d, en, ex);
        if (ref.overlapping) {
          ASSERT_TRUE(hit);
          ASSERT_LT(pendepth::polygon2::cut_sign(en, t, d), 0);
          ASSERT_GT(pendepth::polygon2::cut_sign(ex, t, d), 0);
          EXPECT_LE(ulps(pendepth::polygon2::cut_value(ex, t, d) * d.norm(), ref.depth), 8);
          auto back = pendepth::directional_depth(T, Q, t, -d);
          EXPECT_LE(ulps(-pendepth::polygon2::cut_value(en, t, d) * d.norm(), back.depth), 8);
          ++checked;
        } else if (hit) {
          EXPECT_FALSE(pendepth::polygon2::cut_sign(en, t, d) < 0 && pendepth::polygon2::cut_sign(ex, t, d) > 0);
        }
      }
    }
  }
  EXPECT_GT(checked, 500u);
}

TEST(PolygonDepth, InvalidQueries) {
  PolygonDepth2 q(Polygon::simple(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 4}, {0, 4}}), ConvexPolygon{{0, 0}, {1, 0}, {0, 1}});
  EXPECT_THROW(q.along({1, 1}, {0, 0}), pendepth::InvalidInput);
  EXPECT_THROW(q.along({NAN, 1}, {1, 0}), pendepth::InvalidInput);
  EXPECT_THROW(q.separation({1, 1}, {INFINITY, 0}), pendepth::InvalidInput);
  EXPECT_THROW(q.overlapping({1, INFINITY}), pendepth::InvalidInput);
  // Huge and tiny directions give the same answer as a unit one.
  EXPECT_LE(ulps(q.along({1, 1}, {1e300, 0}).depth, 3), 4);
  EXPECT_LE(ulps(q.along({1, 1}, {1e-310, 0}).depth, 3), 4);
  EXPECT_LE(ulps(q.along({1, 1}, {-1e-310, 1e-310}).depth, 2 * std::sqrt(2.0)), 4);
}

}  // namespace
