// A downstream program that uses only the front door: σ for a unit square pushed 0.25 into a
// 2×2 square, a non-convex pair, a 3D pair and a batch; the exit status says whether all held.
#include <pendepth/pendepth.hpp>

#include <cstdio>
#include <vector>

int main() {
  using namespace pendepth;
  const Shape2 P(std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {}, "P");
  const Shape2 Q(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}, "Q");
  const Pair2 pair(P, Q);
  const Depth2 r = pair.minimum({-0.75, 0.5});
  const Shape2 L = Shape2::from_wkt("POLYGON ((0 0, 3 0, 3 1, 1 1, 1 3, 0 3))", "L");
  const Pair2 lq(L, Q);  // polygon × convex
  const Depth2 a = lq.along({0.5, 0.5}, {1, 0});
  std::vector<Vec2> ts{{-0.75, 0.5}, {5, 5}};
  std::vector<Depth2> out(2);
  pair.minimum(ts, out);
  const Pair3 cubes(Shape3::hull(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1},
                                                   {0, 1, 1}, {1, 1, 1}}),
                    Shape3::hull(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}));
  const Depth3 c = cubes.minimum(Pose3(), Pose3(Vec3(0.9, 0.2, 0.2)));
  std::printf("depth=%.17g along=%.17g batch=%.17g,%.17g 3d=%.17g\n", r.depth, a.depth, out[0].depth, out[1].depth,
              c.depth);
  return r.depth == 0.25 && a.depth == 2.5 && out[0].depth == 0.25 && out[1].depth == 0 && c.depth > 0 ? 0 : 1;
}
