// PolygonDirectionSet (DHS §6, src/polygon2/fixed_directions.cpp): σ_d through the per-direction
// slab decomposition (persistent order) must equal PolygonDepth2::along bit for bit (every field of the result), on
// random polygons with holes (integer and real coordinates), combs whose pockets Q fits exactly
// (slits of ∂O), a frame with collinear vertices, and nesting pieces; placements random, on
// convolution vertices p − q, on edges of the R_i, on ends of ∂O's pieces, and on slab boundary
// lines (a piece end moved along d, exact on integer inputs); directions axis-parallel, random
// integer, parallel to P's and Q's edges (elements parallel to d have no u-extent), irrational.
// The reference along() is itself checked against the exact CGAL union in test_depth.cpp.
// Pinned seeds. Also: bad input errors, and the space per direction: linear in the pieces of ∂O on
// combs seen across their teeth (the slab method's quadratic case), with a stated constant.
#include <pendepth/depth2_polygon_convex.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "polygon2/fixed_directions_persistent.hpp"
#include "polygon2/query_impl.hpp"
#include "polygon2/union_boundary.hpp"
#include "shapes.hpp"
#include "test_scale.hpp"

namespace pendepth::polygon2 {
/// Test hook defined in src/polygon2/fixed_directions.cpp: queries deferred to PolygonDepth2::along.
std::size_t fixed_direction_fallbacks();
}  // namespace pendepth::polygon2

