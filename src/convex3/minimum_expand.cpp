// Exact minimum depth σ = dist(0, ∂M) and directional depth σ_d (Phase D), M = P ⊕ (−Q'), by
// certified expansion of an inner polytope of M: the Expanding Polytope Algorithm (van den Bergen
// 2001; Ericson, Real-Time Collision Detection §9.5) made exact. DEPARTURE from DHS §5: the paper
// computes σ from the explicit M (O(n²)); this is output-sensitive instead — the work is
// proportional to the number of support queries, each an exact warm-started hill climb. The
// O(n·m) enumeration of every implicit facet normal (minkowski_facets.cpp) stays as the test
// reference.
//
// Notation: P fixed (its own frame), Q' = R Q + t with t = tq − tp (exact semantics for the
// doubles R, tq, tp, as in minkowski_facets.hpp). A point of M is kept symbolically as a pair
// (i, j): m = p_i − q'_j, a polynomial of degree 2 in the inputs. K = the current polytope.
//
// Why the answer is exact:
//  * K's vertices are points of M, its triangles are oriented outward and it is convex: a
//    point is added only if it is strictly beyond the expanded facet, and a facet is replaced
//    only if the point is strictly beyond its plane (exact orient3d of pair points; "on the
//    plane" = not visible, so coplanar facets stay and no flat triangle is ever created; the
//    visible facets form a disc, so the horizon is one cycle). Hence K ⊆ M.
//  * Support of M along u: h_M(u) = max u·p − min u·q', each by hill climbing over the vertex
//    adjacency (on a convex polytope a vertex with no strictly better neighbour is a global
//    maximiser, ties included); every "strictly better" is an exact sign.
//  * Phase A (is 0 in int M?): while some facet F of K has 0 on or beyond its plane (exact sign
//    of h_F = n_F·a), take the most violated one and the support s along n_F. If n_F·s ≤ 0,
//    the plane {n_F·x = 0} supports M with 0 on it or outside: not overlapping, depth 0
//    (touching = 0). Otherwise s is strictly beyond F: expand.
//  * Phase B (0 strictly inside K): take the facet F of K nearest to 0 (least rigorous lower
//    bound of the squared plane distance), get the support s along n_F. If s lies exactly on
//    F's plane, that plane supports M: σ ≤ d_F. Since K ⊆ M, σ ≥ dist(0, ∂K) = min over K's
//    facets of the plane distance. So σ = d_F once no facet of K is exactly nearer: facets whose
//    lower bound is below an upper bound of d_F are discarded if coplanar with F, else
//    refined, and remaining near ties are decided exactly (sign of h_F²|n_G|² − h_G²|n_F|²).
//    The upper bound is rigorous from F's rounded values (upper_key: h̃ + he over |ñ| − |ne|),
//    so F itself is refined only if it is the answer's facet (canonical_result) — once per
//    query instead of once per new best facet, the same decisions and answers bit for bit.
//    Otherwise s is strictly beyond F: expand. Every step adds a new pair, so the loop ends.
//  * Values: d_F = h_F/|n_F| from h_F and |n_F|² in double-double with a rigorous error bound
//    (exact rationals when that bound is not within half an ulp): within ~2 ulps.
//  * Phase D (σ_d along d, instead of Phase B; a ray cast by expanding polytope): 0 ∈ int K, so
//    the cones from 0 over K's facets partition space. Take the facet F of K through which the
//    ray s·d (s > 0) leaves K — its closed cone contains d: the exact signs of det(m_a, m_b, d),
//    det(m_b, m_c, d), det(m_c, m_a, d) are >= 0 — and the support s along n_F. If s lies exactly
//    on F's plane, that plane supports M (K ⊆ M below it) and the ray's exit point from K, on F,
//    is its exit from M: σ_d = h_F·|d| / (n_F·d). Otherwise s is strictly beyond F: expand. After
//    an expansion the exit point lies on a facet of the new cone (beyond the old exit point it
//    is on no old facet; at the old exit point it is on the horizon), so only those are tested.
//    Ties (the ray through an edge or vertex of K) may pick any facet containing the exit point.
//    σ_d = (h_F / (n_F·d))·|d| in double-double from values within 2^-60 (rationals when the
//    bound fails), rounded once: within ~half an ulp. Not overlapping (Phase A): depth 0.
//    DEPARTURE from DHS §5.2 (Compute-Depth-3D on the DK hierarchies, O(log n · log m)): output-
//    sensitive like σ and an order of magnitude faster on every input measured, but with no
//    useful worst-case bound (hub vertices make climbs long; k is at most n·m). So Phases A and
//    D count their work (neighbours scanned by the climbs, facets scanned or built) and give up
//    past a budget: depth3.cpp then runs Compute-Depth-3D, which keeps the O(log n · log m)
//    bound (budget: minimum_expand.hpp, measured work: docs/benchmarks.md).
// Predicates: a semi-static filter (uniform per-query bounds on every rounded quantity, from
// the coordinate extents), then exact::exact_sign (running-error double of the full polynomial,
// then GMP). Rounded points are taken relative to reference vertices of P and Q, so offsets of
// the shapes or of the placement do not widen the bounds. Identities that hold by construction
// (a facet's own vertices, the fourth corner of an edge–edge parallelogram, pairs sharing a P or
// a Q index) are recognised symbolically, so the exact zeros met at every termination never
// reach the exact fallback.
//
// Result (σ), canonical: a function of the facets of M at distance σ, never of K — which depends
// on the start (a warm start, survey §3.3) and triangulates a polygonal facet of M in many ways.
// Phase B also expands K's facets exactly as near as the best one on other planes until each is
// on a facet of M, so every facet of M at distance σ is known; the answer ends on the least of
// them by (feature kinds, coordinates of three spanning pairs). Features: a face of P and the
// lexicographically least vertex of Q's support set, a vertex of P (least) and a face of Q, or
// two edges (P's face preferred, as in minkowski_facets); a face is reported by its least
// triangle id (flat faces, their least vertex and boundary neighbours: per-shape tables of
// vertex_adjacency.cpp, O(1) per query). Depth, normal and witnesses are computed from three pairs the features fix (the
// face's least vertex and its two boundary neighbours with Q's vertex; P's vertex with Q's
// triangle; the edges' least endpoints): depth = d_F, lower_bound = upper_bound = depth,
// witnesses = the contact point after the move as in the reference (depth3.cpp): Q's vertex
// moved onto P's face, P's vertex, or the crossing of the two edges; for parallel features
// (face–face, face–edge) a point of the contact region (contact_point). candidates = the number of
// support queries (the only field a start changes). Vertex choices are by coordinates, so a hull
// rebuilt with another vertex numbering answers the same bits (feature indices aside).
// Warm start (ExpandSeed): the previous answer's three pairs (points of M at every pose) and the
// support along the opposite of their normal make the first tetrahedron, then the pairs of the
// neighbouring facets of the previous K are inserted where they lie strictly beyond a facet; Phase
// A and B proceed as from a cold start. Measured: half the support queries on small steps, about
// the same time (docs/benchmarks.md); gated off above 128 vertices per shape and when 0 is no
// longer inside the seed facet's plane (heuristics: any start gives the same answer).
// Result (σ_d): kind Directional, depth = lower = upper bound, translation = σ_d·d̂, normal = d̂,
// facet_normal = n_F/|n_F|, the same features, witnesses = the exit point t·d as a convex
// combination of F's pairs (weights from the accurate dets above), candidates = support queries.
// Complexity: O(k (f + c)) for k support queries, f the facets of K (a branch-free scan for
// the nearest one; f = O(k)), c the climb length (O(1) from warm starts or the cube-map seeds
// of vertex_adjacency.cpp). k is at most n·m in theory; measured counts: docs/benchmarks.md
// (tests/convex3/test_minimum_fast.cpp prints them).
#include "convex3/minimum_expand.hpp"

#include "convex3/polytope_data.hpp"
#include "geometry/exact.hpp"
#include "geometry/isa.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace pendepth::convex3 {

namespace {

using exact::certified_sign;
using predicates::orient3d;
using exact::exact_sign;
using exact::safe_bound;

constexpr double kU = exact::kUnit;       // unit roundoff 2^-53
constexpr double kInflate = 1 + 0x1p-20;  // covers the rounding of the bound formulas themselves
constexpr int kSeedMinK = 4;              // cube maps this fine (n > 54) also seed warm starts

// ---- double-double numbers with a running absolute error bound (accurate distances) ----------
struct DD {
  double hi = 0, lo = 0, e = 0;
};
constexpr double kDDRel = 0x1p-100;    // >= relative error of one operation below (<= 4u²)
constexpr double kDDTiny = 0x1p-1000;  // absolute slack for underflow

inline void two_sum(double a, double b, double& s, double& t) {
  s = a + b;
  double bb = s - a;
  t = (a - (s - bb)) + (b - bb);
}
inline void fast_two_sum(double a, double b, double& s, double& t) {
  s = a + b;
  t = b - (s - a);
}
// Joldes, Muller, Popescu 2017: AccurateDWPlusDW (relative error <= 3u² + 13u³).
[[gnu::always_inline]] inline DD operator+(const DD& x, const DD& y) {
  double sh, sl, th, tl, vh, vl, zh, zl;
  two_sum(x.hi, y.hi, sh, sl);
  two_sum(x.lo, y.lo, th, tl);
  fast_two_sum(sh, sl + th, vh, vl);
  fast_two_sum(vh, tl + vl, zh, zl);
  return {zh, zl, x.e + y.e + std::abs(zh) * kDDRel + kDDTiny};
}
inline DD operator-(const DD& x) { return {-x.hi, -x.lo, x.e}; }
inline DD operator-(const DD& x, const DD& y) { return x + (-y); }
// Same paper: DWTimesDW3 (relative error <= 4u²). std::fma is a library call in the portable
// build (no -mfma; the x86-64-v3 clone expand_v3 below has the instruction, geometry/isa.hpp),
// which also spills every live double: the two fmas of cl2 are skipped when
// both low parts are zero (lifted doubles: the products of m_l and the per-query constants).
// The same bits: cl2 is ±0 then, cl1 is +0 or nonzero (an exact fma result of 0 is +0), so
// cl1 + cl2 = cl1 + 0; a NaN or infinite cl2 comes with a NaN or infinite ch and cl1 anyway.
[[gnu::always_inline]] inline DD operator*(const DD& x, const DD& y) {
  double ch = x.hi * y.hi;
  double cl1 = std::fma(x.hi, y.hi, -ch);
  double cl2 = x.lo == 0 && y.lo == 0 ? 0.0 : std::fma(x.lo, y.hi, std::fma(x.hi, y.lo, x.lo * y.lo));
  double zh, zl;
  fast_two_sum(ch, cl1 + cl2, zh, zl);
  double ax = std::abs(x.hi) * (1 + 0x1p-51), ay = std::abs(y.hi) * (1 + 0x1p-51);
  return {zh, zl, ax * y.e + ay * x.e + x.e * y.e + std::abs(zh) * kDDRel + kDDTiny};
}
struct LiftDD {
  DD operator()(double x) const { return {x, 0, 0}; }
};

/// f's value to within ~half an ulp: double-double, exact rationals when the bound is too wide.
template <class F>
double accurate(F&& f) {
  DD r = f(LiftDD{});
  if (std::isfinite(r.hi) && std::isfinite(r.e) && safe_bound(r.e) <= std::abs(r.hi) * 0x1p-60) return r.hi;
  return exact::cold_eval(f, exact::LiftQ{}).v.get_d();
}

// ---- small vectors of lifted numbers ----------------------------------------------------------
template <class T>
using V3 = std::array<T, 3>;
template <class L>
using Num = decltype(std::declval<L>()(0.0));

template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// ---- symbolic identities of a triangle of pairs (i_k, j_k) ------------------------------------
// n = (m_b − m_a) × (m_c − m_a) is orthogonal to every integer combination of m_b − m_a and
// m_c − m_a. Pairs sharing j differ by p_i − p_i' exactly; pairs sharing i by −R(q_j − q_j').
// With exactly two P indices {i1, i2} and two Q indices {j1, j2} (three corners of an edge–edge
// parallelogram), n ∥ (p_i2 − p_i1) × R(q_j2 − q_j1).
struct Pairs {
  std::array<int, 3> i{}, j{};
};

bool two_by_two(const Pairs& t, int& i1, int& i2, int& j1, int& j2) {
  i1 = t.i[0], i2 = t.i[1] != i1 ? t.i[1] : t.i[2];
  j1 = t.j[0], j2 = t.j[1] != j1 ? t.j[1] : t.j[2];
  if (i1 == i2 || j1 == j2) return false;
  for (int k = 0; k < 3; ++k)
    if ((t.i[k] != i1 && t.i[k] != i2) || (t.j[k] != j1 && t.j[k] != j2)) return false;
  return true;
}
// n·(m_(xi,xj) − m_a) is identically 0.
bool zero_orient(const Pairs& t, int xi, int xj) {
  for (int k = 0; k < 3; ++k)
    if (t.i[k] == xi && t.j[k] == xj) return true;
  int i1, i2, j1, j2;
  return two_by_two(t, i1, i2, j1, j2) && (xi == i1 || xi == i2) && (xj == j1 || xj == j2);
}
// n·(p_w − p_v) (of_p) or n·R(q_w − q_v) (!of_p) is identically 0.
bool zero_pair(const Pairs& t, bool of_p, int v, int w) {
  if (v == w) return true;
  const auto& x = of_p ? t.i : t.j;
  const auto& y = of_p ? t.j : t.i;
  for (int k = 0; k < 3; ++k)
    for (int l = k + 1; l < 3; ++l)
      if (y[k] == y[l] && ((x[k] == v && x[l] == w) || (x[k] == w && x[l] == v))) return true;
  int i1, i2, j1, j2;
  if (!two_by_two(t, i1, i2, j1, j2)) return false;
  int a = of_p ? i1 : j1, b = of_p ? i2 : j2;
  return (v == a && w == b) || (v == b && w == a);
}

// ---- the expansion ---------------------------------------------------------------------------
// Rounded points are formed relative to reference vertices c_P, c_Q (so that offsets of the
// shapes or of the placement do not widen the bounds): m̂ = (p − c_P) − R(q − c_Q) − τ̂ with
// τ = t + R c_Q − c_P (double-double, then rounded). Per query, uniform bounds on every rounded
// quantity (from the coordinate extents) give semi-static filters.
struct Vert {
  int i = -1, j = -1;
  double mh[3];  // m̂ (rounded p_i − q'_j)
};

struct Facet {
  std::array<int, 3> v{}, nb{};  // vertices CCW from outside; nb[k] across edge v[k] -> v[k+1]
  double n[3];                   // rounded outward normal (m_b − m_a) × (m_c − m_a)
  double h = 0, he = 0;          // rounded n·m_a (> 0: 0 strictly inside the half-space), bound
  double eo = 0;                 // bound of the rounded orient() value
  double dist = 0;               // accurate distance (once refined)
  double unit[3];                // n/|n| from the double-double normal (once refined)
  int hsign = 1;                 // Phase A: exact sign of h
  int mark = 0;                  // search stamp (find_horizon, the warm seed's walk)
  int pos = -1;                  // index in the live list alive_ (−1: dead)
  bool refined = false;
};

// A direction of support queries, known exactly as a polynomial.
struct Dir {
  enum Kind { Vector, Normal, Cross } kind = Vector;
  Vec3 d{0, 0, 0};             // Vector: the direction; Cross: (m_b − m_a) × d
  int a = -1, b = -1, c = -1;  // Normal: triangle a, b, c; Cross: a, b
  int sgn = 1;
  Vec3 n{0, 0, 0}, w{0, 0, 0};  // rounded direction and Rᵀ direction
  double ep = 0, eq = 0;        // bounds of the rounded P / Q comparisons (climbs)
  double es = 0, e0 = 0;        // bounds of the rounded n·(m_x − m_a) and n·m_x
  bool structural = false;      // Normal: the identities of `t` hold
  Pairs t;
};

// A stack of trivially copyable T whose storage only grows (clear() keeps it): push_back is a
// compare and a store, emplace_back() hands out a slot without initialising it (the caller sets
// every field). References are invalidated by growth, as with std::vector.
template <class T>
class Stack {
 public:
  Stack() = default;
  Stack(const Stack&) = delete;
  Stack& operator=(const Stack&) = delete;
  std::size_t size() const { return n_; }
  void clear() { n_ = 0; }
  T& operator[](std::size_t k) { return p_[k]; }
  const T& operator[](std::size_t k) const { return p_[k]; }
  T* begin() { return p_; }
  T* end() { return p_ + n_; }
  const T* begin() const { return p_; }
  const T* end() const { return p_ + n_; }
  T& back() { return p_[n_ - 1]; }
  void pop_back() { --n_; }
  [[gnu::always_inline]] void push_back(const T& x) {
    if (n_ == cap_) grow();
    p_[n_++] = x;
  }
  [[gnu::always_inline]] T& emplace_back() {
    if (n_ == cap_) grow();
    return p_[n_++];
  }
  void assign(std::size_t k, const T& x) {
    clear();
    for (std::size_t i = 0; i < k; ++i) push_back(x);
  }

