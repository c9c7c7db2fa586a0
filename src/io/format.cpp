// Result writers: JSON object, CSV row, human summary (docs/design.md §3).
//
// JSON is written by hand with std::to_chars rather than through a DOM: the values are numbers,
// booleans and fixed words, and `pendepth batch` appends 10⁵ objects into one reused buffer
// without a heap allocation per query. Tests parse the output with nlohmann-json.
#include <pendepth/io.hpp>

#include "io/json_fields.hpp"

#include <cassert>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace pendepth::io {

void append_double(std::string& out, double x) {
  assert(!std::isnan(x));
  // An answer whose true value overflows a double is an explicit infinity (docs/robustness.md).
  // JSON has no infinity; 1e999 is a valid JSON number that every parser reads as one.
  if (std::isinf(x)) {
    out += x > 0 ? "1e999" : "-1e999";
    return;
  }
  char buf[32];
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, x);
  assert(ec == std::errc());
  (void)ec;
  out.append(buf, ptr);
}

namespace {

using detail::kind_name;

void append_vec(std::string& out, const Vec2& v) {
  out += '[';
  append_double(out, v.x());
  out += ',';
  append_double(out, v.y());
  out += ']';
}

void append_uint(std::string& out, std::size_t k) {
  char buf[24];
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, k);
  out.append(buf, ptr);
}

// Feature indices in the rings as given: normal-form vertex i is input vertex input_index(i);
// normal-form edge i runs counter-clockwise from vertex i to vertex i + 1.
void append_feature(std::string& out, const Feature& f, const ConvexPolygon& poly) {
  if (f.kind == FeatureKind::None || f.index < 0) {
    out += "{\"kind\":\"none\",\"index\":null}";
    return;
  }
  const std::size_t i = static_cast<std::size_t>(f.index) % poly.size();
  out += f.kind == FeatureKind::Vertex ? "{\"kind\":\"vertex\",\"index\":" : "{\"kind\":\"edge\",\"index\":";
  append_uint(out, poly.input_index(i));
  if (f.kind == FeatureKind::Edge) {
    out += ",\"end\":";
    append_uint(out, poly.input_index((i + 1) % poly.size()));
  }
  out += '}';
}

std::string feature_text(const Feature& f, const ConvexPolygon& poly) {
  if (f.kind == FeatureKind::None || f.index < 0) return "none";
  const std::size_t i = static_cast<std::size_t>(f.index) % poly.size();
  if (f.kind == FeatureKind::Vertex) return "vertex " + std::to_string(poly.input_index(i));
  return "edge from vertex " + std::to_string(poly.input_index(i)) + " to vertex " +
         std::to_string(poly.input_index((i + 1) % poly.size()));
}

// A polygon with holes: global vertex g is vertex input_index(g) of ring ring_of(g) as given;
// global edge g runs from g to next(g) (interior on its left).
void append_feature(std::string& out, const Feature& f, const Polygon& poly) {
  if (f.kind == FeatureKind::None || f.index < 0 || std::size_t(f.index) >= poly.size()) {
    out += "{\"kind\":\"none\",\"index\":null}";
    return;
  }
  const std::size_t g = static_cast<std::size_t>(f.index);
  out += f.kind == FeatureKind::Vertex ? "{\"kind\":\"vertex\",\"ring\":" : "{\"kind\":\"edge\",\"ring\":";
  append_uint(out, poly.ring_of(g));
  out += ",\"index\":";
  append_uint(out, poly.input_index(g));
  if (f.kind == FeatureKind::Edge) {
    out += ",\"end\":";
    append_uint(out, poly.input_index(poly.next(g)));
  }
  out += '}';
}

std::string ring_text(const Polygon& poly, std::size_t g) {
  const std::size_t k = poly.ring_of(g);
  return k == 0 ? "the outer ring" : "hole " + std::to_string(k);
}

std::string feature_text(const Feature& f, const Polygon& poly) {
  if (f.kind == FeatureKind::None || f.index < 0 || std::size_t(f.index) >= poly.size()) return "none";
  const std::size_t g = static_cast<std::size_t>(f.index);
  if (f.kind == FeatureKind::Vertex) return "vertex " + std::to_string(poly.input_index(g)) + " of " + ring_text(poly, g);
  return "edge from vertex " + std::to_string(poly.input_index(g)) + " to vertex " +
         std::to_string(poly.input_index(poly.next(g))) + " of " + ring_text(poly, g);
}

// A point or a segment (Features2::flat vertices): vertex j, the segment's edge 0 from 0 to 1.
void append_feature(std::string& out, const Feature& f, const Features2& s) {
  if (s.convex) return append_feature(out, f, *s.convex);
  if (s.polygon) return append_feature(out, f, *s.polygon);
  if (f.kind == FeatureKind::None || f.index < 0 || std::size_t(f.index) >= s.flat) {
    out += "{\"kind\":\"none\",\"index\":null}";
    return;
  }
  out += f.kind == FeatureKind::Vertex ? "{\"kind\":\"vertex\",\"index\":" : "{\"kind\":\"edge\",\"index\":";
  append_uint(out, static_cast<std::size_t>(f.index));
  if (f.kind == FeatureKind::Edge) out += ",\"end\":1";
  out += '}';
}

