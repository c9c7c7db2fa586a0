// The no-fit polygon's set-up (src/nonconvex2/nfp_build.cpp candidates, geometry::BoxTree (src/geometry/box_tree.hpp)):
// - nfp_candidates (a table of n·m exact cross signs of edge vectors, decided by rounding
//   monotonicity and exact product errors when the edge vectors are exact, else a static filter
//   and the exact predicate) against a plain enumeration with GMP rationals (every turn test
//   evaluated exactly, the rule of nfp_impl.hpp read literally): the same candidates in the same
//   order, same ids, strictness, symbolic fields, rounded ends and boxes. Inputs: random stars and
//   polygons with holes (real and integer coordinates), tiny integer grids and subdivided hulls
//   (many parallel edges: the cross signs are exact zeros), combs, large offsets (inexact edge
//   vectors), tiny and huge scales (products near underflow: the fallback), nesting instances,
//   nearly parallel edges whose rounded cross products tie (only the exact product errors decide;
//   deciding such ties as zero fails it), straight vertices between inexact edge vectors (exact
//   zeros the roundings miss; trusting rounded vectors as exact fails it).
// - BoxTree::build / build_boxes against the previous builder (index array, key table,
//   nth_element, copied here as the reference): identical nodes, on random boxes with many ties;
//   plus the hierarchy invariants (every node box is the exact union of its leaves' boxes).
// - BoxTree::build_in_order (the piece tree of small no-fit polygons, a different tree): the
//   invariants, every node reached once from the root, and its leaves left to right are the
//   input order (so every subtree is a run of consecutive leaves), on reused trees.
// Pinned seeds.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <random>
#include <string>
#include <tuple>

#include "nfp_shapes.hpp"
#include "nonconvex2/nfp_impl.hpp"
#include "polygon2/shapes.hpp"
#include "test_scale.hpp"