namespace {

using pendepth::ConvexPolygon;
using pendepth::Depth2;
using pendepth::Polygon;
using pendepth::PolygonDepth2;
using pendepth::PolygonDirectionSet;
using pendepth::Vec2;

struct Stats {
  std::size_t queries = 0, overlapping = 0, on_slab_lines = 0;
  std::size_t generic = 0, generic_fallbacks = 0;  // random real placements
  std::size_t fallbacks_before = pendepth::polygon2::fixed_direction_fallbacks();
  std::size_t fallbacks() const { return pendepth::polygon2::fixed_direction_fallbacks() - fallbacks_before; }
  double bytes_per_piece_direction = 0;  // summed over pairs
  std::size_t pairs = 0;
};

void expect_identical(const Depth2& a, const Depth2& b, const std::string& what) {
  ASSERT_EQ(a.overlapping, b.overlapping) << what;
  ASSERT_EQ(a.depth, b.depth) << what;
  ASSERT_EQ(a.translation, b.translation) << what;
  ASSERT_EQ(a.normal, b.normal) << what;
  ASSERT_EQ(a.witness_p, b.witness_p) << what;
  ASSERT_EQ(a.witness_q, b.witness_q) << what;
  ASSERT_EQ(a.feature_p, b.feature_p) << what;
  ASSERT_EQ(a.feature_q, b.feature_q) << what;
  ASSERT_EQ(a.kind, b.kind) << what;
}

ConvexPolygon random_convex(std::mt19937_64& rng, int m, double scale, bool grid) {
  for (;;) {
    auto pts = polygon2_test::star_ring(rng, m, Vec2(0, 0), scale / 2, scale, grid);
    try {
      return ConvexPolygon::hull(pts, "Q");
    } catch (const pendepth::InvalidInput&) {
    }
  }
}

void check_pair(const Polygon& P, const ConvexPolygon& Q, std::mt19937_64& rng, int random_queries, Stats& st,
                const std::string& what) {
  const PolygonDepth2 pd(P, Q);
  const auto& ub = pendepth::polygon_depth_impl(pd).U;

  std::vector<Vec2> ds{{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {std::sqrt(2.0), 1 / 3.0}};
  std::uniform_int_distribution<int> ud(-5, 5);
  for (int k = 0; k < 3; ++k) {
    Vec2 d(ud(rng), ud(rng));
    if (d != Vec2(0, 0)) ds.push_back(d);
    const std::size_t g = rng() % P.size();
    ds.push_back(P.vertices()[P.next(g)] - P.vertices()[g]);
    const std::size_t j = rng() % Q.size();
    ds.push_back(Q[(j + 1) % Q.size()] - Q[j]);
  }
  const PolygonDirectionSet set(pd, ds);
  ASSERT_EQ(set.size(), ds.size());
  for (std::size_t k = 0; k < ds.size(); ++k) ASSERT_EQ(set.direction(k), ds[k]);
  st.bytes_per_piece_direction += double(set.bytes()) / double(ub.pieces().size() * ds.size());
  ++st.pairs;

  Vec2 lo = P.vertices()[0], hi = lo;
  for (const Vec2& p : P.vertices()) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  Vec2 qlo = Q[0], qhi = Q[0];
  for (const Vec2& q : Q.vertices()) qlo = qlo.cwiseMin(q), qhi = qhi.cwiseMax(q);
  lo -= qhi;
  hi -= qlo;
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y());

  // special: a convolution vertex, a piece end, a point of an R_i edge, an integer point, or on a
  // line through one along d — the placements that land on slab lines; generic: the others.
  auto check = [&](const Vec2& t, std::size_t k, bool special) {
    const bool slab_line = special;
    const Depth2 want = pd.along(t, ds[k]);
    const std::size_t before = pendepth::polygon2::fixed_direction_fallbacks();
    const Depth2 got = set.along(t, k);
    if (!special) {
      ++st.generic;
      st.generic_fallbacks += pendepth::polygon2::fixed_direction_fallbacks() - before;
    }
    expect_identical(got, want, what + " t=(" + std::to_string(t.x()) + "," + std::to_string(t.y()) + ") d#" + std::to_string(k));
    ++st.queries;
    st.overlapping += want.overlapping;
    st.on_slab_lines += slab_line;
  };
  for (int q = 0; q < random_queries; ++q) {
    Vec2 t(ux(rng), uy(rng));
    if (q % 2) t = Vec2(std::round(t.x()), std::round(t.y()));
    const Vec2 pq = P.vertices()[rng() % P.size()] - Q[rng() % Q.size()];  // a vertex of some R_i
    const std::size_t g = rng() % P.size();
    const Vec2 on_edge = (P.vertices()[g] + P.vertices()[P.next(g)]) / 2 - Q[rng() % Q.size()];
    const std::size_t piece = rng() % ub.pieces().size();
    const Vec2 end = ub.start_point(piece);  // an end of a piece of ∂O (exact on integer inputs)
    for (std::size_t k = 0; k < ds.size(); ++k) {
      check(t, k, q % 2 == 1);  // rounded to integers: often on a slab line of integer inputs
      check(pq, k, true);
      check(on_edge, k, true);
      check(end, k, true);
      // On the slab boundary line through that end (and through p − q): moved along d.
      const double s = double(int(rng() % 9) - 4) / 2;
      check(end + s * ds[k], k, true);
      check(pq + s * ds[k], k, true);
    }
  }
}

TEST(PolygonDirectionSet, RandomPolygonsWithHoles) {
  std::mt19937_64 rng(60606);
  Stats st;
  for (int it = 0; it < pendepth_test::scaled(20); ++it) {
    const Polygon P = polygon2_test::random_polygon(rng, 6 + it % 23, it % 4, it % 2 == 0);
    const ConvexPolygon Q = random_convex(rng, 3 + it % 9, 5 + it % 30, it % 3 == 0);
    check_pair(P, Q, rng, 8, st, "random " + std::to_string(it));
  }
  std::printf("random: %zu queries (%zu overlapping, %zu special placements; deferred to along(): %zu in all, %zu of "
              "%zu generic), %.1f bytes per piece of ∂O per direction\n",
              st.queries, st.overlapping, st.on_slab_lines, st.fallbacks(), st.generic_fallbacks, st.generic,
              st.bytes_per_piece_direction / double(st.pairs));
  EXPECT_GT(st.overlapping, st.queries / 10);
  EXPECT_GT(st.fallbacks(), 0u);                       // exact slab-line placements happen ...
  EXPECT_LT(st.generic_fallbacks, st.generic / 20);    // ... but generic queries use the slabs
}

TEST(PolygonDirectionSet, CombsSlitsAndCollinearVertices) {
  std::mt19937_64 rng(777);
  Stats st;
  const Polygon comb = Polygon::simple(polygon2_test::comb_ring(4, 2, 3, 10, 2));
  check_pair(comb, ConvexPolygon{{0, 0}, {3, 0}, {3, 3}, {0, 3}}, rng, 20, st, "comb/exact square");
  check_pair(comb, ConvexPolygon{{0, 0}, {3, 0}, {1.5, 2}}, rng, 10, st, "comb/triangle");
  check_pair(comb, ConvexPolygon{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, rng, 10, st, "comb/small square");
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
  check_pair(framed, ConvexPolygon{{0, 0}, {3, 0}, {3, 3}, {0, 3}}, rng, 10, st, "frame/square");
  check_pair(framed, ConvexPolygon{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, rng, 10, st, "frame/hole-sized square");
  std::printf("degenerate: %zu queries (%zu overlapping, %zu special; deferred to along(): %zu in all, %zu of %zu "
              "generic)\n",
              st.queries, st.overlapping, st.on_slab_lines, st.fallbacks(), st.generic_fallbacks, st.generic);
  EXPECT_LT(st.generic_fallbacks, st.generic / 3);  // slits: ties deferred
  EXPECT_GT(st.overlapping, st.queries / 10);
}

TEST(PolygonDirectionSet, NestingPieces) {
  std::mt19937_64 rng(4711);
  Stats st;
  for (const char* f : {"albano.json", "shirts.json", "trousers.json"}) {
    const auto pieces = polygon2_test::nesting_pieces(f);
    for (std::size_t k = 0; k < pieces.size(); k += 2) {
      const Polygon P = Polygon::simple(pieces[k], f);
      const ConvexPolygon Q = ConvexPolygon::hull(pieces[(k + 1) % pieces.size()], f);
      check_pair(P, Q, rng, 4, st, std::string(f) + " #" + std::to_string(k));
    }
  }
  std::printf("nesting: %zu queries (%zu overlapping, %zu special; deferred to along(): %zu in all, %zu of %zu "
              "generic)\n",
              st.queries, st.overlapping, st.on_slab_lines, st.fallbacks(), st.generic_fallbacks, st.generic);
  EXPECT_LT(st.generic_fallbacks, st.generic / 20);
  EXPECT_GT(st.overlapping, 0u);
}

// Space per direction on a large star polygon and a comb seen along and across its teeth.
TEST(PolygonDirectionSet, SpacePerDirection) {
  std::mt19937_64 rng(99);
  const int n = pendepth_test::scaled(2000);
  const Polygon star = polygon2_test::random_polygon(rng, n, 0, false);
  const ConvexPolygon Q = random_convex(rng, 16, 6, false);
  const PolygonDepth2 pd(star, Q);
  const PolygonDirectionSet one(pd, {{1, 0}});
  const PolygonDirectionSet four(pd, {{1, 0}, {0, 1}, {1, 1}, {-2, 1}});
  std::printf("star n=%d: %zu bytes for 1 direction, %zu for 4; ∂O %zu bytes\n", n, one.bytes(), four.bytes(),
              pd.boundary_stats().bytes);
  EXPECT_LT(four.bytes(), 5 * one.bytes());
  for (int k = 0; k < 200; ++k) {
    const Vec2 t(double(rng() % 200) - 100, double(rng() % 200) - 100);
    for (std::size_t j = 0; j < four.size(); ++j) expect_identical(four.along(t, j), pd.along(t, four.direction(j)), "star");
  }
  const Polygon comb = Polygon::simple(polygon2_test::comb_ring(100, 1, 3, 20, 2));
  const PolygonDepth2 pc(comb, ConvexPolygon{{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  const PolygonDirectionSet along_teeth(pc, {{0, 1}}), across(pc, {{1, 0}});
  std::printf("comb of 100 teeth: %zu bytes along the teeth, %zu across\n", along_teeth.bytes(), across.bytes());
}

// The persistent sequence alone against snapshots of a std::set: random sweeps (each element
// inserted once, erased at most once, as in the slab sweep; versions without a commit, like thin
// slabs), small integer keys so ties fall to the id. Every version after finish() must list
// exactly its snapshot, and first_not_behind must return the first element ≥ a threshold and its
// successor. Nodes stay linear in the updates (expected O(1) copies per update, DSST).
TEST(PersistentOrder, MatchesSnapshotsOfASortedSet) {
  using pendepth::polygon2::PersistentOrder;
  std::mt19937_64 rng(2024);
  std::size_t worst_nodes = 0, worst_updates = 1;
  for (int run = 0; run < pendepth_test::scaled(40); ++run) {
    const std::uint32_t N = 1 + std::uint32_t(rng() % (run < 20 ? 40 : 3000));
    std::vector<int> key(N);
    for (auto& k : key) k = int(rng() % (1 + N / 4));
    auto less = [&](std::uint32_t a, std::uint32_t b) { return key[a] != key[b] ? key[a] < key[b] : a < b; };
    PersistentOrder order(N);
    std::set<std::uint32_t, decltype(less)> live(less);
    std::vector<std::vector<std::uint32_t>> snap;  // per version; empty and uncommitted alike
    std::vector<bool> committed;
    std::uint32_t next = 0;
    std::size_t updates = 0;
    for (std::uint32_t v = 0; next < N || !live.empty(); ++v) {
      order.begin(v);
      std::vector<std::uint32_t> out;
      for (std::uint32_t x : live)
        if (rng() % 4 == 0) out.push_back(x);
      for (std::uint32_t x : out) order.erase(x), live.erase(x), ++updates;
      for (std::uint32_t k = std::uint32_t(rng() % 6); k > 0 && next < N; --k, ++next) {
        ASSERT_FALSE(order.contains(next));
        order.insert(next, less), live.insert(next), ++updates;
        ASSERT_TRUE(order.contains(next));
      }
      const bool commit = rng() % 8 != 0;
      if (commit) order.commit();
      snap.emplace_back(commit ? std::vector<std::uint32_t>(live.begin(), live.end()) : std::vector<std::uint32_t>{});
      committed.push_back(commit);
    }
    order.finish();
    for (std::uint32_t v = 0; v < snap.size(); ++v) {
      ASSERT_EQ(order.elements(v), snap[v]) << "run " << run << " version " << v;
      for (int q = 0; q < 4; ++q) {
        const int threshold = int(rng() % (N / 4 + 3)) - 1;
        const auto [first, after] =
            order.first_not_behind(v, [&](std::uint32_t e) { return key[e] < threshold; });
        auto it = std::find_if(snap[v].begin(), snap[v].end(), [&](std::uint32_t e) { return key[e] >= threshold; });
        const std::uint32_t want_first = it == snap[v].end() ? PersistentOrder::kNil : *it;
        const std::uint32_t want_after =
            it == snap[v].end() || it + 1 == snap[v].end() ? PersistentOrder::kNil : *(it + 1);
        ASSERT_EQ(first, want_first) << "run " << run << " version " << v << " threshold " << threshold;
        ASSERT_EQ(after, want_after) << "run " << run << " version " << v << " threshold " << threshold;
      }
    }
    if (double(order.node_count()) / double(updates) > double(worst_nodes) / double(worst_updates))
      worst_nodes = order.node_count(), worst_updates = updates;
    EXPECT_LE(order.node_count(), 3 * updates) << "run " << run;
  }
  std::printf("persistent order: at most %.2f nodes per update\n", double(worst_nodes) / double(worst_updates));
}

// The old worst case of the slab method: a comb seen across its teeth, tilted so that every
// tooth corner is its own key and a line parallel to d crosses many teeth (the sorted lists per
// slab took Θ(n²) space: 8.2 MB at n = 10⁴). The persistent order keeps bytes() per direction
// linear: at most kBytesPerPiece bytes per piece of ∂O, for n = 10² … 10⁴ (a bound of the
// structure: per sub-piece 20 bytes + 8 of key ends + ~2 slabs of 4 bytes + expected ~2.4 treap
// nodes of 20 bytes; measured ≤ 102). Queries on those combs equal along() bit for bit.
TEST(PolygonDirectionSet, LinearSpaceOnCombsAcrossTheTeeth) {
  constexpr double kBytesPerPiece = 200;
  std::mt19937_64 rng(31337);
  const std::vector<Vec2> ds{{1, 0.01}, {1, -0.003}, {100, 1}, {1, 0}, {0, 1}, {std::sqrt(2.0), 1 / 3.0}};
  double worst = 0;
  for (int n : {100, 1000, pendepth_test::scaled(10000)}) {
    const Polygon comb = Polygon::simple(polygon2_test::comb_ring(n / 4, 1, 3, 20, 2));
    const PolygonDepth2 pc(comb, ConvexPolygon{{0, 0}, {2, 0}, {2, 2}, {0, 2}});
    const auto stats = pc.boundary_stats();
    const double pieces = double(stats.segments + stats.arcs);
    std::printf("comb n=%d (%.0f pieces of ∂O), bytes per direction (per piece):", n, pieces);
    for (std::size_t k = 0; k < ds.size(); ++k) {
      const PolygonDirectionSet one(pc, {ds[k]});
      const double per_piece = double(one.bytes()) / pieces;
      std::printf(" %zu (%.0f)", one.bytes(), per_piece);
      worst = std::max(worst, per_piece);
      EXPECT_LE(per_piece, kBytesPerPiece) << "n=" << n << " d#" << k;
    }
    std::printf("\n");
    const PolygonDirectionSet set(pc, ds);
    const double W = double(n / 4) * 4;
    std::uniform_real_distribution<double> ux(-3, W + 3), uy(-3, 25);
    std::size_t overlapping = 0, queries = pendepth_test::scaled(300);
    for (std::size_t q = 0; q < queries; ++q) {
      Vec2 t(ux(rng), uy(rng));
      if (q % 3 == 0) t = Vec2(std::round(t.x()), std::round(t.y()));  // on slab lines of the axis directions
      for (std::size_t k = 0; k < ds.size(); ++k) {
        const Depth2 want = pc.along(t, ds[k]);
        expect_identical(set.along(t, k), want, "comb n=" + std::to_string(n) + " d#" + std::to_string(k));
        overlapping += want.overlapping;
      }
    }
    EXPECT_GT(overlapping, queries * ds.size() / 10) << n;
  }
  std::printf("largest: %.0f bytes per piece (bound %.0f)\n", worst, kBytesPerPiece);
}

// The set refers to the PolygonDepth2's heap state, so moving the PolygonDepth2 keeps it valid.
TEST(PolygonDirectionSet, SurvivesMovingThePolygonDepth) {
  PolygonDepth2 pd(Polygon::simple(polygon2_test::comb_ring(4, 2, 3, 10, 2)), ConvexPolygon{{0, 0}, {3, 0}, {1.5, 2}});
  const PolygonDirectionSet set(pd, {{0, 1}, {1, 0}, {1, -2}});
  const PolygonDepth2 moved(std::move(pd));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-5, 20);
  for (int k = 0; k < 300; ++k) {
    const Vec2 t(u(rng), u(rng));
    for (std::size_t j = 0; j < set.size(); ++j) expect_identical(set.along(t, j), moved.along(t, set.direction(j)), "moved");
  }
}

TEST(PolygonDirectionSet, BadInput) {
  const PolygonDepth2 pd(Polygon::simple(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 4}, {0, 4}}), ConvexPolygon{{0, 0}, {1, 0}, {0, 1}});
  auto message = [&](std::vector<Vec2> ds) {
    try {
      PolygonDirectionSet s(pd, std::move(ds));
    } catch (const pendepth::InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({{1, 0}, {0, 0}}), "direction 1 is the zero vector");
  EXPECT_EQ(message({{NAN, 0}}), "direction 0 has a non-finite coordinate");
  EXPECT_EQ(message({{1, 0}, {1, 1}, {0, INFINITY}}), "direction 2 has a non-finite coordinate");
  const PolygonDirectionSet s(pd, {{1, 0}});
  EXPECT_THROW(s.along({1, 1}, 1), pendepth::InvalidInput);
  EXPECT_THROW(s.along({NAN, 1}, 0), pendepth::InvalidInput);
  EXPECT_THROW(s.along({1, INFINITY}, 0), pendepth::InvalidInput);
  // Huge and tiny directions: the same answer as along() (σ_d = 3, analytic, to a few ulps).
  const PolygonDirectionSet scaled(pd, {{1e300, 0}, {1e-310, 0}, {1, 0}, {-1e-310, 1e-310}});
  for (std::size_t k = 0; k < scaled.size(); ++k) {
    expect_identical(scaled.along({1, 1}, k), pd.along({1, 1}, scaled.direction(k)), "scaled " + std::to_string(k));
    EXPECT_NEAR(scaled.along({1, 1}, k).depth, k == 3 ? 2 * std::sqrt(2.0) : 3.0, 1e-15) << k;
  }
  const PolygonDirectionSet empty(pd, {});
  EXPECT_EQ(empty.size(), 0u);
}

}  // namespace
