// Private: the queries of Pair3 on meshes (issue 17 items 3–5): a pair of shapes, each a list of
// convex pieces with disjoint interiors covering the solid (Mesh3::decomposition(); a convex
// shape is one piece), answered from the exact convex engines on pairs of pieces.
//
// Let P = ∪ P_i, Q = ∪ Q_j (pieces), M_ij = P_i ⊕ (−Q'_j), O = ∪ int M_ij the open overlap set
// (pieces have disjoint interiors and cover the solids, so int P ∩ int(Q' + x) ≠ ∅ iff x lies in
// some int M_ij). Files: mesh_pair.cpp (pieces, boxes, overlap, signed distance, σ bounds),
// mesh_line.cpp (σ_d and separation: the open intervals of the line in the int M_ij),
// mesh_cast.cpp (the shape cast: the least convex cast over the piece pairs).
//
// Features of a mesh answer: feature_p / feature_q index the vertices, half-edges and triangles
// of the pieces piece_p / piece_q (pieces() of the pair: Mesh3::decomposition().pieces, or the
// shape's polytope for a convex shape, piece 0).
//
// Exactness: every decision is an exact sign of a polynomial in the doubles of the pieces, the
// poses' R, t and d (as the convex engines). When a decomposition has rounded pieces
// (ConvexDecomposition3::rounded_pieces > 0) the pieces are the rounded ones: the answers are
// exact for that union of pieces, which may differ from the mesh by slivers of ½ ulp.
#pragma once

#include <pendepth/depth3.hpp>
#include <pendepth/pendepth.hpp>

#include <array>
#include <functional>
#include <optional>
#include <vector>

namespace pendepth::mesh3 {

struct Box3 {
  Vec3 lo, hi;
};

/// The pieces of both shapes in engine coordinates (scaled as Pair3's numeric domain says).
struct MeshPair {
  std::vector<ConvexPolytope> P, Q;
  std::vector<Box3> boxP, boxQ;  ///< each piece's box (exact: min / max of its vertices)
  bool exact = true;             ///< no rounded pieces in either decomposition
  static MeshPair make(std::vector<ConvexPolytope> P, std::vector<ConvexPolytope> Q, bool exact);
};

/// The pieces of a shape: its decomposition's (a mesh shape), else the polytope itself.
std::vector<ConvexPolytope> pieces_of(const Shape3& s, bool& exact);

/// Exact: do the interiors overlap? Pairs of pieces whose box sum holds 0, in order, until one
/// overlaps (convex minimum_depth's exact test). O(n·m) box tests + the candidates' tests.
bool overlapping(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q);

/// σ_d (kind Directional) or complete separation (kind Separation) along d (world frame; checked
/// by the caller): see mesh_line.cpp. Exact (lower == upper == depth).
Depth3 along(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d, bool separation);

/// Private (tests, bench): how along() finds a candidate pair's interval on the line. Auto: the
/// implicit facets of M_ij (convex3::minkowski_facets) when n_i·m_j <= kFacetPathMax (vertex
/// counts), else the two DK descents; Descent / Facets force one path. Set only while no query
/// runs (not synchronised).
enum class LinePath { Auto, Descent, Facets };
inline LinePath line_path = LinePath::Auto;
inline constexpr std::size_t kFacetPathMax = 400;

/// σ with certified bounds: lower = max over overlapping piece pairs of the exact σ_ij, upper =
/// the least σ_d over a set of directions (mesh_pair.cpp); depth = upper with its translation.
/// When those bounds do not meet and the exact σ ends within its work limit (kExactSigmaMaxWork,
/// mesh_sigma_exact.hpp: a deterministic count; no SigmaBoundsOnly on the thread): the exact σ
/// (lower, upper = a 1-ulp bracket).
Depth3 minimum(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q);

/// While alive on this thread, minimum() stays on the bounds (thread-local). For callers whose
/// lower bound must be the pairs' max σ_ij rather than σ (generalized depth: rotations can beat
/// σ), and for tests and the bench (the path before the exact σ).
struct SigmaBoundsOnly {
  static inline thread_local int depth = 0;
  SigmaBoundsOnly() { ++depth; }
  ~SigmaBoundsOnly() { --depth; }
  SigmaBoundsOnly(const SigmaBoundsOnly&) = delete;
  SigmaBoundsOnly& operator=(const SigmaBoundsOnly&) = delete;
};

/// While alive on this thread, minimum() also keeps in `bounds` its answer on the certified bounds
/// alone (what it returns under SigmaBoundsOnly, before any exact σ), scaled back to input units by
/// Pair3 as the answer is. For generalized depth, which needs σ and the pairs' max σ_ij from one
/// query instead of two. Only the mesh engine fills it (a mixed pair's σ is its bounds' answer);
/// the innermost guard on the thread receives it.
struct SigmaKeepBounds {
  static inline thread_local SigmaKeepBounds* active = nullptr;
  std::optional<Depth3> bounds;
  SigmaKeepBounds() : outer_(active) { active = this; }
  ~SigmaKeepBounds() { active = outer_; }
  SigmaKeepBounds(const SigmaKeepBounds&) = delete;
  SigmaKeepBounds& operator=(const SigmaKeepBounds&) = delete;

