// pendepth — coaxial pairs in closed form: the pre-step of the certified support-function engine
// (support3.cpp; issue 16 item 5; docs/algorithms.md §R4.8 "Coaxial pairs").
//
// Why. Where σ is attained on a whole curve (a cylinder centred in a rounded cylinder, coaxial
// shapes of revolution) EPA's inner polytope cannot close the bracket: every expansion cuts one
// facet of a continuum of nearest points (docs/robustness.md). Such continua come from symmetry,
// which is exactly when M = P ⊕ (−Q') simplifies: Minkowski sums of exactly parallel components
// are exact — disks with parallel normals sum to a disk of radius R_P + R_Q, axial segments to a
// segment, balls to a ball — so M = K − t with K a rounded cylinder (any of R, H, r may be 0).
//
// Contract (coaxial3.hpp). Decomposition: cylinder(R, H) = disk(R) ⊕ segment(H) along z;
// ellipsoid(a, a, a) = ball(a); a rounding radius = a ball; the point 0 = nothing; a segment
// (0, 0, −H)–(0, 0, H) = segment(H). Anything else (cones, other ellipsoids, polytopes, off-centre
// points) is not decomposed: the caller falls through to EPA unchanged. Parallel: exact tests on
// the double relative rotation R (the engines' certified pose), no epsilon — z ↦ ±z exactly.
// Q' = R·Q + t with the double R: when R is not a signed permutation it is orthogonal only to
// rounding, so Q's disk and ball are stretched by R's singular values σ_i ∈ [1 − η, 1 + η]
// (η ≥ ‖RᵀR − I‖₂, bounded rigorously); by monotonicity of M in each shape, sd_K evaluated at the
// two ends of every size interval brackets the true value.
// Evaluation: sd_K(q) = D(ρ − R, |q_z| − H) − r with ρ = |q_xy| and
//   D(a, b) = max(a, b) when a, b <= 0 (inside the core: minus the distance to its boundary),
//   else |(max(a, 0), max(b, 0))| (outside: the distance to the core),
// non-decreasing in a and b, so the lower (upper) bound is D of the lower (upper) ends, every
// operation rounded down (up) by an error-free transformation (TwoSum, FMA residuals): an exact
// operation is not widened, so lower = upper whenever the closed form is exact in doubles.
// Cost: O(1), no support query.
#include "primitives/coaxial3.hpp"

#include "primitives/directed.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pendepth::primitives {

namespace {
using namespace directed;

// D(a, b) (see the header comment), rounded in direction dir; monotone, so bounds map to bounds.
double core_distance(double a, double b, int dir) {
  if (a <= 0 && b <= 0) return std::max(a, b);
  if (a <= 0) return b;
  if (b <= 0) return a;
  return hypot_dir(a, b, dir);
}

// A shape's components in its own frame (axis z).
struct Parts {
  Interval disk, seg, ball;
  bool axial() const { return disk.hi > 0 || seg.hi > 0; }
};

std::optional<Parts> parts_of(const Support3& s) {
  Parts p;
  p.ball = {s.radius, s.radius};
  switch (s.kind) {
    case Support3::Kind::Cylinder:
      p.disk = {s.a, s.a}, p.seg = {s.b, s.b};
      return p;
    case Support3::Kind::Ellipsoid:
      if (!(s.a == s.b && s.b == s.c)) return std::nullopt;
      p.ball = p.ball + Interval{s.a, s.a};
      return p;
    case Support3::Kind::Cone:
      return std::nullopt;
    case Support3::Kind::Points:
      if (s.points.size() == 1 && s.points[0] == Vec3::Zero()) return p;
      if (s.points.size() == 2 && s.points[0] == -s.points[1] && s.points[0][0] == 0 && s.points[0][1] == 0) {
        const double h = std::abs(s.points[0][2]);
        p.seg = {h, h};
        return p;
      }
      return std::nullopt;
  }
  return std::nullopt;
}

// R maps z to ±z exactly (and the plane z = 0 to itself).
bool keeps_axis(const Eigen::Matrix3d& R) {
  return R(0, 2) == 0 && R(1, 2) == 0 && R(2, 0) == 0 && R(2, 1) == 0 && std::abs(R(2, 2)) == 1;
}

// sd_K(q) with the sizes (R, H, r) rounded in direction dir: the bound of that side.
double sd_bound(double R, double H, double r, const Vec3& q, int dir) {
  const double rho = hypot_dir(q[0], q[1], dir);
  const double a = sub(rho, R, dir), b = sub(std::abs(q[2]), H, dir);
  return sub(core_distance(a, b, dir), r, dir);
}

// ‖R − R0‖_F·rho rounded up, R0 = R with its axis row and column replaced by ±e_z (the sign of
// R22; +e_z when R22 = 0), and that R0.
double tilt_of(const Eigen::Matrix3d& R, double rho, Eigen::Matrix3d& R0) {
  R0 = R;
  R0(0, 2) = R0(1, 2) = R0(2, 0) = R0(2, 1) = 0;
  R0(2, 2) = R(2, 2) < 0 ? -1.0 : 1.0;
  double sq = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double e = std::abs(sub(R(i, j), R0(i, j), R(i, j) >= R0(i, j) ? +1 : -1));
      sq = add(sq, mul(e, e, +1), +1);
    }
  return mul(root(sq, +1), rho, +1);
}

}  // namespace

