// Robust 3D predicates: filtered double with exact GMP fallback (see exact.hpp).
// Declared in include/pendepth/polytope.hpp (pendepth::predicates).
#include <pendepth/polytope.hpp>

#include "geometry/exact.hpp"

namespace pendepth::predicates {

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return exact::exact_sign([&](auto L) {
    auto bx = L(b.x()) - L(a.x()), by = L(b.y()) - L(a.y()), bz = L(b.z()) - L(a.z());
    auto cx = L(c.x()) - L(a.x()), cy = L(c.y()) - L(a.y()), cz = L(c.z()) - L(a.z());
    auto dx = L(d.x()) - L(a.x()), dy = L(d.y()) - L(a.y()), dz = L(d.z()) - L(a.z());
    return dx * (by * cz - bz * cy) + dy * (bz * cx - bx * cz) + dz * (bx * cy - by * cx);
  });
}

bool collinear3(const Vec3& a, const Vec3& b, const Vec3& c) {
  auto proj = [](const Vec3& p, int i, int j) { return Vec2(p[i], p[j]); };
  return orient2d(proj(a, 0, 1), proj(b, 0, 1), proj(c, 0, 1)) == 0 &&
         orient2d(proj(a, 1, 2), proj(b, 1, 2), proj(c, 1, 2)) == 0 &&
         orient2d(proj(a, 2, 0), proj(b, 2, 0), proj(c, 2, 0)) == 0;
}

int dot3_sign(const Vec3& u, const Vec3& a, const Vec3& b) {
  return exact::exact_sign([&](auto L) {
    return L(u.x()) * (L(a.x()) - L(b.x())) + L(u.y()) * (L(a.y()) - L(b.y())) + L(u.z()) * (L(a.z()) - L(b.z()));
  });
}

}  // namespace pendepth::predicates