 private:
  [[gnu::noinline]] void grow() {
    b_.resize(std::max<std::size_t>(64, 2 * b_.size()));
    p_ = b_.data(), cap_ = b_.size();
  }
  std::vector<T> b_;  // owns the storage; p_, cap_ mirror it
  T* p_ = nullptr;
  std::size_t n_ = 0, cap_ = 0;
};

// The support set of a shape on a facet of M (canonical answer: contact_point): vertices,
// boundary segments and triangles of a face.
struct SupportSet {
  std::vector<int> verts;
  std::vector<std::array<int, 2>> edges;
  std::vector<std::array<int, 3>> tris;
};

// Scratch arrays reused across queries of one thread (no allocation in steady state).
struct Workspace {
  SupportSet sp, sq;  // contact_point
  Stack<Vert> V;
  Stack<Facet> F;
  Stack<int> vis;
  std::vector<int> by_start, by_end;
  Stack<std::pair<int, int>> hor;
  Stack<int> alive;  // live facets (dense); each facet's index there is Facet::pos
  Stack<double> keys;     // Phase B key of alive[k]; +inf: not a candidate
  std::vector<int> ties, face;  // Phase B: facets exactly as near as the best; a flat face's triangles
  std::vector<int> face_verts;  // the warm seed: vertices of the answer's flat face
};

// Inlining (a hot path tuned by instruction counts): the named steps are [[gnu::always_inline]],
// compiled into their callers as when they were written there; init_tetrahedron and phase_b stay
// out of line ([[gnu::noinline]]) and the double-double operations inline, as GCC chose for the
// former single functions, which the split would otherwise change (measured: docs/benchmarks.md).
// σ_d (Phase D) instantiates the class a second time, with work counting (kBudget); the
// constructor, phase_a and facet_dir are forced inline so that σ's instantiation keeps GCC's
// former choices (σ within 0.5 % of its instruction count before Phase D existed).
// kBudget: count the work and give up past budget_ (σ_d); σ compiles without either.
template <bool kBudget>
class Expander {
 public:
  [[gnu::always_inline]] Expander(const ConvexPolytope& Pp, const ConvexPolytope& Qp, const RelativePose& rel, Workspace& ws)
      : P_(convex3::data_of(Pp)), Q_(convex3::data_of(Qp)), AP_(vertex_adjacency(P_)), AQ_(vertex_adjacency(Q_)), R_(rel.R),
        V_(ws.V), F_(ws.F), vis_(ws.vis), by_start_(ws.by_start), by_end_(ws.by_end),
        hor_(ws.hor), alive_(ws.alive), keys_(ws.keys), ties_(ws.ties), face_(ws.face), face_verts_(ws.face_verts), sp_(ws.sp), sq_(ws.sq) {
    V_.clear(), F_.clear(), alive_.clear(), keys_.clear();
    init_coordinate_bounds(rel);
    init_normal_bounds();
    fold_facet_constants();
  }

  // σ: the minimum depth in the world frame of P's pose (Rp, tp); a Depth3 with only
  // `candidates` set when the shapes do not overlap (touching included).
  // With a seed (warm start): the first K is built on the seed's facet when it is valid, and the
  // seed receives the answer's facet (invalid when the shapes do not overlap).
  Depth3 run(const Eigen::Matrix3d& Rp, const Vec3& tp, ExpandSeed* seed) {
    if (!(seed && seed->valid && warm_start(*seed))) {
      [[maybe_unused]] const bool built = init_tetrahedron();  // σ has no budget
      assert(built);
    }
    if (phase_a() != Overlap::Yes) {
      if (seed) seed->valid = false;
      Depth3 none;
      none.candidates = iters_;
      return none;
    }
    const int b = phase_b();
    return canonical_result(b, Rp, tp, seed);
  }

  // σ_d along d (P's frame; nonzero, finite, largest |coordinate| in [1/2, 1) so that no product
  // over- or underflows): the exit of the ray s·d (s > 0) from M, in the world frame of P's pose.
  // A Depth3 with only `kind` and `candidates` set when the shapes do not overlap; nullopt when
  // the work exceeded `budget` (see work_).
  std::optional<Depth3> run_directional(const Vec3& d, const Eigen::Matrix3d& Rp, const Vec3& tp,
                                        std::size_t budget) {
    budget_ = budget;
    if (!init_tetrahedron()) return std::nullopt;
    const Overlap o = phase_a();
    if (o == Overlap::Exhausted) return std::nullopt;
    if (o == Overlap::No) {
      Depth3 none;
      none.kind = DepthKind::Directional;
      none.candidates = iters_;
      return none;
    }
    init_direction(d);
    const int f = phase_d();
    if (f < 0) return std::nullopt;
    return directional_result(f, Rp, tp);
  }
  std::size_t work() const { return work_; }

  // Tests: Phase B refines each new best facet at once (the path before upper_key).
  void set_eager_refine(bool on) { eager_refine_ = on; }
  // Tests: over K's live facets after run(), the number of failed links in the chain of bounds
  // behind upper_key() and lower_key(), each checked exactly (rationals): |h̃ − h| <= he,
  // |ñ − n| <= |ne|, hu >= h̃ + he, (nl + |ne|)² <= ñ·ñ, upper_key >= hu²/nl², and finally
  // lower_key <= (h/|n|)² <= upper_key. Each margin of upper_key() is needed by one link, so
  // dropping any of them fails here on some facets. `checked` receives the facets compared.
  int key_violations(int& checked) const {
    int bad = 0;
    checked = 0;
    using Q = mpq_class;
    for (int f : alive_) {
      const Facet& F = F_[f];
      const auto& v = F.v;
      const exact::LiftQ L;
      const auto n = normal_l(L, v[0], v[1], v[2]);
      const Q h = dot(n, m_l(L, V_[v[0]])).v, n2 = dot(n, n).v;
      if (h <= 0 || n2 == 0) continue;
      ++checked;
      const Q d2 = h * h / n2;
      const Q ht(F.h), he(F.he), ne(ne_norm_);
      bad += abs(Q(ht - h)) > he;
      Q diff2 = 0, nt2 = 0;
      for (int k = 0; k < 3; ++k) diff2 += (Q(F.n[k]) - n[k].v) * (Q(F.n[k]) - n[k].v), nt2 += Q(F.n[k]) * Q(F.n[k]);
      bad += diff2 > ne * ne;
      double hu, nl;
      if (upper_parts(f, hu, nl)) {
        bad += Q(hu) < ht + he;
        bad += (Q(nl) + ne) * (Q(nl) + ne) > nt2;
        bad += Q(upper_key(f)) < Q(hu) * Q(hu) / (Q(nl) * Q(nl));
        bad += Q(upper_key(f)) < d2;
      }
      bad += Q(lower_key(f)) > d2;
    }
    return bad;
  }

 private:
  const PolytopeData& P_;
  const PolytopeData& Q_;
  const VertexAdjacency& AP_;
  const VertexAdjacency& AQ_;
  Eigen::Matrix3d R_;
  Vec3 cp_, cq_;
  double thi_[3], tlo_[3], tau_[3];
  double ext_p_[3], bd_[3], ed_[3], B_[3], mb_[3], em_[3], ne_[3], ne_norm_, ed_max_;
  double co_, bo_[3], ch_, bh_[3], cep_, bp_[3], ceq_, bqn_[3], bqw_[3];
  Stack<Vert>& V_;
  Stack<Facet>& F_;
  Stack<int>& vis_;
  std::vector<int>& by_start_;
  std::vector<int>& by_end_;
  Stack<std::pair<int, int>>& hor_;
  Stack<int>& alive_;
  Stack<double>& keys_;
  std::vector<int>& ties_;
  std::vector<int>& face_;
  std::vector<int>& face_verts_;
  SupportSet& sp_;
  SupportSet& sq_;
  int stamp_ = 0;
  std::size_t iters_ = 0;
  int cone_first_ = 0;  // first facet of the last cone built
  // Elementary steps so far (neighbours scanned by the climbs, facets scanned, visited or built)
  // and the limit above which Phases A and D give up (σ: none).
  mutable std::size_t work_ = 0;
  std::size_t budget_ = std::numeric_limits<std::size_t>::max();
  bool eager_refine_ = false;
  enum class Overlap { No, Yes, Exhausted };
  // Phase D: the query direction (P's frame, scaled by a power of two) and the bound of the
  // rounded det(m̂_a, m̂_b, d).
  Vec3 dir_{0, 0, 0};
  double edet_ = 0;

  enum class Mode { A, B, D };  // which phase expands: what a new facet needs

