// Comparison of every pendepth 2D convex query with the exact oracle, and the running statistics.
//
// Tolerance (documented once, used everywhere): a depth must be within kDepthTol units of
// 2^-52 relative to the exact value (the oracle's reference is the exact value rounded to nearest,
// which adds at most 0.5 ulp), plus oracle::kUnderflowSlack (2^-1000) absolute for depths that
// underflow (placements a subnormal distance inside ∂M). Non-overlapping placements (t on ∂M or outside M) must give
// exactly 0 with a zero translation. Two pendepth answers for the same exact depth (rotated,
// swapped or translated scenes) may differ by twice that: kPairTol.
#pragma once

#include <pendepth/depth2.hpp>

#include <cstdio>
#include <string>

#include "oracle/exact_oracle.hpp"

namespace oracle_tests {

inline constexpr double kDepthTol = 4;           // units of 2^-52, relative
inline constexpr double kPairTol = 8 * (1 + 1e-9);  // two answers each within kDepthTol
inline constexpr double kEps = 0x1p-52;
inline constexpr double kNormalRange = 0x1p-900;  // statistics in ulps only above the underflow range

struct Stats {
  long directional = 0, minimum = 0, zeros = 0, boundary = 0;  // queries compared (each over all methods)
  double worst_directional = 0, worst_minimum = 0;              // in units of 2^-52 relative
  int failures = 0;
  void print(const char* name) const {
    std::printf("[%s] σ_d checks %ld (max %.3f ulps rel), σ checks %ld (max %.3f ulps rel), "
                "exact-zero answers %ld, placements on ∂M %ld, failures %d\n",
                name, directional, worst_directional, minimum, worst_minimum, zeros, boundary, failures);
  }
};

/// One pair: P and Q (pendepth), the oracle's M, and a DepthQuery2 built once.
class PairChecker {
 public:
  PairChecker(const pendepth::ConvexPolygon& P, const pendepth::ConvexPolygon& Q, const oracle::ExactDifference& M,
              Stats& stats, std::string context);
  /// σ_d by directional_depth, separation_depth, DepthQuery2::along and ::separation vs the
  /// oracle. False (after ADD_FAILURE with the full input) on disagreement.
  bool directional(const pendepth::Vec2& t, const pendepth::Vec2& d);
  /// σ by minimum_depth, DepthField::minimum and DepthQuery2::minimum vs the oracle.
  bool minimum(const pendepth::Vec2& t);
  const pendepth::DepthQuery2& query() const { return query_; }
  /// "P=[...] Q=[...]" (%.17g) or the sizes and context for large shapes.
  std::string scene() const;

 private:
  const pendepth::ConvexPolygon &P_, &Q_;
  const oracle::ExactDifference& M_;
  pendepth::DepthQuery2 query_;
  Stats& stats_;
  std::string context_;
};

std::string fmt(const pendepth::Vec2& v);
std::string fmt(double x);
std::string fmt_polygon(const pendepth::ConvexPolygon& P);

/// Keeps a test readable: stop a loop after this many reported disagreements.
inline constexpr int kMaxFailures = 10;

}  // namespace oracle_tests
