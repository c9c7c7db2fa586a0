// Pair3 on a non-convex mesh against a segment, both roles (src/mesh3/mesh_segment.cpp and the
// piece pairs of mesh_mixed.cpp).
//
// Oracles.
//  - Polycubes (unions of unit voxels), exactly from the voxels alone in GMP rationals: a point is
//    interior iff every voxel whose closure holds it is in U; along the segment the set of those
//    voxels changes only where a coordinate crosses an integer, so the segment overlaps int U iff
//    the midpoint of two consecutive such parameters (with 0 and 1) is interior. σ_d along an axis
//    (dyadic data): every sampled translation before the answer overlaps (oracle), the next double
//    above the answer does not (oracle), the answer less 1e-9 relative does.
//  - Rotated meshes and poses: the segment sampled at 257 exact dyadic points, each classified by
//    the point path (mesh_point.cpp: its own exact parity on doubles; the placed sample point is
//    exactly the segment's placed point at that parameter): any interior sample ⇒ overlapping.
//  - Closed forms on a comb: segments in a slot (exact fits), lying in the surface (touching, not
//    overlapping), lying in a face two decomposition pieces share (the case the piece union misses:
//    no piece pair overlaps, the segment does), σ_d, σ, distances.
//  - Properties: σ lower <= upper <= σ_d (axes); the two roles agree; the tree path equals the
//    linear scan bit for bit; signed distance = −σ's upper when overlapping, the pieces' min apart.
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh3/mesh_mixed.hpp"
#include "mesh_gen.hpp"

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cmath>
#include <optional>
#include <random>

