// Polygon (with holes): every validation message, and the normal form.
#include <pendepth/polygon.hpp>

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <limits>

#include "shapes.hpp"

namespace {

using pendepth::InvalidInput;
using pendepth::Polygon;
using pendepth::Vec2;
using polygon2_test::Rings;

// The constructor must throw InvalidInput whose message contains every fragment.
void expect_invalid(const Rings& rings, std::initializer_list<const char*> fragments) {
  try {
    Polygon P(rings, "P");
    ADD_FAILURE() << "accepted invalid rings; expected: " << *fragments.begin();
  } catch (const InvalidInput& e) {
    std::string msg = e.what();
    EXPECT_EQ(msg.rfind("P: ", 0), 0u) << msg;
    for (const char* f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "missing '" << f << "' in: " << msg;
  }
}

const std::vector<Vec2> kSquare{{0, 0}, {10, 0}, {10, 10}, {0, 10}};

TEST(PolygonValidation, Messages) {
  expect_invalid({}, {"no rings"});
  expect_invalid({{{0, 0}, {1, 0}}}, {"ring 0 (outer)", "fewer than 3 distinct points (2)"});
  expect_invalid({{{0, 0}, {1, 0}, {0, 0}, {1, 0}}}, {"ring 0", "fewer than 3 distinct"});
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  expect_invalid({{{0, 0}, {1, 0}, {nan, 1}}}, {"ring 0", "vertex 2", "non-finite"});
  expect_invalid({kSquare, {{1, 1}, {inf, 1}, {1, 2}}}, {"ring 1 (hole 1)", "vertex 1", "non-finite"});
  expect_invalid({{{0, 0}, {4, 0}, {4, 4}, {4, 0}, {0, 4}}}, {"ring 0", "vertices 1 and 3 coincide"});
  expect_invalid({{{0, 0}, {1, 1}, {3, 3}, {2, 2}}}, {"ring 0", "zero area"});
  // Bow tie: edges 0 and 2 cross.
  expect_invalid({{{0, 0}, {4, 4}, {4, 0}, {0, 4}}}, {"ring 0", "self-intersecting", "edges 0 and 2"});
  // A vertex touching a non-adjacent edge.
  expect_invalid({{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}}, {"self-intersecting", "edges"});
  // Spike: edges 1 and 2 fold back along the same line (edge 3 then starts on edge 1).
  expect_invalid({{{0, 0}, {4, 0}, {4, 4}, {4, 2}, {0, 4}}}, {"ring 0", "self-intersecting", "edges 1 and"});
  expect_invalid({kSquare, {{2, 2}, {3, 2}, {2, 3}, {3, 3}}}, {"ring 1 (hole 1)", "self-intersecting"});
  // Hole outside the outer ring, hole crossing it, hole touching it at a vertex.
  expect_invalid({kSquare, {{20, 20}, {21, 20}, {21, 21}}}, {"ring 1 (hole 1) lies outside the outer ring"});
  expect_invalid({kSquare, {{8, 8}, {12, 8}, {12, 9}}}, {"ring 0 (outer) and ring 1 (hole 1) touch or cross"});
  expect_invalid({kSquare, {{10, 5}, {8, 4}, {8, 6}}}, {"ring 0 (outer) and ring 1 (hole 1) touch or cross"});
  // Holes overlapping, touching, nested.
  expect_invalid({kSquare, {{1, 1}, {4, 1}, {4, 4}}, {{3, 1}, {5, 1}, {5, 3}}}, {"ring 1 (hole 1) and ring 2 (hole 2) touch or cross"});
  expect_invalid({kSquare, {{1, 1}, {4, 1}, {4, 4}}, {{4, 4}, {6, 4}, {6, 6}}}, {"ring 1 (hole 1) and ring 2 (hole 2) touch or cross"});
  expect_invalid({kSquare, {{1, 1}, {9, 1}, {9, 9}, {1, 9}}, {{4, 4}, {5, 4}, {5, 5}}}, {"ring 2 (hole 2) lies inside ring 1 (hole 1)"});
}

TEST(PolygonValidation, AcceptsValidInputs) {
  // Closing vertex dropped, collinear pass-through vertices kept.
  Polygon a(Rings{{{0, 0}, {5, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}}});
  EXPECT_EQ(a.size(), 5u);
  EXPECT_EQ(a.area(), 100);
  // Clockwise outer ring and counter-clockwise hole are normalised.
  Polygon b(Rings{{{0, 0}, {0, 10}, {10, 10}, {10, 0}}, {{2, 2}, {4, 2}, {4, 4}, {2, 4}}});
  ASSERT_EQ(b.ring_count(), 2u);
  EXPECT_EQ(b.area(), 96);
  for (std::size_t k = 0; k < b.ring_count(); ++k) {
    auto r = b.ring(k);
    mpq_class a2 = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Vec2 &p = r[i], &q = r[(i + 1) % r.size()];
      a2 += mpq_class(p.x()) * q.y() - mpq_class(p.y()) * q.x();
    }
    EXPECT_EQ(sgn(a2), k == 0 ? 1 : -1) << "ring " << k;
    EXPECT_EQ(b.input_index(b.ring_offset(k)), 0u);
  }
  EXPECT_EQ(b.ring(0)[1], Vec2(10, 0));  // reversed: input 0, 3, 2, 1
  EXPECT_EQ(b.input_index(1), 3u);
  for (std::size_t g = 0; g < b.size(); ++g) EXPECT_EQ(b.ring_of(b.next(g)), b.ring_of(g));
  EXPECT_EQ(b.next(3), 0u);
  EXPECT_EQ(b.next(7), 4u);
}

TEST(PolygonValidation, RandomAndNestingPiecesAreAccepted) {
  std::mt19937_64 rng(20240611);
  for (int it = 0; it < 200; ++it) {
    Polygon P = polygon2_test::random_polygon(rng, 5 + it % 40, it % 4, it % 2 == 0);
    EXPECT_EQ(P.ring_count(), static_cast<std::size_t>(1 + it % 4));
    EXPECT_GT(P.area(), 0);
  }
  for (const char* f : {"albano.json", "shirts.json", "trousers.json"})
    for (const auto& piece : polygon2_test::nesting_pieces(f)) EXPECT_NO_THROW(Polygon::simple(piece, f));
  EXPECT_NO_THROW(Polygon::simple(polygon2_test::comb_ring(5, 2, 3, 20, 4)));
}

}  // namespace
