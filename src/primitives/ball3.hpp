// Private: ball pairs in closed form, the second pre-step of the curved engine (ball3.cpp;
// docs/algorithms.md §R4.8 "Ball pairs"): when one shape is a ball (a sphere, a point ⊕ ball, a
// point) and the other a solid of revolution (cone, cylinder, spheroid ellipsoid(A, A, C), each
// optionally ⊕ ball), σ and the signed distance reduce to the signed distance of the ball's
// centre from the other shape — a 2D problem in its meridian plane, answered with directed
// rounding (no support query).
#pragma once

#include "primitives/support3.hpp"

#include <optional>

namespace pendepth::primitives {

/// sd_M(0), M = P ⊕ (−(R·Q + t)) (P's frame; R, t the engines' double relative pose),
/// certified: lo <= sd_M(0) <= hi (lo = hi possible only when every operation is exact); the
/// outward unit normal of M at a nearest boundary point (not certified: moving Q by −sd·normal
/// brings it to touching), and the two shapes' points along it (P's frame, not certified): the
/// point of ∂P nearest Q and the point of ∂Q' nearest P (their difference is sd·normal).
struct BallSd {
  double lo = 0, hi = 0;
  Vec3 normal = Vec3::UnitX();
  Vec3 touch_p = Vec3::Zero(), touch_q = Vec3::Zero();
};

/// The closed form when P or Q is a ball (Support3 Points with one point ⊕ radius >= 0, or an
/// ellipsoid with equal axes ⊕ radius) and the other a cone, cylinder or spheroid (⊕ radius >= 0);
/// else nullopt (the caller goes on to EPA). Cost O(1); a spheroid: a branch and bound of
/// mean ~8 boxes (at most 2,000, then the bracket may miss the target: the caller checks).
std::optional<BallSd> ball_signed_distance(const Support3& P, const Support3& Q, const Eigen::Matrix3d& R, const Vec3& t);

/// Private (tests, benchmarks): while false, ball_signed_distance declines every pair, so EPA
/// answers (the reference the closed form is checked against). Set only while no query runs.
inline bool ball_enabled = true;

/// Private (tests): when in [0, 1], the spheroid's maximiser in doubles is not searched and this s
/// stands for it in both halves (ball3.cpp step (a)): a wrong maximiser costs boxes, never the
/// bracket's validity, and the tests check that. Set only while no query runs.
inline double ellipse_seed = -1;

}  // namespace pendepth::primitives
