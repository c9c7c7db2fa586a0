// Outer Dobkin–Kirkpatrick hierarchy (DHS §5.1 and Fact 5.1; Dobkin–Kirkpatrick 1990;
// docs/algorithms.md §R4.2, §R4.4): P = P_1 ⊂ P_2 ⊂ … ⊂ P_k, H(P_{i+1}) ⊂ H(P_i), the planes
// dropped from P_i bound an independent set of faces of P_i of degree <= 8, and every vertex of
// P_{i+1} that is not a vertex of P_i records the face of P_i whose removal created it
// (OuterLevel::creator).
//
// Construction = the inner hierarchy of the polar dual about an interior point c (see
// outer_hierarchy.hpp): faces are the TRUE faces of P (coplanar triangles merged), the dual
// surface is the face graph of P with each vertex's face cycle fan-triangulated, and the same
// greedy independent set / O(k³) hole DP as dk_hierarchy.cpp runs on it, with the dual orient3d
// evaluated exactly as a 4×4 determinant of plane coefficients (degree 9 in the input doubles;
// a cached filtered-double value of every plane decides almost all signs).
// Departures from the paper: (1) the top level is not a tetrahedron but a polytope of at most 16
// faces or the protected set (a cube has no four faces bounding a tetrahedron); (2) protected
// faces: for each of the four directions (±1, ±1, ±1) with an even number of minus signs, the
// three faces of a fan triangle of the normal cone of the extreme vertex that contains the
// direction — at most 12 faces whose normals positively span R³, so every level is bounded;
// (3) the hierarchy is built lazily on the first line query (outer_hierarchy()), so shapes that
// never use it pay nothing; every inner level P_i gets its own on demand (DHS §5.1: "each P_i is
// represented by an outer polyhedral hierarchy"), O(|P_i| log |P_i|) each, O(n) for all.
// Cost: O(F_i) per level (twins are carried over from the level below, no sort); levels shrink by
// about a quarter each, so O(n) time after the O(n log n) twin sort of level 0, O(n) memory
// (F <= 2n - 4 faces).
#include "convex3/outer_hierarchy.hpp"

#include "convex3/cap_triangulation.hpp"

#include <algorithm>
#include <cassert>
#include <numeric>
#include <sstream>
#include <type_traits>

namespace pendepth::convex3 {

namespace {

constexpr std::size_t kTopSize = 16;

template <class T>
T det4(const PlaneVal<T>& a, const PlaneVal<T>& b, const PlaneVal<T>& c, const PlaneVal<T>& d) {
  auto col = [](const PlaneVal<T>& p, int j) -> const T& { return j < 3 ? p.n[j] : p.h; };
  auto A = [&](int i, int j) { return col(a, i) * col(b, j) - col(a, j) * col(b, i); };
  auto B = [&](int i, int j) { return col(c, i) * col(d, j) - col(c, j) * col(d, i); };
  return A(0, 1) * B(2, 3) - A(0, 2) * B(1, 3) + A(0, 3) * B(1, 2) + A(1, 2) * B(0, 3) - A(1, 3) * B(0, 2) +
         A(2, 3) * B(0, 1);
}

struct Builder {
  const PolytopeData& d;
  OuterHierarchy& O;

