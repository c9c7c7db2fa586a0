// Pair3 on a non-convex mesh against a flat convex polygon, both roles (src/mesh3/mesh_flat.cpp
// and the piece pairs of mesh_mixed.cpp).
//
// Oracles.
//  - Polycubes (unions of unit voxels), exactly from the voxels alone in GMP rationals: a point is
//    interior iff every voxel whose closure holds it is in U. An axis-aligned rectangle R in the
//    plane x_k = c: ∂U ∩ (R's plane) lies on the integer lines of the two other coordinates (and
//    whole unit squares when c is an integer), so on each open cell of R cut by those lines
//    membership in int U is constant: R overlaps int U iff the centre of some cell is interior.
//    σ_d along an axis moves R to another axis-aligned rectangle (dyadic data): every sampled
//    translation before the answer overlaps (oracle), the answer's does not, the answer less 1e-9
//    relative does.
//  - General polygons under rotated poses: sampled at exact dyadic points of F (a grid of convex
//    combinations of its vertices) classified by the point path (mesh_point.cpp, its own exact
//    parity): any interior sample ⇒ overlapping; the tree path equals the linear scan bit for bit.
//  - Closed forms on a comb: a polygon lying in a face two decomposition pieces share (no piece
//    pair overlaps, the polygon does), polygons on the surface (touching, not overlapping), exact
//    fits in a slot, σ_d, σ, distance and cast; 2^±300 scaled copies give the same answers scaled.
//  - The planted bugs: σ_d with each candidate family left out (MixedPair::flat_drop_family) must
//    disagree with the oracle somewhere on a fixed sample — each family is needed; the overlap
//    test without the segments' crossings misses a corner of a triangle poking into a tooth.
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

// An axis-aligned rectangle: coordinate k fixed at c, the others (k+1, k+2 mod 3) in [lo, hi].
struct Rect {
  int k;
  double c;
  std::array<double, 2> lo, hi;
  std::vector<Vec3> corners() const {
    std::vector<Vec3> p;
    for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
      Vec3 v;
      v[k] = c, v[(k + 1) % 3] = i ? hi[0] : lo[0], v[(k + 2) % 3] = j ? hi[1] : lo[1];
      p.push_back(v);
    }
    return p;
  }
  Shape3 shape() const { return Shape3::flat(corners(), "rect"); }
};

// Does R + t meet int U? (file comment)
bool rect_oracle(const std::set<Voxel>& U, const Rect& R, const Vec3& t) {
  const mpq_class c = mpq_class(R.c) + mpq_class(t[R.k]);
  std::array<std::vector<mpq_class>, 2> br;
  for (int j = 0; j < 2; ++j) {
    const int ax = (R.k + 1 + j) % 3;
    const mpq_class lo = mpq_class(R.lo[j]) + mpq_class(t[ax]), hi = mpq_class(R.hi[j]) + mpq_class(t[ax]);
    br[j] = {lo, hi};
    for (int z = -64; z <= 64; ++z)
      if (lo < z && z < hi) br[j].push_back(z);
    std::sort(br[j].begin(), br[j].end());
  }
  for (std::size_t i = 0; i + 1 < br[0].size(); ++i)
    for (std::size_t j = 0; j + 1 < br[1].size(); ++j) {
      Q3 x;
      x[R.k] = c;
      x[(R.k + 1) % 3] = (br[0][i] + br[0][i + 1]) / 2;
      x[(R.k + 2) % 3] = (br[1][j] + br[1][j + 1]) / 2;
      if (interior(U, x)) return true;
    }
  return false;
}

mesh3::MixedPair mixed(const Shape3& mesh, const Shape3& f, bool linear) {
  mesh3::MixedPair m = mesh3::MixedPair::make(mesh, f);
  m.linear = linear;
  return m;
}

const std::set<Voxel> kComb = comb(3);  // x ∈ [0, 5], base y ∈ [0, 1], teeth at x ∈ [0,1], [2,3], [4,5] up to y = 3

