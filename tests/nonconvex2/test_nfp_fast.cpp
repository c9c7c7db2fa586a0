// NoFitPolygon2's floating fast path (nfp_fast.cpp, issue 19 item 1) against its exact path
// (NoFitPolygon2::Impl::overlapping_exact / minimum(t, true) / along(t, d, true): the pair-sum
// overlap test and the best-first hierarchy traversals with every decision exact): every answer
// bit for bit equal — overlap decisions, depth, translation, normal, witnesses, features; the
// lean queries depth_value / directional_depth_value (fast, and minimum_value / along_value on
// the exact path) give the exact full answer's depth, translation and overlap bit for bit — on
// placements where the floating decisions must defer: ring vertices and points on ring edges, each
// moved by ±1 and ±2 ulps, slits (ends, middles, beside them), isolated points, integer grid points
// of integer-coordinate pairs (rays through vertices, placements level with vertices), plus random
// placements; directions along the axes, the diagonals, towards ring vertices (rays through them)
// and random ones. Inputs: nesting pieces (albano every ordered pair, shirts, trousers), exact fits
// (combs, a slot, a hole fit, a bottle neck, a closed slot) and the same pairs with Q, or both,
// turned by quarter turns (exact). The test also checks that both outcomes of the overlap filter
// occur (certified and deferred), so the deferral is exercised. The exact path evaluates the
// winner's values (RN of the exact reals, geometry/rounded.hpp) with rationals alone, so equal
// bits also check the fast double-double values; ProjectionValuesAgainstRationals checks those
// directly, and that every error bound holds (rationals) and is tight enough that shrinking it
// by 2¹² fails; VertexValuesAgainstRationals the same for σ at a sum vertex, EndValuesAgainstRationals
// for σ at a cut end (the per-piece table built with the no-fit polygon);
// NearestCandidateFlagsAgainstExact checks σ's candidate set and its certified flags (projection
// inside / before lo / beyond hi) against exact arithmetic, and the flags' error bound against
// rationals (removing it, or shrinking it by 2¹³, fails); ReflexWedges places t about every ring
// vertex (on the bisector to either side, at the vertex, ulps off, scattered near it) so that σ's
// shared-vertex wedge (NfpFlat::inside_by_nearest) fires, and checks it only ever does for t ∈ O
// (linking convex vertices too fails it and ExactFits); FirstHitCandidatesAgainstExact checks σ_d's
// candidate flags (crossing ahead, from O) and that the first pieces hit are candidates against
// rationals, with t beside pieces and rays nearly along them (the crossing's side certified by
// side_of_piece); LineTableTies checks σ's tie table (pieces grouped by exact line) against
// rationals and places t where candidates on one line tie (albano, shirts, trousers, turned and
// rotated, exact fits). Pinned seeds.
#include <pendepth/nfp2.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <gmpxx.h>

#include "geometry/isa.hpp"
#include "nfp_shapes.hpp"
#include "nonconvex2/nfp_impl.hpp"
#include "nonconvex2/query.hpp"
#include "polygon2/shapes.hpp"

namespace {

using nonconvex2_test::instance;
using nonconvex2_test::mapped;
using pendepth::Depth2;
using pendepth::NoFitPolygon2;
using pendepth::Polygon;
using pendepth::Vec2;

bool same(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
bool same(const Vec2& a, const Vec2& b) { return same(a.x(), b.x()) && same(a.y(), b.y()); }

::testing::AssertionResult same(const Depth2& a, const Depth2& b) {
  if (same(a.depth, b.depth) && same(a.translation, b.translation) && same(a.normal, b.normal) &&
      same(a.witness_p, b.witness_p) && same(a.witness_q, b.witness_q) && a.feature_p == b.feature_p &&
      a.feature_q == b.feature_q && a.overlapping == b.overlapping && a.kind == b.kind)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "fast depth " << a.depth << " (" << a.translation.transpose() << ", features "
                                       << a.feature_p.index << "/" << a.feature_q.index << ") vs exact " << b.depth
                                       << " (" << b.translation.transpose() << ", features " << b.feature_p.index << "/"
                                       << b.feature_q.index << ")";
}

// The lean answer's fields against the full answer's.
::testing::AssertionResult same(const pendepth::DepthValue2& a, const Depth2& b) {
  if (same(a.depth, b.depth) && same(a.translation, b.translation) && a.overlapping == b.overlapping) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "lean depth " << a.depth << " (" << a.translation.transpose() << ", overlapping "
                                       << a.overlapping << ") vs full " << b.depth << " (" << b.translation.transpose()
                                       << ", overlapping " << b.overlapping << ")";
}

struct Counts {
  std::size_t queries = 0, certified = 0, deferred = 0, overlapping = 0;
  // NfpFlat::inside_by_nearest / inside_by_candidates: t ∈ O proved by σ's (σ_d's) candidates,
  // over the checks made; by_wedge: by two candidates meeting at a reflex vertex of O.
  std::size_t by_nearest = 0, by_wedge = 0, by_first_hit = 0, first_hit_checks = 0;
};
Counts& counts() {
  static Counts c;
  return c;
}

Vec2 ulp_step(const Vec2& v, int dx, int dy) {
  auto step = [](double x, int k) {
    for (; k > 0; --k) x = std::nextafter(x, INFINITY);
    for (; k < 0; ++k) x = std::nextafter(x, -INFINITY);
    return x;
  };
  return Vec2(step(v.x(), dx), step(v.y(), dy));
}

// Every query at t with every direction: fast path against exact path, bit for bit.
void check_at(const NoFitPolygon2& nfp, const Vec2& t, const std::vector<Vec2>& dirs, const std::string& what) {
  const NoFitPolygon2::Impl& N = nfp_impl(nfp);
  Counts& c = counts();
  ++c.queries;
  if (N.flat.usable) {
    const int f = N.flat.overlapping(t);
    (f < 0 ? c.deferred : c.certified) += 1;
  }
  const bool exact = N.overlapping_exact(t);
  c.overlapping += exact;
  // The overlap test skipped by σ's and σ_d's fast path: only ever for t ∈ O (exact test).
  std::vector<std::uint32_t> cand;
  if (N.flat.usable) {
    N.flat.nearest_candidates(t, cand);
    const bool by = N.flat.inside_by_nearest(cand);
    c.by_nearest += by;
    c.by_wedge += by && !pendepth::nonconvex2::NfpFlat::inside_by_candidates(cand);
    ASSERT_TRUE(!by || exact) << what << " σ's candidates prove t ∈ O wrongly, t = " << t.transpose();
  }
  ASSERT_EQ(nfp.overlapping(t), exact) << what << " t = " << t.transpose();
  const Depth2 sigma_exact = N.minimum(t, true);
  ASSERT_TRUE(same(nfp.minimum(t), sigma_exact)) << what << " σ at t = " << t.transpose();
  // The lean query (fast and exact path) against the full exact answer's fields, bit for bit.
  ASSERT_TRUE(same(nfp.depth_value(t), sigma_exact)) << what << " lean σ at t = " << t.transpose();
  ASSERT_TRUE(same(N.minimum_value(t, true), sigma_exact)) << what << " lean exact σ at t = " << t.transpose();
  for (const Vec2& d_in : dirs) {
    if (d_in.x() == 0 && d_in.y() == 0) continue;
    const Vec2 d = pendepth::nonconvex2::check_and_scale(t, d_in);
    if (N.flat.usable) {
      cand.clear();
      N.flat.first_hit_candidates(t, d, cand);
      const bool by = pendepth::nonconvex2::NfpFlat::inside_by_candidates(cand);
      c.by_first_hit += by, ++c.first_hit_checks;
      ASSERT_TRUE(!by || exact) << what << " σ_d's candidates prove t ∈ O wrongly, t = " << t.transpose() << " d = " << d.transpose();
    }
    const Depth2 along_exact = N.along(t, d, true);
    ASSERT_TRUE(same(nfp.along(t, d_in), along_exact)) << what << " σ_d at t = " << t.transpose() << " d = " << d_in.transpose();
    ASSERT_TRUE(same(nfp.directional_depth_value(t, d_in), along_exact))
        << what << " lean σ_d at t = " << t.transpose() << " d = " << d_in.transpose();
    ASSERT_TRUE(same(N.along_value(t, d, true), along_exact)) << what << " lean exact σ_d at t = " << t.transpose();
  }
}

// Degenerate and random placements of one pair.
void check_pair(const Polygon& P, const Polygon& Q, std::mt19937_64& rng, int random, const std::string& what,
                bool require_flat = true) {
  const NoFitPolygon2 nfp(P, Q);
  if (require_flat) ASSERT_TRUE(nfp_impl(nfp).flat.usable) << what;
  std::vector<Vec2> verts;
  for (const auto& poly : nfp.polygons())
    for (const auto& ring : poly) verts.insert(verts.end(), ring.begin(), ring.end());
  Vec2 lo = verts[0], hi = verts[0];
  for (const Vec2& v : verts) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y()), ua(0, 2 * M_PI);
  const std::vector<Vec2> axes{{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, 1}};
  auto dirs_for = [&](const Vec2& t) {
    std::vector<Vec2> d = axes;
    for (int k = 0; k < 2; ++k) d.push_back(verts[rng() % verts.size()] - t);  // rays through vertices
    const double a = ua(rng);
    d.emplace_back(std::cos(a), std::sin(a));
    return d;
  };
  auto near = [&](const Vec2& p) {
    for (int dx = -2; dx <= 2; ++dx)
      for (int dy = -2; dy <= 2; ++dy)
        if ((dx + dy) % 2 == 0 || dx == 0 || dy == 0) check_at(nfp, ulp_step(p, dx, dy), dirs_for(p), what);
  };
  // Ring vertices and points on ring edges (a quarter and a half along), with ulp moves.
  std::size_t step = std::max<std::size_t>(1, verts.size() / 24);
  for (const auto& poly : nfp.polygons())
    for (const auto& ring : poly)
      for (std::size_t i = 0; i < ring.size(); i += step) {
        const Vec2 &a = ring[i], &b = ring[(i + 1) % ring.size()];
        near(a);
        near(0.5 * (a + b));
        check_at(nfp, a + 0.25 * (b - a), dirs_for(a), what);
      }
  for (const auto& s : nfp.slits()) {
    near(s[0]), near(s[1]), near(0.5 * (s[0] + s[1]));
    const Vec2 n = Vec2(s[1].y() - s[0].y(), s[0].x() - s[1].x()) * 0x1p-20;
    check_at(nfp, 0.5 * (s[0] + s[1]) + n, dirs_for(s[0]), what);
  }
  for (const Vec2& p : nfp.points()) near(p);
  // Integer grid points in the box (integer pairs: placements level with vertices, on edges).
  if (hi.x() - lo.x() <= 64 && hi.y() - lo.y() <= 64)
    for (double x = std::floor(lo.x()); x <= hi.x(); x += 1)
      for (double y = std::floor(lo.y()); y <= hi.y(); y += 1) check_at(nfp, Vec2(x, y), axes, what);
  for (int k = 0; k < random; ++k) {
    const Vec2 t(ux(rng), uy(rng));
    check_at(nfp, t, dirs_for(t), what);
  }
}

Polygon quarter_turns(const Polygon& S, int k) {
  return mapped(S, [&](const Vec2& p) {
    Vec2 v = p;
    for (int i = 0; i < k; ++i) v = Vec2(-v.y(), v.x());
    return v;
  });
}

// The pair, Q turned by 1–3 quarter turns, and both turned by one.
void check_turned(const Polygon& P, const Polygon& Q, std::mt19937_64& rng, int random, const std::string& what) {
  check_pair(P, Q, rng, random, what);
  for (int k = 1; k < 4; ++k) check_pair(P, quarter_turns(Q, k), rng, random, what + " Q turned " + std::to_string(k));
  check_pair(quarter_turns(P, 1), quarter_turns(Q, 1), rng, random, what + " both turned");
}

TEST(NfpFastPath, ExactFits) {
  std::mt19937_64 rng(19001);
  const Polygon unit = Polygon::simple(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "unit");
  const Polygon square = Polygon::simple(std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, "square");
  {
    const Polygon P = Polygon::simple(polygon2_test::comb_ring(4, 3, 2, 5, 2), "comb P");
    auto r = polygon2_test::comb_ring(3, 2, 3, 5, 2);
    for (auto& p : r) p = Vec2(p.x(), -p.y());
    check_turned(P, Polygon::simple(r, "comb Q"), rng, 40, "combs");
  }
  check_turned(Polygon::simple(std::vector<Vec2>{{0, 0}, {7, 0}, {7, 8}, {5, 8}, {5, 2}, {2, 2}, {2, 8}, {0, 8}}, "U"),
               Polygon::simple(std::vector<Vec2>{{0, 0}, {3, 0}, {3, 1}, {0, 1}}, "block"), rng, 40, "slot");
  check_turned(Polygon({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{4, 4}, {6, 4}, {6, 6}, {4, 6}}}, "plate"), square, rng, 40,
               "hole fit");
  check_turned(Polygon::simple(std::vector<Vec2>{{0, 0}, {10, 0}, {10, 10}, {6, 10}, {6, 7}, {7, 7}, {7, 3}, {3, 3}, {3, 7}, {4, 7}, {4, 10}, {0, 10}},
                               "bottle"),
               square, rng, 40, "bottle");
  check_turned(Polygon({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{3, 4}, {7, 4}, {7, 5}, {3, 5}}}, "plate with a slot"), unit, rng, 40,
               "closed slot");
  // Non-integer exact fit: a slot of width 0.1 (not a dyadic) and a block of the same width.
  check_turned(Polygon::simple(std::vector<Vec2>{{0, 0}, {0.7, 0}, {0.7, 0.8}, {0.5, 0.8}, {0.5, 0.2}, {0.4, 0.2}, {0.4, 0.8}, {0, 0.8}}, "thin U"),
               Polygon::simple(std::vector<Vec2>{{0, 0}, {0.1, 0}, {0.1, 0.3}, {0, 0.3}}, "thin block"), rng, 60, "thin slot");
  const Counts& c = counts();
  EXPECT_GT(c.certified, c.queries / 4);  // the filter decides most placements ...
  EXPECT_GT(c.deferred, c.queries / 50);  // ... and defers on the degenerate ones
  EXPECT_GT(c.overlapping, c.queries / 10);
  std::cout << "[fast path] " << c.queries << " placements, " << c.certified << " certified, " << c.deferred
            << " deferred, " << c.overlapping << " overlapping\n";
}