std::optional<CoaxialSum> coaxial_sum(const Support3& P, const Support3& Q, const Eigen::Matrix3d& R) {
  if (!coaxial_enabled) return std::nullopt;
  const auto p = parts_of(P), q = parts_of(Q);
  if (!p || !q) return std::nullopt;
  Eigen::Matrix3d R0 = R;
  double tilt = 0;
  // Tilted: Q = C ⊕ B(r) with C its disk ⊕ segment; R·B(r) is a ball stretched by R's own
  // singular values whatever the tilt, so only C moves: tilt = ‖R − R0‖_F·ρ_C, ρ_C = |(R_Q, H_Q)|
  // (not Q.rho, which holds the ball too).
  if (q->axial() && !keeps_axis(R)) tilt = tilt_of(R, hypot_dir(q->disk.hi, q->seg.hi, +1), R0);
  const Interval s = stretch(R0), s_ball = tilt > 0 ? stretch(R) : s;
  const Interval disk = p->disk + q->disk * s, seg = p->seg + q->seg, ball = p->ball + q->ball * s_ball;
  return CoaxialSum{disk.lo, disk.hi, seg.lo, seg.hi, ball.lo, ball.hi, tilt};
}

CoaxialSd coaxial_signed_distance(const CoaxialSum& K, const Vec3& q) {
  CoaxialSd out;
  // sd_K decreases as any size grows: the lower bound from the largest sizes, rounded down.
  out.lo = sub(sd_bound(K.R_hi, K.H_hi, K.r_hi, q, -1), K.tilt, -1);
  out.hi = add(sd_bound(K.R_lo, K.H_lo, K.r_lo, q, +1), K.tilt, +1);
  // The outward normal at a nearest boundary point of K (from the nearest core point).
  const double rho = std::hypot(q[0], q[1]);
  const Vec3 radial = rho > 0 ? Vec3(q[0] / rho, q[1] / rho, 0) : Vec3::UnitX();
  const Vec3 axial(0, 0, q[2] < 0 ? -1.0 : 1.0);
  const double a = rho - K.R_hi, b = std::abs(q[2]) - K.H_hi;
  if (a <= 0 && b <= 0) {
    out.normal = a >= b ? radial : axial;  // inside the core: the nearer of side and cap
  } else {
    const Vec3 n = std::max(a, 0.0) * radial + std::max(b, 0.0) * axial;
    out.normal = n.normalized();
  }
  return out;
}


