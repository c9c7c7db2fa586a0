// Prints σ for a unit square pushed 0.25 into a 2×2 square; ctest checks the output.
#include <pendepth/depth2.hpp>  // the only pendepth include: the line to switch to an umbrella header

#include <cstdio>

int main() {
  pendepth::ConvexPolygon P({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, "P");
  pendepth::ConvexPolygon Q({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "Q");
  pendepth::Depth2 r = pendepth::minimum_depth(P, Q, {-0.75, 0.5});
  std::printf("depth=%.17g\n", r.depth);
  return r.depth == 0.25 ? 0 : 1;
}
