// Private: Pair3 on a non-convex mesh against a shape that is not a polytope — a point, segment
// or flat polygon, a rounded shape (sphere, capsule, hull ⊕ ball) or a curved primitive — in
// either role (issue 16 items 4–5 on the meshes of issue 17). Algorithms in mesh_mixed.cpp.
//
// The mesh's convex pieces K_i (Mesh3::decomposition()) cover it with disjoint interiors, so with
// S the other shape the overlap set is O = ∪ int M_i, M_i = the sum of piece pair i (K_i and S in
// their roles): the same union structure as mesh_pair.hpp with one shape a single piece. Each
// piece pair is a convex Pair3 (the pair engines of src/front/pair3.cpp: flat shapes exact,
// rounded shapes exact decisions with certified brackets for σ_d and casts, curved shapes
// certified brackets), in world coordinates; each does its own numeric-domain scaling.
#pragma once

#include <pendepth/pendepth.hpp>

#include "convex3/flat3.hpp"
#include "mesh3/lazy.hpp"
#include "mesh3/tri_tree.hpp"

#include <array>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace pendepth::mesh3 {

struct SegmentTriangles;  // mesh_segment.cpp: the triangles as CGAL exact points

struct MixedPair {
  /// The piece pairs, built on the first query that needs them (mesh3/lazy.hpp; shared by copies).
  struct Pieces {
    std::vector<Pair3> pieces;   ///< piece pair i: (K_i, S) when the mesh is P, (S, K_i) when it is Q
    std::vector<Vec3> center;    ///< a bounding ball of K_i in the mesh's frame: center, radius
    std::vector<double> radius;
  };
  std::shared_ptr<const Lazy<Pieces>> lazy;
  const Pieces& built() const { return lazy->get(); }
  bool mesh_is_p = true;
  double radius_other = 0;       ///< a bounding ball of S about its frame's origin
  /// S a point (mesh_point.cpp): the mesh's triangles (mesh frame), each also as a flat shape,
  /// with their boxes and the box tree over them; `pt` the point. No pieces: the point path
  /// decides everything on the triangles (never builds the pieces).
  bool point = false;
  convex3::FlatShape3 pt;
  std::vector<std::array<Vec3, 3>> tri;
  std::vector<convex3::FlatShape3> tri_flat;
  std::vector<std::array<Vec3, 2>> tri_box;
  std::vector<char> tri_zero;  ///< triangle of zero area (exactly): no plane, skipped by the parity
  TriTree tree;
  /// The reference path: every triangle scanned, no tree (tests compare the two bit for bit).
  bool linear = false;
  /// S a segment (mesh_segment.cpp): its end points `seg` (engine frame, scaled as the triangles
  /// above, which it also uses); the pieces too, for distance, cast and σ's lower bound (overlap
  /// and σ_d never build them).
  bool segment = false;
  std::array<Vec3, 2> seg{};
  std::shared_ptr<const SegmentTriangles> seg_tri;  ///< the triangles as exact points, built once
  /// S a flat convex polygon (mesh_flat.cpp): its vertices `flat_v` (engine frame, the triangles'
  /// scale; seg_tri as for the segment); the pieces too, for distance, cast and σ's lower bound.
  bool flat = false;
  std::vector<Vec3> flat_v;
  /// Tests only: σ_d's candidates of mesh_flat.cpp leave out family 1 (∂P − F's vertices), 2 (the
  /// edge–edge parallelograms) or 3 (mesh vertices − F), or 4: the overlap test's crossings.
  int flat_drop_family = 0;
  /// The point path's numeric domain (src/front/scale.hpp): its data above are the input × 2^-e,
  /// poses are converted in and answers scaled back (the piece pairs scale themselves).
  int scale_exp = 0;
  /// P or Q a non-convex mesh, the other a point, segment, flat polygon, rounded or curved shape.
  static MixedPair make(const Shape3& P, const Shape3& Q);
};

