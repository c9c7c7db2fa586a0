// pendepth — 3D intersection depth of convex polytopes (DHS §5-§6; survey §3).
//
// Notation: P fixed, Q moving; both carry a pose (only the relative pose matters). All work is
// done in P's frame, where Q's vertices are q' = R q + t_Q − t_P with R = R_Pᵀ R_Q and
// t_X = R_Pᵀ (translation of X), R the double matrix of the quaternion's rotation. Exactness is
// with respect to these double R and t (a linear map with det > 0 keeps Q convex exactly);
// with identity rotations it is exact in the input coordinates and translations.
// M = P ⊕ (−Q'); interiors overlap ⇔ 0 ∈ int M. n = |P|, m = |Q|.
//   σ_d : exit parameter of the ray s·d̂ from int M (0 when not overlapping);
//   σ   : dist(0, ∂M) (0 when not overlapping). Touching is not overlapping: depth 0.
#pragma once

#include <pendepth/depth2.hpp>
#include <pendepth/polytope.hpp>

#include <Eigen/Geometry>
#include <cstddef>

namespace pendepth {

/// Rigid placement x ↦ R x + translation, R from the (normalised) unit quaternion.
struct Pose3 {
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Vec3 translation = Vec3::Zero();

  Pose3() = default;
  explicit Pose3(const Vec3& t) : translation(t) {}
  Pose3(const Eigen::Quaterniond& q, const Vec3& t) : rotation(q), translation(t) {}
  /// Rotation matrix of the quaternion q, any magnitude (scaled by a power of two first,
  /// exactly): I + (2/|q|²)·[quadratic terms], one division; each entry within 4.4 ulps of 1 of
  /// the exact rotation (measured). Throws InvalidInput if q is zero or non-finite.
  Eigen::Matrix3d matrix() const;
  Vec3 apply(const Vec3& x) const { return matrix() * x + translation; }
};

enum class FeatureKind3 { None, Vertex, Edge, Face };

/// Vertex i, edge given by a level-0 half-edge id (3·triangle + k), or face = triangle id.
struct Feature3 {
  FeatureKind3 kind = FeatureKind3::None;
  int index = -1;
  friend bool operator==(const Feature3&, const Feature3&) = default;
};

/// Result of a 3D depth query (world frame). Not overlapping: depth 0, vectors 0, features None.
struct Depth3 {
  double depth = 0;          ///< length of the translation, input units, >= 0
  Vec3 translation{0, 0, 0}; ///< move to apply to Q (after its pose) to separate
  Vec3 normal{0, 0, 0};      ///< unit direction of `translation` (d̂ for σ_d); for σ the
                             ///< outward normal of M's nearest facet
  Vec3 facet_normal{0, 0, 0};///< outward unit normal of the facet of M where the move ends
  Vec3 witness_p{0, 0, 0};   ///< point of ∂P touching the moved Q
  Vec3 witness_q{0, 0, 0};   ///< point of the moved ∂Q touching P
  Feature3 feature_p, feature_q;  ///< features spanning M's facet (vertex/edge/face of each)
  double lower_bound = 0, upper_bound = 0;  ///< certified bounds; equal (exact method)
  std::size_t candidates = 0;  ///< candidate facet normals of M examined
  bool overlapping = false;
  /// Pair3 on meshes: the convex pieces (Mesh3::decomposition().pieces; a convex shape is piece
  /// 0) whose features feature_p / feature_q index; -1 for a pair of convex shapes.
  int piece_p = -1, piece_q = -1;
  DepthKind kind = DepthKind::Minimum;
};

/// Signed distance of two posed convex polytopes (conventions of Distance2, world frame):
/// > 0 apart (Euclidean distance), 0 touching, −σ overlapping; witness_q − witness_p =
/// distance·normal, translation = −distance·normal brings Q into touching contact.
/// lower_bound == upper_bound == distance (exact method: a few ulps from the exact value).
/// Apart: witness_p ∈ feature_p of P, witness_q ∈ feature_q of Q (up to rounding); when the
/// closest points are not unique (parallel faces or edges) any closest pair may be reported,
/// with the vertex / edge / face of each shape that contains it. Touching: normal 0, witnesses
/// a contact point. Overlapping: σ's answer (witness_q on the unmoved Q).
struct Distance3 {
  double distance = 0;
  Vec3 translation{0, 0, 0};
  Vec3 normal{0, 0, 0};
  Vec3 witness_p{0, 0, 0};
  Vec3 witness_q{0, 0, 0};
  Feature3 feature_p, feature_q;
  double lower_bound = 0, upper_bound = 0;
  bool overlapping = false;
  int piece_p = -1, piece_q = -1;  ///< Pair3 on meshes: the pieces the features index (as Depth3)
};

/// Shape cast of posed convex polytopes along d (conventions of Cast2, world frame): the
/// smallest s >= 0 with Q + s·d̂ touching P; +infinity (hit false) when never. When s = 0 and
/// the shapes overlap, the vectors are 0 and the features None; when s = 0 and they touch,
/// normal, witnesses and features are those of a facet of P ⊕ (−Q) through the contact (whose
/// normal faces along d when Q moves away at once). A ray that only grazes P ⊕ (−Q) is a hit;
/// its normal is an outward normal of P ⊕ (−Q) at the contact: a facet's facing the motion, or,
/// when the graze is decided by the exact graze routine, that of the supporting plane containing
/// the ray (normal·d = 0), with the support features of P and Q in that plane.
/// lower_bound <= the exact entry <= upper_bound: equal to `distance` for the exact engines
/// (convex and flat shapes: within a few ulps), a certified bracket for rounded shapes (spheres,
/// capsules, rounded hulls: `distance` is its upper end); +infinity both on a miss.
/// Pair3 on meshes: piece_p / piece_q name the convex pieces the features index (as Depth3).
struct Cast3 {
  double distance = 0;
  Vec3 translation{0, 0, 0};
  Vec3 normal{0, 0, 0};
  Vec3 witness_p{0, 0, 0};
  Vec3 witness_q{0, 0, 0};
  Feature3 feature_p, feature_q;
  double lower_bound = 0, upper_bound = 0;
  bool hit = false;
  bool overlapping = false;
  int piece_p = -1, piece_q = -1;
};

/// σ: exact minimum depth = distance from 0 to the nearest facet plane of M (0 when touching or
/// separated). Certified expansion of an inner polytope of the implicit M (exact EPA, see
/// src/convex3/minimum_expand.cpp): vertices are pairs (P vertex, Q vertex), every decision an
/// exact predicate, supports by exact warm-started hill climbing. On overlap lower_bound ==
/// upper_bound == depth (a few ulps from the exact value); `candidates` counts support queries;
/// features are the defining ones of M's facet (P face + Q vertex, P vertex + Q face, or two
/// edges); the witnesses coincide on the contact after the move. Cost O(k log k + climbs) for
/// k support queries (k grows slowly with the size of round hulls, docs/benchmarks.md); the
/// shapes' CSR adjacency is built once on first use (O(n)). Thread-safe.
/// Throws InvalidInput for non-finite or zero quaternions / non-finite translations.
Depth3 minimum_depth(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                     const Pose3& pose_q);

/// σ_d for direction d (world frame): the exit facet u of the ray (u·d > 0), σ_d =
/// h_M(u)/(u·d̂), exact (lower_bound == upper_bound == depth, within an ulp or so). Method: the
/// certified expansion of minimum_depth cast along the ray (src/convex3/minimum_expand.cpp,
/// Phase D: ~10–20 support queries, a few µs, typically no slower than σ), stopped when its work
/// (climb steps, facets) exceeds 4096 + 256·⌈log₂(n+1)⌉·⌈log₂(m+1)⌉ — it needs a small fraction
/// of that on every input measured (docs/benchmarks.md); then Compute-Depth-3D (DHS §5.2) on the
/// inner DK hierarchies (src/convex3/directional3.cpp), so a query costs O(log n · log m)
/// constant-size steps at worst (O(log³) when walk restarts meet vertices of degree > 48).
/// `candidates` counts support queries (expansion) or facet candidates (DK). Throws
/// InvalidInput if d is zero or non-finite (and for bad poses).
Depth3 directional_depth(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                         const Pose3& pose_q, const Vec3& d);

/// Signed distance (Distance3): apart → the exact Euclidean distance of P and Q (within ~2 ulps),
/// its witnesses and the features of each shape defining it (vertex / edge / face); touching →
/// 0 (normal 0); overlapping → −σ (minimum_depth's answer, witness_q on the unmoved Q). Method:
/// GJK on the implicit M with every decision an exact sign and an exact certificate of the
/// final support pair (src/convex3/signed_distance3.cpp); σ when 0 ∈ M. Output-sensitive:
/// O(k·c) for k GJK iterations and climbs of length c (a few µs on real hulls). Thread-safe.
/// Throws InvalidInput for bad poses.
Distance3 signed_distance(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                          const Pose3& pose_q);

/// Shape cast (Cast3) along d (world frame): the entry of the ray s·d̂ into the closed M,
/// exactly: a GJK ray cast with exact certificates, else two line descents of Compute-Depth-3D
/// (src/convex3/cast3.cpp), O(log n · log m). A ray that only grazes M (touches ∂M without
/// entering its interior: a face sliding in a face's plane, an edge grazing an edge) is a hit at
/// its first contact, decided exactly (cast_graze: exact GJK on the projection along d and the
/// support faces of the plane through the ray; then the normal is that plane's, ⊥ d).
/// Throws InvalidInput if d is zero or non-finite (and for bad poses).
Cast3 shape_cast(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q, const Pose3& pose_q,
                 const Vec3& d);

}  // namespace pendepth
