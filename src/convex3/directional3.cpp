// σ_d of two convex polytopes by Algorithm Compute-Depth-3D (DHS §5.2, Phase 1 / Phase 2),
// descending the inner DK hierarchies of P and Q simultaneously (DHS §5.1; docs/algorithms.md §R4).
//
// Notation: everything lives in P's frame; Q' = R Q + t (RelativePose semantics: exact for the
// double R and t); M_i = P_i ⊕ (−Q'_i) for the hierarchy levels (M_0 = M); the query line is
// ℓ = {o + t·d}. X denotes the P side, Y the Q side of a pair (X, Y) of convex polytopes.
// T(X, Y) = the LAST parameter t with X ∩ (Y + t·d) ≠ ∅ ("last contact" = exit of ℓ from
// X ⊕ (−Y)). σ_d = T(P, Q')·|d| when 0 ∈ int M, else 0.
//
// The descent (DHS Phase 2): at level i we know T_i = T(P_i, Q_i) and the exit facet of M_i,
// whose plane H separates P_i from Q_i + T_i·d. Going to level i−1, at most ONE vertex w of
// P_{i−1} lies strictly beyond H (the vertices beyond H are removed vertices, which are
// independent, and induce a connected subgraph by the simplex argument) and P_{i−1} ∩ H⁺ lies
// in its cap C = conv(w ∪ link(w)) (every vertex of P_{i−1} on H is adjacent to w); same for Q
// with a cap D. Every contact after T_i involves C or D (DHS's P'_{i−1}, Q'_{i−1}), so
//     T_{i−1} = max(T_i, T(C, Q_{i−1}), T(P_{i−1}, D))                      (DHS step 2B/2C)
// and the new separating plane is the exit facet of the winning term.
// DHS Phase 1 (P_i, Q_i apart) is the state "ℓ misses M_i": we keep the tangent plane through ℓ
// that touches M_i (the most clockwise vertex of M_i seen around ℓ); caps beyond it are found the
// same way, and the new tangent is the most clockwise of the old one and the two sub-results.
//
// DEPARTURES from DHS, and why:
//  * Corollary 5.5 (σ_d of a constant-size polytope against a hierarchy in O(log n)) is done
//    by the same descent with the constant side fixed (a nested Compute-Depth-3D whose inner
//    steps are constant×constant problems solved by brute force over the facet normals of the
//    tiny Minkowski sum), instead of DHS's ray/line/plane queries (Lemmas 5.2/5.3) on an OUTER
//    hierarchy. No outer hierarchy is needed, so none is built.
//  * Lemma 5.4 (plane contact) is the DK walk of extreme_query.cpp (O'Rourke's L/R walk, here
//    with exact, symbolically perturbed functionals) kept alive along the descent: continued
//    one level (O(1)) while the separating plane is unchanged, restarted from the new support
//    vertex in O(its degree) when the plane changed, walked afresh from the top (O(log)) only
//    if that vertex has degree > 48. The paper's per-level O(log) queries would cost a log more.
//  * DHS's choice of separating planes is not unique in degenerate positions (contacts on edges
//    or vertices of M_i, ℓ parallel to faces, Phase 1 planes with the wrong orientation). We
//    make the line generic by Simulation of Simplicity: o = δ·e_x + δ²·e_y + δ³·e_z and
//    d_ε = d + ε·e₁ + ε²·e₂ (e₁, e₂ the axes other than d's largest), δ ≪ ε ≪ 1. Then every exit
//    point lies in the relative interior of a facet, the separating plane is unique, and "T
//    unchanged" implies "no cap". The answer is read at δ = ε = 0: the exit facet u is a
//    supporting plane of M with u·d > 0 and σ_d = h_M(u)/(u·d̂) exactly (few ulps); 0 ∈ int M
//    iff the exit facets of ℓ in both orientations have h_M(u) > 0.
//  * Overlap is usually certified without the second (−d) descent: the top levels are inner
//    polytopes, so 0 ∈ int (P_top ⊕ (−Q'_top)) — the criterion above applied to the top pair,
//    whose brute-force solve yields the entry facet for free — implies 0 ∈ int M. Only when that
//    fails does the −d descent run.
//  * Caps and top levels are constant-size polytopes that depend only on the shape (and, for
//    their cached vectors, on R; for their points, on the pose). They are kept in a per-thread
//    cache across queries, keyed by the shape's address and validated against a copy of
//    everything they were built from (the apex's star: vertex and half-edge ids, and the
//    coordinates), so a freed shape replaced at the same address is never served stale data.
//    (A per-shape table would avoid the validation; PolytopeData has no slot for it.)
//  * The contact point (witness) is a point of F_P(u) ∩ (F_Q'(u) + v) with both support faces
//    collected exactly, so face–face and parallel-edge contacts report a point of both shapes.
// Every combinatorial decision is the exact sign of a polynomial in the input doubles
// (geometry/exact.hpp); formal quantities are compared coefficient by coefficient. Cached
// doubles only ever serve as filters with rigorous error bounds (per-pair Fl bounds, or one
// static bound per constant×constant subproblem for the edge-pair tests).
//
// Complexity per query (n, m vertices; the hierarchies have O(log n), O(log m) levels): the main
// descent has O(log n + log m) steps, each nesting two descents of O(log n + log m) steps with
// O(1) work (a constant×constant subproblem, a walk step) — O(log n · log m) as in DHS Theorem
// 5.6 for n ≈ m; a walk restart at a vertex of degree > 48 adds O(log) (worst case O(log³)).
// A second descent (−d) decides overlap when the top pair does not. The top levels (≤ 12
// vertices unless the DK build stops early) are solved by brute force, O(size²).
// Most of the cost is the constant×constant subproblems, then the walks (times and profile in
// docs/benchmarks.md).
#include "convex3/minimum_expand.hpp"
#include "convex3/minkowski_facets.hpp"
#include "convex3/polytope_data.hpp"
#include "geometry/exact.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <optional>
#include <unordered_map>
#include <vector>

namespace pendepth::convex3 {

namespace {

using exact::exact_sign;

template <class T>
using V3 = std::array<T, 3>;

template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// ---------------------------------------------------------------------------------------------
// Input geometry and the symbolically perturbed line.

struct Ctx {
  const PolytopeData& P;
  const PolytopeData& Q;
  const RelativePose& pose;
  Vec3 dv[3];  ///< s·d, s·e₁, s·e₂ (s = ±1: the orientation of the current descent)
  std::size_t candidates = 0;

