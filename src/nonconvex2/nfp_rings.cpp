// The per-pair no-fit polygon, export (issue 5 item 4): the exact pieces of ∂O (nfp_build.cpp)
// linked into the rings of cl(O), its slits and its isolated points.
//
// Contract: for N.pieces, fills N.polys (outer rings CCW, then their holes CW), N.slits and
// N.points; every coordinate is the exact vertex rounded to nearest (ties: the neighbour nearer
// zero). Throws std::logic_error on pieces that do not close into rings (internal inconsistency).
//
// Two convex shapes (nfp_export_convex): the pieces are whole candidates, edges of the convex sum;
// sorted by the exact angle of their direction (an input edge vector) and grouped by equal angle,
// they give the ring directly (one vertex per group, its lowest start along the direction), in
// O(N log N) angle comparisons (a rounded −cot key per exact direction, monotone; exact signs only
// on equal keys), started where the general linking below would start it (the lowest line in its
// order: rounded slopes of exact directions, monotone too; the exact line order only on equal
// roundings), so the output is the same. Otherwise:
// Every piece end is an exact point: a sum vertex (P vertex + −Q vertex) or o + μ·dir on the
// piece's ray with μ = num/den the crossing with a cut line (pair_sums.hpp: num, den of degree 2
// in the input doubles, so a coordinate is a degree-3 polynomial over a degree-2 one).
// 1. Each end is rounded to nearest first: a sum vertex by TwoSum; a coordinate along which the
//    ray or the cut line does not move is a sum of two doubles, also TwoSum; a crossing already
//    rounded for another end (the end of one piece and the start of the next are each cut by the
//    other's line: symbolic same_line both ways, or one way and same_point) takes that rounding
//    (rounding is a function of the exact point); on integer input, when FlX certifies num and
//    den (and so the coordinate's numerator) as exact doubles (small integers, |x| < 2^31: the same
//    polynomials in 128-bit integers), the IEEE quotient (never an exact tie: see round_coord); any
//    other by walking
//    from the builder's few-ulp value d (only a starting guess: a bad one costs steps, never the
//    result) until x lies strictly between the midpoints to d's two neighbours. Each midpoint test
//    is the sign of num − m·den from double-doubles of num and den stored per end (certified
//    bound; exact_sign when it cannot decide), never x against d itself, whose frequent exact
//    zero floating point cannot certify. Rounding is monotone, so equal exact points have equal
//    roundings: ends are interned by their rounded coordinates (a hash table, ±0 one key), and ends
//    with equal roundings are the same vertex iff the same sum vertex, equal TwoSum pairs (two sum
//    vertices), num = x·den on exact doubles (a sum vertex against an FlX-exact crossing),
//    symbolically the same (edge_cut.hpp same_point) or exactly equal coordinates.
// 2. Pieces of positive length are grouped by their exact supporting line, ordered by (vertical,
//    slope, offset): interval filters, then exact signs on exact doubles where the ray's direction
//    and origin are exact differences (FMA: equal products compare their rounding errors), else
//    degree-2 signs on the rays (symbolic same_line first); on each line
//    the pieces oriented one way (O on their left) and the other way are cut at every piece end
//    and every other vertex on the line inside its extent (rounded box, then an exact on-line
//    test, symbolic first), giving elementary segments ordered by rounded, then exact, position.
//    Covered both ways: a slit. Covered one way: a boundary edge of cl(O) with O on its left.
// Linked path (export_linked), tried before step 2: when every vertex starts exactly one piece of
//    positive length and ends exactly one (a piece with the same two ends, the same way, as an
//    earlier one is skipped: step 2 covers that segment once), no vertex lies on a piece's line
//    inside its box but its ends, and no chain turns back along its own line, step 2 would make
//    every piece one edge and step 3 would have one choice at each vertex: the rings are the
//    cycles of "the piece leaving this one's end", each started at its first edge in step 2's
//    order (line, then position along it) found by a scan, rings in the order of those edges;
//    collinear consecutive pieces drop their shared vertex (step 3's pass-through). O(N) line
//    comparisons instead of the sort. Otherwise (overlapping collinear pieces with different ends,
//    pinch vertices, slits, a vertex on a piece) nothing is decided and steps 2–3 run (the share
//    of pairs taking it: docs/benchmarks.md).
// 3. Edges are linked end to start by vertex id. Where several edges leave one vertex (two parts
//    of O touching at a point), the incoming edge continues with the sharpest left turn (exact
//    signs on the ray directions), so each ring bounds one side of the touching point. Collinear
//    pass-through vertices are dropped. Rings with O on their left: positive area = outer ring
//    (CCW), negative = hole (CW); each hole goes to the smallest outer ring containing one of its
//    vertices.
// 4. Zero-length pieces that are no vertex of any edge or slit are isolated points of ℝ² \ O
//    (sorted by exact x, then y).
// What stays rational (GMP), only when the floating tiers cannot decide: exact_sign's last tier
// (ties of non-symbolic predicates: equal points or lines not provably equal symbolically),
// rounding of ends beyond the walk (overflow, subnormal gaps, a far-off guess), the area sign of a
// ring the floating shoelace cannot decide, and the hole placement (exact areas and crossing
// tests, only when there are holes).
// Cost: O(N log N) exact predicates of degree ≤ 5 for N pieces (floating filters decide almost
// all), O(N·k) box-filtered on-line tests (k vertices in a line's box), O(H·R·n) rational
// point-in-ring tests for H holes, R outer rings; scratch arrays are thread-local and reused (no
// allocation per call but the output). The output is bit for bit that of the previous
// all-rational export (mpq points in a std::map, rational line keys), which
// tests/nonconvex2/test_nfp_export.cpp keeps as the oracle, running the linked and general paths
// each on their own; measured costs: docs/benchmarks.md.
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <unordered_map>

#include "geometry/exact.hpp"
#include "nonconvex2/nfp_impl.hpp"
#include "nonconvex2/nfp_rings.hpp"

