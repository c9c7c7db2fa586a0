// Points and segments against solid 2D shapes (src/polygon2/flat_depth2.cpp through Pair2; issue 16
// item 4): every query against a brute-force oracle in exact rationals (GMP), written from the
// definitions and sharing nothing with the engine:
//   a point q:         O = int P − q; σ, the distance = min over P's edges of the exact squared
//                      distance; rays against every closed edge; the last exit by testing the
//                      midpoint of every interval between consecutive boundary contacts;
//   a segment [a, b]:  P convex, M = conv{p − a, p − b}: every "supporting pair" (i, j) of those
//                      2n points (all others on its closed left) lies on ∂M and every edge of M is
//                      one, so σ = min over supporting lines, the distance and the rays by the same
//                      segment formulas over the supporting pairs.
// Inputs: random star polygons with and without holes, combs, integer grids, random convex P;
// points on edges and vertices; segments collinear with edges and fitting between two parallel
// edges exactly. Properties: moving by the translation·(1 ± 1e-9), σ ≤ σ_d, the far-side cast
// equals σ_d, batches equal singles, the swapped roles, huge scales. Pinned seeds.
#include <pendepth/pendepth.hpp>

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <random>

#include "oracle.hpp"
#include "polygon2/flat_depth2.hpp"
#include "polygon2/triangulation.hpp"
#include "shapes.hpp"

namespace {

using pendepth::Cast2;
using pendepth::Depth2;
using pendepth::Distance2;
using pendepth::InvalidInput;
using pendepth::Pair2;
using pendepth::Shape2;
using pendepth::Vec2;
using polygon2_test::Rings;

struct Q2 {
  mpq_class x, y;
};
Q2 q(const Vec2& v) { return {mpq_class(v.x()), mpq_class(v.y())}; }
Q2 operator-(const Q2& a, const Q2& b) { return {a.x - b.x, a.y - b.y}; }
Q2 operator+(const Q2& a, const Q2& b) { return {a.x + b.x, a.y + b.y}; }
mpq_class cross(const Q2& a, const Q2& b) { return a.x * b.y - a.y * b.x; }
mpq_class dot(const Q2& a, const Q2& b) { return a.x * b.x + a.y * b.y; }

// Exact squared distance from p to the closed segment [a, b].
mpq_class seg_dist2(const Q2& p, const Q2& a, const Q2& b) {
  const Q2 e = b - a;
  const mpq_class ee = dot(e, e);
  if (ee == 0) return dot(p - a, p - a);
  const mpq_class s = dot(p - a, e);
  if (s <= 0) return dot(p - a, p - a);
  if (s >= ee) return dot(p - b, p - b);
  const mpq_class c = cross(e, p - a);
  return c * c / ee;
}

// The oracle's view of ∂M: a list of closed segments (in t-space), and whether t is inside int M.
struct Oracle {
  std::vector<std::pair<Q2, Q2>> segs;
  std::function<int(const Q2&)> where;  // 1 inside, 0 boundary, -1 outside

