// Quickstart (2D): one header, any two polygons. Shapes are validated once, the pair picks its
// engine and prepares once, then single queries and a parallel batch.
#include <pendepth/pendepth.hpp>

#include <cstdio>
#include <vector>

int main() {
  using namespace pendepth;
  // A plate with a hole (WKT) and a bar given as a ring (either orientation; closing vertex optional).
  const Shape2 P = Shape2::from_wkt("POLYGON ((0 0, 8 0, 8 6, 0 6, 0 0), (2 2, 2 4, 6 4, 6 2, 2 2))", "plate");
  const Shape2 Q(std::vector<Vec2>{{0, 0}, {3, 0}, {3, 1}, {0, 1}}, {}, "bar");

  const Pair2 pair(P, Q);  // polygon with holes × convex: the implicit union boundary, built once
  const Vec2 t(1, 1.5);    // Q placed at t overlaps the rim of the hole

  const Depth2 s = pair.minimum(t);  // σ: the shortest separating move
  std::printf("engine  = %s\n", to_string(pair.engine()));
  std::printf("sigma   = %.17g  move Q by (%.17g, %.17g)\n", s.depth, s.translation.x(), s.translation.y());
  const Depth2 a = pair.along(t, Vec2(0, 1));  // σ_d: move up only
  std::printf("sigma_d = %.17g  along (0, 1)\n", a.depth);

  // The same pair with the roles swapped: the bar fixed, the plate moving; same answers, mirrored.
  const Pair2 swapped(Q, P);
  const Depth2 m = swapped.minimum(-t);
  std::printf("swapped = %.17g  move the plate by (%.17g, %.17g)\n", m.depth, m.translation.x(), m.translation.y());

  // A batch: every core, the single calls' answers bit for bit.
  std::vector<Vec2> ts;
  for (int k = 0; k < 1000; ++k) ts.emplace_back(-2 + 0.01 * k, 1.5);
  std::vector<Depth2> out(ts.size());
  pair.minimum(ts, out);
  int overlapping = 0;
  for (const Depth2& r : out) overlapping += r.overlapping;
  std::printf("batch   : %d of %zu placements overlap\n", overlapping, ts.size());

  // Bad input is reported at the boundary with the shape, ring and vertex.
  try {
    Shape2(std::vector<Vec2>{{0, 0}, {4, 4}, {4, 0}, {0, 4}}, {}, "bow tie");
  } catch (const InvalidInput& e) {
    std::printf("error   : %s\n", e.what());
  }
  const bool ok = s.overlapping && a.depth >= s.depth && m.depth == s.depth && out[300].depth == pair.minimum(ts[300]).depth;
  return ok ? 0 : 1;
}