  template <class Lf>
  V3<decltype(Lf{}(0.0))> lift(Lf L, const Vec3& v) const {
    return {L(v.x()), L(v.y()), L(v.z())};
  }
  template <class Lf>
  auto pvec(Lf L, int a) const { return lift(L, P.v[a]); }
  template <class Lf>
  auto pdiff(Lf L, int a, int b) const {
    const Vec3 &x = P.v[a], &y = P.v[b];
    return V3<decltype(L(0.0))>{L(x.x()) - L(y.x()), L(x.y()) - L(y.y()), L(x.z()) - L(y.z())};
  }
  // R (q_a − q_b): Q' edge vectors without the translation (no cancellation at large offsets).
  template <class Lf>
  auto qdiff(Lf L, int a, int b) const {
    const Vec3 &x = Q.v[a], &y = Q.v[b];
    V3<decltype(L(0.0))> r;
    for (int i = 0; i < 3; ++i)
      r[i] = L(pose.R(i, 0)) * (L(x.x()) - L(y.x())) + L(pose.R(i, 1)) * (L(x.y()) - L(y.y())) +
             L(pose.R(i, 2)) * (L(x.z()) - L(y.z()));
    return r;
  }
  // P[x] − Q'[y]: a point of M.
  template <class Lf>
  auto mpoint(Lf L, int x, int y) const {
    const Vec3 &p = P.v[x], &q = Q.v[y];
    V3<decltype(L(0.0))> r;
    for (int i = 0; i < 3; ++i)
      r[i] = L(p[i]) - (L(pose.R(i, 0)) * L(q.x()) + L(pose.R(i, 1)) * L(q.y()) + L(pose.R(i, 2)) * L(q.z()) +
                        L(pose.tq[i]) - L(pose.tp[i]));
    return r;
  }
  template <class Lf>
  auto vdiff(Lf L, bool isq, int a, int b) const { return isq ? qdiff(L, a, b) : pdiff(L, a, b); }
  const std::vector<Vec3>& local(bool isq) const { return isq ? Q.v : P.v; }
  const PolytopeData& data(bool isq) const { return isq ? Q : P; }
};

// Lexicographic sign of a formal quantity given by its coefficients in order (from `start`).
template <class Coef>
int formal_sign(int n, Coef coef, int start = 0) {
  for (int k = start; k < n; ++k) {
    int s = exact_sign([&](auto L) { return coef(L, k); });
    if (s != 0) return s;
  }
  return 0;
}

// Fast paths: values cached as exact::Fl (double + certified error bound, valid for the
// expression that produced them); `cert` is their certified sign or 2 (undecided), in which case
// the exact formula is evaluated from scratch.
using exact::Fl;
using FV = V3<Fl>;
inline int cert(const Fl& v) { return exact::certified_sign(v); }
inline FV flv(const Vec3& v) { return {Fl{v.x(), 0}, Fl{v.y(), 0}, Fl{v.z(), 0}}; }
inline FV fl_sub(const Vec3& a, const Vec3& b) { return {Fl{a.x(), 0} - Fl{b.x(), 0}, Fl{a.y(), 0} - Fl{b.y(), 0}, Fl{a.z(), 0} - Fl{b.z(), 0}}; }
// A cached vector reduced to doubles: value, Euclidean norm and a bound on the Euclidean distance
// to the exact vector. dot_sign certifies a dot product's sign with ~10 flops, or returns 2.
struct DV {
  Vec3 v;
  double n = 0, e = 0;
};
inline DV to_dv(const FV& a) {
  DV d;
  d.v = Vec3(a[0].v, a[1].v, a[2].v);
  d.n = d.v.norm() * (1 + 4 * exact::kUnit);
  d.e = (a[0].e + a[1].e + a[2].e) * (1 + 4 * exact::kUnit);  // ‖·‖₂ ≤ ‖·‖₁
  return d;
}
inline int dot_sign(const DV& a, const DV& b) {
  double v = a.v.dot(b.v);
  double bound = (a.n * b.e + a.e * b.n + a.e * b.e + 4 * exact::kUnit * a.n * b.n) * (1 + 8 * exact::kUnit) + exact::kTiny;
  return v > bound ? 1 : v < -bound ? -1 : 2;
}

// Rᵀ u, exactly the functional u·(R q) on Q's local coordinates.
inline FV fl_rt(const Eigen::Matrix3d& R, const FV& u) {
  FV w;
  for (int j = 0; j < 3; ++j) w[j] = Fl{R(0, j), 0} * u[0] + Fl{R(1, j), 0} * u[1] + Fl{R(2, j), 0} * u[2];
  return w;
}

// ---------------------------------------------------------------------------------------------
// Facet candidates of X ⊕ (−Y): (face of X, vertex of Y), (vertex of X, face of Y), (edge, edge).

struct Cand {
  enum Kind { FaceX, FaceY, EdgeEdge } kind = FaceX;
  int x[3] = {-1, -1, -1}, y[3] = {-1, -1, -1};  ///< global P ids / Q ids of the features
  int sgn = 1;                                   ///< orientation of the edge-edge normal
  int xs = -1, ys = -1;                          ///< support vertices: P max of u·x, Q min of u·y'
  int dsign = 0;                                 ///< formal sign of u·d_ε
  Fl n0, dd[3];                                  ///< cached u·(x_s − y'_s) and u·dv[b] (dd[0] always)
  // An out-half-edge of x_s (y_s) at hierarchy level xs_lev (ys_lev): where a walk restarts.
  int xs_he = -1, xs_lev = -1, ys_he = -1, ys_lev = -1;
  bool same(const Cand& o) const {
    return kind == o.kind && sgn == o.sgn && xs == o.xs && ys == o.ys && std::equal(x, x + 3, o.x) &&
           std::equal(y, y + 3, o.y);
  }
};

template <class Lf>
auto cand_u(const Ctx& c, const Cand& k, Lf L) {
  switch (k.kind) {
    case Cand::FaceX: return cross(c.pdiff(L, k.x[1], k.x[0]), c.pdiff(L, k.x[2], k.x[0]));
    case Cand::FaceY: return cross(c.qdiff(L, k.y[2], k.y[0]), c.qdiff(L, k.y[1], k.y[0]));  // −n(Q')
    default: {
      auto u = cross(c.pdiff(L, k.x[1], k.x[0]), c.qdiff(L, k.y[1], k.y[0]));
      if (k.sgn < 0) u = {-u[0], -u[1], -u[2]};
      return u;
    }
  }
}

// Exit parameter along the perturbed line: T = N / D with
//   N = h_M(u) − u·o_δ  (coefficients of δ⁰..δ³: u·(x_s − y'_s), −u_x, −u_y, −u_z)
//   D = u·d_ε           (coefficients of ε⁰..ε²: u·dv[0..2]).
template <class Lf>
auto cand_n(const Ctx& c, const Cand& k, Lf L, int a) {
  auto u = cand_u(c, k, L);
  if (a == 0) return dot(u, c.mpoint(L, k.xs, k.ys));
  return -u[a - 1];
}
template <class Lf>
auto cand_d(const Ctx& c, const Cand& k, Lf L, int b) {
  return dot(cand_u(c, k, L), c.lift(L, c.dv[b]));
}

// Caches N's leading coefficient and D, and sets the formal sign of D = u·d_ε.
void prepare(const Ctx& c, Cand& k, const FV& u, const FV& xs, const FV& ys) {
  k.n0 = dot(u, FV{xs[0] - ys[0], xs[1] - ys[1], xs[2] - ys[2]});  // = the expression of mpoint
  k.dsign = 0;
  for (int b = 0; b < 3 && k.dsign == 0; ++b) {  // u·dv[1], u·dv[2] only when u·d may vanish
    k.dd[b] = dot(u, flv(c.dv[b]));
    int s = cert(k.dd[b]);
    k.dsign = s != 2 ? s : formal_sign(3, [&](auto Lf, int bb) { return cand_d(c, k, Lf, bb); }, b);
  }
}

// Sign of T1 − T2 (formal; monomials δ^a ε^b ordered by (a, b): δ ≪ ε).
int compare_t(const Ctx& c, const Cand& k1, const Cand& k2) {
  if (k1.same(k2)) return 0;
  int s = cert(k1.n0 * k2.dd[0] - k2.n0 * k1.dd[0]);
  if (s == 2 || s == 0)
    s = formal_sign(12, [&](auto L, int ab) {
      int a = ab / 3, b = ab % 3;
      return cand_n(c, k1, L, a) * cand_d(c, k2, L, b) - cand_n(c, k2, L, a) * cand_d(c, k1, L, b);
    }, s == 0 ? 1 : 0);
  return s * k1.dsign * k2.dsign;
}

// Sign of det(d_ε, Z1 − o_δ, Z2 − o_δ) for Z = P[x] − Q'[y]; < 0: Z2 is more clockwise around ℓ.
int compare_turn(const Ctx& c, int x1, int y1, int x2, int y2) {
  if (x1 == x2 && y1 == y2) return 0;
  exact::LiftFl Lf;
  int s = cert(dot(flv(c.dv[0]), cross(c.mpoint(Lf, x1, y1), c.mpoint(Lf, x2, y2))));
  if (s == 1 || s == -1) return s;
  // W[0] = Z, W[k] = −e_k (k = 1..3): coefficient of δ^a is Σ_{a1+a2=a} det(d_b, W1[a1], W2[a2]).
  return formal_sign(21, [&](auto L, int ab) {
    using T = decltype(L(0.0));
    int a = ab / 3, b = ab % 3;
    auto W = [&](int which, int k) -> V3<T> {
      if (k == 0) return which == 1 ? c.mpoint(L, x1, y1) : c.mpoint(L, x2, y2);
      V3<T> e{L(0.0), L(0.0), L(0.0)};
      e[k - 1] = L(-1.0);
      return e;
    };
    auto db = c.lift(L, c.dv[b]);
    T sum = L(0.0);
    for (int a1 = std::max(0, a - 3); a1 <= std::min(3, a); ++a1) sum = sum + dot(db, cross(W(1, a1), W(2, a - a1)));
    return sum;
  });
}

// h(u) > 0 for a candidate's plane: 0 strictly inside its half-space (exact; the cached leading
// coefficient of N first).
bool positive_h(const Ctx& c, const Cand& k) {
  const int s = cert(k.n0);
  return (s == 2 ? exact_sign([&](auto L) { return cand_n(c, k, L, 0); }) : s) > 0;
}

// ---------------------------------------------------------------------------------------------
// Constant-size polytopes (top levels and caps) and the brute-force solver for a pair of them.

struct Small {
  bool isq = false;
  std::vector<int> id;                    ///< global vertex ids
  std::vector<std::array<int, 3>> tri;    ///< local indices, CCW seen from outside
  std::vector<std::array<int, 4>> edge;   ///< local a, b, apex of (a,b)'s triangle, of (b,a)'s
  // Cached in P's frame (see prepare_small): M's candidate normal per triangle (n for X,
  // −n(Q') for Y) and, per edge, b − a, c − a, e − a.
  std::vector<FV> tri_u;
  std::vector<std::array<FV, 3>> edge_v;
  std::vector<std::array<DV, 3>> edge_d;  ///< edge_v reduced to doubles
  std::vector<double> e0x, e0y, e0z;       ///< edge_d[·][0].v by coordinate (the hot loop)
  double e0_n = 0, e0_e = 0, w_n = 0, w_e = 0;  ///< maxima of n, e over edge_d[·][0], [·][1..2]
  std::vector<FV> pt;                     ///< vertices in P's frame (Q': R q + tq − tp)
  std::vector<Vec3> loc;                  ///< vertices in their own (local) frame
  std::vector<double> loc_n;              ///< their Euclidean norms, rounded up
  int lev = -1;         ///< hierarchy level the vertices were taken from
  std::vector<int> he;  ///< per vertex an out-half-edge at that level
  int local_of(int g) const { return static_cast<int>(std::find(id.begin(), id.end(), g) - id.begin()); }
};

// The cached edge and face vectors in P's frame (depend only on R on Q's side, on nothing on P's).
void prepare_vectors(const Ctx& c, Small& s) {
  exact::LiftFl L;
  // Vertex vectors relative to local vertex 0 (rotated once per vertex on Q's side); a
  // difference of two of them is a valid Fl of the exact difference (Fl bounds propagate).
  const int nv = static_cast<int>(s.id.size());
  FV relbuf[64];
  std::vector<FV> relbig(nv > 64 ? nv : 0);
  FV* rel = nv > 64 ? relbig.data() : relbuf;
  for (int a = 0; a < nv; ++a) rel[a] = a == 0 ? FV{} : c.vdiff(L, s.isq, s.id[a], s.id[0]);
  auto dv = [&](int a, int b) {
    if (b == 0) return rel[a];
    return FV{rel[a][0] - rel[b][0], rel[a][1] - rel[b][1], rel[a][2] - rel[b][2]};
  };
  s.tri_u.clear();
  s.edge_v.clear();
  for (const auto& t : s.tri) s.tri_u.push_back(s.isq ? cross(dv(t[2], t[0]), dv(t[1], t[0])) : cross(dv(t[1], t[0]), dv(t[2], t[0])));
  // Per edge: its vector e and the apex tests rewritten by the triple product so that a pair
  // costs two dot products per side: for u = e_X × e_Y,
  //   u·(c − a) = e_Y·((c − a) × e_X)   (X side),   u·(c − a) = e_X·(e_Y × (c − a))   (Y side).
  s.edge_d.clear();
  for (const auto& e : s.edge) {
    FV ev = dv(e[1], e[0]), c1 = dv(e[2], e[0]), c2 = dv(e[3], e[0]);
    if (s.isq) s.edge_v.push_back({ev, cross(ev, c1), cross(ev, c2)});
    else s.edge_v.push_back({ev, cross(c1, ev), cross(c2, ev)});
    const auto& b = s.edge_v.back();
    s.edge_d.push_back({to_dv(b[0]), to_dv(b[1]), to_dv(b[2])});
  }
  s.e0x.clear(), s.e0y.clear(), s.e0z.clear();
  s.e0_n = s.e0_e = s.w_n = s.w_e = 0;
  for (const auto& d : s.edge_d) {
    s.e0x.push_back(d[0].v.x()), s.e0y.push_back(d[0].v.y()), s.e0z.push_back(d[0].v.z());
    s.e0_n = std::max(s.e0_n, d[0].n), s.e0_e = std::max(s.e0_e, d[0].e);
    s.w_n = std::max({s.w_n, d[1].n, d[2].n}), s.w_e = std::max({s.w_e, d[1].e, d[2].e});
  }
  s.loc.clear();
  s.loc_n.clear();
  for (int g : s.id) {
    s.loc.push_back(c.local(s.isq)[g]);
    s.loc_n.push_back(s.loc.back().norm() * (1 + 4 * exact::kUnit));
  }
}

// The vertices in P's frame (depends on the whole relative pose on Q's side).
void prepare_points(const Ctx& c, Small& s) {
  exact::LiftFl L;
  s.pt.clear();
  for (int g : s.id) {
    if (!s.isq) {
      s.pt.push_back(c.pvec(L, g));
    } else {
      const Vec3& q = c.Q.v[g];
      FV r;
      for (int i = 0; i < 3; ++i)
        r[i] = L(c.pose.R(i, 0)) * L(q.x()) + L(c.pose.R(i, 1)) * L(q.y()) + L(c.pose.R(i, 2)) * L(q.z()) +
               L(c.pose.tq[i]) - L(c.pose.tp[i]);
      s.pt.push_back(r);
    }
  }
}

// Edges with their two apexes; diagonals of flat facets are left out (the apex test of an
// edge-edge candidate is only meaningful at a true edge, and flat facets are face candidates).
void finish_small(Small& s, const std::vector<Vec3>& V) {
  const int H = 3 * static_cast<int>(s.tri.size());
  std::vector<int> fv(H), twin(H, -1);
  for (int h = 0; h < H; ++h) fv[h] = s.tri[h / 3][h % 3];
  for (int h = 0; h < H; ++h)  // quadratic twin matching: H <= 3·(2·12 − 4)
    for (int g = h + 1; g < H && twin[h] < 0; ++g)
      if (fv[g] == fv[DKLevel::next(h)] && fv[DKLevel::next(g)] == fv[h]) twin[h] = g, twin[g] = h;
  assert(std::find(twin.begin(), twin.end(), -1) == twin.end() && "constant-size polytope is not closed");
  for (int h = 0; h < H; ++h) {
    if (h > twin[h]) continue;
    std::array<int, 4> e{fv[h], fv[DKLevel::next(h)], fv[DKLevel::next(DKLevel::next(h))],
                         fv[DKLevel::next(DKLevel::next(twin[h]))]};
    if (predicates::orient3d(V[s.id[e[0]]], V[s.id[e[1]]], V[s.id[e[2]]], V[s.id[e[3]]]) != 0) s.edge.push_back(e);
  }
}

Small top_small(const PolytopeData& D, bool isq) {
  const DKLevel& L = D.levels.back();
  Small s;
  s.isq = isq;
  s.id = L.verts;
  auto loc = [&](int g) { return static_cast<int>(std::find(s.id.begin(), s.id.end(), g) - s.id.begin()); };
  for (std::size_t f = 0; 3 * f < L.fv.size(); ++f) s.tri.push_back({loc(L.fv[3 * f]), loc(L.fv[3 * f + 1]), loc(L.fv[3 * f + 2])});
  s.lev = static_cast<int>(D.levels.size()) - 1;
  s.he.assign(s.id.size(), -1);
  for (int h = 0; h < static_cast<int>(L.fv.size()); ++h) s.he[loc(L.fv[h])] = h;
  finish_small(s, D.v);
  return s;
}

// Cap C = conv(w ∪ link(w)) of a vertex w at level `lev` given an out-half-edge h0 of w: the
// star of w (faces of the level, hence of C) closed by the faces of conv(link) that w does not
// see, found by the polygon-triangulation DP of dk_hierarchy.cpp with the opposite validity
// (every other point of C on or below the triangle). (The hole triangulation of the next level
// is the other side of conv(link): it is inside C.)
Small make_cap(const PolytopeData& D, bool isq, int lev, int h0) {
  const DKLevel& L = D.levels[lev];
  Small s;
  s.isq = isq;
  s.id.push_back(L.origin(h0));
  s.lev = lev;
  s.he.push_back(h0);
  int h = h0;
  do {
    s.id.push_back(L.target(h));
    s.he.push_back(L.twin[h]);
    h = L.ccw(h);
  } while (h != h0);
  const int k = static_cast<int>(s.id.size()) - 1;  // link a_x = local x + 1
  for (int x = 0; x < k; ++x) s.tri.push_back({0, x + 1, (x + 1) % k + 1});
  const auto& V = D.v;
  auto P = [&](int x) -> const Vec3& { return V[s.id[x + 1]]; };
  const Vec3& W = V[s.id[0]];
  std::vector<signed char> valid(k * k * k, -1);
  auto is_valid = [&](int i, int m, int j) {  // (a_j, a_m, a_i) has all of w ∪ link on or below it
    signed char& v = valid[(i * k + m) * k + j];
    if (v < 0) {
      v = predicates::orient3d(P(i), P(m), P(j), W) >= 0;
      for (int t = 0; t < k && v; ++t)
        if (t != i && t != m && t != j && predicates::orient3d(P(i), P(m), P(j), P(t)) < 0) v = 0;
    }
    return v == 1;
  };
  std::vector<int> choice(k * k, -1);  // apex of the triangle closing i..j; -2 empty
  for (int len = 1; len < k; ++len)
    for (int i = 0; i + len < k; ++i) {
      int j = i + len;
      int& ch = choice[i * k + j];
      if (len == 1) { ch = -2; continue; }
      for (int m = i + 1; m < j && ch == -1; ++m)
        if (choice[i * k + m] != -1 && choice[m * k + j] != -1 && is_valid(i, m, j)) ch = m;
    }
  assert(choice[k - 1] != -1 && "no convex triangulation of a cap's link");
  std::vector<std::pair<int, int>> todo{{0, k - 1}};
  while (!todo.empty()) {
    auto [i, j] = todo.back();
    todo.pop_back();
    int m = choice[i * k + j];
    if (m < 0) continue;
    s.tri.push_back({j + 1, m + 1, i + 1});  // reversed: the cap's bottom faces away from w
    todo.push_back({i, m});
    todo.push_back({m, j});
  }
  finish_small(s, V);
  return s;
}

// Caps and top levels across queries. A Small is a pure function of its level's local
// structure (the star of the cap's apex, or the top level's triangles) and of those vertices'
// coordinates; its cached vectors of R (Q's side) and its points of (R, tq, tp). Entries are
// keyed by the shape's address and validated against a stored copy of all these inputs, so a
// shape freed and replaced at the same address can never be served stale data. One cache per
// thread; cleared between queries when it grows past kMaxEntries.
struct SmallCache {
  struct Key {
    const PolytopeData* D;
    int lev, v;  ///< v = apex vertex; lev = −1 for the top level
    bool isq;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return std::hash<const void*>()(k.D) ^ (std::size_t(k.lev) * 0x9e3779b97f4a7c15ULL) ^ (std::size_t(k.v) << 1) ^ k.isq;
    }
  };
  struct Entry {
    Small s;
    std::vector<int> ids;     ///< structure the Small was built from
    std::vector<Vec3> xyz;    ///< coordinates of those vertices
    bool vec_ok = false, pt_ok = false;
    Eigen::Matrix3d R;
    Vec3 tq, tp;
  };
  static constexpr std::size_t kMaxEntries = 4096;
  std::unordered_map<Key, Entry, KeyHash> map;
};

SmallCache& small_cache() {
  static thread_local SmallCache cache;
  return cache;
}

// Brings the entry's pose-dependent caches up to date for this query's pose.
const Small& prepared(const Ctx& c, SmallCache::Entry& e) {
  const bool q = e.s.isq;
  if (!e.vec_ok || (q && e.R != c.pose.R)) {
    prepare_vectors(c, e.s);
    e.vec_ok = true, e.pt_ok = false;
    e.R = c.pose.R;
  }
  if (!e.pt_ok || (q && (e.tq != c.pose.tq || e.tp != c.pose.tp))) {
    prepare_points(c, e.s);
    e.pt_ok = true;
    e.tq = c.pose.tq, e.tp = c.pose.tp;
  }
  return e.s;
}

// The top level of one side, from the cache when its structure and coordinates are unchanged.
const Small& cached_top(const Ctx& c, bool isq) {
  const PolytopeData& D = c.data(isq);
  const DKLevel& L = D.levels.back();
  auto& e = small_cache().map[SmallCache::Key{&D, -1, 0, isq}];
  std::vector<int> ids(L.verts);
  ids.insert(ids.end(), L.fv.begin(), L.fv.end());
  bool same = e.ids == ids && e.xyz.size() == L.verts.size();
  for (std::size_t i = 0; same && i < L.verts.size(); ++i) same = e.xyz[i] == D.v[L.verts[i]];
  if (!same) {
    e = SmallCache::Entry{};
    e.s = top_small(D, isq);
    e.ids = std::move(ids);
    for (int v : L.verts) e.xyz.push_back(D.v[v]);
  }
  return prepared(c, e);
}

// The cap of vertex w = origin(h) at level lev: built from w's smallest out-half-edge (so the
// result does not depend on which half-edge the walk arrived by), cached as above.
const Small& cached_cap(const Ctx& c, bool isq, int lev, int h) {
  const PolytopeData& D = c.data(isq);
  const DKLevel& L = D.levels[lev];
  int h0 = h;
  for (int g = L.ccw(h); g != h; g = L.ccw(g)) h0 = std::min(h0, g);
  const int w = L.origin(h0);
  auto& e = small_cache().map[SmallCache::Key{&D, lev, w, isq}];
  // Validated inputs: the link's vertices and the star's half-edge ids (the Small keeps them
  // as walk hints), then the coordinates of w and the link.
  std::vector<int> ids{w};
  int g = h0;
  do {
    ids.push_back(L.target(g));
    g = L.ccw(g);
  } while (g != h0);
  const std::size_t nv = ids.size();
  do {
    ids.push_back(g);
    ids.push_back(L.twin[g]);
    g = L.ccw(g);
  } while (g != h0);
  bool same = e.ids == ids;
  for (std::size_t i = 0; same && i < nv; ++i) same = e.xyz[i] == D.v[ids[i]];
  if (!same) {
    e = SmallCache::Entry{};
    e.s = make_cap(D, isq, lev, h0);
    e.ids = std::move(ids);
    for (std::size_t i = 0; i < nv; ++i) e.xyz.push_back(D.v[e.ids[i]]);
  }
  return prepared(c, e);
}

/// State of a pair (X, Y) at one level: Hit (ℓ meets X ⊕ (−Y); exit facet `cand`) or Miss
/// (ℓ misses it; (xc, yc) is the vertex of X ⊕ (−Y) most clockwise around ℓ).
struct State {
  bool hit = false;
  Cand cand;
  int xc = -1, yc = -1;
  int xc_he = -1, xc_lev = -1, yc_he = -1, yc_lev = -1;
  // Support vertex of one side with its half-edge hint.
  std::array<int, 3> support(bool isq) const {
    if (hit) return isq ? std::array<int, 3>{cand.ys, cand.ys_he, cand.ys_lev} : std::array<int, 3>{cand.xs, cand.xs_he, cand.xs_lev};
    return isq ? std::array<int, 3>{yc, yc_he, yc_lev} : std::array<int, 3>{xc, xc_he, xc_lev};
  }
};

// A triangle rotated to start at its lowest id (same orientation), so that equal features from
// different subproblems compare equal structurally.
void canonical(int* t) {
  while (t[0] > t[1] || t[0] > t[2]) std::rotate(t, t + 1, t + 3);
}

// Brute force over the facet normals of X ⊕ (−Y) (a superset is fine: each candidate carries its
// exact support pair, so its half-space contains the sum). O(|X|·|Y|) candidates.
// With `apex` (local index 0 of the cap on side apex_q, caps store their apex first): only the
// facets of X ⊕ (−Y) whose feature on that side contains the apex, and only the exit. Used when
// the state is a hit and the cap came from beyond its plane: the new exit point lies in the
// relative interior of a facet whose contact on the cap's side is strictly beyond the old plane,
// i.e. in the open star of the apex, so that facet is among these candidates; every candidate
// being a supporting plane, their minimum is the exit.
// Local index of a vertex of S extreme for the functional F(v) = w·v on S's local coordinates
// (sense +1: a maximiser, −1: a minimiser; among exact ties the first in S's order, as a plain
// scan would pick). w is the cached Fl value of the exact functional; cmp(g, b) is the exact
// sign of F(v_g) − F(v_b) for global ids. One double dot per vertex; a vertex is compared
// exactly only if the rigorous error bound of the doubles does not separate it from the best.
template <class Cmp>
int extreme_vertex(const Small& S, const FV& w, int sense, Cmp cmp) {
  const DV wd = to_dv(w);
  const int n = static_cast<int>(S.id.size());
  double val[64];
  const bool fast = n <= 64;
  if (fast) {
    int b = 0;
    for (int i = 0; i < n; ++i) {
      val[i] = sense * wd.v.dot(S.loc[i]);
      if (val[i] > val[b]) b = i;
    }
    // |F(v) − w̃·v| ≤ (e_w + 3.01u·|w̃|)·|v| per value, u·|difference| for the subtraction.
    const double E = (wd.e + 4 * exact::kUnit * wd.n) * (1 + 8 * exact::kUnit);
    bool ok = true;
    for (int i = 0; i < n && ok; ++i) {
      if (i == b) continue;
      const double gap = val[b] - val[i];
      if (gap > E * (S.loc_n[i] + S.loc_n[b]) * (1 + 4 * exact::kUnit) + 2 * exact::kUnit * std::abs(gap) + exact::kTiny)
        continue;
      const int s2 = sense * cmp(S.id[i], S.id[b]);
      if (s2 > 0) ok = false;            // the doubles were misled: scan exactly
      else if (s2 == 0 && i < b) b = i;  // exact tie: the first one, like the scan
    }
    if (ok) return b;
  }
  int b = 0;
  for (int i = 1; i < n; ++i)
    if (sense * cmp(S.id[i], S.id[b]) > 0) b = i;
  return b;
}

// With `entry` (full solves only): set to the entry facet when ℓ meets X ⊕ (−Y).
State solve_small(Ctx& c, const Small& X, const Small& Y, const bool* apex_q = nullptr, Cand* entry_out = nullptr) {
  assert(!X.isq && Y.isq);
  const bool rx = apex_q && !*apex_q, ry = apex_q && *apex_q;  // restricted to X's / Y's apex
  const auto& PV = c.P.v;
  const auto& QV = c.Q.v;
  Cand exit, entry;
  bool has_exit = false, has_entry = false;
  auto consider = [&](Cand& k, const FV& u) {
    ++c.candidates;
    int lx = X.local_of(k.xs), ly = Y.local_of(k.ys);
    k.xs_he = X.he[lx], k.xs_lev = X.lev, k.ys_he = Y.he[ly], k.ys_lev = Y.lev;
    prepare(c, k, u, X.pt[lx], Y.pt[ly]);
    if (k.dsign > 0) {
      if (!has_exit || compare_t(c, k, exit) < 0) exit = k, has_exit = true;
    } else if (k.dsign < 0) {
      if (!has_entry || compare_t(c, k, entry) > 0) entry = k, has_entry = true;
    }
  };
  // Faces of X: Y's support minimises u·y' = (Rᵀu)·q + const.
  for (std::size_t f = 0; f < X.tri.size(); ++f) {
    if (rx && X.tri[f][0] != 0 && X.tri[f][1] != 0 && X.tri[f][2] != 0) continue;
    Cand k;
    k.kind = Cand::FaceX;
    for (int e = 0; e < 3; ++e) k.x[e] = X.id[X.tri[f][e]];
    canonical(k.x);
    k.xs = k.x[0];
    FV w = fl_rt(c.pose.R, X.tri_u[f]);
    auto cmp = [&](int g, int b) {  // sign of u·(y'_g − y'_b)
      int sg = cert(dot(w, fl_sub(QV[g], QV[b])));
      return sg != 2 ? sg : exact_sign([&](auto L) { return dot(cand_u(c, k, L), c.qdiff(L, g, b)); });
    };
    int best = Y.id[extreme_vertex(Y, w, -1, cmp)];
    if (ry && best != Y.id[0] && cmp(Y.id[0], best) != 0) continue;  // the apex is not a support
    k.ys = best;
    consider(k, X.tri_u[f]);
  }
  // Faces of Y: M's normal is −n(Q'), X's support maximises it.
  for (std::size_t f = 0; f < Y.tri.size(); ++f) {
    if (ry && Y.tri[f][0] != 0 && Y.tri[f][1] != 0 && Y.tri[f][2] != 0) continue;
    Cand k;
    k.kind = Cand::FaceY;
    for (int e = 0; e < 3; ++e) k.y[e] = Y.id[Y.tri[f][e]];
    canonical(k.y);
    k.ys = k.y[0];
    const FV& u = Y.tri_u[f];
    auto cmp = [&](int g, int b) {  // sign of u·(x_g − x_b)
      int sg = cert(dot(u, fl_sub(PV[g], PV[b])));
      return sg != 2 ? sg : exact_sign([&](auto L) { return dot(cand_u(c, k, L), c.pdiff(L, g, b)); });
    };
    int best = X.id[extreme_vertex(X, u, 1, cmp)];
    if (rx && best != X.id[0] && cmp(X.id[0], best) != 0) continue;  // the apex is not a support
    k.xs = best;
    consider(k, u);
  }
  // Edge pairs extreme for ±u (the test of minkowski_facets.cpp). Static filter first: one
  // error bound for all pairs of this (X, Y) (dot_sign's bound with the maxima of the norms and
  // errors), so most pairs are rejected by two plain dot products; the rest go through
  // dot_sign, the cached Fl values and the exact sign.
  auto static_bound = [](double an, double ae, double bn, double be) {
    return (an * be + ae * bn + ae * be + 4 * exact::kUnit * an * bn) * (1 + 8 * exact::kUnit) + exact::kTiny;
  };
  const double Bx = static_bound(Y.e0_n, Y.e0_e, X.w_n, X.w_e);  // e_Y · ((c − a) × e_X)
  const double By = static_bound(X.e0_n, X.e0_e, Y.w_n, Y.w_e);  // e_X · (e_Y × (c − a))
  auto fsign = [](double a, double B) { return a > B ? 1 : a < -B ? -1 : 2; };
  const std::size_t ny = Y.edge.size();
  const double *Yx = Y.e0x.data(), *Yy = Y.e0y.data(), *Yz = Y.e0z.data();
  for (std::size_t i = 0; i < X.edge.size(); ++i) {
    const auto& ex = X.edge[i];
    if (rx && ex[0] != 0 && ex[1] != 0) continue;
    const auto& xv = X.edge_v[i];
    const auto& xd = X.edge_d[i];
    const Vec3 w1 = xd[1].v, w2 = xd[2].v, ex0 = xd[0].v;
    int pa = X.id[ex[0]], pb = X.id[ex[1]], pc = X.id[ex[2]], pe = X.id[ex[3]];
    for (std::size_t j = 0; j < ny; ++j) {
      const double a1 = Yx[j] * w1.x() + Yy[j] * w1.y() + Yz[j] * w1.z();
      const double a2 = Yx[j] * w2.x() + Yy[j] * w2.y() + Yz[j] * w2.z();
      int s1 = fsign(a1, Bx), s2 = fsign(a2, Bx);
      if (s1 != 2 && s2 != 2 && s1 != s2) continue;  // P's edge is not extreme for ±u
      const auto& ey = Y.edge[j];
      if (ry && ey[0] != 0 && ey[1] != 0) continue;
      const auto& yv = Y.edge_v[j];
      const auto& yd = Y.edge_d[j];
      int qa = Y.id[ey[0]], qb = Y.id[ey[1]], qc = Y.id[ey[2]], qe = Y.id[ey[3]];
      auto U = [&](auto L) { return cross(c.pdiff(L, pb, pa), c.qdiff(L, qb, qa)); };
      // sign of u·(v − a): doubles, then the cached Fl values, then exact
      auto side = [&](const DV& ed, const DV& wd, const FV& e, const FV& w, bool isq, int v, int a) {
        int sg = dot_sign(ed, wd);
        if (sg != 2) return sg;
        sg = cert(dot(e, w));
        if (sg != 2) return sg;
        return exact_sign([&](auto L) { return dot(U(L), c.vdiff(L, isq, v, a)); });
      };
      if (s1 == 2) s1 = side(yd[0], xd[1], yv[0], xv[1], false, pc, pa);
      if (s2 == 2) s2 = side(yd[0], xd[2], yv[0], xv[2], false, pe, pa);
      if (s1 * s2 < 0 || (s1 == 0 && s2 == 0)) continue;
      int sgn = s1 != 0 ? -s1 : -s2;  // P's edge is extreme for sgn·u
      int t1 = fsign(ex0.dot(yd[1].v), By);
      if (t1 == 2) t1 = side(xd[0], yd[1], xv[0], yv[1], true, qc, qa);
      if (sgn * t1 < 0) continue;
      int t2 = fsign(ex0.dot(yd[2].v), By);
      if (t2 == 2) t2 = side(xd[0], yd[2], xv[0], yv[2], true, qe, qa);
      if (sgn * t2 < 0) continue;
      Cand k;  // canonical: lower id first on each edge (each swap flips u)
      k.kind = Cand::EdgeEdge;
      k.x[0] = std::min(pa, pb), k.x[1] = std::max(pa, pb), k.y[0] = std::min(qa, qb), k.y[1] = std::max(qa, qb);
      k.sgn = sgn * (pa > pb ? -1 : 1) * (qa > qb ? -1 : 1);
      k.xs = k.x[0], k.ys = k.y[0];
      FV u = cross(xv[0], yv[0]);  // the candidate's normal is sgn·(e_X × e_Y) in any edge order
      if (sgn < 0) u = {-u[0], -u[1], -u[2]};
      consider(k, u);
    }
  }
  State st;
  if (apex_q) {
    assert(has_exit);
    st.hit = true;
    st.cand = exit;
    return st;
  }
  assert(has_exit && has_entry);
  if (compare_t(c, entry, exit) <= 0) {
    st.hit = true;
    st.cand = exit;
    if (entry_out) *entry_out = entry;
    return st;
  }
  int bx = 0, by = 0;
  for (int x = 0; x < static_cast<int>(X.id.size()); ++x)
    for (int y = 0; y < static_cast<int>(Y.id.size()); ++y)
      if ((x != bx || y != by) && compare_turn(c, X.id[bx], Y.id[by], X.id[x], Y.id[y]) < 0) bx = x, by = y;
  st.xc = X.id[bx], st.yc = Y.id[by];
  st.xc_he = X.he[bx], st.xc_lev = X.lev, st.yc_he = Y.he[by], st.yc_lev = Y.lev;
  return st;
}

// ---------------------------------------------------------------------------------------------
// The plane of a state as a linear functional on one side, and the DK walk that maximises it.

// F(v) = flip·Σ_κ ξ_κ U_κ·v (ξ_κ infinitesimals in decreasing order). Hit: U_0 = u (X side:
// maximise u·x; Y side: minimise u·y'). Miss: U_(a,b) = d_b × W_c[a], f(v) = det(d_ε, W_c, v)
// with W_c = Z_c − o_δ (X side: minimise; Y side: maximise).
struct Func {
  const Ctx* c;
  bool isq;
  State stv;
  int flip;
  const State* st = &stv;
  Func(const Ctx* cc, bool q, const State& s0, int fl) : c(cc), isq(q), stv(s0), flip(fl) {}
  Func(const Func&) = delete;
  int ncoef() const { return st->hit ? 1 : 12; }
  template <class Lf>
  auto U(Lf L, int k) const {
    using T = decltype(L(0.0));
    if (st->hit) return cand_u(*c, st->cand, L);
    int a = k / 3, b = k % 3;
    V3<T> w;
    if (a == 0) w = c->mpoint(L, st->xc, st->yc);
    else {
      w = {L(0.0), L(0.0), L(0.0)};
      w[a - 1] = L(-1.0);
    }
    return cross(c->lift(L, c->dv[b]), w);
  }
  // flip·(F_k(a) − F_k(b))
  template <class Lf>
  auto diff(Lf L, int k, int a, int b) const {
    return L(double(flip)) * dot(U(L, k), c->vdiff(L, isq, a, b));
  }
  int sign(int a, int b) const {
    return formal_sign(ncoef(), [&](auto L, int k) { return diff(L, k, a, b); });
  }
  // Vertices of the exit facet's feature on this side lie on its plane: F is exactly equal on
  // them (the walk meets these ties at every level; certifying them needs no arithmetic).
  bool on_feature(int v) const {
    if (!st->hit) return false;
    const int* f = isq ? st->cand.y : st->cand.x;
    return v == f[0] || v == f[1] || v == f[2];
  }
};

// The O'Rourke / Edelsbrunner–Maurer walk of extreme_query.cpp with the key (F, X, Y), F formal
// and X, Y two local coordinate axes completing F's leading direction to a basis.
struct Walker {
  const Func& f;
  const std::vector<Vec3>& V;
  int kx = 0, ky = 1;
  FV w0;  ///< flip·U_0 on local coordinates (cached leading coefficient)
  explicit Walker(const Func& fn) : f(fn), V(fn.c->local(fn.isq)) {
    FV u0 = f.U(exact::LiftFl{}, 0);
    if (f.isq) u0 = fl_rt(f.c->pose.R, u0);
    for (auto& x : u0) x = Fl{double(f.flip), 0} * x;
    w0 = u0;
    // The key (F, X, Y) orders distinct vertices strictly iff some U_κ has a non-zero component
    // on the axis left out: take the axis of a certified non-zero component of the first
    // non-zero U_κ (in the local frame of this side).
    int third = -1;
    for (int k = 0; k < f.ncoef() && third < 0; ++k) {
      FV u = f.U(exact::LiftFl{}, k);
      if (f.isq) u = fl_rt(f.c->pose.R, u);
      double best = 0;
      for (int i = 0; i < 3; ++i)
        if (std::abs(u[i].v) > u[i].e && std::abs(u[i].v) > best) best = std::abs(u[i].v), third = i;
    }
    for (int i = 0; i < 3 && third < 0; ++i)  // not certified by the filter: exact signs of U_0
      if (exact_sign([&](auto L) {
            auto u = f.U(L, 0);
            if (!f.isq) return u[i];
            return L(f.c->pose.R(0, i)) * u[0] + L(f.c->pose.R(1, i)) * u[1] + L(f.c->pose.R(2, i)) * u[2];
          }) != 0)
        third = i;
    assert(third >= 0);
    kx = third == 0 ? 1 : 0;
    ky = third == 2 ? 1 : 2;
  }
  // Sign of F(p) − F(q) (the formal functional only).
  int fsign(int p, int q) const {
    if (p == q || (f.on_feature(p) && f.on_feature(q))) return 0;
    int s = cert(dot(w0, fl_sub(V[p], V[q])));
    return s == 1 || s == -1 ? s : f.sign(p, q);
  }
  static int sgn(double a, double b) { return (a > b) - (a < b); }
  // A neighbour c of the current top m with its cached differences to m.
  struct Probe {
    int v;
    bool fz;    ///< F(c) = F(m) structurally (both on the exit facet's feature)
    Fl F, X, Y; ///< F(c) − F(m) (leading coefficient), coordinate differences
  };
  Probe probe(int m, int c) const {
    Probe p{c, f.on_feature(c) && f.on_feature(m), dot(w0, fl_sub(V[c], V[m])),
            Fl{V[c][kx], 0} - Fl{V[m][kx], 0}, Fl{V[c][ky], 0} - Fl{V[m][ky], 0}};
    return p;
  }
  int fsign_probe(int m, const Probe& p) const {
    if (p.fz) return 0;
    int s = cert(p.F);
    return s == 1 || s == -1 ? s : f.sign(p.v, m);
  }
  // Sign of A1·F2 − A2·F1 for the coordinate difference A (axis 0: X, 1: Y); exact when a
  // factor vanishes, else filtered with the exact formal evaluation as fallback.
  template <class Formal>
  int cross_term(int m, const Probe& p1, const Probe& p2, int axis, Formal formal) const {
    const int ax = axis == 0 ? kx : ky;
    int a1 = sgn(V[p1.v][ax], V[m][ax]), a2 = sgn(V[p2.v][ax], V[m][ax]);
    if (a1 == 0 && a2 == 0) return 0;
    if (p1.fz || a2 == 0) return a1 * fsign_probe(m, p2);
    if (p2.fz || a1 == 0) return -a2 * fsign_probe(m, p1);
    const Fl& A1 = axis == 0 ? p1.X : p1.Y;
    const Fl& A2 = axis == 0 ? p2.X : p2.Y;
    int s = cert(A1 * p2.F - A2 * p1.F);
    return s == 1 || s == -1 ? s : formal();
  }
  int compare(int p, int q) const {
    if (p == q) return 0;
    int s = fsign(p, q);
    if (s != 0) return s;
    if (V[p][kx] != V[q][kx]) return V[p][kx] > V[q][kx] ? 1 : -1;
    if (V[p][ky] != V[q][ky]) return V[p][ky] > V[q][ky] ? 1 : -1;
    return 0;
  }
  // > 0: the projected edge m→c2 turns counter-clockwise from m→c1.
  int turn(int m, const Probe& p1, const Probe& p2) const {
    const int c1 = p1.v, c2 = p2.v;
    auto X = [&](auto L, int c) { return L(V[c][kx]) - L(V[m][kx]); };
    auto Y = [&](auto L, int c) { return L(V[c][ky]) - L(V[m][ky]); };
    int s = cross_term(m, p1, p2, 0, [&] {
      return formal_sign(f.ncoef(), [&](auto L, int k) {
        return X(L, c1) * f.diff(L, k, c2, m) - X(L, c2) * f.diff(L, k, c1, m);
      });
    });
    if (s != 0) return s;
    s = cert(p1.X * p2.Y - p2.X * p1.Y);
    if (s == 2) s = exact_sign([&](auto L) { return X(L, c1) * Y(L, c2) - X(L, c2) * Y(L, c1); });
    if (s != 0) return s;
    return cross_term(m, p1, p2, 1, [&] {
      return formal_sign(f.ncoef(), [&](auto L, int k) {
        return Y(L, c1) * f.diff(L, k, c2, m) - Y(L, c2) * f.diff(L, k, c1, m);
      });
    });
  }
};

// Position of the walk at one level: the top m and the silhouette edges m→l, m→r.
struct WalkState {
  int lev = -1, m = -1, hl = -1, hr = -1;
};

struct Walk {
  const PolytopeData& D;
  const Walker& fr;
  WalkState& ws;
  std::vector<Walker::Probe>& pr;  ///< scratch buffers, owned by the Query (no allocation per step)
  std::vector<int>& scratch_all;
  std::vector<int>& scratch_out;