  std::optional<mpq_class> dist2(const Q2& t) const {
    std::optional<mpq_class> best;
    for (const auto& [a, b] : segs) {
      const mpq_class d = seg_dist2(t, a, b);
      if (!best || d < *best) best = d;
    }
    return best;
  }
  // The parameters λ > 0 (in units of d) where the ray t + λ·d meets ∂M.
  std::vector<mpq_class> contacts(const Q2& t, const Q2& d) const {
    std::vector<mpq_class> out;
    for (const auto& [a, b] : segs) {
      const Q2 e = b - a;
      const mpq_class den = cross(d, e);
      if (den == 0) {
        if (cross(d, a - t) != 0) continue;  // parallel, off the line
        for (const Q2& x : {a, b}) {
          const mpq_class l = dot(x - t, d) / dot(d, d);
          if (l > 0) out.push_back(l);
        }
        continue;
      }
      const mpq_class l = cross(a - t, e) / den, mu = cross(a - t, d) / den;
      if (mu >= 0 && mu <= 1 && l > 0) out.push_back(l);
    }
    std::sort(out.begin(), out.end());
    return out;
  }
  std::optional<mpq_class> first(const Q2& t, const Q2& d) const {
    const auto c = contacts(t, d);
    if (c.empty()) return std::nullopt;
    return c.front();
  }
  // The last exit from int M: the largest contact whose preceding interval is inside.
  std::optional<mpq_class> last_exit(const Q2& t, const Q2& d) const {
    const auto c = contacts(t, d);
    std::optional<mpq_class> best;
    mpq_class prev = 0;
    for (const mpq_class& l : c) {
      if (l == prev) continue;
      const mpq_class mid = (prev + l) / 2;
      if (where(Q2{t.x + mid * d.x, t.y + mid * d.y}) > 0) best = l;
      prev = l;
    }
    return best;
  }
};

// A point q against the rings of P.
Oracle point_oracle(const Rings& P, const Vec2& qv) {
  Oracle o;
  const Q2 qq = q(qv);
  for (const auto& ring : P)
    for (std::size_t i = 0; i < ring.size(); ++i)
      o.segs.push_back({q(ring[i]) - qq, q(ring[(i + 1) % ring.size()]) - qq});
  o.where = [segs = o.segs](const Q2& t) {
    bool odd = false;
    for (const auto& [a, b] : segs) {
      if (seg_dist2(t, a, b) == 0) return 0;
      if ((a.y > t.y) != (b.y > t.y)) {
        const mpq_class x = a.x + (t.y - a.y) * (b.x - a.x) / (b.y - a.y);
        if (x > t.x) odd = !odd;
      }
    }
    return odd ? 1 : -1;
  };
  return o;
}

// A segment [a, b] against a convex P: the supporting pairs of {p − a, p − b}.
Oracle segment_oracle(const std::vector<Vec2>& P, const Vec2& a, const Vec2& b) {
  std::vector<Q2> pts;
  for (const Vec2& p : P) {
    pts.push_back(q(p) - q(a));
    pts.push_back(q(p) - q(b));
  }
  Oracle o;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = 0; j < pts.size(); ++j) {
      if (i == j || (pts[i].x == pts[j].x && pts[i].y == pts[j].y)) continue;
      bool ok = true;
      for (const Q2& x : pts)
        if (cross(pts[j] - pts[i], x - pts[i]) < 0) {
          ok = false;
          break;
        }
      if (ok) o.segs.push_back({pts[i], pts[j]});
    }
  o.where = [segs = o.segs](const Q2& t) {
    int w = 1;
    for (const auto& [u, v] : segs) {
      const int s = sgn(cross(v - u, t - u));
      if (s < 0) return -1;
      if (s == 0) w = 0;
    }
    return w;
  };
  return o;
}

double to_d(const mpq_class& x) { return x.get_d(); }
double length(const mpq_class& l, const Vec2& d) { return std::sqrt(to_d(l * l)) * std::hypot(d.x(), d.y()); }

// Relative closeness for values that are one rounding chain (a few ulps) from the exact value.
void expect_close(double got, double want, const std::string& what) {
  EXPECT_LE(std::abs(got - want), 1e-13 * std::max(1.0, std::abs(want))) << what << ": " << got << " vs " << want;
}

// Every query of `pair` at t (and along d) against the oracle.
void check_all(const Pair2& pair, const Oracle& o, const Vec2& t, const Vec2& d, const std::string& what) {
  const Q2 tq = q(t), dq = q(d);
  const int w = o.where(tq);
  SCOPED_TRACE(what + " t=(" + std::to_string(t.x()) + "," + std::to_string(t.y()) + ")");
  ASSERT_EQ(pair.overlapping(t), w > 0);
  const Depth2 s = pair.minimum(t);
  ASSERT_EQ(s.overlapping, w > 0);
  const mpq_class d2 = *o.dist2(tq);
  const Distance2 sd = pair.signed_distance(t);
  if (w > 0) {
    expect_close(s.depth, std::sqrt(to_d(d2)), "sigma");
    expect_close(sd.distance, -s.depth, "signed distance inside");
    const Depth2 a = pair.along(t, d);
    const auto l = o.first(tq, dq);
    ASSERT_TRUE(l);
    expect_close(a.depth, length(*l, d), "sigma_d");
    EXPECT_LE(s.depth, a.depth * (1 + 1e-14));
    const Cast2 c = pair.cast(t, d);
    EXPECT_TRUE(c.hit && c.overlapping);
    EXPECT_EQ(c.distance, 0);
  } else {
    EXPECT_EQ(s.depth, 0);
    EXPECT_EQ(pair.along(t, d).depth, 0);
    EXPECT_EQ(sd.overlapping, false);
    expect_close(sd.distance, std::sqrt(to_d(d2)), "distance");
    // The witnesses: witness_q − witness_p = distance·normal; the translation brings Q to touch.
    if (w < 0) {
      EXPECT_LE((sd.witness_q - sd.witness_p - sd.distance * sd.normal).norm(), 1e-12 * (1 + t.norm()));
      if (sd.distance > 1e-6) EXPECT_FALSE(pair.overlapping(t + sd.translation * (1 - 1e-9)));
      if (sd.feature_p.kind == pendepth::FeatureKind::Edge && sd.distance > 1e-6) EXPECT_TRUE(pair.overlapping(t + sd.translation * (1 + 1e-9)));
      EXPECT_NEAR(pair.signed_distance(t + sd.translation).distance, 0, 1e-12 * (1 + t.norm()));
    }
    const Cast2 c = pair.cast(t, d);
    const auto l = o.first(tq, dq);
    if (w == 0) {
      EXPECT_TRUE(c.hit);
      EXPECT_EQ(c.distance, 0);
    } else if (!l) {
      EXPECT_FALSE(c.hit);
      EXPECT_EQ(c.distance, std::numeric_limits<double>::infinity());
    } else {
      EXPECT_TRUE(c.hit);
      expect_close(c.distance, length(*l, d), "cast");
    }
  }
  const Depth2 sep = pair.separation(t, d);
  const auto le = o.last_exit(tq, dq);
  expect_close(sep.depth, le ? length(*le, d) : 0.0, "separation");
  // Properties of σ: 1 − 1e-9 of the move does not separate; the move past an edge does (past a
  // reflex vertex of a non-convex P the point may enter P again: σ is the distance to the nearest
  // touching placement).
  if (w > 0 && s.depth > 1e-6) {
    if (s.feature_p.kind == pendepth::FeatureKind::Edge) EXPECT_FALSE(pair.overlapping(t + s.translation * (1 + 1e-9)));
    EXPECT_TRUE(pair.overlapping(t + s.translation * (1 - 1e-9)));
  }
}