TEST(NfpFastPath, NestingPieces) {
  std::mt19937_64 rng(19002);
  const auto albano = instance("albano.json");
  for (std::size_t i = 0; i < albano.size(); ++i)
    for (std::size_t j = 0; j < albano.size(); ++j)
      check_pair(albano[i], albano[j], rng, 20, "albano " + std::to_string(i) + " " + std::to_string(j));
  for (const std::string file : {"shirts", "trousers"}) {
    const auto pieces = instance(file + ".json");
    for (std::size_t k = 0; k < 6; ++k) {
      const std::size_t i = rng() % pieces.size(), j = rng() % pieces.size();
      check_turned(pieces[i], pieces[j], rng, 10, file + " " + std::to_string(i) + " " + std::to_string(j));
    }
  }
  // Both outcomes of inside_by_candidates occur (the shortcut, and the overlap test after it).
  const Counts& c = counts();
  EXPECT_GT(c.by_nearest, c.overlapping / 4);
  EXPECT_LT(c.by_nearest, c.overlapping);
  EXPECT_GT(c.by_first_hit, c.first_hit_checks / 20);
  EXPECT_GT(c.by_wedge, 0u);
  std::cout << "[inside by candidates] σ " << c.by_nearest << " (" << c.by_wedge << " by a reflex wedge) of " << c.overlapping
            << " overlapping placements, σ_d " << c.by_first_hit << " of " << c.first_hit_checks << " rays\n";
}

// σ's shared-vertex wedge (NfpFlat::inside_by_nearest): placements whose nearest point on ∂O is a
// ring vertex V — on the bisector of the two edges at V, to either side (into O at a reflex vertex,
// out of it at a convex one, where the same flags hold and the wedge must not fire), at several
// distances, at V and ulps from it, and scattered in a small box about V — every answer against
// the exact path (check_at: the shortcut only for t ∈ O, exact overlap test). Every wedge link
// joins two pieces whose rounded ends meet (within ulps) with a right turn of their rounded
// directions (where the rounding cannot flip the sign). Inputs with reflex vertices of O: exact
// fits (a slot, a bottle, combs, a hole fit: shared vertices of both shapes' parallel edges),
// shirts and trousers pieces, quarter turns.
void check_wedges(const Polygon& P, const Polygon& Q, std::mt19937_64& rng, const std::string& what, std::size_t& links) {
  const NoFitPolygon2 nfp(P, Q);
  const NoFitPolygon2::Impl& N = nfp_impl(nfp);
  ASSERT_TRUE(N.flat.usable) << what;
  // Every wedge vertex: its pieces' rounded ends there meet within ulps; arriving and leaving
  // rounded directions turn right where the rounding cannot flip the sign.
  std::vector<std::vector<std::size_t>> at[2];  // per vertex id: pieces leaving (0), arriving (1)
  for (std::size_t k = 0; k < N.wedge.size(); ++k)
    for (int side = 0; side < 2; ++side)
      if (const int v = N.wedge[k][side]; v >= 0) {
        for (auto& a : at) a.resize(std::max(a.size(), std::size_t(v) + 1));
        at[side][std::size_t(v)].push_back(k);
      }
  for (std::size_t v = 0; v < at[0].size(); ++v) {
    if (at[0][v].empty()) continue;
    ++links;
    const Vec2 V = N.pieces[at[0][v][0]].a;
    for (int side = 0; side < 2; ++side)
      for (std::size_t k : at[side][v]) {
        const Vec2 e = side == 0 ? N.pieces[k].a : N.pieces[k].b;
        ASSERT_LE((e - V).cwiseAbs().maxCoeff(), std::max(V.cwiseAbs().maxCoeff(), 1e-300) * 0x1p-48) << what << " wedge " << v << " ends apart";
        if (N.pieces[k].a == N.pieces[k].b) continue;
        for (std::size_t j : at[1 - side][v]) {
          if (N.pieces[j].a == N.pieces[j].b) continue;
          const Vec2 u = (side == 1 ? N.pieces[k] : N.pieces[j]).b - (side == 1 ? N.pieces[k] : N.pieces[j]).a;
          const Vec2 w = (side == 1 ? N.pieces[j] : N.pieces[k]).b - (side == 1 ? N.pieces[j] : N.pieces[k]).a;
          ASSERT_FALSE(u.x() * w.y() - u.y() * w.x() > u.norm() * w.norm() * 0x1p-40) << what << " wedge " << v << " turns left";
        }
      }
  }
  std::uniform_real_distribution<double> unit(-1, 1);
  const std::vector<Vec2> dirs{{1, 0}, {0, 1}, {-1, -1}};
  for (const auto& poly : nfp.polygons())
    for (const auto& ring : poly)
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Vec2 &a = ring[(i + ring.size() - 1) % ring.size()], &V = ring[i], &b = ring[(i + 1) % ring.size()];
        const Vec2 bis = (V - a).normalized() - (b - V).normalized();  // into O at a reflex vertex
        const double len = std::min((V - a).norm(), (b - V).norm());
        for (double s : {0.5, 0.125, 0x1p-10, 0x1p-30})
          for (double side : {1.0, -1.0}) check_at(nfp, V + side * s * len * bis, dirs, what);
        check_at(nfp, V, dirs, what);
        for (int dx = -1; dx <= 1; ++dx)
          for (int dy = -1; dy <= 1; ++dy) check_at(nfp, ulp_step(V, dx, dy), dirs, what);
        for (int r = 0; r < 4; ++r) check_at(nfp, V + 0.25 * len * Vec2(unit(rng), unit(rng)), dirs, what);
      }
}

TEST(NfpFastPath, ReflexWedges) {
  std::mt19937_64 rng(19007);
  counts() = Counts{};
  std::size_t links = 0;
  const Polygon unit = Polygon::simple(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "unit");
  const Polygon square = Polygon::simple(std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, "square");
  const Polygon slot = Polygon::simple(std::vector<Vec2>{{0, 0}, {7, 0}, {7, 8}, {5, 8}, {5, 2}, {2, 2}, {2, 8}, {0, 8}}, "U");
  const Polygon bottle = Polygon::simple(
      std::vector<Vec2>{{0, 0}, {10, 0}, {10, 10}, {6, 10}, {6, 7}, {7, 7}, {7, 3}, {3, 3}, {3, 7}, {4, 7}, {4, 10}, {0, 10}}, "bottle");
  const Polygon comb = Polygon::simple(polygon2_test::comb_ring(4, 3, 2, 5, 2), "comb P");
  const Polygon plate({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{4, 4}, {6, 4}, {6, 6}, {4, 6}}}, "plate");
  for (int k = 0; k < 4; ++k) {
    const std::string turn = " Q turned " + std::to_string(k);
    check_wedges(slot, quarter_turns(Polygon::simple(std::vector<Vec2>{{0, 0}, {3, 0}, {3, 1}, {0, 1}}, "block"), k), rng, "slot" + turn, links);
    check_wedges(bottle, quarter_turns(square, k), rng, "bottle" + turn, links);
    check_wedges(comb, quarter_turns(unit, k), rng, "comb" + turn, links);
    check_wedges(plate, quarter_turns(unit, k), rng, "plate" + turn, links);
    check_wedges(slot, quarter_turns(bottle, k), rng, "slot bottle" + turn, links);
  }
  for (const std::string file : {"shirts", "trousers", "albano"}) {
    const auto pieces = instance(file + ".json");
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t i = rng() % pieces.size(), j = rng() % pieces.size();
      check_wedges(pieces[i], quarter_turns(pieces[j], int(k)), rng, file + " " + std::to_string(i) + " " + std::to_string(j), links);
    }
  }
  const Counts& c = counts();
  EXPECT_GT(links, 40u);
  EXPECT_GT(c.by_wedge, 30u);  // the wedge fires (and, by check_at, only for t ∈ O)
  EXPECT_LT(c.by_nearest, c.overlapping);
  std::cout << "[reflex wedges] " << links << " links, σ proves t ∈ O " << c.by_nearest << " times (" << c.by_wedge
            << " by a wedge) of " << c.overlapping << " overlapping of " << c.queries << " placements\n";
}

// Pieces turned by angles that are not quarter turns (coordinates rounded once): edge directions
// of full 53-bit mantissas, whose four-term sums are often not two doubles (the generic rounded
// tier) and whose projections and crossings are never exact.
TEST(NfpFastPath, RotatedPieces) {
  std::mt19937_64 rng(19006);
  for (const std::string file : {"shirts", "trousers", "albano"}) {
    const auto pieces = instance(file + ".json");
    for (double deg : {30.0, 45.0, 117.0}) {
      const double a = deg * M_PI / 180, c = std::cos(a), s = std::sin(a);
      const std::size_t i = rng() % pieces.size(), j = rng() % pieces.size();
      const Polygon Q = mapped(pieces[j], [&](const Vec2& p) { return Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y()); });
      check_pair(pieces[i], Q, rng, 15, file + " " + std::to_string(i) + " " + std::to_string(j) + " Q turned " + std::to_string(deg));
    }
  }
}

// σ's tie table (NfpFlat::pline, nfp_lines.cpp) against rationals: two pieces share an id only if
// their edge lines are one exact line (cross of the directions and of the offset both 0 in mpq),
// and on these inputs every collinear pair shares one (the filter's windows miss none). Then
// placements where σ's candidates tie on one line: for each collinear pair whose rounded extents
// overlap, t beside the overlap's middle on O's side (left of the piece) at several distances
// (from 2⁻³⁰ to a quarter of the overlap) and at the middle itself — every answer against the exact
// path (check_at, bit for bit), and the number of placements whose candidates include two
// projections on pieces of one id (the lookup taken) counted. Near-collinear steps and tilts of
// 2⁻⁴⁰ put distinct lines inside the grouping's windows. Merging parallel lines without the exact
// test, or taking parallel exact-double lines as one, fails the first check; a tie decided for the
// later index fails check_at.
struct LineStats {
  std::size_t collinear = 0, missed = 0, placements = 0, lookups = 0;
};