namespace {

using pendepth::Polygon;
using pendepth::Vec2;
namespace nc = pendepth::nonconvex2;
using nonconvex2_test::star;

// Exact sign of (a1 − a0) × (b1 − b0) in rationals.
int cross_q(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  const mpq_class ax = mpq_class(a1.x()) - mpq_class(a0.x()), ay = mpq_class(a1.y()) - mpq_class(a0.y());
  const mpq_class bx = mpq_class(b1.x()) - mpq_class(b0.x()), by = mpq_class(b1.y()) - mpq_class(b0.y());
  return sgn(mpq_class(ax * by - ay * bx));
}

struct RefCandidate {
  std::uint32_t p0, q0, p1, q1;
  bool q_edge, strict;
};

// The candidate rule, literally: P edge g with a non-reflex Q vertex q whose two edges lie on the
// closed outer side of g; then Q edge h with a non-reflex P vertex p likewise.
std::vector<RefCandidate> reference(const Polygon& P, const Polygon& Q) {
  const auto VP = P.vertices(), VQ = Q.vertices();
  std::vector<std::uint32_t> prevP(P.size()), prevQ(Q.size());
  for (std::size_t g = 0; g < P.size(); ++g) prevP[P.next(g)] = static_cast<std::uint32_t>(g);
  for (std::size_t g = 0; g < Q.size(); ++g) prevQ[Q.next(g)] = static_cast<std::uint32_t>(g);
  auto turnP = [&](std::size_t g) { return cross_q(VP[prevP[g]], VP[g], VP[g], VP[P.next(g)]); };
  auto turnQ = [&](std::size_t g) { return cross_q(VQ[prevQ[g]], VQ[g], VQ[g], VQ[Q.next(g)]); };
  std::vector<RefCandidate> out;
  for (std::uint32_t g = 0; g < P.size(); ++g) {
    const auto g1 = static_cast<std::uint32_t>(P.next(g));
    for (std::uint32_t q = 0; q < Q.size(); ++q) {
      const int t = turnQ(q);
      if (t < 0 || cross_q(VP[g], VP[g1], VQ[q], VQ[prevQ[q]]) > 0 || cross_q(VP[g], VP[g1], VQ[q], VQ[Q.next(q)]) > 0) continue;
      out.push_back({g, q, g1, q, false, t > 0});
    }
  }
  for (std::uint32_t h = 0; h < Q.size(); ++h) {
    const auto h1 = static_cast<std::uint32_t>(Q.next(h));
    for (std::uint32_t p = 0; p < P.size(); ++p) {
      const int t = turnP(p);
      if (t < 0 || cross_q(VQ[h], VQ[h1], VP[p], VP[prevP[p]]) > 0 || cross_q(VQ[h], VQ[h1], VP[p], VP[P.next(p)]) > 0) continue;
      out.push_back({p, h, p, h1, true, t > 0});
    }
  }
  return out;
}

std::size_t& total_candidates() {
  static std::size_t n = 0;
  return n;
}

void same_candidates(const Polygon& P, const Polygon& Q, const std::string& what) {
  const auto got = nc::nfp_candidates(P, Q);
  const auto ref = reference(P, Q);
  ASSERT_EQ(got.size(), ref.size()) << what;
  const auto VP = P.vertices(), VQ = Q.vertices();
  for (std::size_t k = 0; k < ref.size(); ++k) {
    const nc::NfpCandidate& c = got[k];
    const RefCandidate& r = ref[k];
    ASSERT_TRUE(c.E.p0 == r.p0 && c.E.q0 == r.q0 && c.E.p1 == r.p1 && c.E.q1 == r.q1) << what << " candidate " << k;
    ASSERT_EQ(c.line.q_edge, r.q_edge) << what << " candidate " << k;
    ASSERT_EQ(c.strict, r.strict) << what << " candidate " << k;
    ASSERT_TRUE(c.E.sym && c.line.p0 == r.p0 && c.line.p1 == r.p1 && c.line.q0 == r.q0 && c.line.q1 == r.q1) << what << " " << k;
    // The symbolic fields: from sum vertex (p0, q0) to (p1, q1), line through it along the edge.
    ASSERT_TRUE(c.E.o1 == VP[r.p0] && c.E.o2 == Vec2(-VQ[r.q0]) && c.line.c1 == VP[r.p0] && c.line.c2 == Vec2(-VQ[r.q0])) << what << " " << k;
    if (r.q_edge) {
      ASSERT_TRUE(c.E.a1 == Vec2(-VQ[r.q1]) && c.E.b1 == Vec2(-VQ[r.q0]) && c.line.e0 == Vec2(-VQ[r.q0]) && c.line.e1 == Vec2(-VQ[r.q1])) << what;
    } else {
      ASSERT_TRUE(c.E.a1 == VP[r.p1] && c.E.b1 == VP[r.p0] && c.line.e0 == VP[r.p0] && c.line.e1 == VP[r.p1]) << what;
    }
    ASSERT_TRUE(c.E.a2 == Vec2(0, 0) && c.E.b2 == Vec2(0, 0)) << what;
    // Rounded ends (one rounding each) and a box holding the exact segment.
    const Vec2 A = VP[r.p0] - VQ[r.q0], B = VP[r.p1] - VQ[r.q1];
    ASSERT_TRUE(c.A == A && c.B == B) << what << " " << k;
    for (int i = 0; i < 2; ++i) {
      const mpq_class lo = c.lo[i], hi = c.hi[i];
      const mpq_class a = mpq_class(VP[r.p0][i]) - mpq_class(VQ[r.q0][i]), b = mpq_class(VP[r.p1][i]) - mpq_class(VQ[r.q1][i]);
      ASSERT_TRUE(lo <= a && a <= hi && lo <= b && b <= hi) << what << " box " << k;
    }
  }
  total_candidates() += ref.size();
}

Polygon moved(const Polygon& S, const Vec2& o, double scale) {
  return nonconvex2_test::mapped(S, [&](const Vec2& p) { return Vec2(p * scale + o); });
}

TEST(NfpCandidates, RandomPairs) {
  std::mt19937_64 rng(6061);
  for (int it = 0; it < pendepth_test::scaled(300); ++it) {
    const bool grid = it % 2;
    const Polygon P = it % 3 == 0 ? polygon2_test::random_polygon(rng, 10 + int(rng() % 20), 1 + int(rng() % 2), grid)
                                  : star(rng, 8 + int(rng() % 30), 50, 100, grid);
    const Polygon Q = it % 4 == 3 ? polygon2_test::random_polygon(rng, 8, 1, grid) : star(rng, 5 + int(rng() % 20), 15, 45, grid);
    same_candidates(P, Q, "random " + std::to_string(it));
    same_candidates(Q, P, "random swapped " + std::to_string(it));
  }
}

// Tiny integer shapes: many parallel and collinear edges, straight vertices, P against itself.
TEST(NfpCandidates, GridAndCollinearHeavy) {
  std::mt19937_64 rng(7177);
  for (int it = 0; it < pendepth_test::scaled(600); ++it) {
    const Polygon P = star(rng, 4 + int(rng() % 7), 1, 6, true);
    const Polygon Q = it % 3 == 0 ? P : star(rng, 3 + int(rng() % 6), 1, 4, true);
    same_candidates(P, Q, "grid " + std::to_string(it));
    const Polygon H = nonconvex2_test::convex_hull(rng, 3 + int(rng() % 12), 2 + int(rng() % 9));
    const Polygon G = nonconvex2_test::convex_hull(rng, 3 + int(rng() % 12), 2 + int(rng() % 9));
    same_candidates(nonconvex2_test::subdivided(H), G, "straight hull " + std::to_string(it));
    same_candidates(H, nonconvex2_test::subdivided(H), "hull / straight self " + std::to_string(it));
    same_candidates(nonconvex2_test::subdivided(P), nonconvex2_test::subdivided(H), "straight both " + std::to_string(it));
  }
  const Polygon comb = Polygon::simple(polygon2_test::comb_ring(4, 3, 2, 5, 2), "comb P");
  auto r = polygon2_test::comb_ring(3, 2, 3, 5, 2);
  for (auto& p : r) p = Vec2(p.x(), -p.y());
  const Polygon combQ = Polygon::simple(r, "comb Q");
  same_candidates(comb, combQ, "combs");
  same_candidates(combQ, comb, "combs swapped");
  same_candidates(Polygon(polygon2_test::holes_grid(3, 2, 1, Vec2(0, 0)), "holes grid"),
                  Polygon::simple(std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, "square"), "holes grid");
}

// Offsets make edge vectors inexact (the filter path); tiny scales put products near underflow
// (the exact product errors are not available: the fallback); huge scales near overflow.
TEST(NfpCandidates, OffsetsAndScales) {
  std::mt19937_64 rng(9091);
  for (int it = 0; it < pendepth_test::scaled(60); ++it) {
    const Polygon P = star(rng, 12, 50, 100, it % 2), Q = star(rng, 7, 15, 45, it % 2);
    const Polygon H = nonconvex2_test::subdivided(nonconvex2_test::convex_hull(rng, 10, 6));
    const std::string tag = " " + std::to_string(it);
    same_candidates(moved(P, Vec2(1e6 * (1 + it), -3e5 * it), 1), moved(Q, Vec2(-2e5, 7e5), 1), "offset" + tag);
    same_candidates(moved(H, Vec2(0.1 * it, 1e7 + 0.3), 0.1), moved(H, Vec2(-2e5, 0.7), 0.1), "offset straight" + tag);
    for (double s : {0x1p-30, 0x1p-470, 0x1p-520, 0x1p-600, 0x1p+400, 0x1p+510})
      same_candidates(moved(P, Vec2(0, 0), s), moved(H, Vec2(0, 0), s), "scaled " + std::to_string(std::ilogb(s)) + tag);
  }
}

// Nearly parallel edges with products near 2^54: the two rounded products of a cross are often
// equal while the exact ones differ by a few units (decided by the exact product errors only).
TEST(NfpCandidates, RoundingTiesOfProducts) {
  std::mt19937_64 rng(5150);
  const double h = 0x1p28;
  int ties = 0;
  for (int it = 0; it < pendepth_test::scaled(2000); ++it) {
    // (a, b) and (c, d) with a·d − b·c = e exactly, e ∈ [−2, 2], all four in [1.4·2^26, 2^27):
    // the Bézout solution of a·d0 − b·c0 = 1 scaled by e and shifted along (a, b).
    const std::int64_t a = 0x59'00000 + std::int64_t(rng() % 0x26'00000), b = 0x59'00000 + std::int64_t(rng() % 0x26'00000);
    std::int64_t r0 = a, r1 = b, s0 = 1, s1 = 0, t0 = 0, t1 = 1;  // s·a + t·b = gcd
    while (r1 != 0) {
      const std::int64_t q = r0 / r1;
      std::tie(r0, r1) = std::make_pair(r1, r0 - q * r1);
      std::tie(s0, s1) = std::make_pair(s1, s0 - q * s1);
      std::tie(t0, t1) = std::make_pair(t1, t0 - q * t1);
    }
    if (r0 != 1) continue;  // a·s0 + b·t0 = 1: d0 = s0, c0 = −t0
    const std::int64_t e = std::int64_t(rng() % 5) - 2;
    std::int64_t c = -t0 * e, d = s0 * e;
    const std::int64_t k = (a - c) / a;  // shift c to about a
    c += k * a, d += k * b;
    if (c <= 0 || d <= 0 || c >= std::int64_t(h) || d >= std::int64_t(h)) continue;
    const int turn = int(rng() % 4);  // quarter turns are exact
    auto rot = [&](Vec2 p) {
      for (int k = 0; k < turn; ++k) p = Vec2(-p.y(), p.x());
      return p;
    };
    const double A = double(a), B = double(b), C = double(c), D = double(d);
    const Polygon P = Polygon::simple(std::vector<Vec2>{rot({0, 0}), rot({A, B}), rot({0, h})}, "P");
    const Polygon Q = Polygon::simple(std::vector<Vec2>{rot({0, 0}), rot({C, D}), rot({0, h})}, "Q");
    const Polygon R = Polygon::simple(std::vector<Vec2>{rot({0, 0}), rot({C, D}), rot({C - h, D + h}), rot({-h, h})}, "R");
    ties += (A * D == B * C && e != 0);  // equal roundings, unequal exact products
    const std::string tag = " " + std::to_string(it);
    same_candidates(P, Q, "ties" + tag);
    same_candidates(Q, P, "ties swapped" + tag);
    same_candidates(P, R, "ties quad" + tag);
    same_candidates(R, P, "ties quad swapped" + tag);
  }
  std::cout << "[nfp candidates] " << ties << " pairs of edges whose rounded cross products tie\n";
  EXPECT_GT(ties, pendepth_test::scaled(2000) / 50);  // the case this test is for does occur
}

