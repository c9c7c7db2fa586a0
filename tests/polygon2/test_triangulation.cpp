// Triangulation of polygons with holes: exact coverage, both algorithms (ear clipping for small
// hole-free polygons, CDT otherwise). Checked with GMP rationals, independently of the library's
// predicates: triangle count N - 2 + 2h, every triangle strictly CCW, the triangle areas sum
// exactly to P's area, every triangle lies inside P (its centroid is strictly inside P and no edge
// of P crosses the triangle), and no vertex of P lies in a closed triangle unless it is one of
// its corners (no vertex strictly inside, no T-junction on a triangle edge: straight vertices
// must be corners). Area equality plus containment implies pairwise disjoint interiors.
// The path taken is checked too: every hole-free polygon with N <= kEarMax must be ear-clipped
// (the ear search cannot fail on a valid polygon; a CDT fallback fails the test), every other
// one goes to the CDT. Inputs: straight vertices everywhere (subdivided rectangles, L, U, combs,
// lattice boundaries), reflex vertices exactly on would-be diagonals, thin spikes and notches,
// random stars with decimal coordinates, random polygons on tiny integer grids (collinear runs,
// subdivided), all nesting pieces, large N and holes; each hole-free one also under every cyclic
// shift of its start vertex, reversed and mirrored. Pinned seeds. Every triangulation is also
// computed by the overload writing into a caller's vector (one vector reused by every call): the
// same triangles and path; and every ear-clipped one is compared with a reference ear clipping
// (the algorithm as it stood, orientations in rationals): the same triangles in the same order.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <iostream>

#include "polygon2/triangulation.hpp"
#include "shapes.hpp"
#include "test_scale.hpp"

