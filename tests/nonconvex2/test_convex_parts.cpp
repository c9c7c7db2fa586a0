// Convex parts of a triangulation (src/nonconvex2/convex_parts.cpp, Hertel–Mehlhorn) against
// exact checks: every part is convex and CCW (exact turns), the parts' exact areas (rationals)
// add up to the polygon's (so the triangles are partitioned, nothing lost or doubled), their
// vertices are the polygon's (ids and coordinates agree), every diagonal left between two parts is
// essential (removing it makes a reflex vertex), and with holes (no merging) the parts are the
// triangles. On P and on −Q (negated coordinates, as the no-fit polygon uses them). Inputs: random
// stars (real and integer grid, straight vertices), combs, the nesting pieces; pinned seeds.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>

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

void check(const std::vector<nc::Tri>& tris, const Polygon& S, bool negated, const std::string& what) {
  const bool merge = S.hole_count() == 0;
  nc::ConvexParts parts;
  nc::convex_parts(tris, merge, parts);
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
  std::cout << "[convex parts] triangles " << g_triangles << ", parts " << g_parts << "\n";
}
