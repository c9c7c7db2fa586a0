// Constant-factor fast paths of the no-fit polygon build (issue 19 item 2), each against an
// independent evaluation: piece_dd's direction by one two-sum (nfp_value.cpp) against the general
// expansion path it replaces and against exact rationals. (The convex pairs' straight-vertex
// shortcut of nfp_classify is checked piece by piece against the reference cutting in
// test_nfp_classify.cpp, NfpClassify.ConvexPairs; the whole build's output against main's, byte
// for byte, by scripts/nfp_identity.py.)
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "nonconvex2/nfp_impl.hpp"

namespace {

namespace nc = pendepth::nonconvex2;
using pendepth::Vec2;

// Doubles of mixed kinds: small integers (exact differences), decimals, wide magnitudes, zeros.
double sample(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  switch (rng() % 5) {
    case 0: return double(std::int64_t(rng() % 2001) - 1000);
    case 1: return std::round(u(rng) * 1e6) / 100;  // two decimals
    case 2: return std::ldexp(u(rng), int(rng() % 200) - 100);
    case 3: return 0.0;
    default: return u(rng) * 3000;
  }
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

}  // namespace

TEST(NfpBuildFast, PieceDirectionTwoSumMatchesExpansionAndRationals) {
  std::mt19937_64 rng(19002);
  int compared = 0, inexact = 0;
  for (int it = 0; it < 200000; ++it) {
    nc::Ray E;
    E.o1 = Vec2(sample(rng), sample(rng));
    E.o2 = Vec2(sample(rng), sample(rng));
    E.a1 = Vec2(sample(rng), sample(rng));
    E.b1 = it % 7 == 0 ? E.a1 : Vec2(sample(rng), sample(rng));  // zero directions too
    if (it % 11 == 0) E.b1 = Vec2(E.a1.x(), sample(rng));          // axis-parallel
    const nc::NfpFlat::PieceDD fast = nc::piece_dd(E);
    // The general path on the same exact direction: a2 = b2 = s cancel exactly.
    nc::Ray G = E;
    const double s = std::ldexp(1.0, int(rng() % 40) - 20);
    G.a2 = Vec2(s, -s), G.b2 = Vec2(s, -s);
    const nc::NfpFlat::PieceDD gen = nc::piece_dd(G);
    // The exact direction, as rationals.
    const mpq_class dx = mpq_class(E.a1.x()) - E.b1.x(), dy = mpq_class(E.a1.y()) - E.b1.y();
    if (fast.ok) {
      ASSERT_EQ(mpq_class(fast.dx) + fast.dxl, dx) << it;
      ASSERT_EQ(mpq_class(fast.dy) + fast.dyl, dy) << it;
      // hi is the exact value rounded to nearest (the hardware's subtraction), lo the remainder.
      ASSERT_TRUE(same_bits(fast.dx, dx == 0 ? 0.0 : E.a1.x() - E.b1.x())) << it;
      ASSERT_TRUE(same_bits(fast.dy, dy == 0 ? 0.0 : E.a1.y() - E.b1.y())) << it;
      inexact += fast.dxl != 0 || fast.dyl != 0;
    }
    if (!gen.ok) continue;  // the expansion path gave up (more than two components): nothing to compare
    ++compared;
    ASSERT_TRUE(fast.ok) << it;
    for (const auto [a, b] : {std::pair{fast.dx, gen.dx}, {fast.dxl, gen.dxl}, {fast.dy, gen.dy}, {fast.dyl, gen.dyl}, {fast.dd, gen.dd},
                              {fast.ddl, gen.ddl}, {fast.ox, gen.ox}, {fast.oxl, gen.oxl}, {fast.oy, gen.oy}, {fast.oyl, gen.oyl}})
      ASSERT_TRUE(same_bits(a, b)) << it << ": " << a << " vs " << b;
  }
  // Not vacuous: most pairs compared, and many directions need two doubles.
  EXPECT_GT(compared, 100000);
  EXPECT_GT(inexact, 10000);
}
