// The exact mesh σ (src/mesh3/mesh_sigma_exact.cpp; issue 17 item 4).
//
// Oracles:
//  * polycubes (identity rotations): O = ∪ open boxes (p − q − 1, p − q + 1)³ over voxel pairs;
//    its complement is a union of closed cells of the grid of the boxes' bounds, so the nearest
//    point to t has every coordinate equal to t_k or to a bound: a brute force over that grid,
//    exact in GMP rationals, independent of the decomposition and the convex engines. Random
//    polycubes, translations on the half-integer grid half the time (seams: exact fits between
//    sums touching along coplanar facets, which are NOT in O) and a closed-form slot;
//  * a rotated comb and cup: properties — moving Q by the answer's
//    translation ×(1 + 1e-9) leaves the interiors disjoint and ×(1 − 1e-9) does not (exact
//    overlap test), σ <= σ_d in 64 random directions, the bracket is 1 ulp at most, and the old
//    certified bounds (minimum() under a SigmaBoundsOnly guard) contain the new value;
//  * the planted bug (exact_minimum's skip_cover: no removal of covered points) must disagree
//    with the voxel oracle — it does, so the oracle test can fail.
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh3/mesh_pair.hpp"
#include "mesh3/mesh_sigma_exact.hpp"
#include "mesh_direct.hpp"
#include "mesh_gen.hpp"

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cmath>
#include <cstdint>
#include <random>

