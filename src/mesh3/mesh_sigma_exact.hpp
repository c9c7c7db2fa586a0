// Private: the exact σ of a mesh pair (issue 17 item 4), the refinement of minimum()'s bounds
// (mesh_pair.hpp) where it ends within a work limit; see mesh_sigma_exact.cpp.
#pragma once

#include "mesh3/mesh_pair.hpp"

#include <optional>
#include <utility>
#include <vector>

namespace pendepth::mesh3 {

/// Work limit of the exact path at the front door (minimum()): a deterministic count, never a
/// clock, so that an answer does not depend on the machine or its load. Work, in units of one
/// line–sum interval test, charged as it is done (mesh_sigma_exact.cpp, exact_minimum): 15 per
/// candidate facet (convex3::minkowski_facets) of the piece pairs whose sum box meets B(0, upper)
/// — the setup; per line plane(f) ∩ plane(g) past the interval prunes (line_far), 1 + the covering
/// sums looked at before line_no_offer exits; per line of the exact stage 1 + the covering sums
/// looked at before offer_on_line exits (a covering interval holding the segment) + 20 per exact
/// covering interval computed; 1 per constraint whose λ enclosure was made exact or given its
/// head-and-tail enclosure (refine_ends, fine_lambda.hpp).
/// Measured (docs/benchmarks.md "Exact mesh σ: the work counted as done", "… tight λ
/// enclosures"): ~1.4 µs CPU per unit (±25 %), so the limit is ~1 s and giving up costs about
/// that. Combs against an L block, CGAL's cross and star spend 3 000–9 000 units (3–10 ms);
/// CGAL's tripod against itself 28 000–560 000 over 9 poses (0.02–0.72 s), all within the limit;
/// a torus 8×4 pair 0.51 to ~20 million over the 8 poses of the bench that reach it (0.6 s to
/// ~20 s), 3 within; a torus 16×8 × 8×4 pair 1.9 million on its first (2.7 s). Replaces a limit of 250 000
/// units that charged every covering sum of a line before the line's early exits (16 million on
/// the torus pair's pose 0, whose exact σ took 9 s) and let 5 tripod poses in.
inline constexpr std::size_t kExactSigmaMaxWork = 750000;

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
/// interval's exact end equals an end of the segment [a, b] or another covering interval's end;
/// `refined`: the constraints whose wide λ enclosure was replaced by the head-and-tail or the exact
/// λ's (the exact stage's close calls: mesh_sigma_exact.cpp, refine_ends), counted while a check
/// is alive.
struct SigmaLineCheck {
  static inline thread_local int depth = 0;
  static inline thread_local std::size_t lines = 0, ties = 0, mismatches = 0, no_offer = 0, no_offer_violations = 0,
                                         refined = 0;
  SigmaLineCheck() { ++depth; }
  ~SigmaLineCheck() { --depth; }
  SigmaLineCheck(const SigmaLineCheck&) = delete;
  SigmaLineCheck& operator=(const SigmaLineCheck&) = delete;
};

/// Tests and the bench (last_exact_work): the work count of the last exact_minimum on this thread (set when it
/// returns, also when it gives up): `units` the count compared with max_work; its parts in the
/// filtered tier — `setup` candidate facets, `lines` lines past the interval prunes and their
/// `tests` (covering sums looked at), `exact_lines` lines of the exact stage, their
/// `exact_tests` and `exact_intervals` (covering sums' exact intervals computed), and `refined`
/// (constraints whose wide λ enclosure got the exact λ's: mesh_sigma_exact.cpp, refine_ends), `fined`
/// (those that got the head-and-tail λ's instead: fine_lambda.hpp).
struct SigmaExactWork {
  std::size_t units = 0, setup = 0, lines = 0, tests = 0, exact_lines = 0, exact_tests = 0, exact_intervals = 0,
              refined = 0, fined = 0;
};
inline thread_local SigmaExactWork last_exact_work{};

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
