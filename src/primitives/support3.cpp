// pendepth — the certified support-function engine: every Pair3 query where either shape is a
// curved primitive (cylinder, cone, ellipsoid; issue 16 item 5; docs/algorithms.md "Certified
// support-function engine"; survey §3: GJK and EPA, here with certified bounds).
//
// Contract (support3.hpp). P, Q any convex shapes given by support functions (closed forms for
// the curved primitives, a vertex scan for polytopes and lower-dimensional shapes, + r·v̂ for a
// rounding ball). Work is in P's frame with the relative pose of the exact engines (R = Rpᵀ Rq,
// t = Rpᵀ tq − Rpᵀ tp, the doubles; certified for these, like every 3D engine here).
// M = P ⊕ (−Q'), with support function h_M(u) = h_P(u) + h_Q'(−u) and support points
// x(u) = s_P(u) − s_Q'(−u). Each support evaluation returns a double point x̃ within δ of a point
// of M and a value ⟨x̃, u⟩ within E(u) = δ|u| + 4u·Σ|x̃_k u_k| of h_M(u) (δ from the shapes' sizes,
// |R| and |t|: a rigorous a-priori bound of the rounding of the closed forms and of the pose).
// Signed distance of M at a query point p (sd(p) < 0 ⇔ p ∈ int M, sd = −σ inside):
//   * any unit direction w: sd(p) >= −h_{M−p}(w) (a supporting plane) — certified lower bounds;
//   * any point y of M: sd(p) <= |y − p|; and when a polytope K ⊆ M holds B(p, L): sd(p) <= −L.
// GJK (doubles; Johnson's sub-simplices by enumeration, a triangle's nearest point in an
// orthogonal in-plane frame: triangle_nearest) walks towards p, recording both kinds of bounds;
// when its simplex becomes a tetrahedron holding p strictly (exact orient3d on the
// double points x̃), EPA expands that polytope K̃ = conv(x̃_i), every visibility an exact orient3d,
// so K̃ stays convex with p strictly inside. Its facets' plane distances have rigorous lower
// bounds (differences, cross product and dot with forward error bounds), and since the true
// points x_i are within δ of the x̃_i, conv(x_i) ⊆ M holds B(p, min_F lo_F − δ) (if a ball of
// radius ρ lies in conv(x̃) then B(p, ρ − δ) lies in conv(x): a separating plane argument). σ:
// expand the facet with the least lower bound (its normal's support gives an upper bound of σ
// too) until upper − lower <= kCurvedTargetGap·upper, or no facet can be expanded (the rounding
// floor). σ_d: the same polytope, expanding the facet the ray leaves through; lower bound = the
// exit of the ray from K̃ eroded by δ (every facet plane moved in by δ), upper bound = the least
// h_up(u)/⟨u, d⟩ over the supports evaluated. Cast: conservative advancement along the ray
// (each separating plane certifies that the ray cannot enter M before it reaches the plane),
// then the upper end is the first step past it certified inside M (EPA's ball test).
// Decisions: overlap iff the signed-distance bracket is below 0, apart iff above; a bracket that
// straddles 0 (a contact tangent to within the rounding floor, |sd| <~ δ) is reported as
// touching (docs/robustness.md "Curved primitives").
// Pre-step (σ and signed distance): when P's and Q's components (disk, axial segment, ball) are
// exactly parallel, M is one rounded cylinder answered in closed form (coaxial3.cpp) — the
// symmetric placements where σ is attained on a continuum and EPA cannot close its bracket.
// Near-coaxial pairs (a tilt ε): the tilt-widened closed form, its lower end of σ raised by a
// second-order bound of min h_M over the sphere (coaxial3.cpp), its upper end tightened by a
// compass search of h_M, intersected with EPA's bracket (coaxial_or_epa below). Then ball pairs
// (a ball against a cone, cylinder or spheroid): the signed distance of the ball's centre in the
// other shape's meridian plane, certified (ball3.cpp) — a ring of nearest points on the axis is
// one point there.
// Cost: O(k (log f + s + e)) for k support queries, f facets (a heap by lower bound), s the cost
// of one support (O(1) for curved primitives, O(n) for a polytope's vertex scan), e the faces
// seen around the horizon (by adjacency); k is typically 20–150 for a 1e-13 gap, up to
// kMaxEpaLong near a continuum of almost-nearest points (docs/robustness.md).
#include "primitives/support3.hpp"

#include <pendepth/pendepth.hpp>

#include "primitives/ball3.hpp"
#include "primitives/coaxial3.hpp"
#include <pendepth/polytope.hpp>

#include "convex3/flat3.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <queue>
#include <span>
#include <unordered_map>
#include <vector>

namespace pendepth::primitives {

namespace {
constexpr double kU = 0x1p-53;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMaxGjk = 200;
constexpr int kMaxEpa = 600;
// σ past kMaxEpa: the budget doubles (checkpoints at 2, 4, … × kMaxEpa supports) while each
// doubling at least halves the bracket — near a continuum of almost-nearest points the facets'
// sagitta falls as 1/k² until the ring is resolved, then the bracket collapses (measured: a tilt
// of 1e-6 needs ~19,400 supports); a doubling that does not halve it has met the rounding floor.
// On an exact continuum without a closed form the bracket also shrinks as 1/k² but never
// collapses (a sphere on a cone's axis did, before ball3.cpp: 7e-7 at 4,800 supports), and the
// run cannot tell the two apart: so generic pairs get kMaxEpaGeneric (~15 ms
// at the measured ~3 µs per support), and only near-coaxial pairs whose ring the estimate of
// coaxial_or_epa says will be resolved get kMaxEpaLong (docs/robustness.md "A continuum of
// nearest points"). σ and the signed distance only (σ_d, casts: kMaxEpa).
constexpr int kMaxEpaGeneric = 8 * kMaxEpa;
constexpr int kMaxEpaLong = 64 * kMaxEpa;
constexpr int kMaxCast = 200;

void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}
// (B − A) × (C − A) accurately: the differences exactly as hi + lo (TwoSum), the products'
// leading terms exactly (FMA), so the normal of a sliver triangle keeps its relative accuracy:
// |n_k − ñ_k| <= en (returned) = 2u·max|ñ_k| + 64u²·|B − A|_∞·|C − A|_∞.
Vec3 accurate_normal(const Vec3& A, const Vec3& B, const Vec3& C, double& en) {
  Vec3 bh, bl, ch, cl, n;
  for (int k = 0; k < 3; ++k) {
    two_sum(B[k], -A[k], bh[k], bl[k]);
    two_sum(C[k], -A[k], ch[k], cl[k]);
  }
  en = 0;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double p = bh[i] * ch[j], pe = std::fma(bh[i], ch[j], -p);
    const double q = bh[j] * ch[i], qe = std::fma(bh[j], ch[i], -q);
    const double small = (pe - qe) + (bh[i] * cl[j] + bl[i] * ch[j]) - (bh[j] * cl[i] + bl[j] * ch[i]);
    n[k] = (p - q) + small;
    en = std::max(en, 2 * 0x1p-53 * std::abs(n[k]));
  }
  const double mb = bh.cwiseAbs().maxCoeff(), mc = ch.cwiseAbs().maxCoeff();
  en += 64 * 0x1p-106 * mb * mc;
  return n;
}
double l1(const Vec3& v) { return std::abs(v[0]) + std::abs(v[1]) + std::abs(v[2]); }
double abs_dot(const Vec3& a, const Vec3& b) {
  return std::abs(a[0] * b[0]) + std::abs(a[1] * b[1]) + std::abs(a[2] * b[2]);
}
// a / b rounded down (b > 0 an upper or lower bound chosen by the caller's sign logic).
double down(double x) { return std::nextafter(x, -kInf); }
double upw(double x) { return std::nextafter(x, kInf); }
// x / [blo, bhi] (0 < blo <= bhi) rounded down / up.
double div_down(double x, double blo, double bhi) { return down(x >= 0 ? x / bhi : x / blo); }
double div_up(double x, double blo, double bhi) { return upw(x >= 0 ? x / blo : x / bhi); }
}  // namespace

