// Lower-dimensional shapes in Pair3 (points, segments, flat polygons against a solid; issue 16
// item 4; src/convex3/flat3.cpp) against the independent CGAL oracle of oracle3_cgal.hpp: the
// exact hull of the n·k differences p − q' (q' = R q + tq − tp exactly, `raw_q`: no hull of the
// lower-dimensional side), σ and σ_d and the signed distance and the cast correctly rounded.
//
// Checked per query: overlap and touching exactly as the oracle; σ, σ_d, signed distance and the
// cast's entry within 4 ulps; witnesses on the boundaries; both roles (the lower-dimensional shape
// as Q and as P: the swapped pair answers −d's problem and maps back); σ <= σ_d; moving Q by σ's
// translation leaves the pair touching (exact: signed distance 0 or a tiny residue); batch =
// single; errors (two lower-dimensional shapes, points spanning a solid) are InvalidInput.
#include <gtest/gtest.h>

#include <pendepth/pendepth.hpp>

#include "convex3/shapes3.hpp"
#include "oracle3/oracle3_cgal.hpp"
#include "test_scale.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include "test_ulps.hpp"
#include "test_rotations.hpp"

namespace pendepth {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

double ulps(double a, double b) { return pendepth_test::ulps_in_binade(a, b); }

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) { return pendepth_test::random_quaternion(rng); }

struct Stats {
  int overlapping = 0, touching = 0, apart = 0, hits = 0, casts = 0;
  double ulp_sigma = 0, ulp_dir = 0, ulp_sd = 0, ulp_cast = 0;
  void print(const char* what) const {
    std::printf("%-22s %4d overlapping, %4d touching, %4d apart | casts %4d (%4d hits) | max ulps: σ %.2f, "
                "σ_d %.2f, sd %.2f, cast %.2f\n",
                what, overlapping, touching, apart, casts, hits, ulp_sigma, ulp_dir, ulp_sd, ulp_cast);
  }
};

