// Pair3 on meshes (src/mesh3/mesh_pair.cpp, mesh_line.cpp; issue 17 items 3–5).
//
// Oracle: polycubes (unions of unit voxels, integer coordinates: their decompositions are exact).
// For Q translated by t, the overlap set is O = ∪ over voxel pairs (p, q) of the open box
// (p − q − 1, p − q + 1)³, so overlap, σ_d (the first s >= 0 of t + s·d̂ outside every open box,
// walked from interval to interval), complete separation (the last exit) and the distance when
// apart (the least distance from t to a closed box) are computed exactly in GMP rationals from the
// voxels alone — independent of the decomposition and of the convex engines. Closed-form cases
// (a comb, a slot with an exact fit, a peg in a hole) check the oracle itself; random polycubes,
// random translations (snapped to the half-integer grid half the time: exact fits, shared
// interval ends) and random directions check Pair3 against it. With rotations: properties (moving
// by σ_d separates, 1e-9 less does not; σ's lower ≤ upper, lower ≤ σ_d). Batches equal singles.
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh_gen.hpp"

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <random>
#include <tuple>

namespace {

using namespace pendepth;
using namespace mesh3_test;

Shape3 mesh_shape(const std::set<Voxel>& v, const std::string& name) {
  return Shape3::from_mesh(Mesh3::validate(to_file(polycube(v), name), name));
}

// The exact oracle on voxels (file comment).
struct VoxelOracle {
  std::vector<Voxel> P, Q;
  VoxelOracle(const std::set<Voxel>& p, const std::set<Voxel>& q) : P(p.begin(), p.end()), Q(q.begin(), q.end()) {}

