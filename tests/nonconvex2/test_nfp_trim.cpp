// The classification's step 0 on large shapes (src/nonconvex2/nfp_classify.cpp trim_deep: the
// parts of candidates certified in O are left out of the pairing, candidates certified whole give
// no piece; issue 19 item 4, stars) against the same classification without it
// (nc::nfp_trim_mode() = kTrimOff, the method before the change) and against the reference
// cutting (nfp_cut.cpp, every open pair sum cut exactly from the candidate): the same pieces
// piece by piece (candidate, exact ends by compare_params, in the same order), and the same
// exported no-fit polygon (NoFitPolygon2's rings, slits and points) bit for bit. Inputs where the
// trimming acts (checked: candidates certified whole and trimmed, fewer pairs met): dense random
// stars against an L, a small star and a square (real and integer coordinates: exact ties),
// spirals, combs whose gaps a tooth fits exactly (slits), polygons with holes, swapped roles.
// The trimming runs on every candidate there (kTrimAll); its default mode, on crowded stars only,
// is compared too. Pinned seeds.
#include <gtest/gtest.h>

#include <pendepth/nfp2.hpp>

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

struct Totals {
  std::size_t pairs = 0, dead = 0, trimmed = 0, meets_on = 0, meets_off = 0, pieces = 0;
};
Totals& totals() {
  static Totals t;
  return t;
}

// Sets the mode, restored on scope exit (a failed assertion returns early).
struct TrimSwitch {
  explicit TrimSwitch(int mode) { nc::nfp_trim_mode() = mode; }
  ~TrimSwitch() { nc::nfp_trim_mode() = nc::kTrimAuto; }
};

std::vector<nc::NfpPiece> classify(const pendepth::PairDepth2::Impl& S, const std::vector<nc::NfpCandidate>& cands, int mode,
                                   nc::NfpTrimStats& stats) {
  TrimSwitch sw(mode);
  nc::nfp_trim_stats() = {};
  std::vector<nc::NfpPiece> out;
  nc::nfp_classify(S, cands, out);
  stats = nc::nfp_trim_stats();
  return out;
}

void same(const std::vector<nc::NfpPiece>& got, const std::vector<nc::NfpPiece>& ref, const std::string& what) {
  ASSERT_EQ(got.size(), ref.size()) << what;
  const Vec2 o(0, 0);
  for (std::size_t k = 0; k < ref.size(); ++k) {
    const nc::Ray& E = ref[k].E;
    ASSERT_TRUE(got[k].E.p0 == E.p0 && got[k].E.q0 == E.q0 && got[k].E.p1 == E.p1 && got[k].E.q1 == E.q1) << what << " piece " << k;
    ASSERT_EQ(nc::compare_params(got[k].lo, ref[k].lo, E, o), 0) << what << " piece " << k << " lo";
    ASSERT_EQ(nc::compare_params(got[k].hi, ref[k].hi, E, o), 0) << what << " piece " << k << " hi";
  }
}

// Pieces with the trimming on every candidate (kTrimAll, so every input exercises it), in its
// default mode and without it, and (with `cut`) the reference cutting; then the exported no-fit
// polygons of the builds with and without it.
void check(const Polygon& P, const Polygon& Q, const std::string& what, bool cut = true) {
  const pendepth::PairDepth2::Impl S(P, Q);
  const auto cands = nc::nfp_candidates(P, Q);
  nc::NfpTrimStats on, off, automatic;
  const auto got = classify(S, cands, nc::kTrimAll, on);
  const auto ref = classify(S, cands, nc::kTrimOff, off);
  same(got, ref, what + " (trim / no trim)");
  same(classify(S, cands, nc::kTrimAuto, automatic), ref, what + " (default / no trim)");
  if (cut) {
    std::vector<nc::NfpPiece> exact;
    for (const auto& c : cands)
      if (!c.redundant) nc::nfp_cut(S, c, exact);
    same(got, exact, what + " (trim / reference cutting)");
  }
  EXPECT_EQ(off.dead + off.trimmed, 0u) << what;
  pendepth::NoFitPolygon2 a = [&] {
    TrimSwitch sw(nc::kTrimAll);
    return pendepth::NoFitPolygon2(P, Q);
  }();
  pendepth::NoFitPolygon2 b = [&] {
    TrimSwitch sw(nc::kTrimOff);
    return pendepth::NoFitPolygon2(P, Q);
  }();
  ASSERT_EQ(nonconvex2_test::nfp_difference(a, b), "") << what;
  Totals& t = totals();
  ++t.pairs, t.dead += on.dead, t.trimmed += on.trimmed, t.meets_on += on.meets, t.meets_off += off.meets, t.pieces += ref.size();
}