void check_line_table(const Polygon& P, const Polygon& Q, std::mt19937_64& rng, LineStats& st, const std::string& what) {
  const NoFitPolygon2 nfp(P, Q);
  const auto& N = nfp_impl(nfp);
  if (!N.flat.usable) return;
  ASSERT_EQ(N.flat.pline.size(), N.pieces.size()) << what;
  auto q = [](double x) { return mpq_class(x); };
  auto collinear = [&](const pendepth::nonconvex2::Line& l, const pendepth::nonconvex2::Line& m) {
    const mpq_class lx = q(l.e1.x()) - q(l.e0.x()), ly = q(l.e1.y()) - q(l.e0.y());
    const mpq_class mx = q(m.e1.x()) - q(m.e0.x()), my = q(m.e1.y()) - q(m.e0.y());
    const mpq_class wx = q(m.c1.x()) + q(m.c2.x()) - q(l.c1.x()) - q(l.c2.x()), wy = q(m.c1.y()) + q(m.c2.y()) - q(l.c1.y()) - q(l.c2.y());
    return sgn(lx * my - ly * mx) == 0 && sgn(lx * wy - ly * wx) == 0;
  };
  std::uniform_real_distribution<double> u(0.1, 0.9);
  const std::vector<Vec2> dirs{{1, 0}, {0, 1}, {-1, -1}};
  for (std::size_t i = 0; i < N.pieces.size(); ++i)
    for (std::size_t j = i + 1; j < N.pieces.size(); ++j) {
      const bool col = collinear(N.pieces[i].edge, N.pieces[j].edge), one = N.flat.one_line(std::uint32_t(i), std::uint32_t(j));
      ASSERT_TRUE(!one || col) << what << " pieces " << i << ", " << j << " share a line id off one line";
      st.collinear += col, st.missed += col && !one;
      if (!col) continue;
      // The overlap of the two rounded extents along piece i's direction.
      const auto &a = N.pieces[i], &b = N.pieces[j];
      const Vec2 e = a.b - a.a;
      const double l2 = e.squaredNorm();
      if (!(l2 > 0)) continue;
      auto at = [&](const Vec2& p) { return (p - a.a).dot(e) / l2; };
      const double s0 = std::max(0.0, std::min(at(b.a), at(b.b))), s1 = std::min(1.0, std::max(at(b.a), at(b.b)));
      if (!(s1 - s0 > 0x1p-20)) continue;
      const Vec2 X = a.a + (s0 + u(rng) * (s1 - s0)) * e, n = Vec2(-e.y(), e.x()) / std::sqrt(l2);  // O's side: the left
      for (double d : {0.0, 0x1p-30, 0x1p-12, 0.01, 0.25 * (s1 - s0) * std::sqrt(l2)}) {
        const Vec2 t = X + d * n;
        std::vector<std::uint32_t> cand;
        N.flat.nearest_candidates(t, cand);
        bool tie = false;
        for (std::size_t x = 0; x < cand.size(); ++x)
          for (std::size_t y = x + 1; y < cand.size(); ++y)
            tie |= (cand[x] & cand[y] & pendepth::nonconvex2::NfpFlat::kInside) != 0 &&
                   N.flat.one_line(cand[x] & ~pendepth::nonconvex2::NfpFlat::kFlags, cand[y] & ~pendepth::nonconvex2::NfpFlat::kFlags);
        st.lookups += tie && N.overlapping_exact(t);
        ++st.placements;
        check_at(nfp, t, dirs, what);
      }
    }
}

TEST(NfpFastPath, LineTableTies) {
  std::mt19937_64 rng(19010);
  LineStats st;
  const auto albano = instance("albano.json");
  for (std::size_t i = 0; i < albano.size(); ++i)
    for (std::size_t j = i % 2; j < albano.size(); j += 2) check_line_table(albano[i], albano[j], rng, st, "albano " + std::to_string(i) + " " + std::to_string(j));
  for (const std::string file : {"shirts", "trousers"}) {
    const auto pieces = instance(file + ".json");
    for (std::size_t k = 0; k < 8; ++k) {
      const std::size_t i = rng() % pieces.size(), j = rng() % pieces.size();
      const std::string name = file + " " + std::to_string(i) + " " + std::to_string(j);
      check_line_table(pieces[i], pieces[j], rng, st, name);
      check_line_table(pieces[i], quarter_turns(pieces[j], 1 + int(k % 3)), rng, st, name + " Q turned");
      const double a = (30.0 + 29 * double(k)) * M_PI / 180, c = std::cos(a), s = std::sin(a);
      const Polygon Q = mapped(pieces[j], [&](const Vec2& p) { return Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y()); });
      check_line_table(pieces[i], Q, rng, st, name + " Q rotated");
    }
  }
  // Exact fits: a comb in a comb, a slot (long collinear runs of both shapes' parallel edges).
  const Polygon P = Polygon::simple(polygon2_test::comb_ring(4, 3, 2, 5, 2), "comb P");
  auto r = polygon2_test::comb_ring(3, 2, 3, 5, 2);
  for (auto& p : r) p = Vec2(p.x(), -p.y());
  check_line_table(P, Polygon::simple(r, "comb Q"), rng, st, "combs");
  check_line_table(Polygon::simple(std::vector<Vec2>{{0, 0}, {7, 0}, {7, 8}, {5, 8}, {5, 2}, {2, 2}, {2, 8}, {0, 8}}, "U"),
                   Polygon::simple(std::vector<Vec2>{{0, 0}, {3, 0}, {3, 1}, {0, 1}}, "block"), rng, st, "slot");
  // Near-collinear edges inside the grouping's windows (a step or a tilt of 2⁻⁴⁰ on the top edge):
  // parallel lines 2⁻⁴⁰ apart and lines 2⁻⁴¹ off parallel, which only the exact test separates.
  const Polygon unit = Polygon::simple(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "unit");
  for (const double e : {0x1p-40, -0x1p-40}) {
    const Polygon step = Polygon::simple(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 1}, {2, 1}, {2, 1 + e}, {0, 1 + e}}, "step");
    const Polygon tilt = Polygon::simple(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 1}, {2, 1}, {0, 1 + e}}, "tilt");
    for (int k = 0; k < 4; ++k) {
      check_line_table(quarter_turns(step, k), unit, rng, st, "step " + std::to_string(k));
      check_line_table(quarter_turns(tilt, k), quarter_turns(step, 1), rng, st, "tilt " + std::to_string(k));
    }
  }
  std::cout << "[line table] " << st.collinear << " collinear piece pairs, " << st.missed << " not grouped; " << st.placements
            << " placements beside them, " << st.lookups << " with a tie taken by the table\n";
  EXPECT_GT(st.collinear, 100u);
  EXPECT_EQ(st.missed, 0u);
  EXPECT_GT(st.lookups, st.placements / 20);
}

// Random star pairs with real and integer coordinates, holes included via the shared shapes.
TEST(NfpFastPath, RandomStars) {
  std::mt19937_64 rng(19003);
  for (int k = 0; k < 12; ++k) {
    const bool grid = k % 2 == 0;
    const Polygon P = nonconvex2_test::star(rng, 6 + int(rng() % 10), 5, 10, grid);
    const Polygon Q = nonconvex2_test::star(rng, 4 + int(rng() % 6), 1, 4, grid);
    check_turned(P, Q, rng, 30, "stars " + std::to_string(k));
  }
}

}  // namespace

namespace {

// Larger no-fit polygons: the overlap filter scans only t's horizontal slab of ring edges.
TEST(NfpFastPath, LargeRingsUseSlabs) {
  std::mt19937_64 rng(19004);
  for (int k = 0; k < 3; ++k) {
    const Polygon P = nonconvex2_test::star(rng, 60, 50, 100, k == 1);
    const Polygon Q = nonconvex2_test::star(rng, 24, 5, 12, k == 1);
    const NoFitPolygon2 nfp(P, Q);
    const auto& F = nfp_impl(nfp).flat;
    ASSERT_FALSE(F.slab.empty()) << k;
    ASSERT_TRUE(F.overlap_usable) << k;
    check_pair(P, Q, rng, 300, "large stars " + std::to_string(k), false);
  }
  // A comb against an L: tall edges (the teeth) span many slabs; slabs are kept only while each
  // holds at most max(64, a sixteenth of the) ring edges; the answers stay the exact path's.
  std::vector<Vec2> comb{{0, 0}, {79, 0}};
  for (int k = 39; k >= 0; --k) {
    comb.emplace_back(2 * k + 1, 12), comb.emplace_back(2 * k, 12);
    if (k > 0) comb.emplace_back(2 * k, 2), comb.emplace_back(2 * k - 1, 2);
  }
  const Polygon P = Polygon::simple(comb, "comb"), L = Polygon::simple(std::vector<Vec2>{{0, 0}, {0.5, 0}, {0.5, 2.5}, {3, 2.5}, {3, 3}, {0, 3}}, "L");
  const NoFitPolygon2 nfp(P, L);
  const auto& F = nfp_impl(nfp).flat;
  std::size_t edges = 0;
  for (const auto& poly : nfp.polygons())
    for (const auto& ring : poly) edges += ring.size();
  std::size_t widest = 0;
  for (std::size_t k = 0; k + 1 < F.slab.size(); ++k) widest = std::max<std::size_t>(widest, F.slab[k + 1] - F.slab[k]);
  EXPECT_LE(widest, std::max<std::size_t>(64, edges / 16));
  EXPECT_LE(F.rx0.size(), 8 * edges);
  std::cout << "[comb] " << edges << " ring edges, " << (F.slab.empty() ? 0 : F.slab.size() - 1) << " slabs, widest " << widest
            << ", overlap filter " << (F.overlap_usable ? "on" : "off") << "\n";
  check_pair(P, L, rng, 300, "comb", false);
}

}  // namespace

#include "geometry/rounded.hpp"

