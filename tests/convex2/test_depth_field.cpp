// DepthField (DHS Theorem 3.2: medial axis of M + spoke-tree point location) against the
// independent O(n + m) merge minimum_depth, plus the medial axis itself against brute force.
//
// Agreement criterion: |field − merge| <= 1e-12 · max(field, merge), i.e. RELATIVE 1e-12. Both
// return the certified distance of t to some edge line of M; when they pick the same edge the
// values are bit-identical, on ties they differ by a few ulps.
#include <pendepth/depth2.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "convex2/medial_axis.hpp"
#include "convex2/minkowski_sum.hpp"
#include "test_scale.hpp"

using pendepth::ConvexPolygon;
using pendepth::Depth2;
using pendepth::DepthField;
using pendepth::Vec2;
using pendepth::convex2::MedialAxis;
using pendepth::convex2::MinkowskiSum;

namespace {

constexpr double kRelTol = 1e-12;
constexpr double kPi = std::numbers::pi;
// Medial-axis brute-force check: node positions are constructions, accurate to ~ε·|M|/Δ along
// their spokes (Δ: angle between consecutive edges); 1e-9 relative to M's extent covers Δ down to
// ~1e-7 rad, which the generated shapes stay above.
constexpr double kMedialRelTol = 1e-9;
// Angles (rad) treated as clearly positive/negative when checking wide sectors from rounded
// normals; the field itself decides with exact predicates.
constexpr double kClearAngle = 1e-9;

ConvexPolygon translated(const ConvexPolygon& P, const Vec2& d) {
  std::vector<Vec2> v(P.vertices().begin(), P.vertices().end());
  for (Vec2& p : v) p += d;
  return ConvexPolygon(v);
}

// k points at random angles on an ellipse (semi-axes rx, ry, rotated by phi, centred at c).
ConvexPolygon ellipse_points(std::mt19937_64& rng, std::size_t k, double rx, double ry, double phi,
                             const Vec2& c) {
  std::uniform_real_distribution<double> ang(0, 2 * kPi);
  std::vector<Vec2> pts;
  for (;;) {
    pts.clear();
    for (std::size_t i = 0; i < k; ++i) {
      const double a = ang(rng);
      const Vec2 e(rx * std::cos(a), ry * std::sin(a));
      pts.emplace_back(c.x() + std::cos(phi) * e.x() - std::sin(phi) * e.y(),
                       c.y() + std::sin(phi) * e.x() + std::cos(phi) * e.y());
    }
    try {
      return ConvexPolygon::hull(pts);
    } catch (const pendepth::InvalidInput&) {
    }
  }
}

// Hull of k random integer points of [-R, R]²: exact vertices, many parallel edges across P, Q.
ConvexPolygon grid_points(std::mt19937_64& rng, std::size_t k, int R) {
  std::uniform_int_distribution<int> g(-R, R);
  std::vector<Vec2> pts;
  for (;;) {
    pts.clear();
    for (std::size_t i = 0; i < k; ++i) {
      const int x = g(rng), y = g(rng);
      pts.emplace_back(x, y);
    }
    try {
      return ConvexPolygon::hull(pts);
    } catch (const pendepth::InvalidInput&) {
    }
  }
}

// Hull of k points uniform in a disk of radius r: few, irregular vertices.
ConvexPolygon disk_points(std::mt19937_64& rng, std::size_t k, double r) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec2> pts;
  for (;;) {
    pts.clear();
    while (pts.size() < k) {
      const double x = u(rng), y = u(rng);
      const Vec2 p(x, y);
      if (p.squaredNorm() <= 1) pts.push_back(r * p);
    }
    try {
      return ConvexPolygon::hull(pts);
    } catch (const pendepth::InvalidInput&) {
    }
  }
}

ConvexPolygon regular(std::size_t k, double r, double phase, const Vec2& c = {0, 0}) {
  std::vector<Vec2> v;
  for (std::size_t i = 0; i < k; ++i) {
    const double a = phase + 2 * kPi * double(i) / double(k);
    v.emplace_back(c.x() + r * std::cos(a), c.y() + r * std::sin(a));
  }
  return ConvexPolygon(v);
}

