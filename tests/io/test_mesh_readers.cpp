// Mesh readers (OBJ, OFF, STL ASCII and binary): exact values read back, every accepted variant,
// every error with its line or byte offset, and a cross-format oracle — the 60 shared hulls
// written as OFF, ASCII STL and binary STL by the test give the same hull as their OBJ file.
#include <pendepth/io.hpp>

#include <gtest/gtest.h>

#include "io/reader_errors.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

using pendepth::ConvexPolytope;
using pendepth::InvalidInput;
using pendepth::Vec3;
namespace io = pendepth::io;
namespace fs = std::filesystem;

namespace {

using io_test::error_of;
using io_test::obj_error;
using io_test::off_error;
using io_test::stl_error;

// Binary STL writer (little-endian, as the format requires), independent of the reader.
struct Triangle {
  std::array<std::array<float, 3>, 3> v;
};

void put_u32(std::string& s, std::uint32_t x) {
  for (int k = 0; k < 4; ++k) s += static_cast<char>((x >> (8 * k)) & 0xFF);
}
void put_f32(std::string& s, float x) { put_u32(s, std::bit_cast<std::uint32_t>(x)); }

std::string binary_stl(const std::vector<Triangle>& tris, std::string header = "binary STL written by the test") {
  header.resize(80, ' ');
  std::string s = header;
  put_u32(s, static_cast<std::uint32_t>(tris.size()));
  for (const Triangle& t : tris) {
    for (int k = 0; k < 3; ++k) put_f32(s, 0.0f);  // normal: not read
    for (const auto& v : t.v)
      for (float x : v) put_f32(s, x);
    s += std::string(2, '\0');  // attribute byte count
  }
  return s;
}

std::string ascii_stl(const std::vector<Triangle>& tris) {
  std::string s = "solid test\n";
  for (const Triangle& t : tris) {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for (const auto& v : t.v) {
      s += "      vertex";
      for (float x : v) {
        s += ' ';
        io::append_double(s, x);
      }
      s += '\n';
    }
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid test\n";
}

// The 12 triangles of the unit cube [0,1]³ (orientation irrelevant to the readers).
std::vector<Triangle> cube_triangles() {
  std::vector<Triangle> t;
  auto quad = [&](std::array<float, 3> a, std::array<float, 3> b, std::array<float, 3> c, std::array<float, 3> d) {
    t.push_back({{a, b, c}});
    t.push_back({{a, c, d}});
  };
  quad({0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0});
  quad({0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1});
  quad({0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1});
  quad({0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0});
  quad({0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0});
  quad({1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1});
  return t;
}

std::vector<Vec3> sorted(std::vector<Vec3> p) {
  std::sort(p.begin(), p.end(), [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  return p;
}

std::vector<Vec3> hull_vertices(const ConvexPolytope& P) {
  return sorted(std::vector<Vec3>(P.vertices().begin(), P.vertices().end()));
}

std::vector<Vec3> cube_corners() {
  std::vector<Vec3> c;
  for (int x = 0; x < 2; ++x)
    for (int y = 0; y < 2; ++y)
      for (int z = 0; z < 2; ++z) c.emplace_back(x, y, z);
  return sorted(c);
}

class MeshFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pendepth-test-mesh-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }
  fs::path dir_;
};

}  // namespace

// ---- OBJ ----

TEST(ObjReader, VerticesCommentsAndIgnoredStatements) {
  const auto p = io::parse_obj_points(
      "# a comment\n"
      "mtllib x.mtl\n"
      "o thing\n"
      "v 1 2 3\n"
      "vn 0 0 1\n"
      "vn 0 1 0\n"
      "vn 1 0 0\n"
      "vt 0.5 0.5\n"
      "vt 0.5\n"
      "vt 0.5 0.5 0\n"
      "vp 0.1 0.2\n"
      "  v\t-1.5e2   +4 .25 # trailing comment\r\n"
      "v 7 8 9 0.5\n"            // w: the rational weight, not a divisor
      "v 1 1 1 0.2 0.4 0.6\n"    // x y z r g b
      "f 1 2 3\n"
      "f 1/1/1 2/2/2 3/3/3\n"
      "\n"
      "v 1e-400 -0 4.9e-324");   // underflow rounds to 0, subnormals kept; no final newline
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p[0], Vec3(1, 2, 3));
  EXPECT_EQ(p[1], Vec3(-150, 4, 0.25));
  EXPECT_EQ(p[2], Vec3(7, 8, 9));
  EXPECT_EQ(p[3], Vec3(1, 1, 1));
  EXPECT_EQ(p[4], Vec3(0, 0, 4.9e-324));
  EXPECT_TRUE(io::parse_obj_points("").empty());
  EXPECT_TRUE(io::parse_obj_points("g nothing\n# nothing\n").empty());
}

