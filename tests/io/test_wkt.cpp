// WKT reader/writer: values and source lines, every error with its line, holes, round trips
// (to_wkt → parse gives back the same doubles, bit for bit), convex-polygon errors mapped to the
// line of the vertex they name.
#include <pendepth/io.hpp>

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

using pendepth::ConvexPolygon;
using pendepth::InvalidInput;
using pendepth::Vec2;
namespace io = pendepth::io;
namespace fs = std::filesystem;

namespace {

std::string error_of(std::string_view text) {
  try {
    io::parse_wkt_polygon(text, "in.wkt");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(no error)";
}

// A scratch directory removed at the end of each test.
class WktFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pendepth-test-io-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  std::string convex_error(const std::string& path) {
    try {
      io::read_convex_polygon(path, "P");
    } catch (const InvalidInput& e) {
      return e.what();
    }
    return "(no error)";
  }
  fs::path dir_;
};

// The message ConvexPolygon itself gives for a ring (the reader must pass it on unchanged).
std::string polygon_error(const std::vector<Vec2>& ring) {
  try {
    ConvexPolygon P(ring, "P");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(no error)";
}

// One vertex per line, starting at line `first`: vertex k is on line first + k.
std::string one_per_line(const std::vector<Vec2>& ring) {
  std::string s = "POLYGON ((\n";
  for (std::size_t k = 0; k < ring.size(); ++k) {
    s += std::to_string(ring[k].x()) + " " + std::to_string(ring[k].y());
    s += k + 1 < ring.size() ? ",\n" : "\n";
  }
  return s + "))\n";
}

}  // namespace

TEST(Wkt, ValuesAndLines) {
  const auto w = io::parse_wkt_polygon("\n  polygon((0 0,\n 4 0, 4 4,\n\n 0 4, 0 0))\n");
  ASSERT_EQ(w.rings.size(), 1u);
  EXPECT_EQ(w.first_line, 2u);
  const std::vector<Vec2> expect = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};  // closing vertex dropped
  EXPECT_EQ(w.rings[0], expect);
  EXPECT_EQ(w.lines[0], (std::vector<std::size_t>{2, 3, 3, 5}));
}

TEST(Wkt, NumberSyntaxAndOpenRing) {
  // Signs, exponents, leading dot, tabs and CRLF; a ring without a repeated closing vertex.
  const auto w = io::parse_wkt_polygon("PoLyGoN\t(\r\n( -1.5e2 +2 ,.25 -0, 1E-3 7.0 ) )");
  ASSERT_EQ(w.rings.size(), 1u);
  ASSERT_EQ(w.rings[0].size(), 3u);
  EXPECT_EQ(w.rings[0][0], Vec2(-150, 2));
  EXPECT_EQ(w.rings[0][1], Vec2(0.25, 0));
  EXPECT_TRUE(std::signbit(w.rings[0][1].y()));
  EXPECT_EQ(w.rings[0][2], Vec2(1e-3, 7));
  EXPECT_EQ(w.lines[0], (std::vector<std::size_t>{2, 2, 2}));
}

TEST(Wkt, UnderflowRoundsLikeEveryReader) {
  // One rule for every reader (src/io/number.hpp): below the double range rounds as strtod does.
  const auto w = io::parse_wkt_polygon("POLYGON ((1e-400 0, 1 4.9e-324, 0 1, -1e-320 -2.5e-324))");
  ASSERT_EQ(w.rings[0].size(), 4u);
  EXPECT_EQ(w.rings[0][0].x(), 0.0);
  EXPECT_EQ(w.rings[0][1].y(), 4.9e-324);
  EXPECT_EQ(w.rings[0][3].x(), -1e-320);
  EXPECT_TRUE(std::signbit(w.rings[0][3].x()));
  EXPECT_EQ(w.rings[0][3].y(), -4.9e-324);  // -2.5e-324 rounds to the smallest subnormal
}

TEST(Wkt, ByteOrderMark) {
  const auto w = io::parse_wkt_polygon("\xEF\xBB\xBFPOLYGON ((0 0, 1 0, 0 1))");
  EXPECT_EQ(w.rings.at(0).size(), 3u);
}

TEST(Wkt, Holes) {
  const auto w = io::parse_wkt_polygon(
      "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0),\n"
      "         (2 2, 2 4, 4 4, 4 2, 2 2),\n"
      "         (6 6, 6 8, 8 8))");
  ASSERT_EQ(w.rings.size(), 3u);
  EXPECT_EQ(w.rings[1].size(), 4u);
  EXPECT_EQ(w.rings[2].size(), 3u);
  EXPECT_EQ(w.rings[2][2], Vec2(8, 8));
  EXPECT_EQ(w.lines[1], (std::vector<std::size_t>{2, 2, 2, 2}));
  EXPECT_EQ(w.lines[2], (std::vector<std::size_t>{3, 3, 3}));
}