namespace pendepth {

namespace {

using nonconvex2::Line;
using nonconvex2::NfpPiece;
using nonconvex2::Param;
using nonconvex2::Ray;

// One piece end: the point at parameter *raw of ray E (whose line is `edge`); `kind` is the
// normalised kind (a cut through a vertex of a symbolic ray is that vertex).
struct End {
  // Every member initialised: the ends live in a reused vector that copies them when it grows,
  // and copying an indeterminate value (a bool read as 190 under UBSan) is undefined.
  const Ray* E = nullptr;
  const Line* edge = nullptr;
  const Param* raw = nullptr;
  Param::Kind kind = Param::Zero;
  bool sum = false;                          // a sum vertex (pid, qid) = sp + sb
  bool r_sum = false;                        // r from TwoSum of a sum vertex (round_sum succeeded)
  std::uint32_t pid = 0, qid = 0;
  Vec2 sp{0, 0}, sb{0, 0};
  double tsx = 0, tex = 0, tsy = 0, tey = 0;  // a sum vertex: its exact coordinates as TwoSum pairs (when r_sum)
  int den_sign = 0;                          // sign of the denominator of μ
  Vec2 r{0, 0};                              // rounded to nearest
  bool have_dd = false;                      // xn, yn, den computed (round_coord)
  signed char fx = 0;                        // numerators and denominator exact in doubles: 1 yes, -1 no, 0 not tried
  double fxn = 0, fyn = 0, fden = 0;         // those exact values when fx = 1
  exact::DD xn, yn, den;                     // not a sum vertex: the coordinates' numerators and denominator
  Param param() const { return kind == Param::Zero || kind == Param::One ? Param{kind, {}, 0} : *raw; }
};

// μ = num / den of end v (generic lift).
template <class L>
auto end_nd(const End& v, L lift) {
  using T = decltype(lift(0.0));
  switch (v.kind) {
    case Param::Zero:
      return std::pair<T, T>{lift(0.0), lift(1.0)};
    case Param::One:
      return std::pair<T, T>{lift(1.0), lift(1.0)};
    case Param::Cut:
      return std::pair<T, T>{nonconvex2::line_num(v.raw->line, *v.E, lift), nonconvex2::line_den(v.raw->line, *v.E, lift)};
    default:
      return nonconvex2::param_nd(*v.raw, *v.E, Vec2(0, 0), lift);
  }
}

// Coordinate `axis` of end v as num / den (generic lift): o + μ·dir.
template <class L>
auto coord_num(const End& v, int axis, L lift) {
  const Ray& E = *v.E;
  auto [n, d] = end_nd(v, lift);
  auto o = lift(E.o1[axis]) + lift(E.o2[axis]);
  auto dv = axis == 0 ? nonconvex2::ray_dx(E, lift) : nonconvex2::ray_dy(E, lift);
  return o * d + n * dv;
}
template <class L>
auto coord_den(const End& v, L lift) {
  return end_nd(v, lift).second;
}

// Exact comparison of coordinate `axis` of two ends: -1, 0, +1.
int compare_coord(const End& a, const End& b, int axis) {
  return a.den_sign * b.den_sign * exact::exact_sign([&](auto L) {
           return coord_num(a, axis, L) * coord_den(b, L) - coord_num(b, axis, L) * coord_den(a, L);
         });
}

struct QP {
  mpq_class x, y;
};

QP exact_point(const End& v) {
  const exact::LiftQ L;
  const mpq_class den = coord_den(v, L).v;
  return {coord_num(v, 0, L).v / den, coord_num(v, 1, L).v / den};
}

// Round to nearest (ties: the neighbour nearer zero). get_d truncates towards zero, so q lies
// between d and its neighbour away from zero; that neighbour wins iff |q| is beyond the midpoint.
double round_q(const mpq_class& q) {
  const double d = q.get_d();
  const int sg = sgn(q);
  if (sg == 0) return d;
  const double c = std::nextafter(d, sg > 0 ? INFINITY : -INFINITY);
  if (!std::isfinite(c)) return d;
  mpq_class mid = mpq_class(d) + mpq_class(c);
  mpq_div_2exp(mid.get_mpq_t(), mid.get_mpq_t(), 1);
  return (sg > 0 ? q > mid : q < mid) ? c : d;
}

// round_q of the exact sum a + b without rationals (TwoSum): fl(a + b) is the nearest double, and
// on an exact tie round_q's choice (the neighbour nearer zero) is taken. False if it overflows.
[[gnu::always_inline]] inline bool round_sum(double a, double b, double& out) {
  const double s = a + b, bb = s - a, e = (a - (s - bb)) + (b - bb);
  if (!std::isfinite(s) || !std::isfinite(e)) return false;
  out = s;
  if (e == 0) return true;
  const double c = std::nextafter(s, e > 0 ? INFINITY : -INFINITY);
  if (std::isfinite(c) && 2 * std::abs(e) == std::abs(c - s) && std::abs(c) < std::abs(s)) out = c;
  return true;
}

// FlX values of an end that is not a sum vertex: its coordinates' numerators and denominator as
// exact doubles when every input double is an integer and FlX certifies them (fx = 1), else
// fx = -1. Computed once per end.
void ensure_fx(End& v) {
  if (v.fx != 0) return;
  v.fx = -1;
  const Ray& E = *v.E;
  auto integer = [](double x) {  // |x| ≥ 2^52 is an integer (or not finite: FlX then fails)
    return !(std::abs(x) < 0x1p52) || x == double(static_cast<std::int64_t>(x));
  };
  auto integral = [&](const Vec2& p) { return integer(p.x()) && integer(p.y()); };
  const Line& c = v.raw->line;
  // Small integers (|x| < 2^31, nesting data): the same polynomials in 128-bit integers, exact
  // (|num| < 2^101), each value then an exact double or not one at all.
  auto small = [](const Vec2& p) {
    return std::abs(p.x()) < 0x1p31 && std::abs(p.y()) < 0x1p31 && p.x() == double(std::int64_t(p.x())) &&
           p.y() == double(std::int64_t(p.y()));
  };
  if (v.kind != Param::Proj && v.kind != Param::Value && small(E.o1) && small(E.o2) && small(E.a1) && small(E.a2) && small(E.b1) &&
      small(E.b2) && (v.kind != Param::Cut || (small(c.c1) && small(c.c2) && small(c.e0) && small(c.e1)))) {
    __extension__ typedef __int128 I;  // GCC and Clang on 64-bit targets
    auto i = [](double x) { return I(std::int64_t(x)); };
    const I ox = i(E.o1.x()) + i(E.o2.x()), oy = i(E.o1.y()) + i(E.o2.y());
    const I dx = i(E.a1.x()) + i(E.a2.x()) - i(E.b1.x()) - i(E.b2.x()), dy = i(E.a1.y()) + i(E.a2.y()) - i(E.b1.y()) - i(E.b2.y());
    I n = v.kind == Param::One ? 1 : 0, d = 1;
    if (v.kind == Param::Cut) {
      const I lx = i(c.c1.x()) + i(c.c2.x()) - ox, ly = i(c.c1.y()) + i(c.c2.y()) - oy;
      const I ex = i(c.e1.x()) - i(c.e0.x()), ey = i(c.e1.y()) - i(c.e0.y());
      n = lx * ey - ly * ex;
      d = dx * ey - dy * ex;
    }
    const I xn = ox * d + n * dx, yn = oy * d + n * dy;
    // v as a double when exact (a 128-bit integer converts to the nearest double; exact iff it
    // converts back to itself).
    auto exact_double = [](I x, double& out) {
      out = double(x);
      return I(out) == x;
    };
    if (d != 0 && exact_double(xn, v.fxn) && exact_double(yn, v.fyn) && exact_double(d, v.fden)) v.fx = 1;
    return;
  }
  if (integral(E.o1) && integral(E.o2) && integral(E.a1) && integral(E.a2) && integral(E.b1) && integral(E.b2) &&
      (v.kind != Param::Cut || (integral(c.c1) && integral(c.c2) && integral(c.e0) && integral(c.e1)))) {
    const exact::LiftFlX X;
    const auto [n, dd] = end_nd(v, X);
    const exact::FlX xn = (X(E.o1.x()) + X(E.o2.x())) * dd + n * nonconvex2::ray_dx(E, X);
    const exact::FlX yn = (X(E.o1.y()) + X(E.o2.y())) * dd + n * nonconvex2::ray_dy(E, X);
    if (xn.exact && yn.exact && dd.exact && dd.v != 0) v.fx = 1, v.fxn = xn.v, v.fyn = yn.v, v.fden = dd.v;
  }
}

// round_q of coordinate `axis` of v without rationals: from the guess d (the builder's few-ulp
// value), step to a neighbour while x lies beyond the midpoint to it; d is the result once x lies
// strictly between the midpoints to both neighbours (on a midpoint: the neighbour nearer zero).
// Each test is one exact sign of x − m (m = d ± half the gap, exact as a double-double).
// Rationals only for overflow, subnormal gaps or a guess more than a few steps off.
double round_coord(End& v, int axis, double d) {
  // A coordinate the ray or the cut line does not move along is a sum of two input doubles (the
  // ray's origin resp. the cut line's anchor): exact ties there are common on axis-parallel edges.
  const Ray& E = *v.E;
  double r;
  if ((axis == 0 ? E.a1.x() + E.a2.x() == E.b1.x() + E.b2.x() && E.a2.x() == 0 && E.b2.x() == 0
                 : E.a1.y() + E.a2.y() == E.b1.y() + E.b2.y() && E.a2.y() == 0 && E.b2.y() == 0) &&
      round_sum(E.o1[axis], E.o2[axis], r))
    return r == 0 ? 0.0 : r;
  if (v.kind == Param::Cut && v.raw->line.e0[axis] == v.raw->line.e1[axis] && round_sum(v.raw->line.c1[axis], v.raw->line.c2[axis], r))
    return r == 0 ? 0.0 : r;
  // Integer-like data (every input double an integer): the numerator and denominator are often
  // exact doubles (FlX certifies it); then the IEEE quotient is the nearest double. It is never an
  // exact tie (where IEEE's even choice could differ from round_q's): a tie is odd·2^k with a 54-bit
  // odd part, and num = x·den would carry that odd part, more than a double holds.
  ensure_fx(v);
  if (v.fx > 0) {
    const double num = axis == 0 ? v.fxn : v.fyn, q = num / v.fden;
    if (num == 0) return 0.0;  // an exact zero is +0 (round_q)
    if (std::isfinite(q) && std::abs(q) >= 0x1p-1022) return q;  // normal: correctly rounded
  }
  // Sign of x − (hi + lo): from the stored double-double numerator and denominator when their
  // bounds decide, else exactly.
  if (!v.have_dd) {  // the double-double numerators and denominator, once per end
    const exact::LiftDD D;
    const auto [n, d] = end_nd(v, D);
    v.den = d;
    v.xn = (D(E.o1.x()) + D(E.o2.x())) * d + n * nonconvex2::ray_dx(E, D);
    v.yn = (D(E.o1.y()) + D(E.o2.y())) * d + n * nonconvex2::ray_dy(E, D);
    v.have_dd = true;
  }
  const exact::DD& num = axis == 0 ? v.xn : v.yn;
  auto side = [&](double hi, double lo) {
    const exact::DD m = exact::DD{hi, 0, 0} + exact::DD{lo, 0, 0};
    const exact::DD f = num - m * v.den;
    if (exact::dd_finite(f)) {
      const double b = exact::safe_bound(f.e);
      if (f.hi > b) return v.den_sign;
      if (f.hi < -b) return -v.den_sign;
    }
    return v.den_sign * exact::exact_sign([&](auto L) { return coord_num(v, axis, L) - (L(hi) + L(lo)) * coord_den(v, L); });
  };
  // x against the midpoints to both neighbours of d (never x against d itself: exact coordinates
  // are common and their zero would not be certified in floating point).
  if (std::isfinite(d) && std::abs(d) < 0x1p1000) {
    for (int step = 0; step < 8; ++step) {
      const double up = std::nextafter(d, INFINITY), dn = std::nextafter(d, -INFINITY);
      const double hu = (up - d) * 0.5, hd = (dn - d) * 0.5;  // exact: neighbours, above subnormals
      if (!std::isfinite(up) || !std::isfinite(dn)) break;
      if (std::abs(hu) < 0x1p-960 || std::abs(hd) < 0x1p-960) {
        // Near zero (symmetric pairs put vertices on the axes): an exact zero is +0 (round_q);
        // anything else this small is rounded from the rational.
        if (exact::exact_sign([&](auto L) { return coord_num(v, axis, L); }) == 0) return 0.0;
        break;
      }
      const int tu = side(d, hu);
      if (tu == 0) return std::abs(up) < std::abs(d) ? up : d;  // a tie: the neighbour nearer zero
      if (tu > 0) {
        d = up;
        continue;
      }
      const int td = side(d, hd);
      if (td == 0) return std::abs(dn) < std::abs(d) ? dn : d;
      if (td < 0) {
        d = dn;
        continue;
      }
      return d;
    }
  }
  const exact::LiftQ Q;
  return round_q(coord_num(v, axis, Q).v / coord_den(v, Q).v);
}

// Signed ray direction: sign · (dx, dy) of E.
struct Dir {
  const Ray* E;
  int s;
};

int cross_sign(const Dir& a, const Dir& b) {
  return a.s * b.s * exact::exact_sign([&](auto L) {
           return nonconvex2::ray_dx(*a.E, L) * nonconvex2::ray_dy(*b.E, L) - nonconvex2::ray_dy(*a.E, L) * nonconvex2::ray_dx(*b.E, L);
         });
}
int dot_sign(const Dir& a, const Dir& b) {
  return a.s * b.s * exact::exact_sign([&](auto L) {
           return nonconvex2::ray_dx(*a.E, L) * nonconvex2::ray_dx(*b.E, L) + nonconvex2::ray_dy(*a.E, L) * nonconvex2::ray_dy(*b.E, L);
         });
}

// The CCW angle from r to w in [0, 2π) is larger for a than for b (exact; a, b, r non-zero).
bool larger_ccw_angle(const Dir& r, const Dir& a, const Dir& b) {
  auto half = [&](const Dir& w) {
    const int c = cross_sign(r, w);
    return (c > 0 || (c == 0 && dot_sign(r, w) > 0)) ? 0 : 1;
  };
  const int ha = half(a), hb = half(b);
  if (ha != hb) return ha > hb;
  return cross_sign(a, b) < 0;  // b before a counter-clockwise
}

mpq_class cross(const QP& a, const QP& b) { return a.x * b.y - a.y * b.x; }
QP sub(const QP& a, const QP& b) { return {a.x - b.x, a.y - b.y}; }

// Exact: p strictly inside the ring of vertex ids into V (crossing number; the caller avoids
// points on the ring).
int point_in_ring(const std::vector<QP>& V, const std::vector<int>& ring, const QP& p) {
  bool in = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const QP &a = V[ring[i]], &b = V[ring[(i + 1) % ring.size()]];
    const mpq_class s = cross(sub(b, a), sub(p, a));
    if (s == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y))
      return 0;  // on the ring
    if ((a.y > p.y) != (b.y > p.y)) {
      // Crossing of the horizontal ray to +x: x at height p.y greater than p.x.
      if ((s > 0) == (b.y > a.y)) in = !in;
    }
  }
  return in ? 1 : -1;
}

