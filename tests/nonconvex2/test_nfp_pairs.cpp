// The classification's step 1 pair search (src/nonconvex2/nfp_classify.cpp sweep_pairs: the
// candidates' boxes sorted on x and swept, within a budget of tests; after step 0 the pairs whose
// trimmed boxes still meet, keep_active_pairs) against the box tree's descents (nc::nfp_pairs_mode()
// = kPairsTree, the method before the sweep) and against the reference cutting (nfp_cut.cpp): the
// same pieces piece by piece (candidate, exact ends by compare_params, in the same order), under
// each trimming mode (off, auto, on every candidate: the sweep's pairs filtered by the trimmed
// boxes), as many pairs met, and the same exported no-fit polygon bit for bit. Both searches meet
// the pairs in canonical order, so the pieces agree bit for bit when the pairs do. Inputs: nesting pieces
// (baldacci4, albano), integer histograms
// against histograms with straight vertices (boxes of zero width and exact touches), dense stars
// (the sweep over its budget: the tree's path), hairline histograms (candidates' boxes touching
// exactly in x and in y: closed boxes meet, both searches must report the pair). Both paths must
// act. Pinned seeds.
#include <gtest/gtest.h>

#include <pendepth/nfp2.hpp>

#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <string>

#include "nfp_compare.hpp"
#include "nfp_shapes.hpp"
#include "nonconvex2/nfp_impl.hpp"

namespace {

using pendepth::Polygon;
using pendepth::Vec2;
namespace nc = pendepth::nonconvex2;
using nonconvex2_test::nfp_difference;
using nonconvex2_test::piece_difference;

// Sets both modes for a scope (nfp_compare.hpp).
struct Modes : nonconvex2_test::ScopedModes {
  Modes(int pairs, int trim) : ScopedModes(nc::nfp_pairs_mode(), pairs, nc::kPairsAuto, trim) {}
};

struct Totals {
  std::size_t pairs = 0, pieces = 0, swept = 0, tree_joins = 0;
};
Totals& totals() {
  static Totals t;
  return t;
}

// The pieces, and in `meets` the number of candidate pairs met in step 1.
std::vector<nc::NfpPiece> classify(const pendepth::PairDepth2::Impl& S, const std::vector<nc::NfpCandidate>& cands, int pairs, int trim,
                                   std::size_t& meets) {
  Modes m(pairs, trim);
  nc::nfp_trim_stats() = {};
  std::vector<nc::NfpPiece> out;
  nc::nfp_classify(S, cands, out);
  if (pairs == nc::kPairsAuto) totals().swept += nc::nfp_trim_stats().swept, totals().tree_joins += nc::nfp_trim_stats().tree_joins;
  meets = nc::nfp_trim_stats().meets;
  return out;
}

// Pieces by the sweep against the tree's, under each trimming mode; (with `cut`) against the
// reference cutting; the exported no-fit polygons bit for bit.
void check(const Polygon& P, const Polygon& Q, const std::string& what, bool cut = false) {
  const pendepth::PairDepth2::Impl S(P, Q);
  const auto cands = nc::nfp_candidates(P, Q);
  std::vector<nc::NfpPiece> ref;
  for (const int trim : {nc::kTrimOff, nc::kTrimAuto, nc::kTrimAll}) {
    std::size_t meets_tree = 0, meets_sweep = 0;
    const auto tree = classify(S, cands, nc::kPairsTree, trim, meets_tree);
    const auto sweep = classify(S, cands, nc::kPairsAuto, trim, meets_sweep);
    ASSERT_EQ(piece_difference(sweep, tree), "") << what << " (sweep / tree, trim mode " << trim << ")";
    // A missing pair may split nothing (an end shared with a neighbour that meets anyway): the
    // pairs themselves are compared too (the sweep finds only box-overlapping pairs, each once).
    ASSERT_EQ(meets_sweep, meets_tree) << what << " (pairs met, trim mode " << trim << ")";
    if (trim == nc::kTrimOff) ref = tree;
  }
  if (cut) {
    std::vector<nc::NfpPiece> exact;
    for (const auto& c : cands)
      if (!c.redundant) nc::nfp_cut(S, c, exact);
    ASSERT_EQ(piece_difference(ref, exact), "") << what << " (sweep / reference cutting)";
  }
  auto build = [&](int pairs) {
    Modes m(pairs, nc::kTrimAuto);
    return pendepth::NoFitPolygon2(P, Q);
  };
  const pendepth::NoFitPolygon2 a = build(nc::kPairsAuto), b = build(nc::kPairsTree);
  ASSERT_EQ(nfp_difference(a, b), "") << what;
  ++totals().pairs, totals().pieces += ref.size();
}

// The least double b > a whose conservative box side meets a's exactly, lower(b) = upper(a),
// under nfp_build.cpp's box rounding (lower(x) = x − |x| · 2⁻⁴⁴ − 2⁻¹⁰⁰⁰, upper(x) = x + |x| ·
// 2⁻⁴⁴ + 2⁻¹⁰⁰⁰; a ≥ 1). Restated here to build the inputs only: the test counts the exact
// touches on the candidates' real boxes and fails when there are none.
double touching(double a) {
  const double up = a + std::abs(a) * 0x1p-44 + 0x1p-1000;
  double b = up;
  while (b - std::abs(b) * 0x1p-44 - 0x1p-1000 < up) b = std::nextafter(b, INFINITY);
  return b;
}

// A histogram (columns of integer heights in [1, hmax] on [i, i + 1]) with hairline columns
// [i, touching(i)] at about half the inner column boundaries and, for about a third of the
// columns, the height touching(h) of the column on its left. With a Q that has vertices at x = 0
// and at y = 0 (histogram()), the candidates' boxes touch exactly: in x, the vertical edges at i
// and touching(i) (sums with Q's vertices of x = 0, rounded exactly); in y, the tops at h and
// touching(h) (Q's vertices of y = 0). The segments themselves do not meet.
Polygon hairline_histogram(std::mt19937_64& rng, int k, int hmax) {
  std::vector<double> x{0}, h;
  for (int i = 0; i < k; ++i) {
    h.push_back(!h.empty() && rng() % 3 == 0 ? touching(h.back()) : 1 + double(rng() % hmax));
    x.push_back(i + 1);
    if (i + 1 < k && rng() % 2) h.push_back(1 + double(rng() % hmax)), x.push_back(touching(i + 1));
  }
  std::vector<Vec2> r{{0, 0}, {x.back(), 0}};
  for (std::size_t i = h.size(); i-- > 0;) {
    r.emplace_back(x[i + 1], h[i]);
    if (i == 0 || h[i - 1] != h[i]) r.emplace_back(x[i], h[i]);
  }
  return Polygon::simple(r, "hairline histogram");
}

// The candidate pairs of P ⊕ (−Q) whose boxes touch exactly in x (lo.x of one = hi.x of the
// other) and meet in y, and the converse.
std::array<std::size_t, 2> touching_boxes(const Polygon& P, const Polygon& Q) {
  const auto c = nc::nfp_candidates(P, Q);
  std::array<std::size_t, 2> n{0, 0};
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = 0; j < c.size(); ++j) {
      const bool mx = c[i].lo.x() <= c[j].hi.x() && c[j].lo.x() <= c[i].hi.x();
      const bool my = c[i].lo.y() <= c[j].hi.y() && c[j].lo.y() <= c[i].hi.y();
      n[0] += c[i].lo.x() == c[j].hi.x() && my;
      n[1] += c[i].lo.y() == c[j].hi.y() && mx;
    }
  return n;
}

}  // namespace