  void pick(const DKLevel& L, const int* cand, int nc) {
    pr.clear();
    for (int i = 0; i < nc; ++i) pr.push_back(fr.probe(ws.m, L.target(cand[i])));
    int il = 0, ir = 0;
    for (int i = 1; i < nc; ++i) {
      if (fr.turn(ws.m, pr[ir], pr[i]) > 0) ir = i;
      if (fr.turn(ws.m, pr[il], pr[i]) < 0) il = i;
    }
    ws.hl = cand[il], ws.hr = cand[ir];
  }
  // All out-half-edges of origin(h0) (false if more than `cap` of them).
  static bool around(const DKLevel& L, int h0, std::vector<int>& out, std::size_t cap) {
    out.clear();
    int h = h0;
    do {
      if (out.size() == cap) return false;
      out.push_back(h);
      h = L.ccw(h);
    } while (h != h0);
    return true;
  }
  void scan_around(const DKLevel& L, int h0) {
    std::vector<int>& all = scratch_all;
    around(L, h0, all, std::size_t(-1));
    pick(L, all.data(), static_cast<int>(all.size()));
  }
  // Fresh walk: the top level by brute force.
  void start_top() {
    const DKLevel& top = D.levels.back();
    ws.lev = static_cast<int>(D.levels.size()) - 1;
    ws.m = top.verts[0];
    for (int v : top.verts)
      if (fr.compare(v, ws.m) > 0) ws.m = v;
    for (int h = 0; h < static_cast<int>(top.fv.size()); ++h)
      if (top.fv[h] == ws.m) { scan_around(top, h); break; }
  }
  // Restart at level `lev` from vertex v given an out-half-edge h of v at level hl >= lev:
  // hill-climb by the key (a local maximum of the perturbed linear key is global), then take
  // the silhouette edges. O(degree); gives up (false) on vertices of degree > kMaxScan.
  bool restart(int v, int h, int hlev, int lev) {
    static constexpr std::size_t kMaxScan = 48;
    if (h < 0 || hlev < lev) return false;
    for (int l = hlev; l > lev; --l) h = D.levels[l].down[h];
    const DKLevel& L = D.levels[lev];
    std::vector<int>& out = scratch_out;
    for (bool moved = true; moved;) {
      moved = false;
      if (!around(L, h, out, kMaxScan)) return false;
      for (int g : out)
        if (fr.compare(L.target(g), v) > 0) {
          v = L.target(g), h = L.twin[g], moved = true;
          break;
        }
    }
    ws.lev = lev, ws.m = v;
    pick(L, out.data(), static_cast<int>(out.size()));
    return true;
  }
  // One level down (O'Rourke Lemma 7.10.3: the new top is m or a parent of m→l, m→r).
  void down() {
    const DKLevel& C = D.levels[ws.lev];
    const DKLevel& L = D.levels[ws.lev - 1];
    int left[3], right[3], nl = 0, nr = 0;
    auto expand = [&](int h, int* out, int& no) {
      int g = C.down[h];
      out[no++] = g;
      if (L.target(g) == C.target(h)) {
        out[no++] = L.ccw(g);
        out[no++] = L.cw(g);
      }
    };
    expand(ws.hl, left, nl);
    expand(ws.hr, right, nr);
    --ws.lev;
    int best = -1;
    for (int i = 0; i < nl + nr; ++i) {
      int h = i < nl ? left[i] : right[i - nl];
      if (fr.compare(L.target(h), best < 0 ? ws.m : L.target(best)) > 0) best = h;
    }
    if (best >= 0) {
      ws.m = L.target(best);
      scan_around(L, L.twin[best]);
    } else {
      pick(L, left, nl);
      int keep = ws.hl;
      pick(L, right, nr);
      ws.hl = keep;
    }
  }
};

// ---------------------------------------------------------------------------------------------
// The descent.

/// One side of a pair: a hierarchy down to level `bottom`, or a constant-size polytope.
struct Side {
  bool hier = false;
  int bottom = 0;
  const Small* small = nullptr;
};

struct Query {
  Ctx& c;
  const Small& topP;
  const Small& topQ;
  std::vector<Walker::Probe> probes;
  std::vector<int> walk_all, walk_out;
  /// Set by the outermost descent: 0 ∈ int (P_top ⊕ (−Q'_top)), hence 0 ∈ int M (the top levels
  /// are inner polytopes), by the exit/entry criterion of the header applied to the top pair.
  bool top_inside = false;

