// The properties of docs/design.md §5 on random pairs, decided with the oracle's exact point location:
//  - moving Q by the returned translation v separates: t + (1+ε)v ∉ int M, and any shorter move
//    along v does not: t + (1−ε)v ∈ int M (σ and σ_d);
//  - σ <= σ_d for every direction tried; σ_d along σ's normal equals σ;
//  - the three ways to σ agree: the merge (minimum_depth), the DepthField, and the minimum of σ_d
//    over 720 evenly spaced directions, which lies in [σ, σ / cos(π/720)];
//  - invariance: rotating the scene by 90° ((x, y) → (−y, x), exact), swapping P and Q with
//    t → −t (M reflects through the origin), translating both shapes by an exact offset.
#include <pendepth/depth2.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "oracle/checks.hpp"
#include "oracle/exact_oracle.hpp"
#include "oracle/shapes.hpp"

namespace oracle_tests {
namespace {

#ifdef NDEBUG
constexpr int kPairs = 300;
#else
constexpr int kPairs = 50;  // Debug / sanitizers
#endif

// Rounding when the test forms t + (1±ε)v, relative to |t| + |v|: v is within ~8·2^-52 |v| of the
// exact move (depth and direction), and two roundings add 2^-52 (|t| + 2|v|). The exact point
// t + (1±ε)v_exact is at least ε·σ(t) from ∂M (convexity: the ball B(t, σ) lies in M), so the
// check is decided correctly when ε·σ exceeds that error; ε is raised to make it so.
constexpr double kPointRounding = 16 * kEps;
constexpr double kBaseEps = 1e-9;
constexpr double kMaxEps = 1e-4;  // beyond this the placement is too close to ∂M for the check

struct PropertyStats {
  long moves = 0, moves_skipped = 0, sweeps = 0, rotations = 0, swaps = 0, shifts = 0, comparisons = 0;
  int failures = 0;
};

ConvexPolygon transformed(const ConvexPolygon& S, Vec2 (*f)(const Vec2&, const Vec2&), const Vec2& c) {
  std::vector<Vec2> ring;
  for (const Vec2& v : S.vertices()) ring.push_back(f(v, c));
  return ConvexPolygon(ring, S.name());
}
Vec2 rotate(const Vec2& v, const Vec2&) { return rot90(v); }
Vec2 shift(const Vec2& v, const Vec2& c) { return v + c; }

bool exact_shift(const std::vector<Vec2>& pts, const Vec2& c) {
  for (const Vec2& v : pts)
    if ((v + c) - c != v) return false;
  return true;
}

class PropertyChecker {
 public:
  PropertyChecker(const ConvexPolygon& P, const ConvexPolygon& Q, const oracle::ExactDifference& M, PropertyStats& s,
                  std::string scene)
      : P_(P), Q_(Q), M_(M), s_(s), scene_(std::move(scene)) {}

  // t + (1+ε)v leaves int M and t + (1−ε)v does not; sigma_exact is the oracle's σ(t) > 0.
  void move(const char* what, const Vec2& t, const Vec2& v, double sigma_exact) {
    const double eps = std::max(kBaseEps, 4 * kPointRounding * (t.norm() + v.norm()) / sigma_exact);
    if (eps > kMaxEps) {
      ++s_.moves_skipped;
      return;
    }
    ++s_.moves;
    const Vec2 longer = t + (1 + eps) * v, shorter = t + (1 - eps) * v;
    if (M_.locate(longer) == oracle::Location::Inside) fail(what, "t + (1+ε)v still overlaps", t, v, eps);
    if (M_.locate(shorter) != oracle::Location::Inside) fail(what, "t + (1−ε)v already separates", t, v, eps);
  }

  void fail(const char* what, const std::string& why, const Vec2& t, const Vec2& v, double eps) {
    ++s_.failures;
    ADD_FAILURE() << what << ": " << why << "\n  " << scene_ << "\n  t=" << fmt(t) << " v=" << fmt(v)
                  << " ε=" << eps;
  }
  // a and b are two pendepth answers for the same exact depth.
  void same(const char* what, double a, double b, const Vec2& t, const std::string& extra = "") {
    ++s_.comparisons;
    if (oracle::within(a, b, kPairTol)) return;
    ++s_.failures;
    ADD_FAILURE() << what << ": " << fmt(a) << " vs " << fmt(b) << " (" << oracle::relative_ulps(a, b)
                  << " ulps rel)\n  " << scene_ << "\n  t=" << fmt(t) << extra;
  }
  void check(bool ok, const char* what, const Vec2& t, const std::string& extra = "") {
    if (ok) return;
    ++s_.failures;
    ADD_FAILURE() << what << "\n  " << scene_ << "\n  t=" << fmt(t) << extra;
  }

