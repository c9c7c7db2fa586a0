// Mesh file readers for 3D point sets: OBJ, OFF, STL (ASCII and binary) (docs/design.md §3).
//
// Convex algorithms take the hull of the vertices, so only vertex coordinates are read; faces
// and attributes are skipped without being parsed. Text formats are scanned line by line over
// the whole file held in memory, numbers by std::from_chars (no locale, no allocation per line):
// a 10⁶-vertex file parses in a fraction of a second. Every error names the file and the line
// (text) or the byte offset (binary STL).
#include <pendepth/io.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace pendepth::io {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (lower(a[i]) != lower(b[i])) return false;
  return true;
}

// Lines of a text, numbered from 1; the '\n' is dropped (a '\r' before it is a blank).
class Lines {
 public:
  explicit Lines(std::string_view text) : s_(text) {}
  bool next(std::string_view& out) {
    if (pos_ >= s_.size()) return false;
    ++line_;
    const std::size_t e = s_.find('\n', pos_);
    const std::size_t end = e == std::string_view::npos ? s_.size() : e;
    out = s_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return true;
  }
  std::size_t line() const { return line_; }

 private:
  std::string_view s_;
  std::size_t pos_ = 0, line_ = 0;
};

// The text before a '#' comment.
std::string_view strip_comment(std::string_view line) {
  const std::size_t h = line.find('#');
  return h == std::string_view::npos ? line : line.substr(0, h);
}

// Splits `line` at blanks; stores the first N tokens and returns how many there are in all.
template <std::size_t N>
std::size_t split(std::string_view line, std::array<std::string_view, N>& tok) {
  std::size_t count = 0, i = 0;
  const std::size_t n = line.size();
  for (;;) {
    while (i < n && is_blank(line[i])) ++i;
    if (i == n) return count;
    const std::size_t b = i;
    while (i < n && !is_blank(line[i])) ++i;
    if (count < N) tok[count] = line.substr(b, i - b);
    ++count;
  }
}

enum class Num { Ok, NotNumber, NotFinite };

// One decimal number, the whole token. Underflow rounds to 0 or a subnormal (as strtod does);
// overflow, inf and nan are NotFinite.
Num parse_number(std::string_view f, double& x) {
  const char* b = f.data();
  const char* e = f.data() + f.size();
  if (e - b > 1 && *b == '+' && b[1] != '-' && b[1] != '+') ++b;  // from_chars rejects a leading '+'
  auto [ptr, ec] = std::from_chars(b, e, x, std::chars_format::general);
  if (b == e || ec == std::errc::invalid_argument || ptr != e) return Num::NotNumber;
  if (ec == std::errc::result_out_of_range) {  // from_chars does not say which way: ask strtod
    const std::string copy(b, e);
    x = std::strtod(copy.c_str(), nullptr);
  }
  return std::isfinite(x) ? Num::Ok : Num::NotFinite;
}

std::string shorten(std::string_view s) {
  return s.size() > 24 ? std::string(s.substr(0, 24)) + "..." : std::string(s);
}

[[noreturn]] void fail_at(std::string_view source, std::size_t line, const std::string& what) {
  throw InvalidInput(std::string(source) + ":" + std::to_string(line) + ": " + what);
}

[[noreturn]] void fail_binary(std::string_view source, std::size_t offset, const std::string& what) {
  throw InvalidInput(std::string(source) + ": " + what + " (byte offset " + std::to_string(offset) + ")");
}

constexpr const char* kAxis[] = {"x", "y", "z"};

// x y z from tok[0..2] (already counted), the line's vertex; `what` names the record for errors.
Vec3 parse_xyz(const std::string_view* tok, std::string_view source, std::size_t line, const char* what) {
  Vec3 v;
  for (int k = 0; k < 3; ++k) {
    const Num st = parse_number(tok[k], v[k]);
    if (st == Num::NotNumber)
      fail_at(source, line, std::string("malformed ") + what + ": " + kAxis[k] + " is not a number: '" +
                                shorten(tok[k]) + "'");
    if (st == Num::NotFinite)
      fail_at(source, line, std::string(what) + " has a non-finite " + kAxis[k] + ": '" + shorten(tok[k]) + "'");
  }
  return v;
}

