// Private: the explicit convolution M = P ⊕ (−Q) of two normal-form convex polygons, kept
// symbolic — every vertex is a pair (P vertex ia, Q vertex iq) meaning P[ia] − Q[iq], every edge
// is an edge of P, of −Q, or of both (parallel edges merged), so distances are evaluated from
// input coordinates, never from rounded sums (DHS §3, Theorem 3.1: edges merged in slope order).
#pragma once

#include <pendepth/depth2.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace pendepth::convex2 {

enum class EdgeSource : std::uint8_t { P, Q, Both };

/// Edge k of M runs from vertex k to vertex k+1 (cyclic). Its start vertex is P[ia] − Q[iq].
/// Source P: the edge is P's edge ia (ia -> ia+1) and Q's vertex iq is fixed.
/// Source Q: the edge is −(Q's edge iq) (Q vertex iq -> iq+1 reversed), P's vertex ia fixed.
/// Source Both: P's edge ia and Q's edge iq are parallel; M's edge is their sum.
struct MEdge {
  std::uint32_t ia = 0, iq = 0;
  EdgeSource src = EdgeSource::P;
};

/// Edge k's vector as exact endpoints (from, to): P's edge for sources P and Both, −(Q's edge)
/// for source Q. p, q: normal-form vertices of P and Q.
void edge_points(std::span<const Vec2> p, std::span<const Vec2> q, const MEdge& e, Vec2& from, Vec2& to);
/// Exact sign of the signed distance from t to edge e's line (> 0: strictly inside its half-plane).
int edge_side(std::span<const Vec2> p, std::span<const Vec2> q, const MEdge& e, const Vec2& t);
/// Signed distance from t to the line of edge e of M (positive inside), to a few ulps.
double edge_distance(std::span<const Vec2> p, std::span<const Vec2> q, const MEdge& e, const Vec2& t);
/// The σ result for placement t ∈ int M whose nearest edge of M is e at distance dist >= 0
/// (dist is 0 only when the true distance underflows the double range).
Depth2 edge_result(std::span<const Vec2> p, std::span<const Vec2> q, const MEdge& e, const Vec2& t, double dist);

class MinkowskiSum {
 public:
  /// O(n + m) merge; vertex 0 is P[0] − Q[Q.top()], the lowest-leftmost vertex of M.
  /// Owns copies of the vertices (P and Q may be destroyed afterwards).
  MinkowskiSum(const ConvexPolygon& P, const ConvexPolygon& Q);
  /// An empty sum to be filled by assign_view (scratch objects reused across queries).
  MinkowskiSum() = default;
  MinkowskiSum(const MinkowskiSum&) = delete;
  MinkowskiSum& operator=(const MinkowskiSum&) = delete;
  MinkowskiSum(MinkowskiSum&&) noexcept = default;
  MinkowskiSum& operator=(MinkowskiSum&&) noexcept = default;
  /// Rebuilds as a view: P and Q must outlive this object's use. Reuses the edge buffer, so a
  /// thread-local scratch object makes repeated O(n + m) queries allocation-free.
  void assign_view(const ConvexPolygon& P, const ConvexPolygon& Q);

  std::size_t size() const { return edges_.size(); }
  const MEdge& edge(std::size_t k) const { return edges_[k]; }
  /// Vertex k rounded to double (for drawing and medial-axis construction only).
  Vec2 vertex(std::size_t k) const;
  /// A vector along edge k: P's edge for sources P and Both, −(Q's edge) for source Q (exact
  /// endpoints returned as (from, to) so predicates can use them).
  void edge_points(std::size_t k, Vec2& from, Vec2& to) const;
  /// Unit outward normal of edge k (double).
  Vec2 outward_normal(std::size_t k) const;

  /// Exact sign of the signed distance from t to edge k's line: > 0 strictly inside its half-plane.
  int side(std::size_t k, const Vec2& t) const;
  /// Signed distance from t to edge k's line (positive inside), to a few ulps.
  double distance(std::size_t k, const Vec2& t) const;
  /// Fast double estimate of distance(k, t) and a rigorous bound on its error.
  void distance_estimate(std::size_t k, const Vec2& t, double& value, double& error) const;

  /// Exact: is t in the interior of M? O(log(n + m)) by fan binary search from vertex 0.
  bool contains_interior(const Vec2& t) const;

  /// Builds the σ result for placement t whose nearest edge of M is k at distance `dist` > 0:
  /// translation dist·n_k, witnesses and features.
  Depth2 result_for_edge(std::size_t k, const Vec2& t, double dist) const;

  std::span<const Vec2> p() const { return p_; }
  std::span<const Vec2> q() const { return q_; }

 private:
  void merge(std::size_t top);
  void build_fan();
  static constexpr std::size_t kFanBlock = 64;
  std::vector<std::array<Vec2, 2>> fan_;  // (P vertex, Q vertex) of M's vertices 64k
  std::vector<Vec2> own_p_, own_q_;  // storage when owning
  std::span<const Vec2> p_, q_;      // normal-form vertices of P and Q
  std::vector<MEdge> edges_;
};

/// Nearest edge of M to t among all edges (the O(n + m) scan of minimum_depth), certified:
/// candidates are filtered in double and the near-ties re-evaluated accurately.
/// Returns {edge, distance}; distance <= 0 means t is not in int M.
struct Nearest {
  std::size_t edge = 0;
  double distance = 0;
};
Nearest nearest_edge(const MinkowskiSum& M, const Vec2& t, const std::size_t* first = nullptr,
                     const std::size_t* last = nullptr);

/// Throws InvalidInput naming `what` if v has a non-finite coordinate.
void require_finite(const Vec2& v, const char* what);

}  // namespace pendepth::convex2