  // The walk of one side for the current state's plane, kept from level to level: continued
  // one level down while the state is unchanged, restarted from the new support vertex (its
  // half-edge hint) when it changed, and done afresh from the top only when that fails.
  struct SideWalk {
    std::optional<Func> f;
    std::optional<Walker> fr;
    WalkState ws;
  };

  // The vertex of level `lev` strictly beyond the state's plane on one side, as a cap.
  const Small* cap(const State& st, bool fresh_state, SideWalk& sw, bool isq, int lev) {
    const PolytopeData& D = c.data(isq);
    if (fresh_state || !sw.fr) {
      // X side keeps u·x ≤ h (hit) / f ≥ f(x_c) (miss); Y side the opposite.
      sw.fr.reset();
      sw.f.emplace(&c, isq, st, st.hit ? (isq ? -1 : 1) : (isq ? 1 : -1));
      sw.fr.emplace(*sw.f);
      sw.ws = WalkState{};
    }
    Walk w{D, *sw.fr, sw.ws, probes, walk_all, walk_out};
    auto [ref, ref_he, ref_lev] = st.support(isq);
    if (sw.ws.lev != lev + 1 && !w.restart(ref, ref_he, ref_lev, lev + 1)) {
      w.start_top();
      while (sw.ws.lev > lev + 1) w.down();
    }
    w.down();
    if (sw.fr->fsign(sw.ws.m, ref) <= 0) return nullptr;
    return &cached_cap(c, isq, lev, sw.ws.hl);  // sw.ws.hl: an out-half-edge of the top
  }

