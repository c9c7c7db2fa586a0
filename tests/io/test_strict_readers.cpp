// Strict readers (issue 20, part 2): declared counts are exact (OFF), element references name
// existing vertices (OBJ), ASCII STL has its full structure, a query file's header is accepted only
// when it is exactly the expected names, offending bytes are quoted printably (a NUL does not cut
// a message short or end the input), files are read to their end (FIFOs), and the format of an
// extensionless input is recognised by its content. Each finding of the issue has a test here.
#include <pendepth/io.hpp>

#include <gtest/gtest.h>

#include "io/reader_errors.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

using pendepth::InvalidInput;
using pendepth::Vec3;
namespace io = pendepth::io;
namespace fs = std::filesystem;

namespace {

using io_test::error_of;
using io_test::obj_error;
using io_test::off_error;
using io_test::stl_error;
std::string csv_error(std::string_view text) { return error_of([&] { io::parse_queries_csv(text, "q.csv"); }); }
std::string csv3_error(std::string_view text) { return error_of([&] { io::parse_queries3_csv(text, "q.csv"); }); }
std::string wkt_error(std::string_view text) { return error_of([&] { io::parse_wkt_polygon(text, "p.wkt"); }); }

const std::string kCube8 = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n1 1 0\n1 0 1\n0 1 1\n";

}  // namespace

// ---- OFF: the header's counts are exact ----

TEST(StrictOff, HeaderCountsMustMatchTheVerticesAndFaces) {
  // The input: 5 vertices and 6 faces declared, 8 vertex lines given. Before: accepted,
  // the first 5 vertices used.
  EXPECT_EQ(off_error("OFF\n5 6 0\n" + kCube8),
            "m.off:8: malformed face 0: 1 vertex (at least 3) (the header at line 2 declares 5 vertices and 6 faces)");
  EXPECT_EQ(off_error("OFF\n5 0 0\n" + kCube8),
            "m.off:8: unexpected '1' after the last face (the header at line 2 declares 5 vertices and 0 faces)");
  EXPECT_EQ(io::parse_off_points("OFF\n8 0 0\n" + kCube8).size(), 8u);
  // Fewer faces than declared, more faces than declared.
  const std::string tet = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  EXPECT_EQ(off_error(tet + "3 0 1 2\n3 0 1 3\n"), "m.off:8: the file ends after 2 of 4 faces");
  EXPECT_EQ(off_error(tet + "3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n3 0 1 2\n"),
            "m.off:11: unexpected '3' after the last face (the header at line 2 declares 4 vertices and 4 faces)");
  // Malformed faces: an index out of range, too few indices, a non-integer, a bad colour.
  EXPECT_EQ(off_error(tet + "3 0 1 4\n"),
            "m.off:7: face 0: vertex index 4 is out of range (the file has 4 vertices) (the header at line 2 declares 4 "
            "vertices and 4 faces)");
  EXPECT_EQ(off_error(tet + "3 0 1 2\n4 0 1 2\n"),
            "m.off:8: malformed face 1: only 3 of its 4 vertex indices (the header at line 2 declares 4 vertices and 4 faces)");
  EXPECT_EQ(off_error(tet + "3 0 1 -2\n"),
            "m.off:7: malformed face 0: vertex index 2 is '-2' (expected a non-negative integer) (the header at line 2 "
            "declares 4 vertices and 4 faces)");
  EXPECT_EQ(off_error(tet + "3.0 0 1 2\n"),
            "m.off:7: malformed face 0: expected its vertex count (an integer), got '3.0' (the header at line 2 declares "
            "4 vertices and 4 faces)");
  EXPECT_EQ(off_error(tet + "3 0 1 2 red\n"),
            "m.off:7: malformed face 0: 'red' after its 3 vertex indices is not a colour number (the header at line 2 "
            "declares 4 vertices and 4 faces)");
  EXPECT_EQ(off_error(tet + "3 0 1 2 1 1\n"),
            "m.off:7: malformed face 0: 3 vertex indices then 2 numbers (a colour is 0, 1, 3 or 4 numbers) (the header "
            "at line 2 declares 4 vertices and 4 faces)");
  // A huge declared count with a short file ends cleanly (no allocation of the declared size).
  EXPECT_EQ(off_error("OFF\n18446744073709551615 0 0\n0 0 0\n"),
            "m.off:3: the file ends after 1 of 18446744073709551615 vertices");
  EXPECT_EQ(off_error("OFF\n1 18446744073709551615 0\n0 0 0\n"), "m.off:3: the file ends after 0 of 18446744073709551615 faces");
}