namespace {

using namespace pendepth;
using namespace mesh3_test;

// The algorithm is tested beyond the front door's work limit (kExactSigmaMaxWork).
constexpr std::size_t kTestMaxWork = SIZE_MAX;

// The old certified bounds (minimum() without the exact path).
Depth3 old_bounds(const mesh3::MeshPair& m, const Pose3& pp, const Pose3& pq) {
  mesh3::SigmaBoundsOnly bounds_only;
  return mesh3::minimum(m, pp, pq);
}

// σ² of a polycube pair translated by t (file comment); -1 when not overlapping.
mpq_class voxel_sigma2(const std::set<Voxel>& P, const std::set<Voxel>& Q, const Vec3& t) {
  std::vector<std::array<int, 3>> c;  // box centres p − q; the box is c ± 1
  for (const Voxel& p : P)
    for (const Voxel& q : Q) c.push_back({p[0] - q[0], p[1] - q[1], p[2] - q[2]});
  auto covered = [&](const Vec3& x) {
    for (const auto& b : c) {
      bool in = true;
      for (int k = 0; k < 3 && in; ++k) in = b[k] - 1 < x[k] && x[k] < b[k] + 1;
      if (in) return true;
    }
    return false;
  };
  if (!covered(t)) return -1;
  std::vector<double> V[3];
  for (int k = 0; k < 3; ++k) {
    V[k].push_back(t[k]);
    for (const auto& b : c) V[k].push_back(b[k] - 1), V[k].push_back(b[k] + 1);
    std::sort(V[k].begin(), V[k].end());
    V[k].erase(std::unique(V[k].begin(), V[k].end()), V[k].end());
  }
  mpq_class best = -1;
  for (double x : V[0])
    for (double y : V[1])
      for (double z : V[2]) {
        const Vec3 p(x, y, z);
        if (covered(p)) continue;
        mpq_class d2 = 0;
        for (int k = 0; k < 3; ++k) {
          const mpq_class e = mpq_class(p[k]) - mpq_class(t[k]);
          d2 += e * e;
        }
        if (best < 0 || d2 < best) best = d2;
      }
  return best;
}

// lower <= √q <= upper, exactly.
bool brackets(const Depth3& s, const mpq_class& q) {
  return mpq_class(s.lower_bound) * mpq_class(s.lower_bound) <= q && q <= mpq_class(s.upper_bound) * mpq_class(s.upper_bound);
}

bool one_ulp(const Depth3& s) {
  return s.lower_bound <= s.depth && s.depth <= s.upper_bound &&
         (s.lower_bound == s.upper_bound || std::nextafter(s.lower_bound, INFINITY) == s.upper_bound);
}

std::string show(const Vec3& v) {
  std::ostringstream s;
  s.precision(17);
  s << v.x() << "," << v.y() << "," << v.z();
  return s.str();
}

// Random polycubes against the voxel oracle: the exact path called directly (whether or not the
// old bounds met) and through Pair3.
struct PolycubeCase {
  std::set<Voxel> P, Q;
  Shape3 sp, sq;
};
std::vector<PolycubeCase> polycube_cases(std::mt19937_64& rng, int want) {
  std::vector<PolycubeCase> out;
  for (int attempt = 0; static_cast<int>(out.size()) < want && attempt < 60; ++attempt) {
    const auto P = random_polycube(rng, 7), Q = random_polycube(rng, 4);
    try {
      out.push_back({P, Q, mesh_shape(polycube(P), "P"), mesh_shape(polycube(Q), "Q")});
    } catch (const InvalidInput&) {
      // a non-manifold union: not a valid mesh
    }
  }
  return out;
}

TEST(MeshSigmaExact, PolycubesAgainstVoxelOracle) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> U(-1, 1);
  const auto cases = polycube_cases(rng, 2);
  ASSERT_EQ(cases.size(), 2u);
  int checked = 0, seams = 0, unmet = 0;
  for (std::size_t n = 0; n < cases.size(); ++n) {
    const auto& c = cases[n];
    const mesh3::MeshPair m = direct(c.sp, c.sq);
    const Pair3 pair(c.sp, c.sq);
    for (int k = 0; k < 16; ++k) {
      Vec3 t(2.5 * U(rng), 2.5 * U(rng), 2.5 * U(rng));
      if (k % 2) t = (2 * t).array().round() / 2;
      const mpq_class q = voxel_sigma2(c.P, c.Q, t);
      if (q < 0) continue;
      const std::string what = "case " + std::to_string(n) + " t " + show(t);
      ++checked;
      seams += k % 2;
      const Depth3 old = old_bounds(m, Pose3(), Pose3(t));
      ASSERT_TRUE(old.overlapping) << what;
      unmet += old.lower_bound < old.upper_bound;
      const auto x = mesh3::exact_minimum(m, Pose3(), Pose3(t), old.upper_bound, kTestMaxWork);
      ASSERT_TRUE(x.has_value()) << what;
      EXPECT_TRUE(brackets(*x, q)) << what << " got " << x->depth << " want " << std::sqrt(q.get_d());
      EXPECT_TRUE(one_ulp(*x)) << what;
      EXPECT_TRUE(brackets(old, q)) << what;  // the old bounds hold the exact value
      if (k % 4) continue;
      const Depth3 s = pair.minimum(Pose3(), Pose3(t));
      // Pair3: the exact path's bracket, or (beyond the work limit) the old bounds unchanged.
      if (s.lower_bound == old.lower_bound && s.upper_bound == old.upper_bound) continue;
      EXPECT_TRUE(one_ulp(s)) << what;
      EXPECT_TRUE(brackets(s, q)) << what;
    }
  }
  EXPECT_GE(checked, 8);
  EXPECT_GE(seams, 3);
  EXPECT_GE(unmet, 1);  // cases where the old bounds did not meet: the exact path decided them
}

// A slot: a comb's gap holds a unit cube half-way (t = (1, 0.5, 0): over the base by 0.5, in the
// gap between two teeth). The old bounds: lower = the deepest single pair's σ; the nearest exit
// is up into the gap (0.5) — the exact σ is 0.5 and its seam-touching position is not in O.
TEST(MeshSigmaExact, SlotClosedForm) {
  const auto P = comb(3), Q = std::set<Voxel>{{0, 0, 0}};
  const Shape3 sp = mesh_shape(polycube(P), "comb"), sq = mesh_shape(polycube(Q), "cube");
  const mesh3::MeshPair m = direct(sp, sq);
  struct Case {
    Vec3 t;
    double sigma;
  } cases[] = {{{1, 0.5, 0}, 0.5}, {{0.25, 1.5, 0}, 0.75}, {{2, 2.75, 0.5}, 0.25}, {{1, 0.25, 0.5}, 0.5}};
  for (const Case& c : cases) {
    EXPECT_EQ(voxel_sigma2(P, Q, c.t), mpq_class(c.sigma) * mpq_class(c.sigma)) << show(c.t);
    const auto x = mesh3::exact_minimum(m, Pose3(), Pose3(c.t), old_bounds(m, Pose3(), Pose3(c.t)).upper_bound, kTestMaxWork);
    ASSERT_TRUE(x.has_value());
    EXPECT_EQ(x->depth, c.sigma) << show(c.t);
    EXPECT_EQ(x->lower_bound, c.sigma);
    EXPECT_EQ(x->upper_bound, c.sigma);
    EXPECT_FALSE(Pair3(sp, sq).overlapping(Pose3(), Pose3(c.t + x->translation))) << show(c.t);
  }
}