ConvexPolygon rectangle(double x0, double y0, double x1, double y1) {
  return ConvexPolygon({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

std::size_t ceil_log2(std::size_t n) {
  std::size_t b = 0;
  while ((std::size_t(1) << b) < n) ++b;
  return b;
}

// Runs queries against one field and records the worst disagreement.
class Checker {
 public:
  // expect_tree = false: rounding is expected to leave the medial axis undefined, and the field
  // to fall back to the certified O(N) scan (max_search_depth() == N, no medial nodes).
  Checker(const ConvexPolygon& P, const ConvexPolygon& Q, bool expect_tree = true)
      : P_(P), Q_(Q), M_(P, Q), F_(P, Q) {
    const std::size_t N = M_.size();
    EXPECT_EQ(F_.edge_count(), N);
    if (expect_tree) {
      EXPECT_EQ(F_.node_count(), N - 2);
      EXPECT_LE(F_.max_search_depth(), ceil_log2(N) + 2) << "N = " << N;
    } else {
      EXPECT_EQ(F_.node_count(), 0u);
      EXPECT_EQ(F_.max_search_depth(), N);
    }
    for (std::size_t k = 0; k < N; ++k) world_ = std::max(world_, M_.vertex(k).cwiseAbs().maxCoeff());
  }
  const MinkowskiSum& M() const { return M_; }
  const DepthField& field() const { return F_; }

  // One query: field vs merge, and the separation property of the result.
  void query(const Vec2& t) {
    const Depth2 f = F_.minimum(t);
    const Depth2 g = pendepth::minimum_depth(P_, Q_, t);
    ++queries_;
    ASSERT_EQ(f.overlapping, g.overlapping) << "t = " << t.transpose();
    const double err = std::abs(f.depth - g.depth);
    const double rel = err / std::max(f.depth, g.depth);
    if (err > 0) worst_rel_ = std::max(worst_rel_, rel);
    EXPECT_TRUE(err == 0 || rel <= kRelTol)
        << "t = (" << t.x() << ", " << t.y() << ") field " << f.depth << " merge " << g.depth;
    if (!f.overlapping) {
      EXPECT_EQ(f.depth, 0.0);
      EXPECT_EQ(f.translation, Vec2(0, 0));
      return;
    }
    ++overlapping_;
    EXPECT_GT(f.depth, 0.0);
    EXPECT_NEAR(f.translation.norm(), f.depth, 1e-15 * f.depth);  // |rounded unit normal| = 1 ± 2ε
    // Moving Q by the translation separates it, any shorter move along it does not. Needs the
    // 1e-9 margin to dominate rounding of t + v (about 1e-16 · |t|).
    if (f.depth > 1e-5 * world_) {
      EXPECT_FALSE(M_.contains_interior(t + f.translation * (1 + 1e-9))) << t.transpose();
      EXPECT_TRUE(M_.contains_interior(t + f.translation * (1 - 1e-9))) << t.transpose();
    }
  }

  // Uniform queries in M's bounding box grown by 10%.
  void random_queries(std::mt19937_64& rng, int count) {
    Vec2 lo = M_.vertex(0), hi = lo;
    for (std::size_t k = 1; k < M_.size(); ++k) {
      lo = lo.cwiseMin(M_.vertex(k));
      hi = hi.cwiseMax(M_.vertex(k));
    }
    const Vec2 pad = 0.05 * (hi - lo);
    std::uniform_real_distribution<double> ux(lo.x() - pad.x(), hi.x() + pad.x());
    std::uniform_real_distribution<double> uy(lo.y() - pad.y(), hi.y() + pad.y());
    for (int s = 0; s < count; ++s) query({ux(rng), uy(rng)});
  }

  // Queries exactly on (the rounded) medial vertices and along their spokes.
  void medial_queries(std::size_t max_nodes) {
    const MedialAxis ma = pendepth::convex2::medial_axis(M_);
    ASSERT_TRUE(ma.ok);
    const std::size_t step = std::max<std::size_t>(1, ma.centre.size() / max_nodes);
    for (std::size_t j = 0; j < ma.centre.size(); j += step) {
      const Vec2 v = ma.origin + ma.centre[j];
      query(v);
      for (std::uint32_t e : ma.line[j]) {
        const double r = ma.offset[e] - ma.normal[e].dot(ma.centre[j]);
        for (double s : {0.25, 0.5, 0.999}) query(v + s * r * ma.normal[e]);
      }
    }
  }

  int queries() const { return queries_; }
  int overlapping() const { return overlapping_; }
  double worst_rel() const { return worst_rel_; }
  double world() const { return world_; }

 private:
  ConvexPolygon P_, Q_;
  MinkowskiSum M_;
  DepthField F_;
  double world_ = 0, worst_rel_ = 0;
  int queries_ = 0, overlapping_ = 0;
};

// Brute-force check of the medial axis: every node is a maximal inscribed disk (equidistant from
// its three lines, no line closer), the adjacency is a tree with N leaves and symmetric labels.
void check_medial_axis(const ConvexPolygon& P, const ConvexPolygon& Q) {
  const MinkowskiSum M(P, Q);
  const std::size_t N = M.size();
  const MedialAxis ma = pendepth::convex2::medial_axis(M);
  ASSERT_TRUE(ma.ok);
  ASSERT_EQ(ma.centre.size(), N - 2);
  double extent = 0;
  for (std::size_t k = 0; k < N; ++k) extent = std::max(extent, (M.vertex(k) - ma.origin).norm());
  const double tol = kMedialRelTol * extent;
  std::size_t leaves = 0;
  for (std::size_t j = 0; j < N - 2; ++j) {
    const Vec2& x = ma.centre[j];
    auto dist = [&](std::size_t e) { return ma.offset[e] - ma.normal[e].dot(x); };
    const double r = dist(ma.line[j][0]);
    EXPECT_GE(r, -tol);
    for (std::uint32_t e : ma.line[j]) EXPECT_NEAR(dist(e), r, tol) << "node " << j;
    for (std::size_t e = 0; e < N; ++e) EXPECT_GE(dist(e), r - tol) << "node " << j << " line " << e;
    // The three lines are distinct and in counter-clockwise order of their normals. Edges of M
    // are numbered by increasing direction angle, so going once around is exactly one descent.
    int descents = 0;
    for (int k = 0; k < 3; ++k) descents += ma.line[j][(k + 1) % 3] < ma.line[j][k];
    EXPECT_EQ(descents, 1) << "node " << j;
    EXPECT_TRUE(ma.line[j][0] != ma.line[j][1] && ma.line[j][1] != ma.line[j][2] && ma.line[j][2] != ma.line[j][0]);
    // The sector marked wide is the one spanning more than 180° (checked where angles are clear).
    for (int k = 0; k < 3; ++k) {
      const Vec2 &a = ma.normal[ma.line[j][k]], &b = ma.normal[ma.line[j][(k + 1) % 3]];
      const double ang = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));  // in (−π, π]
      if (ang < -kClearAngle) {
        EXPECT_EQ(ma.wide[j], k) << "node " << j;
      }
      if (ang > kClearAngle && ang < kPi - kClearAngle) {
        EXPECT_NE(ma.wide[j], k) << "node " << j;
      }
    }
    // Creation order: the node consuming j's wavefront vertex comes later (the field roots the
    // tree with it).
    if (std::int32_t(j) != ma.root) {
      EXPECT_GT(ma.adj[j][2], std::int32_t(j));
    }
    for (int k = 0; k < 2; ++k) EXPECT_LT(ma.adj[j][k], std::int32_t(j));
    for (int k = 0; k < 3; ++k) {
      const std::int32_t w = ma.adj[j][k];
      if (w == MedialAxis::kLeaf) {
        ++leaves;
        continue;
      }
      ASSERT_GE(w, 0);
      ASSERT_LT(std::size_t(w), N - 2);
      // The neighbour's sector towards j separates the same two lines, in the other order.
      int back = -1;
      for (int b = 0; b < 3; ++b)
        if (ma.adj[w][b] == std::int32_t(j)) back = b;
      ASSERT_GE(back, 0) << "adjacency not symmetric at " << j;
      EXPECT_EQ(ma.line[w][back], ma.line[j][(k + 1) % 3]);
      EXPECT_EQ(ma.line[w][(back + 1) % 3], ma.line[j][k]);
    }
  }
  EXPECT_EQ(leaves, N);
  // Connected: N − 2 nodes reached from the root.
  std::vector<char> seen(N - 2, 0);
  std::vector<std::int32_t> stack{ma.root};
  seen[ma.root] = 1;
  std::size_t reached = 0;
  while (!stack.empty()) {
    const std::int32_t v = stack.back();
    stack.pop_back();
    ++reached;
    for (std::int32_t w : ma.adj[v])
      if (w >= 0 && !seen[w]) seen[w] = 1, stack.push_back(w);
  }
  EXPECT_EQ(reached, N - 2);
}

}  // namespace

