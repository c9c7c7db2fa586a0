// pendepth — input checks of the front door (src/front/): every query's placement and direction
// is checked at the API boundary, and a batch is checked whole before any query runs, so a bad
// entry is reported by its index and a batch never stops half-way.
#pragma once

#include <pendepth/geometry.hpp>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <span>
#include <string>

namespace pendepth::front {

template <class V>
bool finite(const V& v) {
  for (int k = 0; k < v.size(); ++k)
    if (!std::isfinite(v[k])) return false;
  return true;
}

/// "(x, y[, z])" with every value in full (%.17g: 1e-300 must not print as 0.000000).
template <class V>
std::string text(const V& v) {
  std::string s = "(";
  char buf[32];
  for (int k = 0; k < v.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%.17g", static_cast<double>(v[k]));
    s += (k ? ", " : "") + std::string(buf);
  }
  return s + ")";
}

/// Throws InvalidInput unless t is finite. `what` names the query ("placement", "placement 7").
template <class V>
void check_placement(const V& t, const std::string& what = "placement") {
  if (!finite(t)) throw InvalidInput(what + " " + text(t) + " is not finite");
}

/// Throws InvalidInput for a zero or non-finite direction. Any other magnitude is fine: the
/// engines scale directions (and quaternions) by powers of two themselves, exactly.
template <class V>
void check_direction(const V& d, const std::string& what = "direction") {
  if (!finite(d)) throw InvalidInput(what + " " + text(d) + " is not finite");
  if (d.cwiseAbs().maxCoeff() == 0) throw InvalidInput(what + " is zero");
}

/// A batch: out has one entry per placement; ds is empty (no directions), one direction for all,
/// or one per placement; every placement finite, every direction finite and non-zero.
template <class V>
void check_batch(std::span<const V> ts, std::span<const V> ds, std::size_t out_size, bool directions) {
  if (out_size != ts.size())
    throw InvalidInput("batch: " + std::to_string(ts.size()) + " placements but room for " +
                       std::to_string(out_size) + " results");
  if (directions && ds.size() != 1 && ds.size() != ts.size())
    throw InvalidInput("batch: " + std::to_string(ds.size()) + " directions for " + std::to_string(ts.size()) +
                       " placements (give one direction, or one per placement)");
  for (std::size_t i = 0; i < ts.size(); ++i) check_placement(ts[i], "batch: placement " + std::to_string(i));
  if (directions)
    for (std::size_t i = 0; i < ds.size(); ++i) check_direction(ds[i], "batch: direction " + std::to_string(i));
}

}  // namespace pendepth::front