// The planted bug (no removal of covered points) must be caught by the voxel oracle.
TEST(MeshSigmaExact, PlantedBugIsCaught) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> U(-1, 1);
  const auto cases = polycube_cases(rng, 2);
  int wrong = 0;
  for (const auto& c : cases) {
    const mesh3::MeshPair m = direct(c.sp, c.sq);
    for (int k = 0; k < 15; ++k) {
      const Vec3 t(2.5 * U(rng), 2.5 * U(rng), 2.5 * U(rng));
      const mpq_class q = voxel_sigma2(c.P, c.Q, t);
      if (q < 0) continue;
      const auto x = mesh3::exact_minimum(m, Pose3(), Pose3(t), old_bounds(m, Pose3(), Pose3(t)).upper_bound,
                                          kTestMaxWork, true);
      wrong += !x || !brackets(*x, q);
    }
  }
  EXPECT_GT(wrong, 2);
}

// Properties on rotated non-convex meshes (file comment). Returns how many poses overlapped.
int check_properties(const Shape3& sp, const Shape3& sq, std::mt19937_64& rng, int poses, double spread,
                     const std::string& name, int& unmet) {
  std::uniform_real_distribution<double> U(-1, 1);
  const mesh3::MeshPair m = direct(sp, sq);
  const Pair3 pair(sp, sq);
  int overl = 0;
  for (int k = 0; k < poses; ++k) {
    const Eigen::Quaterniond rq(U(rng), U(rng), U(rng), U(rng)), rp(U(rng), U(rng), U(rng), U(rng));
    const Pose3 pp(rp, Vec3(0.1 * U(rng), 0.1 * U(rng), 0.1 * U(rng)));
    const Pose3 pq(rq, Vec3(spread * U(rng), spread * U(rng), spread * U(rng)));
    if (!pair.overlapping(pp, pq)) continue;
    ++overl;
    const std::string what = name + " pose " + std::to_string(k);
    const Depth3 old = old_bounds(m, pp, pq);
    unmet += old.lower_bound < old.upper_bound;
    const auto x = mesh3::exact_minimum(m, pp, pq, old.upper_bound, kTestMaxWork);
    EXPECT_TRUE(x.has_value()) << what;
    if (!x) continue;
    EXPECT_TRUE(one_ulp(*x)) << what;
    // The old bounds hold σ up to their own accuracy (bounds within 16 ulps are reported equal).
    const double tol = 16 * 0x1p-52 * old.upper_bound;
    EXPECT_LE(old.lower_bound, x->upper_bound + tol) << what;
    EXPECT_LE(x->lower_bound, old.upper_bound + tol) << what << " old " << old.lower_bound << " " << old.upper_bound << " new " << x->depth;
    EXPECT_FALSE(pair.overlapping(pp, Pose3(rq, pq.translation + x->translation * (1 + 1e-9)))) << what;
    EXPECT_TRUE(pair.overlapping(pp, Pose3(rq, pq.translation + x->translation * (1 - 1e-9)))) << what;
    for (int d = 0; d < 64; ++d) {
      const Vec3 dir(U(rng), U(rng), U(rng));
      if (dir == Vec3::Zero()) continue;
      EXPECT_LE(x->lower_bound, pair.along(pp, pq, dir).upper_bound) << what << " d " << show(dir);
    }
    // The front door: the exact path, or the old bounds when they met within 16 ulps or the pair
    // is beyond the work limit.
    const Depth3 s = pair.minimum(pp, pq);
    if (old.lower_bound == old.upper_bound) EXPECT_NEAR(s.depth, x->depth, 16 * 0x1p-52 * x->depth) << what;
    if (old.lower_bound < old.upper_bound && !(s.lower_bound == old.lower_bound && s.upper_bound == old.upper_bound))
      EXPECT_TRUE(one_ulp(s)) << what;  // else beyond the work limit: the old bounds unchanged
  }
  return overl;
}

