// Batch query CSV: skipped lines, the optional header, exact values, every error with its line.
#include <pendepth/io.hpp>

#include <gtest/gtest.h>

#include <random>

using pendepth::InvalidInput;
using pendepth::Vec2;
namespace io = pendepth::io;

namespace {
std::string error_of(std::string_view text) {
  try {
    io::parse_queries_csv(text, "q.csv");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST(QueriesCsv, SkipsBlankCommentsAndHeader) {
  const auto q = io::parse_queries_csv(
      "# offsets then directions\n"
      "\n"
      "x, y, dx, dy\r\n"
      "  1.5 ,-2,0,0\r\n"
      "   \n"
      "# another comment\n"
      "+3e2,4,-1,.5");
  ASSERT_EQ(q.size(), 2u);
  EXPECT_EQ(q[0].t, Vec2(1.5, -2));
  EXPECT_EQ(q[0].d, Vec2(0, 0));
  EXPECT_EQ(q[0].line, 4u);
  EXPECT_EQ(q[1].t, Vec2(300, 4));
  EXPECT_EQ(q[1].d, Vec2(-1, 0.5));
  EXPECT_EQ(q[1].line, 7u);
  const auto bom = io::parse_queries_csv("\xEF\xBB\xBF" "1,2,3,4\n");  // as spreadsheets write it
  ASSERT_EQ(bom.size(), 1u);
  EXPECT_EQ(bom[0].t, Vec2(1, 2));
  EXPECT_TRUE(io::parse_queries_csv("").empty());
  EXPECT_TRUE(io::parse_queries_csv("x,y,dx,dy\n").empty());
}

TEST(QueriesCsv, RandomValuesReadBackExactly) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-1e6, 1e6);
  std::vector<io::Query2> want(500);
  std::string text = "x,y,dx,dy\n";
  for (std::size_t i = 0; i < want.size(); ++i) {
    want[i].t = Vec2(u(rng), u(rng));
    want[i].d = i % 3 == 0 ? Vec2(0, 0) : Vec2(u(rng), u(rng));
    for (double x : {want[i].t.x(), want[i].t.y(), want[i].d.x(), want[i].d.y()}) {
      io::append_double(text, x);
      text += ',';
    }
    text.back() = '\n';
  }
  const auto got = io::parse_queries_csv(text);
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(got[i].t, want[i].t);
    EXPECT_EQ(got[i].d, want[i].d);
    EXPECT_EQ(got[i].line, i + 2);
  }
}

TEST(QueriesCsv, UnderflowRoundsLikeEveryReader) {
  const auto q = io::parse_queries_csv("1e-400,4.9e-324,-1e-320,+2.5e-324\n");
  ASSERT_EQ(q.size(), 1u);
  EXPECT_EQ(q[0].t, Vec2(0, 4.9e-324));
  EXPECT_EQ(q[0].d, Vec2(-1e-320, 4.9e-324));
}

TEST(QueriesCsv, ErrorsNameTheLine) {
  EXPECT_EQ(error_of("x,y,dx,dy\n0,0,1,0\n\n1,2,3\n"), "q.csv:4: expected 4 numbers, got 3");
  EXPECT_EQ(error_of("0,0,1,0,5\n"), "q.csv:1: expected 4 numbers, got 5");
  EXPECT_EQ(error_of("0,0,0,1,0,0\n"), "q.csv:1: expected 4 numbers, got 6 (a 3D query; the shapes are 2D)");
  EXPECT_EQ(error_of("1 2 3 4\n"), "q.csv:1: expected 4 numbers, got 1");
  EXPECT_EQ(error_of("0,0,1,0\n0,,1,0\n"), "q.csv:2: field 2 is empty");
  EXPECT_EQ(error_of("0,0,1,0\n0,0,1,zero\n"), "q.csv:2: field 4 is not a number: 'zero'");
  EXPECT_EQ(error_of("0,0,1,0\n0,0x,1,0\n"), "q.csv:2: field 2 is not a number: '0x'");
  EXPECT_EQ(error_of("0,inf,1,0\n"), "q.csv:1: field 2 is not a finite number: 'inf'");
  EXPECT_EQ(error_of("0,0,1e999,0\n"), "q.csv:1: field 3 is not a finite number: '1e999'");
  EXPECT_EQ(error_of("nan,0,1,0\n"), "q.csv:1: field 1 is not a finite number: 'nan'");
  // Only the first row may be a header.
  EXPECT_EQ(error_of("x,y,dx,dy\nx,y,dx,dy\n"), "q.csv:2: field 1 is not a number: 'x'");
  EXPECT_EQ(error_of("0,0,1,0\nx,y,dx,dy\n"), "q.csv:2: field 1 is not a number: 'x'");
}

namespace {
std::string error3_of(std::string_view text) {
  try {
    io::parse_queries3_csv(text, "q3.csv");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST(QueriesCsv3, ValuesHeaderAndErrors) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  std::vector<pendepth::Vec3> t(300), d(300);
  std::string text = "# 3D queries\nx,y,z,dx,dy,dz\n";
  for (std::size_t i = 0; i < t.size(); ++i) {
    t[i] = pendepth::Vec3(u(rng), u(rng), u(rng));
    d[i] = i % 2 ? pendepth::Vec3(u(rng), u(rng), u(rng)) : pendepth::Vec3(0, 0, 0);
    for (double x : {t[i].x(), t[i].y(), t[i].z(), d[i].x(), d[i].y(), d[i].z()}) {
      io::append_double(text, x);
      text += " , ";
    }
    text.resize(text.size() - 3);
    text += "\r\n";
  }
  const auto got = io::parse_queries3_csv(text);
  ASSERT_EQ(got.size(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_EQ(got[i].t, t[i]);
    EXPECT_EQ(got[i].d, d[i]);
    EXPECT_EQ(got[i].line, i + 3);
  }
  EXPECT_EQ(error3_of("0,0,0,1,0,0\n1,2,3,4\n"), "q3.csv:2: expected 6 numbers, got 4 (a 2D query; the shapes are 3D)");
  EXPECT_EQ(error3_of("0,0,0,1,0\n"), "q3.csv:1: expected 6 numbers, got 5");
  EXPECT_EQ(error3_of("0,0,0,1,0,nan\n"), "q3.csv:1: field 6 is not a finite number: 'nan'");
  EXPECT_EQ(error3_of("x,y,z,dx,dy,dz\n0,0,,1,0,0\n"), "q3.csv:2: field 3 is empty");
}