namespace {

using namespace pendepth;
using namespace mesh3_test;

Shape3 mesh_of(const Gen& g, const std::string& name) { return Shape3::from_mesh(Mesh3::validate(to_file(g, name), name)); }

using Q3 = std::array<mpq_class, 3>;

Q3 q3(const Vec3& v) { return {mpq_class(v[0]), mpq_class(v[1]), mpq_class(v[2])}; }

bool interior(const std::set<Voxel>& U, const Q3& x) {
  std::vector<Voxel> around{{0, 0, 0}};
  for (int k = 0; k < 3; ++k) {
    mpz_class f;
    mpz_fdiv_q(f.get_mpz_t(), x[k].get_num_mpz_t(), x[k].get_den_mpz_t());
    const int fl = static_cast<int>(f.get_si());
    std::vector<Voxel> next;
    for (Voxel v : around) {
      v[k] = fl;
      next.push_back(v);
      if (x[k] == fl) v[k] = fl - 1, next.push_back(v);
    }
    around = next;
  }
  for (const Voxel& v : around)
    if (!U.count(v)) return false;
  return true;
}

// Does the segment [a, b] (exact rationals) meet int U? (file comment)
bool seg_oracle(const std::set<Voxel>& U, const Q3& a, const Q3& b) {
  std::vector<mpq_class> lam{0, 1};
  for (int k = 0; k < 3; ++k) {
    if (a[k] == b[k]) continue;
    for (int c = -64; c <= 64; ++c) {
      const mpq_class l = (mpq_class(c) - a[k]) / (b[k] - a[k]);
      if (l > 0 && l < 1) lam.push_back(l);
    }
  }
  std::sort(lam.begin(), lam.end());
  for (std::size_t i = 0; i + 1 < lam.size(); ++i) {
    if (lam[i] == lam[i + 1]) continue;
    const mpq_class m = (lam[i] + lam[i + 1]) / 2;
    Q3 x;
    for (int k = 0; k < 3; ++k) x[k] = a[k] + m * (b[k] - a[k]);
    if (interior(U, x)) return true;
  }
  return false;
}
bool seg_oracle(const std::set<Voxel>& U, const Vec3& a, const Vec3& b, const Vec3& t) {
  Q3 x = q3(a), y = q3(b);
  const Q3 v = q3(t);
  for (int k = 0; k < 3; ++k) x[k] += v[k], y[k] += v[k];
  return seg_oracle(U, x, y);
}

// The MixedPair itself (tree and linear paths).
mesh3::MixedPair mixed(const Shape3& mesh, const Shape3& seg, bool linear) {
  mesh3::MixedPair m = mesh3::MixedPair::make(mesh, seg);
  m.linear = linear;
  return m;
}

const std::set<Voxel> kComb = comb(3);  // x ∈ [0, 5], base y ∈ [0, 1], teeth at x ∈ [0,1], [2,3], [4,5] up to y = 3

TEST(MeshSegment, CombClosedForms) {
  const Shape3 mesh = mesh_of(polycube(kComb), "comb");
  auto pair = [&](const Vec3& a, const Vec3& b) { return Pair3(mesh, Shape3::segment(a, b, "seg")); };
  // In the slot between teeth 0 and 2 (x ∈ [1, 2], y ∈ [1, 3]): an exact fit touches both walls.
  EXPECT_FALSE(pair(Vec3(1, 1.5, 0.5), Vec3(2, 1.5, 0.5)).overlapping(Pose3(), Pose3()));
  EXPECT_TRUE(pair(Vec3(1 - 0x1p-30, 1.5, 0.5), Vec3(2, 1.5, 0.5)).overlapping(Pose3(), Pose3()));
  EXPECT_TRUE(pair(Vec3(1, 1.5, 0.5), Vec3(2 + 0x1p-30, 1.5, 0.5)).overlapping(Pose3(), Pose3()));
  // Lying on the slot's floor (the base's top face) and on a tooth's outer face: touching only.
  for (const auto& [a, b] : std::vector<std::pair<Vec3, Vec3>>{{Vec3(1, 1, 0), Vec3(2, 1, 1)},
                                                               {Vec3(1.5, 1, 0.25), Vec3(1.5, 1, 0.75)},
                                                               {Vec3(0, 0.5, 0.5), Vec3(0, 2.5, 0.5)},
                                                               {Vec3(0, 0, 0), Vec3(5, 0, 1)},
                                                               {Vec3(0, 3, 0), Vec3(1, 3, 1)}}) {
    const Pair3 p = pair(a, b);
    EXPECT_FALSE(p.overlapping(Pose3(), Pose3()));
    EXPECT_EQ(p.signed_distance(Pose3(), Pose3()).distance, 0.0);
    EXPECT_EQ(p.minimum(Pose3(), Pose3()).depth, 0.0);
    EXPECT_EQ(p.cast(Pose3(), Pose3(), Vec3(0, 0, 1)).distance, 0.0);
  }
  // Half in tooth 0, half in the slot: σ_d +x, +z 0.5 (an exact fit into the slot on +x), +y 1.5,
  // −y through the base 1.5; σ = 0.5.
  const Pair3 p = pair(Vec3(0.5, 1.5, 0.5), Vec3(1.5, 1.5, 0.5));
  EXPECT_TRUE(p.overlapping(Pose3(), Pose3()));
  EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(1, 0, 0)).depth, 0.5);
  EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(-1, 0, 0)).depth, 1.5);  // the whole segment in tooth 0 first
  EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(0, 0, 1)).depth, 0.5);
  EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(0, 1, 0)).depth, 1.5);
  EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(0, -1, 0)).depth, 1.5);
  EXPECT_EQ(p.separation(Pose3(), Pose3(), Vec3(1, 0, 0)).depth, 4.5);  // leaves tooth 4 at x = 5
  const Depth3 s = p.minimum(Pose3(), Pose3());
  EXPECT_LE(s.lower_bound, 0.5);
  EXPECT_EQ(s.upper_bound, 0.5);
  EXPECT_EQ(p.signed_distance(Pose3(), Pose3()).distance, -s.upper_bound);
  // Apart: above the teeth by 0.5; the cast down meets the top at 0.5.
  const Pair3 above = pair(Vec3(0.5, 3.5, 0.5), Vec3(4.5, 3.5, 0.5));
  EXPECT_FALSE(above.overlapping(Pose3(), Pose3()));
  EXPECT_EQ(above.signed_distance(Pose3(), Pose3()).distance, 0.5);
  EXPECT_EQ(above.cast(Pose3(), Pose3(), Vec3(0, -1, 0)).distance, 0.5);
  EXPECT_EQ(above.along(Pose3(), Pose3(), Vec3(0, -1, 0)).depth, 0.0);
}