TEST(ObjReader, RandomValuesReadBackExactly) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(-1e6, 1e6);
  std::vector<Vec3> want(2000);
  std::string text;
  for (Vec3& v : want) {
    v = Vec3(u(rng), u(rng) * 1e-9, std::ldexp(u(rng), int(rng() % 200) - 100));
    text += "v ";
    for (int k = 0; k < 3; ++k) {
      io::append_double(text, v[k]);
      text += ' ';
    }
    text += '\n';
  }
  EXPECT_EQ(io::parse_obj_points(text), want);
}

TEST(ObjReader, ErrorsNameTheLine) {
  EXPECT_EQ(obj_error("v 1 2 3\nv 1 two 3\n"), "m.obj:2: malformed vertex line: y is not a number: 'two'");
  EXPECT_EQ(obj_error("# c\n\nv 1 2\n"), "m.obj:3: malformed vertex line: expected 'v x y z [w]', got 2 numbers");
  EXPECT_EQ(obj_error("v\n"), "m.obj:1: malformed vertex line: expected 'v x y z [w]', got 0 numbers");
  EXPECT_EQ(obj_error("v 1 2 3 4 5\n"), "m.obj:1: malformed vertex line: expected 'v x y z [w]', got 5 numbers");
  EXPECT_EQ(obj_error("v 1 2 3 w\n"), "m.obj:1: malformed vertex line: field 4 is not a number: 'w'");
  EXPECT_EQ(obj_error("v 0 0 0\r\nv 1 2 inf\r\n"), "m.obj:2: vertex line has a non-finite z: 'inf'");
  EXPECT_EQ(obj_error("v nan 0 0\n"), "m.obj:1: vertex line has a non-finite x: 'nan'");
  EXPECT_EQ(obj_error("\n\n\nv 0 -1e999 0\n"), "m.obj:4: vertex line has a non-finite y: '-1e999'");
  EXPECT_EQ(obj_error("v 1,2,3\n"), "m.obj:1: malformed vertex line: expected 'v x y z [w]', got 1 number");
  // The library's own entry point keeps its contract: no vertex at all is an error.
  EXPECT_EQ(error_of([] { pendepth::read_obj_vertices("/nonexistent/dir/a.obj"); }),
            "/nonexistent/dir/a.obj: cannot read file (No such file or directory)");
}

// ---- OFF ----

