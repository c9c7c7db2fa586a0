// Private: curved primitives and the certified support-function engine that answers every Pair3
// query involving one (support3.cpp; docs/algorithms.md "Certified support-function engine").
#pragma once

#include <pendepth/depth3.hpp>

#include <string>
#include <vector>

namespace pendepth {
class Shape3;
}

namespace pendepth::primitives {

/// A curved primitive's parameters (Shape3::cylinder / cone / ellipsoid), centred at the origin.
struct Curved3 {
  enum class Kind { Cylinder, Cone, Ellipsoid };
  Kind kind = Kind::Ellipsoid;
  double a = 0, b = 0, c = 0;  ///< cylinder, cone: R, H (c unused); ellipsoid: semi-axes
  std::string name;
};

/// Any convex shape Pair3 accepts (polytope, point, segment, flat polygon, curved primitive, each
/// optionally ⊕ a ball) as a support function in its own frame.
struct Support3 {
  enum class Kind { Points, Cylinder, Cone, Ellipsoid };
  Kind kind = Kind::Points;
  std::vector<Vec3> points;  ///< Points: the vertices (a polytope's, a lower-dimensional shape's)
  double a = 0, b = 0, c = 0;
  double radius = 0;  ///< the rounding ball
  double rho = 0;     ///< an upper bound of |x| over the shape (the error bounds' scale)
  /// A point of the shape (to within 10u·rho) whose value along v is h(v) to within 8u·rho·|v|.
  Vec3 support(const Vec3& v) const;
};
Support3 support_of(const Shape3& s);

/// The certified answers (world frame, as the exact engines' results). Every length is bracketed:
/// lower_bound <= true value <= upper_bound; decisions (overlap, hit) are certified when the
/// bracket of the signed distance excludes 0, else reported as touching (docs/robustness.md).
Depth3 curved_minimum(const Support3& P, const Pose3& pose_p, const Support3& Q, const Pose3& pose_q);
Depth3 curved_along(const Support3& P, const Pose3& pose_p, const Support3& Q, const Pose3& pose_q, const Vec3& d);
Distance3 curved_distance(const Support3& P, const Pose3& pose_p, const Support3& Q, const Pose3& pose_q);
Cast3 curved_cast(const Support3& P, const Pose3& pose_p, const Support3& Q, const Pose3& pose_q, const Vec3& d);

/// The relative gap the engine aims at (it stops earlier only at the rounding floor).
inline constexpr double kCurvedTargetGap = 0x1p-44;  // ≈ 5.7e-14

}  // namespace pendepth::primitives