Rect rect(int k, double c, double lo0, double hi0, double lo1, double hi1) { return Rect{k, c, {lo0, lo1}, {hi0, hi1}}; }

TEST(MeshFlat, CombClosedForms) {
  const Shape3 mesh = mesh_of(polycube(kComb), "comb");
  auto pair = [&](const Rect& R) { return Pair3(mesh, R.shape()); };
  // A square in the plane z = 0.5 across the slot between teeth 0 and 2 (x ∈ [1, 2], y ∈ [1, 3]):
  // an exact fit touches both walls; wider by 2^-30 it overlaps. (k = 2: coordinates x, y.)
  EXPECT_FALSE(pair(rect(2, 0.5, 1, 2, 1.25, 2)).overlapping(Pose3(), Pose3()));
  EXPECT_TRUE(pair(rect(2, 0.5, 1 - 0x1p-30, 2, 1.25, 2)).overlapping(Pose3(), Pose3()));
  // Down into the slot's floor (the base's top face y = 1) by 2^-30: overlapping.
  EXPECT_TRUE(pair(rect(2, 0.5, 1.25, 1.75, 1 - 0x1p-30, 2)).overlapping(Pose3(), Pose3()));
  // Lying on the surface: the slot's floor (y = 1; k = 1: coordinates z, x), a tooth's outer face
  // x = 0 (k = 0: y, z), the back face z = 0 over the whole comb (k = 2): touching only.
  for (const Rect& R : {rect(1, 1, 0, 1, 1, 2), rect(0, 0, 0.5, 2.5, 0.25, 0.75), rect(2, 0, 0, 5, 0, 3), rect(1, 3, 0, 1, 0, 1)}) {
    const Pair3 p = pair(R);
    EXPECT_FALSE(p.overlapping(Pose3(), Pose3()));
    EXPECT_FALSE(rect_oracle(kComb, R, Vec3::Zero()));
    EXPECT_EQ(p.signed_distance(Pose3(), Pose3()).distance, 0.0);
    EXPECT_EQ(p.minimum(Pose3(), Pose3()).depth, 0.0);
  }
  // A square x ∈ [0.5, 1.5], y ∈ [1.5, 2.5] at z = 0.5: half in tooth 0, half in the slot.
  // σ_d +x 0.5 (an exact fit into the slot), −x 1.5, +y 1.5 (out over the top y = 3 — the part in
  // the slot holds nothing), −y: down through the base (y = 0) 2.5, ±z 0.5; σ = 0.5.
  const Pair3 p = pair(rect(2, 0.5, 0.5, 1.5, 1.5, 2.5));
  EXPECT_TRUE(p.overlapping(Pose3(), Pose3()));
  EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(1, 0, 0)).depth, 0.5);
  EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(-1, 0, 0)).depth, 1.5);
  EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(0, 1, 0)).depth, 1.5);
  EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(0, -1, 0)).depth, 2.5);
  EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(0, 0, 1)).depth, 0.5);
  EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(0, 0, -1)).depth, 0.5);
  EXPECT_EQ(p.separation(Pose3(), Pose3(), Vec3(1, 0, 0)).depth, 4.5);  // leaves tooth 4 at x = 5
  const Depth3 s = p.minimum(Pose3(), Pose3());
  EXPECT_LE(s.lower_bound, 0.5);
  EXPECT_EQ(s.upper_bound, 0.5);
  EXPECT_EQ(p.signed_distance(Pose3(), Pose3()).distance, -s.upper_bound);
  // The other role: the mesh moves by −d.
  EXPECT_EQ(Pair3(rect(2, 0.5, 0.5, 1.5, 1.5, 2.5).shape(), mesh).along(Pose3(), Pose3(), Vec3(-1, 0, 0)).depth, 0.5);
  // A square larger than the comb at z = 0.5: leaves along ±z when the comb's faces z = 0, 1
  // cross its plane (no vertex of the square on the mesh; the mesh's vertices enter its plane).
  EXPECT_EQ(pair(rect(2, 0.5, -1, 6, -1, 4)).along(Pose3(), Pose3(), Vec3(0, 0, 1)).depth, 0.5);
  EXPECT_EQ(pair(rect(2, 0.25, -1, 6, -1, 4)).along(Pose3(), Pose3(), Vec3(0, 0, -1)).depth, 0.25);
  // Apart: above the teeth by 0.5 (y = 3.5, k = 1: coordinates z, x); the cast down meets y = 3.
  const Pair3 above = pair(rect(1, 3.5, 0, 1, 0.5, 4.5));
  EXPECT_FALSE(above.overlapping(Pose3(), Pose3()));
  EXPECT_EQ(above.signed_distance(Pose3(), Pose3()).distance, 0.5);
  EXPECT_EQ(above.cast(Pose3(), Pose3(), Vec3(0, -1, 0)).distance, 0.5);
  EXPECT_EQ(above.along(Pose3(), Pose3(), Vec3(0, -1, 0)).depth, 0.0);
}