// Extra numeric fields (w, colours, normals): numbers, not necessarily finite (they are unused).
void check_numbers(const std::string_view* tok, std::size_t from, std::size_t to, std::string_view source,
                   std::size_t line, const char* what) {
  for (std::size_t k = from; k < to; ++k) {
    double x = 0;
    if (parse_number(tok[k], x) == Num::NotNumber)
      fail_at(source, line, std::string("malformed ") + what + ": field " + std::to_string(k + 1) +
                                " is not a number: '" + shorten(tok[k]) + "'");
  }
}

// Parses an unsigned decimal count (the OFF header); false if the token is not one.
bool parse_count(std::string_view f, std::uint64_t& n) {
  auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), n);
  return !f.empty() && ec == std::errc() && ptr == f.data() + f.size();
}

// ---- STL ----

bool starts_with_solid(std::string_view bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && (is_blank(bytes[i]) || bytes[i] == '\n')) ++i;
  return bytes.size() - i >= 5 && iequals(bytes.substr(i, 5), "solid") &&
         (bytes.size() - i == 5 || is_blank(bytes[i + 5]) || bytes[i + 5] == '\n');
}

// Distinct vertices in order of first appearance; -0 and +0 compare equal (x + 0.0 maps -0 to
// +0). Open addressing with linear probing on the coordinates' bit patterns: several times faster
// than a node-based map on large STL files (docs/benchmarks.md).
class VertexSet {
 public:
  explicit VertexSet(std::size_t expected) {
    points_.reserve(expected);
    keys_.reserve(expected);
    rehash(std::bit_ceil(std::max<std::size_t>(16, 2 * expected)));
  }
  void add(const Vec3& v) {
    const Key k{std::bit_cast<std::uint64_t>(v.x() + 0.0), std::bit_cast<std::uint64_t>(v.y() + 0.0),
                std::bit_cast<std::uint64_t>(v.z() + 0.0)};
    std::size_t i = hash(k) & mask_;
    for (; slots_[i] != kEmpty; i = (i + 1) & mask_)
      if (keys_[slots_[i]] == k) return;
    slots_[i] = points_.size();
    points_.push_back(v);
    keys_.push_back(k);
    if (2 * points_.size() > slots_.size()) rehash(2 * slots_.size());  // load factor <= 1/2
  }
  std::vector<Vec3> take() { return std::move(points_); }

 private:
  using Key = std::array<std::uint64_t, 3>;
  static constexpr std::size_t kEmpty = ~std::size_t(0);
  static std::size_t hash(const Key& k) {
    std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 29) ^ k[1]) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 31) ^ k[2]) * 0x94D049BB133111EBull;
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
  void rehash(std::size_t capacity) {
    slots_.assign(capacity, kEmpty);
    mask_ = capacity - 1;
    for (std::size_t j = 0; j < keys_.size(); ++j) {
      std::size_t i = hash(keys_[j]) & mask_;
      while (slots_[i] != kEmpty) i = (i + 1) & mask_;
      slots_[i] = j;
    }
  }
  std::vector<std::size_t> slots_;
  std::size_t mask_ = 0;
  std::vector<Vec3> points_;
  std::vector<Key> keys_;
};

std::uint32_t read_u32le(const char* p) {
  const auto* u = reinterpret_cast<const unsigned char*>(p);
  return std::uint32_t(u[0]) | std::uint32_t(u[1]) << 8 | std::uint32_t(u[2]) << 16 | std::uint32_t(u[3]) << 24;
}

float read_f32le(const char* p) { return std::bit_cast<float>(read_u32le(p)); }

