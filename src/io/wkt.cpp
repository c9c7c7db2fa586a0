// WKT reader and writer for 2D polygons (docs/design.md §3).
//
// A hand-written scanner over the whole text: one pass, std::from_chars for numbers (a 10⁶-vertex
// file parses in a fraction of a second), a running line counter so every error and every vertex
// carries its source line. Grammar accepted (keywords case-insensitive, whitespace anywhere):
//   POLYGON ( ring { , ring } )      ring := ( x y { , x y } )
// Z/M coordinates, EMPTY and other geometry types are rejected: pendepth is 2D here.
#include <pendepth/io.hpp>

#include "io/wkt_scanner.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <system_error>

namespace pendepth::io {
using namespace wkt_detail;

WktPolygon parse_wkt_polygon(std::string_view text, std::string_view source) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte-order mark
  Scanner sc(text, source);
  WktPolygon out;
  if (sc.at_end()) sc.fail("empty input: expected a POLYGON");
  out.first_line = sc.line();
  std::string_view type = sc.word();
  if (type.empty()) sc.fail("expected a geometry type (POLYGON), got " + sc.token());
  if (!iequals(type, "POLYGON"))
    sc.fail("unknown geometry type '" + detail::printable(type) + "' (expected POLYGON)");
  if (is_alpha(sc.peek())) {
    std::size_t l = sc.line();
    std::string_view tag = sc.word();
    if (iequals(tag, "EMPTY")) sc.fail_at(l, "POLYGON EMPTY: the polygon has no rings");
    if (iequals(tag, "Z") || iequals(tag, "M") || iequals(tag, "ZM"))
      sc.fail_at(l, "POLYGON " + std::string(tag) + ": only 2D coordinates are supported");
    sc.fail_at(l, "unexpected '" + detail::printable(tag) + "' after POLYGON");
  }
  sc.expect('(', "after POLYGON");
  for (std::size_t r = 0;; ++r) {
    const std::string ring_name = r == 0 ? "the outer ring" : "ring " + std::to_string(r);
    sc.expect('(', "at the start of " + ring_name);
    const std::size_t ring_line = sc.line();
    std::vector<Vec2> ring;
    std::vector<std::size_t> lines;
    for (;;) {
      const std::size_t l = (sc.peek(), sc.line());
      const double x = sc.number("x");
      const double y = sc.number("y");
      ring.emplace_back(x, y);
      lines.push_back(l);
      if (sc.number_follows())
        sc.fail("point " + std::to_string(ring.size() - 1) + " of " + ring_name +
                " has more than 2 coordinates (only 2D is supported)");
      const char c = sc.peek();
      if (c == ',') {
        sc.advance();
        continue;
      }
      if (c == ')') {
        sc.advance();
        break;
      }
      sc.fail("missing ',' or ')' after point " + std::to_string(ring.size() - 1) + " of " +
              ring_name + ", got " + sc.token());
    }
    if (ring.size() >= 2 && ring.front() == ring.back()) {  // explicit closing vertex
      ring.pop_back();
      lines.pop_back();
    }
    if (ring.size() < 3)
      sc.fail_at(ring_line, ring_name + " has " + std::to_string(ring.size()) +
                                " point(s); a ring needs at least 3");
    out.rings.push_back(std::move(ring));
    out.lines.push_back(std::move(lines));
    const char c = sc.peek();
    if (c == ',') {
      sc.advance();
      continue;
    }
    if (c == ')') {
      sc.advance();
      break;
    }
    sc.fail("missing ',' or ')' after " + ring_name + ", got " + sc.token());
  }
  if (!sc.at_end()) sc.fail("trailing text after the polygon: " + sc.token());
  return out;
}

WktPolygon read_wkt_polygon(const std::filesystem::path& path) {
  return parse_wkt_polygon(read_text_file(path), path.string());
}

namespace {

// The input vertex index a ConvexPolygon message refers to ("vertex K", "edge K": edge K starts
// at vertex K), if any. The message starts with "<name>: ", skipped so a name cannot match.
std::optional<std::size_t> named_vertex(std::string_view msg, std::string_view name) {
  if (msg.substr(0, name.size()) == name) msg.remove_prefix(name.size());
  for (std::string_view key : {std::string_view("vertex "), std::string_view("edge ")}) {
    const std::size_t at = msg.find(key);
    if (at == std::string_view::npos) continue;
    const char* b = msg.data() + at + key.size();
    std::size_t k = 0;
    auto [ptr, ec] = std::from_chars(b, msg.data() + msg.size(), k);
    if (ec == std::errc() && ptr != b) return k;
  }
  return std::nullopt;
}

}  // namespace

