// Private: the exact σ of a mesh pair (issue 17 item 4), the refinement of minimum()'s bounds
// (mesh_pair.hpp) on pairs small enough; see mesh_sigma_exact.cpp.
#pragma once

#include "mesh3/mesh_pair.hpp"

#include <optional>
#include <utility>
#include <vector>

namespace pendepth::mesh3 {

/// Size limit of the exact path: the total number of candidate facet normals
/// (convex3::minkowski_facets) of the piece pairs whose sum box meets the ball B(0, upper).
/// Beyond it minimum() keeps the certified bounds. Measured (docs/benchmarks.md "Exact mesh σ"):
/// combs against an L block, CGAL's cross and star have 200–1 100 candidates in range (18–315
/// distinct planes) and take 3–10 ms per exact σ ("Exact mesh σ: plane classes, one rounding
/// guard"); a torus 8×4 pair has ~16 900 distinct planes over 437 sums and takes half a minute
/// even with the facet cover by unions (its ~190 facets that reach the lines are the cost), the
/// tripod pair (beyond 1 000) half a second ("… a facet cover by unions"). 600 lets every
/// overlapping bench pose of the combs, the cross and the star meet while keeping
/// tests/mesh3's CGAL sample-mesh properties at ~10 s.
inline constexpr std::size_t kExactSigmaMaxFacets = 600;

/// σ = dist(0, complement of O) exactly, given a certified upper bound `upper` >= σ (today's
/// least σ_d): depth = σ rounded to nearest, lower_bound <= σ <= upper_bound adjacent doubles
/// (equal when σ is a double), translation / normal / witnesses / features / pieces of the
/// nearest point's facet. nullopt when the pairs in range exceed `max_facets`, when 0 is not in
/// O, or when no point of the complement is found within `upper` (upper not an upper bound).
/// `skip_cover` (tests only: the planted bug) omits the removal of covered points.
/// The tiers (tests and the bench): while a SigmaExactUnfiltered is alive on this thread,
/// exact_minimum decides everything with the exact numbers (no interval filters, no filtered
/// prunes) — the reference the filtered tier must equal bit for bit. `planted` (tests only) plants
/// a bug in the filtered prunes (mesh_sigma_exact.cpp) so that the equality test can fail.
struct SigmaExactUnfiltered {
  static inline thread_local int depth = 0;
  static inline thread_local bool planted = false;
  SigmaExactUnfiltered() { ++depth; }
  ~SigmaExactUnfiltered() { --depth; }
  SigmaExactUnfiltered(const SigmaExactUnfiltered&) = delete;
  SigmaExactUnfiltered& operator=(const SigmaExactUnfiltered&) = delete;
};

/// Tests only: while a SigmaCoverCheck is alive on this thread, the filtered tier processes the
/// facets its union cover (mesh_sigma_exact.cpp, face_covered) would skip and counts in
/// `covered` those facets and in `violations` those that offered a point nonetheless (a cover
/// that is not one: must stay 0).
struct SigmaCoverCheck {
  static inline thread_local int depth = 0;
  static inline thread_local std::size_t covered = 0, violations = 0;
  SigmaCoverCheck() { ++depth; }
  ~SigmaCoverCheck() { --depth; }
  SigmaCoverCheck(const SigmaCoverCheck&) = delete;
  SigmaCoverCheck& operator=(const SigmaCoverCheck&) = delete;
};

namespace detail {

/// Tests only: the union cover of the filtered tier (mesh_sigma_exact.cpp: polygon_covered, the
/// fan and midpoint subdivision that face_covered runs on a facet's face) on given sets.
/// OpenConvex: the open set {x : n·x < c for every plane (n, c)}, inside `box`.
struct OpenConvex {
  std::vector<std::pair<Vec3, double>> planes;
  Box3 box;
};
/// `covered`: every point of hull(polygon) at squared distance <= reach2 from 0 is certainly in
/// some open set. `leaves` (kept when keep_leaves, up to the cover's limit; `complete` false
/// beyond it or when not kept): boxes of the unsettled triangles — with the settled ones they
/// cover the polygon.
struct CoverResult {
  bool covered = false, complete = true;
  std::vector<Box3> leaves;
};
CoverResult union_cover(const std::vector<OpenConvex>& sets, const std::vector<Vec3>& polygon, double reach2,
                        bool keep_leaves);

}  // namespace detail

std::optional<Depth3> exact_minimum(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q, double upper,
                                    std::size_t max_facets = kExactSigmaMaxFacets, bool skip_cover = false);

}  // namespace pendepth::mesh3