mpq_class ring_area2(const std::vector<QP>& V, const std::vector<int>& ring) {
  mpq_class a = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) a += cross(V[ring[i]], V[ring[(i + 1) % ring.size()]]);
  return a;
}

// Exact sign of a·b − c·d for doubles, 2 when undecided (a product overflows, or the products are
// equal and one may have lost its rounding error below the normal range). Rounding is monotone, so
// fl(a·b) > fl(c·d) implies a·b > c·d; on equal products the FMA rounding errors decide exactly.
int sign_det(double a, double b, double c, double d) {
  const double p = a * b, q = c * d;
  if (!std::isfinite(p) || !std::isfinite(q)) return 2;
  if (p != q) return p > q ? 1 : -1;
  auto err = [](double x, double y, double r, double& e) {
    if (x == 0 || y == 0) return e = 0, true;
    if (std::abs(r) <= 0x1p-960) return false;
    return e = std::fma(x, y, -r), true;
  };
  double ep, eq;
  if (!err(a, b, p, ep) || !err(c, d, q, eq)) return 2;
  return (ep > eq) - (ep < eq);
}

// x − y exactly as a double, or false.
[[gnu::always_inline]] inline bool exact_diff(double x, double y, double& out) {
  double e;
  exact::two_sum(x, -y, out, e);
  return e == 0 && std::isfinite(out);
}

// A piece of positive length: its ends (vertex ids), its ray and line, and the sign of its
// direction along u (x, or y on a vertical line).
struct Seg {
  Seg() {}  // no zeroing: make_seg sets every member (segs.emplace_back() would value-initialise)
  int a, b;
  const Ray* E;
  const Line* edge;
  bool vertical;
  int sdx;  // exact sign of E's dx (0 iff vertical)
  int su;   // sign of E's direction along u
  exact::Fl dx, dy, ox, oy;  // E's direction and origin with error bounds (filters)
  bool horizontal;           // dy exactly 0
  double s_lo, s_hi;         // interval of the exact slope (not vertical)
  double k_lo, k_hi;         // interval of the exact offset (vertical: x; horizontal: y)
  // Exact doubles when available (integer-like data, nearby coordinates): the direction (ex, ey)
  // when `dexact`, the origin (oxe, oye) when `oexact`; then line comparisons need no lifting.
  bool dexact, oexact;
  double ex, ey, oxe, oye;
};

// Fills s: the Seg of piece pc between vertex ids ia, ib, with its filters.
void make_seg(Seg& s, const NfpPiece& pc, int ia, int ib) {
  const Ray& E = pc.E;
  const exact::LiftFl F;
  s.a = ia, s.b = ib, s.E = &E, s.edge = &pc.edge;
  s.ex = s.ey = s.oxe = s.oye = 0;  // set below only when exact
  s.dexact = E.a2.x() == 0 && E.a2.y() == 0 && E.b2.x() == 0 && E.b2.y() == 0 && exact_diff(E.a1.x(), E.b1.x(), s.ex) &&
             exact_diff(E.a1.y(), E.b1.y(), s.ey);
  s.oexact = exact_diff(E.o1.x(), -E.o2.x(), s.oxe) && exact_diff(E.o1.y(), -E.o2.y(), s.oye);
  if (s.dexact) {
    s.dx = {s.ex, 0};
    s.dy = {s.ey, 0};
    s.sdx = (s.ex > 0) - (s.ex < 0);
  } else {
    s.dx = nonconvex2::ray_dx(E, F);
    s.dy = nonconvex2::ray_dy(E, F);
    s.sdx = exact::certified_sign(s.dx);
    if (s.sdx == 2) s.sdx = exact::exact_sign([&](auto L) { return nonconvex2::ray_dx(E, L); });
  }
  s.ox = s.oexact ? exact::Fl{s.oxe, 0} : F(E.o1.x()) + F(E.o2.x());
  s.oy = s.oexact ? exact::Fl{s.oye, 0} : F(E.o1.y()) + F(E.o2.y());
  s.vertical = s.sdx == 0;
  s.su = s.sdx;
  int sdy;
  if (s.dexact) sdy = (s.ey > 0) - (s.ey < 0);
  else {
    sdy = exact::certified_sign(s.dy);
    if (sdy == 2) sdy = exact::exact_sign([&](auto L) { return nonconvex2::ray_dy(E, L); });
  }
  if (s.vertical) s.su = sdy;
  s.horizontal = sdy == 0;
  // Intervals for line_less: the slope dy/dx from the bounded dx, dy (plus the division's
  // rounding), the offset of an axis-parallel line from the bounded origin coordinate.
  s.s_lo = -INFINITY, s.s_hi = INFINITY;
  const double ex = exact::safe_bound(s.dx.e), ey = exact::safe_bound(s.dy.e);
  if (s.horizontal) s.s_lo = s.s_hi = 0;
  else if (!s.vertical && std::abs(s.dx.v) > 2 * ex) {
    const double q = s.dy.v / s.dx.v, aq = std::abs(q);
    const double e = (ey + aq * (1 + 0x1p-50) * ex) / (std::abs(s.dx.v) - ex) * (1 + 0x1p-40) + aq * 0x1p-51 + 0x1p-1000;
    if (std::isfinite(q) && std::isfinite(e)) s.s_lo = q - e, s.s_hi = q + e;
  }
  const exact::Fl& off = s.vertical ? s.ox : s.oy;
  const double eo = 2 * exact::safe_bound(off.e);  // twice: covers the rounding of v ± bound
  s.k_lo = off.v - eo, s.k_hi = off.v + eo;
}

// Exact order of supporting lines: (vertical, slope, offset) with y = slope·x + offset, or x =
// offset when vertical; a line through E's origin o = o1 + o2 with direction dir.
int compare_lines(const Seg& s, const Seg& t) {
  if (nonconvex2::same_line(*s.edge, *t.edge)) return 0;
  if (s.vertical != t.vertical) return s.vertical ? 1 : -1;
  const Ray &A = *s.E, &B = *t.E;
  using nonconvex2::ray_dx, nonconvex2::ray_dy;
  // Each sign: exact doubles first, then the stored floating values with their bounds, exact
  // (lifted) when undecided.
  if (s.vertical) {
    if (s.oexact && t.oexact) return (s.oxe > t.oxe) - (s.oxe < t.oxe);
    const int c = exact::certified_sign(s.ox - t.ox);
    return c != 2 ? c : exact::exact_sign([&](auto L) { return L(A.o1.x()) + L(A.o2.x()) - L(B.o1.x()) - L(B.o2.x()); });
  }
  // slope_s − slope_t = (dy_s·dx_t − dy_t·dx_s) / (dx_s·dx_t)
  int c = s.dexact && t.dexact ? sign_det(s.ey, t.ex, t.ey, s.ex) : 2;
  if (c == 2) c = exact::certified_sign(s.dy * t.dx - t.dy * s.dx);
  if (c == 2) c = exact::exact_sign([&](auto L) { return ray_dy(A, L) * ray_dx(B, L) - ray_dy(B, L) * ray_dx(A, L); });
  if (c != 0) return s.sdx * t.sdx * c;
  // Equal slopes: offset_s − offset_t = ((oy_s − oy_t)·dx_s − dy_s·(ox_s − ox_t)) / dx_s
  c = 2;
  if (double wx, wy; s.dexact && s.oexact && t.oexact && exact_diff(s.oxe, t.oxe, wx) && exact_diff(s.oye, t.oye, wy))
    c = sign_det(wy, s.ex, s.ey, wx);
  if (c == 2) c = exact::certified_sign((s.oy - t.oy) * s.dx - s.dy * (s.ox - t.ox));
  if (c == 2) {
    // A shared origin term (the same P vertex or the same −Q vertex) cancels exactly.
    const bool same1 = A.o1 == B.o1, same2 = A.o2 == B.o2;
    c = exact::exact_sign([&](auto L) {
      auto ox = same1 ? L(A.o2.x()) - L(B.o2.x()) : same2 ? L(A.o1.x()) - L(B.o1.x()) : L(A.o1.x()) + L(A.o2.x()) - L(B.o1.x()) - L(B.o2.x());
      auto oy = same1 ? L(A.o2.y()) - L(B.o2.y()) : same2 ? L(A.o1.y()) - L(B.o1.y()) : L(A.o1.y()) + L(A.o2.y()) - L(B.o1.y()) - L(B.o2.y());
      return oy * ray_dx(A, L) - ray_dy(A, L) * ox;
    });
  }
  return s.sdx * c;
}

