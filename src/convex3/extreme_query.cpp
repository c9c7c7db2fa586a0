// Extremal (support) query on the inner DK hierarchy: O'Rourke CGC §7.10.5 / Edelsbrunner–Maurer
// walk (docs/algorithms.md §R4.3), used for Lemma 5.4 of DHS (first contact of a translating
// plane).
//
// Notation: u the query direction; k, j the axes of the smallest and middle |u_i|. Functionals
// Z(w) = u·w, X(w) = w_k, Y(w) = w_j are linearly independent (det = ±u_i, i the largest axis).
// Symbolic perturbation: maximise Z_ε = Z + εX + ε²Y (lexicographic key (Z, X, Y): a strict
// total order on distinct points), and project along the kernel of (X_ε, Z_ε) with
// X_ε = X − εZ. The projected polygon then has a unique top vertex m and no two vertices project
// to one point, and the sign of the projected cross product of two edge vectors w1, w2 is the
// lexicographic sign of (X1 Z2 − X2 Z1, X1 Y2 − X2 Y1, Y1 Z2 − Y2 Z1) — zero only for parallel
// vectors, which cannot occur at a vertex of a strictly convex polytope.
// Walk: at every level keep m and the two silhouette edges (m, l), (m, r) of the projection.
// Going one level finer, the new top is m or a parent of (l, m) or (m, r), and the new
// silhouette edges are among those parents' edges at m (O'Rourke Lemma 7.10.3); a new top is a
// removed vertex of degree <= 8 whose edges are scanned. O(1) per level, O(log n) total.
#include "convex3/polytope_data.hpp"

#include "geometry/exact.hpp"

#include <cassert>
#include <cmath>

namespace pendepth {

using convex3::DKLevel;

namespace {

struct Frame {
  Vec3 u;
  int k, j;
  explicit Frame(const Vec3& dir) : u(dir) {
    int a[3] = {0, 1, 2};
    for (int s = 0; s < 3; ++s)  // sort axes by |u_i| ascending, index order on ties
      for (int t = s + 1; t < 3; ++t)
        if (std::abs(u[a[t]]) < std::abs(u[a[s]])) std::swap(a[s], a[t]);
    k = a[0], j = a[1];
  }
  // Sign of key(p) - key(q), key = (u·p, p_k, p_j) lexicographically.
  int compare(const Vec3& p, const Vec3& q) const {
    int s = predicates::dot3_sign(u, p, q);
    if (s != 0) return s;
    if (p[k] != q[k]) return p[k] > q[k] ? 1 : -1;
    if (p[j] != q[j]) return p[j] > q[j] ? 1 : -1;
    return 0;
  }
  // Sign of the projected cross product of w1 = c1 - m and w2 = c2 - m (> 0: w2 is CCW of w1).
  int turn(const Vec3& m, const Vec3& c1, const Vec3& c2) const {
    auto X = [&](auto L, const Vec3& c) { return L(c[k]) - L(m[k]); };
    auto Y = [&](auto L, const Vec3& c) { return L(c[j]) - L(m[j]); };
    auto Z = [&](auto L, const Vec3& c) {
      return L(u.x()) * (L(c.x()) - L(m.x())) + L(u.y()) * (L(c.y()) - L(m.y())) + L(u.z()) * (L(c.z()) - L(m.z()));
    };
    int s = exact::exact_sign([&](auto L) { return X(L, c1) * Z(L, c2) - X(L, c2) * Z(L, c1); });
    if (s != 0) return s;
    s = exact::exact_sign([&](auto L) { return X(L, c1) * Y(L, c2) - X(L, c2) * Y(L, c1); });
    if (s != 0) return s;
    return exact::exact_sign([&](auto L) { return Y(L, c1) * Z(L, c2) - Y(L, c2) * Z(L, c1); });
  }
};

}  // namespace

int convex3::support_brute(const ConvexPolytope& P, const Vec3& u) {
  const auto& V = data_of(P).v;
  Frame fr(u);
  int best = 0;
  for (int i = 1; i < static_cast<int>(V.size()); ++i)
    if (fr.compare(V[i], V[best]) > 0) best = i;
  return best;
}

int ConvexPolytope::support(const Vec3& u) const {
  const auto& V = d_->v;
  const auto& levels = d_->levels;
  Frame fr(u);
  // Among half-edges from m, the right silhouette edge is the most counter-clockwise projected
  // direction (all directions point into the open lower half-plane), the left the most clockwise.
  int m = -1, hl = -1, hr = -1;
  auto pick = [&](const DKLevel& L, const int* cand, int nc) {
    hl = hr = cand[0];
    for (int c = 1; c < nc; ++c) {
      const Vec3& w = V[L.target(cand[c])];
      if (fr.turn(V[m], V[L.target(hr)], w) > 0) hr = cand[c];
      if (fr.turn(V[m], V[L.target(hl)], w) < 0) hl = cand[c];
    }
  };
  auto scan_around = [&](const DKLevel& L, int h0) {  // all out-edges of origin(h0)
    int cand[64];
    int nc = 0;
    std::vector<int> big;
    int h = h0;
    do {
      if (nc < 64) cand[nc++] = h;
      else big.push_back(h);
      h = L.ccw(h);
    } while (h != h0);
    if (big.empty()) return pick(L, cand, nc);
    big.insert(big.begin(), cand, cand + nc);
    pick(L, big.data(), static_cast<int>(big.size()));
  };

  const DKLevel& top = levels.back();
  m = top.verts[0];
  for (int v : top.verts)
    if (fr.compare(V[v], V[m]) > 0) m = v;
  for (int h = 0; h < static_cast<int>(top.fv.size()); ++h)
    if (top.fv[h] == m) { scan_around(top, h); break; }

  for (int lev = static_cast<int>(levels.size()) - 2; lev >= 0; --lev) {
    const DKLevel& C = levels[lev + 1];
    const DKLevel& L = levels[lev];
    int left[3], right[3], nl = 0, nr = 0;
    auto expand = [&](int h, int* out, int& no) {
      int g = C.down[h];
      out[no++] = g;
      if (L.target(g) == C.target(h)) {  // same edge: its two apexes at the finer level
        out[no++] = L.ccw(g);
        out[no++] = L.cw(g);
      }
    };
    expand(hl, left, nl);
    expand(hr, right, nr);
    int best = -1;
    for (int c = 0; c < nl + nr; ++c) {
      int h = c < nl ? left[c] : right[c - nl];
      int w = L.target(h);
      if (fr.compare(V[w], V[best < 0 ? m : L.target(best)]) > 0) best = h;
    }
    if (best >= 0) {  // new top: a removed vertex of degree <= 8
      m = L.target(best);
      scan_around(L, L.twin[best]);
    } else {
      pick(L, left, nl);
      int keep_l = hl;
      pick(L, right, nr);
      hl = keep_l;
    }
  }
  return m;
}

}  // namespace pendepth
