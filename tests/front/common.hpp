// Shared by the front-door tests: bitwise comparison of doubles and the message of an error.
#pragma once

#include <pendepth/geometry.hpp>

#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <string>

namespace front_test {

/// Bitwise equality (-0 ≠ +0, as a user diffing two outputs would see).
inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
template <class V>
bool same_bits_v(const V& a, const V& b) {
  for (int k = 0; k < a.size(); ++k)
    if (!same_bits(a[k], b[k])) return false;
  return true;
}

/// Bitwise equality of two results (Depth2 or Depth3: every field, the bounds where present).
template <class R>
::testing::AssertionResult same(const R& a, const R& b) {
  bool eq = same_bits(a.depth, b.depth) && same_bits_v(a.translation, b.translation) &&
            same_bits_v(a.normal, b.normal) && same_bits_v(a.witness_p, b.witness_p) &&
            same_bits_v(a.witness_q, b.witness_q) && a.feature_p == b.feature_p && a.feature_q == b.feature_q &&
            a.overlapping == b.overlapping && a.kind == b.kind;
  if constexpr (requires { a.lower_bound; })
    eq = eq && same_bits(a.lower_bound, b.lower_bound) && same_bits(a.upper_bound, b.upper_bound);
  if (eq) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "depth " << a.depth << " vs " << b.depth << ", translation ("
                                       << a.translation.transpose() << ") vs (" << b.translation.transpose()
                                       << "), overlapping " << a.overlapping << " vs " << b.overlapping;
}

/// The message of the InvalidInput f throws, or "(no error)".
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const pendepth::InvalidInput& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace front_test