TEST(MedialAxis, MaximalDisksAndTreeOnRandomAndDegenerateShapes) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < pendepth_test::scaled(150); ++trial) {
    const std::size_t n = 3 + rng() % 60, m = 3 + rng() % 60;
    switch (trial % 3) {
      case 0: {
        const double rx = 1 + 3 * u(rng), phi = u(rng) * kPi, ry = 0.2 + u(rng), psi = u(rng) * kPi;
        const ConvexPolygon P = ellipse_points(rng, n, rx, 1, phi, {0, 0});
        check_medial_axis(P, ellipse_points(rng, m, 1, ry, psi, {0.3, -0.1}));
        break;
      }
      case 1:
        check_medial_axis(grid_points(rng, n, 5), grid_points(rng, m, 5));
        break;
      default: {
        const ConvexPolygon P = disk_points(rng, n, 2);
        check_medial_axis(P, P);
      }
    }
  }
  for (std::size_t k = 3; k <= 64; k += (pendepth_test::kDivisor > 1 ? 7 : 1)) {
    check_medial_axis(regular(k, 1, 0), ConvexPolygon({{0, 0}, {1e-3, 0}, {0, 1e-3}}));
    check_medial_axis(regular(k, 1, 0.1), regular(k, 2, 0.1));
  }
  check_medial_axis(rectangle(0, 0, 10, 1), rectangle(0, 0, 2, 3));
  check_medial_axis(rectangle(0, 0, 1, 1), rectangle(-1, -1, 1, 1));
  check_medial_axis(ConvexPolygon({{0, 0}, {1, 0}, {0, 1}}), ConvexPolygon({{0, 0}, {-2, 0}, {0, -2}}));
}

