// Private: exact minimum depth σ and directional depth σ_d by certified expansion on the
// implicit M = P ⊕ (−Q') (see minimum_expand.cpp).
#pragma once

#include <pendepth/depth3.hpp>

#include "convex3/minkowski_facets.hpp"

namespace pendepth::convex3 {

/// σ for Q placed by `rel` in P's frame. The result is expressed in the world frame given by
/// P's pose (x_world = Rp x + tp). Exact: lower_bound == upper_bound == depth on overlap.
Depth3 minimum_depth_expand(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel,
                            const Eigen::Matrix3d& Rp, const Vec3& tp);

/// σ_d along d (P's frame; precondition: finite and nonzero) for Q placed by `rel`: the exit of
/// the ray s·d̂ from int M by the same expansion (Phase D), result in the world frame of P's pose.
/// Exact: lower_bound == upper_bound == depth on overlap; not overlapping (touching included):
/// depth 0, kind Directional.
Depth3 directional_depth_expand(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel,
                                const Vec3& d, const Eigen::Matrix3d& Rp, const Vec3& tp);

/// The same with validation (InvalidInput for a zero or non-finite d and bad poses), d in the
/// world frame: what pendepth::directional_depth runs when |P| + |Q| <= kDirectionalExpandMax.
Depth3 directional_depth_expand(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                                const Pose3& pose_q, const Vec3& d);

/// σ_d by Compute-Depth-3D on the DK hierarchies (directional3.cpp): O(log n · log m).
Depth3 directional_depth_dk(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                            const Pose3& pose_q, const Vec3& d);

/// Crossover of pendepth::directional_depth: the expansion up to this many vertices in total
/// (measured: docs/benchmarks.md), Compute-Depth-3D above (its O(log n · log m) bound).
inline constexpr std::size_t kDirectionalExpandMax = 256;

}  // namespace pendepth::convex3
