// Issue 19 item 2, every engine of Pair2: a Shape2's per-shape work (its triangulated sides in
// roles P and −Q, its triangulation for polygon × convex, its edge tree for the signed distance
// and cast, and its copies scaled into the numeric domain) is made once per shape and shared by
// every pair built from it. The answers must be bit for bit those of a fresh build, whatever
// pair filled the caches, in whatever order, on whatever thread:
//   - fresh, by the engine: PairDepth2 / PolygonDepth2 on the bare polygons (their own
//     triangulations, no cache) for overlap, σ, σ_d and separation;
//   - fresh, by the front door: Pair2 on brand-new Shape2 copies (cold caches) for every query
//     kind (overlap, σ, σ_d, separation, signed distance, cast), scaled pairs included;
//   - shared: all ordered pairs of one set of Shape2 objects, built in reverse order by two
//     threads (cold), then again in forward order (warm), including each shape against itself
//     (its P and −Q sides from the same cache), rotated copies, a polygon with a hole × convex
//     (both ways round), and huge shapes whose pairs are scaled by different powers of two.
#include <pendepth/depth2_polygon_convex.hpp>
#include <pendepth/depth2_polygon_polygon.hpp>
#include <pendepth/motion.hpp>
#include <pendepth/nesting.hpp>
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <mutex>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "front/common.hpp"
#include "front/shape2_data.hpp"

