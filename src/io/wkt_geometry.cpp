// WKT writer and reader for geometries of several parts (`pendepth nfp`: the no-fit polygon as
// polygons with holes, slits and isolated points), docs/design.md §3.
//
// Writer: MULTIPOLYGON when there are only polygons, else a GEOMETRYCOLLECTION of the non-empty
// MULTIPOLYGON / MULTILINESTRING / MULTIPOINT parts; shortest round-trip doubles, so reading the
// text back gives the same doubles. Reader: a recursive-descent parser over the shared scanner
// (io/wkt_scanner.hpp) for
//   geometry   := POLYGON body | MULTIPOLYGON ( body {, body} ) | LINESTRING line
//               | MULTILINESTRING ( line {, line} ) | POINT ( x y ) | MULTIPOINT ( pt {, pt} )
//               | GEOMETRYCOLLECTION ( geometry {, geometry} )       (not nested), each or EMPTY
//   body       := ( ring {, ring} )    ring, line := ( x y {, x y} )    pt := ( x y ) | x y
// O(length of text) for both.
#include <pendepth/io.hpp>

#include "io/wkt_scanner.hpp"

#include <cmath>

namespace pendepth::io {
namespace {

using namespace wkt_detail;

void append_point(std::string& out, const Vec2& p) {
  append_double(out, p.x());
  out += ' ';
  append_double(out, p.y());
}

void check_finite(const Vec2& p, const char* what) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
    throw InvalidInput(std::string("to_wkt: ") + what + " has a non-finite coordinate");
}

// "(x y, ..., x y)"; a ring repeats its first vertex at the end.
void append_path(std::string& out, const std::vector<Vec2>& pts, bool closed) {
  out += '(';
  for (std::size_t i = 0; i < pts.size() + (closed ? 1 : 0); ++i) {
    if (i) out += ", ";
    append_point(out, pts[i % pts.size()]);
  }
  out += ')';
}

class Parser {
 public:
  Parser(std::string_view text, std::string_view source) : sc_(text, source) {}

  Geometry2 run() {
    Geometry2 g;
    if (sc_.at_end()) sc_.fail("empty input: expected a geometry");
    std::string_view type = sc_.word();
    if (iequals(type, "GEOMETRYCOLLECTION")) {
      if (!empty_tag("GEOMETRYCOLLECTION")) {
        sc_.expect('(', "after GEOMETRYCOLLECTION");
        for (;;) {
          std::string_view t = sc_.word();
          if (iequals(t, "GEOMETRYCOLLECTION")) sc_.fail("nested GEOMETRYCOLLECTION is not supported");
          part(t, g);
          if (!list_continues("after a part of the GEOMETRYCOLLECTION")) break;
        }
      }
    } else {
      part(type, g);
    }
    if (!sc_.at_end()) sc_.fail("trailing text after the geometry: " + sc_.token());
    return g;
  }

 private:
  // After an item of a parenthesised list: true on ',', false on ')' (both consumed).
  bool list_continues(const std::string& where) {
    const char c = sc_.peek();
    if (c == ',' || c == ')') {
      sc_.advance();
      return c == ',';
    }
    sc_.fail("missing ',' or ')' " + where + ", got " + sc_.token());
  }

  // Reads an optional EMPTY (true) after a type; rejects Z / M tags.
  bool empty_tag(std::string_view type) {
    if (!is_alpha(sc_.peek())) return false;
    const std::size_t l = sc_.line();
    std::string_view tag = sc_.word();
    if (iequals(tag, "EMPTY")) return true;
    if (iequals(tag, "Z") || iequals(tag, "M") || iequals(tag, "ZM"))
      sc_.fail_at(l, std::string(type) + " " + std::string(tag) + ": only 2D coordinates are supported");
    sc_.fail_at(l, "unexpected '" + detail::printable(tag) + "' after " + std::string(type));
  }

  Vec2 xy(const std::string& what) {
    const double x = sc_.number("x");
    const double y = sc_.number("y");
    if (sc_.number_follows()) sc_.fail(what + " has more than 2 coordinates (only 2D is supported)");
    return Vec2(x, y);
  }

  // ( x y {, x y} ): at least `min_points` after dropping a closing vertex when `ring`.
  std::vector<Vec2> path(const std::string& name, std::size_t min_points, bool ring) {
    sc_.expect('(', "at the start of " + name);
    const std::size_t line = sc_.line();
    std::vector<Vec2> pts;
    do pts.push_back(xy("point " + std::to_string(pts.size()) + " of " + name));
    while (list_continues("after point " + std::to_string(pts.size() - 1) + " of " + name));
    if (ring && pts.size() >= 2 && pts.front() == pts.back()) pts.pop_back();
    if (pts.size() < min_points)
      sc_.fail_at(line, name + " has " + std::to_string(pts.size()) + " point(s); " +
                            (ring ? "a ring needs at least 3" : "a line needs at least 2"));
    return pts;
  }

