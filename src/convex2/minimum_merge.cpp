// σ for one placement in O(n + m): merge the edges of P and −Q in slope order (DHS §3,
// Theorem 3.1) and take the nearest edge line of M. For t ∈ int M, dist(t, ∂M) is the minimum
// over edges of the distance to the edge's line, and the foot of that line lies on the edge.
#include <pendepth/depth2.hpp>

#include "convex2/minkowski_sum.hpp"

namespace pendepth {

Depth2 minimum_depth(const ConvexPolygon& P, const ConvexPolygon& Q, const Vec2& t) {
  convex2::require_finite(t, "placement t");
  const convex2::MinkowskiSum M(P, Q);
  const convex2::Nearest best = convex2::nearest_edge(M, t);
  if (!(best.distance > 0)) return Depth2{};
  return M.result_for_edge(best.edge, t, best.distance);
}

std::vector<Vec2> minkowski_difference(const ConvexPolygon& P, const ConvexPolygon& Q) {
  const convex2::MinkowskiSum M(P, Q);
  std::vector<Vec2> out(M.size());
  for (std::size_t k = 0; k < M.size(); ++k) out[k] = M.vertex(k);
  return out;
}

}  // namespace pendepth
