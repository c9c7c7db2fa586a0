// Private: the WKT scanner shared by the readers of wkt.cpp (POLYGON) and wkt_geometry.cpp
// (MULTIPOLYGON, GEOMETRYCOLLECTION, ...): whitespace skipping with a running line counter,
// keywords, numbers through std::from_chars, errors as InvalidInput "SOURCE:LINE: problem".
#pragma once

#include <pendepth/geometry.hpp>

#include "io/number.hpp"
#include "io/printable.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

namespace pendepth::io::wkt_detail {


inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
inline bool is_delim(char c) { return is_space(c) || c == ',' || c == '(' || c == ')'; }
inline bool is_alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }

inline bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

class Scanner {
 public:
  Scanner(std::string_view text, std::string_view source) : s_(text), src_(source) {}

  // Skips whitespace, counting lines; returns the next character or '\0' at the end (a NUL byte
  // in the text is returned as '\0' too but is not the end: at_end() tells them apart, and
  // token() shows it as \x00).
  char peek() {
    while (pos_ < s_.size() && is_space(s_[pos_])) {
      if (s_[pos_] == '\n') ++line_;
      ++pos_;
    }
    return pos_ < s_.size() ? s_[pos_] : '\0';
  }
  bool at_end() { return peek() == '\0' && pos_ >= s_.size(); }
  std::size_t line() const { return line_; }
  void advance() { ++pos_; }

  // The next token, for messages: up to a delimiter (or the delimiter itself), shortened, bytes
  // that are not printable ASCII (a NUL, a control character) shown as \xNN.
  std::string token() {
    if (at_end()) return "end of input";
    std::size_t e = pos_;
    while (e < s_.size() && !is_delim(s_[e])) ++e;
    if (e == pos_) e = pos_ + 1;
    std::string t = "'";
    t += detail::printable(s_.substr(pos_, e - pos_));
    t += '\'';
    return t;
  }

  std::string_view word() {
    peek();
    std::size_t b = pos_;
    while (pos_ < s_.size() && is_alpha(s_[pos_])) ++pos_;
    return s_.substr(b, pos_ - b);
  }

  void expect(char c, const std::string& where) {
    if (peek() != c) fail("missing '" + std::string(1, c) + "' " + where + ", got " + token());
    ++pos_;
  }

  double number(const char* what) {
    peek();
    const char* first = s_.data() + pos_;
    const char* last = s_.data() + s_.size();
    double x = 0;
    const char* ptr = nullptr;
    const auto st = detail::read_decimal(first, last, x, ptr);  // src/io/number.hpp: underflow rounds
    if (st == detail::Decimal::NotNumber || (ptr < last && !is_delim(*ptr)))
      fail(std::string("expected a number for ") + what + ", got " + token());
    if (st == detail::Decimal::Overflow) fail("number out of range " + token());
    if (st == detail::Decimal::NotFinite) fail("non-finite number " + token());
    pos_ = static_cast<std::size_t>(ptr - s_.data());
    return x;
  }

  bool number_follows() {
    char c = peek();
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
  }

  [[noreturn]] void fail(const std::string& what) const { fail_at(line_, what); }
  [[noreturn]] void fail_at(std::size_t line, const std::string& what) const {
    throw InvalidInput(std::string(src_) + ":" + std::to_string(line) + ": " + what);
  }

 private:
  std::string_view s_, src_;
  std::size_t pos_ = 0, line_ = 1;
};

}  // namespace pendepth::io::wkt_detail