  // ---- per-query bounds (semi-static filters) -------------------------------------------------
  // The reference vertices c_P, c_Q, t = tq − tp exactly (thi_ + tlo_), τ̂, and per coordinate the
  // bounds of |m|, |m̂ − m|, |m_x − m_a| and its rounding error (mb_, em_, bd_, ed_, B_).
  [[gnu::always_inline]] void init_coordinate_bounds(const RelativePose& rel) {
    const Vec3 &cp = P_.v[0], &cq = Q_.v[0];
    cp_ = cp, cq_ = cq;
    for (int k = 0; k < 3; ++k) {
      two_sum(rel.tq[k], -rel.tp[k], thi_[k], tlo_[k]);  // t = tq − tp exactly
      DD tau = (DD{thi_[k]} + DD{tlo_[k]}) +
               ((DD{R_(k, 0)} * DD{cq[0]} + DD{R_(k, 1)} * DD{cq[1]}) + DD{R_(k, 2)} * DD{cq[2]}) - DD{cp[k]};
      tau_[k] = tau.hi;
      double tau_err = std::abs(tau.lo) + safe_bound(tau.e);
      double ep = AP_.extent[k] * (1 + 4 * kU), erq = 0;
      for (int l = 0; l < 3; ++l) erq += std::abs(R_(k, l)) * AQ_.extent[l] * (1 + 4 * kU);
      double dp = kU * ep, dr = 4.03 * kU * erq;  // |fl(p − c_P) − (p − c_P)|, same for R(q − c_Q)
      ext_p_[k] = ep;
      mb_[k] = (ep + erq + std::abs(tau_[k]) + tau_err) * kInflate;                // >= |m_k|
      em_[k] = (dp + dr + tau_err + 2.02 * kU * mb_[k]) * kInflate + exact::kTiny;  // >= |m̂_k − m_k|
      bd_[k] = (ep + erq) * kInflate;                                             // >= |m_x − m_a|_k
      ed_[k] = (2 * em_[k] + 1.01 * kU * (bd_[k] + 2 * em_[k])) * kInflate;       // >= |D̂_k − D_k|
      B_[k] = bd_[k] + ed_[k];                                                    // >= |D̂_k|
    }
  }

  // ne_: the error bound of a rounded facet normal (cross product of two rounded differences),
  // its norm ne_norm_, and ed_max_.
  [[gnu::always_inline]] void init_normal_bounds() {
    double nn = 0;
    for (int k = 0; k < 3; ++k) {  // cross product of two rounded differences
      int y = (k + 1) % 3, z = (k + 2) % 3;
      ne_[k] = (2 * (ed_[y] * bd_[z] + B_[y] * ed_[z]) + 4.02 * kU * B_[y] * B_[z]) * kInflate + exact::kTiny;
      nn += ne_[k] * ne_[k];
    }
    ne_norm_ = std::sqrt(nn) * kInflate;
    ed_max_ = std::max({ed_[0], ed_[1], ed_[2]});
  }

  // The constants of the facet bounds (he, eo of add_facet; ep, eq of facet_dir), affine in |n_k|
  // (and |w_l|): co_, bo_, ch_, bh_, cep_, bp_, ceq_, bqn_, bqw_.
  [[gnu::always_inline]] void fold_facet_constants() {
    // The bounds below are affine in |n_k| (and |w_l|) for facet normals: fold the constants.
    // kInflate also covers the rounding of the short sums that evaluate them.
    co_ = ch_ = cep_ = ceq_ = exact::kTiny;
    for (int k = 0; k < 3; ++k) {
      double eq = AQ_.extent[k] * (1 + 4 * kU), rq = 0, rne = 0;
      for (int l = 0; l < 3; ++l) rq += std::abs(R_(k, l)) * AQ_.extent[l] * (1 + 4 * kU);
      for (int l = 0; l < 3; ++l) rne += std::abs(R_(k, l)) * ne_[k] * AQ_.extent[l] * (1 + 4 * kU);
      ch_ += kInflate * ne_[k] * mb_[k];
      bh_[k] = kInflate * (em_[k] + 3.02 * kU * (mb_[k] + em_[k]));
      co_ += 2 * kInflate * ne_[k] * mb_[k];  // orient = n·m̂_x − h̃: twice he, plus a rounding
      bo_[k] = 2 * bh_[k] + kInflate * 2.02 * kU * (mb_[k] + em_[k]);
      cep_ += kInflate * ne_[k] * ext_p_[k];
      bp_[k] = kInflate * 4.02 * kU * ext_p_[k];
      ceq_ += kInflate * kInflate * rne;
      bqn_[k] = kInflate * kInflate * 3.02 * kU * rq;
      bqw_[k] = kInflate * 4.02 * kU * eq;
    }
  }

  Pairs pairs(int a, int b, int c) const {
    return {{V_[a].i, V_[b].i, V_[c].i}, {V_[a].j, V_[b].j, V_[c].j}};
  }

  // ---- polynomials, written once for every number type (exact fallbacks, accurate values) ----
  template <class L>
  V3<Num<L>> diff_l(L lift, const Vert& x, const Vert& a) const {  // m_x − m_a
    V3<Num<L>> d;
    const Vec3 &px = P_.v[x.i], &pa = P_.v[a.i];
    for (int k = 0; k < 3; ++k) d[k] = x.i == a.i ? lift(0.0) : lift(px[k]) - lift(pa[k]);
    if (x.j != a.j) {
      const Vec3 &qx = Q_.v[x.j], &qa = Q_.v[a.j];
      V3<Num<L>> dq{lift(qx[0]) - lift(qa[0]), lift(qx[1]) - lift(qa[1]), lift(qx[2]) - lift(qa[2])};
      for (int k = 0; k < 3; ++k)
        d[k] = d[k] - (lift(R_(k, 0)) * dq[0] + lift(R_(k, 1)) * dq[1] + lift(R_(k, 2)) * dq[2]);
    }
    return d;
  }
  template <class L>
  V3<Num<L>> m_l(L lift, const Vert& x) const {  // p_i − (R q_j + t)
    const Vec3 &p = P_.v[x.i], &q = Q_.v[x.j];
    V3<Num<L>> m;
    for (int k = 0; k < 3; ++k)
      m[k] = lift(p[k]) - (lift(R_(k, 0)) * lift(q[0]) + lift(R_(k, 1)) * lift(q[1]) + lift(R_(k, 2)) * lift(q[2]) +
                           lift(thi_[k]) + lift(tlo_[k]));
    return m;
  }
  template <class L>
  V3<Num<L>> normal_l(L lift, int a, int b, int c) const {
    return cross(diff_l(lift, V_[b], V_[a]), diff_l(lift, V_[c], V_[a]));
  }
  template <class L>
  V3<Num<L>> dir_l(L lift, const Dir& D) const {
    V3<Num<L>> n;
    if (D.kind == Dir::Vector) {
      n = {lift(D.d[0]), lift(D.d[1]), lift(D.d[2])};
    } else if (D.kind == Dir::Normal) {
      n = normal_l(lift, D.a, D.b, D.c);
    } else {
      n = cross(diff_l(lift, V_[D.b], V_[D.a]), V3<Num<L>>{lift(D.d[0]), lift(D.d[1]), lift(D.d[2])});
    }
    if (D.sgn < 0)
      for (auto& x : n) x = -x;
    return n;
  }

  // ---- rounded values ---------------------------------------------------------------------
  static void diff_r(const Vert& x, const Vert& a, double d[3]) {  // D̂ = m̂_x − m̂_a, see ed_
    for (int k = 0; k < 3; ++k) d[k] = x.mh[k] - a.mh[k];
  }
  static void cross_r(const double a[3], const double b[3], double n[3]) {
    n[0] = a[1] * b[2] - a[2] * b[1];
    n[1] = a[2] * b[0] - a[0] * b[2];
    n[2] = a[0] * b[1] - a[1] * b[0];
  }
  // Bounds of n·(m_x − m_a) and n·m_x for a rounded n with error nerr.
  double bound_side(const double n[3], const double nerr[3]) const {
    double e = 0;
    for (int k = 0; k < 3; ++k) e += nerr[k] * bd_[k] + std::abs(n[k]) * (ed_[k] + 3.02 * kU * B_[k]);
    return e * kInflate + exact::kTiny;
  }
  double bound_zero(const double n[3], const double nerr[3]) const {
    double e = 0;
    for (int k = 0; k < 3; ++k) e += nerr[k] * mb_[k] + std::abs(n[k]) * (em_[k] + 3.02 * kU * (mb_[k] + em_[k]));
    return e * kInflate + exact::kTiny;
  }

  int add_vert(int i, int j) {
    Vert x;
    x.i = i, x.j = j;
    const Vec3 &p = P_.v[i], &q = Q_.v[j];
    double dq[3] = {q[0] - cq_[0], q[1] - cq_[1], q[2] - cq_[2]};
    for (int k = 0; k < 3; ++k)
      x.mh[k] = ((p[k] - cp_[k]) - (R_(k, 0) * dq[0] + R_(k, 1) * dq[1] + R_(k, 2) * dq[2])) - tau_[k];
    V_.push_back(x);
    return static_cast<int>(V_.size()) - 1;
  }

  int add_facet(int a, int b, int c) {
    const int id = static_cast<int>(F_.size());
    Facet& f = F_.emplace_back();  // a recycled slot: every field is set here
    f.v = {a, b, c};
    f.nb = {-1, -1, -1};
    f.dist = 0;
    f.hsign = 1;
    f.refined = false;
    double d1[3], d2[3];
    diff_r(V_[b], V_[a], d1);
    diff_r(V_[c], V_[a], d2);
    cross_r(d1, d2, f.n);
    const double* m = V_[a].mh;
    f.h = f.n[0] * m[0] + f.n[1] * m[1] + f.n[2] * m[2];
    const double a0 = std::abs(f.n[0]), a1 = std::abs(f.n[1]), a2 = std::abs(f.n[2]);
    f.he = ch_ + a0 * bh_[0] + a1 * bh_[1] + a2 * bh_[2];  // = bound_zero(n, ne_)
    f.eo = co_ + a0 * bo_[0] + a1 * bo_[1] + a2 * bo_[2];  // = bound_side(n, ne_)
    f.mark = 0;
    f.pos = static_cast<int>(alive_.size());
    alive_.push_back(id);
    keys_.push_back(std::numeric_limits<double>::infinity());
    return id;
  }
  void kill(int f) {
    int k = F_[f].pos, last = alive_.back();
    alive_[k] = last, keys_[k] = keys_.back(), F_[last].pos = k;
    alive_.pop_back(), keys_.pop_back();
    F_[f].pos = -1;
  }

