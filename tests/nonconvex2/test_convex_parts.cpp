// Convex parts of a triangulation (src/nonconvex2/convex_parts.cpp, Hertel–Mehlhorn) against
// exact checks: every part is convex and CCW (exact turns), the parts' exact areas (rationals)
// add up to the polygon's (so the triangles are partitioned, nothing lost or doubled), their
// vertices are the polygon's (ids and coordinates agree), every diagonal left between two parts is
// essential (removing it makes a reflex vertex), and with holes (no merging) the parts are the
// triangles. On P and on −Q (negated coordinates, as the no-fit polygon uses them). Inputs: random
// stars (real and integer grid, straight vertices), combs, the nesting pieces; pinned seeds.
// The output is also compared with the previous implementation (copied here as the reference:
// per-vertex lists and ring links in fresh vectors, ids read through the triangles): the same
// parts, vertex for vertex, computed into one ConvexParts reused by every call (its capacity and
// stale content from the previous shape, trim()med after the large ones).
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "nfp_shapes.hpp"
#include "nonconvex2/convex_parts.hpp"
#include "polygon2/shapes.hpp"
#include "test_scale.hpp"

namespace {

using pendepth::Polygon;
using pendepth::Vec2;
namespace nc = pendepth::nonconvex2;

mpq_class area2(const std::vector<Vec2>& ring) {
  mpq_class a = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 &p = ring[i], &q = ring[(i + 1) % ring.size()];
    a += mpq_class(p.x()) * mpq_class(q.y()) - mpq_class(q.x()) * mpq_class(p.y());
  }
  return a;
}

std::size_t g_parts = 0, g_triangles = 0;

// The previous convex_parts, verbatim but for names: the reference for "same parts".
void reference_parts(const std::vector<nc::Tri>& tris, bool merge, nc::ConvexParts& out) {
  auto turn = [](const Vec2& a, const Vec2& b, const Vec2& c) { return pendepth::predicates::cross_edges(a, b, b, c); };
  const auto T = static_cast<std::uint32_t>(tris.size());
  out = nc::ConvexParts();
  auto V = [&](std::uint32_t s) -> const Vec2& { return tris[s / 3].v[s % 3]; };
  auto I = [&](std::uint32_t s) { return tris[s / 3].id[s % 3]; };
  std::vector<std::uint32_t> links(10 * T);
  std::uint32_t *next = links.data(), *prev = next + 3 * T, *alias = prev + 3 * T, *part = alias + 3 * T;
  for (std::uint32_t s = 0; s < 3 * T; ++s) {
    next[s] = s % 3 == 2 ? s - 2 : s + 1;
    prev[s] = s % 3 == 0 ? s + 2 : s - 1;
    alias[s] = s;
  }
  for (std::uint32_t t = 0; t < T; ++t) part[t] = t;
  auto live = [&](std::uint32_t s) {
    while (alias[s] != s) s = alias[s] = alias[alias[s]];
    return s;
  };
  auto find = [&](std::uint32_t t) {
    while (part[t] != t) t = part[t] = part[part[t]];
    return t;
  };
  if (merge && T > 1) {
    auto tri_next = [](std::uint32_t s) { return s % 3 == 2 ? s - 2 : s + 1; };
    std::uint32_t nv = 0;
    for (std::uint32_t s = 0; s < 3 * T; ++s) nv = std::max(nv, I(s) + 1);
    constexpr std::uint32_t kNone = ~std::uint32_t(0);
    std::vector<std::uint32_t> lists(nv + 3 * T, kNone);
    std::uint32_t *head = lists.data(), *link = head + nv;
    for (std::uint32_t s = 0; s < 3 * T; ++s) link[s] = head[I(s)], head[I(s)] = s;
    for (std::uint32_t s = 0; s < 3 * T; ++s) {
      const std::uint32_t a = I(s), b = I(tri_next(s));
      if (a > b) continue;
      std::uint32_t r = head[b];
      while (r != kNone && I(tri_next(r)) != a) r = link[r];
      if (r == kNone) continue;
      const std::uint32_t X = find(s / 3), Y = find(r / 3);
      if (X == Y) continue;
      const std::uint32_t u = live(s), v = next[u], yb = live(r), ya = next[yb];
      const std::uint32_t y_after_a = next[ya], y_before_b = prev[yb];
      if (turn(V(prev[u]), V(u), V(y_after_a)) < 0 || turn(V(y_before_b), V(v), V(next[v])) < 0) continue;
      next[u] = y_after_a, prev[y_after_a] = u;
      next[y_before_b] = v, prev[v] = y_before_b;
      alias[ya] = u, alias[yb] = v;
      part[Y] = X;
    }
  }
  for (std::uint32_t t = 0; t < T; ++t) {
    if (find(t) != t) continue;
    const std::uint32_t s0 = live(3 * t);
    out.start.push_back(std::uint32_t(out.v.size()));
    Vec2 lo = V(s0), hi = lo;
    std::uint32_t s = s0;
    do {
      out.v.push_back(V(s));
      out.id.push_back(I(s));
      lo = lo.cwiseMin(V(s));
      hi = hi.cwiseMax(V(s));
      s = next[s];
    } while (s != s0);
    out.lo.push_back(lo);
    out.hi.push_back(hi);
  }
  out.start.push_back(std::uint32_t(out.v.size()));
}

std::size_t g_same = 0;

