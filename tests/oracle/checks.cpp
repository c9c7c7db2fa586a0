// Every pendepth 2D convex query against the exact oracle (see checks.hpp for the tolerance).
#include "oracle/checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace oracle_tests {

using pendepth::Depth2;
using pendepth::DepthKind;
using pendepth::Vec2;

std::string fmt(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}
std::string fmt(const Vec2& v) { return "(" + fmt(v.x()) + ", " + fmt(v.y()) + ")"; }
std::string fmt_polygon(const pendepth::ConvexPolygon& P) {
  std::string s = "[";
  for (std::size_t i = 0; i < P.size(); ++i) s += (i ? ", " : "") + fmt(P[i]);
  return s + "]";
}

PairChecker::PairChecker(const pendepth::ConvexPolygon& P, const pendepth::ConvexPolygon& Q,
                         const oracle::ExactDifference& M, Stats& stats, std::string context)
    : P_(P), Q_(Q), M_(M), query_(P, Q), stats_(stats), context_(std::move(context)) {}

std::string PairChecker::scene() const {
  std::string s = context_ + " n=" + std::to_string(P_.size()) + " m=" + std::to_string(Q_.size());
  if (P_.size() + Q_.size() <= 48) s += " P=" + fmt_polygon(P_) + " Q=" + fmt_polygon(Q_);
  return s;
}

namespace {

bool finite(const Depth2& r) {
  return std::isfinite(r.depth) && r.translation.allFinite() && r.normal.allFinite() && r.witness_p.allFinite() &&
         r.witness_q.allFinite();
}

// The common part of the contract: finite, and exactly zero when the interiors do not overlap.
// Returns an empty string when r is consistent with (inside, want), else the reason.
std::string compare(const Depth2& r, bool inside, double want, double& worst) {
  if (!finite(r)) return "non-finite result";
  if (r.overlapping != inside) return std::string("overlapping=") + (r.overlapping ? "true" : "false");
  if (!inside) {
    if (r.depth != 0 || r.translation != Vec2(0, 0)) return "non-zero answer for a non-overlapping placement";
    return "";
  }
  const double u = oracle::relative_ulps(r.depth, want);
  if (want > kNormalRange) worst = std::max(worst, u);
  if (!oracle::within(r.depth, want, kDepthTol)) return "depth off by " + fmt(u) + " ulps (relative)";
  // The translation has the reported length (to rounding).
  if (!oracle::within(r.translation.norm(), r.depth, 4)) return "|translation| != depth";
  if (!(std::abs(r.normal.norm() - 1) <= 4 * kEps)) return "normal is not a unit vector";
  return "";
}

const char* where(oracle::Location loc) {
  switch (loc) {
    case oracle::Location::Inside: return "inside M";
    case oracle::Location::Boundary: return "on ∂M";
    default: return "outside M";
  }
}

}  // namespace

bool PairChecker::directional(const Vec2& t, const Vec2& d) {
  const oracle::Location loc = M_.locate(t);
  const bool inside = loc == oracle::Location::Inside;
  const double want = M_.directional_depth(t, d);
  const Vec2 dhat = d / d.norm();
  struct Method {
    const char* name;
    Depth2 r;
    DepthKind kind;
  } methods[] = {
      {"directional_depth", pendepth::directional_depth(P_, Q_, t, d), DepthKind::Directional},
      {"separation_depth", pendepth::separation_depth(P_, Q_, t, d), DepthKind::Separation},
      {"DepthQuery2::along", query_.along(t, d), DepthKind::Directional},
      {"DepthQuery2::separation", query_.separation(t, d), DepthKind::Separation},
  };
  ++stats_.directional;
  if (!inside) ++stats_.zeros;
  if (loc == oracle::Location::Boundary) ++stats_.boundary;
  std::string report;
  const double want_sep = M_.separation_depth(t, d);
  for (const Method& m : methods) {
    std::string why;
    if (m.kind == DepthKind::Separation && !inside) {
      // From outside M, complete separation is the end of the ray's interval in int M (or 0).
      if (m.r.overlapping) why = "overlapping=true";
      else if (!finite(m.r)) why = "non-finite result";
      else if (want_sep == 0 ? (m.r.depth != 0 || m.r.translation != Vec2(0, 0))
                             : !oracle::within(m.r.depth, want_sep, kDepthTol))
        why = "separation " + fmt(m.r.depth) + " != exact " + fmt(want_sep);
    } else {
      why = compare(m.r, inside, want, stats_.worst_directional);
      if (why.empty() && m.kind == DepthKind::Separation && !oracle::within(want_sep, want, kDepthTol))
        why = "oracle: separation != σ_d from inside";  // the oracles must agree with each other
    }
    if (why.empty() && m.r.kind != m.kind) why = "wrong kind";
    // σ_d moves along d̂.
    if (why.empty() && (inside || m.r.depth > 0) && !((m.r.normal - dhat).norm() <= 4 * kEps)) why = "normal != d/|d|";
    if (!why.empty())
      report += "\n  " + std::string(m.name) + ": " + why + "; got " + fmt(m.r.depth) +
                " overlapping=" + (m.r.overlapping ? "true" : "false");
  }
  if (report.empty()) return true;
  ++stats_.failures;
  ADD_FAILURE() << "σ_d disagrees with the exact oracle\n  " << scene() << "\n  t=" << fmt(t) << " d=" << fmt(d)
                << "\n  expected " << fmt(want) << " (exact, rounded; t " << where(loc) << ")" << report;
  return false;
}

bool PairChecker::minimum(const Vec2& t) {
  const oracle::Location loc = M_.locate(t);
  const bool inside = loc == oracle::Location::Inside;
  const double want = M_.minimum_depth(t);
  struct Method {
    const char* name;
    Depth2 r;
  } methods[] = {
      {"minimum_depth (merge)", pendepth::minimum_depth(P_, Q_, t)},
      {"DepthField::minimum", query_.field().minimum(t)},
      {"DepthQuery2::minimum", query_.minimum(t)},
  };
  ++stats_.minimum;
  if (!inside) ++stats_.zeros;
  if (loc == oracle::Location::Boundary) ++stats_.boundary;
  std::string report;
  for (const Method& m : methods) {
    std::string why = compare(m.r, inside, want, stats_.worst_minimum);
    if (why.empty() && m.r.kind != DepthKind::Minimum) why = "wrong kind";
    if (why.empty() && !inside && m.r.normal != Vec2(0, 0)) why = "non-zero normal for a non-overlapping placement";
    if (!why.empty())
      report += "\n  " + std::string(m.name) + ": " + why + "; got " + fmt(m.r.depth) +
                " overlapping=" + (m.r.overlapping ? "true" : "false");
  }
  if (report.empty()) return true;
  ++stats_.failures;
  ADD_FAILURE() << "σ disagrees with the exact oracle\n  " << scene() << "\n  t=" << fmt(t) << "\n  expected "
                << fmt(want) << " (exact, rounded; t " << where(loc) << ")" << report;
  return false;
}

}  // namespace oracle_tests