constexpr std::size_t kStlHeader = 84, kStlTriangle = 50;

std::vector<Vec3> parse_binary_stl(std::string_view bytes, std::string_view source) {
  if (bytes.size() < kStlHeader)
    fail_binary(source, bytes.size(),
                "not an STL file: too short for binary STL (" + std::to_string(bytes.size()) +
                    " bytes, at least 84) and does not begin with 'solid'");
  const std::uint64_t count = read_u32le(bytes.data() + 80);
  const std::uint64_t want = kStlHeader + kStlTriangle * count;
  if (bytes.size() != want)
    fail_binary(source, 80,
                "binary STL of " + std::to_string(count) + " triangles must have " + std::to_string(want) +
                    " bytes, the file has " + std::to_string(bytes.size()));
  VertexSet set(static_cast<std::size_t>(count) / 2 + 4);  // closed meshes: V ≈ F / 2
  for (std::size_t t = 0; t < count; ++t) {
    const std::size_t base = kStlHeader + kStlTriangle * t + 12;  // after the facet normal
    for (std::size_t k = 0; k < 3; ++k) {
      Vec3 v;
      for (std::size_t a = 0; a < 3; ++a) {
        const std::size_t off = base + 12 * k + 4 * a;
        v[a] = read_f32le(bytes.data() + off);
        if (!std::isfinite(v[a]))
          fail_binary(source, off,
                      "triangle " + std::to_string(t) + ", vertex " + std::to_string(k) + ": " + kAxis[a] +
                          " is not a finite number");
      }
      set.add(v);
    }
  }
  return set.take();
}

std::vector<Vec3> parse_ascii_stl(std::string_view text, std::string_view source) {
  enum class State { Outside, Solid, Facet, Loop };
  State state = State::Outside;
  VertexSet set(text.size() / 500 + 4);  // ~ 250 bytes per facet, V ≈ F / 2 for closed meshes
  Lines lines(text);
  std::string_view line;
  std::array<std::string_view, 5> tok;
  std::size_t loop_vertices = 0;
  auto expected = [&]() -> std::string {
    switch (state) {
      case State::Outside: return "'solid'";
      case State::Solid: return "'facet' or 'endsolid'";
      case State::Facet: return "'outer loop' or 'endfacet'";
      case State::Loop: return "'vertex' or 'endloop'";
    }
    return "";
  };
  while (lines.next(line)) {
    const std::size_t n = split(line, tok);
    if (n == 0) continue;
    const std::string_view key = tok[0];
    const std::size_t at = lines.line();
    auto unexpected = [&]() {
      fail_at(source, at, "unexpected '" + shorten(key) + "' (expected " + expected() + ")");
    };
    if (state == State::Loop && iequals(key, "vertex")) {
      if (n != 4)
        fail_at(source, at, "malformed vertex line: expected 'vertex x y z', got " + std::to_string(n - 1) +
                                (n == 2 ? " field" : " fields"));
      set.add(parse_xyz(tok.data() + 1, source, at, "vertex"));
      ++loop_vertices;
    } else if (state == State::Outside && iequals(key, "solid")) {
      state = State::Solid;
    } else if (state == State::Solid && iequals(key, "facet")) {
      state = State::Facet;  // the normal is recomputed by the hull: not read
    } else if (state == State::Solid && iequals(key, "endsolid")) {
      state = State::Outside;
    } else if (state == State::Facet && iequals(key, "outer")) {
      if (n < 2 || !iequals(tok[1], "loop")) fail_at(source, at, "expected 'outer loop'");
      state = State::Loop;
      loop_vertices = 0;
    } else if (state == State::Facet && iequals(key, "endfacet")) {
      state = State::Solid;
    } else if (state == State::Loop && iequals(key, "endloop")) {
      if (loop_vertices < 3)
        fail_at(source, at, "a facet loop has " + std::to_string(loop_vertices) + " vertices (at least 3)");
      state = State::Facet;
    } else {
      unexpected();
    }
  }
  if (state != State::Outside)
    fail_at(source, std::max<std::size_t>(lines.line(), 1),
            "the file ends inside a solid (expected " + expected() + ")");
  return set.take();
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = lower(c);
  return ext;
}

}  // namespace