namespace {

using pendepth::nonconvex2::NfpFlat;
using pendepth::nonconvex2::Ray;

// The exact σ² and X − t (X the projection of t on E's line) as rationals, from the generic
// formulas of edge_cut.hpp (sq_dist and the translation numerators, an independent derivation).
struct ExactProjection {
  mpq_class v[3];
};
ExactProjection exact_projection(const Ray& E, const Vec2& t) {
  using pendepth::exact::LiftQ;
  using namespace pendepth::nonconvex2;
  const Cand c{E, Param{Param::Proj, {}}, Line{}};
  ExactProjection r;
  const auto s = sq_dist(c, t, LiftQ{});
  r.v[0] = s.first.v / s.second.v;
  for (int axis = 0; axis < 2; ++axis) {
    auto [n, dd] = param_nd(c.at, E, t, LiftQ{});
    auto o = axis == 0 ? LiftQ{}(E.o1.x()) + LiftQ{}(E.o2.x()) - LiftQ{}(t.x()) : LiftQ{}(E.o1.y()) + LiftQ{}(E.o2.y()) - LiftQ{}(t.y());
    auto dv = axis == 0 ? ray_dx(E, LiftQ{}) : ray_dy(E, LiftQ{});
    r.v[1 + axis] = (o * dd + n * dv).v / dd.v;
  }
  return r;
}

struct ValueStats {
  std::size_t pieces = 0, tried = 0, certified = 0, bounded = 0;
  double worst = 0;  // largest |exact − (hi + lo)| / bound seen
};

// One (E, t): when certified, σ² and X − t are RN of the exact values; whenever the bounds were
// computed, they hold (rationals): |exact − (hi + lo)| ≤ bound.
void check_projection(const Ray& E, const Vec2& t, ValueStats& st, const std::string& what) {
  NfpFlat F;
  F.pdd = {pendepth::nonconvex2::piece_dd(E)};
  ++st.pieces;
  if (!F.pdd[0].ok) return;
  ++st.tried;
  {  // the tabled 1/|D|² (q = c·1/|D|²) within ρ_i < 2⁻⁹⁶ of the exact reciprocal
    auto q = [](double x) { return mpq_class(x); };
    const mpq_class dx = q(E.a1.x()) + q(E.a2.x()) - q(E.b1.x()) - q(E.b2.x()), dy = q(E.a1.y()) + q(E.a2.y()) - q(E.b1.y()) - q(E.b2.y());
    const mpq_class inv = 1 / (dx * dx + dy * dy);
    ASSERT_LE(abs(q(F.pdd[0].ddinv) + q(F.pdd[0].ddinvl) - inv), inv * q(0x1p-96)) << what << " 1/|D|²";
  }
  const ExactProjection X = exact_projection(E, t);
  if (sgn(X.v[0]) == 0) return;  // t on the line: never a query (t ∈ O is on no piece)
  double s2;
  Vec2 tr;
  NfpFlat::ProjectionDiag diag;
  const bool ok = F.projection_values(0, t, s2, tr, &diag);
  if (diag.set) {
    ++st.bounded;
    for (int i = 0; i < 3; ++i) {
      const mpq_class err = abs(X.v[i] - mpq_class(diag.hi[i]) - mpq_class(diag.lo[i]));
      ASSERT_LE(err, mpq_class(diag.bound[i])) << what << " value " << i << " t = " << t.transpose();
      if (diag.bound[i] > 0) st.worst = std::max(st.worst, mpq_class(err / mpq_class(diag.bound[i])).get_d());
    }
  }
  if (!ok) return;
  ++st.certified;
  ASSERT_TRUE(same(s2, pendepth::exact::round_nearest(X.v[0]))) << what << " σ² at t = " << t.transpose();
  ASSERT_TRUE(same(tr.x(), pendepth::exact::round_nearest(X.v[1]))) << what << " x at t = " << t.transpose();
  ASSERT_TRUE(same(tr.y(), pendepth::exact::round_nearest(X.v[2]))) << what << " y at t = " << t.transpose();
}

Ray edge_ray(const Vec2& o1, const Vec2& o2, const Vec2& a1, const Vec2& a2, const Vec2& b1, const Vec2& b2) {
  Ray E;
  E.o1 = o1, E.o2 = o2, E.a1 = a1, E.a2 = a2, E.b1 = b1, E.b2 = b2;
  return E;
}

// nfp_value.cpp's double-double σ² and translation at a projection against exact rationals: every
// certified value is RN(exact) bit for bit, and every error bound holds; the bounds are not loose
// by more than 2¹² on these inputs (shrinking them that much, or dropping them, fails the
// ASSERT_LE above); the per-piece 1/|D|² within its bound 2⁻⁹⁶ (rationals). Inputs: the pieces
// of real no-fit polygons with random placements and placements ulps from the edge lines, random
// edges over 2^±200 magnitudes, axis-parallel edges with placements whose exact offset is a
// rounding tie, and dyadic ties at direction (1, 2).
void projection_values_against_rationals() {
  std::mt19937_64 rng(19005);
  ValueStats st;
  const auto albano = instance("albano.json");
  for (std::size_t i = 0; i < albano.size(); i += 3)
    for (std::size_t j = 0; j < albano.size(); j += 2) {
      const NoFitPolygon2 nfp(albano[i], albano[j]);
      const auto& N = nfp_impl(nfp);
      for (std::size_t k = 0; k < N.pieces.size(); k += 3) {
        const auto& pc = N.pieces[k];
        std::uniform_real_distribution<double> u(-1, 1), f(0, 1);
        const Vec2 span = pc.b - pc.a;
        for (int r = 0; r < 6; ++r) {
          Vec2 t = pc.a + f(rng) * span + Vec2(span.y(), -span.x()) * u(rng) * (r < 3 ? 1.0 : 0x1p-30);
          if (r == 5) t = ulp_step(pc.a + 0.5 * span, 1, -1);
          check_projection(pc.E, t, st, "albano " + std::to_string(i) + " " + std::to_string(j));
        }
      }
    }
  std::uniform_real_distribution<double> m(-1, 1);
  std::uniform_int_distribution<int> ex(-200, 200);
  for (int k = 0; k < 3000; ++k) {
    const double s = std::ldexp(1.0, ex(rng));
    auto v = [&]() -> Vec2 { return Vec2(m(rng), m(rng)) * s; };
    // Directions of two doubles (a sum edge's four-term direction is usually two doubles).
    const Ray E = edge_ray(v(), v() * 0x1p-20, v(), k % 2 ? v() * 0x1p-30 : Vec2(0, 0), Vec2(0, 0), Vec2(0, 0));
    check_projection(E, v(), st, "random " + std::to_string(k));
  }
  // Axis-parallel edges, offsets o − t = 1 + 2⁻⁵³ (a tie: RN = 1) and 1 + 3·2⁻⁵³ (RN = 1 + 2⁻⁵¹).
  for (double tail : {0x1p-53, 3 * 0x1p-53, -0x1p-53})
    for (int axis = 0; axis < 2; ++axis) {
      const Vec2 o2 = axis == 0 ? Vec2(0, tail) : Vec2(tail, 0);
      const Vec2 dir = axis == 0 ? Vec2(3, 0) : Vec2(0, -5);
      const Ray E = edge_ray(Vec2(0.5, 0.5), o2, dir, Vec2(0, 0), Vec2(0, 0), Vec2(0, 0));
      check_projection(E, Vec2(-0.5, -0.5), st, "axis tie");
    }
  // Direction (1, 2), |D|² = 5: translation y = c/5 = 1 + 2⁻⁵³, a tie (exact: must not be certified
  // as 1 + 2⁻⁵² nor mis-rounded).
  check_projection(edge_ray(Vec2(0, 0), Vec2(0, 0), Vec2(1, 2), Vec2(0, 0), Vec2(0, 0), Vec2(0, 0)), Vec2(5 * 0x1p-54, -5), st, "tie (1, 2)");
  // σ_d's crossing value λ = line_num / line_den on the same pieces, random rays.
  std::size_t crossings = 0, crossed = 0, axis_crossings = 0;
  double worst_cross = 0;
  for (std::size_t i = 0; i < albano.size(); i += 3)
    for (std::size_t j = 1; j < albano.size(); j += 2) {
      const NoFitPolygon2 nfp(albano[i], albano[j]);
      const auto& N = nfp_impl(nfp);
      std::uniform_real_distribution<double> f(0, 1), a(0, 2 * M_PI);
      for (std::size_t k = 0; k < N.pieces.size(); ++k) {
        const auto& pc = N.pieces[k];
        const Vec2 t = pc.a + f(rng) * (pc.b - pc.a) + Vec2(f(rng) - 0.5, f(rng) - 0.5) * 50;
        const double an = a(rng);
        const Vec2 d = pendepth::nonconvex2::check_and_scale(t, Vec2(std::cos(an), std::sin(an)));
        const Ray ray = Ray::query(t, d);
        using pendepth::exact::LiftQ;
        const auto den = pendepth::nonconvex2::line_den(pc.edge, ray, LiftQ{});
        if (sgn(den.v) == 0) continue;
        const mpq_class lam = pendepth::nonconvex2::line_num(pc.edge, ray, LiftQ{}).v / den.v;
        if (sgn(lam) == 0) continue;
        ++crossings;
        double l;
        NfpFlat::ProjectionDiag diag;
        const bool ok = N.flat.crossing_value(std::uint32_t(k), t, d, l, &diag);
        if (diag.set) {
          // The certificate's two bounds (nfp_value.cpp crossing_certified): the denominator's
          // double-double within its bound, and the residual N − q·D within E of r̃ (N and D
          // divided by the reported scale: an axis-parallel edge's ±E, else 1).
          const mpq_class sc = mpq_class(diag.scale[0]) + mpq_class(diag.scale[1]);
          ASSERT_NE(sgn(sc), 0) << "crossing scale " << k;
          const mpq_class num = pendepth::nonconvex2::line_num(pc.edge, ray, LiftQ{}).v / sc, dens = den.v / sc;
          axis_crossings += diag.scale[0] != 1 || diag.scale[1] != 0;
          ASSERT_LE(abs(dens - mpq_class(diag.hi[2]) - mpq_class(diag.lo[2])), mpq_class(diag.bound[2])) << "crossing den " << k;
          const mpq_class err = abs(num - mpq_class(diag.hi[0]) * dens - mpq_class(diag.hi[1]));
          ASSERT_LE(err, mpq_class(diag.bound[1])) << "crossing residual " << k;
          worst_cross = std::max(worst_cross, mpq_class(err / mpq_class(diag.bound[1])).get_d());
        }
        if (!ok) continue;
        ++crossed;
        ASSERT_TRUE(same(l, pendepth::exact::round_nearest(lam))) << "crossing " << k << " t = " << t.transpose();
      }
    }
  std::cout << "[crossing values] " << crossings << " rays (" << axis_crossings << " on axis-parallel edges), " << crossed
            << " certified; worst error / bound " << worst_cross << "\n";
  EXPECT_GT(crossed, crossings * 9 / 10);
  EXPECT_GT(axis_crossings, crossings / 10);  // the axis-parallel shortcut is exercised
  EXPECT_GT(worst_cross, 0x1p-12);
  std::cout << "[projection values] " << st.pieces << " edges, " << st.tried << " tried, " << st.bounded << " bounded, " << st.certified
            << " certified; worst error / bound " << st.worst << "\n";
  EXPECT_GT(st.certified, st.tried * 9 / 10);
  EXPECT_GT(st.worst, 0x1p-12);
}

}  // namespace

namespace {

// nfp_fast.cpp's nearest_candidates against exact arithmetic: (1) every piece exactly nearest to t
// is a candidate (brute force over all pieces, exact comparisons of squared distances); (2) every
// flag is right — kInside: t's projection strictly inside the exact piece, kBeforeLo / kBeyondHi:
// strictly before its lo end / beyond its hi end (exact compare_params), the decisions MinBest
// takes from them instead of comparing exactly; (3) the error bound B = 2⁻⁴⁰·M² of the floating
// dot(t − a, b − a) and |b − a|² − dot holds against the exact ends (rationals) on every piece, so
// removing it (B = 0) fails (2), and shrinking it by more than the reported margin fails (3).
// Placements: random, at piece ends and their perpendiculars with ±1–2 ulp moves (projections on
// or next to an end), on albano pairs, rotated pieces (ends not representable) and an exact fit.
// The exact end `p` of piece pc minus t on one axis (rationals).
mpq_class exact_end_rel(const pendepth::nonconvex2::NfpPiece& pc, const pendepth::nonconvex2::Param& p, const Vec2& t, int axis) {
  using namespace pendepth::nonconvex2;
  using pendepth::exact::LiftQ;
  auto [n, dd] = param_nd(p, pc.E, t, LiftQ{});
  auto o = axis == 0 ? LiftQ{}(pc.E.o1.x()) + LiftQ{}(pc.E.o2.x()) - LiftQ{}(t.x()) : LiftQ{}(pc.E.o1.y()) + LiftQ{}(pc.E.o2.y()) - LiftQ{}(t.y());
  auto dv = axis == 0 ? ray_dx(pc.E, LiftQ{}) : ray_dy(pc.E, LiftQ{});
  return mpq_class((o * dd + n * dv).v / dd.v);
}

// The inputs of the candidate-flag suites: every third × fourth ordered albano pair, two random
// shirts and trousers pairs each with Q turned by each of `degrees` (rounded: ends not
// representable), and a thin slot (a non-dyadic exact fit, 40 random placements);
// `check(nfp, random, what)` for each, `random` placements asked of the nesting pairs.
template <class Check>
void flag_inputs(std::mt19937_64& rng, std::initializer_list<double> degrees, int random, Check check) {
  const auto albano = instance("albano.json");
  for (std::size_t i = 0; i < albano.size(); i += 3)
    for (std::size_t j = 1; j < albano.size(); j += 4)
      check(NoFitPolygon2(albano[i], albano[j]), random, "albano " + std::to_string(i) + " " + std::to_string(j));
  for (const std::string file : {"shirts", "trousers"}) {
    const auto pieces = instance(file + ".json");
    for (double deg : degrees) {
      const double a = deg * M_PI / 180, c = std::cos(a), s = std::sin(a);
      const std::size_t i = rng() % pieces.size(), j = rng() % pieces.size();
      const Polygon Q = mapped(pieces[j], [&](const Vec2& p) { return Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y()); });
      check(NoFitPolygon2(pieces[i], Q), random, file + " rotated " + std::to_string(deg));
    }
  }
  check(NoFitPolygon2(Polygon::simple(std::vector<Vec2>{{0, 0}, {0.7, 0}, {0.7, 0.8}, {0.5, 0.8}, {0.5, 0.2}, {0.4, 0.2}, {0.4, 0.8}, {0, 0.8}}, "thin U"),
                      Polygon::simple(std::vector<Vec2>{{0, 0}, {0.1, 0}, {0.1, 0.3}, {0, 0.3}}, "thin block")),
        40, "thin slot");
}