  // The open interval of λ with t + λ·d in the open box of (p, q); false when empty.
  static bool interval(const Voxel& p, const Voxel& q, const Vec3& t, const Vec3& d, mpq_class& a, mpq_class& b) {
    bool first = true;
    for (int k = 0; k < 3; ++k) {
      const mpq_class lo(p[k] - q[k] - 1), hi(p[k] - q[k] + 1), tk(t[k]);
      if (d[k] == 0) {
        if (!(lo < tk && tk < hi)) return false;
        continue;
      }
      const mpq_class dk(d[k]);
      mpq_class x0 = (lo - tk) / dk, x1 = (hi - tk) / dk;
      if (d[k] < 0) std::swap(x0, x1);
      if (first || x0 > a) a = x0;
      if (first || x1 < b) b = x1;
      first = false;
    }
    return a < b;
  }
  bool overlapping(const Vec3& t) const {
    for (const Voxel& p : P)
      for (const Voxel& q : Q) {
        bool in = true;
        for (int k = 0; k < 3; ++k) in = in && mpq_class(p[k] - q[k] - 1) < t[k] && mpq_class(t[k]) < p[k] - q[k] + 1;
        if (in) return true;
      }
    return false;
  }
  // σ_d in units of d (λ), and complete separation.
  mpq_class along(const Vec3& t, const Vec3& d) const {
    std::vector<std::pair<mpq_class, mpq_class>> iv;
    for (const Voxel& p : P)
      for (const Voxel& q : Q) {
        mpq_class a, b;
        if (interval(p, q, t, d, a, b) && b > 0) iv.emplace_back(a, b);
      }
    mpq_class cur = 0;
    for (bool moved = true; moved;) {
      moved = false;
      for (const auto& [a, b] : iv)
        if (a < cur && cur < b) cur = b, moved = true;
    }
    return cur;
  }
  mpq_class separation(const Vec3& t, const Vec3& d) const {
    mpq_class best = 0;
    for (const Voxel& p : P)
      for (const Voxel& q : Q) {
        mpq_class a, b;
        if (interval(p, q, t, d, a, b) && b > best) best = b;
      }
    return best;
  }
  // Squared distance from t to the closed union of the boxes (the distance when apart).
  mpq_class distance2(const Vec3& t) const {
    mpq_class best = -1;
    for (const Voxel& p : P)
      for (const Voxel& q : Q) {
        mpq_class s = 0;
        for (int k = 0; k < 3; ++k) {
          const mpq_class lo(p[k] - q[k] - 1), hi(p[k] - q[k] + 1), tk(t[k]);
          const mpq_class g = tk < lo ? mpq_class(lo - tk) : tk > hi ? mpq_class(tk - hi) : mpq_class(0);
          s += g * g;
        }
        if (best < 0 || s < best) best = s;
      }
    return best;
  }
};

// λ·|d| as a double, for comparison with Pair3's lengths.
double length(const mpq_class& lambda, const Vec3& d) { return lambda.get_d() * d.norm(); }

void expect_close(double got, double want, const std::string& what) {
  if (want == 0) {
    EXPECT_EQ(got, 0) << what;
    return;
  }
  EXPECT_NEAR(got, want, 1e-14 * std::abs(want)) << what;
}

std::string show(const Vec3& v) {
  std::ostringstream s;
  s.precision(17);
  s << v.x() << "," << v.y() << "," << v.z();
  return s.str();
}

// Closed forms (they check the oracle and the pair together).
TEST(MeshPair, CombSlotsAndExactFits) {
  const auto P = comb(3);  // base y∈[0,1], x∈[0,5]; teeth x∈[0,1],[2,3],[4,5], y∈[1,3]
  const auto Q = std::set<Voxel>{{0, 0, 0}};
  const Pair3 pair(mesh_shape(P, "comb"), mesh_shape(Q, "cube"));
  const VoxelOracle o(P, Q);
  struct Case {
    Vec3 t, d;
    double along, separation;
  } cases[] = {
      {{0, 1.5, 0}, {1, 0, 0}, 1, 5},        // out of tooth 0 into the gap: an exact fit, stops
      {{1, 1.5, 0}, {1, 0, 0}, 0, 4},        // in the gap: touching both teeth, not overlapping
      {{1, 1, 0}, {0, -1, 0}, 0, 2},         // on the base in the gap: touching; through the base
      {{1, 0.5, 0}, {0, 1, 0}, 0.5, 0.5},    // into the gap (slides out between the teeth)
      {{1, 0.5, 0}, {0, -1, 0}, 1.5, 1.5},
      {{0.5, 1.5, 0}, {-1, 0, 0}, 1.5, 1.5},
      {{0.5, 1.5, 0}, {1, 0, 0}, 0.5, 4.5},
      {{2, 1.5, 0}, {0, 0, 2}, 1, 1},        // up out of the middle tooth
  };
  for (const Case& c : cases) {
    const std::string what = "t " + show(c.t) + " d " + show(c.d);
    EXPECT_EQ(length(o.along(c.t, c.d), c.d), c.along) << what;
    EXPECT_EQ(length(o.separation(c.t, c.d), c.d), c.separation) << what;
    const Depth3 a = pair.along(Pose3(), Pose3(c.t), c.d);
    EXPECT_EQ(a.depth, c.along) << what;
    EXPECT_EQ(a.kind, DepthKind::Directional);
    EXPECT_EQ(pair.separation(Pose3(), Pose3(c.t), c.d).depth, c.separation) << what;
    EXPECT_EQ(pair.overlapping(Pose3(), Pose3(c.t)), o.overlapping(c.t)) << what;
    if (a.depth > 0) {
      EXPECT_GE(a.piece_p, 0);
      EXPECT_EQ(a.piece_q, 0);
      EXPECT_TRUE(a.overlapping);
    }
  }
}

TEST(MeshPair, PegInHole) {
  // A 3×3×1 ring (hole x, y ∈ [1, 2]) and a unit peg: the hole fits it exactly.
  std::set<Voxel> ring;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      if (x != 1 || y != 1) ring.insert({x, y, 0});
  const auto peg = std::set<Voxel>{{0, 0, 0}, {0, 0, 1}};
  const Pair3 pair(mesh_shape(ring, "ring"), mesh_shape(peg, "peg"));
  EXPECT_FALSE(pair.overlapping(Pose3(), Pose3(Vec3(1, 1, -0.5))));  // through the hole: touching
  EXPECT_EQ(pair.along(Pose3(), Pose3(Vec3(1, 1, -3)), Vec3(0, 0, 1)).depth, 0);
  EXPECT_EQ(pair.separation(Pose3(), Pose3(Vec3(1, 1, -3)), Vec3(0, 0, 1)).depth, 0);  // slides through
  EXPECT_EQ(pair.separation(Pose3(), Pose3(Vec3(1, 1.25, -3)), Vec3(0, 0, 1)).depth, 4);
  const Depth3 s = pair.minimum(Pose3(), Pose3(Vec3(1, 1.5, -0.5)));  // half a cell off the hole
  EXPECT_TRUE(s.overlapping);
  EXPECT_EQ(s.lower_bound, 0.5);
  EXPECT_EQ(s.upper_bound, 0.5);
  EXPECT_EQ(s.depth, 0.5);
  EXPECT_EQ(s.translation, Vec3(0, -0.5, 0));
  const Distance3 sd = pair.signed_distance(Pose3(), Pose3(Vec3(1, 1.5, -0.5)));
  EXPECT_EQ(sd.distance, -0.5);
  EXPECT_TRUE(sd.overlapping);
  const Distance3 apart = pair.signed_distance(Pose3(), Pose3(Vec3(4, 1, 0)));
  EXPECT_EQ(apart.distance, 1);
  EXPECT_EQ(pair.signed_distance(Pose3(), Pose3(Vec3(1, 1, -0.5))).distance, 0);  // in the hole: touching
}

// Random polycube pairs against the voxel oracle (identity rotations).
TEST(MeshPair, RandomPolycubesAgainstVoxelOracle) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> U(-1, 1);
  int shapes = 0, nonzero = 0, fits = 0, apart = 0;
  for (int attempt = 0; shapes < 3 && attempt < 50; ++attempt) {
    const auto P = random_polycube(rng, 7), Q = random_polycube(rng, 4);
    Shape3 sp = Shape3::hull(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    Shape3 sq = sp;
    try {
      sp = mesh_shape(P, "P");
      sq = mesh_shape(Q, "Q");
    } catch (const InvalidInput&) {
      continue;  // a non-manifold union: not a valid mesh
    }
    ++shapes;
    const Pair3 pair(sp, sq);
    const VoxelOracle o(P, Q);
    for (int k = 0; k < 150; ++k) {
      Vec3 t(3 * U(rng), 3 * U(rng), 3 * U(rng));
      if (k % 2) t = (2 * t).array().round() / 2;  // the half-integer grid: fits, shared ends
      Vec3 d(U(rng), U(rng), U(rng));
      if (k % 3 == 0) d = Vec3::Unit(k % 9 / 3) * (k % 4 ? 1.0 : -2.0);
      if (k % 3 == 1) d = d.array().round();
      if (d == Vec3::Zero()) d = Vec3(0, 0, 1);
      const std::string what = "shape " + std::to_string(shapes) + " t " + show(t) + " d " + show(d);
      const bool over = o.overlapping(t);
      EXPECT_EQ(pair.overlapping(Pose3(), Pose3(t)), over) << what;
      const Depth3 a = pair.along(Pose3(), Pose3(t), d);
      expect_close(a.depth, length(o.along(t, d), d), "along " + what);
      EXPECT_EQ(a.overlapping, over) << what;
      expect_close(pair.separation(Pose3(), Pose3(t), d).depth, length(o.separation(t, d), d), "separation " + what);
      nonzero += a.depth > 0;
      fits += a.depth > 0 && t == (2 * t).array().round().matrix() / 2;
      const Distance3 sd = pair.signed_distance(Pose3(), Pose3(t));
      EXPECT_EQ(sd.overlapping, over) << what;
      if (!over) {
        ++apart;
        expect_close(sd.distance, std::sqrt(o.distance2(t).get_d()), "distance " + what);
      } else {
        const Depth3 s = pair.minimum(Pose3(), Pose3(t));
        EXPECT_LE(s.lower_bound, s.upper_bound) << what;
        EXPECT_LE(s.lower_bound, a.depth * (1 + 1e-15)) << what;  // σ <= σ_d
        EXPECT_EQ(sd.distance, -s.upper_bound) << what;
        EXPECT_EQ(sd.upper_bound, -s.lower_bound) << what;
      }
    }
  }
  EXPECT_EQ(shapes, 3);
  EXPECT_GT(nonzero, 60);
  EXPECT_GT(fits, 20);
  EXPECT_GT(apart, 50);
}

// Rotations: moving by σ_d's translation leaves the interiors disjoint, 1e-9 less does not.
TEST(MeshPair, RotatedMovesSeparate) {
  const Pair3 pair(mesh_shape(cup(2), "cup"), mesh_shape(l_block(), "L"));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  int checked = 0;
  for (int k = 0; k < 60; ++k) {
    const Eigen::Quaterniond rq(U(rng), U(rng), U(rng), U(rng)), rp(U(rng), U(rng), U(rng), U(rng));
    const Pose3 pp(rp, Vec3(U(rng), U(rng), U(rng))), pq(rq, Vec3(1.5 + U(rng), 1.5 + U(rng), 1 + U(rng)));
    const Vec3 d(U(rng), U(rng), U(rng));
    const Depth3 a = pair.along(pp, pq, d);
    EXPECT_EQ(a.overlapping, pair.overlapping(pp, pq));
    if (a.depth == 0) continue;
    ++checked;
    EXPECT_FALSE(pair.overlapping(pp, Pose3(rq, pq.translation + a.translation * (1 + 1e-9)))) << k;
    EXPECT_TRUE(pair.overlapping(pp, Pose3(rq, pq.translation + a.translation * (1 - 1e-9)))) << k;
    const Depth3 s = pair.minimum(pp, pq);
    EXPECT_LE(s.lower_bound, s.upper_bound);
    EXPECT_LE(s.lower_bound, a.depth * (1 + 1e-12));
    EXPECT_FALSE(pair.overlapping(pp, Pose3(rq, pq.translation + s.translation * (1 + 1e-9)))) << k;
  }
  EXPECT_GT(checked, 10);
}

TEST(MeshPair, BatchesEqualSingles) {
  const Pair3 pair(mesh_shape(comb(3), "comb"), mesh_shape(l_block(), "L"));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(-2, 4);
  std::vector<Pose3> poses;
  for (int k = 0; k < 12; ++k) poses.emplace_back(Vec3(U(rng), U(rng), U(rng) / 3));
  const Pose3 pp(Eigen::Quaterniond(1, 0.1, 0, 0), Vec3(0.1, 0, 0));
  std::vector<Vec3> ds{Vec3(1, 0.5, 0)};
  std::vector<Depth3> mins(poses.size()), alongs(poses.size());
  std::vector<Distance3> dists(poses.size());
  bool over_b[12];
  pair.minimum(pp, poses, mins, 2);
  pair.along(pp, poses, ds, alongs, 2);
  pair.signed_distance(pp, poses, dists, 2);
  pair.overlapping(poses, std::span<bool>(over_b, 12), 2);
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const Depth3 m = pair.minimum(pp, poses[k]), a = pair.along(pp, poses[k], ds[0]);
    EXPECT_EQ(mins[k].depth, m.depth);
    EXPECT_EQ(mins[k].lower_bound, m.lower_bound);
    EXPECT_EQ(mins[k].translation, m.translation);
    EXPECT_EQ(alongs[k].depth, a.depth);
    EXPECT_EQ(alongs[k].translation, a.translation);
    EXPECT_EQ(dists[k].distance, pair.signed_distance(pp, poses[k]).distance);
    EXPECT_EQ(over_b[k], pair.overlapping(Pose3(), poses[k]));
  }
}

