// Private: the exact σ of a mesh pair (issue 17 item 4), the refinement of minimum()'s bounds
// (mesh_pair.hpp) where it ends within a work limit; see mesh_sigma_exact.cpp.
#pragma once

#include "mesh3/mesh_pair.hpp"

#include <optional>
#include <utility>
#include <vector>

namespace pendepth::mesh3 {

/// Work limit of the exact path at the front door (minimum()): a deterministic count, never a
/// clock, so that an answer does not depend on the machine or its load. Work = 10 × the candidate
/// facets (convex3::minkowski_facets) of the piece pairs whose sum box meets B(0, upper) — the
/// setup, ~10× a line–sum test per facet — plus, for every line plane(f) ∩ plane(g) that passes
/// the interval prunes (line_far) and for every line of the exact stage, 1 + the number of
/// covering sums it is tested against — the line stage, the cost that grows
/// (mesh_sigma_exact.cpp). Beyond it exact_minimum gives up (nullopt) and minimum() keeps the
/// certified bounds; giving up costs ~0.45 s here (1.8 µs per unit). Measured (docs/benchmarks.md
/// "Exact mesh σ: a work limit"): combs against an L block, CGAL's cross and star spend 2 000–6 000
/// units (3–10 ms); CGAL's tripod against itself 19 000–650 000 over 9 poses (0.1–4 s), 5 of them
/// within the limit; a torus 8×4 pair 226 000 in its setup alone and ~16 million in all (half a
/// minute). Replaces a limit of 600 candidate facets, which kept the tripod out.
inline constexpr std::size_t kExactSigmaMaxWork = 250000;

/// σ = dist(0, complement of O) exactly, given a certified upper bound `upper` >= σ (today's
/// least σ_d): depth = σ rounded to nearest, lower_bound <= σ <= upper_bound adjacent doubles
/// (equal when σ is a double), translation / normal / witnesses / features / pieces of the
/// nearest point's facet. nullopt when the work exceeds `max_work`, when 0 is not in
/// O, or when no point of the complement is found within `upper` (upper not an upper bound).
/// `skip_cover` (tests only: the planted bug) omits the removal of covered points.
/// The tiers (tests and the bench): while a SigmaExactUnfiltered is alive on this thread,
/// exact_minimum decides everything with the exact numbers (no interval filters, no filtered
/// prunes) — the reference whose σ (depth, bounds) the filtered tier must equal bit for bit; the
/// nearest point and its facet are the reference's too when one point is nearest, and may be
/// another nearest point at the same σ when several are (the tiers prune different lines and
/// keep the first of equal distances: mesh_sigma_exact.cpp). `planted` (tests only) plants a bug
/// in the filtered prunes (mesh_sigma_exact.cpp) so that the equality test can fail.
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

/// Tests only: while a SigmaLineCheck is alive on this thread, the filtered tier runs the
/// reference offer_on_line_exact (mesh_sigma_exact.cpp) on a copy of the best beside every
/// offer_on_line and counts in `mismatches` the lines where the two do not leave the same best
/// (the same offer or none: squared distance, point and plane, exactly); the lines that
/// line_no_offer settles are run by the reference anyway and counted in `no_offer_violations`
/// when it offers a point. `lines`: lines compared; `ties`: those of them where a covering open
/// interval's exact end equals an end of the segment [a, b] or another covering interval's end.
struct SigmaLineCheck {
  static inline thread_local int depth = 0;
  static inline thread_local std::size_t lines = 0, ties = 0, mismatches = 0, no_offer = 0, no_offer_violations = 0;
  SigmaLineCheck() { ++depth; }
  ~SigmaLineCheck() { --depth; }
  SigmaLineCheck(const SigmaLineCheck&) = delete;
  SigmaLineCheck& operator=(const SigmaLineCheck&) = delete;
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
                                    std::size_t max_work = kExactSigmaMaxWork, bool skip_cover = false);

}  // namespace pendepth::mesh3
