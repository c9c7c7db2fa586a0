// SVG writer: the right elements for overlapping / separate / directional queries, y pointing up,
// everything inside the view box, and half-pixel decimation keeping a 10⁵-gon small but faithful.
#include <pendepth/io.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using pendepth::ConvexPolygon;
using pendepth::Vec2;
namespace io = pendepth::io;
namespace fs = std::filesystem;

namespace {

struct Svg {
  std::string text;
  double width = 0, height = 0;
  std::vector<std::vector<Vec2>> polygons;  // pixel coordinates, in file order

  static Svg read(const fs::path& p) {
    Svg s;
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    s.text = ss.str();
    // Plain string scanning: std::regex recurses per character and overflows on long lists.
    auto attr = [&](std::size_t from, const std::string& name, std::string& value) {
      const std::size_t a = s.text.find(name + "=\"", from);
      if (a == std::string::npos) return a;
      const std::size_t b = a + name.size() + 2, e = s.text.find('"', b);
      value = s.text.substr(b, e - b);
      return e;
    };
    std::string vb;
    if (attr(0, "viewBox", vb) != std::string::npos) {
      std::istringstream in(vb);
      double x0, y0;
      in >> x0 >> y0 >> s.width >> s.height;
    }
    std::string list;
    for (std::size_t at = attr(0, "points", list); at != std::string::npos; at = attr(at, "points", list)) {
      std::vector<Vec2> pts;
      std::istringstream ps(list);
      std::string pair;
      while (ps >> pair) {
        const std::size_t c = pair.find(',');
        pts.emplace_back(std::stod(pair.substr(0, c)), std::stod(pair.substr(c + 1)));
      }
      s.polygons.push_back(std::move(pts));
    }
    return s;
  }
  std::size_t count(const std::string& needle) const {
    std::size_t n = 0;
    for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
    return n;
  }
};

class SvgFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pendepth-test-svg-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

ConvexPolygon regular(std::size_t n, double r, Vec2 c = Vec2(0, 0)) {
  std::vector<Vec2> v;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = 2 * M_PI * double(k) / double(n);
    v.push_back(c + r * Vec2(std::cos(a), std::sin(a)));
  }
  return ConvexPolygon(v);
}

}  // namespace

TEST_F(SvgFiles, ElementsPerQueryKind) {
  const ConvexPolygon P({{0, 0}, {4, 0}, {4, 3}, {0, 3}}), Q({{0, 0}, {1, 0}, {0, 2}});
  const fs::path f = dir_ / "a.svg";

  const Vec2 t(1, 0.5);  // Q + t = (1,.5), (2,.5), (1,2.5): σ = 2 to the left (up 2.5, slant 2.01)
  io::write_svg(f, P, Q, t, pendepth::minimum_depth(P, Q, t));
  Svg s = Svg::read(f);
  EXPECT_EQ(s.text.rfind("<svg ", 0), 0u);
  EXPECT_EQ(s.text.substr(s.text.size() - 7), "</svg>\n");
  EXPECT_EQ(s.polygons.size(), 4u);  // P, Q + t, Q + t + v, M
  EXPECT_EQ(s.count("<circle"), 2u);  // witness, t
  EXPECT_EQ(s.count("marker-end"), 2u);  // the move in both panels
  EXPECT_NE(s.text.find("minimum depth σ = 2</text>"), std::string::npos);

  io::write_svg(f, P, Q, Vec2(10, 10), pendepth::minimum_depth(P, Q, Vec2(10, 10)), {std::nullopt, false});
  s = Svg::read(f);
  EXPECT_EQ(s.polygons.size(), 2u);  // no move, no M
  EXPECT_EQ(s.count("<circle"), 0u);
  EXPECT_NE(s.text.find("interiors do not overlap"), std::string::npos);

  const Vec2 d(1, 2);
  io::write_svg(f, P, Q, t, pendepth::directional_depth(P, Q, t, d), {d, true});
  s = Svg::read(f);
  EXPECT_EQ(s.polygons.size(), 4u);
  EXPECT_EQ(s.count("head-green)"), 1u);  // the direction glyph
  EXPECT_NE(s.text.find("directional depth σ_d"), std::string::npos);

  // Every drawn point inside the view box; y up: P's top edge (y = 3) above its bottom (y = 0).
  for (const auto& poly : s.polygons)
    for (const Vec2& p : poly) {
      EXPECT_GE(p.x(), 0);
      EXPECT_LE(p.x(), s.width);
      EXPECT_GE(p.y(), 0);
      EXPECT_LE(p.y(), s.height);
    }
  const auto& pp = s.polygons[0];  // P in normal form: (0,0), (4,0), (4,3), (0,3)
  ASSERT_EQ(pp.size(), 4u);
  EXPECT_LT(pp[2].y(), pp[1].y());
  EXPECT_LT(pp[0].x(), pp[1].x());
  // Same scale in x and y: P is 4 × 3.
  EXPECT_NEAR((pp[1].x() - pp[0].x()) / (pp[1].y() - pp[2].y()), 4.0 / 3.0, 1e-3);
}

TEST_F(SvgFiles, DecimatesHugePolygonsToHalfPixels) {
  const ConvexPolygon P = regular(100000, 1000), Q = regular(1000, 50, Vec2(3, 1));
  const fs::path f = dir_ / "big.svg";
  const Vec2 t(200, 100);
  io::write_svg(f, P, Q, t, pendepth::minimum_depth(P, Q, t));
  const Svg s = Svg::read(f);
  ASSERT_EQ(s.polygons.size(), 4u);
  EXPECT_LT(fs::file_size(f), 200u * 1024);
  const auto& pp = s.polygons[0];
  // The circle is about 560 pixels across: perimeter ≈ 1760 px, at most one point per half pixel.
  EXPECT_LT(pp.size(), 4000u);
  EXPECT_GT(pp.size(), 500u);
  // Consecutive points at least half a pixel apart (two-decimal rounding aside), gaps at most
  // a couple of pixels, and all on the circle: centre and radius from the extreme points.
  const double cx = (pp[0].x() + pp[pp.size() / 2].x()) / 2;
  double r_min = 1e300, r_max = 0;
  double cy = 0;
  {
    double ymin = 1e300, ymax = -1e300;
    for (const Vec2& p : pp) {
      ymin = std::min(ymin, p.y());
      ymax = std::max(ymax, p.y());
    }
    cy = (ymin + ymax) / 2;
  }
  for (std::size_t i = 0; i < pp.size(); ++i) {
    const double gap = (pp[(i + 1) % pp.size()] - pp[i]).norm();
    if (i + 1 < pp.size()) EXPECT_GT(gap, 0.5 - 0.015);
    EXPECT_LT(gap, 2.0);
    const double r = (pp[i] - Vec2(cx, cy)).norm();
    r_min = std::min(r_min, r);
    r_max = std::max(r_max, r);
  }
  EXPECT_LT(r_max - r_min, 1.0);
}
