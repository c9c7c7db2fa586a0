// Private: directed roundings and outward intervals for the closed forms of the curved engine
// (coaxial3.cpp, ball3.cpp). Each operation returns the round-to-nearest result, moved one step
// only when an error-free transformation (TwoSum, an FMA residual) says the true value lies
// beyond it: an exact operation is never widened, so lower = upper whenever a closed form is
// exact in doubles. Results below kTiny in magnitude (a product or residual may have underflowed)
// are widened by one step.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace pendepth::primitives::directed {

inline constexpr double kU = 0x1p-53;
inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kTiny = 0x1p-960;

// std::nextafter(x, ∓∞) inline (the library call was a sixth of the spheroid's time): on the
// bit pattern, a finite x ≠ 0 steps one unit in the last place towards ∓∞ by adding ∓1 to its
// magnitude's bits when x > 0 and ±1 when x < 0; ±0 gives ∓denorm_min, ∓∞ and NaN stay, ±∞
// gives ±max (the same results as std::nextafter for every input).
inline double next_toward(double x, bool up) {
  if (x != x) return x;
  if (x == 0) return up ? std::numeric_limits<double>::denorm_min() : -std::numeric_limits<double>::denorm_min();
  if (x == (up ? kInf : -kInf)) return x;
  auto bits = std::bit_cast<std::uint64_t>(x);
  bits = (x > 0) == up ? bits + 1 : bits - 1;
  return std::bit_cast<double>(bits);
}
inline double next_dn(double x) { return next_toward(x, false); }
inline double next_up(double x) { return next_toward(x, true); }

// a + b, a · b, √a, a / b, rounded towards −∞ (dir < 0) or +∞ (dir > 0).
inline double add(double a, double b, int dir) {
  const double s = a + b, bb = s - a;
  const double e = (a - (s - bb)) + (b - bb);  // TwoSum: s + e = a + b exactly
  if (e == 0) return s;
  return dir < 0 ? (e < 0 ? next_dn(s) : s) : (e > 0 ? next_up(s) : s);
}
inline double sub(double a, double b, int dir) { return add(a, -b, dir); }
inline double mul(double a, double b, int dir) {
  const double p = a * b;
  if (p != 0 && std::abs(p) < kTiny) return dir < 0 ? next_dn(p) : next_up(p);
  if (p == 0 && a != 0 && b != 0) return dir < 0 ? -std::numeric_limits<double>::denorm_min() : std::numeric_limits<double>::denorm_min();
  const double e = std::fma(a, b, -p);  // a·b − p exactly (no underflow here)
  if (e == 0) return p;
  return dir < 0 ? (e < 0 ? next_dn(p) : p) : (e > 0 ? next_up(p) : p);
}
inline double root(double a, int dir) {  // a: a bound of a value >= 0 (a lower bound may be < 0)
  if (a <= 0) return 0.0;
  const double s = std::sqrt(a);
  const double e = std::fma(s, s, -a);  // s² − a: its sign is that of s − √a
  if (std::abs(s * s) < kTiny) return dir < 0 ? next_dn(s) : next_up(s);
  if (e == 0) return s;
  return dir < 0 ? (e > 0 ? next_dn(s) : s) : (e < 0 ? next_up(s) : s);
}
// |(a, b)| rounded in direction dir.
inline double hypot_dir(double a, double b, int dir) { return root(add(mul(a, a, dir), mul(b, b, dir), dir), dir); }
// a / b (b > 0) rounded in direction dir: q·b − a has the sign of q − a/b.
inline double quot(double a, double b, int dir) {
  const double q = a / b;
  if (std::abs(q) < kTiny && a != 0) return dir < 0 ? next_dn(q) : next_up(q);
  const double e = std::fma(q, b, -a);
  if (e == 0) return q;
  return dir < 0 ? (e > 0 ? next_dn(q) : q) : (e < 0 ? next_up(q) : q);
}

