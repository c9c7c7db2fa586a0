// Shape3 primitives (docs/design.md "Primitives"): boxes are polytopes; spheres, capsules and
// rounded shapes are a core (a point, a segment, any convex shape) ⊕ a ball, answered by Pair3
// through the signed distance of the cores (src/front/rounded3.cpp).
#include <pendepth/pendepth.hpp>

#include <cmath>
#include <cstdio>

namespace pendepth {

namespace {
void check_size(double x, const char* what, std::string_view name, bool zero_ok = false) {
  if (!std::isfinite(x) || x < 0 || (x == 0 && !zero_ok)) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    throw InvalidInput(std::string(name) + ": " + what + " " + buf + " must be finite and " +
                       (zero_ok ? "non-negative" : "positive"));
  }
}
}  // namespace

Shape3 Shape3::box(double hx, double hy, double hz, std::string_view name) {
  check_size(hx, "half extent X", name), check_size(hy, "half extent Y", name), check_size(hz, "half extent Z", name);
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(i & 1 ? hx : -hx, i & 2 ? hy : -hy, i & 4 ? hz : -hz);
  return hull(v, name);
}

Shape3 Shape3::sphere(double r, std::string_view name) {
  check_size(r, "radius", name);
  return rounded(point(Vec3::Zero(), name), r, name);
}

Shape3 Shape3::capsule(double r, double h, std::string_view name) {
  check_size(r, "radius", name), check_size(h, "half height", name);
  return rounded(segment(Vec3(0, 0, -h), Vec3(0, 0, h), name), r, name);
}

Shape3 Shape3::rounded(const Shape3& core, double r, std::string_view name) {
  check_size(r, "radius", name, true);
  if (core.radius_ > 0) throw InvalidInput(std::string(name) + ": the core " + core.name() + " is already rounded");
  Shape3 s = core;
  s.radius_ = r;
  s.rounded_name_ = std::string(name);
  return s;
}

Shape3 Shape3::core() const {
  Shape3 s = *this;
  s.radius_ = 0;
  s.rounded_name_.clear();
  return s;
}

}  // namespace pendepth
