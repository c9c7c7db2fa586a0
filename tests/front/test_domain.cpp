// The front door's numeric domain (src/front/scale.hpp, docs/robustness.md): every finite input
// is answered exactly — the same bits as the same pair at unit size, scaled by the power of two —
// or rejected with an error naming the value and the supported range; never NaN, never a silent
// error, an explicit infinity only where the true value overflows. Regression tests for every
// numeric finding of the robustness issue.
#include <pendepth/io.hpp>
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "convex3/shapes3.hpp"
#include "front/common.hpp"

namespace {

using namespace pendepth;
using front_test::error_of;
using front_test::same_bits;
using Rings = std::vector<std::vector<Vec2>>;
using namespace pendepth::test3;

Rings scaled(Rings r, double s) {
  for (auto& ring : r)
    for (Vec2& v : ring) v *= s;
  return r;
}

Shape2 make(const Rings& r) { return Shape2(r[0], Rings(r.begin() + 1, r.end())); }

const Rings kSquare43{{{0, 0}, {4, 0}, {4, 3}, {0, 3}}};
const Rings kBar{{{0, 0}, {3, 0}, {3, 1}, {0, 1}}};
const Rings kL{{{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 5}, {0, 5}}};
const Rings kPlate{{{0, 0}, {8, 0}, {8, 6}, {0, 6}}, {{2, 2}, {2, 4}, {6, 4}, {6, 2}}};
const Rings kOctagon{{{2, 0}, {4, 0}, {6, 2}, {6, 4}, {4, 6}, {2, 6}, {0, 4}, {0, 2}}};

bool finite(const Depth2& r) {
  return std::isfinite(r.depth) && r.translation.allFinite() && r.normal.allFinite() && r.witness_p.allFinite() &&
         r.witness_q.allFinite();
}

// r_big must be r_unit scaled by 2^k bit for bit (lengths and points), with the same normal,
// features and overlap decision.
::testing::AssertionResult scaled_same(const Depth2& r_unit, const Depth2& r_big, int k) {
  auto s = [k](double x) { return std::ldexp(x, k); };
  auto sv = [&](const Vec2& v) { return Vec2(s(v.x()), s(v.y())); };
  const bool ok = same_bits(s(r_unit.depth), r_big.depth) && front_test::same_bits_v(sv(r_unit.translation), r_big.translation) &&
                  front_test::same_bits_v(r_unit.normal, r_big.normal) &&
                  front_test::same_bits_v(sv(r_unit.witness_p), r_big.witness_p) &&
                  front_test::same_bits_v(sv(r_unit.witness_q), r_big.witness_q) &&
                  r_unit.feature_p == r_big.feature_p && r_unit.feature_q == r_big.feature_q &&
                  r_unit.overlapping == r_big.overlapping;
  if (ok) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "2^" << k << ": depth " << r_big.depth << " vs " << s(r_unit.depth)
                                       << ", translation (" << r_big.translation.transpose() << ") vs ("
                                       << sv(r_unit.translation).transpose() << ")";
}

// Every 2D engine, at sizes from 2^-900 to 2^1000: the answers of the unit-size pair, scaled.
TEST(Domain2, EveryEngineAnswersAtEveryScaleWithTheUnitSizeBits) {
  const std::vector<std::pair<Rings, Rings>> pairs{{kSquare43, kBar}, {kOctagon, kSquare43}, {kL, kBar},
                                                   {kBar, kL},        {kL, kL},               {kPlate, kBar},
                                                   {kPlate, kL}};
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> u(-64, 64);  // placements on a 1/8 grid: exact at every scale
  for (const auto& [p, q] : pairs)
    for (Prepare prep : {Prepare::Queries, Prepare::Full}) {
      const Pair2 unit(make(p), make(q), prep);
      for (int k : {-900, -600, -300, -120, 100, 300, 505, 700, 1000}) {
        const double s = std::ldexp(1.0, k);
        const Pair2 big(make(scaled(p, s)), make(scaled(q, s)), prep);
        ASSERT_EQ(unit.engine(), big.engine());
        for (int i = 0; i < 40; ++i) {
          const Vec2 t(u(rng) / 8.0, u(rng) / 8.0), d(u(rng) + 0.5, u(rng));
          const Vec2 ts = t * s;
          ASSERT_EQ(unit.overlapping(t), big.overlapping(ts));
          ASSERT_TRUE(scaled_same(unit.minimum(t), big.minimum(ts), k)) << "minimum t=" << t.transpose();
          ASSERT_TRUE(scaled_same(unit.along(t, d), big.along(ts, d), k)) << "along t=" << t.transpose();
          ASSERT_TRUE(scaled_same(unit.separation(t, d), big.separation(ts, d), k)) << "separation t=" << t.transpose();
        }
        // The no-fit polygon too, vertex for vertex.
        if (prep == Prepare::Full && !make(p).is_convex() && !make(q).is_convex()) {
          const auto& a = unit.no_fit_polygon();
          const auto& b = big.no_fit_polygon();
          ASSERT_EQ(a.polygons.size(), b.polygons.size());
          for (std::size_t i = 0; i < a.polygons.size(); ++i)
            for (std::size_t r = 0; r < a.polygons[i].size(); ++r)
              for (std::size_t v = 0; v < a.polygons[i][r].size(); ++v)
                ASSERT_TRUE(front_test::same_bits_v(Vec2(a.polygons[i][r][v] * s), b.polygons[i][r][v]));
        }
      }
    }
}

// Finding: `depth L.wkt max.wkt --offset=1,1` (a square with corners ±DBL_MAX) crashed in GMP
// (SIGFPE in mpq_set_d on an infinite difference). A pair that spans 2^1022 is now rejected
// with the range; the same square against itself is answered, with an explicit infinity.
TEST(Domain2, TheLargestSquareIsAnsweredOrRejectedNeverACrash) {
  const double M = std::numeric_limits<double>::max();
  const Rings max_square{{{-M, -M}, {M, -M}, {M, M}, {-M, M}}};
  const std::string e = error_of([&] { Pair2(make(kL), make(max_square)).minimum({1, 1}); });
  EXPECT_NE(e.find("orders of magnitude"), std::string::npos) << e;
  EXPECT_NE(e.find("at most 2^600"), std::string::npos) << e;
  EXPECT_NE(error_of([&] { Pair2(make(max_square), make(kL)).minimum({1, 1}); }), "(no error)");

  const Pair2 same(make(max_square), make(max_square));
  const Depth2 r = same.minimum({1, 1});  // true depth 2·DBL_MAX − 1: overflows
  EXPECT_TRUE(r.overlapping);
  EXPECT_EQ(r.depth, std::numeric_limits<double>::infinity());
  EXPECT_FALSE(std::isnan(r.translation.x()) || std::isnan(r.translation.y()));
  EXPECT_TRUE(r.normal.allFinite());
  EXPECT_TRUE(r.witness_p.allFinite() && r.witness_q.allFinite());
  const Depth2 a = same.along({1, 1}, {0, 1});  // 2·DBL_MAX − 1 along y: overflows as well
  EXPECT_EQ(a.depth, std::numeric_limits<double>::infinity());
  const Depth2 c = same.along({M, M}, {1, 0});  // a quarter overlaps: depth exactly DBL_MAX
  EXPECT_EQ(c.depth, M);
  EXPECT_TRUE(finite(c));
}

// Finding: a 1e300 square against itself gave depth inf and a NaN translation.
TEST(Domain2, HugeShapesGiveFiniteExactAnswers) {
  const Rings sq{{{0, 0}, {1e300, 0}, {1e300, 1e300}, {0, 1e300}}};
  for (Prepare prep : {Prepare::Queries, Prepare::Full}) {
    const Depth2 r = Pair2(make(sq), make(sq), prep).minimum({0, 0});
    EXPECT_EQ(r.depth, 1e300);
    EXPECT_TRUE(finite(r));
    EXPECT_EQ(r.translation.cwiseAbs().maxCoeff(), 1e300);  // (norm() would overflow)
  }
  // The L-shape and the plate with a hole at 2^1000 against a bar at 2^998 (gave translation 0).
  for (const Rings& p : {kL, kPlate}) {
    const double s = std::ldexp(1.0, 998);
    const Depth2 unit = Pair2(make(p), make(kBar)).minimum({1, 1.5});
    const Depth2 big = Pair2(make(scaled(p, 4 * s)), make(scaled(kBar, s))).minimum({s, 1.5 * s});
    const Depth2 mid = Pair2(make(scaled(p, 4)), make(kBar)).minimum({1, 1.5});
    EXPECT_TRUE(scaled_same(mid, big, 998));
    EXPECT_GT(unit.depth, 0);
    EXPECT_GT(big.translation.norm(), 0);
  }
}

// Finding: a 4s×3s rectangle against the 4×3 one at (1, 1) gave depth 0 with "overlapping" for
// s = 1e154 … 1e307. Within the supported ratio (2^600 ≈ 4e180) it is right; beyond, an error.
TEST(Domain2, AHugeShapeAgainstAUnitShapeIsRightOrRejected) {
  for (double s : {1e153, 1e154, 1e170, 1e180}) {
    const Depth2 r = Pair2(make(scaled(kSquare43, s)), make(kSquare43)).minimum({1, 1});
    EXPECT_TRUE(r.overlapping);
    EXPECT_EQ(r.depth, 4) << s;  // move Q down by 4 (the nearest side of the huge rectangle)
    EXPECT_EQ(r.translation, Vec2(0, -4)) << s;
  }
  for (double s : {1e200, 1e300, 1e307}) {
    const std::string e = error_of([&] { Pair2(make(scaled(kSquare43, s)), make(kSquare43)); });
    EXPECT_NE(e.find("orders of magnitude"), std::string::npos) << s << ": " << e;
  }
}

// Finding: a 5e-324 square against the 4×3 square at (1, 1) gave depth inf and "overlapping"
// although the shapes are apart. Against a shape of its own size it is answered exactly.
TEST(Domain2, SubnormalShapes) {
  const double e = 5e-324;
  const Rings tiny{{{0, 0}, {e, 0}, {e, e}, {0, e}}};
  const std::string msg = error_of([&] { Pair2(make(tiny), make(kSquare43)); });
  EXPECT_NE(msg.find("smallest edge 4.9406564584124654e-324"), std::string::npos) << msg;
  const Pair2 both(make(tiny), make(tiny));
  EXPECT_FALSE(both.overlapping({e, 0}));  // side by side: touching
  const Depth2 r = both.minimum({0, 0});
  EXPECT_TRUE(r.overlapping);
  EXPECT_EQ(r.depth, e);
  EXPECT_TRUE(finite(r));
  EXPECT_EQ(both.along({0, 0}, {1, 1}).depth, e);  // (e, e) rounds to the nearest double, e
}

// Placements must be exact at the pair's scale: a tiny offset next to huge shapes, or a huge one
// next to tiny shapes, is named with the range; a batch reports the index and writes nothing.
TEST(Domain2, PlacementsOutsideThePairsScaleAreNamed) {
  const double s = std::ldexp(1.0, 1000);
  const Pair2 big(make(scaled(kL, s)), make(scaled(kBar, s)));
  EXPECT_NO_THROW(big.minimum({s, 0}));
  EXPECT_NO_THROW(big.minimum({0, 0}));
  const std::string e = error_of([&] { big.minimum({1e-300, 0}); });
  EXPECT_NE(e.find("too small"), std::string::npos) << e;
  EXPECT_NE(e.find("(1e-300, 0)"), std::string::npos) << e;

  const double t = std::ldexp(1.0, -1000);
  const Pair2 small(make(scaled(kL, t)), make(scaled(kBar, t)));
  EXPECT_NO_THROW(small.minimum({1e-290, 0}));
  EXPECT_EQ(small.minimum({1e-290, -1e-290}).depth, 0);  // far apart (2^-1000 shapes): depth 0
  const std::string f = error_of([&] { small.minimum({1e10, 0}); });
  EXPECT_NE(f.find("too large"), std::string::npos) << f;

  std::vector<Vec2> ts{{s, 0}, {0, 0}, {1e-300, 0}};
  std::vector<Depth2> out(3);
  out[0].depth = 42;
  const std::string g = error_of([&] { big.minimum(ts, out); });
  EXPECT_NE(g.find("placement 2"), std::string::npos) << g;
  EXPECT_EQ(out[0].depth, 42);
}

// ---- 3D ----

Shape3 hull_scaled(const std::vector<Vec3>& pts, double s) {
  std::vector<Vec3> v = pts;
  for (Vec3& x : v) x *= s;
  return Shape3::hull(v);
}

std::vector<Vec3> box(double a, double b, double c) {
  std::vector<Vec3> v;
  for (double x : {-a, a})
    for (double y : {-b, b})
      for (double z : {-c, c}) v.emplace_back(x, y, z);
  return v;
}

bool finite(const Depth3& r) {
  return std::isfinite(r.depth) && std::isfinite(r.lower_bound) && std::isfinite(r.upper_bound) &&
         r.translation.allFinite() && r.normal.allFinite() && r.witness_p.allFinite() && r.witness_q.allFinite();
}

::testing::AssertionResult scaled_same(const Depth3& a, const Depth3& b, int k) {
  auto s = [k](double x) { return std::ldexp(x, k); };
  auto sv = [&](const Vec3& v) { return Vec3(s(v.x()), s(v.y()), s(v.z())); };
  const bool ok = same_bits(s(a.depth), b.depth) && same_bits(s(a.lower_bound), b.lower_bound) &&
                  same_bits(s(a.upper_bound), b.upper_bound) && front_test::same_bits_v(sv(a.translation), b.translation) &&
                  front_test::same_bits_v(a.normal, b.normal) && front_test::same_bits_v(sv(a.witness_p), b.witness_p) &&
                  front_test::same_bits_v(sv(a.witness_q), b.witness_q) && a.feature_p == b.feature_p &&
                  a.feature_q == b.feature_q && a.overlapping == b.overlapping;
  if (ok) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "2^" << k << ": depth " << b.depth << " vs " << s(a.depth) << " bounds "
                                       << b.lower_bound << " " << b.upper_bound << " vs " << s(a.lower_bound) << " "
                                       << s(a.upper_bound) << "\n translation " << b.translation.transpose() << " vs "
                                       << sv(a.translation).transpose() << "\n normal " << b.normal.transpose() << " vs "
                                       << a.normal.transpose() << "\n witness_p " << b.witness_p.transpose() << " vs "
                                       << sv(a.witness_p).transpose() << "\n witness_q " << b.witness_q.transpose()
                                       << " vs " << sv(a.witness_q).transpose();
}

// Finding: cubes scaled by 1e300 gave depth -nan and NaN bounds. Every scale now gives the
// unit-size bits, σ and σ_d, with rotations.
TEST(Domain3, EveryScaleGivesTheUnitSizeBits) {
  std::mt19937_64 rng(11);
  const std::vector<std::pair<std::vector<Vec3>, std::vector<Vec3>>> pairs{
      {box(1, 1, 1), box(2, 1, 0.5)}, {integer_sphere(27), bipyramid(25)}, {random_ball(rng, 30), prism(25)}};
  std::uniform_int_distribution<int> u(-16, 16);
  std::normal_distribution<double> g;
  for (const auto& [p, q] : pairs) {
    const Pair3 unit(Shape3::hull(p), Shape3::hull(q));
    for (int k : {-900, -400, -150, 120, 400, 1000}) {
      const double s = std::ldexp(1.0, k);
      const Pair3 big(hull_scaled(p, s), hull_scaled(q, s));
      for (int i = 0; i < 20; ++i) {
        const Vec3 t(u(rng) / 8.0, u(rng) / 8.0, u(rng) / 8.0), d(u(rng) + 0.5, u(rng), u(rng));
        Pose3 pose(t);
        if (i % 2) pose.rotation = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng));
        const Pose3 pose_big(pose.rotation, t * s);
        ASSERT_TRUE(scaled_same(unit.minimum(Pose3(), pose), big.minimum(Pose3(), pose_big), k));
        ASSERT_TRUE(scaled_same(unit.along(Pose3(), pose, d), big.along(Pose3(), pose_big, d), k));
      }
    }
  }
  const Depth3 r = Pair3(hull_scaled(box(1, 1, 1), 1e300), hull_scaled(box(1, 1, 1), 1e300))
                       .minimum(Pose3(), Pose3(Vec3(1e299, 0, 0)));
  EXPECT_TRUE(finite(r));
  EXPECT_EQ(r.depth, 1.9e300);
}

