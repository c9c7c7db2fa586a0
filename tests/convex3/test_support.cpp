// Extremal query on the DK hierarchy vs brute force (docs/algorithms.md §R4.3, §R5): integer
// spheres (massive coplanarity, directions along facet normals), prisms, bipyramids, random hulls,
// shared hulls.
#include <gtest/gtest.h>

#include <pendepth/polytope.hpp>

#include "convex3/polytope_data.hpp"
#include "shapes3.hpp"

namespace pendepth {
namespace {

std::vector<Vec3> directions(const ConvexPolytope& P, std::mt19937_64& rng, int count) {
  std::vector<Vec3> d;
  for (int a = 0; a < 3; ++a)
    for (double s : {1.0, -1.0}) {
      Vec3 e = Vec3::Zero();
      e[a] = s;
      d.push_back(e);
    }
  std::uniform_int_distribution<int> small(-3, 3);
  std::normal_distribution<double> g;
  while (static_cast<int>(d.size()) < count) {
    int kind = static_cast<int>(d.size()) % 3;
    Vec3 u;
    if (kind == 0) u = Vec3(small(rng), small(rng), small(rng));  // ties with integer shapes
    else if (kind == 1) u = Vec3(g(rng), g(rng), g(rng));
    else {  // a facet normal (exact for small integer coordinates): whole facets tie
      auto t = P.triangles()[rng() % P.triangles().size()];
      u = (P[t[1]] - P[t[0]]).cross(P[t[2]] - P[t[0]]);
    }
    if (u != Vec3::Zero()) d.push_back(u);
  }
  return d;
}

void check_support(const ConvexPolytope& P, const std::string& name, int count, std::mt19937_64& rng) {
  SCOPED_TRACE(name);
  int mismatches = 0;
  for (const Vec3& u : directions(P, rng, count)) {
    int m = P.support(u), b = convex3::support_brute(P, u);
    if (m != b) ++mismatches;
    // Exactly maximal: no vertex strictly better.
    for (std::size_t w = 0; w < P.size(); ++w)
      if (predicates::dot3_sign(u, P[w], P[m]) > 0) {
        ADD_FAILURE() << "not extreme for u = " << u.transpose();
        return;
      }
  }
  EXPECT_EQ(mismatches, 0);  // same documented tie-break as brute force
}

TEST(Support, StandardClouds) {
  std::mt19937_64 rng(99);
  for (const auto& c : test3::standard_clouds()) {
    auto P = ConvexPolytope::hull(c.pts, c.name);
    check_support(P, c.name, P.size() > 1000 ? 150 : 400, rng);
  }
}

TEST(Support, SharedHulls) {
  std::mt19937_64 rng(5);
  for (const auto& f : test3::shared_hull_files()) {
    auto P = ConvexPolytope::hull(read_obj_vertices(f), f);
    check_support(P, f, 200, rng);
  }
}

TEST(Support, LargeOffsetAndTinyScale) {
  std::mt19937_64 rng(11);
  auto pts = test3::random_sphere(rng, 300, 1e-3);
  for (auto& p : pts) p += Vec3(1e6, 2e6, -3e6);
  auto P = ConvexPolytope::hull(pts, "offset");
  check_support(P, "offset", 300, rng);
}

}  // namespace
}  // namespace pendepth
