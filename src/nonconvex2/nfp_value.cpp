// The per-pair no-fit polygon, fast value of σ at a projection (issue 19 item 1): σ² and the
// translation from t to its orthogonal projection X on a piece's edge line, each the exact value
// rounded to nearest (RN, geometry/rounded.hpp) — the same doubles as the rationals give, found in
// double-double arithmetic with a static error bound.
//
// Formulas (exact reals): o = o1 + o2 and D = (a1 + a2) − (b1 + b2) the edge ray's origin and
// direction, W = t − o, c = W × D = Wx·Dy − Wy·Dx, |D|² = Dx² + Dy². The projection is
// X = o + (W·D/|D|²)·D, and W = ((W·D)·D + c·(Dy, −Dx))/|D|², so
//   X − t = (c/|D|²)·(−Dy, Dx),   σ² = |X − t|² = c²/|D|² = c·q with q = c/|D|².
// Precomputed per piece (build_values): o exactly as a double-double (two-sum); D exactly when its
// four-term sum is two doubles (else the piece has no fast value); |D|² to ρ_D = 2⁻⁹⁹ relative.
// Error bounds (u = 2⁻⁵³; double-double (dd) operands normalised, |lo| ≤ u·|hi|):
//   W: two-sum(t, −o_hi) = s + e exactly; r = RN(e − o_lo) is off by ≤ u·|r|; two-sum(s, r) is
//     exact: |W̃ − W| ≤ e_W = 2⁻⁵²·|r|.
//   dd product a·b (p = RN(ah·bh), its exact residual (Veltkamp–Dekker, below), plus RN(ah·bl +
//     al·bh), fast two-sum): the dropped al·bl (≤ u²), the two products' rounding (≤ 2u²) and the
//     two sums' (≤ 5u²) stay below 9u²·|ah·bh|(1 + 2u).
//   dd sum (two two-sums, exact.hpp's operator+): ≤ 2⁻¹⁰⁰·(|a| + |b|) (exact.hpp's kUnitDD).
//   c = t × D − k with k = o × D tabled per piece (k̃ from dd products and a dd sum: |k̃ − k| ≤ e_k =
//     2⁻⁹⁹·(|k1| + |k2|)), so W is not formed on the general path (a shorter dependent chain):
//     c̃ = (tx·Dy − ty·Dx) − k̃: |c̃ − c| ≤ e_c = 2⁻⁹⁹·(|P1| + |P2|) + 2⁻¹⁰⁰·(|S| + |k̃|) + e_k, inflated
//     by 2⁻⁵⁰ (9u² + 2⁻¹⁰⁰ < 2⁻⁹⁹ per product's magnitude, S = P1 − P2); ρ_c = e_c/|c̃| (required
//     ≤ 2⁻⁶⁰: a cancellation |k|/|c| up to about 2³⁸ still certifies, t nearer its line defers).
//   1/|D|² tabled per piece as a double-double ĩ (div below on |D|²'s double-double: 2⁻⁹⁷ for
//     exact operands; |D|² itself within ρ_D, and 1/(x(1 + δ)) = (1/x)(1 − δ/(1 + δ))):
//     ρ_i = (ρ_D + 2⁻⁹⁷)(1 + 2⁻⁴⁰) < 2⁻⁹⁶.
//   q̃ = c̃·ĩ (a dd product, ≤ 9u²(1 + 2u) < 2⁻¹⁰² of |q| once the operands' errors are in): ρ_q =
//     (ρ_c + ρ_i)(1 + 2⁻⁴⁰) + 2⁻¹⁰² ((1 + ε_c)(1 + ε_i) − 1 ≤ (ε_c + ε_i)(1 + 2⁻⁴⁰) as both are
//     below 2⁻⁴⁰). One product instead of the division's dependent chain (two products, a dd
//     sum, a third product, on the path to σ² = c·q); it needs |q̃_hi| within [2⁻⁸⁰⁰, 2⁸⁰⁰] for
//     the residual to be exact (else the generic tier).
//   σ̃² = c̃·q̃: ρ_σ = (ρ_c + ρ_q)(1 + 2⁻⁴⁰) + 2⁻¹⁰²; translation q̃·(−Dy), q̃·Dx: ρ_q + 2⁻¹⁰²
//     (a zero component of D gives an exact zero).
// Axis-parallel edges (Dx or Dy exactly 0): X − t = −W on the other axis, σ² = W² (below). At a
// sum vertex (μ = 0 or 1): vertex_values; at a cut end (O's reflex vertices, ~3 % of the σ
// winners on nesting pieces, which took the generic tier before): end_values from the ends'
// double-doubles tabled once per piece (end_dd; below).
// Each value is returned only when rounds_to certifies the whole interval inside one rounding
// cell (or, for a coordinate at a vertex or cut end, when it is exact: point_values; σ_d's λ by
// its residual instead: crossing_certified, or by one division where it is a quotient of two
// doubles: axis_crossing_exact); magnitudes are kept inside [2⁻⁸⁰⁰, 2⁸⁰⁰] (products' residuals representable) or zero.
// Cost: ~80 flops per query, no branch on data beyond the range checks.
#include <bit>
#include <cmath>
#include <cstdint>

