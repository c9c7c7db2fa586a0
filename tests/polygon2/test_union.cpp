// The implicit union boundary ∂O (DHS §4.1 Step 3) and the queries built on it (σ_d fast and
// scanning, σ, complete separation), against independent references:
//   - the exact CGAL union of the explicit R_i (oracle.hpp): every vertex of CGAL's union boundary
//     lies on our boundary and every vertex of ours on CGAL's (or is a slit / isolated point:
//     inside the regularised union but not in O), exactly; ring counts; area to 1e-12;
//     σ against the exact distance to the regularised boundary;
//   - the exact scan of the convolved triangles (along_triangles, separation_triangles);
//   - properties: rings close exactly; σ ≤ σ_d for 64 directions and σ ≈ min over dense
//     directions; σ_d along σ's normal is σ; points before the move are overlapping.
// Shapes: random star-shaped polygons with holes, spirals, combs whose pockets Q fits exactly,
// squares with grids of holes (Q smaller than / exactly the size of a hole), a frame with
// collinear vertices, axis-parallel P and Q, coordinates offset by 1e6, nesting pieces.
#include <pendepth/depth2_polygon_convex.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "../test_scale.hpp"
#include "oracle.hpp"
#include "polygon2/query_impl.hpp"
#include "polygon2/triangulation.hpp"
#include "shapes.hpp"
#include "test_ulps.hpp"

