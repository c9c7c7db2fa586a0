// Generalized penetration depth PD_g (include/pendepth/motion.hpp, src/motion/).
//
// Oracles: brute force over rigid motions — a fine grid of angles, at each the exact σ of P and
// Q.rotated(θ) from a 5×5 grid of rotation centres over Q's box (a different, larger set of
// centres than the search's three), every motion verified separating by the exact overlap test
// and costed by displacement_upper. Properties: the theorem PD_g = σ for convex pairs (2D: no
// brute-force motion is cheaper than σ; 3D: random rotations with the best translation for each
// from Pair3's σ at the rotated pose), PD_g ≤ σ always, lower ≤ grid minimum (the grid's motions
// are real, so their minimum is an upper bound of PD_g), the reported motion separates and costs
// what is reported. Inputs: random convex pairs, L-shapes, combs, a peg in a slot (rotation helps
// a lot), nesting pieces. Pinned seeds.
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <numbers>
#include <random>

#include "motion_shapes.hpp"

namespace {

using namespace pendepth;
using namespace pendepth::motion_test;

constexpr double kPi = std::numbers::pi;

std::vector<Vec2> hull_vertices(const Shape2& Q) {
  const ConvexPolygon h = ConvexPolygon::hull(Q.rings().front());
  return {h.vertices().begin(), h.vertices().end()};
}

// Q's vertices rotated exactly as Shape2::rotated does (same formula, same bits).
// The cost of the motion (deg, v) on Q's coordinates as Shape2::rotated gives them.
double motion_cost(const Shape2& Q, double deg, const Vec2& v) {
  const auto h = hull_vertices(Q);
  std::vector<Vec2> rh(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) rh[i] = turned(h[i], deg);
  return displacement_upper(h.data(), rh.data(), h.size(), v);
}

// The cheapest verified motion over `angles`: at each, σ of the rotated Q about a 5×5 grid of
// centres over Q's box. Also reports the smallest cost at angle 0 and the count of motions.
struct Brute {
  double best = std::numeric_limits<double>::infinity();
  double best_angle = 0;
  std::size_t motions = 0;
};
Brute brute_force(const Shape2& P, const Shape2& Q, const Vec2& t, const std::vector<double>& angles) {
  Brute b;
  const auto h = hull_vertices(Q);
  Vec2 lo = h[0], hi = h[0];
  for (const Vec2& q : h) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  for (double deg : angles) {
    const Shape2 Qr = Q.rotated(deg);
    const Pair2 pair(P, Qr);
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j) {
        const Vec2 c(lo.x() + (hi.x() - lo.x()) * i / 4, lo.y() + (hi.y() - lo.y()) * j / 4);
        const Vec2 shift = c - turned(c, deg);
        const Depth2 d = pair.minimum(t + shift);
        for (double eps : {0.0, 0x1p-50, 0x1p-44, 0x1p-36}) {
          const Vec2 T = t + (shift + d.translation) * (1 + eps);
          if (pair.overlapping(T)) continue;
          const double cost = motion_cost(Q, deg, T - t);
          ++b.motions;
          if (cost < b.best) b.best = cost, b.best_angle = deg;
          break;
        }
      }
  }
  return b;
}

std::vector<double> grid(double lo, double hi, int n) {
  std::vector<double> a;
  for (int i = 0; i <= n; ++i) a.push_back(lo + (hi - lo) * i / n);
  return a;
}

// The contract of a result on an overlapping pair: bounds ordered, PD_g ≤ σ, the motion separates
// (exact test on the same rotated coordinates) and costs at most `depth`.
void check_result(const Shape2& P, const Shape2& Q, const Vec2& t, const GeneralizedDepth2& r) {
  const Depth2 s = Pair2(P, Q).minimum(t);
  ASSERT_TRUE(r.overlapping);
  EXPECT_EQ(r.sigma, s.depth);
  EXPECT_LE(r.lower_bound, r.upper_bound);
  EXPECT_EQ(r.depth, r.upper_bound);
  EXPECT_GT(r.lower_bound, 0);
  EXPECT_LE(r.depth, s.depth * (1 + 1e-12));
  const Shape2 Qr = Q.rotated(r.angle);
  EXPECT_FALSE(Pair2(P, Qr).overlapping(t + r.translation)) << "angle " << r.angle;
  EXPECT_LE(motion_cost(Q, r.angle, r.translation), r.depth * (1 + 1e-13));
  EXPECT_EQ(r.rotation_exact, Shape2::rotation_is_exact(r.angle));
  EXPECT_NEAR(r.sigma_at_angle, Pair2(P, Qr).minimum(t).depth, 1e-12 * (1 + s.depth));
  if (r.converged) EXPECT_LE(r.upper_bound - r.lower_bound, 1e-6 * r.upper_bound);
}