  // ---- exact predicates --------------------------------------------------------------------
  // Sign of n_abc·(m_x − m_a) when the four pairs share their Q vertex (then it is
  // orient3d(p_a, p_b, p_c, p_x)) or their P vertex (then −orient3d(q_a, q_b, q_c, q_x): with
  // u, v, w the differences of the q's, (Ru × Rv)·(−Rw) = −det(R)·(u × v)·w and det(R) > 0 for
  // the double matrix of a rotation); 2 otherwise. A degree-3 sign of input coordinates instead
  // of the degree-6 polynomial of pairs: the exact zeros of coplanar pairs (a polygonal facet of
  // M met again, e.g. by a warm start) cost far less.
  int shared_orient(int a, int b, int c, const Vert& X) const {
    const Vert &A = V_[a], &B = V_[b], &C = V_[c];
    if (A.j == X.j && B.j == X.j && C.j == X.j) return orient3d(P_.v[A.i], P_.v[B.i], P_.v[C.i], P_.v[X.i]);
    if (A.i == X.i && B.i == X.i && C.i == X.i) return -orient3d(Q_.v[A.j], Q_.v[B.j], Q_.v[C.j], Q_.v[X.j]);
    return 2;
  }
  // Sign of n_f·(m_x − m_a): > 0 iff x is strictly beyond facet f's plane.
  int orient(int f, int x) const {
    const Facet& F = F_[f];
    const Vert& X = V_[x];
    double s = (F.n[0] * X.mh[0] + F.n[1] * X.mh[1] + F.n[2] * X.mh[2]) - F.h;
    if (s > F.eo) return 1;
    if (s < -F.eo) return -1;
    if (zero_orient(pairs(F.v[0], F.v[1], F.v[2]), X.i, X.j)) return 0;
    if (const int o = shared_orient(F.v[0], F.v[1], F.v[2], X); o != 2) return o;
    const Vert& A = V_[F.v[0]];
    return exact_sign([&](auto L) { return dot(normal_l(L, F.v[0], F.v[1], F.v[2]), diff_l(L, X, A)); });
  }
  int hsign(int f) const {
    const Facet& F = F_[f];
    if (F.h > F.he) return 1;
    if (F.h < -F.he) return -1;
    const auto& v = F.v;
    return exact_sign([&](auto L) { return dot(normal_l(L, v[0], v[1], v[2]), m_l(L, V_[v[0]])); });
  }
  // Sign of D·(m_x − m_a).
  int dir_side(const Dir& D, int x, int a) const {
    const Vert &X = V_[x], &A = V_[a];
    if (X.i == A.i && X.j == A.j) return 0;
    if (D.structural && zero_orient(D.t, X.i, X.j)) return 0;
    if (D.kind == Dir::Cross && X.i == V_[D.b].i && X.j == V_[D.b].j) return 0;
    double d[3];
    diff_r(X, A, d);
    double s = D.n.dot(Vec3(d[0], d[1], d[2]));
    if (s > D.es) return 1;
    if (s < -D.es) return -1;
    return exact_sign([&](auto L) { return dot(dir_l(L, D), diff_l(L, X, A)); });
  }
  // Sign of D·m_x = h_M(D) when x is the support along D.
  int side0(const Dir& D, int x) const {
    const double* m = V_[x].mh;
    double s = D.n[0] * m[0] + D.n[1] * m[1] + D.n[2] * m[2];
    if (s > D.e0) return 1;
    if (s < -D.e0) return -1;
    return exact_sign([&](auto L) { return dot(dir_l(L, D), m_l(L, V_[x])); });
  }
  // cmp_p / cmp_q by orient3d of input points when D is the normal of a triangle of pairs sharing
  // their Q vertex (cmp_p: n·(p_w − p_v) = O(p_w) − O(p_v), O(x) = orient3d(p_a, p_b, p_c, x)) or
  // their P vertex (cmp_q: n·R(q_v − q_w) = det(R)·(O(q_v) − O(q_w)), see shared_orient), and the
  // two signs decide the difference (one is 0, or they differ); 2 otherwise.
  int shared_difference(const Dir& D, bool of_p, int v, int w) const {
    if (D.kind != Dir::Normal) return 2;
    const Vert &A = V_[D.a], &B = V_[D.b], &C = V_[D.c];
    int ov, ow;
    // O(x) = 0 by construction when x is one of the triangle's own vertices (the climbs and the
    // support features start there): no orient3d, whose exact zeros are its slowest case.
    auto o = [](const PolytopeData& S, int a, int b, int c, int x) {
      return x == a || x == b || x == c ? 0 : orient3d(S.v[a], S.v[b], S.v[c], S.v[x]);
    };
    if (of_p && A.j == B.j && B.j == C.j) {
      ov = o(P_, A.i, B.i, C.i, v), ow = o(P_, A.i, B.i, C.i, w);
      std::swap(ov, ow);  // the sign of O(w) − O(v)
    } else if (!of_p && A.i == B.i && B.i == C.i) {
      ov = o(Q_, A.j, B.j, C.j, v), ow = o(Q_, A.j, B.j, C.j, w);
    } else {
      return 2;
    }
    // Now the sign wanted is D.sgn · sign(O1 − O2) with O1 ~ ov, O2 ~ ow.
    if (ow == 0) return D.sgn * ov;
    if (ov == 0) return -D.sgn * ow;
    if (ov != ow) return D.sgn * ov;
    return 2;
  }
  // Sign of D·(p_w − p_v) (> 0: w is a strictly better P support).
  int cmp_p(const Dir& D, int v, int w) const {
    const Vec3 &pv = P_.v[v], &pw = P_.v[w];
    double s = D.n.dot(pw - pv);
    if (s > D.ep) return 1;
    if (s < -D.ep) return -1;
    if (v == w || (D.structural && zero_pair(D.t, true, v, w))) return 0;
    if (const int o = shared_difference(D, true, v, w); o != 2) return o;
    return exact_sign([&](auto L) {
      V3<Num<decltype(L)>> e{L(pw[0]) - L(pv[0]), L(pw[1]) - L(pv[1]), L(pw[2]) - L(pv[2])};
      return dot(dir_l(L, D), e);
    });
  }
  // Sign of D·R(q_v − q_w) (> 0: w is a strictly better Q' support, i.e. lower D·q').
  int cmp_q(const Dir& D, int v, int w) const {
    const Vec3 &qv = Q_.v[v], &qw = Q_.v[w];
    double s = D.w.dot(qv - qw);
    if (s > D.eq) return 1;
    if (s < -D.eq) return -1;
    if (v == w || (D.structural && zero_pair(D.t, false, v, w))) return 0;
    if (const int o = shared_difference(D, false, v, w); o != 2) return o;
    return exact_sign([&](auto L) {
      auto n = dir_l(L, D);
      V3<Num<decltype(L)>> e{L(qv[0]) - L(qw[0]), L(qv[1]) - L(qw[1]), L(qv[2]) - L(qw[2])};
      Num<decltype(L)> s = L(0.0);
      for (int k = 0; k < 3; ++k) s = s + n[k] * (L(R_(k, 0)) * e[0] + L(R_(k, 1)) * e[1] + L(R_(k, 2)) * e[2]);
      return s;
    });
  }

  // ---- directions and supports -------------------------------------------------------------
  // Fills w and the bounds from the rounded n and its error bound nerr.
  void finish_dir(Dir& D, const double nerr[3]) const {
    double n[3] = {D.n[0], D.n[1], D.n[2]}, werr[3];
    D.ep = D.eq = 0;
    for (int l = 0; l < 3; ++l) {
      D.w[l] = R_(0, l) * n[0] + R_(1, l) * n[1] + R_(2, l) * n[2];
      werr[l] = 0;
      for (int k = 0; k < 3; ++k) werr[l] += std::abs(R_(k, l)) * (nerr[k] + 3.02 * kU * std::abs(n[k]));
      D.ep += (nerr[l] + 4.02 * kU * std::abs(n[l])) * ext_p_[l];
      D.eq += (werr[l] * kInflate + 4.02 * kU * std::abs(D.w[l])) * AQ_.extent[l] * (1 + 4 * kU);
    }
    D.ep = D.ep * kInflate + exact::kTiny;
    D.eq = D.eq * kInflate + exact::kTiny;
    D.es = bound_side(n, nerr);
    D.e0 = bound_zero(n, nerr);
  }
  [[gnu::always_inline]] Dir facet_dir(int f) const {
    const Facet& F = F_[f];
    Dir D;
    D.kind = Dir::Normal;
    D.a = F.v[0], D.b = F.v[1], D.c = F.v[2];
    D.n = Vec3(F.n[0], F.n[1], F.n[2]);
    D.structural = true;
    D.t = pairs(D.a, D.b, D.c);
    // finish_dir(D, ne_) with the folded constants.
    const double a0 = std::abs(F.n[0]), a1 = std::abs(F.n[1]), a2 = std::abs(F.n[2]);
    D.w = R_.transpose() * D.n;
    D.ep = cep_ + a0 * bp_[0] + a1 * bp_[1] + a2 * bp_[2];
    D.eq = ceq_ + a0 * bqn_[0] + a1 * bqn_[1] + a2 * bqn_[2] + std::abs(D.w[0]) * bqw_[0] +
           std::abs(D.w[1]) * bqw_[1] + std::abs(D.w[2]) * bqw_[2];
    D.es = F.eo;
    D.e0 = F.he;
    return D;
  }

  // Hill climbing: steepest certified ascent by the rounded values, exact checks only for
  // neighbours the semi-static bound cannot separate from v.
  int climb_p(const Dir& D, int v) const { return climb(D, P_, AP_, D.n, D.ep, true, v); }
  int climb_q(const Dir& D, int v) const { return climb(D, Q_, AQ_, -D.w, D.eq, false, v); }
  // Maximises u·x over the vertices x of S (u = n for P, −Rᵀn for Q). The rounded edge vectors
  // are within u·extent of the exact ones, which eb accounts for; when eb is this small no
  // product can overflow, so no rounded value is NaN.
  int climb(const Dir& D, const PolytopeData& S, const VertexAdjacency& A, const Vec3& u, double eb, bool of_p,
            int v) const {
    (void)S;
    const double u0 = u[0], u1 = u[1], u2 = u[2];
    const double *dx = A.dx.data(), *dy = A.dy.data(), *dz = A.dz.data();
    const bool finite = eb < 1e280;
    // The work counter in a register; a climb cut short by the budget returns a non-maximal
    // vertex, which the caller never uses (over_budget()).
    std::size_t work = work_;
    const std::size_t budget = kBudget ? budget_ : std::numeric_limits<std::size_t>::max();
    for (;;) {
      const int b = A.start[v], end = A.start[v + 1];
      if constexpr (kBudget) work += static_cast<std::size_t>(end - b);
      double bv = -std::numeric_limits<double>::infinity();
      int be = b;
      for (int e = b; e < end; ++e) {
        double s = u0 * dx[e] + u1 * dy[e] + u2 * dz[e];
        be = s > bv ? e : be;
        bv = s > bv ? s : bv;
      }
      if (finite && bv > eb && work <= budget) {
        v = A.nbr[be];
        continue;
      }
      if ((finite && bv < -eb) || work > budget) break;  // every neighbour certified lower
      int next = -1;
      for (int e = b; e < end && next < 0; ++e)
        if ((of_p ? cmp_p(D, v, A.nbr[e]) : cmp_q(D, v, A.nbr[e])) > 0) next = A.nbr[e];
      if (next < 0) break;
      v = next;
    }
    if constexpr (kBudget) work_ = work;
    return v;
  }
  // Adds the support of M along D (a new vertex of V_; the caller may pop it).
  int support(const Dir& D, int p0, int q0) {
    ++iters_;
    return add_vert(climb_p(D, p0), climb_q(D, q0));
  }
  int support_cold(const Dir& D) { return support(D, seed_vertex(AP_, D.n), seed_vertex(AQ_, -D.w)); }
  int support_facet(int f, const Dir& D) {
    // Warm start: the best of the facet's own pairs and (for large shapes, where early facets
    // are far from their supports) the cube-map seed, by rounded values.
    const auto& v = F_[f].v;
    int p0 = V_[v[0]].i, q0 = V_[v[0]].j;
    if (AP_.cube_k >= kSeedMinK) p0 = seed_vertex(AP_, D.n);
    if (AQ_.cube_k >= kSeedMinK) q0 = seed_vertex(AQ_, -D.w);
    double bp = D.n.dot(P_.v[p0]), bq = D.w.dot(Q_.v[q0]);
    for (int k = 0; k < 3; ++k) {
      if (double s = D.n.dot(P_.v[V_[v[k]].i]); s > bp) bp = s, p0 = V_[v[k]].i;
      if (double s = D.w.dot(Q_.v[V_[v[k]].j]); s < bq) bq = s, q0 = V_[v[k]].j;
    }
    return support(D, p0, q0);
  }

  // ---- the polytope ------------------------------------------------------------------------
  // Directions of the first supports are generic (neither axis-aligned nor opposite), so that
  // boxes and other axis-aligned or centrally symmetric shapes meet no exact ties there; any
  // direction would be correct.
  static constexpr double kGeneric[3][3] = {
      {0.4612, -0.6287, 0.6262}, {-0.7033, 0.2117, 0.6786}, {0.3819, 0.8573, 0.3452}};

  // The initial K: a tetrahedron of four pairs (M is full-dimensional), facets linked, Phase A
  // signs set. False (and no K) when over budget.
  [[gnu::noinline]] bool init_tetrahedron() {
    int s1, s2;
    if (!first_supports(s1, s2)) return false;
    double e[3];  // the rounded m_s2 − m_s1
    diff_r(V_[s2], V_[s1], e);
    int s3 = third_support(s1, s2, e);
    if (s3 < 0) return false;
    int o = 0;
    const int s4 = fourth_support(s1, s2, s3, e, o);
    if (s4 < 0) return false;
    if (o > 0) std::swap(s2, s3);  // now s4 lies below the plane of (s1, s2, s3)
    add_facet(s1, s2, s3), add_facet(s1, s4, s2), add_facet(s2, s4, s3), add_facet(s3, s4, s1);
    F_[0].nb = {1, 2, 3}, F_[1].nb = {3, 2, 0}, F_[2].nb = {1, 3, 0}, F_[3].nb = {2, 1, 0};  // twins
    for (int a = 0; a < 4; ++a) F_[a].hsign = hsign(a);
    return true;
  }
  bool over_budget() const { return kBudget && work_ > budget_; }

  // A support query along a plain vector d (exact as given).
  [[gnu::always_inline]] Dir vec_dir(const Vec3& d) const {
    const double zero[3] = {0, 0, 0};
    Dir D;
    D.d = D.n = d;
    finish_dir(D, zero);
    return D;
  }

  // s1, s2: two different pairs, the supports along d1 (from M's centre towards 0, tilted) and
  // about −d1 (exactly −d1 if that gave s1 again). False when over budget.
  [[gnu::always_inline]] bool first_supports(int& s1, int& s2) {
    const Vec3 g0(kGeneric[0][0], kGeneric[0][1], kGeneric[0][2]), g1(kGeneric[1][0], kGeneric[1][1], kGeneric[1][2]);
    Vec3 d1 = R_ * AQ_.centroid + Vec3(thi_[0], thi_[1], thi_[2]) - AP_.centroid;
    d1 += 0.125 * d1.norm() * g0;
    if (!(d1.allFinite() && d1.squaredNorm() > 0)) d1 = g0;
    s1 = support_cold(vec_dir(d1));
    if (over_budget()) return false;
    Vec3 d2 = -d1 + 0.25 * d1.norm() * g1;
    if (!(d2.allFinite() && d2.squaredNorm() > 0)) d2 = -d1;
    s2 = support_cold(vec_dir(d2));
    if (over_budget()) return false;
    if (V_[s2].i == V_[s1].i && V_[s2].j == V_[s1].j) {  // M is full-dimensional: ±d1 differ
      V_.pop_back();
      s2 = support_cold(vec_dir(-d1));
    }
    return !over_budget();
  }

