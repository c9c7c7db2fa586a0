// End-to-end tests of the `pendepth` binary (docs/design.md §3): exit codes, one-line errors naming
// file and line, JSON keys, and batch output equal bit for bit to the library's answers.
#include <pendepth/depth2.hpp>
#include <pendepth/io.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include "cli/cli_fixture.hpp"

using pendepth::ConvexPolygon;
using pendepth::Depth2;
using pendepth::Vec2;
namespace io = pendepth::io;
namespace fs = std::filesystem;
using nlohmann::json;

using cli_test::quote;
using cli_test::Result;
using cli_test::slurp;

namespace {

class Cli : public cli_test::CliFixture {
 protected:
  std::string square_p() { return write("P.wkt", "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))\n"); }
  std::string square_q() { return write("Q.wkt", "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))\n"); }
};

Vec2 vec_of(const json& j) { return Vec2(j.at(0).get<double>(), j.at(1).get<double>()); }

void expect_same(const json& j, const Depth2& r) {
  EXPECT_EQ(j.at("depth").get<double>(), r.depth);
  EXPECT_EQ(vec_of(j.at("translation")), r.translation);
  EXPECT_EQ(vec_of(j.at("normal")), r.normal);
  EXPECT_EQ(vec_of(j.at("witness_p")), r.witness_p);
  EXPECT_EQ(vec_of(j.at("witness_q")), r.witness_q);
  EXPECT_EQ(j.at("overlapping").get<bool>(), r.overlapping);
}

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> v;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

ConvexPolygon random_convex(std::mt19937_64& rng, std::size_t n, Vec2 c, double r) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec2> pts;
  while (pts.size() < n) {
    const Vec2 p(u(rng), u(rng));
    if (p.squaredNorm() <= 1) pts.push_back(c + r * p);
  }
  return ConvexPolygon::hull(pts);
}

}  // namespace