/// A real number x with lo <= x <= hi; every operation rounds outward, so the result holds the
/// exact operation's result for any arguments in the operands.
struct Interval {
  double lo = 0, hi = 0;
  Interval operator+(const Interval& o) const { return {add(lo, o.lo, -1), add(hi, o.hi, +1)}; }
  Interval operator-(const Interval& o) const { return {sub(lo, o.hi, -1), sub(hi, o.lo, +1)}; }
  Interval operator-() const { return {-hi, -lo}; }
  Interval operator*(const Interval& o) const {  // the least and greatest corner products, outward
    const double a[4] = {lo, lo, hi, hi}, b[4] = {o.lo, o.hi, o.lo, o.hi};
    Interval r{kInf, -kInf};
    for (int i = 0; i < 4; ++i) r.lo = std::min(r.lo, mul(a[i], b[i], -1)), r.hi = std::max(r.hi, mul(a[i], b[i], +1));
    return r;
  }
  /// o.lo > 0: x / y is monotone in each argument on that box, so its ends are corner quotients.
  Interval operator/(const Interval& o) const {
    return {std::min(quot(lo, o.lo, -1), quot(lo, o.hi, -1)), std::max(quot(hi, o.lo, +1), quot(hi, o.hi, +1))};
  }
  double mag() const { return std::max(std::abs(lo), std::abs(hi)); }  ///< max |x|
};
inline Interval iv(double x) { return {x, x}; }
/// a · b for b.lo >= 0: the least product is a.lo times b's end by a.lo's sign, the greatest
/// a.hi times b's end by a.hi's sign (x·y is monotone in x on each sign of y and conversely), and
/// the directed rounding is monotone: operator*'s ends with 2 roundings instead of 8.
inline Interval mul_nonneg(const Interval& a, const Interval& b) {
  return {mul(a.lo, a.lo >= 0 ? b.lo : b.hi, -1), mul(a.hi, a.hi >= 0 ? b.hi : b.lo, +1)};
}
/// a / b for b.lo > 0: the least quotient is a.lo over b's end by a.lo's sign, the greatest
/// likewise (operator/'s ends with 2 roundings instead of 4).
inline Interval div_pos(const Interval& a, const Interval& b) {
  return {quot(a.lo, a.lo >= 0 ? b.hi : b.lo, -1), quot(a.hi, a.hi >= 0 ? b.lo : b.hi, +1)};
}
/// √x (x >= 0; a negative lower end is clamped to 0): √ is increasing.
inline Interval sqrt(const Interval& x) { return {root(x.lo, -1), root(x.hi, +1)}; }
/// |(a, b)| for a, b in intervals: the least |a| and |b| give the lower end (0 when 0 is inside).
inline Interval hypot(const Interval& a, const Interval& b) {
  const auto least = [](const Interval& x) { return x.lo > 0 ? x.lo : x.hi < 0 ? -x.hi : 0.0; };
  return {hypot_dir(least(a), least(b), -1), hypot_dir(a.mag(), b.mag(), +1)};
}

/// |(x, y, z)| rounded up for x, y, z bracketed componentwise.
inline double norm_up(const Interval& x, const Interval& y, const Interval& z) {
  const double a = x.mag(), b = y.mag(), c = z.mag();
  return root(add(add(mul(a, a, +1), mul(b, b, +1), +1), mul(c, c, +1), +1), +1);
}

/// Every entry 0 or ±1, one non-zero per row and column: an exact isometry.
inline bool signed_permutation(const Eigen::Matrix3d& R) {
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

/// [σ_min, σ_max] of R, outward. G = RᵀR − I by nested FMAs: each of the three roundings errs by
/// at most u·2 (|R_ij| <= 1 + 4u for the matrix of a normalised quaternion, so every partial sum
/// is below 2 in magnitude), so |G_ij − G̃_ij| <= 8u; G is symmetric, so ‖G‖₂ <= ‖G‖∞ <= η =
/// max_i Σ_j |G̃_ij| + 24u, and σ² ∈ [1 − η, 1 + η]. Then √(1 + η) <= 1 + η/2 (square both sides)
/// and, for η <= 1/2, √(1 − η) >= 1 − η/2 − η² ((1 − η/2 − η²)² = 1 − η − 7η²/4 + η³ + η⁴).
inline Interval stretch(const Eigen::Matrix3d& R) {
  if (signed_permutation(R)) return {1, 1};
  double eta = 0;
  for (int i = 0; i < 3; ++i) {
    double row = 0;
    for (int j = 0; j < 3; ++j) {
      const double g = std::fma(R(0, i), R(0, j), std::fma(R(1, i), R(1, j), std::fma(R(2, i), R(2, j), i == j ? -1.0 : 0.0)));
      row = add(row, std::abs(g), +1);
    }
    eta = std::max(eta, row);
  }
  eta = add(eta, 24 * kU, +1);
  if (!(eta <= 0.5)) return {std::max(0.0, sub(1, eta, -1)), add(1, eta, +1)};  // (not a rotation: √(1 ± η) ∈ 1 ± η)
  const double half = eta / 2;  // exact
  return {sub(sub(1, half, -1), mul(eta, eta, +1), -1), add(1, half, +1)};
}

}  // namespace pendepth::primitives::directed
