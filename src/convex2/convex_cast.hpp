// Private: the shape cast of two convex polygons in O(log n + log m) (issue 16 item 3) and the
// localisation of their distance (item 2; docs/algorithms.md "Signed distance and shape cast in
// 2D"), defined in directional.cpp next to the prune-and-search and chains they reuse.
//
// Contract: P, Q convex, t finite with the interiors of P and Q + t not overlapping (the caller
// checked), d finite non-zero. The ray t + s·d̂ enters the closed M = P ⊕ (−Q) where the line
// leaves M along −d: find_exit on the back chains (the front chains of −d), the same simultaneous
// binary search as σ_d. Returns the Cast2 (engine coordinates) when the line crosses int M or
// misses M; nullopt when the line only touches ∂M (tangent at an extreme vertex or along an edge
// parallel to d), which the caller answers on the boundaries (src/nonconvex2/boundary_distance).
#pragma once

#include <pendepth/depth2.hpp>

#include <array>
#include <cstddef>
#include <optional>

namespace pendepth::convex2 {

std::optional<Cast2> convex_cast(const ConvexPolygon& P, const ConvexPolygon& Q, const Vec2& t, const Vec2& d);

/// The distance of two convex polygons, localised (issue 16 item 2): for t strictly outside M, a
/// vertex (P index, Q index) of M next to which the nearest point of M to t lies: on one of the
/// edges of M within two path steps of it (the caller measures the segments a ⊕ (−q) and
/// p ⊕ (−e) around it exactly). By the search of DHS §3 on the angle windows around the edge
/// where the ray from t towards an interior point of M enters: along M, the support-line
/// distance u·t − h_M(u) is concave where positive, so "the nearest point is at or before this
/// edge" is monotone over the edges of the window; binary search over P's edges, each placed
/// among Q's by a binary search, then over Q's: O(log n · log m). nullopt when the ray does not
/// cross int M cleanly (t on ∂M, a tangent ray): the caller uses the boundary search.
std::optional<std::array<std::size_t, 2>> convex_nearest_vertex(const ConvexPolygon& P, const ConvexPolygon& Q,
                                                                const Vec2& t);

}  // namespace pendepth::convex2