  // orient3d of dual points D_a, D_b, D_c, D_e: sign of det[D_b − D_a, D_c − D_a, D_e − D_a]
  // = −sign det4[(n_i, h_i)] since every h_i > 0.
  int orient(int a, int b, int c, int e) const {
    int s = exact::certified_sign(det4(O.fl[a], O.fl[b], O.fl[c], O.fl[e]));
    if (s == 2)
      s = exact::exact_sign([&](auto L) {
        auto pa = eval_plane(O.face_plane(d.v, a), O.center, L);
        auto pb = eval_plane(O.face_plane(d.v, b), O.center, L);
        auto pc = eval_plane(O.face_plane(d.v, c), O.center, L);
        auto pe = eval_plane(O.face_plane(d.v, e), O.center, L);
        return det4(pa, pb, pc, pe);
      });
    return -s;
  }
};

// Union of triangles across flat-facet diagonals (edges whose two triangles are coplanar).
std::vector<int> true_faces(const std::vector<Vec3>& P, const DKLevel& B, int& count) {
  const int T = static_cast<int>(B.fv.size() / 3);
  std::vector<int> parent(T);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (int h = 0; h < static_cast<int>(B.fv.size()); ++h) {
    int g = B.twin[h];
    if (h < g && predicates::orient3d(P[B.fv[h]], P[B.target(h)], P[B.target(B.next(h))],
                                      P[B.target(B.next(g))]) == 0)
      parent[find(h / 3)] = find(g / 3);
  }
  std::vector<int> id(T, -1), face(T);
  count = 0;
  for (int t = 0; t < T; ++t) {
    int r = find(t);
    if (id[r] < 0) id[r] = count++;
    face[t] = id[r];
  }
  return face;
}

// The faces around the origin of out-half-edge h0, counter-clockwise seen from outside.
void faces_around(const DKLevel& B, const std::vector<int>& face_of_tri, int h0, std::vector<int>& out) {
  out.clear();
  int h = h0;
  do {
    int f = face_of_tri[h / 3];
    if (out.empty() || out.back() != f) out.push_back(f);
    h = B.ccw(h);
  } while (h != h0);
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
}

bool strictly_interior(const std::vector<Vec3>& P, const OuterHierarchy& O, const Vec3& c) {
  for (const auto& t : O.face_ref)
    if (predicates::orient3d(P[t[0]], P[t[1]], P[t[2]], c) >= 0) return false;
  return true;
}

int extreme_vertex(const std::vector<Vec3>& P, const std::vector<int>& verts, const Vec3& u) {
  int best = verts[0];
  for (int i : verts)
    if (predicates::dot3_sign(u, P[i], P[best]) > 0) best = i;
  return best;
}

}  // namespace

std::shared_ptr<const OuterHierarchy> build_outer_hierarchy(const PolytopeData& d, std::size_t level) {
  auto out = std::make_shared<OuterHierarchy>();
  OuterHierarchy& O = *out;
  const std::vector<Vec3>& P = d.v;
  const DKLevel& S = d.levels.at(level);  // the surface of the polytope this hierarchy describes
  const std::vector<int>& verts = S.verts;
  int F = 0;
  O.face_of_tri = true_faces(P, S, F);
  O.face_ref.assign(F, {-1, -1, -1});
  for (int t = 0; 3 * t < static_cast<int>(S.fv.size()); ++t)
    if (O.face_ref[O.face_of_tri[t]][0] < 0) O.face_ref[O.face_of_tri[t]] = {S.fv[3 * t], S.fv[3 * t + 1], S.fv[3 * t + 2]};
  std::vector<int> vhe(P.size(), -1);  // an outgoing half-edge per vertex of S
  for (int h = 0; h < static_cast<int>(S.fv.size()); ++h) vhe[S.fv[h]] = h;

  {  // centre: a rounded centroid, accepted only if exactly strictly inside every face (the
     // protected tetrahedron of the inner hierarchy is in every inner level)
    std::vector<Vec3> cand;
    Vec3 s = Vec3::Zero();
    for (int v : d.protected_tet) s += P[v];
    cand.push_back(s / 4);
    Vec3 e = Vec3::Zero();
    for (int a = 0; a < 3; ++a)
      for (double sg : {1.0, -1.0}) {
        Vec3 u = Vec3::Zero();
        u[a] = sg;
        e += P[extreme_vertex(P, verts, u)];
      }
    cand.push_back(e / 6);
    Vec3 m = Vec3::Zero();
    for (int v : verts) m += P[v] / double(verts.size());
    cand.push_back(m);
    bool ok = false;
    for (const Vec3& c : cand)
      if (c.allFinite() && strictly_interior(P, O, c)) {
        O.center = c;
        ok = true;
        break;
      }
    if (!ok) {
      std::ostringstream os;
      os << d.name << ": polytope too thin to hold an interior point in double precision (outer hierarchy)";
      throw InvalidInput(os.str());
    }
  }

  O.fl.resize(F);
  for (int f = 0; f < F; ++f) O.fl[f] = eval_plane(O.face_plane(P, f), O.center, exact::LiftFl{});
  Builder b{d, O};

  // Level 0: the dual surface, one fan per vertex of P.
  OuterLevel base;
  std::vector<int> ring;
  for (int v : verts) {
    faces_around(S, O.face_of_tri, vhe[v], ring);
    assert(ring.size() >= 3);
    for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
      base.dual.fv.insert(base.dual.fv.end(), {ring[0], ring[i], ring[i + 1]});
      O.base_vertex.push_back(v);
    }
  }
  bool ok = build_twins(base.dual.fv, base.dual.twin);
  assert(ok && "dual surface is not a closed 2-manifold");
  (void)ok;
  base.dual.verts.resize(F);
  std::iota(base.dual.verts.begin(), base.dual.verts.end(), 0);
  O.levels.push_back(std::move(base));

