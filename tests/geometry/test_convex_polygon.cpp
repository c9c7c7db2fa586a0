#include <pendepth/polygon.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using pendepth::ConvexPolygon;
using pendepth::InvalidInput;
using pendepth::Vec2;

namespace {
std::string error_of(std::vector<Vec2> ring, const char* name = "Q") {
  try {
    ConvexPolygon P(ring, name);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}
void expect_normal_form(const ConvexPolygon& P) {
  const std::size_t n = P.size();
  ASSERT_GE(n, 3u);
  for (std::size_t i = 1; i < n; ++i)
    EXPECT_TRUE(P[0].y() < P[i].y() || (P[0].y() == P[i].y() && P[0].x() < P[i].x()));
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_EQ(pendepth::predicates::orient2d(P[i], P[(i + 1) % n], P[(i + 2) % n]), 1);
}
}  // namespace

TEST(ConvexPolygon, NormalFormFromClockwiseWithClosingVertexDuplicatesAndCollinear) {
  std::vector<Vec2> ring = {{2, 2}, {2, 0}, {2, 0}, {1, 0}, {0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2}};
  ConvexPolygon P(ring);
  ASSERT_EQ(P.size(), 4u);
  expect_normal_form(P);
  EXPECT_EQ(P[0], Vec2(0, 0));
  EXPECT_EQ(P[1], Vec2(2, 0));
  EXPECT_EQ(P.input_index(0), 4u);
  EXPECT_EQ(P[P.top()], Vec2(2, 2));
  EXPECT_DOUBLE_EQ(P.area(), 4.0);
}

TEST(ConvexPolygon, Errors) {
  EXPECT_NE(error_of({{0, 0}, {1, 0}}).find("fewer than 3 distinct points"), std::string::npos);
  EXPECT_NE(error_of({{0, 0}, {1, 0}, {0, 0}, {1, 0}}).find("fewer than 3 distinct points"), std::string::npos);
  EXPECT_NE(error_of({{0, 0}, {1, 1}, {2, 2}, {3, 3}}).find("zero area"), std::string::npos);
  std::string nonconvex = error_of({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}});
  EXPECT_NE(nonconvex.find("not convex: reflex vertex 3"), std::string::npos) << nonconvex;
  EXPECT_NE(nonconvex.find("Q:"), std::string::npos);
  double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_NE(error_of({{0, 0}, {1, nan}, {0, 1}}).find("vertex 1 has a non-finite"), std::string::npos);
  EXPECT_NE(error_of({{0, 0}, {1, 0}, {inf, 1}}).find("vertex 2 has a non-finite"), std::string::npos);
  std::string bowtie = error_of({{0, 0}, {2, 2}, {2, 0}, {0, 2}});
  EXPECT_NE(bowtie.find("self-intersecting"), std::string::npos) << bowtie;
  // A pentagram: every turn has the same sign but the ring winds twice.
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k) star.emplace_back(std::cos(4 * M_PI * k / 5), std::sin(4 * M_PI * k / 5));
  std::string s = error_of(star);
  EXPECT_NE(s.find("winds 2 times"), std::string::npos) << s;
  std::string spike = error_of({{0, 0}, {2, 0}, {4, 0}, {3, 0}, {2, 2}});
  EXPECT_NE(spike.find("spike"), std::string::npos) << spike;
}

TEST(ConvexPolygon, HullOfRandomPointsIsNormalFormAndContainsAll) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> coord(-5, 5);
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<Vec2> pts;
    for (int k = 0; k < 30; ++k) pts.emplace_back(coord(rng), coord(rng));
    ConvexPolygon H = ConvexPolygon::hull(pts);
    expect_normal_form(H);
    for (const Vec2& p : pts)
      for (std::size_t i = 0; i < H.size(); ++i)
        ASSERT_GE(pendepth::predicates::orient2d(H[i], H.at_cyclic(i + 1), p), 0);
    // Re-validating the hull as a ring is the identity.
    ConvexPolygon R(H.vertices());
    ASSERT_EQ(R.size(), H.size());
    for (std::size_t i = 0; i < H.size(); ++i) ASSERT_EQ(R[i], H[i]);
  }
}