Vec2 random_dir(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  for (;;) {
    const Vec2 d(u(rng), u(rng));
    if (d.norm() > 0.1) return rng() % 4 == 0 ? Vec2(std::round(d.x() * 2), std::round(d.y() * 2)) : d;
  }
}

Vec2 nonzero(const Vec2& d) { return d == Vec2(0, 0) ? Vec2(1, 0) : d; }

TEST(Flat2, PointAgainstPolygonsMatchesExactOracle) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> u(-110, 110);
  for (int iter = 0; iter < 24; ++iter) {
    const bool grid = iter % 3 == 0;
    const pendepth::Polygon poly = polygon2_test::random_polygon(rng, 6 + iter % 20, iter % 4, grid);
    const Shape2 P(poly);
    Rings rings = P.rings();
    const Vec2 qv = grid ? Vec2(std::round(u(rng) / 10), std::round(u(rng) / 10)) : Vec2(u(rng) / 10, u(rng) / 10);
    const Oracle o = point_oracle(rings, qv);
    const Pair2 pair(P, Shape2::point(qv));
    EXPECT_EQ(pair.engine(), pendepth::Engine2::Flat);
    for (int k = 0; k < 25; ++k) {
      Vec2 t(u(rng), u(rng));
      if (grid) t = Vec2(std::round(t.x()), std::round(t.y()));
      check_all(pair, o, t, nonzero(random_dir(rng)), "point");
    }
    // On vertices and edges of ∂M (touching), and just inside at vertices.
    for (const auto& ring : rings)
      for (std::size_t i = 0; i < ring.size(); i += 3) {
        const Vec2 a = ring[i] - qv, b = ring[(i + 1) % ring.size()] - qv;
        check_all(pair, o, a, nonzero(random_dir(rng)), "vertex");
        check_all(pair, o, 0.5 * (a + b), b - a, "edge midpoint, along the edge");
      }
  }
}

TEST(Flat2, SegmentAgainstConvexMatchesExactOracle) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-60, 60);
  for (int iter = 0; iter < 30; ++iter) {
    const bool grid = iter % 2 == 0;
    const pendepth::ConvexPolygon cp = polygon2_test::random_convex(rng, 3 + iter % 12, 40, grid);
    const Shape2 P(cp);
    const std::vector<Vec2> verts(cp.vertices().begin(), cp.vertices().end());
    Vec2 a(u(rng) / 3, u(rng) / 3), b(u(rng) / 3, u(rng) / 3);
    if (grid) a = Vec2(std::round(a.x()), std::round(a.y())), b = Vec2(std::round(b.x()), std::round(b.y()));
    if (iter % 5 == 1) b = a + (verts[1] - verts[0]) * 0.5;  // parallel to an edge of P
    if (a == b) b = a + Vec2(1, 2);
    const Oracle o = segment_oracle(verts, a, b);
    const Pair2 pair(P, Shape2::segment(a, b));
    for (int k = 0; k < 30; ++k) {
      Vec2 t(u(rng), u(rng));
      if (grid) t = Vec2(std::round(t.x()), std::round(t.y()));
      Vec2 d = nonzero(random_dir(rng));
      if (k % 7 == 0) d = b - a;  // along the segment
      check_all(pair, o, t, d, "segment");
    }
    // On M's vertices and edges: the supporting pairs' ends and midpoints.
    for (std::size_t k = 0; k < o.segs.size(); k += 5) {
      const Vec2 x(to_d(o.segs[k].first.x), to_d(o.segs[k].first.y));
      if (q(x).x == o.segs[k].first.x && q(x).y == o.segs[k].first.y) check_all(pair, o, x, nonzero(random_dir(rng)), "M vertex");
    }
  }
}