// The box of the pieces' rounded ends.
void piece_box(const NoFitPolygon2::Impl& N, Vec2& lo, Vec2& hi) {
  lo = hi = N.pieces[0].a;
  for (const auto& pc : N.pieces) lo = lo.cwiseMin(pc.a).cwiseMin(pc.b), hi = hi.cwiseMax(pc.a).cwiseMax(pc.b);
}

struct FlagStats {
  std::size_t queries = 0, candidates = 0, inside = 0, before = 0, beyond = 0, unflagged = 0, wrong_unguarded = 0;
  double worst = 0;  // largest |exact − floating| / B over the dot values checked
};

void check_flags(const NoFitPolygon2& nfp, const Vec2& t, FlagStats& st, const std::string& what) {
  using namespace pendepth::nonconvex2;
  using pendepth::exact::LiftQ;
  const auto& N = nfp_impl(nfp);
  const NfpFlat& F = N.flat;
  if (!F.usable) return;
  ++st.queries;
  std::vector<std::uint32_t> cand;
  F.nearest_candidates(t, cand);
  const double M = std::max({std::abs(t.x()), std::abs(t.y()), F.rmax}), B = 0x1p-40 * M * M;
  const Param proj{Param::Proj, {}};
  // Exact nearest point of each piece (as MinBest: the projection, clamped exactly).
  auto cand_of = [&](std::size_t k) {
    const NfpPiece& pc = N.pieces[k];
    Cand c{pc.E, proj, pc.edge};
    if (compare_params(proj, pc.lo, pc.E, t) <= 0) c.at = pc.lo;
    else if (compare_params(proj, pc.hi, pc.E, t) >= 0) c.at = pc.hi;
    return c;
  };
  auto sq = [&](const Cand& c) {
    const auto s = sq_dist(c, t, LiftQ{});
    return mpq_class(s.first.v / s.second.v);
  };
  std::vector<mpq_class> d(N.pieces.size());
  mpq_class best;
  for (std::size_t k = 0; k < N.pieces.size(); ++k) {
    d[k] = sq(cand_of(k));
    if (k == 0 || d[k] < best) best = d[k];
  }
  std::vector<bool> is_cand(N.pieces.size(), false);
  for (std::uint32_t c : cand) is_cand[c & ~NfpFlat::kFlags] = true;
  for (std::size_t k = 0; k < N.pieces.size(); ++k)
    if (d[k] == best) ASSERT_TRUE(is_cand[k]) << what << " nearest piece " << k << " not a candidate, t = " << t.transpose();
  // The floating dot values against the exact ends A, B (rationals), on every piece.
  for (std::size_t k = 0; k < N.pieces.size(); ++k) {
    const NfpPiece& pc = N.pieces[k];
    const mpq_class ax = exact_end_rel(pc, pc.lo, t, 0), ay = exact_end_rel(pc, pc.lo, t, 1), bx = exact_end_rel(pc, pc.hi, t, 0),
                    by = exact_end_rel(pc, pc.hi, t, 1);
    const mpq_class dot_exact = -(ax * (bx - ax) + ay * (by - ay));       // (t − A)·(B − A)
    const mpq_class rest_exact = bx * (bx - ax) + by * (by - ay);         // (B − t)·(B − A)
    const double wx = t.x() - F.px0[k], wy = t.y() - F.py0[k], ex = F.pex[k], ey = F.pey[k];
    const mpq_class cross_exact = (bx - ax) * -ay - (by - ay) * -ax;      // (B − A) × (t − A)
    const double dot = wx * ex + wy * ey, rest = ex * ex + ey * ey - dot, cross = F.side_of_piece(k, t.x(), t.y());
    for (const auto& [f, x] : {std::pair{dot, dot_exact}, std::pair{rest, rest_exact}, std::pair{cross, cross_exact}}) {
      const mpq_class err = abs(x - mpq_class(f));
      ASSERT_LE(err, mpq_class(B)) << what << " piece " << k << " t = " << t.transpose();
      st.worst = std::max(st.worst, mpq_class(err / mpq_class(B)).get_d());
      if ((f < 0) != (sgn(x) < 0) || (f > 0) != (sgn(x) > 0)) ++st.wrong_unguarded;  // the sign without B
    }
  }
  for (std::uint32_t c : cand) {
    ++st.candidates;
    const std::uint32_t k = c & ~NfpFlat::kFlags;
    const NfpPiece& pc = N.pieces[k];
    if (c & NfpFlat::kFromO) {  // t strictly left of the exact piece (on O's side)
      ASSERT_GT(pendepth::exact::exact_sign([&](auto L) {
                  return ray_dx(pc.E, L) * (L(t.y()) - L(pc.E.o1.y()) - L(pc.E.o2.y())) -
                         ray_dy(pc.E, L) * (L(t.x()) - L(pc.E.o1.x()) - L(pc.E.o2.x()));
                }),
                0)
          << what << " piece " << k << " t = " << t.transpose();
    }
    if (c & NfpFlat::kInside) {
      ++st.inside;
      ASSERT_GT(compare_params(proj, pc.lo, pc.E, t), 0) << what << " piece " << k << " t = " << t.transpose();
      ASSERT_LT(compare_params(proj, pc.hi, pc.E, t), 0) << what << " piece " << k << " t = " << t.transpose();
    } else if (c & NfpFlat::kBeforeLo) {
      ++st.before;
      ASSERT_LT(compare_params(proj, pc.lo, pc.E, t), 0) << what << " piece " << k << " t = " << t.transpose();
    } else if (c & NfpFlat::kBeyondHi) {
      ++st.beyond;
      ASSERT_GT(compare_params(proj, pc.hi, pc.E, t), 0) << what << " piece " << k << " t = " << t.transpose();
    } else {
      ++st.unflagged;
    }
  }
}

void check_flags_pair(const NoFitPolygon2& nfp, std::mt19937_64& rng, int random, FlagStats& st, const std::string& what) {
  const auto& N = nfp_impl(nfp);
  if (N.pieces.empty()) return;
  Vec2 lo, hi;
  piece_box(N, lo, hi);
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y()), u(0.01, 1);
  for (int k = 0; k < random; ++k) check_flags(nfp, Vec2(ux(rng), uy(rng)), st, what);
  // Perpendiculars at the ends of a few pieces: the projection falls on the end, or ulps beside.
  for (std::size_t k = 0; k < N.pieces.size(); k += std::max<std::size_t>(1, N.pieces.size() / 6)) {
    const auto& pc = N.pieces[k];
    const Vec2 n = Vec2(pc.a.y() - pc.b.y(), pc.b.x() - pc.a.x()) * u(rng);
    for (const Vec2& end : {pc.a, pc.b})
      for (int s = -2; s <= 2; ++s) check_flags(nfp, ulp_step(end + n, s, -s), st, what), check_flags(nfp, ulp_step(end, s, s), st, what);
  }
}

TEST(NfpFastPath, NearestCandidateFlagsAgainstExact) {
  std::mt19937_64 rng(19007);
  FlagStats st;
  flag_inputs(rng, {30.0, 117.0}, 10, [&](const NoFitPolygon2& nfp, int random, const std::string& what) {
    check_flags_pair(nfp, rng, random, st, what);
  });
  std::cout << "[nearest flags] " << st.queries << " placements, " << st.candidates << " candidates: " << st.inside << " inside, "
            << st.before << " before lo, " << st.beyond << " beyond hi, " << st.unflagged << " decided exactly; floating sign wrong "
            << "without the bound " << st.wrong_unguarded << " times; worst error / bound " << st.worst << "\n";
  EXPECT_GT(st.inside, st.queries / 4);
  EXPECT_GT(st.before + st.beyond, st.queries / 20);
  EXPECT_GT(st.unflagged, 0u);
  EXPECT_GT(st.wrong_unguarded, 0u);  // the bound is needed: B = 0 would mis-flag these
  EXPECT_GT(st.worst, 0x1p-13);       // and B shrunk by 2¹³ fails the ASSERT_LE above
}

// nfp_fast.cpp's first_hit_candidates against exact arithmetic (rationals on the exact piece ends,
// exact_end_rel): (1) every flag is right — kInside: the ray crosses the exact piece's interior
// at some λ > 0 (ends strictly on opposite sides of the ray's line, λ = A × (B − A) / d × (B − A)
// > 0 with A, B the ends minus t), kFromO: and its lo end strictly right of the ray — for any t
// (inside_by_candidates trusts them before the overlap test); (2) for t ∈ O (exact test) every
// piece hit first (least exact λ > 0 over all pieces: a crossing, or a collinear piece's nearer
// end) is a candidate. Placements stress the pieces spanning t's perpendicular, whose side of
// the crossing the scan now certifies by side_of_piece: t beside a piece's middle at 2⁻⁴⁰ to 0.5
// of its length on either side, rays along the piece (parallel: undecided), turned by 2⁻³⁰ to
// 0.3 rad either way (crossing just ahead or just behind t), and random t and d.
struct HitStats {
  std::size_t rays = 0, candidates = 0, crossing = 0, from_o = 0, spanning = 0, completeness = 0;
};

