// pendepth — the per-pair no-fit polygon of two simple polygons with holes (issue 5 item 4;
// DHS §6 "build the convolution", survey §2 reduced convolution).
//
// Conventions and semantics as depth2_polygon_polygon.hpp: P fixed, Q placed at t, M = P ⊕ (−Q),
// the overlap set O = {t : int P ∩ int(Q + t) ≠ ∅} = ∪ int S_ij (S_ij = T_i ⊕ (−U_j) for the
// triangles T_i of P and U_j of Q). NoFitPolygon2 builds ∂O once, exactly, and answers batches of
// queries with a spatial index; every answer equals PairDepth2's (same kind, features, value to a
// few ulps, identical overlap decisions).
//
// Degenerate fits (documented semantics, tested): touching is not overlapping, so
//   - a slit is a segment of ℝ² \ O with O on both sides: Q slides exactly in a slot of P of Q's
//     width. Placements on it have depth 0 (overlapping false); next to it depth is positive and
//     small (the slit is part of ∂O, so σ measures the distance to it);
//   - an isolated point is a placement where Q fits a pocket or hole of P exactly: depth 0 there,
//     positive around it.
// M itself (the closed Minkowski sum) contains slits and points in its interior; cl(O) = M up to
// those lower-dimensional pieces, and cl(O) is what polygons() exports.
//
// Construction (see src/nonconvex2/nfp_build.cpp for the details and complexity):
//   1. candidates = the reduced convolution: an edge of P paired with each vertex of −Q at which
//      Q + x can touch that edge from outside only at the vertex (both incident Q edges lie on the
//      non-P side), and symmetrically an edge of Q with the vertices of P; every candidate is an
//      edge of some convex pair sum S_ij, kept symbolic (P vertex + −Q vertex); of the collinear
//      candidates of two antiparallel edges, one convolution path's are redundant (the other
//      path covers them) and only split the others in step 2;
//   2. each candidate is split where other candidates meet it (crossings, collinear ends) and each
//      part, and each split point, is classified by one exact point test against the open sums
//      S_ij whose boxes hold it; maximal uncovered runs are the pieces of ∂O (the same pieces as
//      cutting every candidate by every open sum meeting it, the reference kept as fallback);
//   3. pieces are linked into rings by exact equality of their symbolic ends; rings are oriented
//      with O on the left (outer rings CCW, holes CW); pieces with O on both sides are slits,
//      zero-length pieces with O all around are isolated points;
//   4. a bounding-volume hierarchy over the pieces answers the queries.
//
// Complexity (n, m vertices of P, Q; K candidates, K ≤ nm; X box-overlapping candidate pairs; N
// pieces of ∂O): build O(nm) candidate tests, O(K log K + X) meeting tests and one point test per
// part and split point (a few sums on real pieces, worst O(nm)); a candidate met by more than 256
// others is cut instead (O(nm)), so the worst case stays O(n²m²) exact tests, the bound of the
// explicit convolution (DHS §6); export O(N log N) filtered exact predicates. Queries (issue 19
// item 1, src/nonconvex2/nfp_fast.cpp): a floating fast path over flat arrays of ∂O whose every
// decision is certified by a static error bound, exact predicates only where it is too close to
// call. overlapping(t): parity over the ring edges (above 16 edges only those of t's horizontal
// slab, O(√N)-ish on round shapes), the exact pair-sum test when undecided (t on or ulps from
// ∂O, level with a vertex) or when slabs do not pay (tall edges). σ / σ_d up to 256 pieces: a
// scan for the pieces that can win, then only those evaluated exactly (O(N) flops plus O(1)
// exact work on real pieces); beyond, a best-first traversal of the piece hierarchy, O(log N + k)
// node visits for k boxes near the answer (worst O(N)). Pieces exactly equally near (or hit at
// the same λ) report the lowest piece index's features. Values: σ = √RN(σ²), σ_d = RN(λ) times
// ‖d‖ (λ on the scaled d; ‖d‖ to ~1 ulp, the product rounded) and σ's translation coordinates
// RN(exact), RN the exact real rounded to nearest — a function of the exact value only
// (src/geometry/rounded.hpp): double-double with a static error bound where that certifies it
// (src/nonconvex2/nfp_value.cpp), rationals otherwise.
// Build and query times, and the comparison with CGAL's minkowski_sum_2: docs/benchmarks.md.
// Internal inconsistencies of the pieces (a chain that does not close, a hole outside every outer
// ring) throw std::logic_error rather than export a wrong polygon; no test input has produced one.
// Departure from a winding-number / ray-parity NFP: membership in O is always decided by the open
// convex pair sums (exact and symbolic), which is what separates slits and isolated points from the
// interior of M.
#pragma once

