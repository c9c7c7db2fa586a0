#include <pendepth/geometry.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using pendepth::Vec2;
namespace pr = pendepth::predicates;

TEST(Predicates, Orient2dBasic) {
  EXPECT_EQ(pr::orient2d({0, 0}, {1, 0}, {0, 1}), 1);
  EXPECT_EQ(pr::orient2d({0, 0}, {1, 0}, {0, -1}), -1);
  EXPECT_EQ(pr::orient2d({0, 0}, {1, 1}, {2, 2}), 0);
}

// Points on the line y = x at tiny perturbations: the naive double formula gets signs wrong
// (Kettner et al., "Classroom examples of robustness problems"); the exact sign is known by
// construction because (0.5 + k·ulp) is exactly representable.
TEST(Predicates, Orient2dNearDegenerateMatchesExactConstruction) {
  const Vec2 a(12, 12), b(24, 24);
  const double base = 0.5, ulp = std::nextafter(0.5, 1.0) - 0.5;
  for (int i = -64; i <= 64; ++i)
    for (int j = -64; j <= 64; ++j) {
      Vec2 c(base + i * ulp, base + j * ulp);
      int expected = (j > i) ? 1 : (j < i ? -1 : 0);  // c above the diagonal ⇔ y > x
      ASSERT_EQ(pr::orient2d(a, b, c), expected) << i << "," << j;
    }
}

TEST(Predicates, LargeOffsetsExact) {
  // Collinear points far from the origin: exact zero despite huge cancellation.
  const double o = 1e15;
  EXPECT_EQ(pr::orient2d({o, o}, {o + 1, o + 1}, {o + 3, o + 3}), 0);
  EXPECT_EQ(pr::orient2d({o, o}, {o + 1, o + 1}, {o + 3, o + 4}), 1);
  EXPECT_EQ(pr::cross_edges({o, 0}, {o + 1, 1}, {-o, 2}, {-o + 2, 4}), 0);
}

TEST(Predicates, CompareAngleIsATotalOrderOnDirections) {
  // 16 directions in increasing angle from +x.
  std::vector<Vec2> dirs = {{1, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 1}, {-1, 2}, {-1, 1}, {-2, 1},
                            {-1, 0}, {-2, -1}, {-1, -1}, {-1, -2}, {0, -1}, {1, -2}, {1, -1}, {2, -1}};
  const Vec2 z(0, 0);
  for (std::size_t i = 0; i < dirs.size(); ++i)
    for (std::size_t j = 0; j < dirs.size(); ++j) {
      int expected = i < j ? -1 : (i > j ? 1 : 0);
      EXPECT_EQ(pr::compare_angle(z, dirs[i], z, dirs[j]), expected) << i << " " << j;
      EXPECT_EQ(pr::compare_angle(z, dirs[i], z, 3.0 * dirs[j]), expected);
    }
}

TEST(Predicates, DotEdges) {
  EXPECT_EQ(pr::dot_edges({0, 0}, {1, 0}, {5, 5}, {5, 7}), 0);
  EXPECT_EQ(pr::dot_edges({0, 0}, {1, 0}, {5, 5}, {6, 7}), 1);
  EXPECT_EQ(pr::dot_edges({0, 0}, {1, 0}, {5, 5}, {4, 7}), -1);
}