// A segment against non-convex polygons with holes: the CGAL union oracle of the convolved
// triangles T_i ⊕ (−F) (oracle.hpp). For a segment parallel to no diagonal of the triangulation
// (random segments) their open union is O exactly, and its regularised boundary is ∂O.
TEST(Flat2, SegmentAgainstPolygonsMatchesUnionOracle) {
  std::mt19937_64 rng(2026);
  int inside = 0, apart = 0, hits = 0;
  std::uniform_real_distribution<double> u(-110, 110);
  for (int iter = 0; iter < 16; ++iter) {
    const pendepth::Polygon poly = polygon2_test::random_polygon(rng, 6 + iter, iter % 3, false);
    std::vector<std::array<Vec2, 3>> tris;
    for (const auto& t : pendepth::polygon2::triangulate(poly))
      tris.push_back({poly.vertices()[t[0]], poly.vertices()[t[1]], poly.vertices()[t[2]]});
    const Vec2 a(u(rng) / 6, u(rng) / 6), b(u(rng) / 6, u(rng) / 6);
    const polygon2_test::UnionOracle o(tris, {a, b});
    const Pair2 pair(Shape2(poly), Shape2::segment(a, b));
    for (int k = 0; k < 40; ++k) {
      const Vec2 t(u(rng), u(rng)), d = nonzero(random_dir(rng));
      SCOPED_TRACE("iter " + std::to_string(iter) + " k " + std::to_string(k));
      const bool in = o.inside(t);
      ASSERT_EQ(pair.overlapping(t), in);
      const Depth2 s = pair.minimum(t);
      const Distance2 sd = pair.signed_distance(t);
      if (in) {
        expect_close(s.depth, o.boundary_distance(t), "sigma");
        expect_close(pair.along(t, d).depth, o.along(t, d), "sigma_d");
        EXPECT_EQ(sd.distance, -s.depth);
      } else if (!o.inside_union(t)) {
        expect_close(sd.distance, o.boundary_distance(t), "distance");
        ++apart;
        // The cast: at its distance the shapes touch (distance 0 up to rounding), before they do not.
        const Cast2 c = pair.cast(t, d);
        if (c.hit && c.distance > 1e-6) {
          EXPECT_NEAR(pair.signed_distance(t + c.translation).distance, 0, 1e-9 * c.distance);
          EXPECT_GT(pair.signed_distance(t + c.translation * (1 - 1e-6)).distance, 0);
          ++hits;
        }
      }
      inside += in;
      expect_close(pair.separation(t, d).depth, o.separation(t, d), "separation");
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(apart, 100);
  EXPECT_GT(hits, 20);
}

TEST(Flat2, SwappedRolesMirrorTheAnswers) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-50, 50);
  const Shape2 P(polygon2_test::random_polygon(rng, 12, 2, false));
  const Shape2 C(polygon2_test::random_convex(rng, 9, 30, false));
  const Shape2 pt = Shape2::point(Vec2(1.5, -2.25)), sg = Shape2::segment(Vec2(-3, 1), Vec2(4, 2.5));
  const std::vector<std::pair<Shape2, Shape2>> cases{{P, pt}, {C, pt}, {C, sg}, {P, sg}};
  for (const auto& [solid, flat] : cases) {
    const Pair2 a(solid, flat), b(flat, solid);
    for (int k = 0; k < 40; ++k) {
      const Vec2 t(u(rng), u(rng)), d = nonzero(random_dir(rng));
      const Vec2 mt = Vec2(0, 0) - t, md = Vec2(0, 0) - d;
      EXPECT_EQ(a.overlapping(t), b.overlapping(mt));
      const Depth2 x = a.minimum(t), y = b.minimum(mt);
      EXPECT_EQ(x.depth, y.depth);
      EXPECT_EQ(x.translation, Vec2(0, 0) - y.translation);
      EXPECT_EQ(x.feature_p, y.feature_q);
      if (x.overlapping) EXPECT_LE((y.witness_p - (x.witness_q - t - x.translation)).norm(), 1e-12 * (1 + t.norm()));
      EXPECT_EQ(a.along(t, d).depth, b.along(mt, md).depth);
      EXPECT_EQ(a.separation(t, d).depth, b.separation(mt, md).depth);
      const Distance2 p = a.signed_distance(t), r = b.signed_distance(mt);
      EXPECT_EQ(p.distance, r.distance);
      EXPECT_EQ(p.normal, Vec2(0, 0) - r.normal);
      // In b, P is the flat shape placed at the origin and Q the solid at −t: witnesses swap roles.
      EXPECT_LE((r.witness_q - (p.witness_p - t)).norm(), 1e-12 * (1 + t.norm()));
      const Cast2 c1 = a.cast(t, d), c2 = b.cast(mt, md);
      EXPECT_EQ(c1.distance, c2.distance);
      EXPECT_EQ(c1.hit, c2.hit);
    }
  }
}

