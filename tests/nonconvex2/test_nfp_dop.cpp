// The classification's k-DOP pruning on large shapes (src/nonconvex2/nfp_classify.cpp PieceDop,
// dop_misses: the pieces' dual descent also prunes node pairs by their extents along the
// diagonals; issue 19 item 4, stars) against the same classification with boxes only
// (nc::nfp_dop_mode() = kDopOff, the method before the change) and against the reference cutting
// (nfp_cut.cpp): the same pieces piece by piece (candidate, exact ends by compare_params, in the
// same order), with the trimming step in its default mode, on every candidate and off (so the
// point tests of step 3 meet every candidate, not only the probes of step 0), and the same
// exported no-fit polygon bit for bit. Inputs: dense random stars (real and integer coordinates:
// exact ties on the diagonals) against an L, a small star and a square, the roles swapped, stars
// scaled by 2^±300 (the margin's relative and absolute terms), spirals, combs with exact fits (also
// rotated by 45°) and polygons with holes. The pruning must act (node pairs pruned by the DOP
// that the boxes kept), and a planted wrong margin (kDopPlanted: each extent shrunk by 1/64 of
// its width) must change the pieces: the comparison can fail. Pinned seeds.
#include <gtest/gtest.h>

#include <pendepth/nfp2.hpp>

#include <cmath>
#include <iostream>
#include <random>
#include <string>

#include "nfp_compare.hpp"
#include "nfp_shapes.hpp"
#include "nonconvex2/nfp_impl.hpp"
#include "polygon2/shapes.hpp"
#include "test_scale.hpp"

namespace {

using pendepth::Polygon;
using pendepth::Vec2;
namespace nc = pendepth::nonconvex2;
using nonconvex2_test::nfp_difference;
using nonconvex2_test::piece_difference;

// Sets both modes for a scope (nfp_compare.hpp).
struct Modes : nonconvex2_test::ScopedModes {
  Modes(int dop, int trim) : ScopedModes(nc::nfp_dop_mode(), dop, nc::kDopOn, trim) {}
};

std::vector<nc::NfpPiece> classify(const pendepth::PairDepth2::Impl& S, const std::vector<nc::NfpCandidate>& cands, int dop, int trim,
                                   std::size_t* pruned = nullptr) {
  Modes m(dop, trim);
  nc::nfp_trim_stats() = {};
  std::vector<nc::NfpPiece> out;
  nc::nfp_classify(S, cands, out);
  if (pruned) *pruned += nc::nfp_trim_stats().dop_pruned;
  return out;
}

struct Totals {
  std::size_t pairs = 0, pieces = 0, pruned = 0, planted_caught = 0, planted_tried = 0;
};
Totals& totals() {
  static Totals t;
  return t;
}

// Pieces with the pruning against without it, under each trimming mode, (with `cut`) against the
// reference cutting, and the exported no-fit polygons bit for bit; (with `plant`) whether the
// planted wrong margin changes the pieces.
void check(const Polygon& P, const Polygon& Q, const std::string& what, bool cut = false, bool plant = false) {
  const pendepth::PairDepth2::Impl S(P, Q);
  const auto cands = nc::nfp_candidates(P, Q);
  Totals& t = totals();
  std::vector<nc::NfpPiece> ref;
  for (const int trim : {nc::kTrimOff, nc::kTrimAuto, nc::kTrimAll}) {
    const auto off = classify(S, cands, nc::kDopOff, trim);
    const auto on = classify(S, cands, nc::kDopOn, trim, &t.pruned);
    ASSERT_EQ(piece_difference(on, off), "") << what << " (DOP / boxes only, trim mode " << trim << ")";
    if (trim == nc::kTrimOff) ref = off;
  }
  if (cut) {
    std::vector<nc::NfpPiece> exact;
    for (const auto& c : cands)
      if (!c.redundant) nc::nfp_cut(S, c, exact);
    ASSERT_EQ(piece_difference(ref, exact), "") << what << " (DOP / reference cutting)";
  }
  if (plant) {
    ++t.planted_tried;
    t.planted_caught += !piece_difference(classify(S, cands, nc::kDopPlanted, nc::kTrimOff), ref).empty();
  }
  auto build = [&](int dop) {
    Modes m(dop, nc::kTrimAuto);
    return pendepth::NoFitPolygon2(P, Q);
  };
  const pendepth::NoFitPolygon2 a = build(nc::kDopOn), b = build(nc::kDopOff);
  ASSERT_EQ(nfp_difference(a, b), "") << what;
  ++t.pairs, t.pieces += ref.size();
}

Polygon L_shape(double s) {
  const std::vector<Vec2> L{{0, 0}, {0.5 * s, 0}, {0.5 * s, 2.5 * s}, {3 * s, 2.5 * s}, {3 * s, 3 * s}, {0, 3 * s}};
  return Polygon::simple(L, "L");
}

Polygon scaled(const Polygon& S, double f) {
  return nonconvex2_test::mapped(S, [&](const Vec2& p) { return Vec2(p * f); });
}

}  // namespace

