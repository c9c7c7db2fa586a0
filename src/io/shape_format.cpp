// Which reader a shape file needs: by its extension, or, for standard input and files without an
// extension (a pipe, /dev/stdin, a process substitution), by its first bytes (docs/design.md §3).
#include <pendepth/io.hpp>

#include <cctype>
#include <cstdint>

namespace pendepth::io {
namespace {

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

// [ST][C][N][4][n]OFF, as parse_off_points reads it (4OFF and nOFF included: that reader names
// the problem).
bool is_off_keyword(std::string_view k) {
  if (k.starts_with("ST")) k.remove_prefix(2);
  if (k.starts_with("C")) k.remove_prefix(1);
  if (k.starts_with("N")) k.remove_prefix(1);
  if (k.starts_with("4")) k.remove_prefix(1);
  if (k.starts_with("n")) k.remove_prefix(1);
  return k == "OFF";
}

bool is_obj_keyword(std::string_view k) {
  static constexpr std::string_view kObj[] = {"v", "vt", "vn", "vp", "f", "fo", "l", "p", "o", "g", "s",
                                              "mg", "usemtl", "mtllib", "cstype", "deg", "curv", "curv2",
                                              "surf", "call", "csh", "maplib", "usemap", "lod"};
  for (std::string_view o : kObj)
    if (k == o) return true;
  return false;
}

bool is_wkt_type(std::string_view k) {
  for (std::string_view t : {"POLYGON", "MULTIPOLYGON", "POINT", "MULTIPOINT", "LINESTRING", "MULTILINESTRING",
                             "GEOMETRYCOLLECTION", "TRIANGLE", "TIN", "POLYHEDRALSURFACE"})
    if (iequals(k, t)) return true;
  return false;
}

}  // namespace

std::optional<ShapeFormat> shape_format_of(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".wkt") return ShapeFormat::Wkt;
  if (ext == ".obj") return ShapeFormat::Obj;
  if (ext == ".off") return ShapeFormat::Off;
  if (ext == ".stl") return ShapeFormat::Stl;
  if (ext == ".ply") return ShapeFormat::Ply;
  return std::nullopt;
}

std::optional<ShapeFormat> guess_shape_format(std::string_view bytes) {
  // PLY: the header's first line is exactly `ply` (binary bodies follow the header, so this comes
  // before the STL size test).
  if (bytes.starts_with("ply\n") || bytes.starts_with("ply\r\n")) return ShapeFormat::Ply;
  // Binary STL: exactly 84 + 50·count bytes, count the little-endian uint32 at byte 80.
  if (bytes.size() >= 84) {
    const auto* u = reinterpret_cast<const unsigned char*>(bytes.data() + 80);
    const std::uint64_t count = std::uint32_t(u[0]) | std::uint32_t(u[1]) << 8 | std::uint32_t(u[2]) << 16 |
                                std::uint32_t(u[3]) << 24;
    if (bytes.size() == 84 + 50 * count) return ShapeFormat::Stl;
  }
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);  // UTF-8 byte-order mark (WKT)
  // The first word, past blank lines and '#' comment lines (OBJ and OFF have them).
  std::size_t i = 0;
  for (;;) {
    while (i < bytes.size() && is_space(bytes[i])) ++i;
    if (i < bytes.size() && bytes[i] == '#') {
      while (i < bytes.size() && bytes[i] != '\n') ++i;
      continue;
    }
    break;
  }
  if (i == bytes.size()) return std::nullopt;
  std::size_t e = i;
  while (e < bytes.size() && !is_space(bytes[e]) && bytes[e] != '(' && bytes[e] != '#') ++e;
  const std::string_view word = bytes.substr(i, e - i);
  if (is_wkt_type(word)) return ShapeFormat::Wkt;
  if (iequals(word, "solid")) return ShapeFormat::Stl;
  if (is_off_keyword(word)) return ShapeFormat::Off;
  if (is_obj_keyword(word)) return ShapeFormat::Obj;
  if (!word.empty() && word.find_first_not_of("0123456789") == std::string_view::npos) return ShapeFormat::Off;
  return std::nullopt;
}

}  // namespace pendepth::io