  static bool better_hit(Ctx& c, const State& a, const State& b) {  // a's exit later than b's
    return compare_t(c, a.cand, b.cand) > 0;
  }

  State combine(const State& s0, const State* r1, const State* r2) {
    State best = s0;
    for (const State* r : {r1, r2}) {
      if (!r) continue;
      if (r->hit) {
        if (!best.hit || better_hit(c, *r, best)) best = *r;
      } else if (!best.hit && compare_turn(c, best.xc, best.yc, r->xc, r->yc) < 0) {
        best = *r;
      }
    }
    return best;
  }

  State descend(const Side& X, const Side& Y) {
    const int KP = static_cast<int>(c.P.levels.size()), KQ = static_cast<int>(c.Q.levels.size());
    const int nx = X.hier ? KP - 1 - X.bottom : 0, ny = Y.hier ? KQ - 1 - Y.bottom : 0;
    const bool outermost = X.hier && Y.hier && X.bottom == 0 && Y.bottom == 0;
    Cand entry;
    State st = solve_small(c, X.hier ? topP : *X.small, Y.hier ? topQ : *Y.small, nullptr, outermost ? &entry : nullptr);
    if (outermost) top_inside = st.hit && positive_h(c, st.cand) && positive_h(c, entry);
    SideWalk wx, wy;
    bool stale_x = true, stale_y = true;  // the state changed since that side's last walk
    for (int s = std::max(nx, ny); s >= 1; --s) {
      bool xr = X.hier && s <= nx, yr = Y.hier && s <= ny;
      const Small* C = xr ? cap(st, stale_x, wx, false, X.bottom + s - 1) : nullptr;
      const Small* D = yr ? cap(st, stale_y, wy, true, Y.bottom + s - 1) : nullptr;
      stale_x = stale_x && !xr, stale_y = stale_y && !yr;
      const bool hc = C != nullptr, hd = D != nullptr;
      if (!hc && !hd) continue;
      State r1, r2;
      static constexpr bool kApexX = false, kApexY = true;
      if (hc) {
        Side cx{false, 0, C};
        Side y = Y.hier ? Side{true, Y.bottom + std::min(s - 1, ny), nullptr} : Y;
        r1 = !Y.hier && st.hit ? solve_small(c, *C, *Y.small, &kApexX) : descend(cx, y);
      }
      if (hd) {
        Side dy{false, 0, D};
        Side x = X.hier ? Side{true, X.bottom + std::min(s - 1, nx), nullptr} : X;
        r2 = !X.hier && st.hit ? solve_small(c, *X.small, *D, &kApexY) : descend(x, dy);
      }
      State next = combine(st, hc ? &r1 : nullptr, hd ? &r2 : nullptr);
      // Generic line: a cap beyond the plane always moves the exit or the tangent.
      assert(next.hit != st.hit || (next.hit ? compare_t(c, next.cand, st.cand) > 0
                                             : compare_turn(c, st.xc, st.yc, next.xc, next.yc) < 0));
      st = next;
      stale_x = stale_y = true;
    }
    return st;
  }
};

// Level-0 features of the answer. The stars of the feature's vertices are scanned in lockstep,
// so the cost is O(smallest degree), not O(degree of a hub vertex).
// A level-0 triangle in the plane through the feature f (2 or 3 vertex ids, -1 padded) with
// normal u: the triangle f itself if it exists, else a coplanar one (flat facets; exact test).
template <class UF>
int face_in_plane(const Ctx& c, bool isq, const int* f, UF u_of) {
  const PolytopeData& D = c.data(isq);
  const DKLevel& L = D.levels[0];
  const int nf = f[2] < 0 ? 2 : 3;
  int h[3], h0[3];
  for (int i = 0; i < nf; ++i) h[i] = h0[i] = D.vertex_he[f[i]];
  auto on = [&](int w, int v) {
    return w == f[0] || w == f[1] || (nf == 3 && w == f[2]) ||
           exact_sign([&](auto Lf) { return dot(u_of(Lf), c.vdiff(Lf, isq, w, v)); }) == 0;
  };
  for (bool more = true; more;) {
    more = false;
    for (int i = 0; i < nf; ++i) {
      if (h[i] < 0) continue;
      if (on(L.target(h[i]), f[i]) && on(L.target(DKLevel::next(h[i])), f[i])) return h[i] / 3;
      h[i] = L.ccw(h[i]);
      if (h[i] == h0[i]) h[i] = -1;
      more = more || h[i] >= 0;
    }
  }
  return -1;
}

// The level-0 half-edge a → b, or -1 if (a, b) is not an edge.
int edge_he(const PolytopeData& D, int a, int b) {
  const DKLevel& L = D.levels[0];
  int ha = D.vertex_he[a], hb = D.vertex_he[b], ha0 = ha, hb0 = hb;
  while (ha >= 0 || hb >= 0) {
    if (ha >= 0) {
      if (L.target(ha) == b) return ha;
      ha = L.ccw(ha);
      if (ha == ha0) ha = -1;
    }
    if (hb >= 0) {
      if (L.target(hb) == a) return L.twin[hb];
      hb = L.ccw(hb);
      if (hb == hb0) hb = -1;
    }
  }
  return -1;
}

// Vertices of the support face of one side through its support vertex s for the exit facet
// normal u (X side: u·x = max; Y side: u·y' = min): flood over level-0 edges with exact
// equality. O(Σ degrees of the face's vertices) (one vertex in general position).
// `known`: further vertices on the plane by construction (the candidate's own feature), so that
// the exact zeros they would produce are never evaluated.
template <class UF>
std::vector<int> plane_face(const Ctx& c, bool isq, int s, std::initializer_list<int> known, UF u_of) {
  const PolytopeData& D = c.data(isq);
  const DKLevel& L = D.levels[0];
  std::vector<int> out{s};
  for (int k : known)
    if (k >= 0 && std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const int h0 = D.vertex_he[out[i]];
    int h = h0;
    do {
      const int w = L.target(h);
      if (std::find(out.begin(), out.end(), w) == out.end() &&
          exact_sign([&](auto Lf) { return dot(u_of(Lf), c.vdiff(Lf, isq, w, s)); }) == 0)
        out.push_back(w);
      h = L.ccw(h);
    } while (h != h0);
  }
  return out;
}

// A point of conv(A) ∩ conv(B) for two convex point sets lying (up to rounding) in one plane
// with unit normal u, known to intersect exactly. The intersection is the hull of vertices of A
// in conv(B), vertices of B in conv(A) and crossings of their edges; among these candidates the
// one least outside both (2D signed distances, doubles) is returned. O(|A|·|B|·(|A| + |B|)).
Vec3 contact_point(const std::vector<Vec3>& A, const std::vector<Vec3>& B, const Vec3& u) {
  if (A.size() == 1) return A[0];
  if (B.size() == 1) return B[0];
  const Vec3 e1 = u.unitOrthogonal(), e2 = u.cross(e1);
  const Vec3 o = A[0];
  using P2 = Eigen::Vector2d;
  auto to2 = [&](const std::vector<Vec3>& S) {  // projected, in convex (CCW) order
    std::vector<P2> r;
    P2 m = P2::Zero();
    for (const auto& x : S) r.emplace_back((x - o).dot(e1), (x - o).dot(e2)), m += r.back();
    m /= double(r.size());
    std::sort(r.begin(), r.end(), [&](const P2& a, const P2& b) {
      return std::atan2(a.y() - m.y(), a.x() - m.x()) < std::atan2(b.y() - m.y(), b.x() - m.x());
    });
    return r;
  };
  const std::vector<P2> a = to2(A), b = to2(B);
  auto outside = [](const P2& x, const std::vector<P2>& S) {  // ≈ distance outside conv(S)
    auto seg = [&](const P2& p, const P2& q) {
      P2 d = q - p;
      double t = d.squaredNorm() > 0 ? std::clamp((x - p).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      return (x - p - t * d).norm();
    };
    if (S.size() == 2) return seg(S[0], S[1]);
    double worst = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < S.size(); ++i) {
      P2 d = S[(i + 1) % S.size()] - S[i];
      double n = d.norm();
      if (n > 0) worst = std::max(worst, (d.x() * (x.y() - S[i].y()) - d.y() * (x.x() - S[i].x())) / -n);
    }
    return worst;
  };
  P2 best = a[0];
  double best_score = std::numeric_limits<double>::infinity();
  auto consider = [&](const P2& x) {
    double sc = std::max(outside(x, a), outside(x, b));
    if (sc < best_score) best_score = sc, best = x;
  };
  for (const auto& x : a) consider(x);
  for (const auto& x : b) consider(x);
  const std::size_t na = a.size() == 2 ? 1 : a.size(), nb = b.size() == 2 ? 1 : b.size();
  for (std::size_t i = 0; i < na; ++i)
    for (std::size_t j = 0; j < nb; ++j) {
      P2 p = a[i], r = a[(i + 1) % a.size()] - p, q = b[j], s = b[(j + 1) % b.size()] - q;
      double den = r.x() * s.y() - r.y() * s.x();
      if (den == 0) continue;
      double t = ((q - p).x() * s.y() - (q - p).y() * s.x()) / den;
      consider(p + std::clamp(t, 0.0, 1.0) * r);
    }
  return o + best.x() * e1 + best.y() * e2;
}

}  // namespace

