// Front door, 2D signed distance and shape cast (Pair2::signed_distance, Pair2::cast; issue 16
// items 2–3): properties on every engine — sd < 0 ⇔ overlapping, −sd = σ bit for bit, sd is
// 1-Lipschitz (continuous through contact), moving Q by `translation` touches, a cast's
// translation touches, a cast from the far side equals σ_d for convex pairs, the batch equals
// single calls bit for bit at any thread count, huge and tiny pairs give the unit-size bits,
// errors at the boundary. The exact values are checked against CGAL in
// tests/nonconvex2/test_boundary_distance.cpp.
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
using Rings = std::vector<std::vector<Vec2>>;

Shape2 make(const Rings& r) { return Shape2(r[0], Rings(r.begin() + 1, r.end())); }
Rings scaled(Rings r, double s) {
  for (auto& ring : r)
    for (Vec2& v : ring) v *= s;
  return r;
}

const Rings kSquare43{{{0, 0}, {4, 0}, {4, 3}, {0, 3}}};
const Rings kBar{{{0, 0}, {3, 0}, {3, 1}, {0, 1}}};
const Rings kL{{{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 5}, {0, 5}}};
const Rings kPlate{{{0, 0}, {8, 0}, {8, 6}, {0, 6}}, {{2, 2}, {2, 4}, {6, 4}, {6, 2}}};
const Rings kOctagon{{{2, 0}, {4, 0}, {6, 2}, {6, 4}, {4, 6}, {2, 6}, {0, 4}, {0, 2}}};
const Rings kTri{{{0, 0}, {1.5, 0.25}, {0.5, 1.75}}};

// (P, Q, prepare) covering every engine.
struct Case {
  Rings p, q;
  Prepare prep;
};
std::vector<Case> cases() {
  return {{kOctagon, kSquare43, Prepare::Queries}, {kOctagon, kTri, Prepare::Full}, {kL, kBar, Prepare::Auto},
          {kBar, kL, Prepare::Auto},               {kL, kL, Prepare::Queries},      {kL, kL, Prepare::Full},
          {kPlate, kTri, Prepare::Auto},           {kPlate, kL, Prepare::Full}};
}

::testing::AssertionResult same(const Distance2& a, const Distance2& b) {
  if (same_bits(a.distance, b.distance) && same_bits_v(a.translation, b.translation) && same_bits_v(a.normal, b.normal) &&
      same_bits_v(a.witness_p, b.witness_p) && same_bits_v(a.witness_q, b.witness_q) && a.feature_p == b.feature_p &&
      a.feature_q == b.feature_q && a.overlapping == b.overlapping)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "distance " << a.distance << " vs " << b.distance;
}

std::vector<Vec2> random_placements(std::mt19937_64& rng, int count, double span) {
  std::uniform_real_distribution<double> u(-span, span);
  std::vector<Vec2> ts;
  for (int k = 0; k < count; ++k) ts.emplace_back(u(rng), u(rng));
  return ts;
}

}  // namespace

TEST(Distance2, SignIsOverlapNegativeIsSigmaAndTranslationTouches) {
  std::mt19937_64 rng(11);
  int over = 0, apart = 0, touch = 0;
  for (const Case& c : cases()) {
    const Pair2 pair(make(c.p), make(c.q), c.prep);
    auto ts = random_placements(rng, 150, 9);
    const auto pr = make(c.p).rings(), qr = make(c.q).rings();
    for (const Vec2& v : pr[0]) ts.push_back(v - qr[0][rng() % qr[0].size()]);
    for (const Vec2& t : ts) {
      const Distance2 sd = pair.signed_distance(t);
      const bool o = pair.overlapping(t);
      ASSERT_EQ(sd.overlapping, o) << to_string(pair.engine()) << " t=" << t.transpose();
      ASSERT_EQ(sd.distance < 0, o);
      if (o) {
        ++over;
        const Depth2 s = pair.minimum(t);
        EXPECT_TRUE(same_bits(sd.distance, -s.depth));
        EXPECT_TRUE(same_bits_v(sd.translation, s.translation));
        EXPECT_TRUE(same_bits_v(sd.normal, s.normal));
      } else {
        sd.distance == 0 ? ++touch : ++apart;
      }
      // Moving Q by `translation` gives a touching placement (up to the rounding of t + translation).
      const Distance2 after = pair.signed_distance(t + sd.translation);
      EXPECT_LE(std::abs(after.distance), 1e-13 * (1 + t.norm())) << to_string(pair.engine()) << " t=" << t.transpose();
      EXPECT_NEAR((sd.witness_q - sd.witness_p - sd.distance * sd.normal).norm(), 0, 1e-13 * (1 + t.norm()));
    }
  }
  EXPECT_GT(over, 100);
  EXPECT_GT(apart, 100);
  EXPECT_GT(touch, 5);
}