// The case the piece union misses: polygons lying in the internal grid planes of the comb (faces
// between voxels). Some lie in a face two decomposition pieces share: no piece pair overlaps, the
// polygon does (the oracle says so too).
TEST(MeshFlat, SharedInternalFace) {
  const Shape3 mesh = mesh_of(polycube(kComb), "comb");
  const auto& pieces = mesh.mesh()->decomposition().pieces;
  int shared = 0, total = 0;
  std::vector<Shape3> shapes;
  for (int c = 1; c <= 4; ++c) {
    shapes.push_back(rect(0, c, 0.25, 0.75, 0.25, 0.75).shape());  // x = c, y, z inside the base
    const std::vector<Vec3> tri{Vec3(c, 0.1, 0.1), Vec3(c, 0.9, 0.2), Vec3(c, 0.3, 0.9)};
    shapes.push_back(Shape3::flat(tri, "tri"));
    shapes.push_back(rect(1, 1, 0.25, 0.75, 0.25 + (c % 2) * 2, 0.75 + (c % 2) * 2).shape());  // y = 1 under a tooth
    shapes.push_back(rect(1, 2, 0.2, 0.8, 0.2 + (c % 3) * 2, 0.8 + (c % 3) * 2).shape());  // y = 2 in a tooth
  }
  for (const Shape3& f : shapes) {
    const Pair3 p(mesh, f);
    EXPECT_TRUE(p.overlapping(Pose3(), Pose3()));
    EXPECT_TRUE(Pair3(f, mesh).overlapping(Pose3(), Pose3()));
    bool any = false;
    for (const ConvexPolytope& k : pieces) any = any || Pair3(Shape3(k), f).overlapping(Pose3(), Pose3());
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
  EXPECT_GT(shared, 0) << "no polygon in a face shared by two pieces among " << total;
}

Rect random_rect(std::mt19937_64& rng, int lo, int hi) {
  std::uniform_int_distribution<int> C(4 * lo - 2, 4 * hi + 2), K(0, 2);
  Rect R;
  R.k = K(rng);
  R.c = C(rng) / 4.0;
  if (rng() % 2) R.c = std::round(R.c);  // often in a grid plane
  for (int j = 0; j < 2; ++j) {
    int a = C(rng), b = C(rng);
    while (a == b) b = C(rng);
    R.lo[j] = std::min(a, b) / 4.0, R.hi[j] = std::max(a, b) / 4.0;
  }
  return R;
}

std::string str(const Rect& R) {
  return "k " + std::to_string(R.k) + " c " + std::to_string(R.c) + " [" + std::to_string(R.lo[0]) + "," +
         std::to_string(R.hi[0]) + "]x[" + std::to_string(R.lo[1]) + "," + std::to_string(R.hi[1]) + "]";
}

// Random polycubes and rectangles on a 1/4 grid (often in grid planes, on the surface, in shared
// faces), both roles, against the voxel oracle; σ_d along axes against the oracle's samples.
TEST(MeshFlat, PolycubeOracle) {
  std::mt19937_64 rng(20261127);
  int over = 0, apart = 0, checked_exit = 0;
  std::vector<std::set<Voxel>> sets{kComb, l_block(), cup(2)};
  for (int r = 0; r < 2; ++r) sets.push_back(random_polycube(rng, 7));
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
    for (int it = 0; it < 24; ++it) {
      const Rect R = random_rect(rng, lo, hi);
      const Shape3 f = R.shape();
      const Pair3 p(mesh, f), sw(f, mesh);
      const bool want = rect_oracle(U, R, Vec3::Zero());
      const std::string what = str(R) + " set " + std::to_string(&U - sets.data());
      ASSERT_EQ(p.overlapping(Pose3(), Pose3()), want) << what;
      EXPECT_EQ(sw.overlapping(Pose3(), Pose3()), want) << what;
      (want ? over : apart)++;
      if (!want) {
        const Distance3 d = p.signed_distance(Pose3(), Pose3());
        EXPECT_GE(d.distance, 0) << what;
        EXPECT_EQ(sw.signed_distance(Pose3(), Pose3()).distance, d.distance) << what;
        continue;
      }
      for (int ax = 0; ax < 6; ++ax) {
        if (ax % 2 != it % 2) continue;  // three of the six axes per case (time)
        Vec3 u = Vec3::Zero();
        u[ax / 2] = ax % 2 ? -1 : 1;
        const Depth3 e = p.along(Pose3(), Pose3(), u);
        ASSERT_TRUE(e.overlapping) << what;
        ASSERT_GT(e.depth, 0) << what;
        EXPECT_EQ(sw.along(Pose3(), Pose3(), -u).depth, e.depth) << what;
        // The exit itself is not in O (exact: dyadic data along an axis); it may be re-entered at
        // once (a rectangle sliding past an internal corner touches ∂O at one point).
        EXPECT_FALSE(rect_oracle(U, R, e.depth * u)) << what << " ax " << ax << " σ_d " << e.depth;
        EXPECT_TRUE(rect_oracle(U, R, e.depth * (1 - 1e-9) * u)) << what << " ax " << ax;
        for (int j = 1; j < 16; ++j) EXPECT_TRUE(rect_oracle(U, R, (e.depth * j / 16) * u)) << what << " ax " << ax;
        ++checked_exit;
      }
    }
  }
  EXPECT_GT(over, 20);
  EXPECT_GT(apart, 20);
  EXPECT_GT(checked_exit, 60);
}