TEST(NfpPairs, NestingPieces) {
  for (const char* name : {"baldacci4", "albano"}) {
    auto polys = nonconvex2_test::instance(std::string(name) + ".json");
    ASSERT_GE(polys.size(), 5u) << name;
    polys.erase(polys.begin() + 5, polys.end());
    for (std::size_t i = 0; i < polys.size(); ++i)
      for (std::size_t j = 0; j < polys.size(); ++j) check(polys[i], polys[j], polys[i].name() + " / " + polys[j].name(), i == j);
  }
}

TEST(NfpPairs, HistogramsAndStars) {
  std::mt19937_64 rng(1919);
  for (int it = 0; it < 6; ++it) {
    const Polygon P = nonconvex2_test::histogram(rng, 20 + int(rng() % 30), 8), Q = nonconvex2_test::histogram(rng, 4 + int(rng() % 10), 6);
    const std::string tag = " " + std::to_string(it);
    check(P, Q, "histograms" + tag, it < 2);
    check(nonconvex2_test::subdivided(Q), P, "straight histogram / histogram" + tag, it < 1);
  }
  for (int it = 0; it < 2; ++it) {
    const bool grid = it % 2;
    const double s = grid ? 40 : 1;
    const Polygon P = nonconvex2_test::star(rng, 300 + int(rng() % 200), 60 * s, 100 * s, grid);
    const Polygon Q = nonconvex2_test::star(rng, 6 + int(rng() % 10), 6 * s, 10 * s, grid);
    check(P, Q, "star / star " + std::to_string(it) + (grid ? " grid" : ""));
  }
  const Totals& t = totals();
  std::cout << "[nfp pairs] " << t.pairs << " pairs, " << t.pieces << " pieces identical by sweep and tree; step 1 by the sweep "
            << t.swept << " times, by the tree " << t.tree_joins << " times\n";
  EXPECT_GT(t.swept, 0u);
  EXPECT_GT(t.tree_joins, 0u);
}

// Closed boxes that touch exactly (a comparison < instead of <= in the sweep's x or y test would
// drop these pairs: the pairs met differ from the tree's). Large pairs (K > 64: the sweep runs).
TEST(NfpPairs, TouchingBoxes) {
  std::mt19937_64 rng(2611);
  std::size_t touch_x = 0, touch_y = 0;
  const std::size_t swept = totals().swept;
  for (int it = 0; it < 4; ++it) {
    const Polygon P = hairline_histogram(rng, 20 + int(rng() % 20), 8);
    const Polygon Q = it % 2 ? hairline_histogram(rng, 4 + int(rng() % 6), 6) : nonconvex2_test::histogram(rng, 4 + int(rng() % 10), 6);
    ASSERT_GT(nc::nfp_candidates(P, Q).size(), 64u);
    const auto n = touching_boxes(P, Q);
    touch_x += n[0], touch_y += n[1];
    check(P, Q, "hairline histogram / " + Q.name() + " " + std::to_string(it), it < 1);
  }
  std::cout << "[nfp pairs] hairline histograms: " << touch_x << " candidate pairs with boxes touching in x, " << touch_y
            << " in y\n";
  EXPECT_GT(touch_x, 0u);
  EXPECT_GT(touch_y, 0u);
  EXPECT_GT(totals().swept, swept);
}
