// Private: the closed-form pre-step of the curved engine (coaxial3.cpp; docs/algorithms.md §R4.8
// "Coaxial pairs"): when every component of P and Q (disk, axial segment, ball) is exactly
// parallel in the relative frame, M = P ⊕ (−Q') is ONE rounded cylinder, answered in closed form.
#pragma once

#include "primitives/support3.hpp"

#include <optional>

namespace pendepth::primitives {

/// K = {x : |x_xy| <= R, |x_z| <= H} ⊕ B(r), centred at the origin, axis z (P's frame); each size
/// as a certified interval (the sums of the two shapes' sizes, and Q's sizes stretched by the
/// singular values of the double relative rotation when it is not a signed permutation).
/// M = K − t, so sd_M(0) = sd_K(t).
/// Near-coaxial (`tilt` > 0): Q's axis is not exactly parallel; K is then the sum for R0 (R with
/// its axis row and column replaced by ±e_z) and `tilt` >= ‖R − R0‖_F·ρ_C (ρ_C the radius of Q's
/// disk ⊕ segment; its ball is R·B, stretched by R's own singular values) bounds the Hausdorff
/// distance between R·Q and R0·Q, hence between M and K − t: sd_M = sd_K(t) ± tilt.
struct CoaxialSum {
  double R_lo = 0, R_hi = 0, H_lo = 0, H_hi = 0, r_lo = 0, r_hi = 0;
  double tilt = 0;
};

/// The sum when both shapes are centred disk ⊕ axial segment ⊕ ball (cylinder, rounded cylinder,
/// sphere, capsule, ellipsoid with equal axes, the point 0, a segment symmetric about 0 along z)
/// and Q's disk and segment (if any) are exactly parallel to P's: the rotation R maps z to ±z
/// exactly in doubles (R02 = R12 = R20 = R21 = 0, |R22| = 1); else (tilted) with `tilt` set —
/// the caller keeps that bracket only when it is narrower than EPA's. Other shapes: nullopt.
std::optional<CoaxialSum> coaxial_sum(const Support3& P, const Support3& Q, const Eigen::Matrix3d& R);

/// Near-coaxial (K.tilt > 0): a certified lower bound of min over unit u of h_M(u), M = P ⊕ (−(R·Q + t))
/// (that minimum is σ when positive and −sd_M(0) in general), second order in the tilt where the
/// tilt bound of K is first order: exact (to a few ulps) for a centred pair whose σ lies on the
/// ring of almost-nearest side directions. −∞ when it does not apply (P or Q not decomposable, a
/// non-finite intermediate). Proof and cover of the sphere: coaxial3.cpp "The tilted ring".
double near_coaxial_lower(const Support3& P, const Support3& Q, const Eigen::Matrix3d& R, const Vec3& t, const CoaxialSum& K);

/// Private (tests): while false, coaxial_sum declines every pair, so EPA answers (the reference
/// the closed form is checked against). Set only while no query runs.
inline bool coaxial_enabled = true;

/// The signed distance of q from K, certified: lo <= sd_K(q) <= hi (directed roundings: lo = hi
/// when every operation is exact), widened by K.tilt on both sides, and the outward unit normal of K at a nearest boundary point
/// (not certified; for the reported move and witnesses).
struct CoaxialSd {
  double lo = 0, hi = 0;
  Vec3 normal = Vec3::UnitX();
};
CoaxialSd coaxial_signed_distance(const CoaxialSum& K, const Vec3& q);

}  // namespace pendepth::primitives