// σ_d with one candidate family left out must be caught by the oracle (each family is needed):
// the same kind of sample as PolycubeOracle on the comb and the cup.
TEST(MeshFlat, PlantedBugIsCaught) {
  for (int family = 1; family <= 3; ++family) {
    std::mt19937_64 rng(4242);
    int wrong = 0, tried = 0;
    for (const auto& U : {kComb, cup(2), l_block()}) {
      const Shape3 mesh = mesh_of(polycube(U), "poly");
      int lo = 99, hi = -99;
      for (const Voxel& v : U)
        for (int k = 0; k < 3; ++k) lo = std::min(lo, v[k]), hi = std::max(hi, v[k] + 1);
      for (int it = 0; it < 40 && wrong == 0; ++it) {
        // First a square over the whole shape in the plane z = 1/2 (leaving along z only mesh
        // vertices enter its plane: family 3), then a small one in voxel (0, 0, 0) inside one
        // triangle of its faces z = 0, 1 (leaving along z only its vertices meet a triangle:
        // family 1), then random rectangles (their edges cross the quads' diagonals: family 2).
        const Rect R = it == 0   ? rect(2, 0.5, lo - 1, hi + 1, lo - 1, hi + 1)
                       : it == 1 ? rect(2, 0.5, 0.45, 0.55, 0.02, 0.08)
                                 : random_rect(rng, lo, hi);
        if (!rect_oracle(U, R, Vec3::Zero())) continue;
        mesh3::MixedPair m = mesh3::MixedPair::make(mesh, R.shape());
        m.flat_drop_family = family;
        for (int ax = 0; ax < 6 && wrong == 0; ++ax) {
          Vec3 u = Vec3::Zero();
          u[ax / 2] = ax % 2 ? -1 : 1;
          ++tried;
          try {
            const Depth3 e = mesh3::along(m, Pose3(), Pose3(), u, false);
            wrong += rect_oracle(U, R, e.depth * u) || !rect_oracle(U, R, e.depth * (1 - 1e-9) * u);
          } catch (const std::logic_error&) {
            ++wrong;  // no candidate left the set: also caught
          }
        }
      }
    }
    EXPECT_GT(wrong, 0) << "dropping candidate family " << family << " went unnoticed over " << tried << " σ_d";
  }
}