std::vector<Vec3> parse_obj_points(std::string_view text, std::string_view source) {
  std::vector<Vec3> pts;
  pts.reserve(text.size() / 32);
  Lines lines(text);
  std::string_view line;
  std::array<std::string_view, 8> tok;
  while (lines.next(line)) {
    // Quick reject: only "v" statements matter (vn, vt, vp, f, ... start differently).
    std::size_t i = 0;
    while (i < line.size() && is_blank(line[i])) ++i;
    if (i >= line.size() || line[i] != 'v' || (i + 1 < line.size() && !is_blank(line[i + 1]))) continue;
    const std::size_t n = split(strip_comment(line.substr(i + 1)), tok);
    if (n != 3 && n != 4 && n != 6)
      fail_at(source, lines.line(),
              "malformed vertex line: expected 'v x y z [w]', got " + std::to_string(n) +
                  (n == 1 ? " number" : " numbers"));
    pts.push_back(parse_xyz(tok.data(), source, lines.line(), "vertex line"));
    check_numbers(tok.data(), 3, n, source, lines.line(), "vertex line");
  }
  return pts;
}

std::vector<Vec3> parse_off_points(std::string_view text, std::string_view source) {
  Lines lines(text);
  std::string_view line;
  std::array<std::string_view, 16> tok;
  std::size_t n = 0;

  // Header tokens, read across lines: [keyword [dimension]] vertices faces [edges]; the counts
  // end their line and the vertices start on the next one.
  auto next_line = [&](const char* wanted) {
    for (;;) {
      if (!lines.next(line))
        fail_at(source, std::max<std::size_t>(lines.line(), 1), std::string("the file ends before ") + wanted);
      n = split(strip_comment(line), tok);
      if (n > 0) return;
    }
  };
  next_line("the OFF header");
  std::size_t k = 0;
  std::size_t per_vertex_min = 3, per_vertex_max = 3;
  std::uint64_t unused = 0;
  if (!parse_count(tok[0], unused)) {  // the keyword is optional: a count may come first
    std::string_view key = tok[0];
    const std::string_view full = key;
    bool st = false, colour = false, normal = false, four = false, ndim = false;
    if (key.starts_with("ST")) st = true, key.remove_prefix(2);
    if (key.starts_with("C")) colour = true, key.remove_prefix(1);
    if (key.starts_with("N")) normal = true, key.remove_prefix(1);
    if (key.starts_with("4")) four = true, key.remove_prefix(1);
    if (key.starts_with("n")) ndim = true, key.remove_prefix(1);
    if (key != "OFF")
      fail_at(source, lines.line(), "expected the OFF header keyword ([ST][C][N][4][n]OFF), got '" + shorten(full) + "'");
    if (four) fail_at(source, lines.line(), "4D OFF files (" + std::string(full) + ") are not supported: need 3D points");
    if (n > 1 && tok[1] == "BINARY") fail_at(source, lines.line(), "binary OFF files are not supported");
    per_vertex_min = per_vertex_max = 3 + (normal ? 3 : 0) + (st ? 2 : 0);
    if (colour) per_vertex_min += 1, per_vertex_max += 4;  // colour-map index, RGB or RGBA
    k = 1;
    if (ndim) {
      if (k == n) next_line("the dimension"), k = 0;
      std::uint64_t dim = 0;
      if (!parse_count(tok[k], dim)) fail_at(source, lines.line(), "expected the dimension, got '" + shorten(tok[k]) + "'");
      if (dim != 3)
        fail_at(source, lines.line(), "dimension " + std::to_string(dim) + " is not supported: need 3D points");
      ++k;
    }
    if (k == n) next_line("the vertex count"), k = 0;
  }
  if (n - k < 2 || n - k > 3)
    fail_at(source, lines.line(), "expected the counts 'vertices faces [edges]', got " + std::to_string(n - k) +
                                      (n - k == 1 ? " field" : " fields"));
  std::uint64_t counts[3] = {0, 0, 0};
  static constexpr const char* kCountName[] = {"vertex count", "face count", "edge count"};
  for (std::size_t c = 0; c < n - k; ++c)
    if (!parse_count(tok[k + c], counts[c]))
      fail_at(source, lines.line(),
              std::string("expected the ") + kCountName[c] + " (a non-negative integer), got '" + shorten(tok[k + c]) + "'");

  const std::uint64_t nv = counts[0];
  std::vector<Vec3> pts;
  pts.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(nv, text.size() / 6 + 1)));
  while (pts.size() < nv) {
    if (!lines.next(line))
      fail_at(source, std::max<std::size_t>(lines.line(), 1),
              "the file ends after " + std::to_string(pts.size()) + " of " + std::to_string(nv) + " vertices");
    n = split(strip_comment(line), tok);
    if (n == 0) continue;
    if (n < per_vertex_min || n > per_vertex_max) {
      std::string want = std::to_string(per_vertex_min);
      if (per_vertex_max != per_vertex_min) want += " to " + std::to_string(per_vertex_max);
      fail_at(source, lines.line(),
              "malformed vertex " + std::to_string(pts.size()) + ": expected " + want + " numbers, got " +
                  std::to_string(n));
    }
    pts.push_back(parse_xyz(tok.data(), source, lines.line(), "vertex line"));
    check_numbers(tok.data(), 3, n, source, lines.line(), "vertex line");
  }
  return pts;
}