  // s3: a support strictly off the line of s1, s2 (e = the rounded m_s2 − m_s1), along some
  // ±(m_s2 − m_s1) × g: first g = ê × m̂_s1 (normalised), so that the direction is GJK's, from the
  // line towards 0, then the g_k (M is full-dimensional; the g_k are linearly independent). Any
  // g is correct (the direction is exactly orthogonal to m_s2 − m_s1 for the doubles g); this
  // one aims, as GJK, at a first tetrahedron that contains 0 (fewer supports and less time per
  // σ: docs/benchmarks.md). σ only: its answer is canonical, the same from any start
  // (scripts/sigma_identity.py diffs it), while σ_d's choice among facets tied at the exit point
  // depends on K, so σ_d (kBudget) keeps the start it had. −1 when over budget.
  [[gnu::always_inline]] int third_support(int s1, int s2, const double e[3]) {
    int s3 = -1;
    const double bmax = std::max({B_[0], B_[1], B_[2]});
    const double cerr[3] = {2.02 * (ed_max_ + 2.02 * kU * bmax), 2.02 * (ed_max_ + 2.02 * kU * bmax),
                            2.02 * (ed_max_ + 2.02 * kU * bmax)};  // D̂ × g rounded, |g| <= 1
    double towards0[3];
    cross_r(e, V_[s1].mh, towards0);
    const Vec3 t0 = Vec3(towards0[0], towards0[1], towards0[2]);
    const double len = t0.norm();
    const bool use_t0 = !kBudget && std::isfinite(len) && len > 0;
    for (int k = use_t0 ? -1 : 0; k < 3 && s3 < 0; ++k)
      for (int sg : {1, -1}) {
        Dir D;
        D.kind = Dir::Cross;
        D.a = s1, D.b = s2, D.sgn = sg;
        D.d = k < 0 ? t0 * ((1 - 0x1p-50) / len) : Vec3(kGeneric[k][0], kGeneric[k][1], kGeneric[k][2]);
        double g[3] = {D.d[0], D.d[1], D.d[2]}, n[3];
        cross_r(e, g, n);
        D.n = sg * Vec3(n[0], n[1], n[2]);
        finish_dir(D, cerr);
        int x = support_cold(D);
        if (over_budget()) return -1;
        if (dir_side(D, x, s1) != 0) { s3 = x; break; }
        V_.pop_back();
      }
    assert(s3 >= 0 && "M is not full-dimensional");
    return s3;
  }

  // s4: a support strictly off the plane of s1, s2, s3, along ± its normal; o > 0 when s4 lies
  // above that plane (on the side of the normal (m_s2 − m_s1) × (m_s3 − m_s1)). −1 when over
  // budget.
  [[gnu::always_inline]] int fourth_support(int s1, int s2, int s3, const double e[3], int& o) {
    int s4 = -1;
    // σ: first towards 0 (GJK's choice: the tetrahedron then tends to contain 0); either order is
    // correct. σ_d keeps + first (see third_support).
    double e2[3], n[3];
    diff_r(V_[s3], V_[s1], e2);
    cross_r(e, e2, n);
    const double* a = V_[s1].mh;
    const int first = !kBudget && n[0] * a[0] + n[1] * a[1] + n[2] * a[2] > 0 ? -1 : 1;
    for (int sg : {first, -first}) {
      Dir D;
      D.kind = Dir::Normal;
      D.a = s1, D.b = s2, D.c = s3, D.sgn = sg;
      D.structural = true;  // identities of the triangle hold for either sign
      D.t = pairs(s1, s2, s3);
      D.n = sg * Vec3(n[0], n[1], n[2]);
      finish_dir(D, ne_);
      int x = support_cold(D);
      if (over_budget()) return -1;
      if (int side = dir_side(D, x, s1); side != 0) { s4 = x, o = side * sg; break; }
      V_.pop_back();
    }
    assert(s4 >= 0 && "M is not full-dimensional");
    return s4;
  }

  Vec3 approx(int x) const { return Vec3(V_[x].mh[0], V_[x].mh[1], V_[x].mh[2]); }

  // Replaces the facets visible from s (strictly beyond their planes; f0 is one) by the cone
  // from s over the horizon. Visible facets of a convex polytope form a disc, so each horizon
  // vertex starts exactly one horizon edge.
  [[gnu::always_inline]] void expand(int f0, int s, Mode mode) {
    find_horizon(f0, s);
    build_cone(s, mode);
  }

  // vis_: the facets visible from s (a search from f0 over neighbours); hor_: the horizon, each
  // edge as (visible facet, edge index), its other side hidden.
  [[gnu::always_inline]] void find_horizon(int f0, int s) {
    ++stamp_;
    const int vis = 2 * stamp_, hid = 2 * stamp_ + 1;
    vis_.clear();
    hor_.clear();
    vis_.push_back(f0);
    F_[f0].mark = vis;
    for (std::size_t q = 0; q < vis_.size(); ++q) {
      int f = vis_[q];
      for (int k = 0; k < 3; ++k) {
        int g = F_[f].nb[k];
        if (F_[g].mark == vis) continue;
        if (F_[g].mark != hid) {
          if (orient(g, s) > 0) {
            F_[g].mark = vis;
            vis_.push_back(g);
            continue;
          }
          F_[g].mark = hid;
        }
        hor_.push_back({f, k});
      }
    }
  }

  // Kills the visible facets and adds the cone from s over the horizon, linked to its neighbours;
  // each new facet gets its Phase A sign or (Phase B) its key (Phase D needs neither). The new
  // facets are F_[cone_first_, F_.size()).
  [[gnu::always_inline]] void build_cone(int s, Mode mode) {
    for (int f : vis_) kill(f);
    if (by_start_.size() < V_.size()) by_start_.resize(2 * V_.size()), by_end_.resize(2 * V_.size());
    const int first = static_cast<int>(F_.size());
    cone_first_ = first;
    if constexpr (kBudget) work_ += vis_.size() + hor_.size();
    for (auto [f, k] : hor_) {
      int a = F_[f].v[k], b = F_[f].v[(k + 1) % 3], g = F_[f].nb[k];
      int id = add_facet(a, b, s);
      F_[id].nb[0] = g;
      // G's edge b -> a is the one whose neighbour is f (two facets of K share at most one edge).
      Facet& G = F_[g];
      for (int e = 0; e < 3; ++e)
        if (G.nb[e] == f) G.nb[e] = id;
      by_start_[a] = id;
      by_end_[b] = id;
    }
    for (int id = first; id < static_cast<int>(F_.size()); ++id) {
      Facet& N = F_[id];
      N.nb[1] = by_start_[N.v[1]];
      N.nb[2] = by_end_[N.v[0]];
      assert(F_[N.nb[1]].v[0] == N.v[1] && F_[N.nb[2]].v[1] == N.v[0]);
      if (mode == Mode::A) N.hsign = hsign(id);
      else if (mode == Mode::B) keys_[F_[id].pos] = lower_key(id);
    }
  }

  // ---- Phase A: decide 0 ∈ int M exactly --------------------------------------------------------
  [[gnu::always_inline]] Overlap phase_a() {
    for (;;) {
      if constexpr (kBudget) work_ += alive_.size();
      if (over_budget()) return Overlap::Exhausted;
      int f = -1;
      double worst = 0;
      for (int g : alive_) {
        const Facet& G = F_[g];
        if (G.hsign > 0) continue;
        double sd = G.h / std::sqrt(G.n[0] * G.n[0] + G.n[1] * G.n[1] + G.n[2] * G.n[2]);  // for choice only
        if (f < 0 || sd < worst) f = g, worst = sd;
      }
      if (f < 0) return Overlap::Yes;  // 0 strictly inside every facet: 0 ∈ int K ⊆ int M
      Dir D = facet_dir(f);
      int s = support_facet(f, D);
      if (over_budget()) return Overlap::Exhausted;
      if (side0(D, s) <= 0) return Overlap::No;  // h_M(n_f) <= 0: 0 ∉ int M
      expand(f, s, Mode::A);
    }
  }

  // ---- Phase B: nearest facet, certified -------------------------------------------------------
  // Keys are squared distances (no square roots on the hot path). A lower bound of the exact
  // (h/|n|)² from the rounded values and their bounds: |n| <= |ñ| + |ne|, |ñ|² <= nn(1 + 4u).
  double lower_key(int f) const {
    const Facet& F = F_[f];
    double hl = F.h - F.he;
    double nn = F.n[0] * F.n[0] + F.n[1] * F.n[1] + F.n[2] * F.n[2];
    double nu = nn * (1 + 4 * kU) + ne_norm_ * (2 * std::abs(F.n[0]) + 2 * std::abs(F.n[1]) + 2 * std::abs(F.n[2]) + ne_norm_);
    return hl > 0 ? hl * hl / nu * (1 - 0x1p-49) : 0.0;
  }
  // An upper bound of the same (h/|n|)² from the rounded values, without refine(): h <= h̃ + he,
  // |n| >= |ñ| − |ne| with |ñ| >= sqrt(ñ·ñ)(1 − 3u); each of the few roundings below is within u,
  // which the factors cover. +inf when |ñ| is not well above its error bound (then refine).
  double upper_key(int f) const {
    double hu, nl;
    if (!upper_parts(f, hu, nl)) return std::numeric_limits<double>::infinity();
    return hu * hu / (nl * nl) * (1 + 0x1p-48);
  }
  // hu >= h̃ + he >= h and 0 < nl <= |ñ| − |ne| <= |n|; false when unusable.
  bool upper_parts(int f, double& hu, double& nl) const {
    const Facet& F = F_[f];
    hu = (F.h + F.he) * (1 + 0x1p-50);
    const double len = std::sqrt(F.n[0] * F.n[0] + F.n[1] * F.n[1] + F.n[2] * F.n[2]);
    nl = len * (1 - 0x1p-50) - ne_norm_ * (1 + 0x1p-50);
    return nl > 0.5 * len && hu > 0;
  }
  // The facet's vertices rotated so that the least pair (by P's then Q's vertex coordinates)
  // comes first: the values of refine() are then a function of the three pairs, whichever
  // facet of K holds them (canonical_result reuses best's values when it is the canonical triple).
  bool pair_less(int x, int y) const {
    const Vert &X = V_[x], &Y = V_[y];
    if (X.i != Y.i) return lex_less(P_, X.i, Y.i);
    return X.j != Y.j && lex_less(Q_, X.j, Y.j);
  }
  std::array<int, 3> rotated_least(int f) const {
    const auto& v = F_[f].v;
    const int r = pair_less(v[1], v[0]) ? (pair_less(v[2], v[1]) ? 2 : 1) : (pair_less(v[2], v[0]) ? 2 : 0);
    return {v[r], v[(r + 1) % 3], v[(r + 2) % 3]};
  }
  void refine(int f) {
    const auto v = rotated_least(f);
    auto h_l = [&](auto L) { return dot(normal_l(L, v[0], v[1], v[2]), m_l(L, V_[v[0]])); };
    auto n2_l = [&](auto L) {
      auto n = normal_l(L, v[0], v[1], v[2]);
      return dot(n, n);
    };
    // One double-double evaluation of the normal serves both values; rationals if needed.
    auto n = normal_l(LiftDD{}, v[0], v[1], v[2]);
    DD h = dot(n, m_l(LiftDD{}, V_[v[0]])), n2 = dot(n, n);
    auto ok = [](const DD& r) {
      return std::isfinite(r.hi) && std::isfinite(r.e) && safe_bound(r.e) <= std::abs(r.hi) * 0x1p-60;
    };
    double hv = ok(h) ? h.hi : accurate(h_l), n2v = ok(n2) ? n2.hi : accurate(n2_l);
    F_[f].dist = hv / std::sqrt(n2v);
    F_[f].refined = true;
    // The unit normal: each component of n from the double-double value when that is accurate,
    // else exactly (a normal spanned by pairs that differ by far less than the shapes' size can
    // cancel completely in double-double: 1e-44 details on a unit shape gave n̂ = 0, a move of 0);
    // normalised after scaling by a power of two, so that no square underflows.
    // An exactly zero component (a facet of M parallel to an axis: P's or Q's face normal) is
    // recognised by its exact sign first (cheap when the inputs' products are exact doubles).
    Vec3 nv;
    for (int k = 0; k < 3; ++k) {
      auto nk = [&](auto L) { return normal_l(L, v[0], v[1], v[2])[k]; };
      nv[k] = ok(n[k]) ? n[k].hi : exact_sign(nk) == 0 ? 0.0 : accurate(nk);
    }
    const Vec3 u = unit_vector(nv);
    for (int k = 0; k < 3; ++k) F_[f].unit[k] = u[k];
  }
  // v / |v| with v first scaled by a power of two (exact), so that |v|² neither under- nor
  // overflows; bit-identical to v.normalized() whenever that does not.
  static Vec3 unit_vector(const Vec3& v) {
    const double m = v.cwiseAbs().maxCoeff();
    if (!(m > 0)) return Vec3::Zero();
    const Vec3 w = v * std::ldexp(1.0, -std::ilogb(m));
    return w / w.norm();
  }
  bool coplanar(int f, int g) const {
    for (int x : F_[f].v)
      if (orient(g, x) != 0) return false;
    return true;
  }
  int closer(int f, int g) const {  // sign(d_f − d_g), exactly
    const auto a = F_[f].v, b = F_[g].v;
    return exact_sign([&](auto L) {
      auto nf = normal_l(L, a[0], a[1], a[2]), ng = normal_l(L, b[0], b[1], b[2]);
      auto hf = dot(nf, m_l(L, V_[a[0]])), hg = dot(ng, m_l(L, V_[b[0]]));
      return hf * hf * dot(ng, ng) - hg * hg * dot(nf, nf);
    });
  }

