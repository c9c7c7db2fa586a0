// pendepth — 2D intersection depth of a simple polygon with holes P and a convex polygon Q
// (DHS §4, Remark after Theorem 4.4; §6 complete separation).
//
// Conventions as depth2.hpp: P fixed, Q placed at t, M = P ⊕ (−Q), d̂ = d/|d|.
// Semantics (exact): P is triangulated into T_1..T_s and R_i = T_i ⊕ (−Q). The overlap set
//   O = {t : int P ∩ int(Q + t) ≠ ∅} = ∪ int R_i
// exactly (an open non-empty int P ∩ int(Q + t) meets some int T_i; for convex T_i and Q,
// int T_i ∩ int(Q + t) ≠ ∅ ⇔ t ∈ int R_i). O ⊆ int M, but NOT always equal: where Q fits a
// pocket exactly, M has a slit of touching placements inside its topological interior (DHS
// Lemma 2.1 assumes this away). Touching is not overlapping (DESIGN.md §1), so O is used:
//   overlapping(t)  ⇔ t ∈ O;
//   σ_d(t)          = end of the connected component containing λ = 0 of {λ : t + λ·d̂ ∈ O}, the
//                     union of the open intervals the line spends in each int R_i. Intervals that
//                     only share an endpoint are NOT connected: Q touches P there, e.g. Q sliding
//                     along a slot it fits exactly has depth 0 along the slot;
//   separation(t,d) = sup{λ ≥ 0 : t + λ·d̂ ∈ O} (0 if the ray never meets O): the last exit, after
//                     which Q slides to infinity without overlap (DESIGN.md §1 literally: also
//                     positive when t ∉ O but the ray meets O later; `overlapping` tells t ∈ O).
// Features in results use Polygon's global numbering (vertex g = Polygon::vertices()[g], edge g
// from g to Polygon::next(g)) and Q's normal-form numbering.
#pragma once

#include <pendepth/depth2.hpp>
#include <pendepth/polygon.hpp>

#include <memory>

namespace pendepth {

/// Per-pair query object for P (simple, with holes) against convex Q. The construction
/// triangulates P and builds the implicit convolved triangles (DHS §4.1 Steps 1-2):
/// O(n log n + n log m). Queries here are the exact reference implementation: each one visits all
/// s = O(n) convolved triangles in O(log m) and merges their intervals, O(n log m + n log n).
class PolygonDepth2 {
 public:
  PolygonDepth2(const Polygon& P, const ConvexPolygon& Q);
  ~PolygonDepth2();
  PolygonDepth2(PolygonDepth2&&) noexcept;
  PolygonDepth2& operator=(PolygonDepth2&&) noexcept;

  /// Exact: do the interiors of P and Q + t overlap? Throws InvalidInput for non-finite t.
  bool overlapping(const Vec2& t) const;
  /// σ_d (kind Directional). Throws InvalidInput for non-finite t or zero / non-finite d.
  Depth2 along(const Vec2& t, const Vec2& d) const;
  /// Complete separation along d (kind Separation); `overlapping` reports t ∈ O (the depth may be
  /// positive when t ∉ O). Witnesses and features describe the final contact. Throws as along().
  Depth2 separation(const Vec2& t, const Vec2& d) const;

  std::size_t triangle_count() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace pendepth