Depth3 directional_depth_dk(const ConvexPolytope& Pp, const Pose3& pose_p, const ConvexPolytope& Qp,
                            const Pose3& pose_q, const Vec3& d_world) {
  if (!d_world.allFinite() || d_world == Vec3::Zero()) throw InvalidInput("direction: zero or non-finite");
  if (!pose_p.translation.allFinite()) throw InvalidInput("pose of P: non-finite translation");
  if (!pose_q.translation.allFinite()) throw InvalidInput("pose of Q: non-finite translation");
  const Eigen::Matrix3d Rp = pose_p.matrix(), Rq = pose_q.matrix();
  RelativePose pose;
  pose.R = Rp.transpose() * Rq;
  pose.tq = Rp.transpose() * pose_q.translation;
  pose.tp = Rp.transpose() * pose_p.translation;
  const Vec3 d_local = Rp.transpose() * d_world;
  Depth3 none;
  none.kind = DepthKind::Directional;
  if (d_local == Vec3::Zero()) throw InvalidInput("direction: underflows to zero in P's frame");
  // Scale d by a power of two (exact) so that its products neither overflow nor underflow.
  int ex = 0;
  std::frexp(d_local.cwiseAbs().maxCoeff(), &ex);
  const Vec3 d = Vec3(std::ldexp(d_local.x(), -ex), std::ldexp(d_local.y(), -ex), std::ldexp(d_local.z(), -ex));
  int big = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(d[i]) > std::abs(d[big])) big = i;
  Ctx c{convex3::data_of(Pp), convex3::data_of(Qp), pose, {}, 0};
  if (small_cache().map.size() > SmallCache::kMaxEntries) small_cache().map.clear();
  const Small& topP = cached_top(c, false);
  const Small& topQ = cached_top(c, true);
  Query q{c, topP, topQ, {}, {}, {}};
  auto run = [&](int s) {
    c.dv[0] = s * d;
    c.dv[1] = s * Vec3::Unit((big + 1) % 3);
    c.dv[2] = s * Vec3::Unit((big + 2) % 3);
    return q.descend(Side{true, 0, nullptr}, Side{true, 0, nullptr});
  };
  auto positive = [&](const State& st) {  // h_M(u) > 0: 0 strictly inside the exit half-space
    return st.hit && exact_sign([&](auto L) { return cand_n(c, st.cand, L, 0); }) > 0;
  };
  State fwd = run(1);
  none.candidates = c.candidates;
  if (!positive(fwd)) return none;
  // Overlap: certified already if 0 ∈ int of the top pair's sum; else the descent along −d.
  if (!q.top_inside) {
    State bwd = run(-1);
    none.candidates = c.candidates;
    if (!positive(bwd)) return none;
  }
  c.dv[0] = d;
  const Cand& k = fwd.cand;
  // 0 ∈ int M: the exit facet has u·d > 0 (proof in the header) and σ_d = h_M(u)/(u·d̂).
  assert(exact_sign([&](auto L) { return cand_d(c, k, L, 0); }) > 0);
  double t = exact::accurate_ratio([&](auto L) { return cand_n(c, k, L, 0); },
                                   [&](auto L) { return cand_d(c, k, L, 0); });
  Depth3 r;
  r.kind = DepthKind::Directional;
  r.overlapping = true;
  r.candidates = c.candidates;
  r.depth = r.lower_bound = r.upper_bound = t * d.norm();
  const Vec3 dir = d.normalized();
  const Vec3 v = r.depth * dir;
  auto uf = cand_u(c, k, exact::LiftFl{});
  const Vec3 u = Vec3(uf[0].v, uf[1].v, uf[2].v).normalized();
  auto U = [&](auto L) { return cand_u(c, k, L); };
  if (k.kind == Cand::FaceX) {
    r.feature_p = {FeatureKind3::Face, face_in_plane(c, false, k.x, U)};
    r.feature_q = {FeatureKind3::Vertex, k.ys};
  } else if (k.kind == Cand::FaceY) {
    r.feature_p = {FeatureKind3::Vertex, k.xs};
    r.feature_q = {FeatureKind3::Face, face_in_plane(c, true, k.y, U)};
  } else {
    int hp = edge_he(c.P, k.x[0], k.x[1]), hq = edge_he(c.Q, k.y[0], k.y[1]);
    // An edge of a cap's bottom may be a diagonal of a flat facet of the polytope: report the face.
    r.feature_p = hp >= 0 ? Feature3{FeatureKind3::Edge, hp} : Feature3{FeatureKind3::Face, face_in_plane(c, false, k.x, U)};
    r.feature_q = hq >= 0 ? Feature3{FeatureKind3::Edge, hq} : Feature3{FeatureKind3::Face, face_in_plane(c, true, k.y, U)};
  }
  // Contact point (P's frame): a point of F_P(u) ∩ (F_Q'(u) + v), the support faces taken
  // exactly (face–face and parallel-edge contacts touch along a polygon or a segment).
  std::vector<Vec3> fp, fq;
  const bool fx = k.kind != Cand::FaceY, fy = k.kind != Cand::FaceX;  // x[], y[] are features
  for (int i : plane_face(c, false, k.xs, {fx ? k.x[0] : -1, fx ? k.x[1] : -1, fx ? k.x[2] : -1}, U))
    fp.push_back(Pp[i]);
  for (int j : plane_face(c, true, k.ys, {fy ? k.y[0] : -1, fy ? k.y[1] : -1, fy ? k.y[2] : -1}, U))
    fq.push_back(pose.place(Qp[j]) + v);
  const Vec3 w = contact_point(fp, fq, u);
  r.translation = Rp * v;
  r.normal = Rp * dir;
  r.facet_normal = Rp * u;
  r.witness_p = r.witness_q = Rp * w + pose_p.translation;
  return r;
}


