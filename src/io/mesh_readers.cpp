// Mesh file readers for 3D point sets: OBJ, OFF, STL (ASCII and binary) (docs/design.md §3).
//
// Convex algorithms take the hull of the vertices, so only vertex coordinates are read; faces
// and attributes are skipped without being parsed. Text formats are scanned line by line over
// the whole file held in memory, numbers by std::from_chars (no locale, no allocation per line):
// a 10⁶-vertex file parses in a fraction of a second. Every error names the file and the line
// (text) or the byte offset (binary STL).
#include <pendepth/io.hpp>

#include "io/number.hpp"
#include "io/printable.hpp"

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

// The blank-separated tokens of a line, one at a time (for lines of any length).
class Tokens {
 public:
  explicit Tokens(std::string_view line) : s_(line) {}
  bool next(std::string_view& out) {
    while (i_ < s_.size() && is_blank(s_[i_])) ++i_;
    if (i_ == s_.size()) return false;
    const std::size_t b = i_;
    while (i_ < s_.size() && !is_blank(s_[i_])) ++i_;
    out = s_.substr(b, i_ - b);
    return true;
  }

 private:
  std::string_view s_;
  std::size_t i_ = 0;
};

enum class Num { Ok, NotNumber, NotFinite };

// One decimal number, the whole token (src/io/number.hpp: underflow rounds to 0 or a subnormal;
// overflow, inf and nan are NotFinite).
Num parse_number(std::string_view f, double& x) {
  const char* end = nullptr;
  const auto st = detail::read_decimal(f.data(), f.data() + f.size(), x, end);
  if (st == detail::Decimal::NotNumber || end != f.data() + f.size()) return Num::NotNumber;
  return st == detail::Decimal::Ok ? Num::Ok : Num::NotFinite;  // inf, nan or overflow
}

std::string shorten(std::string_view s) { return detail::printable(s); }

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
  std::size_t add(const Vec3& v) {
    const Key k{std::bit_cast<std::uint64_t>(v.x() + 0.0), std::bit_cast<std::uint64_t>(v.y() + 0.0),
                std::bit_cast<std::uint64_t>(v.z() + 0.0)};
    std::size_t i = hash(k) & mask_;
    for (; slots_[i] != kEmpty; i = (i + 1) & mask_)
      if (keys_[slots_[i]] == k) return slots_[i];
    const std::size_t id = points_.size();
    slots_[i] = id;
    points_.push_back(v);
    keys_.push_back(k);
    if (2 * points_.size() > slots_.size()) rehash(2 * slots_.size());  // load factor <= 1/2
    return id;
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

std::vector<Vec3> parse_binary_stl(std::string_view bytes, std::string_view source, MeshFile* mesh = nullptr) {
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
    if (mesh) mesh->begin_face(base - 12);
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
      const std::size_t id = set.add(v);
      if (mesh) mesh->indices.push_back(id);
    }
  }
  return set.take();
}