void check(const std::vector<nc::Tri>& tris, const Polygon& S, bool negated, const std::string& what) {
  const bool merge = S.hole_count() == 0;
  static nc::ConvexParts parts;  // reused by every call, like the builder's per-thread parts
  nc::convex_parts(tris, merge, parts);
  {
    nc::ConvexParts ref;
    reference_parts(tris, merge, ref);
    ASSERT_TRUE(parts.v == ref.v && parts.id == ref.id && parts.start == ref.start && parts.lo == ref.lo && parts.hi == ref.hi)
        << what << ": not the previous implementation's parts";
    ++g_same;
  }
  ASSERT_EQ(parts.start.size(), parts.size() + 1) << what;
  ASSERT_GE(parts.size(), 1u) << what;
  if (!merge) ASSERT_EQ(parts.size(), tris.size()) << what;
  const auto V = S.vertices();
  mpq_class total = 0, expect = 0;
  for (const auto& T : tris) expect += area2({T.v[0], T.v[1], T.v[2]});
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::size_t, std::size_t>> edge_at;  // (a, b) → (part, index)
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const std::size_t s = parts.start[k], n = parts.start[k + 1] - s;
    ASSERT_GE(n, 3u) << what;
    std::vector<Vec2> ring(parts.v.begin() + s, parts.v.begin() + s + n);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 expect_v = negated ? Vec2(-V[parts.id[s + i]]) : V[parts.id[s + i]];
      ASSERT_EQ(ring[i], expect_v) << what << " part " << k << " vertex " << i;
      ASSERT_GE(pendepth::predicates::cross_edges(ring[(i + n - 1) % n], ring[i], ring[i], ring[(i + 1) % n]), 0)
          << what << " part " << k << " reflex at " << i;
      ASSERT_TRUE((parts.lo[k].array() <= ring[i].array()).all() && (ring[i].array() <= parts.hi[k].array()).all()) << what;
      edge_at[{parts.id[s + i], parts.id[s + (i + 1) % n]}] = {k, i};
    }
    const mpq_class a = area2(ring);
    ASSERT_GT(a, 0) << what << " part " << k << " not CCW";
    total += a;
  }
  ASSERT_EQ(total, expect) << what << ": the parts do not partition the triangles";
  if (merge) {
    for (const auto& [e, at] : edge_at) {
      const auto it = edge_at.find({e.second, e.first});
      if (it == edge_at.end()) continue;  // a polygon edge
      // Removing the diagonal u → v (in part X) / v → u (in part Y) must leave a reflex vertex.
      auto vert = [&](std::size_t k, std::size_t i) {
        const std::size_t s = parts.start[k], n = parts.start[k + 1] - s;
        return parts.v[s + (i % n + n) % n];
      };
      const auto [X, i] = at;
      const auto [Y, j] = it->second;
      const std::size_t ny = parts.start[Y + 1] - parts.start[Y];
      const Vec2 u = vert(X, i), v = vert(X, i + 1), x_prev = vert(X, i + parts.start[X + 1] - parts.start[X] - 1), x_next = vert(X, i + 2);
      const Vec2 y_after_u = vert(Y, j + 2), y_before_v = vert(Y, j + ny - 1);
      ASSERT_TRUE(pendepth::predicates::cross_edges(x_prev, u, u, y_after_u) < 0 || pendepth::predicates::cross_edges(y_before_v, v, v, x_next) < 0)
          << what << ": an inessential diagonal was kept";
    }
  }
  g_parts += parts.size();
  g_triangles += tris.size();
  parts.trim();
}

void check_pair(const Polygon& P, const Polygon& Q, const std::string& what) {
  const pendepth::PairDepth2::Impl S(P, Q);
  check(S.tp, P, false, what + " P");
  check(S.tb, Q, true, what + " -Q");
}

}  // namespace

TEST(ConvexParts, RandomShapes) {
  std::mt19937_64 rng(2611);
  for (int it = 0; it < pendepth_test::scaled(300); ++it) {
    const bool grid = it % 2;
    const Polygon P = it % 3 == 0 ? polygon2_test::random_polygon(rng, 10 + int(rng() % 30), int(rng() % 3), grid)
                    : it % 5 == 0 ? nonconvex2_test::star(rng, 4 + int(rng() % 7), 1, 6, true)  // tiny grid: straight vertices
                                  : nonconvex2_test::star(rng, 4 + int(rng() % 60), 50, 100, grid);
    const Polygon Q = nonconvex2_test::star(rng, 3 + int(rng() % 6), 1, 4, true);
    check_pair(P, Q, "random " + std::to_string(it));
    // Once a large shape (the reused buffers grow past their trim thresholds), then small again.
    if (it == 5) check_pair(nonconvex2_test::star(rng, 5000, 50, 100, false), Q, "large star");
  }
}

TEST(ConvexParts, CombsAndNestingPieces) {
  const Polygon comb = Polygon::simple(polygon2_test::comb_ring(6, 1, 1, 4, 2), "comb");
  check_pair(comb, comb, "comb");
  for (const char* inst : {"albano.json", "shirts.json", "trousers.json"}) {
    const auto pieces = polygon2_test::nesting_pieces(inst);
    for (const auto& p : pieces) {
      const Polygon S = Polygon::simple(p, "piece");
      check_pair(S, S, inst);
    }
  }
  std::cout << "[convex parts] triangles " << g_triangles << ", parts " << g_parts << ", " << g_same
            << " decompositions identical to the reference\n";
}
