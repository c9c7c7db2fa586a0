// End-to-end tests of `pendepth distance`, `pendepth cast` and `pendepth batch --signed` on 2D
// shapes (docs/design.md §3, issue 16 item 7): the printed values are the library's bits
// (Pair2::signed_distance, Pair2::cast), analytic cases, the CSV and JSON Lines of the batch,
// bad input (exit 2, one line) and a failed write (exit 3).
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "cli/cli_fixture.hpp"

using namespace pendepth;
using cli_test::quote;
using cli_test::Result;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

Vec2 vec_of(const json& j) { return Vec2(j.at(0).get<double>(), j.at(1).get<double>()); }

// A distance field: a number, or "inf" where the output had 1e999 (see run_json).
double distance_of(const json& j) {
  return j.at("distance").is_string() ? std::numeric_limits<double>::infinity() : j.at("distance").get<double>();
}

template <class R>
void expect_same(const json& j, const R& r) {
  EXPECT_EQ(distance_of(j), r.distance);
  EXPECT_EQ(vec_of(j.at("translation")), r.translation);
  EXPECT_EQ(vec_of(j.at("normal")), r.normal);
  EXPECT_EQ(vec_of(j.at("witness_p")), r.witness_p);
  EXPECT_EQ(vec_of(j.at("witness_q")), r.witness_q);
  EXPECT_EQ(j.at("overlapping").get<bool>(), r.overlapping);
  if constexpr (requires { r.hit; }) EXPECT_EQ(j.at("hit").get<bool>(), r.hit);
}

class CliDistance : public cli_test::CliFixture {
 protected:
  // P an L (non-convex), Q a 3 × 1 bar, C a convex octagon.
  std::string L() { return write("L.wkt", "POLYGON ((0 0, 6 0, 6 2, 2 2, 2 5, 0 5, 0 0))\n"); }
  std::string bar() { return write("bar.wkt", "POLYGON ((0 0, 3 0, 3 1, 0 1, 0 0))\n"); }
  std::string octagon() { return write("oct.wkt", "POLYGON ((2 0, 4 0, 6 2, 6 4, 4 6, 2 6, 0 4, 0 2, 2 0))\n"); }
  json run_json(const std::string& args) {
    const Result r = run(args + " --json");
    EXPECT_EQ(r.status, 0) << args << ": " << r.err;
    EXPECT_EQ(r.err, "");
    // nlohmann::json rejects 1e999 (the writer's infinity, a valid JSON number): read it as "inf".
    std::string out = r.out;
    for (std::size_t at; (at = out.find("1e999")) != std::string::npos;) out.replace(at, 5, "\"inf\"");
    return r.status == 0 ? json::parse(out) : json();
  }
  // The tool with standard output on /dev/full: its exit status and stderr.
  Result to_full(const std::string& args) {
    const fs::path err = dir_ / "full_err.txt";
    const int rc = std::system((quote(PENDEPTH_CLI) + " " + args + " > /dev/full 2> " + quote(err.string())).c_str());
    Result r;
    r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    r.err = cli_test::slurp(err);
    return r;
  }
};

}  // namespace

TEST_F(CliDistance, DistancePrintsTheLibrarysBitsApartTouchingOverlapping) {
  const std::string P = L(), Q = bar(), pq = quote(P) + " " + quote(Q);
  const Pair2 pair(Shape2::from_file(P), Shape2::from_file(Q));
  // Apart by exactly 1 (Q's left side one unit right of the L's stem), touching, overlapping.
  const json apart = run_json("distance " + pq + " --offset 3,3");
  EXPECT_EQ(apart.at("distance").get<double>(), 1);
  EXPECT_EQ(vec_of(apart.at("translation")), Vec2(-1, 0));
  EXPECT_EQ(apart.at("feature_q").at("kind"), "vertex");
  expect_same(apart, pair.signed_distance(Vec2(3, 3)));
  const json touching = run_json("distance " + pq + " --offset 2,3");
  EXPECT_EQ(touching.at("distance").get<double>(), 0);
  EXPECT_FALSE(touching.at("overlapping").get<bool>());
  const json over = run_json("distance " + pq + " --offset=1,1");
  EXPECT_TRUE(over.at("overlapping").get<bool>());
  EXPECT_EQ(over.at("distance").get<double>(), -pair.minimum(Vec2(1, 1)).depth);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-6, 9);
  for (int k = 0; k < 10; ++k) {
    const Vec2 t(u(rng), u(rng));
    char off[96];
    std::snprintf(off, sizeof off, "--offset=%.17g,%.17g", t.x(), t.y());
    expect_same(run_json("distance " + pq + " " + off), pair.signed_distance(t));
  }
  const Result summary = run("distance " + pq + " --offset 3,3");
  EXPECT_EQ(summary.status, 0);
  EXPECT_NE(summary.out.find("apart"), std::string::npos) << summary.out;
  EXPECT_NE(summary.out.find("distance:    1\n"), std::string::npos) << summary.out;
}

