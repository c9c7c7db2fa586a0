// Private: exact minimum depth σ by certified expansion on the implicit M = P ⊕ (−Q')
// (see minimum_expand.cpp).
#pragma once

#include <pendepth/depth3.hpp>

#include "convex3/minkowski_facets.hpp"

namespace pendepth::convex3 {

/// σ for Q placed by `rel` in P's frame. The result is expressed in the world frame given by
/// P's pose (x_world = Rp x + tp). Exact: lower_bound == upper_bound == depth on overlap.
Depth3 minimum_depth_expand(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel,
                            const Eigen::Matrix3d& Rp, const Vec3& tp);

}  // namespace pendepth::convex3