Vec3 Support3::support(const Vec3& v0) const {
  // v scaled by a power of two (exact: the same direction) so that its largest component is ~1.
  const double big = v0.cwiseAbs().maxCoeff();
  const Vec3 v = big > 0 && std::isfinite(big) ? Vec3(std::ldexp(v0[0], -std::ilogb(big)), std::ldexp(v0[1], -std::ilogb(big)),
                                                      std::ldexp(v0[2], -std::ilogb(big)))
                                               : v0;
  Vec3 s = Vec3::Zero();
  switch (kind) {
    case Kind::Points: {
      std::size_t best = 0;
      double bv = -kInf;
      for (std::size_t i = 0; i < points.size(); ++i)
        if (const double x = points[i].dot(v); x > bv) bv = x, best = i;
      s = points[best];
      break;
    }
    case Kind::Cylinder: {
      const double r = std::hypot(v[0], v[1]);
      if (r > 0) s[0] = a * (v[0] / r), s[1] = a * (v[1] / r);
      s[2] = v[2] > 0 ? b : v[2] < 0 ? -b : 0.0;
      break;
    }
    case Kind::Cone: {
      const double r = std::hypot(v[0], v[1]);
      if (b * v[2] >= a * r - b * v[2]) {
        s = Vec3(0, 0, b);
      } else {
        if (r > 0) s[0] = a * (v[0] / r), s[1] = a * (v[1] / r);
        s[2] = -b;
      }
      break;
    }
    case Kind::Ellipsoid: {
      const Vec3 w(a * v[0], b * v[1], c * v[2]);
      const double n = w.norm();
      if (n > 0) s = Vec3(a * (w[0] / n), b * (w[1] / n), c * (w[2] / n));
      break;
    }
  }
  if (radius > 0) {
    const double n = v.norm();
    if (n > 0) s += radius * (v / n);
  }
  return s;
}

Support3 support_of(const Shape3& shape) {
  Support3 s;
  s.radius = shape.radius();
  const Shape3 core = shape.core();
  double rho = 0;
  if (const Curved3* c = core.curved()) {
    s.kind = c->kind == Curved3::Kind::Cylinder ? Support3::Kind::Cylinder
             : c->kind == Curved3::Kind::Cone   ? Support3::Kind::Cone
                                                : Support3::Kind::Ellipsoid;
    s.a = c->a, s.b = c->b, s.c = c->c;
    rho = c->kind == Curved3::Kind::Ellipsoid ? std::max({c->a, c->b, c->c}) : std::hypot(c->a, c->b);
  } else {
    if (core.dimension() < 3) {
      const auto v = core.flat_vertices();
      s.points.assign(v.begin(), v.end());
    } else {
      const auto v = core.polytope().vertices();
      s.points.assign(v.begin(), v.end());
    }
    for (const Vec3& p : s.points) rho = std::max(rho, p.norm());
  }
  s.rho = (rho + s.radius) * (1 + 0x1p-40);
  return s;
}

namespace {

// A point of M − p with the two shape points that make it (P's frame).
struct Vert {
  Vec3 x = Vec3::Zero(), p = Vec3::Zero(), q = Vec3::Zero();
};

class Engine {
 public:
  Engine(const Support3& P, const Support3& Q, const Eigen::Matrix3d& R, const Vec3& t)
      : P_(P), Q_(Q), R_(R), Rt_(R.transpose()), t_(t) {
    const double n1 = R.cwiseAbs().colwise().sum().maxCoeff(), ninf = R.cwiseAbs().rowwise().sum().maxCoeff();
    nR_ = std::sqrt(n1 * ninf) * (1 + 0x1p-40);
    set_query(Vec3::Zero());
  }
  void set_query(const Vec3& p) {
    p_ = p;
    delta_ = kU * (16 * P_.rho + 24 * nR_ * Q_.rho + 4 * t_.norm() + 2 * p.norm()) * (1 + 0x1p-30);
  }
  const Vec3& query() const { return p_; }
  double delta() const { return delta_; }
  Vert support(const Vec3& u) const {
    ++supports;
    Vert v;
    v.p = P_.support(u);
    v.q = R_ * Q_.support(Rt_ * (-u)) + t_;
    v.x = (v.p - v.q) - p_;
    return v;
  }
  // An upper bound of h_{M−p}(u) from its support point.
  double value_up(const Vert& v, const Vec3& u) const {
    const double h = v.x.dot(u);
    return upw(h + (delta_ * u.norm() * (1 + 4 * kU) + 4 * kU * abs_dot(v.x, u)) * (1 + 0x1p-40));
  }
  mutable int supports = 0;

