// Prints σ_d for a unit square at t = (-0.75, 0.5) inside a 2×2 square, pushed up along
// d = (0, 1); ctest checks the exit status.
#include <pendepth/depth2.hpp>  // the only pendepth include: the line to switch to an umbrella header

#include <cstdio>

int main() {
  pendepth::ConvexPolygon P({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, "P");
  pendepth::ConvexPolygon Q({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "Q");
  pendepth::Depth2 r = pendepth::directional_depth(P, Q, {-0.75, 0.5}, {0, 1});
  std::printf("depth=%.17g\n", r.depth);
  return r.depth == 1.5 ? 0 : 1;
}