// One pose of a (solid S, lower-dimensional L) pair, checked in both roles.
void check(const std::vector<Vec3>& solid, const std::vector<Vec3>& low, const Pose3& ps, const Pose3& pl,
           const std::vector<Vec3>& dirs, Stats& st, const std::string& what) {
  const Shape3 S = Shape3::hull(solid, "S"), L = Shape3::flat(low, "L");
  const oracle3::ExactHull hs(solid);
  // The exact gap of a world point to ∂S (S's frame).
  auto gap_s = [&](const Vec3& w) { return std::abs(hs.gap(ps.matrix().transpose() * (w - ps.translation))); };
  const Eigen::Matrix3d Rs = ps.matrix(), Rl = pl.matrix();
  const oracle3::ExactDifference M(solid, low, Rs.transpose() * Rl, Rs.transpose() * pl.translation,
                                   Rs.transpose() * ps.translation, true);
  const double o_sd = M.signed_distance();
  const oracle3::Answer o_sigma = M.sigma();
  if (o_sd < 0) ++st.overlapping;
  else if (o_sd == 0) ++st.touching;
  else ++st.apart;
  const double scale = 2 + ps.translation.norm() + pl.translation.norm();
  for (int swap = 0; swap < 2; ++swap) {
    const std::string w = what + (swap ? " (L as P)" : " (L as Q)");
    const Pair3 pair = swap ? Pair3(L, S) : Pair3(S, L);
    const Pose3 &pp = swap ? pl : ps, &pq = swap ? ps : pl;
    const double sgn = swap ? -1 : 1;  // the swapped pair's M is −M: directions reverse
    // overlap and σ
    const Depth3 m = pair.minimum(pp, pq);
    ASSERT_EQ(m.overlapping, o_sigma.overlapping) << w;
    ASSERT_EQ(pair.overlapping(pp, pq), o_sigma.overlapping) << w;
    if (m.overlapping) {
      const double e = ulps(m.depth, o_sigma.depth);
      st.ulp_sigma = std::max(st.ulp_sigma, e);
      EXPECT_LE(e, 4) << w << ": σ " << m.depth << " exact " << o_sigma.depth;
      EXPECT_EQ(m.lower_bound, m.depth);
      EXPECT_EQ(m.upper_bound, m.depth);
      EXPECT_LE((m.translation - m.depth * m.normal).norm(), 8 * kEps * m.depth) << w;
      // Q moved by the translation touches P: the signed distance after the move is ~0.
      Pose3 moved = pq;
      moved.translation += m.translation;
      EXPECT_LE(std::abs(pair.signed_distance(pp, moved).distance), 1e-12 * scale) << w << ": not touching after σ";
      if (!swap) EXPECT_LE(gap_s(m.witness_p), 1e-12 * scale) << w << ": σ's contact off ∂S";
    } else {
      EXPECT_EQ(m.depth, 0) << w;
    }
    // σ_d
    for (const Vec3& d : dirs) {
      const Depth3 a = pair.along(pp, pq, d);
      const oracle3::Answer o = M.sigma_d(sgn * (Rs.transpose() * d));
      ASSERT_EQ(a.overlapping, o.overlapping) << w;
      if (!o.overlapping) {
        EXPECT_EQ(a.depth, 0) << w;
        continue;
      }
      const double e = ulps(a.depth, o.depth);
      st.ulp_dir = std::max(st.ulp_dir, e);
      EXPECT_LE(e, 4) << w << ": σ_d " << a.depth << " exact " << o.depth;
      EXPECT_LE(m.depth, a.depth * (1 + 8 * kEps)) << w << ": σ > σ_d";
      EXPECT_LE((a.translation - a.depth * d.normalized()).norm(), 8 * kEps * a.depth) << w;
      if (!swap) EXPECT_LE(gap_s(a.witness_p), 1e-12 * scale) << w << ": σ_d's contact off ∂S";
    }
    // signed distance
    const Distance3 sd = pair.signed_distance(pp, pq);
    EXPECT_EQ(sd.overlapping, o_sd < 0) << w;
    if (o_sd == 0) {
      EXPECT_EQ(sd.distance, 0) << w;
    } else {
      ASSERT_EQ(sd.distance > 0, o_sd > 0) << w << ": pendepth " << sd.distance << " exact " << o_sd;
      const double e = ulps(sd.distance, o_sd);
      st.ulp_sd = std::max(st.ulp_sd, e);
      EXPECT_LE(e, 4) << w << ": sd " << sd.distance << " exact " << o_sd;
      EXPECT_NEAR(sd.normal.norm(), 1, 8 * kEps) << w;
      EXPECT_LE((sd.translation + sd.distance * sd.normal).norm(), 8 * kEps * std::abs(sd.distance)) << w;
      EXPECT_LE((sd.witness_q - sd.witness_p - sd.distance * sd.normal).norm(), 1e-12 * scale) << w;
      // The witness on the solid lies on its boundary (unmoved for the signed distance).
      EXPECT_LE(gap_s(swap ? sd.witness_q : sd.witness_p), 1e-12 * scale) << w << ": witness off ∂S";
    }
    // cast
    for (const Vec3& d : dirs) {
      const Cast3 c = pair.cast(pp, pq, d);
      const oracle3::CastAnswer o = M.cast(sgn * (Rs.transpose() * d));
      EXPECT_EQ(c.lower_bound, c.distance) << w;  // exact: the bracket is the answer (+inf on a miss)
      EXPECT_EQ(c.upper_bound, c.distance) << w;
      ++st.casts;
      st.hits += o.hit;
      ASSERT_EQ(c.hit, o.hit) << w << " cast exact " << o.distance;
      if (!o.hit) {
        EXPECT_EQ(c.distance, std::numeric_limits<double>::infinity()) << w;
        continue;
      }
      const double e = ulps(c.distance, o.distance);
      st.ulp_cast = std::max(st.ulp_cast, e);
      EXPECT_LE(e, 4) << w << ": cast " << c.distance << " exact " << o.distance;
      EXPECT_EQ(c.overlapping, o_sd < 0) << w;
      if (c.distance > 0) {
        EXPECT_LE((c.translation - c.distance * d.normalized()).norm(), 8 * kEps * c.distance) << w;
        Pose3 moved = pq;
        moved.translation += c.translation;
        EXPECT_LE(std::abs(pair.signed_distance(pp, moved).distance), 1e-12 * scale) << w << ": not touching after cast";
        if (!swap) EXPECT_LE(gap_s(c.witness_p), 1e-12 * scale) << w << ": the cast's contact off ∂S";
      }
    }
  }
}

