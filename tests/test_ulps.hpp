// Distances between doubles in units in the last place, shared by the suites that compare an engine
// with an oracle.
#pragma once

#include <algorithm>
#include <cmath>

namespace pendepth_test {

/// |got − want| in ulps of `want`'s magnitude (relative): 0 when equal, +∞ when want is 0 and got is not.
inline double ulps_of_want(double got, double want) {
  if (want == 0) return got == 0 ? 0 : INFINITY;
  return std::abs(got - want) / (std::abs(want) * 0x1p-52);
}

/// |a − b| in ulps of the binade of the larger magnitude (symmetric; 0 when both are 0).
inline double ulps_in_binade(double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  if (scale == 0) return 0;
  return std::abs(a - b) / (std::ldexp(1.0, std::ilogb(scale)) * 0x1p-52);
}

}  // namespace pendepth_test