TEST(Flat2, DegenerateContactsAndFits) {
  // A comb: teeth 2 wide, gaps 1 wide and 3 deep. A unit horizontal segment fits a gap exactly.
  const Shape2 comb(polygon2_test::comb_ring(4, 2, 1, 3, 1));
  const Shape2 sq(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  const Shape2 p = Shape2::point(Vec2(0, 0));
  const Pair2 cp(comb, p);
  // A point on an edge, at a vertex: touching.
  EXPECT_FALSE(cp.overlapping(Vec2(1, 0)));
  EXPECT_FALSE(cp.overlapping(Vec2(0, 0)));
  EXPECT_EQ(cp.signed_distance(Vec2(1, 0)).distance, 0);
  EXPECT_EQ(cp.minimum(Vec2(1, 0)).depth, 0);
  // In the middle of a tooth: σ = half the tooth width; in a gap: outside, distance 0.5.
  EXPECT_EQ(cp.minimum(Vec2(1, 3)).depth, 1);
  EXPECT_EQ(cp.signed_distance(Vec2(2.5, 3)).distance, 0.5);
  EXPECT_EQ(cp.signed_distance(Vec2(1, 3)).distance, -1);
  // σ_d straight up from inside a tooth exits at the top (y = 4), complete separation also at 4;
  // sideways from inside tooth 0 the first exit is its side, the last the far side of tooth 3.
  EXPECT_EQ(cp.along(Vec2(1, 2), Vec2(0, 1)).depth, 2);
  EXPECT_EQ(cp.separation(Vec2(0.5, 2), Vec2(1, 0)).depth, 10.5);
  EXPECT_EQ(cp.along(Vec2(0.5, 2), Vec2(1, 0)).depth, 1.5);
  // Cast from above a gap straight down: reaches the gap's floor at y = 1.
  const Cast2 c = cp.cast(Vec2(2.5, 9), Vec2(0, -1));
  EXPECT_TRUE(c.hit);
  EXPECT_EQ(c.distance, 8);
  EXPECT_EQ(c.witness_p, Vec2(2.5, 1));
  // A ray grazing a vertex from outside does not count as an exit: along y = 4 (the teeth tops).
  EXPECT_EQ(cp.separation(Vec2(-1, 4), Vec2(1, 0)).depth, 0);
  // A segment on a square: collinear with an edge (touching), exactly spanning it, inside.
  const Pair2 ss(sq, Shape2::segment(Vec2(0, 0), Vec2(4, 0)));
  EXPECT_FALSE(ss.overlapping(Vec2(0, 0)));   // lies on the bottom edge
  EXPECT_FALSE(ss.overlapping(Vec2(0, 4)));   // on the top edge
  EXPECT_TRUE(ss.overlapping(Vec2(0, 1)));
  EXPECT_TRUE(ss.overlapping(Vec2(3.5, 2)));  // sticks out to the right, still inside partly
  EXPECT_FALSE(ss.overlapping(Vec2(4, 2)));   // touches the right edge with its left end
  EXPECT_EQ(ss.minimum(Vec2(0, 1)).depth, 1);
  EXPECT_EQ(ss.minimum(Vec2(-1, 2)).depth, 2);  // out through the top or bottom, or right by 3
  EXPECT_EQ(ss.along(Vec2(-1, 2), Vec2(-1, 0)).depth, 3);
  EXPECT_EQ(ss.signed_distance(Vec2(6, 7)).distance, std::hypot(2.0, 3.0));
  const Distance2 e = ss.signed_distance(Vec2(-2, 6));  // end (2, 6) above the top edge: distance 2
  EXPECT_EQ(e.distance, 2);
  EXPECT_EQ(e.normal, Vec2(0, 1));
  // A unit segment fits a unit gap of the comb exactly: spanning it at the gap's floor level it
  // touches both teeth (not overlapping); half a unit higher it touches both sides too (a slit of
  // O's complement inside M), lifted out of the gap it is free.
  const Pair2 cs(comb, Shape2::segment(Vec2(0, 0), Vec2(1, 0)));
  EXPECT_FALSE(cs.overlapping(Vec2(2, 2)));   // spans the gap [2, 3] at y = 2
  EXPECT_EQ(cs.minimum(Vec2(2, 2)).depth, 0);
  EXPECT_EQ(cs.signed_distance(Vec2(2, 2)).distance, 0);
  EXPECT_TRUE(cs.overlapping(Vec2(2.5, 2)));  // shifted right: into the tooth
  EXPECT_EQ(cs.minimum(Vec2(2.5, 2)).depth, 0.5);
  EXPECT_EQ(cs.minimum(Vec2(1.75, 2)).depth, 0.25);
  EXPECT_EQ(cs.along(Vec2(2.5, 2), Vec2(0, 1)).depth, 2);  // up and out of the comb
  // From inside the base straight up: out at the gap's floor (y = 1), and then it slides up the
  // gap touching both sides, never overlapping again: complete separation 0.5, not 3.5.
  EXPECT_EQ(cs.separation(Vec2(2, 0.5), Vec2(0, 1)).depth, 0.5);
  EXPECT_EQ(cs.separation(Vec2(2.25, 0.5), Vec2(0, 1)).depth, 3.5);  // off the gap: out at the top
  // Falling onto the gap: its ends touch the teeth's top corners first (y = 4).
  EXPECT_EQ(cs.cast(Vec2(2, 9), Vec2(0, -1)).distance, 5);
  const Vec2 w = cs.cast(Vec2(2, 9), Vec2(0, -1)).witness_p;  // either corner
  EXPECT_TRUE(w == Vec2(2, 4) || w == Vec2(3, 4));
  // A square frame [0, 4]² with the hole [1, 3]²: a segment of length 2 spans the hole exactly.
  const Shape2 frame(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 4}, {0, 4}},
                     std::vector<std::vector<Vec2>>{{{1, 1}, {1, 3}, {3, 3}, {3, 1}}});
  const Pair2 fs(frame, Shape2::segment(Vec2(0, 0), Vec2(2, 0)));
  EXPECT_FALSE(fs.overlapping(Vec2(1, 2)));  // from (1, 2) to (3, 2): touches both sides of the hole
  EXPECT_EQ(fs.signed_distance(Vec2(1, 2)).distance, 0);
  EXPECT_TRUE(fs.overlapping(Vec2(1.25, 2)));
  EXPECT_EQ(fs.minimum(Vec2(1.25, 2)).depth, 0.25);    // back left by 0.25 (up: 1.0 out of the hole's top)
  EXPECT_EQ(fs.along(Vec2(1.25, 2), Vec2(0, 1)).depth, 2);  // up: the right end leaves the frame's top wall at y = 4
  EXPECT_EQ(fs.signed_distance(Vec2(1.5, 2.5)).distance, -0.5);  // overlaps the right wall by 0.5
  const Pair2 fp(frame, Shape2::point(Vec2(0, 0)));
  EXPECT_FALSE(fp.overlapping(Vec2(2, 2)));             // in the hole
  EXPECT_EQ(fp.signed_distance(Vec2(2, 2)).distance, 1);
  EXPECT_EQ(fp.minimum(Vec2(0.5, 2)).depth, 0.5);
  // Two flat shapes are invalid.
  EXPECT_THROW(Pair2(p, Shape2::segment(Vec2(0, 0), Vec2(1, 0))), InvalidInput);
  EXPECT_THROW(Pair2(p, p), InvalidInput);
  EXPECT_THROW(Shape2::segment(Vec2(1, 1), Vec2(1, 1)), InvalidInput);
  EXPECT_THROW(Shape2::point(Vec2(std::nan(""), 0)), InvalidInput);
  EXPECT_THROW(p.polygon(), InvalidInput);
  EXPECT_EQ(p.dimension(), 0);
  EXPECT_FALSE(p.is_convex());
  EXPECT_THROW(cp.along(Vec2(0, 0), Vec2(0, 0)), InvalidInput);
  EXPECT_THROW(cp.minimum(Vec2(INFINITY, 0)), InvalidInput);
}

