// Pair3's mesh σ_d against CGAL's exact Minkowski sum (issue 17 "How it must be shown"): the Nef
// polyhedron S = P ⊕ (−Q) (CGAL::minkowski_sum_3, exact kernel) and exact ray queries on it: the
// ray t + s·d crosses ∂S only at parameters where it meets the plane of a halffacet of S, so the
// first s >= 0 that is not in int S is found by locating (exactly, Nef point location) each such
// parameter and the midpoint after it. Without exact fits between P and Q, int S = O (the union of
// the open piece sums), so σ_d must agree exactly; the L-block and a small non-convex polycube have
// none (no slot as wide as a part of the other). Small meshes (≤ 100 triangles) keep the Nef sum
// to a fraction of a second.
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh_gen.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/minkowski_sum_3.h>

#include <gtest/gtest.h>

#include <random>

namespace {

using namespace pendepth;
using namespace mesh3_test;
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Nef = CGAL::Nef_polyhedron_3<K>;
using FT = K::FT;

// The Nef polyhedron of a polycube's boundary, negated (x → −x) when `negate`.
Nef nef_of(const Gen& g, bool negate) {
  CGAL::Surface_mesh<K::Point_3> sm;
  std::vector<CGAL::Surface_mesh<K::Point_3>::Vertex_index> id;
  const double s = negate ? -1 : 1;
  for (const Vec3& p : g.points) id.push_back(sm.add_vertex(K::Point_3(s * p.x(), s * p.y(), s * p.z())));
  for (const auto& f : g.faces) {
    std::vector<CGAL::Surface_mesh<K::Point_3>::Vertex_index> face;
    for (std::size_t v : f) face.push_back(id[v]);
    if (negate) std::reverse(face.begin(), face.end());  // x → −x reverses orientation
    sm.add_face(face);
  }
  return Nef(sm);
}

bool interior(const Nef& S, const K::Point_3& x) {
  Nef::Volume_const_handle v;
  return CGAL::assign(v, S.locate(x)) && v->mark();
}

// σ_d in units of d: the first s >= 0 of t + s·d not in int S (exact rationals).
FT oracle_along(const Nef& S, const Vec3& t, const Vec3& d) {
  const K::Point_3 o(t.x(), t.y(), t.z());
  const K::Vector_3 v(d.x(), d.y(), d.z());
  std::vector<FT> params{FT(0)};
  for (auto h = S.halffacets_begin(); h != S.halffacets_end(); ++h) {
    const K::Plane_3 pl = h->plane();
    const FT den = pl.a() * v.x() + pl.b() * v.y() + pl.c() * v.z();
    if (den == 0) continue;
    const FT s = -(pl.a() * o.x() + pl.b() * o.y() + pl.c() * o.z() + pl.d()) / den;
    if (s > 0) params.push_back(s);
  }
  std::sort(params.begin(), params.end());
  params.erase(std::unique(params.begin(), params.end()), params.end());
  for (std::size_t k = 0; k < params.size(); ++k) {
    if (!interior(S, o + params[k] * v)) return params[k];
    if (k + 1 == params.size() || !interior(S, o + (params[k] + params[k + 1]) / 2 * v)) return params[k];
  }
  return params.back();
}

TEST(MeshPairNef, AlongMatchesExactMinkowskiSum) {
  const std::set<Voxel> pv = l_block(), qv{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}};  // L-block, a twisted 4-voxel part
  const Gen pg = polycube(pv), qg = polycube(qv);
  Nef NP = nef_of(pg, false), NQ = nef_of(qg, true);
  const Nef S = CGAL::minkowski_sum_3(NP, NQ);
  const Pair3 pair(Shape3::from_mesh(Mesh3::validate(to_file(pg, "L"), "L")),
                   Shape3::from_mesh(Mesh3::validate(to_file(qg, "Q"), "Q")));
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> U(-1, 1);
  int nonzero = 0;
  for (int k = 0; k < 40; ++k) {
    Vec3 t(1 + 2 * U(rng), 1 + 2 * U(rng), U(rng)), d(U(rng), U(rng), U(rng));
    if (k % 4 == 0) t = (2 * t).array().round() / 2;  // vertices, edges and faces of S on the ray
    if (k % 4 == 1) d = d.array().round();
    if (d == Vec3::Zero()) d = Vec3(1, 0, 0);
    const FT want = oracle_along(S, t, d);
    const double got = pair.along(Pose3(), Pose3(t), d).depth;
    const double w = CGAL::to_double(want) * d.norm();
    if (w == 0) {
      EXPECT_EQ(got, 0) << k;
    } else {
      ++nonzero;
      EXPECT_NEAR(got, w, 1e-14 * w) << "k " << k << " t " << t.transpose() << " d " << d.transpose();
    }
    EXPECT_EQ(pair.overlapping(Pose3(), Pose3(t)), interior(S, K::Point_3(t.x(), t.y(), t.z()))) << k;
  }
  EXPECT_GT(nonzero, 10);
}

// A curved non-convex mesh (a bumpy sphere, 36 triangles) against the L-block: its decomposition
// has rounded cut vertices (pieces within ½ ulp of the mesh), so σ_d is compared to 1e-9; the
// ray parameters still agree to within that on every ray.
TEST(MeshPairNef, CurvedMeshAgainstExactMinkowskiSum) {
  std::mt19937_64 rng(31);
  const Gen pg = bumpy_sphere(rng, 4, 6, 0.3), qg = polycube(l_block());
  Nef NP = nef_of(pg, false), NQ = nef_of(qg, true);
  const Nef S = CGAL::minkowski_sum_3(NP, NQ);
  const Mesh3 mp = Mesh3::validate(to_file(pg, "bumpy"), "bumpy");
  ASSERT_FALSE(mp.convex());
  EXPECT_GT(mp.decomposition().rounded_pieces, 0u);  // 12 of its 12 pieces (this seed)
  const Pair3 pair(Shape3::from_mesh(mp), Shape3::from_mesh(Mesh3::validate(to_file(qg, "L"), "L")));
  std::uniform_real_distribution<double> U(-1, 1);
  int nonzero = 0;
  for (int k = 0; k < 24; ++k) {
    const Vec3 t(-1.5 + 1.5 * U(rng), -1.5 + 1.5 * U(rng), -0.5 + U(rng)), d(U(rng), U(rng), U(rng));
    const double w = CGAL::to_double(oracle_along(S, t, d)) * d.norm();
    const double got = pair.along(Pose3(), Pose3(t), d).depth;
    nonzero += w > 0;
    EXPECT_NEAR(got, w, 1e-9 * std::max(1.0, w)) << "k " << k << " t " << t.transpose() << " d " << d.transpose();
  }
  EXPECT_GT(nonzero, 8);
}

}  // namespace
