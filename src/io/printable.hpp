// Private: input text quoted safely in error messages (readers of src/io). Error messages are one
// line on a terminal: a byte of the input that is not printable ASCII (a NUL, a newline, an escape
// sequence, a stray byte of a binary file) would cut, split or garble it, so it is shown as \xNN.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace pendepth::io::detail {

/// `s` with every byte outside printable ASCII (0x20–0x7E) written as \xNN (two hex digits),
/// cut after `max` input bytes with "..." appended. O(min(|s|, max)).
inline std::string printable(std::string_view s, std::size_t max = 24) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  const std::size_t n = s.size() < max ? s.size() : max;
  out.reserve(n + 3);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7F) {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 0xF];
    }
  }
  if (s.size() > max) out += "...";
  return out;
}

}  // namespace pendepth::io::detail
