// Writers for the signed distance and the shape cast (Distance2/3, Cast2/3): JSON object, CSV
// row, human summary (docs/design.md §3 `distance`, `cast`, `batch --signed`). Same number and
// feature formatting as the depth writers (json_fields.hpp).
#include <pendepth/io.hpp>

#include "io/json_fields.hpp"

#include <cmath>

namespace pendepth::io {

namespace {

using detail::append_vec2;
using detail::append_vec3;

void append_feature(std::string& out, const Feature& f, Features2 s) { detail::append_feature2(out, f, s); }
void append_feature(std::string& out, const Feature3& f, const ConvexPolytope& s) { detail::append_feature3(out, f, s); }
std::string feature_text(const Feature& f, Features2 s) { return detail::feature2_text(f, s); }
std::string feature_text(const Feature3& f, const ConvexPolytope& s) { return detail::feature3_text(f, s); }
void append_vec(std::string& out, const Vec2& v) { append_vec2(out, v); }
void append_vec(std::string& out, const Vec3& v) { append_vec3(out, v); }
std::string vec_text(const Vec2& v) { return detail::vec2_text(v); }
std::string vec_text(const Vec3& v) { return detail::vec3_text(v); }

// The fields every distance and cast object shares, after "distance" (and "hit").
template <class R, class SP, class SQ>
void append_common(std::string& out, const R& r, const SP& P, const SQ& Q) {
  out += ",\"translation\":";
  append_vec(out, r.translation);
  out += ",\"normal\":";
  append_vec(out, r.normal);
  out += ",\"witness_p\":";
  append_vec(out, r.witness_p);
  out += ",\"witness_q\":";
  append_vec(out, r.witness_q);
  out += ",\"overlapping\":";
  out += r.overlapping ? "true" : "false";
  out += ",\"feature_p\":";
  append_feature(out, r.feature_p, P);
  out += ",\"feature_q\":";
  append_feature(out, r.feature_q, Q);
}

// The certified bracket and the mesh pieces (3D results; a cast's bounds are +inf on a miss).
template <class R>
void append_bounds_pieces(std::string& out, const R& r) {
  if constexpr (requires { r.lower_bound; }) {
    out += ",\"lower_bound\":";
    append_double(out, r.lower_bound);
    out += ",\"upper_bound\":";
    append_double(out, r.upper_bound);
  }
  if constexpr (requires { r.piece_p; })
    if (r.piece_p >= 0)  // a mesh pair: the pieces the features index (Pair3, meshes)
      out += ",\"piece_p\":" + std::to_string(r.piece_p) + ",\"piece_q\":" + std::to_string(r.piece_q);
}

template <class R, class SP, class SQ>
void append_distance(std::string& out, const R& r, const SP& P, const SQ& Q) {
  out += "{\"distance\":";
  append_double(out, r.distance);
  append_common(out, r, P, Q);
  append_bounds_pieces(out, r);
  out += '}';
}

template <class R, class SP, class SQ>
void append_cast(std::string& out, const R& r, const SP& P, const SQ& Q) {
  out += "{\"distance\":";
  append_double(out, r.distance);
  out += ",\"hit\":";
  out += r.hit ? "true" : "false";
  append_common(out, r, P, Q);
  append_bounds_pieces(out, r);
  out += '}';
}

template <class R>
void append_row(std::string& out, const R& r) {
  append_double(out, r.distance);
  for (int k = 0; k < r.translation.size(); ++k) {
    out += ',';
    append_double(out, r.translation[k]);
  }
  out += '\n';
}

template <class R, class SP, class SQ>
std::string distance_summary(const R& r, const SP& P, const SQ& Q) {
  std::string s = "signed distance (> 0 apart, 0 touching, -depth overlapping)\n  state:       ";
  s += r.overlapping ? "overlapping\n" : r.distance == 0 ? "touching\n" : "apart\n";
  s += "  distance:    ";
  append_double(s, r.distance);
  s += "\n  translation: " + vec_text(r.translation) + "  (move Q by this to touch)\n";
  if (r.distance != 0) s += "  normal:      " + vec_text(r.normal) + "\n";
  s += "  witness P:   " + vec_text(r.witness_p) + "  on " + feature_text(r.feature_p, P) + " of P\n";
  s += "  witness Q:   " + vec_text(r.witness_q) + "  on " + feature_text(r.feature_q, Q) + " of Q\n";
  return s;
}

template <class R, class SP, class SQ>
std::string cast_summary(const R& r, const SP& P, const SQ& Q) {
  std::string s = "shape cast along the given direction (first contact)\n  state:       ";
  s += r.overlapping ? "overlapping at the start\n" : r.hit ? (r.distance == 0 ? "touching at the start\n" : "hit\n") : "miss (never touches)\n";
  s += "  distance:    ";
  if (r.hit) append_double(s, r.distance);
  else s += "inf";
  s += "\n";
  if (r.hit && !r.overlapping) {
    s += "  translation: " + vec_text(r.translation) + "  (move Q by this to touch)\n";
    s += "  normal:      " + vec_text(r.normal) + "\n";
    s += "  contact:     " + vec_text(r.witness_p) + "  on " + feature_text(r.feature_p, P) + " of P, " +
         feature_text(r.feature_q, Q) + " of Q\n";
  }
  return s;
}

}  // namespace

void append_json(std::string& out, const Distance2& r, Features2 P, Features2 Q) { append_distance(out, r, P, Q); }
void append_json(std::string& out, const Cast2& r, Features2 P, Features2 Q) { append_cast(out, r, P, Q); }
void append_csv_row(std::string& out, const Distance2& r) { append_row(out, r); }
std::string summary(const Distance2& r, Features2 P, Features2 Q) { return distance_summary(r, P, Q); }
std::string summary(const Cast2& r, Features2 P, Features2 Q) { return cast_summary(r, P, Q); }
void append_json(std::string& out, const Distance3& r, const ConvexPolytope& P, const ConvexPolytope& Q) {
  append_distance(out, r, P, Q);
}
void append_json(std::string& out, const Cast3& r, const ConvexPolytope& P, const ConvexPolytope& Q) {
  append_cast(out, r, P, Q);
}
void append_csv_row(std::string& out, const Distance3& r) { append_row(out, r); }
std::string summary(const Distance3& r, const ConvexPolytope& P, const ConvexPolytope& Q) {
  return distance_summary(r, P, Q);
}
std::string summary(const Cast3& r, const ConvexPolytope& P, const ConvexPolytope& Q) { return cast_summary(r, P, Q); }

}  // namespace pendepth::io
