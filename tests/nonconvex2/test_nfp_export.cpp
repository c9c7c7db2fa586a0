// The no-fit polygon export without rationals (src/nonconvex2/nfp_rings.cpp) against the previous
// all-rational export (nfp_export_rational.hpp, the oracle), bit for bit: for the same pieces the
// same rings (same order, same starting vertex, same doubles, signs of zeros included), the same
// slits and the same isolated points. Inputs: every ordered pair of the three nesting instances,
// random star pairs (integer and real coordinates, with holes), small integer stars (parallel,
// collinear and coincident edges, slits, touching parts), the same stars scaled by 1/10 (non-dyadic
// coordinates: the exact ties then need more than the floating tiers), the slit / hole-fit / comb
// cases of test_nfp.cpp, rounding ties of sum vertices and of crossings (offset 2^52), offsets of
// 1e6, scales of 2^-30 and 2^-960 (subnormal gaps: the rational fallbacks), inputs chosen to take
// each exact-double shortcut of the export and each of its fallbacks (integers, large integers,
// dyadic offsets, integers against tenths); each also with its pieces shuffled (another interning
// and grouping order); the export's linked path and its general path each run on their own on the
// same pieces (nesting pairs, grid stars, holes, a point on an edge). Pinned seeds.
#include <pendepth/nfp2.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "nfp_export_rational.hpp"
#include "nfp_shapes.hpp"
#include "nonconvex2/nfp_impl.hpp"
#include "nonconvex2/nfp_rings.hpp"
#include "polygon2/shapes.hpp"
#include "test_scale.hpp"