// compare_lines with interval filters: slopes, and offsets of vertical or horizontal lines,
// decided by disjoint intervals of their exact values; exact otherwise.
int compare_lines_filtered(const Seg& s, const Seg& t) {
  if (s.vertical != t.vertical) return s.vertical ? 1 : -1;
  if (!s.vertical) {
    if (s.s_hi < t.s_lo) return -1;
    if (t.s_hi < s.s_lo) return 1;
  }
  if (s.vertical || (s.horizontal && t.horizontal)) {  // equal slopes: the offsets decide
    if (s.k_hi < t.k_lo) return -1;
    if (t.k_hi < s.k_lo) return 1;
  }
  return compare_lines(s, t);
}

// Exact: end v lies on the line of s (symbolically when its own line, its cut line or its sum
// vertex is s's, else the degree-4 sign of cross(dir, v − o)).
bool on_line(const End& v, const Seg& s) {
  const Line& l = *s.edge;
  if (nonconvex2::same_line(*v.edge, l)) return true;
  if (v.kind == Param::Cut && nonconvex2::same_line(v.raw->line, l)) return true;
  if (v.sum && ((l.p0 == v.pid && l.q0 == v.qid) || (l.p1 == v.pid && l.q1 == v.qid))) return true;
  const Ray& R = *s.E;
  return exact::exact_sign([&](auto L) {
           auto d = coord_den(v, L);
           auto x = coord_num(v, 0, L) - (L(R.o1.x()) + L(R.o2.x())) * d;
           auto y = coord_num(v, 1, L) - (L(R.o1.y()) + L(R.o2.y())) * d;
           return nonconvex2::ray_dx(R, L) * y - nonconvex2::ray_dy(R, L) * x;
         }) == 0;
}

// The sum vertex at end j (0: μ = 0, 1: μ = 1) of a candidate ray, as P vertex + −Q vertex.
struct SumPoint {
  Vec2 p, b;
  std::uint32_t pid, qid;
};
SumPoint sum_end(const Ray& E, int j) {
  if (j == 0) return {E.o1, E.o2, E.p0, E.q0};
  return {E.p0 == E.p1 ? E.o1 : E.a1, E.q0 == E.q1 ? E.o2 : E.a1, E.p1, E.q1};
}
// Exact sign of dot(dir E, x − y).
int along_sign(const Ray& E, const SumPoint& x, const SumPoint& y) {
  if (x.pid == y.pid && x.qid == y.qid) return 0;
  return exact::exact_sign([&](auto L) {
    auto dx = L(E.a1.x()) - L(E.b1.x()), dy = L(E.a1.y()) - L(E.b1.y());
    return dx * (L(x.p.x()) + L(x.b.x()) - L(y.p.x()) - L(y.b.x())) + dy * (L(x.p.y()) + L(x.b.y()) - L(y.p.y()) - L(y.b.y()));
  });
}

}  // namespace

bool nfp_export_convex(NoFitPolygon2::Impl& N) {
  const std::size_t np = N.pieces.size();
  if (np < 2) return false;
  auto whole = [](const NfpPiece& pc) {
    auto kind = [&](const Param& p) {
      if (p.kind != Param::Cut) return p.kind;
      const int k = nonconvex2::known_lambda(p.line, pc.E);
      return k == 0 ? Param::Zero : k == 1 ? Param::One : Param::Cut;
    };
    return pc.E.sym && kind(pc.lo) == Param::Zero && kind(pc.hi) == Param::One;
  };
  for (const NfpPiece& pc : N.pieces)
    if (!whole(pc)) return false;
  // The pieces by the angle of their direction (an input edge vector a1 − b1), exactly.
  thread_local std::vector<int> order;  // reused buffers (no allocation per call)
  order.resize(np);
  for (std::size_t k = 0; k < np; ++k) order[k] = int(k);
  // Per piece: the half-plane of its direction and the direction as exact doubles when the
  // differences are exact; compare_angle (the same order) only where those cannot decide.
  // Exact directions also get a key increasing with the angle inside their half-plane, −x/y
  // rounded (−cot: a correctly rounded quotient is monotone, so different keys are a strict order
  // and only equal keys need the exact comparison), −∞ on the half's first ray (y = 0).
  struct AngleKey {
    int half;
    bool exact;
    double x, y, key;
  };
  thread_local std::vector<AngleKey> ak;
  ak.resize(np);
  for (std::size_t k = 0; k < np; ++k) {
    const Ray& E = N.pieces[k].E;
    ak[k].half = (E.a1.y() < E.b1.y() || (E.a1.y() == E.b1.y() && E.a1.x() < E.b1.x())) ? 1 : 0;
    ak[k].exact = exact_diff(E.a1.x(), E.b1.x(), ak[k].x) && exact_diff(E.a1.y(), E.b1.y(), ak[k].y);
    ak[k].key = ak[k].y == 0 ? -INFINITY : -ak[k].x / ak[k].y;
  }
  auto angle = [&](int a, int b) {
    if (ak[a].half != ak[b].half) return ak[a].half < ak[b].half ? -1 : 1;
    if (ak[a].exact && ak[b].exact) {
      if (ak[a].key != ak[b].key) return ak[a].key < ak[b].key ? -1 : 1;
      if (const int c = sign_det(ak[a].x, ak[b].y, ak[a].y, ak[b].x); c != 2) return -c;
    }
    const Ray &A = N.pieces[a].E, &B = N.pieces[b].E;
    return predicates::compare_angle(A.b1, A.a1, B.b1, B.a1);
  };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return angle(a, b) < 0; });
  // One group per direction: an edge of the convex sum from its lowest start to its highest end.
  struct Group {
    std::size_t b, e;  // order[b, e)
    SumPoint lo, hi;
  };
  thread_local std::vector<Group> groups;
  groups.clear();
  for (std::size_t b = 0, e; b < np; b = e) {
    e = b + 1;
    while (e < np && angle(order[b], order[e]) == 0) ++e;
    const Ray& E = N.pieces[order[b]].E;
    Group g{b, e, sum_end(E, 0), sum_end(E, 1)};
    for (std::size_t i = b + 1; i < e; ++i) {
      const Ray& F = N.pieces[order[i]].E;
      if (const SumPoint s = sum_end(F, 0); along_sign(E, s, g.lo) < 0) g.lo = s;
      if (const SumPoint t = sum_end(F, 1); along_sign(E, t, g.hi) > 0) g.hi = t;
    }
    groups.push_back(g);
  }
  const std::size_t ng = groups.size();
  if (ng < 3) return false;
  // Consecutive edges meet (a closed convex ring); anything else goes to the general export.
  for (std::size_t k = 0; k < ng; ++k) {
    const SumPoint &x = groups[k].hi, &y = groups[(k + 1) % ng].lo;
    if (x.pid == y.pid && x.qid == y.qid) continue;
    for (int axis = 0; axis < 2; ++axis)
      if (exact::exact_sign([&](auto L) { return L(x.p[axis]) + L(x.b[axis]) - L(y.p[axis]) - L(y.b[axis]); }) != 0) return false;
  }
  // The general export starts its ring on the lowest line in (vertical last, slope, offset) order,
  // at that edge's first elementary segment in increasing u (x, or y when vertical): the edge's
  // start when it runs towards increasing u or has no vertex inside, else its end.
  std::size_t first = 0;
  thread_local std::vector<Seg> segs;  // segs[k]: group k's line, made only where needed
  segs.clear();  // (a Seg is not initialised until made: never copied by a reallocation)
  segs.resize(ng);
  thread_local std::vector<char> made;
  made.assign(ng, 0);
  auto seg = [&](std::size_t k) -> const Seg& {
    if (!made[k]) make_seg(segs[k], N.pieces[order[groups[k].b]], 0, 0), made[k] = 1;
    return segs[k];
  };
  // Directions (a1 − b1) as exact doubles (x, y): the rounded slope fl(y / x) is monotone in the exact slope
  // (a correctly rounded quotient), so a smaller rounded slope is a smaller slope and only equal
  // roundings (parallel edges, or nearly so) need the exact line order; vertical lines come last
  // and, the ring having ≥ 3 directions, one line is not vertical.
  bool by_slope = true;
  for (const Group& g : groups) {
    const Ray& E = N.pieces[order[g.b]].E;
    by_slope = by_slope && ak[order[g.b]].exact && E.a2 == Vec2(0, 0) && E.b2 == Vec2(0, 0);
  }
  double qmin = INFINITY;
  std::size_t ties = 0;
  if (by_slope) {
    for (std::size_t k = 0; k < ng; ++k) {
      const AngleKey& a = ak[order[groups[k].b]];
      if (a.x == 0) continue;
      const double q = a.y / a.x;
      if (ties == 0 || q < qmin) qmin = q, first = k, ties = 1;
      else if (q == qmin) ++ties;
    }
    if (ties > 1) {  // the exact order among the lines of the smallest rounded slope
      const std::size_t f0 = first;
      for (std::size_t k = f0 + 1; k < ng; ++k) {
        const AngleKey& a = ak[order[groups[k].b]];
        if (a.x != 0 && a.y / a.x == qmin && compare_lines_filtered(seg(k), seg(first)) < 0) first = k;
      }
    }
  }
  if (ties == 0) {  // not by slope (or, defensively, no line that is not vertical)
    first = 0;
    for (std::size_t k = 1; k < ng; ++k)
      if (compare_lines_filtered(seg(k), seg(first)) < 0) first = k;
  }
  if (seg(first).su < 0) {
    const Group& g = groups[first];
    const Ray& E = N.pieces[order[g.b]].E;
    bool inside = false;
    for (std::size_t i = g.b; i < g.e && !inside; ++i)
      for (int j = 0; j < 2 && !inside; ++j) {
        const SumPoint x = sum_end(N.pieces[order[i]].E, j);
        inside = along_sign(E, x, g.lo) > 0 && along_sign(E, x, g.hi) < 0;
      }
    if (inside) first = (first + 1) % ng;
  }
  std::vector<Vec2> ring(ng);
  for (std::size_t k = 0; k < ng; ++k) {
    const SumPoint& v = groups[(first + k) % ng].lo;
    if (!round_sum(v.p.x(), v.b.x(), ring[k].x()) || !round_sum(v.p.y(), v.b.y(), ring[k].y())) return false;
  }
  N.polys.assign(1, {std::move(ring)});
  N.slits.clear();
  N.points.clear();
  return true;
}