std::vector<Vec3> random_dirs(std::mt19937_64& rng, int k) {
  std::normal_distribution<double> g;
  std::vector<Vec3> d;
  while (static_cast<int>(d.size()) < k) d.emplace_back(g(rng), g(rng), g(rng));
  return d;
}

// k points of a convex polygon in the plane z = 0 (exactly coplanar), or fewer.
std::vector<Vec3> lower_shape(std::mt19937_64& rng, int k) {
  std::uniform_real_distribution<double> U(-0.7, 0.7), A(0, 2 * M_PI);
  if (k == 1) return {Vec3(U(rng), U(rng), U(rng))};
  if (k == 2) return {Vec3(U(rng), U(rng), U(rng)), Vec3(U(rng), U(rng), U(rng))};
  std::vector<double> ang(k);
  for (auto& a : ang) a = A(rng);
  std::sort(ang.begin(), ang.end());
  std::vector<Vec3> p;
  for (double a : ang) p.emplace_back(0.6 * std::cos(a), 0.4 * std::sin(a), 0.25);
  return p;
}

TEST(Flat3Oracle, RandomPointsSegmentsPolygons) {
  std::mt19937_64 rng(1611);
  std::uniform_real_distribution<double> U(-1, 1);
  Stats st;
  for (int k : {1, 2, 3, 5, 8}) {
    for (int r = 0; r < pendepth_test::scaled(3); ++r) {
      const std::vector<Vec3> solid = test3::random_ball(rng, 6 + 4 * r);
      const std::vector<Vec3> low = lower_shape(rng, k);
      for (int j = 0; j < 4; ++j) {
        const Pose3 ps = j % 2 ? Pose3(random_rotation(rng), 0.3 * Vec3(U(rng), U(rng), U(rng))) : Pose3();
        const Pose3 pl(random_rotation(rng), (0.2 + 0.6 * j) * Vec3(U(rng), U(rng), U(rng)));
        check(solid, low, ps, pl, random_dirs(rng, 3), st, "k=" + std::to_string(k) + " r=" + std::to_string(r));
      }
    }
  }
  st.print("random");
  const int drawn = pendepth_test::scaled(3);  // shapes per k (fewer in sanitized Debug builds)
  EXPECT_GT(st.overlapping, 2 * drawn);
  EXPECT_GT(st.apart, 4 * drawn);
  EXPECT_GT(st.hits, 10 * drawn);
}

std::vector<Vec3> box(Vec3 lo, Vec3 hi) {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  return p;
}

// Integer grids, identity and exact quarter-turn rotations: points on faces, edges and vertices,
// segments in face planes and along edges, squares flush with faces — touching exactly.
TEST(Flat3Oracle, DegenerateGrids) {
  Stats st;
  const std::vector<Vec3> cube = box(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  const std::vector<std::vector<Vec3>> lows = {
      {Vec3(0, 0, 0)},
      {Vec3(0, 0, 0), Vec3(1, 0, 0)},
      {Vec3(0, -1, 0), Vec3(0, 1, 0)},
      {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)},
      {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(0, 0, 0)},  // inner point dropped
      {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 0, 2)},
  };
  const std::vector<Vec3> dirs = {{1, 0, 0}, {0, 0, -1}, {1, 1, 0}, {-1, 2, 3}};
  const Eigen::Quaterniond rots[] = {Eigen::Quaterniond(1, 0, 0, 0), Eigen::Quaterniond(0.5, 0.5, 0.5, 0.5),
                                     Eigen::Quaterniond(0, 0, 0, 1)};
  for (const auto& low : lows)
    for (const auto& rot : rots)
      for (double x : {-2.0, -1.0, 0.5})
        for (double y : {-1.0, 0.0})
          for (double z : {-2.0, -1.0, 0.0, 1.0, 2.0})
            check(cube, low, Pose3(), Pose3(rot, Vec3(x, y, z)), dirs, st,
                  "grid " + std::to_string(low.size()) + " at " + std::to_string(x) + "," + std::to_string(y) + "," +
                      std::to_string(z));
  st.print("degenerate grids");
  EXPECT_GT(st.touching, 20);
  EXPECT_GT(st.overlapping, 20);
}