 private:
  const Support3 &P_, &Q_;
  Eigen::Matrix3d R_, Rt_;
  Vec3 t_, p_;
  double nR_ = 1, delta_ = 0;
};

// |u| bounds of a double vector: [lo, hi].
std::array<double, 2> norm_bounds(const Vec3& u) {
  const double n = u.norm();
  return {n * (1 - 4 * kU), n * (1 + 4 * kU)};
}

// ---- GJK: the nearest point of conv(simplex) to the origin (Johnson by enumeration) -----------
struct Simplex {
  std::array<Vert, 4> v;
  std::array<double, 4> w{};  // barycentric weights of the nearest point
  int n = 0;
};

bool strictly_inside(const Simplex& s) {
  static constexpr int f[4][4] = {{1, 2, 3, 0}, {0, 3, 2, 1}, {0, 1, 3, 2}, {0, 2, 1, 3}};
  const Vec3 o = Vec3::Zero();
  for (const auto& k : f) {
    const int a = predicates::orient3d(s.v[k[0]].x, s.v[k[1]].x, s.v[k[2]].x, s.v[k[3]].x);
    const int b = predicates::orient3d(s.v[k[0]].x, s.v[k[1]].x, s.v[k[2]].x, o);
    if (a == 0 || a != b) return false;
  }
  return true;
}

// The nearest point of the triangle ABC to the origin when it is the projection of the origin
// onto ABC's plane, strictly inside ABC (else false: the nearest point lies on an edge, which the
// enumeration covers). Why not Johnson's normal equations: near contact |y| << the triangle's
// size L, and an in-plane error e of y adds |e|²/2|y| to |y|; on a ridge of M (a ruled strip —
// a cone's slant line, a cylinder's side line, a box edge — against a rim) GJK's triangles are
// slivers and needles whose Gram matrix squares their condition number, and the clamped,
// misplaced y lost to the previous face: GJK cycled, its bracket stuck at 1e-12…3e-11
// (docs/robustness.md "Gap"). Here an orthogonal in-plane frame instead: A, B the longest edge's
// ends, e1 = B − A, e2 = C − A, n = e1 × e2 accurately (accurate_normal), p = n × e1 = |e1|²·e2⊥
// (e2⊥ = e2 − c·e1, c = ⟨e2, e1⟩/|e1|²). The foot f = A + s·e1 + t·e2⊥ with s = −⟨A, e1⟩/|e1|²,
// t = −⟨A, e2⊥⟩/|e2⊥|² = −⟨A, p⟩|e1|²/|p|², so f = A + (s − t·c)·e1 + t·e2. Rounding moves f by
// Δs·|e1| + Δt·|e2⊥| + Δc·t·|e1| = O(u·(|A| + L)) in the plane, whatever the shape of ABC (Δt is
// large for a needle, but it moves f along e2⊥, |e2⊥| ~ the needle's width). y = A + λ_B·e1 +
// λ_C·e2 with λ_B, λ_C >= 0 and fl(λ_B + λ_C) < 1 (so λ_B + λ_C <= 1) is an exact convex
// combination of A, B, C evaluated within 7.1u·m per component, m = max |x_i| (point_up).
bool triangle_nearest(const std::array<const Vec3*, 3>& x, std::array<double, 3>& w, Vec3& y) {
  const double e01 = (*x[1] - *x[0]).squaredNorm(), e12 = (*x[2] - *x[1]).squaredNorm(), e20 = (*x[0] - *x[2]).squaredNorm();
  const int c = e01 >= e12 && e01 >= e20 ? 2 : e12 >= e20 ? 0 : 1, a = (c + 1) % 3, b = (c + 2) % 3;
  const Vec3 &A = *x[a], &B = *x[b], &C = *x[c];
  const Vec3 e1 = B - A, e2 = C - A;
  double en = 0;
  const Vec3 pn = accurate_normal(A, B, C, en).cross(e1);
  const double e1e1 = e1.squaredNorm(), pp = pn.squaredNorm();
  if (!(pp > 0 && e1e1 > 0) || !std::isfinite(pp)) return false;
  const double s = -A.dot(e1) / e1e1, t = -A.dot(pn) / pp * e1e1, cc = e2.dot(e1) / e1e1;
  const double lb = s - t * cc, lc = t;
  if (!(lb > 0 && lc > 0 && lb + lc < 1)) return false;
  // (A's weight kept > 0: the caller keeps A in the simplex, so point_up's m covers it)
  w[b] = lb, w[c] = lc, w[a] = std::max(1 - lb - lc, std::numeric_limits<double>::denorm_min());
  y = A + (lb * e1 + lc * e2);
  return true;
}

// Reduces s to the face whose relative interior holds the nearest point (weights set) and returns
// that point; `inside` when s is a tetrahedron holding 0 strictly (exact).
Vec3 nearest(Simplex& s, bool& inside) {
  inside = false;
  if (s.n == 4 && strictly_inside(s)) {
    inside = true;
    return Vec3::Zero();
  }
  double best = kInf;
  int best_mask = 0;
  std::array<double, 4> best_w{};
  Vec3 best_y = Vec3::Zero();
  const int full = (1 << s.n) - 1;
  for (int mask = 1; mask <= full; ++mask) {
    if (mask == full && s.n == 4) continue;  // the tetrahedron's interior: handled above
    int idx[4], k = 0;
    for (int i = 0; i < s.n; ++i)
      if (mask >> i & 1) idx[k++] = i;
    const Vec3& a = s.v[idx[0]].x;
    std::array<double, 4> w{};
    Vec3 y;
    if (k == 1) {
      w[idx[0]] = 1, y = a;
    } else if (k == 3) {
      std::array<double, 3> tw{};
      if (!triangle_nearest({&s.v[idx[0]].x, &s.v[idx[1]].x, &s.v[idx[2]].x}, tw, y)) continue;
      for (int j = 0; j < 3; ++j) w[idx[j]] = tw[j];
    } else {
      Eigen::Matrix<double, 3, Eigen::Dynamic> E(3, k - 1);
      for (int j = 1; j < k; ++j) E.col(j - 1) = s.v[idx[j]].x - a;
      const Eigen::MatrixXd G = E.transpose() * E;
      const Eigen::VectorXd rhs = -(E.transpose() * a);
      // Any solution will do (the weights are clamped and y recomputed below, so a poorly
      // conditioned sliver still gives a true convex combination); only non-finite ones are skipped.
      Eigen::FullPivLU<Eigen::MatrixXd> lu(G);
      lu.setThreshold(std::numeric_limits<double>::denorm_min());
      const Eigen::VectorXd mu = lu.solve(rhs);
      if (!mu.allFinite()) continue;
      // Weights clamped to >= 0 and renormalised: y below is then a true convex combination
      // (computed from those weights), whatever the conditioning of the solve.
      double sum = 1;
      w[idx[0]] = 1;
      for (int j = 1; j < k; ++j) {
        w[idx[j]] = std::max(0.0, mu[j - 1]);
        w[idx[0]] -= mu[j - 1];
      }
      w[idx[0]] = std::max(0.0, w[idx[0]]);
      sum = 0;
      for (int j = 0; j < k; ++j) sum += w[idx[j]];
      if (!(sum > 0)) continue;
      y = Vec3::Zero();
      for (int j = 0; j < k; ++j) w[idx[j]] /= sum, y += w[idx[j]] * s.v[idx[j]].x;
    }
    const double d = y.squaredNorm();
    if (d < best) {
      best = d, best_w = w, best_y = y, best_mask = 0;
      for (int i = 0; i < s.n; ++i)
        if (w[i] > 0) best_mask |= 1 << i;
    }
  }
  if (best_mask == 0) best_mask = 1, best_w = {1, 0, 0, 0}, best_y = s.v[0].x;  // (guard)
  Simplex r;
  for (int i = 0; i < s.n; ++i)
    if (best_mask >> i & 1) r.v[r.n] = s.v[i], r.w[r.n] = best_w[i], ++r.n;
  s = r;
  return best_y;
}

// Whether a's points are b's first a.n points (b: a with one point appended).
bool same_points(const Simplex& a, const Simplex& b) {
  for (int i = 0; i < a.n; ++i)
    if (a.v[i].x != b.v[i].x) return false;
  return true;
}

struct GjkOut {
  bool tetra = false;  // s holds the query strictly (EPA can start)
  Simplex s;
  double lo = -kInf, hi = kInf;  // signed distance bracket from GJK's bounds
  Vec3 sep_w = Vec3::Zero();     // the best separating direction: M − p ⊂ {⟨x, w⟩ <= sep_h}
  double sep_h = kInf;
  Vec3 y = Vec3::Zero();  // the nearest point found (M − p coordinates)
};

// The upper bound |y| + error for a convex combination y of the simplex's points: y computed
// within 8u·m of one (Johnson's weights) or within 7.1u·m per component, 12.3u·m in norm, of one
// (triangle_nearest's anchored form); m = max |x_i|.
double point_up(const Simplex& s, const Vec3& y, double delta) {
  double m = 0;
  for (int i = 0; i < s.n; ++i) m = std::max(m, s.v[i].x.norm());
  return upw((y.norm() + delta + 13 * kU * m) * (1 + 4 * kU));
}

GjkOut gjk(const Engine& E, Vec3 dir) {
  GjkOut out;
  if (!(dir.squaredNorm() > 0) || !dir.allFinite()) dir = Vec3(1, 0, 0);
  out.s.v[0] = E.support(dir), out.s.n = 1, out.s.w[0] = 1;
  auto plane = [&](const Vec3& w, const Vert& v) {
    const double hup = E.value_up(v, w);
    const auto nb = norm_bounds(w);
    const double lo = div_down(-hup, nb[0], nb[1]);
    if (lo > out.lo) out.lo = lo, out.sep_w = w, out.sep_h = hup;
  };
  plane(dir, out.s.v[0]);
  int blowups = 0;
  for (int it = 0; it < kMaxGjk; ++it) {
    bool inside = false;
    const Simplex before = out.s;
    const Vec3 y = nearest(out.s, inside);
    if (inside) {
      out.tetra = true;
      return out;
    }
    // The point just added was dropped and the simplex is the one before it, in the same order:
    // every later iteration would repeat this one bit for bit (the rounding floor), so stop.
    if (it > 0 && out.s.n == before.n - 1 && y == out.y && same_points(out.s, before)) break;
    out.y = y;
    const double yy = y.squaredNorm();
    Vert v;
    if (yy == 0) {  // the query lies on the simplex (of dimension < 3): blow it up
      if (++blowups > 4) break;  // on the boundary of every simplex tried: the caller's hull start
      Vec3 cand[6];
      int nc = 0;
      if (out.s.n == 1) {
        cand[0] = Vec3(1, 0, 0), cand[1] = Vec3(-1, 0, 0), cand[2] = Vec3(0, 1, 0), cand[3] = Vec3(0, -1, 0),
        cand[4] = Vec3(0, 0, 1), cand[5] = Vec3(0, 0, -1), nc = 6;
      } else if (out.s.n == 2) {
        const Vec3 e = out.s.v[1].x - out.s.v[0].x;
        int k = 0;
        e.cwiseAbs().minCoeff(&k);
        const Vec3 a = e.cross(Vec3::Unit(k)), b = e.cross(a);
        cand[0] = a, cand[1] = -a, cand[2] = b, cand[3] = -b, nc = 4;
      } else {
        const Vec3 nrm = (out.s.v[1].x - out.s.v[0].x).cross(out.s.v[2].x - out.s.v[0].x);
        cand[0] = nrm, cand[1] = -nrm, nc = 2;
      }
      bool grown = false;
      for (int c = 0; c < nc && !grown; ++c) {
        if (!(cand[c].squaredNorm() > 0)) continue;
        v = E.support(cand[c]);
        plane(cand[c], v);
        bool fresh = true;
        for (int i = 0; i < out.s.n; ++i) fresh = fresh && v.x != out.s.v[i].x;
        if (!fresh) continue;
        if (out.s.n == 2 && predicates::collinear3(out.s.v[0].x, out.s.v[1].x, v.x)) continue;
        if (out.s.n == 3 && predicates::orient3d(out.s.v[0].x, out.s.v[1].x, out.s.v[2].x, v.x) == 0) continue;
        out.s.v[out.s.n++] = v, grown = true;
      }
      if (!grown) break;  // M − p is flat around the query to rounding: undecided
      continue;
    }
    out.hi = std::min(out.hi, point_up(out.s, y, E.delta()));
    // The search direction: from y towards the query; on a triangle its accurate normal (y's
    // direction has error u·|x|/|y| near contact, the normal of differences does not).
    Vec3 w = -y;
    if (out.s.n == 3) {
      double en = 0;
      Vec3 nrm = accurate_normal(out.s.v[0].x, out.s.v[1].x, out.s.v[2].x, en);
      if (nrm.dot(y) > 0) nrm = -nrm;
      if (nrm.squaredNorm() > 0 && en < 1e-3 * nrm.cwiseAbs().maxCoeff()) w = nrm;
    } else if (out.s.n == 2) {  // (a × b) × (b − a): in the plane of 0 and the edge, ⟂ the edge
      double en = 0;
      const Vec3 &a = out.s.v[0].x, &b = out.s.v[1].x;
      const Vec3 ab = accurate_normal(Vec3::Zero(), a, b, en);
      Vec3 nrm = ab.cross(b - a);
      if (nrm.dot(y) > 0) nrm = -nrm;
      if (nrm.squaredNorm() > 0 && en < 1e-3 * ab.cwiseAbs().maxCoeff()) w = nrm;
    }
    v = E.support(w);
    plane(w, v);
    if (out.hi - out.lo <= kCurvedTargetGap * std::max(std::abs(out.hi), std::abs(out.lo))) break;
    // No progress: the new point is not beyond y's plane by more than rounding.
    if ((v.x - y).dot(w) <= 0x1p-44 * std::sqrt(yy) * w.norm()) break;
    bool fresh = true;
    for (int i = 0; i < out.s.n; ++i) fresh = fresh && v.x != out.s.v[i].x;
    if (!fresh || out.s.n == 4) break;
    out.s.v[out.s.n++] = v;

  }
  return out;
}

// ---- EPA on the certified inner polytope --------------------------------------------------
struct Face {
  int a, b, c;
  Vec3 n;                  // (b − a) × (c − a) rounded, outward
  double nn = 0;           // |n| rounded
  double en = 0;           // bound of |n_true − n| per component
  double est = 0, lo = 0;  // plane distance: estimate and rigorous lower bound
  double den_lo = 0;       // lower bound of |n_true|
  bool alive = true, final = false;
  std::array<int, 3> nb{-1, -1, -1};  // the faces across edges (a, b), (b, c), (c, a)
};

class Epa {
 public:
  Epa(const Engine& E, const Simplex& s) : E_(E) {
    for (int i = 0; i < 4; ++i) v_.push_back(s.v[i]);
    static constexpr int f[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
    for (const auto& k : f) {
      if (predicates::orient3d(v_[k[0]].x, v_[k[1]].x, v_[k[2]].x, v_[k[3]].x) > 0)
        add_face(k[0], k[2], k[1]);
      else
        add_face(k[0], k[1], k[2]);
    }
    link_all();
  }

  // From any polytope given as vertices and outward triangles (0 strictly inside).
  Epa(const Engine& E, std::vector<Vert> verts, std::span<const std::array<int, 3>> tris) : E_(E), v_(std::move(verts)) {
    for (const auto& t : tris) add_face(t[0], t[1], t[2]);
    link_all();
  }

  // Lower bound of σ at the query: every facet's lower bound, minus δ.
  double lower() const {
    double m = kInf;
    for (const Face& f : f_)
      if (f.alive) m = std::min(m, f.lo);
    return down(m - E_.delta() * (1 + 0x1p-40));
  }

  // σ: expand until the bracket [lower, U] is within the target (or mode `certify`: until the
  // lower bound is positive), or until the facet with the least lower bound cannot be expanded.
  // The facet with the least lower bound comes from a heap (O(log f) per support; the same
  // facet as a scan in index order, ties to the lowest index). Budget: kMaxEpa supports, then
  // doublings while each halves the bracket, up to `budget` (>= kMaxEpa; certify: kMaxEpa).
  void minimum(bool certify, int budget) {
    double checkpoint_gap = kInf;
    for (int it = 0, checkpoint = kMaxEpa; it < budget; ++it) {
      while (!heap_.empty() && !f_[heap_.top().second].alive) heap_.pop();
      if (heap_.empty()) return;
      const int fi = heap_.top().second;
      const double L = down(heap_.top().first - E_.delta() * (1 + 0x1p-40));
      if (certify ? L > 0 : U_ < kInf && U_ - L <= kCurvedTargetGap * U_) return;
      if (f_[fi].final) return;
      if (it == checkpoint) {  // past kMaxEpa only while each doubling halves the bracket
        const double gap = U_ - L;
        if (certify || !(gap <= 0.5 * checkpoint_gap)) return;
        checkpoint_gap = gap, checkpoint *= 2;
      }
      step(fi);
    }
  }

  // σ_d along d: expand the facet the ray leaves through until [lambda_lo, lambda_hi] (in units
  // of d) is within the target.
  void along(const Vec3& d) {
    const double dl1 = l1(d);
    {  // an upper bound from the support along d itself
      const Vert v = E_.support(d);
      ray_plane(d, v, d);
    }
    for (int it = 0; it < kMaxEpa; ++it) {
      int fi = -1;
      double best = kInf, lam_lo = kInf;
      const double delta = E_.delta() * (1 + 0x1p-40);
      for (std::size_t i = 0; i < f_.size(); ++i) {
        const Face& f = f_[i];
        if (!f.alive) continue;
        const double nd = f.n.dot(d);
        if (nd > 0 && f.est * f.nn / nd < best) best = f.est * f.nn / nd, fi = static_cast<int>(i);
        const double c_up = upw(nd + (f.en * dl1 + 4 * kU * abs_dot(f.n, d)) * (1 + 0x1p-40));
        if (!(c_up > 0)) continue;
        const double num = down(f.lo - delta);
        if (!(num > 0) || !(f.den_lo > 0)) {
          lam_lo = 0;
          continue;
        }
        lam_lo = std::min(lam_lo, down(down(num * f.den_lo) / c_up));
      }
      lam_lo_ = lam_lo == kInf ? 0 : lam_lo;
      if (lam_hi_ < kInf && lam_hi_ - lam_lo_ <= kCurvedTargetGap * lam_hi_) return;
      if (fi < 0 || f_[fi].final) return;
      step(fi, &d);
    }
  }

  double U() const { return U_; }
  const Vec3& U_dir() const { return U_dir_; }
  const Vert& U_vert() const { return U_vert_; }
  double lam_lo() const { return lam_lo_; }
  double lam_hi() const { return lam_hi_; }
  const Vec3& lam_dir() const { return lam_dir_; }
  const Vert& lam_vert() const { return lam_vert_; }

 private:
  const Engine& E_;
  std::vector<Vert> v_;
  std::vector<Face> f_;
  // Min-heap of (lower bound, face index) over the faces with a finite lower bound; dead faces
  // are dropped when they reach the top.
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap_;
  // step()'s scratch, kept across steps: marks by stamp (no per-step allocation of O(f)).
  std::vector<unsigned> seen_, vis_;
  unsigned stamp_ = 0;
  std::vector<int> stack_, visible_;
  std::vector<std::pair<int, int>> horizon_;  // (visible face, its edge k)
  std::vector<int> from_, to_;                  // vertex → the new face whose horizon edge starts / ends there
  double U_ = kInf;
  Vec3 U_dir_ = Vec3::Zero();
  Vert U_vert_{};
  double lam_lo_ = 0, lam_hi_ = kInf;
  Vec3 lam_dir_ = Vec3::Zero();
  Vert lam_vert_{};

  static std::uint64_t key(int i, int j) { return static_cast<std::uint64_t>(i) << 32 | static_cast<std::uint32_t>(j); }
  static std::pair<int, int> edge(const Face& F, int k) {
    return k == 0 ? std::pair{F.a, F.b} : k == 1 ? std::pair{F.b, F.c} : std::pair{F.c, F.a};
  }
  // The initial polytope's adjacency (closed: every directed edge (i, j) has its twin (j, i)).
  void link_all() {
    std::unordered_map<std::uint64_t, int> owner;
    for (std::size_t g = 0; g < f_.size(); ++g)
      for (int k = 0; k < 3; ++k) owner[key(edge(f_[g], k).first, edge(f_[g], k).second)] = static_cast<int>(g);
    for (Face& F : f_)
      for (int k = 0; k < 3; ++k)
        if (const auto it = owner.find(key(edge(F, k).second, edge(F, k).first)); it != owner.end()) F.nb[k] = it->second;
  }

  void add_face(int a, int b, int c) {
    Face f{a, b, c, Vec3::Zero()};
    const Vec3 &A = v_[a].x, &B = v_[b].x, &C = v_[c].x;
    // (B − A) × (C − A) accurately: the differences exactly as hi + lo (TwoSum), the products'
    // leading terms exactly (FMA), so the normal of a sliver triangle keeps its relative accuracy:
    // |n_k − ñ_k| <= 2u|ñ_k| + 32u²·|B − A|_∞·|C − A|_∞.
    double en = 0;
    f.n = accurate_normal(A, B, C, en);
    f.en = upw(en * (1 + 0x1p-40));
    f.nn = f.n.norm();
    const double dot = f.n.dot(A);
    f.est = f.nn > 0 ? dot / f.nn : -kInf;
    const double num = down((dot - f.en * l1(A) - 4 * kU * abs_dot(f.n, A)) * (1 - 0x1p-50));
    const double den_up = upw((f.nn * (1 + 4 * kU) + 1.75 * f.en) * (1 + 0x1p-50));
    f.den_lo = down((f.nn * (1 - 4 * kU) - 1.75 * f.en) * (1 - 0x1p-50));
    f.lo = num >= 0 ? down(num / den_up) : f.den_lo > 0 ? down(num / f.den_lo) : -kInf;
    const int id = static_cast<int>(f_.size());
    f_.push_back(f);
    seen_.push_back(0), vis_.push_back(0);
    if (f.lo < kInf) heap_.push({f.lo, id});  // (a NaN or +∞ bound is never the least)
  }

  void ray_plane(const Vec3& u, const Vert& v, const Vec3& d) {
    const double hup = E_.value_up(v, u);
    const double ud = down(u.dot(d) - 4 * kU * abs_dot(u, d));
    if (!(ud > 0)) return;
    const double lam = hup <= 0 ? 0.0 : upw(hup / ud);
    if (lam < lam_hi_) lam_hi_ = lam, lam_dir_ = u, lam_vert_ = v;
  }

  // The support along facet fi's normal: bounds, then expansion (or the facet is final).
  void step(int fi, const Vec3* d = nullptr) {
    Face& f = f_[fi];
    if (!(f.nn > 0) || !std::isfinite(f.nn)) {  // (an underflowed normal: nothing to expand)
      f.final = true;
      return;
    }
    const Vec3 u = f.n / f.nn;
    const Vert v = E_.support(u);
    {
      const double hup = E_.value_up(v, u);
      const auto nb = norm_bounds(u);
      const double cand = div_up(hup, nb[0], nb[1]);
      if (cand < U_) U_ = cand, U_dir_ = u, U_vert_ = v;
    }
    if (d) ray_plane(u, v, *d);
    if (predicates::orient3d(v_[f.a].x, v_[f.b].x, v_[f.c].x, v.x) <= 0) {
      f.final = true;
      return;
    }
    const int nv = static_cast<int>(v_.size());
    v_.push_back(v);
    // The visible faces (connected, from fi, by adjacency), then the horizon as directed edges
    // (i, j) of visible faces with the face h beyond, in a fixed order: the new faces' indices,
    // hence the heap's ties, do not depend on anything but the polytope.
    ++stamp_;
    stack_.assign(1, fi), visible_.clear(), horizon_.clear();
    seen_[fi] = stamp_, vis_[fi] = stamp_;
    while (!stack_.empty()) {
      const int g = stack_.back();
      stack_.pop_back();
      visible_.push_back(g);
      for (const int h : f_[g].nb) {
        if (h < 0 || seen_[h] == stamp_) continue;
        seen_[h] = stamp_;
        const Face& H = f_[h];
        if (predicates::orient3d(v_[H.a].x, v_[H.b].x, v_[H.c].x, v.x) > 0) vis_[h] = stamp_, stack_.push_back(h);
      }
    }
    for (int g : visible_)
      for (int k = 0; k < 3; ++k)
        if (const int h = f_[g].nb[k]; h < 0 || vis_[h] != stamp_) horizon_.push_back({g, k});
    for (int g : visible_) f_[g].alive = false;
    // The cone from nv over the horizon (a simple cycle): face (i, j, nv) has h across (i, j), the
    // new face starting at j across (j, nv), the one ending at i across (nv, i).
    from_.resize(v_.size()), to_.resize(v_.size());
    const int first = static_cast<int>(f_.size());
    for (auto [g, k] : horizon_) {
      const auto [i, j] = edge(f_[g], k);
      const int h = f_[g].nb[k], id = static_cast<int>(f_.size());
      add_face(i, j, nv);
      f_[id].nb[0] = h;
      if (h >= 0)
        for (int m = 0; m < 3; ++m)
          if (edge(f_[h], m) == std::pair{j, i}) f_[h].nb[m] = id;
      from_[i] = id, to_[j] = id;
    }
    for (int id = first; id < static_cast<int>(f_.size()); ++id) f_[id].nb[1] = from_[f_[id].b], f_[id].nb[2] = to_[f_[id].a];
  }
};

// ---- the queries ----------------------------------------------------------------------------
struct Frame {
  Eigen::Matrix3d Rp;
  Vec3 tp;
  Eigen::Matrix3d R;  // relative rotation
  Vec3 t;             // relative translation (Q's origin in P's frame)
  Vec3 point(const Vec3& x) const { return Rp * x + tp; }
  Vec3 vec(const Vec3& x) const { return Rp * x + Vec3::Zero(); }
};

Frame frame_of(const Pose3& pp, const Pose3& pq) {
  Frame f;
  f.Rp = pp.matrix();
  const Eigen::Matrix3d Rq = pq.matrix();
  f.tp = pp.translation;
  f.R = f.Rp.transpose() * Rq;
  f.t = f.Rp.transpose() * pq.translation - f.Rp.transpose() * pp.translation;
  return f;
}

// The signed distance at the engine's query: bracket and the objects to report.
struct Sd {
  double lo = -kInf, hi = kInf;
  int state = 0;  // +1 apart (lo > 0), −1 overlapping (hi < 0), 0 undecided
  GjkOut g;
  double L = 0, U = kInf;  // overlapping: σ ∈ [L, U]
  Vec3 U_dir = Vec3::Zero();
  Vert U_vert{};
};

Sd signed_distance_at(const Engine& E, bool certify_only, std::unique_ptr<Epa>* keep = nullptr, int budget = kMaxEpa) {
  Sd r;
  r.g = gjk(E, -(E.query()) + Vec3(0x1p-20, 0, 0));
  r.lo = r.g.lo, r.hi = r.g.hi;
  for (int i = 0; i < r.g.s.n; ++i) {  // any point of M bounds sd from above
    Simplex one;
    one.v[0] = r.g.s.v[i], one.n = 1;
    r.hi = std::min(r.hi, point_up(one, r.g.s.v[i].x, E.delta()));
  }
  std::unique_ptr<Epa> epa;
  if (r.g.tetra) {
    epa = std::make_unique<Epa>(E, r.g.s);
  } else if (!(r.lo > 0)) {
    // GJK ended without a tetrahedron holding the query strictly (it lies on an edge or face of
    // every simplex tried: symmetric placements). Start from the exact hull of the supports
    // along 26 directions (and GJK's points) when it holds the query strictly.
    std::vector<Vert> pts;
    for (int i = 0; i < r.g.s.n; ++i) pts.push_back(r.g.s.v[i]);
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int c = -1; c <= 1; ++c)
          if (a || b || c) pts.push_back(E.support(Vec3(a, b, c) + Vec3(0x1p-12 * b, 0x1p-13 * c, 0x1p-14 * a)));
    std::vector<Vec3> xs;
    for (const Vert& v : pts) xs.push_back(v.x);
    try {
      const ConvexPolytope H = ConvexPolytope::hull(xs);
      bool inside = true;
      for (const auto& t : H.triangles()) inside = inside && predicates::orient3d(H[t[0]], H[t[1]], H[t[2]], Vec3::Zero()) < 0;
      if (inside) {
        std::vector<Vert> hv;
        for (const Vec3& x : H.vertices())
          for (const Vert& v : pts)
            if (v.x == x) {
              hv.push_back(v);
              break;
            }
        if (hv.size() == H.vertices().size()) epa = std::make_unique<Epa>(E, std::move(hv), H.triangles());
      }
    } catch (const InvalidInput&) {  // the supports are flat: no interior found, undecided
    }
  }
  if (epa) {
    epa->minimum(certify_only, budget);
    r.L = epa->lower();
    r.U = epa->U();
    r.U_dir = epa->U_dir(), r.U_vert = epa->U_vert();
    if (r.L > 0) r.hi = std::min(r.hi, -r.L);
    if (r.U < kInf) r.lo = std::max(r.lo, -r.U);
    if (keep) *keep = std::move(epa);
  }
  r.state = r.lo > 0 ? 1 : r.hi < 0 ? -1 : 0;
  return r;
}

Vec3 combo(const Simplex& s, bool p) {
  Vec3 x = Vec3::Zero();
  double sw = 0;
  for (int i = 0; i < s.n; ++i) x += s.w[i] * (p ? s.v[i].p : s.v[i].q), sw += s.w[i];
  return sw > 0 ? Vec3(x / sw) : x;
}

// ---- coaxial pairs: M = K − t in closed form (coaxial3.cpp) ---------------------------------
// sd_M(0) = sd_K(t) and the support pair along K's outward normal n at the nearest point.
struct ClosedForm {
  CoaxialSd sd;
  Vert touch{};
};
ClosedForm closed_form(const Support3& P, const Support3& Q, const Frame& F, const CoaxialSum& K) {
  ClosedForm c;
  c.sd = coaxial_signed_distance(K, F.t);
  const Vec3& n = c.sd.normal;
  c.touch.p = P.support(n);
  c.touch.q = F.R * Q.support(F.R.transpose() * (-n)) + F.t;
  return c;
}

double norm_up(const Vec3& d) { return upw(d.norm() * (1 + 4 * kU)); }
double norm_down(const Vec3& d) { return down(d.norm() * (1 - 4 * kU)); }

// The answers from the closed form, in the engine's bracket semantics (as below): apart when the
// bracket of sd is above 0, overlapping when below, else touching with the bracket kept.
Distance3 coaxial_distance(const ClosedForm& c, const Frame& F) {
  Distance3 out;
  out.lower_bound = c.sd.lo, out.upper_bound = c.sd.hi;
  const Vec3 n = F.vec(c.sd.normal);
  if (c.sd.lo > 0) {
    out.distance = c.sd.hi;
    out.normal = n;
    out.translation = -out.distance * n + Vec3::Zero();
    out.witness_p = F.point(c.touch.p), out.witness_q = F.point(c.touch.q);
  } else if (c.sd.hi < 0) {
    out.overlapping = true;
    out.distance = c.sd.lo;
    out.normal = n;
    out.translation = -c.sd.lo * n + Vec3::Zero();
    out.witness_p = F.point(c.touch.p), out.witness_q = F.point(c.touch.q);
  } else {
    out.witness_p = out.witness_q = F.point(c.touch.p);
  }
  return out;
}

Depth3 coaxial_minimum(const ClosedForm& c, const Frame& F) {
  Depth3 out;
  out.kind = DepthKind::Minimum;
  if (c.sd.lo > 0) return out;
  if (!(c.sd.hi < 0)) {
    out.upper_bound = std::max(0.0, -c.sd.lo);
    return out;
  }
  out.overlapping = true;
  out.depth = out.upper_bound = -c.sd.lo;
  out.lower_bound = -c.sd.hi;
  out.normal = out.facet_normal = F.vec(c.sd.normal);
  out.translation = F.vec(out.depth * c.sd.normal);
  out.witness_p = out.witness_q = F.point(c.touch.p);
  return out;
}

Distance3 epa_distance(const Support3& P, const Support3& Q, const Frame& F, int budget) {
  const Engine E(P, Q, F.R, F.t);
  const Sd s = signed_distance_at(E, false, nullptr, budget);
  Distance3 out;
  out.lower_bound = s.lo, out.upper_bound = s.hi;
  if (s.state > 0) {  // apart: the upper end, realised by a pair of points within rounding
    out.distance = s.hi;
    const Vec3 n = -s.g.y.normalized();
    out.normal = F.vec(n);
    out.translation = -out.distance * out.normal + Vec3::Zero();
    out.witness_p = F.point(combo(s.g.s, true));
    out.witness_q = F.point(combo(s.g.s, false));
  } else if (s.state < 0) {  // overlapping: −σ's upper end, σ's move
    out.overlapping = true;
    out.distance = -s.U;
    out.normal = F.vec(s.U_dir.normalized());
    out.translation = s.U * out.normal + Vec3::Zero();
    out.witness_p = F.point(s.U_vert.p);
    out.witness_q = F.point(s.U_vert.q);
  } else {  // undecided (tangent to the rounding floor): reported as touching, the bracket kept
    out.distance = 0;
    out.witness_p = out.witness_q = F.point(combo(s.g.s, true));
  }
  return out;
}

Depth3 epa_minimum(const Support3& P, const Support3& Q, const Frame& F, int budget) {
  const Engine E(P, Q, F.R, F.t);
  const Sd s = signed_distance_at(E, false, nullptr, budget);
  Depth3 out;
  out.kind = DepthKind::Minimum;
  out.candidates = static_cast<std::size_t>(E.supports);
  if (s.state > 0) return out;
  if (s.state == 0) {  // undecided: depth 0 (touching), the bracket of σ kept
    out.upper_bound = std::max(0.0, -s.lo);
    return out;
  }
  out.overlapping = true;
  out.depth = out.upper_bound = s.U;
  out.lower_bound = s.L;
  out.normal = out.facet_normal = F.vec(s.U_dir.normalized());
  out.translation = F.vec(s.U * s.U_dir.normalized());
  out.witness_p = out.witness_q = F.point(s.U_vert.p);
  return out;
}

// Near-coaxial, overlapping: σ = min over unit u of h_{M}(u) (0 inside M), so every direction
// gives a certified upper bound h_up(u)/|u| (as EPA's U). A compass search in the tangent basis
// at u0 (horizontal e1 = e_z × u0 along the ring of almost-nearest directions, e2 across it: the
// kinks of h_M run along these), steps halving from 1/4 to 2⁻⁵² (at most kMaxSearch supports).
// Three starts, K's side normal towards t, its cap normal, and the ring direction orthogonal to
// both axes: with the query near K's centre each is (almost) nearest and h_M has a local minimum
// at each (the third is the ring's exact minimiser at t = 0). The upper end then sits on the tilted
// M's true minimum to rounding, where the tilt bound only gives σ_K + tilt. The reported move is
// along the best u.
constexpr int kMaxSearch = 300;
struct Searched {
  double upper = kInf;
  Vec3 u = Vec3::UnitX();
  Vert v{};
};
Searched compass_search(const Engine& E, const Vec3& u0) {
  Vec3 e1 = Vec3::UnitZ().cross(u0);
  if (!(e1.norm() > 0.5)) e1 = Vec3::UnitX().cross(u0);  // (at the axis: any tangent pair)
  e1.normalize();
  const Vec3 e2 = u0.cross(e1);
  auto upper = [&](const Vec3& u, Vert& v) {
    v = E.support(u);
    const auto nb = norm_bounds(u);
    return div_up(E.value_up(v, u), nb[0], nb[1]);
  };
  Searched r;
  r.u = u0;
  r.upper = upper(u0, r.v);
  const int end = E.supports + kMaxSearch;
  for (double step = 0.25; step >= 0x1p-52 && E.supports < end;) {
    bool moved = false;
    for (const Vec3& d : {e1, Vec3(-e1), e2, Vec3(-e2)}) {
      Vert v;
      const Vec3 cand = r.u + step * d;
      if (const double h = upper(cand, v); h < r.upper) r.upper = h, r.u = cand, r.v = v, moved = true;
    }
    if (!moved) step /= 2;
  }
  return r;
}
void tighten_upper_by_search(const Support3& P, const Support3& Q, const Frame& F, double tilt, ClosedForm& c) {
  const Engine E(P, Q, F.R, F.t);
  const double rho = std::hypot(F.t[0], F.t[1]);
  const Vec3 side = rho > 0 ? Vec3(F.t[0] / rho, F.t[1] / rho, 0) : Vec3::UnitX();
  const Vec3 cap(0, 0, F.t[2] < 0 ? -1.0 : 1.0);
  // The ring's own minimiser at t = 0: horizontal and orthogonal to Q's axis R·e_z (both kinks
  // of h_M at once, where the ring bound of coaxial3.cpp is attained), turned towards t. Searched
  // only while t's horizontal part is within a few tilts (past that the side start is the ring's
  // minimiser to first order): a scheduling choice, the bracket is certified either way.
  Vec3 ring = Vec3::Zero();
  if (std::hypot(F.t[0], F.t[1]) <= 4 * tilt) ring = Vec3::UnitZ().cross(Vec3(F.R.col(2)));
  if (ring.squaredNorm() > 0) ring.normalize();
  if (ring.dot(F.t) < 0) ring = -ring;
  for (const Vec3& u0 : {side, cap, ring}) {
    if (!(u0.squaredNorm() > 0)) continue;
    const Searched r = compass_search(E, u0);
    if (-r.upper > c.sd.lo) c.sd.lo = -r.upper, c.sd.normal = r.u.normalized(), c.touch = r.v;
  }
}

// Both brackets are certified, so is their intersection: the reported value (and its move,
// witnesses) from the result whose reporting end is better, the other end the better of the two.
// When the two disagree on the state (overlapping / apart / touching): the narrower one.
template <class Result>
Result narrower(const Result& c, const Result& e) {
  return c.upper_bound - c.lower_bound < e.upper_bound - e.lower_bound ? c : e;
}
Depth3 intersect(const Depth3& c, const Depth3& e) {  // reported: depth = upper_bound
  if (!(c.overlapping && e.overlapping)) return narrower(c, e);
  Depth3 r = c.upper_bound < e.upper_bound ? c : e;
  r.lower_bound = std::max(c.lower_bound, e.lower_bound);
  return r;
}
Distance3 intersect(const Distance3& c, const Distance3& e) {
  if (c.overlapping && e.overlapping) {  // reported: distance = lower_bound (−σ's upper end)
    Distance3 r = c.lower_bound > e.lower_bound ? c : e;
    r.upper_bound = std::min(c.upper_bound, e.upper_bound);
    return r;
  }
  if (c.lower_bound > 0 && e.lower_bound > 0) {  // apart, reported: distance = upper_bound
    Distance3 r = c.upper_bound < e.upper_bound ? c : e;
    r.lower_bound = std::max(c.lower_bound, e.lower_bound);
    return r;
  }
  return narrower(c, e);
}

// Ball pairs (ball3.cpp): the closed form, kept alone when it meets EPA's target or, at a contact,
// the floor 2⁻⁴⁴ of the pair's size (the rounding of the pose, |sd| ~ 0); else — a spheroid whose
// branch and bound ran out of boxes on a near-flat maximum (near-spherical, centre near its
// centre) — intersected with EPA's bracket. Other pairs: EPA.
template <class Result, class Closed, class Epa>
Result ball_or_epa(const Support3& P, const Support3& Q, const Frame& F, Closed closed, Epa epa) {
  const auto b = ball_signed_distance(P, Q, F.R, F.t);
  if (!b) return epa(kMaxEpaGeneric);
  const Result c = closed(ClosedForm{{b->lo, b->hi, b->normal}, {Vec3::Zero(), b->touch_p, b->touch_q}});
  const double scale = std::max(std::abs(c.lower_bound), std::abs(c.upper_bound)), size = P.rho + Q.rho + F.t.norm();
  if (c.upper_bound - c.lower_bound <= std::max(kCurvedTargetGap * scale, 0x1p-44 * size)) return c;
  return intersect(c, epa(kMaxEpaGeneric));
}

// Coaxial pairs: the closed form. Near-coaxial (a tilt bound > 0): the closed form widened by the
// tilt, its lower end of σ (upper end of sd) raised by the second-order ring bound
// (coaxial3.cpp near_coaxial_lower: min over the sphere of the explicit h_M, region by region),
// its upper end of σ tightened by the search above; kept alone when it meets EPA's target,
// else intersected with EPA's bracket (EPA's answer bit for bit when the closed form narrows
// neither end). EPA's budget: the supports a ring of almost-nearest directions of width ~tilt
// needs are ~13–18·√(σ/tilt) (measured: docs/benchmarks.md "Long EPA runs"); kMaxEpaLong when
// that fits it, else the generic pairs' kMaxEpaGeneric (was kMaxEpa: a placement off the centre by
// |t| >> tilt, whose ring t breaks, closed within EPA alone's 4,800 supports but not in 600; a
// scheduling estimate: the answer stays certified either way).
template <class Result, class Closed, class Epa>
Result coaxial_or_epa(const Support3& P, const Support3& Q, const Frame& F, Closed closed, Epa epa) {
  const auto K = coaxial_sum(P, Q, F.R);
  if (!K) return ball_or_epa<Result>(P, Q, F, closed, epa);
  ClosedForm cf = closed_form(P, Q, F, *K);
  if (K->tilt > 0) cf.sd.hi = std::min(cf.sd.hi, -near_coaxial_lower(P, Q, F.R, F.t, *K));
  if (K->tilt > 0 && cf.sd.hi < 0) tighten_upper_by_search(P, Q, F, K->tilt, cf);
  const Result c = closed(cf);
  const double scale = std::max(std::abs(c.lower_bound), std::abs(c.upper_bound));
  if (K->tilt == 0 || c.upper_bound - c.lower_bound <= kCurvedTargetGap * scale) return c;
  const double need = 24 * std::sqrt(scale / K->tilt);
  return intersect(c, epa(need <= kMaxEpaLong ? kMaxEpaLong : kMaxEpaGeneric));
}

}  // namespace

