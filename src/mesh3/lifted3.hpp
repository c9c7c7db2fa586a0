// 3-vectors over a lifted number type (exact.hpp's tiers: double, Fl, expansions, rationals), for
// the mesh engines' exact predicates: lv lifts a Vec3 with the tier's lift, sub / cross / dot
// build the polynomial whose sign is asked.
#pragma once

#include <pendepth/geometry.hpp>

#include <array>

namespace pendepth::mesh3::lifted {

template <class T>
using A3 = std::array<T, 3>;

template <class L>
auto lv(L lift, const Vec3& v) {
  using T = decltype(lift(0.0));
  return A3<T>{lift(v.x()), lift(v.y()), lift(v.z())};
}
template <class T>
A3<T> sub(const A3<T>& a, const A3<T>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class T>
A3<T> cross(const A3<T>& a, const A3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
T dot(const A3<T>& a, const A3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace pendepth::mesh3::lifted
