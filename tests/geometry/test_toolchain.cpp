// Guards the build configuration against a GCC 12 wrong-code bug that hit exact.hpp's FlX tier.
// IPA-modref records that a function passes the elements of its `const std::array<FlX, 3>&`
// parameters only as by-value arguments of a non-inlined FlX call (an escape point, resolved at
// IPA time); IPA pure-const then finds that callee const, the flag propagation skips calls to
// const functions, and the read implied by the by-value copy is lost.
// The parameter ends summarised as never read (EAF no_direct_read, while its load summary lists
// it), and DSE deletes the caller's code that computes the argument: the callee multiplies
// uninitialised stack. Seen as the Oracle3.IdenticalShapes hang (directional3.cpp: cand_u<LiftFlX>
// lost its pdiff/qdiff calls) when FlX's operator* stopped being inlined. The top-level
// CMakeLists passes -fno-ipa-modref to GCC; this test fails if that flag is lost while the
// compiler is affected (GCC 12.2 at -O2/-O3). noinline keeps the call structure the bug needs.
#include "geometry/exact.hpp"

#include <gtest/gtest.h>

#include <array>
#include <random>

namespace pendepth {
namespace {

using exact::FlX;
using V3 = std::array<FlX, 3>;

__attribute__((noinline)) inline FlX mul(FlX a, FlX b) { return a * b; }

__attribute__((noinline)) V3 cross_by_ref(const V3& a, const V3& b) {
  return {mul(a[1], b[2]) - mul(a[2], b[1]), mul(a[2], b[0]) - mul(a[0], b[2]),
          mul(a[0], b[1]) - mul(a[1], b[0])};
}

__attribute__((noinline)) V3 lift(const double* p) { return {FlX{p[0], true}, FlX{p[1], true}, FlX{p[2], true}}; }

__attribute__((noinline)) V3 cross_of(const double* p, const double* q) { return cross_by_ref(lift(p), lift(q)); }

TEST(Toolchain, ByValueAggregateArgumentsAreRead) {
  // Small integers: every product and difference is exact, so the FlX result must equal the
  // double cross product exactly and be flagged exact.
  std::mt19937_64 rng(20261121);
  std::uniform_int_distribution<int> k(-1000, 1000);
  for (int it = 0; it < 1000; ++it) {
    const double p[3] = {double(k(rng)), double(k(rng)), double(k(rng))};
    const double q[3] = {double(k(rng)), double(k(rng)), double(k(rng))};
    const double want[3] = {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
    const V3 r = cross_of(p, q);
    for (int i = 0; i < 3; ++i) {
      ASSERT_EQ(r[i].v, want[i]) << "component " << i << " at iteration " << it;
      ASSERT_TRUE(r[i].exact) << "component " << i << " at iteration " << it;
    }
  }
}

}  // namespace
}  // namespace pendepth
