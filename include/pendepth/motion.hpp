// pendepth — depth under rigid motion: the generalized penetration depth PD_g (survey §4,
// Zhang, Kim, Varadhan, Manocha). Included at the end of pendepth.hpp.
//
// P is fixed; Q, placed at t (2D) or posed (3D), may rotate about its reference point (its own
// origin, placed at t) and translate. The cost of a rigid motion is DISP, the largest distance any
// point of Q travels between its start and its end:
//     DISP(θ, v) = max_{q ∈ Q} |R_θ q + v − q|          (q in Q's own frame),
// and PD_g = min { DISP(θ, v) : the interiors of P and Q moved by (θ, v) are disjoint }.
// DISP depends on the end placement only (not on the rotation centre used to describe it), a pure
// translation v costs |v| (so PD_g ≤ σ), and it is a lower bound of the survey's path metric D_g
// (an arc is at least its chord), so PD_g under DISP ≤ PD_g under D_g with equality for convex
// pairs. Theorem (docs/algorithms.md "Generalized depth"): when P and Q are both convex,
// PD_g = σ. Proof: a separating end placement M(Q) and P are split by a line with unit normal n,
// M(Q) on the side {x : n·x ≥ h_P(n)}; the point a ∈ Q deepest against n (n·a = −h_{−Q}(n))
// moves by at least n·(M(a) − a) ≥ h_P(n) + h_{−Q}(n) ≥ σ, since σ is the smallest support overlap
// of two convex sets. The same argument in 3D with a plane. It needs both shapes convex.
#pragma once

#include <pendepth/pendepth.hpp>

#include <cstddef>

