// The exact mesh σ's two tiers (src/mesh3/mesh_sigma_exact.cpp): the filtered tier (interval
// filters with proven enclosures, the interval prunes of lines and covering sums) must give the
// same bits as the pure exact path (every decision on the exact numbers: a
// mesh3::SigmaExactUnfiltered guard) — σ's rounding and its 1-ulp bracket — on random rotated and
// translated poses of combs and cups, whether or not the certified bounds met. (Small tori are not
// here: the exact path on them is still too slow for a test — docs/benchmarks.md.) The planted bug (SigmaExactUnfiltered::planted:
// the line prune's distance bound divided by 1e6, so lines nearer than the best are dropped)
// must make the comparison fail on the rotated comb–cup poses (there the nearest points lie on
// lines, not at feet of facet planes; on the axis-aligned poses they are all feet).
#include <pendepth/io.hpp>
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh3/mesh_pair.hpp"
#include "mesh3/mesh_sigma_exact.hpp"
#include "mesh_direct.hpp"
#include "mesh_gen.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <random>

namespace {

using namespace pendepth;
using namespace mesh3_test;

constexpr std::size_t kNoLimit = SIZE_MAX;  // no work limit

// Poses: Q's translation uniform in ±spread (half of them on the half-integer grid when `grid`),
// rotations random unless `axis_aligned`; `same_pose`: Q at P's pose (a mesh against itself: O
// is centrally symmetric, every plane has its mirror at the same distance from 0). Returns
// (compared, mismatched) over the overlapping poses.
std::pair<int, int> compare_tiers(const Shape3& sp, const Shape3& sq, std::mt19937_64& rng, int poses, double spread,
                                  bool axis_aligned, const std::string& name, bool expect_equal,
                                  bool same_pose = false) {
  std::uniform_real_distribution<double> U(-1, 1);
  const mesh3::MeshPair m = direct(sp, sq);
  const Pair3 pair(sp, sq);
  int compared = 0, mismatched = 0;
  for (int k = 0; k < poses; ++k) {
    Pose3 pp, pq;
    if (axis_aligned) {
      Vec3 t(spread * U(rng), spread * U(rng), spread * U(rng));
      if (k % 2) t = (2 * t).array().round() / 2;
      pq = Pose3(t);
    } else {
      const Eigen::Quaterniond rq(U(rng), U(rng), U(rng), U(rng)), rp(U(rng), U(rng), U(rng), U(rng));
      pp = Pose3(rp, Vec3(0.1 * U(rng), 0.1 * U(rng), 0.1 * U(rng)));
      pq = Pose3(rq, Vec3(spread * U(rng), spread * U(rng), spread * U(rng)));
    }
    if (same_pose) pq = pp;
    if (!pair.overlapping(pp, pq)) continue;
    Depth3 old;
    {
      mesh3::SigmaBoundsOnly bounds_only;
      old = mesh3::minimum(m, pp, pq);
    }
    const auto filtered = mesh3::exact_minimum(m, pp, pq, old.upper_bound, kNoLimit);
    std::optional<Depth3> exact;
    {
      mesh3::SigmaExactUnfiltered unfiltered;
      exact = mesh3::exact_minimum(m, pp, pq, old.upper_bound, kNoLimit);
    }
    ++compared;
    // The whole answer, not σ's bits only: the same nearest point (translation, normal) on the
    // same facet (features, pieces, witnesses) — the exact line stage's offer (offer_on_line
    // against offer_on_line_exact) picks one of the points at the least distance.
    const bool same = filtered.has_value() == exact.has_value() &&
                      (!exact || (filtered->depth == exact->depth && filtered->lower_bound == exact->lower_bound &&
                                  filtered->upper_bound == exact->upper_bound &&
                                  filtered->translation == exact->translation && filtered->normal == exact->normal &&
                                  filtered->facet_normal == exact->facet_normal &&
                                  filtered->witness_p == exact->witness_p && filtered->witness_q == exact->witness_q &&
                                  filtered->feature_p == exact->feature_p && filtered->feature_q == exact->feature_q &&
                                  filtered->piece_p == exact->piece_p && filtered->piece_q == exact->piece_q));
    mismatched += !same;
    if (expect_equal) {
      EXPECT_TRUE(exact.has_value()) << name << " pose " << k;
      EXPECT_TRUE(same) << name << " pose " << k << ": filtered " << (filtered ? filtered->depth : -1) << " exact "
                        << (exact ? exact->depth : -1);
    }
  }
  return {compared, mismatched};
}

TEST(MeshSigmaTiers, FilteredEqualsExactCombsAndCups) {
  std::mt19937_64 rng(101);
  const Shape3 comb3 = mesh_shape(polycube(comb(3)), "comb"), cup2 = mesh_shape(polycube(cup(2)), "cup");
  const Shape3 comb4 = mesh_shape(polycube(comb(4)), "comb4"), l = mesh_shape(polycube(l_block()), "L");
  int n = 0;
  n += compare_tiers(comb3, cup2, rng, 3, 1.5, false, "comb3-cup2 rotated", true).first;
  n += compare_tiers(comb4, l, rng, 16, 2.5, true, "comb4-L axis-aligned", true).first;  // seams, exact ties
  EXPECT_GE(n, 6);
}

// A mesh against itself at one rotated pose: each plane's mirror lies at the same distance, and
// the same planes recur across many sums — the classes of equal planes (plane_classes: a line
// run once per facet and class) must merge only planes that are exactly equal.
TEST(MeshSigmaTiers, FilteredEqualsExactSymmetricPoses) {
  std::mt19937_64 rng(5);
  const Shape3 l = mesh_shape(polycube(l_block()), "L");
  EXPECT_EQ(compare_tiers(l, l, rng, 2, 0, false, "L itself", true, true).first, 2);
}

#ifdef PENDEPTH_CGAL_MESHES
// CGAL's sample meshes (rotated poses: the nearest points on lines between many overlapping
// sums, where the interval line stage, the facet cover by unions and the exact-sign fallbacks of
// nearly parallel planes decide most of the work).
TEST(MeshSigmaTiers, FilteredEqualsExactCgalMeshes) {
  std::mt19937_64 rng(7);
  int n = 0;
  for (const char* name : {"cross.off", "star.off"}) {
    const std::string file = std::string(PENDEPTH_CGAL_MESHES) + "/" + name;
    const Shape3 s = Shape3::from_mesh(Mesh3::validate(io::read_mesh(file), name));
    n += compare_tiers(s, s, rng, 3, 0.3, false, name, true).first;
  }
  EXPECT_GE(n, 4);
}
#endif

// The union cover (face_covered: a facet whose face, within the best, lies in the union of the
// other open sums is skipped) against the exact path itself: under a SigmaCoverCheck the skipped
// facets are processed anyway, and none may offer a point (an offer is a point of R_f nearer
// than the best: the facet was not covered). Poses where the cover does work (`covered` > 0):
// rotated comb–cup, axis-aligned comb–L on the half-integer grid (seams: exact fits where two
// sums meet and no third covers), CGAL's cross and star. Returns (covered, violations).
std::pair<std::size_t, std::size_t> check_cover(const Shape3& sp, const Shape3& sq, std::mt19937_64& rng, int poses,
                                                double spread, bool axis_aligned) {
  std::uniform_real_distribution<double> U(-1, 1);
  const mesh3::MeshPair m = direct(sp, sq);
  const Pair3 pair(sp, sq);
  mesh3::SigmaCoverCheck check;
  mesh3::SigmaCoverCheck::covered = mesh3::SigmaCoverCheck::violations = 0;
  for (int k = 0; k < poses; ++k) {
    Pose3 pp, pq;
    if (axis_aligned) {
      pq = Pose3(Vec3((2 * Vec3(spread * U(rng), spread * U(rng), spread * U(rng))).array().round() / 2));
    } else {
      const Eigen::Quaterniond rq(U(rng), U(rng), U(rng), U(rng)), rp(U(rng), U(rng), U(rng), U(rng));
      pp = Pose3(rp, Vec3(0.1 * U(rng), 0.1 * U(rng), 0.1 * U(rng)));
      pq = Pose3(rq, Vec3(spread * U(rng), spread * U(rng), spread * U(rng)));
    }
    if (!pair.overlapping(pp, pq)) continue;
    Depth3 old;
    {
      mesh3::SigmaBoundsOnly bounds_only;
      old = mesh3::minimum(m, pp, pq);
    }
    EXPECT_TRUE(mesh3::exact_minimum(m, pp, pq, old.upper_bound, kNoLimit).has_value()) << k;
  }
  return {mesh3::SigmaCoverCheck::covered, mesh3::SigmaCoverCheck::violations};
}

TEST(MeshSigmaCover, CoveredFacetsOfferNothing) {
  std::mt19937_64 rng(202);
  const Shape3 comb3 = mesh_shape(polycube(comb(3)), "comb"), cup2 = mesh_shape(polycube(cup(2)), "cup");
  const Shape3 comb4 = mesh_shape(polycube(comb(4)), "comb4"), l = mesh_shape(polycube(l_block()), "L");
  for (const auto& [name, r] : {std::pair{"comb3-cup2 rotated", check_cover(comb3, cup2, rng, 16, 1.5, false)},
                                std::pair{"comb4-L seams", check_cover(comb4, l, rng, 64, 2.5, true)}}) {
    EXPECT_GE(r.first, 5u) << name;
    EXPECT_EQ(r.second, 0u) << name << ": " << r.first << " covered";
  }
#ifdef PENDEPTH_CGAL_MESHES
  for (const char* name : {"cross.off", "star.off"}) {
    const std::string file = std::string(PENDEPTH_CGAL_MESHES) + "/" + name;
    const Shape3 s = Shape3::from_mesh(Mesh3::validate(io::read_mesh(file), name));
    const auto [covered, violations] = check_cover(s, s, rng, 4, 0.3, false);
    EXPECT_GE(covered, 5u) << name;
    EXPECT_EQ(violations, 0u) << name << ": " << covered << " covered";
  }
#endif
}

// The planted bug in the filtered tier must make the comparison fail.
TEST(MeshSigmaTiers, PlantedFilterBugIsCaught) {
  std::mt19937_64 rng(101);  // the rotated comb–cup poses of FilteredEqualsExactCombsAndCups
  const Shape3 comb3 = mesh_shape(polycube(comb(3)), "comb"), cup2 = mesh_shape(polycube(cup(2)), "cup");
  mesh3::SigmaExactUnfiltered::planted = true;
  const auto [n, bad] = compare_tiers(comb3, cup2, rng, 3, 1.5, false, "planted", false);
  mesh3::SigmaExactUnfiltered::planted = false;
  EXPECT_GE(n, 2);
  EXPECT_GE(bad, 1) << n;
}

}  // namespace
