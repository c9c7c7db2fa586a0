#include <pendepth/depth2.hpp>
#include <gtest/gtest.h>
TEST(Directional, Square) {
  pendepth::ConvexPolygon P({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  pendepth::ConvexPolygon Q({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  auto r = pendepth::directional_depth(P, Q, {0.5, 0.5}, {1, 0});
  EXPECT_DOUBLE_EQ(r.depth, 1.5);
  r = pendepth::directional_depth(P, Q, {0.5, 0.5}, {-1, 0});
  EXPECT_DOUBLE_EQ(r.depth, 1.5);
  r = pendepth::directional_depth(P, Q, {0.5, 0.5}, {1, 1});
  EXPECT_DOUBLE_EQ(r.depth, 1.5 * std::sqrt(2.0));
  auto m = pendepth::minimum_depth(P, Q, {0.25, 0.5});
  EXPECT_DOUBLE_EQ(m.depth, 1.25);
  EXPECT_EQ(m.normal, pendepth::Vec2(-1, 0));
}