void check_first_hits(const NoFitPolygon2& nfp, const Vec2& t, const Vec2& d_in, HitStats& st, const std::string& what) {
  using namespace pendepth::nonconvex2;
  const auto& N = nfp_impl(nfp);
  const NfpFlat& F = N.flat;
  if (!F.usable || (d_in.x() == 0 && d_in.y() == 0)) return;
  const Vec2 d = check_and_scale(t, d_in);
  ++st.rays;
  std::vector<std::uint32_t> cand;
  F.first_hit_candidates(t, d, cand);
  {
    // The same list from the other ISA's line test (four lanes, two lanes and scalar steps).
    std::vector<std::uint32_t> other;
    const bool saved = pendepth::isa::use_v3();
    pendepth::isa::use_v3() = !saved && pendepth::isa::v3_available();
    F.first_hit_candidates(t, d, other);
    pendepth::isa::use_v3() = saved;
    ASSERT_EQ(cand, other) << what << " t = " << t.transpose() << " d = " << d.transpose();
  }
  const mpq_class dx(d.x()), dy(d.y());
  // Per piece: the exact λ of its first point on the ray (λ > 0), or none.
  const std::size_t n = N.pieces.size();
  std::vector<mpq_class> lambda(n);
  std::vector<bool> hit(n, false);
  std::vector<int> sa(n), sb(n), slam(n);
  for (std::size_t k = 0; k < n; ++k) {
    const NfpPiece& pc = N.pieces[k];
    const mpq_class ax = exact_end_rel(pc, pc.lo, t, 0), ay = exact_end_rel(pc, pc.lo, t, 1), bx = exact_end_rel(pc, pc.hi, t, 0),
                    by = exact_end_rel(pc, pc.hi, t, 1);
    const mpq_class ca = dx * ay - dy * ax, cb = dx * by - dy * bx, den = cb - ca;
    sa[k] = sgn(ca), sb[k] = sgn(cb), slam[k] = 0;
    if (sa[k] * sb[k] > 0) continue;  // misses the line
    if (den != 0) {
      const mpq_class l = (ax * (by - ay) - ay * (bx - ax)) / den;
      slam[k] = sgn(l);
      if (l > 0) lambda[k] = l, hit[k] = true;
    } else if (sa[k] == 0) {  // along the line: the nearer end ahead
      const mpq_class la = (dx * ax + dy * ay) / (dx * dx + dy * dy), lb = (dx * bx + dy * by) / (dx * dx + dy * dy);
      if (la > 0 && lb > 0) lambda[k] = std::min(la, lb), hit[k] = true;
    }
  }
  std::vector<bool> is_cand(n, false);
  for (std::uint32_t c : cand) {
    ++st.candidates;
    const std::uint32_t k = c & ~NfpFlat::kFlags;
    is_cand[k] = true;
    if (c & NfpFlat::kInside) {
      ++st.crossing;
      ASSERT_TRUE(sa[k] * sb[k] < 0 && slam[k] > 0) << what << " piece " << k << " flagged crossing, t = " << t.transpose() << " d = " << d.transpose();
      if (std::min(mpq_class(d.x() * (F.px0[k] - t.x()) + d.y() * (F.py0[k] - t.y())),
                   mpq_class(d.x() * (F.px1[k] - t.x()) + d.y() * (F.py1[k] - t.y()))) <= 0)
        ++st.spanning;  // certified by the side of t, not by the dot products
    }
    if (c & NfpFlat::kFromO) {
      ++st.from_o;
      ASSERT_TRUE((c & NfpFlat::kInside) && sa[k] < 0) << what << " piece " << k << " flagged from O, t = " << t.transpose();
    }
  }
  if (!N.overlapping_exact(t)) return;
  const mpq_class* best = nullptr;
  for (std::size_t k = 0; k < n; ++k)
    if (hit[k] && (!best || lambda[k] < *best)) best = &lambda[k];
  ASSERT_TRUE(best) << what << " t ∈ O but the ray hits no piece, t = " << t.transpose();
  for (std::size_t k = 0; k < n; ++k)
    if (hit[k] && lambda[k] == *best) {
      ++st.completeness;
      ASSERT_TRUE(is_cand[k]) << what << " first piece " << k << " not a candidate, t = " << t.transpose() << " d = " << d.transpose();
    }
}

void check_first_hits_pair(const NoFitPolygon2& nfp, std::mt19937_64& rng, int random, HitStats& st, const std::string& what) {
  const auto& N = nfp_impl(nfp);
  if (N.pieces.empty()) return;
  Vec2 lo, hi;
  piece_box(N, lo, hi);
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y()), ua(0, 2 * M_PI);
  for (int k = 0; k < random; ++k) {
    const double a = ua(rng);
    check_first_hits(nfp, Vec2(ux(rng), uy(rng)), Vec2(std::cos(a), std::sin(a)), st, what);
  }
  auto turned = [](const Vec2& v, double a) { return Vec2(std::cos(a) * v.x() - std::sin(a) * v.y(), std::sin(a) * v.x() + std::cos(a) * v.y()); };
  for (std::size_t k = 0; k < N.pieces.size(); k += std::max<std::size_t>(1, N.pieces.size() / 8)) {
    const auto& pc = N.pieces[k];
    const Vec2 e = pc.b - pc.a, nrm(-e.y(), e.x());
    if (e.x() == 0 && e.y() == 0) continue;
    for (double off : {0x1p-40, 0x1p-20, 0.01, 0.5})
      for (double side : {1.0, -1.0}) {
        const Vec2 t = 0.5 * (pc.a + pc.b) + side * off * nrm;
        for (double dir : {1.0, -1.0})
          for (double a : {0.0, 0x1p-30, -0x1p-30, 0.01, -0.01, 0.3, -0.3}) check_first_hits(nfp, t, turned(dir * e, a), st, what);
      }
  }
}

TEST(NfpFastPath, FirstHitCandidatesAgainstExact) {
  std::mt19937_64 rng(19011);
  HitStats st;
  flag_inputs(rng, {0.0, 30.0}, 20, [&](const NoFitPolygon2& nfp, int random, const std::string& what) {
    check_first_hits_pair(nfp, rng, random, st, what);
  });
  std::cout << "[first-hit flags] " << st.rays << " rays, " << st.candidates << " candidates: " << st.crossing << " crossing ("
            << st.spanning << " spanning t's perpendicular), " << st.from_o << " from O; " << st.completeness << " first pieces found\n";
  EXPECT_GT(st.spanning, st.rays / 50);  // the side certificate is exercised
  EXPECT_GT(st.candidates, st.crossing);  // and undecided pieces occur
  EXPECT_GT(st.completeness, st.rays / 4);
}

}  // namespace

namespace {

// One certified value against exact rationals (σ² = s2x, translation V): every error bound the
// diagnostics report holds (the σ² one's tightness is kept in `worst`), and a certified answer
// (ok) is RN(exact) bit for bit.
void check_certified_values(const std::string& what, const Vec2& t, const mpq_class& s2x, const mpq_class V[2],
                            const pendepth::nonconvex2::NfpFlat::ProjectionDiag& diag, bool ok, double s2,
                            const Vec2& tr, double& worst) {
  if (diag.set) {
    const mpq_class ex[3] = {s2x, V[0], V[1]};
    for (int i = 0; i < 3; ++i) {
      const mpq_class err = abs(ex[i] - mpq_class(diag.hi[i]) - mpq_class(diag.lo[i]));
      ASSERT_LE(err, mpq_class(diag.bound[i])) << what << " value " << i << " t = " << t.transpose();
      if (i == 0) worst = std::max(worst, mpq_class(err / mpq_class(diag.bound[0])).get_d());
    }
  }
  if (!ok) return;
  ASSERT_TRUE(same(s2, pendepth::exact::round_nearest(s2x))) << what << " σ² at t = " << t.transpose();
  ASSERT_TRUE(same(tr.x(), pendepth::exact::round_nearest(V[0]))) << what << " x at t = " << t.transpose();
  ASSERT_TRUE(same(tr.y(), pendepth::exact::round_nearest(V[1]))) << what << " y at t = " << t.transpose();
}

// nfp_value.cpp's σ² and translation at a sum vertex (μ = 0: X = o, μ = 1: X = o + D) against
// exact rationals: every certified value is RN(exact) bit for bit and every error bound holds;
// the σ² bound is not loose by more than 2¹² on these inputs (shrinking it that much, or dropping
// it, fails). Inputs: the ends of real no-fit polygon edges with placements at random distances,
// ulps away and on an axis through the vertex (an exact zero coordinate), random rays over 2^±200.
void vertex_values_against_rationals() {
  using pendepth::exact::LiftQ;
  using namespace pendepth::nonconvex2;
  std::mt19937_64 rng(19008);
  std::size_t tried = 0, certified = 0;
  double worst = 0;
  auto check = [&](const Ray& E, int end, const Vec2& t, const std::string& what) {
    NfpFlat F;
    F.pdd = {piece_dd(E)};
    if (!F.pdd[0].ok) return;
    mpq_class V[2];
    for (int axis = 0; axis < 2; ++axis) {
      auto o = axis == 0 ? LiftQ{}(E.o1.x()) + LiftQ{}(E.o2.x()) - LiftQ{}(t.x()) : LiftQ{}(E.o1.y()) + LiftQ{}(E.o2.y()) - LiftQ{}(t.y());
      V[axis] = end == 0 ? o.v : mpq_class(o.v + (axis == 0 ? ray_dx(E, LiftQ{}) : ray_dy(E, LiftQ{})).v);
    }
    const mpq_class s2x = V[0] * V[0] + V[1] * V[1];
    if (sgn(s2x) == 0) return;
    ++tried;
    double s2;
    Vec2 tr;
    NfpFlat::ProjectionDiag diag;
    const bool ok = F.vertex_values(0, end, t, s2, tr, &diag);
    check_certified_values(what, t, s2x, V, diag, ok, s2, tr, worst);
    certified += ok;
  };
  const auto albano = instance("albano.json");
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t i = 0; i < albano.size(); i += 3)
    for (std::size_t j = 0; j < albano.size(); j += 2) {
      const NoFitPolygon2 nfp(albano[i], albano[j]);
      const auto& N = nfp_impl(nfp);
      for (std::size_t k = 0; k < N.pieces.size(); k += 2) {
        const auto& pc = N.pieces[k];
        for (int end = 0; end < 2; ++end) {
          const Vec2 X = end == 0 ? Vec2(pc.E.o1 + pc.E.o2) : Vec2(pc.E.o1 + pc.E.o2 + pc.E.a1 + pc.E.a2 - pc.E.b1 - pc.E.b2);
          check(pc.E, end, X + Vec2(u(rng), u(rng)) * 30, "albano far");
          check(pc.E, end, X + Vec2(u(rng), u(rng)) * 0x1p-30, "albano near");
          check(pc.E, end, ulp_step(X, 1, -2), "albano ulps");
          check(pc.E, end, Vec2(X.x(), X.y() + 7 * u(rng)), "albano axis");
        }
      }
    }
  std::uniform_real_distribution<double> m(-1, 1);
  std::uniform_int_distribution<int> ex(-200, 200);
  for (int k = 0; k < 3000; ++k) {
    const double s = std::ldexp(1.0, ex(rng));
    auto v = [&]() -> Vec2 { return Vec2(m(rng), m(rng)) * s; };
    const Ray E = edge_ray(v(), v() * 0x1p-20, v(), k % 2 ? v() * 0x1p-30 : Vec2(0, 0), Vec2(0, 0), Vec2(0, 0));
    check(E, k % 2, k % 3 ? v() : Vec2(E.o1 + E.o2) + v() * 0x1p-40, "random " + std::to_string(k));
  }
  // X − t an exact rounding tie per coordinate: 1 + 2⁻⁵³ (RN = 1, even), 1 + 3·2⁻⁵³ (RN = 1 + 2⁻⁵¹),
  // a tie in y only, and t beyond X; both ends (μ = 1: X = o + D, D exact).
  std::size_t ties = 0;
  for (const Vec2& t : {Vec2(-0x1p-53, 0.25), Vec2(-3 * 0x1p-53, -3 * 0x1p-53), Vec2(3 + 0x1p-52, 0.5), Vec2(0.5, -0x1p-53)})
    for (int end = 0; end < 2; ++end) {
      const std::size_t before = certified;
      check(edge_ray(Vec2(end == 0 ? 1 : -1, end == 0 ? 1 : -2), Vec2(0, 0), Vec2(2, 3), Vec2(0, 0), Vec2(0, 0), Vec2(0, 0)), end, t, "tie");
      ties += certified - before;
    }
  EXPECT_EQ(ties, 8u);  // exact ties are certified at both ends (e = 0; μ = 1 from the tabled o + D), checked against RN above
  std::cout << "[vertex values] " << ties << " of 8 exact ties certified; " << tried << " tried, " << certified << " certified; worst error / bound " << worst << "\n";
  EXPECT_GT(certified, tried * 9 / 10);
  EXPECT_GT(worst, 0x1p-12);
}

