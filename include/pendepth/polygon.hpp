// pendepth — validated 2D shapes.
//
// ConvexPolygon is the normal form every O(log n) search relies on (docs/design.md §1.3,
// docs/algorithms.md §R2.1): counter-clockwise, no duplicate or collinear vertices (strictly
// convex), vertex 0 the lowest then leftmost. Then edge vectors e_i = v_{i+1} - v_i have strictly
// increasing polar angle in [0, 2*pi), and extreme-vertex / front-chain questions are binary
// searches by exact angle order.
#pragma once

#include <pendepth/geometry.hpp>

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pendepth {

class ConvexPolygon {
 public:
  /// Validates a ring (either orientation, closing vertex optional) and stores its normal form.
  /// Consecutive duplicate vertices and collinear pass-through vertices are dropped.
  /// Throws InvalidInput, naming `name` and the input vertex index (0-based), for: fewer than 3
  /// distinct points, non-finite coordinates, zero area, a reflex vertex (non-convex), a spike
  /// (edge folding back on itself), self-intersection (ring winding more than once). O(n).
  explicit ConvexPolygon(std::span<const Vec2> ring, std::string_view name = "polygon");
  ConvexPolygon(std::initializer_list<Vec2> ring, std::string_view name = "polygon")
      : ConvexPolygon(std::span<const Vec2>(ring.begin(), ring.size()), name) {}

  /// Convex hull of a point set (Andrew's monotone chain, exact orientation), in normal form.
  /// Throws InvalidInput for non-finite coordinates or fewer than 3 non-collinear points.
  /// O(n log n).
  static ConvexPolygon hull(std::span<const Vec2> points, std::string_view name = "points");

  std::size_t size() const { return v_.size(); }
  const Vec2& operator[](std::size_t i) const { return v_[i]; }
  /// Vertex i with cyclic indexing (i may be any integer >= 0).
  const Vec2& at_cyclic(std::size_t i) const { return v_[i % v_.size()]; }
  std::span<const Vec2> vertices() const { return v_; }
  /// Vertices 64k and 64k+1 are also kept in a compact side array (n/32 entries) so the first
  /// steps of every O(log n) search on a huge polygon stay in cache; same value as operator[].
  static constexpr std::size_t kBlock = 64;
  const Vec2& vertex_cached(std::size_t i) const {
    const std::size_t r = i & (kBlock - 1);
    return r < 2 ? sample_[2 * (i / kBlock) + r] : v_[i];
  }
  /// Index of the highest-then-rightmost vertex: vertex 0 of the normal form of -P.
  std::size_t top() const { return top_; }
  /// Input index (0-based, in the ring as given) of normal-form vertex i.
  std::size_t input_index(std::size_t i) const { return input_index_[i]; }
  double area() const;
  const std::string& name() const { return name_; }

 private:
  ConvexPolygon() = default;
  void finish();
  std::vector<Vec2> v_;
  std::vector<std::size_t> input_index_;
  std::vector<Vec2> sample_;  // v[64k], v[(64k+1) mod n]
  std::size_t top_ = 0;
  std::string name_;
};

/// A simple polygon, possibly with holes (docs/design.md §1.3): ring 0 is the outer boundary, ring
/// k >= 1 is hole k. Normal form: outer ring counter-clockwise, holes clockwise (so P's interior is
/// on the left of every edge), a repeated closing vertex dropped. Each ring keeps its input vertex
/// 0 as vertex 0 (a reversed ring reads 0, n-1, ..., 1). Collinear pass-through vertices are KEPT
/// (they are legitimate vertices of a simple polygon; the triangulation handles them).
///
/// Validation (throws InvalidInput naming `name`, ring k — 0 = outer, k = hole k — and input
/// vertex/edge indices, edge i joining input vertices i and i+1 of its ring): non-finite
/// coordinates, fewer than 3 distinct points, repeated vertices, zero area (all collinear),
/// self-intersecting ring (edges i and j touch or cross, or adjacent edges fold back), two rings
/// touching or crossing (any common point is rejected: holes must lie strictly inside the outer
/// ring and be pairwise disjoint as closed sets), a hole outside the outer ring, a hole inside
/// another hole. All decisions are exact predicates. Cost: O(N log N) for the edges (a box sweep
/// with a budget of O(N) box-overlapping pairs, then a Shamos–Hoey sweep;
/// src/polygon2/edge_sweep.cpp), plus O(h·N) point-in-ring tests for the containment of h holes.
class Polygon {
 public:
  explicit Polygon(const std::vector<std::vector<Vec2>>& rings, std::string_view name = "polygon");
  /// A polygon without holes.
  static Polygon simple(std::span<const Vec2> outer, std::string_view name = "polygon");

  std::size_t ring_count() const { return offset_.size() - 1; }
  std::size_t hole_count() const { return ring_count() - 1; }
  /// Normalised ring k (0 = outer, CCW; k >= 1 holes, CW).
  std::span<const Vec2> ring(std::size_t k) const {
    return std::span<const Vec2>(v_).subspan(offset_[k], offset_[k + 1] - offset_[k]);
  }
  /// All vertices, rings concatenated: global vertex index g = ring_offset(k) + i.
  std::span<const Vec2> vertices() const { return v_; }
  std::size_t size() const { return v_.size(); }
  std::size_t ring_offset(std::size_t k) const { return offset_[k]; }
  std::size_t ring_of(std::size_t g) const;
  /// The next vertex of g's ring in normal-form order: edge g = (g, next(g)) has P's interior
  /// on its left. Global edge index g names that edge.
  std::size_t next(std::size_t g) const {
    if (offset_.size() == 2) return g + 1 == v_.size() ? 0 : g + 1;  // one ring: no search
    const std::size_t k = ring_of(g);
    return g + 1 == offset_[k + 1] ? offset_[k] : g + 1;
  }
  /// Index of global vertex g in its ring as given (closing vertex dropped).
  std::size_t input_index(std::size_t g) const { return input_index_[g]; }
  /// Area (outer minus holes), computed exactly and rounded once.
  double area() const { return area_; }
  const std::string& name() const { return name_; }

 private:
  Polygon() = default;
  std::vector<Vec2> v_;
  std::vector<std::size_t> offset_, input_index_;
  double area_ = 0;
  std::string name_;
};

}  // namespace pendepth
