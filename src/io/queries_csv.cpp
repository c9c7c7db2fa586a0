// Batch query files: one `x,y,dx,dy` (2D) or `x,y,z,dx,dy,dz` (3D) per line (docs/design.md §3,
// `pendepth batch`).
//
// One pass over the text, std::from_chars per field, no allocation per line, so 10⁵ queries
// parse in milliseconds. Errors name the source line. A header is accepted only as the first data
// line and only when it is exactly the expected names: anything else that is not numbers (a
// misspelt header, ';' separators, quoted fields, hexadecimal, a binary file) is an error, never
// silently skipped.
#include <pendepth/io.hpp>

#include "io/number.hpp"
#include "io/printable.hpp"

#include <charconv>
#include <cmath>
#include <span>
#include <utility>

namespace pendepth::io {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

enum class Field { Ok, Empty, NotNumber, NotFinite };

Field parse_field(std::string_view f, double& x) {
  f = trim(f);
  if (f.empty()) return Field::Empty;
  const char* end = nullptr;
  const auto st = detail::read_decimal(f.data(), f.data() + f.size(), x, end);  // src/io/number.hpp
  if (st == detail::Decimal::NotNumber || end != f.data() + f.size()) return Field::NotNumber;
  return st == detail::Decimal::Ok ? Field::Ok : Field::NotFinite;  // inf, nan or overflow
}

std::string shorten(std::string_view s) { return detail::printable(trim(s)); }

// The header names of a row of N fields: offset then direction.
constexpr std::string_view kNames4[] = {"x", "y", "dx", "dy"};
constexpr std::string_view kNames6[] = {"x", "y", "z", "dx", "dy", "dz"};

// True if `row` is exactly the header names, fields trimmed of spaces and tabs.
template <std::size_t N>
bool is_header(std::string_view row) {
  const auto& names = N == 4 ? std::span<const std::string_view>(kNames4) : std::span<const std::string_view>(kNames6);
  for (std::size_t k = 0; k < N; ++k) {
    const std::size_t comma = row.find(',');
    if ((comma == std::string_view::npos) != (k + 1 == N)) return false;
    if (trim(row.substr(0, comma)) != names[k]) return false;
    if (comma != std::string_view::npos) row.remove_prefix(comma + 1);
  }
  return true;
}

template <std::size_t N>
std::string header_text() {
  std::string h;
  for (std::string_view n : N == 4 ? std::span<const std::string_view>(kNames4) : std::span<const std::string_view>(kNames6)) {
    if (!h.empty()) h += ',';
    h += n;
  }
  return h;
}

// Rows of N = 2·dim numbers: offset then direction. `Query` is Query2 or Query3.
template <class Query, std::size_t N>
std::vector<Query> parse_rows(std::string_view text, std::string_view source) {
  constexpr std::size_t kOther = N == 4 ? 6 : 4;  // the other dimension's row length
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte-order mark
  std::vector<Query> out;
  out.reserve(text.size() / (4 * N));
  bool first_row = true;  // only the first non-comment row may be a header
  std::size_t line = 0, pos = 0;
  auto fail = [&](const std::string& what) {
    throw InvalidInput(std::string(source) + ":" + std::to_string(line) + ": " + what);
  };
  while (pos < text.size()) {
    ++line;
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view row = trim(text.substr(pos, end - pos));
    pos = end + 1;
    if (row.empty() || row.front() == '#') continue;
    const bool first = std::exchange(first_row, false);
    if (first && is_header<N>(row)) continue;
    // A first row starting with a letter may be meant as a header: say which one is accepted.
    const bool letter = (row.front() >= 'a' && row.front() <= 'z') || (row.front() >= 'A' && row.front() <= 'Z');
    const std::string hint =
        first && letter ? " (a header line must be exactly '" + header_text<N>() + "')" : std::string();

    std::size_t count = 1;
    for (char c : row) count += c == ',';
    if (count != N) {
      std::string why;
      if (count == kOther) why = N == 4 ? " (a 3D query; the shapes are 2D)" : " (a 2D query; the shapes are 3D)";
      else if (count == 1 && row.find(';') != std::string_view::npos) why = " (fields are separated by ',', not ';')";
      else if (count == 1 && row.find('\t') != std::string_view::npos) why = " (fields are separated by ',', not tabs)";
      fail("expected " + std::to_string(N) + " numbers, got " + std::to_string(count) + (why.empty() ? hint : why));
    }
    double v[N];
    std::string_view rest = row;
    for (std::size_t k = 0; k < N; ++k) {
      const std::size_t comma = rest.find(',');
      const std::string_view f = rest.substr(0, comma);
      rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
      double x = 0;
      const Field st = parse_field(f, x);
      if (st == Field::Empty) fail("field " + std::to_string(k + 1) + " is empty");
      if (st == Field::NotNumber)
        fail("field " + std::to_string(k + 1) + " is not a number: '" + shorten(f) + "'" + hint);
      if (st == Field::NotFinite)
        fail("field " + std::to_string(k + 1) + " is not a finite number: '" + shorten(f) + "'");
      v[k] = x;
    }
    Query q;
    for (std::size_t k = 0; k < N / 2; ++k) {
      q.t[k] = v[k];
      q.d[k] = v[N / 2 + k];
    }
    q.line = line;
    out.push_back(q);
  }
  return out;
}

}  // namespace

std::vector<Query2> parse_queries_csv(std::string_view text, std::string_view source) {
  return parse_rows<Query2, 4>(text, source);
}

std::vector<Query3> parse_queries3_csv(std::string_view text, std::string_view source) {
  return parse_rows<Query3, 6>(text, source);
}

std::vector<Query3> read_queries3_csv(const std::filesystem::path& path) {
  return parse_queries3_csv(read_text_file(path), path.string());
}

std::vector<Query2> read_queries_csv(const std::filesystem::path& path) {
  return parse_queries_csv(read_text_file(path), path.string());
}

}  // namespace pendepth::io