TEST_F(Cli, DepthMinimumJsonMatchesLibraryAndAnalyticValue) {
  const std::string P = square_p(), Q = square_q();
  const Result r = run("depth " + quote(P) + " " + quote(Q) + " --offset 0.5,0.25 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  ASSERT_EQ(lines_of(r.out).size(), 1u);
  const json j = json::parse(r.out);
  for (const char* key : {"depth", "translation", "normal", "witness_p", "witness_q", "kind", "overlapping",
                          "feature_p", "feature_q"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["kind"], "minimum");
  EXPECT_EQ(j["depth"].get<double>(), 1.25);  // analytic: Q + t = [.5,1.5]×[.25,1.25], down by 1.25
  EXPECT_EQ(vec_of(j["translation"]), Vec2(0, -1.25));
  const ConvexPolygon PP = io::read_convex_polygon(P, "P"), QQ = io::read_convex_polygon(Q, "Q");
  expect_same(j, pendepth::minimum_depth(PP, QQ, Vec2(0.5, 0.25)));
}

TEST_F(Cli, DepthDirectionalSeparationAndSummary) {
  const std::string P = square_p(), Q = square_q();
  Result r = run("depth " + quote(P) + " " + quote(Q) + " --offset=-0.5,0.5 --direction 3,0 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  json j = json::parse(r.out);
  EXPECT_EQ(j["kind"], "directional");
  EXPECT_EQ(j["depth"].get<double>(), 2.5);  // analytic: left side of Q + t at x = −0.5 must reach 2
  EXPECT_EQ(vec_of(j["normal"]), Vec2(1, 0));

  r = run("depth " + quote(P) + " " + quote(Q) + " --offset 0.5,0.5 --direction 0,-1 --separate --json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = json::parse(r.out);
  EXPECT_EQ(j["kind"], "separation");
  EXPECT_EQ(j["depth"].get<double>(), 1.5);

  r = run("depth " + quote(P) + " " + quote(Q) + " --offset 0.5,0.5 --direction 0,-1");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("directional depth"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("depth:       1.5\n"), std::string::npos) << r.out;

  r = run("depth " + quote(P) + " " + quote(Q) + " --offset 5,5");  // apart: depth 0
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("overlapping: no"), std::string::npos) << r.out;
  r = run("depth " + quote(P) + " " + quote(Q) + " --offset 2,0 --json");  // touching: depth 0
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(json::parse(r.out)["depth"].get<double>(), 0.0);
  EXPECT_FALSE(json::parse(r.out)["overlapping"].get<bool>());
}

TEST_F(Cli, DepthWritesSvg) {
  const std::string P = square_p(), Q = square_q(), svg = (dir_ / "pic.svg").string();
  const Result r = run("depth " + quote(P) + " " + quote(Q) + " --offset 0.5,0.5 --direction 1,1 --svg " + quote(svg));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string s = slurp(svg);
  EXPECT_EQ(s.rfind("<svg ", 0), 0u);
  EXPECT_NE(s.find("</svg>"), std::string::npos);
}

TEST_F(Cli, ExampleShapes) {
  const std::string data = std::string(PENDEPTH_SOURCE_DIR) + "/examples/data/";
  struct Case {
    const char *p, *q;
    Vec2 t;
  };
  for (const Case& c : {Case{"octagon.wkt", "hexagon.wkt", Vec2(2.5, 2)},
                        Case{"albano_item2.wkt", "hexagon.wkt", Vec2(1000, 800)},
                        Case{"trousers_item14.wkt", "trousers_item16.wkt", Vec2(1, 3)}}) {
    const std::string t = std::to_string(c.t.x()) + "," + std::to_string(c.t.y());
    const Result r = run("depth " + quote(data + c.p) + " " + quote(data + c.q) + " --offset " + t + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const ConvexPolygon P = io::read_convex_polygon(data + c.p, "P"), Q = io::read_convex_polygon(data + c.q, "Q");
    const json j = json::parse(r.out);
    EXPECT_TRUE(j["overlapping"].get<bool>()) << c.p;
    expect_same(j, pendepth::minimum_depth(P, Q, c.t));
  }
}

TEST_F(Cli, Help) {
  Result r = run("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("depth"), std::string::npos);
  EXPECT_NE(r.out.find("batch"), std::string::npos);
  r = run("depth --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--direction"), std::string::npos);
  EXPECT_NE(r.out.find("--separate"), std::string::npos);
  r = run("batch --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--queries"), std::string::npos);
}

TEST_F(Cli, BadInputExitsWithOneLine) {
  const std::string P = square_p(), Q = square_q();
  const std::string bad = write("bad.wkt", "POLYGON ((0 0, 2 0,\n 2 x, 0 2))\n");
  expect_error("depth " + quote(bad) + " " + quote(Q), bad + ":2: expected a number for y, got 'x'");
  expect_error("batch " + quote(P) + " " + quote(bad) + " --queries " + quote(P),
               bad + ":2: expected a number for y, got 'x'");

  const std::string dent = write("dent.wkt", "POLYGON ((\n0 0,\n4 0,\n4 4,\n2 1,\n0 4))\n");
  const std::string holes = write("holes.wkt", "POLYGON ((0 0, 9 0, 9 9, 0 9), (1 1, 1 2, 2 2))");
  // Non-convex polygons are supported (tests/cli/test_cli_polygon.cpp, test_cli_nonconvex.cpp);
  // their validation errors name the file and line.
  expect_error("depth " + quote(holes) + " " + quote(dent) + " --direction 0,0", "--direction: the direction is zero");
  const std::string missing = (dir_ / "missing.wkt").string();
  expect_error("depth " + quote(P) + " " + quote(missing), missing + ": cannot read file (No such file or directory)");
  const std::string obj = write("hull.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n");
  expect_error("depth " + quote(obj) + " " + quote(Q),  // mixing dimensions (3D: tests/cli/test_cli3.cpp)
               Q + ": Q is a 2D shape but P (" + obj + ") is 3D; both must be 2D (.wkt) or both 3D (.obj, .off, .stl, .ply)");
  const std::string txt = write("shape.txt", "POLYGON ((0 0, 1 0, 0 1))");
  expect_error("depth " + quote(P) + " " + quote(txt), txt + ": unknown shape format '.txt' (expected .wkt, .obj, .off, .stl or .ply)");

  const std::string pq = quote(P) + " " + quote(Q);
  expect_error("depth " + pq + " --direction 0,0", "--direction: the direction is zero");
  expect_error("depth " + pq + " --direction 0,-0", "--direction: the direction is zero");
  expect_error("depth " + pq + " --direction 1,nan", "--direction: non-finite number in '1,nan'");
  expect_error("depth " + pq + " --offset 1,b", "--offset: expected X,Y (two numbers), got '1,b'");
  expect_error("depth " + pq + " --offset 1", "--offset: expected X,Y (two numbers), got '1'");
  expect_error("depth " + pq + " --offset 1,2,3", "--offset: expected X,Y (two numbers), got '1,2,3'");
  expect_error("depth " + pq + " --rotate-q 1,0,0,0", "--rotate-q: expected DEG (one number), got '1,0,0,0'");  // 2D: an angle

  // Usage errors: status 2 and one line too.
  for (const std::string& args : std::vector<std::string>{"", "depth " + quote(P), "depth " + pq + " --separate", "batch " + pq,
                                 "frobnicate", "depth " + pq + " --bogus"}) {
    const Result r = run(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }

  const std::string csv = write("queries.csv", "x,y,dx,dy\n0.5,0.5,0,0\n0.5,0.5,1\n");
  expect_error("batch " + pq + " --queries " + quote(csv), csv + ":3: expected 4 numbers, got 3");
  const std::string csv2 = write("q2.csv", "0.5,0.5,0,0\n\n# c\n0.5,abc,1,0\n");
  expect_error("batch " + pq + " --queries " + quote(csv2), csv2 + ":4: field 2 is not a number: 'abc'");
  expect_error("batch " + pq + " --queries " + quote(missing), missing + ": cannot read file (No such file or directory)");
}

TEST_F(Cli, BatchMatchesLibraryBitForBit) {
  std::mt19937_64 rng(314159);
  const ConvexPolygon P = random_convex(rng, 80, Vec2(0, 0), 3), Q = random_convex(rng, 30, Vec2(1, -1), 1);
  const std::string pp = write("P.wkt", io::to_wkt(P)), qq = write("Q.wkt", io::to_wkt(Q));
  const pendepth::DepthQuery2 query(P, Q);
  const std::vector<Vec2> M = pendepth::minkowski_difference(P, Q);

  std::uniform_real_distribution<double> u(-4.5, 4.5), ud(-1, 1);
  std::vector<std::pair<Vec2, Vec2>> qs;
  std::string csv = "x,y,dx,dy\n# random offsets, half of them asking for the minimum\n";
  for (int k = 0; k < 600; ++k) {
    Vec2 t(u(rng), u(rng));
    if (k % 10 == 0) t = M[rng() % M.size()];  // on ∂M: touching, depth 0
    const Vec2 d = k % 2 ? Vec2(ud(rng), ud(rng)) : Vec2(0, 0);
    qs.emplace_back(t, d);
    for (double x : {t.x(), t.y(), d.x(), d.y()}) {
      io::append_double(csv, x);
      csv += ',';
    }
    csv.back() = '\n';
  }
  const std::string file = write("q.csv", csv);
  auto expected = [&](std::size_t k) {
    const auto& [t, d] = qs[k];
    return d == Vec2(0, 0) ? query.minimum(t) : pendepth::directional_depth(P, Q, t, d);
  };

  Result r = run("batch " + quote(pp) + " " + quote(qq) + " --queries " + quote(file));
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<std::string> rows = lines_of(r.out);
  ASSERT_EQ(rows.size(), qs.size() + 1);
  EXPECT_EQ(rows[0], "depth,tx,ty");
  int overlapping = 0;
  for (std::size_t k = 0; k < qs.size(); ++k) {
    const Depth2 e = expected(k);
    double v[3];
    const char* p = rows[k + 1].data();
    const char* end = p + rows[k + 1].size();
    for (double& x : v) {
      auto [ptr, ec] = std::from_chars(p, end, x);
      ASSERT_EQ(ec, std::errc()) << rows[k + 1];
      p = ptr + (ptr < end);
    }
    EXPECT_EQ(p, end);
    EXPECT_EQ(v[0], e.depth) << k;
    EXPECT_EQ(v[1], e.translation.x()) << k;
    EXPECT_EQ(v[2], e.translation.y()) << k;
    overlapping += e.overlapping;
  }
  EXPECT_GT(overlapping, 100);

  r = run("batch " + quote(pp) + " " + quote(qq) + " --queries " + quote(file) + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  rows = lines_of(r.out);
  ASSERT_EQ(rows.size(), qs.size());
  for (std::size_t k = 0; k < qs.size(); ++k) {
    const json j = json::parse(rows[k]);
    EXPECT_EQ(j.size(), 9u);
    EXPECT_EQ(j["kind"], qs[k].second == Vec2(0, 0) ? "minimum" : "directional");
    expect_same(j, expected(k));
  }
}

TEST_F(Cli, DirectionScaleDoesNotMatter) {
  // The same direction from subnormal to huge magnitudes gives the same answer (analytic: 1.5).
  const std::string P = square_p(), Q = square_q();
  std::string csv;
  for (const char* d : {"1,0", "5e-324,0", "1e-300,0", "1e300,0", "1.7e308,0"}) csv += std::string("0.5,0.5,") + d + "\n";
  csv += "0.5,0.5,1e-310,1e-310\n0.5,0.5,1e308,1e308\n";  // diagonal: analytic 1.5·√2
  const std::string file = write("q.csv", csv);
  const Result r = run("batch " + quote(P) + " " + quote(Q) + " --queries " + quote(file));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = lines_of(r.out);
  ASSERT_EQ(rows.size(), 8u);
  EXPECT_EQ(rows[1], "1.5,1.5,0");
  for (std::size_t k = 1; k <= 7; ++k) {  // a few ulps: d̂ is rounded
    double v[3];
    std::istringstream in(rows[k]);
    char comma;
    in >> v[0] >> comma >> v[1] >> comma >> v[2];
    ASSERT_TRUE(in && std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2])) << rows[k];
    const bool diagonal = k >= 6;
    EXPECT_NEAR(v[0], diagonal ? 1.5 * std::sqrt(2.0) : 1.5, 1e-15) << rows[k];
    EXPECT_NEAR(v[1], 1.5, 1e-15) << rows[k];
    EXPECT_NEAR(v[2], diagonal ? 1.5 : 0.0, 1e-15) << rows[k];
  }
}

// --threads changes nothing in the output; --progress adds a progress line on stderr only.
TEST_F(Cli, BatchThreadsAndProgress) {
  const std::string P = square_p(), Q = square_q();
  std::string csv;
  for (int k = 0; k < 40000; ++k) csv += std::to_string(0.001 * (k % 997)) + ",0.5," + (k % 3 ? "1,0.25" : "0,0") + "\n";
  const std::string file = write("many.csv", csv);
  const Result all = run("batch " + quote(P) + " " + quote(Q) + " --queries " + quote(file));
  ASSERT_EQ(all.status, 0) << all.err;
  EXPECT_EQ(all.err, "");  // stderr is a file here: no progress unless asked for
  const Result one = run("batch " + quote(P) + " " + quote(Q) + " --queries " + quote(file) + " --threads 1");
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(one.out, all.out);
  const Result bar = run("batch " + quote(P) + " " + quote(Q) + " --queries " + quote(file) + " --progress");
  ASSERT_EQ(bar.status, 0) << bar.err;
  EXPECT_EQ(bar.out, all.out);
  EXPECT_NE(bar.err.find("pendepth batch: 40000 / 40000 queries\n"), std::string::npos) << bar.err;
  // σ queries (every third line) in one chunk, then the σ_d queries in chunks of 16384.
  EXPECT_NE(bar.err.find("\rpendepth batch: 13334 / 40000 queries\rpendepth batch: 29718 / 40000"), std::string::npos) << bar.err;
}

TEST_F(Cli, BatchDirectionalOnlyAndEmpty) {
  const std::string P = square_p(), Q = square_q();
  const std::string csv = write("q.csv", "0.5,0.5,1,0\n0.5,0.5,0,2\n9,9,1,1\n");
  Result r = run("batch " + quote(P) + " " + quote(Q) + " --queries " + quote(csv));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "depth,tx,ty\n1.5,1.5,0\n1.5,0,1.5\n0,0,0\n");  // analytic
  const std::string empty = write("e.csv", "x,y,dx,dy\n");
  r = run("batch " + quote(P) + " " + quote(Q) + " --queries " + quote(empty));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "depth,tx,ty\n");
}