TEST(Flat2, FarSideCastEqualsDirectionalDepth) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-20, 20);
  const Shape2 C(polygon2_test::random_convex(rng, 11, 30, false));
  const Pair2 pair(C, Shape2::segment(Vec2(-4, 1), Vec2(5, -2)));
  int n = 0;
  for (int k = 0; k < 200; ++k) {
    const Vec2 t(u(rng), u(rng)), d = nonzero(random_dir(rng));
    const Depth2 a = pair.along(t, d);
    if (!a.overlapping) continue;
    ++n;
    const Vec2 dh = d / d.norm();
    const double S = 1000;
    const Cast2 c = pair.cast(t + S * dh, Vec2(0, 0) - d);
    ASSERT_TRUE(c.hit);
    EXPECT_NEAR(S - c.distance, a.depth, 1e-10 * S);
    // σ ≤ σ_d; the signed distance is continuous through contact along d.
    EXPECT_LE(pair.minimum(t).depth, a.depth * (1 + 1e-14));
    const Vec2 x = t + a.translation;
    EXPECT_NEAR(pair.signed_distance(x + 1e-7 * dh).distance, 0, 2e-7);
    EXPECT_NEAR(pair.signed_distance(x - 1e-7 * dh).distance, 0, 2e-7);
  }
  EXPECT_GT(n, 20);
}