// A straight vertex M of P on the line y = 3x, between points of very different magnitudes: the
// edge vectors of P are rounded differences (inexact), exactly parallel to each other and to
// Q's edge direction (−1, −3), while their roundings are not. Every decision at M is an exact
// zero that only the exact predicate gets right.
TEST(NfpCandidates, InexactEdgeVectors) {
  std::mt19937_64 rng(2718);
  std::uniform_real_distribution<double> U(0.5, 1);
  auto bits51 = [](double x) { return std::ldexp(std::floor(std::ldexp(x, 51 - std::ilogb(x))), std::ilogb(x) - 51); };  // 3x exact
  int inexact = 0;
  for (int it = 0; it < pendepth_test::scaled(500); ++it) {
    const double r1 = bits51(U(rng) * 1e-3), r2 = bits51(U(rng) * 3), R = bits51(U(rng) * 1e4);
    const int turn = int(rng() % 4);
    auto rot = [&](Vec2 p) {
      for (int k = 0; k < turn; ++k) p = Vec2(-p.y(), p.x());
      return p;
    };
    const Polygon P = Polygon::simple(std::vector<Vec2>{rot({-r1, -3 * r1}), rot({r2, 3 * r2}), rot({R, 3 * R}), rot({-R, 3 * R})}, "P");
    const Polygon Q = Polygon::simple(std::vector<Vec2>{rot({1, 3}), rot({0, 0}), rot({2, 0})}, "Q");
    inexact += mpq_class(r2 + r1) != mpq_class(r2) + mpq_class(r1) || mpq_class(3 * r2 + 3 * r1) != mpq_class(3 * r2) + mpq_class(3 * r1);
    const std::string tag = " " + std::to_string(it);
    same_candidates(P, Q, "inexact" + tag);
    same_candidates(Q, P, "inexact swapped" + tag);
    same_candidates(P, P, "inexact self" + tag);
  }
  std::cout << "[nfp candidates] " << inexact << " straight vertices between inexact edge vectors\n";
  EXPECT_GT(inexact, pendepth_test::scaled(500) / 2);
}

