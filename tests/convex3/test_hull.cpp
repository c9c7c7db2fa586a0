// ConvexPolytope::hull: normal form (strictly convex, triangulated, outward CCW, closed
// 2-manifold), errors, OBJ reading, and the DK hierarchy's structural invariants.
#include <gtest/gtest.h>

#include <pendepth/polytope.hpp>

#include "shapes3.hpp"

#include <fstream>
#include <set>

namespace pendepth {
namespace {

using predicates::orient3d;
using test3::NamedCloud;

// Every point of `pts` lies on or below every triangle's plane (exact).
void expect_contains(const std::vector<Vec3>& V, const std::vector<std::array<int, 3>>& T,
                     const std::vector<Vec3>& pts, const std::string& what) {
  for (const auto& t : T)
    for (std::size_t i = 0; i < pts.size(); ++i)
      ASSERT_LE(orient3d(V[t[0]], V[t[1]], V[t[2]], pts[i]), 0) << what << " point " << i;
}

// Exact local test that v is a proper extreme point: its incident triangles span >= 3 planes.
// Independent of the implementation's test: compare the normals' directions via cross products.
bool is_proper_vertex(const ConvexPolytope& P, int v) {
  std::vector<Vec3> normals;
  for (const auto& t : P.triangles())
    if (t[0] == v || t[1] == v || t[2] == v) {
      const Vec3 &a = P[t[0]], &b = P[t[1]], &c = P[t[2]];
      normals.push_back((b - a).cross(c - a).normalized());
    }
  // Three normals pairwise at angle > 1e-9 rad count as distinct planes; shapes in these tests
  // have well-separated facet planes, so this float check is unambiguous there.
  std::vector<Vec3> distinct;
  for (const auto& n : normals) {
    bool seen = false;
    for (const auto& m : distinct) seen |= (n - m).norm() < 1e-9;
    if (!seen) distinct.push_back(n);
  }
  return distinct.size() >= 3;
}

void check_polytope(const ConvexPolytope& P, const std::vector<Vec3>& input, const std::string& name,
                    bool well_separated_planes = true) {
  SCOPED_TRACE(name);
  std::vector<Vec3> V(P.vertices().begin(), P.vertices().end());
  std::vector<std::array<int, 3>> T(P.triangles().begin(), P.triangles().end());
  // Closed 2-manifold, Euler characteristic 2.
  const int F = static_cast<int>(T.size());
  ASSERT_EQ(F, 2 * static_cast<int>(V.size()) - 4);
  for (int h = 0; h < 3 * F; ++h) {
    int g = P.twin(h);
    ASSERT_EQ(P.twin(g), h);
    ASSERT_EQ(T[h / 3][h % 3], T[g / 3][(g % 3 + 1) % 3]);
  }
  // Outward orientation: positive volume.
  double vol = 0;
  for (const auto& t : T) vol += (V[t[0]] - V[0]).dot((V[t[1]] - V[0]).cross(V[t[2]] - V[0]));
  EXPECT_GT(vol, 0);
  // Convex and containing the input (exact); vertices are input points.
  if (V.size() * input.size() < 4'000'000) expect_contains(V, T, input, name);
  for (std::size_t i = 0; i < V.size(); ++i) ASSERT_EQ(V[i], input[P.input_index(i)]);
  // No triangle is degenerate; every vertex is a proper extreme point.
  for (const auto& t : T) ASSERT_FALSE(predicates::collinear3(V[t[0]], V[t[1]], V[t[2]]));
  if (V.size() <= 3000 && well_separated_planes)
    for (int v = 0; v < static_cast<int>(V.size()); ++v) ASSERT_TRUE(is_proper_vertex(P, v)) << "vertex " << v;
}

TEST(Hull, StandardCloudsAreNormalForm) {
  for (const NamedCloud& c : test3::standard_clouds()) {
    auto P = ConvexPolytope::hull(c.pts, c.name);
    check_polytope(P, c.pts, c.name);
  }
}

TEST(Hull, AnalyticVertexCounts) {
  EXPECT_EQ(ConvexPolytope::hull(test3::grid(5)).size(), 8u);  // the cube's corners only
  for (int N : {25, 50, 65, 325, 1105})                           // cospherical: all extreme
    EXPECT_EQ(ConvexPolytope::hull(test3::integer_sphere(N)).size(), test3::integer_sphere(N).size());
  for (int N : {25, 325, 5525}) {
    EXPECT_EQ(ConvexPolytope::hull(test3::prism(N)).size(), 2 * test3::integer_circle(N).size());
    EXPECT_EQ(ConvexPolytope::hull(test3::bipyramid(N)).size(), test3::integer_circle(N).size() + 2);
  }
  // Octahedron with points on its edges and face centres: 6 vertices remain.
  std::vector<Vec3> oct{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1},
                        {0.5, 0.5, 0}, {0.25, 0.25, 0.5}, {0, 0, 0}, {0, -0.5, 0.5}};
  EXPECT_EQ(ConvexPolytope::hull(oct).size(), 6u);
}

TEST(Hull, DuplicatesAndOffsets) {
  std::mt19937_64 rng(7);
  auto pts = test3::random_sphere(rng, 200);
  auto dup = pts;
  dup.insert(dup.end(), pts.begin(), pts.end());
  for (auto& p : dup) p += Vec3(1e6, -1e6, 1e6);
  auto P = ConvexPolytope::hull(dup, "dup");
  check_polytope(P, dup, "dup+offset");
  EXPECT_LE(P.size(), 200u);
}

TEST(Hull, NearlyCoplanarFacets) {
  // A square pyramid whose apex is lifted by 1 ulp-scale amounts above the base plane's
  // extension: exact orient3d must still see every point as a vertex or not.
  std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1},
                      {0.5, -1e-300, 0}, {0.5, 1e-17, 0}, {0.5, 0, 0}};
  auto P = ConvexPolytope::hull(p, "nearflat");
  check_polytope(P, p, "nearflat", false);
  // (0.5, -1e-300, 0) is strictly outside the base edge: a vertex; (0.5, 0, 0) is on the edge.
  std::set<std::size_t> in;
  for (std::size_t i = 0; i < P.size(); ++i) in.insert(P.input_index(i));
  EXPECT_TRUE(in.count(5));
  EXPECT_FALSE(in.count(7));
  EXPECT_FALSE(in.count(6));
}