TEST(Flat2, BatchesEqualSinglesAndHugeScalesScaleExactly) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-110, 110);
  const Shape2 P(polygon2_test::random_polygon(rng, 14, 1, false));
  const Pair2 pair(P, Shape2::point(Vec2(0.25, 0.5)));
  std::vector<Vec2> ts(300);
  for (auto& t : ts) t = Vec2(u(rng), u(rng));
  std::vector<Depth2> m(ts.size()), a(ts.size());
  std::vector<Distance2> s(ts.size());
  const std::vector<Vec2> ds{Vec2(1, 2)};
  pair.minimum(ts, m, 2);
  pair.along(ts, ds, a, 2);
  pair.signed_distance(ts, s, 2);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    EXPECT_EQ(m[i].depth, pair.minimum(ts[i]).depth);
    EXPECT_EQ(m[i].translation, pair.minimum(ts[i]).translation);
    EXPECT_EQ(a[i].depth, pair.along(ts[i], ds[0]).depth);
    EXPECT_EQ(s[i].distance, pair.signed_distance(ts[i]).distance);
    EXPECT_EQ(s[i].witness_p, pair.signed_distance(ts[i]).witness_p);
  }
  // The same pair scaled by 2^700 (outside the comfort band: answered on scaled copies).
  const double k = std::ldexp(1.0, 700);
  auto rings = P.rings();
  for (auto& r : rings)
    for (auto& v : r) v *= k;
  const Vec2 qv(0.25 * k, 0.5 * k);
  const Pair2 big(Shape2(rings[0], Rings(rings.begin() + 1, rings.end())), Shape2::point(qv));
  for (std::size_t i = 0; i < 50; ++i) {
    EXPECT_EQ(big.minimum(ts[i] * k).depth, m[i].depth * k);
    EXPECT_EQ(big.signed_distance(ts[i] * k).distance, s[i].distance * k);
    EXPECT_EQ(big.along(ts[i] * k, ds[0]).depth, a[i].depth * k);
  }
  const Pair2 bs(Shape2(polygon2_test::random_convex(rng, 7, 30 * k, false)), Shape2::segment(Vec2(0, 0), Vec2(k, k)));
  EXPECT_TRUE(bs.overlapping(Vec2(0, 0)));
  EXPECT_GT(bs.minimum(Vec2(0, 0)).depth, 0);
}

TEST(Flat2, NoFitPolygonIsM) {
  const Shape2 sq(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  const auto parts = pendepth::no_fit_polygon(sq, Shape2::point(Vec2(1, 1)));
  ASSERT_EQ(parts.polygons.size(), 1u);
  ASSERT_EQ(parts.polygons[0].size(), 1u);
  EXPECT_EQ(parts.polygons[0][0].size(), 4u);
  EXPECT_EQ(parts.polygons[0][0][0], Vec2(-1, -1));
  const auto seg = Pair2(sq, Shape2::segment(Vec2(0, 0), Vec2(1, 0))).no_fit_polygon();
  ASSERT_EQ(seg.polygons.size(), 1u);
  EXPECT_EQ(seg.polygons[0][0].size(), 4u);  // [-1, 4] × [0, 4]: the sweep is collinear with the edges
}

// The general path's box tree (flat_segment2.cpp: "segment meets int P" visits only the edges near
// the tested segment, signs read off rigorous boxes) against the same path scanning all n edges
// with exact signs only: every answer bit for bit, on random stars with holes (grid ones with
// many collinear and touching cases) and combs up to a few hundred vertices, placements over M's
// box and on grid points.
void expect_same(const Depth2& a, const Depth2& b) {
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.translation, b.translation);
  EXPECT_EQ(a.normal, b.normal);
  EXPECT_EQ(a.witness_p, b.witness_p);
  EXPECT_EQ(a.witness_q, b.witness_q);
  EXPECT_EQ(a.feature_p, b.feature_p);
  EXPECT_EQ(a.feature_q, b.feature_q);
  EXPECT_EQ(a.overlapping, b.overlapping);
  EXPECT_EQ(a.kind, b.kind);
}