  // Protected faces: for u in four positively spanning directions, a fan triangle of the normal
  // cone of the u-extreme vertex that contains u.
  {
    std::vector<char> isprot(F, 0);
    const Vec3 dirs[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    for (const Vec3& u : dirs) {
      int w = extreme_vertex(P, verts, u);
      faces_around(S, O.face_of_tri, vhe[w], ring);
      auto det = [&](int f, int g, int hh, const Vec3* uu) {
        return exact::exact_sign([&](auto L) {
          auto a = eval_plane(O.face_plane(d.v, f), O.center, L);
          auto c = eval_plane(O.face_plane(d.v, g), O.center, L);
          std::remove_reference_t<decltype(a.n[0])> x[3];
          if (uu) {
            for (int i = 0; i < 3; ++i) x[i] = L((*uu)[i]);
          } else {
            auto e = eval_plane(O.face_plane(d.v, hh), O.center, L);
            for (int i = 0; i < 3; ++i) x[i] = e.n[i];
          }
          return x[0] * (a.n[1] * c.n[2] - a.n[2] * c.n[1]) + x[1] * (a.n[2] * c.n[0] - a.n[0] * c.n[2]) +
                 x[2] * (a.n[0] * c.n[1] - a.n[1] * c.n[0]);
        });
      };
      bool found = false;
      for (std::size_t i = 1; i + 1 < ring.size() && !found; ++i) {
        int f0 = ring[0], f1 = ring[i], f2 = ring[i + 1];
        int s = det(f0, f1, f2, nullptr);  // non-zero: three extreme rays of a pointed cone
        if (det(f0, f1, -1, &u) * s >= 0 && det(f1, f2, -1, &u) * s >= 0 && det(f2, f0, -1, &u) * s >= 0) {
          for (int f : {f0, f1, f2})
            if (!isprot[f]) isprot[f] = 1, O.protected_faces.push_back(f);
          found = true;
        }
      }
      assert(found && "extreme direction outside the normal cone of its vertex");
    }
  }

  // Greedy DK levels on the dual.
  O.last_level.assign(F, -1);
  O.last_he.assign(F, -1);
  std::vector<char> prot(F, 0), marked(F, 0), removed(F, 0);
  for (int f : O.protected_faces) prot[f] = 1;
  std::vector<int> outh(F, -1), deg(F, 0);
  while (O.levels.back().dual.verts.size() > kTopSize) {
    const DKLevel& L = O.levels.back().dual;
    const int level = static_cast<int>(O.levels.size()) - 1;
    const int H = static_cast<int>(L.fv.size());
    for (int v : L.verts) deg[v] = 0, marked[v] = 0;
    for (int h = 0; h < H; ++h) ++deg[L.fv[h]], outh[L.fv[h]] = h;
    std::vector<int> R;
    for (int dg = 3; dg <= kMaxRemovedDegree; ++dg)
      for (int v : L.verts) {
        if (deg[v] != dg || prot[v] || marked[v]) continue;
        R.push_back(v);
        marked[v] = 1;
        int h = outh[v];
        do { marked[L.target(h)] = 1; h = L.ccw(h); } while (h != outh[v]);
      }
    if (R.empty()) break;
    for (int v : R) removed[v] = 1, O.last_level[v] = level, O.last_he[v] = outh[v];

    OuterLevel N;
    // newof[old half-edge] = the new half-edge with the same directed edge (kept triangles, and
    // link edges of the holes): twins are then read off the old level in O(1), no sort.
    std::vector<int> newof(H, -1);
    for (int f = 0; 3 * f < H; ++f) {
      if (removed[L.fv[3 * f]] || removed[L.fv[3 * f + 1]] || removed[L.fv[3 * f + 2]]) continue;
      for (int k = 0; k < 3; ++k) {
        newof[3 * f + k] = static_cast<int>(N.dual.fv.size());
        N.dual.fv.push_back(L.fv[3 * f + k]);
        N.dual.down.push_back(3 * f + k);
      }
      N.creator.push_back(-1);
    }
    N.dual.twin.assign(N.dual.fv.size(), -1);
    std::vector<int> link, spoke;
    std::vector<std::array<int, 3>> caps, diag;
    for (int v : R) {
      link.clear(), spoke.clear(), caps.clear();
      int h = outh[v];
      do { spoke.push_back(h); link.push_back(L.target(h)); h = L.ccw(h); } while (h != outh[v]);
      bool capped = cap_triangulation(
          static_cast<int>(link.size()),
          [&](int i, int m, int j, int t) { return b.orient(link[i], link[m], link[j], link[t]) > 0; }, caps);
      assert(capped && "no convex retriangulation of a dual hole");
      (void)capped;
      const int k = static_cast<int>(link.size());
      diag.clear();
      for (const auto& t : caps) {
        for (int e = 0; e < 3; ++e) {
          int x = t[e], y = t[(e + 1) % 3];
          const int nh = static_cast<int>(N.dual.fv.size());
          N.dual.fv.push_back(link[x]);
          N.dual.twin.push_back(-1);
          if (y == (x + 1) % k) {
            N.dual.down.push_back(DKLevel::next(spoke[x]));
            newof[DKLevel::next(spoke[x])] = nh;
          } else {
            N.dual.down.push_back(L.twin[spoke[x]]);
            diag.push_back({link[x], link[y], nh});
          }
        }
        N.creator.push_back(v);
      }
      for (std::size_t a = 0; a < diag.size(); ++a)  // diagonals pair up inside their hole
        for (std::size_t c = a + 1; c < diag.size(); ++c)
          if (diag[a][0] == diag[c][1] && diag[a][1] == diag[c][0])
            N.dual.twin[diag[a][2]] = diag[c][2], N.dual.twin[diag[c][2]] = diag[a][2];
    }
    for (int h = 0; h < static_cast<int>(N.dual.fv.size()); ++h)
      if (N.dual.twin[h] < 0) N.dual.twin[h] = newof[L.twin[N.dual.down[h]]];
    for (int v : L.verts)
      if (!removed[v]) N.dual.verts.push_back(v);
#ifndef NDEBUG
    std::vector<int> check;
    assert(build_twins(N.dual.fv, check) && check == N.dual.twin && "outer level twins");
#endif
    O.levels.push_back(std::move(N));
  }
  const int top = static_cast<int>(O.levels.size()) - 1;
  for (int v : O.levels.back().dual.verts) O.last_level[v] = top;
  return out;
}

const OuterHierarchy& outer_hierarchy(const PolytopeData& d, std::size_t level) {
  std::lock_guard<std::mutex> lock(d.outer_cache.mu);
  auto& v = d.outer_cache.value;
  if (v.size() <= level) v.resize(d.levels.size());
  if (!v[level]) v[level] = build_outer_hierarchy(d, level);
  return *v[level];
}

}  // namespace pendepth::convex3