  // The index into alive_ of the live facet with the least key, that key in `key` (a dense scan:
  // K has few facets, no branches).
  [[gnu::always_inline]] std::size_t least_key(double& key) const {
    const std::size_t na = keys_.size();
    std::size_t kmin = 0;
    key = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < na; ++k) {
      kmin = keys_[k] < key ? k : kmin;
      key = keys_[k] < key ? keys_[k] : key;
    }
    return kmin;
  }

  // Facet f (alive_[kmin], least key) against the best facet so far: −1 if f is exactly nearer
  // to 0, 0 if exactly as near (a tie on another plane), 1 if it is settled: coplanar with best
  // or farther (key +inf), or not yet refined (refined, the key raised to its accurate distance).
  [[gnu::always_inline]] int nearer_than_best(int f, std::size_t kmin, int best) {
    if (coplanar(f, best)) {  // same plane, same distance (often a symbolic identity)
      keys_[kmin] = std::numeric_limits<double>::infinity();
      return 1;
    }
    if (!F_[f].refined) {
      refine(f);
      keys_[kmin] = F_[f].dist * F_[f].dist * (1 - 0x1p-47);  // dist within 2 ulps
      return 1;
    }
    keys_[kmin] = std::numeric_limits<double>::infinity();
    return closer(f, best);
  }

  // The nearest facet of M (its index in F_), certified: K is expanded until the facet of K
  // nearest to 0 has a supporting plane of M and no other facet of K is exactly nearer. Facets of
  // K exactly as near as best on other planes are expanded too, until each is on a plane of M
  // (ties_: one facet of K per such plane, duplicates possible), so that ties_ and best together
  // hold every facet of M at distance σ (a facet of M at distance σ contains the point σ·u of
  // ∂M, which lies on ∂K, on a facet of K at distance σ and on the same plane) and the answer
  // can be chosen among them by a rule that does not depend on K (canonical_result).
  [[gnu::noinline]] int phase_b() {
    for (std::size_t k = 0; k < alive_.size(); ++k) keys_[k] = lower_key(alive_[k]);
    int best = -1;
    double best_hi = 0;
    ties_.clear();
    for (;;) {
      double key;
      const std::size_t kmin = least_key(key);
      if (best >= 0 && !(key < best_hi)) break;  // every other facet is at least as far as best
      const int f = alive_[kmin];
      int c = -1;  // sign(d_f − d_best)
      if (best >= 0 && (c = nearer_than_best(f, kmin, best)) > 0) continue;
      Dir D = facet_dir(f);
      int s = support_facet(f, D);
      int o = orient(f, s);
      assert(o >= 0 && "a support point below the facet's plane");
      if (o <= 0) {  // f's plane supports M
        V_.pop_back();
        keys_[F_[f].pos] = std::numeric_limits<double>::infinity();
        if (c == 0) {  // another facet of M at distance σ
          ties_.push_back(f);
          continue;
        }
        // The cutoff: best's accurate distance when known, else the rounded upper bound (refine()
        // then runs once, in canonical_result, on the answer's facet only).
        best = f;
        best_hi = F_[f].refined ? F_[f].dist * F_[f].dist * (1 + 0x1p-47)
                  : eager_refine_ ? std::numeric_limits<double>::infinity()
                                  : upper_key(f);
        if (!(best_hi < std::numeric_limits<double>::infinity())) {
          refine(f);
          best_hi = F_[f].dist * F_[f].dist * (1 + 0x1p-47);
        }
        ties_.clear();
        continue;
      }
      expand(f, s, Mode::B);
    }
    return best;
  }

  // ---- Phase D: the exit of the ray s·d from M (σ_d) --------------------------------------------
  // 0 ∈ int K, so the cones from 0 over K's facets partition space: the ray leaves K through the
  // facet (a, b, c) whose closed cone contains d, i.e. det(m_a, m_b, d), det(m_b, m_c, d) and
  // det(m_c, m_a, d) are all >= 0 (each is λ·det(m_a, m_b, m_c) for a barycentric weight λ of the
  // exit point, and det(m_a, m_b, m_c) = h > 0). Ties (the ray through an edge or a vertex of K)
  // accept every facet containing the exit point: any of them is correct below.

  // The bound of the rounded d·(m̂_a × m̂_b) (semi-static: uniform over pairs). With |m_k| <= mb_k,
  // |m̂_k − m_k| <= em_k, A_k = mb_k + em_k: each cross component carries the input error
  // em_y mb_z + A_y em_z + em_z mb_y + A_z em_y and the rounding 4u A_y A_z (two products, one
  // difference), and |ĉ_k| <= 2.01 A_y A_z; the dot product adds γ₃ Σ|d_k||ĉ_k|.
  void init_direction(const Vec3& d) {
    dir_ = d;
    double e = 0;
    for (int k = 0; k < 3; ++k) {
      const int y = (k + 1) % 3, z = (k + 2) % 3;
      const double Ay = mb_[y] + em_[y], Az = mb_[z] + em_[z];
      const double ce = em_[y] * mb_[z] + Ay * em_[z] + em_[z] * mb_[y] + Az * em_[y] + 4.02 * kU * Ay * Az;
      e += std::abs(d[k]) * (ce * kInflate + 3.02 * kU * 2.01 * Ay * Az);
    }
    edet_ = e * kInflate + exact::kTiny;
  }

  // Sign of det(m_a, m_b, d) = d·(m_a × m_b), exactly.
  int det_sign(int a, int b) const {
    const double *x = V_[a].mh, *y = V_[b].mh;
    const double s = dir_[0] * (x[1] * y[2] - x[2] * y[1]) + dir_[1] * (x[2] * y[0] - x[0] * y[2]) +
                     dir_[2] * (x[0] * y[1] - x[1] * y[0]);
    if (s > edet_) return 1;
    if (s < -edet_) return -1;
    return exact_sign([&](auto L) {
      V3<Num<decltype(L)>> dl{L(dir_[0]), L(dir_[1]), L(dir_[2])};
      return dot(dl, cross(m_l(L, V_[a]), m_l(L, V_[b])));
    });
  }
  // True iff the closed cone from 0 over facet f contains d.
  bool cone_contains(int f) const {
    const auto& v = F_[f].v;
    return det_sign(v[0], v[1]) >= 0 && det_sign(v[1], v[2]) >= 0 && det_sign(v[2], v[0]) >= 0;
  }
  // The exit facet of K: among the facets of the last cone when K was just expanded (the exit
  // point of the larger K lies on it: either beyond the old exit point, hence not on an old facet,
  // or the old exit point itself, on the horizon then, hence on a closed cone facet), else among
  // all live facets.
  int exit_facet(bool after_expand) const {
    if (after_expand) {
      for (int f = cone_first_; f < static_cast<int>(F_.size()); ++f)
        if (cone_contains(f)) return f;
      assert(false && "the ray leaves K through no facet of the new cone");
    }
    if constexpr (kBudget) work_ += alive_.size();
    for (int f : alive_)
      if (cone_contains(f)) return f;
    assert(false && "the ray leaves K through no facet");
    return alive_[0];
  }

  // The facet of K on the ray's exit point whose plane supports M: then that point is the
  // ray's exit from M (K ⊆ M lies below the plane, and the point is in K). −1: over budget.
  int phase_d() {
    bool expanded = false;
    for (;;) {
      if (over_budget()) return -1;
      const int f = exit_facet(expanded);
      Dir D = facet_dir(f);
      const int s = support_facet(f, D);
      if (over_budget()) return -1;
      const int o = orient(f, s);
      assert(o >= 0 && "a support point below the facet's plane");
      if (o <= 0) {  // f's plane supports M
        V_.pop_back();
        return f;
      }
      expand(f, s, Mode::D);
      expanded = true;
    }
  }

  // σ_d on facet f: depth = (h_f / (n_f·d))·|d|, h_f and n_f·d to within 2^-60 relative
  // (double-double with a rigorous bound, exact rationals otherwise), the quotient, |d| and the
  // product in double-double, rounded once: within ~half an ulp (exact depths come out exact).
  // Also the unit normal.
  double exit_distance(int f, Vec3& unit) const {
    const auto v = F_[f].v;
    auto n = normal_l(LiftDD{}, v[0], v[1], v[2]);
    const V3<DD> dd{DD{dir_[0]}, DD{dir_[1]}, DD{dir_[2]}};
    const DD h = dot(n, m_l(LiftDD{}, V_[v[0]])), nd = dot(n, dd);
    auto ok = [](const DD& r) {
      return std::isfinite(r.hi) && std::isfinite(r.e) && safe_bound(r.e) <= std::abs(r.hi) * 0x1p-60;
    };
    // The unit normal as refine() makes it (exact components where double-double cancelled).
    Vec3 nv;
    for (int k = 0; k < 3; ++k)
      nv[k] = ok(n[k]) ? n[k].hi : accurate([&](auto L) { return normal_l(L, v[0], v[1], v[2])[k]; });
    unit = unit_vector(nv);
    DD t;
    if (ok(h) && ok(nd)) {
      const double q1 = h.hi / nd.hi;
      const DD r = h - DD{q1} * nd;  // h − q1·nd, nearly exact
      fast_two_sum(q1, r.hi / nd.hi, t.hi, t.lo);
    } else {
      const exact::LiftQ L;
      auto nq = normal_l(L, v[0], v[1], v[2]);
      const V3<exact::Rat> dq{L(dir_[0]), L(dir_[1]), L(dir_[2])};
      const mpq_class q = dot(nq, m_l(L, V_[v[0]])).v / dot(nq, dq).v;
      t.hi = q.get_d();
      t.lo = mpq_class(q - t.hi).get_d();
    }
    // |d| = sqrt(d·d): the squares and their sum in double-double, one Newton step.
    const DD s = (dd[0] * dd[0] + dd[1] * dd[1]) + dd[2] * dd[2];
    const double x = std::sqrt(s.hi);
    const DD res = s - DD{x} * DD{x};
    DD norm;
    fast_two_sum(x, res.hi / (2 * x), norm.hi, norm.lo);
    return (t * norm).hi;
  }

  // ---- result ------------------------------------------------------------------------------
  // Dimension (0, 1, 2) of the support face of P (of_p) or Q' around vertex v for D, and the
  // feature: the vertex, an edge (half-edge, the one with the smaller id), or a triangle.
  Feature3 support_feature(const Dir& D, bool of_p, int v, int& dim) const {
    const PolytopeData& S = of_p ? P_ : Q_;
    const VertexAdjacency& A = of_p ? AP_ : AQ_;
    const int b = A.start[v], deg = A.start[v + 1] - b;
    constexpr int kMaxLocal = 64;
    char local[kMaxLocal];
    std::vector<char> big(deg > kMaxLocal ? deg : 0);
    char* tie = deg > kMaxLocal ? big.data() : local;
    int ties = 0, one = -1;
    for (int e = 0; e < deg; ++e) {
      int w = A.nbr[b + e];
      tie[e] = (of_p ? cmp_p(D, v, w) : cmp_q(D, v, w)) == 0;
      if (tie[e]) ++ties, one = e;
    }
    dim = std::min(ties, 2);
    if (ties == 0) return {FeatureKind3::Vertex, v};
    if (ties >= 2)
      for (int e = 0; e < deg; ++e)
        if (tie[e] && tie[(e + 1) % deg]) return {FeatureKind3::Face, A.he[b + e] / 3};
    dim = 1;  // two tied neighbours always span a triangle on a strictly convex polytope
    int h = A.he[b + one];
    return {FeatureKind3::Edge, std::min(h, S.levels[0].twin[h])};
  }

