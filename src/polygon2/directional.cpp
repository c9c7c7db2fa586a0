// σ_d for a polygon with holes against a convex polygon: the exact reference along_triangles()
// (DHS §4.2, with the convolved triangles of §4.1 Step 2 instead of the union boundary of Step 3;
// the union-boundary paths along() / along_scan() are in ray_shooting.cpp).
//
// The line t + λ·d meets each open R_i in an open interval (entry_i, exit_i) (O(log m) each).
// The overlap set is O = ∪ int R_i (depth2_polygon_convex.hpp), so σ_d is the end of the connected component of ∪ (entry_i, exit_i) that
// contains 0: sort the intervals ending after 0 by entry, and extend the running end `cur` by every
// interval with entry < cur < exit (strict: intervals sharing only an endpoint leave a point of ∂M
// between them). All comparisons of λ values are exact. O(n log m + n log n).
#include <algorithm>

#include "polygon2/query_impl.hpp"

namespace pendepth {

Depth2 polygon2::along_triangles(const PolygonDepth2& pd, const Vec2& t, const Vec2& d_in) {
  const PolygonDepth2::Impl& S = polygon_depth_impl(pd);
  const Vec2 d = polygon2::check_and_scale(t, d_in);
  using polygon2::Cut;
  struct Iv {
    Cut entry, exit;
  };
  std::vector<Iv> ivs;
  for (std::size_t i = 0; i < S.R.size(); ++i) {
    Iv iv;
    if (S.R.line_interval(i, t, d, iv.entry, iv.exit) && polygon2::cut_sign(iv.exit, t, d) > 0) ivs.push_back(iv);
  }
  std::sort(ivs.begin(), ivs.end(),
            [&](const Iv& a, const Iv& b) { return polygon2::compare_cuts(a.entry, b.entry, t, d) < 0; });
  const Cut* cur = nullptr;  // nullptr: λ = 0
  for (const Iv& iv : ivs) {
    const bool starts_before = cur ? polygon2::compare_cuts(iv.entry, *cur, t, d) < 0 : polygon2::cut_sign(iv.entry, t, d) < 0;
    if (!starts_before) break;  // sorted by entry: no later interval reaches back before cur
    if (!cur || polygon2::compare_cuts(iv.exit, *cur, t, d) > 0) cur = &iv.exit;
  }
  Depth2 r;
  r.kind = DepthKind::Directional;
  if (!cur) return r;
  r = polygon2::result_at_cut(S, *cur, t, d);
  r.kind = DepthKind::Directional;
  r.overlapping = true;
  return r;
}

}  // namespace pendepth
