// Private: the rows of the numeric CSV files of src/io (batch queries, trajectory poses), read one
// way. Blank lines and '#' lines are skipped; a header is accepted only as the first data line
// and only when it is exactly the expected names (spaces and tabs around a name allowed); every
// other line is exactly N numbers separated by ',' (src/io/number.hpp: nearest double, underflow
// rounds, inf / nan / overflow rejected); a UTF-8 byte-order mark is skipped. Errors are
// InvalidInput "SOURCE:LINE: problem", with hints for ';' and tab separators, a header that is
// not the expected one, and a row of the other dimension's length. One pass, no allocation per
// row.
#pragma once

#include <pendepth/geometry.hpp>

#include "io/number.hpp"
#include "io/printable.hpp"

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

namespace pendepth::io::detail {

inline std::string_view trim_blanks(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

/// The layout of one kind of file: its header names, and the row length of the other
/// dimension's files with the hint naming them (e.g. " (a 3D query; the shapes are 2D)").
template <std::size_t N>
struct CsvLayout {
  std::array<std::string_view, N> names;
  std::size_t other_count;
  std::string_view other_hint;
};

/// Calls each(values, line, fail) for every data row; values is a const double (&)[N], fail a
/// callable throwing "SOURCE:LINE: what" for row checks of the caller's own.
template <std::size_t N, class Each>
void parse_csv_rows(std::string_view text, std::string_view source, const CsvLayout<N>& layout, Each&& each) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte-order mark
  std::string header;
  for (std::string_view x : layout.names) {
    if (!header.empty()) header += ',';
    header += x;
  }
  bool first_row = true;  // only the first non-comment row may be a header
  std::size_t line = 0, pos = 0;
  auto fail = [&](const std::string& what) {
    throw InvalidInput(std::string(source) + ":" + std::to_string(line) + ": " + what);
  };
  auto is_header = [&](std::string_view row) {
    for (std::size_t k = 0; k < N; ++k) {
      const std::size_t comma = row.find(',');
      if ((comma == std::string_view::npos) != (k + 1 == N)) return false;
      if (trim_blanks(row.substr(0, comma)) != layout.names[k]) return false;
      if (comma != std::string_view::npos) row.remove_prefix(comma + 1);
    }
    return true;
  };
  while (pos < text.size()) {
    ++line;
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view row = trim_blanks(text.substr(pos, end - pos));
    pos = end + 1;
    if (row.empty() || row.front() == '#') continue;
    const bool first = std::exchange(first_row, false);
    if (first && is_header(row)) continue;
    // A first row starting with a letter may be meant as a header: say which one is accepted.
    const bool letter = (row.front() >= 'a' && row.front() <= 'z') || (row.front() >= 'A' && row.front() <= 'Z');
    const std::string hint = first && letter ? " (a header line must be exactly '" + header + "')" : std::string();
    std::size_t count = 1;
    for (char c : row) count += c == ',';
    if (count != N) {
      std::string why;
      if (count == layout.other_count) why = layout.other_hint;
      else if (count == 1 && row.find(';') != std::string_view::npos) why = " (fields are separated by ',', not ';')";
      else if (count == 1 && row.find('\t') != std::string_view::npos) why = " (fields are separated by ',', not tabs)";
      fail("expected " + std::to_string(N) + " numbers, got " + std::to_string(count) + (why.empty() ? hint : why));
    }
    double v[N];
    std::string_view rest = row;
    for (std::size_t k = 0; k < N; ++k) {
      const std::size_t comma = rest.find(',');
      const std::string_view f = trim_blanks(rest.substr(0, comma));
      rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
      if (f.empty()) fail("field " + std::to_string(k + 1) + " is empty");
      const char* stop = nullptr;
      const Decimal st = read_decimal(f.data(), f.data() + f.size(), v[k], stop);
      if (st == Decimal::NotNumber || stop != f.data() + f.size())
        fail("field " + std::to_string(k + 1) + " is not a number: '" + printable(f) + "'" + hint);
      if (st != Decimal::Ok) fail("field " + std::to_string(k + 1) + " is not a finite number: '" + printable(f) + "'");
    }
    each(v, line, fail);
  }
}

}  // namespace pendepth::io::detail
