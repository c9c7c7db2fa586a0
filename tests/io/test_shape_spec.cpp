// Primitive shape specs (include/pendepth/shape_spec.hpp; src/io/shape_spec.cpp): what is a spec,
// what each builds, and the one-line errors naming the spec.
#include <pendepth/shape_spec.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace pendepth;

namespace {

std::string error_of(const std::string& arg) {
  try {
    io::parse_shape_spec(arg);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(ShapeSpec, ParsesTheImplementedKinds) {
  EXPECT_FALSE(io::parse_shape_spec("part.obj"));
  EXPECT_FALSE(io::parse_shape_spec("dir:with/colon.obj"));  // not a known kind: a path
  const auto s = io::parse_shape_spec("sphere:0.5");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->kind, "sphere");
  EXPECT_EQ(s->numbers, std::vector<double>{0.5});
  EXPECT_EQ(io::shape3_from_spec(*s).radius(), 0.5);
  const auto c = io::parse_shape_spec("capsule:+1,2e-1");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->numbers, (std::vector<double>{1, 0.2}));
  const Shape3 cap = io::shape3_from_spec(*c);
  EXPECT_EQ(cap.radius(), 1);
  ASSERT_EQ(cap.core().flat_vertices().size(), 2u);
  EXPECT_EQ(cap.core().flat_vertices()[0], Vec3(0, 0, -0.2));
  const Shape3 box = io::shape3_from_spec(*io::parse_shape_spec("box:1,2,3"));
  EXPECT_EQ(box.size(), 8u);
  EXPECT_EQ(box.polytope().vertices()[0].cwiseAbs(), Vec3(1, 2, 3));
  EXPECT_EQ(io::shape3_from_spec(*io::parse_shape_spec("point:1,2,3")).flat_vertices()[0], Vec3(1, 2, 3));
  EXPECT_EQ(io::shape3_from_spec(*io::parse_shape_spec("segment:0,0,0,1,1,1")).dimension(), 1);
  const auto dir = std::filesystem::temp_directory_path() / "pendepth_shape_spec_test";
  std::filesystem::create_directories(dir);
  const auto obj = dir / "tet.obj";
  std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  const auto r = io::parse_shape_spec("rounded:0.25:" + obj.string());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->file, obj.string());
  const Shape3 rounded = io::shape3_from_spec(*r);
  EXPECT_EQ(rounded.radius(), 0.25);
  EXPECT_EQ(rounded.polytope().size(), 4u);
  std::filesystem::remove_all(dir);
}

TEST(ShapeSpec, ErrorsNameTheSpec) {
  EXPECT_EQ(error_of("sphere:x"), "shape spec 'sphere:x': 'x' is not a number (expected sphere:R)");
  EXPECT_EQ(error_of("sphere:1,2"), "shape spec 'sphere:1,2': 2 numbers given (expected sphere:R)");
  EXPECT_EQ(error_of("sphere:"), "shape spec 'sphere:': '' is not a number (expected sphere:R)");
  EXPECT_EQ(error_of("box:1,2,inf"), "shape spec 'box:1,2,inf': 'inf' is not finite (expected box:X,Y,Z)");
  EXPECT_EQ(error_of("box:1,2,3;"), "shape spec 'box:1,2,3;': unexpected ';' (expected box:X,Y,Z)");
  EXPECT_EQ(error_of("rounded:1"), "shape spec 'rounded:1': no file (expected rounded:R:FILE)");
  EXPECT_EQ(error_of("cylinder:1"), "shape spec 'cylinder:1': 1 number given (expected cylinder:R,H)");
  EXPECT_EQ(error_of("ellipsoid:1,2"), "shape spec 'ellipsoid:1,2': 2 numbers given (expected ellipsoid:A,B,C)");
  for (const char* ok : {"cylinder:1,2", "cone:1,2", "ellipsoid:1,2,3"}) {
    const Shape3 c = io::shape3_from_spec(*io::parse_shape_spec(ok), "C");
    EXPECT_NE(c.curved(), nullptr) << ok;
    EXPECT_EQ(c.name(), "C");
  }
  try {
    io::shape3_from_spec(*io::parse_shape_spec("cone:1,0"));
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "shape spec 'cone:1,0': shape: half height 0 must be finite and positive");
  }
  // 2D specs: point:X,Y and segment:X1,Y1,X2,Y2 (Shape2::point, Shape2::segment).
  const auto p2 = io::parse_shape_spec("point:1,2");
  ASSERT_TRUE(p2);
  EXPECT_EQ(p2->dimension, 2);
  EXPECT_EQ(io::shape2_from_spec(*p2).flat_vertices()[0], Vec2(1, 2));
  EXPECT_EQ(io::shape2_from_spec(*io::parse_shape_spec("segment:0,0,1,-1")).dimension(), 1);
  EXPECT_THROW(io::shape3_from_spec(*p2), InvalidInput);
  EXPECT_THROW(io::shape2_from_spec(*io::parse_shape_spec("point:1,2,3")), InvalidInput);
  EXPECT_THROW(io::shape2_from_spec(*io::parse_shape_spec("segment:1,1,1,1")), InvalidInput);
  EXPECT_EQ(error_of("point:1"), "shape spec 'point:1': 1 number given (expected point:X,Y,Z)");
  try {
    io::shape3_from_spec(*io::parse_shape_spec("sphere:-1"));
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "shape spec 'sphere:-1': shape: radius -1 must be finite and positive");
  }
  EXPECT_THROW(io::shape3_from_spec(*io::parse_shape_spec("segment:1,1,1,1,1,1")), InvalidInput);
  EXPECT_THROW(io::shape3_from_spec(*io::parse_shape_spec("rounded:1:/nonexistent/file.obj")), InvalidInput);
}

}  // namespace
