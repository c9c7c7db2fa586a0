// pendepth — 2D intersection depth of convex polygons (DHS §2-§3).
//
// Notation: P fixed, Q moving, placed at translation t (Q + t). M = P ⊕ (−Q); the interiors of
// P and Q + t overlap ⇔ t ∈ int M (DHS Lemma 2.1). n = |P|, m = |Q|.
//   σ_d(t): exit parameter of the ray t + s·d̂ from int M (0 when t ∉ int M);
//   σ(t)  : dist(t, ∂M) for t ∈ int M, else 0.
// Touching (t ∈ ∂M) is not overlapping: depth 0. All results are finite; queries on valid shapes
// never throw except for an invalid direction (zero or non-finite d), which throws InvalidInput.
#pragma once

#include <pendepth/geometry.hpp>
#include <pendepth/polygon.hpp>

#include <cstddef>
#include <memory>
#include <vector>

namespace pendepth {

enum class FeatureKind { None, Vertex, Edge };

/// A vertex or an edge of a normal-form polygon. Edge i joins vertex i and vertex i+1 (cyclic).
/// Indices refer to the normal form (ConvexPolygon::operator[]); ConvexPolygon::input_index maps
/// vertices back to the ring as given.
struct Feature {
  FeatureKind kind = FeatureKind::None;
  int index = -1;
  friend bool operator==(const Feature&, const Feature&) = default;
};

enum class DepthKind { Minimum, Directional, Separation };

/// Result of a 2D depth query. When the interiors do not overlap (and, for a separation query,
/// the ray never meets P): depth 0, translation 0, normal 0, overlapping false, features None,
/// witnesses 0. `overlapping` is decided exactly; a
/// depth below the double range (placements at subnormal scale) is reported as overlapping with
/// depth 0 and a valid unit normal.
struct Depth2 {
  double depth = 0;          ///< length of the translation, input units, >= 0
  Vec2 translation{0, 0};    ///< move to apply to Q (after its placement t) to separate
  Vec2 normal{0, 0};         ///< unit direction of `translation` (d̂ for σ_d); outward normal of M
                             ///< at the exit point for σ
  Vec2 witness_p{0, 0};      ///< point of ∂P touching the moved Q (world frame)
  Vec2 witness_q{0, 0};      ///< point of ∂(Q + t + translation) touching P (world frame)
  Feature feature_p;         ///< feature of P at the contact after the move
  Feature feature_q;         ///< feature of Q at the contact after the move
  bool overlapping = false;  ///< interiors of P and Q + t overlap
  DepthKind kind = DepthKind::Minimum;
};

/// The lean answer of σ / σ_d (Pair2::depth_value / directional_depth_value,
/// NoFitPolygon2::depth_value / directional_depth_value; issue 19 item 1, for nesting loops): the
/// depth and the translation only, each bit for bit the field of the full query's Depth2.
struct DepthValue2 {
  double depth = 0;          ///< Depth2::depth (0 when not overlapping)
  Vec2 translation{0, 0};    ///< Depth2::translation
  bool overlapping = false;  ///< Depth2::overlapping
};

/// Signed distance (docs/design.md §1; the FCL / Drake / Coal convention): `distance` > 0 when
/// the shapes are apart (their Euclidean distance), 0 when they touch, −σ(t) when the interiors
/// overlap. Uniformly: witness_p ∈ ∂P and witness_q ∈ ∂(Q + t) (the unmoved Q, world frame) with
/// witness_q − witness_p = distance·normal; `normal` is the unit direction in which moving Q
/// increases the distance (from P towards Q when apart, σ's normal when overlapping; 0 when
/// touching); `translation` = witness_p − witness_q = −distance·normal brings Q into touching
/// contact (towards P when apart, out of P when overlapping). Features as in Depth2 (of Q + t).
struct Distance2 {
  double distance = 0;
  Vec2 translation{0, 0};
  Vec2 normal{0, 0};
  Vec2 witness_p{0, 0};
  Vec2 witness_q{0, 0};
  Feature feature_p;
  Feature feature_q;
  bool overlapping = false;  ///< interiors of P and Q + t overlap (distance < 0)
};

/// Shape cast (time of impact) along d: the smallest s >= 0 with Q + t + s·d̂ touching P, i.e.
/// the ray t + s·d̂ entering P ⊕ (−Q) (closed). `distance` = s: 0 when Q + t already touches or
/// overlaps P, +infinity when the ray never meets P ⊕ (−Q) (then `hit` is false and the vectors
/// are 0). On a hit: `translation` = s·d̂, `normal` the outward unit normal of P ⊕ (−Q) at the
/// entry point (pointing from P towards Q; 0 when s = 0 and the shapes overlap), witnesses the
/// contact point on ∂P and on the moved ∂Q (they coincide), features of the contact.
struct Cast2 {
  double distance = 0;
  Vec2 translation{0, 0};
  Vec2 normal{0, 0};
  Vec2 witness_p{0, 0};
  Vec2 witness_q{0, 0};
  Feature feature_p;
  Feature feature_q;
  bool hit = false;          ///< the ray meets P ⊕ (−Q) (distance finite)
  bool overlapping = false;  ///< interiors of P and Q + t overlap at s = 0
};

/// σ_d: smallest s >= 0 such that P and Q + t + s·d̂ have disjoint interiors, by prune-and-search
/// on the implicit front chains of P and −Q (DHS §3; docs/algorithms.md §R2.7). O(log n + log m), M
/// never built. Throws InvalidInput if d is zero or non-finite, or t is non-finite.
Depth2 directional_depth(const ConvexPolygon& P, const ConvexPolygon& Q, const Vec2& t, const Vec2& d);

/// Complete separation along d (DHS §6): smallest s >= 0 such that Q + t + s'·d̂ is
/// interior-disjoint from P for every s' >= s. M is convex, so the ray meets int M in at most one
/// interval and this is its end: equal to σ_d whenever the interiors overlap at t, and also
/// positive when t ∉ int M but the ray enters M later (then `overlapping` is false and `depth` is
/// the length of the move past P). Kind Separation. O(log n + log m).
Depth2 separation_depth(const ConvexPolygon& P, const ConvexPolygon& Q, const Vec2& t, const Vec2& d);

/// σ: the shortest separating translation, by merging the edges of P and −Q in slope order and
/// taking the nearest edge line of M (DHS §3). O(n + m). Throws InvalidInput if t is non-finite.
Depth2 minimum_depth(const ConvexPolygon& P, const ConvexPolygon& Q, const Vec2& t);

/// The explicit M = P ⊕ (−Q) in normal form (CCW, strictly convex, vertex 0 lowest-leftmost),
/// vertices rounded to double. O(n + m). For export and drawing; queries never use it.
std::vector<Vec2> minkowski_difference(const ConvexPolygon& P, const ConvexPolygon& Q);

/// Preprocessed depth field for a fixed pair (DHS Theorem 3.2): the medial axis of M and a
/// point-location structure over it (centroid decomposition of the medial-axis tree, 3-sector
/// tests; docs/algorithms.md §R3). Build O((n + m) log(n + m)); query O(log(n + m)).
/// The field keeps copies of what it needs; P and Q may be destroyed afterwards.
class DepthField {
 public:
  DepthField(const ConvexPolygon& P, const ConvexPolygon& Q);
  ~DepthField();
  DepthField(DepthField&&) noexcept;
  DepthField& operator=(DepthField&&) noexcept;

  /// σ(t), same contract and result as minimum_depth(P, Q, t). O(log(n + m)).
  Depth2 minimum(const Vec2& t) const;

  /// Number of edges of M and of medial-axis nodes (for tests and benchmarks).
  std::size_t edge_count() const;
  std::size_t node_count() const;
  /// Maximum number of point-location steps any query can take.
  std::size_t max_search_depth() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

/// Per-pair query object: validate once, preprocess once, query many (docs/design.md §2).
/// minimum() uses the DepthField (O(log)), along()/separation() the O(log n + log m) search.
class DepthQuery2 {
 public:
  DepthQuery2(ConvexPolygon P, ConvexPolygon Q);
  Depth2 minimum(const Vec2& t) const { return field_.minimum(t); }
  Depth2 along(const Vec2& t, const Vec2& d) const { return directional_depth(P_, Q_, t, d); }
  Depth2 separation(const Vec2& t, const Vec2& d) const { return separation_depth(P_, Q_, t, d); }
  const ConvexPolygon& P() const { return P_; }
  const ConvexPolygon& Q() const { return Q_; }
  const DepthField& field() const { return field_; }

 private:
  ConvexPolygon P_, Q_;
  DepthField field_;
};

}  // namespace pendepth
