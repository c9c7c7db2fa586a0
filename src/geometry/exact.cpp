// Robust 2D predicates: filtered double with exact GMP fallback (see exact.hpp).
#include <pendepth/geometry.hpp>

#include "geometry/exact.hpp"

#include <cmath>

namespace pendepth::predicates {

using exact::exact_sign;

int orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double p1 = (b.x() - a.x()) * (c.y() - a.y()), p2 = (b.y() - a.y()) * (c.x() - a.x());
  return exact::exact_sign_filtered(p1 - p2, exact::kCrossBound * (std::abs(p1) + std::abs(p2)) + exact::kTiny, [&](auto L) {
    return (L(b.x()) - L(a.x())) * (L(c.y()) - L(a.y())) - (L(b.y()) - L(a.y())) * (L(c.x()) - L(a.x()));
  });
}

int cross(const Vec2& a, const Vec2& b) {
  return exact_sign([&](auto L) { return L(a.x()) * L(b.y()) - L(a.y()) * L(b.x()); });
}

int cross_edges(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  const double p1 = (a1.x() - a0.x()) * (b1.y() - b0.y()), p2 = (a1.y() - a0.y()) * (b1.x() - b0.x());
  return exact::exact_sign_filtered(p1 - p2, exact::kCrossBound * (std::abs(p1) + std::abs(p2)) + exact::kTiny, [&](auto L) {
    return (L(a1.x()) - L(a0.x())) * (L(b1.y()) - L(b0.y())) - (L(a1.y()) - L(a0.y())) * (L(b1.x()) - L(b0.x()));
  });
}

int dot_edges(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  return exact_sign([&](auto L) {
    return (L(a1.x()) - L(a0.x())) * (L(b1.x()) - L(b0.x())) + (L(a1.y()) - L(a0.y())) * (L(b1.y()) - L(b0.y()));
  });
}

namespace {
// Upper half-plane [0, pi) -> 0, lower [pi, 2pi) -> 1, for the vector (a1 - a0); exact since the
// sign of a difference of two doubles is the comparison of the doubles.
int half_of(const Vec2& a0, const Vec2& a1) {
  return (a1.y() < a0.y() || (a1.y() == a0.y() && a1.x() < a0.x())) ? 1 : 0;
}
}  // namespace

int compare_angle(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  int ha = half_of(a0, a1), hb = half_of(b0, b1);
  if (ha != hb) return ha < hb ? -1 : 1;
  return -cross_edges(a0, a1, b0, b1);
}

}  // namespace pendepth::predicates