  Depth3 directional_result(int f, const Eigen::Matrix3d& Rp, const Vec3& tp) const {
    Depth3 r;
    r.kind = DepthKind::Directional;
    r.overlapping = true;
    r.candidates = iters_;
    Vec3 u;
    r.depth = r.lower_bound = r.upper_bound = exit_distance(f, u);
    const Vec3 dir = unit_vector(dir_);
    const Vec3 move = r.depth * dir;
    // The exit point t·d of facet f, barycentric weights ∝ det(m_b, m_c, d), … (>= 0 exactly): a
    // point wp of P and wq of Q' on the contact (after the move). The rounded dets (error <=
    // edet_ each) when their sum exceeds 2^40 edet_ (weights within 3·2^-40 ≈ 3e-12), else in
    // double-double with exact zeros (K's facets may be slivers).
    const auto& v = F_[f].v;
    auto det_r = [&](int a, int b) { return std::max(0.0, dir_.dot(approx(a).cross(approx(b)))); };
    double lam[3] = {det_r(v[1], v[2]), det_r(v[2], v[0]), det_r(v[0], v[1])};
    double sum = lam[0] + lam[1] + lam[2];
    if (!(sum > 0x1p40 * edet_)) {
      const V3<DD> dl{DD{dir_[0]}, DD{dir_[1]}, DD{dir_[2]}};
      const V3<DD> m[3] = {m_l(LiftDD{}, V_[v[0]]), m_l(LiftDD{}, V_[v[1]]), m_l(LiftDD{}, V_[v[2]])};
      for (int k = 0; k < 3; ++k) {
        const int b = (k + 1) % 3, c = (k + 2) % 3;
        const DD x = dot(dl, cross(m[b], m[c]));
        const bool sure = std::isfinite(x.hi) && std::abs(x.hi) > safe_bound(x.e);
        lam[k] = std::max(0.0, sure || det_sign(v[b], v[c]) != 0 ? x.hi : 0.0);
      }
      sum = lam[0] + lam[1] + lam[2];
    }
    if (!(sum > 0 && std::isfinite(sum))) lam[0] = lam[1] = lam[2] = sum = 1;
    Vec3 wp = Vec3::Zero(), wq = Vec3::Zero();
    const Vec3 t(thi_[0] + tlo_[0], thi_[1] + tlo_[1], thi_[2] + tlo_[2]);
    for (int k = 0; k < 3; ++k) {
      const Vert& X = V_[v[k]];
      wp += lam[k] / sum * P_.v[X.i];
      wq += lam[k] / sum * (R_ * Q_.v[X.j] + t);
    }
    wq += move;
    r.translation = Rp * move;
    r.normal = Rp * dir;
    r.facet_normal = Rp * u;
    r.witness_p = Rp * wp + tp;
    r.witness_q = Rp * wq + tp;
    features(f, r);
    return r;
  }

  // ---- the canonical answer (σ) -------------------------------------------------------------
  // σ's answer is a function of the facet of M it ends on, never of K (which depends on the
  // start, e.g. a warm start, and triangulates a polygonal facet of M in many ways): among the
  // facets of M at distance σ (best and ties_), the one whose canonical features are least;
  // its distance, normal and witnesses computed from three pairs fixed by those features.
  using Features = std::array<Feature3, 2>;

  // Whether half-edge h of S's level 0 is a true edge (not a diagonal of a flat face).
  static bool true_edge(const PolytopeData& S, int h) {
    const int e = std::min(h, S.levels[0].twin[h]);
    return std::binary_search(S.edges.begin(), S.edges.end(), e);
  }
  // face_: the triangles of S's flat face containing triangle t (precomputed per shape:
  // VertexAdjacency::face_of).
  void flat_face(const PolytopeData& S, int t) {
    const VertexAdjacency& A = &S == &P_ ? AP_ : AQ_;
    const int f = A.face_of[t];
    face_.assign(A.face_tris.begin() + A.face_start[f], A.face_tris.begin() + A.face_start[f + 1]);
  }
  // Vertices in the lexicographic order of their coordinates (distinct vertices differ): the
  // canonical choices below depend on the shapes' geometry, not on their vertex numbering (a
  // shape rebuilt from its vertices, e.g. unpickled, answers the same bits).
  static bool lex_less(const PolytopeData& S, int a, int b) {
    const Vec3 &x = S.v[a], &y = S.v[b];
    return x[0] != y[0] ? x[0] < y[0] : x[1] != y[1] ? x[1] < y[1] : x[2] < y[2];
  }
  // The flat face of S containing triangle t: its least triangle id, its lexicographically least
  // vertex a, and the canonical triangle (a, next(a), prev(a)) — a and its neighbours on the face's
  // boundary, counter-clockwise from outside (a is a corner: S has no collinear boundary vertices).
  struct FaceCanon {
    int tri, least;
    std::array<int, 3> t;
  };
  FaceCanon face_canon(const PolytopeData& S, int t) const {  // precomputed per shape
    const VertexAdjacency& A = &S == &P_ ? AP_ : AQ_;
    const auto& c = A.face_canon[A.face_of[t]];
    return {c[0], c[1], {c[1], c[2], c[3]}};
  }
  // The least vertex (lexicographically) of a support set of dimension dim around feature f.
  int least_vertex(const PolytopeData& S, const Feature3& f, int dim) {
    if (dim == 0) return f.index;
    if (dim == 2) return face_canon(S, f.index).least;
    const auto& L = S.levels[0];
    const int a = L.origin(f.index), b = L.target(f.index);
    return lex_less(S, a, b) ? a : b;
  }
  // The canonical features of the facet of M that facet f of K lies on (P's face and Q's least
  // vertex in its support set, else P's least vertex and Q's face, else the two edges) and three
  // pairs spanning it in outward order (edge–edge: the caller fixes the orientation).
  struct Canon {
    Features c;
    std::array<int, 6> pr;
    Feature3 raw_p, raw_q;  // support features as found, and their dimensions
    int dp = 0, dq = 0;
  };
  Canon canonical_of(int f) {
    const Facet& B = F_[f];
    const Dir D = facet_dir(f);
    int dp = 0, dq = 0;
    const Feature3 fp = support_feature(D, true, V_[B.v[0]].i, dp);
    const Feature3 fq = support_feature(D, false, V_[B.v[0]].j, dq);
    Canon k;
    k.raw_p = fp, k.raw_q = fq, k.dp = dp, k.dq = dq;
    if (dp == 2) {
      const int j = least_vertex(Q_, fq, dq);
      const FaceCanon F = face_canon(P_, fp.index);
      k.c = {Feature3{FeatureKind3::Face, F.tri}, Feature3{FeatureKind3::Vertex, j}};
      k.pr = {F.t[0], j, F.t[1], j, F.t[2], j};
    } else if (dq == 2) {
      const int i = least_vertex(P_, fp, dp);
      const FaceCanon F = face_canon(Q_, fq.index);
      k.c = {Feature3{FeatureKind3::Vertex, i}, Feature3{FeatureKind3::Face, F.tri}};
      k.pr = {i, F.t[0], i, F.t[2], i, F.t[1]};  // −Q's face: Q's triangle reversed
    } else {
      const auto &LP = P_.levels[0], &LQ = Q_.levels[0];
      int a = LP.origin(fp.index), b = LP.target(fp.index), x = LQ.origin(fq.index), y = LQ.target(fq.index);
      if (lex_less(P_, b, a)) std::swap(a, b);
      if (lex_less(Q_, y, x)) std::swap(x, y);
      k.c = {fp, fq};
      k.pr = {a, x, b, x, a, y};
    }
    return k;
  }
  // The order of facets of M at distance σ: kinds, then the coordinates of the spanning pairs.
  bool less(const Canon& a, const Canon& b) const {
    for (int k = 0; k < 2; ++k)
      if (a.c[k].kind != b.c[k].kind) return a.c[k].kind < b.c[k].kind;
    for (int k = 0; k < 6; ++k) {
      const PolytopeData& S = k % 2 == 0 ? P_ : Q_;
      if (a.pr[k] != b.pr[k]) return lex_less(S, a.pr[k], b.pr[k]);
    }
    return false;
  }

  // ---- a contact point of parallel features (face–face, face–edge, edge–face) -----------------
  // The support set of S: vertices (lexicographic order), boundary segments (endpoints and the
  // segments in lexicographic order) and triangles of a face.
  void support_set(const PolytopeData& S, const Feature3& raw, int dim, SupportSet& out) {
    out.verts.clear(), out.edges.clear(), out.tris.clear();
    const auto& L = S.levels[0];
    auto lex = [&](int a, int b) { return lex_less(S, a, b); };
    if (dim == 1) {
      out.edges.push_back({L.origin(raw.index), L.target(raw.index)});
    } else {
      flat_face(S, raw.index);
      for (int g : face_) {
        out.tris.push_back(S.tris[g]);
        for (int k = 0; k < 3; ++k)
          if (true_edge(S, 3 * g + k)) out.edges.push_back({L.origin(3 * g + k), L.target(3 * g + k)});
      }
    }
    for (auto& e : out.edges) {
      if (lex(e[1], e[0])) std::swap(e[0], e[1]);
      out.verts.push_back(e[0]), out.verts.push_back(e[1]);
    }
    std::sort(out.verts.begin(), out.verts.end(), lex);
    out.verts.erase(std::unique(out.verts.begin(), out.verts.end()), out.verts.end());
    std::sort(out.edges.begin(), out.edges.end(), [&](const auto& a, const auto& b) {
      return a[0] != b[0] ? lex(a[0], b[0]) : lex(a[1], b[1]);
    });
  }
  // A point where P's support set touches the moved Q' (P's frame; shift = t + move): a vertex of
  // Q moved into P's face, a vertex of P in the moved Q's face, or the crossing of two boundary
  // segments — M's facet is covered by these pieces (a convex polygon plus the other translated,
  // swept along its edges) — the first in that order (vertices and segments by coordinates, so
  // the point does not depend on the numbering), in the facet's plane (axes: u without its
  // largest component). Rounded tests: a point within rounding of a piece's border may pick the
  // next piece, or the piece it is nearest to if none holds it; always the same one for the same
  // input.
  Vec3 contact_point(const Canon& k, const Vec3& shift, const Vec3& u) {
    SupportSet &sp = sp_, &sq = sq_;
    support_set(P_, k.raw_p, k.dp, sp);
    support_set(Q_, k.raw_q, k.dq, sq);
    int ax = 0;
    for (int a = 1; a < 3; ++a)
      if (std::abs(u[a]) > std::abs(u[ax])) ax = a;
    const int a1 = (ax + 1) % 3, a2 = (ax + 2) % 3;
    auto qm = [&](int j) -> Vec3 { return R_ * Q_.v[j] + shift; };
    auto cross2 = [&](const Vec3& o, const Vec3& a, const Vec3& b) {
      return (a[a1] - o[a1]) * (b[a2] - o[a2]) - (a[a2] - o[a2]) * (b[a1] - o[a1]);
    };
    // The least normalised barycentric weight of x in triangle (a, b, c).
    auto weight = [&](const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
      const double area = cross2(a, b, c);
      if (!(area != 0)) return -std::numeric_limits<double>::infinity();
      return std::min({cross2(x, b, c) / area, cross2(a, x, c) / area, cross2(a, b, x) / area});
    };
    Vec3 best = Vec3::Zero();
    double best_w = -std::numeric_limits<double>::infinity();
    auto offer = [&](double w, const Vec3& x) {
      if (w > best_w) best_w = w, best = x;
      return w >= 0;
    };
    for (int j : sq.verts) {
      const Vec3 x = qm(j);
      for (const auto& t : sp.tris)
        if (offer(weight(x, P_.v[t[0]], P_.v[t[1]], P_.v[t[2]]), x)) return x;
    }
    for (int i : sp.verts) {
      const Vec3& x = P_.v[i];
      for (const auto& t : sq.tris)
        if (offer(weight(x, qm(t[0]), qm(t[1]), qm(t[2])), x)) return x;
    }
    for (const auto& e : sp.edges)
      for (const auto& f : sq.edges) {
        const Vec3 &pa = P_.v[e[0]], &pb = P_.v[e[1]];
        const Vec3 qa = qm(f[0]), qb = qm(f[1]);
        const double den = cross2(Vec3::Zero(), pb - pa, qb - qa);
        if (!(den != 0)) continue;
        const double lam = cross2(Vec3::Zero(), qa - pa, qb - qa) / den, mu = cross2(Vec3::Zero(), qa - pa, pb - pa) / den;
        const Vec3 x = pa + std::clamp(lam, 0.0, 1.0) * (pb - pa);
        if (offer(std::min({lam, 1 - lam, mu, 1 - mu}), x)) return x;
      }
    return best;
  }

