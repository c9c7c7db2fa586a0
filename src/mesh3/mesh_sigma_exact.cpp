// The exact σ of a pair of meshes (issue 17 item 4; survey §3.5–§4, DHS §6: σ of a union as the
// distance to the union's boundary). Contract in mesh_sigma_exact.hpp.
//
// O = ∪_k int S_k, S_k = P_i ⊕ (−Q'_j) (pieces have disjoint interiors and cover the solids).
// For 0 ∈ O, σ = dist(0, Oᶜ) and the nearest point of Oᶜ lies on ∂O ⊂ ∪ ∂S_k, so
//   σ = min over facets f of every S_k of dist(0, R_f),  R_f = f \ ∪_l int S_l
// (R_f ⊂ Oᶜ, closed). Seams where two sums touch along coplanar facets are not in O (exact fits):
// they are points of R_f, as they must be. dist(0, R_f): the foot p of 0 on plane(f) when
// p ∈ R_f; otherwise the nearest point lies on the relative boundary of R_f, i.e. on a line
// L = plane(f) ∩ plane(g) for a facet g of some S_l (f's own edges included). On L the set
// R_f ∩ L is the closed segment L ∩ S_k minus the open intervals L ∩ int S_l, and its point
// nearest 0 is the foot of 0 on L when uncovered, else an uncovered interval end.
//
// Representation: every S_k by its supporting planes n·x <= c from convex3::minkowski_facets (a
// superset of its facet normals, each plane supporting S_k: offset = support value), held as
// interval enclosures of the exact polynomials in the input doubles (Interval_nt on the same
// expressions: a proven forward error bound) and rebuilt exactly as PlaneNumbers (plane_number.hpp:
// unreduced quotients of exact binary floats, no lazy DAG, no gcd) only when a filter cannot
// decide (exact_plane, on demand) — q' = R q + tq − tp exactly for the doubles R, tq, tp as in
// the convex engines. Every decision (inside / strictly
// inside / interval order / distance order) is an exact comparison; σ² is rational,
// σ = RN(√σ²) with a certified 1-ulp bracket.
// Ties handled structurally (exact tests, both tiers): planes of one sum that are the same
// half-space (minkowski_facets repeats a plane through FaceP / FaceQ / EdgeEdge candidates) are
// kept once; for each facet plane f, the planes of the sums in range equal to plane(f) (either
// side: f's own, a neighbour touching along the seam) are marked once — a sum holding one has no
// interior point on plane(f), so it never covers there, its marked planes are no constraint on
// the foot or on lines in plane(f), and the line's own plane g empties its sum's open interval.
// Those are exactly the ties (zero signs) that otherwise went to the rationals.
// Tiers: the filtered tier (default) decides by Interval_nt enclosures (outward rounding: a
// proven forward error bound) and falls back to the exact numbers when a sign is uncertain; it
// also prunes a line L = plane(f) ∩ plane(g), g of S_l, when L ∩ box ∩ S_k ∩ S_l is certainly
// empty or certainly beyond the best (only there can R_f's relative boundary on L lie: a
// boundary point x of R_f off relbd f lies on ∂S_l for some covering S_l, on a plane g of S_l
// active at x and not parallel to f), and drops sums whose box certainly misses plane(f). Under a
// SigmaExactUnfiltered guard every decision is exact and those prunes are off: the reference
// whose σ the filtered tier must equal bit for bit — σ's rounding and bracket
// (tests/mesh3/test_mesh_sigma_tiers.cpp). The rest of the answer (the nearest point x, its
// facet: translation, normals, witnesses, features, pieces) is sure to equal the reference's
// only when one point of Oᶜ is nearest: `offer` keeps the first of equal squared distances, and the
// filtered prunes (line_far's S_l clipping and its >= bound, plane_misses_box) skip lines the
// reference runs, lines that offer no point nearer than the best but can offer one at the same
// distance first — another nearest point, the same σ (random polycubes at exact ties: 7 of 314
// poses, RandomPolycubesAtExactTies).
// Filtered tier, further (both decide nothing the exact path would not): a facet whose face
// f ∩ S_k, within the best, lies in the union of the other open sums (face_covered: the face's
// vertices as enclosures, ties decided exactly; fan triangles, each certainly strictly inside one
// open sum, or beyond the best, or split at its midpoints into four, kCoverDepth levels) has no
// point of R_f nearer than the best and is skipped — a seam where two sums meet is in neither
// open sum, so it is covered only when a third sum holds it strictly; when it is not covered,
// its unsettled triangles (boxes) hold R_f ∩ B(0, best), and a line whose plane g certainly
// misses them all is not run (line_misses_leaves); a line is
// first run on enclosures (line_no_offer: its segment in S_k, the covering intervals, every
// candidate certainly covered or certainly beyond the best), signs of n·u near 0 (planes nearly
// parallel to the line: rounding in symmetric meshes) taken exactly, a plane equal to g's
// (seams) by the exact plane test; the exact line stage runs only when that is undecided, and
// there (offer_on_line) a covering interval certainly holding the segment strictly ends the line
// (as in line_no_offer; looked for on enclosures over all covering sums before any exact
// interval), a covering interval's exact ends are computed only when a comparison on their
// enclosures is undecided, and a line's λ on a plane once per class of equal planes; the
// interval ends there are kept sharp — a constraint whose λ enclosure is wider than a few ulps and
// may attain an end gets a head-and-tail enclosure of its λ from the exact line and plane rounded
// once (fine_lambda.hpp: ~2⁻¹⁰⁰ of the terms, sound by construction), the exact λ only where that
// is not tight (refine_ends), a = n·u near 0 its exact value — so that fewer covering intervals
// are left Unknown and fewer comparisons undecided; and an end whose attaining plane is certain
// (end_plane) is compared with another such end without the exact numbers: equal when their
// planes are of one class, else by the head-and-tail order of their λ (fine_compare) — the torus
// 8×4 pair's pose 0: 99 000 exact covering intervals and 638 000 exact λ before, 31 000 and 300
// after (docs/benchmarks.md "… tight λ enclosures", "… a head-and-tail filter for λ").
// Filtered tier, lines once per class: planes equal across sums (the same geometric plane, either
// side, decided exactly) form classes (plane_classes), and for a facet f each line plane(f) ∩
// plane(g) is run once per class of g — the same line offers the same points. The interval
// products of the filters run as Interval_nt<false> under one rounding-mode guard (the same
// enclosures, without Interval_nt<true>'s mode switch at every operation).
// Pruning by the certified upper bound U (today's least σ_d): no point farther than reach
// (U widened by 2⁻³⁰) is ever offered (Best::beyond: it cannot be the answer); only sums whose
// box meets B(0, U) can matter, only facets whose plane lies within the running best,
// processed nearest plane first and stopping when the next plane is farther than the best; lines only from planes
// within the best, covering sets only from sums whose box meets B(0, best). The double
// distances used for pruning are accurate to a few ulps (minkowski_facets) and compared with a
// 2⁻⁴⁰ relative margin, so pruning never drops a candidate nearer than the best.
// Cost: for F facets in range and K sums, O(F) projections of O(K·f̄) tests each, and up to
// O(F²) lines of O(K·f̄ + K²) each in the worst case (f̄ = facets per sum); in practice the
// projections settle most facets. Measured (docs/benchmarks.md "Exact mesh σ: interval planes,
// one-sum facet cover", "… a plane number type", "… plane classes, one rounding guard", "… a
// facet cover by unions"): with the union cover the tripod pair takes ~2 000 facets (2 reach the
// lines) and 0.4 s; a torus 8×4 pair ~8 900 facets (~190 reach the lines, fewer of their lines
// run: those through unsettled triangles) and half a minute, ~8 s since a covering interval
// certainly holding a line's segment ends the line ("… a covering interval holding the segment").
// Work limit (max_work, the front door's kExactSigmaMaxWork): a deterministic count of the setup's
// candidate facets, of the line stage's line–sum tests done up to each line's early exit and of
// its exact covering intervals, charged as the work is done; past it the query gives up (nullopt)
// having decided nothing, so a limited run either equals the unlimited one or gives up, and
// answers exactly from its own count on (tests/mesh3/test_mesh_sigma_exact.cpp,
// WorkLimitAnswersOrGivesUp).
#include "mesh3/mesh_sigma_exact.hpp"

#include "convex3/minkowski_facets.hpp"
#include "convex3/polytope_data.hpp"

#include "mesh3/fine_lambda.hpp"
#include "mesh3/line_lambda.hpp"
#include "mesh3/plane_classes.hpp"
#include "mesh3/plane_number.hpp"