// nfp_value.cpp's table of cut ends (NfpFlat::pend: O's reflex vertices, the crossing of a piece's
// edge with another candidate's line) and σ² and translation there against exact rationals: every
// tabled coordinate lies within its bound of the exact end (a zero bound: exactly equal), every
// certified value is RN(exact) bit for bit, every error bound holds, and the σ² bound is not loose
// by more than 2¹² (shrinking it that much, or dropping it, fails). Inputs: every cut end of real
// no-fit polygons (albano, and shirts / trousers with Q turned by 30°: ends not representable),
// placements at random distances, ulps away and on an axis through the end (a zero coordinate).
void end_values_against_rationals() {
  using pendepth::exact::LiftQ;
  using namespace pendepth::nonconvex2;
  std::mt19937_64 rng(19009);
  std::size_t ends = 0, tabled = 0, exact_coords = 0, tried = 0, certified = 0;
  double worst = 0;
  std::uniform_real_distribution<double> u(-1, 1);
  auto check_nfp = [&](const NoFitPolygon2& nfp, const std::string& what) {
    const auto& N = nfp_impl(nfp);
    ASSERT_EQ(N.flat.pend.size(), N.pieces.size());
    for (std::uint32_t k = 0; k < N.pieces.size(); ++k) {
      const NfpPiece& pc = N.pieces[k];
      for (int end = 0; end < 2; ++end) {
        const Param& p = end == 0 ? pc.lo : pc.hi;
        const NfpFlat::EndDD& x = N.flat.pend[k][end];
        if (p.kind != Param::Cut) {
          ASSERT_FALSE(x.ok) << what << " piece " << k;
          continue;
        }
        ++ends;
        if (!x.ok) continue;
        ++tabled;
        mpq_class X[2];
        for (int axis = 0; axis < 2; ++axis) {
          const auto nd = point_nd(p, pc.E, Vec2(0, 0), axis, LiftQ{});
          X[axis] = nd.first.v / nd.second.v;
          const double hi = axis == 0 ? x.x : x.y, lo = axis == 0 ? x.xl : x.yl, e = axis == 0 ? x.ex : x.ey;
          ASSERT_LE(abs(X[axis] - mpq_class(hi) - mpq_class(lo)), mpq_class(e)) << what << " piece " << k << " end " << end;
          exact_coords += e == 0;
        }
        // `far`: t at a query's usual distance; within ~2⁻⁴⁰·|X| of the end the table's bound
        // (2⁻⁹⁷·|X|) cannot certify X − t's rounding and the generic tier answers.
        auto check = [&](const Vec2& t, bool far) {
          const mpq_class V[2] = {X[0] - mpq_class(t.x()), X[1] - mpq_class(t.y())};
          const mpq_class s2x = V[0] * V[0] + V[1] * V[1];
          if (sgn(s2x) == 0) return;
          tried += far;
          double s2;
          Vec2 tr;
          NfpFlat::ProjectionDiag diag;
          const bool ok = N.flat.end_values(k, end, t, s2, tr, &diag);
          check_certified_values(what, t, s2x, V, diag, ok, s2, tr, worst);
          certified += far && ok;
        };
        const Vec2 a = end == 0 ? pc.a : pc.b;
        for (int r = 0; r < 4; ++r) check(a + Vec2(u(rng), u(rng)) * 30, true);
        check(a + Vec2(u(rng), u(rng)) * 0x1p-30, false);
        check(ulp_step(a, 1, -2), false);
        check(Vec2(a.x(), a.y() + 7 * u(rng)), false);  // on an axis through the rounded end
        check(Vec2(a.x() + 7 * u(rng), a.y()), false);
      }
    }
  };
  const auto albano = instance("albano.json");
  for (std::size_t i = 0; i < albano.size(); i += 2)
    for (std::size_t j = 1; j < albano.size(); j += 2) check_nfp(NoFitPolygon2(albano[i], albano[j]), "albano");
  for (const std::string file : {"shirts", "trousers"}) {
    const auto pieces = instance(file + ".json");
    const double a = 30 * M_PI / 180, c = std::cos(a), s = std::sin(a);
    for (int r = 0; r < 4; ++r) {
      const std::size_t i = rng() % pieces.size(), j = rng() % pieces.size();
      const Polygon Q = mapped(pieces[j], [&](const Vec2& p) { return Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y()); });
      check_nfp(NoFitPolygon2(pieces[i], Q), file + " rotated");
      check_nfp(NoFitPolygon2(pieces[i], pieces[j]), file);
    }
  }
  std::cout << "[end values] " << ends << " cut ends, " << tabled << " tabled (" << exact_coords << " coordinates exact); " << tried
            << " placements at query distances, " << certified << " certified; worst error / bound " << worst << "\n";
  EXPECT_GT(tabled, ends * 9 / 10);
  EXPECT_GT(exact_coords, 0u);
  EXPECT_GT(certified, tried * 9 / 10);
  EXPECT_GT(worst, 0x1p-12);
}

// The value functions have two builds (nfp_value.cpp): with the FMA instruction where the
// processor has it, else the residuals by splitting; both must give the same doubles. Each value
// test runs in both, and the two builds' outputs (values, certificates, the diagnostics' double-
// doubles and bounds) are compared bit for bit, plus the fast-vs-exact answers in the other build.
struct ValuesBuild {
  bool saved = pendepth::nonconvex2::nfp_values_fma();
  explicit ValuesBuild(bool fma) { pendepth::nonconvex2::nfp_values_fma() = fma && __builtin_cpu_supports("fma"); }
  ~ValuesBuild() { pendepth::nonconvex2::nfp_values_fma() = saved; }
};

TEST(NfpFastPath, ProjectionValuesAgainstRationals) {
  for (bool fma : {true, false}) {
    const ValuesBuild b(fma);
    projection_values_against_rationals();
  }
}

TEST(NfpFastPath, VertexValuesAgainstRationals) {
  for (bool fma : {true, false}) {
    const ValuesBuild b(fma);
    vertex_values_against_rationals();
  }
}

TEST(NfpFastPath, EndValuesAgainstRationals) {
  for (bool fma : {true, false}) {
    const ValuesBuild b(fma);
    end_values_against_rationals();
  }
}

// σ_d's crossing value λ = line_num / line_den on synthetic lines, against the rationals: λ
// exactly a double, exactly a rounding tie (never certified to the wrong side), one quarter-ulp
// either side of a tie, next to powers of two (the smaller gap below), and random lines and rays
// over 2^±200 magnitudes with inexact two-double points. Every certified value is RN(λ) bit for
// bit, in the FMA and the portable build.
TEST(NfpFastPath, CrossingValuesAgainstRationals) {
  using pendepth::exact::LiftQ;
  using pendepth::nonconvex2::Line;
  std::size_t tried = 0, certified = 0;
  auto check = [&](const Line& L, const Vec2& t, const Vec2& d, const std::string& what) {
    const pendepth::nonconvex2::Ray ray = pendepth::nonconvex2::Ray::query(t, d);
    const auto den = pendepth::nonconvex2::line_den(L, ray, LiftQ{});
    if (sgn(den.v) == 0) return;
    const mpq_class lam = pendepth::nonconvex2::line_num(L, ray, LiftQ{}).v / den.v;
    NfpFlat F;
    F.pdd = {pendepth::nonconvex2::piece_dd(pendepth::nonconvex2::Ray{}, &L)};
    ++tried;
    double v[2];
    bool ok[2];
    for (int m = 0; m < 2; ++m) {
      const ValuesBuild b(m == 0);
      ok[m] = F.crossing_value(0, t, d, v[m]);
    }
    ASSERT_EQ(ok[0], ok[1]) << what;
    if (!ok[0]) return;
    ++certified;
    ASSERT_TRUE(same(v[0], v[1])) << what;
    ASSERT_TRUE(same(v[0], pendepth::exact::round_nearest(lam))) << what << ": " << v[0] << " against " << lam.get_d();
  };
  auto line = [](const Vec2& c1, const Vec2& c2, const Vec2& e) {
    Line L;
    L.c1 = c1, L.c2 = c2, L.e0 = Vec2(0, 0), L.e1 = e;
    return L;
  };
  // Vertical line x = C, ray from 0 along (3, 0): λ = C/3 with C = 3·(m + δ) exactly (c1 + c2).
  std::size_t exact_ties = 0;
  for (double m : {1.0, 1.5, 2.0, 0.75, 1.0 + 0x1p-52})
    for (double frac : {0.0, 0.5, 0.25, 0.75, -0.5, -0.25, 1.0})
      for (double sgn_d : {1.0, -1.0}) {
        const double gap = m == 1.0 || m == 2.0 ? (frac < 0 ? 0.5 : 1.0) * 0x1p-52 * m : std::nextafter(m, 4.0) - m;
        const double delta = frac * gap;  // λ = m + δ: a tie at frac = ±0.5
        exact_ties += frac == 0.5 || frac == -0.5;
        check(line(Vec2(3 * m * sgn_d, 0), Vec2(3 * delta * sgn_d, 0), Vec2(0, 1)), Vec2(0, 0), Vec2(3 * sgn_d, 0), "tie family");
        check(line(Vec2(0, 5 * m), Vec2(0, 5 * delta), Vec2(1, 0)), Vec2(0, 0), Vec2(0, 5), "tie family y");
      }
  std::mt19937_64 rng(19011);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> ex(-200, 200);
  for (int k = 0; k < 20000; ++k) {
    const double s = std::ldexp(1.0, ex(rng));
    auto v = [&]() -> Vec2 { return Vec2(u(rng), u(rng)) * s; };
    check(line(v(), k % 2 ? v() * 0x1p-40 : Vec2(0, 0), v()), v(), Vec2(u(rng), u(rng)), "random " + std::to_string(k));
  }
  // Axis-parallel lines (λ = W/d on one axis: nfp_value.cpp's shortcut), points c1 + c2 of one and
  // two doubles, tails down to 2⁻⁶⁰ of the point (W inexact: its bound e_W), random and axis rays.
  for (int k = 0; k < 20000; ++k) {
    const double s = std::ldexp(1.0, ex(rng));
    auto v = [&]() -> Vec2 { return Vec2(u(rng), u(rng)) * s; };
    const Vec2 e = k % 2 ? Vec2(u(rng) * s, 0) : Vec2(0, u(rng) * s);
    const Vec2 c2 = k % 3 == 0 ? Vec2(0, 0) : v() * std::ldexp(1.0, -20 - int(rng() % 41));
    const Vec2 d = k % 5 == 0 ? Vec2(u(rng), 0) : k % 5 == 1 ? Vec2(0, u(rng)) : Vec2(u(rng), u(rng));
    check(line(v(), c2, e), v(), d, "axis " + std::to_string(k));
  }
  // Axis-parallel lines whose W = c − t on that axis is exactly a double (nfp_value.cpp's
  // axis_crossing_exact: λ = W/d by one division, no certificate): integer-like and binary-fraction
  // coordinates and placements, t level with c (W = 0: no crossing value), rays along every
  // quadrant, directions with one component a power of two or 1 + 2⁻⁵² (quotients on and next to
  // rounding midpoints of λ's neighbours), and exponents over the whole range.
  std::size_t exact_w = 0;
  std::uniform_int_distribution<int> small(-1000, 1000);
  for (int k = 0; k < 20000; ++k) {
    const double s = std::ldexp(1.0, ex(rng) / 2);
    const bool vertical = k % 2;
    const double c = small(rng) * s * (k % 7 == 0 ? 0.125 : 1), tt = small(rng) * s * (k % 5 == 0 ? 0.5 : 1), other = u(rng) * s;
    const double dc = k % 3 == 0 ? std::ldexp(1.0, int(rng() % 5)) * (k % 2 ? -1 : 1) : k % 3 == 1 ? 1 + 0x1p-52 : u(rng);
    const Vec2 t = vertical ? Vec2(tt, other) : Vec2(other, tt);
    const Vec2 d = vertical ? Vec2(dc, u(rng)) : Vec2(u(rng), dc);
    const Vec2 e = vertical ? Vec2(0, u(rng) * s + s) : Vec2(-u(rng) * s - s, 0);
    const Vec2 c1 = vertical ? Vec2(c, u(rng) * s) : Vec2(u(rng) * s, c);
    double w, err;
    pendepth::exact::two_sum(c, -tt, w, err);
    exact_w += err == 0 && w != 0;
    check(line(c1, Vec2(0, 0), e), t, d, "axis exact " + std::to_string(k));
  }
  std::cout << "[crossing certificate] " << tried << " lines, " << certified << " certified, " << exact_ties << " exact ties, " << exact_w
            << " exact W on axis-parallel lines\n";
  EXPECT_GT(exact_w, 10000u);  // the one-division shortcut is exercised
  EXPECT_GT(certified, tried * 9 / 10);
}