TEST(Wkt, ErrorsNameTheLine) {
  EXPECT_EQ(error_of(""), "in.wkt:1: empty input: expected a POLYGON");
  EXPECT_EQ(error_of("\n \n"), "in.wkt:3: empty input: expected a POLYGON");
  EXPECT_EQ(error_of("\nLINESTRING (0 0, 1 1)"), "in.wkt:2: unknown geometry type 'LINESTRING' (expected POLYGON)");
  EXPECT_EQ(error_of("MULTIPOLYGON (((0 0, 1 0, 0 1)))"),
            "in.wkt:1: unknown geometry type 'MULTIPOLYGON' (expected POLYGON)");
  EXPECT_EQ(error_of("((0 0, 1 0, 0 1))"), "in.wkt:1: expected a geometry type (POLYGON), got '('");
  EXPECT_EQ(error_of("\n\nPOLYGON\nEMPTY"), "in.wkt:4: POLYGON EMPTY: the polygon has no rings");
  EXPECT_EQ(error_of("POLYGON Z ((0 0 0, 1 0 0, 0 1 0))"), "in.wkt:1: POLYGON Z: only 2D coordinates are supported");
  EXPECT_EQ(error_of("POLYGON\n(0 0, 1 0, 0 1)"), "in.wkt:2: missing '(' at the start of the outer ring, got '0'");
  EXPECT_EQ(error_of("POLYGON 0 0, 1 0, 0 1)"), "in.wkt:1: missing '(' after POLYGON, got '0'");
  EXPECT_EQ(error_of("POLYGON ((0 0,\n1 0,\n0 1)\n"), "in.wkt:4: missing ',' or ')' after the outer ring, got end of input");
  EXPECT_EQ(error_of("POLYGON ((0 0,\n1 0,\n0 1"),
            "in.wkt:3: missing ',' or ')' after point 2 of the outer ring, got end of input");
  EXPECT_EQ(error_of("POLYGON ((0 0, 1 0, 0 1) (2 2, 3 2, 2 3))"),
            "in.wkt:1: missing ',' or ')' after the outer ring, got '('");
  EXPECT_EQ(error_of("POLYGON ((0 0,\n1 a,\n0 1))"), "in.wkt:2: expected a number for y, got 'a'");
  EXPECT_EQ(error_of("POLYGON ((0 0, 1.5x 0, 0 1))"), "in.wkt:1: expected a number for x, got '1.5x'");
  EXPECT_EQ(error_of("POLYGON ((0 0, 1,0, 0 1))"), "in.wkt:1: expected a number for y, got ','");
  EXPECT_EQ(error_of("POLYGON ((0 0, +-1 0, 0 1))"), "in.wkt:1: expected a number for x, got '+-1'");
  EXPECT_EQ(error_of("POLYGON ((0 0, 1 0,\n\n0 inf))"), "in.wkt:3: non-finite number 'inf'");
  EXPECT_EQ(error_of("POLYGON ((0 0, NaN 0, 0 1))"), "in.wkt:1: non-finite number 'NaN'");
  EXPECT_EQ(error_of("POLYGON ((0 0, 1 0, 0 1e400))"), "in.wkt:1: number out of range '1e400'");
  EXPECT_EQ(error_of("POLYGON ((0 0,\n1 0 5, 0 1))"),
            "in.wkt:2: point 1 of the outer ring has more than 2 coordinates (only 2D is supported)");
  EXPECT_EQ(error_of("POLYGON (\n(0 0, 1 1, 0 0))"), "in.wkt:2: the outer ring has 2 point(s); a ring needs at least 3");
  EXPECT_EQ(error_of("POLYGON ((0 0, 9 0, 0 9),\n  (1 1, 2 1))"), "in.wkt:2: ring 1 has 2 point(s); a ring needs at least 3");
  EXPECT_EQ(error_of("POLYGON ((0 0, 1 0, 0 1))\n\n  garbage"), "in.wkt:3: trailing text after the polygon: 'garbage'");
  EXPECT_EQ(error_of("POLYGON ((0 0, 1 0, 0 1)))"), "in.wkt:1: trailing text after the polygon: ')'");
  EXPECT_EQ(error_of("POLYGON ((0 0, 1 0, 0 1)) POLYGON ((0 0, 1 0, 0 1))"),
            "in.wkt:1: trailing text after the polygon: 'POLYGON'");
}

