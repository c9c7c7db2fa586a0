// Triangulation of polygons with holes: exact coverage. Checked with GMP rationals: triangle
// count N - 2 + 2h, every triangle strictly CCW, the triangle areas sum exactly to P's area, and
// every triangle lies inside P (its centroid is strictly inside P and no edge of P crosses the
// triangle's interior). Area equality plus containment implies pairwise disjoint interiors.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include "polygon2/triangulation.hpp"
#include "shapes.hpp"

namespace {

using pendepth::Polygon;
using pendepth::Vec2;
using pendepth::predicates::orient2d;

struct QPoint {
  mpq_class x, y;
};
mpq_class orient_q(const QPoint& a, const QPoint& b, const QPoint& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}
QPoint lift(const Vec2& p) { return {mpq_class(p.x()), mpq_class(p.y())}; }

// Winding number of all rings of P around p (exact), p not on ∂P.
int winding_q(const Polygon& P, const QPoint& p) {
  int w = 0;
  for (std::size_t g = 0; g < P.size(); ++g) {
    QPoint a = lift(P.vertices()[g]), b = lift(P.vertices()[P.next(g)]);
    if (a.y <= p.y) {
      if (b.y > p.y && sgn(orient_q(a, b, p)) > 0) ++w;
    } else if (b.y <= p.y && sgn(orient_q(a, b, p)) < 0) {
      --w;
    }
  }
  return w;
}

void check_triangulation(const Polygon& P, const std::string& what) {
  auto tris = pendepth::polygon2::triangulate(P);
  ASSERT_EQ(tris.size(), P.size() - 2 + 2 * P.hole_count()) << what;
  mpq_class sum = 0, area = 0;
  for (std::size_t g = 0; g < P.size(); ++g) {
    QPoint a = lift(P.vertices()[g]), b = lift(P.vertices()[P.next(g)]);
    area += a.x * b.y - a.y * b.x;
  }
  const auto V = P.vertices();
  for (const auto& t : tris) {
    const Vec2 &a = V[t[0]], &b = V[t[1]], &c = V[t[2]];
    ASSERT_EQ(orient2d(a, b, c), 1) << what;
    sum += orient_q(lift(a), lift(b), lift(c));
    QPoint cen{(lift(a).x + lift(b).x + lift(c).x) / 3, (lift(a).y + lift(b).y + lift(c).y) / 3};
    ASSERT_NE(winding_q(P, cen), 0) << what << ": triangle centroid outside P";
    for (std::size_t g = 0; g < P.size(); ++g) {
      const Vec2 &p = V[g], &q = V[P.next(g)];
      // A vertex of P strictly inside the triangle.
      ASSERT_FALSE(orient2d(a, b, p) > 0 && orient2d(b, c, p) > 0 && orient2d(c, a, p) > 0) << what;
      // An edge of P properly crossing a triangle edge.
      const Vec2* tv[3] = {&a, &b, &c};
      for (int e = 0; e < 3; ++e) {
        const Vec2 &u = *tv[e], &w = *tv[(e + 1) % 3];
        bool cross = orient2d(u, w, p) * orient2d(u, w, q) < 0 && orient2d(p, q, u) * orient2d(p, q, w) < 0;
        ASSERT_FALSE(cross) << what;
      }
    }
  }
  EXPECT_EQ(sum, area) << what;
}

TEST(Triangulation, RandomPolygonsWithHoles) {
  std::mt19937_64 rng(77);
  for (int it = 0; it < 120; ++it)
    check_triangulation(polygon2_test::random_polygon(rng, 4 + it % 50, it % 5, it % 3 != 0), "random " + std::to_string(it));
}

TEST(Triangulation, CombsCollinearAndNestingPieces) {
  check_triangulation(Polygon::simple(polygon2_test::comb_ring(7, 2, 3, 40, 5)), "comb");
  // Many collinear vertices on every side, plus a hole with collinear vertices.
  std::vector<Vec2> outer, hole;
  for (int i = 0; i < 10; ++i) outer.push_back({double(i), 0});
  for (int i = 0; i < 10; ++i) outer.push_back({10, double(i)});
  for (int i = 10; i > 0; --i) outer.push_back({double(i), 10});
  for (int i = 10; i > 0; --i) outer.push_back({0, double(i)});
  for (int i = 3; i < 7; ++i) hole.push_back({double(i), 3});
  for (int i = 3; i < 7; ++i) hole.push_back({7, double(i)});
  for (int i = 7; i > 3; --i) hole.push_back({double(i), 7});
  for (int i = 7; i > 3; --i) hole.push_back({3, double(i)});
  check_triangulation(Polygon({outer, hole}), "collinear grid");
  for (const char* f : {"albano.json", "shirts.json", "trousers.json"}) {
    int k = 0;
    for (const auto& piece : polygon2_test::nesting_pieces(f))
      check_triangulation(Polygon::simple(piece), std::string(f) + " #" + std::to_string(k++));
  }
}

}  // namespace