#include <CGAL/Interval_nt.h>
#include <CGAL/Uncertain.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace pendepth::mesh3 {
namespace {

using FT = PlaneNumber;  // exact, non-lazy (plane_number.hpp)
using I = CGAL::Interval_nt<true>;  // the filter: intervals that hold the exact values

// Vectors of exact numbers (V3) or of intervals (IV3): the same polynomials in both.
template <class T>
struct Vec {
  T x, y, z;
};
using V3 = Vec<FT>;
using IV3 = Vec<I>;
template <class T>
Vec<T> lift(const Vec3& v) {
  return {T(v.x()), T(v.y()), T(v.z())};
}
template <class T>
Vec<T> operator-(const Vec<T>& a, const Vec<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
Vec<T> operator+(const Vec<T>& a, const Vec<T>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T>
Vec<T> operator*(const T& s, const Vec<T>& a) {
  return {s * a.x, s * a.y, s * a.z};
}
template <class T>
T dot(const Vec<T>& a, const Vec<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
// The interval products of the filters under one rounding-mode guard: Interval_nt<false>
// arithmetic with the FPU rounding upward gives the same enclosures, bit for bit, as
// Interval_nt<true>, which switches the rounding mode twice at every operation (a dot product:
// ten switches; half of the torus pair's profile, docs/benchmarks.md "Exact mesh σ: plane
// classes, one rounding guard").
using IF = CGAL::Interval_nt<false>;
IF fast(const I& v) { return IF(v.inf(), v.sup()); }
I safe(const IF& v) { return I(v.inf(), v.sup()); }
IF dotf(const IV3& a, const IV3& b) { return fast(a.x) * fast(b.x) + fast(a.y) * fast(b.y) + fast(a.z) * fast(b.z); }
template <>
I dot<I>(const IV3& a, const IV3& b) {
  CGAL::Protect_FPU_rounding<true> up;
  return safe(dotf(a, b));
}
template <class T>
Vec<T> cross(const Vec<T>& a, const Vec<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
I iv(const FT& v) {
  const auto r = to_interval(v);
  return I(r.first, r.second);
}
IV3 iv(const V3& v) { return {iv(v.x), iv(v.y), iv(v.z)}; }
bool is_zero(const V3& a) { return is_zero(a.x) && is_zero(a.y) && is_zero(a.z); }
Vec3 to_vec(const V3& a) { return {to_double(a.x), to_double(a.y), to_double(a.z)}; }

Box3 box_of_sum(const MeshPair& m, const Placed& pl, std::size_t i, std::size_t j) { return sum_box(m, pl, i, j); }

double box_distance(const Box3& b) {  // distance from 0 to the box, rounded
  Vec3 c = Vec3::Zero();
  for (int k = 0; k < 3; ++k) c[k] = b.lo[k] > 0 ? b.lo[k] : b.hi[k] < 0 ? -b.hi[k] : 0.0;
  return c.norm();
}

// A supporting plane n·x <= c of a sum, with its defining candidate: the enclosures of n and c
// (intervals of the same polynomials evaluated on the input doubles: a proven forward error
// bound); the exact n and c are built on demand (exact_plane) when a filter cannot decide.
struct Plane {
  IV3 ni;
  I ci;
  double dist = 0;  // |c|/|n|, a few ulps
  std::size_t sum = 0;
  convex3::FacetCandidate k;
};
struct ExactPlane {
  V3 n;
  FT c;
};

// a = n·u and b = c − n·x0 of the plane m on the line x0 + λu: the constraint a·λ <= b, in
// Interval_nt<false> — the caller holds the rounding guard (upward).
std::pair<IF, IF> constraint_on_line(const Plane& m, const IV3& x0, const IV3& u) {
  return {dotf(m.ni, u), fast(m.ci) - dotf(m.ni, x0)};
}

struct Sum {
  std::size_t i = 0, j = 0;
  std::size_t first = 0, count = 0;  // planes[first, first + count)
  double box_dist = 0;
  Box3 box;
};

struct Ctx {
  const MeshPair& m;
  Placed pl;
  std::vector<Sum> sums;
  std::vector<Plane> planes;
  bool filt = true;        // the interval tier (false: SigmaExactUnfiltered, every decision exact)
  bool planted = false;    // tests: the planted bug in the filtered prunes
  std::vector<char> on_f;  // planes equal to the current plane(f), either side (exact)
  std::vector<std::size_t> cls;  // filtered tier: planes[p]'s class of equal planes (plane_classes)
  // Filtered tier: the exact λ of the current exact line (line_id) on each class of planes, once
  // computed (LineConstraints::lambda_e): lam_line[class] == line_id when lam_val[class] holds it.
  std::size_t line_id = 0;
  mutable std::size_t refined = 0;  // constraints refine_ends gave the exact λ (the work count)
  mutable std::size_t fined = 0;    // constraints refine_ends gave the head-and-tail λ (the work count)
  mutable std::vector<std::size_t> lam_line;
  mutable std::vector<FT> lam_val;
  mutable std::vector<std::optional<ExactPlane>> exact;  // planes[p]'s exact numbers, on demand
  mutable std::vector<std::optional<detail::FinePlane>> fine;  // the same rounded once (fine_lambda.hpp), on demand
};

template <class T>
Vec<T> placed(const Placed& pl, const Vec3& q) {
  T r[3];
  for (int a = 0; a < 3; ++a)
    r[a] = T(pl.R(a, 0)) * T(q.x()) + T(pl.R(a, 1)) * T(q.y()) + T(pl.R(a, 2)) * T(q.z()) + T(pl.tq[a]) - T(pl.tp[a]);
  return {r[0], r[1], r[2]};
}
template <class T>
Vec<T> rotated(const Placed& pl, const Vec<T>& e) {
  return {T(pl.R(0, 0)) * e.x + T(pl.R(0, 1)) * e.y + T(pl.R(0, 2)) * e.z,
          T(pl.R(1, 0)) * e.x + T(pl.R(1, 1)) * e.y + T(pl.R(1, 2)) * e.z,
          T(pl.R(2, 0)) * e.x + T(pl.R(2, 1)) * e.y + T(pl.R(2, 2)) * e.z};
}

// The plane n·x <= c of a candidate (the normals of minkowski_facets, the same polynomials), in
// exact numbers (T = FT) or intervals (T = I: throws CGAL::Uncertain_conversion_exception when
// the orientation of an edge–edge normal is not certain).
template <class T>
std::pair<Vec<T>, T> plane_poly(const Placed& pl, const convex3::PolytopeData& P, const convex3::PolytopeData& Q,
                                const convex3::FacetCandidate& k) {
  const convex3::DKLevel &LP = P.levels[0], &LQ = Q.levels[0];
  Vec<T> u;
  switch (k.source) {
    case convex3::FacetSource::FaceP: {
      const auto& t = P.tris[k.p_feature];
      const Vec<T> a = lift<T>(P.v[t[0]]);
      u = cross(lift<T>(P.v[t[1]]) - a, lift<T>(P.v[t[2]]) - a);
      break;
    }
    case convex3::FacetSource::FaceQ: {
      const auto& t = Q.tris[k.q_feature];
      const Vec<T> a = lift<T>(Q.v[t[0]]);
      u = cross(rotated(pl, lift<T>(Q.v[t[2]]) - a), rotated(pl, lift<T>(Q.v[t[1]]) - a));
      break;
    }
    case convex3::FacetSource::EdgeEdge: {
      const Vec<T> ep = lift<T>(P.v[LP.target(k.p_feature)]) - lift<T>(P.v[LP.origin(k.p_feature)]);
      const Vec<T> eq = rotated(pl, lift<T>(Q.v[LQ.target(k.q_feature)]) - lift<T>(Q.v[LQ.origin(k.q_feature)]));
      u = cross(ep, eq);
      // minkowski_facets orients u by the edges' extremality; recover the sign from P's apex.
      const Vec<T> pc = lift<T>(P.v[LP.target(LP.next(k.p_feature))]);
      const Vec<T> pe = lift<T>(P.v[LP.target(LP.next(LP.twin[k.p_feature]))]);
      const Vec<T> pa = lift<T>(P.v[LP.origin(k.p_feature)]);
      const T s1 = dot(u, pc - pa), s2 = dot(u, pe - pa);
      if (is_positive(s1) || is_positive(s2)) u = T(-1) * u;
      break;
    }
  }
  const T c = dot(u, lift<T>(P.v[k.p_vertex]) - placed<T>(pl, Q.v[k.q_vertex]));
  return {u, c};
}

const convex3::PolytopeData& data_p(const Ctx& c, const Sum& s) { return convex3::data_of(c.m.P[s.i]); }
const convex3::PolytopeData& data_q(const Ctx& c, const Sum& s) { return convex3::data_of(c.m.Q[s.j]); }

// The exact numbers of planes[p] (built once, on first use).
const ExactPlane& exact_plane(const Ctx& c, std::size_t p) {
  auto& e = c.exact[p];
  if (!e) {
    const Sum& s = c.sums[c.planes[p].sum];
    auto [n, off] = plane_poly<FT>(c.pl, data_p(c, s), data_q(c, s), c.planes[p].k);
    e = ExactPlane{std::move(n), std::move(off)};
  }
  return *e;
}

// A candidate's plane as intervals; when its orientation is uncertain in intervals, from the
// exact numbers (then stored in `exact`).
Plane plane_of(const Placed& pl, const convex3::PolytopeData& P, const convex3::PolytopeData& Q,
               const convex3::FacetCandidate& k, std::optional<ExactPlane>& exact) {
  Plane r;
  r.dist = std::abs(k.distance);
  r.k = k;
  try {
    std::tie(r.ni, r.ci) = plane_poly<I>(pl, P, Q, k);
  } catch (const CGAL::Uncertain_conversion_exception&) {
    auto [n, off] = plane_poly<FT>(pl, P, Q, k);
    r.ni = iv(n), r.ci = iv(off);
    exact = ExactPlane{std::move(n), std::move(off)};
  }
  return r;
}

bool certainly_nonzero(const I& v) { return v.inf() > 0 || v.sup() < 0; }
bool certainly_zero(const I& v) { return v.inf() == 0 && v.sup() == 0; }

// n = 0 exactly (exact when the filter cannot tell).
bool zero_normal(const Ctx& c, std::size_t p) {
  const Plane& a = c.planes[p];
  if (c.filt) {
    if (certainly_nonzero(a.ni.x) || certainly_nonzero(a.ni.y) || certainly_nonzero(a.ni.z)) return false;
    if (certainly_zero(a.ni.x) && certainly_zero(a.ni.y) && certainly_zero(a.ni.z)) return true;
  }
  return is_zero(exact_plane(c, p).n);
}

// The planes of the sums as detail::same_plane / plane_classes see them (plane_classes.hpp).
struct CtxPlanes {
  const Ctx& c;
  double dist(std::size_t p) const { return c.planes[p].dist; }
  const IV3& ni(std::size_t p) const { return c.planes[p].ni; }
  const I& ci(std::size_t p) const { return c.planes[p].ci; }
  const ExactPlane& exact(std::size_t p) const { return exact_plane(c, p); }
};

// The same half-space: b.n = t·a.n with t > 0 and b.c = t·a.c, exactly (interval filter first).
bool same_plane(const Ctx& c, std::size_t pa, std::size_t pb) {
  return detail::same_plane(CtxPlanes{c}, pa, pb, true, c.filt);
}

// The same plane, either side: b.n = t·a.n (t != 0) and b.c = t·a.c, exactly (filter first).
bool same_plane_any(const Ctx& c, std::size_t pa, std::size_t pb) {
  return detail::same_plane(CtxPlanes{c}, pa, pb, false, c.filt);
}

// Classes of equal planes across sums (filtered tier; detail::plane_classes: cls[p] = the first
// plane, in order of distance from 0, that is the same plane as p on either side, decided
// exactly). The same geometric plane recurs in many sums (a face of P_i with the same extreme
// vertex of several pieces Q_j sharing it, seams of neighbouring sums), and a line
// plane(f) ∩ plane(g) depends only on g's class: the main loop runs it once per facet. Missing an
// equality would only cost repeated work; merging distinct planes would skip lines (tested:
// tests/mesh3/test_plane_classes.cpp). `order`: every plane, by increasing distance.
void plane_classes(Ctx& c, const std::vector<std::size_t>& order) { detail::plane_classes(CtxPlanes{c}, order, c.cls); }

// x in the closed S (all planes), skipping plane `skip` and the planes equal to plane(f) (x is
// on plane(f): those hold with equality).
// (xi: intervals of x.)
bool in_closed(const Ctx& c, const Sum& s, const V3& x, const IV3& xi, std::size_t skip) {
  for (std::size_t p = s.first; p < s.first + s.count; ++p) {
    if (p == skip || c.on_f[p]) continue;
    if (c.filt) {
      const I v = dot(c.planes[p].ni, xi) - c.planes[p].ci;
      if (v.inf() > 0) return false;
      if (v.sup() <= 0) continue;
    }
    const ExactPlane& e = exact_plane(c, p);
    if (dot(e.n, x) > e.c) return false;
  }
  return true;
}
bool in_open(const Ctx& c, const Sum& s, const V3& x, const IV3& xi) {
  for (std::size_t p = s.first; p < s.first + s.count; ++p) {
    if (c.filt) {
      const I v = dot(c.planes[p].ni, xi) - c.planes[p].ci;
      if (v.sup() < 0) continue;
      if (v.inf() >= 0) return false;
    }
    const ExactPlane& e = exact_plane(c, p);
    if (!(dot(e.n, x) < e.c)) return false;
  }
  return true;
}

I comp(const IV3& v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }

// Clips the λ-range [lo, hi] of the line x0 + λu (intervals holding the exact values) to a
// superset of its part in the convex set of the planes [first, first + count). False when that
// part is certainly empty.
bool clip_planes(const Ctx& c, std::size_t first, std::size_t count, const IV3& x0, const IV3& u, double& lo,
                 double& hi) {
  CGAL::Protect_FPU_rounding<true> up;  // IF arithmetic below
  for (std::size_t p = first; p < first + count; ++p) {
    const auto [a, b] = constraint_on_line(c.planes[p], x0, u);
    if (a.inf() > 0) hi = std::min(hi, (b / a).sup());
    else if (a.sup() < 0) lo = std::max(lo, (b / a).inf());
    if (lo > hi) return false;
  }
  return true;
}

// Interval filter of a line L = plane(f) ∩ plane(g), g a plane of the sum S_l: true when
// certainly no point of L ∩ S_k ∩ S_l lies nearer than √bound2 (or that set is certainly empty).
// Only L ∩ S_k ∩ S_l can hold the relative boundary of R_f on L (file comment), so the line is
// not needed otherwise. Every quantity is an interval holding the exact value (Interval_nt:
// outward rounding, a proven forward error bound); nothing is decided on a rounded value.
// The line L = plane(f) ∩ plane(g) as x0 + λu (x0 its point nearest 0, u = n_f × n_g, the
// exact path's parametrisation), in intervals holding the exact values.
struct LineI {
  IV3 u, x0;
  I u2, l2;                       // |u|², |x0|²
  std::size_t f = 0, g = 0;       // the planes
  mutable std::optional<V3> ue;   // the exact u, built on demand (exact_u)
  mutable std::optional<V3> x0e;  // the exact x0, built on demand (exact_x0)
  mutable std::optional<detail::FineLine> fl;  // the exact u and x0 rounded once (fine_lambda)
};
LineI interval_line(const Plane& f, const Plane& g, std::size_t fi, std::size_t gi) {
  LineI L;
  L.f = fi, L.g = gi;
  L.u = cross(f.ni, g.ni);
  L.u2 = dot(L.u, L.u);
  L.x0 = (I(1) / L.u2) * (f.ci * cross(g.ni, L.u) + g.ci * cross(L.u, f.ni));
  L.l2 = dot(L.x0, L.x0);
  return L;
}

bool line_far(const Ctx& c, const LineI& L, const Sum& sk, const Sum& sl, double bound2) {
  if (c.planted) bound2 *= 1e-6;  // the planted bug (tests): the bound /1e6, lines nearer than the best pruned
  const IV3 &u = L.u, &x0 = L.x0;
  const I &u2 = L.u2, &l2 = L.l2;
  if (u2.sup() <= 0) return true;  // u = 0 exactly: parallel planes, no line
  if (!(u2.inf() > 0)) return false;
  if (l2.inf() >= bound2) return true;
  double lo = -INFINITY, hi = INFINITY;  // λ ∈ [lo, hi] ⊇ L ∩ S_k ∩ S_l
  // The boxes first (certified enclosures of the sums: sum_box widens outward).
  for (int a = 0; a < 3; ++a) {
    double blo = std::max(sk.box.lo[a], sl.box.lo[a]), bhi = std::min(sk.box.hi[a], sl.box.hi[a]);
    if (blo > bhi) return true;
    const I ua = comp(u, a), xa = comp(x0, a);
    if (ua.inf() > 0) {
      lo = std::max(lo, ((I(blo) - xa) / ua).inf()), hi = std::min(hi, ((I(bhi) - xa) / ua).sup());
    } else if (ua.sup() < 0) {
      lo = std::max(lo, ((I(bhi) - xa) / ua).inf()), hi = std::min(hi, ((I(blo) - xa) / ua).sup());
    } else if (ua.inf() == 0 && ua.sup() == 0 && (xa.inf() > bhi || xa.sup() < blo)) {
      return true;  // u_a = 0 exactly: the line is parallel to the slab and outside it
    }
    if (lo > hi) return true;
  }
  if (!clip_planes(c, sk.first, sk.count, x0, u, lo, hi)) return true;
  if (&sl != &sk && !clip_planes(c, sl.first, sl.count, x0, u, lo, hi)) return true;
  const double mn = lo > 0 ? lo : hi < 0 ? -hi : 0.0;
  return (l2 + I(mn) * I(mn) * u2).inf() >= bound2;
}

// Certainly: the plane n·x = c misses the box (the whole box strictly on one side).
// (Interval_nt<false> under one rounding guard: the same enclosures.)
bool plane_misses_box(const Plane& f, const Box3& b) {
  CGAL::Protect_FPU_rounding<true> up;
  IF lo(0), hi(0);
  for (int a = 0; a < 3; ++a) {
    const IF n = fast(comp(f.ni, a)), x = n * IF(b.lo[a]), y = n * IF(b.hi[a]);
    lo = lo + IF(std::min(x.inf(), y.inf())), hi = hi + IF(std::max(x.sup(), y.sup()));
  }
  return (lo - fast(f.ci)).inf() > 0 || (hi - fast(f.ci)).sup() < 0;
}

// Interval filter of a covering sum: true when L ∩ int S_l is certainly empty or certainly
// disjoint from (a_inf, b_sup) ⊇ the segment [a, b]. First the segment's box (x0 + λu over
// λ ∈ [a_inf, b_sup] in intervals) against S_l's box (S_l ⊂ box: a segment outside the box's
// interior misses int S_l) — O(1), and on the torus pair it settles two thirds of the tests that
// the planes' loop (O(planes)) settles (docs/benchmarks.md "Exact mesh σ: a covering interval
// holding the segment").
bool open_misses(const Ctx& c, const Sum& s, const IV3& x0, const IV3& u, double a_inf, double b_sup) {
  double lo = -INFINITY, hi = INFINITY;  // ⊇ the open interval
  CGAL::Protect_FPU_rounding<true> up;  // IF arithmetic below
  if (std::isfinite(a_inf) && std::isfinite(b_sup)) {
    const IF lam(a_inf, b_sup);
    for (int a = 0; a < 3; ++a) {
      const IF x = fast(comp(x0, a)) + lam * fast(comp(u, a));
      if (x.sup() <= s.box.lo[a] || x.inf() >= s.box.hi[a]) return true;
    }
  }
  for (std::size_t p = s.first; p < s.first + s.count; ++p) {
    const auto [a, b] = constraint_on_line(c.planes[p], x0, u);
    if (a.inf() > 0) hi = std::min(hi, (b / a).sup());
    else if (a.sup() < 0) lo = std::max(lo, (b / a).inf());
    else if (a.inf() == 0 && a.sup() == 0 && b.sup() <= 0) return true;  // n·u = 0 exactly, n·x0 >= c
    if (lo >= hi || hi <= a_inf || lo >= b_sup) return true;
  }
  return false;
}

// The running best, and the cap reach² before there is one: points farther than reach are no
// answer (σ <= upper < reach; the end returns nothing beyond it), so they are never offered.
struct Best {
  std::optional<FT> d2;
  V3 x;
  std::size_t plane = 0;
  double radius;  // >= √d2 (or the search radius U), for the double prunes
  FT cap2;        // reach², exact
  double sup2;    // >= *d2, or >= cap2 without a best
  double inf2;    // <= *d2, or <= cap2 without a best
  std::size_t offers = 0;  // points accepted so far (SigmaCoverCheck)
  // A point at squared distance e2 is no improvement: not nearer than the best, or beyond the cap.
  bool beyond(const FT& e2) const { return d2 ? !(e2 < *d2) : e2 > cap2; }
  // The same, certain on an enclosure of e2.
  bool beyond(const I& e2) const { return d2 ? e2.inf() >= sup2 : e2.inf() > sup2; }
  // Certainly not beyond (an improvement), on an enclosure of e2.
  bool within(const I& e2) const { return d2 ? e2.sup() < inf2 : e2.sup() <= inf2; }
};

void offer(Best& b, const FT& d2, const V3& x, std::size_t plane) {
  if (b.beyond(d2)) return;
  const auto [inf2, sup2] = to_interval(d2);
  b.d2 = d2, b.x = x, b.plane = plane, b.sup2 = sup2, b.inf2 = inf2, ++b.offers;
  b.radius = std::min(b.radius, std::sqrt(to_double(d2)) * (1 + 0x1p-40) + 0x1p-1000);
}

const V3& exact_u(const Ctx& c, const LineI& L) {
  if (!L.ue) L.ue = cross(exact_plane(c, L.f).n, exact_plane(c, L.g).n);
  return *L.ue;
}

const V3& exact_x0(const Ctx& c, const LineI& L) {
  if (!L.x0e) {
    const ExactPlane &f = exact_plane(c, L.f), &g = exact_plane(c, L.g);
    const V3& u = exact_u(c, L);
    L.x0e = (FT(1) / dot(u, u)) * (f.c * cross(g.n, u) + g.c * cross(u, f.n));
  }
  return *L.x0e;
}

I imin(const I& a, const I& b) { return I(std::min(a.inf(), b.inf()), std::min(a.sup(), b.sup())); }
I imax(const I& a, const I& b) { return I(std::max(a.inf(), b.inf()), std::max(a.sup(), b.sup())); }

// line_interval (below) on the enclosures: Empty or Range only when the exact path certainly
// decides the same (Range: lo, hi enclose its ends), Unknown when a sign or an order is uncertain.
enum class Span { Empty, Range, Unknown };
// The enclosure is finite and its width at most 2^-bits of its magnitude: tight (2⁻³⁰) — the
// double enclosure of a well-conditioned λ = b/a is ~2⁻⁵⁰ wide —, sharp (2⁻⁵⁰: a few ulps, the
// rounding of a well-conditioned λ or of the head-and-tail λ, fine_lambda.hpp).
bool narrow(const I& l, double rel) {
  return std::isfinite(l.inf()) && std::isfinite(l.sup()) &&
         l.sup() - l.inf() <= rel * std::max(std::abs(l.inf()), std::abs(l.sup()));
}
bool tight(const I& l) { return narrow(l, 0x1p-30); }
bool sharp(const I& l) { return narrow(l, 0x1p-50); }
// planes[p] and the line L rounded once (fine_lambda.hpp: the exact plane; L's exact u and x0),
// cached per plane and per line.
const detail::FinePlane& fine_plane(const Ctx& c, std::size_t p) {
  auto& r = c.fine[p];
  if (!r) {
    const ExactPlane& e = exact_plane(c, p);
    r = detail::fine_plane(e.n, e.c);
  }
  return *r;
}
const detail::FineLine& fine_line(const Ctx& c, const LineI& L) {
  if (!L.fl) L.fl = detail::fine_line(exact_u(c, L), exact_x0(c, L));
  return *L.fl;
}
// The head-and-tail enclosure of the exact λ of planes[p] on the line L (detail::fine_lambda);
// nullopt out of its range.
std::optional<I> fine_lambda(const Ctx& c, const LineI& L, std::size_t p) {
  const detail::FineLine& fl = fine_line(c, L);  // rounded to nearest
  const detail::FinePlane& fp = fine_plane(c, p);
  CGAL::Protect_FPU_rounding<true> up;  // the head-and-tail arithmetic: upward
  const auto l = detail::fine_lambda(fl, fp);
  if (!l) return std::nullopt;
  return I(l->first, l->second);
}
// The sign of λ_p − λ_q on L (detail::fine_compare), nullopt when undecided.
std::optional<int> fine_compare(const Ctx& c, const LineI& L, std::size_t p, std::size_t q) {
  const detail::FineLine& fl = fine_line(c, L);
  const detail::FinePlane &fp = fine_plane(c, p), &fq = fine_plane(c, q);
  CGAL::Protect_FPU_rounding<true> up;
  return detail::fine_compare(fl, fp, fq);
}
// The ends' enclosures lo = imax, hi = imin over the constraints' λ are as wide as the widest
// constraint that may attain them (a or b of a large relative error: a plane nearly parallel to
// the line, or nearly through its point x0), and wide ends leave a covering interval Unknown or
// its comparisons undecided — each then an exact covering interval (the torus 8×4 pair's pose 0:
// 111 000 Unknown covering intervals, a third of the undecided comparisons with enclosures wider
// than the ends' distance). On a line whose exact x0 and u are known (the exact stage), the wide
// constraints `ls` (side, λ enclosure; wide: not sharp) that may attain an end — their enclosure
// reaches past the other constraints' certain bound — get the head-and-tail enclosure of their λ
// (fine_lambda.hpp: an ulp or two), intersected with theirs, and the enclosure of the exact λ
// (an exact number rounded outward) only when that is still not tight; the ends are recomputed
// from all: still enclosures of the exact ends, so no decision changes, only fewer are left to
// the exact intervals (docs/benchmarks.md "Exact mesh σ: tight λ enclosures", "… a head-and-tail
// filter for λ"). O(count) + a head-and-tail λ per refined constraint (~12 operations; the line
// and plane rounded once), rarely an exact one.
struct SideLambda {
  std::size_t p;
  bool pos;  // a > 0: an upper bound on λ (else a lower bound)
  I l;
};
void refine_ends(const Ctx& c, const LineI& L, std::vector<SideLambda>& ls, I& lo, I& hi) {
  double lo_bound = -INFINITY, hi_bound = INFINITY;  // certain: max λ⁻ >= lo_bound, min λ⁺ <= hi_bound
  for (const SideLambda& q : ls) {
    if (q.pos) hi_bound = std::min(hi_bound, q.l.sup());
    else lo_bound = std::max(lo_bound, q.l.inf());
  }
  for (SideLambda& q : ls) {
    if (sharp(q.l) || (q.pos ? q.l.inf() >= hi_bound : q.l.sup() <= lo_bound)) continue;  // cannot widen an end
    if (const auto f = fine_lambda(c, L, q.p)) {  // both hold the exact λ: so does their intersection
      q.l = I(std::max(q.l.inf(), f->inf()), std::min(q.l.sup(), f->sup()));
      ++c.fined;
    }
    if (!tight(q.l)) {
      const ExactPlane& e = exact_plane(c, q.p);
      q.l = iv((e.c - dot(e.n, *L.x0e)) / dot(e.n, *L.ue));
      ++c.refined;
    }
    SigmaLineCheck::refined += SigmaLineCheck::depth > 0;
    if (q.pos) hi_bound = std::min(hi_bound, q.l.sup());
    else lo_bound = std::max(lo_bound, q.l.inf());
  }
  double lo_sup = -INFINITY, hi_inf = INFINITY;
  for (const SideLambda& q : ls) {
    if (q.pos) hi_inf = std::min(hi_inf, q.l.inf());
    else lo_sup = std::max(lo_sup, q.l.sup());
  }
  lo = I(lo_bound, lo_sup), hi = I(hi_inf, hi_bound);
}
// A plane attaining the end `end` of L (the least λ of the a > 0 side when `pos`, else the
// greatest of a < 0): the extremum, by fine_compare, of the constraints that may attain it (their
// enclosure reaches the end's enclosure; one class of planes, Ctx::cls, needs no comparison);
// SIZE_MAX when a comparison is undecided. The exact end is the λ of a constraint that attains it,
// which passes the test, so it is the λ of that plane — and of any plane of its class (one
// geometric plane, either side: n, c scaled by t != 0, b/a unchanged): ends of one class on one
// line are equal exactly, and ends of known planes are ordered by their planes (fine_compare) —
// offer_on_line's exact ties and near ties decided without the exact numbers.
std::size_t end_plane(const Ctx& c, const LineI& L, const std::vector<SideLambda>& ls, bool pos, const I& end) {
  std::size_t k = SIZE_MAX;
  for (const SideLambda& q : ls) {
    if (q.pos != pos || (pos ? q.l.inf() > end.sup() : q.l.sup() < end.inf())) continue;
    if (k == SIZE_MAX || c.cls[q.p] == c.cls[k]) {
      if (k == SIZE_MAX) k = q.p;
      continue;
    }
    const auto r = fine_compare(c, L, q.p, k);  // sign(λ_q − λ_k)
    if (!r) return SIZE_MAX;
    if (pos ? *r < 0 : *r > 0) k = q.p;
  }
  return k;
}
// `planes` (optional, the filtered tier's exact stage): planes attaining lo and hi (end_plane),
// SIZE_MAX where not certain or not computed.
Span line_interval_i(const Ctx& c, const Sum& s, const LineI& L, bool strict, I& lo, I& hi, std::size_t gp,
                     std::array<std::size_t, 2>* planes = nullptr) {
  if (planes) *planes = {SIZE_MAX, SIZE_MAX};
  bool has_lo = false, has_hi = false;
  const bool refine = L.x0e && L.ue;  // exact x0 and u known: wide ends are refined (refine_ends)
  bool any_wide = false;
  static thread_local std::vector<SideLambda> ls;
  ls.clear();
  for (std::size_t p = s.first; p < s.first + s.count; ++p) {
    if (p == gp || c.on_f[p]) {
      if (strict) return Span::Empty;
      continue;
    }
    I a, b;
    {
      CGAL::Protect_FPU_rounding<true> up;
      const auto [af, bf] = constraint_on_line(c.planes[p], L.x0, L.u);
      a = safe(af), b = safe(bf);
    }
    // n·u near 0 is frequent (n parallel or nearly parallel to f's or g's normal: the same
    // piece face in several sums, the faces of a symmetric mesh parallel up to rounding): a is
    // taken from the exact numbers rather than giving up — its sign, and its value for λ below.
    std::optional<FT> ae;
    if (!certainly_zero(a) && !certainly_nonzero(a)) ae = dot(exact_plane(c, p).n, exact_u(c, L));
    const CGAL::Sign sa = ae                  ? sign(*ae)
                          : certainly_zero(a) ? CGAL::ZERO
                                              : (a.inf() > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE);
    // b near 0 too: plane p nearly holds the line (equal to g's plane at a seam, or nearly
    // coplanar with f or g in a rounded symmetric mesh): b exactly, and λ exactly when a != 0
    // (the exact number's enclosure after its exact evaluation is tight).
    std::optional<FT> be;
    if (!certainly_nonzero(a) && !certainly_nonzero(b) && !certainly_zero(b))
      be = exact_plane(c, p).c - dot(exact_plane(c, p).n, exact_x0(c, L));
    if (sa == CGAL::ZERO) {
      const CGAL::Sign sb = be ? sign(*be)
                            : b.inf() > 0 ? CGAL::POSITIVE
                            : b.sup() < 0 ? CGAL::NEGATIVE
                                          : CGAL::ZERO;
      if (strict ? sb != CGAL::POSITIVE : sb == CGAL::NEGATIVE) return Span::Empty;
      continue;
    }
    // λ = b/a (a of known sign). When a's enclosure holds 0: b/a on the enclosure of the exact a
    // computed for its sign (tight: the exact number rounded outward) — finite, where a
    // half-bounded λ widened the end (refine_ends); the side of λ that b's certain sign bounds
    // only when that enclosure still holds 0 (underflow).
    I l;
    const I at = ae ? iv(*ae) : a;
    if (certainly_nonzero(a)) l = b / a;
    else if (be) l = iv(*be / *ae);
    else if (certainly_nonzero(at)) l = b / at;
    else if ((sa == CGAL::POSITIVE) == (b.inf() > 0))
      l = I((I(b.inf() > 0 ? b.inf() : b.sup()) / I(sa == CGAL::POSITIVE ? a.sup() : a.inf())).inf(), INFINITY);
    else
      l = I(-INFINITY, (I(b.inf() > 0 ? b.inf() : b.sup()) / I(sa == CGAL::POSITIVE ? a.sup() : a.inf())).sup());
    if (sa == CGAL::POSITIVE) {
      hi = has_hi ? imin(hi, l) : l, has_hi = true;
    } else {
      lo = has_lo ? imax(lo, l) : l, has_lo = true;
    }
    if (refine) ls.push_back({p, sa == CGAL::POSITIVE, l}), any_wide = any_wide || !sharp(l);
    if (has_lo && has_hi && (strict ? lo.inf() >= hi.sup() : lo.inf() > hi.sup())) return Span::Empty;
  }
  if (!has_lo || !has_hi) return Span::Unknown;
  if (any_wide && !(sharp(lo) && sharp(hi))) refine_ends(c, L, ls, lo, hi);
  if (planes && refine) *planes = {end_plane(c, L, ls, false, lo), end_plane(c, L, ls, true, hi)};
  return (strict ? lo.sup() < hi.inf() : lo.sup() <= hi.inf()) ? Span::Range : Span::Unknown;
}

// Certainly: L's open interval in S (line_interval, strict) misses (a_inf, b_sup) ⊇ [a, b]:
// the exact path would not list S among the covering intervals.
bool cover_misses(const Ctx& c, const Sum& s, const LineI& L, std::size_t gp, double a_inf, double b_sup) {
  if (open_misses(c, s, L.x0, L.u, a_inf, b_sup)) return true;
  I lo, hi;
  const Span sp = line_interval_i(c, s, L, true, lo, hi, gp);
  return sp == Span::Empty || (sp == Span::Range && (hi.sup() <= a_inf || lo.inf() >= b_sup));
}

// The work of one line in the filtered tier, counted as it is done (exact_minimum's work count):
// `tests` the covering sums looked at (each an O(f̄) interval test, before any early exit),
// `exact` the covering sums' exact intervals computed (offer_on_line).
struct LineWork {
  std::size_t tests = 0, exact = 0;
};

// The exact line stage (main loop) on the enclosures: true when it certainly offers nothing —
// L ∩ S_k certainly empty, or every candidate point (a superset of the exact path's: the foot
// of 0 clamped to [a, b], a, b, every covering interval's ends) certainly covered by an open
// covering interval or certainly beyond the best (Best::beyond) — at once when one covering
// interval certainly holds [a, b] strictly. False whenever a sign or an order is uncertain: the
// exact path decides.
bool line_no_offer(const Ctx& c, const LineI& L, const Sum& sk, std::size_t gp, const std::vector<std::size_t>& cover,
                   const Best& best, std::vector<std::pair<I, I>>& ivs, LineWork& work) {
  if (!(L.u2.inf() > 0)) return false;
  I a, b;
  const Span sp = line_interval_i(c, sk, L, false, a, b, gp);
  if (sp != Span::Range) return sp == Span::Empty;
  ivs.clear();
  for (std::size_t l : cover) {
    ++work.tests;
    if (cover_misses(c, c.sums[l], L, gp, a.inf(), b.sup())) continue;
    I lo, hi;
    const Span sl = line_interval_i(c, c.sums[l], L, true, lo, hi, gp);
    if (sl == Span::Empty) continue;
    if (sl == Span::Unknown) return false;
    if (hi.sup() <= a.inf() || lo.inf() >= b.sup()) continue;  // certainly hi <= a or lo >= b
    if (lo.sup() < a.inf() && b.sup() < hi.inf()) return true;  // certainly [a, b] ⊂ (lo, hi): all covered
    if (!(hi.inf() > a.sup() && lo.sup() < b.inf())) return false;
    ivs.emplace_back(lo, hi);
  }
  auto settled = [&](const I& lam) {
    if (best.beyond(L.l2 + square(lam) * L.u2)) return true;
    for (const auto& [lo, hi] : ivs)
      if (lo.sup() < lam.inf() && lam.sup() < hi.inf()) return true;
    return false;
  };
  I foot(0);  // the exact path's clamp of 0 into [a, b]
  if (a.inf() > 0) foot = a;
  else if (b.sup() < 0) foot = b;
  else if (!(a.sup() <= 0 && b.inf() >= 0)) return false;
  if (!settled(foot) || !settled(a) || !settled(b)) return false;
  for (const auto& [lo, hi] : ivs)
    if (!settled(lo) || !settled(hi)) return false;
  return true;
}

bool boxes_meet(const Box3& a, const Box3& b) {
  return (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
}

// The interval of λ with x0 + λu in S: closed (strict = false) or open (strict = true).
// False when empty. x0, u: L's exact numbers (exact_x0, exact_u).
// The planes equal to plane(f) and the plane g (index `gp`) contain the line (a = b = 0 exactly,
// by construction of x0 and u): no constraint when closed, an empty open interval.
// Both tiers: detail::lambda_interval (line_lambda.hpp) on the constraints a·λ <= b, a = n·u,
// b = c − n·x0 of the sum's planes — the filtered tier evaluates exactly only the planes whose
// λ enclosure may attain the extremum or whose sign of a is uncertain.
struct LineConstraints {
  const Ctx& c;
  const LineI& L;
  const V3 &u, &x0;
  std::size_t gp;
  bool on_line(std::size_t p) const { return p == gp || c.on_f[p]; }
  I a_i(std::size_t p) const { return dot(c.planes[p].ni, L.u); }
  I b_i(std::size_t p) const { return c.planes[p].ci - dot(c.planes[p].ni, L.x0); }
  FT a_e(std::size_t p) const { return dot(exact_plane(c, p).n, u); }
  FT b_e(std::size_t p) const {
    const ExactPlane& e = exact_plane(c, p);
    return e.c - dot(e.n, x0);
  }
  // λ = b/a (a = a_e(p) != 0), once per class of equal planes per line in the filtered tier:
  // planes of one class are the same geometric plane (either side: n, c scaled by t != 0, so b/a
  // is the same number), and the covering sums of a line share planes (on the torus pair 13 % of
  // the exact stage's 11 M λ before offer_on_line's exit: docs/benchmarks.md "Exact mesh σ: a
  // covering interval holding the segment").
  FT lambda_e(std::size_t p) const {
    if (!c.filt) return b_e(p) / a_e(p);
    const std::size_t k = c.cls[p];
    if (c.lam_line[k] != c.line_id) c.lam_line[k] = c.line_id, c.lam_val[k] = b_e(p) / a_e(p);
    return c.lam_val[k];
  }
};
bool line_interval(const Ctx& c, const Sum& s, const LineI& L, bool strict, std::optional<FT>& lo,
                   std::optional<FT>& hi, std::size_t gp) {
  const LineConstraints cs{c, L, exact_u(c, L), exact_x0(c, L), gp};
  return detail::lambda_interval(cs, s.first, s.count, strict, c.filt, lo, hi);
}

// A line L = x0 + λu in plane(f) (exact x0, u; l2 = |x0|², u2 = |u|²) and its segment [a, b] in
// S_k, exact: the point of R_f ∩ L nearest 0 — the segment minus the open intervals of the
// covering sums — is offered. Candidates: the foot of 0 clamped to [a, b], a, b, and every
// covering interval end within [a, b], by increasing |λ| (σ² = l2 + λ²u2 grows with |λ|); the
// first one that no open interval covers is the nearest point, unless it is beyond the best.
struct LineSegment {
  const LineI& L;
  const V3 &u, &x0;
  const FT &l2, &u2, &a, &b;
};

// The reference (every number exact: the SigmaExactUnfiltered tier): each covering sum's open
// interval by line_interval, every comparison on the exact numbers. O(K) exact intervals and
// O(m log m) exact comparisons for m candidates.
void offer_on_line_exact(const Ctx& c, const LineSegment& s, const std::vector<std::size_t>& cover, Best& best) {
  const FT &a = s.a, &b = s.b;
  // Covering open intervals (the ones meeting [a, b]).
  std::vector<std::pair<FT, FT>> ivs;
  for (std::size_t l : cover) {
    std::optional<FT> lo, hi;
    if (!line_interval(c, c.sums[l], s.L, true, lo, hi, s.L.g) || !lo || !hi) continue;
    if (*hi <= a || *lo >= b) continue;
    ivs.emplace_back(*lo, *hi);
  }
  std::vector<FT> cand;
  cand.push_back(is_positive(a) ? a : is_negative(b) ? b : FT(0));
  cand.push_back(a), cand.push_back(b);
  for (const auto& [lo, hi] : ivs) {
    if (lo >= a) cand.push_back(lo);
    if (hi <= b) cand.push_back(hi);
  }
  std::sort(cand.begin(), cand.end(), [](const FT& x, const FT& y) { return abs(x) < abs(y); });
  for (const FT& lam : cand) {
    const FT e2 = s.l2 + lam * lam * s.u2;
    if (best.beyond(e2)) break;
    bool covered = false;
    for (const auto& [lo, hi] : ivs)
      if (lo < lam && lam < hi) {
        covered = true;
        break;
      }
    if (!covered) {
      offer(best, e2, s.x0 + lam * s.u, s.L.f);
      break;
    }
  }
}

// An end of an interval on the line: an enclosure of its exact value, and the value once a
// comparison needs it (offer_on_line).
struct LazyEnd {
  I i;
  std::optional<FT> e;
  std::size_t plane = SIZE_MAX;  // a plane attaining it, when certain (end_plane)
};
// A covering sum's open interval on the line: its ends as enclosures (line_interval_i) until a
// comparison needs one exactly, then both by line_interval.
struct CoverSpan {
  std::size_t sum;
  LazyEnd lo, hi;
};
// A candidate: an end, and the span it belongs to (nullptr: the segment's, exact from the start).
struct LineCandidate {
  LazyEnd* v;
  CoverSpan* span;
};

// The filtered tier of offer_on_line_exact: the same covering intervals in the same order, the
// same candidates in the same order, every comparison the same exact predicate — decided on the
// enclosures when they are disjoint, else on the exact numbers, computed then (a covering sum's
// exact interval only when one of its ends is compared undecided or is offered) — so the sort
// sees the same outcomes and the same point is offered, bit for bit (the tiers' test). A covering
// interval that certainly holds [a, b] strictly ends the line at once: every candidate lies in
// [a, b], so the reference offers nothing. On the torus pair (~42 covering intervals per exact
// line, their ends tied exactly: shared planes and vertices, so the lazy ends alone saved 14 % of
// the exact intervals) that exit makes the query 4–5× faster (docs/benchmarks.md "Exact mesh σ:
// a covering interval holding the segment").
void offer_on_line(const Ctx& c, const LineSegment& s, const std::vector<std::size_t>& cover, Best& best,
                   std::vector<CoverSpan>& spans, LineWork& work) {
  auto value = [&](LazyEnd& x, CoverSpan* span) -> const FT& {
    if (!x.e) {
      ++work.exact;
      std::optional<FT> lo, hi;
      if (!line_interval(c, c.sums[span->sum], s.L, true, lo, hi, s.L.g) || !lo || !hi)
        throw std::logic_error("offer_on_line: an enclosed interval is empty exactly");
      span->lo.e = std::move(lo), span->hi.e = std::move(hi);
    }
    return *x.e;
  };
  // The order of two ends of known planes (end_plane): equal when of one class, else by the
  // head-and-tail comparison of their planes' λ (fine_compare); nullopt when undecided.
  auto plane_order = [&](const LazyEnd& x, const LazyEnd& y) -> std::optional<int> {
    if (x.plane == SIZE_MAX || y.plane == SIZE_MAX) return std::nullopt;
    if (c.cls[x.plane] == c.cls[y.plane]) return 0;
    return fine_compare(c, s.L, x.plane, y.plane);
  };
  auto less = [&](LazyEnd& x, CoverSpan* sx, LazyEnd& y, CoverSpan* sy) {  // x < y, exactly
    if (x.i.sup() < y.i.inf()) return true;
    if (x.i.inf() >= y.i.sup()) return false;
    if (const auto r = plane_order(x, y)) return *r < 0;
    return value(x, sx) < value(y, sy);
  };
  LazyEnd a{iv(s.a), s.a}, b{iv(s.b), s.b};
  {  // the classes attaining a and b (S_k's closed interval again on enclosures)
    std::array<std::size_t, 2> k;
    I ai, bi;
    line_interval_i(c, c.sums[c.planes[s.L.f].sum], s.L, false, ai, bi, s.L.g, &k);
    a.plane = k[0], b.plane = k[1];
  }
  const FT foot_v = is_positive(s.a) ? s.a : is_negative(s.b) ? s.b : FT(0);
  LazyEnd foot{iv(foot_v), foot_v, is_positive(s.a) ? a.plane : is_negative(s.b) ? b.plane : SIZE_MAX};
  // Covering open intervals (the ones meeting [a, b]): certainly missing ones (open_misses, an
  // empty enclosure) dropped; first on enclosures only, so that a covering interval certainly
  // holding [a, b] strictly — lo < a and b < hi certainly: every candidate (all in [a, b]) is
  // covered, the reference offers nothing — ends the line before any exact interval of the
  // others is computed (docs/benchmarks.md "Exact mesh σ: tight λ enclosures").
  spans.clear();
  static thread_local std::vector<Span> kinds;  // spans[k]'s line_interval_i outcome
  kinds.clear();
  auto holds = [&](const CoverSpan& sp) { return sp.lo.i.sup() < a.i.inf() && b.i.sup() < sp.hi.i.inf(); };
  for (std::size_t l : cover) {
    ++work.tests;
    if (open_misses(c, c.sums[l], s.L.x0, s.L.u, a.i.inf(), b.i.sup())) continue;
    CoverSpan sp{l, {}, {}};
    std::array<std::size_t, 2> k;
    const Span r = line_interval_i(c, c.sums[l], s.L, true, sp.lo.i, sp.hi.i, s.L.g, &k);
    sp.lo.plane = k[0], sp.hi.plane = k[1];
    if (r == Span::Empty) continue;
    if (r == Span::Range && holds(sp)) return;
    spans.push_back(std::move(sp)), kinds.push_back(r);
  }
  // Then in the reference's order: the undecided ones exactly, the order of each against a and b
  // decided as the reference does.
  std::size_t kept = 0;
  for (std::size_t k = 0; k < spans.size(); ++k) {
    CoverSpan& sp = spans[k];
    if (kinds[k] == Span::Unknown) {
      ++work.exact;
      std::optional<FT> lo, hi;
      if (!line_interval(c, c.sums[sp.sum], s.L, true, lo, hi, s.L.g) || !lo || !hi) continue;
      sp.lo = {iv(*lo), std::move(lo), sp.lo.plane}, sp.hi = {iv(*hi), std::move(hi), sp.hi.plane};
      if (holds(sp)) return;
    }
    if (!less(a, nullptr, sp.hi, &sp) || !less(sp.lo, &sp, b, nullptr)) continue;  // hi <= a or lo >= b
    if (kept != k) spans[kept] = std::move(sp);
    ++kept;
  }
  spans.resize(kept);
  std::vector<LineCandidate> cand{{&foot, nullptr}, {&a, nullptr}, {&b, nullptr}};
  for (CoverSpan& sp : spans) {
    if (!less(sp.lo, &sp, a, nullptr)) cand.push_back({&sp.lo, &sp});
    if (!less(b, nullptr, sp.hi, &sp)) cand.push_back({&sp.hi, &sp});
  }
  std::sort(cand.begin(), cand.end(), [&](const LineCandidate& x, const LineCandidate& y) {  // |x| < |y|
    const I ax = CGAL::abs(x.v->i), ay = CGAL::abs(y.v->i);
    if (ax.sup() < ay.inf()) return true;
    if (ax.inf() >= ay.sup()) return false;
    const int sx = x.v->i.inf() > 0 ? 1 : x.v->i.sup() < 0 ? -1 : 0, sy = y.v->i.inf() > 0 ? 1 : y.v->i.sup() < 0 ? -1 : 0;
    if (sx != 0 && sx == sy)  // of one certain sign: |x| < |y| is x < y (or y < x)
      if (const auto r = plane_order(*x.v, *y.v)) return sx * *r < 0;
    return abs(value(*x.v, x.span)) < abs(value(*y.v, y.span));
  });
  for (const LineCandidate& k : cand) {
    const bool covered = std::any_of(spans.begin(), spans.end(), [&](CoverSpan& sp) {
      return less(sp.lo, &sp, *k.v, k.span) && less(*k.v, k.span, sp.hi, &sp);
    });
    if (covered) {  // the reference goes on unless the point is beyond the best
      const I e2 = s.L.l2 + square(k.v->i) * s.L.u2;
      if (best.within(e2)) continue;
      if (best.beyond(e2)) break;
    }
    const FT& lam = value(*k.v, k.span);
    const FT e2 = s.l2 + lam * lam * s.u2;
    if (best.beyond(e2)) break;
    if (covered) continue;
    offer(best, e2, s.x0 + lam * s.u, s.L.f);
    break;
  }
}

// SigmaLineCheck (tests): the line through the filtered tier (offer_on_line, unless line_no_offer
// settled it) and through the reference on a copy of the best; counts the lines whose outcomes
// differ and those with exact ties among the ends of [a, b] and of the covering intervals.
void check_line(const Ctx& c, const LineSegment& s, const std::vector<std::size_t>& cover, Best& best,
                std::vector<CoverSpan>& spans, bool no_offer, LineWork& work) {
  Best ref = best;
  offer_on_line_exact(c, s, cover, ref);
  if (no_offer) {
    ++SigmaLineCheck::no_offer;
    SigmaLineCheck::no_offer_violations += ref.offers != best.offers;
    return;
  }
  std::vector<FT> ends{s.a, s.b};
  for (std::size_t l : cover) {
    std::optional<FT> lo, hi;
    if (!line_interval(c, c.sums[l], s.L, true, lo, hi, s.L.g) || !lo || !hi || *hi < s.a || *lo > s.b) continue;
    ends.push_back(*lo), ends.push_back(*hi);
  }
  std::sort(ends.begin(), ends.end());
  SigmaLineCheck::ties += std::adjacent_find(ends.begin(), ends.end()) != ends.end();
  offer_on_line(c, s, cover, best, spans, work);
  ++SigmaLineCheck::lines;
  const bool same = ref.offers == best.offers &&
                    (!ref.d2 || (*ref.d2 == *best.d2 && ref.plane == best.plane && ref.x.x == best.x.x &&
                                 ref.x.y == best.x.y && ref.x.z == best.x.z));
  SigmaLineCheck::mismatches += !same;
}

// Of the candidates `idx` (those whose enclosure may attain the extremum), keeps the ones whose
// exact value (value(i), exact) is the maximum (`max`) or the minimum: the ties the intervals
// cannot split (faces coplanar up to rounding, e.g. a mesh's planar quads split in two triangles)
// are decided exactly, so a face keeps its true vertices only.
template <class Value>
void keep_extreme(std::vector<std::size_t>& idx, bool max, Value value) {
  if (idx.size() < 2) return;
  std::vector<FT> v;
  for (std::size_t i : idx) v.push_back(value(i));
  FT best = v[0];
  for (const FT& x : v)
    if (max ? x > best : x < best) best = x;
  std::size_t k = 0;
  for (std::size_t i = 0; i < idx.size(); ++i)
    if (v[i] == best) idx[k++] = idx[i];
  idx.resize(k);
}

// Enclosures of the vertices of the face f ∩ S_k = F_P(n) ⊕ −F_Q'(n) (n = f's normal,
// S_k = P_i ⊕ −Q'_j, f a supporting plane): p − q' for every vertex p of P_i maximising n·p and
// every q of Q_j minimising n·q' (interval comparisons against the certain bounds first, the
// remaining ties exactly: keep_extreme). Their hull is the face.
void face_points(const Ctx& c, std::size_t fi, std::vector<IV3>& pts) {
  const Plane& f = c.planes[fi];
  const Sum& s = c.sums[f.sum];
  const convex3::PolytopeData &P = data_p(c, s), &Q = data_q(c, s);
  std::vector<IV3> ps, qs;
  std::vector<I> hp, hq;
  double maxp = -INFINITY, minq = INFINITY;  // certain: max n·p >= maxp, min n·q' <= minq
  for (const Vec3& v : P.v) {
    ps.push_back(lift<I>(v)), hp.push_back(dot(f.ni, ps.back()));
    maxp = std::max(maxp, hp.back().inf());
  }
  for (const Vec3& v : Q.v) {
    qs.push_back(placed<I>(c.pl, v)), hq.push_back(dot(f.ni, qs.back()));
    minq = std::min(minq, hq.back().sup());
  }
  std::vector<std::size_t> A, B;
  for (std::size_t a = 0; a < ps.size(); ++a)
    if (hp[a].sup() >= maxp) A.push_back(a);
  for (std::size_t b = 0; b < qs.size(); ++b)
    if (hq[b].inf() <= minq) B.push_back(b);
  const V3& n = exact_plane(c, fi).n;
  keep_extreme(A, true, [&](std::size_t a) { return dot(n, lift<FT>(P.v[a])); });
  keep_extreme(B, false, [&](std::size_t b) { return dot(n, placed<FT>(c.pl, Q.v[b])); });
  pts.clear();
  for (std::size_t a : A)
    for (std::size_t b : B) pts.push_back(ps[a] - qs[b]);
}

// An enclosure of the squared distance from 0 to the box b (IF: the caller holds the rounding
// guard).
I box_distance2(const Box3& b) {
  IF d2(0);
  for (int a = 0; a < 3; ++a) {
    const double g = b.lo[a] > 0 ? b.lo[a] : b.hi[a] < 0 ? -b.hi[a] : 0.0;
    d2 += IF(g) * IF(g);
  }
  return safe(d2);
}

// A box holding the enclosures `pts`.
Box3 box_of(const IV3* pts, std::size_t n) {
  Box3 b{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
  for (std::size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a)
      b.lo[a] = std::min(b.lo[a], comp(pts[i], a).inf()), b.hi[a] = std::max(b.hi[a], comp(pts[i], a).sup());
  return b;
}

// The enclosures t certainly lie in the open S (each strictly inside every plane): then their
// hull does (S open and convex). IF: the caller holds the rounding guard.
bool strictly_inside(const Ctx& c, const Sum& s, const std::array<IV3, 3>& t) {
  for (std::size_t p = s.first; p < s.first + s.count; ++p)
    for (const IV3& x : t)
      if (!((dotf(c.planes[p].ni, x) - fast(c.planes[p].ci)).sup() < 0)) return false;
  return true;
}

// The enclosure x certainly lies outside the open S (on or beyond one of its planes). IF: the
// caller holds the rounding guard.
bool certainly_outside(const Ctx& c, const Sum& s, const IV3& x) {
  for (int a = 0; a < 3; ++a)
    if (comp(x, a).sup() <= s.box.lo[a] || comp(x, a).inf() >= s.box.hi[a]) return true;
  for (std::size_t p = s.first; p < s.first + s.count; ++p)
    if ((dotf(c.planes[p].ni, x) - fast(c.planes[p].ci)).inf() >= 0) return true;
  return false;
}

// Depth of the subdivision in face_covered (each level splits a triangle into 4 at its edge
// midpoints): a face whose union cover needs finer pieces goes to the line stage.
constexpr int kCoverDepth = 4;

// The triangle of enclosures t (its hull, a superset of the true triangle) certainly offers no
// point: it lies beyond the best (Best::beyond on its box's distance), or in
// ∪ int S_l over the sums `cand` (those whose box meets it): in one of them whole, or, down to
// `depth` more levels, each of its four midpoint sub-triangles (midpoints as enclosures of the
// exact midpoints: the four hulls cover the true triangle). Only strict, certain inclusions
// count, so a point on a seam where two sums meet (in neither open sum) is never covered unless
// a third sum holds it in its interior. `hint`: the sum tried first (the one found last).
// The triangles left unsettled (boxes of their hulls): with the settled ones they cover the face,
// so R_f ∩ B(0, best) lies in their union. `complete` false: exploration stopped at `max`.
struct Leaves {
  std::vector<Box3> boxes;
  bool complete = true;
  std::size_t max = 0;
};
// At most kMaxLeaves unsettled triangles are kept, and only for faces that kLeavesMinSums other
// sums' boxes meet (the line stage's cost grows with them; below, the first unsettled triangle
// ends the cover test as the one-sum test did: the full exploration cost 8–23 % on the combs and
// the cross, docs/benchmarks.md "Exact mesh σ: a facet cover by unions").
constexpr std::size_t kMaxLeaves = 64, kLeavesMinSums = 32;

bool triangle_covered(const Ctx& c, const std::array<IV3, 3>& t, const std::vector<std::size_t>& cand,
                      const Best& best, int depth, std::size_t& hint, Leaves& out) {
  CGAL::Protect_FPU_rounding<true> up;  // IF arithmetic below
  const Box3 b = box_of(t.data(), 3);
  if (best.beyond(box_distance2(b))) return true;  // every point is beyond the best: no offer
  auto holds = [&](std::size_t l) {
    const Sum& s = c.sums[l];
    return (s.box.lo.array() < b.lo.array()).all() && (b.hi.array() < s.box.hi.array()).all() &&
           strictly_inside(c, s, t);
  };
  if (hint < c.sums.size() && holds(hint)) return true;
  for (std::size_t l : cand)
    if (l != hint && holds(l)) return hint = l, true;
  auto leaf = [&] {
    if (out.boxes.size() >= out.max) out.complete = false;
    else out.boxes.push_back(b);
    return false;
  };
  if (depth == 0) return leaf();
  // A vertex certainly in no open sum and not certainly beyond the best may be a point of R_f:
  // stop here (the lines decide) rather than subdivide around it.
  for (const IV3& x : t)
    if (!best.beyond(safe(dotf(x, x))) && std::all_of(cand.begin(), cand.end(), [&](std::size_t l) { return certainly_outside(c, c.sums[l], x); }))
      return leaf();
  std::vector<std::size_t> sub;  // the sums whose box meets t's: only they can hold a part of it
  for (std::size_t l : cand)
    if (boxes_meet(c.sums[l].box, b)) sub.push_back(l);
  if (sub.size() < 2) return leaf();  // one sum does not hold t: its parts would not be covered either
  auto mid = [&](const IV3& x, const IV3& y) {
    return IV3{safe(IF(0.5) * (fast(x.x) + fast(y.x))), safe(IF(0.5) * (fast(x.y) + fast(y.y))),
               safe(IF(0.5) * (fast(x.z) + fast(y.z)))};
  };
  const IV3 m01 = mid(t[0], t[1]), m12 = mid(t[1], t[2]), m20 = mid(t[2], t[0]);
  bool all = true;
  for (const std::array<IV3, 3>& q : {std::array<IV3, 3>{t[0], m01, m20}, std::array<IV3, 3>{m01, t[1], m12},
                                      std::array<IV3, 3>{m20, m12, t[2]}, std::array<IV3, 3>{m01, m12, m20}}) {
    all = triangle_covered(c, q, sub, best, depth - 1, hint, out) && all;
    if (!out.complete) return false;
  }
  return all;
}

// The convex polygon hull(pts) (its vertices as enclosures, in any order) certainly offers no
// point: the fan triangles from pts[0] over every pair of the others cover it, and each must be
// covered by ∪ int S_l over `cand` or lie beyond the best (triangle_covered). `out.max`: the
// unsettled triangles kept; `out`: their boxes (complete = false when not all were explored).
bool polygon_covered(const Ctx& c, const std::vector<IV3>& pts, const std::vector<std::size_t>& cand, const Best& best,
                     Leaves& out) {
  out.boxes.clear(), out.complete = true;
  std::size_t hint = SIZE_MAX;
  bool all = true;
  for (std::size_t i = 1; i < pts.size() && out.complete; ++i)
    for (std::size_t j = i + 1; j < pts.size() && out.complete; ++j)
      all = triangle_covered(c, {pts[0], pts[i], pts[j]}, cand, best, kCoverDepth, hint, out) && all;
  return all && out.complete;
}

// The face f ∩ S_k certainly offers nothing: its part within the best lies in ∪ int S_l over
// the other sums, so R_f = f ∩ S_k \ ∪ int S_l holds no point nearer than the best (the exact
// path would offer nothing from f: its offers are points of R_f, and the best does not change
// between this test and f's lines). The face is the hull of its face_points (polygon_covered;
// tests/mesh3/test_union_cover.cpp checks it on constructed sets through detail::union_cover).
// Sums whose box does not meet the face's are left out. Cost: O(K) box tests per triangle
// tried, and per sum tried its planes against 3 points; at most 4^kCoverDepth triangles per fan
// triangle (measured in docs/benchmarks.md "Exact mesh σ: a facet cover by unions").
// `out`: the unsettled triangles' boxes (complete = false when not all were explored).
bool face_covered(const Ctx& c, std::size_t fi, const Best& best, std::vector<IV3>& pts, Leaves& out) {
  out.boxes.clear(), out.complete = true;
  face_points(c, fi, pts);
  if (pts.size() < 3 || pts.size() > 32) return out.complete = false;
  const Box3 b = box_of(pts.data(), pts.size());
  std::vector<std::size_t> cand;
  for (std::size_t l = 0; l < c.sums.size(); ++l)
    if (l != c.planes[fi].sum && boxes_meet(c.sums[l].box, b)) cand.push_back(l);
  out.max = cand.size() >= kLeavesMinSums ? kMaxLeaves : 0;
  return polygon_covered(c, pts, cand, best, out);
}

// The line plane(f) ∩ plane(g) certainly misses every unsettled triangle of f's face (plane(g)
// misses their boxes): it holds no point of R_f nearer than the best, so it offers nothing.
bool line_misses_leaves(const Plane& g, const Leaves& leaves) {
  return leaves.complete && std::all_of(leaves.boxes.begin(), leaves.boxes.end(),
                                        [&](const Box3& b) { return plane_misses_box(g, b); });
}

Feature3 feat(FeatureKind3 k, int i) { return Feature3{k, i}; }

}  // namespace

namespace detail {

// The sets as sums without pieces (a Ctx on an empty MeshPair: the cover reads only the sums'
// boxes and their planes' enclosures, here the exact doubles), no best yet (beyond = past reach2).
CoverResult union_cover(const std::vector<OpenConvex>& sets, const std::vector<Vec3>& polygon, double reach2,
                        bool keep_leaves) {
  static const MeshPair none{};
  Ctx c{none, Placed{}, {}, {}, true, false, {}, {}, 0, {}, {}, {}, {}, {}, {}};
  for (const OpenConvex& o : sets) {
    Sum s;
    s.first = c.planes.size(), s.count = o.planes.size(), s.box = o.box;
    for (const auto& [n, d] : o.planes) c.planes.push_back(Plane{lift<I>(n), I(d), 0, c.sums.size(), {}});
    c.sums.push_back(s);
  }
  std::vector<IV3> pts;
  for (const Vec3& v : polygon) pts.push_back(lift<I>(v));
  const Box3 b = box_of(pts.data(), pts.size());
  std::vector<std::size_t> cand;
  for (std::size_t l = 0; l < c.sums.size(); ++l)
    if (boxes_meet(c.sums[l].box, b)) cand.push_back(l);
  Best best{};
  best.radius = std::sqrt(reach2), best.sup2 = best.inf2 = reach2;
  Leaves out;
  out.max = keep_leaves ? kMaxLeaves : 0;
  CoverResult r;
  r.covered = polygon_covered(c, pts, cand, best, out);
  r.leaves = std::move(out.boxes), r.complete = out.complete;
  return r;
}

}  // namespace detail

std::optional<Depth3> exact_minimum(const MeshPair& m, const Pose3& pose_p, const Pose3& pose_q, double upper,
                                    std::size_t max_work, bool skip_cover) {
  SigmaExactWork& stats = last_exact_work;
  stats = {};
  if (!(upper >= 0) || !std::isfinite(upper)) return std::nullopt;
  Ctx c{m, place(m, pose_p, pose_q), {}, {}, SigmaExactUnfiltered::depth == 0, SigmaExactUnfiltered::planted, {}, {}, 0, {}, {}, {}, {}, {}, {}};
  const convex3::RelativePose rel{c.pl.R, c.pl.tq, c.pl.tp};
  const double reach = upper * (1 + 0x1p-30) + 0x1p-1000;
  // The work count (mesh_sigma_exact.hpp, kExactSigmaMaxWork): deterministic, never a clock, in
  // units of one line–sum interval test. Charged as done: a candidate facet of the setup
  // (minkowski_facets, its plane, the repeated-plane test) kSetupWeight; a line past the interval
  // prunes 1 + the covering sums line_no_offer looked at before it exits; a line of the exact stage
  // kExactLineWeight (its exact u, x0, S_k's interval) + the covering sums offer_on_line looked
  // at before its exit + kExactIntervalWeight per exact covering interval computed; in either
  // stage kRefineWeight per constraint whose λ refine_ends made exact and kFineWeight per one it
  // gave the head-and-tail λ (fine_lambda.hpp). Weights fitted to CPU time
  // per query over the tripod's, the combs', the cross's, the star's and the torus pair's exact
  // σ: ~1.3 µs per unit, within ±25 % (log sd 0.22) on queries over 20 ms (docs/benchmarks.md
  // "Exact mesh σ: the work counted as done"; refit with kRefineWeight: 1.4 µs, log sd 0.22,
  // "… tight λ enclosures"; with kFineWeight: 1.3 µs at load 5, log sd 0.20, "… a head-and-tail
  // filter for λ"), so that giving up costs about the same time whichever stage reaches the limit.
  constexpr std::size_t kSetupWeight = 15, kExactLineWeight = 1, kExactIntervalWeight = 20, kRefineWeight = 1,
                        kFineWeight = 1;
  std::size_t work = 0, refined_charged = 0, fined_charged = 0;
  auto spend = [&](std::size_t units) {  // + the exact λ of refine_ends since the last charge
    units += kRefineWeight * (c.refined - refined_charged), refined_charged = stats.refined = c.refined;
    units += kFineWeight * (c.fined - fined_charged), fined_charged = stats.fined = c.fined;
    return (stats.units = work += units) <= max_work;
  };
  // The sums in range and their planes.
  for (std::size_t i = 0; i < m.P.size(); ++i)
    for (std::size_t j = 0; j < m.Q.size(); ++j) {
      const double bd = box_distance(box_of_sum(m, c.pl, i, j));
      if (bd * (1 - 0x1p-30) > reach) continue;
      const auto cand = convex3::minkowski_facets(m.P[i], m.Q[j], rel, std::nullopt);
      stats.setup += cand.size();
      if (!spend(kSetupWeight * cand.size())) return std::nullopt;
      const convex3::PolytopeData& P = convex3::data_of(m.P[i]);
      const convex3::PolytopeData& Q = convex3::data_of(m.Q[j]);
      Sum s{i, j, c.planes.size(), cand.size(), bd, box_of_sum(m, c.pl, i, j)};
      c.sums.push_back(s);
      for (const auto& k : cand) {
        const std::size_t np = c.planes.size();
        c.exact.emplace_back();
        c.planes.push_back(plane_of(c.pl, P, Q, k, c.exact.back()));
        c.planes.back().sum = c.sums.size() - 1;
        bool drop = zero_normal(c, np);  // supports nothing (0·x <= 0)
        // The same plane, the same side: one constraint, one facet, one set of lines.
        for (std::size_t e = s.first; e < np && !drop; ++e) drop = same_plane(c, e, np);
        if (drop) c.planes.pop_back(), c.exact.pop_back();
      }
      c.sums.back().count = c.planes.size() - s.first;
    }
  // 0 ∈ O?
  const V3 zero{FT(0), FT(0), FT(0)};
  bool inside = false;
  const IV3 zi{I(0), I(0), I(0)};
  for (const Sum& s : c.sums) inside = inside || in_open(c, s, zero, zi);
  if (!inside) return std::nullopt;

  c.fine.resize(c.planes.size());
  std::vector<std::size_t> order(c.planes.size());
  for (std::size_t p = 0; p < order.size(); ++p) order[p] = p;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return c.planes[a].dist < c.planes[b].dist; });

  Best best;
  best.radius = reach;
  best.cap2 = FT(reach) * FT(reach);
  std::tie(best.inf2, best.sup2) = to_interval(best.cap2);
  auto near = [&](double d) { return d * (1 - 0x1p-40) <= best.radius; };
  std::vector<std::size_t> cover;    // sums whose box meets B(0, best.radius): they cover
  std::vector<std::size_t> sources;  // the same and f's own sum: their planes cut f's lines
  std::vector<std::size_t> marked;   // the planes set in c.on_f
  c.on_f.assign(c.planes.size(), 0);
  std::size_t lines = 0;
  std::vector<std::pair<I, I>> ivs_i;  // line_no_offer's scratch
  std::vector<CoverSpan> spans;        // offer_on_line's scratch
  std::vector<IV3> face;               // face_covered's scratch
  Leaves leaves;                       // face_covered's unsettled triangles of the current facet
  // Filtered tier: the class of g whose line plane(f) ∩ plane(g) was run for the current facet
  // (line_done[class] = fi): the same line from another plane of the class offers the same points
  // (x0 + λu is the same point set; planes holding the line give the same empty or unconstrained
  // intervals as g, exactly), and the best only decreases, so it is not run again.
  std::vector<std::size_t> line_done;
  if (c.filt) {
    plane_classes(c, order), line_done.assign(c.planes.size(), SIZE_MAX);
    c.lam_line.assign(c.planes.size(), SIZE_MAX), c.lam_val.resize(c.planes.size());
  }
  // SigmaCoverCheck (tests): a facet found covered is processed anyway; an offer from it is a
  // violation (checked when the next facet starts and after the loop).
  std::size_t checked_offers = SIZE_MAX;  // best.offers when the last covered facet started
  auto check_cover = [&] {
    if (checked_offers != SIZE_MAX && best.offers != checked_offers) ++SigmaCoverCheck::violations;
    checked_offers = SIZE_MAX;
  };
  for (std::size_t fi : order) {
    check_cover();
    const Plane& f = c.planes[fi];
    if (!near(f.dist)) break;
    const Sum& sk = c.sums[f.sum];
    if (!near(sk.box_dist)) continue;  // f ⊂ S_k lies beyond the best
    if (c.filt && !skip_cover && face_covered(c, fi, best, face, leaves)) {  // no point of R_f nearer than the best
      if (SigmaCoverCheck::depth == 0) continue;
      ++SigmaCoverCheck::covered, checked_offers = best.offers;
      leaves.complete = false;  // every line of the facet runs
    }
    cover.clear(), sources.clear();
    for (std::size_t p : marked) c.on_f[p] = 0;
    marked.clear();
    for (std::size_t l = 0; l < c.sums.size(); ++l)
      if (l == f.sum || (near(c.sums[l].box_dist) && boxes_meet(c.sums[l].box, sk.box) &&
                         !(c.filt && plane_misses_box(f, c.sums[l].box)))) {  // else ∂S_l misses f
        sources.push_back(l);
        // Seams (exact ties, handled once): a sum with plane(f) among its planes (f's own sum, a
        // neighbour touching along it, or lying on its other side) has no interior point on
        // plane(f), so it covers nothing there; its planes equal to plane(f) are marked.
        bool twin = false;
        const Sum& sl = c.sums[l];
        for (std::size_t p = sl.first; p < sl.first + sl.count; ++p)
          if (p == fi || same_plane_any(c, p, fi)) c.on_f[p] = 1, marked.push_back(p), twin = true;
        if (!skip_cover && !twin) cover.push_back(l);
      }
    const ExactPlane& fe = exact_plane(c, fi);
    const FT n2 = dot(fe.n, fe.n);
    if (is_zero(n2)) continue;  // a degenerate candidate normal supports nothing
    // The foot of 0 on plane(f).
    const FT d2 = fe.c * fe.c / n2;
    if (best.beyond(d2)) continue;
    const V3 p = (fe.c / n2) * fe.n;
    const IV3 pi = iv(p);
    if (in_closed(c, sk, p, pi, fi)) {
      bool covered = false;
      for (std::size_t l : cover)
        if (in_open(c, c.sums[l], p, pi)) {
          covered = true;
          break;
        }
      if (!covered) {
        offer(best, d2, p, fi);
        continue;  // the foot is the nearest point of the plane
      }
    }
    // Lines plane(f) ∩ plane(g).
    for (std::size_t l : sources) {
      const Sum& sl = c.sums[l];
      for (std::size_t gi = sl.first; gi < sl.first + sl.count; ++gi) {
        const Plane& g = c.planes[gi];
        if (gi == fi || !near(g.dist)) continue;
        bool no_offer = false;  // line_no_offer settled the line (run anyway under a SigmaLineCheck)
        const double bound2 = best.d2 ? to_interval(*best.d2).second : reach * reach * (1 + 0x1p-40);
        if (c.filt) {
          if (line_done[c.cls[gi]] == fi) continue;  // this line was run for f
          if (!skip_cover && line_misses_leaves(g, leaves)) continue;
          const LineI L = interval_line(f, g, fi, gi);
          if (line_far(c, L, sk, sl, bound2)) continue;
          line_done[c.cls[gi]] = fi;
          LineWork w;
          no_offer = line_no_offer(c, L, sk, gi, cover, best, ivs_i, w);
          ++stats.lines, stats.tests += w.tests;
          if (!spend(1 + w.tests)) return std::nullopt;
          if (no_offer && SigmaLineCheck::depth == 0) continue;
          ++stats.exact_lines;  // its exact u, x0 and S_k's exact interval
          if (!spend(kExactLineWeight)) return std::nullopt;
        }
        const ExactPlane& ge = exact_plane(c, gi);
        const V3 u = cross(fe.n, ge.n);
        if (is_zero(u)) continue;
        const FT u2 = dot(u, u);
        const V3 x0 = (FT(1) / u2) * (fe.c * cross(ge.n, u) + ge.c * cross(u, fe.n));
        const FT l2 = dot(x0, x0);
        if (best.beyond(l2)) continue;
        std::optional<FT> a, b;
        const LineI Le{iv(u), iv(x0), iv(u2), iv(l2), fi, gi, u, x0, {}};
        ++c.line_id;  // a new line: no λ cached (LineConstraints::lambda_e)
        if (!line_interval(c, sk, Le, false, a, b, gi)) continue;
        if (!a || !b) continue;  // unreachable: S_k is bounded
        ++lines;
        const LineSegment seg{Le, u, x0, l2, u2, *a, *b};
        if (!c.filt) {
          if (!spend(1 + cover.size())) return std::nullopt;
          offer_on_line_exact(c, seg, cover, best);
          continue;
        }
        LineWork w;
        if (SigmaLineCheck::depth) check_line(c, seg, cover, best, spans, no_offer, w);
        else offer_on_line(c, seg, cover, best, spans, w);
        stats.exact_tests += w.tests, stats.exact_intervals += w.exact;
        if (!spend(w.tests + kExactIntervalWeight * w.exact)) return std::nullopt;
      }
    }
  }
  check_cover();
  // No point of Oᶜ within `upper`: it was not an upper bound (a caller's bug): no answer.
  if (!best.d2 || *best.d2 > FT(reach) * FT(reach)) return std::nullopt;

  // σ = RN(√σ²) and a certified bracket.
  const FT q = *best.d2;
  double s = std::sqrt(to_double(q));
  auto cmp = [&](double v) { return compare(FT(v) * FT(v), q); };  // sign(v² − σ²)
  while (cmp(s) == CGAL::SMALLER) s = std::nextafter(s, INFINITY);
  while (s > 0 && cmp(std::nextafter(s, 0.0)) != CGAL::SMALLER) s = std::nextafter(s, 0.0);
  // Now s = the least double with s² >= σ².
  double lo = s, hi = s;
  if (cmp(s) != CGAL::EQUAL) lo = std::nextafter(s, 0.0);
  double depth = hi;
  if (lo != hi) {
    const FT mid = (FT(lo) + FT(hi)) / 2;
    const CGAL::Comparison_result r = compare(mid * mid, q);
    depth = r == CGAL::LARGER ? lo : r == CGAL::SMALLER ? hi : (std::bit_cast<std::uint64_t>(lo) % 2 == 0 ? lo : hi);
  }

  const Plane& f = c.planes[best.plane];
  const Sum& sk = c.sums[f.sum];
  const Vec3 x = to_vec(best.x);
  Depth3 r;
  r.kind = DepthKind::Minimum;
  r.overlapping = true;
  r.depth = depth;
  r.lower_bound = lo;
  r.upper_bound = hi;
  const Vec3 dir = x.norm() > 0 ? Vec3(x.normalized()) : f.k.unit;
  r.translation = c.pl.Rp * (depth * dir);
  r.normal = c.pl.Rp * dir;
  r.facet_normal = c.pl.Rp * f.k.unit;
  // Contact: p − q' = x with p, q' on the facet's defining features (rounded).
  const convex3::PolytopeData& P = convex3::data_of(m.P[sk.i]);
  const convex3::PolytopeData& Q = convex3::data_of(m.Q[sk.j]);
  const Vec3 qv = c.pl.R * Q.v[f.k.q_vertex] + (c.pl.tq - c.pl.tp);
  Vec3 contact = P.v[f.k.p_vertex];
  switch (f.k.source) {
    case convex3::FacetSource::FaceP:
      contact = x + qv;
      r.feature_p = feat(FeatureKind3::Face, f.k.p_feature), r.feature_q = feat(FeatureKind3::Vertex, f.k.q_vertex);
      break;
    case convex3::FacetSource::FaceQ:
      r.feature_p = feat(FeatureKind3::Vertex, f.k.p_vertex), r.feature_q = feat(FeatureKind3::Face, f.k.q_feature);
      break;
    case convex3::FacetSource::EdgeEdge: {
      // p = pa + α ep, q' = qa' + β eq with p − q' = x: least squares in (α, β).
      const convex3::DKLevel &LP = P.levels[0], &LQ = Q.levels[0];
      const Vec3 pa = P.v[LP.origin(f.k.p_feature)], ep = P.v[LP.target(f.k.p_feature)] - pa;
      const Vec3 qa = c.pl.R * Q.v[LQ.origin(f.k.q_feature)] + (c.pl.tq - c.pl.tp);
      const Vec3 eq = c.pl.R * (Q.v[LQ.target(f.k.q_feature)] - Q.v[LQ.origin(f.k.q_feature)]);
      Eigen::Matrix<double, 3, 2> A;
      A.col(0) = ep, A.col(1) = -eq;
      const Eigen::Vector2d ab = A.colPivHouseholderQr().solve(Vec3(x + qa - pa));
      contact = pa + ab[0] * ep;
      r.feature_p = feat(FeatureKind3::Edge, f.k.p_feature), r.feature_q = feat(FeatureKind3::Edge, f.k.q_feature);
      break;
    }
  }
  r.witness_p = r.witness_q = c.pl.Rp * contact + c.pl.tp_world;
  r.piece_p = static_cast<int>(sk.i), r.piece_q = static_cast<int>(sk.j);
  r.candidates = c.planes.size() + lines;
  return r;
}

}  // namespace pendepth::mesh3