namespace {

using pendepth::ConvexPolygon;
using pendepth::Polygon;
using pendepth::PolygonDepth2;
using pendepth::Vec2;
using polygon2_test::UnionOracle;
using EP = UnionOracle::ExactPoint;

std::vector<std::array<Vec2, 3>> triangles_of(const Polygon& P) {
  std::vector<std::array<Vec2, 3>> out;
  for (const auto& t : pendepth::polygon2::triangulate(P)) out.push_back({P.vertices()[t[0]], P.vertices()[t[1]], P.vertices()[t[2]]});
  return out;
}

double ulps(double a, double b) { return pendepth_test::ulps_of_want(a, b); }

struct Stats {
  std::size_t cases = 0, pieces = 0, vertices_checked = 0, slit_vertices = 0, rays = 0, rays_overlapping = 0,
              bit_scan = 0, bit_tri = 0, minima = 0, feet = 0, seps = 0, bit_sep = 0;
  double max_ulps_sep = 0, max_ulps_scan = 0, max_ulps_tri = 0, max_ulps_min = 0, max_area_rel = 0;
};

// All boundary points of ∂O in ring order: piece starts, arc vertices, piece ends (exact).
std::vector<std::vector<EP>> exact_rings(const pendepth::polygon2::UnionBoundary& U) {
  std::vector<std::vector<EP>> out;
  for (const auto& rg : U.rings()) {
    std::vector<EP> pts;
    for (std::uint32_t q = 0; q < rg.count; ++q) {
      const std::size_t k = rg.first + q;
      auto s = U.exact_start(k);
      pts.push_back({s[0], s[1]});
      for (std::size_t j = 1; j < U.element_count(k); ++j) {
        const auto E = U.element(k, j);
        pts.push_back({mpq_class(E.pt.x()) + mpq_class(E.pb.x()), mpq_class(E.pt.y()) + mpq_class(E.pb.y())});
      }
      auto e = U.exact_end(k);
      pts.push_back({e[0], e[1]});
    }
    out.push_back(std::move(pts));
  }
  return out;
}

void check_case(const std::string& what, const Polygon& P, const ConvexPolygon& Q, bool generic, std::mt19937_64& rng,
                int placements, Stats& st) {
  SCOPED_TRACE(what);
  ++st.cases;
  placements = std::max(2, pendepth_test::scaled(placements));  // Debug / sanitizer builds: fewer
  PolygonDepth2 pd(P, Q);
  const auto& U = pendepth::polygon_depth_impl(pd).U;
  std::vector<Vec2> qv(Q.vertices().begin(), Q.vertices().end());
  UnionOracle oracle(triangles_of(P), qv);
  st.pieces += U.pieces().size();

  // --- the boundary itself ---
  const auto rings = exact_rings(U);
  std::vector<std::array<EP, 2>> segs;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& rg = U.rings()[r];
    for (std::uint32_t q = 0; q < rg.count; ++q) {  // rings close exactly: end(k) = start(next(k))
      const std::size_t k = rg.first + q, n = U.pieces()[k].next;
      auto e = U.exact_end(k), s = U.exact_start(n);
      ASSERT_TRUE(e[0] == s[0] && e[1] == s[1]) << "ring " << r << " piece " << k;
    }
    for (std::size_t i = 0; i + 1 < rings[r].size(); ++i) segs.push_back({rings[r][i], rings[r][i + 1]});
    if (rings[r].size() == 1 || (rings[r].size() == 2 && rings[r][0].x == rings[r][1].x && rings[r][0].y == rings[r][1].y))
      segs.push_back({rings[r][0], rings[r][0]});
  }
  EXPECT_EQ(oracle.vertices_off(segs), 0u);
  for (const auto& ring : rings)
    for (const EP& v : ring) {
      ++st.vertices_checked;
      ASSERT_FALSE(oracle.inside(v));  // ∂O ∩ O = ∅
      if (!oracle.on_union_boundary(v)) {
        ASSERT_TRUE(oracle.inside_union(v)) << "vertex off both the union boundary and the slits";
        ++st.slit_vertices;
      }
    }
  double area = 0;
  for (const auto& ring : pd.boundary_rings())
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 &a = ring[i], &b = ring[(i + 1) % ring.size()];
      area += a.x() * b.y() - a.y() * b.x();
    }
  area /= 2;
  const double want_area = oracle.union_area();
  const double rel = std::abs(area - want_area) / want_area;
  EXPECT_LE(rel, 1e-12) << area << " vs " << want_area;
  st.max_area_rel = std::max(st.max_area_rel, rel);
  std::size_t outer = 0, holes = 0, flat = 0;
  for (const auto& rg : U.rings()) (rg.area_sign > 0 ? outer : rg.area_sign < 0 ? holes : flat)++;
  const auto stats = pd.boundary_stats();
  EXPECT_EQ(stats.rings, U.rings().size());
  EXPECT_EQ(stats.segments + stats.arcs, U.pieces().size());
  if (generic) {
    EXPECT_EQ(outer, oracle.outer_count());
    EXPECT_EQ(holes, oracle.hole_count());
    EXPECT_EQ(flat, 0u);
  }

  // --- queries ---
  std::vector<Vec2> ts;
  Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  for (std::size_t k = 0; k < U.pieces().size(); ++k) {
    const auto b = U.box(k);
    lo = lo.cwiseMin(Vec2(b[0], b[1]));
    hi = hi.cwiseMax(Vec2(b[2], b[3]));
  }
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y());
  for (int k = 0; k < placements; ++k) ts.push_back({ux(rng), uy(rng)});
  for (int k = 0; k < placements / 2 && !U.pieces().empty(); ++k) ts.push_back(U.start_point(rng() % U.pieces().size()));
  for (int k = 0; k < placements / 2; ++k) ts.push_back(P.vertices()[rng() % P.size()] - qv[rng() % qv.size()]);
  std::vector<Vec2> ds{{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {std::sqrt(2.0), 1 / 3.0}};
  for (int k = 0; k < 3; ++k) {
    const std::size_t g = rng() % P.size();
    ds.push_back(P.vertices()[P.next(g)] - P.vertices()[g]);
    const std::size_t j = rng() % qv.size();
    ds.push_back(qv[(j + 1) % qv.size()] - qv[j]);
  }
  std::vector<Vec2> dirs64;
  const int nd = pendepth_test::scaled(64);
  for (int k = 0; k < nd; ++k) dirs64.push_back({std::cos(2 * polygon2_test::kPi * k / nd), std::sin(2 * polygon2_test::kPi * k / nd)});

  for (std::size_t ti = 0; ti < ts.size(); ++ti) {
    const Vec2& t = ts[ti];
    // Properties after rounding t + move need a placement away from ∂O: the random ones.
    const bool generic_t = ti < std::size_t(placements);
    const bool inside = oracle.inside(t);
    ASSERT_EQ(pd.overlapping(t), inside) << t.transpose();
    for (const Vec2& d : ds) {
      ++st.rays;
      const auto a = pd.along(t, d), s = pendepth::polygon2::along_scan(pd, t, d), r = pendepth::polygon2::along_triangles(pd, t, d);
      ASSERT_EQ(a.overlapping, inside);
      ASSERT_EQ(s.overlapping, inside);
      st.rays_overlapping += inside;
      const double es = ulps(a.depth, s.depth), er = ulps(a.depth, r.depth);
      ASSERT_LE(es, 4) << "t=" << t.transpose() << " d=" << d.transpose() << " " << a.depth << " vs scan " << s.depth;
      ASSERT_LE(er, 8) << "t=" << t.transpose() << " d=" << d.transpose() << " " << a.depth << " vs triangles " << r.depth;
      st.bit_scan += a.depth == s.depth;
      st.bit_tri += a.depth == r.depth;
      st.max_ulps_scan = std::max(st.max_ulps_scan, es);
      st.max_ulps_tri = std::max(st.max_ulps_tri, er);
      // The points before the exit overlap (moves large enough to survive rounding t + move).
      if (generic_t && inside && a.depth > 1e-6 * (t.norm() + 1))
        EXPECT_TRUE(pd.overlapping(t + (1 - 1e-9) * a.translation)) << t.transpose() << " " << d.transpose();
      const auto sp = pd.separation(t, d), sr = pendepth::polygon2::separation_triangles(pd, t, d);
      ++st.seps;
      // Same exact λ; the exit line may differ where several meet (edge sausage vs triangle).
      const double esp = ulps(sp.depth, sr.depth);
      ASSERT_LE(esp, 4) << "t=" << t.transpose() << " d=" << d.transpose() << " " << sp.depth << " vs " << sr.depth;
      st.bit_sep += sp.depth == sr.depth;
      st.max_ulps_sep = std::max(st.max_ulps_sep, esp);
      EXPECT_EQ(sp.overlapping, inside);
      EXPECT_GE(sp.depth, a.depth * (1 - 0x1p-50));
    }
    const auto mn = pd.minimum(t);
    ASSERT_EQ(mn.overlapping, inside);
    if (!inside) {
      EXPECT_EQ(mn.depth, 0);
      continue;
    }
    ++st.minima;
    ASSERT_GT(mn.depth, 0);
    EXPECT_NEAR(mn.normal.norm(), 1, 1e-15);
    for (const Vec2& d : dirs64) EXPECT_LE(mn.depth, pd.along(t, d).depth * (1 + 0x1p-50));
    // Along σ's normal the ray meets ∂O at distance σ; a rounded normal can only graze past a
    // nearest VERTEX (a corner of ∂O pointing into O), so the upper bound is checked at feet.
    const double along_normal = pd.along(t, mn.normal).depth;
    EXPECT_GE(along_normal, mn.depth * (1 - 0x1p-50));
    pendepth::polygon2::Near near;
    ASSERT_TRUE(U.nearest(t, near));
    if (near.kind == pendepth::polygon2::Near::Kind::Foot) {
      ++st.feet;
      EXPECT_LE(along_normal, mn.depth * (1 + 1e-9));
    }
    if (generic_t && mn.depth > 1e-6 * (t.norm() + 1)) EXPECT_TRUE(pd.overlapping(t + (1 - 1e-9) * mn.translation));
    const double want = oracle.boundary_distance(t);  // ∂(regularised union) ⊆ ∂O
    EXPECT_GE(want, mn.depth * (1 - 0x1p-50));
    if (generic) {
      const double e = ulps(mn.depth, want);
      EXPECT_LE(e, 8) << "t=" << t.transpose() << " " << mn.depth << " vs " << want;
      st.max_ulps_min = std::max(st.max_ulps_min, e);
    }
  }
  // σ ≈ min over dense directions (a few placements).
  int dense = 0;
  for (const Vec2& t : ts) {
    if (dense >= pendepth_test::scaled(3)) break;
    if (!pd.overlapping(t)) continue;
    ++dense;
    const double s = pd.minimum(t).depth;
    double best = INFINITY;
    const int dense_dirs = pendepth_test::scaled(2048);
    for (int k = 0; k < dense_dirs; ++k) {
      const double a = 2 * polygon2_test::kPi * (k + 0.5) / dense_dirs;
      best = std::min(best, pd.along(t, {std::cos(a), std::sin(a)}).depth);
    }
    EXPECT_GE(best, s * (1 - 0x1p-50));
    pendepth::polygon2::Near near;
    // At a foot the best sampled direction is within π/dense_dirs of the normal: σ / cos(π/dense_dirs).
    const double slack = 2 * std::pow(polygon2_test::kPi / dense_dirs, 2);
    if (U.nearest(t, near) && near.kind == pendepth::polygon2::Near::Kind::Foot) EXPECT_LE(best, s * (1 + slack));
  }
}