namespace {

// Reused buffers of the general export (one per thread): its scratch arrays are sized by the
// pieces, so after the first pairs no call allocates except for its output.
struct Workspace {
  std::vector<End> ends;
  std::vector<int> id, rep, order, zero_points, stamp, pos, us, first, out, fill, ring_verts, ring_start;
  std::unordered_multimap<std::uint64_t, int> cut_buckets;  // round_ends: rounded crossing ends by coarse position
  std::vector<Vec2> rv;
  std::vector<char> fixed, is_vertex, used;
  std::vector<Seg> segs;
  struct Edge {
    int a, b;
    std::size_t line;  // the group of its exact supporting line
    bool fwd;          // along increasing u of that line
  };
  struct Iv {
    int lo, hi;  // vertex ids (lower and higher u)
    bool fwd;
  };
  std::vector<Edge> edges;
  std::vector<Iv> ivs;
  std::vector<std::array<int, 2>> cover;  // cut_lines: interval coverage differences per direction
  std::vector<std::array<int, 2>> slits;
  std::vector<std::size_t> chain, outer, holes, owner;
  std::vector<int> table, ghead, vnext;  // interning: hash table of rounding groups, vertex lists
  std::vector<Vec2> gkey;
  struct VX {
    double x, y;  // the vertex's rounding
    int v;
  };
  std::vector<VX> verts;
  // The linked path: per vertex the piece leaving it and whether one enters; per ring its first
  // piece and its chain in ring_chain[ring_at[k], ring_at[k + 1]).
  std::vector<int> next_seg, ring_chain, ring_at, ring_first, ring_rank;
  std::vector<char> has_in, dup, through;
};

thread_local NfpExportPath last_path = NfpExportPath::General;

// The linked path: when every vertex (of a piece of positive length) starts exactly one piece and
// ends exactly one, no vertex lies on a piece's line inside its box other than its own ends, and no
// two consecutive pieces of a chain run back along one line, the general path's elementary
// segments are the pieces themselves and its linking has one choice at every vertex: the rings are
// the cycles of "the piece leaving the end of this one". The general path takes its rings in the
// order of their first edge (by line, then by position along it) and starts each at that edge;
// here the same first edge is found by a scan of each cycle (O(N) line comparisons instead of the
// O(N log N) sort). Collinear consecutive pieces (the same exact line, same direction) drop their
// shared vertex, as the general path's pass-through. False, nothing decided, when the pieces are
// not of this form (then the general path runs).
bool export_linked(Workspace& W, const std::vector<End>& ends, const std::vector<Vec2>& rv, int nv) {
  const std::vector<Seg>& segs = W.segs;
  const std::size_t ns = segs.size();
  if (ns < 3) return false;
  std::vector<int>& next = W.next_seg;
  next.assign(nv, -1);
  std::vector<char>& has_in = W.has_in;
  has_in.assign(nv, 0);
  // A piece with the same ends as an earlier one, the same way (coinciding candidates of different
  // edge pairs): the general path covers that segment once, one edge; it is skipped here.
  std::vector<char>& dup = W.dup;
  dup.assign(ns, 0);
  for (std::size_t i = 0; i < ns; ++i) {
    const Seg& s = segs[i];
    if (next[s.a] >= 0 && segs[std::size_t(next[s.a])].b == s.b) {
      dup[i] = 1;
      continue;
    }
    if (next[s.a] >= 0 || has_in[s.b]) return false;
    next[s.a] = int(i);
    has_in[s.b] = 1;
  }
  for (int v = 0; v < nv; ++v)
    if ((next[v] >= 0) != (has_in[v] != 0)) return false;
  // No vertex splits a piece (the general path would cut it there, and mark that vertex).
  const std::vector<Workspace::VX>& verts = W.verts;
  for (std::size_t i = 0; i < ns; ++i) {
    if (dup[i]) continue;
    const Seg& s = segs[i];
    const Vec2 lo = rv[s.a].cwiseMin(rv[s.b]), hi = rv[s.a].cwiseMax(rv[s.b]);
    auto it = std::lower_bound(verts.begin(), verts.end(), lo.x(), [](const Workspace::VX& a, double x) { return a.x < x; });
    for (; it != verts.end() && it->x <= hi.x(); ++it) {
      if (it->y < lo.y() || it->y > hi.y() || it->v == s.a || it->v == s.b) continue;
      if (on_line(ends[W.rep[it->v]], s)) return false;
    }
  }
  // The general path's edge order: line order, then along the line by the lower end (pieces on
  // one line are disjoint but for shared ends here). 0 only for one piece (or an inconsistency).
  auto edge_order = [&](int x, int y) {
    if (x == y) return 0;
    const Seg &s = segs[x], &t = segs[y];
    if (const int c = compare_lines_filtered(s, t); c != 0) return c;
    const int axis = s.vertical ? 1 : 0;
    const int p = s.su > 0 ? s.a : s.b, q = t.su > 0 ? t.a : t.b;
    if (rv[p][axis] != rv[q][axis]) return rv[p][axis] < rv[q][axis] ? -1 : 1;
    return p == q ? 0 : compare_coord(ends[W.rep[p]], ends[W.rep[q]], axis);
  };
  std::vector<char>& used = W.used;
  used.assign(ns, 0);
  std::vector<int>&chain = W.ring_chain, &at = W.ring_at, &first = W.ring_first;
  std::vector<char>& through = W.through;  // through[i]: the piece before chain[i] is on its line
  chain.clear();
  through.clear();
  at.assign(1, 0);
  first.clear();
  for (std::size_t i0 = 0; i0 < ns; ++i0) {
    if (used[i0] || dup[i0]) continue;
    const std::size_t c0 = chain.size();
    for (int i = int(i0); !used[i]; i = next[segs[i].b]) {
      used[i] = 1;
      chain.push_back(i);
    }
    const std::size_t m = chain.size() - c0;
    if (m < 3) return false;  // two pieces between the same two vertices: a slit
    std::size_t best = c0;
    for (std::size_t k = c0; k < chain.size(); ++k) {
      const Seg &in = segs[chain[k == c0 ? chain.size() - 1 : k - 1]], &o = segs[chain[k]];
      const int c = compare_lines_filtered(in, o);
      if (c == 0 && in.su != o.su) return false;  // back along the same line: overlapping pieces
      through.push_back(c == 0);
      if (k > c0) {
        const int b = edge_order(chain[k], chain[best]);
        if (b == 0) return false;
        if (b < 0) best = k;
      }
    }
    std::rotate(chain.begin() + c0, chain.begin() + best, chain.end());
    std::rotate(through.begin() + c0, through.begin() + best, through.end());
    first.push_back(chain[c0]);
    at.push_back(int(chain.size()));
  }
  // Rings in the order of their first edges (few rings: insertion sort).
  const std::size_t nr = first.size();
  std::vector<int>& rank = W.ring_rank;
  rank.resize(nr);
  for (std::size_t k = 0; k < nr; ++k) {
    std::size_t j = k;
    for (; j > 0; --j) {
      const int b = edge_order(first[k], first[rank[j - 1]]);
      if (b == 0) return false;
      if (b > 0) break;
      rank[j] = rank[j - 1];
    }
    rank[j] = int(k);
  }
  std::vector<int>&ring_verts = W.ring_verts, &ring_start = W.ring_start;
  for (std::size_t r = 0; r < nr; ++r) {
    const std::size_t k = std::size_t(rank[r]), r0 = ring_verts.size();
    for (int i = at[k]; i < at[k + 1]; ++i)
      if (!through[std::size_t(i)]) ring_verts.push_back(segs[chain[std::size_t(i)]].a);
    if (ring_verts.size() - r0 >= 3) ring_start.push_back(int(ring_verts.size()));
    else ring_verts.resize(r0);
  }
  for (const Seg& s : segs) W.is_vertex[s.a] = W.is_vertex[s.b] = 1;
  return true;
}

// ---- the steps of the general export (nfp_export_by), in their order --------------------------

// Step 1: fills W.ends (ends[2k], ends[2k + 1]: piece k's lo and hi), each rounded to nearest.
void round_ends(Workspace& W, const NoFitPolygon2::Impl& N) {
  const std::size_t np = N.pieces.size();
  std::vector<End>& ends = W.ends;
  ends.resize(2 * np);
  // Rounded crossing ends, for reuse, by a coarse key of their position (the rounding with the
  // last 12 mantissa bits cleared): a crossing's guess is within a few ulps of its rounding, so
  // the earlier end of the same crossing is nearly always in the guess's bucket. One it misses
  // costs a rounding (the same value); a scan of every earlier cut was quadratic in the pieces.
  auto& cuts = W.cut_buckets;
  cuts.clear();
  auto key = [](const Vec2& p) {
    std::uint64_t h = 0;
    for (int a = 0; a < 2; ++a) {
      const double x = p[a] + 0.0;  // −0 and +0 one key
      std::uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      h = h * 0x9e3779b97f4a7c15ull ^ (b & ~std::uint64_t(0xfff));
    }
    return h;
  };
  for (std::size_t k = 0; k < np; ++k) {
    const NfpPiece& pc = N.pieces[k];
    for (int j = 0; j < 2; ++j) {
      End& v = ends[2 * k + j];
      v.E = &pc.E;
      v.edge = &pc.edge;
      v.raw = j == 0 ? &pc.lo : &pc.hi;
      v.kind = v.raw->kind;
      if (v.kind == Param::Cut)
        if (const int k = nonconvex2::known_lambda(v.raw->line, pc.E); k >= 0) v.kind = k == 0 ? Param::Zero : Param::One;
      v.sum = pc.E.sym && v.kind != Param::Cut;
      v.r_sum = false;
      if (v.sum) {
        const int e = v.kind == Param::Zero ? 0 : 1;
        const Ray& E = pc.E;
        v.pid = e == 0 ? E.p0 : E.p1;
        v.qid = e == 0 ? E.q0 : E.q1;
        v.sp = e == 0 || E.p0 == E.p1 ? E.o1 : E.a1;
        v.sb = e == 0 || E.q0 == E.q1 ? E.o2 : E.a1;
        v.den_sign = 1;
        v.r_sum = round_sum(v.sp.x(), v.sb.x(), v.r.x()) && round_sum(v.sp.y(), v.sb.y(), v.r.y());
        exact::two_sum(v.sp.x(), v.sb.x(), v.tsx, v.tex);
        exact::two_sum(v.sp.y(), v.sb.y(), v.tsy, v.tey);
        if (!v.r_sum) v.r = Vec2(round_q(mpq_class(v.sp.x()) + v.sb.x()), round_q(mpq_class(v.sp.y()) + v.sb.y()));
        continue;
      }
      v.pid = v.qid = 0;
      v.have_dd = false;
      v.fx = 0;
      // The sign of μ's denominator (Proj: a squared length, positive); only the denominator lifted.
      v.den_sign = v.kind == Param::Cut ? exact::exact_sign([&](auto L) { return nonconvex2::line_den(v.raw->line, pc.E, L); }) : 1;
      // The crossing of the same two lines was rounded already (the end of one piece and the start
      // of the next): rounding is a function of the exact point, so its rounding is this one's.
      bool reused = false;
      const Vec2& guess = j == 0 ? pc.a : pc.b;
      if (v.kind == Param::Cut) {
        const auto [from, to] = cuts.equal_range(key(guess));
        for (auto it = from; it != to; ++it) {
          const int c = it->second;
          const End& u = ends[c];
          const bool uv = nonconvex2::same_line(u.raw->line, *v.edge), vu = nonconvex2::same_line(v.raw->line, *u.edge);
          // Each cut by the other's line: the same crossing symbolically; one way only: same_point
          // decides (the other line collinear, exactly).
          if ((uv && vu) ||
              ((uv || vu) && nonconvex2::same_point(nonconvex2::Cand{*u.E, u.param(), *u.edge}, nonconvex2::Cand{*v.E, v.param(), *v.edge}))) {
            v.r = u.r;
            reused = true;
            break;
          }
        }
      }
      if (reused) continue;
      v.r = Vec2(round_coord(v, 0, guess.x()), round_coord(v, 1, guess.y()));
      if (v.kind == Param::Cut) cuts.emplace(key(v.r), int(2 * k + j));
    }
  }
}

// Step 1 (interning): vertex ids of the ends (W.id), one representative end per vertex (W.rep) and
// its exported rounding (W.rv); ends with equal roundings are one vertex iff the same exact point.
// Returns the number of vertices.
int intern_ends(Workspace& W) {
  std::vector<End>& ends = W.ends;
  std::vector<int>& id = W.id;
  id.assign(ends.size(), -1);
  int nv = 0;
  std::vector<int>& rep = W.rep;  // rep[vertex id] = one of its ends
  rep.clear();
  std::vector<Vec2>& rv = W.rv;  // rv[vertex id]: its rounding (below)
  rv.clear();
  std::vector<char>& fixed = W.fixed;  // rv from a TwoSum rounding of a sum vertex
  fixed.clear();
  // A sum vertex that is an exact double pair against a crossing with FlX-exact numerators and
  // denominator (integer data): equal iff num = x·den for both coordinates, each product exact
  // or not a double at all (then not num). 1 equal, 0 not, -1 undecided.
  auto sum_vs_cut = [&](const End& sv, End& c) {
    if (!sv.sum || !sv.r_sum || sv.tex != 0 || sv.tey != 0 || c.sum || c.kind != Param::Cut) return -1;
    ensure_fx(c);
    if (c.fx <= 0) return -1;
    int r = 1;
    for (const auto& [t, num] : {std::pair{sv.tsx, c.fxn}, std::pair{sv.tsy, c.fyn}}) {
      const double p = t * c.fden;
      if (!std::isfinite(p) || (t != 0 && std::abs(p) <= 0x1p-960)) return -1;
      if (std::fma(t, c.fden, -p) != 0 || p != num) r = 0;
    }
    return r;
  };
  auto same = [&](End& a, End& b) {
    if (a.sum && b.sum) {
      if (a.pid == b.pid && a.qid == b.qid) return true;
      // Two sums of two doubles, both TwoSum pairs finite: equal iff the pairs are (s = fl(x)
      // and e = x − s are functions of the exact x).
      if (a.r_sum && b.r_sum) return a.tsx == b.tsx && a.tex == b.tex && a.tsy == b.tsy && a.tey == b.tey;
    } else if (int r = sum_vs_cut(a, b); r >= 0 || (r = sum_vs_cut(b, a)) >= 0) {
      return r == 1;
    }
    if (nonconvex2::same_point(nonconvex2::Cand{*a.E, a.param(), *a.edge}, nonconvex2::Cand{*b.E, b.param(), *b.edge})) return true;
    return compare_coord(a, b, 0) == 0 && compare_coord(a, b, 1) == 0;
  };
  // Groups of equal roundings (−0 = +0) in an open-addressing table; each group lists its
  // vertices. Ends are visited in index order, so a vertex's representative is its first end.
  int bits = 4;
  while ((std::size_t(1) << bits) < 2 * ends.size()) ++bits;
  std::vector<int>& table = W.table;
  table.assign(std::size_t(1) << bits, -1);
  std::vector<Vec2>& gkey = W.gkey;
  gkey.clear();
  std::vector<int>&ghead = W.ghead, &vnext = W.vnext;
  ghead.clear();
  vnext.clear();
  const std::size_t mask = (std::size_t(1) << bits) - 1;
  for (std::size_t e = 0; e < ends.size(); ++e) {
    const double x = ends[e].r.x() + 0.0, y = ends[e].r.y() + 0.0;  // +0.0: one key for ±0
    std::size_t h = std::size_t((std::bit_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull ^ std::bit_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full) >> (64 - bits));
    int g;
    for (;; h = (h + 1) & mask) {
      g = table[h];
      if (g < 0 || (gkey[g].x() == x && gkey[g].y() == y)) break;
    }
    if (g < 0) {
      g = table[h] = int(gkey.size());
      gkey.emplace_back(x, y);
      ghead.push_back(-1);
    }
    for (int v = ghead[g]; v >= 0 && id[e] < 0; v = vnext[v])
      if (same(ends[rep[v]], ends[e])) id[e] = v;
    if (id[e] < 0) {
      id[e] = nv++;
      rep.push_back(int(e));
      vnext.push_back(ghead[g]);
      ghead[g] = id[e];
      // The exported rounding of a vertex: that of its first sum-vertex end with a TwoSum rounding
      // (the previous export's choice, which also fixes the sign of a zero), else of its first end.
      rv.push_back(ends[e].r);
      fixed.push_back(ends[e].r_sum);
    } else if (ends[e].r_sum && !fixed[id[e]]) {
      rv[id[e]] = ends[e].r;
      fixed[id[e]] = 1;
    }
  }
  return nv;
}

// W.segs: the pieces of positive length with their line filters; W.zero_points: the vertex of
// each zero-length piece.
void collect_segs(Workspace& W, const NoFitPolygon2::Impl& N) {
  std::vector<Seg>& segs = W.segs;
  segs.clear();
  std::vector<int>& zero_points = W.zero_points;
  zero_points.clear();
  const std::vector<int>& id = W.id;
  for (std::size_t k = 0; k < N.pieces.size(); ++k) {
    const int ia = id[2 * k], ib = id[2 * k + 1];
    if (ia == ib) {
      zero_points.push_back(ia);
      continue;
    }
    make_seg(segs.emplace_back(), N.pieces[k], ia, ib);
  }
}

// W.verts: every vertex (each is an end of a piece of positive length or a zero-length one) with
// its rounding inline, sorted by rounded x for range scans.
void sort_vertices(Workspace& W, int nv) {
  std::vector<Workspace::VX>& verts = W.verts;
  const std::vector<Vec2>& rv = W.rv;
  verts.resize(nv);
  for (int v = 0; v < nv; ++v) verts[v] = {rv[v].x(), rv[v].y(), v};
  std::sort(verts.begin(), verts.end(), [](const Workspace::VX& a, const Workspace::VX& b) { return a.x < b.x; });
}

// Empties the output of the linking steps: slits, is_vertex (nv zeros) and the rings (ring k is
// ring_verts[ring_start[k], ring_start[k + 1]), vertex ids).
void clear_rings(Workspace& W, int nv) {
  W.slits.clear();
  W.is_vertex.assign(nv, 0);  // ends of edges and slit pieces
  W.ring_verts.clear();
  W.ring_start.assign(1, 0);
}

// Step 2: W.order, the segments sorted by exact supporting line (indices only: a Seg is large).
void sort_by_line(Workspace& W) {
  const std::vector<Seg>& segs = W.segs;
  std::vector<int>& order = W.order;
  order.resize(segs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  std::sort(order.begin(), order.end(), [&](int x, int y) { return compare_lines_filtered(segs[x], segs[y]) < 0; });
}

// Step 2: per exact line (a run of W.order), the pieces cut at every vertex on the line inside
// their extent into elementary segments: W.edges (covered one way), W.slits (both ways), and
// is_vertex for their ends.
void cut_lines(Workspace& W, int nv) {
  const std::vector<Seg>& segs = W.segs;
  const std::vector<int>& order = W.order;
  const std::vector<End>& ends = W.ends;
  const std::vector<int>& rep = W.rep;
  const std::vector<Vec2>& rv = W.rv;
  const std::vector<Workspace::VX>& verts = W.verts;
  std::vector<std::array<int, 2>>& slits = W.slits;
  std::vector<char>& is_vertex = W.is_vertex;
  auto sgs = [&](std::size_t k) -> const Seg& { return segs[std::size_t(order[k])]; };
  using Iv = Workspace::Iv;
  std::vector<Workspace::Edge>& edges = W.edges;
  edges.clear();
  std::vector<int>&stamp = W.stamp, &pos = W.pos;
  stamp.assign(nv, -1);
  pos.assign(nv, 0);
  std::vector<Iv>& ivs = W.ivs;
  std::vector<int>& us = W.us;
  for (std::size_t g0 = 0, g1; g0 < segs.size(); g0 = g1) {
    g1 = g0 + 1;
    while (g1 < segs.size() && compare_lines_filtered(sgs(g1), sgs(g0)) == 0) ++g1;
    const int axis = sgs(g0).vertical ? 1 : 0;
    ivs.clear();
    us.clear();
    Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
    for (std::size_t k = g0; k < g1; ++k) {
      const Seg& s = sgs(k);
      const bool fwd = s.su > 0;  // b − a is a positive multiple of E's direction
      ivs.push_back({fwd ? s.a : s.b, fwd ? s.b : s.a, fwd});
      for (int v : {s.a, s.b}) {
        if (stamp[v] != int(g0)) stamp[v] = int(g0), us.push_back(v);
        lo = lo.cwiseMin(rv[v]);
        hi = hi.cwiseMax(rv[v]);
      }
    }
    // Other exact vertices on this line inside its extent split it too. Rounding is monotone, so
    // the extent's points round into [lo, hi]; those in the box are tested exactly.
    auto it = std::lower_bound(verts.begin(), verts.end(), lo.x(), [](const Workspace::VX& a, double x) { return a.x < x; });
    bool split = false;
    for (; it != verts.end() && it->x <= hi.x(); ++it) {
      const int v = it->v;
      if (it->y < lo.y() || it->y > hi.y() || stamp[v] == int(g0)) continue;
      if (!on_line(ends[rep[v]], sgs(g0))) continue;
      stamp[v] = int(g0);
      us.push_back(v);
      split = true;
    }
    if (g1 == g0 + 1 && !split) {  // a lone piece on its line, nothing inside it: one boundary edge
      is_vertex[sgs(g0).a] = 1;
      is_vertex[sgs(g0).b] = 1;
      edges.push_back({sgs(g0).a, sgs(g0).b, g0, ivs[0].fwd});
      continue;
    }
    // Distinct vertices on one line have distinct u: rounded u first, exact on equal roundings.
    std::sort(us.begin(), us.end(), [&](int x, int y) {
      if (rv[x][axis] != rv[y][axis]) return rv[x][axis] < rv[y][axis];
      return x != y && compare_coord(ends[rep[x]], ends[rep[y]], axis) < 0;
    });
    for (std::size_t i = 0; i < us.size(); ++i) pos[us[i]] = int(i);
    // Elementary interval i (between us[i] and us[i + 1]) is covered by iv iff pos[lo] ≤ i <
    // pos[hi]: counts per direction by a difference array and a running sum, O(|us| + |ivs|)
    // (a line holding many pieces — the comb's collinear tooth tops — made the scan of every
    // piece per interval quadratic).
    std::vector<std::array<int, 2>>& cover = W.cover;
    cover.assign(us.size() + 1, {0, 0});
    for (const Iv& iv : ivs) {
      if (pos[iv.lo] >= pos[iv.hi]) continue;  // covers no interval
      ++cover[std::size_t(pos[iv.lo])][iv.fwd ? 0 : 1];
      --cover[std::size_t(pos[iv.hi])][iv.fwd ? 0 : 1];
    }
    bool slit_open = false;
    int slit_start = -1;
    int nf = 0, nb = 0;
    for (std::size_t i = 0; i + 1 < us.size(); ++i) {
      nf += cover[i][0], nb += cover[i][1];
      const bool f = nf > 0, b = nb > 0;
      const int p0 = us[i], p1 = us[i + 1];
      if (f || b) {
        is_vertex[p0] = 1;
        is_vertex[p1] = 1;
      }
      if (f && b) {
        if (!slit_open) slit_start = p0;
        slit_open = true;
        if (i + 2 == us.size()) slits.push_back({slit_start, p1});
        continue;
      }
      if (slit_open) slits.push_back({slit_start, p0});
      slit_open = false;
      if (f) edges.push_back({p0, p1, g0, true});
      else if (b) edges.push_back({p1, p0, g0, false});
    }
  }
}

// Step 3: W.edges linked end to start into rings (W.ring_verts, W.ring_start), the sharpest left
// turn where several edges leave a vertex, collinear pass-through vertices dropped. Throws
// std::logic_error on a chain that does not close.
void link_rings(Workspace& W, int nv) {
  using Edge = Workspace::Edge;
  const std::vector<Edge>& edges = W.edges;
  const std::vector<Seg>& segs = W.segs;
  const std::vector<int>& order = W.order;
  auto sgs = [&](std::size_t k) -> const Seg& { return segs[std::size_t(order[k])]; };
  std::vector<int>&ring_verts = W.ring_verts, &ring_start = W.ring_start;
  // Edges leaving each vertex, in edge order (compressed rows).
  std::vector<int>&first = W.first, &out = W.out, &fill = W.fill;
  first.assign(nv + 1, 0);
  out.resize(edges.size());
  for (const Edge& e : edges) ++first[e.a + 1];
  for (int v = 0; v < nv; ++v) first[v + 1] += first[v];
  fill.assign(first.begin(), first.end() - 1);
  for (std::size_t e = 0; e < edges.size(); ++e) out[fill[edges[e].a]++] = int(e);
  std::vector<char>& used = W.used;
  used.assign(edges.size(), 0);
  // The direction of an edge: its line's ray direction, signed to point from a to b.
  auto dir = [&](const Edge& e) {
    const Seg& s = sgs(e.line);
    return Dir{s.E, e.fwd ? s.su : -s.su};
  };
  std::vector<std::size_t>& chain = W.chain;
  for (std::size_t e0 = 0; e0 < edges.size(); ++e0) {
    if (used[e0]) continue;
    chain.clear();
    std::size_t e = e0;
    for (;;) {
      used[e] = 1;
      chain.push_back(e);
      const int v = edges[e].b;
      std::size_t best = edges.size();
      for (int i = first[v]; i < first[v + 1]; ++i) {
        const std::size_t c = std::size_t(out[i]);
        if (used[c] && c != e0) continue;
        if (best == edges.size()) {
          best = c;
          continue;
        }
        Dir r = dir(edges[e]);  // back along the incoming edge
        r.s = -r.s;
        if (larger_ccw_angle(r, dir(edges[c]), dir(edges[best]))) best = c;
      }
      if (best == e0) break;  // closed
      // Every vertex of ∂O has as many pieces leaving as entering; a dead end means the pieces
      // are inconsistent, which must not be exported as if it were a ring.
      if (best == edges.size())
        throw std::logic_error("no-fit polygon: a boundary chain does not close (internal inconsistency)");
      e = best;
    }
    const std::size_t r0 = ring_verts.size();
    for (std::size_t k = 0; k < chain.size(); ++k) {
      const Edge& in = edges[chain[(k + chain.size() - 1) % chain.size()]];
      const Edge& o = edges[chain[k]];
      // Pass-through: the same exact line (one group per line) in the same direction.
      if (chain.size() > 2 && in.line == o.line && in.fwd == o.fwd) continue;
      ring_verts.push_back(o.a);
    }
    if (ring_verts.size() - r0 >= 3) ring_start.push_back(int(ring_verts.size()));
    else ring_verts.resize(r0);
  }
}

// Ring k as a vector of vertex ids.
std::vector<int> ring_of(const Workspace& W, std::size_t k) {
  return std::vector<int>(W.ring_verts.begin() + W.ring_start[k], W.ring_verts.begin() + W.ring_start[k + 1]);
}

// V: the exact vertices (rationals), computed on first use (only for the rare rational decisions).
void exact_vertices(const Workspace& W, int nv, std::vector<QP>& V) {
  if (V.empty())
    for (int v = 0; v < nv; ++v) V.push_back(exact_point(W.ends[W.rep[v]]));
}

// Step 3: W.outer and W.holes, the rings by the sign of their area (positive: outer), a floating
// shoelace sum on the rounded vertices with a bound covering the rounding of the vertices (2^-53
// relative each) and of the sum; exact rationals (V) when it cannot decide.
void split_rings(Workspace& W, int nv, std::vector<QP>& V) {
  const std::vector<Vec2>& rv = W.rv;
  const std::vector<int>&ring_verts = W.ring_verts, &ring_start = W.ring_start;
  const std::size_t nr = ring_start.size() - 1;
  std::vector<std::size_t>&outer = W.outer, &holes = W.holes;
  outer.clear();
  holes.clear();
  for (std::size_t k = 0; k < nr; ++k) {
    const int* r = ring_verts.data() + ring_start[k];
    const std::size_t m = std::size_t(ring_start[k + 1] - ring_start[k]);
    const double n = double(m);
    double a = 0, big = 0;
    for (std::size_t i = 0; i < m; ++i) {
      const Vec2 &u = rv[r[i]], &w = rv[r[i + 1 == m ? 0 : i + 1]];
      a += u.x() * w.y() - w.x() * u.y();
      big = std::max(big, u.cwiseAbs().maxCoeff());
    }
    const double bound = (4 * n * n + 8 * n) * big * big * 0x1p-50 + 0x1p-1000;
    int sign;
    if (std::isfinite(a) && std::isfinite(bound) && std::abs(a) > bound) sign = a > 0 ? 1 : -1;
    else exact_vertices(W, nv, V), sign = sgn(ring_area2(V, ring_of(W, k)));
    (sign > 0 ? outer : holes).push_back(k);
  }
}

// Step 3: W.owner[h], the outer ring (index into W.outer) of hole h: the smallest (exact area)
// containing one of its vertices, or an edge midpoint when all lie on that ring. Throws
// std::logic_error on a hole in no outer ring.
void place_holes(Workspace& W, int nv, std::vector<QP>& V) {
  const std::vector<std::size_t>&outer = W.outer, &holes = W.holes;
  std::vector<std::size_t>& owner = W.owner;
  owner.assign(holes.size(), 0);
  if (holes.empty()) return;
  exact_vertices(W, nv, V);
  const std::size_t nr = W.ring_start.size() - 1;
  std::vector<std::vector<int>> rings(nr);
  for (std::size_t k = 0; k < nr; ++k) rings[k] = ring_of(W, k);
  std::vector<mpq_class> area(nr);
  for (std::size_t o : outer) area[o] = ring_area2(V, rings[o]);
  for (std::size_t hi = 0; hi < holes.size(); ++hi) {
    const std::size_t h = holes[hi];
    std::size_t best = outer.size();
    for (std::size_t o = 0; o < outer.size(); ++o) {
      int side = 0;
      for (int p : rings[h]) {
        side = point_in_ring(V, rings[outer[o]], V[p]);
        if (side != 0) break;
      }
      // All vertices on that ring's boundary: decide by the midpoints of the hole's edges (a
      // hole that shares every vertex with the ring still has an edge off it, or it is the ring).
      for (std::size_t i = 0; side == 0 && i < rings[h].size(); ++i) {
        const QP &a = V[rings[h][i]], &b = V[rings[h][(i + 1) % rings[h].size()]];
        side = point_in_ring(V, rings[outer[o]], QP{(a.x + b.x) / 2, (a.y + b.y) / 2});
      }
      if (side > 0 && (best == outer.size() || area[outer[o]] < area[outer[best]])) best = o;
    }
    if (best == outer.size())
      throw std::logic_error("no-fit polygon: a hole ring lies in no outer ring (internal inconsistency)");
    owner[hi] = best;
  }
}

// N.wedge: the reflex vertices of O where σ's fast path may prove t ∈ O (nfp_fast.cpp). A vertex
// v (vertex ids: one exact point) is one when at least one piece of positive length arrives at v
// (its hi end) and one leaves it (its lo end), all arriving ones along one exact direction u, all
// leaving ones along one direction w (exact signs: cross 0, dot > 0; pieces along their rays'
// directions, lo to hi, O on the left), and the boundary turns strictly right from u to w
// (cross(u, w) < 0); other pieces ending at v have length zero (a piece through v inside its
// extent is no end here: σ's fast path then has a candidate without a wedge end, and no
// shortcut). Per piece: the wedge vertex at
// its lo end and at its hi end (both for a zero-length piece there), else -1. O(N) and O(1) exact
// signs (floating filter first) per piece end.
void link_wedges(const Workspace& W, NoFitPolygon2::Impl& N, int nv) {
  const std::vector<int>& id = W.id;
  const std::size_t n = N.pieces.size();
  // Per vertex: the first piece arriving and leaving (-1: none yet), and whether it still qualifies.
  std::vector<std::array<int, 2>> first(std::size_t(nv), {-1, -1});
  std::vector<char> ok(std::size_t(nv), 1);
  auto dir = [&](int k) { return Dir{&N.pieces[std::size_t(k)].E, 1}; };
  for (std::size_t k = 0; k < n; ++k) {
    const int ends[2] = {id[2 * k], id[2 * k + 1]};
    if (ends[0] == ends[1]) continue;
    for (int side = 0; side < 2; ++side) {  // 0: k leaves ends[0]; 1: k arrives at ends[1]
      const std::size_t v = std::size_t(ends[side]);
      int& f = first[v][side];
      if (f < 0) f = int(k);
      else if (ok[v] && (cross_sign(dir(f), dir(int(k))) != 0 || dot_sign(dir(f), dir(int(k))) <= 0)) ok[v] = 0;
    }
  }
  for (std::size_t v = 0; v < std::size_t(nv); ++v)
    ok[v] = ok[v] && first[v][0] >= 0 && first[v][1] >= 0 && cross_sign(dir(first[v][1]), dir(first[v][0])) < 0;
  N.wedge.assign(n, {-1, -1});
  for (std::size_t k = 0; k < n; ++k)
    for (int side = 0; side < 2; ++side)
      if (const int v = id[2 * k + side]; ok[std::size_t(v)]) N.wedge[k][side] = v;
}

// Steps 3–4: N.polys (each outer ring, then its holes), N.slits and N.points (the zero-length
// pieces that are no vertex of an edge or slit, in exact (x, y) order), as rounded coordinates.
void write_output(NoFitPolygon2::Impl& N, Workspace& W) {
  const std::vector<Vec2>& rv = W.rv;
  const std::vector<std::size_t>&outer = W.outer, &holes = W.holes, &owner = W.owner;
  auto ring_points = [&](std::size_t k) {
    std::vector<Vec2> pts(std::size_t(W.ring_start[k + 1] - W.ring_start[k]));
    for (std::size_t i = 0; i < pts.size(); ++i) pts[i] = rv[W.ring_verts[std::size_t(W.ring_start[k]) + i]];
    return pts;
  };
  N.polys.clear();
  N.polys.reserve(outer.size());
  for (std::size_t o = 0; o < outer.size(); ++o) {
    std::vector<std::vector<Vec2>>& poly = N.polys.emplace_back();
    poly.reserve(1);
    poly.push_back(ring_points(outer[o]));
    for (std::size_t hi = 0; hi < holes.size(); ++hi)
      if (owner[hi] == o) poly.push_back(ring_points(holes[hi]));
  }
  N.slits.clear();
  for (const auto& sl : W.slits) N.slits.push_back({rv[sl[0]], rv[sl[1]]});
  // Isolated points in exact (x, y) order: rounded first (monotone), exact on equal roundings.
  const std::vector<End>& ends = W.ends;
  const std::vector<int>& rep = W.rep;
  std::vector<int>& zero_points = W.zero_points;
  std::sort(zero_points.begin(), zero_points.end(), [&](int x, int y) {
    if (x == y) return false;
    for (int axis = 0; axis < 2; ++axis) {
      if (rv[x][axis] != rv[y][axis]) return rv[x][axis] < rv[y][axis];
      if (const int c = compare_coord(ends[rep[x]], ends[rep[y]], axis); c != 0) return c < 0;
    }
    return false;
  });
  zero_points.erase(std::unique(zero_points.begin(), zero_points.end()), zero_points.end());
  N.points.clear();
  for (int p : zero_points)
    if (!W.is_vertex[p]) N.points.push_back(rv[p]);
}

}  // namespace

const NoFitPolygon2::Impl& nfp_impl(const NoFitPolygon2& n) { return *n.impl_; }

NfpExportPath nfp_export_last_path() { return last_path; }

void nfp_export(NoFitPolygon2::Impl& N) { nfp_export_by(N, NfpExportPath::Any); }

bool nfp_export_by(NoFitPolygon2::Impl& N, NfpExportPath path) {
  // Two convex shapes: the pieces are edges of the convex sum, ordered by angle.
  if (path == NfpExportPath::Convex || (path == NfpExportPath::Any && nonconvex2::convex_shape(N.S.P) && nonconvex2::convex_shape(N.S.Q))) {
    if (nfp_export_convex(N)) {
      N.wedge.clear();  // a convex O has no reflex vertex
      last_path = NfpExportPath::Convex;
      return true;
    }
    if (path == NfpExportPath::Convex) return false;
  }
  thread_local Workspace W;
  round_ends(W, N);                  // 1. every end rounded to nearest
  const int nv = intern_ends(W);     //    and interned: vertex ids
  link_wedges(W, N, nv);             //    reflex vertices between two pieces (σ's fast path)
  collect_segs(W, N);                //    pieces of positive length, zero-length points
  sort_vertices(W, nv);              //    vertices by rounded x
  clear_rings(W, nv);
  const bool linked = path != NfpExportPath::General && export_linked(W, W.ends, W.rv, nv);  // rings directly
  if (!linked && path == NfpExportPath::Linked) return false;
  last_path = linked ? NfpExportPath::Linked : NfpExportPath::General;
  if (!linked) {
    sort_by_line(W);    // 2. pieces by exact line
    cut_lines(W, nv);   //    elementary segments: edges and slits
    link_rings(W, nv);  // 3. edges into rings
  }
  std::vector<QP> V;      // exact vertices, only for the rare rational decisions
  split_rings(W, nv, V);  //    outer rings and holes by area sign
  place_holes(W, nv, V);  //    each hole in its smallest outer ring
  write_output(N, W);     // 4. rings, slits, isolated points
  return true;
}

}  // namespace pendepth
