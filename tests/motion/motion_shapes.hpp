// Shared by the PD_g tests (test_motion.cpp, test_generalized_bnb.cpp): the map of
// Shape2::rotated, the non-convex test shapes and the nesting pieces of ../shared/data.
#pragma once

#include <pendepth/pendepth.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

namespace pendepth::motion_test {

/// p rotated by deg about the origin exactly as Shape2::rotated does (same formula, same bits).
inline Vec2 turned(const Vec2& p, double deg) {
  double r = std::fmod(deg, 360.0);
  if (r < 0) r += 360.0;
  if (r == 360.0) r = 0;
  if (std::fmod(r, 90.0) == 0) {
    switch (static_cast<int>(r / 90)) {
      case 0: return p;
      case 1: return Vec2(-p.y(), p.x());
      case 2: return Vec2(-p.x(), -p.y());
      default: return Vec2(p.y(), -p.x());
    }
  }
  const double a = r * (std::numbers::pi / 180.0), c = std::cos(a), s = std::sin(a);
  return Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y());
}

/// An L of arm length 3s and width s with its corner at o.
inline Shape2 l_shape(double s, const Vec2& o, std::string_view name) {
  return Shape2({o + Vec2(0, 0), o + Vec2(3 * s, 0), o + Vec2(3 * s, s), o + Vec2(s, s), o + Vec2(s, 3 * s),
                 o + Vec2(0, 3 * s)},
                {}, name);
}

/// A comb of `teeth` teeth of width w and length h hanging below a spine of height 1, from o.
inline Shape2 comb(int teeth, double w, double h, const Vec2& o, std::string_view name) {
  std::vector<Vec2> r;
  for (int i = 0; i < teeth; ++i) {
    r.push_back(o + Vec2((2 * i) * w, -h));
    r.push_back(o + Vec2((2 * i + 1) * w, -h));
    r.push_back(o + Vec2((2 * i + 1) * w, 0));
    if (i + 1 < teeth) r.push_back(o + Vec2((2 * i + 2) * w, 0));
  }
  r.push_back(o + Vec2((2 * teeth - 1) * w, 1));
  r.push_back(o + Vec2(0, 1));
  return Shape2(r, {}, name);
}

/// The pieces of an ESICUP instance in ../shared/data/nesting (jagua-rs JSON).
inline std::vector<Shape2> nesting(const std::string& file) {
  std::ifstream in(std::string(PENDEPTH_SHARED_DATA) + "/nesting/" + file);
  nlohmann::json j;
  in >> j;
  std::vector<Shape2> out;
  for (const auto& item : j["items"]) {
    std::vector<Vec2> r;
    for (const auto& p : item["shape"]["data"]) r.push_back({p[0].get<double>(), p[1].get<double>()});
    out.emplace_back(r, std::vector<std::vector<Vec2>>{}, file);
  }
  return out;
}

}  // namespace pendepth::motion_test
