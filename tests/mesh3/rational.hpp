// Tests: the exact σ's numbers (src/mesh3/plane_number.hpp) as GMP rationals, the independent
// exact field their oracles use.
#pragma once

#include "mesh3/plane_number.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

namespace mesh3_test {

inline mpq_class rational(const CGAL::Gmpzf& v) {
  mpq_class r{mpz_class(v.man())};
  if (v.exp() >= 0) mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(v.exp()));
  else mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(-v.exp()));
  return r;
}
inline mpq_class rational(const pendepth::mesh3::PlaneNumber& v) {
  EXPECT_GT(CGAL::sign(v.denominator()), 0);
  return rational(v.numerator()) / rational(v.denominator());
}

}  // namespace mesh3_test
