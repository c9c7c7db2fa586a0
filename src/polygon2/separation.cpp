// Complete separation along d for a polygon with holes against a convex polygon (DHS §6): the last
// exit sup{λ ≥ 0 : t + λ·d ∈ O} of the line t + λ·d from the overlap set O = ∪ int R_i (the sup of
// a union of open intervals is the largest of their ends).
//   separation_triangles(): the largest exit from every open R_i, O(n log m) (exact reference).
//   separation():           the largest exit from the open edge sausages int(f ⊕ B) (just before
//                           the last exit Q + x overlaps P without lying inside it, so some edge
//                           crosses int(Q + x)), branch-and-bound over their bounding-volume
//                           hierarchy, farthest boxes first (UnionBoundary::last_exit). Departure
//                           from DHS §6, which shoots at the outer ring of ∂O: the last exit lies
//                           on the outer ring, and it is found here without walking the ring.
//                           Same exact λ as the reference; the exit line may differ where several
//                           meet (a few ulps).
#include "polygon2/query_impl.hpp"

namespace pendepth {

Depth2 polygon2::separation_triangles(const PolygonDepth2& pd, const Vec2& t, const Vec2& d_in) {
  const PolygonDepth2::Impl& S = polygon_depth_impl(pd);
  const Vec2 d = polygon2::check_and_scale(t, d_in);
  polygon2::Cut best, entry, exit;
  bool found = false;
  for (std::size_t i = 0; i < S.R.size(); ++i)
    if (S.R.line_interval(i, t, d, entry, exit) && polygon2::cut_sign(exit, t, d) > 0 &&
        (!found || polygon2::compare_cuts(exit, best, t, d) > 0)) {
      best = exit;
      found = true;
    }
  Depth2 r;
  if (found) r = polygon2::result_at_cut(S, best, t, d);
  r.kind = DepthKind::Separation;
  r.overlapping = pd.overlapping(t);
  return r;
}

Depth2 PolygonDepth2::separation(const Vec2& t, const Vec2& d_in) const {
  const Vec2 d = polygon2::check_and_scale(t, d_in);
  polygon2::Cut best;
  Depth2 r;
  if (impl_->U.last_exit(t, d, best)) r = polygon2::result_at_cut(*impl_, best, t, d);
  r.kind = DepthKind::Separation;
  r.overlapping = impl_->U.in_overlap(t);
  return r;
}

}  // namespace pendepth
