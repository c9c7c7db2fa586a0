// End-to-end tests of `pendepth depth P Q --approximate DELTA` (3D point files): the JSON equals the
// library's approximate_minimum_depth bit for bit, brackets the analytic σ, and bad values exit 2.
#include <pendepth/approximate.hpp>
#include <pendepth/io.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <vector>

#include "cli/cli_fixture.hpp"

using pendepth::Pose3;
using pendepth::Vec3;
namespace io = pendepth::io;
using nlohmann::json;
using cli_test::quote;
using cli_test::Result;

namespace {

std::vector<Vec3> box(double s) {  // the corners of [0, s]³ and its centre
  std::vector<Vec3> c;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) c.emplace_back(s * x, s * y, s * z);
  c.emplace_back(s / 2, s / 2, s / 2);
  return c;
}

std::string obj_text(const std::vector<Vec3>& pts) {
  std::string s;
  for (const Vec3& p : pts) {
    s += "v";
    for (int k = 0; k < 3; ++k) s += ' ', io::append_double(s, p[k]);
    s += '\n';
  }
  return s;
}

Vec3 vec_of(const json& j) { return Vec3(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()); }

class CliApproximate : public cli_test::CliFixture {};

TEST_F(CliApproximate, CubesJsonEqualsLibraryAndBracketsSigma) {
  const std::string P = write("P.obj", obj_text(box(2))), Q = write("Q.obj", obj_text(box(1)));
  const Result r = run("depth " + quote(P) + " " + quote(Q) + " --offset 0.5,0.25,0.5 --approximate 0.01 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const json j = json::parse(r.out);
  const auto lib = pendepth::approximate_minimum_depth(box(2), Pose3(), box(1), Pose3(Vec3(0.5, 0.25, 0.5)), 0.01);
  EXPECT_EQ(j.at("depth").get<double>(), lib.depth);
  EXPECT_EQ(j.at("lower_bound").get<double>(), lib.lower_bound);
  EXPECT_EQ(j.at("upper_bound").get<double>(), lib.upper_bound);
  EXPECT_EQ(vec_of(j.at("normal")), lib.normal);
  EXPECT_EQ(vec_of(j.at("translation")), lib.translation);
  EXPECT_TRUE(j.at("converged").get<bool>());
  EXPECT_TRUE(j.at("overlapping").get<bool>());
  // Q + t = [.5,1.5]×[.25,1.25]×[.5,1.5] in [0,2]³: σ = 1.25 (down in y).
  EXPECT_LE(lib.lower_bound, 1.25);
  EXPECT_GE(lib.upper_bound, 1.25);
  EXPECT_LE(lib.upper_bound, 1.01 * lib.lower_bound);
  const Result text = run("depth " + quote(P) + " " + quote(Q) + " --offset 0.5,0.25,0.5 --approximate 0.01");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("lower_bound "), std::string::npos) << text.out;
}

TEST_F(CliApproximate, BadValuesExitTwo) {
  const std::string P = write("P.obj", obj_text(box(2))), Q = write("Q.obj", obj_text(box(1)));
  const std::string W = write("A.wkt", "POLYGON ((0 0, 1 0, 1 1, 0 0))");
  for (const std::string args : {quote(P) + " " + quote(Q) + " --approximate 0", quote(P) + " " + quote(Q) + " --approximate 1",
                                 quote(P) + " " + quote(Q) + " --approximate abc",
                                 quote(P) + " " + quote(Q) + " --approximate 0.1 --direction 1,0,0",
                                 quote(W) + " " + quote(W) + " --approximate 0.1"}) {
    const Result r = run("depth " + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