namespace {

using pendepth::Polygon;
using pendepth::Vec2;
using pendepth::polygon2::kEarMax;
using pendepth::polygon2::TriangulationPath;
using Ring = std::vector<Vec2>;

struct QPoint {
  mpq_class x, y;
};
int orient_q(const QPoint& a, const QPoint& b, const QPoint& c) {
  return sgn(mpq_class((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)));
}
mpq_class cross_q(const QPoint& a, const QPoint& b, const QPoint& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}
QPoint lift(const Vec2& p) { return {mpq_class(p.x()), mpq_class(p.y())}; }

// Winding number of all rings of P around p (exact), p not on ∂P.
int winding_q(const Polygon& P, const std::vector<QPoint>& Q, const QPoint& p) {
  int w = 0;
  for (std::size_t g = 0; g < P.size(); ++g) {
    const QPoint &a = Q[g], &b = Q[P.next(g)];
    if (a.y <= p.y) {
      if (b.y > p.y && orient_q(a, b, p) > 0) ++w;
    } else if (b.y <= p.y && orient_q(a, b, p) < 0) {
      --w;
    }
  }
  return w;
}

// The ear clipping of src/polygon2/triangulation.cpp as it was before its orientation filter was
// inlined, with every orientation decided here in rationals: the library must return exactly
// these triangles (same ears, same order). Empty if no ear is found.
std::vector<pendepth::polygon2::TriangleIds> reference_ear_clip(const Polygon& P, const std::vector<QPoint>& Q) {
  const auto V = P.vertices();
  const unsigned n = static_cast<unsigned>(P.size());
  std::vector<unsigned> prv(n), nxt(n), reflex;
  std::vector<bool> convex(n), ear(n);
  std::vector<double> key(n);
  for (unsigned i = 0; i < n; ++i) prv[i] = i == 0 ? n - 1 : i - 1, nxt[i] = i + 1 == n ? 0 : i + 1;
  for (unsigned i = 0; i < n; ++i) {
    convex[i] = orient_q(Q[prv[i]], Q[i], Q[nxt[i]]) > 0;
    if (!convex[i]) reflex.push_back(i);
  }
  auto is_ear = [&](unsigned v) {
    if (!convex[v]) return false;
    const Vec2 lo = V[prv[v]].cwiseMin(V[v]).cwiseMin(V[nxt[v]]), hi = V[prv[v]].cwiseMax(V[v]).cwiseMax(V[nxt[v]]);
    for (unsigned x : reflex) {
      const Vec2& p = V[x];
      if (p.x() < lo.x() || p.x() > hi.x() || p.y() < lo.y() || p.y() > hi.y() || x == prv[v] || x == nxt[v]) continue;
      if (orient_q(Q[prv[v]], Q[v], Q[x]) >= 0 && orient_q(Q[v], Q[nxt[v]], Q[x]) >= 0 && orient_q(Q[nxt[v]], Q[prv[v]], Q[x]) >= 0)
        return false;
    }
    return true;
  };
  auto refresh = [&](unsigned i) {
    if (convex[i] || orient_q(Q[prv[i]], Q[i], Q[nxt[i]]) <= 0) return;
    convex[i] = true;
    for (std::size_t k = 0; k < reflex.size(); ++k)
      if (reflex[k] == i) {
        reflex[k] = reflex.back();
        reflex.pop_back();
        break;
      }
  };
  auto update = [&](unsigned v) {
    ear[v] = is_ear(v);
    if (ear[v]) key[v] = (V[nxt[v]] - V[prv[v]]).squaredNorm();
  };
  for (unsigned i = 0; i < n; ++i) update(i);
  std::vector<pendepth::polygon2::TriangleIds> out;
  unsigned first = 0;
  for (unsigned left = n; left > 3; --left) {
    unsigned best = n;
    for (unsigned k = 0, v = first; k < left; ++k, v = nxt[v])
      if (ear[v] && (best == n || key[v] < key[best])) best = v;
    if (best == n) return {};
    const unsigned u = prv[best], w = nxt[best];
    out.push_back({u, best, w});
    nxt[u] = w;
    prv[w] = u;
    first = w;
    refresh(u);
    refresh(w);
    update(u);
    update(w);
  }
  if (orient_q(Q[prv[first]], Q[first], Q[nxt[first]]) <= 0) return {};
  out.push_back({prv[first], first, nxt[first]});
  return out;
}

std::size_t g_same_ears = 0;

struct PathCounts {
  std::size_t ear = 0, fallback = 0, cdt = 0;
};
PathCounts& counts() {
  static PathCounts c;
  return c;
}

void check_triangulation(const Polygon& P, const std::string& what) {
  TriangulationPath path{};
  const auto tris = pendepth::polygon2::triangulate(P, &path);
  {  // The overload writing into a caller's vector, reused across every call (stale content).
    static std::vector<pendepth::polygon2::TriangleIds> reused;
    TriangulationPath path2{};
    pendepth::polygon2::triangulate(P, reused, &path2);
    ASSERT_TRUE(reused == tris && path2 == path) << what << ": the reusing overload differs";
  }
  const bool small = P.hole_count() == 0 && P.size() <= kEarMax;
  (path == TriangulationPath::ear_clipping ? counts().ear : path == TriangulationPath::cdt ? counts().cdt : counts().fallback)++;
  EXPECT_NE(path, TriangulationPath::cdt_fallback) << what << ": ear clipping found no ear";
  if (path != TriangulationPath::cdt_fallback) EXPECT_EQ(path == TriangulationPath::ear_clipping, small) << what;
  ASSERT_EQ(tris.size(), P.size() - 2 + 2 * P.hole_count()) << what;
  const auto V = P.vertices();
  std::vector<QPoint> Q;
  for (const Vec2& v : V) Q.push_back(lift(v));
  mpq_class sum = 0, area = 0;
  for (std::size_t g = 0; g < P.size(); ++g) area += Q[g].x * Q[P.next(g)].y - Q[g].y * Q[P.next(g)].x;
  for (const auto& t : tris) {
    for (int k = 0; k < 3; ++k) ASSERT_LT(t[k], P.size()) << what;
    const QPoint &a = Q[t[0]], &b = Q[t[1]], &c = Q[t[2]];
    ASSERT_EQ(orient_q(a, b, c), 1) << what << ": triangle not strictly CCW";
    sum += cross_q(a, b, c);
    const QPoint cen{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
    ASSERT_NE(winding_q(P, Q, cen), 0) << what << ": triangle centroid outside P";
    for (std::size_t g = 0; g < P.size(); ++g) {
      const QPoint &p = Q[g], &q = Q[P.next(g)];
      if (g != t[0] && g != t[1] && g != t[2])
        ASSERT_FALSE(orient_q(a, b, p) >= 0 && orient_q(b, c, p) >= 0 && orient_q(c, a, p) >= 0)
            << what << ": vertex " << g << " inside or on an edge of triangle (" << t[0] << ", " << t[1] << ", " << t[2] << ")";
      // An edge of P properly crossing a triangle edge.
      const QPoint* tv[3] = {&a, &b, &c};
      for (int e = 0; e < 3; ++e) {
        const QPoint &u = *tv[e], &w = *tv[(e + 1) % 3];
        const bool cross = orient_q(u, w, p) * orient_q(u, w, q) < 0 && orient_q(p, q, u) * orient_q(p, q, w) < 0;
        ASSERT_FALSE(cross) << what << ": edge " << g << " crosses a triangle";
      }
    }
  }
  EXPECT_EQ(sum, area) << what;
  if (path == TriangulationPath::ear_clipping) {
    ASSERT_TRUE(tris == reference_ear_clip(P, Q)) << what << ": not the reference ear clipping's triangles";
    ++g_same_ears;
  }
}

// A hole-free ring, also under every cyclic shift of its first vertex (at most `shifts`, evenly
// spread), reversed and mirrored: the ear order, ties and orientation handling all change.
void check_ring(const Ring& ring, const std::string& what, std::size_t shifts = 1000) {
  const std::size_t n = ring.size(), step = std::max<std::size_t>(1, n / std::min(n, shifts));
  for (std::size_t s = 0; s < n; s += step) {
    Ring r(ring.begin() + s, ring.end());
    r.insert(r.end(), ring.begin(), ring.begin() + s);
    check_triangulation(Polygon::simple(r), what + " shift " + std::to_string(s));
    std::reverse(r.begin(), r.end());
    check_triangulation(Polygon::simple(r), what + " shift " + std::to_string(s) + " reversed");
    for (Vec2& p : r) p.x() = -p.x();
    check_triangulation(Polygon::simple(r), what + " shift " + std::to_string(s) + " mirrored");
  }
}

// Every edge split into k equal parts by k - 1 straight vertices, exactly: the ring (integer
// coordinates) is scaled by k first, so the new vertices are integers on the edges.
Ring subdivide(const Ring& ring, int k) {
  Ring out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = k * ring[i], b = k * ring[(i + 1) % ring.size()];
    for (int j = 0; j < k; ++j) out.push_back(a + (b - a) / k * j);
  }
  return out;
}

// A random valid hole-free ring from `make` (retried until Polygon accepts it).
template <class Make>
Ring valid_ring(Make&& make) {
  for (int tries = 0; tries < 10000; ++tries) {
    Ring r = make();
    try {
      const Polygon P = Polygon::simple(r);  // normal form: no repeated vertices
      return Ring(P.ring(0).begin(), P.ring(0).end());
    } catch (const pendepth::InvalidInput&) {
    }
  }
  ADD_FAILURE() << "generator made no valid ring";
  return {{0, 0}, {1, 0}, {0, 1}};
}

// Per test: the paths taken, printed; at least `min_ear`
// polygons must have been ear-clipped, none may have fallen back to the CDT.
void report(const char* test, std::size_t min_ear) {
  std::cout << "[ " << test << " ] ear clipping " << counts().ear << ", CDT " << counts().cdt << ", fallback "
            << counts().fallback << " (ear clippings identical to the reference so far " << g_same_ears << ")\n";
  EXPECT_GE(counts().ear, min_ear);
  EXPECT_EQ(counts().fallback, 0u);
}

// Counts start at zero in every test.
class Triangulation : public ::testing::Test {
 protected:
  void SetUp() override { counts() = {}; }
};

TEST_F(Triangulation, RandomPolygonsWithHoles) {
  std::mt19937_64 rng(77);
  for (int it = 0; it < pendepth_test::scaled(120); ++it)
    check_triangulation(polygon2_test::random_polygon(rng, 4 + it % 50, it % 5, it % 3 != 0), "random " + std::to_string(it));
  report("RandomPolygonsWithHoles", 1);
}

TEST_F(Triangulation, CombsCollinearAndNestingPieces) {
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
  check_triangulation(Polygon::simple(outer), "collinear grid boundary (40 vertices, CDT)");
  for (const char* f : {"albano.json", "shirts.json", "trousers.json"}) {
    int k = 0;
    for (const auto& piece : polygon2_test::nesting_pieces(f)) {
      const Polygon P = Polygon::simple(piece);  // closing vertex dropped
      check_ring(Ring(P.ring(0).begin(), P.ring(0).end()), std::string(f) + " #" + std::to_string(k++));
    }
  }
  report("CombsCollinearAndNestingPieces", 33 * 3);
}

// Rectangles, L, U and comb shapes with every edge subdivided: most vertices are straight, and
// they can be neither ear tips nor skipped.
TEST_F(Triangulation, StraightVertices) {
  const std::vector<std::pair<std::string, Ring>> shapes = {
      {"rectangle", {{0, 0}, {4, 0}, {4, 3}, {0, 3}}},
      {"L", {{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}}},
      {"U", {{0, 0}, {5, 0}, {5, 4}, {4, 4}, {4, 1}, {1, 1}, {1, 4}, {0, 4}}},
      {"comb", polygon2_test::comb_ring(3, 2, 3, 4, 1)},
      {"staircase", {{0, 0}, {3, 0}, {3, 1}, {2, 1}, {2, 2}, {1, 2}, {1, 3}, {0, 3}}},
  };
  const std::size_t shifts = pendepth_test::scaled(16);
  for (const auto& [name, ring] : shapes)
    for (int k = 1; k <= 5 && ring.size() * k <= kEarMax + 8; ++k) check_ring(subdivide(ring, k), name + " /" + std::to_string(k), shifts);
  // Lattice boundaries: every integer point of the boundary of a w x h rectangle is a vertex.
  for (int w = 1; w <= 8; ++w)
    for (int h = 1; h <= 8; ++h) {
      Ring r;
      for (int x = 0; x < w; ++x) r.push_back({double(x), 0});
      for (int y = 0; y < h; ++y) r.push_back({double(w), double(y)});
      for (int x = w; x > 0; --x) r.push_back({double(x), double(h)});
      for (int y = h; y > 0; --y) r.push_back({0, double(y)});
      check_ring(r, "lattice " + std::to_string(w) + "x" + std::to_string(h), pendepth_test::scaled(4));
    }
  // A triangle whose every side carries many straight vertices: only 3 possible tips.
  Ring tri;
  for (int i = 0; i < 10; ++i) tri.push_back({double(i), 0});
  for (int i = 0; i < 10; ++i) tri.push_back({double(10 - i), double(i)});
  for (int i = 0; i < 10; ++i) tri.push_back({0, double(10 - i)});
  check_ring(tri, "subdivided triangle", shifts);
  report("StraightVertices", pendepth_test::scaled(500));
}

// Reflex vertices exactly on the diagonal u-w of a convex vertex (the ear must be refused: a
// T-junction), on the extension of edges, and thin spikes and notches.
TEST_F(Triangulation, DiagonalsThroughVerticesAndSpikes) {
  check_ring({{0, 0}, {2, -2}, {4, 0}, {4, 2}, {2, 0}, {0, 2}}, "W (reflex vertex on u-w)");
  // The shortest diagonals, (0, 0)-(2, 0), (10, 0)-(1, 0) and (1, 0)-(-8, 0), all run through a
  // vertex: only the ears at (10, 0) and (-8, 0) are valid.
  check_ring({{0, 0}, {1, -1}, {2, 0}, {10, 0}, {10, 10}, {1, 0}, {-8, 10}, {-8, 0}}, "pocket under a reflex vertex");
  check_ring({{0, 0}, {1, -1}, {2, 0}, {3, -1}, {4, 0}, {4, 2}, {3, 0}, {2, 1}, {1, 0}, {0, 2}}, "double W");
  check_ring({{0, 0}, {6, 0}, {6, 3}, {5, 1}, {4, 3}, {3, 1}, {2, 3}, {1, 1}, {0, 3}}, "crown");
  // Reflex vertices aligned with other vertices along both axes.
  check_ring({{0, 0}, {4, 0}, {4, 4}, {3, 4}, {3, 1}, {2, 4}, {1, 1}, {1, 4}, {0, 4}}, "aligned notches");
  // A fan: every reflex vertex on the segment between its neighbours' neighbours.
  {
    Ring r;
    for (int i = 0; i <= 6; ++i) r.push_back({double(i), i % 2 == 0 ? 0.0 : -1.0});
    r.push_back({6, 2});
    for (int i = 5; i >= 1; --i) r.push_back({double(i), i % 2 == 0 ? 1.0 : 2.0});
    r.push_back({0, 2});
    check_ring(r, "zigzag band");
  }
  // Thin spikes out and thin notches in (widths ~1e-9 of the size).
  check_ring({{0, 0}, {10, 0}, {10, 10}, {5.000000001, 10}, {5, 1e6}, {4.999999999, 10}, {0, 10}}, "spike");
  check_ring({{0, 0}, {10, 0}, {10, 10}, {5.000000001, 10}, {5, 1e-9}, {4.999999999, 10}, {0, 10}}, "notch");
  check_ring({{0, 0}, {1e-9, 0}, {1e-9, 1e6}, {5e-10, 1e6 + 1}, {0, 1e6}}, "needle");
  std::mt19937_64 rng(5150);
  std::uniform_real_distribution<double> u01(0, 1);
  for (int it = 0; it < pendepth_test::scaled(200); ++it) {
    const int n = 4 + it % 20;
    Ring r = valid_ring([&] {
      Ring s = polygon2_test::star_ring(rng, n, Vec2(u01(rng), u01(rng)), 10, 20, false);
      const std::size_t k = rng() % s.size();  // vertex k becomes a spike (out) or a notch (in)
      const Vec2 d = s[k].normalized();
      const Vec2 t(-d.y(), d.x());
      const double len = it % 2 ? 1e4 : 1e-3 + 9 * u01(rng), half = 1e-7 * u01(rng);
      s[k] = len * d;
      s.insert(s.begin() + k + 1, 10 * d + half * t);  // CCW: angles increase along the ring
      s.insert(s.begin() + k, 10 * d - half * t);
      return s;
    });
    check_ring(r, "spiky star " + std::to_string(it), 3);
  }
  report("DiagonalsThroughVerticesAndSpikes", 3 * pendepth_test::scaled(200));
}

// Random stars with decimal coordinates (all N up to kEarMax and beyond), and random polygons on
// tiny integer grids (collinear runs, vertices on would-be diagonals), plain and subdivided.
TEST_F(Triangulation, RandomSmallPolygons) {
  std::mt19937_64 rng(2718);
  std::uniform_real_distribution<double> u01(0, 1);
  for (int it = 0; it < pendepth_test::scaled(400); ++it) {
    const int n = 3 + it % static_cast<int>(kEarMax + 6);
    Ring r = valid_ring([&] {
      return polygon2_test::star_ring(rng, n, Vec2(0.1 * u01(rng), 0.1 * u01(rng)), 0.05 + 0.5 * u01(rng), 1.3, false);
    });
    check_ring(r, "decimal star " + std::to_string(it), 1);
  }
  for (int it = 0; it < pendepth_test::scaled(1000); ++it) {
    const int R = 2 + it % 5, n = 3 + it % (2 * R + 2);  // n small enough for the lattice points
    Ring r = valid_ring([&] { return polygon2_test::star_ring(rng, n, Vec2(0, 0), 0.3 * R, R, true); });
    const int k = it % 3 == 2 ? 2 : 1;
    check_ring(subdivide(r, k), "grid star " + std::to_string(it) + " /" + std::to_string(k), 2);
  }
  report("RandomSmallPolygons", 3 * pendepth_test::scaled(1000));
}

TEST_F(Triangulation, PathSelection) {
  std::mt19937_64 rng(31);
  // Right at the threshold, both sides, and large N (CDT).
  for (std::size_t n : {kEarMax - 1, kEarMax, kEarMax + 1, std::size_t(100), std::size_t(400)}) {
    Ring r = valid_ring([&] { return polygon2_test::star_ring(rng, static_cast<int>(n), Vec2(0, 0), 30, 100, false); });
    check_triangulation(Polygon::simple(r), "star N = " + std::to_string(n));
  }
  // A small polygon with a hole goes to the CDT.
  check_triangulation(Polygon({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {1, 2}, {2, 2}, {2, 1}}}), "square with hole");
  EXPECT_EQ(counts().ear, 2u);
  EXPECT_EQ(counts().cdt, 4u);
  report("PathSelection", 2);
}

}  // namespace
