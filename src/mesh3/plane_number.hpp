// Private: the exact number type of the exact mesh σ (mesh_sigma_exact.cpp, issue 17 item 4).
//
// The exact σ's numbers are rational functions of the input doubles: plane normals (degree 2)
// and offsets (degree 3), lines and points of plane intersections (their quotients). A value is
// held as a quotient n / d of two exact binary floating-point numbers (CGAL::Gmpzf: a GMP
// integer times a power of two — every double, sum and product is exact), d > 0, never reduced:
// no gcd (a rational type reduces at every operation: hundreds of ns to µs at these sizes) and
// no lazy DAG (Epeck's FT builds a node per operation and evaluates it under a thread-safe
// std::call_once: the profile of the exact σ showed 35 % of its time in __pthread_once_slow /
// futex). Every operation is exact; comparisons are exact (cross-multiplied by the positive
// denominators). The common denominator is kept when both operands share it (a point
// (1/w)·X, a dot product of such points with exact planes) so that degrees grow only as the
// formulas do.
// Cost: + − × are one to three GMP multiplications of the operands' sizes (a few hundred bits:
// ~50–200 ns), no allocation beyond the results' limbs. to_interval encloses the value (two
// outward-rounded conversions and an interval division); to_double rounds to nearest once
// (MPFR). Tested against GMP rationals in tests/mesh3/test_plane_number.cpp.
#pragma once

#include <CGAL/Gmpzf.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/enum.h>

#include <mpfr.h>

#include <utility>

namespace pendepth::mesh3 {

class PlaneNumber {
 public:
  PlaneNumber() : n_(0), d_(1) {}
  PlaneNumber(double v) : n_(v), d_(1) {}  // NOLINT(google-explicit-constructor): exact
  PlaneNumber(int v) : n_(v), d_(1) {}     // NOLINT(google-explicit-constructor): exact

  const CGAL::Gmpzf& numerator() const { return n_; }
  const CGAL::Gmpzf& denominator() const { return d_; }

  friend PlaneNumber operator-(const PlaneNumber& a) { return {-a.n_, a.d_, a.one_}; }
  friend PlaneNumber operator+(const PlaneNumber& a, const PlaneNumber& b) { return add(a, b, false); }
  friend PlaneNumber operator-(const PlaneNumber& a, const PlaneNumber& b) { return add(a, b, true); }
  friend PlaneNumber operator*(const PlaneNumber& a, const PlaneNumber& b) {
    if (a.one_ && b.one_) return {a.n_ * b.n_, a.d_, true};
    return {a.n_ * b.n_, a.one_ ? b.d_ : b.one_ ? a.d_ : a.d_ * b.d_, false};
  }
  // b != 0 (a precondition, as for any field division).
  friend PlaneNumber operator/(const PlaneNumber& a, const PlaneNumber& b) {
    CGAL::Gmpzf n = b.one_ ? a.n_ : a.n_ * b.d_, d = a.one_ ? b.n_ : a.d_ * b.n_;
    if (CGAL::is_negative(d)) n = -n, d = -d;
    return {std::move(n), std::move(d), false};
  }
  PlaneNumber& operator+=(const PlaneNumber& b) { return *this = *this + b; }
  PlaneNumber& operator*=(const PlaneNumber& b) { return *this = *this * b; }

  friend CGAL::Sign sign(const PlaneNumber& a) { return CGAL::sign(a.n_); }
  friend bool is_zero(const PlaneNumber& a) { return CGAL::is_zero(a.n_); }
  friend bool is_positive(const PlaneNumber& a) { return CGAL::is_positive(a.n_); }
  friend bool is_negative(const PlaneNumber& a) { return CGAL::is_negative(a.n_); }
  friend PlaneNumber abs(const PlaneNumber& a) { return is_negative(a) ? -a : a; }
  friend PlaneNumber square(const PlaneNumber& a) { return a * a; }
  friend CGAL::Comparison_result compare(const PlaneNumber& a, const PlaneNumber& b) {
    if (a.one_ && b.one_) return CGAL::compare(a.n_, b.n_);
    if (same_den(a, b)) return CGAL::compare(a.n_, b.n_);
    return CGAL::compare(b.one_ ? a.n_ : a.n_ * b.d_, a.one_ ? b.n_ : b.n_ * a.d_);
  }
  friend bool operator==(const PlaneNumber& a, const PlaneNumber& b) { return compare(a, b) == CGAL::EQUAL; }
  friend bool operator<(const PlaneNumber& a, const PlaneNumber& b) { return compare(a, b) == CGAL::SMALLER; }
  friend bool operator>(const PlaneNumber& a, const PlaneNumber& b) { return compare(a, b) == CGAL::LARGER; }
  friend bool operator<=(const PlaneNumber& a, const PlaneNumber& b) { return compare(a, b) != CGAL::LARGER; }
  friend bool operator>=(const PlaneNumber& a, const PlaneNumber& b) { return compare(a, b) != CGAL::SMALLER; }

  // An interval holding the value (outward rounding).
  friend std::pair<double, double> to_interval(const PlaneNumber& a) {
    using I = CGAL::Interval_nt<true>;
    const I n(a.n_.to_interval());
    if (a.one_) return {n.inf(), n.sup()};
    const I q = n / I(a.d_.to_interval());
    return {q.inf(), q.sup()};
  }
  // The value rounded to nearest (one rounding).
  friend double to_double(const PlaneNumber& a) {
    if (a.one_ && CGAL::is_zero(a.n_)) return 0.0;
    mpfr_t n, d, q;
    init_exact(n, a.n_), init_exact(d, a.d_);
    mpfr_init2(q, 53);
    mpfr_div(q, n, d, MPFR_RNDN);
    const double r = mpfr_get_d(q, MPFR_RNDN);
    mpfr_clears(n, d, q, static_cast<mpfr_ptr>(nullptr));
    return r;
  }

 private:
  PlaneNumber(CGAL::Gmpzf n, CGAL::Gmpzf d, bool one) : n_(std::move(n)), d_(std::move(d)), one_(one) {}

  static bool same_den(const PlaneNumber& a, const PlaneNumber& b) {
    return a.one_ == b.one_ && (a.one_ || (a.d_.exp() == b.d_.exp() && mpz_cmp(a.d_.man(), b.d_.man()) == 0));
  }
  static PlaneNumber add(const PlaneNumber& a, const PlaneNumber& b, bool sub) {
    if (same_den(a, b)) return {sub ? a.n_ - b.n_ : a.n_ + b.n_, a.d_, a.one_};
    const CGAL::Gmpzf x = b.one_ ? a.n_ : a.n_ * b.d_, y = a.one_ ? b.n_ : b.n_ * a.d_;
    return {sub ? x - y : x + y, a.one_ ? b.d_ : b.one_ ? a.d_ : a.d_ * b.d_, false};
  }
  static void init_exact(mpfr_t r, const CGAL::Gmpzf& v) {
    const auto bits = mpz_sizeinbase(v.man(), 2);
    mpfr_init2(r, static_cast<mpfr_prec_t>(bits < 2 ? 2 : bits));
    mpfr_set_z_2exp(r, v.man(), v.exp(), MPFR_RNDN);  // exact: the precision holds the mantissa
  }

  CGAL::Gmpzf n_, d_;  // the value n_ / d_, d_ > 0
  bool one_ = true;    // d_ == 1
};

}  // namespace pendepth::mesh3