// ---- OBJ: element references are well formed and in range ----

TEST(StrictObj, ElementReferencesNameExistingVertices) {
  const std::string v4 = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  // Accepted: absolute, relative, with texture vertices and normals, forward references.
  EXPECT_EQ(io::parse_obj_points(v4 + "f 1 2 3\nf -1 -2 -3 -4\nl 1 2\np 4\nvt 0 0\nvn 0 0 1\nf 1/1 2/1 3/1\n"
                                      "f 1//1 2//1 3//1\nf 1/1/1 2/1/1 3/1/-1\nf 1 2 5\nv 1 1 1\n")
                .size(),
            5u);
  EXPECT_EQ(obj_error(v4 + "f 1 2 5\n"), "m.obj:5: reference to vertex 5, but the file has 4 vertices");
  EXPECT_EQ(obj_error(v4 + "f 1 2 0\n"),
            "m.obj:5: malformed face: reference 3 is '0' (expected v, v/vt, v//vn or v/vt/vn with non-zero integers)");
  EXPECT_EQ(obj_error(v4 + "f 1 2 -5\n"),
            "m.obj:5: face reference 3 ('-5') names a vertex before the first (4 vertices read so far)");
  EXPECT_EQ(obj_error(v4 + "f 1 2\n"), "m.obj:5: malformed face: 2 vertex references (at least 3)");
  EXPECT_EQ(obj_error(v4 + "f 1 2 3.5\n"),
            "m.obj:5: malformed face: reference 3 is '3.5' (expected v, v/vt, v//vn or v/vt/vn with non-zero integers)");
  EXPECT_EQ(obj_error(v4 + "f 1/ 2/ 3/\n"),
            "m.obj:5: malformed face: reference 1 is '1/' (expected v, v/vt, v//vn or v/vt/vn with non-zero integers)");
  EXPECT_EQ(obj_error(v4 + "f 1/1/1/1 2 3\n"),
            "m.obj:5: malformed face: reference 1 is '1/1/1/1' (expected v, v/vt, v//vn or v/vt/vn with non-zero "
            "integers)");
  EXPECT_EQ(obj_error(v4 + "f 1/1 2/1 3/1\n"), "m.obj:5: reference to texture vertex 1, but the file has 0 texture vertices");
  EXPECT_EQ(obj_error(v4 + "vn 0 0 1\nf 1//2 2//1 3//1\n"), "m.obj:6: reference to normal 2, but the file has 1 normals");
  EXPECT_EQ(obj_error(v4 + "l 1\n"), "m.obj:5: malformed line element: 1 vertex reference (at least 2)");
  EXPECT_EQ(obj_error(v4 + "l 1//1 2\n"),
            "m.obj:5: malformed line element: reference 1 is '1//1' (expected v or v/vt with non-zero integers)");
  EXPECT_EQ(obj_error(v4 + "p 1/1\n"), "m.obj:5: malformed point element: reference 1 is '1/1' (expected a non-zero integer)");
  EXPECT_EQ(obj_error(v4 + "f 1 2 -9223372036854775808\n"),
            "m.obj:5: face reference 3 ('-9223372036854775808') names a vertex before the first (4 vertices read so far)");
  // Texture vertices and normals are numbers; statements outside the OBJ specification are errors.
  EXPECT_EQ(obj_error("vn 0 0\n"), "m.obj:1: malformed normal line: expected 'vn i j k', got 2 numbers");
  EXPECT_EQ(obj_error("vt\n"), "m.obj:1: malformed texture vertex line: expected 'vt u [v [w]]', got 0 numbers");
  EXPECT_EQ(obj_error("vt 0 x\n"), "m.obj:1: malformed texture vertex line: field 2 is not a number: 'x'");
  EXPECT_EQ(obj_error(v4 + "vx 1 2 3\n"), "m.obj:5: unknown OBJ statement 'vx'");
  EXPECT_EQ(obj_error("\x7f" "ELF\x02\x01\n"), "m.obj:1: unknown OBJ statement '\\x7FELF\\x02\\x01'");
  EXPECT_EQ(obj_error("v 0 0 \\\n0\n"), "m.obj:1: line continuation ('\\' at the end of a line) is not supported");
}