Shape2 random_convex(std::mt19937_64& rng, int n, double radius, std::string_view name) {
  std::uniform_real_distribution<double> a(0, 2 * kPi), rr(0.3, 1.0);
  std::vector<Vec2> pts;
  for (int i = 0; i < n; ++i) {
    const double th = a(rng), r = radius * rr(rng);
    pts.emplace_back(r * std::cos(th) + 0.3 * radius, r * std::sin(th) - 0.2 * radius);
  }
  return Shape2(ConvexPolygon::hull(pts, name));
}

// ---- the theorem in 2D --------------------------------------------------------------------------

TEST(Generalized2, ConvexPairsEqualSigmaAndNoMotionBeatsIt) {
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  int overlapping = 0;
  for (int k = 0; k < 24; ++k) {
    const Shape2 P = random_convex(rng, 5 + k % 9, 1.0, "P"), Q = random_convex(rng, 3 + k % 7, 0.7, "Q");
    const Vec2 t(u(rng), u(rng));
    const Depth2 s = Pair2(P, Q).minimum(t);
    const GeneralizedDepth2 r = generalized_depth(P, Q, t);
    EXPECT_EQ(r.depth, s.depth);
    EXPECT_EQ(r.lower_bound, s.depth);
    EXPECT_EQ(r.upper_bound, s.depth);
    EXPECT_EQ(r.angle, 0);
    if (!s.overlapping) {
      EXPECT_FALSE(r.overlapping);
      continue;
    }
    ++overlapping;
    // The theorem by brute force: no motion over a grid of angles (and centres) is cheaper.
    const Brute b = brute_force(P, Q, t, grid(-180, 180, 72));
    ASSERT_GT(b.motions, 0u);
    EXPECT_GE(b.best, s.depth * (1 - 1e-12) - 1e-14) << "pair " << k << " angle " << b.best_angle;
    // The search itself (the theorem's short cut off) finds nothing cheaper, and its parts bound
    // (the pair itself) closes the gap at once.
    GeneralizedOptions2 o;
    o.convex_theorem = false;
    const GeneralizedDepth2 g = generalized_depth(P, Q, t, o);
    check_result(P, Q, t, g);
    EXPECT_GE(g.depth, s.depth * (1 - 1e-12) - 1e-14);
    EXPECT_TRUE(g.converged);
    EXPECT_EQ(g.probes, 1u);
  }
  EXPECT_GE(overlapping, 12);
}

// ---- non-convex pairs ---------------------------------------------------------------------------

// A block with a slot [−w/2, w/2] × [−L, L] open at the top, and a bar of width b < w and length
// 2·len centred on Q's origin, turned by `deg` so that it pokes into both walls.
Shape2 slot_block(double w, double L) {
  return Shape2({Vec2(-3, -L - 1), Vec2(3, -L - 1), Vec2(3, L), Vec2(w / 2, L), Vec2(w / 2, -L), Vec2(-w / 2, -L),
                 Vec2(-w / 2, L), Vec2(-3, L)},
                {}, "slot");
}
Shape2 bar(double b, double len, double deg) {
  std::vector<Vec2> r{Vec2(-b / 2, -len), Vec2(b / 2, -len), Vec2(b / 2, len), Vec2(-b / 2, len)};
  for (Vec2& p : r) p = turned(p, deg);
  return Shape2(r, {}, "bar");
}

void check_against_brute(const Shape2& P, const Shape2& Q, const Vec2& t, const GeneralizedDepth2& r, int n) {
  check_result(P, Q, t, r);
  const Brute b = brute_force(P, Q, t, grid(-180, 180, n));
  ASSERT_GT(b.motions, 0u);
  EXPECT_LE(r.lower_bound, b.best) << "grid minimum at " << b.best_angle;
}

TEST(Generalized2, PegInSlotRotationHelps) {
  // The bar (width 0.5, length 6) turned by 3° in a slot 0.52 wide: both walls are hit, so σ pulls
  // it sideways through a wall or out of the slot; turning back by ~3° costs about 3·0.05 ≈ 0.16.
  const Shape2 P = slot_block(0.52, 4), Q = bar(0.5, 3, 3.0);
  const Vec2 t(0, 0);
  const GeneralizedDepth2 r = generalized_depth(P, Q, t);
  check_against_brute(P, Q, t, r, 720);
  EXPECT_LT(r.depth, 0.25 * r.sigma) << "sigma " << r.sigma << " depth " << r.depth;
  EXPECT_LT(r.angle, 0);
  EXPECT_GT(r.angle, -4);
  // The brute force over a much finer angle window near the optimum never beats the certified
  // lower bound.
  const Brute fine = brute_force(P, Q, t, grid(-4, 0, 400));
  EXPECT_LE(r.lower_bound, fine.best);
}

