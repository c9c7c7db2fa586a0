// Private: a point or a segment F against a solid 2D shape P (issue 16 item 4; docs/design.md
// "Lower-dimensional shapes", docs/algorithms.md "Points and segments in 2D"; flat_depth2.cpp).
//
// Notation: P solid (convex, or a simple polygon with holes), F = {q} or [a, b], placed at t.
// M = P ⊕ (−F) is built once as explicit rings whose vertices are exact differences p − q
// (p a vertex of P, q an end of F), never rounded:
//   F a point:        M = P − q, P's rings shifted (any P);
//   F a segment [a,b], P convex: M = hull{p − a, p − b}, a convex polygon;
//   F a segment, P not convex: the general path (struct General below, flat_segment2.cpp).
// The overlap set is O = int P ⊕ (−F) = int M (a point: always; a segment: P convex), so every
// such query is a question about one explicit polygon with holes: t ∈ int M, dist(t, ∂M), the first
// and last exits of a ray from int M, its first entry into M. Each is one pass over M's edges
// with exact predicates (src/geometry/exact.hpp: polynomials in the input doubles), candidates
// kept by floating filters with rigorous error bounds and compared exactly; the answers' lengths
// are one exactly-rounded ratio or square root from the exact value (a few ulps).
// Cost: build O(n) (a point) or O(n log n) (a segment: the exact hull); every query O(n). The
// general path: see General.
#pragma once

#include <pendepth/depth2.hpp>
#include <pendepth/pendepth.hpp>

#include <memory>
#include <span>
#include <vector>

namespace pendepth::polygon2 {

class FlatDepth2 {
 public:
  /// P's rings in normal form (outer counter-clockwise, holes clockwise; feature numbering: the
  /// position in the concatenated rings), F one point or two distinct points. A segment against a
  /// non-convex P takes the general path (flat_segment2.cpp, below).
  FlatDepth2(const std::vector<std::vector<Vec2>>& rings, bool convex, std::span<const Vec2> F);

  // Queries on validated input (t finite, d finite and non-zero), results as Pair2's.
  bool overlapping(const Vec2& t) const;
  Depth2 minimum(const Vec2& t) const;
  Depth2 along(const Vec2& t, const Vec2& d) const;
  Depth2 separation(const Vec2& t, const Vec2& d) const;
  Distance2 signed_distance(const Vec2& t) const;
  Cast2 cast(const Vec2& t, const Vec2& d) const;
  /// M's rings, vertices rounded to nearest (outer ring counter-clockwise first, holes clockwise).
  /// The general path builds none: throws InvalidInput.
  NoFitPolygonParts parts() const;

  /// A vertex of M: p − q, with the vertex index of p in P and of q in F.
  struct V {
    Vec2 p, q;
    int pi = 0, qi = 0;
  };

  /// The general path, a segment F = [a, b] against a non-convex P (flat_segment2.cpp): O =
  /// int P ⊕ (−F) is not int M at slits, so M is not built. ∂O and ∂M lie on 3n candidate
  /// segments (P's edges − a, − b; p − [a, b] for each vertex p). σ, σ_d and the separation are the
  /// nearest / first / last point outside O among the candidates' vertices, feet, pairwise
  /// crossings and ray crossings, each tested exactly (does the placed segment meet int P: a box
  /// tree over P's edges visits those near the segment);
  /// the distance and the cast are the nearest / first point of the candidates (M closed).
  struct General;

 private:
  std::shared_ptr<const General> general_;
  std::vector<V> v_;
  std::vector<std::size_t> ring_;  // ring k is v_[ring_[k], ring_[k + 1])
  int nf_ = 1;                     // vertices of F
  std::size_t next(std::size_t k) const;
  std::size_t prev(std::size_t k) const;
  enum class Where { Inside, Boundary, Outside };
  Where locate(const Vec2& t) const;
  struct Near {
    bool edge = false;  // the foot lies strictly inside edge k; else vertex k
    std::size_t k = 0;
  };
  Near nearest(const Vec2& t) const;
  struct Hit {
    bool edge = false;  // a proper crossing of edge k; else vertex k on the ray
    std::size_t k = 0;
  };
  // The hits of the ray t + λ·d (λ > 0): the first one, or the last exit from int M.
  /// The first hit (`first`) or the last exit of the ray t + λd, λ > 0 (flat_depth2.cpp).
  bool extreme_hit(const Vec2& t, const Vec2& d, bool first, Hit& out) const;
  Depth2 hit_result(const Hit& h, const Vec2& t, const Vec2& d) const;
  Feature feature_p(bool edge, std::size_t k) const;
  Feature feature_q(bool edge, std::size_t k) const;
  Vec2 contact(bool edge, std::size_t k, const Vec2& x) const;
};

// The general path's queries (flat_segment2.cpp), same contracts as FlatDepth2's.
/// The signed distance of an overlapping placement from its σ answer: −σ, the same translation
/// (out of P), Q's witness where Q is now (before the move).
Distance2 overlap_distance(const Depth2& sigma);

namespace flat_general {
/// brute: every "segment meets int P" test scans all n edges (the reference the tests compare the
/// box-tree path with; same answers).
std::shared_ptr<const FlatDepth2::General> build(const std::vector<std::vector<Vec2>>& rings, std::span<const Vec2> F,
                                                 bool brute = false);
bool overlapping(const FlatDepth2::General& G, const Vec2& t);
Depth2 minimum(const FlatDepth2::General& G, const Vec2& t);
Depth2 along(const FlatDepth2::General& G, const Vec2& t, const Vec2& d);
Depth2 separation(const FlatDepth2::General& G, const Vec2& t, const Vec2& d);
Distance2 signed_distance(const FlatDepth2::General& G, const Vec2& t);
Cast2 cast(const FlatDepth2::General& G, const Vec2& t, const Vec2& d);
}  // namespace flat_general

}  // namespace pendepth::polygon2
