// Quickstart: validate two convex polygons once, then ask for the minimum depth σ and the depth
// along a direction σ_d. Shapes are given in their own coordinates; Q is placed at t.
#include <pendepth/depth2.hpp>

#include <cstdio>

int main() {
  using pendepth::Vec2;
  // Either orientation is accepted; the closing vertex may be repeated.
  pendepth::ConvexPolygon P({{0, 0}, {4, 0}, {5, 2}, {3, 4}, {0, 3}}, "P");
  pendepth::ConvexPolygon Q({{0, 0}, {2, 0}, {2, 1}, {0, 1}}, "Q");

  pendepth::DepthQuery2 query(P, Q);  // builds the depth field of M = P ⊕ (−Q) once
  const Vec2 t(3, 1);                  // Q placed at t overlaps P

  pendepth::Depth2 s = query.minimum(t);  // σ: shortest separating move, O(log n)
  std::printf("sigma   = %.17g  move Q by (%.17g, %.17g)\n", s.depth, s.translation.x(), s.translation.y());

  pendepth::Depth2 a = query.along(t, Vec2(-1, 0));  // σ_d: move along −x, O(log n + log m)
  std::printf("sigma_d = %.17g  along (-1, 0)\n", a.depth);

  // Bad input is reported at the boundary with the reason and the vertex.
  try {
    pendepth::ConvexPolygon bad({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}, "bad");
  } catch (const pendepth::InvalidInput& e) {
    std::printf("error   : %s\n", e.what());
  }
  return (s.depth > 0 && a.depth >= s.depth) ? 0 : 1;
}