void report(const char* name, const Stats& st) {
  std::printf(
      "%s: %zu cases, %zu pieces, %zu boundary vertices checked exactly (%zu on slits/points), %zu rays (%zu "
      "overlapping): along = along_scan bit for bit %zu, = along_triangles %zu, max ulps %.1f / %.1f; %zu minima "
      "(max %.1f ulps vs CGAL, %zu at a foot), %zu separations (= separation_triangles bit for bit %zu, max %.1f ulps); max area error %.2e\n",
      name, st.cases, st.pieces, st.vertices_checked, st.slit_vertices, st.rays, st.rays_overlapping, st.bit_scan, st.bit_tri,
      st.max_ulps_scan, st.max_ulps_tri, st.minima, st.max_ulps_min, st.feet, st.seps, st.bit_sep, st.max_ulps_sep, st.max_area_rel);
}

TEST(UnionBoundary, RandomPolygonsWithHoles) {
  std::mt19937_64 rng(2024);
  Stats st;
  for (int it = 0; it < pendepth_test::scaled(16); ++it) {
    Polygon P = polygon2_test::random_polygon(rng, 8 + it * 3, it % 4, it % 2 == 0);
    ConvexPolygon Q = polygon2_test::random_convex(rng, 3 + it % 9, 6 + 2 * it, it % 3 == 0);
    check_case("random " + std::to_string(it), P, Q, true, rng, 10, st);
  }
  report("random", st);
}

