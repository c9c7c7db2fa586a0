// Vertex adjacency of a ConvexPolytope in flat arrays (CSR), built once per shape on first use:
// the neighbours of v in counter-clockwise order (seen from outside) with their half-edge ids
// and the rounded edge vectors, coordinate extents, a cube map of seed
// vertices for support queries, and the flat faces of level 0 with their canonical corner (σ's
// canonical answer). Hill-climbing support queries (minimum_expand.cpp) scan these
// arrays instead of chasing half-edge twins, and start from the cube map when they have no
// better warm start. O(n) time and memory (the cube map has about n cells).
#include "convex3/polytope_data.hpp"

#include <algorithm>
#include <cmath>

namespace pendepth::convex3 {

namespace {

// Rounded steepest ascent of u·v from v (approximate; strictly increasing, so it terminates).
int climb_rounded(const PolytopeData& d, const VertexAdjacency& a, const Vec3& u, int v) {
  double bv = u.dot(d.v[v]);
  for (;;) {
    int next = -1;
    for (int e = a.start[v]; e < a.start[v + 1]; ++e)
      if (double s = u.dot(d.v[a.nbr[e]]); s > bv) bv = s, next = a.nbr[e];
    if (next < 0) return v;
    v = next;
  }
}

Vec3 cell_direction(int face, int i, int j, int k) {
  int ax = face / 2;
  Vec3 u = Vec3::Zero();
  u[ax] = face % 2 ? -1 : 1;
  u[(ax + 1) % 3] = -1 + (2 * i + 1) / double(k);
  u[(ax + 2) % 3] = -1 + (2 * j + 1) / double(k);
  return u;
}

// The flat faces of level 0 (see VertexAdjacency::face_of): triangles in increasing id, each
// unassigned one floods its face across diagonals (level-0 edges that are not true edges). O(n).
void build_flat_faces(const PolytopeData& d, VertexAdjacency& a) {
  const DKLevel& L = d.levels[0];
  const int nt = static_cast<int>(d.tris.size());
  std::vector<char> is_true(L.fv.size(), 0);  // half-edge h lies on a true edge (not a diagonal)
  for (int e : d.edges) is_true[e] = is_true[L.twin[e]] = 1;
  auto true_edge = [&](int h) { return is_true[h] != 0; };
  auto lex_less = [&](int x, int y) {
    const Vec3 &p = d.v[x], &q = d.v[y];
    return p[0] != q[0] ? p[0] < q[0] : p[1] != q[1] ? p[1] < q[1] : p[2] < q[2];
  };
  a.face_of.assign(nt, -1);
  a.face_start.assign(1, 0);
  a.face_tris.clear();
  a.face_canon.clear();
  for (int t = 0; t < nt; ++t) {
    if (a.face_of[t] >= 0) continue;
    const int f = static_cast<int>(a.face_canon.size()), first = static_cast<int>(a.face_tris.size());
    a.face_of[t] = f;
    a.face_tris.push_back(t);
    for (std::size_t q = first; q < a.face_tris.size(); ++q)
      for (int k = 0; k < 3; ++k) {
        const int h = 3 * a.face_tris[q] + k;
        if (true_edge(h)) continue;
        const int g = L.twin[h] / 3;
        if (a.face_of[g] < 0) a.face_of[g] = f, a.face_tris.push_back(g);
      }
    int least = d.tris[t][0];
    for (std::size_t q = first; q < a.face_tris.size(); ++q)
      for (int x : d.tris[a.face_tris[q]])
        if (lex_less(x, least)) least = x;
    int next = -1, prev = -1;
    for (std::size_t q = first; q < a.face_tris.size(); ++q)
      for (int k = 0; k < 3; ++k) {
        const int h = 3 * a.face_tris[q] + k;
        if (!true_edge(h)) continue;
        if (L.origin(h) == least) next = L.target(h);
        if (L.target(h) == least) prev = L.origin(h);
      }
    a.face_canon.push_back({t, least, next, prev});
    a.face_start.push_back(static_cast<int>(a.face_tris.size()));
  }
}

}  // namespace

const VertexAdjacency& vertex_adjacency(const PolytopeData& d) {
  if (d.adjacency_cache.ready.load(std::memory_order_acquire)) return d.adjacency_cache.value;
  std::call_once(d.adjacency_cache.once, [&] {
    VertexAdjacency& a = d.adjacency_cache.value;
    const DKLevel& L = d.levels[0];
    const int n = static_cast<int>(d.v.size());
    a.start.assign(n + 1, 0);
    for (auto* vec : {&a.nbr, &a.he}) vec->clear(), vec->reserve(L.fv.size());
    for (auto* vec : {&a.dx, &a.dy, &a.dz}) vec->clear(), vec->reserve(L.fv.size());
    for (int v = 0; v < n; ++v) {
      a.start[v] = static_cast<int>(a.nbr.size());
      int h0 = d.vertex_he[v], h = h0;
      do {
        int w = L.target(h);
        a.nbr.push_back(w);
        a.he.push_back(h);
        a.dx.push_back(d.v[w].x() - d.v[v].x());
        a.dy.push_back(d.v[w].y() - d.v[v].y());
        a.dz.push_back(d.v[w].z() - d.v[v].z());
        h = L.ccw(h);
      } while (h != h0);
    }
    a.start[n] = static_cast<int>(a.nbr.size());
    Vec3 lo = d.v[0], hi = d.v[0], sum = Vec3::Zero();
    for (const Vec3& p : d.v) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
      sum += p;
    }
    a.extent = hi - lo;
    a.centroid = sum / double(n);
    // About n cells: a seed is then typically at most one or two edges from the maximiser.
    a.cube_k = std::clamp(static_cast<int>(std::ceil(std::sqrt(n / 6.0))), 1, 64);
    const int k = a.cube_k;
    a.cube.assign(6 * k * k, 0);
    int v = 0;
    for (int face = 0; face < 6; ++face)
      for (int i = 0; i < k; ++i)
        for (int jj = 0; jj < k; ++jj) {
          int j = i % 2 ? k - 1 - jj : jj;  // boustrophedon: consecutive cells are neighbours
          v = climb_rounded(d, a, cell_direction(face, i, j, k), v);
          a.cube[(face * k + i) * k + j] = v;
        }
    build_flat_faces(d, a);
    d.adjacency_cache.ready.store(true, std::memory_order_release);
  });
  return d.adjacency_cache.value;
}

}  // namespace pendepth::convex3