// The case the piece union misses: segments lying in the internal grid planes of the comb (faces
// between voxels). Some lie in a face two decomposition pieces share: no piece pair overlaps,
// the segment does (the oracle says so too).
TEST(MeshSegment, SharedInternalFace) {
  const Shape3 mesh = mesh_of(polycube(kComb), "comb");
  const auto& pieces = mesh.mesh()->decomposition().pieces;
  int shared = 0, total = 0;
  for (int c = 1; c <= 4; ++c)
    for (const auto& [a, b] :
         std::vector<std::pair<Vec3, Vec3>>{{Vec3(c, 0.25, 0.25), Vec3(c, 0.75, 0.75)},
                                            {Vec3(c, 0.5, 0.1), Vec3(c, 0.5, 0.9)},
                                            {Vec3(0.25 + (c % 2) * 2, 1, 0.5), Vec3(0.75 + (c % 2) * 2, 1, 0.5)},
                                            {Vec3(0.5 + (c % 3) * 2, 2, 0.2), Vec3(0.5 + (c % 3) * 2, 2, 0.8)}}) {
      const Shape3 seg = Shape3::segment(a, b, "seg");
      const bool want = seg_oracle(kComb, a, b, Vec3::Zero());
      ASSERT_TRUE(want);
      const Pair3 p(mesh, seg);
      EXPECT_TRUE(p.overlapping(Pose3(), Pose3()));
      EXPECT_TRUE(Pair3(seg, mesh).overlapping(Pose3(), Pose3()));
      bool any = false;
      for (const ConvexPolytope& k : pieces) any = any || Pair3(Shape3(k), seg).overlapping(Pose3(), Pose3());
      shared += !any, ++total;
      if (!any) {  // σ: no piece overlaps, the bounds still hold (lower 0)
        const Depth3 s = p.minimum(Pose3(), Pose3());
        EXPECT_TRUE(s.overlapping);
        EXPECT_GT(s.upper_bound, 0);
        EXPECT_LE(s.lower_bound, s.upper_bound);
        EXPECT_LT(p.signed_distance(Pose3(), Pose3()).distance, 0);
        EXPECT_EQ(p.cast(Pose3(), Pose3(), Vec3(1, 0, 0)).distance, 0);
      }
    }
  EXPECT_GT(shared, 0) << "no segment in a face shared by two pieces among " << total;
}