TEST(UnionBoundary, SpiralsAndHoleGrids) {
  std::mt19937_64 rng(77);
  Stats st;
  const Polygon spiral = Polygon::simple(polygon2_test::spiral_ring(3, 2, 2.5, 2.5, 60));
  check_case("spiral/small", spiral, polygon2_test::random_convex(rng, 7, 1.0, false), true, rng, 10, st);
  check_case("spiral/wide", spiral, polygon2_test::random_convex(rng, 5, 4.0, false), true, rng, 10, st);
  const Polygon grid(polygon2_test::holes_grid(3, 4, 2, {0, 0}));
  check_case("hole grid/small square", grid, ConvexPolygon{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, true, rng, 10, st);
  check_case("hole grid/rotated", grid, polygon2_test::random_convex(rng, 6, 1.5, false), true, rng, 10, st);
  // Q exactly the size of the holes: O has an isolated boundary point per hole.
  check_case("hole grid/exact fit", grid, ConvexPolygon{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, false, rng, 10, st);
  // Offset by 1e6 (coordinates still exact on the grid).
  const Polygon far(polygon2_test::holes_grid(2, 4, 2, {1e6, 1e6}));
  check_case("hole grid/offset 1e6", far, ConvexPolygon{{0, 0}, {2, 0}, {1, 3}}, true, rng, 10, st);
  report("spirals/grids", st);
}

TEST(UnionBoundary, DegenerateExactFits) {
  std::mt19937_64 rng(5);
  Stats st;
  const Polygon comb = Polygon::simple(polygon2_test::comb_ring(4, 2, 3, 10, 2));
  const ConvexPolygon sq{{0, 0}, {3, 0}, {3, 3}, {0, 3}};
  check_case("comb/square (slits)", comb, sq, false, rng, 16, st);
  check_case("comb/triangle", comb, ConvexPolygon{{0, 0}, {3, 0}, {1.5, 2}}, false, rng, 10, st);
  check_case("comb/narrow", comb, ConvexPolygon{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, true, rng, 10, st);
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
  check_case("collinear frame/square", framed, sq, true, rng, 12, st);
  check_case("collinear frame/hole-sized square", framed, ConvexPolygon{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, false, rng, 12, st);
  report("degenerate", st);
  EXPECT_GT(st.slit_vertices, 0u);

  // Analytic: the square hole [4, 6]² of [0, 10]² and Q = [0, 2]²: t = (4, 4) is the only
  // placement inside the hole region that does not overlap; rays through it stop there.
  const Polygon sh({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{4, 4}, {4, 6}, {6, 6}, {6, 4}}});
  PolygonDepth2 pd(sh, ConvexPolygon{{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  EXPECT_FALSE(pd.overlapping({4, 4}));
  EXPECT_EQ(pd.along({4, 3.5}, {0, 1}).depth, 0.5);
  EXPECT_EQ(pd.along({3, 3}, {1, 1}).depth, std::sqrt(2.0));
  EXPECT_EQ(pd.minimum({4, 3.75}).depth, 0.25);
  EXPECT_EQ(pd.along({4.5, 4}, {-1, 0}).depth, 0.5);

}

TEST(UnionBoundary, NestingPieces) {
  std::mt19937_64 rng(11);
  Stats st;
  for (const char* f : {"albano.json", "shirts.json", "trousers.json"}) {
    auto pieces = polygon2_test::nesting_pieces(f);
    for (std::size_t k = 0; k < pieces.size(); k += std::max<std::size_t>(1, pendepth_test::kDivisor * 4)) {
      Polygon P = Polygon::simple(pieces[k], f);
      ConvexPolygon Q = ConvexPolygon::hull(pieces[(k + 1) % pieces.size()], f);
      check_case(std::string(f) + " #" + std::to_string(k), P, Q, true, rng, 6, st);
    }
  }
  report("nesting", st);
}

// The implicit structure is linear in n + m: pieces and bytes per (n + m) stay bounded.
TEST(UnionBoundary, SizeIsLinear) {
  std::mt19937_64 rng(99);
  for (int n : {16, 256, pendepth_test::scaled(4096)})
    for (int m : {4, 64, 512}) {
      Polygon P = polygon2_test::random_polygon(rng, n, 0, false);
      std::vector<Vec2> ring;  // a regular m-gon of radius 20 (all m vertices on the hull)
      for (int k = 0; k < m; ++k) ring.push_back(20 * Vec2(std::cos(2 * polygon2_test::kPi * k / m), std::sin(2 * polygon2_test::kPi * k / m)));
      ConvexPolygon Q = ConvexPolygon::hull(ring, "Q");
      const auto t0 = std::chrono::steady_clock::now();
      PolygonDepth2 pd(P, Q);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      const auto s = pd.boundary_stats();
      std::printf("n=%5d m=%4d (Q size %zu): rings %zu vertices %zu segments %zu arcs %zu bytes %zu (%.0f B/(n+m)), build %.2f ms\n",
                  n, m, Q.size(), s.rings, s.vertices, s.segments, s.arcs, s.bytes, double(s.bytes) / (n + Q.size()), ms);
      EXPECT_LE(s.vertices + s.segments + s.arcs, 6 * (P.size() + Q.size()));
      EXPECT_LE(s.bytes, 2000 * (P.size() + Q.size()));
    }
}

}  // namespace