TEST(DepthField, RandomPairsAgreeWithMerge) {
  std::mt19937_64 rng(777);
  std::uniform_real_distribution<double> u(0, 1);
  // Sizes log-uniform in [3, 2000].
  auto size = [&] { return std::size_t(std::exp(std::log(3.0) + u(rng) * std::log(2000.0 / 3.0))); };
  int pairs = 0, queries = 0, overlapping = 0;
  double worst = 0;
  for (int trial = 0; trial < pendepth_test::scaled(2400); ++trial) {
    ConvexPolygon P = regular(3, 1, 0), Q = P;
    switch (trial % 4) {
      case 0: {  // points on ellipses: near-parallel edges, smooth medial axes
        const std::size_t n = size(), m = size();
        const double a[10] = {u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
        P = ellipse_points(rng, n, 0.5 + 4 * a[0], 0.5 + a[1], a[2] * kPi, {a[3], a[4]});
        Q = ellipse_points(rng, m, 0.2 + a[5], 0.2 + 2 * a[6], a[7] * kPi, {a[8], -a[9]});
        break;
      }
      case 1:  // small integer grid: many parallel edge pairs, exact vertices
        P = grid_points(rng, 3 + rng() % 40, 5);
        Q = grid_points(rng, 3 + rng() % 40, 5);
        break;
      case 2: {  // points on circles
        const std::size_t n = size(), m = size();
        P = ellipse_points(rng, n, 1, 1, 0, {0, 0});
        Q = ellipse_points(rng, m, 0.3, 0.3, 0, {0.1, 0.2});
        break;
      }
      default: {  // random hulls of disk points
        const std::size_t n = size(), m = size();
        const double rp = 1 + 3 * u(rng), rq = 0.1 + u(rng);
        P = disk_points(rng, n, rp);
        Q = disk_points(rng, m, rq);
      }
    }
    Checker c(P, Q);
    c.random_queries(rng, 24);
    if (trial % 8 == 0) c.medial_queries(40);
    ++pairs;
    queries += c.queries();
    overlapping += c.overlapping();
    worst = std::max(worst, c.worst_rel());
    if (HasFailure()) break;
  }
  EXPECT_GT(overlapping, queries / 3);
  std::printf("random pairs %d, queries %d (overlapping %d), worst relative difference %.3g\n", pairs,
              queries, overlapping, worst);
}

TEST(DepthField, RegularPolygonsSimultaneousEvents) {
  std::mt19937_64 rng(31);
  for (std::size_t k = 3; k <= 64; k += (pendepth_test::kDivisor > 1 ? 7 : 1)) {
    for (const ConvexPolygon& Q : {regular(4, 0.25, 0), regular(k, 0.5, 0), regular(k, 0.5, kPi / double(k)),
                                   regular(3, 0.1, 0.3)}) {
      Checker c(regular(k, 1, 0), Q);
      c.random_queries(rng, 40);
      c.medial_queries(200);
      c.query({0, 0});  // the common centre of all simultaneous events
    }
  }
}

TEST(DepthField, RectanglesMatchAnalyticAnswer) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < pendepth_test::scaled(200); ++trial) {
    const double w = trial % 5 == 0 ? 1 : 0.1 + 10 * u(rng), h = trial % 5 == 0 ? 1 : 0.1 + 10 * u(rng);
    const double qw = trial % 7 == 0 ? w : 0.1 + 3 * u(rng), qh = trial % 7 == 0 ? h : 0.1 + 3 * u(rng);
    const ConvexPolygon P = rectangle(0, 0, w, h), Q = rectangle(-qw, -qh, 0, 0);
    // M = [0, w + qw] × [0, h + qh].
    Checker c(P, Q);
    c.medial_queries(50);
    for (int s = 0; s < 50; ++s) {
      const double sx = u(rng), sy = u(rng);
      const Vec2 t(sx * (w + qw), sy * (h + qh));
      c.query(t);
      const double expect = std::min({t.x(), w + qw - t.x(), t.y(), h + qh - t.y()});
      EXPECT_NEAR(c.field().minimum(t).depth, expect, 1e-15 * (w + h + qw + qh));
    }
  }
}

