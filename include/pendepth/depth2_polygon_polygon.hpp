// pendepth — 2D intersection depth of two simple polygons, both possibly non-convex and with holes
// (DHS §6, last paragraphs; issue 5).
//
// Conventions as depth2.hpp: P fixed, Q placed at t, M = P ⊕ (−Q), d̂ = d/|d|.
// Semantics (exact, as depth2_polygon_convex.hpp): P is triangulated into T_1..T_s, Q into U_1..U_r, and
// S_ij = T_i ⊕ (−U_j) (a convex polygon with at most 6 edges). The overlap set is
//   O = {t : int P ∩ int(Q + t) ≠ ∅} = ∪ int S_ij
// exactly (a non-empty open int P ∩ int(Q + t) meets some int T_i ∩ int(U_j + t), and for convex
// pieces that is t ∈ int S_ij). O ⊆ int M but not always equal: where Q fits a slot of P exactly,
// M has slits of touching placements; touching is not overlapping, so those have depth 0.
//   overlapping(t)  ⇔ t ∈ O;
//   along(t, d)     = σ_d: end of the connected component containing λ = 0 of {λ : t + λ·d̂ ∈ O}
//                     (open intervals sharing only an endpoint are NOT connected);
//   minimum(t)      = σ: dist(t, ℝ² \ O) for t ∈ O (the nearest placement that only touches);
//   separation(t,d) = sup{λ ≥ 0 : t + λ·d̂ ∈ O}, 0 if the ray never meets O: the smallest s with
//                     Q + t + s'·d̂ interior-disjoint from P for every s' ≥ s (DHS §6 "complete
//                     separation"; positive also when t ∉ O but the ray meets O later).
// Features in results use each Polygon's global numbering (vertex g = Polygon::vertices()[g], edge g
// from g to Polygon::next(g)); feature_p refers to P, feature_q to Q.
#pragma once

#include <pendepth/depth2.hpp>
#include <pendepth/polygon.hpp>

#include <cstddef>
#include <memory>

namespace pendepth {

/// Work counters of one query (for tests and benchmarks): node pairs of the two box hierarchies
/// visited and convex pair sums S_ij examined exactly.
struct PairQueryStats {
  std::size_t node_pairs = 0;
  std::size_t pairs = 0;
};

/// Per-pair query object for two simple polygons with holes. Construction triangulates both
/// (exact ear clipping for hole-free shapes of ≤ 32 vertices, CGAL constrained Delaunay otherwise;
/// no Steiner points) and builds a bounding-box hierarchy over each
/// triangulation: O(n log n + m log m). The s·r ≤ (n + 2h_P)(m + 2h_Q) pair sums are never stored;
/// each is rebuilt in O(1) (exact angle merge of 3 + 3 edges) when a query reaches it.
/// Queries never throw for valid t, d; non-finite t or a zero / non-finite d throw InvalidInput.
class PairDepth2 {
 public:
  PairDepth2(const Polygon& P, const Polygon& Q);
  ~PairDepth2();
  PairDepth2(PairDepth2&&) noexcept;
  PairDepth2& operator=(PairDepth2&&) noexcept;

  /// Exact: t ∈ O. Dual-tree descent to the pairs whose sum box contains t. Worst case O(nm).
  bool overlapping(const Vec2& t, PairQueryStats* stats = nullptr) const;

  /// σ_d (kind Directional). Best-first dual-tree traversal: node pairs in order of the ray's entry
  /// into box(A) ⊕ (−box(B)); stops once no unvisited pair can start before the running end of the
  /// component. Worst case O(nm log(nm)); measured counts in docs/algorithms.md.
  Depth2 along(const Vec2& t, const Vec2& d, PairQueryStats* stats = nullptr) const;

  /// σ (kind Minimum). Upper bound U = min of σ_d over 8 directions; the pair sums meeting the disk
  /// of radius U around t are collected; every edge of each is cut by the open others (exact
  /// parameters along the edge), and the nearest point of the uncovered closed pieces is taken
  /// (exact comparisons of squared distances). Worst case O(K²) for K sums meeting the disk
  /// (K ≤ nm); the normal is the unit vector from t to the nearest boundary point of O.
  Depth2 minimum(const Vec2& t, PairQueryStats* stats = nullptr) const;

  /// Complete separation along d (kind Separation), DHS §6: the right envelope of P's outer ring
  /// seen from infinity along +d and the left envelope of Q's outer ring seen from −∞ are merged by
  /// the coordinate perpendicular to d; the answer is the largest one-sided limit of (P envelope −
  /// Q envelope) at the merged breakpoints, clamped at 0. Holes never matter (a hole lies inside
  /// the outer ring, which alone bounds what the other shape can reach from infinity). Each
  /// envelope is the external visibility polygon of the outer ring from the point at infinity,
  /// built by a linear-time stack walk (the paper's "standard visibility-polygon algorithm"); the
  /// merge and evaluation are linear: O(n + m) per query, plus the overlap test reported in
  /// `overlapping` (t ∈ O).
  Depth2 separation(const Vec2& t, const Vec2& d) const;

  std::size_t triangle_count_p() const;
  std::size_t triangle_count_q() const;

  struct Impl;
  /// Internal (src/front/pair2.cpp): wraps a built Impl (one made from shared per-shape sides).
  friend PairDepth2 pair_from_impl(std::unique_ptr<Impl> impl);

 private:
  explicit PairDepth2(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace pendepth