// solid [name] { facet normal nx ny nz / outer loop / vertex x y z (3 times) / endloop / endfacet }
// endsolid [name], several solids allowed; keywords case-insensitive, one statement per line.
std::vector<Vec3> parse_ascii_stl(std::string_view text, std::string_view source, MeshFile* mesh = nullptr) {
  enum class State { Outside, Solid, Facet, Loop, LoopDone };
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
      case State::Facet: return "'outer loop'";
      case State::Loop: return loop_vertices < 3 ? "'vertex'" : "'endloop'";
      case State::LoopDone: return "'endfacet'";
    }
    return "";
  };
  while (lines.next(line)) {
    const std::size_t n = split(line, tok);
    if (n == 0) continue;
    const std::string_view key = tok[0];
    const std::size_t at = lines.line();
    auto malformed = [&](const char* form) {
      std::string_view text = line;
      while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
      while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
      fail_at(source, at, std::string("expected '") + form + "', got '" + detail::printable(text, 40) + "'");
    };
    if (state == State::Loop && loop_vertices < 3 && iequals(key, "vertex")) {
      if (n != 4)
        fail_at(source, at, "malformed vertex line: expected 'vertex x y z', got " + std::to_string(n - 1) +
                                (n == 2 ? " field" : " fields"));
      const std::size_t id = set.add(parse_xyz(tok.data() + 1, source, at, "vertex"));
      if (mesh) mesh->indices.push_back(id);
      ++loop_vertices;
    } else if (state == State::Outside && iequals(key, "solid")) {
      state = State::Solid;  // the name, if any, is free text
    } else if (state == State::Solid && iequals(key, "facet")) {
      // The normal is recomputed by the hull: checked to be three numbers, not read.
      if (n != 5 || !iequals(tok[1], "normal")) malformed("facet normal nx ny nz");
      check_numbers(tok.data(), 2, 5, source, at, "facet normal");
      if (mesh) mesh->begin_face(at);
      state = State::Facet;
    } else if (state == State::Solid && iequals(key, "endsolid")) {
      state = State::Outside;
    } else if (state == State::Facet && iequals(key, "outer")) {
      if (n != 2 || !iequals(tok[1], "loop")) malformed("outer loop");
      state = State::Loop;
      loop_vertices = 0;
    } else if (state == State::Loop && loop_vertices == 3 && iequals(key, "endloop")) {
      if (n != 1) malformed("endloop");
      state = State::LoopDone;
    } else if (state == State::LoopDone && iequals(key, "endfacet")) {
      if (n != 1) malformed("endfacet");
      state = State::Solid;
    } else if (state == State::Loop && iequals(key, "endloop")) {
      fail_at(source, at, "a facet loop has " + std::to_string(loop_vertices) + " vertices (STL facets are triangles)");
    } else if (state == State::Loop && iequals(key, "vertex")) {
      fail_at(source, at, "a facet loop has more than 3 vertices (STL facets are triangles)");
    } else {
      fail_at(source, at, "unexpected '" + shorten(key) + "' (expected " + expected() + ")");
    }
  }
  if (state != State::Outside)
    fail_at(source, std::max<std::size_t>(lines.line(), 1),
            "the file ends inside a solid (expected " + expected() + ")");
  return set.take();
}

}  // namespace

namespace {

// Statements of the OBJ specification (Wavefront, appendix B1) that pendepth does not use: they
// are accepted without being read. Anything else is an error (a file that is not OBJ at all).
bool known_obj_statement(std::string_view k) {
  static constexpr std::string_view kKnown[] = {
      "vp",     "cstype", "deg",      "bmat",     "step",     "curv",  "curv2",      "surf",
      "parm",   "trim",   "hole",     "scrv",     "sp",       "end",   "con",        "g",
      "s",      "mg",     "o",        "bevel",    "c_interp", "d_interp", "lod",     "usemtl",
      "mtllib", "shadow_obj", "trace_obj", "ctech", "stech",  "maplib", "usemap",   "call",
      "csh"};
  for (std::string_view s : kKnown)
    if (k == s) return true;
  return false;
}

// One vertex reference of an element: v, v/vt, v//vn or v/vt/vn (`parts` of them allowed: 1 for
// points, 2 for lines, 3 for faces), each a non-zero integer, negative = relative to the vertices
// read so far. Returns false if malformed; stores the absolute 1-based indices (0 = absent).
bool parse_obj_ref(std::string_view r, int parts, const std::array<std::uint64_t, 3>& count,
                   std::array<std::int64_t, 3>& idx) {
  idx = {0, 0, 0};
  std::array<std::string_view, 3> f;
  int slashes = 0;
  for (;;) {
    const std::size_t slash = r.find('/');
    f[slashes] = r.substr(0, slash);
    if (slash == std::string_view::npos) break;
    if (++slashes >= parts) return false;
    r.remove_prefix(slash + 1);
  }
  for (int k = 0; k <= slashes; ++k) {
    if (f[k].empty()) {
      if (k == 1 && slashes == 2) continue;  // v//vn
      return false;
    }
    std::int64_t i = 0;
    auto [ptr, ec] = std::from_chars(f[k].data(), f[k].data() + f[k].size(), i);
    if (ec != std::errc() || ptr != f[k].data() + f[k].size() || i == 0) return false;
    // Relative: -1 is the last one read so far; before the first one is out of range (-1 here).
    const auto n = static_cast<std::int64_t>(count[k]);
    if (i < 0) i = i >= -n ? n + i + 1 : -1;
    idx[k] = i;
  }
  return true;
}

}  // namespace

