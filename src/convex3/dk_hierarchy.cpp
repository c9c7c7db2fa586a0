// Inner Dobkin–Kirkpatrick hierarchy (DHS §5.1, Fact 5.1; Dobkin–Kirkpatrick 1990;
// docs/algorithms.md §R4.2).
//
// Level i+1 = conv(V_i \ R_i) where R_i is an independent set of vertices of degree <= 8 in
// level i, chosen greedily lowest degree first. Four affinely independent vertices are protected
// so that every level stays a 3-polytope (a bipyramid would otherwise lose both apexes and
// collapse to a flat polygon). The hole left by v ∈ R_i is retriangulated by an O(k³) DP over
// triangulations of its link polygon a_0..a_{k-1} that accepts triangle (a_i, a_m, a_j) only
// if every other link vertex lies on or below its plane (exact orient3d) — this survives flat
// (coplanar) links, where an arbitrary hull triangulation need not contain the link edges.
// Every edge of level i+1 keeps a `down` link to level i (its own copy, or origin -> v for a
// diagonal created in the hole of v: the parent pointer of DHS §5.1 item 1).
// Stops when at most kTopSize vertices remain or nothing can be removed. In practice about a
// quarter of the vertices disappear per level (docs/algorithms.md §R4.2), so there are about
// 2 log2 n levels; O(n log n) time (the twin arrays are rebuilt by sorting per level), O(n) memory
// (levels shrink geometrically).
#include "convex3/cap_triangulation.hpp"
#include "convex3/polytope_data.hpp"

#include <algorithm>
#include <cassert>

namespace pendepth::convex3 {

namespace {
constexpr std::size_t kTopSize = 12;
}  // namespace

void build_dk_hierarchy(PolytopeData& d) {
  const std::vector<Vec3>& P = d.v;
  const int n = static_cast<int>(P.size());
  {  // protected tetrahedron
    int a = 0, b = 1, c = -1, e = -1;
    for (int i = 2; i < n && c < 0; ++i)
      if (!predicates::collinear3(P[a], P[b], P[i])) c = i;
    for (int i = 2; i < n && e < 0; ++i)
      if (i != c && predicates::orient3d(P[a], P[b], P[c], P[i]) != 0) e = i;
    assert(c >= 0 && e >= 0);
    d.protected_tet = {a, b, c, e};
  }
  std::vector<char> prot(n, 0), marked(n, 0), removed(n, 0);
  for (int v : d.protected_tet) prot[v] = 1;
  std::vector<int> out(n, -1), deg(n, 0);

  while (d.levels.back().verts.size() > kTopSize) {
    const DKLevel& L = d.levels.back();
    const int H = static_cast<int>(L.fv.size());
    for (int v : L.verts) deg[v] = 0, marked[v] = 0;
    for (int h = 0; h < H; ++h) ++deg[L.fv[h]], out[L.fv[h]] = h;
    // Greedy independent set, lowest degree first (counting sort by degree <= 8).
    std::vector<int> R;
    for (int dg = 3; dg <= kMaxRemovedDegree; ++dg)
      for (int v : L.verts) {
        if (deg[v] != dg || prot[v] || marked[v]) continue;
        R.push_back(v);
        marked[v] = 1;
        int h = out[v];
        do { marked[L.target(h)] = 1; h = L.ccw(h); } while (h != out[v]);
      }
    if (R.empty()) break;
    for (int v : R) removed[v] = 1;

    DKLevel N;
    // Kept triangles keep their half-edges as `down` links.
    for (int f = 0; 3 * f < H; ++f) {
      if (removed[L.fv[3 * f]] || removed[L.fv[3 * f + 1]] || removed[L.fv[3 * f + 2]]) continue;
      for (int k = 0; k < 3; ++k) {
        N.fv.push_back(L.fv[3 * f + k]);
        N.down.push_back(3 * f + k);
      }
    }
    std::vector<int> link, spoke;
    std::vector<std::array<int, 3>> caps;
    for (int v : R) {
      link.clear(), spoke.clear(), caps.clear();
      int h = out[v];
      do { spoke.push_back(h); link.push_back(L.target(h)); h = L.ccw(h); } while (h != out[v]);
      bool ok = cap_triangulation(
          static_cast<int>(link.size()),
          [&](int i, int m, int j, int t) {
            return predicates::orient3d(P[link[i]], P[link[m]], P[link[j]], P[link[t]]) > 0;
          },
          caps);
      assert(ok && "no convex retriangulation of a hole");
      (void)ok;
      const int k = static_cast<int>(link.size());
      for (const auto& t : caps)
        for (int e = 0; e < 3; ++e) {
          int x = t[e], y = t[(e + 1) % 3];
          N.fv.push_back(link[x]);
          // Link edge a_x -> a_{x+1} is the edge opposite v in the old triangle (v, a_x, a_{x+1});
          // a diagonal descends to (a_x -> v), the parent vertex's spoke reversed.
          N.down.push_back(y == (x + 1) % k ? DKLevel::next(spoke[x]) : L.twin[spoke[x]]);
        }
    }
    for (int v : L.verts)
      if (!removed[v]) N.verts.push_back(v);
    bool ok = build_twins(N.fv, N.twin);
    assert(ok && "DK level is not a closed 2-manifold");
    (void)ok;
    d.levels.push_back(std::move(N));
  }
}

}  // namespace pendepth::convex3