// The signed distance is the signed distance to ∂M: 1-Lipschitz, so continuous through contact.
TEST(Distance2, ContinuousThroughContact) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> ang(0, 6.283185307179586);
  for (const Case& c : cases()) {
    const Pair2 pair(make(c.p), make(c.q), c.prep);
    for (int line = 0; line < 6; ++line) {
      const double a = ang(rng);
      const Vec2 dir(std::cos(a), std::sin(a));
      Vec2 prev = -12.0 * dir;
      double sd_prev = pair.signed_distance(prev).distance;
      int sign_changes = 0;
      for (int k = 1; k <= 600; ++k) {
        const Vec2 t = (-12.0 + k * 0.04) * dir;
        const double sd = pair.signed_distance(t).distance;
        EXPECT_LE(std::abs(sd - sd_prev), (t - prev).norm() * (1 + 1e-12) + 1e-14) << to_string(pair.engine());
        sign_changes += (sd < 0) != (sd_prev < 0);
        prev = t, sd_prev = sd;
      }
      EXPECT_GE(sign_changes, 2);  // the line enters and leaves M
    }
  }
}

TEST(Cast2, HitsTouchMissesAreInfiniteOverlapIsZero) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0, misses = 0;
  for (const Case& c : cases()) {
    const Pair2 pair(make(c.p), make(c.q), c.prep);
    for (const Vec2& t : random_placements(rng, 150, 12)) {
      const Vec2 d(u(rng), u(rng));
      const Cast2 r = pair.cast(t, d);
      const Distance2 sd = pair.signed_distance(t);
      if (sd.overlapping) {
        EXPECT_TRUE(r.hit && r.overlapping && r.distance == 0);
        continue;
      }
      if (!r.hit) {
        ++misses;
        EXPECT_EQ(r.distance, std::numeric_limits<double>::infinity());
        continue;
      }
      ++hits;
      EXPECT_GE(r.distance * (1 + 1e-15), sd.distance);  // no move shorter than the distance touches
      EXPECT_NEAR(r.translation.norm(), r.distance, 1e-14 * (1 + r.distance));
      EXPECT_LE(std::abs(pair.signed_distance(t + r.translation).distance), 1e-13 * (1 + t.norm()));
      EXPECT_NEAR(r.normal.norm(), 1, 1e-15);
      EXPECT_LE(r.normal.dot(d), 1e-15);  // entering M: against the outward normal
    }
  }
  EXPECT_GT(hits, 100);
  EXPECT_GT(misses, 100);
}

