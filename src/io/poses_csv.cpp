// Trajectory files (`pendepth trajectory --poses FILE`, docs/design.md §3): one pose per line,
// 2D `x,y,angle_deg` (Q rotated by angle_deg about its origin, then placed at (x, y)) or 3D
// `x,y,z,qw,qx,qy,qz` (Q rotated by the quaternion, normalised, then translated).
//
// The conventions of the batch query files (queries_csv.cpp): blank lines and '#' lines skipped,
// a header accepted only as the first data line and only when it is exactly the expected names,
// any other line exactly N finite numbers separated by ','; errors "SOURCE:LINE: problem". In
// 3D a zero quaternion is an error too (it is no rotation). One pass, std::from_chars per field.
#include <pendepth/io.hpp>

#include "io/printable.hpp"

#include <charconv>
#include <cmath>
#include <utility>

namespace pendepth::io {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// The fields of `row` split at ','.
std::vector<std::string_view> split(std::string_view row) {
  std::vector<std::string_view> f;
  for (;;) {
    const std::size_t comma = row.find(',');
    f.push_back(trim(row.substr(0, comma)));
    if (comma == std::string_view::npos) return f;
    row.remove_prefix(comma + 1);
  }
}

// Rows of names.size() numbers; `each(values, line)` receives every data row.
template <class Each>
void parse_rows(std::string_view text, std::string_view source, std::span<const std::string_view> names,
                std::size_t other, const char* other_why, Each&& each) {
  const std::size_t n = names.size();
  std::string header;
  for (std::string_view x : names) header += (header.empty() ? "" : ",") + std::string(x);
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte-order mark
  bool first_row = true;
  std::size_t line = 0, pos = 0;
  std::vector<double> v(n);
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
    const auto fields = split(row);
    if (first && fields.size() == n && std::equal(fields.begin(), fields.end(), names.begin())) continue;
    const bool letter = (row.front() >= 'a' && row.front() <= 'z') || (row.front() >= 'A' && row.front() <= 'Z');
    const std::string hint = first && letter ? " (a header line must be exactly '" + header + "')" : std::string();
    if (fields.size() != n) {
      std::string why = hint;
      if (fields.size() == other) why = other_why;
      else if (fields.size() == 1 && row.find(';') != std::string_view::npos) why = " (fields are separated by ',', not ';')";
      else if (fields.size() == 1 && row.find('\t') != std::string_view::npos) why = " (fields are separated by ',', not tabs)";
      fail("expected " + std::to_string(n) + " numbers, got " + std::to_string(fields.size()) + why);
    }
    for (std::size_t k = 0; k < n; ++k) {
      const std::string_view f = fields[k];
      if (f.empty()) fail("field " + std::to_string(k + 1) + " is empty");
      const char* b = f.data();
      const char* e = f.data() + f.size();
      if (e - b > 1 && *b == '+' && b[1] != '-') ++b;  // from_chars rejects a leading '+'
      auto [ptr, ec] = std::from_chars(b, e, v[k], std::chars_format::general);
      if (ec == std::errc::invalid_argument || ptr != e)
        fail("field " + std::to_string(k + 1) + " is not a number: '" + detail::printable(f) + "'" + hint);
      if (ec == std::errc::result_out_of_range || !std::isfinite(v[k]))
        fail("field " + std::to_string(k + 1) + " is not a finite number: '" + detail::printable(f) + "'");
    }
    each(v, line, fail);
  }
}

constexpr std::string_view kNames2[] = {"x", "y", "angle_deg"};
constexpr std::string_view kNames3[] = {"x", "y", "z", "qw", "qx", "qy", "qz"};

}  // namespace

std::vector<PoseLine2> parse_poses2_csv(std::string_view text, std::string_view source) {
  std::vector<PoseLine2> out;
  parse_rows(text, source, kNames2, 7, " (a 3D pose x,y,z,qw,qx,qy,qz; the shapes are 2D)",
             [&](const std::vector<double>& v, std::size_t line, auto&&) {
               out.push_back({Vec2(v[0], v[1]), v[2], line});
             });
  return out;
}

std::vector<PoseLine3> parse_poses3_csv(std::string_view text, std::string_view source) {
  std::vector<PoseLine3> out;
  parse_rows(text, source, kNames3, 3, " (a 2D pose x,y,angle_deg; the shapes are 3D)",
             [&](const std::vector<double>& v, std::size_t line, auto&& fail) {
               if (v[3] == 0 && v[4] == 0 && v[5] == 0 && v[6] == 0)
                 fail("the rotation quaternion is zero (it must be a rotation)");
               out.push_back({Vec3(v[0], v[1], v[2]), Eigen::Quaterniond(v[3], v[4], v[5], v[6]), line});
             });
  return out;
}

std::vector<PoseLine2> read_poses2_csv(const std::filesystem::path& path) {
  return parse_poses2_csv(read_text_file(path), path.string());
}

std::vector<PoseLine3> read_poses3_csv(const std::filesystem::path& path) {
  return parse_poses3_csv(read_text_file(path), path.string());
}

}  // namespace pendepth::io