// ---- The tilted ring: a second-order lower bound of σ (near_coaxial_lower) --------------------
//
// Why. With Q tilted by ε the tilt bound |h_M − h_{K−t}| <= tilt ≈ ε·ρ_C is first order, and EPA's
// inner polytope needs ~13–18·√(σ/ε) supports to resolve the ring of almost-nearest side
// directions (docs/benchmarks.md "Long EPA runs"). But h_M is explicit, and at a centred placement
// σ does not move at first order (the side direction orthogonal to both axes keeps h_M = σ_K):
// a certified minimisation of h_M over the unit sphere, in three regions, closes the bracket.
//
// Notation (P's frame). Every size is replaced by its lower end (a smaller component gives a
// smaller M, so a lower bound of its h is one of h_M). For unit u: s = u_z, ρ = |u_xy| = √(1 − s²),
// v = R̃ᵀu (Q's frame; |v| ∈ [m, m̄], the bounds of R̃'s singular values, `stretch`), w = v_z =
// ⟨a, u⟩ with a = R̃e_z (the double R̃'s third column). Then, exactly,
//   h_M(u) = R_P ρ + H_P|s| + r_P + R_Q|v_xy| + H_Q|w| + r_Q|v| − ⟨t, u⟩,  |v_xy| = √(|v|² − w²).
// Chord: on [0, b] (b < 1) the concave √(1 − x²) lies above its chord: √(1 − x²) >= 1 − k(b)·x,
// k(b) = b / (1 + √(1 − b²)), increasing in b (so an upper bound of b and of k keeps it true);
// scaled: √(c² − x²) >= c − k(b)·x for 0 <= x <= b·c.
// Cover: every unit u has |s| <= β (the side band S), or ρ <= β (the caps C), or both > β (T).
// S: ρ >= 1 − k(β)|s|. |w| <= |s| + |⟨a − ±e_z, u⟩| <= β + τ (τ >= |a ∓ e_z|), so with
//    b_w >= (β + τ)/m: |v_xy| >= √(m² − w²) >= m − k(b_w)|w|, and r_Q|v| >= r_Q·m. Hence
//      h_M(u) >= C_S + α|s| + γ|w| − ⟨t, u⟩,  C_S = R_P + r_P + (R_Q + r_Q)m,
//      α = H_P − R_P k(β), γ = H_Q − R_Q k(b_w)
//    (a negative coefficient is replaced by 0 and its least value, α·β or γ·(β + τ), moved into
//    C_S). For y = a1·e_z + b1·a with |a1| <= α, |b1| <= γ: α|s| >= a1·s and γ|w| >= b1·w, so
//    h_M(u) >= C_S + ⟨y − t, u⟩ >= C_S − |t − y|.
// C: |s| = √(1 − ρ²) >= 1 − k(β)ρ. v_xy = B·u_xy + s·(R̃20, R̃21) with B a 2×2 block of R̃ᵀ
//    (‖B‖ <= ‖R̃‖ <= m̄), so |v_xy| <= m̄β + τ3 (τ3 >= |(R̃20, R̃21)|), and with b_c >=
//    (m̄β + τ3)/m: |w| = √(|v|² − |v_xy|²) >= m − k(b_c)|v_xy|. Hence
//      h_M(u) >= C_C + α'ρ + γ'|v_xy| − ⟨t, u⟩,  C_C = H_P + r_P + (H_Q + r_Q)m,
//      α' = R_P − H_P k(β), γ' = R_Q − H_Q k(b_c)   (negative: as above, with β and m̄β + τ3).
//    For y = α'd1 + γ'R̃d2 with d1, d2 horizontal in the unit disk: α'ρ >= ⟨α'd1, u⟩ and
//    γ'|v_xy| >= γ'⟨d2, v⟩ = ⟨γ'R̃d2, u⟩, so h_M(u) >= C_C − |t − y|.
// T: the tilt bound (coaxial3.hpp): h_M(u) >= R_K ρ + H_K|s| + r_K − tilt − ⟨t, u⟩ (K's lower
//    sizes) >= Aρ + B|s| + r_K − tilt, A = R_K − |t_xy|, B = H_K − |t_z|. (ρ, |s|) runs over the
//    open arc of the unit circle where both exceed β; Aρ + B|s| = |(A, B)|·cos(angle to (A, B)) is
//    least at an endpoint, (√(1 − β²), β) or (β, √(1 − β²)), unless the arc holds the direction
//    −(A, B) — only when A < 0 and B < 0, and then −|(A, B)| bounds it.
// So min(S, C, T) <= min over unit u of h_M(u), for every β; the bound is the best over
// β = 2⁻¹ … 2⁻⁴⁰ (the tilt margin of T wants β·min(R_K, H_K) >~ tilt, the chords' loss grows
// with β). Every operation is rounded towards the safe side (directed add/mul/quot/root,
// intervals for |t − y|). The candidates y are the nearest points of the parallelogram
// {a1·e_z + b1·a} and of the disk sum to t for a placement near the centre (any y is valid; a
// poorer y only loosens the bound). At t = 0 both are 0 and the bound is min(C_S, C_C) when the
// ring's kinks dominate (α, γ >= 0): σ to the stretch m (~1e-16). Cost: O(40) closed forms.
namespace {


// k(b) of the chord, rounded up (b >= 0 an upper bound of the interval's end, b < 1).
double chord_slope_up(double b) { return quot(b, add(1, root(sub(1, mul(b, b, +1), -1), -1), -1), +1); }

double clamp_abs(double x, double c) { return std::clamp(x, -c, c); }
// (x, y) scaled into the closed unit disk (certified by the rounded-up norm); 0 if it will not go.
void into_unit_disk(double& x, double& y) {
  for (int i = 0; i < 4 && hypot_dir(x, y, +1) > 1; ++i) {
    const double n = std::hypot(x, y) * (1 + 0x1p-48);
    x /= n, y /= n;
  }
  if (hypot_dir(x, y, +1) > 1) x = y = 0;
}

// The lower-end sizes of both shapes and the pose quantities every β shares.
struct Ring {
  double Rp, Hp, rp, Rq, Hq, rq;  // lower ends
  double m, mbar, tau, tau3;
  Eigen::Matrix3d R;
  Vec3 t;
  CoaxialSum K;
};

// The lower ends of a region's two half sizes and its constant, shared by both regions: P's half
// size α' = kept_p − cut_p·slope(β) and Q's γ' = kept_q − cut_q·slope(β_q) (the chords of
// √(1 − x²) over the region's widths β and β_q), C = (cut_p + r_P) + (cut_q + r_Q)·m. A negative
// half size is moved into C times its width (β for P, w_q for Q) and becomes 0, so the region's
// set stays a parallelogram / sum of disks. Rounded towards a lower bound throughout.
struct RegionSizes {
  double alpha, gamma, C;
};
RegionSizes region_sizes(const Ring& g, double kept_p, double cut_p, double kept_q, double cut_q,
                         double beta, double beta_q, double w_q) {
  RegionSizes r{sub(kept_p, mul(cut_p, chord_slope_up(beta), +1), -1),
                sub(kept_q, mul(cut_q, chord_slope_up(beta_q), +1), -1),
                add(add(cut_p, g.rp, -1), mul(add(cut_q, g.rq, -1), g.m, -1), -1)};
  if (r.alpha < 0) r.C = add(r.C, mul(r.alpha, beta, -1), -1), r.alpha = 0;
  if (r.gamma < 0) r.C = add(r.C, mul(r.gamma, w_q, -1), -1), r.gamma = 0;
  return r;
}

// Region S: C_S − |t − y|, y the parallelogram's point nearest t (b1 across, then a1 along z).
double side_band(const Ring& g, double beta) {
  const double bt = add(beta, g.tau, +1), bw = quot(bt, g.m, +1);
  if (!(bw < 1)) return -kInf;
  const auto [alpha, gamma, C] = region_sizes(g, g.Hp, g.Rp, g.Hq, g.Rq, beta, bw, bt);
  const Eigen::Matrix3d& R = g.R;
  const Vec3& t = g.t;
  // b1 matches t across (along a_xy) as far as a1 can still match t_z (|t_z − b1·a_z| <= α).
  const double n2 = R(0, 2) * R(0, 2) + R(1, 2) * R(1, 2);
  double b1 = n2 > 0 ? clamp_abs((t[0] * R(0, 2) + t[1] * R(1, 2)) / n2, gamma) : 0.0;
  if (R(2, 2) != 0) {
    const double e1 = (t[2] - alpha) / R(2, 2), e2 = (t[2] + alpha) / R(2, 2);
    b1 = std::clamp(b1, std::min(e1, e2), std::max(e1, e2));
    b1 = clamp_abs(b1, gamma);
  }
  const double a1 = clamp_abs(t[2] - b1 * R(2, 2), alpha);
  const Interval x = iv(t[0]) - iv(b1) * iv(R(0, 2)), y = iv(t[1]) - iv(b1) * iv(R(1, 2));
  const Interval z = iv(t[2]) - iv(a1) - iv(b1) * iv(R(2, 2));
  return sub(C, norm_up(x, y, z), -1);
}

// Region C: C_C − |t − y|, y = α'd1 + γ'R̃d2 with d2 along the tilt's steepest ascent (matching
// t_z) and d1 the horizontal remainder.
double caps(const Ring& g, double beta) {
  const double vb = add(mul(g.mbar, beta, +1), g.tau3, +1), bc = quot(vb, g.m, +1);
  if (!(bc < 1)) return -kInf;
  const auto [alpha, gamma, C] = region_sizes(g, g.Rp, g.Hp, g.Rq, g.Hq, beta, bc, vb);
  const Eigen::Matrix3d& R = g.R;
  const Vec3& t = g.t;
  double d2x = 0, d2y = 0, d1x = 0, d1y = 0;
  const double n3 = std::hypot(R(2, 0), R(2, 1));
  if (gamma > 0 && n3 > 0) {
    // d2 = λ·ĝ, ĝ = ±(R̃20, R̃21)/n3 towards t_z: the height λγ'n3 matches t_z as far as λ <= 1
    // and the horizontal remainder t_xy − λ·c (c = γ'(R̃ĝ)_xy) stays in α'D (the larger root of
    // |t_xy − λc|² = α'²), so that d1 can take it.
    const double sg = t[2] < 0 ? -1.0 : 1.0, gx = sg * R(2, 0) / n3, gy = sg * R(2, 1) / n3;
    const double cx = gamma * (R(0, 0) * gx + R(0, 1) * gy), cy = gamma * (R(1, 0) * gx + R(1, 1) * gy);
    const double cc = cx * cx + cy * cy, pc = t[0] * cx + t[1] * cy;
    const double disc = pc * pc - cc * (t[0] * t[0] + t[1] * t[1] - alpha * alpha);
    double lam = std::min(1.0, std::abs(t[2]) / (gamma * n3));
    if (cc > 0 && disc >= 0) lam = std::clamp((pc + std::sqrt(disc)) / cc, 0.0, lam);
    d2x = lam * gx, d2y = lam * gy;
    into_unit_disk(d2x, d2y);
  }
  if (alpha > 0) {
    d1x = (t[0] - gamma * (R(0, 0) * d2x + R(0, 1) * d2y)) / alpha;
    d1y = (t[1] - gamma * (R(1, 0) * d2x + R(1, 1) * d2y)) / alpha;
    into_unit_disk(d1x, d1y);
  }
  Interval z[3];
  for (int i = 0; i < 3; ++i) {
    const Interval d1 = iv(i == 0 ? d1x : i == 1 ? d1y : 0.0);
    z[i] = iv(t[i]) - iv(alpha) * d1 - iv(gamma) * (iv(R(i, 0)) * iv(d2x) + iv(R(i, 1)) * iv(d2y));
  }
  return sub(C, norm_up(z[0], z[1], z[2]), -1);
}

// Region T: the tilt bound's least value over the arc between the band and the caps.
double between(const Ring& g, double beta) {
  const Vec3& t = g.t;
  const double A = sub(g.K.R_lo, hypot_dir(t[0], t[1], +1), -1), B = sub(g.K.H_lo, std::abs(t[2]), -1);
  double lin;
  if (A < 0 && B < 0) {
    lin = -root(add(mul(A, A, +1), mul(B, B, +1), +1), +1);
  } else {
    const double c_lo = root(sub(1, mul(beta, beta, +1), -1), -1), c_hi = root(sub(1, mul(beta, beta, -1), +1), +1);
    const auto times_c = [&](double x) { return std::min(mul(x, c_lo, -1), mul(x, c_hi, -1)); };
    lin = std::min(add(times_c(A), mul(B, beta, -1), -1), add(mul(A, beta, -1), times_c(B), -1));
  }
  return add(sub(g.K.r_lo, g.K.tilt, -1), lin, -1);
}

}  // namespace