ConvexPolygon read_convex_polygon(const std::filesystem::path& path, std::string_view name) {
  WktPolygon w = read_wkt_polygon(path);
  const std::string src = path.string();
  if (w.rings.size() > 1)
    throw InvalidInput(src + ": convex polygons cannot have holes (read it with io::read_polygon: "
                             "polygons with holes are supported against a convex polygon)");
  try {
    return ConvexPolygon(w.rings[0], name);
  } catch (const InvalidInput& e) {
    std::size_t line = w.lines[0].front();
    if (auto k = named_vertex(e.what(), name); k && *k < w.lines[0].size()) line = w.lines[0][*k];
    throw InvalidInput(src + ":" + std::to_string(line) + ": " + e.what());
  }
}

namespace {

// The first number after `key` in msg (from `from`), if any.
std::optional<std::size_t> number_after(std::string_view msg, std::string_view key, std::size_t& at) {
  at = msg.find(key, at);
  if (at == std::string_view::npos) return std::nullopt;
  const char* b = msg.data() + at + key.size();
  std::size_t k = 0;
  auto [ptr, ec] = std::from_chars(b, msg.data() + msg.size(), k);
  if (ec != std::errc() || ptr == b) return std::nullopt;
  return k;
}

// The source line a Polygon message points at: the first "ring K" it names, then the first
// vertex or edge ("vertex I", "vertices I", "edge I", "edges I") named after it.
std::size_t polygon_error_line(const WktPolygon& w, std::string_view msg, std::string_view name) {
  if (msg.substr(0, name.size()) == name) msg.remove_prefix(name.size());
  std::size_t at = 0;
  const auto ring = number_after(msg, "ring ", at);
  if (!ring || *ring >= w.rings.size()) return w.first_line;
  std::size_t best = std::string_view::npos;
  std::optional<std::size_t> index;
  for (std::string_view key : {"vertex ", "vertices ", "edge ", "edges "}) {
    std::size_t k_at = at;
    if (auto k = number_after(msg, key, k_at); k && k_at < best) {
      best = k_at;
      index = k;
    }
  }
  const auto& lines = w.lines[*ring];
  return index && *index < lines.size() ? lines[*index] : lines.front();
}

Polygon validate_polygon(const WktPolygon& w, const std::string& src, std::string_view name) {
  try {
    return Polygon(w.rings, name);
  } catch (const InvalidInput& e) {
    throw InvalidInput(src + ":" + std::to_string(polygon_error_line(w, e.what(), name)) + ": " + e.what());
  }
}

}  // namespace

Polygon read_polygon(const std::filesystem::path& path, std::string_view name) {
  return validate_polygon(read_wkt_polygon(path), path.string(), name);
}

Shape2 read_shape2(const std::filesystem::path& path, std::string_view name) {
  return shape2_from_wkt(read_wkt_polygon(path), path.string(), name);
}

Shape2 shape2_from_wkt(const WktPolygon& w, std::string_view source, std::string_view name) {
  const std::string src(source);
  Shape2 s;
  if (w.rings.size() == 1) {
    try {
      s.convex.emplace(w.rings[0], name);
      return s;
    } catch (const InvalidInput& e) {
      // Not convex (a reflex vertex, or a ring winding around twice): maybe a simple polygon.
      const std::string msg = e.what();
      if (msg.find("not convex") == std::string::npos && msg.find("self-intersecting") == std::string::npos) {
        std::size_t line = w.lines[0].front();
        if (auto k = named_vertex(msg, name); k && *k < w.lines[0].size()) line = w.lines[0][*k];
        throw InvalidInput(src + ":" + std::to_string(line) + ": " + msg);
      }
    }
  }
  s.polygon.emplace(validate_polygon(w, src, name));
  return s;
}

std::string to_wkt(std::span<const Vec2> ring) {
  for (std::size_t i = 0; i < ring.size(); ++i)
    if (!std::isfinite(ring[i].x()) || !std::isfinite(ring[i].y()))
      throw InvalidInput("to_wkt: vertex " + std::to_string(i) + " has a non-finite coordinate");
  if (ring.empty()) return "POLYGON EMPTY";
  std::string out = "POLYGON ((";
  out.reserve(16 + 48 * (ring.size() + 1));
  for (std::size_t i = 0; i <= ring.size(); ++i) {
    const Vec2& p = ring[i % ring.size()];
    if (i > 0) out += ", ";
    append_double(out, p.x());
    out += ' ';
    append_double(out, p.y());
  }
  out += "))";
  return out;
}

std::string to_wkt(const ConvexPolygon& polygon) { return to_wkt(polygon.vertices()); }

}  // namespace pendepth::io