  std::vector<std::vector<Vec2>> polygon_body(const std::string& name) {
    sc_.expect('(', "at the start of " + name);
    std::vector<std::vector<Vec2>> rings;
    do rings.push_back(path("ring " + std::to_string(rings.size()) + " of " + name, 3, true));
    while (list_continues("after ring " + std::to_string(rings.size() - 1) + " of " + name));
    return rings;
  }

  void part(std::string_view type, Geometry2& g) {
    if (type.empty()) sc_.fail("expected a geometry type, got " + sc_.token());
    auto known = [&](const char* k) { return iequals(type, k); };
    if (!(known("POLYGON") || known("MULTIPOLYGON") || known("LINESTRING") || known("MULTILINESTRING") ||
          known("POINT") || known("MULTIPOINT")))
      sc_.fail("unknown geometry type '" + detail::printable(type) +
               "' (expected POLYGON, MULTIPOLYGON, LINESTRING, MULTILINESTRING, POINT, MULTIPOINT or "
               "GEOMETRYCOLLECTION)");
    if (empty_tag(type)) return;
    if (known("POLYGON")) {
      g.polygons.push_back(polygon_body("polygon " + std::to_string(g.polygons.size())));
    } else if (known("MULTIPOLYGON")) {
      sc_.expect('(', "after MULTIPOLYGON");
      do g.polygons.push_back(polygon_body("polygon " + std::to_string(g.polygons.size())));
      while (list_continues("after polygon " + std::to_string(g.polygons.size() - 1)));
    } else if (known("LINESTRING")) {
      g.lines.push_back(path("line " + std::to_string(g.lines.size()), 2, false));
    } else if (known("MULTILINESTRING")) {
      sc_.expect('(', "after MULTILINESTRING");
      do g.lines.push_back(path("line " + std::to_string(g.lines.size()), 2, false));
      while (list_continues("after line " + std::to_string(g.lines.size() - 1)));
    } else if (known("POINT")) {
      sc_.expect('(', "after POINT");
      g.points.push_back(xy("point " + std::to_string(g.points.size())));
      sc_.expect(')', "after point " + std::to_string(g.points.size() - 1));
    } else {  // MULTIPOINT ((x y), (x y)) or MULTIPOINT (x y, x y)
      sc_.expect('(', "after MULTIPOINT");
      do {
        const std::string name = "point " + std::to_string(g.points.size());
        if (sc_.peek() == '(') {
          sc_.advance();
          g.points.push_back(xy(name));
          sc_.expect(')', "after " + name);
        } else {
          g.points.push_back(xy(name));
        }
      } while (list_continues("after point " + std::to_string(g.points.size() - 1)));
    }
  }

  Scanner sc_;
};

}  // namespace

std::string to_wkt(const Geometry2& g) {
  for (const auto& poly : g.polygons) {
    if (poly.empty()) throw InvalidInput("to_wkt: a polygon has no rings");
    for (const auto& ring : poly) {
      if (ring.size() < 3) throw InvalidInput("to_wkt: a ring has fewer than 3 points");
      for (const Vec2& p : ring) check_finite(p, "a ring vertex");
    }
  }
  for (const auto& line : g.lines) {
    if (line.size() < 2) throw InvalidInput("to_wkt: a line has fewer than 2 points");
    for (const Vec2& p : line) check_finite(p, "a line vertex");
  }
  for (const Vec2& p : g.points) check_finite(p, "a point");

  std::string out;
  auto multipolygon = [&] {
    if (g.polygons.empty()) {
      out += "MULTIPOLYGON EMPTY";
      return;
    }
    out += "MULTIPOLYGON (";
    for (std::size_t k = 0; k < g.polygons.size(); ++k) {
      out += k ? ", (" : "(";
      for (std::size_t j = 0; j < g.polygons[k].size(); ++j) {
        if (j) out += ", ";
        append_path(out, g.polygons[k][j], true);
      }
      out += ')';
    }
    out += ')';
  };
  if (g.lines.empty() && g.points.empty()) {
    multipolygon();
    return out;
  }
  out += "GEOMETRYCOLLECTION (";
  bool first = true;
  auto sep = [&] {
    if (!first) out += ", ";
    first = false;
  };
  if (!g.polygons.empty()) {
    sep();
    multipolygon();
  }
  if (!g.lines.empty()) {
    sep();
    out += "MULTILINESTRING (";
    for (std::size_t k = 0; k < g.lines.size(); ++k) {
      if (k) out += ", ";
      append_path(out, g.lines[k], false);
    }
    out += ')';
  }
  if (!g.points.empty()) {
    sep();
    out += "MULTIPOINT (";
    for (std::size_t k = 0; k < g.points.size(); ++k) {
      out += k ? ", (" : "(";
      append_point(out, g.points[k]);
      out += ')';
    }
    out += ')';
  }
  out += ')';
  return out;
}

Geometry2 parse_wkt_geometry(std::string_view text, std::string_view source) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte-order mark
  return Parser(text, source).run();
}

}  // namespace pendepth::io