// A ray through a convex M enters where the reversed ray leaves: cast(t + L·x̂, −x̂) = L − σ_x̂(t).
TEST(Cast2, FromTheFarSideEqualsDirectionalDepthForConvexPairs) {
  std::mt19937_64 rng(14);
  std::uniform_int_distribution<int> u(-40, 40);
  const std::vector<std::pair<Rings, Rings>> pairs{{kOctagon, kSquare43}, {kOctagon, kTri}, {kTri, kSquare43}};
  int checked = 0;
  for (const auto& [p, q] : pairs) {
    const Pair2 pair(make(p), make(q));
    ASSERT_EQ(pair.engine(), Engine2::Convex);
    for (int k = 0; k < 200; ++k) {
      const Vec2 t(u(rng) / 8.0, u(rng) / 8.0);  // a grid: t + (64, 0) exact
      for (const Vec2& d : {Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0)}) {
        const Depth2 s = pair.along(t, d);
        if (!s.overlapping) continue;
        const Cast2 c = pair.cast(t + 64.0 * d, Vec2(0, 0) - d);
        ASSERT_TRUE(c.hit);
        EXPECT_NEAR(c.distance, 64 - s.depth, 64 * 0x1p-50) << "t=" << t.transpose();
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(Distance2, BatchEqualsSinglesBitForBitAtAnyThreadCount) {
  std::mt19937_64 rng(15);
  for (const Case& c : cases()) {
    const Pair2 pair(make(c.p), make(c.q), c.prep);
    const auto ts = random_placements(rng, 300, 10);
    std::vector<Distance2> single;
    for (const Vec2& t : ts) single.push_back(pair.signed_distance(t));
    for (unsigned threads : {1u, 2u, 8u, 0u}) {
      std::vector<Distance2> out(ts.size());
      pair.signed_distance(ts, out, threads);
      for (std::size_t i = 0; i < ts.size(); ++i) ASSERT_TRUE(same(single[i], out[i])) << "threads " << threads << " i " << i;
    }
  }
}

// Huge and tiny pairs are answered on scaled copies: the unit-size bits times 2^k.
TEST(Distance2, EveryScaleGivesTheUnitSizeBits) {
  std::mt19937_64 rng(16);
  std::uniform_int_distribution<int> u(-64, 64);
  for (const Case& c : cases()) {
    const Pair2 unit(make(c.p), make(c.q), c.prep);
    for (int k : {-900, -300, -120, 100, 300, 700, 1000}) {
      const double s = std::ldexp(1.0, k);
      auto sv = [&](const Vec2& v) { return Vec2(std::ldexp(v.x(), k), std::ldexp(v.y(), k)); };
      const Pair2 big(make(scaled(c.p, s)), make(scaled(c.q, s)), c.prep);
      for (int i = 0; i < 30; ++i) {
        const Vec2 t(u(rng) / 8.0, u(rng) / 8.0), d(u(rng) + 0.5, u(rng));
        const Distance2 a = unit.signed_distance(t), b = big.signed_distance(t * s);
        ASSERT_TRUE(same_bits(std::ldexp(a.distance, k), b.distance)) << k << " t=" << t.transpose();
        ASSERT_TRUE(same_bits_v(sv(a.translation), b.translation) && same_bits_v(a.normal, b.normal) &&
                    same_bits_v(sv(a.witness_p), b.witness_p) && same_bits_v(sv(a.witness_q), b.witness_q) &&
                    a.feature_p == b.feature_p && a.feature_q == b.feature_q);
        const Cast2 ca = unit.cast(t, d), cb = big.cast(t * s, d);
        ASSERT_TRUE(same_bits(std::ldexp(ca.distance, k), cb.distance)) << k << " t=" << t.transpose();
        ASSERT_TRUE(same_bits_v(sv(ca.translation), cb.translation) && same_bits_v(ca.normal, cb.normal) &&
                    same_bits_v(sv(ca.witness_p), cb.witness_p) && ca.hit == cb.hit && ca.feature_p == cb.feature_p);
      }
    }
  }
}

TEST(Distance2, BadInputIsNamed) {
  const Pair2 pair(make(kL), make(kBar));
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  EXPECT_NE(error_of([&] { pair.signed_distance(Vec2(nan, 0)); }), "(no error)");
  EXPECT_NE(error_of([&] { pair.cast(Vec2(inf, 0), Vec2(1, 0)); }), "(no error)");
  EXPECT_NE(error_of([&] { pair.cast(Vec2(0, 0), Vec2(0, 0)); }), "(no error)");
  EXPECT_NE(error_of([&] { pair.cast(Vec2(0, 0), Vec2(nan, 1)); }), "(no error)");
  std::vector<Vec2> ts{{0, 0}, {1, nan}};
  std::vector<Distance2> out(2);
  EXPECT_NE(error_of([&] { pair.signed_distance(ts, out); }).find("1"), std::string::npos);
  std::vector<Distance2> short_out(1);
  EXPECT_NE(error_of([&] { pair.signed_distance(std::span<const Vec2>(ts.data(), 1), std::span<Distance2>(short_out.data(), 0)); }),
            "(no error)");
}
