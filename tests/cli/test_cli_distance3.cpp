// End-to-end tests of `pendepth distance`, `pendepth cast` and `pendepth batch --signed` on 3D
// shapes (docs/design.md §3, issue 16 item 7), through Pair3::signed_distance / Pair3::cast.
// Analytic answers on axis-aligned cubes (P = [0,2]³, Q = [0,1]³) and the library's bits.
#include <pendepth/io.hpp>
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "cli/cli_fixture.hpp"

using namespace pendepth;
using cli_test::quote;
using cli_test::Result;
using nlohmann::json;

namespace {

std::string cube_obj(double s) {
  std::string t;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) {
        t += "v";
        for (double c : {s * x, s * y, s * z}) {
          t += ' ';
          io::append_double(t, c);
        }
        t += '\n';
      }
  return t;
}

Vec3 vec_of(const json& j) { return Vec3(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()); }

class CliDistance3 : public cli_test::CliFixture {
 protected:
  json run_json(const std::string& args) {
    const Result r = run(args + " --json");
    EXPECT_EQ(r.status, 0) << args << ": " << r.err;
    return r.status == 0 ? json::parse(r.out) : json();
  }
};

}  // namespace

TEST_F(CliDistance3, DistanceAndCastOfCubes) {
  const std::string P = write("P.obj", cube_obj(2)), Q = write("Q.obj", cube_obj(1)), pq = quote(P) + " " + quote(Q);
  const json apart = run_json("distance " + pq + " --offset 5,0.5,0.5");
  EXPECT_EQ(apart.at("distance").get<double>(), 3);
  EXPECT_EQ(vec_of(apart.at("translation")), Vec3(-3, 0, 0));
  EXPECT_EQ(vec_of(apart.at("normal")), Vec3(1, 0, 0));
  const json over = run_json("distance " + pq + " --offset 1.75,0.5,0.5");
  EXPECT_TRUE(over.at("overlapping").get<bool>());
  EXPECT_EQ(over.at("distance").get<double>(), -0.25);
  const json touch = run_json("distance " + pq + " --offset 2,0.5,0.5");
  EXPECT_EQ(touch.at("distance").get<double>(), 0);
  const json hit = run_json("cast " + pq + " --offset 5,0.5,0.5 --direction -1,0,0");
  EXPECT_TRUE(hit.at("hit").get<bool>());
  EXPECT_EQ(hit.at("distance").get<double>(), 3);
  EXPECT_EQ(hit.at("lower_bound").get<double>(), 3);  // exact: the bracket is the answer
  EXPECT_EQ(hit.at("upper_bound").get<double>(), 3);
  const Result miss = run("cast " + pq + " --offset 5,0.5,0.5 --direction 1,0,0 --json");
  EXPECT_EQ(miss.status, 0);
  EXPECT_NE(miss.out.find("\"distance\":1e999,\"hit\":false"), std::string::npos) << miss.out;
  EXPECT_NE(miss.out.find("\"lower_bound\":1e999,\"upper_bound\":1e999"), std::string::npos) << miss.out;
  // The library's bits, with a rotation of Q.
  const Pair3 pair(Shape3::from_file(P), Shape3::from_file(Q));
  const Eigen::Quaterniond rq = Eigen::Quaterniond(0.9, 0.1, 0.3, -0.2).normalized();
  const Distance3 r = pair.signed_distance(Pose3(), Pose3(rq, Vec3(3.5, 1, 0.25)));
  const json j = run_json("distance " + pq + " --offset 3.5,1,0.25 --rotate-q 0.9,0.1,0.3,-0.2");
  EXPECT_EQ(j.at("distance").get<double>(), r.distance);
  EXPECT_EQ(vec_of(j.at("translation")), r.translation);
}

TEST_F(CliDistance3, BatchSigned) {
  const std::string P = write("P.obj", cube_obj(2)), Q = write("Q.obj", cube_obj(1));
  const std::string F = write("q.csv", "x,y,z,dx,dy,dz\n5,0.5,0.5,0,0,0\n1.75,0.5,0.5,0,0,0\n");
  const Result r = run("batch " + quote(P) + " " + quote(Q) + " --queries " + quote(F) + " --signed");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "distance,tx,ty,tz\n3,-3,0,0\n-0.25,0.25,0,0\n");
  const std::string G = write("g.csv", "5,0.5,0.5,0,0,0\n5,0.5,0.5,0,1,0\n");
  expect_error("batch " + quote(P) + " " + quote(Q) + " --queries " + quote(G) + " --signed",
               G + ":2: --signed takes placements only: the direction columns must be 0");
}