// Dense stars (spikes closer than Q is wide; thin radial pieces at every angle): the case the
// pruning is for.
TEST(NfpDop, DenseStars) {
  std::mt19937_64 rng(4242);
  for (int it = 0; it < pendepth_test::scaled(8); ++it) {
    const bool grid = it % 2;
    const double s = grid ? 40 : 1;  // integer stars need room between their vertices
    const int n = 300 + int(rng() % 400);
    const Polygon P = nonconvex2_test::star(rng, n, 60 * s, 100 * s, grid);
    const Polygon Q = it % 4 < 2 ? L_shape(s) : nonconvex2_test::star(rng, 6 + int(rng() % 20), 6 * s, 10 * s, grid);
    const std::string tag = std::to_string(it) + (grid ? " grid" : "");
    check(P, Q, "star / " + Q.name() + " " + tag, it < 4, true);
    check(Q, P, Q.name() + " / star " + tag, it < 1, true);
    if (grid)
      check(P, Polygon::simple(std::vector<Vec2>{{0, 0}, {2 * s, 0}, {2 * s, 2 * s}, {0, 2 * s}}, "square"), "star / square " + tag, false,
            true);
  }
  // Far from 1: the margin's terms relative to the coordinates and its absolute floor.
  for (const double f : {std::ldexp(1.0, -300), std::ldexp(1.0, 300)}) {
    const Polygon P = scaled(nonconvex2_test::star(rng, 400, 60, 100, false), f);
    check(P, scaled(L_shape(1), f), "star / L scaled " + std::to_string(std::log2(f)));
  }
}

// Spirals (a long winding pocket), combs with exact fits (slits) and polygons with holes.
TEST(NfpDop, SpiralsCombsHoles) {
  std::mt19937_64 rng(2121);
  const Polygon spiral = Polygon::simple(polygon2_test::spiral_ring(20, 30 / (2 * polygon2_test::kPi), 1.5, 5, 400), "spiral");
  check(spiral, L_shape(1), "spiral / L", true);
  check(spiral, nonconvex2_test::star(rng, 12, 2, 6, false), "spiral / star");
  const Polygon comb = Polygon::simple(polygon2_test::comb_ring(150, 1, 1, 10, 2), "comb");
  const Polygon tooth = Polygon::simple(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 10}, {0, 10}}, "tooth");
  check(comb, tooth, "comb / tooth", true);
  check(comb, L_shape(1), "comb / L");
  // Rotated by 45° (coordinates rounded): long thin pieces along a diagonal, whose extents along
  // the other diagonal are what the pruning tests.
  const double c = std::sqrt(0.5);
  const Polygon turned = nonconvex2_test::mapped(comb, [&](const Vec2& p) { return Vec2(c * p.x() - c * p.y(), c * p.x() + c * p.y()); });
  check(turned, L_shape(1), "comb rotated 45° / L", true);
  check(L_shape(1), turned, "L / comb rotated 45°");
  for (int it = 0; it < pendepth_test::scaled(3); ++it) {
    const Polygon W = polygon2_test::random_polygon(rng, it % 2 ? 80 : 300, 1 + int(rng() % 3), it % 2);
    check(W, L_shape(1), "holes / L " + std::to_string(it));
    check(W, nonconvex2_test::star(rng, 8, 3, 8, it % 2), "holes / star " + std::to_string(it));
  }
}

// The comparisons are not vacuous: on a dense star the pruning acts (more node pairs pruned than
// there are candidates), and a planted wrong margin changes the pieces, here and on dense stars
// of DenseStars (19 of its 20 inputs in a Release build).
TEST(NfpDop, ActsAndPlantedBugIsCaught) {
  std::mt19937_64 rng(77);
  const Polygon P = nonconvex2_test::star(rng, 3000, 60, 100, false), Q = L_shape(1);
  const pendepth::PairDepth2::Impl S(P, Q);
  const auto cands = nc::nfp_candidates(P, Q);
  std::size_t pruned = 0;
  const auto ref = classify(S, cands, nc::kDopOff, nc::kTrimOff);
  ASSERT_EQ(piece_difference(classify(S, cands, nc::kDopOn, nc::kTrimOff, &pruned), ref), "") << "star 3000 / L";
  const std::string planted = piece_difference(classify(S, cands, nc::kDopPlanted, nc::kTrimOff), ref);
  std::cout << "[nfp dop] star 3000 / L: " << cands.size() << " candidates, " << ref.size() << " pieces; node pairs pruned by the DOP "
            << pruned << "; planted wrong margin: " << (planted.empty() ? "not caught" : "caught (" + planted + ")") << "\n";
  EXPECT_GT(pruned, cands.size());
  EXPECT_NE(planted, "");
  const Totals& t = totals();
  if (t.planted_tried > 0) {  // after DenseStars (same executable, default order)
    std::cout << "[nfp dop] earlier: pairs " << t.pairs << ", pieces " << t.pieces << " identical; node pairs pruned " << t.pruned
              << "; planted wrong margin caught on " << t.planted_caught << " of " << t.planted_tried << " inputs\n";
    EXPECT_GT(t.planted_caught, 0u);
  }
}