#include "geometry/exact.hpp"
#include "geometry/rounded.hpp"
#include "nonconvex2/nfp_impl.hpp"

namespace pendepth::nonconvex2 {

namespace {

using exact::quick_two_sum;
using exact::two_sum;

struct D2 {
  double hi, lo;
};

// The exact residual a·b − RN(a·b) by Veltkamp splitting and Dekker's product: the same double as
// std::fma(a, b, −RN(a·b)) whenever that residual is exact, i.e. when |a|, |b| < 2⁹⁹⁶ (no overflow
// in the split) and the exponents of a and b sum to at least −969 (no underflow) — every use below
// has |a·b| ≥ 2⁻⁸⁰⁰ or refuses the result (rounds_to: [2⁻⁸⁰⁰, 2⁸⁰⁰]; an overflowed split gives
// NaN, refused too). Inline arithmetic instead of a call to libm's fma (no FMA instruction in the
// baseline target): the callers keep their registers.
inline void split(double a, double& h, double& l) {
  const double c = 134217729.0 * a;  // (2²⁷ + 1)·a
  h = c - (c - a);
  l = a - h;
}
inline double residual(double a, double b, double p) {
  double ah, al, bh, bl;
  split(a, ah, al);
  split(b, bh, bl);
  return ((ah * bh - p) + ah * bl + al * bh) + al * bl;
}

// F: the residual by the FMA instruction (the same double: both are exact here; used only in the
// functions compiled for it, below), else by splitting.
template <bool F>
[[gnu::always_inline]] inline double residual_of(double a, double b, double p) {
  if constexpr (F) return std::fma(a, b, -p);
  else return residual(a, b, p);
}

template <bool F = false>
[[gnu::always_inline]] inline D2 mul(D2 a, D2 b) {
  const double p = a.hi * b.hi;
  const double e = residual_of<F>(a.hi, b.hi, p) + (a.hi * b.lo + a.lo * b.hi);
  D2 r;
  quick_two_sum(p, e, r.hi, r.lo);
  return r;
}

[[gnu::always_inline]] inline D2 add(D2 a, D2 b) {
  const exact::DD r = exact::DD{a.hi, a.lo, 0} + exact::DD{b.hi, b.lo, 0};
  return {r.hi, r.lo};
}

// a / b in double-double from inv = RN(1 / b.hi) (per piece, built once, or computed off the
// critical path): two products instead of exact::dd_div's two dependent divisions. Error (a, b
// exact, normalised double-doubles; u = 2⁻⁵³): q1 = RN(a.hi·inv) = (a/b)(1 + η), |η| ≤ 4.1u (a.hi
// against a, b.hi against b, inv and the product: u each); r = a − q1·b in double-double is −η·a
// within 9u²·|a|(1 + 5u) (the product) + 2⁻¹⁰⁰·(|a| + |q1·b|) (the sum), < 140u²·|a|; q2 =
// RN(r.hi·inv) is r/b within 4.1u, so |q2 − r/b| < 4.1u·(4.1u + 140u²)·|a/b| < 18u²·|a/b|; the
// fast two-sum of q1 and q2 is exact: within 158u² < 2⁻⁹⁸ of a/b relative, under exact::kDivBound
// (2⁻⁹⁷) as for dd_div. Products' residuals exact: |a|, |b.hi|, |q1| below 2⁹⁹⁶, |q1·b.hi| ≈ |a.hi|
// ≥ 2⁻⁸⁰⁰ (the callers' range checks).
template <bool F = false>
[[gnu::always_inline]] inline D2 div(D2 a, D2 b, double inv) {
  const double q1 = a.hi * inv;
  const D2 p = mul<F>({q1, 0}, b);
  const D2 r = add(a, {-p.hi, -p.lo});
  D2 q;
  quick_two_sum(q1, r.hi * inv, q.hi, q.lo);
  return q;
}

// 0 or within [2⁻⁴⁰⁰, 2⁴⁰⁰]: products of two such are 0 or in [2⁻⁸⁰⁰, 2⁸⁰⁰].
inline bool in_range(double x) {
  const double a = std::abs(x);
  return a == 0 || (a >= 0x1p-400 && a <= 0x1p400);
}

// W = t − (o + ol) as a double-double with its error bound (0 when exact).
// With ol = ±0 (o a double: integer and most real data) the result is (s + 0, e + 0) for
// two_sum(t, −o) = s + e, bit for bit what the two further two-sums give (r = e + ∓0 is e up to a
// zero's sign, RN(s + r) = s as s = RN(t − o) and s + e = t − o, the error +0 + r; a zero's sign
// normalised by + 0 as there; err 0), without their latency (a third of the chain before σ_d's
// crossing and σ's axis-parallel projection).
inline void diff(double t, double o, double ol, D2& w, double& err) {
  double s, e, r, r2;
  two_sum(t, -o, s, e);
  if (ol == 0) {
    w = {s + 0.0, e + 0.0};
    err = 0;
    return;
  }
  two_sum(e, -ol, r, r2);
  two_sum(s, r, w.hi, w.lo);
  err = r2 == 0 ? 0.0 : 0x1p-52 * std::abs(r);  // 0: W = s + r exactly
}

}  // namespace

NfpFlat::PieceDD piece_dd(const Ray& E, const Line* edge) {
  NfpFlat::PieceDD v;
  if (edge) {
    two_sum(edge->c1.x(), edge->c2.x(), v.cx, v.cxl);
    two_sum(edge->c1.y(), edge->c2.y(), v.cy, v.cyl);
    two_sum(edge->e1.x(), -edge->e0.x(), v.ex, v.exl);
    two_sum(edge->e1.y(), -edge->e0.y(), v.ey, v.eyl);
    v.line_ok = in_range(v.cx) && in_range(v.cy) && in_range(v.ex) && in_range(v.ey) && (v.ex != 0 || v.ey != 0);
  }
  two_sum(E.o1.x(), E.o2.x(), v.ox, v.oxl);
  two_sum(E.o1.y(), E.o2.y(), v.oy, v.oyl);
  bool ok = true;
  // An exact expansion as a normalised double-double (zeros as +0), false when it needs more.
  auto exact_dd = [](const exact::Ex& e, double& hi, double& lo) {
    if (!e.ok || e.n > 2) return false;
    if (e.n == 0) hi = lo = 0;
    else if (e.n == 1) hi = e.c[0], lo = 0;
    else two_sum(e.c[1], e.c[0], hi, lo);
    return true;
  };
  auto dir = [&](double a1, double a2, double b1, double b2, double& hi, double& lo) {
    // The common case (every candidate's ray: a2 = b2 = 0): D = a1 − b1, whose two-sum is the
    // same normalised pair as the general expansion below (RN of the exact value and the exact
    // remainder; zeros as +0), without building expansions. Overflow takes the general path.
    if (a2 == 0 && b2 == 0) {
      two_sum(a1, -b1, hi, lo);
      if (std::isfinite(hi) && std::isfinite(lo)) {
        if (hi == 0) hi = 0;
        if (lo == 0) lo = 0;
        return;
      }
    }
    const exact::LiftEx L;
    if (!exact_dd(L(a1) + L(a2) - L(b1) - L(b2), hi, lo)) ok = false;
  };
  dir(E.a1.x(), E.a2.x(), E.b1.x(), E.b2.x(), v.dx, v.dxl);
  dir(E.a1.y(), E.a2.y(), E.b1.y(), E.b2.y(), v.dy, v.dyl);
  // The sum vertex at μ = 1, o + D (a P vertex plus a −Q vertex: two doubles), exactly. The common
  // case (a sum edge's ray: a2 = b2 = 0 and the edge's start b1 one of o's terms, so o + D is the
  // other term plus a1) by one two-sum — the same normalised pair as the expansion (zeros as +0).
  auto end1 = [&](double o1, double o2, double a1, double a2, double b1, double b2, double& hi, double& lo) {
    if (a2 == 0 && b2 == 0 && (o1 == b1 || o2 == b1)) {
      two_sum(a1, o1 == b1 ? o2 : o1, hi, lo);
      if (std::isfinite(hi) && std::isfinite(lo)) {
        if (hi == 0) hi = 0;
        if (lo == 0) lo = 0;
        return true;
      }
    }
    const exact::LiftEx L;
    return exact_dd(L(o1) + L(o2) + L(a1) + L(a2) - L(b1) - L(b2), hi, lo);
  };
  v.v1_ok = end1(E.o1.x(), E.o2.x(), E.a1.x(), E.a2.x(), E.b1.x(), E.b2.x(), v.v1x, v.v1xl) && in_range(v.v1x) &&
            end1(E.o1.y(), E.o2.y(), E.a1.y(), E.a2.y(), E.b1.y(), E.b2.y(), v.v1y, v.v1yl) && in_range(v.v1y);
  if (!ok || !in_range(v.ox) || !in_range(v.oy) || !in_range(v.dx) || !in_range(v.dy)) return v;
  const D2 dd = add(mul({v.dx, v.dxl}, {v.dx, v.dxl}), mul({v.dy, v.dyl}, {v.dy, v.dyl}));
  v.dd = dd.hi, v.ddl = dd.lo;
  v.ok = dd.hi >= 0x1p-800;
  const D2 inv = div({1, 0}, dd, 1 / dd.hi);  // 1/|D|², ρ_i (header): |D|² in [2⁻⁸⁰⁰, 2⁸⁰¹] when ok
  v.ddinv = inv.hi, v.ddinvl = inv.lo;
  // o × D (dd products ≤ 9u²·|hi| each, their difference 2⁻¹⁰⁰ of the operands: 2⁻⁹⁹ in all).
  const D2 k1 = mul({v.ox, v.oxl}, {v.dy, v.dyl}), k2 = mul({v.oy, v.oyl}, {v.dx, v.dxl});
  const D2 k = add(k1, {-k2.hi, -k2.lo});
  v.k = k.hi, v.kl = k.lo, v.ke = 0x1p-99 * (std::abs(k1.hi) + std::abs(k2.hi)) * (1 + 0x1p-50);
  return v;
}

// A cut end X = o + μ·D, μ = line_num / line_den (edge_cut.hpp's point_nd with t = 0), one
// coordinate at a time: o1 + o2 exactly (two-sum) when D is exactly 0 on that axis (axis-parallel
// edges; D from the piece's PieceDD); else exact::dd_ratio's double-double and absolute bound
// (rounded.hpp; 2⁻⁹⁷ relative), the bound dropped to 0 when X equals the double hi exactly
// (checked only when |lo| is within the bound, exact-double tier first: integer-like data), and
// an exact 0 recognised exactly. ok false when a
// coordinate is out of range or the tier cannot bound it (then the generic tier answers).
NfpFlat::EndDD end_dd(const Ray& E, const Param& p, const NfpFlat::PieceDD& v) {
  NfpFlat::EndDD r;
  if (!v.ok || p.kind == Param::Zero || p.kind == Param::One || p.kind == Param::Proj) return r;
  const Vec2 origin(0, 0);
  auto coord = [&](int axis, double& hi, double& lo, double& e) {
    auto f = [&](auto L) { return point_nd(p, E, origin, axis, L); };
    e = 0;
    if ((axis == 0 ? v.dx : v.dy) == 0) {  // v.ok: D exactly (hi, lo), so D = 0 on this axis iff hi = 0
      two_sum(axis == 0 ? E.o1.x() : E.o1.y(), axis == 0 ? E.o2.x() : E.o2.y(), hi, lo);
      return in_range(hi) && std::isfinite(lo);
    }
    double b;
    if (!exact::dd_ratio(f, hi, lo, b)) {
      hi = lo = 0;
      return exact::exact_sign_tie_likely([&](auto L) { return f(L).first; }) == 0;
    }
    if (std::abs(lo) <= b && exact::exact_sign_tie_likely([&](auto L) {
                               const auto q = f(L);
                               return q.first - L(hi) * q.second;
                             }) == 0)
      lo = 0;
    else e = b;
    return in_range(hi) && std::isfinite(e);
  };
  r.ok = coord(0, r.x, r.xl, r.ex) && coord(1, r.y, r.yl, r.ey);
  return r;
}

void build_values(const NoFitPolygon2::Impl& N, std::vector<NfpFlat::PieceDD>& out, std::vector<std::array<NfpFlat::EndDD, 2>>& ends) {
  out.clear();
  out.reserve(N.pieces.size());
  ends.clear();
  ends.reserve(N.pieces.size());
  for (const NfpPiece& pc : N.pieces) {
    out.push_back(piece_dd(pc.E, &pc.edge));
    ends.push_back({end_dd(pc.E, pc.lo, out.back()), end_dd(pc.E, pc.hi, out.back())});
  }
}

template <bool F>
[[gnu::always_inline]] inline bool projection_values_body(const NfpFlat& self, std::uint32_t k, const Vec2& t, double& sigma2, Vec2& translation, NfpFlat::ProjectionDiag* diag) {
  const NfpFlat::PieceDD& v = self.pdd[k];
  if (!v.ok || !in_range(t.x()) || !in_range(t.y())) return false;
  const D2 Dx{v.dx, v.dxl}, Dy{v.dy, v.dyl};
  // An axis-parallel edge (frequent on real pieces): X − t = −W along the other axis and σ² = W²
  // on it. When W = s + r exactly (e_W = 0), RN(W) is two-sum's hi (the hardware's rounding of
  // s + r: RN of the exact sum, ties to even), so no tie can defeat the certificate.
  if (v.dx == 0 || v.dy == 0) {
    const bool horizontal = v.dy == 0;
    D2 w;
    double ew;
    if (horizontal) diff(t.y(), v.oy, v.oyl, w, ew);
    else diff(t.x(), v.ox, v.oxl, w, ew);
    if (!in_range(w.hi) || ew != 0 || w.hi == 0) return false;
    const D2 w2 = mul<F>(w, w);
    if (diag) *diag = {{w2.hi, horizontal ? 0.0 : -w.hi, horizontal ? -w.hi : 0.0}, {w2.lo, horizontal ? 0.0 : -w.lo, horizontal ? -w.lo : 0.0},
                       {0x1p-102 * std::abs(w2.hi), 0, 0}, true};
    if (!exact::rounds_to(w2.hi, w2.lo, 0x1p-102 * std::abs(w2.hi))) return false;
    sigma2 = w2.hi;
    translation = horizontal ? Vec2(0, -w.hi) : Vec2(-w.hi, 0);
    return true;
  }
  // c = t × D − o × D: two products of a double by an exact double-double and two sums, with
  // o × D tabled per piece (no t − o first: a shorter dependent chain).
  const D2 p1 = mul<F>({t.x(), 0}, Dy), p2 = mul<F>({t.y(), 0}, Dx);
  const D2 s = add(p1, {-p2.hi, -p2.lo});
  const D2 c = add(s, {-v.k, -v.kl});
  const double ac = std::abs(c.hi);
  if (!(ac >= 0x1p-800 && ac <= 0x1p800)) return false;
  const double ec = (0x1p-99 * (std::abs(p1.hi) + std::abs(p2.hi)) + 0x1p-100 * (std::abs(s.hi) + std::abs(v.k)) + v.ke) * (1 + 0x1p-50);
  const double rc = ec / ac * (1 + 0x1p-50);
  if (!(rc <= 0x1p-60)) return false;
  const D2 q = mul<F>(c, {v.ddinv, v.ddinvl});
  const double aq = std::abs(q.hi);
  if (!(aq >= 0x1p-800 && aq <= 0x1p800)) return false;
  const double rq = (rc + (0x1p-99 + exact::kDivBound) * (1 + 0x1p-40)) * (1 + 0x1p-40) + 0x1p-102;
  const D2 s2 = mul<F>(c, q);
  const double rs = (rc + rq) * (1 + 0x1p-40) + 0x1p-102;
  const double bs = rs * std::abs(s2.hi) * (1 + 0x1p-40);
  if (diag) diag->hi[0] = s2.hi, diag->lo[0] = s2.lo, diag->bound[0] = bs, diag->set = false;
  const bool ok_s = exact::rounds_to(s2.hi, s2.lo, bs);
  if (!ok_s && !diag) return false;
  // A component: q·f for f = −Dy or Dx; exactly 0 when f is.
  auto comp = [&](D2 f, double& out, int i) __attribute__((always_inline)) {
    const D2 x = f.hi == 0 ? D2{0, 0} : mul<F>(q, f);
    const double b = (rq + 0x1p-102) * (1 + 0x1p-40) * std::abs(x.hi) * (1 + 0x1p-40);
    if (diag) diag->hi[i] = x.hi, diag->lo[i] = x.lo, diag->bound[i] = b;
    out = x.hi;
    return f.hi == 0 || exact::rounds_to(x.hi, x.lo, b);
  };
  double tx, ty;
  const bool cx = comp({-v.dy, -v.dyl}, tx, 1), cy = comp(Dx, ty, 2);
  if (diag) diag->set = true;
  if (!cx || !cy || !ok_s) return false;
  sigma2 = s2.hi;
  translation = Vec2(tx, ty);
  return true;
}

// σ² = |V|² and V from the double-doubles Ṽ with |V − Ṽ| ≤ e per axis (bound: vertex_values_body's
// comment), each RN(exact) when certified.
template <bool F>
[[gnu::always_inline]] inline bool point_values(const D2 V[2], const double e[2], double& sigma2, Vec2& translation, NfpFlat::ProjectionDiag* diag) {
  const D2 s0 = mul<F>(V[0], V[0]), s1 = mul<F>(V[1], V[1]);
  const D2 s2 = add(s0, s1);
  double bs = 0x1p-99 * (std::abs(s0.hi) + std::abs(s1.hi));
  for (int i = 0; i < 2; ++i) bs += e[i] * (2 * std::abs(V[i].hi) * (1 + 0x1p-50) + e[i]);
  bs *= 1 + 0x1p-40;
  if (diag) *diag = {{s2.hi, V[0].hi, V[1].hi}, {s2.lo, V[0].lo, V[1].lo}, {bs, e[0], e[1]}, true};
  // e = 0: V is exactly hi + lo with hi = RN(hi + lo) (every caller's V with e = 0 is a two-sum's
  // output, negated: the hardware's rounding of the exact sum, ties to even; zero included), so hi
  // is the answer even when V is a rounding tie — frequent: the difference of two doubles whose
  // exponents differ by one needs one bit more than a double; those went to the generic tier's
  // exact midpoint test. Else the interval must round to hi.
  auto coord_ok = [&](int i) { return e[i] == 0 || exact::rounds_to(V[i].hi, V[i].lo, e[i]); };
  if (!coord_ok(0) || !coord_ok(1) || !exact::rounds_to(s2.hi, s2.lo, bs)) return false;
  sigma2 = s2.hi;
  translation = Vec2(V[0].hi + 0.0, V[1].hi + 0.0);  // + 0: an exact zero is +0, as RN(0) is
  return true;
}

// At a vertex of the sum X (μ = 0: X = o; μ = 1: X = o + D, tabled exactly as v1), V = X − t = −W
// with W̃ from diff(t, X) (|W̃ − W| ≤ e_W; e_W = 0 when exact, so a coordinate at a rounding tie is
// certified, as for μ = 0 — at μ = 1 the former V = D − W̃ in double-double carried a bound and
// sent every such tie to the generic tier's exact midpoint test: a quarter of shirts' σ winners at a
// sum vertex). σ² = Vx² + Vy²: |Ṽ² − V²| ≤ e_V·(2|Ṽ| + e_V) per
// axis, each dd square ≤ 9u²·|Ṽ_hi²|(1 + 2u), the sum ≤ 2⁻¹⁰⁰ of the squares' magnitudes: in all
// e_σ = Σ e_V(2|Ṽ_hi|(1 + 2⁻⁵⁰) + e_V) + 2⁻⁹⁹·(Ṽx_hi² + Ṽy_hi²), inflated by 2⁻⁴⁰ relative.
template <bool F>
[[gnu::always_inline]] inline bool vertex_values_body(const NfpFlat& self, std::uint32_t k, int end, const Vec2& t, double& sigma2, Vec2& translation, NfpFlat::ProjectionDiag* diag) {
  const NfpFlat::PieceDD& v = self.pdd[k];
  if (!v.ok || (end == 1 && !v.v1_ok) || !in_range(t.x()) || !in_range(t.y())) return false;
  D2 w[2];
  double e[2];
  diff(t.x(), end == 0 ? v.ox : v.v1x, end == 0 ? v.oxl : v.v1xl, w[0], e[0]);
  diff(t.y(), end == 0 ? v.oy : v.v1y, end == 0 ? v.oyl : v.v1yl, w[1], e[1]);
  D2 V[2];
  for (int i = 0; i < 2; ++i) {
    if (!in_range(w[i].hi)) return false;
    V[i] = {-w[i].hi, -w[i].lo};
  }
  return point_values<F>(V, e, sigma2, translation, diag);
}

// At a cut end (pend): X̃ = x + xl within e_X of X per coordinate, V = X − t = −W for W = t − X̃
// from diff, so e_V = (e_W + e_X)(1 + 2⁻⁵⁰) (the sum's rounding); then as at a vertex.
template <bool F>
[[gnu::always_inline]] inline bool end_values_body(const NfpFlat& self, std::uint32_t k, int end, const Vec2& t, double& sigma2, Vec2& translation, NfpFlat::ProjectionDiag* diag) {
  const NfpFlat::EndDD& x = self.pend[k][end];
  if (!x.ok || !in_range(t.x()) || !in_range(t.y())) return false;
  D2 w[2];
  double e[2];
  diff(t.x(), x.x, x.xl, w[0], e[0]);
  diff(t.y(), x.y, x.yl, w[1], e[1]);
  D2 V[2];
  for (int i = 0; i < 2; ++i) {
    if (!in_range(w[i].hi)) return false;
    V[i] = {-w[i].hi, -w[i].lo};
    e[i] = (e[i] + (i == 0 ? x.ex : x.ey)) * (1 + 0x1p-50);
  }
  return point_values<F>(V, e, sigma2, translation, diag);
}

// λ = N/D from double-doubles num ≈ N (within en) and den ≈ D (within ed ≤ 2⁻⁶⁰·|den_hi|), without
// a double-double division: a candidate double q is RN(λ) iff λ lies strictly inside q's rounding
// cell, which holds when |λ − q| < h, h half the smaller gap next to q (as rounded.hpp's rounds_to:
// powers of two safe, no tie certified). λ − q = (N − q·D)/D, and r̃ = num − q·den is evaluated as
// ((num_hi − p) − ρ) + (num_lo − RN(q·den_lo)) with p = RN(q·den_hi) and ρ = q·den_hi − p exactly
// (residual_of): num_hi − p is exact (Sterbenz: q is within 3u of num_hi/den_hi, so p is within a
// factor 2 of num_hi); the four roundings left (ρ's subtraction, the product, two sums) are each
// ≤ u of their result, in all below 2⁻⁵⁰·(|RN(q·den_lo)| + |num_lo| + |r̃|). So |N − q·D − r̃| ≤ E
// = that + en + |q|·ed, and |D| ≥ |den_hi|·(1 − 2⁻⁵⁰) (|den_lo| ≤ u·|den_hi|, ed ≤ 2⁻⁶⁰·|den_hi|):
// certified when (|r̃| + E)·(1 + 2⁻⁴⁰) < h·|den_hi|·(1 − 2⁻⁴⁰) (h·|den_hi| exact: h a power of two,
// |q·den_hi| ≥ 2⁻⁸⁰⁰ so nothing underflows; the left side's own roundings are inside the 2⁻⁴⁰).
// One division instead of three and no double-double quotient (the crossing value was a quarter of
// σ_d lean's time): q = RN(num_hi/den_hi) is RN(λ) about three times in four; otherwise its
// neighbour towards λ (one step of the last bit) is tried the same way.
inline bool crossing_certified(double q, double r, double E, double den_hi) {
  const double a = std::abs(q);
  const double h = 0.5 * (a - std::bit_cast<double>(std::bit_cast<std::uint64_t>(a) - 1));  // exact (Sterbenz)
  return (std::abs(r) + E) * (1 + 0x1p-40) < h * std::abs(den_hi) * (1 - 0x1p-40);
}

// λ = W/d on an axis-parallel edge (crossing_value_body) when W = c − t on that axis is exactly a
// double: c = cx + cxl (or cy + cyl) with a zero tail and the two-sum c − t exact (a third to over
// half of σ_d's winners' crossings on nesting pieces, docs/benchmarks.md "Fourteenth step"). Then
// the division's correctly rounded quotient is RN(λ) itself — ties to even as RN; an exact tie
// cannot occur (a midpoint's odd significand has 54 bits, and W = q·d would need its odd part,
// a multiple of it, within 53) — and normal by the range checks
// (|W|, |d|, |q| within [2⁻⁸⁰⁰, 2⁸⁰⁰]): no residual and no certificate. False: not this case.
inline bool axis_crossing_exact(const NfpFlat::PieceDD& v, const Vec2& t, const Vec2& d, double& lambda) {
  const bool horizontal = v.ey == 0;  // v.line_ok: E ≠ 0, so one of ex, ey is nonzero
  if (!v.line_ok || (v.ex != 0 && !horizontal) || (horizontal ? v.cyl : v.cxl) != 0) return false;
  double w, e;
  two_sum(horizontal ? v.cy : v.cx, -(horizontal ? t.y() : t.x()), w, e);
  const double den = horizontal ? d.y() : d.x(), q = w / den;
  const double aw = std::abs(w), ad = std::abs(den), aq = std::abs(q);
  if (e != 0 || !(aw >= 0x1p-800 && aw <= 0x1p800 && ad >= 0x1p-800 && ad <= 0x1p800 && aq >= 0x1p-800 && aq <= 0x1p800)) return false;
  lambda = q;
  return true;
}

template <bool F>
[[gnu::always_inline]] inline bool crossing_value_body(const NfpFlat& self, std::uint32_t k, const Vec2& t, const Vec2& d, double& lambda, NfpFlat::ProjectionDiag* diag) {
  const NfpFlat::PieceDD& v = self.pdd[k];
  // (diag, tests: the general path's bounds are reported, so the shortcut is skipped.)
  if (!diag && axis_crossing_exact(v, t, d, lambda)) return true;
  if (!v.line_ok || !in_range(t.x()) || !in_range(t.y()) || !in_range(d.x()) || !in_range(d.y())) return false;
  // λ = ((C − t) × E) / (d × E), C = c1 + c2, E = e1 − e0 (exact double-doubles).
  D2 num, den;
  double en, ed, sc[2] = {1, 0};  // num, den: N, D divided by sc[0] + sc[1] (diag)
  if (v.ex == 0 || v.ey == 0) {
    // An axis-parallel edge (a third to two thirds of the pieces' edges on nesting instances): with
    // Ey = 0, N = −Ex·Wy and D = −Ex·dy, so λ = Wy/dy (Ex = 0: Wx/dx) — the numerator W̃ within
    // e_W on that axis (W = C − t on the other axis not needed) and the denominator the exact
    // double d, without the four double-double products (the same certificate below, for the
    // same RN(λ)).
    const bool horizontal = v.ey == 0;  // the two-sum's hi is 0 iff E is exactly 0 on that axis
    if (horizontal) diff(v.cy, t.y(), -v.cyl, num, en);  // C − t: (c − t) + cl
    else diff(v.cx, t.x(), -v.cxl, num, en);
    if (!in_range(num.hi)) return false;
    den = {horizontal ? d.y() : d.x(), 0};
    ed = 0;
    sc[0] = horizontal ? -v.ex : v.ey, sc[1] = horizontal ? -v.exl : v.eyl;
  } else {
    D2 wx, wy;
    double ewx, ewy;
    diff(v.cx, t.x(), -v.cxl, wx, ewx);  // C − t: (cx − t) + cxl
    diff(v.cy, t.y(), -v.cyl, wy, ewy);
    if (!in_range(wx.hi) || !in_range(wy.hi)) return false;
    const D2 Ex{v.ex, v.exl}, Ey{v.ey, v.eyl};
    const D2 n1 = mul<F>(wx, Ey), n2 = mul<F>(wy, Ex);
    num = add(n1, {-n2.hi, -n2.lo});
    const D2 m1 = mul<F>({d.x(), 0}, Ey), m2 = mul<F>({d.y(), 0}, Ex);
    den = add(m1, {-m2.hi, -m2.lo});
    en = (std::abs(v.ey) * ewx + std::abs(v.ex) * ewy) * (1 + 0x1p-50) + 0x1p-99 * (std::abs(n1.hi) + std::abs(n2.hi));
    ed = 0x1p-99 * (std::abs(m1.hi) + std::abs(m2.hi));
  }
  const double an = std::abs(num.hi), ad = std::abs(den.hi);
  if (!(an >= 0x1p-800 && an <= 0x1p800 && ad >= 0x1p-800 && ad <= 0x1p800)) return false;
  // The candidate q = RN(num_hi / den_hi), else its neighbour towards λ (num_lo and den_lo move λ
  // by up to about an ulp of q), each certified by its residual (crossing_certified).
  double q = num.hi / den.hi;
  if (!(std::abs(q) >= 0x1p-800 && std::abs(q) <= 0x1p800) || !(ed <= 0x1p-60 * ad)) return false;
  double r, E;
  auto residual = [&](double x) __attribute__((always_inline)) {
    const double p = x * den.hi, t2 = x * den.lo;
    r = ((num.hi - p) - residual_of<F>(x, den.hi, p)) + (num.lo - t2);
    E = 0x1p-50 * (std::abs(t2) + std::abs(num.lo) + std::abs(r)) + en + std::abs(x) * ed;
  };
  residual(q);
  auto report = [&] {
    if (diag) *diag = {{q, r, den.hi}, {0, 0, den.lo}, {0, E, ed}, true, {sc[0], sc[1]}};
  };
  if (!crossing_certified(q, r, E, den.hi)) {
    const bool up = (r > 0) == (den.hi > 0);  // λ − q has the sign of r·D
    q = std::bit_cast<double>(std::bit_cast<std::uint64_t>(q) + (up == (q > 0) ? 1 : -1));
    residual(q);
    if (!crossing_certified(q, r, E, den.hi)) return report(), false;
  }
  report();
  lambda = q;
  return true;
}

// The members: the FMA build of each body where the processor has the instruction (the baseline
// target has none: libm's fma would be a call), else the portable one; the same doubles.
namespace {
[[gnu::target("fma")]] bool projection_fma(const NfpFlat& f, std::uint32_t k, const Vec2& t, double& s2, Vec2& tr, NfpFlat::ProjectionDiag* diag) {
  return projection_values_body<true>(f, k, t, s2, tr, diag);
}
[[gnu::target("fma")]] bool vertex_fma(const NfpFlat& f, std::uint32_t k, int end, const Vec2& t, double& s2, Vec2& tr, NfpFlat::ProjectionDiag* diag) {
  return vertex_values_body<true>(f, k, end, t, s2, tr, diag);
}
[[gnu::target("fma")]] bool end_fma(const NfpFlat& f, std::uint32_t k, int end, const Vec2& t, double& s2, Vec2& tr, NfpFlat::ProjectionDiag* diag) {
  return end_values_body<true>(f, k, end, t, s2, tr, diag);
}
[[gnu::target("fma")]] bool crossing_fma(const NfpFlat& f, std::uint32_t k, const Vec2& t, const Vec2& d, double& lambda, NfpFlat::ProjectionDiag* diag) {
  return crossing_value_body<true>(f, k, t, d, lambda, diag);
}
}  // namespace

bool& nfp_values_fma() {
  static bool use = __builtin_cpu_supports("fma");
  return use;
}

bool NfpFlat::projection_values(std::uint32_t k, const Vec2& t, double& sigma2, Vec2& translation, ProjectionDiag* diag) const {
  return nfp_values_fma() ? projection_fma(*this, k, t, sigma2, translation, diag) : projection_values_body<false>(*this, k, t, sigma2, translation, diag);
}

bool NfpFlat::vertex_values(std::uint32_t k, int end, const Vec2& t, double& sigma2, Vec2& translation, ProjectionDiag* diag) const {
  return nfp_values_fma() ? vertex_fma(*this, k, end, t, sigma2, translation, diag) : vertex_values_body<false>(*this, k, end, t, sigma2, translation, diag);
}

bool NfpFlat::end_values(std::uint32_t k, int end, const Vec2& t, double& sigma2, Vec2& translation, ProjectionDiag* diag) const {
  return nfp_values_fma() ? end_fma(*this, k, end, t, sigma2, translation, diag) : end_values_body<false>(*this, k, end, t, sigma2, translation, diag);
}

bool NfpFlat::crossing_value(std::uint32_t k, const Vec2& t, const Vec2& d, double& lambda, ProjectionDiag* diag) const {
  return nfp_values_fma() ? crossing_fma(*this, k, t, d, lambda, diag) : crossing_value_body<false>(*this, k, t, d, lambda, diag);
}

}  // namespace pendepth::nonconvex2