TEST(NfpCandidates, NestingInstances) {
  for (const char* name : {"albano", "shirts", "trousers"}) {
    const auto polys = nonconvex2_test::instance(std::string(name) + ".json");
    ASSERT_FALSE(polys.empty()) << name;
    for (const Polygon& P : polys)
      for (const Polygon& Q : polys) same_candidates(P, Q, P.name() + " / " + Q.name());
  }
  std::cout << "[nfp candidates] " << total_candidates() << " candidates identical to the rational enumeration\n";
}

// The previous BoxTree builder, verbatim in substance: index array, key table, nth_element.
nc::BoxTree reference_tree(const std::vector<nc::Tri>& tris) {
  nc::BoxTree T;
  if (tris.empty()) return T;
  std::vector<std::uint32_t> idx(tris.size());
  std::iota(idx.begin(), idx.end(), 0u);
  std::vector<std::array<double, 2>> key(tris.size());
  for (std::size_t k = 0; k < tris.size(); ++k) key[k] = {tris[k].lo.x() + tris[k].hi.x(), tris[k].lo.y() + tris[k].hi.y()};
  struct Job {
    std::int32_t node;
    std::size_t b, e;
  };
  T.nodes.push_back({});
  std::vector<Job> jobs{{0, 0, tris.size()}};
  while (!jobs.empty()) {
    Job J = jobs.back();
    jobs.pop_back();
    Vec2 lo = tris[idx[J.b]].lo, hi = tris[idx[J.b]].hi;
    for (std::size_t k = J.b + 1; k < J.e; ++k) {
      lo = lo.cwiseMin(tris[idx[k]].lo);
      hi = hi.cwiseMax(tris[idx[k]].hi);
    }
    T.nodes[J.node].lo = lo;
    T.nodes[J.node].hi = hi;
    if (J.e - J.b == 1) {
      T.nodes[J.node].tri = idx[J.b];
      continue;
    }
    const int axis = (hi.x() - lo.x()) >= (hi.y() - lo.y()) ? 0 : 1;
    const std::size_t mid = (J.b + J.e) / 2;
    std::nth_element(idx.begin() + J.b, idx.begin() + mid, idx.begin() + J.e,
                     [&](std::uint32_t a, std::uint32_t b) { return key[a][axis] < key[b][axis]; });
    const auto l = static_cast<std::int32_t>(T.nodes.size());
    T.nodes.push_back({});
    T.nodes.push_back({});
    T.nodes[J.node].left = l;
    T.nodes[J.node].right = l + 1;
    jobs.push_back({l, J.b, mid});
    jobs.push_back({l + 1, mid, J.e});
  }
  return T;
}