// The overlap test's planted bug: without the crossings of the cut segments with F's edges, the
// chords miss a small corner of a large triangle that pokes into a tooth (the crossings bound that
// cell's φ-extent); the exact test sees it, as does the point path at a point of the corner.
TEST(MeshFlat, PlantedOverlapBugIsCaught) {
  const Shape3 mesh = mesh_of(polycube(kComb), "comb");
  // The vertex (0.25, 2.875) is 1/8 below the top y = 3 of tooth 0 (x ∈ [0, 1]); the edges from
  // it leave the tooth through its top at x = 0.15 and ≈ 0.33 (the top's cut by F's plane ends at
  // x = 0, 1 and its diagonal's crossing x = 0.5, all outside F); the rest of F is above the comb.
  const std::vector<Vec3> tri{Vec3(0.25, 2.875, 0.5), Vec3(-2.25, 6, 0.5), Vec3(2.75, 7, 0.5)};
  const Shape3 f = Shape3::flat(tri, "tri");
  EXPECT_TRUE(Pair3(mesh, Shape3::point(Vec3(0.25, 2.95, 0.5))).overlapping(Pose3(), Pose3()));
  EXPECT_TRUE(Pair3(mesh, f).overlapping(Pose3(), Pose3()));
  EXPECT_FALSE(Pair3(mesh, f).overlapping(Pose3(), Pose3(Vec3(0, 0.125, 0))));  // the vertex on the top: touching
  mesh3::MixedPair m = mesh3::MixedPair::make(mesh, f);
  m.flat_drop_family = 4;
  EXPECT_FALSE(mesh3::overlapping(m, Pose3(), Pose3())) << "the planted bug went unnoticed";
}

