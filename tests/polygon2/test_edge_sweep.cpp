// Polygon validation step 2 (src/polygon2/edge_sweep.cpp): the O(N log N) Shamos–Hoey sweep, the
// box sweep and their combination check_edges (box sweep, budget exhausted, Shamos–Hoey) against
// the brute force over all edge pairs with the same pairwise rule
// (polygon2::edge_pair_violation, the rule the former box sweep applied) on random rings full of
// degeneracies, and the large families (star, comb, spiral of 10^5 vertices) accepted.
#include <pendepth/polygon.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <string>

#include "polygon2/edge_sweep.hpp"
#include "shapes.hpp"

namespace {

using pendepth::InvalidInput;
using pendepth::Polygon;
using pendepth::Vec2;
using polygon2_test::Rings;
namespace pg = pendepth::polygon2;

// Step 1's preconditions of the sweep: >= 3 vertices per ring, no repeated vertex within a ring.
bool preconditions(const Rings& rings) {
  for (const auto& r : rings) {
    if (r.size() < 3) return false;
    std::vector<std::pair<double, double>> v;
    for (const Vec2& p : r) v.emplace_back(p.x(), p.y());
    std::sort(v.begin(), v.end());
    if (std::adjacent_find(v.begin(), v.end()) != v.end()) return false;
  }
  return true;
}

// Every violating pair's message (with the "T: " prefix), all pairs.
std::set<std::string> brute_force(const Rings& rings) {
  std::set<std::string> msgs;
  for (std::size_t a = 0; a < rings.size(); ++a)
    for (std::size_t i = 0; i < rings[a].size(); ++i)
      for (std::size_t b = a; b < rings.size(); ++b)
        for (std::size_t j = b == a ? i + 1 : 0; j < rings[b].size(); ++j)
          if (auto m = pg::edge_pair_violation(rings, a, i, b, j)) msgs.insert("T: " + *m);
  return msgs;
}

// nullopt: accepted; else the message. impl 0: the Shamos–Hoey sweep alone; 1: the box sweep
// without budget; 2: check_edges with a budget of 1 pair per edge (the box sweep gives up early on
// most inputs and the Shamos–Hoey sweep finishes).
std::optional<std::string> run(const Rings& rings, int impl) {
  try {
    if (impl == 0) {
      pg::check_edges_sweep(rings, "T");
    } else if (impl == 1) {
      EXPECT_TRUE(pg::check_edges_boxes(rings, "T", std::numeric_limits<std::size_t>::max()));
    } else {
      pg::check_edges(rings, "T", 1);
    }
    return std::nullopt;
  } catch (const InvalidInput& e) {
    return std::string(e.what());
  }
}
std::optional<std::string> sweep(const Rings& rings) { return run(rings, 0); }

struct Tally {
  int accepted = 0, rejected = 0;
};

// Same verdict as the brute force; a rejection names one of the violating pairs.
void compare(const Rings& rings, Tally& t, const std::string& what) {
  if (!preconditions(rings)) return;
  const auto bf = brute_force(rings);
  for (int impl = 0; impl < 3; ++impl) {
    const auto sw = run(rings, impl);
    ASSERT_EQ(bf.empty(), !sw.has_value())
        << "impl " << impl << ": " << what
        << (sw ? ": rejected: " + *sw : ": accepted, brute force: " + *bf.begin());
    if (sw) EXPECT_TRUE(bf.count(*sw)) << "impl " << impl << ": " << what << ": " << *sw;
  }
  ++(bf.empty() ? t.accepted : t.rejected);
}

void report(const Tally& t) {
  std::printf("accepted %d, rejected %d\n", t.accepted, t.rejected);
}

std::string dump(const Rings& rings) {
  std::string s;
  for (const auto& r : rings) {
    s += "[";
    for (const Vec2& p : r) s += "(" + std::to_string(p.x()) + "," + std::to_string(p.y()) + ")";
    s += "]";
  }
  return s;
}

// Random walk of n vertices on the integer grid [0, g)^2: collinear, vertical, touching,
// folded-back edges galore.
std::vector<Vec2> grid_walk(std::mt19937_64& rng, int n, int g, Vec2 o = Vec2(0, 0)) {
  std::vector<Vec2> r;
  for (int k = 0; k < n; ++k) r.push_back(o + Vec2(double(rng() % g), double(rng() % g)));
  return r;
}

TEST(EdgeSweep, RandomGridWalks) {
  std::mt19937_64 rng(1901);
  Tally t;
  for (int it = 0; it < 6000; ++it) {
    const int g = 2 + int(rng() % 6), n = 3 + int(rng() % 9);
    Rings rings{grid_walk(rng, n, g)};
    compare(rings, t, dump(rings));
  }
  report(t);
  EXPECT_GT(t.accepted, 300);
  EXPECT_GT(t.rejected, 1000);
}

TEST(EdgeSweep, RandomStars) {
  std::mt19937_64 rng(1902);
  Tally t;
  for (int it = 0; it < 3000; ++it) {
    const int n = 3 + int(rng() % 40);
    const bool grid = it % 2 == 0;
    const double rmax = grid ? 3 + double(rng() % 8) : 100;
    Rings rings{polygon2_test::star_ring(rng, n, Vec2(0, 0), rmax / 3, rmax, grid)};
    if (it % 3 == 0) std::swap(rings[0][rng() % n], rings[0][rng() % n]);  // may cross
    if (it % 7 == 0) rings[0][rng() % n] = Vec2(0, 0);                       // spike to the centre
    compare(rings, t, dump(rings));
  }
  report(t);
  EXPECT_GT(t.accepted, 500);
  EXPECT_GT(t.rejected, 400);
}

// Outer ring and holes: small grids so that holes touch each other and the outer ring at
// vertices and along edges, or overlap; plus real-coordinate stars.
TEST(EdgeSweep, RandomRingsWithHoles) {
  std::mt19937_64 rng(1903);
  Tally t;
  for (int it = 0; it < 12000; ++it) {
    Rings rings;
    const int g = 6 + int(rng() % 5);
    if (it % 2 == 0) {
      rings.push_back({{0, 0}, {double(g), 0}, {double(g), double(g)}, {0, double(g)}});
    } else {
      rings.push_back(polygon2_test::star_ring(rng, 4 + int(rng() % 12), Vec2(g / 2.0, g / 2.0), g / 3.0, g / 1.5, true));
    }
    const int holes = 1 + int(rng() % 3);
    for (int k = 0; k < holes; ++k) {
      if (rng() % 2) {  // small triangle or quad anywhere on the grid (also on the outer ring)
        rings.push_back(grid_walk(rng, 3 + int(rng() % 2), 3, Vec2(double(rng() % (g - 1)), double(rng() % (g - 1)))));
      } else {
        const Vec2 c(1 + double(rng() % (g - 1)), 1 + double(rng() % (g - 1)));
        rings.push_back(polygon2_test::star_ring(rng, 3 + int(rng() % 4), c, 0.5, 2, true));
      }
      if (rng() % 2) std::reverse(rings.back().begin(), rings.back().end());
    }
    compare(rings, t, dump(rings));
  }
  report(t);
  EXPECT_GT(t.accepted, 500);
  EXPECT_GT(t.rejected, 2000);
}

TEST(EdgeSweep, RealCoordinateWalks) {
  std::mt19937_64 rng(1904);
  std::uniform_real_distribution<double> u(-1, 1);
  Tally t;
  for (int it = 0; it < 2000; ++it) {
    const int n = 3 + int(rng() % 8);
    std::vector<Vec2> r;
    for (int k = 0; k < n; ++k) r.emplace_back(u(rng), u(rng));
    // Degenerate extras: a vertex on a non-adjacent edge (exactly representable midpoint of a
    // dyadic edge) or a vertical pair.
    if (it % 4 == 1 && n >= 5) r[3] = Vec2(r[0].x(), 0.5);
    if (it % 4 == 2 && n >= 5) {
      r[0] = Vec2(0.25, 0.5);
      r[1] = Vec2(0.75, 0.5);
      r[3] = Vec2(0.5, 0.5);  // on edge 0
    }
    Rings rings{r};
    compare(rings, t, dump(rings));
  }
  report(t);
  EXPECT_GT(t.accepted, 200);
  EXPECT_GT(t.rejected, 500);
}

// Hand-made degeneracies, each with its expected verdict (and the brute force agreeing).
TEST(EdgeSweep, Degenerate) {
  struct Case {
    Rings rings;
    bool valid;
  };
  const std::vector<Vec2> sq{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const std::vector<Case> cases{
      {{sq}, true},
      {{{{0, 0}, {4, 0}, {4, 4}, {4, 2}, {0, 4}}}, false},           // fold back along a vertical
      {{{{0, 0}, {4, 0}, {2, 0}, {2, 3}}}, false},                    // fold back along a horizontal
      {{{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}}, false},           // vertex on a non-adjacent edge
      {{{{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}}, true},            // collinear pass-through vertex
      {{{{0, 0}, {0, 2}, {0, 4}, {-4, 4}, {-4, 0}}}, true},          // vertical pass-through
      {{{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}, {0, 2}}}, true},    // a notch
      {{{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {3, 2}, {4, 2}}}, false},   // vertex on a vertical edge
      {{sq, {{0, 0}, {2, 1}, {1, 2}}}, false},                        // hole touching the outer ring at a vertex
      {{sq, {{5, 0}, {6, 1}, {4, 1}}}, false},                        // hole vertex on an outer edge
      {{sq, {{0, 5}, {1, 4}, {1, 6}}}, false},                        // hole vertex on a vertical outer edge
      {{sq, {{1, 1}, {3, 1}, {3, 3}}, {{3, 3}, {5, 3}, {5, 5}}}, false},  // holes touching at a vertex
      {{sq, {{1, 1}, {3, 1}, {3, 3}}, {{3, 1}, {5, 1}, {5, 3}}}, false},  // holes sharing a vertex and a collinear edge
      {{sq, {{1, 1}, {3, 1}, {3, 3}}, {{4, 1}, {6, 1}, {6, 3}}}, true},
      {{sq, {{1, 1}, {3, 1}, {3, 3}}, {{2, 1}, {5, 1}, {5, 3}}}, false},  // overlapping collinear edges
      {{sq, {{2, 2}, {2, 8}, {3, 5}}, {{4, 2}, {4, 8}, {3.5, 5}}}, true},  // vertical edges side by side
      {{sq, {{2, 2}, {2, 8}, {3, 5}}, {{2, 4}, {1, 6}, {1, 3}}}, false},   // vertex on a vertical hole edge
  };
  for (std::size_t c = 0; c < cases.size(); ++c) {
    EXPECT_EQ(brute_force(cases[c].rings).empty(), cases[c].valid) << "case " << c;
    for (int impl = 0; impl < 3; ++impl)
      EXPECT_EQ(!run(cases[c].rings, impl).has_value(), cases[c].valid)
          << "case " << c << ", impl " << impl << ": " << run(cases[c].rings, impl).value_or("");
  }
}

// The families of issue 19 item 4 (bench/bench_polygon2.cpp), 10^5 vertices: accepted (the
// former box sweep was Θ(n²) on the star); one planted crossing in each: rejected.
TEST(EdgeSweep, LargeFamilies) {
  std::mt19937_64 rng(1905);
  const int n = 100000;
  std::vector<std::vector<Vec2>> rings;
  rings.push_back(polygon2_test::star_ring(rng, n, Vec2(0, 0), 60, 100, false));
  rings.push_back(polygon2_test::comb_ring(n / 4, 1, 3, 20, 2));
  rings.push_back(polygon2_test::spiral_ring(20, 30 / (2 * polygon2_test::kPi), 1.5, 5, n / 2));
  for (std::size_t k = 0; k < rings.size(); ++k) {
    const auto& r = rings[k];
    ASSERT_GE(r.size(), std::size_t(n / 2));
    EXPECT_NO_THROW(pg::check_edges_sweep(Rings{r}, "big"));
    // The box sweep decides the comb and the spiral within check_edges' budget; the star's box
    // pairs are Θ(n²), so there the Shamos–Hoey sweep runs.
    EXPECT_EQ(pg::check_edges_boxes(Rings{r}, "big", pg::kBoxBudgetPerEdge * r.size()), k != 0) << "family " << k;
    EXPECT_NO_THROW(Polygon(Rings{r}, "big"));
    std::vector<Vec2> bad = r;
    std::swap(bad[10], bad[bad.size() / 2]);  // two spikes across the ring
    EXPECT_THROW(Polygon(Rings{bad}, "big"), InvalidInput);
  }
}

}  // namespace