TEST(Generalized2, LShapesCombsHoles) {
  std::mt19937_64 rng(1818);
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  int n = 0;
  for (int k = 0; k < 10; ++k) {
    const Shape2 P = k % 2 ? l_shape(1.0, Vec2(-1, -1), "L") : comb(4, 0.3, 1.0, Vec2(-1, 0), "comb");
    const Shape2 Q = k % 3 == 0 ? l_shape(0.6, Vec2(-0.4, -0.3), "l")
                     : k % 3 == 1 ? comb(3, 0.2, 0.7, Vec2(-0.5, 0.2), "c")
                                  : Shape2({Vec2(-0.7, -0.7), Vec2(0.7, -0.7), Vec2(0.7, 0.7), Vec2(-0.7, 0.7)},
                                           {{Vec2(-0.3, -0.3), Vec2(-0.3, 0.3), Vec2(0.3, 0.3), Vec2(0.3, -0.3)}},
                                           "frame");
    const Vec2 t(u(rng), u(rng));
    if (!Pair2(P, Q).overlapping(t)) continue;
    ++n;
    const GeneralizedDepth2 r = generalized_depth(P, Q, t);
    SCOPED_TRACE("case " + std::to_string(k));
    check_against_brute(P, Q, t, r, 180);
  }
  EXPECT_GE(n, 6);
}

TEST(Generalized2, NestingPieces) {
  std::mt19937_64 rng(77);
  int n = 0, certified = 0;
  for (const char* file : {"albano.json", "trousers.json", "shirts.json"}) {
    const auto pieces = nesting(file);
    ASSERT_GE(pieces.size(), 4u) << file;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        const Shape2 &P = pieces[i], &Q = pieces[j];
        // Q placed so that its box centre lands near P's: a deep overlap.
        Vec2 plo(1e300, 1e300), phi(-1e300, -1e300), qlo = plo, qhi = phi;
        const auto pr = P.rings(), qr = Q.rings();
        for (const Vec2& p : pr[0]) plo = plo.cwiseMin(p), phi = phi.cwiseMax(p);
        for (const Vec2& q : qr[0]) qlo = qlo.cwiseMin(q), qhi = qhi.cwiseMax(q);
        std::uniform_real_distribution<double> u(-0.2, 0.2);
        const Vec2 t = 0.5 * (plo + phi - qlo - qhi) + Vec2(u(rng) * (phi - plo).x(), u(rng) * (phi - plo).y());
        if (!Pair2(P, Q).overlapping(t)) continue;
        ++n;
        const GeneralizedDepth2 r = generalized_depth(P, Q, t);
        SCOPED_TRACE(std::string(file) + " pieces " + std::to_string(i) + ", " + std::to_string(j));
        check_against_brute(P, Q, t, r, 72);
        certified += r.converged;
        if (P.is_convex() && Q.is_convex()) EXPECT_TRUE(r.converged);
      }
  }
  EXPECT_GE(n, 20);
  RecordProperty("certified", certified);
}

TEST(Generalized2, QuarterTurnsAndApart) {
  // A frame whose square hole holds the square Q exactly.
  const Shape2 Q({Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}, {}, "sq");
  const Shape2 P({Vec2(-3, -3), Vec2(3, -3), Vec2(3, 3), Vec2(-3, 3)},
                 {{Vec2(-1, -1), Vec2(-1, 1), Vec2(1, 1), Vec2(1, -1)}}, "frame");
  // Q exactly in the hole: touching, not overlapping.
  const GeneralizedDepth2 a = generalized_depth(P, Q, Vec2(0, 0));
  EXPECT_FALSE(a.overlapping);
  EXPECT_EQ(a.depth, 0);
  EXPECT_EQ(a.upper_bound, 0);
  // Q turned by 90° is the same square: exact quarter turn, still touching.
  EXPECT_FALSE(generalized_depth(P, Q.rotated(90), Vec2(0, 0)).overlapping);
  // Q turned by 30°: the exact answer is to turn back (or on by 60°, the square's symmetry) into
  // the exact fit, cost 2·sin(15°)·√2 ≈ 0.732 (the corners travel most). The rounded copies at
  // ±30° are a hair larger than the hole (σ = 4: pulled out), so the search's upper bound is a
  // neighbouring angle; the certified bounds must bracket the exact value.
  const Shape2 Q30 = Q.rotated(30);
  const GeneralizedDepth2 r = generalized_depth(P, Q30, Vec2(0, 0));
  check_against_brute(P, Q30, Vec2(0, 0), r, 360);
  const double exact = 2 * std::sin(kPi / 12) * std::sqrt(2.0);
  EXPECT_LE(r.lower_bound, exact);
  EXPECT_GE(r.upper_bound, exact * (1 - 1e-12));
  EXPECT_LT(r.depth, 0.5 * r.sigma);
  EXPECT_FALSE(r.rotation_exact);
}