TEST(OffReader, HeaderVariants) {
  const std::vector<Vec3> want = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::string faces = "3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n";
  EXPECT_EQ(io::parse_off_points("OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces), want);
  EXPECT_EQ(io::parse_off_points("# made by hand\nOFF 4 4 6\n\n0 0 0 # origin\n1 0 0\n  0 1 0\n0 0 1\n" + faces), want);
  EXPECT_EQ(io::parse_off_points("4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces), want);  // keyword optional
  EXPECT_EQ(io::parse_off_points("OFF\n4 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces), want);  // no edge count
  EXPECT_EQ(io::parse_off_points("OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"), want);  // a point set
  // Face colours: a colour-map index, RGB, RGBA; comments and blank lines after the last face.
  EXPECT_EQ(io::parse_off_points("OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2 7\n3 0 1 3 1 0 0\n"
                                 "3 0 2 3 0.5 0.5 0.5 1\n4 1 2 3 3\n\n# end\n  \n"),
            want);
  EXPECT_EQ(io::parse_off_points("COFF\n4 4 6\n0 0 0 255 0 0 255\n1 0 0 0 255 0\n0 1 0 0.5 0.5 0.5 1\n0 0 1 7\n" + faces),
            want);  // RGBA, RGB, float RGBA, colour-map index
  EXPECT_EQ(io::parse_off_points("NOFF\n4 4 6\n0 0 0 0 0 -1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n" + faces), want);
  EXPECT_EQ(io::parse_off_points("CNOFF\n4 4 6\n0 0 0 0 0 -1 1 1 1\n1 0 0 1 0 0 1 1 1\n0 1 0 0 1 0 1 1 1\n0 0 1 0 0 1 1 1 1\n" +
                                 faces),
            want);
  EXPECT_EQ(io::parse_off_points("STOFF\n4 4 6\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n0 0 1 1 1\n" + faces), want);
  EXPECT_EQ(io::parse_off_points("nOFF\n3\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces), want);
  EXPECT_EQ(io::parse_off_points("nOFF 3 4 4 6\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n0 0 1\r\n3 0 1 2\r\n3 0 1 3\r\n"
                                 "3 0 2 3\r\n3 1 2 3\r\n"),
            want);
  EXPECT_TRUE(io::parse_off_points("OFF\n0 0 0\n").empty());
}

TEST(OffReader, ErrorsNameTheLine) {
  EXPECT_EQ(off_error(""), "m.off:1: the file ends before the OFF header");
  EXPECT_EQ(off_error("# only a comment\n"), "m.off:1: the file ends before the OFF header");
  EXPECT_EQ(off_error("\nPLY\n3 1 0\n"), "m.off:2: expected the OFF header keyword ([ST][C][N][4][n]OFF), got 'PLY'");
  EXPECT_EQ(off_error("4OFF\n1 0 0\n0 0 0 0\n"), "m.off:1: 4D OFF files (4OFF) are not supported: need 3D points");
  EXPECT_EQ(off_error("OFF BINARY\n"), "m.off:1: binary OFF files are not supported");
  EXPECT_EQ(off_error("nOFF\n4\n1 0 0\n"), "m.off:2: dimension 4 is not supported: need 3D points");
  EXPECT_EQ(off_error("nOFF\nx\n"), "m.off:2: expected the dimension, got 'x'");
  EXPECT_EQ(off_error("OFF\n"), "m.off:1: the file ends before the vertex count");
  EXPECT_EQ(off_error("OFF\n4\n"), "m.off:2: expected the counts 'vertices faces [edges]', got 1 field");
  EXPECT_EQ(off_error("OFF\n4 4 6 1\n"), "m.off:2: expected the counts 'vertices faces [edges]', got 4 fields");
  EXPECT_EQ(off_error("OFF\n-4 4 6\n"), "m.off:2: expected the vertex count (a non-negative integer), got '-4'");
  EXPECT_EQ(off_error("OFF\n4 4.5 6\n"), "m.off:2: expected the face count (a non-negative integer), got '4.5'");
  EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n\n1 0 0\n"), "m.off:5: the file ends after 2 of 3 vertices");
  EXPECT_EQ(off_error("OFF\n2 0 0\n0 0 0\n1 0\n"), "m.off:4: malformed vertex 1: expected 3 numbers, got 2");
  EXPECT_EQ(off_error("OFF\n2 0 0\n0 0 0 1 1 1\n"), "m.off:3: malformed vertex 0: expected 3 numbers, got 6");
  EXPECT_EQ(off_error("COFF\n1 0 0\n0 0 0\n"), "m.off:3: malformed vertex 0: expected 4 to 7 numbers, got 3");
  EXPECT_EQ(off_error("OFF\n2 0 0\n0 0 0\n1 q 0\n"), "m.off:4: malformed vertex line: y is not a number: 'q'");
  EXPECT_EQ(off_error("OFF\n2 0 0\n0 0 0\n1 0 -inf\n"), "m.off:4: vertex line has a non-finite z: '-inf'");
  EXPECT_EQ(off_error("NOFF\n1 0 0\n0 0 0 0 zz 1\n"), "m.off:3: malformed vertex line: field 5 is not a number: 'zz'");
}

// ---- STL ----

TEST(StlReader, AsciiCubeDistinctVerticesInOrder) {
  const auto p = io::parse_stl_points(ascii_stl(cube_triangles()));
  ASSERT_EQ(p.size(), 8u);  // 36 vertex records, 8 distinct
  EXPECT_EQ(p[0], Vec3(0, 0, 0));
  EXPECT_EQ(p[1], Vec3(0, 1, 0));
  EXPECT_EQ(p[2], Vec3(1, 1, 0));
  EXPECT_EQ(sorted(p), cube_corners());
  // Case-insensitive keywords, a named solid, two solids in one file, -0 equal to 0.
  const auto q = io::parse_stl_points(
      "SOLID Part 1\nFACET NORMAL 0 0 1\nOUTER LOOP\nVERTEX 0 0 0\nVERTEX 1 0 0\nVERTEX 0 1 0\nENDLOOP\nENDFACET\n"
      "ENDSOLID Part 1\n"
      "solid b\nfacet normal 0 0 1\nouter loop\nvertex -0 0 -0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid\n");
  EXPECT_EQ(q, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}));
  EXPECT_TRUE(io::parse_stl_points("solid empty\nendsolid empty\n").empty());
}

TEST(StlReader, BinaryIsDetectedBySizeAndReadExactly) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<float> u(-100, 100);
  std::vector<Triangle> tris(500);
  for (auto& t : tris)
    for (auto& v : t.v)
      for (float& x : v) x = u(rng);
  tris[3].v[1] = tris[0].v[2];  // repeated vertices appear once, at their first position
  tris[7].v[0] = {-0.0f, 0.0f, 1.0f};
  tris[7].v[2] = {0.0f, -0.0f, 1.0f};
  // A header beginning with "solid", as many exporters write: the size decides.
  const std::string bytes = binary_stl(tris, "solid binary");
  const auto p = io::parse_stl_points(bytes);
  std::vector<Vec3> want;
  for (const auto& t : tris)
    for (const auto& v : t.v) {
      const Vec3 w(v[0] + 0.0, v[1] + 0.0, v[2] + 0.0);
      if (std::find(want.begin(), want.end(), w) == want.end()) want.push_back(w);
    }
  ASSERT_EQ(want.size(), 3 * tris.size() - 2);
  EXPECT_EQ(p, want);
  EXPECT_EQ(sorted(io::parse_stl_points(binary_stl(cube_triangles()))), cube_corners());
  EXPECT_TRUE(io::parse_stl_points(binary_stl({})).empty());
}

TEST(StlReader, AsciiErrorsNameTheLine) {
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 x 0\n"),
            "m.stl:5: malformed vertex: y is not a number: 'x'");
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 nan\n"),
            "m.stl:4: vertex has a non-finite z: 'nan'");
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n"),
            "m.stl:4: malformed vertex line: expected 'vertex x y z', got 2 fields");
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0 1\n  vertex 0 0 0\n"),
            "m.stl:3: unexpected 'vertex' (expected 'outer loop')");
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0 1\nouter\n"), "m.stl:3: expected 'outer loop', got 'outer'");
  EXPECT_EQ(stl_error("solid a\nendfacet\n"), "m.stl:2: unexpected 'endfacet' (expected 'facet' or 'endsolid')");
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n"),
            "m.stl:6: a facet loop has 2 vertices (STL facets are triangles)");
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"),
            "m.stl:4: the file ends inside a solid (expected 'vertex')");
  EXPECT_EQ(stl_error("solid a\n"), "m.stl:1: the file ends inside a solid (expected 'facet' or 'endsolid')");
  EXPECT_EQ(stl_error("solid a\nendsolid a\nvertex 0 0 0\n"), "m.stl:3: unexpected 'vertex' (expected 'solid')");
}

