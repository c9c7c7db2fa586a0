// Private: one decimal number of an input file, read the same way by every reader of src/io (WKT,
// CSV, OBJ/OFF/STL/PLY): the nearest double, as strtod rounds it. A value below the double range
// rounds to a subnormal or 0 (a tiny coordinate is a tiny coordinate, as in Python's float() and
// numpy); one above it, and "inf" / "nan", are not finite and every reader rejects them.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <system_error>

namespace pendepth::io::detail {

enum class Decimal { Ok, NotNumber, NotFinite, Overflow };

/// Reads the longest number at [first, last) (a leading '+' allowed) into x and sets `end` past
/// it. NotNumber when no number starts at first; NotFinite for inf/nan; Overflow beyond ±DBL_MAX.
inline Decimal read_decimal(const char* first, const char* last, double& x, const char*& end) {
  const char* b = first;
  if (last - b > 1 && *b == '+' && b[1] != '-' && b[1] != '+') ++b;  // from_chars rejects a leading '+'
  auto [ptr, ec] = std::from_chars(b, last, x, std::chars_format::general);
  end = ptr;
  if (ec == std::errc::invalid_argument || ptr == b) {
    end = first;
    return Decimal::NotNumber;
  }
  if (ec == std::errc::result_out_of_range) {  // from_chars does not say which way: ask strtod
    x = std::strtod(std::string(b, ptr).c_str(), nullptr);
    if (!std::isfinite(x)) return Decimal::Overflow;
  }
  return std::isfinite(x) ? Decimal::Ok : Decimal::NotFinite;
}

}  // namespace pendepth::io::detail
