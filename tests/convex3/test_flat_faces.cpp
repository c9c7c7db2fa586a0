// The flat-face tables of VertexAdjacency (src/convex3/vertex_adjacency.cpp: face_of, face_tris,
// face_canon), which σ's canonical answer reads (minimum_expand.cpp), against two independent
// computations on every triangle of the standard degenerate and random families plus slivers,
// ±1 ulp boxes and the shared real hulls:
//  * exact geometry: triangles joined across an edge iff the neighbour's far vertex is coplanar
//    (orient3d == 0), union-find; per class the least triangle, the lexicographically least
//    vertex and its boundary neighbours (half-edges whose twin lies in another class);
//  * the flood across non-true edges (PolytopeData::edges) that minimum_expand.cpp ran on every
//    query before the tables existed (the path they replace, kept here as the reference).
// Every field must be equal; the order of face_tris is free except its first entry (the least).
#include <gtest/gtest.h>

#include <pendepth/polytope.hpp>

#include "convex3/polytope_data.hpp"
#include "shapes3.hpp"

#include <algorithm>
#include <cstdio>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace pendepth {
namespace {

using convex3::PolytopeData;
using convex3::VertexAdjacency;

bool lex_less(const PolytopeData& S, int a, int b) {
  const Vec3 &x = S.v[a], &y = S.v[b];
  return x[0] != y[0] ? x[0] < y[0] : x[1] != y[1] ? x[1] < y[1] : x[2] < y[2];
}

// Canonical data of one face from its triangle set: {least tri, least vertex, next, prev}, where
// `in_face(h)` tells whether half-edge h's twin triangle is in the same face.
template <class InFace>
std::array<int, 4> canon_of(const PolytopeData& S, const std::vector<int>& tris, InFace&& in_face) {
  const auto& L = S.levels[0];
  int least_tri = *std::min_element(tris.begin(), tris.end()), least = S.tris[tris[0]][0];
  for (int g : tris)
    for (int x : S.tris[g])
      if (lex_less(S, x, least)) least = x;
  int next = -1, prev = -1, nnext = 0, nprev = 0;
  for (int g : tris)
    for (int k = 0; k < 3; ++k) {
      const int h = 3 * g + k;
      if (in_face(h)) continue;
      if (L.origin(h) == least) next = L.target(h), ++nnext;
      if (L.target(h) == least) prev = L.origin(h), ++nprev;
    }
  EXPECT_EQ(nnext, 1);  // the least vertex is a corner of the face's boundary cycle
  EXPECT_EQ(nprev, 1);
  return {least_tri, least, next, prev};
}

struct Count {
  int shapes = 0, faces = 0, multi = 0;  // multi: faces of more than one triangle
};

void check(const ConvexPolytope& P, const std::string& what, Count& cnt) {
  SCOPED_TRACE(what);
  const PolytopeData& S = convex3::data_of(P);
  const VertexAdjacency& A = convex3::vertex_adjacency(S);
  const auto& L = S.levels[0];
  const int nt = static_cast<int>(S.tris.size());
  ASSERT_EQ(static_cast<int>(A.face_of.size()), nt);
  ++cnt.shapes;

  // Oracle 1: exact coplanarity of neighbouring triangles, union-find.
  std::vector<int> parent(nt);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  auto coplanar_across = [&](int h) {
    const int g = L.twin[h] / 3;
    const auto& t = S.tris[h / 3];
    for (int x : S.tris[g])
      if (predicates::orient3d(S.v[t[0]], S.v[t[1]], S.v[t[2]], S.v[x]) != 0) return false;
    return true;
  };
  for (int h = 0; h < 3 * nt; ++h)
    if (coplanar_across(h)) parent[find(h / 3)] = find(L.twin[h] / 3);
  std::vector<std::vector<int>> cls(nt);
  for (int t = 0; t < nt; ++t) cls[find(t)].push_back(t);

  // Oracle 2: the flood across non-true edges (the former per-query flat_face).
  auto true_edge = [&](int h) {
    const int e = std::min(h, L.twin[h]);
    return std::binary_search(S.edges.begin(), S.edges.end(), e);
  };
  auto flood = [&](int t) {
    std::vector<int> face{t};
    for (std::size_t q = 0; q < face.size(); ++q)
      for (int k = 0; k < 3; ++k) {
        const int h = 3 * face[q] + k;
        if (true_edge(h)) continue;
        const int g = L.twin[h] / 3;
        if (std::find(face.begin(), face.end(), g) == face.end()) face.push_back(g);
      }
    return face;
  };

  for (int t = 0; t < nt; ++t) {
    const int f = A.face_of[t];
    ASSERT_GE(f, 0);
    ASSERT_LT(f + 1, static_cast<int>(A.face_start.size()));
    std::vector<int> mine(A.face_tris.begin() + A.face_start[f], A.face_tris.begin() + A.face_start[f + 1]);
    std::vector<int> geo = cls[find(t)], fl = flood(t);
    EXPECT_EQ(mine.front(), *std::min_element(mine.begin(), mine.end()));
    for (auto* v : {&mine, &geo, &fl}) std::sort(v->begin(), v->end());
    EXPECT_EQ(mine, geo) << "triangle " << t;
    EXPECT_EQ(mine, fl) << "triangle " << t;
    for (int g : mine) EXPECT_EQ(A.face_of[g], f);
    const std::vector<int> in(mine.begin(), mine.end());
    auto in_geo = [&](int h) { return std::binary_search(in.begin(), in.end(), L.twin[h] / 3); };
    auto in_flood = [&](int h) { return !true_edge(h); };
    const auto c = A.face_canon[f];
    EXPECT_EQ(c, canon_of(S, geo, in_geo)) << "triangle " << t;
    EXPECT_EQ(c, canon_of(S, fl, in_flood)) << "triangle " << t;
    if (t == mine.front()) ++cnt.faces, cnt.multi += mine.size() > 1;
  }
}

std::vector<Vec3> ellipsoid(std::mt19937_64& rng, int n, double a, double b, double c) {
  std::normal_distribution<double> g;
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) {
    Vec3 x(g(rng), g(rng), g(rng));
    x.normalize();
    p.emplace_back(a * x[0], b * x[1], c * x[2]);
  }
  return p;
}