  const ConvexPolygon &P_, &Q_;
  const oracle::ExactDifference& M_;
  PropertyStats& s_;
  std::string scene_;
};

// sweep: also the σ_d(normal) and 720-direction checks (the expensive part).
void placement_properties(PropertyChecker& C, const pendepth::DepthField& field, Rng& rng, const Vec2& t,
                          const std::vector<Vec2>& dirs, bool sweep) {
  const ConvexPolygon &P = C.P_, &Q = C.Q_;
  const double sigma_exact = C.M_.minimum_depth(t);
  const bool inside = C.M_.locate(t) == oracle::Location::Inside;
  const pendepth::Depth2 r = pendepth::minimum_depth(P, Q, t);
  C.check(r.overlapping == inside && oracle::within(r.depth, sigma_exact, kDepthTol), "minimum_depth vs oracle", t,
          " σ=" + fmt(r.depth) + " exact " + fmt(sigma_exact));
  if (inside && sigma_exact > 0) C.move("σ", t, r.translation, sigma_exact);

  // σ <= σ_d, and the σ_d translation separates (and only just).
  for (const Vec2& d : dirs) {
    const pendepth::Depth2 rd = pendepth::directional_depth(P, Q, t, d);
    C.check(r.depth <= rd.depth * (1 + kPairTol * kEps) + oracle::kUnderflowSlack, "σ > σ_d", t,
            " d=" + fmt(d) + " σ=" + fmt(r.depth) + " σ_d=" + fmt(rd.depth));
    if (inside && sigma_exact > 0) C.move("σ_d", t, rd.translation, sigma_exact);
  }
  if (!inside || !sweep) return;

  // σ_d along σ's normal is σ (the exit point is the foot of the perpendicular).
  C.check(r.normal.allFinite() && r.normal != Vec2(0, 0), "σ: no normal for an overlapping placement", t);
  if (r.normal.allFinite() && r.normal != Vec2(0, 0))
    C.same("σ_d(normal of σ) vs σ", pendepth::directional_depth(P, Q, t, r.normal).depth, r.depth, t,
           " normal=" + fmt(r.normal));

  // Three routes to σ: merge, field, and the minimum over 720 directions (each σ_d >= σ, and the
  // direction nearest the true normal is within π/720 of it: σ_d <= σ / cos(π/720)).
  C.same("DepthField vs merge", field.minimum(t).depth, r.depth, t);
  double lo = INFINITY;
  const double phase = uniform(rng, 0, std::numbers::pi / 360);
  for (int k = 0; k < 720; ++k) {
    const double a = phase + k * std::numbers::pi / 360;
    const double sd = pendepth::directional_depth(P, Q, t, Vec2(std::cos(a), std::sin(a))).depth;
    C.check(r.depth <= sd * (1 + kPairTol * kEps) + oracle::kUnderflowSlack, "σ > σ_d in the sweep", t,
            " angle=" + fmt(a));
    lo = std::min(lo, sd);
  }
  ++C.s_.sweeps;
  C.check(lo <= r.depth / std::cos(std::numbers::pi / 720) * (1 + kPairTol * kEps) + oracle::kUnderflowSlack,
          "min over 720 σ_d exceeds σ / cos(π/720)", t, " min=" + fmt(lo) + " σ=" + fmt(r.depth));
}

TEST(OracleProperties, RandomPairs) {
  const auto start = std::chrono::steady_clock::now();
  Rng rng(0x9709e7);
  PropertyStats ps;
  for (int trial = 0; trial < kPairs && ps.failures < kMaxFailures; ++trial) {
    const int n = uniform_int(rng, 3, 60), m = uniform_int(rng, 3, 60);
    Shape P = shape(rng, random_kind(rng, n), n);
    Shape Q = shape(rng, random_kind(rng, m), m, uniform_int(rng, 0, 2) ? 1.0 : 0.1);
    const oracle::ExactDifference M(P.pts, Q.pts);
    const std::string scene = "trial " + std::to_string(trial) + " P=" + fmt_polygon(*P.poly) + " Q=" + fmt_polygon(*Q.poly);
    PropertyChecker C(*P.poly, *Q.poly, M, ps, scene);
    const pendepth::DepthField field(*P.poly, *Q.poly);
    const ConvexPolygon Pr = transformed(*P.poly, rotate, {}), Qr = transformed(*Q.poly, rotate, {});
    const Vec2 c(1e6, -1e6);
    const bool shiftable = exact_shift(P.pts, c) && exact_shift(Q.pts, c);
    const ConvexPolygon Ps = transformed(*P.poly, shift, shiftable ? c : Vec2(0, 0));
    const ConvexPolygon Qs = transformed(*Q.poly, shift, shiftable ? c : Vec2(0, 0));

    // Placements: mostly inside M (drawn until inside), some one ulp inside ∂M, some outside.
    std::vector<Vec2> ts;
    for (const Vec2& t : placements(rng, M, 40, 2))
      if (ts.size() < 8 && (M.locate(t) == oracle::Location::Inside || uniform_int(rng, 0, 5) == 0)) ts.push_back(t);
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const Vec2 t = ts[i];
      std::vector<Vec2> dirs;
      for (int k = 0; k < 4; ++k) dirs.push_back(direction(rng, *P.poly, *Q.poly, M));
      placement_properties(C, field, rng, t, dirs, i < 3);

      // Rotation by 90°: the same exact depths.
      C.same("σ of the rotated scene", pendepth::minimum_depth(Pr, Qr, rot90(t)).depth,
             pendepth::minimum_depth(*P.poly, *Q.poly, t).depth, t);
      for (const Vec2& d : dirs)
        C.same("σ_d of the rotated scene", pendepth::directional_depth(Pr, Qr, rot90(t), rot90(d)).depth,
               pendepth::directional_depth(*P.poly, *Q.poly, t, d).depth, t, " d=" + fmt(d));
      ++ps.rotations;

      // Swapping roles: Q fixed, P moving by −t; M' = −M, so σ is the same and σ_d(t, d) = σ'_{−d}(−t).
      C.same("σ with P and Q swapped", pendepth::minimum_depth(*Q.poly, *P.poly, -t).depth,
             pendepth::minimum_depth(*P.poly, *Q.poly, t).depth, t);
      for (const Vec2& d : dirs)
        C.same("σ_d with P and Q swapped", pendepth::directional_depth(*Q.poly, *P.poly, -t, -d).depth,
               pendepth::directional_depth(*P.poly, *Q.poly, t, d).depth, t, " d=" + fmt(d));
      ++ps.swaps;

      // Translating both shapes by an exactly representable offset leaves M unchanged.
      if (shiftable) {
        C.same("σ with both shapes shifted by (1e6, -1e6)", pendepth::minimum_depth(Ps, Qs, t).depth,
               pendepth::minimum_depth(*P.poly, *Q.poly, t).depth, t);
        for (const Vec2& d : dirs)
          C.same("σ_d with both shapes shifted by (1e6, -1e6)", pendepth::directional_depth(Ps, Qs, t, d).depth,
                 pendepth::directional_depth(*P.poly, *Q.poly, t, d).depth, t, " d=" + fmt(d));
        ++ps.shifts;
      }
      if (ps.failures >= kMaxFailures) break;
    }
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[properties] %d pairs: %ld separating-move checks (%ld placements too close to ∂M for ε), %ld "
              "720-direction sweeps, %ld rotated, %ld swapped, %ld shifted scenes, %ld value comparisons, "
              "failures %d, %.1f s\n",
              kPairs, ps.moves, ps.moves_skipped, ps.sweeps, ps.rotations, ps.swaps, ps.shifts, ps.comparisons,
              ps.failures, secs);
  EXPECT_EQ(ps.failures, 0);
  EXPECT_GT(ps.moves, 10 * kPairs);
  EXPECT_GT(ps.sweeps, kPairs);
}

}  // namespace
}  // namespace oracle_tests
