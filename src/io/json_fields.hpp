// Private: the JSON fields shared by the 2D and 3D result writers (format.cpp, format3.cpp), so
// both dimensions print the same keys in the same order with the same number formatting.
#pragma once

#include <pendepth/depth2.hpp>
#include <pendepth/io.hpp>

#include <string>

namespace pendepth::io::detail {

inline const char* kind_name(DepthKind k) {
  switch (k) {
    case DepthKind::Minimum: return "minimum";
    case DepthKind::Directional: return "directional";
    case DepthKind::Separation: return "separation";
  }
  return "minimum";
}

/// Writes `{"depth":…,…,"feature_q":…` (no closing brace: the caller may add fields).
/// append_vec(out, v) and append_feature(out, feature, shape) format one dimension's types.
template <class Result, class ShapeP, class ShapeQ, class AppendVec, class AppendFeature>
void append_result_fields(std::string& out, const Result& r, const ShapeP& P, const ShapeQ& Q, AppendVec&& append_vec,
                          AppendFeature&& append_feature) {
  out += "{\"depth\":";
  append_double(out, r.depth);
  out += ",\"translation\":";
  append_vec(out, r.translation);
  out += ",\"normal\":";
  append_vec(out, r.normal);
  out += ",\"witness_p\":";
  append_vec(out, r.witness_p);
  out += ",\"witness_q\":";
  append_vec(out, r.witness_q);
  out += ",\"kind\":\"";
  out += kind_name(r.kind);
  out += "\",\"overlapping\":";
  out += r.overlapping ? "true" : "false";
  out += ",\"feature_p\":";
  append_feature(out, r.feature_p, P);
  out += ",\"feature_q\":";
  append_feature(out, r.feature_q, Q);
}

/// "vertex 4", "edge from vertex 1 to vertex 2", "face (triangle of vertices 0, 3, 5)": input
/// vertex indices, as the 3D summary prints them (format3.cpp); "none" for FeatureKind3::None.
std::string feature3_text(const Feature3& f, const ConvexPolytope& poly);

/// "(x, y, z)" with shortest round-trip doubles, as the 3D summary prints vectors (format3.cpp).
std::string vec3_text(const Vec3& v);

/// The feature and vector formatting of the 2D and 3D writers (format.cpp, format3.cpp), for the
/// signed distance and cast writers (format_distance.cpp).
void append_feature2(std::string& out, const Feature& f, const ConvexPolygon& poly);
void append_feature2(std::string& out, const Feature& f, const Polygon& poly);
std::string feature2_text(const Feature& f, const ConvexPolygon& poly);
std::string feature2_text(const Feature& f, const Polygon& poly);
void append_feature2(std::string& out, const Feature& f, const Features2& s);
std::string feature2_text(const Feature& f, const Features2& s);
std::string vec2_text(const Vec2& v);
void append_vec2(std::string& out, const Vec2& v);
void append_feature3(std::string& out, const Feature3& f, const ConvexPolytope& poly);
void append_vec3(std::string& out, const Vec3& v);

}  // namespace pendepth::io::detail