double near_coaxial_lower(const Support3& P, const Support3& Q, const Eigen::Matrix3d& R, const Vec3& t, const CoaxialSum& K) {
  const auto p = parts_of(P), q = parts_of(Q);
  if (!p || !q) return -kInf;
  const Interval s = stretch(R);
  Ring g{p->disk.lo, p->seg.lo, p->ball.lo, q->disk.lo, q->seg.lo, q->ball.lo, s.lo, s.hi, 0, 0, R, t, K};
  const double sign = R(2, 2) < 0 ? -1.0 : 1.0;
  const double d = std::abs(sub(R(2, 2), sign, R(2, 2) >= sign ? +1 : -1));
  g.tau = root(add(add(mul(R(0, 2), R(0, 2), +1), mul(R(1, 2), R(1, 2), +1), +1), mul(d, d, +1), +1), +1);
  g.tau3 = hypot_dir(R(2, 0), R(2, 1), +1);
  if (!(g.m > 0)) return -kInf;
  double best = -kInf;
  for (int j = 1; j <= 40; ++j) {
    const double beta = std::ldexp(1.0, -j);
    best = std::max(best, std::min({side_band(g, beta), caps(g, beta), between(g, beta)}));
  }
  return std::isfinite(best) ? best : -kInf;
}

}  // namespace pendepth::primitives
