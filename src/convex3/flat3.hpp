// Private: lower-dimensional shapes in 3D (points, segments, flat convex polygons) and their
// queries against a solid convex polytope (flat3.cpp; docs/design.md "Lower-dimensional shapes").
#pragma once

#include <pendepth/depth3.hpp>

#include "convex3/minkowski_facets.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pendepth::convex3 {

/// A convex point set of dimension 0, 1 or 2 in normal form: one point; the two ends of a
/// segment; or the strictly convex vertices of a flat polygon in cyclic order (no three
/// collinear). Edge j runs from v[j] to v[(j + 1) % k] (a segment has the one edge 0).
struct FlatShape3 {
  std::vector<Vec3> v;
  std::vector<std::size_t> input;  ///< index of v[j] in the input point list
  int dim = 0;
  std::string name;
  /// Exact parallel classes of a polygon with at most 64 vertices (else empty): edge_dir[j] the
  /// least edge parallel to edge j; chord_dir[a·k + b] that of the chord v[a]–v[b], −1 when no
  /// edge is parallel to it. A direction orthogonal to edge j is orthogonal to every chord of
  /// its class, so the engines skip those known ties (exact zeros cost the slowest tier).
  std::vector<int> edge_dir, chord_dir;
};

/// The normal form of a point set of dimension at most 2, decided exactly (collinear3, orient3d,
/// orient2d on the projection along the plane's dominant normal axis). Throws InvalidInput naming
/// `name` for an empty set, a non-finite point, or a full-dimensional set (use the hull).
/// O(k log k).
FlatShape3 flat_shape(std::span<const Vec3> points, std::string_view name);

/// σ (kind Minimum), σ_d (kind Directional; d in the world frame) and the signed distance of the
/// solid S (posed by pose_s, the role of P) and the lower-dimensional L (pose_l, the role of Q).
/// Exact in the sense of the other 3D engines: every decision an exact sign of a polynomial in
/// the input doubles (the placed vertices R·l + t are never rounded), lengths within a few ulps.
/// Features of L: vertex j, edge j (v[j]–v[j+1]), face 0. Cost O(C·c) for the
/// C = O(f_S + e_S·k) candidate normals (σ, σ_d) or O(n·k + e_S·k) more (distance), c a vertex
/// degree; witnesses in doubles, up to rounding (flat3.cpp).
Depth3 flat_minimum(const ConvexPolytope& S, const Pose3& pose_s, const FlatShape3& L, const Pose3& pose_l);
Depth3 flat_directional(const ConvexPolytope& S, const Pose3& pose_s, const FlatShape3& L, const Pose3& pose_l,
                        const Vec3& d);
Distance3 flat_signed_distance(const ConvexPolytope& S, const Pose3& pose_s, const FlatShape3& L,
                               const Pose3& pose_l);
/// The signed distance of two lower-dimensional shapes (the cores of rounded shapes), exact as
/// flat_signed_distance: apart → the distance; touching → 0, witnesses a common point, and
/// `touch_normal`, if given, receives a unit normal of a plane through 0 supporting
/// M = A ⊕ (−B'), world frame; overlapping (only when the dimensions sum to 3 or more — a
/// segment and a polygon, two polygons — and M is solid with 0 inside) → −σ of M, as
/// flat_signed_distance. Method: the same candidate directions with A in S's role (A's normal,
/// edge × edge, the closest pairs). Cost O((k_A·k_B)·(k_A + k_B)).
Distance3 flat_flat_distance(const FlatShape3& A, const Pose3& pose_a, const FlatShape3& B, const Pose3& pose_b,
                             Vec3* touch_normal = nullptr);
/// Shape cast of L along d (world frame) towards S: the entry of the ray s·d̂ into M = S ⊕ (−L),
/// exactly (ratios compared by exact signs): +inf (hit false) when the ray misses M.
Cast3 flat_cast(const ConvexPolytope& S, const Pose3& pose_s, const FlatShape3& L, const Pose3& pose_l,
                const Vec3& d);

}  // namespace pendepth::convex3