std::vector<Vec3> parse_stl_points(std::string_view bytes, std::string_view source) {
  if (bytes.size() >= kStlHeader && bytes.size() == kStlHeader + kStlTriangle * std::uint64_t(read_u32le(bytes.data() + 80)))
    return parse_binary_stl(bytes, source);
  if (starts_with_solid(bytes) && bytes.find('\0') == std::string_view::npos) return parse_ascii_stl(bytes, source);
  return parse_binary_stl(bytes, source);  // reports the size mismatch
}

std::vector<Vec3> read_mesh_points(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  const std::string src = path.string();
  if (ext != ".obj" && ext != ".off" && ext != ".stl")
    throw InvalidInput(src + ": unknown 3D shape format '" + path.extension().string() +
                       "' (expected .obj, .off or .stl)");
  const std::string text = read_text_file(path);
  if (ext == ".obj") return parse_obj_points(text, src);
  if (ext == ".off") return parse_off_points(text, src);
  return parse_stl_points(text, src);
}

ConvexPolytope read_convex_polytope(const std::filesystem::path& path, std::string_view name) {
  const std::vector<Vec3> pts = read_mesh_points(path);
  const std::string src = path.string();
  if (pts.size() < 4)
    throw InvalidInput(src + ": " + std::string(name) + ": only " + std::to_string(pts.size()) +
                       (pts.size() == 1 ? " point" : " points") + " (a polytope needs 4 affinely independent points)");
  try {
    return ConvexPolytope::hull(pts, name);
  } catch (const InvalidInput& e) {
    throw InvalidInput(src + ": " + e.what());
  }
}

}  // namespace pendepth::io

namespace pendepth {

// Declared in io.hpp (the library's own OBJ entry point, used by tests and benchmarks).
std::vector<Vec3> read_obj_vertices(const std::string& path) {
  std::vector<Vec3> pts = io::parse_obj_points(io::read_text_file(path), path);
  if (pts.empty()) throw InvalidInput(path + ": no vertex ('v x y z') lines");
  return pts;
}

}  // namespace pendepth