namespace pendepth {

/// Options of generalized_depth (2D).
struct GeneralizedOptions2 {
  /// The rotations Q may take, in degrees, counter-clockwise about its reference point. The range
  /// must contain 0 (so that σ's motion is allowed and PD_g ≤ σ).
  double min_degrees = -180, max_degrees = 180;
  /// Angles probed at most (each probe: Q rotated once, a Pair2, a few σ and overlap queries).
  /// The search stops earlier when the gap closes.
  std::size_t max_probes = 512;
  /// Stop when upper_bound − lower_bound ≤ tolerance · upper_bound.
  double tolerance = 1e-6;
  /// Budget of the branch and bound over angle intervals: lower-bound evaluations at most (each: Q's
  /// convex parts rotated and eroded, their sums with P's parts, one free-space minimisation; and
  /// the exact best motion at the interval's middle angle). When it runs out the gap is reported
  /// (converged false).
  std::size_t max_intervals = 4000;
  /// How each probe's Pair2 prepares (Auto: the no-fit polygon for small non-convex pairs, whose
  /// build costs less than a few per-query σ answers; docs/benchmarks.md "Generalized depth").
  Prepare prepare = Prepare::Auto;
  /// Both shapes convex: answer σ by the theorem without probing (false: search anyway; tests).
  bool convex_theorem = true;
};

/// 2D generalized depth. `depth` = upper_bound, the DISP cost of the best motion found: rotate Q
/// by `angle` degrees about its reference point (coordinates as Shape2::rotated(angle), which
/// rounds them unless angle is a multiple of 90) and move its reference point by `translation`;
/// that motion separates P and the rotated Q, decided exactly. `lower_bound` ≤ PD_g ≤ upper_bound.
struct GeneralizedDepth2 {
  double depth = 0, lower_bound = 0, upper_bound = 0;
  double angle = 0;            ///< degrees
  Vec2 translation{0, 0};      ///< of Q's reference point, after the rotation
  double sigma = 0;            ///< translational σ at angle 0 (≥ depth)
  double sigma_at_angle = 0;   ///< σ of P and Q.rotated(angle) at the same t
  bool overlapping = false;
  bool rotation_exact = true;  ///< angle is a multiple of 90 (Shape2::rotation_is_exact)
  bool converged = true;       ///< upper − lower ≤ tolerance·upper (else the gap is reported as is)
  std::size_t probes = 0;      ///< angles probed by σ about three centres
  std::size_t intervals = 0;   ///< angle intervals bounded by the branch and bound
};

/// PD_g of P and Q + t (2D). Both convex: σ, lower = upper (the theorem). Otherwise a branch and
/// bound over angle intervals I = [m − h, m + h] (docs/algorithms.md "Generalized depth"):
///   lower bound per interval: Q's convex parts rotated by m about the centre ζ of Q's smallest
///     enclosing circle and eroded by a disk of radius ≥ 2 sin(h/2)·max|q − ζ| (rounded inwards and
///     certified) stay inside Q turned by any θ ∈ I, so a separating motion puts ζ outside the open
///     union of their sums with P's parts; its DISP is ≥ max_k |u − z_k| − 2 sin(h/2)|q_k − ζ|
///     (z_k: where ζ goes when q_k stays), minimised over that free set (its boundary's pieces,
///     exact signs, rounded down); also ≥ 2|sin(θ/2)|·(enclosing radius) and ≥ the largest
///     σ(P_i, Q_j) of overlapping convex parts;
///   upper bound: verified motions — σ of the rotated Q about three centres at angle 0, the quarter
///     turns and the edge-alignment angles, and the exact best motion at those angles and at the
///     middle of every interval left open (the same free-space minimum on Q.rotated's
///     coordinates, checked by the exact overlap test, nudged out by ulps if rounding put it in);
///   best-first on the intervals' lower bounds until upper − lower ≤ tolerance·upper (converged)
///     or max_intervals runs out (converged false, the gap reported as is).
/// Throws InvalidInput for a non-finite t, a non-finite angle range or one without 0, a negative
/// tolerance.
GeneralizedDepth2 generalized_depth(const Shape2& P, const Shape2& Q, const Vec2& t,
                                    const GeneralizedOptions2& options = {});

/// Options of generalized_depth (3D). Used only when either shape is non-convex (a mesh).
struct GeneralizedOptions3 {
  /// Rotations probed at most by the local search (each probe: one σ_d of the mesh pair at a
  /// rotated pose of Q and a few exact overlap tests). 0: the translational answer.
  std::size_t max_probes = 64;
  /// Stop when upper_bound − lower_bound ≤ tolerance · upper_bound (the bounds stay as found).
  double tolerance = 1e-9;
  /// Both shapes convex: answer σ by the theorem without probing (false: search anyway; tests).
  bool convex_theorem = true;
};

/// 3D generalized depth: Q, at pose_q, rotates by `rotation` (world frame, about its placed
/// reference point pose_q.translation) then moves by `translation`. `pose` is Q's pose after the
/// motion, the one verified not to overlap P (exact overlap test): its rotation is
/// rotation · pose_q.rotation (normalised; pose_q.rotation itself when `rotation` is the
/// identity) and its translation pose_q.translation + translation (these doubles: recomposing
/// gives the same bits). `depth` = upper_bound, a certified upper bound of that motion's DISP
/// (rounded up past every rounding of its evaluation, with the rotation matrices of the poses).
struct GeneralizedDepth3 {
  double depth = 0, lower_bound = 0, upper_bound = 0;
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Vec3 translation{0, 0, 0};
  Pose3 pose;                ///< Q's pose after the motion (verified separating)
  double sigma = 0;          ///< translational σ at pose_q (meshes: its upper bound, ≥ depth)
  bool overlapping = false;
  bool converged = true;     ///< upper − lower ≤ tolerance·upper (convex: lower == upper); meshes: often false, the gap is reported
  std::size_t probes = 0;    ///< rotations probed (0 for convex pairs)
};

/// PD_g of P at pose_p and Q at pose_q (3D).
///   Both convex: σ (the theorem): identity rotation, σ's translation, σ's certified bounds.
///   Either a mesh (non-convex; docs/algorithms.md "Depth under rigid motion"):
///     lower bound: the mesh σ lower bound, max σ(P_i, Q_j) over overlapping pairs of convex
///       pieces — a motion separating P and Q separates P_i from the moved Q_j, whose DISP is at
///       most Q's and at least σ(P_i, Q_j) by the theorem;
///     upper bound: local search over rotations from the translational answer (identity, the
///       mesh σ upper bound's translation): pattern search on the rotation vector (world axes,
///       steps halving); at each probed rotation (about the reference point and the hull box
///       centre) the turn alone, the turn plus the best translation so far, and the exact σ_d of
///       the turned pose along that translation's direction;
///       every accepted motion verified by the exact overlap test at `pose`. Rotation can only
///       help: depth ≤ σ's upper bound (up to the few ulps the certified cost is rounded up by).
///       The bounds generally do not meet (converged false).
/// Throws InvalidInput for a non-finite or zero pose (as Pair3), a negative or NaN tolerance.
GeneralizedDepth3 generalized_depth(const Shape3& P, const Pose3& pose_p, const Shape3& Q, const Pose3& pose_q,
                                    const GeneralizedOptions3& options = {});

/// DISP of a 2D motion for Q's vertices `q` (own frame) rotated to `rq` (same order) and
/// translated by v: max |rq − q + v|, rounded up past the evaluation's rounding (a certified
/// upper bound of the displacement of those coordinates). Used by the search and the tests.
double displacement_upper(const Vec2* q, const Vec2* rq, std::size_t n, const Vec2& v);

}  // namespace pendepth
