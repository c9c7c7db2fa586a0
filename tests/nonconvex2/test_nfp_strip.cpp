// The Steiner pieces for the fans of a long edge (src/nonconvex2/strip_pieces.cpp, used by the
// classification's large path through ShapeSide::pieces; issue 19 item 4, a comb rotated by 45°)
// against the same classification with the Hertel–Mehlhorn parts as they are
// (nc::nfp_strip_mode() = kStripOff, the method before) and against the reference cutting
// (nfp_cut.cpp, independent of any decomposition): the same pieces piece by piece (candidate,
// exact ends by compare_params, in the same order), with the trimming step off (every candidate's
// parts meet the point tests) and in its default mode, and the same exported no-fit polygon bit
// for bit. Inputs: combs rotated by 45° with rounded coordinates (the case: a base whose top is
// not collinear, so the parts fan to the base's far corners) against an L, a rotated tooth and
// the roles swapped; integer combs with bumpy gap bottoms rotated exactly (x − y, x + y), against
// a tooth that fits the gaps exactly (slits); stars, spirals, polygons with holes. The re-covering
// must act on the rotated combs (regions replaced), and a planted wrong cover (kStripPlanted: two
// pieces left out) must change the pieces: the comparison can fail. Pinned seeds.
#include <gtest/gtest.h>

#include <pendepth/nfp2.hpp>

#include <cmath>
#include <iostream>
#include <random>
#include <string>

#include "nfp_compare.hpp"
#include "nfp_shapes.hpp"
#include "nonconvex2/nfp_impl.hpp"
#include "nonconvex2/strip_pieces.hpp"
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
  Modes(int strip, int trim) : ScopedModes(nc::nfp_strip_mode(), strip, nc::kStripOn, trim) {}
};

// The pieces are made per side on first use: a fresh pair per mode.
std::vector<nc::NfpPiece> classify(const Polygon& P, const Polygon& Q, int strip, int trim, std::size_t* replaced = nullptr) {
  Modes m(strip, trim);
  nc::nfp_strip_stats() = {};
  const pendepth::PairDepth2::Impl S(P, Q);
  const auto cands = nc::nfp_candidates(P, Q);
  std::vector<nc::NfpPiece> out;
  nc::nfp_classify(S, cands, out);
  if (replaced) *replaced += nc::nfp_strip_stats().replaced;
  return out;
}

struct Totals {
  std::size_t pairs = 0, pieces = 0, replaced = 0, planted_caught = 0, planted_tried = 0;
};
Totals& totals() {
  static Totals t;
  return t;
}

// Pieces with the re-covering against without it, under two trimming modes, (with `cut`) against
// the reference cutting, the exported no-fit polygons bit for bit, and (with `plant`) whether the
// planted wrong cover changes the pieces. Returns the regions replaced.
std::size_t check(const Polygon& P, const Polygon& Q, const std::string& what, bool cut = false, bool plant = false) {
  Totals& t = totals();
  std::size_t replaced = 0;
  std::vector<nc::NfpPiece> ref;
  for (const int trim : {nc::kTrimOff, nc::kTrimAuto}) {
    const auto off = classify(P, Q, nc::kStripOff, trim);
    const auto on = classify(P, Q, nc::kStripOn, trim, &replaced);
    EXPECT_EQ(piece_difference(on, off), "") << what << " (Steiner pieces / parts, trim mode " << trim << ")";
    if (trim == nc::kTrimOff) ref = off;
  }
  if (cut) {
    const pendepth::PairDepth2::Impl S(P, Q);
    std::vector<nc::NfpPiece> exact;
    for (const auto& c : nc::nfp_candidates(P, Q))
      if (!c.redundant) nc::nfp_cut(S, c, exact);
    EXPECT_EQ(piece_difference(classify(P, Q, nc::kStripOn, nc::kTrimOff), exact), "") << what << " (Steiner pieces / reference cutting)";
  }
  if (plant) {
    ++t.planted_tried;
    const bool caught = !piece_difference(classify(P, Q, nc::kStripPlanted, nc::kTrimOff), ref).empty();
    t.planted_caught += caught;
    if (caught) std::cout << "[nfp strip] planted wrong cover caught on " << what << "\n";
  }
  auto build = [&](int strip) {
    Modes m(strip, nc::kTrimAuto);
    return pendepth::NoFitPolygon2(P, Q);
  };
  const pendepth::NoFitPolygon2 a = build(nc::kStripOn), b = build(nc::kStripOff);
  EXPECT_EQ(nfp_difference(a, b), "") << what;
  ++t.pairs, t.pieces += ref.size(), t.replaced += replaced;
  return replaced;
}

Polygon L_shape(double s) {
  const std::vector<Vec2> L{{0, 0}, {0.5 * s, 0}, {0.5 * s, 2.5 * s}, {3 * s, 2.5 * s}, {3 * s, 3 * s}, {0, 3 * s}};
  return Polygon::simple(L, "L");
}

// Rotated by 45° as a user would (cos and sin of π/4 differ in the last bit), rounded.
Polygon turned(const Polygon& S) {
  const double c = std::cos(polygon2_test::kPi / 4), s = std::sin(polygon2_test::kPi / 4);
  return nonconvex2_test::mapped(S, [&](const Vec2& p) { return Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y()); });
}

// Exactly rotated by 45° and scaled by √2: (x − y, x + y), integers stay integers.
Polygon turned_exact(const Polygon& S) {
  return nonconvex2_test::mapped(S, [&](const Vec2& p) { return Vec2(p.x() - p.y(), p.x() + p.y()); });
}

