// End-to-end: primitive specs as shape arguments (issue 16 item 7; include/pendepth/shape_spec.hpp)
// in `depth`, `distance`, `cast` and `batch`: the library's answers, and one-line errors (exit 2).
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "cli/cli_fixture.hpp"

using namespace pendepth;
using cli_test::Result;
using nlohmann::json;

namespace {

class CliPrimitives : public cli_test::CliFixture {
 protected:
  json run_json(const std::string& args) {
    const Result r = run(args + " --json");
    EXPECT_EQ(r.status, 0) << args << ": " << r.err;
    return r.status == 0 ? json::parse(r.out) : json();
  }
};

}  // namespace

TEST_F(CliPrimitives, AnswersAsTheLibrary) {
  EXPECT_EQ(run_json("distance sphere:1 box:1,1,1 --offset 2.5,0,0").at("distance").get<double>(), 0.5);
  EXPECT_EQ(run_json("depth sphere:1 box:1,1,1 --offset 1.5,0,0").at("depth").get<double>(), 0.5);
  EXPECT_EQ(run_json("depth box:1,1,1 point:0.5,0.25,0").at("depth").get<double>(), 0.5);
  EXPECT_EQ(run_json("depth box:1,1,1 segment:0,0,0,0.5,0,0 --direction 0,1,0").at("depth").get<double>(), 1);
  const json c = run_json("cast capsule:0.5,1 sphere:0.5 --offset 5,0,0 --direction -1,0,0");
  EXPECT_TRUE(c.at("hit").get<bool>());
  EXPECT_EQ(c.at("distance").get<double>(), 4);
  // A rounded pair's cast: its certified bracket, distance its upper end (the library's bits).
  const Cast3 lc = Pair3(Shape3::capsule(0.5, 1), Shape3::sphere(0.5)).cast(Pose3(), Pose3(Vec3(5, 0, 0)), Vec3(-1, 0, 0));
  EXPECT_EQ(c.at("lower_bound").get<double>(), lc.lower_bound);
  EXPECT_EQ(c.at("upper_bound").get<double>(), lc.upper_bound);
  EXPECT_LE(c.at("lower_bound").get<double>(), 4);
  EXPECT_EQ(c.at("upper_bound").get<double>(), 4);
  const std::string P = write("tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n");
  const Pair3 pair(Shape3::rounded(Shape3::from_file(P), 0.125), Shape3::capsule(0.25, 0.5));
  const Eigen::Quaterniond rq = Eigen::Quaterniond(0.9, 0.1, 0.3, -0.2).normalized();
  const Distance3 r = pair.signed_distance(Pose3(), Pose3(rq, Vec3(1, 1, 0.5)));
  const json j = run_json("distance rounded:0.125:" + P + " capsule:0.25,0.5 --offset 1,1,0.5 --rotate-q 0.9,0.1,0.3,-0.2");
  EXPECT_EQ(j.at("distance").get<double>(), r.distance);
  EXPECT_EQ(j.at("feature_q").at("kind").get<std::string>(), "none");  // a capsule has no polytope
  const std::string F = write("q.csv", "x,y,z,dx,dy,dz\n2.5,0,0,0,0,0\n1.5,0,0,0,0,0\n");
  const Result b = run("batch sphere:1 box:1,1,1 --queries " + F + " --signed");
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_EQ(b.out, "distance,tx,ty,tz\n0.5,-0.5,0,0\n-0.5,0.5,0,0\n");
  // Curved primitives (certified brackets): the library's answer, bit for bit.
  const Pair3 cp(Shape3::cylinder(0.1, 0.2), Shape3::ellipsoid(0.1, 0.2, 0.3));
  const Depth3 cd = cp.minimum(Pose3(), Pose3(Vec3(0.1, 0, 0)));
  const json cj = run_json("depth cylinder:0.1,0.2 ellipsoid:0.1,0.2,0.3 --offset 0.1,0,0");
  EXPECT_EQ(cj.at("depth").get<double>(), cd.depth);
  const Distance3 cs = cp.signed_distance(Pose3(), Pose3(Vec3(0.5, 0, 0)));
  EXPECT_EQ(run_json("distance cylinder:0.1,0.2 ellipsoid:0.1,0.2,0.3 --offset 0.5,0,0").at("distance").get<double>(),
            cs.distance);
  const json cc = run_json("cast cone:0.1,0.2 ellipsoid:0.1,0.2,0.3 --offset 1,0,0 --direction -1,0,0");
  EXPECT_TRUE(cc.at("hit").get<bool>());
  const Result s = run("depth box:1,1,1 sphere:1 --offset 1.5,0,0");
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_NE(s.out.find("Q Q (a primitive)"), std::string::npos) << s.out;
}

TEST_F(CliPrimitives, Errors) {
  expect_error("depth sphere:x box:1,1,1", "shape spec 'sphere:x': 'x' is not a number (expected sphere:R)");
  expect_error("distance cylinder:1,0 box:1,1,1", "shape spec 'cylinder:1,0': P: half height 0 must be finite and positive");
  expect_error("depth box:1,1,1 sphere:0", "shape spec 'sphere:0': Q: radius 0 must be finite and positive");
  expect_error("depth sphere:1 box:1,1,1 --approximate 0.01",
               "--approximate: reads point files; 'sphere:1' is a primitive spec");
  const Result both = run("depth point:0,0,0 segment:0,0,0,1,1,1");
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("both shapes are lower-dimensional"), std::string::npos) << both.err;
}
