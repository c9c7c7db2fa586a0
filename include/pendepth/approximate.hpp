// pendepth — certified (1+δ)-approximate minimum depth σ of two huge point sets' convex hulls
// (survey §3.4–§4: Agarwal et al.'s ε-kernels; DHS §5 for the exact σ it calls on small hulls).
//
// Definitions as in depth3.hpp: P fixed, Q moving, both posed; M = conv P ⊕ (−conv Q') in P's
// frame with q' = R q + t (R, t the doubles of RelativePose, exactly as minimum_depth uses them);
// σ = dist(0, ∂M) when 0 ∈ int M, else 0. No hull of the full point sets is ever built.
//
// The two certificates (proof in docs/algorithms.md, "Approximate σ"):
//   lower: for subsets K_P ⊆ P, K_Q ⊆ Q (the kernels), conv K_P ⊕ −conv K_Q' ⊆ M, so
//          σ(K_P, K_Q) ≤ σ(P, Q) (σ is monotone under inclusion of M, and is 0 when 0 ∉ int M).
//          σ(K_P, K_Q) is the exact minimum_depth of the kernels' hulls.
//   upper: for every direction u ≠ 0, σ ≤ h_M(u)/|u| = (max_p u·p − min_q u·q')/|u| (0 ∈ int M:
//          σ = min over unit u of h_M(u); otherwise σ = 0 ≤ max(0, ·)). h_M(u) is evaluated on
//          the FULL point sets: one O(n + m) scan each, exact argmax/argmin (exact predicates on the
//          few candidates a floating filter leaves), value accurate to an ulp, rounded upwards.
//          Moving Q by upper·û separates the shapes (it ends touching in direction û).
//   h_M(u) ≤ 0 exactly ⇒ σ = 0 (certified separated or touching: lower = upper = 0).
// The kernels are refined (extreme points of the full sets in the directions where the kernels'
// Minkowski sum is lowest are added) until upper ≤ (1+δ)·lower; so the answer is a (1+δ)
// approximation whatever the kernel: σ ≤ depth = upper ≤ (1+δ)·lower ≤ (1+δ)·σ.
//
// The refinement works on a working set W ⊆ X per shape, the ε-kernel of the column grid
// (Agarwal–Har-Peled–Varadarajan's simple kernel: for each coordinate axis a G×G grid of columns
// over the bounding box, the top and bottom point of each column; O(n), at most 6·G² points,
// additive directional error ≤ √2 · the column width), so its O(|W|) scans are cheap; the full
// sets are scanned only to certify the upper bound (and to repair W where it is too coarse).
//
// Cost: O(n + m) for W, then per refinement round O(|W|·B) scans plus the exact σ of the kernels'
// hulls (O(k log k)), and a few O(n + m) certification scans; kernel sizes grow like O(1/δ) for
// round shapes (the ε-kernel bound for d = 3), far less for polytopes with few faces.
// Limits: δ in [1e-9, 1) (the certificates carry a relative rounding of ~1e-15). Magnitudes: a
// pair whose largest coordinate or translation lies outside [2^-60, 2^60) is answered on copies
// scaled by a power of two (lengths scaled back exactly, as the front door does,
// docs/robustness.md); a coordinate with no exact value at that scale is InvalidInput. A touching pair is certified σ = 0 only when a floating
// direction separates exactly (a rounded facet normal of the kernels' Minkowski difference that is
// exact: contacts along axis-aligned planes, or planes like x + y + z = 1); otherwise the
// answer is lower = 0, upper = a few ulps of the shapes' size, converged = false.
#pragma once

#include <pendepth/depth3.hpp>
#include <pendepth/geometry.hpp>

#include <cstddef>
#include <span>

namespace pendepth {

/// Result of approximate_minimum_depth (world frame).
struct ApproxDepth3 {
  double depth = 0;        ///< == upper_bound: the length of `translation`, a certified separating move
  double lower_bound = 0;  ///< certified: lower_bound ≤ σ ≤ upper_bound
  double upper_bound = 0;
  Vec3 normal{0, 0, 0};       ///< unit direction of the move (for σ = 0: a separating direction, or 0)
  Vec3 translation{0, 0, 0};  ///< depth·normal: moving Q (after its pose) by it separates the shapes
  bool overlapping = false;   ///< certified when converged: σ > 0
  bool converged = false;     ///< upper ≤ (1+δ)·lower (σ > 0) or lower == upper == 0
  std::size_t kernel_p = 0, kernel_q = 0;    ///< kernel sizes (points whose hulls gave lower_bound)
  std::size_t working_p = 0, working_q = 0;  ///< sizes of the working sets W (column-grid kernels)
  std::size_t rounds = 0;       ///< refinement rounds (exact σ of the kernels' hulls)
  std::size_t full_scans = 0;   ///< O(n + m) scans of the full point sets after W was built
};

/// (1+δ)-approximate σ of conv P_points (posed pose_p) and conv Q_points (posed pose_q), see the
/// header comment: certified lower ≤ σ ≤ upper = depth with upper ≤ (1+δ)·lower when converged
/// (always, in every test and benchmark; the refinement is capped at 400 rounds and 64 full scans).
/// Throws InvalidInput for: empty or flat point sets (fewer than 4 affinely independent points),
/// non-finite coordinates, coordinates with no exact value at the pair's power-of-two scale, bad
/// poses, δ not in [1e-9, 1).
ApproxDepth3 approximate_minimum_depth(std::span<const Vec3> P_points, const Pose3& pose_p,
                                       std::span<const Vec3> Q_points, const Pose3& pose_q, double delta);

}  // namespace pendepth
