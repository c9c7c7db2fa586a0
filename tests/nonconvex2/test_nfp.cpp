// NoFitPolygon2 (issue 5 item 4): the exported cl(O) against the independent exact CGAL oracle
// (area, and every vertex of ours a vertex of the oracle's rings and every oracle vertex on our
// boundary), and every query (overlap, σ_d, σ) against PairDepth2, a second algorithm that never
// builds the boundary (itself checked against the oracle in test_pair_depth.cpp). Inputs: random
// star pairs (with holes in P or Q, integer and real coordinates), combs that fit each other, a slot
// of Q's width (a slit), a hole Q fits exactly (an isolated point), collinear contacts, every
// ordered pair of albano and pairs of shirts and trousers, large offsets, placements on vertices
// of ∂O. The documented semantics of slits and isolated points are checked explicitly. Pinned seeds.
#include <pendepth/depth2_polygon_polygon.hpp>
#include <pendepth/nfp2.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include "nfp_shapes.hpp"
#include "oracle.hpp"
#include "polygon2/shapes.hpp"
#include "test_scale.hpp"
#include "test_ulps.hpp"

namespace {

using nonconvex2_test::instance;
using nonconvex2_test::PairOracle;
using nonconvex2_test::shifted;
using nonconvex2_test::star;
using pendepth::Depth2;
using pendepth::NoFitPolygon2;
using pendepth::PairDepth2;
using pendepth::Polygon;
using pendepth::Vec2;

constexpr double kMaxUlps = 8;

double ulps(double a, double b) { return pendepth_test::ulps_of_want(a, b); }

struct Stats {
  std::size_t pairs = 0, placements = 0, overlapping = 0, along = 0, minimum = 0, vertices = 0, rings = 0, slits = 0, points = 0;
  std::size_t pieces = 0, candidates = 0;
  double max_along = 0, max_min = 0, max_area = 0;
  double t_build = 0, t_along = 0, t_min = 0, t_pd_along = 0, t_pd_min = 0;
};
Stats& totals() {
  static Stats s;
  return s;
}

template <class F>
auto timed(double& acc, F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  auto r = f();
  acc += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

double seg_dist(const Vec2& x, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double u = l2 > 0 ? std::clamp((x - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (x - a - u * ab).norm();
}

double feature_distance(const Polygon& S, const pendepth::Feature& f, const Vec2& offset, const Vec2& x) {
  const Vec2 a = S.vertices()[f.index] + offset;
  if (f.kind == pendepth::FeatureKind::Vertex) return (x - a).norm();
  return seg_dist(x, a, S.vertices()[S.next(f.index)] + offset);
}

// The reported contact is a real touching contact (as in test_pair_depth.cpp).
void check_contact(const Polygon& P, const Polygon& Q, const Vec2& t, const Depth2& r, const std::string& what) {
  if (r.depth == 0) return;
  ASSERT_NE(r.feature_p.kind, pendepth::FeatureKind::None) << what;
  ASSERT_NE(r.feature_q.kind, pendepth::FeatureKind::None) << what;
  const double scale = 1e-9 * (1 + t.norm() + r.depth + P.vertices()[0].norm() + Q.vertices()[0].norm());
  EXPECT_LE(feature_distance(P, r.feature_p, Vec2(0, 0), r.witness_p), scale) << what;
  EXPECT_LE(feature_distance(Q, r.feature_q, t + r.translation, r.witness_q), scale) << what;
  EXPECT_LE((r.witness_p - r.witness_q).norm(), scale) << what;
}

// The exported rings against CGAL's exact cl(O).
void check_rings(const NoFitPolygon2& nfp, const PairOracle& oracle, const std::string& what) {
  Stats& st = totals();
  double area = 0, scale = 0;
  std::vector<std::pair<Vec2, Vec2>> segs;
  std::vector<Vec2> ours;
  for (const auto& poly : nfp.polygons()) {
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const auto& ring = poly[k];
      ASSERT_GE(ring.size(), 3u) << what;
      double a = 0;  // shoelace relative to the ring's first vertex (no cancellation at large offsets)
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Vec2 &p = ring[i], &q = ring[(i + 1) % ring.size()];
        const Vec2 u = p - ring[0], v = q - ring[0];
        a += u.x() * v.y() - u.y() * v.x();
        segs.push_back({p, q});
        ours.push_back(p);
        scale = std::max(scale, p.cwiseAbs().maxCoeff());
      }
      if (k == 0) EXPECT_GT(a, 0) << what << ": outer rings are CCW";
      else EXPECT_LT(a, 0) << what << ": holes are CW";
      area += a / 2;
    }
  }
  const double want = oracle.closure_area();
  const double rel = std::abs(area - want) / std::max(std::abs(want), 1e-300);
  st.max_area = std::max(st.max_area, rel);
  EXPECT_LE(rel, 1e-9) << what << " area " << area << " want " << want;
  const auto theirs = oracle.closure_vertices();
  const double tol = (1 + scale) * 1e-12;
  for (const Vec2& p : ours) {
    double best = INFINITY;
    for (const Vec2& q : theirs) best = std::min(best, (p - q).cwiseAbs().maxCoeff());
    EXPECT_LE(best, tol) << what << ": our vertex " << p.transpose() << " is no vertex of cl(O)";
  }
  for (const Vec2& q : theirs) {
    double best = INFINITY;
    for (const auto& [a, b] : segs) best = std::min(best, seg_dist(q, a, b));
    EXPECT_LE(best, tol) << what << ": oracle vertex " << q.transpose() << " not on our boundary";
  }
  st.vertices += ours.size();
}

// Every query of the no-fit polygon against PairDepth2.
void check_queries(const Polygon& P, const Polygon& Q, const NoFitPolygon2& nfp, const PairDepth2& pd, std::mt19937_64& rng, int nt,
                   int nd, const std::string& what) {
  Stats& st = totals();
  Vec2 lo = P.vertices()[0] - Q.vertices()[0], hi = lo;
  for (const Vec2& p : P.vertices())
    for (const Vec2& q : Q.vertices()) {
      lo = lo.cwiseMin(p - q);
      hi = hi.cwiseMax(p - q);
    }
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y());
  std::vector<Vec2> ts;
  for (int k = 0; k < nt; ++k) {
    Vec2 t(ux(rng), uy(rng));
    if (k % 4 == 1) t = Vec2(std::round(t.x()), std::round(t.y()));
    if (k % 4 == 2) t = P.vertices()[rng() % P.size()] - Q.vertices()[rng() % Q.size()];
    ts.push_back(t);
  }
  // Vertices of ∂O (exact when the rounding is exact, e.g. integer inputs) and points just inside.
  for (const auto& poly : nfp.polygons())
    for (const auto& ring : poly)
      for (std::size_t i = 0; i < ring.size(); i += 1 + ring.size() / 6) {
        ts.push_back(ring[i]);
        ts.push_back(ring[i] + 1e-7 * (ring[(i + 1) % ring.size()] - ring[i]) + 1e-7 * (ring[(i + ring.size() - 1) % ring.size()] - ring[i]));
      }
  std::uniform_real_distribution<double> ua(0, 2 * polygon2_test::kPi);
  for (const Vec2& t : ts) {
    const bool ov = nfp.overlapping(t);
    ASSERT_EQ(ov, pd.overlapping(t)) << what << " t=" << t.transpose();
    ++st.placements;
    st.overlapping += ov;
    for (int k = 0; k < nd; ++k) {
      Vec2 d;
      if (k % 3 == 0) {
        const double a = ua(rng);
        d = Vec2(std::cos(a), std::sin(a));
      } else if (k % 3 == 1) {
        const std::size_t g = rng() % P.size();
        d = P.vertices()[P.next(g)] - P.vertices()[g];
      } else {
        d = k % 2 ? Vec2(1, 0) : Vec2(0, -1);
      }
      const Depth2 a = timed(st.t_along, [&] { return nfp.along(t, d); });
      const Depth2 b = timed(st.t_pd_along, [&] { return pd.along(t, d); });
      ++st.along;
      const double e = ulps(a.depth, b.depth);
      st.max_along = std::max(st.max_along, e);
      ASSERT_LE(e, kMaxUlps) << what << " along t=" << t.transpose() << " d=" << d.transpose() << " got " << a.depth << " want " << b.depth;
      EXPECT_EQ(a.overlapping, b.overlapping) << what;
      EXPECT_EQ(a.kind, b.kind) << what;
      check_contact(P, Q, t, a, what + " along");
    }
    if (ov) {
      const Depth2 m = timed(st.t_min, [&] { return nfp.minimum(t); });
      const Depth2 w = timed(st.t_pd_min, [&] { return pd.minimum(t); });
      ++st.minimum;
      const double e = ulps(m.depth, w.depth);
      st.max_min = std::max(st.max_min, e);
      ASSERT_LE(e, kMaxUlps) << what << " minimum t=" << t.transpose() << " got " << m.depth << " want " << w.depth;
      EXPECT_EQ(m.kind, w.kind);
      EXPECT_TRUE(m.overlapping);
      check_contact(P, Q, t, m, what + " minimum");
    } else {
      EXPECT_EQ(nfp.minimum(t).depth, 0) << what;
    }
  }
}

void check_all(const Polygon& P, const Polygon& Q, std::mt19937_64& rng, int nt, int nd, const std::string& what) {
  Stats& st = totals();
  const NoFitPolygon2 nfp = timed(st.t_build, [&] { return NoFitPolygon2(P, Q); });
  const PairDepth2 pd(P, Q);
  const PairOracle oracle(P, Q);
  ++st.pairs;
  const auto sz = nfp.size();
  st.rings += sz.rings;
  st.slits += sz.slits;
  st.points += sz.points;
  st.pieces += sz.pieces;
  st.candidates += sz.candidates;
  EXPECT_GT(sz.bytes, 0u);
  check_rings(nfp, oracle, what);
  check_queries(P, Q, nfp, pd, rng, nt, nd, what);
}

TEST(NoFitPolygon2, RandomStarPairs) {
  std::mt19937_64 rng(20261121);
  for (int it = 0; it < pendepth_test::scaled(24); ++it) {
    const bool grid = it % 2;
    const Polygon P = it % 3 == 0 ? polygon2_test::random_polygon(rng, 10 + int(rng() % 10), 1 + int(rng() % 2), grid)
                                  : star(rng, 8 + int(rng() % 16), 50, 100, grid);
    const Polygon Q = it % 4 == 3 ? polygon2_test::random_polygon(rng, 8, 1, grid) : star(rng, 5 + int(rng() % 10), 15, 45, grid);
    check_all(P, Q, rng, 30, 3, "random " + std::to_string(it));
  }
}

// Small integer stars: many parallel, collinear and coincident edges, touching parts of O, slits.
TEST(NoFitPolygon2, SmallGridPairsDegenerate) {
  std::mt19937_64 rng(4711);
  for (int it = 0; it < pendepth_test::scaled(60); ++it) {
    const Polygon P = star(rng, 5 + int(rng() % 6), 2, 6, true);
    const Polygon Q = it % 3 == 0 ? P : star(rng, 4 + int(rng() % 5), 1, 4, true);
    check_all(P, Q, rng, 20, 3, "grid " + std::to_string(it));
  }
}

// Rectilinear histograms (nfp_shapes.hpp) against each other and turned by 180°: antiparallel
// edge pairs everywhere (redundant collinear candidates), straight vertices, exact fits.
TEST(NoFitPolygon2, RectilinearHistograms) {
  std::mt19937_64 rng(5151);
  for (int it = 0; it < pendepth_test::scaled(40); ++it) {
    const Polygon P = nonconvex2_test::histogram(rng, 2 + int(rng() % 6), 4), Q = nonconvex2_test::histogram(rng, 1 + int(rng() % 4), 3);
    const Polygon R = nonconvex2_test::mapped(Q, [](const Vec2& p) { return Vec2(-p); });
    check_all(P, Q, rng, 20, 3, "histograms " + std::to_string(it));
    check_all(P, R, rng, 20, 3, "histogram / turned " + std::to_string(it));
  }
}

TEST(NoFitPolygon2, LargeOffsets) {
  std::mt19937_64 rng(8086);
  for (int it = 0; it < pendepth_test::scaled(4); ++it) {
    const Vec2 o(1e6 * (1 + it), -3e5 * it);
    const Polygon P = shifted(star(rng, 12, 50, 100, it % 2), o);
    const Polygon Q = shifted(star(rng, 7, 15, 45, it % 2), Vec2(-2e5, 7e5));
    check_all(P, Q, rng, 30, 3, "offset " + std::to_string(it));
  }
}

// P: comb with pockets gw wide; Q: comb with teeth gw wide, upside down, fitting at t0.
TEST(NoFitPolygon2, CombsFitExactly) {
  constexpr double tw = 3, gw = 2, h = 5, base = 2;
  const Polygon P = Polygon::simple(polygon2_test::comb_ring(4, tw, gw, h, base), "comb P");
  auto r = polygon2_test::comb_ring(3, gw, tw, h, base);
  for (auto& p : r) p = Vec2(p.x(), -p.y());
  const Polygon Q = Polygon::simple(r, "comb Q");
  const Vec2 t0(tw, 2 * base + h);
  const NoFitPolygon2 nfp(P, Q);
  // Q's teeth slide out of P's pockets upwards, touching: a slit from t0 up by h.
  bool found = false;
  for (const auto& s : nfp.slits()) {
    const Vec2 a = s[0].y() < s[1].y() ? s[0] : s[1], b = s[0].y() < s[1].y() ? s[1] : s[0];
    if (a == t0 && b == t0 + Vec2(0, h)) found = true;
  }
  EXPECT_TRUE(found);
  EXPECT_FALSE(nfp.overlapping(t0));
  for (double s : {0.25, 0.5, 1.5}) {
    EXPECT_EQ(nfp.along(t0 - Vec2(0, s), Vec2(0, 1)).depth, s);
    EXPECT_EQ(nfp.minimum(t0 - Vec2(0, s)).depth, s);
    EXPECT_EQ(nfp.minimum(t0 + Vec2(s / 4, 0)).depth, s / 4);
  }
  std::mt19937_64 rng(4243);
  check_all(P, Q, rng, pendepth_test::scaled(60), 3, "combs");
}

// A slot of exactly Q's width: the slit (2, 2)–(2, 8); depth 0 on it, the distance to it next to it.
TEST(NoFitPolygon2, SlotIsASlit) {
  const Polygon P = Polygon::simple(std::vector<Vec2>{{0, 0}, {7, 0}, {7, 8}, {5, 8}, {5, 2}, {2, 2}, {2, 8}, {0, 8}}, "U");
  const Polygon Q = Polygon::simple(std::vector<Vec2>{{0, 0}, {3, 0}, {3, 1}, {0, 1}}, "block");
  const NoFitPolygon2 nfp(P, Q);
  ASSERT_EQ(nfp.slits().size(), 1u);
  const auto s = nfp.slits()[0];
  EXPECT_TRUE((s[0] == Vec2(2, 2) && s[1] == Vec2(2, 8)) || (s[1] == Vec2(2, 2) && s[0] == Vec2(2, 8)));
  EXPECT_TRUE(nfp.points().empty());
  ASSERT_EQ(nfp.polygons().size(), 1u);
  EXPECT_EQ(nfp.polygons()[0].size(), 1u);  // no holes: the slit hangs from the outer ring
  for (double y : {2.0, 3.5, 7.0, 8.0}) {
    const Vec2 t(2, y);
    EXPECT_FALSE(nfp.overlapping(t));
    EXPECT_EQ(nfp.minimum(t).depth, 0);
    EXPECT_EQ(nfp.along(t, Vec2(1, 1)).depth, 0);
    for (double e : {0.125, 0.25}) {
      if (y == 8.0) continue;
      EXPECT_TRUE(nfp.overlapping(t + Vec2(e, 0)));
      EXPECT_EQ(nfp.minimum(t + Vec2(e, 0)).depth, e);
      EXPECT_EQ(nfp.minimum(t - Vec2(e, 0)).depth, e);
      EXPECT_EQ(nfp.along(t + Vec2(e, 0), Vec2(-1, 0)).depth, e);
    }
  }
  std::mt19937_64 rng(100);
  check_all(P, Q, rng, pendepth_test::scaled(60), 3, "slot");
}

// Q fits a hole of P exactly: the isolated point (4, 4); a larger hole gives a hole of cl(O).
TEST(NoFitPolygon2, HoleFitIsAnIsolatedPoint) {
  const std::vector<Vec2> outer{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Polygon Q = Polygon::simple(std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, "square");
  {
    const Polygon P({outer, {{4, 4}, {6, 4}, {6, 6}, {4, 6}}}, "plate");
    const NoFitPolygon2 nfp(P, Q);
    ASSERT_EQ(nfp.points().size(), 1u);
    EXPECT_EQ(nfp.points()[0], Vec2(4, 4));
    EXPECT_TRUE(nfp.slits().empty());
    ASSERT_EQ(nfp.polygons().size(), 1u);
    EXPECT_EQ(nfp.polygons()[0].size(), 1u);
    EXPECT_FALSE(nfp.overlapping(Vec2(4, 4)));
    EXPECT_EQ(nfp.minimum(Vec2(4, 4)).depth, 0);
    EXPECT_EQ(nfp.along(Vec2(4, 4), Vec2(1, 0)).depth, 0);
    for (const Vec2& e : {Vec2(0.25, 0), Vec2(0, -0.5), Vec2(0.25, 0.25)}) {
      EXPECT_TRUE(nfp.overlapping(Vec2(4, 4) + e));
      EXPECT_EQ(nfp.minimum(Vec2(4, 4) + e).depth, e.norm());
      EXPECT_EQ(nfp.along(Vec2(4, 4) + e, -e).depth, e.norm());
    }
    std::mt19937_64 rng(7);
    check_all(P, Q, rng, pendepth_test::scaled(40), 3, "hole fit");
  }
  {
    const Polygon P({outer, {{3, 3}, {7, 3}, {7, 7}, {3, 7}}}, "plate");
    const NoFitPolygon2 nfp(P, Q);
    ASSERT_EQ(nfp.polygons().size(), 1u);
    ASSERT_EQ(nfp.polygons()[0].size(), 2u);
    EXPECT_EQ(nfp.polygons()[0][1].size(), 4u);
    EXPECT_FALSE(nfp.overlapping(Vec2(4, 4)));
    EXPECT_EQ(nfp.minimum(Vec2(2.5, 4)).depth, 0.5);
    std::mt19937_64 rng(8);
    check_all(P, Q, rng, pendepth_test::scaled(40), 3, "hole");
  }
}

// A chamber reached through a neck exactly Q's width: free placements in the chamber form a hole of
// cl(O), joined to the outside by the slit of the neck (a slit touching a hole and the outer ring).
TEST(NoFitPolygon2, BottleNeckSlitJoinsHoleAndOutside) {
  const Polygon P = Polygon::simple(
      std::vector<Vec2>{{0, 0}, {10, 0}, {10, 10}, {6, 10}, {6, 7}, {7, 7}, {7, 3}, {3, 3}, {3, 7}, {4, 7}, {4, 10}, {0, 10}}, "bottle");
  const Polygon Q = Polygon::simple(std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, "square");
  const NoFitPolygon2 nfp(P, Q);
  ASSERT_EQ(nfp.slits().size(), 1u);
  const auto s = nfp.slits()[0];
  EXPECT_TRUE((s[0] == Vec2(4, 5) && s[1] == Vec2(4, 10)) || (s[1] == Vec2(4, 5) && s[0] == Vec2(4, 10)));
  ASSERT_EQ(nfp.polygons().size(), 1u);
  ASSERT_EQ(nfp.polygons()[0].size(), 2u);
  std::vector<Vec2> hole = nfp.polygons()[0][1];
  std::sort(hole.begin(), hole.end(), [](const Vec2& a, const Vec2& b) { return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y(); });
  EXPECT_EQ(hole, (std::vector<Vec2>{{3, 3}, {3, 5}, {5, 3}, {5, 5}}));
  EXPECT_FALSE(nfp.overlapping(Vec2(4, 8)));
  EXPECT_EQ(nfp.minimum(Vec2(4.25, 8)).depth, 0.25);
  EXPECT_EQ(nfp.minimum(Vec2(4, 5.5)).depth, 0);
  EXPECT_EQ(nfp.along(Vec2(3.75, 9), Vec2(1, 0)).depth, 0.25);
  std::mt19937_64 rng(12);
  check_all(P, Q, rng, pendepth_test::scaled(60), 3, "bottle");
}

// A closed slot (a hole of P) exactly Q's height: a slit surrounded by O, touching no ring.
TEST(NoFitPolygon2, ClosedSlotIsAFreeSlit) {
  const Polygon P({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{3, 4}, {7, 4}, {7, 5}, {3, 5}}}, "plate with a slot");
  const Polygon Q = Polygon::simple(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "unit");
  const NoFitPolygon2 nfp(P, Q);
  ASSERT_EQ(nfp.slits().size(), 1u);
  const auto s = nfp.slits()[0];
  EXPECT_TRUE((s[0] == Vec2(3, 4) && s[1] == Vec2(6, 4)) || (s[1] == Vec2(3, 4) && s[0] == Vec2(6, 4)));
  EXPECT_TRUE(nfp.points().empty());
  ASSERT_EQ(nfp.polygons().size(), 1u);
  EXPECT_EQ(nfp.polygons()[0].size(), 1u);
  EXPECT_EQ(nfp.minimum(Vec2(4, 4)).depth, 0);
  EXPECT_EQ(nfp.minimum(Vec2(4, 4.25)).depth, 0.25);
  EXPECT_EQ(nfp.minimum(Vec2(2.5, 4)).depth, 0.5);  // nearest: the slit's end (3, 4)
  EXPECT_EQ(nfp.along(Vec2(4, 3.5), Vec2(0, 1)).depth, 0.5);
  std::mt19937_64 rng(13);
  check_all(P, Q, rng, pendepth_test::scaled(60), 3, "closed slot");
}

TEST(NoFitPolygon2, CollinearContacts) {
  const Polygon P = Polygon::simple(std::vector<Vec2>{{0, 0}, {2, 0}, {4, 0}, {4, 2}, {0, 2}}, "rect with a collinear vertex");
  const Polygon Q = Polygon::simple(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "unit");
  const NoFitPolygon2 nfp(P, Q);
  ASSERT_EQ(nfp.polygons().size(), 1u);
  EXPECT_EQ(nfp.polygons()[0][0].size(), 4u);  // the collinear vertices are no vertices of ∂O
  EXPECT_EQ(nfp.minimum(Vec2(1.5, 0.25)).depth, 1.25);
  EXPECT_EQ(nfp.along(Vec2(1.5, 0.25), Vec2(1, 0)).depth, 2.5);
  std::mt19937_64 rng(6);
  check_all(P, Q, rng, pendepth_test::scaled(60), 3, "collinear");
}

TEST(NoFitPolygon2, NestingAlbanoEveryOrderedPair) {
  const auto polys = instance("albano.json");
  std::mt19937_64 rng(31338);
  for (std::size_t i = 0; i < polys.size(); ++i)
    for (std::size_t j = 0; j < polys.size(); ++j)
      check_all(polys[i], polys[j], rng, pendepth_test::scaled(12), 2, "albano " + std::to_string(i) + "/" + std::to_string(j));
}

TEST(NoFitPolygon2, NestingShirtsTrousersPairs) {
  std::mt19937_64 rng(31339);
  for (const char* file : {"shirts.json", "trousers.json"}) {
    const auto polys = instance(file);
    for (int k = 0; k < pendepth_test::scaled(12); ++k) {
      const std::size_t i = rng() % polys.size(), j = rng() % polys.size();
      check_all(polys[i], polys[j], rng, 12, 2, std::string(file) + " " + std::to_string(i) + "/" + std::to_string(j));
    }
  }
}

// Vertices of ∂O that are exact ties between two doubles (P vertex + −Q vertex halfway between
// neighbours): each exported coordinate is one of the two nearest doubles of the exact value, and
// the queries still agree with PairDepth2. O = (2^-52, 2 + 2^-52)², exact.
TEST(NoFitPolygon2, RoundingTiesOfSumVertices) {
  const double a = -0x1p-52;
  const Polygon P = Polygon::simple(std::vector<Vec2>{{1, 1}, {2, 1}, {2, 2}, {1, 2}}, "square");
  const Polygon Q = Polygon::simple(std::vector<Vec2>{{a, a}, {a + 1, a}, {a + 1, a + 1}, {a, a + 1}}, "offset square");
  ASSERT_EQ(a + 1, 1 - 0x1p-52);  // Q's coordinates are exact
  const NoFitPolygon2 nfp(P, Q);
  ASSERT_EQ(nfp.polygons().size(), 1u);
  ASSERT_EQ(nfp.polygons()[0].size(), 1u);
  const auto& ring = nfp.polygons()[0][0];
  ASSERT_EQ(ring.size(), 4u);
  for (const Vec2& v : ring)
    for (int k = 0; k < 2; ++k) {
      const bool low = v[k] == 0x1p-52;                      // exact
      const bool high = v[k] == 2 || v[k] == 2 + 0x1p-51;  // 2 + 2^-52: a tie between these two
      EXPECT_TRUE(low || high) << v[k];
    }
  std::mt19937_64 rng(21);
  check_all(P, Q, rng, pendepth_test::scaled(30), 3, "rounding ties");
}

TEST(NoFitPolygon2, InvalidQueriesThrow) {
  const Polygon Q = Polygon::simple(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "unit");
  const NoFitPolygon2 nfp(Q, Q);
  EXPECT_THROW(nfp.along(Vec2(0, 0), Vec2(0, 0)), pendepth::InvalidInput);
  EXPECT_THROW(nfp.along(Vec2(0, 0), Vec2(NAN, 1)), pendepth::InvalidInput);
  EXPECT_THROW(nfp.minimum(Vec2(INFINITY, 0)), pendepth::InvalidInput);
  EXPECT_THROW(nfp.overlapping(Vec2(0, NAN)), pendepth::InvalidInput);
}

class Summary : public ::testing::Environment {
 public:
  void TearDown() override {
    const Stats& s = totals();
    if (s.pairs == 0) return;
    std::cout << "[nfp] pairs " << s.pairs << ", candidates " << s.candidates << ", pieces " << s.pieces << ", rings " << s.rings << ", slits "
              << s.slits << ", points " << s.points << ", ring vertices checked " << s.vertices << "\n"
              << "[nfp] placements " << s.placements << " (overlapping " << s.overlapping << "), sigma_d " << s.along << ", sigma " << s.minimum
              << "; max ulps vs PairDepth2: sigma_d " << s.max_along << ", sigma " << s.max_min << "; max relative area error "
              << s.max_area << "\n"
              << "[nfp] mean build " << 1e6 * s.t_build / double(s.pairs) << " us; per query (us): nfp sigma_d "
              << 1e6 * s.t_along / double(std::max<std::size_t>(s.along, 1)) << " vs PairDepth2 "
              << 1e6 * s.t_pd_along / double(std::max<std::size_t>(s.along, 1)) << ", nfp sigma "
              << 1e6 * s.t_min / double(std::max<std::size_t>(s.minimum, 1)) << " vs PairDepth2 "
              << 1e6 * s.t_pd_min / double(std::max<std::size_t>(s.minimum, 1)) << "\n";
  }
};
[[maybe_unused]] ::testing::Environment* const summary_env = ::testing::AddGlobalTestEnvironment(new Summary);

}  // namespace
