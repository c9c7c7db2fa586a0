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

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pendepth::primitives {

namespace {
constexpr double kU = 0x1p-53;
constexpr double kInf = std::numeric_limits<double>::infinity();
// Below this magnitude a product or residual may have underflowed: widened by one step.
constexpr double kTiny = 0x1p-960;

double next_dn(double x) { return std::nextafter(x, -kInf); }
double next_up(double x) { return std::nextafter(x, kInf); }

// a + b, a · b, √a, rounded towards −∞ (dir < 0) or +∞ (dir > 0): the round-to-nearest result,
// moved one step only when the exact residual says the true value lies beyond it.
double add(double a, double b, int dir) {
  const double s = a + b, bb = s - a;
  const double e = (a - (s - bb)) + (b - bb);  // TwoSum: s + e = a + b exactly
  if (e == 0) return s;
  return dir < 0 ? (e < 0 ? next_dn(s) : s) : (e > 0 ? next_up(s) : s);
}
double sub(double a, double b, int dir) { return add(a, -b, dir); }
double mul(double a, double b, int dir) {
  const double p = a * b;
  if (p != 0 && std::abs(p) < kTiny) return dir < 0 ? next_dn(p) : next_up(p);
  if (p == 0 && a != 0 && b != 0) return dir < 0 ? -std::numeric_limits<double>::denorm_min() : std::numeric_limits<double>::denorm_min();
  const double e = std::fma(a, b, -p);  // a·b − p exactly (no underflow here)
  if (e == 0) return p;
  return dir < 0 ? (e < 0 ? next_dn(p) : p) : (e > 0 ? next_up(p) : p);
}
double root(double a, int dir) {  // a: a bound of a value >= 0 (a lower bound may be < 0)
  if (a <= 0) return 0.0;
  const double s = std::sqrt(a);
  const double e = std::fma(s, s, -a);  // s² − a: its sign is that of s − √a
  if (std::abs(s * s) < kTiny) return dir < 0 ? next_dn(s) : next_up(s);
  if (e == 0) return s;
  return dir < 0 ? (e > 0 ? next_dn(s) : s) : (e < 0 ? next_up(s) : s);
}

// |(a, b)| rounded in direction dir.
double hypot_dir(double a, double b, int dir) { return root(add(mul(a, a, dir), mul(b, b, dir), dir), dir); }

// D(a, b) (see the header comment), rounded in direction dir; monotone, so bounds map to bounds.
double core_distance(double a, double b, int dir) {
  if (a <= 0 && b <= 0) return std::max(a, b);
  if (a <= 0) return b;
  if (b <= 0) return a;
  return hypot_dir(a, b, dir);
}

struct Interval {
  double lo = 0, hi = 0;
  Interval operator+(const Interval& o) const { return {add(lo, o.lo, -1), add(hi, o.hi, +1)}; }
  Interval operator*(const Interval& o) const {  // both >= 0
    return {mul(lo, o.lo, -1), mul(hi, o.hi, +1)};
  }
};

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

// Every entry 0 or ±1, one non-zero per row and column: an exact isometry.
bool signed_permutation(const Eigen::Matrix3d& R) {
  for (int i = 0; i < 3; ++i) {
    int row = 0, col = 0;
    for (int j = 0; j < 3; ++j) {
      if (R(i, j) != 0 && std::abs(R(i, j)) != 1) return false;
      row += R(i, j) != 0, col += R(j, i) != 0;
    }
    if (row != 1 || col != 1) return false;
  }
  return true;
}

// [σ_min, σ_max] of R, outward. G = RᵀR − I by nested FMAs: each of the three roundings errs by
// at most u·2 (|R_ij| <= 1 + 4u for the matrix of a normalised quaternion, so every partial sum
// is below 2 in magnitude), so |G_ij − G̃_ij| <= 8u; ‖G‖₂ <= Σ|G_ij|; σ² ∈ [1 − η, 1 + η].
Interval stretch(const Eigen::Matrix3d& R) {
  if (signed_permutation(R)) return {1, 1};
  double eta = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double g = std::fma(R(0, i), R(0, j), std::fma(R(1, i), R(1, j), std::fma(R(2, i), R(2, j), i == j ? -1.0 : 0.0)));
      eta = add(eta, std::abs(g), +1);
    }
  eta = add(eta, 72 * kU, +1);
  // √(1 ± η) lies within 1 ± η.
  return {std::max(0.0, sub(1, eta, -1)), add(1, eta, +1)};
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

}  // namespace pendepth::primitives
