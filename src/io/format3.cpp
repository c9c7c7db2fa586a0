// Result writers for 3D queries: JSON object, CSV row, human summary (docs/design.md §3).
//
// Same approach as format.cpp (hand-written JSON into a reused buffer, shortest round-trip
// doubles). Features are reported with the vertex indices of the input file, so a user can find
// them in the mesh: a hull vertex i is input vertex input_index(i); a level-0 half-edge
// h = 3f + k runs from triangles()[f][k] to triangles()[f][(k + 1) % 3].
#include <pendepth/io.hpp>

#include "io/json_fields.hpp"

#include <charconv>

namespace pendepth::io {
namespace {

using detail::kind_name;

void append_vec(std::string& out, const Vec3& v) {
  out += '[';
  append_double(out, v.x());
  out += ',';
  append_double(out, v.y());
  out += ',';
  append_double(out, v.z());
  out += ']';
}

void append_uint(std::string& out, std::size_t k) {
  char buf[24];
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, k);
  out.append(buf, ptr);
}

// Input indices of a feature's vertices: 1 (vertex), 2 (edge, origin → target) or 3 (face,
// counter-clockwise from outside); 0 for None or an index out of range.
std::size_t feature_vertices(const Feature3& f, const ConvexPolytope& poly, std::size_t (&v)[3]) {
  const auto tris = poly.triangles();
  const auto idx = static_cast<std::size_t>(f.index);
  switch (f.kind) {
    case FeatureKind3::Vertex:
      if (f.index < 0 || idx >= poly.size()) return 0;
      v[0] = poly.input_index(idx);
      return 1;
    case FeatureKind3::Edge: {
      if (f.index < 0 || idx >= 3 * tris.size()) return 0;
      const auto& t = tris[idx / 3];
      v[0] = poly.input_index(static_cast<std::size_t>(t[idx % 3]));
      v[1] = poly.input_index(static_cast<std::size_t>(t[(idx + 1) % 3]));
      return 2;
    }
    case FeatureKind3::Face:
      if (f.index < 0 || idx >= tris.size()) return 0;
      for (std::size_t k = 0; k < 3; ++k) v[k] = poly.input_index(static_cast<std::size_t>(tris[idx][k]));
      return 3;
    case FeatureKind3::None: return 0;
  }
  return 0;
}

void append_feature(std::string& out, const Feature3& f, const ConvexPolytope& poly) {
  std::size_t v[3];
  switch (feature_vertices(f, poly, v)) {
    case 1:
      out += "{\"kind\":\"vertex\",\"index\":";
      append_uint(out, v[0]);
      break;
    case 2:
      out += "{\"kind\":\"edge\",\"index\":";
      append_uint(out, v[0]);
      out += ",\"end\":";
      append_uint(out, v[1]);
      break;
    case 3:
      out += "{\"kind\":\"face\",\"index\":";
      append_uint(out, static_cast<std::size_t>(f.index));
      out += ",\"vertices\":[";
      for (std::size_t k = 0; k < 3; ++k) {
        if (k) out += ',';
        append_uint(out, v[k]);
      }
      out += ']';
      break;
    default: out += "{\"kind\":\"none\",\"index\":null"; break;
  }
  out += '}';
}

std::string feature_text(const Feature3& f, const ConvexPolytope& poly) {
  std::size_t v[3];
  switch (feature_vertices(f, poly, v)) {
    case 1: return "vertex " + std::to_string(v[0]);
    case 2: return "edge from vertex " + std::to_string(v[0]) + " to vertex " + std::to_string(v[1]);
    case 3:
      return "face (triangle of vertices " + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " +
             std::to_string(v[2]) + ")";
    default: return "none";
  }
}

std::string vec_text(const Vec3& v) {
  std::string s = "(";
  append_double(s, v.x());
  s += ", ";
  append_double(s, v.y());
  s += ", ";
  append_double(s, v.z());
  return s + ")";
}

}  // namespace

std::string detail::feature3_text(const Feature3& f, const ConvexPolytope& poly) { return feature_text(f, poly); }
std::string detail::vec3_text(const Vec3& v) { return vec_text(v); }
void detail::append_feature3(std::string& out, const Feature3& f, const ConvexPolytope& poly) { append_feature(out, f, poly); }
void detail::append_vec3(std::string& out, const Vec3& v) { append_vec(out, v); }

void append_json(std::string& out, const Depth3& r, const ConvexPolytope& P, const ConvexPolytope& Q) {
  detail::append_result_fields(
      out, r, P, Q, [](std::string& o, const auto& v) { append_vec(o, v); },
      [](std::string& o, const auto& f, const auto& shape) { append_feature(o, f, shape); });
  out += ",\"lower_bound\":";
  append_double(out, r.lower_bound);
  out += ",\"upper_bound\":";
  append_double(out, r.upper_bound);
  if (r.piece_p >= 0) {  // a mesh pair: the pieces the features index (Pair3, meshes)
    out += ",\"piece_p\":";
    append_uint(out, static_cast<std::size_t>(r.piece_p));
    out += ",\"piece_q\":";
    append_uint(out, static_cast<std::size_t>(r.piece_q));
  }
  out += '}';
}

void append_csv_row(std::string& out, const Depth3& r) {
  append_double(out, r.depth);
  out += ',';
  append_double(out, r.translation.x());
  out += ',';
  append_double(out, r.translation.y());
  out += ',';
  append_double(out, r.translation.z());
  out += '\n';
}

std::string summary(const Depth3& r, const ConvexPolytope& P, const ConvexPolytope& Q) {
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
  if (r.overlapping) {
    s += "  normal:      " + vec_text(r.normal) + "\n";
    s += "  witness P:   " + vec_text(r.witness_p) + "\n";
    s += "  witness Q:   " + vec_text(r.witness_q) + "\n";
    // The features span the facet of M where the move ends; in a face-face or edge-face contact
    // the witness is one point of the contact region, not necessarily on a named vertex.
    s += "  features:    " + feature_text(r.feature_p, P) + " of P, " + feature_text(r.feature_q, Q) + " of Q\n";
    if (r.piece_p >= 0)
      s += "  pieces:      P piece " + std::to_string(r.piece_p) + ", Q piece " + std::to_string(r.piece_q) +
           " (the features' vertices are those pieces')\n";
    if (r.lower_bound != r.upper_bound) {
      s += "  bounds:      [";
      append_double(s, r.lower_bound);
      s += ", ";
      append_double(s, r.upper_bound);
      s += "]\n";
    }
  }
  s += "  shapes:      P " + std::to_string(P.size()) + " hull vertices, Q " + std::to_string(Q.size()) +
       " hull vertices\n";
  return s;
}

}  // namespace pendepth::io