bool overlapping(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q);
/// σ_d (the first exit of the ray from O, a walk over exact overlap tests), or complete
/// separation (the last exit of the ray from O) when `separation`.
Depth3 along(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d, bool separation);
/// σ: lower = the deepest piece pair's σ, upper = the least σ_d over a few directions.
Depth3 minimum(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q);
Distance3 signed_distance(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q);
Cast3 cast(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d);

// S a point (mesh_point.cpp): O = int P − q for the mesh P (the piece union misses the faces
// shared by pieces, so these go through the mesh's triangles). Called by the functions above.
bool point_overlapping(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q);
Depth3 point_along(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d, bool separation);
Depth3 point_minimum(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q);
Distance3 point_distance(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q);
Cast3 point_cast(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d);
// S a segment (mesh_segment.cpp): O = {v : (S + v) ∩ int P ≠ ∅} decided on the mesh's
// triangles with exact rationals (the pieces' union misses S lying in a shared internal face).
std::shared_ptr<const SegmentTriangles> segment_triangles(const MixedPair& m);
bool segment_overlapping(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q);
Depth3 segment_along(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d, bool separation);

// S a flat convex polygon (mesh_flat.cpp): O = {v : (F + v) ∩ int P ≠ ∅} on the mesh's triangles,
// exact (the pieces' union misses F lying in an internal face).
bool flat_overlapping(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q);
Depth3 flat_along(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3& d, bool separation);

/// The other shape S in the mesh's frame, where the point, segment and flat polygon paths decide
/// on the mesh's own triangles: a point y of S's engine frame is placed at R y + tq − tp (the
/// relative pose in doubles; each path evaluates that sum exactly or in its own certified way), and
/// a ray along the world direction d moves S relatively along d' = Rmᵀ d, negated when the mesh is
/// the moving shape Q.
struct MeshFrame {
  Eigen::Matrix3d Rm;  ///< the mesh's rotation and translation (world)
  Vec3 tm;
  Eigen::Matrix3d R;   ///< Rmᵀ R_S
  Vec3 tq, tp;         ///< Rmᵀ t_S, Rmᵀ tm
  Vec3 d = Vec3::Zero();  ///< d' (zero when no direction is given)
};
/// The frame of the pair at these poses; d' too when `d` is given (InvalidInput when it
/// underflows to zero there). O(1).
MeshFrame mesh_frame(const MixedPair& m, const Pose3& pose_p, const Pose3& pose_q, const Vec3* d);

/// Ray parity for a point on no triangle (mesh_point.cpp's file comment; the segment and flat
/// paths too): over the moment-curve directions d = (q², pq, p²), the reduced fractions s = p/q with
/// 4096 ≤ q ≤ 8192 and p < 2^26 (exact doubles, distinct directions), the first answer of
/// `parity(d)` — the crossing parity along d, or nullopt when d is degenerate (through an edge or a
/// vertex, or in a triangle's plane). logic_error (naming `what`) when ~9·10⁷ directions are all
/// degenerate (more than 2·(E + T) + 1: never below ~1.8·10⁷ triangles).
template <class F>
bool moment_ray_parity(const char* what, F&& parity) {
  for (long qi = 8192; qi >= 4096; --qi)
    for (long k = 0; k < 23000; ++k) {
      const long pi = 5217 + 2897 * k;
      if (std::gcd(pi, qi) != 1) continue;
      const double p = static_cast<double>(pi), q = static_cast<double>(qi);
      if (const std::optional<bool> in = parity(Vec3(q * q, p * q, p * p))) return *in;
    }
  throw std::logic_error(std::string(what) + ": no non-degenerate parity ray among ~9e7 directions (more than 2(E+T)+1)");
}

/// Is the triangle of zero area (its three vertices collinear, exactly)?
bool point_zero_area(const std::array<Vec3, 3>& T);

}  // namespace pendepth::mesh3