#include <pendepth/depth2.hpp>
#include <pendepth/polygon.hpp>

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace pendepth {

/// Size of a built no-fit polygon (for tests, benchmarks and the CLI).
struct NfpSize {
  std::size_t candidates = 0;  // reduced-convolution segments examined
  std::size_t pieces = 0;      // uncovered closed pieces of ∂O kept
  std::size_t rings = 0, slits = 0, points = 0;
  std::size_t bytes = 0;       // heap bytes of the structure (pieces + index + exported rings)
};

/// The per-pair no-fit polygon of two simple polygons with holes (issue 5 item 4): the boundary of
/// the overlap set O (same O as PairDepth2: O = ∪ int S_ij = {t : int P ∩ int(Q+t) ≠ ∅}), built
/// once, exactly, with a spatial index for batches of queries.
class NoFitPolygon2 {
 public:
  /// Builds ∂O. Throws nothing for valid Polygons.
  NoFitPolygon2(const Polygon& P, const Polygon& Q);
  ~NoFitPolygon2();
  NoFitPolygon2(NoFitPolygon2&&) noexcept;
  NoFitPolygon2& operator=(NoFitPolygon2&&) noexcept;

  /// Exact: t ∈ O. Same answer as PairDepth2::overlapping.
  bool overlapping(const Vec2& t) const;
  /// σ_d, same contract, kind and value (to a few ulps) as PairDepth2::along: 0 (not overlapping)
  /// for t ∉ O, else the distance along d̂ to the first point of ∂O (slits and points included).
  Depth2 along(const Vec2& t, const Vec2& d) const;
  /// σ, same contract, kind and value (to a few ulps) as PairDepth2::minimum: 0 for t ∉ O, else
  /// the distance from t to the nearest point of ∂O (slits and points included).
  Depth2 minimum(const Vec2& t) const;
  /// Lean σ and σ_d: minimum(t) / along(t, d) without the contact's features, witnesses and
  /// normal — depth, translation and overlapping bit for bit those of the full query (the same
  /// winner and values), for loops that only need the move. Same input checks.
  DepthValue2 depth_value(const Vec2& t) const;
  DepthValue2 directional_depth_value(const Vec2& t, const Vec2& d) const;

  /// cl(O) as polygons with holes: polygons()[k][0] is an outer ring (CCW), polygons()[k][1..]
  /// its holes (CW); no closing vertex repeated. Vertices are the exact vertices of ∂O rounded to
  /// the nearest double. Slits and isolated points (below) are not part of these rings.
  const std::vector<std::vector<std::vector<Vec2>>>& polygons() const;
  /// Slits: maximal segments of ℝ² \ O with O on both sides (Q slides exactly in a slot of P:
  /// touching, depth 0). Ends rounded to nearest.
  const std::vector<std::array<Vec2, 2>>& slits() const;
  /// Isolated points of ℝ² \ O surrounded by O (Q fits a pocket or hole exactly).
  const std::vector<Vec2>& points() const;
  NfpSize size() const;

  struct Impl;
  /// Test hook (private header nfp_impl.hpp has Impl): the stored pieces and rings.
  friend const Impl& nfp_impl(const NoFitPolygon2& nfp);
  /// Internal (src/front/pair2.cpp): wraps a built Impl (one made from shared per-shape sides).
  friend NoFitPolygon2 nfp_from_impl(std::unique_ptr<Impl> impl);

 private:
  explicit NoFitPolygon2(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace pendepth