// The exit of the line {s·d} from M for a shape cast (cast3.cpp): the same descent as
// directional_depth_dk along +d, without the overlap test. See LineExit (minimum_expand.hpp).
LineExit line_exit_dk(const ConvexPolytope& Pp, const ConvexPolytope& Qp, const RelativePose& pose,
                      const Vec3& d_local, int orient) {
  // Scale d by a power of two (exact) so that its products neither overflow nor underflow.
  int ex = 0;
  std::frexp(d_local.cwiseAbs().maxCoeff(), &ex);
  const Vec3 d = Vec3(std::ldexp(d_local.x(), -ex), std::ldexp(d_local.y(), -ex), std::ldexp(d_local.z(), -ex));
  int big = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(d[i]) > std::abs(d[big])) big = i;
  Ctx c{convex3::data_of(Pp), convex3::data_of(Qp), pose, {}, 0};
  if (small_cache().map.size() > SmallCache::kMaxEntries) small_cache().map.clear();
  const Small& topP = cached_top(c, false);
  const Small& topQ = cached_top(c, true);
  Query q{c, topP, topQ, {}, {}, {}};
  c.dv[0] = d;
  c.dv[1] = orient * Vec3::Unit((big + 1) % 3);
  c.dv[2] = orient * Vec3::Unit((big + 2) % 3);
  const State st = q.descend(Side{true, 0, nullptr}, Side{true, 0, nullptr});
  LineExit r;
  if (!st.hit) return r;
  r.hit = true;
  const Cand& k = st.cand;
  r.h_sign = exact_sign([&](auto L) { return cand_n(c, k, L, 0); });
  // u·d > 0 for the exit facet of a line that meets int M (proof in the header).
  const double t = r.h_sign == 0 ? 0.0
                                 : exact::accurate_ratio([&](auto L) { return cand_n(c, k, L, 0); },
                                                         [&](auto L) { return cand_d(c, k, L, 0); });
  r.exit = t * d.norm();
  const Vec3 v = t * d;
  auto uf = cand_u(c, k, exact::LiftFl{});
  r.unit = Vec3(uf[0].v, uf[1].v, uf[2].v).normalized();
  auto U = [&](auto L) { return cand_u(c, k, L); };
  if (k.kind == Cand::FaceX) {
    r.feature_p = {FeatureKind3::Face, face_in_plane(c, false, k.x, U)};
    r.feature_q = {FeatureKind3::Vertex, k.ys};
  } else if (k.kind == Cand::FaceY) {
    r.feature_p = {FeatureKind3::Vertex, k.xs};
    r.feature_q = {FeatureKind3::Face, face_in_plane(c, true, k.y, U)};
  } else {
    int hp = edge_he(c.P, k.x[0], k.x[1]), hq = edge_he(c.Q, k.y[0], k.y[1]);
    r.feature_p = hp >= 0 ? Feature3{FeatureKind3::Edge, hp} : Feature3{FeatureKind3::Face, face_in_plane(c, false, k.x, U)};
    r.feature_q = hq >= 0 ? Feature3{FeatureKind3::Edge, hq} : Feature3{FeatureKind3::Face, face_in_plane(c, true, k.y, U)};
  }
  std::vector<Vec3> fp, fq;
  const bool fx = k.kind != Cand::FaceY, fy = k.kind != Cand::FaceX;
  for (int i : plane_face(c, false, k.xs, {fx ? k.x[0] : -1, fx ? k.x[1] : -1, fx ? k.x[2] : -1}, U))
    fp.push_back(Pp[i]);
  for (int j : plane_face(c, true, k.ys, {fy ? k.y[0] : -1, fy ? k.y[1] : -1, fy ? k.y[2] : -1}, U))
    fq.push_back(pose.place(Qp[j]) + v);
  r.contact = contact_point(fp, fq, r.unit);
  return r;
}


