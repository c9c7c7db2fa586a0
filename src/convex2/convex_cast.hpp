// Private: the shape cast of two convex polygons in O(log n + log m) (issue 16 item 3;
// docs/algorithms.md "Signed distance and shape cast in 2D"), defined in directional.cpp next to
// the prune-and-search it reuses.
//
// Contract: P, Q convex, t finite with the interiors of P and Q + t not overlapping (the caller
// checked), d finite non-zero. The ray t + s·d̂ enters the closed M = P ⊕ (−Q) where the line
// leaves M along −d: find_exit on the back chains (the front chains of −d), the same simultaneous
// binary search as σ_d. Returns the Cast2 (engine coordinates) when the line crosses int M or
// misses M; nullopt when the line only touches ∂M (tangent at an extreme vertex or along an edge
// parallel to d), which the caller answers on the boundaries (src/nonconvex2/boundary_distance).
#pragma once

#include <pendepth/depth2.hpp>

#include <optional>

namespace pendepth::convex2 {

std::optional<Cast2> convex_cast(const ConvexPolygon& P, const ConvexPolygon& Q, const Vec2& t, const Vec2& d);

}  // namespace pendepth::convex2