TEST_F(CliDistance, CastPrintsTheLibrarysBitsHitsMissesAndOverlap) {
  const std::string P = L(), Q = bar(), C = octagon();
  const std::string pq = quote(P) + " " + quote(Q);
  const Pair2 pair(Shape2::from_file(P), Shape2::from_file(Q));
  const json down = run_json("cast " + pq + " --offset 3,6 --direction 0,-2");
  EXPECT_EQ(down.at("distance").get<double>(), 4);  // the bar lands on the L's foot (top y = 2)
  EXPECT_TRUE(down.at("hit").get<bool>());
  EXPECT_EQ(vec_of(down.at("normal")), Vec2(0, 1));
  expect_same(down, pair.cast(Vec2(3, 6), Vec2(0, -2)));
  const Result miss = run("cast " + pq + " --offset 3,6 --direction 0,1 --json");
  ASSERT_EQ(miss.status, 0);
  EXPECT_NE(miss.out.find("\"distance\":1e999,\"hit\":false"), std::string::npos) << miss.out;
  const json over = run_json("cast " + pq + " --offset 1,1 --direction 1,0");
  EXPECT_EQ(over.at("distance").get<double>(), 0);
  EXPECT_TRUE(over.at("overlapping").get<bool>());
  const Pair2 convex(Shape2::from_file(C), Shape2::from_file(Q));
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-8, 10), w(-1, 1);
  for (int k = 0; k < 10; ++k) {
    const Vec2 t(u(rng), u(rng)), d(w(rng), w(rng));
    char args[200];
    std::snprintf(args, sizeof args, "--offset=%.17g,%.17g --direction=%.17g,%.17g", t.x(), t.y(), d.x(), d.y());
    expect_same(run_json("cast " + quote(C) + " " + quote(Q) + " " + args), convex.cast(t, d));
  }
  const Result summary = run("cast " + pq + " --offset 3,6 --direction 0,1");
  EXPECT_NE(summary.out.find("miss"), std::string::npos) << summary.out;
}

TEST_F(CliDistance, BatchSignedWritesDistanceAndTranslationToTouching) {
  const std::string P = L(), Q = bar();
  const Pair2 pair(Shape2::from_file(P), Shape2::from_file(Q), Prepare::Full);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-6, 9);
  std::string csv = "x,y,dx,dy\n";
  std::vector<Vec2> ts;
  for (int k = 0; k < 200; ++k) {
    ts.emplace_back(u(rng), u(rng));
    char line[96];
    std::snprintf(line, sizeof line, "%.17g,%.17g,0,0\n", ts.back().x(), ts.back().y());
    csv += line;
  }
  const std::string F = write("q.csv", csv);
  const Result r = run("batch " + quote(P) + " " + quote(Q) + " --queries " + quote(F) + " --signed --threads 2");
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<Distance2> expect(ts.size());
  pair.signed_distance(ts, expect, 1);
  std::string want = "distance,tx,ty\n";
  for (const Distance2& d : expect) io::append_csv_row(want, d);
  EXPECT_EQ(r.out, want);
  const Result j = run("batch " + quote(P) + " " + quote(Q) + " --queries " + quote(F) + " --signed --json");
  ASSERT_EQ(j.status, 0) << j.err;
  std::size_t pos = 0, k = 0;
  for (; k < ts.size(); ++k) {
    const std::size_t nl = j.out.find('\n', pos);
    ASSERT_NE(nl, std::string::npos);
    expect_same(json::parse(j.out.substr(pos, nl - pos)), expect[k]);
    pos = nl + 1;
  }
  EXPECT_EQ(pos, j.out.size());
}

TEST_F(CliDistance, BadInputExitsTwoFailedWriteExitsThree) {
  const std::string P = L(), Q = bar(), pq = quote(P) + " " + quote(Q);
  const std::string F = write("q.csv", "1,1,0,0\n# comment\n2,2,1,0\n");
  expect_error("batch " + pq + " --queries " + quote(F) + " --signed", F + ":3: --signed takes placements only: the direction columns must be 0");
  expect_error("cast " + pq + " --offset 1,1 --direction 0,0", "--direction: the direction is zero");
  expect_error("distance " + pq + " --rotate-q 1,0,0,0", "--rotate-q: rotations apply to 3D shapes only");
  expect_error("distance " + pq + " --offset 1", "--offset: expected X,Y (two numbers), got '1'");
  const Result no_dir = run("cast " + pq + " --offset 1,1");
  EXPECT_EQ(no_dir.status, 2);
  EXPECT_NE(no_dir.err.find("--direction"), std::string::npos) << no_dir.err;
  ASSERT_TRUE(fs::exists("/dev/full")) << "the test needs /dev/full (every Linux has it)";
  for (const std::string& args : {"distance " + pq + " --offset 3,3 --json", "cast " + pq + " --offset 3,6 --direction 0,-1"}) {
    const Result full = to_full(args);
    EXPECT_EQ(full.status, 3) << args;
    EXPECT_EQ(full.err, "pendepth: standard output: cannot write (No space left on device)\n") << args;
  }
}