TEST(Wkt, RoundTripRandomDoublesBitForBit) {
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> uni(-1e3, 1e3);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vec2> ring(3 + rng() % 40);
    for (Vec2& p : ring) {
      if (trial % 2 == 0) {
        p = Vec2(uni(rng), uni(rng));
      } else {  // any finite bit pattern: subnormals, huge exponents, negative zero
        auto any = [&] {
          double x;
          do x = std::bit_cast<double>(rng()); while (!std::isfinite(x));
          return x;
        };
        p = Vec2(any(), any());
      }
    }
    // Round trip of the text is exact; a ring whose last point equals the first would lose it.
    if (ring.front() == ring.back()) ring.back().x() += 1;
    const auto w = io::parse_wkt_polygon(io::to_wkt(ring));
    ASSERT_EQ(w.rings.size(), 1u);
    ASSERT_EQ(w.rings[0].size(), ring.size());
    for (std::size_t k = 0; k < ring.size(); ++k) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(w.rings[0][k].x()), std::bit_cast<std::uint64_t>(ring[k].x()));
      EXPECT_EQ(std::bit_cast<std::uint64_t>(w.rings[0][k].y()), std::bit_cast<std::uint64_t>(ring[k].y()));
    }
  }
}

TEST(Wkt, ToWktOfConvexPolygonIsItsNormalForm) {
  const ConvexPolygon P({{4, 4}, {4, 0}, {2, 0}, {0, 0}, {0, 4}}, "P");  // clockwise, collinear
  EXPECT_EQ(io::to_wkt(P), "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))");
  const double nan = std::nan("");
  const std::vector<Vec2> bad = {{0, 0}, {1, nan}, {0, 1}};
  EXPECT_THROW(io::to_wkt(bad), InvalidInput);
}

TEST_F(WktFiles, ConvexPolygonRoundTripThroughFile) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> ang(0, 2 * M_PI), rad(0.5, 2);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vec2> pts(5 + rng() % 100);
    for (Vec2& p : pts) {
      const double a = ang(rng), r = rad(rng);
      p = Vec2(1e3 + r * std::cos(a), -7 + r * std::sin(a));
    }
    const ConvexPolygon H = ConvexPolygon::hull(pts, "H");
    const std::string path = write("h.wkt", io::to_wkt(H) + "\n");
    const ConvexPolygon R = io::read_convex_polygon(path, "R");
    ASSERT_EQ(R.size(), H.size());
    for (std::size_t k = 0; k < H.size(); ++k) EXPECT_EQ(R[k], H[k]);
  }
}

TEST_F(WktFiles, ConvexPolygonErrorsPointAtTheVertexLine) {
  // Reflex vertex 3 on line 1 + 1 + 3 = 5 (the keyword line comes first).
  const std::vector<Vec2> dent = {{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}};
  std::string path = write("dent.wkt", one_per_line(dent));
  EXPECT_EQ(convex_error(path), path + ":5: " + polygon_error(dent));
  EXPECT_NE(polygon_error(dent).find("vertex 3"), std::string::npos);

  // Bow tie: the message names an edge; the line is that of the edge's start vertex.
  const std::vector<Vec2> bowtie = {{0, 0}, {2, 2}, {2, 0}, {0, 2}};
  path = write("bowtie.wkt", one_per_line(bowtie));
  const std::string msg = polygon_error(bowtie);
  const std::size_t at = msg.find("edge ");
  ASSERT_NE(at, std::string::npos) << msg;
  const std::size_t k = std::stoul(msg.substr(at + 5));
  EXPECT_EQ(convex_error(path), path + ":" + std::to_string(2 + k) + ": " + msg);

  // Spike (edge folding back): vertex 2 of the input.
  const std::vector<Vec2> spike = {{0, 0}, {4, 0}, {6, 0}, {5, 0}, {4, 4}};
  path = write("spike.wkt", one_per_line(spike));
  const std::string smsg = polygon_error(spike);
  const std::size_t sv = smsg.find("vertex ");
  ASSERT_NE(sv, std::string::npos) << smsg;
  EXPECT_EQ(convex_error(path), path + ":" + std::to_string(2 + std::stoul(smsg.substr(sv + 7))) + ": " + smsg);

  // No vertex named (all collinear): the line of the first vertex.
  const std::vector<Vec2> flat = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  path = write("flat.wkt", "\n" + one_per_line(flat));
  EXPECT_EQ(convex_error(path), path + ":3: " + polygon_error(flat));

  path = write("holes.wkt", "POLYGON ((0 0, 10 0, 10 10, 0 10), (2 2, 2 4, 4 4))");
  EXPECT_EQ(convex_error(path), path + ": convex polygons cannot have holes (read it with io::read_polygon: polygons with holes are supported against a convex polygon)");

  path = (dir_ / "missing.wkt").string();
  EXPECT_EQ(convex_error(path), path + ": cannot read file (No such file or directory)");
  EXPECT_EQ(convex_error(dir_.string()), dir_.string() + ": cannot read file (is a directory)");
}
