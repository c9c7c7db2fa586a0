// End-to-end tests of 2D point and segment specs (point:X,Y, segment:X1,Y1,X2,Y2; issue 16 items 4
// and 7) in `depth`, `distance`, `cast` and `batch [--signed]`, either role: the printed values
// are the library's bits (Pair2 with Shape2::point / segment), the features name the point's or
// segment's vertices, bad combinations exit 2 with one line.
#include <pendepth/io.hpp>
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "cli/cli_fixture.hpp"

using namespace pendepth;
using cli_test::Result;
using nlohmann::json;

namespace {

class CliFlat2 : public cli_test::CliFixture {};

Vec2 vec_of(const json& j) { return Vec2(j.at(0).get<double>(), j.at(1).get<double>()); }

TEST_F(CliFlat2, PointAndSegmentSpecsAnswerAsTheLibrary) {
  const std::string sq = write("sq.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))");
  const std::string l = write("l.wkt", "POLYGON ((0 0, 4 0, 4 1, 1 1, 1 4, 0 4, 0 0))");
  const Shape2 SQ = Shape2::from_file(sq), L = Shape2::from_file(l);
  {
    const Result r = run("depth " + l + " point:0.25,0.5 --offset 0.25,1 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const json j = json::parse(r.out);
    const Depth2 want = Pair2(L, Shape2::point(Vec2(0.25, 0.5))).minimum(Vec2(0.25, 1));
    EXPECT_EQ(j.at("depth").get<double>(), want.depth);
    EXPECT_EQ(vec_of(j.at("translation")), want.translation);
    EXPECT_EQ(j.at("feature_q").at("kind"), "vertex");
    EXPECT_EQ(j.at("feature_q").at("index"), 0);
  }
  {
    const Result r = run("depth segment:0,0,1,1 " + sq + " --offset -2,-1.5 --direction 1,0 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const json j = json::parse(r.out);
    const Depth2 want =
        Pair2(Shape2::segment(Vec2(0, 0), Vec2(1, 1)), SQ).along(Vec2(-2, -1.5), Vec2(1, 0));
    EXPECT_EQ(j.at("depth").get<double>(), want.depth);
    EXPECT_EQ(vec_of(j.at("witness_p")), want.witness_p);
  }
  {
    const Result r = run("distance " + l + " point:3,3 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const json j = json::parse(r.out);
    const Distance2 want = Pair2(L, Shape2::point(Vec2(3, 3))).signed_distance(Vec2(0, 0));
    EXPECT_EQ(j.at("distance").get<double>(), want.distance);
    EXPECT_EQ(vec_of(j.at("witness_p")), want.witness_p);
    EXPECT_EQ(vec_of(j.at("normal")), want.normal);
  }
  {
    const Result r = run("cast " + sq + " segment:-1,0,0,1 --offset -5,2 --direction 1,0 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const json j = json::parse(r.out);
    const Cast2 want = Pair2(SQ, Shape2::segment(Vec2(-1, 0), Vec2(0, 1))).cast(Vec2(-5, 2), Vec2(1, 0));
    EXPECT_EQ(j.at("distance").get<double>(), want.distance);
    EXPECT_EQ(want.distance, 5);
  }
  {
    const std::string qs = write("q.csv", "0.5,0.5,0,0\n2,2,0,0\n9,9,0,0\n");
    const Pair2 pair(L, Shape2::point(Vec2(0, 0)));
    std::string signed_rows = "distance,tx,ty\n", rows = "depth,tx,ty\n";
    for (const Vec2& t : {Vec2(0.5, 0.5), Vec2(2, 2), Vec2(9, 9)}) {
      io::append_csv_row(signed_rows, pair.signed_distance(t));
      io::append_csv_row(rows, pair.minimum(t));
    }
    const Result r = run("batch " + l + " point:0,0 --queries " + qs + " --signed");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, signed_rows);
    EXPECT_EQ(signed_rows.substr(0, 24), "distance,tx,ty\n-0.5,0,-0");
    const Result d = run("batch " + l + " point:0,0 --queries " + qs);
    ASSERT_EQ(d.status, 0) << d.err;
    EXPECT_EQ(d.out, rows);
    EXPECT_EQ(rows, "depth,tx,ty\n0.5,0,-0.5\n0,0,0\n0,0,0\n");
  }
  // The picture shows a point as a dot.
  const std::string svg = (dir_ / "p.svg").string();
  ASSERT_EQ(run("depth " + l + " point:0.25,0.5 --offset 0.25,1 --svg " + svg).status, 0);
  EXPECT_NE(cli_test::slurp(svg).find("<circle"), std::string::npos);
  // A segment against the non-convex L (the general path), with a picture (no no-fit polygon panel).
  const Result s = run("depth " + l + " segment:0,0,1,1 --offset 0.25,0.25 --json --svg " + (dir_ / "s.svg").string());
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_EQ(json::parse(s.out).at("depth").get<double>(),
            Pair2(L, Shape2::segment(Vec2(0, 0), Vec2(1, 1))).minimum(Vec2(0.25, 0.25)).depth);
  EXPECT_EQ(run("nfp " + l + " segment:0,0,1,1").status, 2);  // not built for this pair
  expect_error("depth point:0,0 segment:0,0,1,1",
               "pair: P (P) and Q (Q) are both lower-dimensional (a point or a segment); one of them must be a solid polygon");
  const Result m = run("depth point:0,0 cube.obj");
  EXPECT_EQ(m.status, 2);
}

}  // namespace
