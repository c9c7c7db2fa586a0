// Complete separation along d for a polygon with holes against a convex polygon (DHS §6),
// exact reference: the last exit of the line t + λ·d from any open R_i, if it lies after 0
// (sup{λ ≥ 0 : t + λ·d ∈ O}, O = ∪ int R_i the overlap set). O(n log m).
#include "polygon2/query_impl.hpp"

namespace pendepth {

Depth2 PolygonDepth2::separation(const Vec2& t, const Vec2& d_in) const {
  const Vec2 d = polygon2::check_and_scale(t, d_in);
  polygon2::Cut best, entry, exit;
  bool found = false;
  for (std::size_t i = 0; i < impl_->R.size(); ++i)
    if (impl_->R.line_interval(i, t, d, entry, exit) && polygon2::cut_sign(exit, t, d) > 0 &&
        (!found || polygon2::compare_cuts(exit, best, t, d) > 0)) {
      best = exit;
      found = true;
    }
  Depth2 r;
  if (found) r = polygon2::result_at_cut(*impl_, best, t, d);
  r.kind = DepthKind::Separation;
  r.overlapping = overlapping(t);
  return r;
}

}  // namespace pendepth
