// Front door, lean σ / σ_d (issue 19 item 1): Pair2::depth_value / directional_depth_value give
// the depth, translation and overlap of Pair2::minimum / along bit for bit, on every engine
// (the no-fit polygon's own lean query on nesting pieces, the full answer's fields elsewhere),
// through the numeric-domain scaling (a pair at 2^998), and reject the same bad input with the
// same message (bad placements and directions; placements outside a scaled pair's domain).
// Placements: ring vertices of the no-fit polygon with ±1 ulp moves (on ∂O, where
// the fast path defers) and random ones; directions along the axes, towards
// ring vertices and random. Pinned seeds.
#include <pendepth/nfp2.hpp>
#include <pendepth/nesting.hpp>
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "front/common.hpp"

namespace {

using namespace pendepth;
using front_test::error_of;
using front_test::same_bits;
using front_test::same_bits_v;

::testing::AssertionResult same_value(const DepthValue2& a, const Depth2& b) {
  if (same_bits(a.depth, b.depth) && same_bits_v(a.translation, b.translation) && a.overlapping == b.overlapping)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "lean " << a.depth << " (" << a.translation.transpose() << ") vs full " << b.depth
                                       << " (" << b.translation.transpose() << ")";
}

Vec2 ulps(const Vec2& v, int dx, int dy) {
  auto step = [](double x, int k) { return k == 0 ? x : std::nextafter(x, k > 0 ? INFINITY : -INFINITY); };
  return Vec2(step(v.x(), dx), step(v.y(), dy));
}

// Lean against full at placements around the pair's no-fit polygon; returns the overlapping count.
std::size_t check_pair(const Pair2& pair, const std::vector<Vec2>& verts, std::mt19937_64& rng, const std::string& what) {
  Vec2 lo = verts[0], hi = verts[0];
  for (const Vec2& v : verts) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y()), ua(0, 2 * M_PI);
  std::vector<Vec2> ts;
  for (std::size_t i = 0; i < verts.size(); i += std::max<std::size_t>(1, verts.size() / 12))
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) ts.push_back(ulps(verts[i], dx, dy));
  for (int k = 0; k < 40; ++k) ts.emplace_back(ux(rng), uy(rng));
  std::size_t overlapping = 0;
  for (const Vec2& t : ts) {
    // Placements the pair's domain rejects (a subnormal coordinate at a large scale): the same error.
    const std::string e = error_of([&] { pair.minimum(t); });
    if (e != "(no error)") {
      EXPECT_EQ(error_of([&] { pair.depth_value(t); }), e) << what;
      EXPECT_EQ(error_of([&] { pair.directional_depth_value(t, Vec2(1, 0)); }), error_of([&] { pair.along(t, Vec2(1, 0)); })) << what;
      continue;
    }
    const Depth2 full = pair.minimum(t);
    overlapping += full.overlapping;
    EXPECT_TRUE(same_value(pair.depth_value(t), full)) << what << " σ at " << t.transpose();
    const double a = ua(rng);
    for (const Vec2& d : {Vec2(1, 0), Vec2(0, -1), Vec2(-3, 2), Vec2(std::cos(a), std::sin(a)), Vec2(verts[rng() % verts.size()] - t)}) {
      if (d.x() == 0 && d.y() == 0) continue;
      EXPECT_TRUE(same_value(pair.directional_depth_value(t, d), pair.along(t, d))) << what << " σ_d at " << t.transpose() << " d " << d.transpose();
    }
  }
  return overlapping;
}

std::vector<Vec2> nfp_vertices(const Shape2& P, const Shape2& Q) {
  std::vector<Vec2> v;
  for (const auto& poly : no_fit_polygon(P, Q).polygons)
    for (const auto& ring : poly) v.insert(v.end(), ring.begin(), ring.end());
  return v;
}

TEST(DepthValue2, NestingPiecesOnTheNoFitPolygonEngine) {
  std::mt19937_64 rng(1901);
  const NestingInstance inst = read_nesting_instance(std::string(PENDEPTH_SHARED_DATA) + "/nesting/albano.json");
  std::size_t pairs = 0, overlapping = 0;
  for (std::size_t i = 0; i < inst.items.size(); i += 2)
    for (std::size_t j = 1; j < inst.items.size(); j += 2) {
      const Pair2 pair(inst.items[i].shape, inst.items[j].shape, Prepare::Full);
      if (pair.engine() != Engine2::NoFitPolygon) continue;
      ++pairs;
      overlapping += check_pair(pair, nfp_vertices(inst.items[i].shape, inst.items[j].shape), rng, "albano " + std::to_string(i) + " " + std::to_string(j));
    }
  EXPECT_GT(pairs, 3u);
  EXPECT_GT(overlapping, 10 * pairs);
}

TEST(DepthValue2, OtherEnginesAndTheScaledDomain) {
  std::mt19937_64 rng(1902);
  const std::vector<Vec2> square{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, tri{{0, 0}, {3, 0}, {1, 2}};
  const std::vector<Vec2> L{{0, 0}, {5, 0}, {5, 1}, {1, 1}, {1, 4}, {0, 4}}, U{{0, 0}, {7, 0}, {7, 8}, {5, 8}, {5, 2}, {2, 2}, {2, 8}, {0, 8}};
  auto scaled = [](std::vector<Vec2> r, double s) {
    for (Vec2& p : r) p *= s;
    return r;
  };
  std::size_t engines_seen = 0;
  for (double s : {1.0, std::ldexp(1.0, 998), std::ldexp(1.0, -990)})
    for (const auto& [p, q] : {std::pair{square, tri}, std::pair{L, tri}, std::pair{tri, L}, std::pair{U, L}, std::pair{L, U}}) {
      const Shape2 P(scaled(p, s)), Q(scaled(q, s));
      for (Prepare prep : {Prepare::Auto, Prepare::Queries, Prepare::Full}) {
        const Pair2 pair(P, Q, prep);
        ++engines_seen;
        check_pair(pair, nfp_vertices(P, Q), rng, "engine " + std::to_string(int(pair.engine())) + " scale " + std::to_string(std::log2(s)));
      }
    }
  EXPECT_EQ(engines_seen, 45u);
}

TEST(DepthValue2, BadInputTheSameErrors) {
  const Pair2 pair(Shape2(std::vector<Vec2>{{0, 0}, {5, 0}, {5, 1}, {1, 1}, {1, 4}, {0, 4}}),
                   Shape2(std::vector<Vec2>{{0, 0}, {7, 0}, {7, 8}, {5, 8}, {5, 2}, {2, 2}, {2, 8}, {0, 8}}), Prepare::Full);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const Vec2& t : {Vec2(nan, 0), Vec2(0, inf)}) {
    const std::string e = error_of([&] { pair.minimum(t); });
    EXPECT_NE(e, "(no error)");
    EXPECT_EQ(error_of([&] { pair.depth_value(t); }), e);
    EXPECT_EQ(error_of([&] { pair.directional_depth_value(t, Vec2(1, 0)); }), error_of([&] { pair.along(t, Vec2(1, 0)); }));
  }
  for (const Vec2& d : {Vec2(0, 0), Vec2(nan, 1), Vec2(inf, 0)}) {
    const std::string e = error_of([&] { pair.along(Vec2(1, 1), d); });
    EXPECT_NE(e, "(no error)");
    EXPECT_EQ(error_of([&] { pair.directional_depth_value(Vec2(1, 1), d); }), e);
  }
}

}  // namespace