TEST(Flat3, ShapesAndErrors) {
  const Shape3 p = Shape3::point(Vec3(1, 2, 3));
  EXPECT_EQ(p.dimension(), 0);
  EXPECT_EQ(p.size(), 1u);
  const Shape3 s = Shape3::segment(Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_EQ(s.dimension(), 1);
  const std::vector<Vec3> col = {Vec3(0, 0, 0), Vec3(2, 2, 2), Vec3(1, 1, 1), Vec3(-1, -1, -1)};
  const Shape3 c = Shape3::flat(col, "collinear");
  EXPECT_EQ(c.dimension(), 1);
  ASSERT_EQ(c.flat_vertices().size(), 2u);
  EXPECT_EQ(c.flat_vertices()[0], Vec3(-1, -1, -1));
  EXPECT_EQ(c.flat_vertices()[1], Vec3(2, 2, 2));
  const std::vector<Vec3> sq = {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0.5, 0.5, 1), Vec3(1, 1, 1), Vec3(0, 1, 1),
                                Vec3(0.5, 0, 1)};
  const Shape3 f = Shape3::flat(sq, "square");
  EXPECT_EQ(f.dimension(), 2);
  EXPECT_EQ(f.flat_vertices().size(), 4u);  // interior and edge points dropped
  EXPECT_EQ(Shape3::hull(box(Vec3(0, 0, 0), Vec3(1, 1, 1))).dimension(), 3);
  EXPECT_TRUE(f.flat_vertices().size() && Shape3::hull(box(Vec3(0, 0, 0), Vec3(1, 1, 1))).flat_vertices().empty());
  EXPECT_THROW(f.polytope(), InvalidInput);
  EXPECT_THROW(Shape3::segment(Vec3(1, 1, 1), Vec3(1, 1, 1)), InvalidInput);
  EXPECT_THROW(Shape3::flat(box(Vec3(0, 0, 0), Vec3(1, 1, 1))), InvalidInput);
  EXPECT_THROW(Shape3::flat(std::vector<Vec3>{}), InvalidInput);
  EXPECT_THROW(Shape3::point(Vec3(0, NAN, 0)), InvalidInput);
  try {
    Pair3 bad(p, f);
    FAIL() << "two lower-dimensional shapes accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("lower-dimensional"), std::string::npos) << e.what();
  }
  // A point Q gives the signed distance field of P (the unit cube at the origin).
  const Pair3 field(Shape3::hull(box(Vec3(-1, -1, -1), Vec3(1, 1, 1))), Shape3::point(Vec3(0, 0, 0)));
  EXPECT_EQ(field.signed_distance(Pose3(), Pose3(Vec3(0.25, 0, 0))).distance, -0.75);
  EXPECT_EQ(field.signed_distance(Pose3(), Pose3(Vec3(4, 0, 0))).distance, 3);
  EXPECT_EQ(field.signed_distance(Pose3(), Pose3(Vec3(4, 5, 1))).distance, 5);
  EXPECT_EQ(field.signed_distance(Pose3(), Pose3(Vec3(1, 0.5, 0))).distance, 0);
  EXPECT_EQ(field.minimum(Pose3(), Pose3(Vec3(0.25, 0.5, 0))).depth, 0.5);
  EXPECT_EQ(field.along(Pose3(), Pose3(Vec3(0.25, 0.5, 0)), Vec3(-1, 0, 0)).depth, 1.25);
  EXPECT_EQ(field.cast(Pose3(), Pose3(Vec3(5, 0.5, 0)), Vec3(-2, 0, 0)).distance, 4);
}