  // σ's answer from phase B's best facet: see above. The seed (if any) receives the pairs.
  Depth3 canonical_result(int best, const Eigen::Matrix3d& Rp, const Vec3& tp, ExpandSeed* seed) {
    Canon best_c = canonical_of(best);
    for (int t : ties_)
      if (Canon ct = canonical_of(t); less(ct, best_c)) best_c = ct;
    const Features c = best_c.c;
    std::array<int, 6> pr = best_c.pr;
    // best's own values when it is spanned by the same pairs (refine() starts at the least pair,
    // which pr does too), else those of the canonical triple.
    int f = best;
    const auto bv = rotated_least(best);
    bool same = true;
    for (int k = 0; k < 3 && same; ++k) same = V_[bv[k]].i == pr[2 * k] && V_[bv[k]].j == pr[2 * k + 1];
    if (c[0].kind == FeatureKind3::Edge && !same) {  // the other orientation of the edge–edge triple
      same = true;
      for (int k = 0; k < 3 && same; ++k) {
        const int m = k == 0 ? 0 : 3 - k;
        same = V_[bv[k]].i == pr[2 * m] && V_[bv[k]].j == pr[2 * m + 1];
      }
      if (same) std::swap(pr[2], pr[4]), std::swap(pr[3], pr[5]);
    }
    if (!same) {
      const int a = add_vert(pr[0], pr[1]), b = add_vert(pr[2], pr[3]), x = add_vert(pr[4], pr[5]);
      f = add_facet(a, b, x);
      if (c[0].kind == FeatureKind3::Edge && hsign(f) < 0) {  // 0 strictly inside: h > 0 outward
        f = add_facet(a, x, b);
        std::swap(pr[2], pr[4]), std::swap(pr[3], pr[5]);
      }
      refine(f);
    } else if (!F_[f].refined) {
      refine(f);
    }
    const Facet& B = F_[f];
    Depth3 r;
    r.kind = DepthKind::Minimum;
    r.overlapping = true;
    r.candidates = iters_;
    r.depth = r.lower_bound = r.upper_bound = B.dist;
    const Vec3 u(B.unit[0], B.unit[1], B.unit[2]);
    const Vec3 move = B.dist * u;
    // The contact point after the move (P's frame), as in the reference (depth3.cpp): Q's vertex
    // moved onto P's face plane; P's vertex; or the crossing of the two edges (closest point of
    // P's edge to the moved Q edge's line).
    const Vec3 t(thi_[0] + tlo_[0], thi_[1] + tlo_[1], thi_[2] + tlo_[2]);
    Vec3 w;
    if ((best_c.dp == 2 && best_c.dq >= 1) || (best_c.dq == 2 && best_c.dp >= 1)) {
      w = contact_point(best_c, t + move, u);
    } else if (c[0].kind == FeatureKind3::Face) {
      w = R_ * Q_.v[c[1].index] + t + move;
    } else if (c[1].kind == FeatureKind3::Face) {
      w = P_.v[c[0].index];
    } else {  // pr = (a, x), (b, x), (a, y) or (a, x), (a, y), (b, x)
      const int a = pr[0], x = pr[1], b = pr[2] == a ? pr[4] : pr[2], y = pr[3] == x ? pr[5] : pr[3];
      const Vec3 pa = P_.v[a], e = P_.v[b] - pa;
      const Vec3 qa = R_ * Q_.v[x] + t + move;
      const Vec3 g = R_ * (Q_.v[y] - Q_.v[x]);
      const Vec3 n = e.cross(g);
      const double s = (qa - pa).cross(g).dot(n) / n.squaredNorm();
      w = pa + (std::isfinite(s) ? std::clamp(s, 0.0, 1.0) : 0.0) * e;
    }
    r.translation = Rp * move;
    r.normal = r.facet_normal = Rp * u;
    r.witness_p = r.witness_q = Rp * w + tp;
    r.feature_p = c[0], r.feature_q = c[1];
    if (seed) save_seed(pr, best, c, *seed);
    return r;
  }

  // ---- warm start --------------------------------------------------------------------------
  // The seed: the canonical facet's pairs, then the vertices of K's facets up to kSeedDepth steps
  // from best (breadth first), distinct, at most ExpandSeed::kMaxPairs in all. Measured
  // (bench_motion_trajectory, docs/benchmarks.md): one step saves the most time on real hulls;
  // more steps save support queries but cost more to insert.
  static constexpr std::size_t kSeedDepth = 1;
  static constexpr std::size_t kWarmMaxVertices = 128;
  void save_seed(const std::array<int, 6>& pr, int best, const Features& c, ExpandSeed& seed) {
    std::copy(pr.begin(), pr.end(), seed.pairs.begin());
    seed.count = 3;
    seed.valid = true;
    // Pairs on the facet's plane by the structure of a face of P (or Q) met by one vertex of Q
    // (of P) are left out: they would only be found coplanar again (exact zeros).
    const bool face_p = c[0].kind == FeatureKind3::Face, face_q = c[1].kind == FeatureKind3::Face;
    std::vector<int>& face_verts = face_verts_;
    face_verts.clear();
    if (face_p || face_q) {
      const PolytopeData& S = face_p ? P_ : Q_;
      flat_face(S, c[face_p ? 0 : 1].index);
      for (int g : face_)
        for (int x : S.tris[g]) face_verts.push_back(x);
    }
    auto add = [&](int x) {
      const int i = V_[x].i, j = V_[x].j;
      if (face_p && j == pr[1] && std::find(face_verts.begin(), face_verts.end(), i) != face_verts.end()) return;
      if (face_q && i == pr[0] && std::find(face_verts.begin(), face_verts.end(), j) != face_verts.end()) return;
      for (int k = 0; k < seed.count; ++k)
        if (seed.pairs[2 * k] == i && seed.pairs[2 * k + 1] == j) return;
      if (seed.count < ExpandSeed::kMaxPairs) seed.pairs[2 * seed.count] = i, seed.pairs[2 * seed.count + 1] = j, ++seed.count;
    };
    ++stamp_;
    const int seen = 2 * stamp_;
    vis_.assign(1, best);
    F_[best].mark = seen;
    std::size_t level_end = 1;
    for (std::size_t q = 0, depth = 0; q < vis_.size() && depth <= kSeedDepth; ++q) {
      if (q == level_end) ++depth, level_end = vis_.size();
      if (depth > kSeedDepth) break;
      for (int k = 0; k < 3; ++k) {
        add(F_[vis_[q]].v[k]);
        const int g = F_[vis_[q]].nb[k];
        if (F_[g].mark != seen) F_[g].mark = seen, vis_.push_back(g);
      }
    }
  }
  // The first K from a seed: the tetrahedron on its facet (warm_tetrahedron), then its other
  // pairs inserted where they lie strictly beyond a facet (K stays a polytope of pairs, convex,
  // outward). False (nothing built) when the seed is not usable.
  bool warm_start(const ExpandSeed& sd) {
    // Measured (docs/benchmarks.md): on larger round hulls the seed's small facets make the
    // filters of the first steps fail and the warm start costs more than it saves: start cold.
    if (P_.v.size() > kWarmMaxVertices || Q_.v.size() > kWarmMaxVertices) return false;
    std::array<int, 6> facet;
    std::copy(sd.pairs.begin(), sd.pairs.begin() + 6, facet.begin());
    if (sd.count < 3 || sd.count > ExpandSeed::kMaxPairs || !warm_tetrahedron(facet)) return false;
    const int n = static_cast<int>(P_.v.size()), m = static_cast<int>(Q_.v.size());
    for (int k = 3; k < sd.count; ++k) {
      const int i = sd.pairs[2 * k], j = sd.pairs[2 * k + 1];
      if (i < 0 || i >= n || j < 0 || j >= m) continue;
      const int x = add_vert(i, j);
      int f = -1;
      for (int g : alive_)
        if (orient(g, x) > 0) {
          f = g;
          break;
        }
      if (f < 0) {
        V_.pop_back();
        continue;
      }
      expand(f, x, Mode::A);
    }
    return true;
  }

  // The first K from a seed: the three pairs of the previous answer's facet (points of M at any
  // pose) and the support along the opposite of their normal (or along it), a tetrahedron when
  // that support is strictly off their plane. False (nothing built) when the seed is not usable
  // here (indices out of range, repeated pairs, pairs now collinear or the support on their plane).
  bool warm_tetrahedron(const std::array<int, 6>& sd) {
    const int n = static_cast<int>(P_.v.size()), m = static_cast<int>(Q_.v.size());
    for (int k = 0; k < 3; ++k)
      if (sd[2 * k] < 0 || sd[2 * k] >= n || sd[2 * k + 1] < 0 || sd[2 * k + 1] >= m) return false;
    for (int k = 0; k < 3; ++k)
      if (sd[2 * k] == sd[2 * ((k + 1) % 3)] && sd[2 * k + 1] == sd[2 * ((k + 1) % 3) + 1]) return false;
    int s1 = add_vert(sd[0], sd[1]), s2 = add_vert(sd[2], sd[3]), s3 = add_vert(sd[4], sd[5]);
    double e[3], e2[3], nr[3];
    diff_r(V_[s2], V_[s1], e);
    diff_r(V_[s3], V_[s1], e2);
    cross_r(e, e2, nr);
    // A heuristic gate (any start is correct): the seed helps only while 0 is still on the inner
    // side of its facet's plane (rounded); after a jump it would only cost, start cold then.
    const double* ma = V_[s1].mh;
    if (!(nr[0] * ma[0] + nr[1] * ma[1] + nr[2] * ma[2] > 0)) {
      V_.clear();
      return false;
    }
    // The support along ∓ the rounded normal (a plain vector: any direction is correct, and its
    // exact comparisons are cheap), then its exact side of the pairs' plane.
    int s4 = -1, o = 0;
    add_facet(s1, s2, s3);
    for (int sg : {-1, 1}) {
      const int x = support_cold(vec_dir(sg * Vec3(nr[0], nr[1], nr[2])));
      if (const int side = orient(0, x); side != 0) {
        s4 = x, o = side;
        break;
      }
      V_.pop_back();
    }
    F_.clear(), alive_.clear(), keys_.clear();
    if (s4 < 0) {  // the pairs are collinear now (their normal is 0) or M is flat: start cold
      V_.clear();
      return false;
    }
    if (o > 0) std::swap(s2, s3);  // now s4 lies below the plane of (s1, s2, s3)
    add_facet(s1, s2, s3), add_facet(s1, s4, s2), add_facet(s2, s4, s3), add_facet(s3, s4, s1);
    F_[0].nb = {1, 2, 3}, F_[1].nb = {3, 2, 0}, F_[2].nb = {1, 3, 0}, F_[3].nb = {2, 1, 0};  // twins
    for (int f = 0; f < 4; ++f) F_[f].hsign = hsign(f);
    return true;
  }

  // The defining features of M's facet b: a face of P and a vertex of Q, a vertex of P and a face
  // of Q, or two edges (P's face preferred).
  [[gnu::always_inline]] void features(int b, Depth3& r) const {
    const Facet& B = F_[b];
    Dir D = facet_dir(b);
    int dp = 0, dq = 0;
    Feature3 fp = support_feature(D, true, V_[B.v[0]].i, dp);
    Feature3 fq = support_feature(D, false, V_[B.v[0]].j, dq);
    if (dp == 2) {
      r.feature_p = fp, r.feature_q = {FeatureKind3::Vertex, V_[B.v[0]].j};
    } else if (dq == 2) {
      r.feature_p = {FeatureKind3::Vertex, V_[B.v[0]].i}, r.feature_q = fq;
    } else {
      r.feature_p = fp, r.feature_q = fq;
    }
  }
};

// One scratch workspace per thread, shared by σ and σ_d.
Workspace& workspace() {
  thread_local Workspace ws;
  return ws;
}

}  // namespace

namespace {

Depth3 expand(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel, const Eigen::Matrix3d& Rp,
              const Vec3& tp, ExpandSeed* seed) {
  return Expander<false>(P, Q, rel, workspace()).run(Rp, tp, seed);
}

#if PENDEPTH_V3_CLONES
// The same call tree compiled for x86-64-v3 (geometry/isa.hpp): the double-double products' fmas
// become instructions instead of libm calls; the same bits.
PENDEPTH_V3_CLONE Depth3 expand_v3(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel,
                                   const Eigen::Matrix3d& Rp, const Vec3& tp, ExpandSeed* seed) {
  return expand(P, Q, rel, Rp, tp, seed);
}
#endif

}  // namespace

Depth3 minimum_depth_expand(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel,
                            const Eigen::Matrix3d& Rp, const Vec3& tp, ExpandSeed* seed) {
#if PENDEPTH_V3_CLONES
  if (isa::use_v3()) return expand_v3(P, Q, rel, Rp, tp, seed);
#endif
  return expand(P, Q, rel, Rp, tp, seed);
}

Depth3 minimum_depth_expand_eager(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel,
                                  const Eigen::Matrix3d& Rp, const Vec3& tp, ExpandSeed* seed) {
  Expander<false> e(P, Q, rel, workspace());
  e.set_eager_refine(true);
  return e.run(Rp, tp, seed);
}

int minimum_expand_key_violations(const ConvexPolytope& P, const ConvexPolytope& Q, const RelativePose& rel,
                                  int& checked) {
  Expander<false> e(P, Q, rel, workspace());
  (void)e.run(Eigen::Matrix3d::Identity(), Vec3::Zero(), nullptr);
  return e.key_violations(checked);
}

std::optional<Depth3> directional_depth_expand(const ConvexPolytope& P, const ConvexPolytope& Q,
                                               const RelativePose& rel, const Vec3& d, const Eigen::Matrix3d& Rp,
                                               const Vec3& tp, std::size_t budget, std::size_t* work) {
  assert(d.allFinite() && d != Vec3::Zero());
  // Scale d by a power of two (exact: the same ray) so that its products neither overflow nor
  // underflow.
  int ex = 0;
  std::frexp(d.cwiseAbs().maxCoeff(), &ex);
  const Vec3 ds(std::ldexp(d.x(), -ex), std::ldexp(d.y(), -ex), std::ldexp(d.z(), -ex));
  Expander<true> e(P, Q, rel, workspace());
  std::optional<Depth3> r = e.run_directional(ds, Rp, tp, budget);
  if (work) *work = e.work();
  return r;
}

}  // namespace pendepth::convex3