TEST(StlReader, BinaryErrorsNameTheByteOffset) {
  std::string bytes = binary_stl(cube_triangles());
  EXPECT_EQ(stl_error(bytes.substr(0, bytes.size() - 1)),  // truncated
            "m.stl: binary STL of 12 triangles must have 684 bytes, the file has 683 (byte offset 80)");
  EXPECT_EQ(stl_error(bytes + "x"), "m.stl: binary STL of 12 triangles must have 684 bytes, the file has 685 (byte offset 80)");
  EXPECT_EQ(stl_error("hello"), "m.stl: not an STL file: too short for binary STL (5 bytes, at least 84) and does not "
                                "begin with 'solid' (byte offset 5)");
  EXPECT_EQ(stl_error(""), "m.stl: not an STL file: too short for binary STL (0 bytes, at least 84) and does not "
                           "begin with 'solid' (byte offset 0)");
  // A non-finite coordinate: triangle 5, vertex 2, y at 84 + 50·5 + 12 + 12·2 + 4.
  std::string bad = bytes;
  const std::size_t off = 84 + 50 * 5 + 12 + 24 + 4;
  const std::uint32_t inf = std::bit_cast<std::uint32_t>(std::numeric_limits<float>::infinity());
  for (int k = 0; k < 4; ++k) bad[off + k] = static_cast<char>((inf >> (8 * k)) & 0xFF);
  EXPECT_EQ(stl_error(bad), "m.stl: triangle 5, vertex 2: y is not a finite number (byte offset 374)");
  ASSERT_EQ(off, 374u);
  // A "solid" text with a NUL byte (a damaged binary file) is reported as binary.
  std::string damaged = binary_stl(cube_triangles(), "solid x");
  damaged.resize(200);
  EXPECT_EQ(stl_error(damaged), "m.stl: binary STL of 12 triangles must have 684 bytes, the file has 200 (byte offset 80)");
}