TEST(DepthField, IdenticalShapesAndTriangles) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < pendepth_test::scaled(150); ++trial) {
    const std::size_t n = 3 + rng() % 300;
    const double phi = u(rng);
    const ConvexPolygon P = trial % 2 ? disk_points(rng, n, 1) : ellipse_points(rng, n, 2, 1, phi, {0, 0});
    Checker c(P, P);  // M = P ⊕ (−P): centrally symmetric, every edge of source Both
    c.random_queries(rng, 30);
    c.medial_queries(30);
    c.query({0, 0});
  }
  // Triangles: homothetic pair (M is a triangle, N = 3), random pairs, P with itself.
  const ConvexPolygon T({{0, 0}, {1, 0}, {0, 1}});
  {
    Checker c(T, ConvexPolygon({{0, 0}, {-2, 0}, {0, -2}}));
    EXPECT_EQ(c.M().size(), 3u);
    EXPECT_EQ(c.field().max_search_depth(), 1u);
    c.random_queries(rng, 200);
    c.medial_queries(10);
    // Incentre of the triangle (0,0), (3,0), (0,3): r = 3 / (2 + √2).
    const double r = 3 / (2 + std::sqrt(2.0));
    EXPECT_NEAR(c.field().minimum({r, r}).depth, r, 1e-15);
  }
  for (int trial = 0; trial < pendepth_test::scaled(300); ++trial) {
    const ConvexPolygon A = disk_points(rng, 3, 1), B = disk_points(rng, 3, 1);
    Checker c(A, B);
    c.random_queries(rng, 20);
    c.medial_queries(10);
    Checker d(A, A);
    d.random_queries(rng, 20);
  }
}

TEST(DepthField, FarFromOrigin) {
  std::mt19937_64 rng(1000000);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < pendepth_test::scaled(100); ++trial) {
    const std::size_t n = 3 + rng() % 300, m = 3 + rng() % 50;
    const double phi = u(rng), ox = 1e6 * (1 + u(rng)), oy = -1e6 * (1 + u(rng));
    const ConvexPolygon P0 = ellipse_points(rng, n, 1, 0.5, phi, {0, 0});
    const ConvexPolygon Q0 = disk_points(rng, m, 0.4);
    const Vec2 off(ox, oy);
    {  // both far: M near the origin, built from large coordinates
      Checker c(translated(P0, off), translated(Q0, off));
      c.random_queries(rng, 30);
      c.medial_queries(20);
    }
    {  // P far: M far from the origin
      Checker c(translated(P0, off), Q0);
      c.random_queries(rng, 30);
      c.medial_queries(20);
    }
  }
}