TEST(MeshPair, ErrorsAndScale) {
  const Shape3 comb3 = mesh_shape(comb(3), "comb"), cube1 = mesh_shape({{0, 0, 0}}, "cube");
  const Pair3 pair(comb3, cube1);
  EXPECT_THROW(pair.along(Pose3(), Pose3(), Vec3::Zero()), InvalidInput);
  EXPECT_THROW(pair.separation(Pose3(), Pose3(), Vec3(NAN, 0, 0)), InvalidInput);
  EXPECT_THROW(pair.minimum(Pose3(), Pose3(Vec3(INFINITY, 0, 0))), InvalidInput);
  // The numeric domain: the same pair scaled by 2^200 answers the same, scaled (front/scale.hpp).
  Gen big = polycube(comb(3)), bigq = polycube({{0, 0, 0}});
  for (auto* g : {&big, &bigq})
    for (Vec3& v : g->points) v *= 0x1p200;
  const Pair3 scaled(Shape3::from_mesh(Mesh3::validate(to_file(big, "big"), "big")),
                     Shape3::from_mesh(Mesh3::validate(to_file(bigq, "bigq"), "bigq")));
  for (const Vec3& t : {Vec3(0, 1.5, 0), Vec3(0.5, 1.25, 0.5), Vec3(1, 0.5, 0)}) {
    const Vec3 d(1, 0.25, 0);
    EXPECT_EQ(scaled.along(Pose3(), Pose3(t * 0x1p200), d).depth, pair.along(Pose3(), Pose3(t), d).depth * 0x1p200);
    EXPECT_EQ(scaled.minimum(Pose3(), Pose3(t * 0x1p200)).depth, pair.minimum(Pose3(), Pose3(t)).depth * 0x1p200);
  }
  // A translation with no exact value at the scale of the huge pair is refused.
  EXPECT_THROW(scaled.along(Pose3(), Pose3(Vec3(1e-300, 0, 0)), Vec3(1, 0, 0)), InvalidInput);
}