Distance3 curved_distance(const Support3& P, const Pose3& pose_p, const Support3& Q, const Pose3& pose_q) {
  const Frame F = frame_of(pose_p, pose_q);
  return coaxial_or_epa<Distance3>(
      P, Q, F, [&](const ClosedForm& c) { return coaxial_distance(c, F); }, [&](int budget) { return epa_distance(P, Q, F, budget); });
}

Depth3 curved_minimum(const Support3& P, const Pose3& pose_p, const Support3& Q, const Pose3& pose_q) {
  const Frame F = frame_of(pose_p, pose_q);
  return coaxial_or_epa<Depth3>(
      P, Q, F, [&](const ClosedForm& c) { return coaxial_minimum(c, F); }, [&](int budget) { return epa_minimum(P, Q, F, budget); });
}

Depth3 curved_along(const Support3& P, const Pose3& pose_p, const Support3& Q, const Pose3& pose_q, const Vec3& dw) {
  const Frame F = frame_of(pose_p, pose_q);
  const Engine E(P, Q, F.R, F.t);
  const Vec3 d = F.Rp.transpose() * dw;
  std::unique_ptr<Epa> epa;
  const Sd s = signed_distance_at(E, true, &epa);
  Depth3 out;
  out.kind = DepthKind::Directional;
  if (s.state >= 0) {
    if (s.state == 0) out.upper_bound = std::max(0.0, -s.lo);  // undecided: touching, bracket kept
    out.candidates = static_cast<std::size_t>(E.supports);
    return out;
  }
  epa->along(d);
  const double lo = epa->lam_lo(), hi = epa->lam_hi();
  const Vec3 dir = epa->lam_dir();
  const Vert v = epa->lam_vert();
  out.overlapping = true;
  out.lower_bound = down(lo * norm_down(d));
  out.depth = out.upper_bound = upw(hi * norm_up(d));
  out.normal = dw.normalized();
  out.translation = F.vec(hi * d);
  out.facet_normal = F.vec(dir.normalized());
  out.witness_p = out.witness_q = F.point(v.p);
  out.candidates = static_cast<std::size_t>(E.supports);
  return out;
}