// General polygons under rotated poses: overlap against the point path on exact samples of the
// polygon; σ_d's properties; the tree equals the linear scan bit for bit; the two roles agree.
TEST(MeshFlat, RotatedSamplesAndTree) {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> U(-1, 1);
  const Shape3 cupm = mesh_of(polycube(cup(2)), "cup");
  const Shape3 cmb = mesh_of(polycube(kComb), "comb");
  auto dy = [](double x) { return std::ldexp(std::round(std::ldexp(x, 8)), -8); };
  int inside_found = 0, agree = 0, n = 0, dirs = 0;
  for (const Shape3* mesh : {&cupm, &cmb}) {
    const double R = mesh == &cupm ? 2 : 3.5;
    const Vec3 c = mesh == &cupm ? Vec3(1.5, 1.5, 1.5) : Vec3(2.5, 1.5, 0.5);
    for (int it = 0; it < 12; ++it) {
      // A dyadic triangle (so its barycentric samples with weights i/8 are exact).
      Vec3 a, b, e;
      for (int k = 0; k < 3; ++k) a[k] = dy(c[k] + R * U(rng));
      for (int k = 0; k < 3; ++k) b[k] = dy(a[k] + 1.5 * U(rng)), e[k] = dy(a[k] + 1.5 * U(rng));
      const std::vector<Vec3> pts{a, b, e};
      std::optional<Shape3> fs;
      try {
        fs = Shape3::flat(pts, "tri");
      } catch (const InvalidInput&) {
        continue;
      }
      if (fs->dimension() != 2) continue;
      const Eigen::Quaterniond qm(U(rng), U(rng), U(rng), U(rng)), qs(U(rng), U(rng), U(rng), U(rng));
      const Pose3 pm(qm, Vec3(U(rng), U(rng), U(rng)));
      const Pose3 pf(Eigen::Quaterniond(qm.coeffs() + 0.01 * qs.coeffs()), pm.translation);
      const Pair3 p(*mesh, *fs);
      const bool over = p.overlapping(pm, pf);
      bool sample_in = false;
      for (int i = 0; i <= 8 && !sample_in; ++i)
        for (int j = 0; i + j <= 8 && !sample_in; ++j) {
          const Vec3 x = a + (i / 8.0) * (b - a) + (j / 8.0) * (e - a);
          sample_in = Pair3(*mesh, Shape3::point(x)).overlapping(pm, pf);
        }
      ++n;
      inside_found += sample_in;
      if (sample_in) EXPECT_TRUE(over) << it;
      agree += sample_in == over;
      EXPECT_EQ(Pair3(*fs, *mesh).overlapping(pf, pm), over) << it;
      const mesh3::MixedPair tree = mixed(*mesh, *fs, false), lin = mixed(*mesh, *fs, true);
      EXPECT_EQ(mesh3::overlapping(lin, pm, pf), over) << it;
      if (!over) {
        EXPECT_GE(p.signed_distance(pm, pf).distance, 0) << it;
        continue;
      }
      const Vec3 d(U(rng), U(rng), U(rng));
      const Depth3 ed = mesh3::along(tree, pm, pf, d, false), el = mesh3::along(lin, pm, pf, d, false);
      EXPECT_EQ(ed.depth, el.depth) << it;
      const Vec3 u = d.normalized();
      EXPECT_TRUE(p.overlapping(pm, Pose3(pf.rotation, pm.translation + (1 - 1e-9) * ed.depth * u))) << it;
      EXPECT_FALSE(p.overlapping(pm, Pose3(pf.rotation, pm.translation + (1 + 1e-9) * ed.depth * u))) << it;
      ++dirs;
    }
  }
  EXPECT_GT(inside_found, 3);
  EXPECT_GT(dirs, 3);
  EXPECT_GE(agree, n * 8 / 10) << "sampling should see nearly every overlap";
}

// The numeric domain (src/front/scale.hpp): the comb and polygon scaled by 2^±300 give the same
// answers scaled.
TEST(MeshFlat, HugeAndTinyScale) {
  for (const int e : {300, -300}) {
    Gen g = polycube(kComb);
    for (Vec3& v : g.points) v = std::ldexp(1.0, e) * v;
    const Shape3 mesh = mesh_of(g, "comb");
    auto S = [&](double x) { return std::ldexp(x, e); };
    const Shape3 f = rect(2, S(0.5), S(0.5), S(1.5), S(1.5), S(2.5)).shape();
    const Pair3 p(mesh, f);
    EXPECT_TRUE(p.overlapping(Pose3(), Pose3()));
    EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(1, 0, 0)).depth, S(0.5));
    EXPECT_EQ(p.along(Pose3(), Pose3(), Vec3(0, -1, 0)).depth, S(2.5));
    EXPECT_EQ(p.minimum(Pose3(), Pose3()).upper_bound, S(0.5));
    EXPECT_FALSE(p.overlapping(Pose3(), Pose3(Vec3(S(0.5), 0, 0))));
    const Pair3 fit(mesh, rect(2, S(0.5), S(1), S(2), S(1.25), S(2)).shape());
    EXPECT_FALSE(fit.overlapping(Pose3(), Pose3()));
    EXPECT_EQ(fit.signed_distance(Pose3(), Pose3()).distance, 0.0);
    EXPECT_EQ(Pair3(f, mesh).along(Pose3(), Pose3(Vec3(0, 0, S(0.25))), Vec3(0, 0, -1)).depth,
              S(0.75));  // the mesh moves down: the polygon leaves through the comb's top (z = 1)
  }
}

}  // namespace
