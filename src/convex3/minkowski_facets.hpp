// Private: the facet normals of M = P ⊕ (−Q') enumerated implicitly, each with its exact
// support pair and accurately evaluated support value (see minkowski_facets.cpp).
#pragma once

#include <pendepth/depth3.hpp>

#include "convex3/polytope_data.hpp"

#include <optional>
#include <vector>

namespace pendepth::convex3 {

/// Q placed in P's frame: q' = R q + tq − tp (exact semantics for the double R, tq, tp).
struct RelativePose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Vec3 tq = Vec3::Zero(), tp = Vec3::Zero();
  Vec3 place(const Vec3& q) const { return R * q + (tq - tp); }
};

/// Q's pose relative to P's (R = Rpᵀ Rq, tq = Rpᵀ t_q, tp = Rpᵀ t_p); P's rotation matrix into
/// *Rp_out when given, so that a query computes each pose's matrix once. Throws InvalidInput on
/// a non-finite translation (and, from Pose3::matrix, on a zero or non-finite quaternion).
RelativePose relative_pose(const Pose3& pp, const Pose3& pq, Eigen::Matrix3d* Rp_out = nullptr);

enum class FacetSource { FaceP, FaceQ, EdgeEdge };

/// One candidate normal u of M (not normalised, known exactly as a polynomial in the inputs).
struct FacetCandidate {
  FacetSource source{};
  int p_feature = -1, q_feature = -1;  ///< P face / P vertex / P half-edge; same for Q
  int p_vertex = -1, q_vertex = -1;    ///< exact support vertices: P max of u·p, Q min of u·q'
  int sign = 0;             ///< exact sign of h_M(u) = u·(p − q')
  double distance = 0;      ///< h_M(u)/|u| accurate to a few ulps
  int dir_sign = 0;         ///< exact sign of u·d (directional queries only)
  double exit = 0;          ///< h_M(u)·|d|/(u·d) when dir_sign > 0
  Vec3 unit{0, 0, 0};       ///< u/|u| rounded
};

/// Every facet normal of M appears (a superset may appear; each value is a valid bound).
/// With `d`, also evaluates the ray-exit quantities along d.
std::vector<FacetCandidate> minkowski_facets(const ConvexPolytope& P, const ConvexPolytope& Q,
                                             const RelativePose& pose, const std::optional<Vec3>& d);

}  // namespace pendepth::convex3