Polygon L_shape(double s) {
  const std::vector<Vec2> L{{0, 0}, {0.5 * s, 0}, {0.5 * s, 2.5 * s}, {3 * s, 2.5 * s}, {3 * s, 3 * s}, {0, 3 * s}};
  return Polygon::simple(L, "L");
}

}  // namespace

// Dense stars (spikes closer than Q is wide): most candidates lie deep in O.
TEST(NfpTrim, DenseStars) {
  std::mt19937_64 rng(1919);
  for (int it = 0; it < pendepth_test::scaled(8); ++it) {
    const bool grid = it % 2;
    const double s = grid ? 40 : 1;  // integer stars need room between their vertices
    const int n = 200 + int(rng() % 300);
    const Polygon P = nonconvex2_test::star(rng, n, 60 * s, 100 * s, grid);
    const Polygon Q = it % 4 < 2 ? L_shape(s) : nonconvex2_test::star(rng, 6 + int(rng() % 20), 6 * s, 10 * s, grid);
    const std::string tag = std::to_string(it) + (grid ? " grid" : "");
    check(P, Q, "star / " + Q.name() + " " + tag, it < 4);
    check(Q, P, Q.name() + " / star " + tag, it < 1);
    if (grid) check(P, Polygon::simple(std::vector<Vec2>{{0, 0}, {2 * s, 0}, {2 * s, 2 * s}, {0, 2 * s}}, "square"), "star / square " + tag, false);
  }
}

// Spirals (a long winding pocket), combs with exact fits (slits) and polygons with holes.
TEST(NfpTrim, SpiralsCombsHoles) {
  std::mt19937_64 rng(2020);
  const Polygon spiral = Polygon::simple(polygon2_test::spiral_ring(20, 30 / (2 * polygon2_test::kPi), 1.5, 5, 400), "spiral");
  check(spiral, L_shape(1), "spiral / L");
  check(spiral, nonconvex2_test::star(rng, 12, 2, 6, false), "spiral / star");
  const Polygon comb = Polygon::simple(polygon2_test::comb_ring(150, 1, 1, 10, 2), "comb");
  const Polygon tooth = Polygon::simple(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 10}, {0, 10}}, "tooth");
  check(comb, tooth, "comb / tooth");
  check(comb, L_shape(1), "comb / L");
  for (int it = 0; it < pendepth_test::scaled(3); ++it) {
    const Polygon W = polygon2_test::random_polygon(rng, it % 2 ? 80 : 300, 1 + int(rng() % 3), it % 2);
    check(W, L_shape(1), "holes / L " + std::to_string(it));
    check(W, nonconvex2_test::star(rng, 8, 3, 8, it % 2), "holes / star " + std::to_string(it));
  }
  const Totals& t = totals();
  std::cout << "[nfp trim] pairs " << t.pairs << ", pieces " << t.pieces << " identical with and without the trimming; candidates "
            << t.dead << " certified whole in O, " << t.trimmed << " trimmed; pairs met " << t.meets_on << " (without: " << t.meets_off
            << ")\n";
  EXPECT_GT(t.dead, 0u);  // the comparisons are not vacuous
  EXPECT_GT(t.trimmed, 0u);
}

// The comparisons above are not vacuous: the trimming acted, and it removed most pair meetings
// on the dense stars.
TEST(NfpTrim, ActsOnStars) {
  std::mt19937_64 rng(77);
  const Polygon P = nonconvex2_test::star(rng, 3000, 60, 100, false);
  nc::NfpTrimStats on, off;
  const pendepth::PairDepth2::Impl S(P, L_shape(1));
  const auto cands = nc::nfp_candidates(P, L_shape(1));
  same(classify(S, cands, nc::kTrimAuto, on), classify(S, cands, nc::kTrimOff, off), "star 3000 / L");
  std::cout << "[nfp trim] star 3000 / L: " << cands.size() << " candidates, " << on.dead << " certified whole in O, " << on.trimmed
            << " trimmed; pairs met " << on.meets << " (without: " << off.meets << ")\n";
  EXPECT_GT(on.dead, cands.size() / 2);
  EXPECT_GT(on.trimmed, 0u);
  EXPECT_LT(4 * on.meets, off.meets);
}