// ---- STL ASCII: the whole structure ----

TEST(StrictStl, AsciiFacetsHaveTheirFullStructure) {
  const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  EXPECT_EQ(io::parse_stl_points("solid a\n" + facet + "endsolid a\n").size(), 3u);
  EXPECT_EQ(io::parse_stl_points("solid a\nfacet normal nan nan nan\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                 "vertex 0 1 0\nendloop\nendfacet\nendsolid\n")
                .size(),
            3u);  // the normal is not used: a degenerate facet's NaN normal is accepted
  EXPECT_EQ(stl_error("solid a\nfacet\n"), "m.stl:2: expected 'facet normal nx ny nz', got 'facet'");
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0\n"), "m.stl:2: expected 'facet normal nx ny nz', got 'facet normal 0 0'");
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0 one\n"), "m.stl:2: malformed facet normal: field 5 is not a number: 'one'");
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0 1\nouter loop now\n"), "m.stl:3: expected 'outer loop', got 'outer loop now'");
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0 1\nendfacet\n"), "m.stl:3: unexpected 'endfacet' (expected 'outer loop')");
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\n"),
            "m.stl:7: a facet loop has more than 3 vertices (STL facets are triangles)");
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop x\n"),
            "m.stl:7: expected 'endloop', got 'endloop x'");
  EXPECT_EQ(stl_error("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
                      "outer loop\n"),
            "m.stl:8: unexpected 'outer' (expected 'endfacet')");
  EXPECT_EQ(stl_error("solid a\n" + facet + "endsolid a\n\x01\x02garbage\n"),
            "m.stl:10: unexpected '\\x01\\x02garbage' (expected 'solid')");
  // Binary: the triangle count must match the size exactly (also checked in test_mesh_readers).
  std::string bin(84 + 50, '\0');
  bin[80] = 2;
  EXPECT_EQ(stl_error(bin), "m.stl: binary STL of 2 triangles must have 184 bytes, the file has 134 (byte offset 80)");
}

// ---- query CSV: a header only when it is exactly the expected names ----

TEST(StrictQueriesCsv, OnlyTheExactHeaderIsSkipped) {
  // The inputs: each was taken as a header (no rows, exit 0).
  EXPECT_EQ(csv_error("1;1;0;0\n"), "q.csv:1: expected 4 numbers, got 1 (fields are separated by ',', not ';')");
  EXPECT_EQ(csv_error("\"1\",\"1\",\"0\",\"0\"\n"), "q.csv:1: field 1 is not a number: '\"1\"'");
  EXPECT_EQ(csv_error("0x1,1,0,0\n"), "q.csv:1: field 1 is not a number: '0x1'");
  EXPECT_EQ(csv_error("\x89PNG\r\n\x1a\n"), "q.csv:1: expected 4 numbers, got 1");
  EXPECT_EQ(csv_error("\x01,\x02,\x03,\xff\n"), "q.csv:1: field 1 is not a number: '\\x01'");
  EXPECT_EQ(csv_error("1\t1\t0\t0\n"), "q.csv:1: expected 4 numbers, got 1 (fields are separated by ',', not tabs)");
  // Headers: exactly the names (spaces and tabs around them allowed), first data line only.
  EXPECT_TRUE(io::parse_queries_csv("x,y,dx,dy\n").empty());
  EXPECT_TRUE(io::parse_queries_csv("# c\n\n x ,\ty , dx,dy \r\n").empty());
  EXPECT_EQ(io::parse_queries_csv("x,y,dx,dy\n1,2,3,4\n").size(), 1u);
  EXPECT_TRUE(io::parse_queries3_csv("x,y,z,dx,dy,dz\n").empty());
  EXPECT_EQ(csv_error("X,Y,DX,DY\n"), "q.csv:1: field 1 is not a number: 'X' (a header line must be exactly 'x,y,dx,dy')");
  EXPECT_EQ(csv_error("x,y,dx,dz\n"), "q.csv:1: field 1 is not a number: 'x' (a header line must be exactly 'x,y,dx,dy')");
  EXPECT_EQ(csv_error("x,y\n"), "q.csv:1: expected 4 numbers, got 2 (a header line must be exactly 'x,y,dx,dy')");
  EXPECT_EQ(csv_error("x,y,z,dx,dy,dz\n"), "q.csv:1: expected 4 numbers, got 6 (a 3D query; the shapes are 2D)");
  EXPECT_EQ(csv3_error("x,y,dx,dy\n"), "q.csv:1: expected 6 numbers, got 4 (a 2D query; the shapes are 3D)");
  EXPECT_EQ(csv3_error("t,x,y,z,dx,dy\n"),
            "q.csv:1: field 1 is not a number: 't' (a header line must be exactly 'x,y,z,dx,dy,dz')");
  EXPECT_EQ(csv_error("1,2,3,4\nx,y,dx,dy\n"), "q.csv:2: field 1 is not a number: 'x'");
}