// Random polycubes and segments on a 1/4 grid (often in grid planes, on the surface, in shared
// faces), both roles, against the voxel oracle; σ_d along axes against the oracle's samples.
TEST(MeshSegment, PolycubeOracle) {
  std::mt19937_64 rng(20261127);
  std::uniform_int_distribution<int> G(-4, 16);
  int over = 0, apart = 0, checked_exit = 0;
  std::vector<std::set<Voxel>> sets{kComb, l_block(), cup(2)};
  for (int r = 0; r < 3; ++r) sets.push_back(random_polycube(rng, 8));
  for (const auto& U : sets) {
    std::optional<Shape3> built;
    try {
      built = mesh_of(polycube(U), "poly");
    } catch (const InvalidInput&) {
      continue;  // a random polycube whose boundary is not a manifold
    }
    const Shape3& mesh = *built;
    int lo = 99, hi = -99;
    for (const Voxel& v : U)
      for (int k = 0; k < 3; ++k) lo = std::min(lo, v[k]), hi = std::max(hi, v[k] + 1);
    std::uniform_int_distribution<int> C(4 * lo - 2, 4 * hi + 2);
    for (int it = 0; it < 40; ++it) {
      Vec3 a, b;
      for (int k = 0; k < 3; ++k) a[k] = C(rng) / 4.0, b[k] = C(rng) / 4.0;
      if (rng() % 2) {  // more segments in grid planes
        const int k = static_cast<int>(rng() % 3);
        a[k] = b[k] = std::round(a[k]);
      }
      if (a == b) continue;
      const Shape3 seg = Shape3::segment(a, b, "seg");
      const Pair3 p(mesh, seg), sw(seg, mesh);
      const bool want = seg_oracle(U, a, b, Vec3::Zero());
      const std::string what = "a " + std::to_string(a[0]) + "," + std::to_string(a[1]) + "," + std::to_string(a[2]) +
                               " b " + std::to_string(b[0]) + "," + std::to_string(b[1]) + "," + std::to_string(b[2]);
      ASSERT_EQ(p.overlapping(Pose3(), Pose3()), want) << what;
      EXPECT_EQ(sw.overlapping(Pose3(), Pose3()), want) << what;
      (want ? over : apart)++;
      if (!want) {
        const Distance3 d = p.signed_distance(Pose3(), Pose3());
        EXPECT_GE(d.distance, 0) << what;
        EXPECT_EQ(sw.signed_distance(Pose3(), Pose3()).distance, d.distance) << what;
        continue;
      }
      double least = INFINITY;
      for (int ax = 0; ax < 6; ++ax) {
        Vec3 u = Vec3::Zero();
        u[ax / 2] = ax % 2 ? -1 : 1;
        const Depth3 e = p.along(Pose3(), Pose3(), u);
        ASSERT_TRUE(e.overlapping) << what;
        ASSERT_GT(e.depth, 0) << what;
        least = std::min(least, e.depth);
        // The other role: the mesh moves by −v.
        EXPECT_EQ(sw.along(Pose3(), Pose3(), -u).depth, e.depth) << what;
        // The exit is not in O, just before it is, and every sample before it is.
        EXPECT_FALSE(seg_oracle(U, a, b, std::nextafter(e.depth, INFINITY) * u)) << what << " ax " << ax;
        EXPECT_TRUE(seg_oracle(U, a, b, e.depth * (1 - 1e-9) * u)) << what << " ax " << ax;
        for (int j = 1; j < 16; ++j) EXPECT_TRUE(seg_oracle(U, a, b, (e.depth * j / 16) * u)) << what << " ax " << ax;
        EXPECT_FALSE(p.overlapping(Pose3(), Pose3(std::nextafter(e.depth, INFINITY) * u))) << what;
        ++checked_exit;
      }
      const Depth3 s = p.minimum(Pose3(), Pose3());
      EXPECT_LE(s.lower_bound, s.upper_bound) << what;
      EXPECT_LE(s.upper_bound, least) << what;
      EXPECT_GT(s.upper_bound, 0) << what;
      EXPECT_EQ(p.signed_distance(Pose3(), Pose3()).distance, -s.upper_bound) << what;
    }
  }
  EXPECT_GT(over, 30);
  EXPECT_GT(apart, 30);
  EXPECT_GT(checked_exit, 100);
}