TEST(MeshSigmaExact, RotatedCombAndCup) {
  std::mt19937_64 rng(37);
  const Shape3 a = mesh_shape(polycube(comb(3)), "comb"), b = mesh_shape(polycube(cup(2)), "cup");
  int unmet = 0;
  EXPECT_GE(check_properties(a, b, rng, 4, 1.5, "comb-cup", unmet), 2);
}

// The work limit (kExactSigmaMaxWork: a count, never a clock): under any limit the exact path
// either gives the unlimited answer, bit for bit, or gives up; it gives up below one threshold
// and answers from it on (the count is deterministic and only grows); limit 0 gives up (the setup
// spends); the threshold is the unlimited run's own count (mesh3::last_exact_work.units: the
// work is charged as done); the front door equals the exact path under the default limit.
TEST(MeshSigmaExact, WorkLimitAnswersOrGivesUp) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> U(-1, 1);
  const Shape3 sp = mesh_shape(polycube(comb(3)), "comb"), sq = mesh_shape(polycube(cup(2)), "cup");
  const mesh3::MeshPair m = direct(sp, sq);
  const Pair3 pair(sp, sq);
  int answered = 0;
  for (int k = 0; k < 12 && answered < 4; ++k) {
    const Pose3 pq(Eigen::Quaterniond(U(rng), U(rng), U(rng), U(rng)), Vec3(1.5 * U(rng), 1.5 * U(rng), 1.5 * U(rng)));
    if (!pair.overlapping(Pose3(), pq)) continue;
    const Depth3 old = old_bounds(m, Pose3(), pq);
    if (!(old.lower_bound < old.upper_bound)) continue;
    const auto full = mesh3::exact_minimum(m, Pose3(), pq, old.upper_bound, SIZE_MAX);
    ASSERT_TRUE(full.has_value()) << k;
    ++answered;
    // The count is the work done, deterministic: the run answers from exactly its own count on.
    const std::size_t units = mesh3::last_exact_work.units;
    ASSERT_GT(units, 0u) << k;
    EXPECT_TRUE(mesh3::exact_minimum(m, Pose3(), pq, old.upper_bound, units).has_value()) << k;
    EXPECT_EQ(mesh3::last_exact_work.units, units) << k;
    EXPECT_FALSE(mesh3::exact_minimum(m, Pose3(), pq, old.upper_bound, units - 1).has_value()) << k;
    EXPECT_FALSE(mesh3::exact_minimum(m, Pose3(), pq, old.upper_bound, 0).has_value()) << k;
    bool gave_up = true;
    for (std::size_t w = 1; w < (std::size_t{1} << 40); w = w * 3 / 2 + 1) {
      const auto x = mesh3::exact_minimum(m, Pose3(), pq, old.upper_bound, w);
      if (!x) {
        EXPECT_TRUE(gave_up) << k << " gave up at " << w << " after answering below it";
        continue;
      }
      gave_up = false;
      EXPECT_EQ(x->depth, full->depth) << k << " w " << w;
      EXPECT_EQ(x->lower_bound, full->lower_bound) << k << " w " << w;
      EXPECT_EQ(x->upper_bound, full->upper_bound) << k << " w " << w;
      EXPECT_EQ(x->translation, full->translation) << k << " w " << w;
      EXPECT_EQ(x->piece_p, full->piece_p) << k << " w " << w;
      EXPECT_EQ(x->piece_q, full->piece_q) << k << " w " << w;
      if (w > mesh3::kExactSigmaMaxWork) break;
    }
    EXPECT_FALSE(gave_up) << k;
    const auto limited = mesh3::exact_minimum(m, Pose3(), pq, old.upper_bound);
    const Depth3 s = pair.minimum(Pose3(), pq);
    if (limited) {
      EXPECT_EQ(s.depth, limited->depth) << k;
      EXPECT_EQ(s.lower_bound, limited->lower_bound) << k;
      EXPECT_EQ(s.upper_bound, limited->upper_bound) << k;
    } else {
      EXPECT_EQ(s.lower_bound, old.lower_bound) << k;
      EXPECT_EQ(s.upper_bound, old.upper_bound) << k;
    }
  }
  EXPECT_GE(answered, 2);
}


}  // namespace
