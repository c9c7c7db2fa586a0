// Private: exact minimum depth σ and directional depth σ_d by certified expansion on the
// implicit M = P ⊕ (−Q') (see minimum_expand.cpp).
#pragma once

#include <pendepth/depth3.hpp>

#include "convex3/minkowski_facets.hpp"

#include <array>
#include <bit>
#include <cstddef>
#include <limits>
#include <optional>

namespace pendepth::convex3 {

/// Warm start of σ (coherent motion, survey §3.3): the pairs (i, j) spanning the previous
/// answer's facet of M and its neighbourhood in the previous K. Any seed gives the same answer bit for bit (only `candidates`, the work,
/// differs); a seed from the same pair of shapes at a nearby pose saves most support queries.
struct ExpandSeed {
  static constexpr int kMaxPairs = 16;
  /// (i, j) × count: the facet's three pairs, then pairs of K's nearby vertices (on the facets
  /// of K next to the answer's), which the warm start inserts first.
  std::array<int, 2 * kMaxPairs> pairs{};
  int count = 0;
  bool valid = false;
};

/// σ for Q placed by `rel` in P's frame. The result is expressed in the world frame given by
/// P's pose (x_world = Rp x + tp). Exact: lower_bound == upper_bound == depth on overlap. The
/// answer is a function of M's facet alone (canonical: the least features among the facets at
/// distance σ), so with a seed it is the same; the seed then receives this answer's facet
/// (invalid when the shapes do not overlap).
Depth3 minimum_depth_expand(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel,
                            const Eigen::Matrix3d& Rp, const Vec3& tp, ExpandSeed* seed = nullptr);

/// Tests: the same by the path before the lazy refinement of Phase B (each new best facet of K
/// refined at once, its accurate distance the cutoff): the same answer bit for bit.
Depth3 minimum_depth_expand_eager(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel,
                                  const Eigen::Matrix3d& Rp, const Vec3& tp, ExpandSeed* seed = nullptr);

/// Tests: runs σ's expansion, then counts K's live facets whose rounded Phase B keys fail to
/// bracket the exact squared plane distance (h/|n|)² (rationals); `checked` = facets compared.
int minimum_expand_key_violations(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel,
                                  int& checked);

/// The same from poses (validated as minimum_depth), with an optional seed (Pair3's warm start).
Depth3 minimum_depth_seeded(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                            const Pose3& pose_q, ExpandSeed* seed);

/// σ_d along d (P's frame; precondition: finite and nonzero) for Q placed by `rel`: the exit of
/// the ray s·d̂ from int M by the same expansion (Phase D), result in the world frame of P's pose.
/// Exact: lower_bound == upper_bound == depth on overlap; not overlapping (touching included):
/// depth 0, kind Directional. nullopt when the work (climb steps, facets scanned or built)
/// exceeds `budget`; `work` (if given) receives the work done.
std::optional<Depth3> directional_depth_expand(const ConvexPolytope& P, const ConvexPolytope& Q,
                                               const RelativePose& rel, const Vec3& d, const Eigen::Matrix3d& Rp,
                                               const Vec3& tp,
                                               std::size_t budget = std::numeric_limits<std::size_t>::max(),
                                               std::size_t* work = nullptr);

/// The same with validation (InvalidInput for a zero or non-finite d and bad poses), d in the
/// world frame, no budget (tests, benchmarks).
Depth3 directional_depth_expand(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                                const Pose3& pose_q, const Vec3& d);

/// σ_d by Compute-Depth-3D on the DK hierarchies (directional3.cpp): O(log n · log m).
Depth3 directional_depth_dk(const ConvexPolytope& P, const Pose3& pose_p, const ConvexPolytope& Q,
                            const Pose3& pose_q, const Vec3& d);

/// The exit of the line {s·d : s real} (P's frame, d finite and non-zero) from M, by the
/// descent of Compute-Depth-3D (directional3.cpp) on the line made generic by its Simulation of
/// Simplicity: hit = the perturbed line meets int M; then the exit facet u (u·d > 0, a
/// supporting plane of M), h_sign = exact sign of h_M(u) (the exit lies at s >= 0 iff h_sign
/// >= 0), exit = h_M(u)·|d|/(u·d) (few ulps; 0 when h_sign = 0), the features of M's facet and
/// a contact point of P and Q' + exit·d̂ (P's frame). O(log n · log m).
struct LineExit {
  bool hit = false;
  int h_sign = 0;
  double exit = 0;
  Vec3 unit{0, 0, 0};
  Feature3 feature_p, feature_q;
  Vec3 contact{0, 0, 0};
};
/// `orient` = ±1 multiplies the direction perturbation: line_exit_dk(d, −1) descends the same
/// perturbed line as line_exit_dk(−d, +1), reversed (as directional_depth_dk's two descents), so
/// that 0 ∈ int M iff both exits have h_sign > 0.
LineExit line_exit_dk(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel, const Vec3& d,
                      int orient = 1);

/// Whether the line {s·d : s real} (P's frame) meets the closed M, by the exact GJK of
/// signed_distance3.cpp on the projection along d (0 ∈ π(M)); if so, the 1–3 pairs (i, j) of
/// the final simplex, whose projections' hull holds 0 (size 1: m_ij lies on the line; size 2:
/// the segment of the two points of M crosses the line). O(k·c) as signed_distance.
struct LineTouch {
  bool touch = false;
  int size = 0;
  int i[4] = {-1, -1, -1, -1}, j[4] = {-1, -1, -1, -1};
};
LineTouch line_touch_gjk(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel, const Vec3& d);

/// The shape cast of a line that does not meet int M (directional3.cpp): hit iff the ray
/// {s·d : s >= 0} meets the closed M, then the first contact (exact decisions; see cast3.cpp).
/// d in P's frame; result in the world frame of (Rp, tp).
Cast3 cast_graze(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel, const Vec3& d,
                 const Eigen::Matrix3d& Rp, const Vec3& tp);

/// Shape cast fast path (signed_distance3.cpp): a GJK ray cast in doubles proposes the entry
/// triangle of pairs (or a separating plane), then exact certificates (the line crosses the
/// triangle, its plane supports M with n·d < 0 and the entry at s >= 0; or a plane v with
/// h_M(v) < 0 <= v·d; or the line misses M, by exact GJK on the projection along d). nullopt when a certificate fails or the entry is at an edge or vertex of
/// M: the caller then uses line_exit_dk. d in P's frame; result in the world frame.
std::optional<Cast3> shape_cast_certified(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel,
                                          const Vec3& d, const Eigen::Matrix3d& Rp, const Vec3& tp);

/// Signed distance (signed_distance3.cpp) for Q placed by `rel`, result in the world frame of
/// P's pose (Rp, tp).
Distance3 signed_distance_gjk(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel,
                              const Eigen::Matrix3d& Rp, const Vec3& tp);

/// The work budget of the expansion in pendepth::directional_depth, O(log n · log m): beyond it
/// the query is answered by Compute-Depth-3D (so the bound of DHS Theorem 5.6 holds). The
/// constants are set from the measured work (docs/benchmarks.md): typical queries use a small
/// fraction of it.
inline constexpr std::size_t kExpandWorkBase = 4096, kExpandWorkPerLog = 256;
inline std::size_t directional_work_budget(std::size_t n, std::size_t m) {
  auto lg = [](std::size_t x) { return static_cast<std::size_t>(std::bit_width(x)); };  // ⌈log2(x + 1)⌉
  return kExpandWorkBase + kExpandWorkPerLog * lg(n) * lg(m);
}

}  // namespace pendepth::convex3