#ifdef PENDEPTH_CGAL_MESHES
// Real meshes nobody here drew (libcgal-demo): moving Q by σ_d's translation leaves the interiors
// disjoint (exact test), 1e-9 less does not; σ's lower <= upper <= σ_d; separation >= σ_d.
TEST(MeshPair, CgalSampleMeshProperties) {
  const std::string dir = PENDEPTH_CGAL_MESHES;
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(0, 1);
  // cross and star decompose exactly; tripod has rounded pieces (the answers are the pieces').
  for (const auto& [pname, qname, count] : {std::tuple{"cross", "star", 16}, std::tuple{"tripod", "star", 6}}) {
    SCOPED_TRACE(pname);
    const Shape3 P = Shape3::from_file(dir + "/" + pname + ".off", pname), Q = Shape3::from_file(dir + "/" + qname + ".off", qname);
    ASSERT_FALSE(P.is_convex());
    ASSERT_FALSE(Q.is_convex());
    const Pair3 pair(P, Q);
    Vec3 lo = P.polytope()[0], hi = lo;
    for (const Vec3& v : P.polytope().vertices()) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    int checked = 0;
    for (int k = 0; k < count; ++k) {
      const Pose3 pq(Eigen::Quaterniond(U(rng), U(rng), U(rng), U(rng)), lo + (hi - lo).cwiseProduct(Vec3(U(rng), U(rng), U(rng))));
      const Vec3 d(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
      const Depth3 a = pair.along(Pose3(), pq, d);
      ASSERT_EQ(a.overlapping, pair.overlapping(Pose3(), pq));
      if (a.depth == 0) continue;
      ++checked;
      EXPECT_FALSE(pair.overlapping(Pose3(), Pose3(pq.rotation, pq.translation + a.translation * (1 + 1e-9)))) << k;
      EXPECT_TRUE(pair.overlapping(Pose3(), Pose3(pq.rotation, pq.translation + a.translation * (1 - 1e-9)))) << k;
      EXPECT_GE(pair.separation(Pose3(), pq, d).depth, a.depth);
      const Depth3 s = pair.minimum(Pose3(), pq);
      EXPECT_LE(s.lower_bound, s.upper_bound);
      EXPECT_LE(s.lower_bound, a.depth * (1 + 1e-12));
      EXPECT_FALSE(pair.overlapping(Pose3(), Pose3(pq.rotation, pq.translation + s.translation * (1 + 1e-9)))) << k;
    }
    EXPECT_GT(checked, count / 3);
  }
}
#endif

}  // namespace
