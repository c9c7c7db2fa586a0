// Private: the Euclidean distance and the shape cast (time of impact) of two polygons with
// disjoint interiors, on their boundaries (issue 16 items 2–3; docs/algorithms.md "Signed
// distance and shape cast in 2D").
//
// Contract. P fixed, Q placed at t; both any valid Polygon (holes allowed; a convex shape as its
// one-ring polygon). The caller has established that the interiors of P and Q + t do not overlap
// (Pair2 asks its engine first and answers overlapping placements from σ).
//   distance(t): min over the boundaries of |x − y|. With disjoint interiors, two boundary edges
//     never cross properly, so the minimum is attained at a vertex of one shape and an edge of the
//     other: it is the minimum over the vertex–edge pairs both ways. 0 exactly when they touch.
//   cast(t, d): the smallest s >= 0 with Q + t + s·d̂ touching P. The boundaries first meet at a
//     vertex of one shape reaching an edge of the other (a vertex of Q moving along d against an
//     edge of P, or a vertex of P moving along −d against an edge of Q), so s is the minimum
//     over those events; +inf when there is none.
// Exactness. Every value is a ratio of polynomials in the input doubles (coordinates, t, d):
// each branch (projection inside the edge, ray parameter >= 0, hit inside the edge) is an exact
// sign (src/geometry/exact.hpp), candidates are ordered by the exact sign of the cross-multiplied
// difference whenever their rounded values are too close to order, exact ties keep the first
// candidate in a fixed visiting order (so the features do not depend on threads or history).
// The squared distance and the ray parameter are evaluated to ~1 ulp and rounded once; the
// distance is their square root (a few ulps).
// Complexity. Box trees over the edges of P and of Q (O(n log n + m log m), built once; through
// Pair2 once per shape, shared by its pairs: shape_side.hpp's ShapeCache). A
// query visits every vertex of both shapes and searches the other shape's tree: branch and bound
// with the best distance so far (distance), or the ray against the boxes cut at the best
// parameter so far (cast): O((n + m) log(n + m)) typical, O(nm) worst case.
#pragma once

#include <pendepth/depth2.hpp>
#include <pendepth/polygon.hpp>

#include "geometry/box_tree.hpp"

#include <cstddef>
#include <memory>

namespace pendepth::nonconvex2 {

class BoundaryPair2 {
 public:
  BoundaryPair2(const Polygon& P, const Polygon& Q);
  /// The same with the shapes' edge trees given (edge_tree(P), edge_tree(Q), shared per shape:
  /// shape_side.hpp's ShapeCache); the same bits as building them here.
  BoundaryPair2(const Polygon& P, const Polygon& Q, std::shared_ptr<const geometry::BoxTree> p_tree,
                std::shared_ptr<const geometry::BoxTree> q_tree);
  /// The box tree over S's edges (leaf k: edge k, global vertex k to next(k)). O(n log n).
  static std::shared_ptr<const geometry::BoxTree> edge_tree(const Polygon& S);

  /// Distance of P and Q + t (precondition: interiors do not overlap). `overlapping` false;
  /// distance 0 and normal 0 when touching; features as in Distance2 (global vertex/edge indices).
  Distance2 distance(const Vec2& t) const;
  /// The same answer computed from the vertex–edge pairs around one vertex of M (P vertex ip,
  /// Q vertex iq) and its two possible predecessors on ∂M only: for two convex shapes whose
  /// nearest point of M to t lies there (convex2::convex_nearest_vertex). O(1) pairs.
  Distance2 distance_near(const Vec2& t, std::size_t ip, std::size_t iq) const;
  /// Cast of Q + t along d (d finite, non-zero; precondition: interiors do not overlap at t).
  Cast2 cast(const Vec2& t, const Vec2& d) const;

 private:
  const Polygon &P_, &Q_;
  std::shared_ptr<const geometry::BoxTree> p_tree_, q_tree_;  // owners (possibly shared per shape)
  const geometry::BoxTree &p_edges_, &q_edges_;             // leaf k: edge k (global vertex k to next(k))
};

}  // namespace pendepth::nonconvex2
