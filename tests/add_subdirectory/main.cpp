// Prints σ_d for a unit square at t = (-0.75, 0.5) inside a 2×2 square, pushed up along
// d = (0, 1); ctest checks the exit status.
#include <pendepth/pendepth.hpp>

#include <cstdio>
#include <vector>

int main() {
  const pendepth::Shape2 P(std::vector<pendepth::Vec2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {}, "P");
  const pendepth::Shape2 Q(std::vector<pendepth::Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}, "Q");
  const pendepth::Depth2 r = pendepth::Pair2(P, Q).along({-0.75, 0.5}, {0, 1});
  std::printf("depth=%.17g\n", r.depth);
  return r.depth == 1.5 ? 0 : 1;
}
