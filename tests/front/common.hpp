// Shared by the front-door tests: bitwise comparison of doubles and the message of an error.
#pragma once

#include <pendepth/geometry.hpp>

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