// ---- files and hulls ----

TEST_F(MeshFiles, ReadByExtensionAndFileErrors) {
  const std::string obj = write("A.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n");
  const std::string off = write("a.off", "OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
  const std::string stl = write("a.Stl", binary_stl(cube_triangles()));
  EXPECT_EQ(io::read_mesh_points(obj).size(), 4u);
  EXPECT_EQ(io::read_mesh_points(off).size(), 4u);
  EXPECT_EQ(io::read_mesh_points(stl).size(), 8u);
  EXPECT_EQ(hull_vertices(io::read_convex_polytope(stl, "P")), cube_corners());

  const std::string missing = (dir_ / "missing.obj").string();
  EXPECT_EQ(error_of([&] { io::read_mesh_points(missing); }), missing + ": cannot read file (No such file or directory)");
  const std::string sub = (dir_ / "sub.stl").string();
  fs::create_directories(sub);
  EXPECT_EQ(error_of([&] { io::read_mesh_points(sub); }), sub + ": cannot read file (is a directory)");
  const std::string ply = write("a.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                         "property float z\nend_header\n1 2 3\n");
  EXPECT_EQ(io::read_mesh_points(ply), std::vector<Vec3>{Vec3(1, 2, 3)});  // PLY: parse_ply's vertices
  const std::string txt = write("a.txt", "v 0 0 0\n");
  EXPECT_EQ(error_of([&] { io::read_mesh_points(txt); }),
            txt + ": unknown 3D shape format '.txt' (expected .obj, .off, .stl or .ply)");
  const std::string bad = write("bad.off", "OFF\n1 0 0\n1 2 three\n");
  EXPECT_EQ(error_of([&] { io::read_convex_polytope(bad, "Q"); }),
            bad + ":3: malformed vertex line: z is not a number: 'three'");
}

TEST_F(MeshFiles, TooFewOrFlatPointsNameFileAndShape) {
  const std::string three = write("three.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_EQ(error_of([&] { io::read_convex_polytope(three, "P"); }),
            three + ": P: only 3 points (a polytope needs 4 affinely independent points)");
  const std::string none = write("none.obj", "# empty\n");
  EXPECT_EQ(error_of([&] { io::read_convex_polytope(none, "Q"); }),
            none + ": Q: only 0 points (a polytope needs 4 affinely independent points)");
  const std::string one = write("one.stl", binary_stl({}));
  EXPECT_EQ(error_of([&] { io::read_convex_polytope(one, "Q"); }),
            one + ": Q: only 0 points (a polytope needs 4 affinely independent points)");
  const std::string flat = write("flat.off", "OFF\n5 0 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n5 5 0\n");
  EXPECT_EQ(error_of([&] { io::read_convex_polytope(flat, "P"); }),
            flat + ": P: all points are coplanar (flat input; need 4 affinely independent points)");
  const std::string same = write("same.obj", "v 1 1 1\nv 1 1 1\nv 1 1 1\nv 1 1 1\nv 1 1 1\n");
  EXPECT_EQ(error_of([&] { io::read_convex_polytope(same, "P"); }),
            same + ": P: all points coincide (need 4 affinely independent points)");
}

TEST_F(MeshFiles, SharedHullsInEveryFormatGiveTheSameHull) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(std::string(PENDEPTH_SHARED_DATA) + "/hulls"))
    if (e.path().extension() == ".obj") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_EQ(files.size(), 60u);
  std::size_t total = 0;
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    const std::vector<Vec3> pts = io::read_mesh_points(f);
    ASSERT_GE(pts.size(), 4u);
    total += pts.size();
    EXPECT_EQ(pts, pendepth::read_obj_vertices(f.string()));
    const ConvexPolytope H = io::read_convex_polytope(f, "P");
    const std::vector<Vec3> hv = hull_vertices(H);
    EXPECT_EQ(hv, hull_vertices(ConvexPolytope::hull(pts)));

    // OFF: all points, shortest round-trip text; the file's own vertex list comes back exactly.
    std::string off = "OFF\n" + std::to_string(pts.size()) + " 0 0\n";
    for (const Vec3& p : pts) {
      for (int k = 0; k < 3; ++k) {
        io::append_double(off, p[k]);
        off += k < 2 ? ' ' : '\n';
      }
    }
    const std::string off_path = write("h.off", off);
    EXPECT_EQ(io::read_mesh_points(off_path), pts);

    // STL, ASCII and binary: the hull's triangles (the data are float-exact, checked here).
    std::vector<Triangle> tris;
    for (const auto& t : H.triangles()) {
      Triangle tr;
      for (int k = 0; k < 3; ++k)
        for (int a = 0; a < 3; ++a) {
          tr.v[k][a] = static_cast<float>(H[t[k]][a]);
          ASSERT_EQ(double(tr.v[k][a]), H[t[k]][a]);
        }
      tris.push_back(tr);
    }
    const std::string ascii_path = write("h.stl", ascii_stl(tris));
    EXPECT_EQ(sorted(io::read_mesh_points(ascii_path)), hv);
    EXPECT_EQ(hull_vertices(io::read_convex_polytope(ascii_path, "P")), hv);
    const std::string bin_path = write("hb.stl", binary_stl(tris));
    EXPECT_EQ(sorted(io::read_mesh_points(bin_path)), hv);
    EXPECT_EQ(hull_vertices(io::read_convex_polytope(bin_path, "P")), hv);
  }
  EXPECT_GT(total, 5000u);
}
