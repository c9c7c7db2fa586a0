// Outer DK hierarchy (outer_hierarchy.cpp, DHS §5.1 / Fact 5.1), checked with exact predicates:
// true faces are maximal coplanar sets; every outer level is a bounded convex polytope whose
// vertices (meets of three planes) lie on or inside all of its planes; planes only disappear
// going up (H(P_{i+1}) ⊂ H(P_i)); each removed set is independent with degree <= 8; protected
// faces stay; creation pointers name a removed face adjacent to the three planes, with the new
// vertex on or beyond its plane; height <= 3 log2 F + 3 and total size <= 6 × level 0.
#include <gtest/gtest.h>

#include <pendepth/polytope.hpp>

#include "convex3/outer_hierarchy.hpp"
#include "shapes3.hpp"
#include "test_scale.hpp"

#include <cmath>
#include <map>
#include <set>

namespace pendepth {
namespace {

using convex3::DKLevel;
using convex3::OuterHierarchy;

struct Check {
  const ConvexPolytope& P;
  const OuterHierarchy& O;

  template <class L>
  auto plane(int f, L lift) const {
    return convex3::eval_plane(O.face_plane(convex3::data_of(P).v, f), O.center, lift);
  }
  int dsign(int a, int b, int c) const {
    return exact::exact_sign([&](auto L) { return convex3::meet(plane(a, L), plane(b, L), plane(c, L)).D; });
  }
  // side of plane g for the meet of a, b, c
  int side(int g, int a, int b, int c) const {
    int s = exact::exact_sign([&](auto L) {
      return convex3::side_num(plane(g, L), convex3::meet(plane(a, L), plane(b, L), plane(c, L)));
    });
    return s * dsign(a, b, c);
  }
};

void check_hierarchy(const ConvexPolytope& P, const std::string& name, std::mt19937_64& rng, std::size_t level = 0) {
  SCOPED_TRACE(name + " inner level " + std::to_string(level));
  const auto& d = convex3::data_of(P);
  const OuterHierarchy& O = convex3::outer_hierarchy(d, level);
  Check ck{P, O};
  const int F = static_cast<int>(O.face_ref.size());
  if (level == 0) {
    ASSERT_EQ(P.face_count(), static_cast<std::size_t>(F));
  }

  // True faces: every triangle lies in its face's plane; triangles across a true edge do not.
  const auto tris = P.level_triangles(level);
  ASSERT_EQ(O.face_of_tri.size(), tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const auto& r = O.face_ref[O.face_of_tri[t]];
    for (int v : tris[t]) ASSERT_EQ(predicates::orient3d(d.v[r[0]], d.v[r[1]], d.v[r[2]], d.v[v]), 0);
  }
  if (level == 0) {
    for (int h : d.edges) ASSERT_NE(O.face_of_tri[h / 3], O.face_of_tri[d.levels[0].twin[h] / 3]);
  }
  // The centre is strictly inside.
  for (const auto& r : O.face_ref) ASSERT_LT(predicates::orient3d(d.v[r[0]], d.v[r[1]], d.v[r[2]], O.center), 0);

  // Level 0: each dual triangle is the vertex of P it stands for (on all three planes).
  const DKLevel& B = O.levels[0].dual;
  ASSERT_EQ(O.base_vertex.size(), B.fv.size() / 3);
  for (std::size_t t = 0; t < O.base_vertex.size(); ++t) {
    const Vec3& v = d.v[O.base_vertex[t]];
    for (int k = 0; k < 3; ++k) {
      const auto& r = O.face_ref[B.fv[3 * t + k]];
      ASSERT_EQ(predicates::orient3d(d.v[r[0]], d.v[r[1]], d.v[r[2]], v), 0);
    }
  }

  std::size_t total = 0;
  const std::set<int> prot(O.protected_faces.begin(), O.protected_faces.end());
  EXPECT_LE(prot.size(), 12u);
  for (std::size_t j = 0; j < O.levels.size(); ++j) {
    const DKLevel& L = O.levels[j].dual;
    total += L.fv.size() / 3;
    std::vector<char> present(F, 0);
    for (int f : L.verts) present[f] = 1;
    for (int f : prot) ASSERT_TRUE(present[f]) << "protected face removed at level " << j;
    // Closed surface over present faces.
    for (std::size_t h = 0; h < L.fv.size(); ++h) {
      ASSERT_TRUE(present[L.fv[h]]);
      ASSERT_EQ(L.fv[L.twin[h]], L.target(static_cast<int>(h)));
    }
    // Convex and bounded: every vertex is a proper meet, on or inside every plane of the level
    // (all pairs on small levels, a random sample of vertices on big ones).
    const std::size_t T = L.fv.size() / 3;
    const std::size_t budget = pendepth_test::scaled(40000);
    const std::size_t samples = T * L.verts.size() <= budget ? T : budget / L.verts.size() + 1;
    for (std::size_t s = 0; s < samples; ++s) {
      std::size_t t = samples == T ? s : rng() % T;
      int a = L.fv[3 * t], b = L.fv[3 * t + 1], c = L.fv[3 * t + 2];
      ASSERT_NE(ck.dsign(a, b, c), 0) << "level " << j << " vertex " << t << " is not a point";
      for (int g : L.verts)
        if (g != a && g != b && g != c) {
          ASSERT_LE(ck.side(g, a, b, c), 0) << "level " << j << " not convex";
        }
    }
    if (j == 0) continue;
    // Planes only disappear; the removed ones form an independent set of degree <= 8 one level
    // finer, and each created vertex names one of them.
    const DKLevel& C = O.levels[j - 1].dual;
    std::vector<char> below(F, 0);
    for (int f : C.verts) below[f] = 1;
    for (int f : L.verts) ASSERT_TRUE(below[f]);
    std::vector<int> deg(F, 0);
    for (std::size_t h = 0; h < C.fv.size(); ++h) {
      ++deg[C.fv[h]];
      int u = C.fv[h], v = C.target(static_cast<int>(h));
      ASSERT_FALSE(!present[u] && !present[v]) << "removed faces " << u << ", " << v << " adjacent";
    }
    for (int f : C.verts)
      if (!present[f]) {
        ASSERT_LE(deg[f], 8);
        ASSERT_EQ(O.last_level[f], static_cast<int>(j - 1));
      }
    std::set<std::array<int, 3>> finer;
    for (std::size_t t = 0; t < C.fv.size() / 3; ++t) {
      std::array<int, 3> k{C.fv[3 * t], C.fv[3 * t + 1], C.fv[3 * t + 2]};
      std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
      finer.insert(k);
    }
    std::map<int, std::set<int>> removed_nbrs;  // neighbours one level finer of each removed face
    for (std::size_t h = 0; h < C.fv.size(); ++h)
      if (!present[C.fv[h]]) removed_nbrs[C.fv[h]].insert(C.target(static_cast<int>(h)));
    const auto& cr = O.levels[j].creator;
    ASSERT_EQ(cr.size(), T);
    for (std::size_t t = 0; t < T; ++t) {
      std::array<int, 3> k{L.fv[3 * t], L.fv[3 * t + 1], L.fv[3 * t + 2]};
      std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
      if (cr[t] < 0) {
        ASSERT_TRUE(finer.count(k)) << "vertex without creator is not a vertex one level finer";
        continue;
      }
      const int g = cr[t];
      ASSERT_FALSE(present[g]);
      ASSERT_TRUE(below[g]);
      // the three planes are neighbours of g one level finer
      for (int f : k) ASSERT_TRUE(removed_nbrs[g].count(f));
      ASSERT_GE(ck.side(g, k[0], k[1], k[2]), 0) << "created vertex strictly inside its creator's plane";
    }
  }
  const double lg = std::log2(double(F));
  EXPECT_LE(O.levels.size(), static_cast<std::size_t>(3 * lg + 3));
  EXPECT_LE(total, 6 * (B.fv.size() / 3));
  EXPECT_LE(O.levels.back().dual.verts.size(), std::max<std::size_t>(16, prot.size()));
}

TEST(OuterHierarchy, StandardClouds) {
  std::mt19937_64 rng(17);
  for (const auto& c : test3::standard_clouds()) {
    auto P = ConvexPolytope::hull(c.pts, c.name);
    check_hierarchy(P, c.name, rng);
    // DHS §5.1 twin representation: the outer hierarchies of inner levels too.
    for (std::size_t level : {std::size_t(1), P.hierarchy_levels() / 2, P.hierarchy_levels() - 1})
      if (level > 0 && level < P.hierarchy_levels()) check_hierarchy(P, c.name, rng, level);
  }
}

TEST(OuterHierarchy, RandomHulls) {
  std::mt19937_64 rng(18);
  for (int n : {4, 5, 7, 12, 50, 400, 5000}) {
    check_hierarchy(ConvexPolytope::hull(test3::random_sphere(rng, n), "s"), "sphere" + std::to_string(n), rng);
    check_hierarchy(ConvexPolytope::hull(test3::random_ball(rng, 4 * n), "b"), "ball" + std::to_string(n), rng);
  }
  std::vector<Vec3> off = test3::random_sphere(rng, 500);
  for (auto& p : off) p += Vec3(1e6, 1e6, -1e6);
  check_hierarchy(ConvexPolytope::hull(off, "offset"), "offset1e6", rng);
}

TEST(OuterHierarchy, SharedHulls) {
  std::mt19937_64 rng(19);
  for (const auto& f : test3::shared_hull_files())
    check_hierarchy(ConvexPolytope::hull(read_obj_vertices(f), f), f, rng);
}

TEST(OuterHierarchy, LevelsGrowLogarithmically) {
  std::mt19937_64 rng(20);
  for (int n : {1000, pendepth_test::scaled(40000)}) {
    auto P = ConvexPolytope::hull(test3::random_sphere(rng, n), "s");
    const auto& O = convex3::outer_hierarchy(convex3::data_of(P));
    std::size_t total = 0;
    for (const auto& l : O.levels) total += l.dual.fv.size();
    std::cout << "[ stats    ] n = " << n << ": " << O.face_ref.size() << " faces, " << O.levels.size()
              << " outer levels, " << double(total) / double(O.levels[0].dual.fv.size()) << "× level-0 size\n";
    EXPECT_LE(O.levels.size(), static_cast<std::size_t>(3 * std::log2(double(O.face_ref.size())) + 3));
  }
}

}  // namespace
}  // namespace pendepth