TEST(FlatFaces, EqualToCoplanarityAndFlood) {
  Count cnt;
  for (const auto& c : test3::standard_clouds()) check(ConvexPolytope::hull(c.pts, c.name), c.name, cnt);
  std::mt19937_64 rng(20261126);
  // Slivers: ellipsoids flattened to 1e-6 and 1e-12 (near-coplanar, never exactly).
  for (double flat : {1e-6, 1e-12}) check(ConvexPolytope::hull(ellipsoid(rng, 200, 1, 0.7, flat), "sliver"), "sliver", cnt);
  // Integer boxes, and the same with one corner moved by ±1 ulp (a face no longer flat).
  for (int k = 0; k < 8; ++k) {
    std::vector<Vec3> box;
    for (int x : {-3, 5})
      for (int y : {-2, 7})
        for (int z : {-1, 4}) box.emplace_back(x, y, z);
    check(ConvexPolytope::hull(box, "box"), "box", cnt);
    box[k][k % 3] = std::nextafter(box[k][k % 3], k % 2 ? 1e9 : -1e9);
    check(ConvexPolytope::hull(box, "box ulp"), "box ±1 ulp, corner " + std::to_string(k), cnt);
  }
  for (const auto& f : test3::shared_hull_files()) check(ConvexPolytope::hull(read_obj_vertices(f), f), f, cnt);
  EXPECT_GT(cnt.multi, 100);  // the families have many polygonal faces (non-vacuous)
  std::printf("flat faces: %d shapes, %d faces, %d of them polygons\n", cnt.shapes, cnt.faces, cnt.multi);
}

}  // namespace
}  // namespace pendepth