// ---- quoting: NUL and other non-printable bytes ----

TEST(StrictQuoting, NulInAWktNumberIsShownAndIsNotTheEnd) {
  using namespace std::string_literals;
  // The input: a NUL inside a number cut the message at the NUL.
  const std::string nul = "POLYGON ((0 0, 1\0002 0, 1 1))"s;
  EXPECT_EQ(wkt_error(nul), "p.wkt:1: expected a number for x, got '1\\x002'");
  EXPECT_EQ(wkt_error("POLYGON ((0 0, 1 0, 0 1))\0"s), "p.wkt:1: trailing text after the polygon: '\\x00'");
  EXPECT_EQ(wkt_error("POLYGON ((0 0, 1 0, 0 1)\0)"s), "p.wkt:1: missing ',' or ')' after the outer ring, got '\\x00'");
  EXPECT_EQ(wkt_error("\0POLYGON ((0 0, 1 0, 0 1))"s), "p.wkt:1: expected a geometry type (POLYGON), got '\\x00POLYGON'");
  EXPECT_EQ(error_of([&] { io::parse_wkt_geometry("MULTIPOINT ((0 0)\0"s, "g.wkt"); }),
            "g.wkt:1: missing ',' or ')' after point 0, got '\\x00'");
  EXPECT_EQ(wkt_error("POLYGON ((0 0, 1 0, 0 \x1b[31m1))"), "p.wkt:1: expected a number for y, got '\\x1B[31m1'");
  EXPECT_EQ(csv_error("0,0,1\0,0\n"s), "q.csv:1: field 3 is not a number: '1\\x00'");
  EXPECT_EQ(obj_error("v 0 0 0\0\n"s), "m.obj:1: malformed vertex line: z is not a number: '0\\x00'");
  EXPECT_EQ(off_error("OFF\n1 0 0\n0 \xff 0\n"), "m.off:3: malformed vertex line: y is not a number: '\\xFF'");
  // Long tokens are cut after 24 bytes.
  EXPECT_EQ(csv_error(std::string(40, '7') + "x,0,0,0\n"), "q.csv:1: field 1 is not a number: '777777777777777777777777...'");
}

// ---- files are read to their end: FIFOs, streams ----

class StrictFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pendepth-test-strict-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(StrictFiles, ANamedPipeIsReadToItsEnd) {
  // Before: a FIFO has no size, so it was read as empty ("empty input: expected a POLYGON").
  const fs::path fifo = dir_ / "shape.wkt";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string big = "POLYGON ((0 0, 4 0, 4 3, 0 3, 0 0))";
  big += std::string(200000, ' ');  // more than a pipe holds at once
  std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << big; });
  const io::WktPolygon w = io::read_wkt_polygon(fifo);
  writer.join();
  ASSERT_EQ(w.rings.size(), 1u);
  EXPECT_EQ(w.rings[0].size(), 4u);

  const fs::path fifo3 = dir_ / "shape.off";
  ASSERT_EQ(::mkfifo(fifo3.c_str(), 0600), 0);
  std::thread writer3([&] { std::ofstream(fifo3, std::ios::binary) << "OFF\n8 0 0\n" + kCube8; });
  EXPECT_EQ(io::read_mesh_points(fifo3).size(), 8u);
  writer3.join();
}