namespace {

std::vector<Vec3> parse_obj(std::string_view text, std::string_view source, MeshFile* mesh) {
  std::vector<Vec3> pts;
  pts.reserve(text.size() / 32);
  Lines lines(text);
  std::string_view line;
  std::array<std::string_view, 8> tok;
  // Vertices, texture vertices, normals read so far; the largest positive reference of each kind
  // and its line, checked at the end (an element may name a vertex defined further down).
  std::array<std::uint64_t, 3> count = {0, 0, 0};
  std::array<std::int64_t, 3> max_ref = {0, 0, 0};
  std::array<std::size_t, 3> max_ref_line = {0, 0, 0};
  static constexpr const char* kKind[] = {"vertex", "texture vertex", "normal"};
  static constexpr const char* kKinds[] = {"vertices", "texture vertices", "normals"};
  while (lines.next(line)) {
    const std::string_view body = strip_comment(line);
    const std::size_t n = split(body, tok);
    if (n == 0) continue;
    const std::string_view key = tok[0];
    const std::size_t at = lines.line();
    std::string_view end = body;
    while (!end.empty() && is_blank(end.back())) end.remove_suffix(1);
    if (end.ends_with('\\'))
      fail_at(source, at, "line continuation ('\\' at the end of a line) is not supported");
    if (key == "v") {
      if (n != 4 && n != 5 && n != 7)
        fail_at(source, at,
                "malformed vertex line: expected 'v x y z [w]', got " + std::to_string(n - 1) +
                    (n == 2 ? " number" : " numbers"));
      pts.push_back(parse_xyz(tok.data() + 1, source, at, "vertex line"));
      check_numbers(tok.data() + 1, 3, n - 1, source, at, "vertex line");
      ++count[0];
    } else if (key == "vt" || key == "vn") {
      const bool normal = key == "vn";
      if (normal ? n != 4 : (n < 2 || n > 4))
        fail_at(source, at,
                std::string("malformed ") + (normal ? "normal line: expected 'vn i j k'" : "texture vertex line: expected 'vt u [v [w]]'") +
                    ", got " + std::to_string(n - 1) + (n == 2 ? " number" : " numbers"));
      check_numbers(tok.data() + 1, 0, n - 1, source, at, normal ? "normal line" : "texture vertex line");
      ++count[normal ? 2 : 1];
    } else if (key == "f" || key == "fo" || key == "l" || key == "p") {
      const bool face = key[0] == 'f';
      const int parts = face ? 3 : key == "l" ? 2 : 1;
      const std::size_t min_refs = face ? 3 : key == "l" ? 2 : 1;
      const char* what = face ? "face" : key == "l" ? "line element" : "point element";
      std::size_t refs = 0;
      if (mesh && face) mesh->begin_face(at);
      Tokens t(body);
      std::string_view r;
      t.next(r);  // the keyword
      while (t.next(r)) {
        ++refs;
        std::array<std::int64_t, 3> idx;
        if (!parse_obj_ref(r, parts, count, idx))
          fail_at(source, at,
                  std::string("malformed ") + what + ": reference " + std::to_string(refs) + " is '" + shorten(r) +
                      (face ? "' (expected v, v/vt, v//vn or v/vt/vn with non-zero integers)"
                            : parts == 2 ? "' (expected v or v/vt with non-zero integers)"
                                         : "' (expected a non-zero integer)"));
        for (int k = 0; k < 3; ++k) {
          if (idx[k] < 0)
            fail_at(source, at,
                    std::string(what) + " reference " + std::to_string(refs) + " ('" + shorten(r) + "') names a " +
                        kKind[k] + " before the first (" + std::to_string(count[k]) + " " + kKinds[k] +
                        " read so far)");
          if (idx[k] > max_ref[k]) max_ref[k] = idx[k], max_ref_line[k] = at;
        }
        if (mesh && face) mesh->indices.push_back(static_cast<std::size_t>(idx[0] - 1));
      }
      if (refs < min_refs)
        fail_at(source, at,
                std::string("malformed ") + what + ": " + std::to_string(refs) + " vertex reference" +
                    (refs == 1 ? "" : "s") + " (at least " + std::to_string(min_refs) + ")");
    } else if (!known_obj_statement(key)) {
      fail_at(source, at, "unknown OBJ statement '" + shorten(key) + "'");
    }
  }
  for (int k = 0; k < 3; ++k)
    if (max_ref[k] > 0 && static_cast<std::uint64_t>(max_ref[k]) > count[k])
      fail_at(source, max_ref_line[k],
              std::string("reference to ") + kKind[k] + " " + std::to_string(max_ref[k]) + ", but the file has " +
                  std::to_string(count[k]) + " " + kKinds[k]);
  return pts;
}

std::vector<Vec3> parse_off(std::string_view text, std::string_view source, MeshFile* mesh) {
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

  const std::uint64_t nv = counts[0], nf = counts[1];
  const std::size_t header_line = lines.line();
  const auto declared = [&] {
    return " (the header at line " + std::to_string(header_line) + " declares " + std::to_string(nv) +
           (nv == 1 ? " vertex and " : " vertices and ") + std::to_string(nf) + (nf == 1 ? " face)" : " faces)");
  };
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

  // Faces: `k i_1 ... i_k [colour]`, k >= 3, indices 0-based below the vertex count, the colour
  // a colour-map index, RGB or RGBA (0, 1, 3 or 4 numbers). Faces are checked, not kept.
  for (std::uint64_t f = 0; f < nf;) {
    if (!lines.next(line))
      fail_at(source, std::max<std::size_t>(lines.line(), 1),
              "the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    const std::string_view body = strip_comment(line);
    Tokens t(body);
    std::string_view w;
    if (!t.next(w)) continue;
    const std::string face = "face " + std::to_string(f);
    std::uint64_t k = 0;
    if (mesh) mesh->begin_face(lines.line());
    if (!parse_count(w, k))
      fail_at(source, lines.line(),
              "malformed " + face + ": expected its vertex count (an integer), got '" + shorten(w) + "'" + declared());
    if (k < 3) fail_at(source, lines.line(), "malformed " + face + ": " + std::to_string(k) + (k == 1 ? " vertex" : " vertices") + " (at least 3)" + declared());
    for (std::uint64_t j = 0; j < k; ++j) {
      std::uint64_t v = 0;
      if (!t.next(w))
        fail_at(source, lines.line(),
                "malformed " + face + ": only " + std::to_string(j) + " of its " + std::to_string(k) + " vertex indices" +
                    declared());
      if (!parse_count(w, v))
        fail_at(source, lines.line(),
                "malformed " + face + ": vertex index " + std::to_string(j) + " is '" + shorten(w) +
                    "' (expected a non-negative integer)" + declared());
      if (v >= nv)
        fail_at(source, lines.line(),
                face + ": vertex index " + std::to_string(v) + " is out of range (the file has " + std::to_string(nv) +
                    (nv == 1 ? " vertex)" : " vertices)") + declared());
      if (mesh) mesh->indices.push_back(static_cast<std::size_t>(v));
    }
    std::size_t colour = 0;
    for (; t.next(w); ++colour) {
      double x = 0;
      if (parse_number(w, x) == Num::NotNumber)
        fail_at(source, lines.line(),
                "malformed " + face + ": '" + shorten(w) + "' after its " + std::to_string(k) +
                    " vertex indices is not a colour number" + declared());
    }
    if (colour == 2 || colour > 4)
      fail_at(source, lines.line(),
              "malformed " + face + ": " + std::to_string(k) + " vertex indices then " + std::to_string(colour) +
                  " numbers (a colour is 0, 1, 3 or 4 numbers)" + declared());
    ++f;
  }
  while (lines.next(line))
    if (split(strip_comment(line), tok) > 0)
      fail_at(source, lines.line(),
              "unexpected '" + shorten(tok[0]) + "' after the last face" + declared());
  return pts;
}

std::vector<Vec3> parse_stl(std::string_view bytes, std::string_view source, MeshFile* mesh) {
  const bool binary =
      bytes.size() >= kStlHeader && bytes.size() == kStlHeader + kStlTriangle * std::uint64_t(read_u32le(bytes.data() + 80));
  if (mesh) mesh->byte_offsets = binary;
  if (binary) return parse_binary_stl(bytes, source, mesh);
  if (starts_with_solid(bytes) && bytes.find('\0') == std::string_view::npos) return parse_ascii_stl(bytes, source, mesh);
  if (mesh) mesh->byte_offsets = true;
  return parse_binary_stl(bytes, source, mesh);  // reports the size mismatch
}

}  // namespace

std::vector<Vec3> parse_obj_points(std::string_view text, std::string_view source) {
  return parse_obj(text, source, nullptr);
}

std::vector<Vec3> parse_off_points(std::string_view text, std::string_view source) {
  return parse_off(text, source, nullptr);
}

std::vector<Vec3> parse_stl_points(std::string_view bytes, std::string_view source) {
  return parse_stl(bytes, source, nullptr);
}

MeshFile parse_mesh(std::string_view bytes, MeshFormat format, std::string_view source) {
  MeshFile m;
  m.source = std::string(source);
  switch (format) {
    case MeshFormat::Obj: m.index_base = 1, m.points = parse_obj(bytes, source, &m); break;
    case MeshFormat::Off: m.points = parse_off(bytes, source, &m); break;
    case MeshFormat::Stl: m.points = parse_stl(bytes, source, &m); break;
    case MeshFormat::Ply: m = parse_ply(bytes, source); break;
  }
  m.face_start.push_back(m.indices.size());
  return m;
}

MeshFormat mesh_format(ShapeFormat format, std::string_view source) {
  switch (format) {
    case ShapeFormat::Obj: return MeshFormat::Obj;
    case ShapeFormat::Off: return MeshFormat::Off;
    case ShapeFormat::Stl: return MeshFormat::Stl;
    case ShapeFormat::Ply: return MeshFormat::Ply;
    case ShapeFormat::Wkt: break;
  }
  throw InvalidInput(std::string(source) + ": a 2D shape (WKT) where a 3D shape (.obj, .off, .stl, .ply) is expected");
}

MeshFile read_mesh(const std::filesystem::path& path) {
  const std::string src = path.string();
  const std::optional<ShapeFormat> format = shape_format_of(path);
  if (!format || *format == ShapeFormat::Wkt)
    throw InvalidInput(src + ": unknown 3D shape format '" + path.extension().string() +
                       "' (expected .obj, .off, .stl or .ply)");
  return parse_mesh(read_text_file(path), mesh_format(*format, src), src);
}

std::vector<Vec3> parse_mesh_points(std::string_view bytes, ShapeFormat format, std::string_view source) {
  switch (mesh_format(format, source)) {  // Wkt throws
    case MeshFormat::Obj: return parse_obj_points(bytes, source);
    case MeshFormat::Off: return parse_off_points(bytes, source);
    case MeshFormat::Stl: return parse_stl_points(bytes, source);
    case MeshFormat::Ply: return parse_ply(bytes, source).points;
  }
  return {};
}

std::vector<Vec3> read_mesh_points(const std::filesystem::path& path) {
  const std::string src = path.string();
  const std::optional<ShapeFormat> format = shape_format_of(path);
  if (!format || *format == ShapeFormat::Wkt)
    throw InvalidInput(src + ": unknown 3D shape format '" + path.extension().string() +
                       "' (expected .obj, .off, .stl or .ply)");
  return parse_mesh_points(read_text_file(path), *format, src);
}

ConvexPolytope convex_polytope_from_points(std::span<const Vec3> pts, std::string_view source, std::string_view name) {
  const std::string src(source);
  if (pts.size() < 4)
    throw InvalidInput(src + ": " + std::string(name) + ": only " + std::to_string(pts.size()) +
                       (pts.size() == 1 ? " point" : " points") + " (a polytope needs 4 affinely independent points)");
  try {
    return ConvexPolytope::hull(pts, name);
  } catch (const InvalidInput& e) {
    throw InvalidInput(src + ": " + e.what());
  }
}

ConvexPolytope read_convex_polytope(const std::filesystem::path& path, std::string_view name) {
  return convex_polytope_from_points(read_mesh_points(path), path.string(), name);
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

namespace pendepth::io {

std::string MeshFile::face_where(std::size_t f) const {
  const std::string loc = f < face_location.size() ? std::to_string(face_location[f]) : "?";
  if (byte_offsets) return source + ": face " + std::to_string(f) + " (byte offset " + loc + ")";
  return source + ":" + loc + ": face " + std::to_string(f);
}

}  // namespace pendepth::io
