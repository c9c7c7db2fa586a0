// Test helpers for the curved primitives (tests/primitives): the NESTED TESSELLATIONS oracle —
// each curved shape C gets an inscribed polytope I ⊆ C and a circumscribed one O ⊇ C (double
// coordinates; both containments verified with the closed-form support function / implicit
// equation and a margin far above their rounding), so that by monotonicity of M in each shape
// the exact polytope engines on I and O bracket every query — and random poses.
#pragma once

#include <gtest/gtest.h>

#include <pendepth/pendepth.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace pendepth::curved_test {

constexpr double kPi = std::numbers::pi;
constexpr double kIn = 1 - 1e-10, kOut = 1 + 1e-10;

enum class K { Cyl, Cone, Ell };
struct Curved {
  K k;
  double a, b, c;
  Shape3 shape() const {
    return k == K::Cyl ? Shape3::cylinder(a, b) : k == K::Cone ? Shape3::cone(a, b) : Shape3::ellipsoid(a, b, c);
  }
  // The closed-form support function (independent of the engine's support points).
  double h(const Vec3& n) const {
    const double r = std::hypot(n[0], n[1]);
    if (k == K::Cyl) return a * r + b * std::abs(n[2]);
    if (k == K::Cone) return std::max(b * n[2], a * r - b * n[2]);
    return std::sqrt(a * a * n[0] * n[0] + b * b * n[1] * n[1] + c * c * n[2] * n[2]);
  }
  // Whether x lies in the shape, with a relative margin 1e-12 (far above rounding).
  bool contains(const Vec3& x) const {
    const double m = 1 - 1e-12;
    const double r = std::hypot(x[0], x[1]);
    if (k == K::Cyl) return r <= a * m && std::abs(x[2]) <= b * m;
    if (k == K::Cone) return std::abs(x[2]) <= b * m && r <= a * m * (b - x[2]) / (2 * b);
    const double q = x[0] * x[0] / (a * a) + x[1] * x[1] / (b * b) + x[2] * x[2] / (c * c);
    return q <= m;
  }
};

// Unit sphere points: a latitude–longitude grid with poles.
inline std::vector<Vec3> sphere_points(int n) {
  std::vector<Vec3> v{Vec3(0, 0, 1), Vec3(0, 0, -1)};
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const double th = kPi * i / n, ph = kPi * j / n;
      v.emplace_back(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
    }
  return v;
}

// The inscribed (outer = false) or circumscribed polytope with n segments.
inline Shape3 tessellation(const Curved& c, int n, bool outer) {
  std::vector<Vec3> v;
  if (c.k == K::Ell) {
    const auto s = sphere_points(n);
    double rin = 1;
    if (outer) {  // the inscribed polytope's inradius r: the sphere ⊆ (1/r)·hull
      const Shape3 hs = Shape3::hull(s);
      const ConvexPolytope& P = hs.polytope();
      for (const auto& t : P.triangles()) {
        const Vec3 nn = (P[t[1]] - P[t[0]]).cross(P[t[2]] - P[t[0]]);
        rin = std::min(rin, nn.dot(P[t[0]]) / nn.norm());
      }
      rin *= 1 - 1e-12;
    }
    for (const Vec3& p : s) {
      const double f = outer ? kOut / rin : kIn;
      v.emplace_back(c.a * p[0] * f, c.b * p[1] * f, c.c * p[2] * f);
    }
  } else {
    const double r = outer ? c.a / std::cos(kPi / n) * kOut : c.a * kIn;
    const double hz = outer ? c.b * kOut : c.b * kIn;
    for (int j = 0; j < n; ++j) {
      const double ph = 2 * kPi * j / n;
      v.emplace_back(r * std::cos(ph), r * std::sin(ph), -hz);
      if (c.k == K::Cyl) v.emplace_back(r * std::cos(ph), r * std::sin(ph), hz);
    }
    if (c.k == K::Cone) {
      if (outer) {  // apex raised so the slanted facets also clear the rounding of the base
        v.emplace_back(0, 0, c.b * kOut);
      } else {
        v.emplace_back(0, 0, c.b * kIn);
      }
    }
  }
  return Shape3::hull(v);
}

// The containments I ⊆ C ⊆ O, verified.
inline void verify_nesting(const Curved& c, const Shape3& in, const Shape3& out) {
  for (const Vec3& p : in.polytope().vertices()) ASSERT_TRUE(c.contains(p)) << p.transpose();
  const ConvexPolytope& P = out.polytope();
  for (const auto& t : P.triangles()) {
    const Vec3 nn = (P[t[1]] - P[t[0]]).cross(P[t[2]] - P[t[0]]);
    const Vec3 u = nn / nn.norm();
    ASSERT_LE(c.h(u) * (1 + 1e-13), u.dot(P[t[0]]));
  }
}

inline Pose3 random_pose(std::mt19937_64& rng, double spread) {
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(-spread, spread);
  return Pose3(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)), Vec3(u(rng), u(rng), u(rng)));
}

}  // namespace pendepth::curved_test
