// The out-of-line ray–box test with per-bound widening (see box_tree.hpp). O(1).
#include "geometry/box_tree.hpp"

namespace pendepth::geometry {

template <>
bool ray_box<RaySlack::Bounds>(const Vec2& t, const Vec2& d, const Vec2& lo, const Vec2& hi, double& lmin, double& lmax) {
  return detail::ray_box<RaySlack::Bounds>(t, d, lo, hi, lmin, lmax);
}

}  // namespace pendepth::geometry