// Batches answer as singles, bit for bit; the numeric domain scales lower-dimensional shapes.
TEST(Flat3, BatchAndScale) {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> U(-1, 1);
  const std::vector<Vec3> solid = test3::random_ball(rng, 20);
  const std::vector<Vec3> low = lower_shape(rng, 4);
  for (double sc : {1.0, 0x1p-200, 0x1p150}) {
    std::vector<Vec3> a = solid, b = low;
    for (auto& x : a) x *= sc;
    for (auto& x : b) x *= sc;
    const Pair3 pair(Shape3::hull(a), Shape3::flat(b));
    const Pair3 unit(Shape3::hull(solid), Shape3::flat(low));
    std::vector<Pose3> poses;
    for (int i = 0; i < 40; ++i) poses.emplace_back(random_rotation(rng), 0.8 * sc * Vec3(U(rng), U(rng), U(rng)));
    std::vector<Depth3> out(poses.size());
    std::vector<Distance3> dout(poses.size());
    pair.minimum(poses, out, 2);
    pair.signed_distance(poses, dout, 2);
    for (std::size_t i = 0; i < poses.size(); ++i) {
      const Depth3 s = pair.minimum(Pose3(), poses[i]);
      EXPECT_EQ(out[i].depth, s.depth);
      EXPECT_EQ(out[i].translation, s.translation);
      EXPECT_EQ(dout[i].distance, pair.signed_distance(Pose3(), poses[i]).distance);
      // Scaling by a power of two is exact: the same bits as at unit size, scaled.
      const Pose3 pu(poses[i].rotation, poses[i].translation / sc);
      EXPECT_EQ(s.depth, sc * unit.minimum(Pose3(), pu).depth);
      EXPECT_EQ(dout[i].distance, sc * unit.signed_distance(Pose3(), pu).distance);
    }
  }
}

}  // namespace
}  // namespace pendepth

namespace pendepth {
namespace {

// Awkward inputs never crash, hang or return NaN: tiny segments next to large solids, points
// exactly on vertices and edges, nearly collinear polygons, far-away placements, both roles.
TEST(Flat3, AwkwardInputsStayFinite) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> U(-1, 1);
  const std::vector<Vec3> cube = {Vec3(-1, -1, -1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(1, 1, -1),
                                  Vec3(-1, -1, 1),  Vec3(1, -1, 1),  Vec3(-1, 1, 1),  Vec3(1, 1, 1)};
  const Shape3 S = Shape3::hull(cube, "cube");
  std::vector<Shape3> lows = {
      Shape3::point(Vec3(1, 1, 1)),
      Shape3::segment(Vec3(0, 0, 0), Vec3(1e-12, 0, 0)),
      Shape3::segment(Vec3(-1, -1, -1), Vec3(1, 1, 1)),
      Shape3::flat(std::vector<Vec3>{Vec3(0, 0, 0), Vec3(1, 1e-15, 0), Vec3(2, 0, 0)}),
      Shape3::flat(std::vector<Vec3>{Vec3(0, 0, 0), Vec3(1e6, 0, 0), Vec3(0, 1e6, 0), Vec3(1e6, 1e6, 0)}),
  };
  auto finite = [](const Vec3& v) { return v.allFinite(); };
  for (const Shape3& L : lows)
    for (int swap = 0; swap < 2; ++swap) {
      const Pair3 pair = swap ? Pair3(L, S) : Pair3(S, L);
      for (int k = 0; k < 40; ++k) {
        const double far = k % 4 == 3 ? 1e8 : 1.5;
        const Pose3 pq(Eigen::Quaterniond(U(rng), U(rng), U(rng), U(rng)), far * Vec3(U(rng), U(rng), U(rng)));
        const Vec3 d(U(rng), U(rng), U(rng));
        const Depth3 m = pair.minimum(Pose3(), pq), a = pair.along(Pose3(), pq, d);
        const Distance3 s = pair.signed_distance(Pose3(), pq);
        const Cast3 c = pair.cast(Pose3(), pq, d);
        ASSERT_TRUE(std::isfinite(m.depth) && finite(m.translation) && finite(m.witness_p)) << L.name();
        ASSERT_TRUE(std::isfinite(a.depth) && finite(a.translation) && finite(a.witness_p)) << L.name();
        ASSERT_TRUE(std::isfinite(s.distance) && finite(s.normal) && finite(s.witness_p) && finite(s.witness_q)) << L.name();
        ASSERT_TRUE(!std::isnan(c.distance) && finite(c.normal) && finite(c.witness_p)) << L.name();
        EXPECT_EQ(m.overlapping, s.distance < 0) << L.name();
        EXPECT_LE(m.depth, a.depth * (1 + 1e-15) + 1e-300) << L.name();
      }
    }
}

}  // namespace
}  // namespace pendepth
