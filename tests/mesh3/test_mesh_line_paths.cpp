// Mesh σ_d's two interval paths (src/mesh3/mesh_line.cpp): the implicit facets of M_ij
// (convex3::minkowski_facets, small pieces) against the two DK descents. Every decision of the
// walk (which pairs hold the line, which exit wins, shared ends) is an exact comparison of the
// pairs' interval ends, so the answers must agree exactly: the same winning pair, features,
// normal, witness and examined count, and depths within a few ulps (two accurate evaluations of
// the same exact value). Inputs: random polycubes with translations on the half-integer grid and
// axis-parallel / integer directions (lines through vertices, in face planes, grazing, exact
// fits), diagonal lines through vertices, and rotated non-convex meshes (bumpy spheres, a cup and
// an L) with random directions; along (σ_d) and separation both.
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh3/mesh_pair.hpp"
#include "mesh_gen.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace pendepth;
using namespace mesh3_test;

struct PathGuard {
  ~PathGuard() { mesh3::line_path = mesh3::LinePath::Auto; }
};

bool ulps_close(double a, double b) {
  if (a == b) return true;
  return std::abs(a - b) <= 8 * 0x1p-53 * std::max(std::abs(a), std::abs(b));
}

// Runs one query on both paths and compares; returns whether the answer is non-zero.
bool same_on_both(const Pair3& pair, const Pose3& pp, const Pose3& pq, const Vec3& d, bool separation,
                  const std::string& what) {
  PathGuard g;
  mesh3::line_path = mesh3::LinePath::Descent;
  const Depth3 a = separation ? pair.separation(pp, pq, d) : pair.along(pp, pq, d);
  mesh3::line_path = mesh3::LinePath::Facets;
  const Depth3 b = separation ? pair.separation(pp, pq, d) : pair.along(pp, pq, d);
  EXPECT_TRUE(ulps_close(a.depth, b.depth)) << what << ": " << a.depth << " vs " << b.depth;
  EXPECT_EQ(a.overlapping, b.overlapping) << what;
  EXPECT_EQ(a.candidates, b.candidates) << what;
  EXPECT_EQ(a.piece_p, b.piece_p) << what;
  EXPECT_EQ(a.piece_q, b.piece_q) << what;
  EXPECT_EQ(a.feature_p.kind, b.feature_p.kind) << what;
  EXPECT_EQ(a.feature_p.index, b.feature_p.index) << what;
  EXPECT_EQ(a.feature_q.kind, b.feature_q.kind) << what;
  EXPECT_EQ(a.feature_q.index, b.feature_q.index) << what;
  EXPECT_EQ(a.facet_normal, b.facet_normal) << what;
  EXPECT_EQ(a.witness_p, b.witness_p) << what;
  return a.depth > 0;
}

Shape3 mesh_shape(const Gen& g, const std::string& name) { return Shape3::from_mesh(Mesh3::validate(to_file(g, name), name)); }

TEST(MeshLinePaths, PolycubesDegenerateLines) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> U(-1, 1);
  int shapes = 0, nonzero = 0;
  for (int attempt = 0; shapes < 3 && attempt < 50; ++attempt) {
    Shape3 sp = Shape3::hull(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), sq = sp;
    try {
      sp = mesh_shape(polycube(random_polycube(rng, 7)), "P");
      sq = mesh_shape(polycube(random_polycube(rng, 4)), "Q");
    } catch (const InvalidInput&) {
      continue;
    }
    ++shapes;
    const Pair3 pair(sp, sq);
    for (int k = 0; k < 120; ++k) {
      Vec3 t(3 * U(rng), 3 * U(rng), 3 * U(rng));
      if (k % 2) t = (2 * t).array().round() / 2;  // faces in planes, shared ends, exact fits
      if (k % 5 == 0) t = t.array().round();        // vertices on vertices
      Vec3 d(U(rng), U(rng), U(rng));
      if (k % 3 == 0) d = Vec3::Unit(k % 9 / 3) * (k % 4 ? 1.0 : -2.0);
      if (k % 3 == 1) d = d.array().round();  // (1, 0, −1), (1, 1, 1): lines through vertices, edges
      if (d == Vec3::Zero()) d = Vec3(1, 1, 1);
      const std::string what = "shape " + std::to_string(shapes) + " k " + std::to_string(k);
      nonzero += same_on_both(pair, Pose3(), Pose3(t), d, false, "along " + what);
      same_on_both(pair, Pose3(), Pose3(t), d, true, "separation " + what);
    }
  }
  EXPECT_EQ(shapes, 3);
  EXPECT_GT(nonzero, 60);
}

TEST(MeshLinePaths, RotatedCurvedMeshes) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> U(-1, 1);
  const Pair3 spheres(mesh_shape(bumpy_sphere(rng, 5, 6, 0.3), "P"), mesh_shape(bumpy_sphere(rng, 4, 5, 0.3), "Q"));
  const Pair3 cup_l(mesh_shape(polycube(cup(2)), "cup"), mesh_shape(polycube(l_block()), "L"));
  int nonzero = 0;
  for (int k = 0; k < 30; ++k) {
    const Eigen::Quaterniond rq(U(rng), U(rng), U(rng), U(rng)), rp(U(rng), U(rng), U(rng), U(rng));
    const Vec3 d(U(rng), U(rng), U(rng));
    const std::string what = "k " + std::to_string(k);
    const Pose3 pp(rp, Vec3(U(rng), U(rng), U(rng)));
    nonzero += same_on_both(spheres, pp, Pose3(rq, Vec3(U(rng), U(rng), U(rng))), d, false, "spheres " + what);
    same_on_both(spheres, pp, Pose3(rq, Vec3(U(rng), U(rng), U(rng))), d, true, "spheres sep " + what);
    nonzero += same_on_both(cup_l, pp, Pose3(rq, Vec3(1.5 + U(rng), 1.5 + U(rng), 1 + U(rng))), d, false, "cup " + what);
    // Q's faces in P's planes: a rotation about z by a quarter turn keeps the grid.
    const Pose3 quarter(Eigen::Quaterniond(std::sqrt(0.5), 0, 0, std::sqrt(0.5)), Vec3(1.5, 1, 0.5 * (k % 4)));
    same_on_both(cup_l, Pose3(), quarter, Vec3::Unit(k % 3) * (k % 2 ? 1 : -1), false, "quarter " + what);
  }
  EXPECT_GT(nonzero, 15);
}

}  // namespace