TEST(DepthField, BoundaryAndOutsideAreZero) {
  std::mt19937_64 rng(2718);
  for (int trial = 0; trial < pendepth_test::scaled(200); ++trial) {
    // Integer shapes: M's vertices and edge midpoints are exact doubles on ∂M.
    const ConvexPolygon P = grid_points(rng, 3 + rng() % 30, 5 + trial % 20);
    const ConvexPolygon Q = grid_points(rng, 3 + rng() % 30, 5);
    Checker c(P, Q);
    const MinkowskiSum& M = c.M();
    for (std::size_t k = 0; k < M.size(); ++k) {
      const Vec2 v = M.vertex(k), w = M.vertex((k + 1) % M.size());
      for (const Vec2& t : {v, Vec2(0.5 * (v + w)), Vec2(0.25 * v + 0.75 * w)}) {
        const Depth2 r = c.field().minimum(t);
        EXPECT_FALSE(r.overlapping) << t.transpose();
        EXPECT_EQ(r.depth, 0.0);
        c.query(t);
      }
      // Just outside across edge k, and far away.
      c.query(0.5 * (v + w) + 1e-9 * M.outward_normal(k));
      EXPECT_EQ(c.field().minimum(0.5 * (v + w) + 1e-9 * M.outward_normal(k)).depth, 0.0);
      EXPECT_EQ(c.field().minimum(v + 1e3 * M.outward_normal(k)).depth, 0.0);
    }
    c.random_queries(rng, 20);
  }
}

TEST(DepthField, NearlyCollinearRuns) {
  const double s = 0x1p50;
  std::mt19937_64 rng(4);
  {
    // Runs of edges whose directions differ by ~1e-15 rad: still a medial axis in double.
    std::vector<Vec2> v;
    for (int k = 0; k <= 6; ++k) v.emplace_back(k * s, k * s + double(k) * k);
    v.emplace_back(0, 4 * s);
    const ConvexPolygon P(v);
    for (const ConvexPolygon& Q : {ConvexPolygon({{0, 0}, {1, 0}, {0, 1}}), P,
                                   ConvexPolygon({{0, 0}, {s, 1}, {s, s}})}) {
      Checker c(P, Q);
      c.random_queries(rng, 500);
    }
  }
  {
    // Consecutive edge directions 2^-101 rad apart: the rounded normals coincide, the bisectors
    // of a shrinking edge are parallel in double, and the field must fall back to the scan.
    const ConvexPolygon P({{0, 0}, {s + 1, s}, {2 * s + 3, 2 * s + 1}, {3 * s + 6, 3 * s + 3},
                           {4 * s + 10, 4 * s + 6}, {0, 4 * s}});
    for (const ConvexPolygon& Q : {ConvexPolygon({{0, 0}, {1, 0}, {0, 1}}), P}) {
      Checker c(P, Q, false);
      c.random_queries(rng, 2000);
      EXPECT_GT(c.overlapping(), 500);
    }
  }
}

TEST(DepthField, LargeSpotCheck) {
  std::mt19937_64 rng(424242);
  const ConvexPolygon P = ellipse_points(rng, 100000, 3, 1, 0.3, {0.5, 0.25});
  const ConvexPolygon Q = ellipse_points(rng, 100000, 1, 1, 0, {0, 0});
  Checker c(P, Q);
  EXPECT_GT(c.M().size(), 190000u);
  c.random_queries(rng, 400);
  c.medial_queries(25);
  EXPECT_GT(c.overlapping(), 250);
  std::printf("N = %zu, depth %zu, worst relative difference %.3g\n", c.M().size(),
              c.field().max_search_depth(), c.worst_rel());
}

TEST(DepthField, DepthQuery2UsesField) {
  const ConvexPolygon P = regular(12, 2, 0.2), Q = regular(5, 1, 0);
  const pendepth::DepthQuery2 q(P, Q);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int s = 0; s < 200; ++s) {
    const double x = u(rng), y = u(rng);
    const Vec2 t(x, y);
    EXPECT_EQ(q.minimum(t).depth, q.field().minimum(t).depth);
    EXPECT_NEAR(q.minimum(t).depth, pendepth::minimum_depth(P, Q, t).depth, 1e-15);
  }
  EXPECT_THROW(q.minimum({std::nan(""), 0}), pendepth::InvalidInput);
}