// The cast of a line ℓ = {s·d} that does not meet int M (cast3.cpp calls it when a perturbed
// descent misses): ℓ ∩ M is empty, or a point or segment [a, b] of ∂M, and every decision is
// the exact sign of a polynomial in the input doubles.
//  1. ℓ meets M iff 0 ∈ π(M), π the projection along d: exact GJK (line_touch_gjk). Since ℓ
//     misses int M, 0 ∈ ∂π(M), so the final simplex is a pair (i, j) with m_ij ∈ ℓ or two pairs
//     whose segment crosses ℓ inside the boundary line of π(M).
//  2. A supporting plane H ⊃ ℓ of M, normal u ⊥ d: for two pairs, u = ±(m_b − m_a) × d; for one
//     pair, u = g* × d with g* an extreme generator of the tangent cone of M at m_ij (generators
//     p_k − p_i, q'_j − q'_l over the neighbours; [d, g*, g] >= 0 for all g). The sign is the one
//     for which the pair is a local, hence global, maximum of u·m (exact climb test).
//  3. ℓ ∩ M = ℓ ∩ F with F = M ∩ H = F_P(u) ⊕ (−F_Q'(u)), the support faces flooded exactly
//     (plane_face). In H, F is the intersection of the half-planes w·x <= h_F(w) for w among
//     ±d, ±e and ±u × e over the level-0 edges e of F_P and F_Q' (the edge normals of the sum,
//     and what bounds a segment or a point), so [a, b] = [max h/(w·d) over w·d < 0,
//     min h/(w·d) over w·d > 0], compared by exact cross-multiplied signs.
//  4. b < 0: miss; a > 0: first contact at a; else touching at 0 (never overlapping). The normal
//     is u/|u| (the supporting plane through the ray, ⊥ d), the features those of F_P and F_Q'.
// Cost: O(k·c) for step 1, O(degree²) for step 2, O(f·(f + g)) for faces of f and g vertices.
Cast3 cast_graze(const ConvexPolytope& Pp, const ConvexPolytope& Qp, const RelativePose& pose, const Vec3& d_local,
                 const Eigen::Matrix3d& Rp, const Vec3& tp_world) {
  Cast3 r;
  r.distance = std::numeric_limits<double>::infinity();
  int ex = 0;
  std::frexp(d_local.cwiseAbs().maxCoeff(), &ex);
  const Vec3 d = Vec3(std::ldexp(d_local.x(), -ex), std::ldexp(d_local.y(), -ex), std::ldexp(d_local.z(), -ex));
  const LineTouch t = line_touch_gjk(Pp, Qp, pose, d);
  if (!t.touch || t.size < 1 || t.size > 2) return r;  // sizes 3, 4 would mean ℓ meets int M
  Ctx c{convex3::data_of(Pp), convex3::data_of(Qp), pose, {}, 0};
  auto around = [](const PolytopeData& D, int v, auto&& f) {
    const DKLevel& L = D.levels[0];
    const int h0 = D.vertex_he[v];
    int h = h0;
    do {
      f(L.target(h));
      h = L.ccw(h);
    } while (h != h0);
  };
  auto dl = [&](auto L) { return c.lift(L, d); };
  // A vector g of M's tangent cone: P side p_a − p_b, Q side q'_a − q'_b; or m_(a, ja) − m_(b, jb).
  struct Vec {
    int kind = 0;  // 0: P difference, 1: Q' difference, 2: pair difference
    int a = 0, b = 0, ja = 0, jb = 0;
  };
  auto vec = [&](auto L, const Vec& g) {
    if (g.kind == 0) return c.pdiff(L, g.a, g.b);
    auto q = c.qdiff(L, g.kind == 1 ? g.a : g.ja, g.kind == 1 ? g.b : g.jb);
    if (g.kind == 1) return q;
    auto p = c.pdiff(L, g.a, g.b);
    return decltype(q){p[0] - q[0], p[1] - q[1], p[2] - q[2]};
  };
  Vec gs;
  const int i0 = t.i[0], j0 = t.j[0];
  if (t.size == 2) {
    gs = Vec{2, t.i[1], t.i[0], t.j[1], t.j[0]};
  } else {
    std::vector<Vec> gens;
    around(c.P, i0, [&](int k) { gens.push_back(Vec{0, k, i0}); });
    around(c.Q, j0, [&](int l) { gens.push_back(Vec{1, j0, l}); });
    auto tri = [&](const Vec& x, const Vec& y) {
      return exact_sign([&](auto L) { return dot(dl(L), cross(vec(L, x), vec(L, y))); });
    };
    bool found = false;
    for (const Vec& g : gens) {
      bool par = true;  // g ∥ d: in every supporting plane through ℓ
      for (int k = 0; k < 3 && par; ++k)
        par = exact_sign([&](auto L) { return cross(vec(L, g), dl(L))[k]; }) == 0;
      if (par) continue;
      bool ok = true;
      for (const Vec& h : gens)
        if (tri(g, h) < 0) {
          ok = false;
          break;
        }
      if (ok) {
        gs = g, found = true;
        break;
      }
    }
    if (!found) return r;  // the cone is the whole plane: ℓ would meet int M (unreachable)
  }
  int sign = 1;
  auto U = [&](auto L) {
    auto u = cross(vec(L, gs), dl(L));
    if (sign < 0)
      for (auto& x : u) x = L(0.0) - x;
    return u;
  };
  auto supporting = [&]() {  // (i0, j0) maximises u·m: local test over the neighbours
    bool ok = true;
    around(c.P, i0, [&](int k) { ok = ok && exact_sign([&](auto L) { return dot(U(L), c.pdiff(L, k, i0)); }) <= 0; });
    around(c.Q, j0, [&](int l) { ok = ok && exact_sign([&](auto L) { return dot(U(L), c.qdiff(L, l, j0)); }) >= 0; });
    return ok;
  };
  if (!supporting()) {
    sign = -1;
    if (!supporting()) return r;  // unreachable: one side of the line through 0 supports π(M)
  }
  const std::vector<int> fp = plane_face(c, false, i0, {}, U);
  const std::vector<int> fq = plane_face(c, true, j0, {}, U);
  // Half-plane normals w: ±d, and ±e, ±u × e over the edges e of F_P and F_Q'.
  struct W {
    int kind = 0;  // 0: d, 1: e, 2: u × e
    int sg = 1;
    Vec e;
  };
  std::vector<W> ws{{0, 1, {}}, {0, -1, {}}};
  auto add_edges = [&](const PolytopeData& D, const std::vector<int>& f, int side) {
    for (int x : f)
      around(D, x, [&](int y) {
        if (y > x && std::find(f.begin(), f.end(), y) != f.end())
          for (int kind = 1; kind <= 2; ++kind)
            for (int sg : {1, -1}) ws.push_back(W{kind, sg, Vec{side, y, x}});
      });
  };
  add_edges(c.P, fp, 0);
  add_edges(c.Q, fq, 1);
  auto wvec = [&](auto L, const W& w) {
    auto v = w.kind == 0 ? dl(L) : w.kind == 1 ? vec(L, w.e) : cross(U(L), vec(L, w.e));
    if (w.sg < 0)
      for (auto& x : v) x = L(0.0) - x;
    return v;
  };
  // h_F(w) attained at the pair (x*, y*).
  struct Bound {
    W w;
    int x = -1, y = -1;
  };
  auto bound = [&](const W& w) {
    Bound b{w, fp[0], fq[0]};
    for (int x : fp)
      if (x != b.x && exact_sign([&](auto L) { return dot(wvec(L, w), c.pdiff(L, x, b.x)); }) > 0) b.x = x;
    for (int y : fq)
      if (y != b.y && exact_sign([&](auto L) { return dot(wvec(L, w), c.qdiff(L, y, b.y)); }) < 0) b.y = y;
    return b;
  };
  auto hval = [&](auto L, const Bound& b) { return dot(wvec(L, b.w), c.mpoint(L, b.x, b.y)); };
  auto dval = [&](auto L, const Bound& b) { return dot(wvec(L, b.w), dl(L)); };
  std::optional<Bound> lo, hi;
  for (const W& w : ws) {
    const int wd = exact_sign([&](auto L) { return dot(wvec(L, w), dl(L)); });
    if (wd == 0) continue;
    const Bound b = bound(w);
    std::optional<Bound>& best = wd < 0 ? lo : hi;
    if (!best) {
      best = b;
      continue;
    }
    // h_b/D_b vs h_best/D_best, both denominators of sign wd: h_b·D_best − h_best·D_b.
    const int cmp =
        exact_sign([&](auto L) { return hval(L, b) * dval(L, *best) - hval(L, *best) * dval(L, b); });
    if (wd < 0 ? cmp > 0 : cmp < 0) best = b;
  }
  // ±d always bound both ends. b < 0 ⇔ h_hi < 0; a > 0 ⇔ h_lo < 0.
  if (exact_sign([&](auto L) { return hval(L, *hi); }) < 0) return r;
  const bool ahead = exact_sign([&](auto L) { return hval(L, *lo); }) < 0;
  const double s = ahead ? exact::accurate_ratio([&](auto L) { return hval(L, *lo); },
                                                 [&](auto L) { return dval(L, *lo); })
                         : 0.0;
  r.hit = true;
  r.distance = s * d.norm();
  const Vec3 dir = d.normalized();
  r.translation = Rp * (r.distance * dir);
  const auto uf = U(exact::LiftFl{});
  const Vec3 unit = Vec3(uf[0].v, uf[1].v, uf[2].v).normalized();
  r.normal = Rp * unit;
  auto feature = [&](bool isq, const std::vector<int>& f) -> Feature3 {
    if (f.size() == 1) return {FeatureKind3::Vertex, f[0]};
    if (f.size() == 2)
      if (const int h = edge_he(c.data(isq), f[0], f[1]); h >= 0) return {FeatureKind3::Edge, h};
    const int ids[3] = {f[0], f[1], f.size() > 2 ? f[2] : -1};
    return {FeatureKind3::Face, face_in_plane(c, isq, ids, U)};
  };
  r.feature_p = feature(false, fp);
  r.feature_q = feature(true, fq);
  std::vector<Vec3> ap, aq;
  const Vec3 v = s * d;
  for (int i : fp) ap.push_back(Pp[i]);
  for (int j : fq) aq.push_back(pose.place(Qp[j]) + v);
  r.witness_p = r.witness_q = Rp * contact_point(ap, aq, unit) + tp_world;
  return r;
}

}  // namespace pendepth::convex3