 private:
  SigmaKeepBounds* outer_;
};

/// σ's upper bound by directions (meshes and mixed pairs, mesh_mixed.hpp): the least σ_d
/// (along_d) over `normals` (the deepest pairs' first) and the six axes, stopping once it meets
/// `lower` within 16 ulps, then up to three times along the facet normal where the best move
/// ends while that improves. Returns that σ_d's answer as kind Minimum, overlapping,
/// upper_bound = depth (or the answer's own upper bound), lower_bound = depth when the bounds
/// meet, else min(lower, depth); candidates = work + the σ_d's.
Depth3 least_directional(double lower, const std::vector<Vec3>& normals, std::size_t work,
                         const std::function<Depth3(const Vec3&)>& along_d);

/// The signed distance of an overlapping union from its σ answer s: distance = lower_bound =
/// −s.upper_bound, upper_bound = −s.lower_bound, and s's translation, normal, witnesses, features
/// and pieces.
Distance3 overlap_distance3(const Depth3& s);

/// One overlapping piece pair's σ (or its lower bound) and normal: the input of least_from_deep.
struct DeepPair {
  double s;
  Vec3 normal;
};

/// σ of a union from its overlapping piece pairs: none → not overlapping (candidates = work);
/// else least_directional with lower = the deepest s and the normals of the four deepest first.
Depth3 least_from_deep(std::vector<DeepPair> deep, std::size_t work,
                       const std::function<Depth3(const Vec3&)>& along_d);

/// Signed distance: apart / touching → min over piece pairs of the exact convex signed distance
/// (pruned by box distances; exact); overlapping → −σ from minimum()'s bounds (distance =
/// −upper, lower_bound = −upper, upper_bound = −lower).
Distance3 signed_distance(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q);

/// Shape cast along d (world frame, checked by the caller): the least exact convex cast over the
/// piece pairs whose box sum the ray meets (mesh_cast.cpp); 0 and overlapping when the interiors
/// overlap (exact), +∞ and hit false when no pair is ever touched. Exact (bounds equal distance);
/// piece_p / piece_q name the pair of the contact.
Cast3 cast(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d);

// ---- shared by mesh_pair.cpp, mesh_line.cpp and mesh_cast.cpp ----

/// The pose of Q in P's frame and the boxes of Q's pieces there (rounded, then widened so that
/// they hold the exact placed pieces).
struct Placed {
  Eigen::Matrix3d Rp;
  Vec3 tp_world;
  Eigen::Matrix3d R;  ///< R = Rpᵀ Rq
  Vec3 tq, tp;        ///< Rpᵀ translations (q' = R q + tq − tp, exact semantics for these doubles)
  std::vector<Box3> boxQ;
};
Placed place(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q);

/// Box of M_ij = box(P_i) ⊕ −box(Q'_j), widened by a relative margin.
Box3 sum_box(const MeshPair& m, const Placed& pl, std::size_t i, std::size_t j);

}  // namespace pendepth::mesh3