// An integer comb: teeth and gaps S = 2²⁰ wide, 10·S high, base 2·S high, the right end of
// every gap's bottom raised by one unit (so the base's top is not collinear, by a hair, and its
// parts fan to the base's far corners); a tooth S wide fits every gap exactly.
constexpr double kS = 1 << 20;
Polygon bumpy_comb(int teeth) {
  auto r = polygon2_test::comb_ring(teeth, kS, kS, 10 * kS, 2 * kS);
  for (std::size_t i = 2; i < r.size(); ++i)
    if (r[i].y() == 2 * kS && std::fmod(r[i].x(), 2 * kS) == 0 && r[i].x() > 0) r[i].y() += 1;
  return Polygon::simple(r, "bumpy comb");
}

}  // namespace

// The case the pieces are for: combs rotated by 45° (rounded), against an L (whose arm enters
// the gaps), a rotated tooth, and the roles swapped; the reference cutting on the smaller ones.
TEST(NfpStrip, RotatedCombs) {
  for (const int teeth : {150, pendepth_test::scaled(1) > 1 ? 600 : 300}) {
    const Polygon comb = turned(Polygon::simple(polygon2_test::comb_ring(teeth, 1, 1, 10, 2), "comb"));
    const std::string tag = std::to_string(teeth) + " teeth";
    EXPECT_GT(check(comb, L_shape(1), "comb 45° / L " + tag, teeth <= 150, true), 0u) << tag << ": no region re-covered";
    check(comb, turned(Polygon::simple(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 10}, {0, 10}}, "tooth")), "comb 45° / tooth 45° " + tag,
          teeth <= 150, true);
    check(L_shape(1), comb, "L / comb 45° " + tag, teeth <= 150);
  }
}

// Exact fits: integer combs with bumpy gap bottoms, rotated exactly, against a tooth that slides
// in every gap (slits) and against an L; unrotated too.
TEST(NfpStrip, ExactFits) {
  for (const int teeth : {200, pendepth_test::scaled(1) > 1 ? 500 : 260}) {
    const Polygon comb = bumpy_comb(teeth), rot = turned_exact(comb);
    const Polygon tooth = Polygon::simple(std::vector<Vec2>{{0, 0}, {kS, 0}, {kS, 10 * kS}, {0, 10 * kS}}, "tooth");
    const std::string tag = std::to_string(teeth) + " teeth";
    EXPECT_GT(check(rot, turned_exact(tooth), "bumpy comb 45° / tooth 45° " + tag, teeth <= 200, true), 0u) << tag;
    const pendepth::NoFitPolygon2 fit(rot, turned_exact(tooth));
    EXPECT_GT(fit.slits().size(), 0u) << tag << ": the tooth should fit the gaps exactly";
    check(rot, turned_exact(L_shape(kS)), "bumpy comb 45° / L " + tag, false, true);
    EXPECT_GT(check(comb, tooth, "bumpy comb / tooth " + tag, false, true), 0u) << tag;
  }
}

// Other families: whatever the re-covering does there (it may act or not), the same answers.
TEST(NfpStrip, StarsSpiralsHoles) {
  std::mt19937_64 rng(5151);
  for (int it = 0; it < pendepth_test::scaled(4); ++it) {
    const bool grid = it % 2;
    const double s = grid ? 40 : 1;
    const Polygon P = nonconvex2_test::star(rng, 300 + int(rng() % 400), 60 * s, 100 * s, grid);
    check(P, L_shape(s), "star / L " + std::to_string(it), it < 2, true);
    check(L_shape(s), P, "L / star " + std::to_string(it));
  }
  const Polygon spiral = Polygon::simple(polygon2_test::spiral_ring(20, 30 / (2 * polygon2_test::kPi), 1.5, 5, 400), "spiral");
  check(spiral, L_shape(1), "spiral / L", true);
  check(turned(spiral), L_shape(1), "spiral 45° / L");
  for (int it = 0; it < pendepth_test::scaled(2); ++it) {
    const Polygon W = polygon2_test::random_polygon(rng, it % 2 ? 80 : 300, 1 + int(rng() % 3), it % 2);
    check(W, L_shape(1), "holes / L " + std::to_string(it));
  }
}

// The comparisons are not vacuous: regions were re-covered, and the planted wrong cover (one piece
// left out) was caught.
TEST(NfpStrip, ActsAndPlantedBugIsCaught) {
  const Totals& t = totals();
  std::cout << "[nfp strip] pairs " << t.pairs << ", pieces " << t.pieces << " identical; regions re-covered " << t.replaced
            << "; planted wrong cover caught on " << t.planted_caught << " of " << t.planted_tried << " inputs\n";
  const Polygon comb = bumpy_comb(200);
  const Polygon tooth = Polygon::simple(std::vector<Vec2>{{0, 0}, {kS, 0}, {kS, 10 * kS}, {0, 10 * kS}}, "tooth");
  const auto ref = classify(comb, tooth, nc::kStripOff, nc::kTrimOff);
  std::size_t replaced = 0;
  EXPECT_EQ(piece_difference(classify(comb, tooth, nc::kStripOn, nc::kTrimOff, &replaced), ref), "");
  EXPECT_GT(replaced, 0u);
  const std::string planted = piece_difference(classify(comb, tooth, nc::kStripPlanted, nc::kTrimOff), ref);
  std::cout << "[nfp strip] bumpy comb / tooth, 200 teeth: planted wrong cover " << (planted.empty() ? "not caught" : "caught (" + planted + ")")
            << "\n";
  EXPECT_NE(planted, "");
  if (t.planted_tried > 0) EXPECT_GT(t.planted_caught, 0u);  // after the tests above (same executable, default order)
}
