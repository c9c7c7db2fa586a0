// pendepth — 2D intersection depth of a simple polygon with holes P and a convex polygon Q
// (DHS §4, Remark after Theorem 4.4; §6 complete separation).
//
// Conventions as depth2.hpp: P fixed, Q placed at t, M = P ⊕ (−Q), d̂ = d/|d|.
// Semantics (exact): P is triangulated into T_1..T_s and R_i = T_i ⊕ (−Q). The overlap set
//   O = {t : int P ∩ int(Q + t) ≠ ∅} = ∪ int R_i
// exactly (an open non-empty int P ∩ int(Q + t) meets some int T_i; for convex T_i and Q,
// int T_i ∩ int(Q + t) ≠ ∅ ⇔ t ∈ int R_i). O ⊆ int M, but NOT always equal: where Q fits a
// pocket exactly, M has a slit of touching placements inside its topological interior (DHS
// Lemma 2.1 assumes this away). Touching is not overlapping (docs/design.md §1.2), so O is used:
//   overlapping(t)  ⇔ t ∈ O;
//   σ_d(t)          = end of the connected component containing λ = 0 of {λ : t + λ·d̂ ∈ O}, the
//                     union of the open intervals the line spends in each int R_i. Intervals that
//                     only share an endpoint are NOT connected: Q touches P there, e.g. Q sliding
//                     along a slot it fits exactly has depth 0 along the slot;
//   separation(t,d) = sup{λ ≥ 0 : t + λ·d̂ ∈ O} (0 if the ray never meets O): the last exit, after
//                     which Q slides to infinity without overlap (docs/design.md §1.1 literally: also
//                     positive when t ∉ O but the ray meets O later; `overlapping` tells t ∈ O).
// Features in results use Polygon's global numbering (vertex g = Polygon::vertices()[g], edge g
// from g to Polygon::next(g)) and Q's normal-form numbering.
#pragma once

#include <pendepth/depth2.hpp>
#include <pendepth/polygon.hpp>

#include <memory>
#include <vector>

namespace pendepth {

/// Per-pair query object for P (simple, with holes) against convex Q. The construction
/// triangulates P, builds the implicit convolved triangles (DHS §4.1 Steps 1-2) and the implicit
/// boundary of their union (Step 3) with a ray-shooting index. along() is the fast σ_d path
/// (§4.3), separation() shoots at the outer boundary of the union (§6).
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

  /// σ (kind Minimum): dist(t, ∂O) for t ∈ O (0 and overlapping = false otherwise), the nearest
  /// point of the implicit union boundary (DHS §4.2, Lemma 4.3). Throws InvalidInput for non-finite t.
  Depth2 minimum(const Vec2& t) const;
  std::size_t triangle_count() const;

  /// Size of the implicit union boundary ∂O (DHS §4.1 Step 3, Facts 4.1-4.2).
  struct BoundaryStats {
    std::size_t rings = 0;     ///< closed boundary cycles of O (outer + holes of O)
    std::size_t vertices = 0;  ///< explicit vertices (intersection points and piece ends)
    std::size_t segments = 0;  ///< straight pieces (a triangle edge translated by a vertex of −Q)
    std::size_t arcs = 0;      ///< convex arcs (a chain of −Q's edges translated by a vertex of P)
    std::size_t bytes = 0;     ///< heap bytes of the structure, ray-shooting index included
  };
  BoundaryStats boundary_stats() const;
  /// ∂O as closed rings of points for drawing and export, arcs expanded into the vertices of −Q
  /// they pass (O(n·m) points in the worst case; the structure itself stays O(n + m)). Outer
  /// rings counter-clockwise, holes of O clockwise; points rounded to doubles. Degenerate parts of
  /// ∂O are kept: a slit (Q fits a pocket exactly) is walked along both sides, an isolated
  /// boundary point (Q fits a hole exactly) is a ring of one point.
  std::vector<std::vector<Vec2>> boundary_rings() const;

  struct Impl;
  /// Test and benchmark hook: the private header src/polygon2/query_impl.hpp has Impl and the
  /// reference query paths (along_scan, along_triangles, separation_triangles).
  friend const Impl& polygon_depth_impl(const PolygonDepth2& pd);
  /// Internal (src/front/pair2.cpp): wraps a built Impl (one made from a shape's shared triangulation).
  friend PolygonDepth2 polygon_depth_from_impl(std::unique_ptr<Impl> impl);

 private:
  explicit PolygonDepth2(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// σ_d for a fixed list of directions (DHS §6): one decomposition of the overlap set O per
/// direction (slabs parallel to it, their orders kept in a persistent search tree), with point
/// location answering each query in expected O(log n) exact tests (O(log n · log m) on arcs), in
/// expected O(n) space per direction (bytes() reports it).
class PolygonDirectionSet {
 public:
  /// Throws InvalidInput naming the index of a zero or non-finite direction.
  PolygonDirectionSet(const PolygonDepth2& pd, std::vector<Vec2> directions);
  ~PolygonDirectionSet();
  PolygonDirectionSet(PolygonDirectionSet&&) noexcept;
  PolygonDirectionSet& operator=(PolygonDirectionSet&&) noexcept;

  std::size_t size() const;
  const Vec2& direction(std::size_t k) const;
  /// σ_d along direction k (kind Directional); equal to PolygonDepth2::along(t, direction(k)).
  /// Throws InvalidInput for non-finite t or k out of range.
  Depth2 along(const Vec2& t, std::size_t k) const;
  std::size_t bytes() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace pendepth