namespace {

using nonconvex2_test::instance;
using nonconvex2_test::mapped;
using nonconvex2_test::shifted;
using nonconvex2_test::star;
using pendepth::NoFitPolygon2;
using pendepth::Polygon;
using pendepth::Vec2;

struct Counts {
  std::size_t pairs = 0, pieces = 0, rings = 0, vertices = 0, slits = 0, points = 0, shuffled = 0;
};
Counts& counts() {
  static Counts c;
  return c;
}

bool same_bits(const Vec2& a, const Vec2& b) {
  return std::bit_cast<std::uint64_t>(a.x()) == std::bit_cast<std::uint64_t>(b.x()) &&
         std::bit_cast<std::uint64_t>(a.y()) == std::bit_cast<std::uint64_t>(b.y());
}

std::string str(const Vec2& v) {
  char b[96];
  std::snprintf(b, sizeof b, "(%a, %a)", v.x(), v.y());
  return b;
}

// The export of `N` (already run on N.pieces) equals the oracle's on the same pieces, bit for bit.
void expect_same(const NoFitPolygon2::Impl& N, const std::string& what) {
  nonconvex2_test::Export want;
  nonconvex2_test::nfp_export_rational(N.pieces, want);
  ASSERT_EQ(N.polys.size(), want.polys.size()) << what;
  for (std::size_t k = 0; k < want.polys.size(); ++k) {
    ASSERT_EQ(N.polys[k].size(), want.polys[k].size()) << what << " polygon " << k;
    for (std::size_t r = 0; r < want.polys[k].size(); ++r) {
      ASSERT_EQ(N.polys[k][r].size(), want.polys[k][r].size()) << what << " polygon " << k << " ring " << r;
      for (std::size_t i = 0; i < want.polys[k][r].size(); ++i)
        ASSERT_TRUE(same_bits(N.polys[k][r][i], want.polys[k][r][i]))
            << what << " polygon " << k << " ring " << r << " vertex " << i << ": " << str(N.polys[k][r][i]) << " vs "
            << str(want.polys[k][r][i]);
      counts().vertices += want.polys[k][r].size();
    }
    counts().rings += want.polys[k].size();
  }
  ASSERT_EQ(N.slits.size(), want.slits.size()) << what;
  for (std::size_t k = 0; k < want.slits.size(); ++k)
    for (int j = 0; j < 2; ++j) ASSERT_TRUE(same_bits(N.slits[k][j], want.slits[k][j])) << what << " slit " << k;
  ASSERT_EQ(N.points.size(), want.points.size()) << what;
  for (std::size_t k = 0; k < want.points.size(); ++k) ASSERT_TRUE(same_bits(N.points[k], want.points[k])) << what << " point " << k;
  counts().slits += want.slits.size();
  counts().points += want.points.size();
}

// Builds the NFP of (P, Q) (which runs the new export), compares; with `rng`, also on a copy whose
// pieces are shuffled (both exports rerun on it).
void check(const Polygon& P, const Polygon& Q, const std::string& what, std::mt19937_64* rng = nullptr) {
  const NoFitPolygon2 nfp(P, Q);
  const NoFitPolygon2::Impl& N = nfp_impl(nfp);
  ++counts().pairs;
  counts().pieces += N.pieces.size();
  expect_same(N, what);
  if (!rng || ::testing::Test::HasFatalFailure()) return;
  NoFitPolygon2::Impl copy = N;
  std::shuffle(copy.pieces.begin(), copy.pieces.end(), *rng);
  pendepth::nfp_export(copy);
  ++counts().shuffled;
  expect_same(copy, what + " (pieces shuffled)");
}

Polygon scaled_by(const Polygon& S, double s) {
  return mapped(S, [&](const Vec2& p) { return Vec2(p * s); });
}

TEST(NfpExport, NestingEveryOrderedPair) {
  std::mt19937_64 rng(31340);
  for (const char* file : {"albano.json", "shirts.json", "trousers.json"}) {
    const auto polys = instance(file);
    for (std::size_t i = 0; i < polys.size(); ++i)
      for (std::size_t j = 0; j < polys.size(); ++j) {
        check(polys[i], polys[j], std::string(file) + " " + std::to_string(i) + "/" + std::to_string(j), &rng);
        if (HasFatalFailure()) return;
      }
  }
}

TEST(NfpExport, NestingOffsetAndScaled) {
  std::mt19937_64 rng(31341);
  const auto polys = instance("albano.json");
  for (std::size_t i = 0; i < polys.size(); ++i)
    for (std::size_t j = 0; j < polys.size(); j += 3) {
      check(shifted(polys[i], Vec2(1e6, -2e6)), shifted(polys[j], Vec2(-3e6, 1e6)), "albano offset " + std::to_string(i) + "/" + std::to_string(j), &rng);
      check(scaled_by(polys[i], 0x1p-30), scaled_by(polys[j], 0x1p-30), "albano 2^-30 " + std::to_string(i) + "/" + std::to_string(j), &rng);
      if (HasFatalFailure()) return;
    }
}

TEST(NfpExport, RandomStarPairs) {
  std::mt19937_64 rng(20261122);
  for (int it = 0; it < pendepth_test::scaled(80); ++it) {
    const bool grid = it % 2;
    const Polygon P = it % 3 == 0 ? polygon2_test::random_polygon(rng, 10 + int(rng() % 10), 1 + int(rng() % 2), grid)
                                  : star(rng, 8 + int(rng() % 16), 50, 100, grid);
    const Polygon Q = it % 4 == 3 ? polygon2_test::random_polygon(rng, 8, 1, grid) : star(rng, 5 + int(rng() % 10), 15, 45, grid);
    check(P, Q, "random " + std::to_string(it), &rng);
    if (HasFatalFailure()) return;
    const Vec2 o(1e6 * (1 + it % 3), -7e5);
    check(shifted(P, o), shifted(Q, Vec2(-2e5, 3e5)), "random offset " + std::to_string(it), &rng);
    check(scaled_by(P, 0x1p-30), scaled_by(Q, 0x1p-30), "random 2^-30 " + std::to_string(it), &rng);
    if (HasFatalFailure()) return;
  }
}

// Small integer stars: parallel, collinear and coincident edges, touching parts of O, slits; then
// the same scaled by 1/10 (rounded coordinates, no longer integers: exact ties are not certified by
// exact floating products there).
TEST(NfpExport, SmallGridPairsDegenerate) {
  std::mt19937_64 rng(4712);
  for (int it = 0; it < pendepth_test::scaled(150); ++it) {
    const Polygon P = star(rng, 5 + int(rng() % 6), 2, 6, true);
    const Polygon Q = it % 3 == 0 ? P : star(rng, 4 + int(rng() % 5), 1, 4, true);
    check(P, Q, "grid " + std::to_string(it), &rng);
    if (HasFatalFailure()) return;
    check(scaled_by(P, 0.1), scaled_by(Q, 0.1), "grid / 10 " + std::to_string(it), &rng);
    // At 2^-960 the gaps between doubles near the vertices are subnormal: rounding falls back to
    // rationals (and the exact predicates to their rational tier).
    if (it % 5 == 0) check(scaled_by(P, 0x1p-960), scaled_by(Q, 0x1p-960), "grid 2^-960 " + std::to_string(it), &rng);
    check(shifted(P, Vec2(1e6, 1e6)), Q, "grid offset " + std::to_string(it), &rng);
    // At 2^52 the doubles are the integers: crossings with a denominator 2 are rounding ties.
    check(shifted(P, Vec2(0x1p52, 0x1p52)), Q, "grid offset 2^52 " + std::to_string(it), &rng);
    if (HasFatalFailure()) return;
  }
}

// The slit, hole-fit and comb cases of test_nfp.cpp, also scaled by 1/10, 2^-30 and offset by 1e6.
TEST(NfpExport, SlitsHolesPointsCombs) {
  const std::vector<Vec2> outer{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Polygon square = Polygon::simple(std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, "square");
  const Polygon unit = Polygon::simple(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "unit");
  auto comb_q = polygon2_test::comb_ring(3, 2, 3, 5, 2);
  for (auto& p : comb_q) p = Vec2(p.x(), -p.y());
  const std::vector<std::pair<Polygon, Polygon>> cases{
      {Polygon::simple(polygon2_test::comb_ring(4, 3, 2, 5, 2), "comb P"), Polygon::simple(comb_q, "comb Q")},
      {Polygon::simple(std::vector<Vec2>{{0, 0}, {7, 0}, {7, 8}, {5, 8}, {5, 2}, {2, 2}, {2, 8}, {0, 8}}, "U"),
       Polygon::simple(std::vector<Vec2>{{0, 0}, {3, 0}, {3, 1}, {0, 1}}, "block")},
      {Polygon({outer, {{4, 4}, {6, 4}, {6, 6}, {4, 6}}}, "plate"), square},
      {Polygon({outer, {{3, 3}, {7, 3}, {7, 7}, {3, 7}}}, "plate"), square},
      {Polygon::simple(std::vector<Vec2>{{0, 0}, {10, 0}, {10, 10}, {6, 10}, {6, 7}, {7, 7}, {7, 3}, {3, 3}, {3, 7}, {4, 7}, {4, 10}, {0, 10}},
                       "bottle"),
       square},
      {Polygon({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{3, 4}, {7, 4}, {7, 5}, {3, 5}}}, "plate with a slot"), unit},
      {Polygon::simple(std::vector<Vec2>{{0, 0}, {2, 0}, {4, 0}, {4, 2}, {0, 2}}, "rect with a collinear vertex"), unit},
      // Sum vertices halfway between two doubles (rounding ties).
      {Polygon::simple(std::vector<Vec2>{{1, 1}, {2, 1}, {2, 2}, {1, 2}}, "square"),
       Polygon::simple(std::vector<Vec2>{{-0x1p-52, -0x1p-52}, {1 - 0x1p-52, -0x1p-52}, {1 - 0x1p-52, 1 - 0x1p-52}, {-0x1p-52, 1 - 0x1p-52}},
                       "offset square")},
  };
  std::mt19937_64 rng(99);
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto& [P, Q] = cases[k];
    const std::string what = P.name() + " / " + Q.name();
    check(P, Q, what, &rng);
    check(Q, P, what + " swapped", &rng);
    check(scaled_by(P, 0.1), scaled_by(Q, 0.1), what + " / 10", &rng);
    check(scaled_by(P, 0x1p-30), scaled_by(Q, 0x1p-30), what + " 2^-30", &rng);
    check(scaled_by(P, 0x1p-960), scaled_by(Q, 0x1p-960), what + " 2^-960", &rng);
    check(shifted(P, Vec2(1e6, -1e6)), shifted(Q, Vec2(-1e6, 1e6)), what + " offset", &rng);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(counts().slits, 0u);   // the cases above do produce slits, points and holes
  EXPECT_GT(counts().points, 0u);
}

// The export's shortcuts and their fallbacks on inputs chosen to take each: small integers (exact
// doubles: line and angle order by FMA products, crossings rounded from FlX-exact quotients, sum
// vertices interned by TwoSum pairs); integers scaled by the odd 99991 (every input an integer, but
// the crossing numerators exceed 53 bits: FlX fails and the double-double walk rounds); dyadic
// offsets (exact differences, non-integer anchors: exact slopes, lifted offsets, walked rounding);
// an integer P against a Q scaled by 1/10 (inexact differences: the lifted line order throughout).
TEST(NfpExport, ExactDoubleShortcutsAndFallbacks) {
  std::mt19937_64 rng(777001);
  for (int it = 0; it < pendepth_test::scaled(120); ++it) {
    const Polygon P = star(rng, 5 + int(rng() % 8), 2, 7, true);
    const Polygon Q = it % 4 == 0 ? P : star(rng, 4 + int(rng() % 6), 1, 4, true);
    const std::string tag = " " + std::to_string(it);
    check(P, Q, "integers" + tag, &rng);
    check(scaled_by(P, 99991), scaled_by(Q, 99991), "integers x 99991" + tag, &rng);
    check(shifted(P, Vec2(0.5, -0.25)), shifted(Q, Vec2(0.125, 0.75)), "dyadic offsets" + tag, &rng);
    check(P, scaled_by(Q, 0.1), "integers / tenths" + tag, &rng);
    if (HasFatalFailure()) return;
  }
}

// Two convex shapes: the export by angle (nfp_export_convex) must give the oracle's output bit for
// bit, on the builder's pieces and shuffled; it must also be the path taken (all pieces whole)
// except where a straight vertex leaves a cut piece. Hulls of grid points (parallel edges, equal
// slopes at different offsets), rectangles and an octagon (axis-parallel and vertical edges: the
// ring's start rule), straight vertices on every edge, offsets and scales.
TEST(NfpExport, ConvexPairsByAngle) {
  std::mt19937_64 rng(4242);
  const std::vector<Vec2> oct{{1, 0}, {2, 0}, {3, 1}, {3, 2}, {2, 3}, {1, 3}, {0, 2}, {0, 1}};
  const Polygon octagon = Polygon::simple(oct, "octagon");
  std::size_t fast = 0, general = 0;
  auto run = [&](const Polygon& P, const Polygon& Q, const std::string& what) {
    const NoFitPolygon2 nfp(P, Q);
    NoFitPolygon2::Impl copy = nfp_impl(nfp);
    std::shuffle(copy.pieces.begin(), copy.pieces.end(), rng);
    if (pendepth::nfp_export_convex(copy)) {
      ++fast;
      expect_same(copy, what + " (by angle, shuffled)");
    } else {
      ++general;
    }
    check(P, Q, what);
  };
  for (int it = 0; it < pendepth_test::scaled(300) && !HasFatalFailure(); ++it) {
    const Polygon P = nonconvex2_test::convex_hull(rng, 3 + int(rng() % 12), 2 + int(rng() % 9));
    const Polygon Q = it % 3 == 0 ? P : nonconvex2_test::convex_hull(rng, 3 + int(rng() % 12), 2 + int(rng() % 9));
    const std::string tag = " " + std::to_string(it);
    run(P, Q, "hulls" + tag);
    run(nonconvex2_test::subdivided(P), Q, "straight P hull" + tag);
    run(nonconvex2_test::subdivided(P), nonconvex2_test::subdivided(Q), "straight hulls" + tag);
    run(shifted(scaled_by(P, 0.1), Vec2(1e6, -3e5)), shifted(scaled_by(Q, 0.1), Vec2(-2e5, 7e5)), "moved hulls" + tag);
    run(scaled_by(P, 0x1p-30), scaled_by(Q, 0x1p-30), "2^-30 hulls" + tag);
    const double w = 1 + double(rng() % 5), h = 1 + double(rng() % 5);
    const std::vector<Vec2> rect{{0, 0}, {w, 0}, {w, h}, {0, h}};
    const Polygon R = Polygon::simple(rect, "rectangle");
    run(R, P, "rectangle / hull" + tag);
    run(R, octagon, "rectangle / octagon" + tag);
    run(octagon, nonconvex2_test::subdivided(R), "octagon / straight rectangle" + tag);
  }
  std::cout << "[nfp export] convex pairs by angle " << fast << ", general " << general << "\n";
  EXPECT_GT(fast, 10 * general);  // the angle path is the one taken on convex pairs
}

// The linked path (every vertex starts one piece and ends one, no vertex inside a piece: the pieces
// are the edges) and the general path (line groups cut into elementary segments), each run on its
// own on the same pieces and compared with the oracle: every pair must give the oracle's output
// by the general path, and by the linked path wherever that one applies. Inputs chosen to take
// each: nesting pairs (both: overlapping collinear pieces with different ends send 3–31 % of the
// non-convex pairs to the general path; coinciding pieces, the same ends the same way, are one edge
// on both), small integer stars (slits, touching parts, overlapping collinear pieces),
// the same moved and scaled (the linked path's line order and its tie-break along a line on
// inexact data), plates with a hole (a hole ring: ring order by first edge), a rectangle with a
// collinear vertex (consecutive pieces on one line: pass-through vertices dropped), random
// polygons with holes against stars (a vertex of one part on an edge of another). Also checks
// that nfp_export itself takes the linked path whenever it applies to a non-convex pair.
TEST(NfpExport, LinkedAndGeneralPaths) {
  std::mt19937_64 rng(5150);
  std::size_t linked = 0, general = 0;
  auto run = [&](const Polygon& P, const Polygon& Q, const std::string& what) {
    const NoFitPolygon2 nfp(P, Q);
    const bool convex = pendepth::nonconvex2::convex_shape(P) && pendepth::nonconvex2::convex_shape(Q);
    const pendepth::NfpExportPath took = pendepth::nfp_export_last_path();
    for (int shuffled = 0; shuffled < 2; ++shuffled) {
      NoFitPolygon2::Impl copy = nfp_impl(nfp);
      if (shuffled) std::shuffle(copy.pieces.begin(), copy.pieces.end(), rng);
      const std::string tag = what + (shuffled ? " (shuffled)" : "");
      ASSERT_TRUE(pendepth::nfp_export_by(copy, pendepth::NfpExportPath::General));
      expect_same(copy, tag + " by the general path");
      const bool applies = pendepth::nfp_export_by(copy, pendepth::NfpExportPath::Linked);
      if (applies) {
        ++linked;
        expect_same(copy, tag + " by the linked path");
        if (!shuffled && !convex) EXPECT_EQ(int(took), int(pendepth::NfpExportPath::Linked)) << what;
      } else {
        ++general;
        if (!shuffled && !convex) EXPECT_EQ(int(took), int(pendepth::NfpExportPath::General)) << what;
      }
      if (HasFatalFailure()) return;
    }
  };
  for (const char* file : {"albano.json", "shirts.json", "trousers.json"}) {
    const auto polys = instance(file);
    for (std::size_t i = 0; i < polys.size() && !HasFatalFailure(); ++i)
      for (std::size_t j = 0; j < polys.size() && !HasFatalFailure(); ++j) {
        const std::string what = std::string(file) + " " + std::to_string(i) + "/" + std::to_string(j);
        run(polys[i], polys[j], what);
        if ((i + j) % 4 == 0) run(shifted(scaled_by(polys[i], 0.1), Vec2(1e6, -2e6)), scaled_by(polys[j], 0.1), what + " moved / 10");
      }
  }
  for (int it = 0; it < pendepth_test::scaled(150) && !HasFatalFailure(); ++it) {
    const Polygon P = star(rng, 5 + int(rng() % 6), 2, 6, true);
    const Polygon Q = it % 3 == 0 ? P : star(rng, 4 + int(rng() % 5), 1, 4, true);
    run(P, Q, "grid " + std::to_string(it));
    run(scaled_by(P, 0.1), scaled_by(Q, 0.1), "grid / 10 " + std::to_string(it));
    run(shifted(P, Vec2(0.5, -0.25)), shifted(Q, Vec2(0.125, 0.75)), "grid dyadic offsets " + std::to_string(it));
  }
  // Random polygons with holes against stars: vertices of one part touching an edge of another
  // (a vertex inside a piece: the general path must cut it there).
  for (int it = 0; it < pendepth_test::scaled(200) && !HasFatalFailure(); ++it) {
    const bool grid = it % 2;
    const Polygon P = it % 3 == 0 ? polygon2_test::random_polygon(rng, 10 + int(rng() % 10), 1 + int(rng() % 2), grid)
                                  : star(rng, 8 + int(rng() % 16), 50, 100, grid);
    const Polygon Q = it % 4 == 3 ? polygon2_test::random_polygon(rng, 8, 1, grid) : star(rng, 5 + int(rng() % 10), 15, 45, grid);
    run(P, Q, "random " + std::to_string(it));
  }
  const std::vector<Vec2> outer{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Polygon square = Polygon::simple(std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, "square");
  const Polygon unit = Polygon::simple(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "unit");
  run(Polygon({outer, {{3, 3}, {7, 3}, {7, 7}, {3, 7}}}, "plate"), unit, "plate / unit");
  run(Polygon({outer, {{3, 3}, {7, 3}, {7, 7}, {3, 7}}}, "plate"), square, "plate / square");
  run(Polygon::simple(std::vector<Vec2>{{0, 0}, {2, 0}, {4, 0}, {4, 2}, {0, 2}}, "rect with a collinear vertex"), unit, "collinear vertex");
  // A grid star pair (RandomStarPairs' pair 25) whose no-fit polygon has a zero-length piece on the
  // interior of a piece: not an isolated point (the general path cuts the piece there), so the
  // linked path must refuse it.
  const Polygon star_p = Polygon::simple(
      std::vector<Vec2>{{77, 1}, {63, 28}, {39, 46}, {-14, 57}, {-54, 27}, {-53, -9}, {-75, -58}, {-11, -63}, {74, -46}, {74, -17},
                        {69, -9}, {72, -8}},
      "star P");
  const Polygon star_q = Polygon::simple(
      std::vector<Vec2>{{35, 22}, {0, 31}, {-8, 31}, {-16, 32}, {-13, 23}, {-28, 21}, {-25, 18}, {-31, -10}, {-14, -38}, {-4, -19}, {26, -24}},
      "star Q");
  run(star_p, star_q, "point on an edge");
  run(scaled_by(star_p, 0.1), scaled_by(star_q, 0.1), "point on an edge / 10");
  std::cout << "[nfp export] linked path " << linked << ", general only " << general << "\n";
  // Both paths exercised on many inputs each (Release ~2100 and ~220; sanitizer builds, which run
  // an eighth of the random inputs, ~1100 and ~100).
  EXPECT_GT(linked, 500u);
  EXPECT_GT(general, 50u);
}

class Summary : public ::testing::Environment {
 public:
  void TearDown() override {
    const Counts& c = counts();
    if (c.pairs == 0) return;
    std::cout << "[nfp export] pairs " << c.pairs << " (+" << c.shuffled << " with shuffled pieces), pieces " << c.pieces << "; identical: rings "
              << c.rings << ", ring vertices " << c.vertices << ", slits " << c.slits << ", points " << c.points << "\n";
  }
};
[[maybe_unused]] ::testing::Environment* const summary_env = ::testing::AddGlobalTestEnvironment(new Summary);

}  // namespace