// Every node's box is exactly the union of its leaves' boxes; each leaf appears once.
void check_tree(const nc::BoxTree& T, const std::vector<nc::Tri>& tris, const std::string& what) {
  ASSERT_EQ(T.nodes.size(), tris.empty() ? 0 : 2 * tris.size() - 1) << what;
  std::vector<int> seen(tris.size(), 0);
  for (std::size_t k = T.nodes.size(); k-- > 0;) {
    const auto& N = T.nodes[k];
    if (N.left < 0) {
      ASSERT_LT(N.tri, tris.size()) << what;
      ++seen[N.tri];
      ASSERT_TRUE(N.lo == tris[N.tri].lo && N.hi == tris[N.tri].hi) << what;
    } else {
      const auto &L = T.nodes[N.left], &R = T.nodes[N.right];
      ASSERT_TRUE(N.lo == L.lo.cwiseMin(R.lo) && N.hi == L.hi.cwiseMax(R.hi)) << what << " node " << k;
    }
  }
  for (int s : seen) ASSERT_EQ(s, 1) << what;
}

TEST(BoxTree, SameTreeAsReference) {
  std::mt19937_64 rng(31337);
  std::size_t trees = 0;
  for (int it = 0; it < pendepth_test::scaled(3000); ++it) {
    const std::size_t s = it < 40 ? std::size_t(it) : 1 + rng() % (it % 10 == 0 ? 2000 : 70);
    const int span = 1 + int(rng() % (it % 3 == 0 ? 4 : 1000));  // small spans: many equal keys
    std::vector<nc::Tri> tris(s);
    for (auto& t : tris) {
      const Vec2 a(double(rng() % span), double(rng() % span)), b(double(rng() % span), double(rng() % span));
      t.lo = a.cwiseMin(b);
      t.hi = a.cwiseMax(b);
    }
    const std::string what = "boxes " + std::to_string(it) + " (" + std::to_string(s) + ")";
    nc::BoxTree got;
    got.nodes.resize(3);  // a reused tree must be rebuilt from scratch
    got.build(tris);
    const nc::BoxTree ref = reference_tree(tris);
    ASSERT_EQ(got.nodes.size(), ref.nodes.size()) << what;
    for (std::size_t k = 0; k < ref.nodes.size(); ++k) {
      const auto &a = got.nodes[k], &b = ref.nodes[k];
      ASSERT_TRUE(a.lo == b.lo && a.hi == b.hi && a.left == b.left && a.right == b.right && a.tri == b.tri) << what << " node " << k;
    }
    check_tree(got, tris, what);
    nc::BoxTree via;
    via.build_boxes(
        s, [&](std::size_t k) -> const Vec2& { return tris[k].lo; }, [&](std::size_t k) -> const Vec2& { return tris[k].hi; });
    ASSERT_EQ(via.nodes.size(), got.nodes.size()) << what;
    for (std::size_t k = 0; k < via.nodes.size(); ++k) ASSERT_TRUE(via.nodes[k].tri == got.nodes[k].tri && via.nodes[k].left == got.nodes[k].left) << what;
    ++trees;
  }
  std::cout << "[box tree] " << trees << " trees identical to the reference builder\n";
}