std::string feature_text(const Feature& f, const Features2& s) {
  if (s.convex) return feature_text(f, *s.convex);
  if (s.polygon) return feature_text(f, *s.polygon);
  if (f.kind == FeatureKind::None || f.index < 0 || std::size_t(f.index) >= s.flat) return "none";
  if (f.kind == FeatureKind::Vertex) return s.flat == 1 ? "the point" : "end " + std::to_string(f.index);
  return "the segment";
}

std::string vec_text(const Vec2& v) {
  std::string s = "(";
  append_double(s, v.x());
  s += ", ";
  append_double(s, v.y());
  return s + ")";
}

}  // namespace

void detail::append_feature2(std::string& out, const Feature& f, const ConvexPolygon& poly) { append_feature(out, f, poly); }
void detail::append_feature2(std::string& out, const Feature& f, const Polygon& poly) { append_feature(out, f, poly); }
std::string detail::feature2_text(const Feature& f, const ConvexPolygon& poly) { return feature_text(f, poly); }
std::string detail::feature2_text(const Feature& f, const Polygon& poly) { return feature_text(f, poly); }
void detail::append_feature2(std::string& out, const Feature& f, const Features2& s) { append_feature(out, f, s); }
std::string detail::feature2_text(const Feature& f, const Features2& s) { return feature_text(f, s); }
std::string detail::vec2_text(const Vec2& v) { return vec_text(v); }
void detail::append_vec2(std::string& out, const Vec2& v) { append_vec(out, v); }

namespace {
template <class ShapeP, class ShapeQ>
void append_json_any(std::string& out, const Depth2& r, const ShapeP& P, const ShapeQ& Q) {
  detail::append_result_fields(
      out, r, P, Q, [](std::string& o, const auto& v) { append_vec(o, v); },
      [](std::string& o, const auto& f, const auto& shape) { append_feature(o, f, shape); });
  out += '}';
}
}  // namespace

void append_json(std::string& out, const Depth2& r, const ConvexPolygon& P, const ConvexPolygon& Q) {
  append_json_any(out, r, P, Q);
}
void append_json(std::string& out, const Depth2& r, const Polygon& P, const ConvexPolygon& Q) {
  append_json_any(out, r, P, Q);
}
void append_json(std::string& out, const Depth2& r, const ConvexPolygon& P, const Polygon& Q) {
  append_json_any(out, r, P, Q);
}
void append_json(std::string& out, const Depth2& r, const Polygon& P, const Polygon& Q) {
  append_json_any(out, r, P, Q);
}

void append_json(std::string& out, const Depth2& r, Features2 P, Features2 Q) { append_json_any(out, r, P, Q); }

void append_json(std::string& out, const Geometry2& g) {
  auto ring = [&](const std::vector<Vec2>& pts) {
    out += '[';
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (i) out += ',';
      append_vec(out, pts[i]);
    }
    out += ']';
  };
  out += "{\"polygons\":[";
  for (std::size_t k = 0; k < g.polygons.size(); ++k) {
    out += k ? ",[" : "[";
    for (std::size_t j = 0; j < g.polygons[k].size(); ++j) {
      if (j) out += ',';
      ring(g.polygons[k][j]);
    }
    out += ']';
  }
  out += "],\"lines\":[";
  for (std::size_t k = 0; k < g.lines.size(); ++k) {
    if (k) out += ',';
    ring(g.lines[k]);
  }
  out += "],\"points\":";
  ring(g.points);
  out += '}';
}

void append_csv_row(std::string& out, const Depth2& r) {
  append_double(out, r.depth);
  out += ',';
  append_double(out, r.translation.x());
  out += ',';
  append_double(out, r.translation.y());
  out += '\n';
}

namespace {
template <class ShapeP, class ShapeQ>
std::string summary_any(const Depth2& r, const ShapeP& P, const ShapeQ& Q) {
  std::string s;
  switch (r.kind) {
    case DepthKind::Minimum: s += "minimum depth (shortest separating translation)\n"; break;
    case DepthKind::Directional: s += "directional depth along the given direction\n"; break;
    case DepthKind::Separation: s += "complete separation along the given direction\n"; break;
  }
  s += "  overlapping: ";
  s += r.overlapping ? "yes\n" : "no (interiors disjoint; touching counts as not overlapping)\n";
  s += "  depth:       ";
  append_double(s, r.depth);
  s += "\n  translation: " + vec_text(r.translation) + "  (move Q by this to separate)\n";
  if (r.overlapping || (r.kind == DepthKind::Separation && r.depth > 0)) {
    s += "  normal:      " + vec_text(r.normal) + "\n";
    s += "  witness P:   " + vec_text(r.witness_p) + "  on " + feature_text(r.feature_p, P) + " of P\n";
    s += "  witness Q:   " + vec_text(r.witness_q) + "  on " + feature_text(r.feature_q, Q) + " of Q\n";
  }
  return s;
}
}  // namespace

std::string summary(const Depth2& r, const ConvexPolygon& P, const ConvexPolygon& Q) { return summary_any(r, P, Q); }
std::string summary(const Depth2& r, const Polygon& P, const ConvexPolygon& Q) { return summary_any(r, P, Q); }
std::string summary(const Depth2& r, const ConvexPolygon& P, const Polygon& Q) { return summary_any(r, P, Q); }
std::string summary(const Depth2& r, const Polygon& P, const Polygon& Q) { return summary_any(r, P, Q); }
std::string summary(const Depth2& r, Features2 P, Features2 Q) { return summary_any(r, P, Q); }

}  // namespace pendepth::io
