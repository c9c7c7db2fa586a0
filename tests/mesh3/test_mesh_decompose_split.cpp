// The split convex decomposition (src/mesh3/convex_decomposition.cpp: exact axis-parallel cuts
// into cells, CGAL's convex_decomposition_3 per cell) checked exactly against the mesh, before
// rounding: the Nef union of the exact pieces equals the mesh's Nef polyhedron, their exact
// volumes sum to the mesh's (so their interiors are disjoint) and each is convex (exact
// orientation of every vertex against every facet plane). The one-run decomposition (max_depth 0,
// the previous algorithm) is checked the same way as the reference. Splits are forced on small
// meshes (few reflex edges per cell, up to 8 levels) so that the Nef unions stay cheap.
#include <pendepth/io.hpp>
#include <pendepth/mesh3.hpp>

#include "mesh3/convex_decomposition_nef.hpp"
#include "mesh_gen.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace pendepth;
using namespace mesh3_test;

namespace {

// expect_split: true / false: the split must / must not cut; unset: either (a cut that leaves a
// cell with all the reflex edges, e.g. long ones across it, is not made).
void expect_exact_tiling(const Mesh3& m, const detail::DecompositionSplit& split, std::optional<bool> expect_split) {
  const detail::DecompositionCheck c = detail::check_decomposition(m, split);
  EXPECT_TRUE(c.union_is_mesh);
  EXPECT_TRUE(c.volumes_sum);
  EXPECT_TRUE(c.each_convex);
  EXPECT_GE(c.pieces, 2u);
  if (expect_split == true) EXPECT_GT(c.cells, 1u);
  if (expect_split == false) EXPECT_EQ(c.cells, 1u);
}

void check_both(const Mesh3& m, std::optional<bool> must_split = true) {
  {
    SCOPED_TRACE("reference: one run");
    expect_exact_tiling(m, {1000000, 0}, false);
  }
  {
    SCOPED_TRACE("split: ≤ 2 reflex edges per cell, 3 levels");
    expect_exact_tiling(m, {2, 3}, must_split);
  }
  {
    // Deep kd-trees: every cell is cut from the solid by its own leaf box (never from a cell), so
    // boxes' edges and corners meet mesh edges and faces in every way the levels allow.
    SCOPED_TRACE("split: ≤ 1 reflex edge per cell, 8 levels");
    expect_exact_tiling(m, {1, 8}, must_split);
  }
}

}  // namespace

TEST(MeshDecompositionSplit, GeneratedMeshesTileExactly) {
  std::mt19937_64 rng(5);
  {
    SCOPED_TRACE("torus 8 x 5 (rational cut vertices)");
    check_both(Mesh3::validate(to_file(torus(8, 5)), "torus"));
  }
  {
    SCOPED_TRACE("comb of 6 teeth (cuts through integer planes)");
    check_both(Mesh3::validate(to_file(polycube(comb(6))), "comb"));
  }
  {
    SCOPED_TRACE("bumpy sphere");
    check_both(Mesh3::validate(to_file(bumpy_sphere(rng, 8, 6, 0.3)), "bumpy"));
  }
}

// Random polycubes: integer vertices, cuts at half-integers, triangulated square faces whose
// diagonals cross the boxes' edges at their midpoints and box corners on the faces — the
// degenerate contacts between the leaf boxes and the mesh, decided exactly by Nef.
TEST(MeshDecompositionSplit, RandomPolycubesTileExactlyUnderDeepSplits) {
  std::mt19937_64 rng(17);
  int checked = 0;
  for (int trial = 0; trial < 12 && checked < 3; ++trial) {
    std::optional<Mesh3> m;
    try {
      m = Mesh3::validate(to_file(polycube(random_polycube(rng, 10))), "polycube");
    } catch (const InvalidInput&) {
      continue;  // a non-manifold boundary (edge- or vertex-adjacent voxels)
    }
    if (m->convex() || m->reflex_edges() < 2) continue;
    SCOPED_TRACE("polycube " + std::to_string(trial));
    check_both(*m, std::nullopt);
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

// Near the largest doubles: the cut boxes reach beyond the mesh by its own extent, which would
// overflow to ±∞ at this scale; they stop at ±DBL_MAX instead and the tiling stays exact.
TEST(MeshDecompositionSplit, HugeCoordinatesTileExactly) {
  Gen g = polycube(comb(6));
  double extent = 0;
  for (const Vec3& p : g.points) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  const double scale = std::ldexp(1.0, 1023 - std::ilogb(extent));  // a power of two: exact, the top coordinate ≥ 2^1023
  for (Vec3& p : g.points) p = (p * scale).eval();
  for (Vec3& p : g.points) p.x() -= scale;  // both signs on x
  check_both(Mesh3::validate(to_file(g), "huge comb"));
}

#ifdef PENDEPTH_CGAL_MESHES
TEST(MeshDecompositionSplit, RealMeshesTileExactly) {
  for (const auto& [name, splits] : std::vector<std::pair<const char*, std::optional<bool>>>{
           {"star.off", true}, {"pipe.off", true}, {"tripod.off", std::nullopt}, {"hole.off", std::nullopt}}) {
    SCOPED_TRACE(name);
    check_both(Mesh3::validate(io::read_mesh(std::string(PENDEPTH_CGAL_MESHES) + "/" + name), name), splits);
  }
}

// The default split (> 128 reflex edges per cell) on a real mesh that it cuts: mpi_triang has 72
// reflex edges, so it is forced at 24 per cell; the public entry point reports the cells.
TEST(MeshDecompositionSplit, DefaultEntryPointSplitsLargeMeshesOnly) {
  const Mesh3 m = Mesh3::validate(io::read_mesh(std::string(PENDEPTH_CGAL_MESHES) + "/mpi_triang.off"), "mpi");
  expect_exact_tiling(m, {24, 4}, true);
  EXPECT_EQ(m.decomposition().cells, 1u);  // 72 ≤ 128: one run, as before
  const Mesh3 t = Mesh3::validate(to_file(torus(16, 8)), "torus");  // 129 reflex edges
  ASSERT_GT(t.reflex_edges(), 128u);
  EXPECT_GT(t.decomposition().cells, 1u);
}
#endif