TEST(Hull, InvalidInputMessages) {
  auto msg = [](std::vector<Vec3> p) {
    try {
      ConvexPolytope::hull(p, "shapeA");
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("no throw");
  };
  EXPECT_NE(msg({}).find("shapeA: no points"), std::string::npos);
  EXPECT_NE(msg({{1, 2, 3}, {1, 2, 3}}).find("coincide"), std::string::npos);
  EXPECT_NE(msg({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}).find("collinear"), std::string::npos);
  EXPECT_NE(msg({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {5, 7, 0}}).find("coplanar"), std::string::npos);
  EXPECT_NE(msg({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).find("coplanar"), std::string::npos);
  EXPECT_NE(msg({{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}, {0, 0, 1}}).find("point 2 has a non-finite"),
            std::string::npos);
  EXPECT_NE(msg({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, INFINITY}}).find("point 3"), std::string::npos);
}

TEST(Hull, SharedObjHulls) {
  auto files = test3::shared_hull_files();
  ASSERT_EQ(files.size(), 60u);
  std::size_t dropped = 0;
  for (const auto& f : files) {
    auto pts = read_obj_vertices(f);
    auto P = ConvexPolytope::hull(pts, f);
    check_polytope(P, pts, f);
    dropped += pts.size() - P.size();
  }
  EXPECT_GT(dropped, 0u);  // the data README: some points are interior or on facets
}

TEST(MeshIo, Errors) {
  EXPECT_THROW(read_obj_vertices("/nonexistent/file.obj"), InvalidInput);
  auto tmp = std::filesystem::temp_directory_path() / "pendepth_test_bad.obj";
  {
    std::ofstream o(tmp);
    o << "# comment\nv 1 2 3\nv 1 two 3\n";
  }
  try {
    read_obj_vertices(tmp.string());
    ADD_FAILURE() << "no throw";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(":3: malformed"), std::string::npos) << e.what();
  }
  {
    std::ofstream o(tmp);
    o << "f 1 2 3\n";
  }
  EXPECT_THROW(read_obj_vertices(tmp.string()), InvalidInput);
  std::filesystem::remove(tmp);
}

TEST(DKHierarchy, LevelsAreNestedConvexAndShrink) {
  for (const NamedCloud& c : test3::standard_clouds()) {
    SCOPED_TRACE(c.name);
    auto P = ConvexPolytope::hull(c.pts, c.name);
    auto sizes = P.level_sizes();
    std::size_t total = 0;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      total += sizes[i];
      if (i > 0) EXPECT_LT(sizes[i], sizes[i - 1]);
      auto T = P.level_triangles(i);
      EXPECT_EQ(T.size(), 2 * sizes[i] - 4);
      std::set<int> vs;
      for (const auto& t : T) vs.insert(t.begin(), t.end());
      ASSERT_EQ(vs.size(), sizes[i]);
      if (sizes[i] <= 600) {  // convex: every level vertex on/below every level triangle
        std::vector<Vec3> lv;
        for (int v : vs) lv.push_back(P[v]);
        expect_contains(std::vector<Vec3>(P.vertices().begin(), P.vertices().end()), T, lv, "level");
      }
    }
    EXPECT_LE(sizes.back(), 12u);
    EXPECT_LE(total, 5 * P.size());  // O(n) memory
    EXPECT_LE(P.hierarchy_levels(), 3 * std::log2(double(P.size())) + 2);
  }
}

}  // namespace
}  // namespace pendepth