Cast3 curved_cast(const Support3& P, const Pose3& pose_p, const Support3& Q, const Pose3& pose_q, const Vec3& dw) {
  const Frame F = frame_of(pose_p, pose_q);
  Engine E(P, Q, F.R, F.t);
  const Vec3 d = F.Rp.transpose() * dw;
  Cast3 out;
  Sd s = signed_distance_at(E, true);
  if (s.state <= 0) {  // overlapping, or touching to the rounding floor: s = 0
    out.hit = true;
    out.overlapping = s.state < 0;
    if (!out.overlapping) out.witness_p = out.witness_q = F.point(combo(s.g.s, true));
    return out;
  }
  // Conservative advancement: from λ (before the entry, certified), the plane M − λd ⊂
  // {⟨x, w⟩ <= h} with h < 0 is reached along d only when ⟨d, w⟩ < 0, after −h/−⟨d, w⟩.
  double lam = 0;
  auto miss = [&] {
    out.distance = out.lower_bound = out.upper_bound = kInf;
    return out;
  };
  Vec3 normal = Vec3::Zero();
  Vert touch{};
  for (int k = 0; k < kMaxCast; ++k) {
    const Vec3 w = s.g.sep_w;
    const double h = s.g.sep_h;
    const double dw_up = upw(w.dot(d) + 4 * kU * abs_dot(w, d));
    if (!(h < 0)) break;  // (state > 0 guarantees a plane with h < 0)
    if (!(dw_up < 0)) return miss();
    const double step = down(down(-h) / -dw_up);
    normal = -s.g.y;
    touch.p = combo(s.g.s, true), touch.q = combo(s.g.s, false);
    const double next = down(lam + step);
    if (!(next > lam)) break;
    lam = next;
    E.set_query(lam * d);
    s = signed_distance_at(E, true);
    if (s.state <= 0) break;
    if (s.lo <= 0x1p-40 * lam * norm_down(d)) break;
  }
  // The upper end: the first λ past lam certified inside M (steps doubling from the residual).
  double hi = kInf;
  const double dn = norm_down(d);
  double stepv = std::max({s.hi > 0 && s.hi < kInf ? s.hi / dn : 0.0, 0x1p-50 * lam, 0x1p-1000});
  // A ray that passes M within the rounding floor never gets a certified inside point: after
  // kMaxCast doublings it is reported as a miss (docs/robustness.md "Curved primitives").
  for (int k = 0; k < kMaxCast && hi == kInf && std::isfinite(stepv); ++k, stepv *= 2) {
    const double t = upw(lam + stepv);
    E.set_query(t * d);
    if (signed_distance_at(E, true).state < 0) hi = t;
  }
  if (hi == kInf) return miss();
  // Bisection to a relative target between the certified before (lam) and inside (hi) ends.
  for (int k = 0; k < 60 && hi - lam > kCurvedTargetGap * hi; ++k) {
    const double mid = lam + (hi - lam) / 2;
    if (!(mid > lam && mid < hi)) break;
    E.set_query(mid * d);
    const Sd in = signed_distance_at(E, true);
    if (in.state < 0) hi = mid;
    else if (in.state > 0) lam = mid;
    else break;
  }
  out.hit = true;
  out.distance = out.upper_bound = upw(hi * norm_up(d));
  out.lower_bound = down(lam * norm_down(d));  // lam is certified before the entry
  out.translation = F.vec(hi * d);
  if (normal.squaredNorm() > 0) out.normal = F.vec(normal.normalized());
  out.witness_p = out.witness_q = F.point(touch.p);
  return out;
}

}  // namespace pendepth::primitives