// Finding: a 1.7e308 cube as Q along z gave NaN witnesses. Against a unit cube the pair spans
// 2^1022 (rejected with the range); against itself the depth overflows: explicit infinity.
TEST(Domain3, TheLargestCubeIsAnsweredOrRejected) {
  const std::string e = error_of([&] { Pair3(hull_scaled(box(1, 1, 1), 1), hull_scaled(box(1, 1, 1), 1.7e308)); });
  EXPECT_NE(e.find("at most 2^280"), std::string::npos) << e;
  const Pair3 same(hull_scaled(box(1, 1, 1), 1.7e308), hull_scaled(box(1, 1, 1), 1.7e308));
  const Depth3 r = same.along(Pose3(), Pose3(Vec3(0, 0, 1)), {0, 0, 1});
  EXPECT_EQ(r.depth, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(r.normal.allFinite() && r.witness_p.allFinite() && r.witness_q.allFinite());
  EXPECT_FALSE(std::isnan(r.translation.z()));
  const Depth3 m = same.minimum(Pose3(), Pose3(Vec3(1.7e308, 0, 0)));  // half overlaps: 1.7e308
  EXPECT_NEAR(m.depth, 1.7e308, 1.7e308 * 1e-15);
  EXPECT_TRUE(finite(m));
}

// Fuzzing finding (tests/fuzz/findings/README.md): a hull mixing 0 and 1 with 1e-44 coordinates
// against itself got the right σ but a zero translation and normal (the facet normal cancelled in
// double-double). The move must now have the depth's length, and must separate.
TEST(Domain3, TinyDetailsOnAUnitHullKeepTheirNormal) {
  const Shape3 P = Shape3::from_file(std::string(PENDEPTH_SOURCE_DIR) +
                                     "/tests/fuzz/corpus/fuzz_shapes_raw/sigma3-tiny-coordinates-zero-translation.stl",
                                     "shape", /*hull=*/true);  // a triangle soup: its hull
  const Pair3 pair(P, P);
  const Pose3 q(Eigen::Quaterniond(-3, 4, 2, 2), Vec3(0.15151515151515138, 0.33712121212121238, 0.35984848484848486));
  const Depth3 r = pair.minimum(Pose3(), q);
  EXPECT_NEAR(r.depth, 0.82196969696969679, 1e-15);
  EXPECT_NEAR(r.translation.norm(), r.depth, 1e-15);
  EXPECT_NEAR(r.normal.norm(), 1, 1e-15);
  // Moved a little further than the answer, Q no longer overlaps; a little less, it still does.
  EXPECT_FALSE(pair.overlapping(Pose3(), Pose3(q.rotation, q.translation + r.translation * (1 + 1e-9))));
  EXPECT_TRUE(pair.overlapping(Pose3(), Pose3(q.rotation, q.translation + r.translation * (1 - 1e-9))));
  // The same at scales the domain moves into the engines' band, and for the raw engine.
  for (int k : {-500, 300}) {
    const Pair3 s(Shape3(P.polytope().scaled(k)), Shape3(P.polytope().scaled(k)));
    const Depth3 rs = s.minimum(Pose3(), Pose3(q.rotation, q.translation * std::ldexp(1.0, k)));
    EXPECT_NEAR(std::ldexp(rs.translation.norm(), -k), r.depth, 1e-15) << k;
  }
  EXPECT_NEAR(minimum_depth(P.polytope(), Pose3(), P.polytope(), q).translation.norm(), r.depth, 1e-15);
  // σ_d's exit facet has such a normal too.
  for (const Vec3& d : {Vec3(0, 1, 0), Vec3(1, 2, -3), Vec3(0.1, 0.9, -0.2)}) {
    const Depth3 a = pair.along(Pose3(), q, d);
    ASSERT_TRUE(a.overlapping);
    EXPECT_NEAR(a.facet_normal.norm(), 1, 1e-15) << d.transpose();
    EXPECT_GT(a.facet_normal.dot(d), 0) << d.transpose();  // the ray leaves through that facet
    EXPECT_GE(a.depth, r.depth * (1 - 1e-15));            // σ ≤ σ_d
  }
}

// A pose translation that has no exact value at the pair's scale is named; batches check first.
TEST(Domain3, PoseTranslationsOutsideThePairsScaleAreNamed) {
  const Pair3 big(hull_scaled(box(1, 1, 1), 1e300), hull_scaled(box(1, 2, 3), 1e300));
  const std::string e = error_of([&] { big.minimum(Pose3(), Pose3(Vec3(1e-300, 0, 0))); });
  EXPECT_NE(e.find("pose of Q translation"), std::string::npos) << e;
  EXPECT_NE(e.find("too small"), std::string::npos) << e;
  std::vector<Pose3> poses{Pose3(Vec3(1e299, 0, 0)), Pose3(Vec3(0, 1e-300, 0))};
  std::vector<Depth3> out(2);
  const std::string f = error_of([&] { big.minimum(poses, out); });
  EXPECT_NE(f.find("batch: pose 1"), std::string::npos) << f;
}

// JSON has no infinity: an overflowing answer is written as 1e999, which parsers read as one.
TEST(Domain, JsonWritesInfinityAsAValidNumber) {
  std::string s = "[";
  io::append_double(s, std::numeric_limits<double>::infinity());
  s += ",";
  io::append_double(s, -std::numeric_limits<double>::infinity());
  s += "]";
  EXPECT_EQ(s, "[1e999,-1e999]");
  // Python's json and JavaScript's JSON.parse read 1e999 as infinity; so does strtod.
  EXPECT_EQ(std::strtod("1e999", nullptr), std::numeric_limits<double>::infinity());
}

}  // namespace