// check_and_scale's power-of-two product against the ldexp reference (the former code), and
// norm_accurate against the full tiered evaluation (on the raw and the scaled directions): the same
// doubles bit for bit on random directions over the whole exponent range, subnormal and
// near-overflow components, and components whose scaled partner underflows (rounded).
TEST(NfpFastPath, DirectionScalingMatchesLdexp) {
  auto reference = [](const Vec2& d) {
    const int e = std::ilogb(std::max(std::abs(d.x()), std::abs(d.y())));
    return Vec2(std::ldexp(d.x(), -e), std::ldexp(d.y(), -e));
  };
  std::mt19937_64 rng(19012);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> ex(-1074, 1023);
  std::vector<Vec2> ds = {{1, 0}, {0, -1}, {0x1p-1074, 0}, {-0x1p-1074, 0x1p-1060}, {0x1.fffffffffffffp1023, 1},
                          {0x1p1023, -0x1p-1074}, {0x1p-1022, 0x1.8p-1074}, {0x1p1022, 0x1.3p-60}, {0x1.2345p1000, 0x1.5p-70}};
  for (int k = 0; k < 200000; ++k) ds.emplace_back(std::ldexp(u(rng), ex(rng)), std::ldexp(u(rng), ex(rng)));
  std::size_t compared = 0;
  const bool saved = pendepth::isa::use_v3();
  for (const Vec2& d : ds) {
    if (d.x() == 0 && d.y() == 0) continue;
    ++compared;
    ASSERT_TRUE(same(pendepth::nonconvex2::check_and_scale(Vec2(0, 0), d), reference(d))) << std::hexfloat << d.transpose();
    // norm_accurate's direct DD tier against the full tiered evaluation (the former code), on the
    // portable path and on the x86-64-v3 clone where the processor has it.
    for (const Vec2& v : {d, pendepth::nonconvex2::check_and_scale(Vec2(0, 0), d)}) {
      const double want = std::sqrt(pendepth::exact::accurate_value([&](auto L) { return L(v.x()) * L(v.x()) + L(v.y()) * L(v.y()); }));
      for (bool v3 : {false, pendepth::isa::v3_available()}) {
        pendepth::isa::use_v3() = v3;
        const double got = pendepth::nonconvex2::norm_accurate(v);
        pendepth::isa::use_v3() = saved;
        ASSERT_TRUE(same(got, want)) << std::hexfloat << v.transpose() << " v3 " << v3;
      }
    }
  }
  EXPECT_GT(compared, 200000u);
}

TEST(NfpFastPath, FmaAndPortableValuesAgree) {
  // (Without FMA on this processor both runs take the portable build: the comparison is then trivial.)
  using pendepth::nonconvex2::NfpFlat;
  std::mt19937_64 rng(19005);
  const auto albano = instance("albano.json");
  std::size_t compared = 0, certified = 0;
  auto same_diag = [](const NfpFlat::ProjectionDiag& a, const NfpFlat::ProjectionDiag& b) {
    for (int i = 0; i < 3; ++i)
      if (!same(a.hi[i], b.hi[i]) || !same(a.lo[i], b.lo[i]) || !same(a.bound[i], b.bound[i])) return false;
    return a.set == b.set;
  };
  for (std::size_t i = 0; i < albano.size(); i += 2)
    for (std::size_t j = 1; j < albano.size(); j += 3) {
      const NoFitPolygon2 nfp(albano[i], albano[j]);
      const NfpFlat& F = nfp_impl(nfp).flat;
      std::uniform_real_distribution<double> f(0, 1), a(0, 2 * M_PI);
      for (std::uint32_t k = 0; k < F.pdd.size(); ++k) {
        const auto& pc = nfp_impl(nfp).pieces[k];
        const Vec2 t = pc.a + f(rng) * (pc.b - pc.a) + Vec2(f(rng) - 0.5, f(rng) - 0.5) * 50;
        const double an = a(rng);
        const Vec2 d = pendepth::nonconvex2::check_and_scale(t, Vec2(std::cos(an), std::sin(an)));
        double v[2][6] = {};
        Vec2 tr[2][2];
        bool ok[2][6];
        NfpFlat::ProjectionDiag dg[2][6] = {};
        for (int m = 0; m < 2; ++m) {
          const ValuesBuild b(m == 0);
          ok[m][0] = F.projection_values(k, t, v[m][0], tr[m][0], &dg[m][0]);
          ok[m][1] = F.vertex_values(k, 0, t, v[m][1], tr[m][1], &dg[m][1]);
          ok[m][2] = F.vertex_values(k, 1, t, v[m][2], tr[m][1], &dg[m][2]);
          ok[m][4] = F.end_values(k, 0, t, v[m][4], tr[m][1], &dg[m][4]);
          ok[m][5] = F.end_values(k, 1, t, v[m][5], tr[m][1], &dg[m][5]);
          ok[m][3] = F.crossing_value(k, t, d, v[m][3], &dg[m][3]);
        }
        for (int q = 0; q < 6; ++q) {
          ASSERT_EQ(ok[0][q], ok[1][q]) << i << " " << j << " piece " << k << " value " << q;
          ASSERT_TRUE(same_diag(dg[0][q], dg[1][q])) << i << " " << j << " piece " << k << " value " << q;
          if (ok[0][q]) ASSERT_TRUE(same(v[0][q], v[1][q])) << i << " " << j << " piece " << k << " value " << q;
          if (q < 4 || F.pend[k][q - 4].ok) ++compared, certified += ok[0][q];  // cut ends: tabled ones only
        }
        ASSERT_TRUE(same(tr[0][0], tr[1][0]) && same(tr[0][1], tr[1][1])) << i << " " << j << " piece " << k;
      }
    }
  EXPECT_GT(certified, compared / 2);
  std::cout << "[fma vs portable] " << compared << " values compared, " << certified << " certified\n";
  // The answers in the portable build, against the exact path (the default build runs above).
  const ValuesBuild b(false);
  std::mt19937_64 rng2(19006);
  for (std::size_t i = 0; i < albano.size(); i += 3)
    for (std::size_t j = 0; j < albano.size(); j += 2) check_pair(albano[i], albano[j], rng2, 10, "portable albano " + std::to_string(i) + " " + std::to_string(j));
}

}  // namespace

namespace {

bool same(const pendepth::DepthValue2& a, const pendepth::DepthValue2& b) {
  return same(a.depth, b.depth) && same(a.translation, b.translation) && a.overlapping == b.overlapping;
}

// The lean queries (NoFitPolygon2::depth_value / directional_depth_value: the fast path) against
// the exact path's lean answers (minimum_value / along_value with exact_path: the hierarchy and
// rationals only) bit for bit, in the FMA and the portable build, on placements that stress the
// certified values: exactly on pieces (their rounded ends, ±1 ulp, points of axis-parallel pieces
// at random abscissae — exactly on the edge line for integer data — and midpoints), exactly on
// ring vertices, just inside O beside pieces (ulps to a tenth of the piece away), and random;
// directions along the axes (rays parallel to the axis-parallel edges, and crossings that take
// nfp_value's axis-parallel shortcut), diagonals and random ones. Pairs: albano (every ordered
// pair), shirts, trousers, baldacci4 (random pairs), and pieces turned by 30° (coordinates
// rounded: no axis-parallel edges, inexact ends).
TEST(NfpFastPath, LeanValuesAgainstExactPath) {
  using pendepth::DepthValue2;
  std::mt19937_64 rng(19013);
  std::uniform_real_distribution<double> f(0, 1), ang(0, 2 * M_PI);
  std::size_t queries = 0, overlapping = 0, pairs = 0, flat = 0;
  auto check = [&](const NoFitPolygon2& nfp, const Vec2& t, const std::string& what) {
    const auto& N = nfp_impl(nfp);
    const double a = ang(rng);
    const std::vector<Vec2> dirs{{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, -1}, {std::cos(a), std::sin(a)}};
    const DepthValue2 se = N.minimum_value(t, true);
    ++queries, overlapping += se.overlapping;
    std::vector<DepthValue2> de;
    for (const Vec2& d : dirs) de.push_back(N.along_value(t, pendepth::nonconvex2::check_and_scale(t, d), true));
    for (int m = 0; m < 2; ++m) {
      const ValuesBuild b(m == 0);
      const DepthValue2 s = nfp.depth_value(t);
      ASSERT_TRUE(same(s, se)) << what << (m ? " portable" : "") << " σ at " << std::hexfloat << t.transpose() << ": " << s.depth
                               << " vs exact " << se.depth;
      for (std::size_t i = 0; i < dirs.size(); ++i) {
        const DepthValue2 v = nfp.directional_depth_value(t, dirs[i]);
        ASSERT_TRUE(same(v, de[i])) << what << (m ? " portable" : "") << " σ_d at " << std::hexfloat << t.transpose() << " d "
                                    << dirs[i].transpose() << ": " << v.depth << " vs exact " << de[i].depth;
      }
    }
  };
  auto pair = [&](const Polygon& P, const Polygon& Q, std::size_t piece_step, int random, const std::string& what) {
    const NoFitPolygon2 nfp(P, Q);
    const auto& N = nfp_impl(nfp);
    ++pairs;
    flat += N.flat.usable;  // beyond 256 pieces (baldacci4's larger pairs) the hierarchy answers
    for (std::size_t k = 0; k < N.pieces.size(); k += piece_step) {
      const Vec2 a = N.pieces[k].a, b = N.pieces[k].b;
      for (const Vec2& p : {a, b, ulp_step(a, 1, 0), ulp_step(a, 0, -1), Vec2(0.5 * (a + b))}) check(nfp, p, what + " piece");
      if (a.y() == b.y()) check(nfp, Vec2(a.x() + f(rng) * (b.x() - a.x()), a.y()), what + " horizontal piece");
      if (a.x() == b.x()) check(nfp, Vec2(a.x(), a.y() + f(rng) * (b.y() - a.y())), what + " vertical piece");
      // Just inside O (on the piece's left), from ulps to a tenth of its length away.
      const Vec2 n(a.y() - b.y(), b.x() - a.x());
      for (double h : {0x1p-40, 0x1p-12, 0.1}) check(nfp, a + f(rng) * (b - a) + h * f(rng) * n, what + " beside a piece");
    }
    Vec2 lo = N.pieces[0].a, hi = lo;
    for (const auto& poly : nfp.polygons())
      for (const auto& ring : poly)
        for (std::size_t i = 0; i < ring.size(); ++i) {
          lo = lo.cwiseMin(ring[i]), hi = hi.cwiseMax(ring[i]);
          if (i % piece_step == 0) check(nfp, ring[i], what + " ring vertex");
        }
    for (int r = 0; r < random; ++r) check(nfp, Vec2(lo.x() + f(rng) * (hi.x() - lo.x()), lo.y() + f(rng) * (hi.y() - lo.y())), what + " random");
  };
  const auto albano = instance("albano.json");
  for (std::size_t i = 0; i < albano.size(); ++i)
    for (std::size_t j = 0; j < albano.size(); ++j) pair(albano[i], albano[j], 2, 20, "albano " + std::to_string(i) + " " + std::to_string(j));
  for (const std::string file : {"shirts", "trousers", "baldacci4"}) {
    const auto pieces = instance(file + ".json");
    for (int k = 0; k < 8; ++k) {
      const std::size_t i = rng() % pieces.size(), j = rng() % pieces.size();
      pair(pieces[i], pieces[j], 2, 20, file + " " + std::to_string(i) + " " + std::to_string(j));
    }
  }
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  for (int k = 0; k < 6; ++k) {
    const std::size_t i = rng() % albano.size(), j = rng() % albano.size();
    const Polygon Q = mapped(albano[j], [&](const Vec2& p) { return Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y()); });
    pair(albano[i], Q, 2, 20, "albano " + std::to_string(i) + " " + std::to_string(j) + " Q turned 30°");
  }
  std::cout << "[lean vs exact] " << pairs << " pairs (" << flat << " on the flat scan), " << queries << " placements ("
            << overlapping << " overlapping), σ and 6 σ_d each, both builds\n";
  EXPECT_GT(overlapping, queries / 4);
  EXPECT_GT(flat, pairs * 3 / 4);
}

}  // namespace
