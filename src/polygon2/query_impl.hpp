// Private: state shared by the PolygonDepth2 queries (DHS §4) and helpers building results.
#pragma once

#include <pendepth/depth2_polygon_convex.hpp>

#include "polygon2/convolved_triangles.hpp"
#include "polygon2/union_boundary.hpp"

namespace pendepth {

struct PolygonDepth2::Impl {
  Polygon P;
  ConvexPolygon Q;
  polygon2::ConvolvedTriangles R;
  polygon2::UnionBoundary U;  ///< refers to P and R above (Impl is never moved: held by unique_ptr)
  /// `tris`: P's triangulation when already made (ConvolvedTriangles), else triangulated here.
  Impl(const Polygon& p, const ConvexPolygon& q, const std::vector<polygon2::TriangleIds>* tris = nullptr)
      : P(p), Q(q), R(P, Q, tris), U(P, R) {}
};

/// Internal (src/front/pair2.cpp): wraps a built Impl (one made from a shape's shared triangulation).
PolygonDepth2 polygon_depth_from_impl(std::unique_ptr<PolygonDepth2::Impl> impl);

const PolygonDepth2::Impl& polygon_depth_impl(const PolygonDepth2& pd);

namespace polygon2 {

// ---- reference paths (tests and benchmarks): same contract and results as PolygonDepth2's ----

/// σ_d by visiting every piece of the implicit union boundary, O(n log m) (DHS §4.2): the second,
/// independent query path of along().
Depth2 along_scan(const PolygonDepth2& pd, const Vec2& t, const Vec2& d);
/// σ_d from the convolved triangles directly (exact reference, O(n log m + n log n)).
Depth2 along_triangles(const PolygonDepth2& pd, const Vec2& t, const Vec2& d);
/// Complete separation from the convolved triangles directly (exact reference, O(n log m)).
Depth2 separation_triangles(const PolygonDepth2& pd, const Vec2& t, const Vec2& d);

/// Validates (t, d) like the convex queries and returns d scaled by a power of two (exact, same
/// direction) so its largest component is in [1, 2).
Vec2 check_and_scale(const Vec2& t, const Vec2& d);
/// The result of moving from t along d (scaled) to the line of cut c: depth, translation, witnesses,
/// features. `overlapping` and `kind` are set by the caller.
Depth2 result_at_cut(const PolygonDepth2::Impl& S, const Cut& c, const Vec2& t, const Vec2& d);
/// The same for a hit of the union boundary (a cut, or an explicit convolution vertex p + b).
Depth2 result_at_hit(const PolygonDepth2::Impl& S, const Hit& h, const Vec2& t, const Vec2& d);

}  // namespace polygon2
}  // namespace pendepth