// Rotated meshes and poses: overlap against the point path on 257 exact samples of the segment;
// σ_d's properties; the tree equals the linear scan bit for bit.
TEST(MeshSegment, RotatedSamplesAndTree) {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> U(-1, 1);
  const Shape3 cupm = mesh_of(polycube(cup(2)), "cup");
  const Shape3 cmb = mesh_of(polycube(kComb), "comb");
  int inside_found = 0, agree = 0, n = 0;
  for (const Shape3* mesh : {&cupm, &cmb}) {
    const double R = mesh == &cupm ? 2 : 3.5;
    const Vec3 c = mesh == &cupm ? Vec3(1.5, 1.5, 1.5) : Vec3(2.5, 1.5, 0.5);
    for (int it = 0; it < 30; ++it) {
      // Dyadic end points (so a + k/256 (b − a) is exact), random rotations of both shapes.
      Vec3 a, b;
      for (int k = 0; k < 3; ++k) a[k] = std::ldexp(std::round(std::ldexp(c[k] + R * U(rng), 8)), -8);
      for (int k = 0; k < 3; ++k) b[k] = std::ldexp(std::round(std::ldexp(a[k] + 2 * U(rng), 8)), -8);
      const Eigen::Quaterniond qm(U(rng), U(rng), U(rng), U(rng)), qs(U(rng), U(rng), U(rng), U(rng));
      // The segment in the mesh's rotated frame, slightly turned (qs near qm) so the placement is
      // not the identity.
      const Pose3 pm(qm, Vec3(U(rng), U(rng), U(rng)));
      const Pose3 pseg(Eigen::Quaterniond(qm.coeffs() + 0.01 * qs.coeffs()), pm.translation);
      const Shape3 seg = Shape3::segment(a, b, "seg");
      const Pair3 p(*mesh, seg);
      const bool over = p.overlapping(pm, pseg);
      bool sample_in = false;
      for (int k = 0; k <= 256 && !sample_in; ++k) {
        const Vec3 x = a + (k / 256.0) * (b - a);
        sample_in = Pair3(*mesh, Shape3::point(x)).overlapping(pm, pseg);
      }
      ++n;
      inside_found += sample_in;
      if (sample_in) EXPECT_TRUE(over) << it;
      agree += sample_in == over;
      // The other role and the linear reference.
      EXPECT_EQ(Pair3(seg, *mesh).overlapping(pseg, pm), over) << it;
      const mesh3::MixedPair tree = mixed(*mesh, seg, false), lin = mixed(*mesh, seg, true);
      EXPECT_EQ(mesh3::overlapping(lin, pm, pseg), over) << it;
      if (!over) continue;
      const Vec3 d(U(rng), U(rng), U(rng));
      const Depth3 e = mesh3::along(tree, pm, pseg, d, false), el = mesh3::along(lin, pm, pseg, d, false);
      EXPECT_EQ(e.depth, el.depth) << it;
      EXPECT_EQ(mesh3::along(tree, pm, pseg, d, true).depth, mesh3::along(lin, pm, pseg, d, true).depth) << it;
      const Vec3 u = d.normalized();
      EXPECT_TRUE(p.overlapping(pm, Pose3(pseg.rotation, pm.translation + (1 - 1e-9) * e.depth * u))) << it;
      EXPECT_FALSE(p.overlapping(pm, Pose3(pseg.rotation, pm.translation + (1 + 1e-9) * e.depth * u))) << it;
      const Depth3 s = p.minimum(pm, pseg);
      EXPECT_LE(s.lower_bound, s.upper_bound) << it;
      EXPECT_LE(s.upper_bound, e.depth) << it;
    }
  }
  EXPECT_GT(inside_found, 5);
  EXPECT_GE(agree, n * 9 / 10) << "sampling should see nearly every overlap";
}

// The numeric domain (src/front/scale.hpp): the comb and segment scaled by 2^±300 give the same
// answers scaled (the triangles' path is scaled into the engine's band, the pieces scale
// themselves).
TEST(MeshSegment, HugeAndTinyScale) {
  for (const int e : {300, -300}) {
    Gen g = polycube(kComb);
    for (Vec3& v : g.points) v = std::ldexp(1.0, e) * v;
    const Shape3 mesh = mesh_of(g, "comb");
    auto S = [&](double x) { return std::ldexp(x, e); };
    const Pair3 p(mesh, Shape3::segment(Vec3(S(0.5), S(1.5), S(0.5)), Vec3(S(1.5), S(1.5), S(0.5)), "seg"));
    EXPECT_TRUE(p.overlapping(Pose3(), Pose3()));
    EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(1, 0, 0)).depth, S(0.5));
    EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(0, -1, 0)).depth, S(1.5));
    EXPECT_EQ(p.minimum(Pose3(), Pose3()).upper_bound, S(0.5));
    EXPECT_FALSE(p.overlapping(Pose3(), Pose3(Vec3(S(0.5), 0, 0))));
    const Pair3 fit(mesh, Shape3::segment(Vec3(S(1), S(1.5), S(0.5)), Vec3(S(2), S(1.5), S(0.5)), "seg"));
    EXPECT_FALSE(fit.overlapping(Pose3(), Pose3()));
    EXPECT_EQ(fit.signed_distance(Pose3(), Pose3()).distance, 0.0);
    EXPECT_EQ(Pair3(Shape3::segment(Vec3(S(0.5), S(1.5), S(0.5)), Vec3(S(1.5), S(1.5), S(0.5)), "seg"), mesh)
                  .along(Pose3(), Pose3(Vec3(0, 0, S(0.25))), Vec3(0, 0, -1))
                  .depth,
              S(0.75));  // the mesh moves down: the segment leaves through the comb's top (z = 1)
  }
}

}  // namespace
