// The union boundary's output-sensitive first pass (UnionBoundary, nearest_first; issue 19 item
// 4) against the previous method (nearest_first = false: every candidate gathers every sausage in
// reach) on the same P and R: the pieces must be the same bit for bit (kind, P / B indices,
// candidate, symbolic ends, ring links), the rings the same, and every piece end the same exact
// rational point. Inputs: dense random stars under a large Q (where the pass decides most
// candidates: the test asserts it ran), random polygons with holes, grid-rounded stars (exact
// collinearities), spirals, combs whose pockets Q fits exactly (slits), hole grids with holes of
// Q's exact size (isolated points), a frame of collinear vertices, and a 1e6 offset.
// The exact correctness of the pieces themselves is test_union.cpp's (CGAL's exact union).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../test_scale.hpp"
#include "polygon2/convolved_triangles.hpp"
#include "polygon2/union_boundary.hpp"
#include "shapes.hpp"

namespace {

using pendepth::ConvexPolygon;
using pendepth::Polygon;
using pendepth::Vec2;
using pendepth::polygon2::ConvolvedTriangles;
using pendepth::polygon2::EndPoint;
using pendepth::polygon2::Piece;
using pendepth::polygon2::UnionBoundary;

bool same_end(const EndPoint& a, const EndPoint& b) {
  if (a.kind != b.kind) return false;
  switch (a.kind) {
    case EndPoint::Kind::Crossing:
      return a.other.pt == b.other.pt && a.other.pb == b.other.pb && a.other.e0 == b.other.e0 &&
             a.other.e1 == b.other.e1;
    case EndPoint::Kind::Point:
      return a.p == b.p && a.b == b.b && a.p_index == b.p_index && a.b_index == b.b_index;
    default:
      return true;
  }
}

struct Totals {
  std::size_t cases = 0, candidates_early = 0, pieces = 0, chain_pruned = 0;
};

// Builds ∂O both ways and compares; returns the number of candidates the first pass decided.
void compare(const std::string& what, const Polygon& P, const ConvexPolygon& Q, Totals& tot) {
  SCOPED_TRACE(what);
  const ConvolvedTriangles R(P, Q);
  const UnionBoundary fast(P, R), ref(P, R, false);
  EXPECT_EQ(ref.covered_early(), 0u);
  EXPECT_EQ(ref.chain_pruned(), 0u);
  ++tot.cases;
  tot.candidates_early += fast.covered_early();
  tot.chain_pruned += fast.chain_pruned();
  ASSERT_EQ(fast.pieces().size(), ref.pieces().size());
  ASSERT_EQ(fast.rings().size(), ref.rings().size());
  tot.pieces += ref.pieces().size();
  for (std::size_t k = 0; k < ref.pieces().size(); ++k) {
    const Piece &a = fast.pieces()[k], &b = ref.pieces()[k];
    ASSERT_EQ(a.kind, b.kind) << k;
    ASSERT_EQ(a.p, b.p) << k;
    ASSERT_EQ(a.b0, b.b0) << k;
    ASSERT_EQ(a.b1, b.b1) << k;
    ASSERT_EQ(a.candidate, b.candidate) << k;
    ASSERT_TRUE(same_end(a.start, b.start)) << k;
    ASSERT_TRUE(same_end(a.end, b.end)) << k;
    ASSERT_EQ(a.ring, b.ring) << k;
    ASSERT_EQ(a.next, b.next) << k;
    ASSERT_EQ(a.prev, b.prev) << k;
    ASSERT_EQ(fast.exact_start(k), ref.exact_start(k)) << k;
    ASSERT_EQ(fast.exact_end(k), ref.exact_end(k)) << k;
  }
  for (std::size_t r = 0; r < ref.rings().size(); ++r) {
    EXPECT_EQ(fast.rings()[r].first, ref.rings()[r].first);
    EXPECT_EQ(fast.rings()[r].count, ref.rings()[r].count);
    EXPECT_EQ(fast.rings()[r].area_sign, ref.rings()[r].area_sign);
  }
  EXPECT_EQ(fast.vertex_count(), ref.vertex_count());
}

// Dense stars under a Q much larger than the spikes: most candidates lie inside O and have more
// than 64 sausages in reach, so the first pass decides them.
TEST(UnionNearestFirst, DenseStarsMatchPreviousMethod) {
  std::mt19937_64 rng(1919);
  Totals tot;
  // Every shape is generated (the same shapes in every build); a scaled build (Debug, sanitizers)
  // compares only the last, largest ones, where the first pass decides candidates.
  const int first = 8 - pendepth_test::scaled(8);
  for (int it = 0; it < 8; ++it) {
    const int n = 400 + 200 * it;
    // Odd cases: integer coordinates (exact collinearities), the star scaled by 16 so that the
    // rounding keeps it simple.
    const bool grid = it % 2 == 1;
    const double s = grid ? 16 : 1;
    Polygon P = [&] {
      for (;;) {
        try {
          return Polygon::simple(polygon2_test::star_ring(rng, n, Vec2(0, 0), 60 * s, 100 * s, grid), "star");
        } catch (const pendepth::InvalidInput&) {
        }
      }
    }();
    const ConvexPolygon Q = polygon2_test::random_convex(rng, 3 + 13 * (it % 4), (4 + it) * s, grid);
    if (it >= first) compare("star " + std::to_string(it), P, Q, tot);
  }
  std::printf("dense stars: %zu cases, %zu pieces, %zu candidates decided by the first pass\n", tot.cases, tot.pieces,
              tot.candidates_early);
  // The pass ran (the comparison is not vacuous): 2,823 candidates over all 8 stars in Release,
  // 1,803 in the last (a scaled build's only case; segment candidates with at most 64 sausages left
  // by the chain hierarchy skip the pass).
  EXPECT_GT(tot.candidates_early, pendepth_test::kDivisor == 1 ? 1000u : 100u);
}

TEST(UnionNearestFirst, RandomPolygonsWithHolesMatchPreviousMethod) {
  std::mt19937_64 rng(2026);
  Totals tot;
  const int first = 24 - pendepth_test::scaled(24);  // a scaled build: the last, largest cases
  for (int it = 0; it < 24; ++it) {
    // Integer coordinates only while the rounded star stays simple (small n).
    const Polygon P = polygon2_test::random_polygon(rng, 40 + 30 * it, it % 5, it % 3 == 0 && it < 6);
    const ConvexPolygon Q = polygon2_test::random_convex(rng, 3 + it % 11, 2 + it, it % 4 == 0);
    if (it >= first) compare("random " + std::to_string(it), P, Q, tot);
  }
  std::printf("random: %zu cases, %zu pieces, %zu candidates decided by the first pass\n", tot.cases, tot.pieces,
              tot.candidates_early);
  EXPECT_GT(tot.candidates_early, 0u);
}

TEST(UnionNearestFirst, DegenerateInputsMatchPreviousMethod) {
  std::mt19937_64 rng(7);
  Totals tot;
  // Combs: Q fits the pockets exactly (slits), and a Q spanning many teeth (> 64 in reach).
  const Polygon comb = Polygon::simple(polygon2_test::comb_ring(120, 2, 3, 10, 2));
  compare("comb/exact fit", comb, ConvexPolygon{{0, 0}, {3, 0}, {3, 3}, {0, 3}}, tot);
  compare("comb/wide square", comb, ConvexPolygon{{0, 0}, {40, 0}, {40, 40}, {0, 40}}, tot);
  compare("comb/wide triangle", comb, ConvexPolygon{{0, 0}, {60, 0}, {30, 9}}, tot);
  // Hole grids: Q exactly the size of a hole (isolated points) and Q spanning several holes.
  const Polygon grid(polygon2_test::holes_grid(12, 4, 2, {0, 0}));
  compare("hole grid/exact fit", grid, ConvexPolygon{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, tot);
  compare("hole grid/wide", grid, ConvexPolygon{{0, 0}, {20, 0}, {20, 13}, {0, 13}}, tot);
  const Polygon far(polygon2_test::holes_grid(10, 4, 2, {1e6, 1e6}));
  compare("hole grid/offset 1e6", far, ConvexPolygon{{0, 0}, {16, 0}, {8, 20}}, tot);
  // A frame of 4·60 collinear vertices with a collinear hole, Q from hole-sized to large.
  std::vector<Vec2> outer, hole;
  for (int i = 0; i < 60; ++i) outer.push_back({double(i), 0});
  for (int i = 0; i < 60; ++i) outer.push_back({60, double(i)});
  for (int i = 60; i > 0; --i) outer.push_back({double(i), 60});
  for (int i = 60; i > 0; --i) outer.push_back({0, double(i)});
  for (int i = 10; i < 50; ++i) hole.push_back({double(i), 10});
  for (int i = 10; i < 50; ++i) hole.push_back({50, double(i)});
  for (int i = 50; i > 10; --i) hole.push_back({double(i), 50});
  for (int i = 50; i > 10; --i) hole.push_back({10, double(i)});
  const Polygon framed({outer, hole});
  for (double s : {40.0, 25.0, 7.0})
    compare("collinear frame/square " + std::to_string(s), framed, ConvexPolygon{{0, 0}, {s, 0}, {s, s}, {0, s}}, tot);
  // Spirals: Q much smaller than the arms' gap, and larger than the arms.
  const Polygon spiral = Polygon::simple(polygon2_test::spiral_ring(3, 2, 2.5, 4, 600));
  compare("spiral/small", spiral, polygon2_test::random_convex(rng, 7, 1.0, false), tot);
  compare("spiral/wide", spiral, polygon2_test::random_convex(rng, 9, 12.0, false), tot);
  std::printf("degenerate: %zu cases, %zu pieces, %zu candidates decided by the first pass\n", tot.cases, tot.pieces,
              tot.candidates_early);
  EXPECT_GT(tot.candidates_early, 100u);
}

// Finely sampled spirals (the chain hierarchy's case, issue 19 item 4): every candidate on the
// arms keeps a piece while Q spans hundreds of edges, so the full gathering runs for each and the
// hierarchy's separation tests skip most sausages in box reach. Q from a few edges wide to wider
// than the gap between the arms (sausages of two arms meet), arms far from the origin (large
// coordinates: the tests' rounding margins) and grid-rounded spirals (exact collinear and
// parallel edges). The test asserts the pruning ran.
TEST(UnionNearestFirst, FineSpiralsMatchPreviousMethod) {
  std::mt19937_64 rng(4242);
  Totals tot;
  struct Spec {
    int steps;
    double q;      // Q's scale
    int m;         // Q's vertex count
    double scale;  // the spiral's scale (integer-rounded when grid)
    bool grid;
    Vec2 offset;
  };
  const std::vector<Spec> specs = {
      {1500, 2.0, 12, 1, false, {0, 0}},    {1500, 9.0, 40, 1, false, {0, 0}},
      {2500, 5.0, 7, 1, false, {0, 0}},     {1200, 30.0, 16, 1, false, {0, 0}},
      {1500, 4.0, 9, 1, false, {3e5, -2e5}}, {800, 400.0, 10, 64, true, {0, 0}},
  };
  const int count = static_cast<int>(specs.size());
  const int first = count - pendepth_test::scaled(count);  // a scaled build: the last cases
  for (int it = 0; it < count; ++it) {
    const Spec& sp = specs[static_cast<std::size_t>(it)];
    std::vector<Vec2> ring = polygon2_test::spiral_ring(20, 4, 1.5, 4, sp.steps);
    for (Vec2& v : ring) {
      v = sp.scale * v;
      if (sp.grid) v = Vec2(std::round(v.x()), std::round(v.y()));
      v += sp.offset;
    }
    const ConvexPolygon Q = polygon2_test::random_convex(rng, sp.m, sp.q, sp.grid);
    if (it < first) continue;
    const Polygon P = Polygon::simple(ring, "spiral");
    compare("spiral " + std::to_string(it), P, Q, tot);
  }
  std::printf("fine spirals: %zu cases, %zu pieces, %zu chain nodes / edges pruned\n", tot.cases, tot.pieces,
              tot.chain_pruned);
  // The pruning ran (the comparison is not vacuous): 137 k nodes / edges in Release, 9.9 k in the
  // last case (a scaled build's only one).
  EXPECT_GT(tot.chain_pruned, pendepth_test::kDivisor == 1 ? 20000u : 1000u);
}

}  // namespace