TEST(Generalized2, InvalidInput) {
  const Shape2 Q({Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}, {}, "q");
  EXPECT_THROW(generalized_depth(Q, Q, Vec2(NAN, 0)), InvalidInput);
  GeneralizedOptions2 o;
  o.min_degrees = 10;
  EXPECT_THROW(generalized_depth(Q, Q, Vec2(0, 0), o), InvalidInput);
  o.min_degrees = -INFINITY;
  EXPECT_THROW(generalized_depth(Q, Q, Vec2(0, 0), o), InvalidInput);
  o = {};
  o.tolerance = -1;
  EXPECT_THROW(generalized_depth(Q, Q, Vec2(0, 0), o), InvalidInput);
}

TEST(Generalized2, HugeAndTinyPairsScale) {
  // The same L-shapes at 2^±400: every length scales by the power of two, the angle stays.
  const Shape2 P = l_shape(1.0, Vec2(-1, -1), "L"), Q = l_shape(0.6, Vec2(-0.4, -0.3), "l");
  const Vec2 t(0.3, 0.2);
  const GeneralizedDepth2 r = generalized_depth(P, Q, t);
  for (int e : {400, -400}) {
    auto scaled = [&](const Shape2& s) {
      auto rings = s.rings();
      for (auto& ring : rings)
        for (Vec2& p : ring) p = std::ldexp(1.0, e) * p;
      return Shape2(rings[0], {}, s.name());
    };
    const GeneralizedDepth2 g = generalized_depth(scaled(P), scaled(Q), std::ldexp(1.0, e) * t);
    EXPECT_EQ(g.depth, std::ldexp(r.depth, e));
    EXPECT_EQ(g.lower_bound, std::ldexp(r.lower_bound, e));
    EXPECT_EQ(g.angle, r.angle);
  }
}

// ---- the theorem in 3D --------------------------------------------------------------------------

TEST(Generalized3, ConvexPolytopesEqualSigmaAndNoRotationBeatsIt) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  int overlapping = 0;
  for (int k = 0; k < 12; ++k) {
    std::vector<Vec3> a, b;
    for (int i = 0; i < 12 + k; ++i) a.emplace_back(g(rng), g(rng), 0.6 * g(rng));
    for (int i = 0; i < 8 + k; ++i) b.emplace_back(0.7 * g(rng) + 0.2, 0.5 * g(rng), g(rng));
    const Shape3 P = Shape3::hull(a, "P"), Q = Shape3::hull(b, "Q");
    const Pose3 pp(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)), Vec3(u(rng), u(rng), u(rng)));
    const Pose3 pq(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)), Vec3(u(rng), u(rng), u(rng)));
    const Pair3 pair(P, Q);
    const Depth3 s = pair.minimum(pp, pq);
    const GeneralizedDepth3 r = generalized_depth(P, pp, Q, pq);
    EXPECT_EQ(r.depth, s.depth);
    EXPECT_EQ(r.lower_bound, s.overlapping ? s.lower_bound : 0);
    EXPECT_EQ(r.upper_bound, s.overlapping ? s.upper_bound : 0);
    EXPECT_TRUE(r.translation == s.translation);
    EXPECT_TRUE(r.rotation.coeffs() == Eigen::Quaterniond::Identity().coeffs());
    if (!s.overlapping) continue;
    ++overlapping;
    // Random rotations (large and small) about Q's placed reference point, each with the best
    // translation for it (Pair3's σ at the rotated pose): DISP over Q's vertices ≥ σ.
    const Eigen::Matrix3d Rq = pq.matrix();
    double least = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 200; ++i) {
      Eigen::Quaterniond rot(g(rng), g(rng), g(rng), g(rng));
      if (i % 2) rot = Eigen::Quaterniond(1, 0.05 * g(rng), 0.05 * g(rng), 0.05 * g(rng));
      rot.normalize();
      const Pose3 moved(rot * pq.rotation.normalized(), pq.translation);
      const Depth3 d = pair.minimum(pp, moved);
      const Eigen::Matrix3d Rm = moved.matrix();
      double cost = 0;
      for (const Vec3& x : Q.polytope().vertices())
        cost = std::max(cost, (Rm * x + d.translation - Rq * x).norm());
      least = std::min(least, cost);
    }
    EXPECT_GE(least, s.depth * (1 - 1e-9)) << "pair " << k;
  }
  EXPECT_GE(overlapping, 4);
}

}  // namespace
