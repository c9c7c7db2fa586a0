// Shape3's curved primitives (docs/design.md "Primitives"): cylinder, cone, ellipsoid, held as
// their parameters and answered by Pair3 through the certified support-function engine
// (src/primitives/support3.cpp).
#include <pendepth/pendepth.hpp>

#include "primitives/support3.hpp"

#include <cmath>
#include <cstdio>

namespace pendepth {

namespace {
void check_positive(double x, const char* what, std::string_view name) {
  if (!std::isfinite(x) || !(x > 0)) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    throw InvalidInput(std::string(name) + ": " + what + " " + buf + " must be finite and positive");
  }
}
Shape3 make(primitives::Curved3 c) {
  return Shape3::from_curved(std::make_shared<const primitives::Curved3>(std::move(c)));
}
}  // namespace

Shape3 Shape3::from_curved(std::shared_ptr<const primitives::Curved3> c) {
  Shape3 s;
  s.curved_ = std::move(c);
  return s;
}

Shape3 Shape3::cylinder(double r, double h, std::string_view name) {
  check_positive(r, "radius", name), check_positive(h, "half height", name);
  return make({primitives::Curved3::Kind::Cylinder, r, h, 0, std::string(name)});
}

Shape3 Shape3::cone(double r, double h, std::string_view name) {
  check_positive(r, "base radius", name), check_positive(h, "half height", name);
  return make({primitives::Curved3::Kind::Cone, r, h, 0, std::string(name)});
}

Shape3 Shape3::ellipsoid(double a, double b, double c, std::string_view name) {
  check_positive(a, "semi-axis A", name), check_positive(b, "semi-axis B", name), check_positive(c, "semi-axis C", name);
  return make({primitives::Curved3::Kind::Ellipsoid, a, b, c, std::string(name)});
}

}  // namespace pendepth