TEST(Flat2, SegmentGeneralPathBoxTreeEqualsFullScan) {
  namespace fg = pendepth::polygon2::flat_general;
  std::mt19937_64 rng(1616);
  std::uniform_real_distribution<double> u(-1, 1);
  int overlapping = 0, apart = 0;
  for (int iter = 0; iter < 14; ++iter) {
    std::vector<std::vector<Vec2>> rings;
    const bool grid = iter % 3 == 1;
    if (iter % 5 == 4) {
      const Shape2 comb(polygon2_test::comb_ring(4 + 5 * iter, 2, 1, 3, 1));
      rings = {std::vector<Vec2>(comb.polygon().ring(0).begin(), comb.polygon().ring(0).end())};
    } else {
      const int n = std::vector<int>{8, 24, 60, 150, 300}[iter % 5];
      const pendepth::Polygon poly = polygon2_test::random_polygon(rng, n, iter % 3, grid);
      for (std::size_t k = 0; k < poly.ring_count(); ++k) rings.emplace_back(poly.ring(k).begin(), poly.ring(k).end());
    }
    Vec2 lo = rings[0][0], hi = lo;
    for (const auto& r : rings)
      for (const Vec2& p : r) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const double span = (hi - lo).maxCoeff();
    std::array<Vec2, 2> F{Vec2(u(rng), u(rng)) * span / 8, Vec2(u(rng), u(rng)) * span / 8};
    if (grid || iter % 5 == 4) F = {Vec2(std::round(F[0].x()), std::round(F[0].y())), Vec2(std::round(F[0].x()) + 1 + rng() % 2, std::round(F[0].y()))};
    const auto fast = fg::build(rings, F), slow = fg::build(rings, F, true);
    for (int k = 0; k < 24; ++k) {
      SCOPED_TRACE("iter " + std::to_string(iter) + " k " + std::to_string(k));
      Vec2 t((lo.x() + hi.x()) / 2 + u(rng) * span * 0.6, (lo.y() + hi.y()) / 2 + u(rng) * span * 0.6);
      if (grid || k % 4 == 0) t = Vec2(std::round(t.x()), std::round(t.y()));
      const Vec2 d = nonzero(random_dir(rng));
      const bool in = fg::overlapping(*fast, t);
      ASSERT_EQ(in, fg::overlapping(*slow, t));
      (in ? overlapping : apart) += 1;
      expect_same(fg::minimum(*fast, t), fg::minimum(*slow, t));
      expect_same(fg::along(*fast, t, d), fg::along(*slow, t, d));
      expect_same(fg::separation(*fast, t, d), fg::separation(*slow, t, d));
      const Distance2 a = fg::signed_distance(*fast, t), b = fg::signed_distance(*slow, t);
      EXPECT_EQ(a.distance, b.distance);
      EXPECT_EQ(a.translation, b.translation);
      EXPECT_EQ(a.normal, b.normal);
      EXPECT_EQ(a.witness_p, b.witness_p);
      EXPECT_EQ(a.witness_q, b.witness_q);
      EXPECT_EQ(a.feature_p, b.feature_p);
      EXPECT_EQ(a.feature_q, b.feature_q);
      EXPECT_EQ(a.overlapping, b.overlapping);
      const Cast2 c = fg::cast(*fast, t, d), e = fg::cast(*slow, t, d);
      EXPECT_EQ(c.distance, e.distance);
      EXPECT_EQ(c.translation, e.translation);
      EXPECT_EQ(c.normal, e.normal);
      EXPECT_EQ(c.witness_p, e.witness_p);
      EXPECT_EQ(c.feature_p, e.feature_p);
      EXPECT_EQ(c.feature_q, e.feature_q);
      EXPECT_EQ(c.hit, e.hit);
      EXPECT_EQ(c.overlapping, e.overlapping);
    }
  }
  EXPECT_GT(overlapping, 80);
  EXPECT_GT(apart, 80);
}

}  // namespace
