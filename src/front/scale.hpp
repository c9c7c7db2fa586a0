// pendepth — the front door's numeric domain (docs/robustness.md "Numeric domain").
//
// Every answer is covariant under scaling by a power of two: σ(2^k P, 2^k Q, 2^k t) = 2^k σ(P, Q, t),
// and in floating point every step of the engines scales exactly as long as nothing over- or
// underflows. The engines are exact while the pair's sizes stay inside a measured band of
// exponents (their products and filters neither overflow nor sink below the filters' absolute
// slack). A pair inside the comfort part of the band (every ordinary input) uses the shapes as
// they are: no copy, no cost, the same bits as always. Any other pair is answered on copies
// scaled by 2^-e so that its exponent range sits in the middle of the band, and every length of
// the answer is scaled back by 2^e: an explicit ±infinity only where the true value overflows a
// double.
//
// The domain, checked at the boundary with errors naming the value and the supported range:
//   * shape coordinates finite (the shapes check this);
//   * a pair's largest coordinate over its smallest edge at most 2^600 in 2D, 2^280 in 3D;
//   * coordinates, placements and pose translations exact after scaling by 2^-e (a tiny
//     non-zero offset next to huge shapes, or a huge one next to tiny shapes, is rejected with
//     the range it must lie in).
#pragma once

#include <pendepth/geometry.hpp>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstdio>
#include <limits>
#include <string>

namespace pendepth::front {

/// The sizes of a pair that decide its scale: the largest coordinate magnitude and the smallest
/// edge (the larger |component| of its vector) of either shape.
struct Extent {
  double largest = 0, smallest_edge = std::numeric_limits<double>::infinity();
  int smallest_edge_exp = std::numeric_limits<int>::max();  // binary exponent of smallest_edge

  void add_point(double m) { largest = std::max(largest, m); }
  /// An edge from a to b. A difference that overflows (an edge longer than DBL_MAX) is measured
  /// on the halved points; only its exponent matters.
  template <class V>
  void add_edge(const V& a, const V& b) {
    const double m = (b - a).cwiseAbs().maxCoeff();
    if (!(m > 0)) return;
    const int k = std::isfinite(m) ? std::ilogb(m) : std::ilogb((0.5 * b - 0.5 * a).cwiseAbs().maxCoeff()) + 1;
    if (k < smallest_edge_exp) smallest_edge_exp = k, smallest_edge = m;
  }
};

/// Where an engine family is exact, as binary exponents: every pair with its largest coordinate
/// below 2^comfort_hi and its smallest edge above 2^comfort_lo is used unscaled; any other pair
/// is scaled so that the middle of its exponent range sits at `centre`, and is rejected when
/// that range is wider than `max_range` (measured bands, docs/robustness.md: 2D engines exact
/// for whole shapes from 2^-257 to 2^508, 3D from 2^-198 to 2^152).
struct Band {
  int comfort_lo, comfort_hi, centre, max_range;
  const char* what;
};
inline constexpr Band kBand2{-96, 96, 125, 600, "2D"};
inline constexpr Band kBand3{-96, 96, -20, 280, "3D"};

/// Engine coordinates = input coordinates × 2^-e.
struct Scale {
  int e = 0;

  bool identity() const { return e == 0; }

  /// The pair's scale; throws InvalidInput when its sizes span more than the band allows.
  static Scale for_pair(const Extent& x, const Band& band) {
    Scale s;
    if (!(x.largest > 0) || !std::isfinite(x.largest) || x.smallest_edge_exp == std::numeric_limits<int>::max())
      return s;
    const int hi = std::ilogb(x.largest), lo = std::min(hi, x.smallest_edge_exp);
    if (hi < band.comfort_hi && lo >= band.comfort_lo) return s;
    if (hi - lo > band.max_range) {
      char buf[320];
      std::snprintf(buf, sizeof buf,
                    "pair: the shapes' sizes span too many orders of magnitude for exact %s answers: the "
                    "largest coordinate is %.17g and the smallest edge %.17g long (ratio about 2^%d; at "
                    "most 2^%d, about 1e%d, is supported)",
                    band.what, x.largest, x.smallest_edge, hi - lo, band.max_range,
                    static_cast<int>(band.max_range * 0.30103));
      throw InvalidInput(buf);
    }
    s.e = (hi + lo) / 2 - band.centre;
    return s;
  }

  /// x × 2^-e, or nullopt-like failure reported through `ok` when bits would be lost (underflow)
  /// or the value would overflow.
  bool to_engine(double x, double& out) const {
    out = std::ldexp(x, -e);
    return std::isfinite(out) && std::ldexp(out, e) == x;
  }

  /// v × 2^-e, or InvalidInput "WHAT VALUE-and-range" when a coordinate has no exact engine
  /// value. `what` is a callable returning the message's subject: it runs only on failure, so an
  /// ordinary query formats nothing.
  template <class V, class What>
    requires std::invocable<What&>
  V vec_to_engine(const V& v, What&& what) const {
    if (identity()) return v;
    V out = v;
    for (int k = 0; k < v.size(); ++k)
      if (!to_engine(v[k], out[k])) throw InvalidInput(what() + " " + describe(v[k]));
    return out;
  }
  template <class V>
  V vec_to_engine(const V& v, const std::string& what) const {
    return vec_to_engine(v, [&] { return what; });
  }

  double length(double x) const { return identity() ? x : std::ldexp(x, e); }
  template <class V>
  V vec(const V& v) const {
    if (identity()) return v;
    V out = v;
    for (int k = 0; k < v.size(); ++k) out[k] = std::ldexp(v[k], e);
    return out;
  }

  /// An engine answer (Depth2 or Depth3) back to input units: every length and point scaled by
  /// 2^e (normals and features are scale-free). A length that overflows becomes an explicit
  /// infinity.
  template <class Result>
  Result answer(Result r) const {
    if (identity()) return r;
    r.depth = length(r.depth);
    if constexpr (requires { r.lower_bound; }) {
      r.lower_bound = length(r.lower_bound);
      r.upper_bound = length(r.upper_bound);
    }
    r.translation = vec(r.translation);
    r.witness_p = vec(r.witness_p);
    r.witness_q = vec(r.witness_q);
    return r;
  }

  /// Why `x` has no exact engine value at this scale, with the range it must lie in.
  std::string describe(double x) const {
    char buf[256];
    if (e > 0)
      std::snprintf(buf, sizeof buf,
                    "%.17g is too small for this pair of large shapes: non-zero values must be multiples of "
                    "2^%d (exact at the pair's scale 2^%d)",
                    x, -1074 + e, e);
    else
      std::snprintf(buf, sizeof buf,
                    "%.17g is too large for this pair of small shapes: values must be below 2^%d in "
                    "magnitude (the pair's scale is 2^%d)",
                    x, 1024 + e, e);
    return buf;
  }
};

}  // namespace pendepth::front
