// Private: state shared by the PolygonDepth2 queries (DHS §4) and helpers building results.
#pragma once

#include <pendepth/depth2_polygon.hpp>

#include "polygon2/convolved_triangles.hpp"

namespace pendepth {

struct PolygonDepth2::Impl {
  Polygon P;
  ConvexPolygon Q;
  polygon2::ConvolvedTriangles R;
  Impl(const Polygon& p, const ConvexPolygon& q) : P(p), Q(q), R(p, q) {}
};

namespace polygon2 {

/// Validates (t, d) like the convex queries and returns d scaled by a power of two (exact, same
/// direction) so its largest component is in [1, 2).
Vec2 check_and_scale(const Vec2& t, const Vec2& d);
/// The result of moving from t along d (scaled) to the line of cut c: depth, translation, witnesses,
/// features. `overlapping` and `kind` are set by the caller.
Depth2 result_at_cut(const PolygonDepth2::Impl& S, const Cut& c, const Vec2& t, const Vec2& d);

}  // namespace polygon2
}  // namespace pendepth