TEST(BoxTree, InOrderBuilder) {
  std::mt19937_64 rng(4242);
  nc::BoxTree got;
  got.nodes.resize(5);  // a reused tree must be rebuilt from scratch
  std::size_t trees = 0;
  for (int it = 0; it < pendepth_test::scaled(2000); ++it) {
    const std::size_t s = it < 70 ? std::size_t(it) : 1 + rng() % (it % 10 == 0 ? 1000 : 300);  // both sides of 256
    const int span = 1 + int(rng() % (it % 3 == 0 ? 4 : 1000));
    std::vector<nc::Tri> tris(s);
    for (auto& t : tris) {
      const Vec2 a(double(rng() % span), double(rng() % span)), b(double(rng() % span), double(rng() % span));
      t.lo = a.cwiseMin(b);
      t.hi = a.cwiseMax(b);
    }
    const std::string what = "in order " + std::to_string(it) + " (" + std::to_string(s) + ")";
    got.build_in_order(
        s, [&](std::size_t k) -> const Vec2& { return tris[k].lo; }, [&](std::size_t k) -> const Vec2& { return tris[k].hi; });
    check_tree(got, tris, what);
    if (s == 0) continue;
    // Depth first from the root, left child first: every node once, leaves in input order.
    std::vector<int> visits(got.nodes.size(), 0);
    std::vector<std::int32_t> stack{0};
    std::uint32_t expect = 0;
    while (!stack.empty()) {
      const std::int32_t k = stack.back();
      stack.pop_back();
      ASSERT_TRUE(k >= 0 && std::size_t(k) < got.nodes.size()) << what;
      ASSERT_EQ(++visits[k], 1) << what << " node " << k << " reached twice";
      const auto& N = got.nodes[k];
      if (N.left < 0) {
        ASSERT_EQ(N.tri, expect++) << what << ": leaves out of input order";
        continue;
      }
      stack.push_back(N.right);
      stack.push_back(N.left);
    }
    ASSERT_EQ(expect, s) << what;
    ++trees;
  }
  std::cout << "[box tree] " << trees << " in-order trees checked\n";
}

}  // namespace