TEST_F(StrictFiles, StreamsAndFilesReadExactly) {
  std::string bytes;
  for (int i = 0; i < 300000; ++i) bytes += static_cast<char>(i * 7 + i / 256);
  std::istringstream in(bytes);
  EXPECT_EQ(io::read_stream(in, "<stdin>"), bytes);
  std::istringstream empty("");
  EXPECT_EQ(io::read_stream(empty, "<stdin>"), "");
  const fs::path f = dir_ / "b.bin";
  std::ofstream(f, std::ios::binary) << bytes;
  EXPECT_EQ(io::read_text_file(f), bytes);
  EXPECT_EQ(io::read_text_file("/dev/null"), "");
}

// ---- the format of an input without an extension ----

TEST(StrictFormat, GuessedFromTheContent) {
  using F = io::ShapeFormat;
  EXPECT_EQ(io::guess_shape_format("POLYGON ((0 0, 1 0, 0 1))"), F::Wkt);
  EXPECT_EQ(io::guess_shape_format("\xEF\xBB\xBF  polygon((0 0, 1 0, 0 1))"), F::Wkt);
  EXPECT_EQ(io::guess_shape_format("MULTIPOLYGON EMPTY"), F::Wkt);  // the WKT reader names the problem
  EXPECT_EQ(io::guess_shape_format("# made by hand\nv 0 0 0\n"), F::Obj);
  EXPECT_EQ(io::guess_shape_format("mtllib a.mtl\n"), F::Obj);
  EXPECT_EQ(io::guess_shape_format("OFF\n4 0 0\n"), F::Off);
  EXPECT_EQ(io::guess_shape_format("COFF 4 0 0\n"), F::Off);
  EXPECT_EQ(io::guess_shape_format("# no keyword\n4 0 0\n"), F::Off);
  EXPECT_EQ(io::guess_shape_format("  solid cube\nfacet normal 0 0 1\n"), F::Stl);
  std::string bin(84 + 50, 'x');
  bin[80] = 1, bin[81] = bin[82] = bin[83] = 0;
  EXPECT_EQ(io::guess_shape_format(bin), F::Stl);
  EXPECT_EQ(io::guess_shape_format(""), std::nullopt);
  EXPECT_EQ(io::guess_shape_format("# only a comment\n"), std::nullopt);
  EXPECT_EQ(io::guess_shape_format("hello world"), std::nullopt);
  EXPECT_EQ(io::guess_shape_format("ply\nformat ascii 1.0\n"), F::Ply);
  EXPECT_EQ(io::guess_shape_format("ply\r\nformat ascii 1.0\r\n"), F::Ply);
  EXPECT_EQ(io::guess_shape_format("plyx\n"), std::nullopt);
  EXPECT_EQ(io::shape_format_of("a/b.WKT"), F::Wkt);
  EXPECT_EQ(io::shape_format_of("b.Stl"), F::Stl);
  EXPECT_EQ(io::shape_format_of("b.PLY"), F::Ply);
  EXPECT_EQ(io::shape_format_of("/dev/stdin"), std::nullopt);
  EXPECT_EQ(error_of([] { io::parse_mesh_points("POLYGON ((0 0, 1 0, 0 1))", io::ShapeFormat::Wkt, "<stdin>"); }),
            "<stdin>: a 2D shape (WKT) where a 3D shape (.obj, .off, .stl, .ply) is expected");
  EXPECT_EQ(error_of([] {
              io::convex_polytope_from_points(io::parse_mesh_points("v 0 0 0\n", io::ShapeFormat::Obj, "<stdin>"),
                                              "<stdin>", "P");
            }),
            "<stdin>: P: only 1 point (a polytope needs 4 affinely independent points)");
}
