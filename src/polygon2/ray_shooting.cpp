// σ_d on the implicit union boundary ∂O (DHS §4.2 and the fast path of §4.3).
//
// For t ∈ O (O = ∪ int R_i open), σ_d(t) is the first λ > 0 with t + λ·d̂ ∈ ∂O: the points of the
// ray before it are in O, and ∂O ∩ O = ∅, so the first boundary point is exactly where the ray
// leaves O (touching a union vertex or an isolated boundary point ends it too).
//   along_scan(): visits every piece of ∂O, O(|∂O| log m) = O(n log m) (DHS §4.2).
//   along():      branch-and-bound ray shooting in a bounding-volume hierarchy over the piece
//                 boxes, nearest boxes first, pruned by the best hit so far; arcs are located by
//                 binary search on B (O(log m)). Departure from DHS §4.3 (ears + partition trees):
//                 the hierarchy is simpler and its measured query time grows sublinearly in n
//                 (report / bench); the worst case stays O(n log m). t ∈ O is decided exactly with
//                 the hierarchy over the R_i.
#include "polygon2/query_impl.hpp"

namespace pendepth {

namespace {
Depth2 along_with(const PolygonDepth2::Impl& S, const Vec2& t, const Vec2& d_in, bool scan) {
  const Vec2 d = polygon2::check_and_scale(t, d_in);
  Depth2 r;
  r.kind = DepthKind::Directional;
  if (!S.U.in_overlap(t)) return r;
  polygon2::Hit h;
  const bool hit = scan ? S.U.ray_first_scan(t, d, h) : S.U.ray_first(t, d, h);
  if (!hit) return r;  // unreachable: O is bounded
  r = polygon2::result_at_hit(S, h, t, d);
  r.kind = DepthKind::Directional;
  r.overlapping = true;
  return r;
}
}  // namespace

Depth2 PolygonDepth2::along(const Vec2& t, const Vec2& d) const { return along_with(*impl_, t, d, false); }
Depth2 PolygonDepth2::along_scan(const Vec2& t, const Vec2& d) const { return along_with(*impl_, t, d, true); }

}  // namespace pendepth