namespace {

using namespace pendepth;
using front_test::same;
using front_test::same_bits;
using front_test::same_bits_v;

::testing::AssertionResult same_d(const Distance2& a, const Distance2& b) {
  if (same_bits(a.distance, b.distance) && same_bits_v(a.translation, b.translation) && same_bits_v(a.normal, b.normal) &&
      same_bits_v(a.witness_p, b.witness_p) && same_bits_v(a.witness_q, b.witness_q) && a.feature_p == b.feature_p &&
      a.feature_q == b.feature_q && a.overlapping == b.overlapping)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "distance " << a.distance << " vs " << b.distance;
}

::testing::AssertionResult same_c(const Cast2& a, const Cast2& b) {
  if (same_bits(a.distance, b.distance) && same_bits_v(a.translation, b.translation) && same_bits_v(a.normal, b.normal) &&
      same_bits_v(a.witness_p, b.witness_p) && same_bits_v(a.witness_q, b.witness_q) && a.feature_p == b.feature_p &&
      a.feature_q == b.feature_q && a.hit == b.hit && a.overlapping == b.overlapping)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "cast " << a.distance << " vs " << b.distance;
}

std::string instance(const std::string& name) { return std::string(PENDEPTH_SHARED_DATA) + "/nesting/" + name + ".json"; }

// A brand-new Shape2 with the same rings (nothing cached).
Shape2 fresh_copy(const Shape2& s) {
  if (s.is_convex()) return Shape2(ConvexPolygon(s.convex()));
  return Shape2(Polygon(s.polygon()));
}

Shape2 scaled(const Shape2& s, double f) {
  auto rings = s.rings();
  for (auto& r : rings)
    for (Vec2& v : r) v *= f;
  std::vector<std::vector<Vec2>> holes(rings.begin() + 1, rings.end());
  return Shape2(rings[0], holes, s.name());
}

// The answers of one pair at its placements (deterministic in the pair's index and sizes).
struct Answers {
  std::vector<bool> overlap;
  std::vector<Depth2> sigma, along, sep;
  std::vector<Distance2> dist;
  std::vector<Cast2> cast;
};

struct Probe {
  std::vector<Vec2> ts, ds;
};

double extent(const Shape2& s) {
  double e = 0;
  for (const auto& r : s.rings())
    for (const Vec2& v : r) e = std::max({e, std::abs(v.x()), std::abs(v.y())});
  return e;
}

Probe probe(const Shape2& P, const Shape2& Q, std::size_t k) {
  std::mt19937_64 rng(1000 + k);
  const double span = 0.75 * (extent(P) + extent(Q));
  std::uniform_real_distribution<double> u(-span, span), a(0, 6.283185307179586);
  Probe p;
  p.ts.push_back(Vec2(0, 0));
  for (int i = 0; i < 4; ++i) p.ts.push_back(Vec2(u(rng), u(rng)));
  for (std::size_t i = 0; i < p.ts.size(); ++i) {
    const double th = a(rng);
    p.ds.push_back(Vec2(std::cos(th), std::sin(th)));
  }
  return p;
}

Answers ask(const Pair2& pair, const Probe& p) {
  Answers r;
  for (std::size_t i = 0; i < p.ts.size(); ++i) {
    const Vec2 &t = p.ts[i], &d = p.ds[i];
    r.overlap.push_back(pair.overlapping(t));
    r.sigma.push_back(pair.minimum(t));
    r.along.push_back(pair.along(t, d));
    r.sep.push_back(pair.separation(t, d));
    r.dist.push_back(pair.signed_distance(t));
    r.cast.push_back(pair.cast(t, d));
  }
  return r;
}

void expect_same(const Answers& a, const Answers& b, const std::string& what) {
  ASSERT_EQ(a.sigma.size(), b.sigma.size()) << what;
  for (std::size_t i = 0; i < a.sigma.size(); ++i) {
    EXPECT_EQ(a.overlap[i], b.overlap[i]) << what << " placement " << i;
    EXPECT_TRUE(same(a.sigma[i], b.sigma[i])) << what << " σ, placement " << i;
    EXPECT_TRUE(same(a.along[i], b.along[i])) << what << " σ_d, placement " << i;
    EXPECT_TRUE(same(a.sep[i], b.sep[i])) << what << " separation, placement " << i;
    EXPECT_TRUE(same_d(a.dist[i], b.dist[i])) << what << " signed distance, placement " << i;
    EXPECT_TRUE(same_c(a.cast[i], b.cast[i])) << what << " cast, placement " << i;
  }
}

// The shapes: nesting pieces (albano, shirts), rotated copies (exact and rounded), a polygon with
// a hole, a convex hexagon and a convex nesting piece if any.
std::vector<Shape2> nesting_shapes() {
  std::vector<Shape2> s;
  const NestingInstance albano = read_nesting_instance(instance("albano"));
  const NestingInstance shirts = read_nesting_instance(instance("shirts"));
  for (std::size_t k = 0; k < 4 && k < albano.items.size(); ++k) s.push_back(albano.items[k].shape);
  for (std::size_t k = 0; k < 3 && k < shirts.items.size(); ++k) s.push_back(shirts.items[k].shape);
  s.push_back(s[0].rotated(90));
  s.push_back(s[4].rotated(45));
  s.push_back(Shape2({{0, 0}, {40, 0}, {40, 30}, {0, 30}}, {{{10, 10}, {10, 20}, {25, 20}, {25, 10}}}, "frame"));
  s.push_back(Shape2({{0, -6}, {5, -3}, {5, 3}, {0, 6}, {-5, 3}, {-5, -3}}, {}, "hexagon"));
  return s;
}

// All ordered pairs of `shapes` with `prep`: shared (reverse order on two threads, then forward
// again warm) against fresh Pair2s on new copies, and against the engines on bare polygons.
void check_all_pairs(const std::vector<Shape2>& shapes, Prepare prep, bool engine_oracle, std::size_t& scaled_pairs,
                     std::set<Engine2>& engines) {
  const std::size_t n = shapes.size(), N = n * n;
  std::vector<Probe> probes(N);
  std::vector<Answers> fresh(N);
  for (std::size_t k = 0; k < N; ++k) {
    const Shape2 &P = shapes[k / n], &Q = shapes[k % n];
    probes[k] = probe(P, Q, k);
    const Pair2 f(fresh_copy(P), fresh_copy(Q), prep);
    fresh[k] = ask(f, probes[k]);
  }
  // Shared, cold: reverse pair order, two threads interleaved (thread r takes k ≡ r mod 2).
  std::vector<Answers> cold(N);
  std::vector<std::thread> threads;
  for (int r = 0; r < 2; ++r)
    threads.emplace_back([&, r] {
      for (std::size_t k = N; k-- > 0;)
        if (k % 2 == std::size_t(r)) cold[k] = ask(Pair2(shapes[k / n], shapes[k % n], prep), probes[k]);
    });
  for (auto& t : threads) t.join();
  for (std::size_t k = 0; k < N; ++k) {
    const std::string what = "pair " + std::to_string(k / n) + " × " + std::to_string(k % n);
    const Pair2 warm(shapes[k / n], shapes[k % n], prep);
    engines.insert(warm.engine());
    expect_same(cold[k], fresh[k], what + " (shared, cold, reverse, 2 threads)");
    expect_same(ask(warm, probes[k]), fresh[k], what + " (shared, warm, forward)");
    if (std::abs(extent(shapes[k / n])) > 1e20) ++scaled_pairs;
    if (!engine_oracle) continue;
    // The engines on the bare polygons (their own triangulations).
    const Shape2 &P = shapes[k / n], &Q = shapes[k % n];
    const Probe& p = probes[k];
    if (!P.is_convex() && !Q.is_convex()) {
      const PairDepth2 e(P.polygon(), Q.polygon());
      for (std::size_t i = 0; i < p.ts.size(); ++i) {
        EXPECT_EQ(e.overlapping(p.ts[i]), fresh[k].overlap[i]) << what;
        if (prep == Prepare::Queries) {  // PairPerQuery answers σ and σ_d with this engine
          EXPECT_TRUE(same(e.minimum(p.ts[i]), fresh[k].sigma[i])) << what << " engine σ " << i;
          EXPECT_TRUE(same(e.along(p.ts[i], p.ds[i]), fresh[k].along[i])) << what << " engine σ_d " << i;
        }
        EXPECT_TRUE(same(e.separation(p.ts[i], p.ds[i]), fresh[k].sep[i])) << what << " engine separation " << i;
      }
    } else if (!P.is_convex() && Q.is_convex()) {
      const PolygonDepth2 e(P.polygon(), Q.convex());
      for (std::size_t i = 0; i < p.ts.size(); ++i) {
        EXPECT_EQ(e.overlapping(p.ts[i]), fresh[k].overlap[i]) << what;
        EXPECT_TRUE(same(e.minimum(p.ts[i]), fresh[k].sigma[i])) << what << " engine σ " << i;
        EXPECT_TRUE(same(e.along(p.ts[i], p.ds[i]), fresh[k].along[i])) << what << " engine σ_d " << i;
        EXPECT_TRUE(same(e.separation(p.ts[i], p.ds[i]), fresh[k].sep[i])) << what << " engine separation " << i;
      }
    }
  }
}

TEST(SharedShapes2, EveryEngineAndQueryEqualsTheFreshBuildInAnyOrder) {
  std::size_t scaled_pairs = 0;
  std::set<Engine2> engines;
  // Queries: polygon × polygon on PairDepth2 (PairPerQuery), polygon × convex both ways, convex × convex.
  check_all_pairs(nesting_shapes(), Prepare::Queries, true, scaled_pairs, engines);
  // Full: polygon × polygon on the no-fit polygon (separation from the shared PairDepth2).
  check_all_pairs(nesting_shapes(), Prepare::Full, true, scaled_pairs, engines);
  EXPECT_EQ(scaled_pairs, 0u);
  EXPECT_EQ(engines, (std::set<Engine2>{Engine2::Convex, Engine2::PolygonConvex, Engine2::PolygonConvexSwapped,
                                        Engine2::PairPerQuery, Engine2::NoFitPolygon}));
}

TEST(SharedShapes2, ScaledPairsShareTheScaledCopyAndEqualTheFreshBuild) {
  // Huge copies: every pair leaves the comfort band and is scaled into engine coordinates; two
  // magnitudes, so one shape is scaled by different powers of two in different pairs.
  const std::vector<Shape2> base = nesting_shapes();
  std::vector<Shape2> huge;
  for (std::size_t k : {0u, 4u, 8u, 9u, 10u}) huge.push_back(scaled(base[k], 0x1p300));
  for (std::size_t k : {1u, 9u}) huge.push_back(scaled(base[k], 0x1p420));
  std::size_t scaled_pairs = 0;
  std::set<Engine2> engines;
  check_all_pairs(huge, Prepare::Queries, false, scaled_pairs, engines);
  check_all_pairs(huge, Prepare::Full, false, scaled_pairs, engines);
  EXPECT_EQ(engines, (std::set<Engine2>{Engine2::Convex, Engine2::PolygonConvex, Engine2::PolygonConvexSwapped,
                                        Engine2::PairPerQuery, Engine2::NoFitPolygon}));
  EXPECT_EQ(scaled_pairs, 2 * huge.size() * huge.size());
  // One shape is scaled by different powers of two by different partners (the exponent follows
  // the pair's largest coordinate): each huge shape holds one shared scaled copy per exponent its
  // pairs used (src/front/shape2_data.hpp), at most one per partner although 4 passes × 2
  // orders built each pair many times.
  for (std::size_t k = 0; k < huge.size(); ++k) {
    const auto& d = shape_data(huge[k]);
    std::lock_guard lock(d.scaled_mutex);
    EXPECT_GE(d.scaled.size(), 2u) << "shape " << k;             // scaled differently by different partners
    EXPECT_LE(d.scaled.size(), huge.size()) << "shape " << k;    // one copy per exponent, not per pair
  }
}

// generalized_depth (PD_g) takes the convex parts of a non-convex shape from the same per-shape
// cache (role P's side): the same bounds and motion as on fresh copies, with the shapes' caches
// already filled by pairs in both roles, and a shape against itself.
TEST(SharedShapes2, GeneralizedDepthUsesTheSharedConvexParts) {
  const std::vector<Shape2> shapes = nesting_shapes();
  for (std::size_t i : {0u, 4u})
    for (std::size_t j : {1u, 4u}) {
      (void)Pair2(shapes[j], shapes[i], Prepare::Full).minimum(Vec2(0, 0));  // fill both roles' caches
      GeneralizedOptions2 o;
      o.max_intervals = 16;
      ASSERT_FALSE(shapes[i].is_convex() && shapes[j].is_convex());  // the parts path
      // The first placement of a grid where the pair overlaps.
      const Probe p = probe(shapes[i], shapes[j], 7 * i + j);
      const Pair2 fresh_pair(fresh_copy(shapes[i]), fresh_copy(shapes[j]), Prepare::Queries);
      Vec2 t = p.ts[0];
      for (const Vec2& c : p.ts)
        if (fresh_pair.overlapping(c)) {
          t = c;
          break;
        }
      const GeneralizedDepth2 a = generalized_depth(shapes[i], shapes[j], t, o);
      const GeneralizedDepth2 b = generalized_depth(fresh_copy(shapes[i]), fresh_copy(shapes[j]), t, o);
      EXPECT_TRUE(a.overlapping) << i << ", " << j;
      EXPECT_TRUE(same_bits(a.depth, b.depth) && same_bits(a.lower_bound, b.lower_bound) &&
                  same_bits(a.upper_bound, b.upper_bound) && same_bits(a.angle, b.angle) &&
                  same_bits_v(a.translation, b.translation) && a.intervals == b.intervals)
          << i << ", " << j << ": " << a.lower_bound << " ≤ " << a.upper_bound << " vs " << b.lower_bound << " ≤ " << b.upper_bound;
    }
}

}  // namespace
