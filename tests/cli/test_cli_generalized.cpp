// End-to-end tests of `pendepth depth --generalized` (issue 18 item 5) and the 2D `--rotate-q DEG`
// (issue 19 item 3):
//   - 2D --generalized --json equals generalized_depth run in-process on the same files, bit for
//     bit (every field: depth, bounds, angle, translation, σ, intervals, kind "generalized");
//   - 3D --generalized --json equals σ of Pair3 (the theorem for convex polytopes), identity
//     rotation quaternion;
//   - --rotate-q DEG in 2D equals Pair2 on Q.rotated(DEG); a quarter turn reports
//     rotation_exact true and no note, 30° reports rotation_exact false and the human note;
//   - batch --rotate-q DEG answers on Q.rotated(DEG), the rounding note on stderr;
//   - bad combinations: exit 2 with one line (--direction with --generalized, --rotate-p in 2D,
//     a non-numeric angle).
#include <pendepth/pendepth.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/cli_fixture.hpp"

using namespace pendepth;
using cli_test::quote;
using cli_test::Result;

namespace {

class CliGeneralized : public cli_test::CliFixture {};

const cli_test::Rings kSlot{{Vec2(-3, -5), Vec2(3, -5), Vec2(3, 4), Vec2(0.26, 4), Vec2(0.26, -4), Vec2(-0.26, -4),
                             Vec2(-0.26, 4), Vec2(-3, 4)}};

cli_test::Rings bar_turned(double deg) {
  const Shape2 b = Shape2({Vec2(-0.25, -3), Vec2(0.25, -3), Vec2(0.25, 3), Vec2(-0.25, 3)}, {}, "bar").rotated(deg);
  return b.rings();
}

TEST_F(CliGeneralized, Depth2MatchesLibrary) {
  const std::string p = write("slot.wkt", cli_test::wkt_of(kSlot)), q = write("bar.wkt", cli_test::wkt_of(bar_turned(3)));
  const Shape2 P = Shape2::from_file(p, "P"), Q = Shape2::from_file(q, "Q");
  for (const Vec2 t : {Vec2(0, 0), Vec2(0.05, -0.5), Vec2(10, 0)}) {
    const Result r = run("depth " + quote(p) + " " + quote(q) + " --generalized --json --offset=" +
                         std::to_string(t.x()) + "," + std::to_string(t.y()));
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const GeneralizedDepth2 g = generalized_depth(P, Q, Vec2(std::stod(std::to_string(t.x())), std::stod(std::to_string(t.y()))));
    EXPECT_EQ(j["kind"], "generalized");
    EXPECT_EQ(j["overlapping"].get<bool>(), g.overlapping);
    EXPECT_EQ(j["depth"].get<double>(), g.depth);
    EXPECT_EQ(j["lower_bound"].get<double>(), g.lower_bound);
    EXPECT_EQ(j["upper_bound"].get<double>(), g.upper_bound);
    EXPECT_EQ(j["angle"].get<double>(), g.angle);
    EXPECT_EQ(j["translation"][0].get<double>(), g.translation.x());
    EXPECT_EQ(j["translation"][1].get<double>(), g.translation.y());
    EXPECT_EQ(j["sigma"].get<double>(), g.sigma);
    EXPECT_EQ(j["converged"].get<bool>(), g.converged);
    EXPECT_EQ(j["intervals"].get<std::size_t>(), g.intervals);
    if (t == Vec2(0, 0)) {
      EXPECT_TRUE(g.overlapping);
      EXPECT_LT(g.depth, 0.1 * g.sigma);  // turning back beats pulling out
      EXPECT_TRUE(g.converged);           // the branch and bound over angles closes the gap
    }
  }
  // The human summary names the bounds, the rotation and the translation.
  const Result h = run("depth " + quote(p) + " " + quote(q) + " --generalized");
  ASSERT_EQ(h.status, 0) << h.err;
  EXPECT_NE(h.out.find("generalized depth PD_g"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("certified bounds: ["), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("motion: rotate Q by -"), std::string::npos) << h.out;
}

TEST_F(CliGeneralized, Depth3IsSigma) {
  // Tetrahedra as closed meshes (faces outward), so convex: the CLI answers their hulls.
  const std::string p = write("p.off", "OFF\n4 4 0\n0 0 0\n2 0 0\n0 2 0\n0 0 2\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const std::string q = write("q.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const Result r = run("depth " + quote(p) + " " + quote(q) + " --generalized --json --offset=0.2,0.3,0.1 --rotate-q 1,0.1,0,0");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const Shape3 P = Shape3::from_file(p, "P", true), Q = Shape3::from_file(q, "Q", true);  // the hulls: the same solids
  const Depth3 s = Pair3(P, Q).minimum(Pose3(), Pose3(Eigen::Quaterniond(1, 0.1, 0, 0), Vec3(0.2, 0.3, 0.1)));
  ASSERT_TRUE(s.overlapping);
  EXPECT_EQ(j["kind"], "generalized");
  EXPECT_EQ(j["depth"].get<double>(), s.depth);
  EXPECT_EQ(j["lower_bound"].get<double>(), s.lower_bound);
  EXPECT_EQ(j["upper_bound"].get<double>(), s.upper_bound);
  EXPECT_EQ(j["rotation"], nlohmann::json::parse("[1,0,0,0]"));
  for (int k = 0; k < 3; ++k) EXPECT_EQ(j["translation"][k].get<double>(), s.translation[k]);
}

TEST_F(CliGeneralized, RotateQ2) {
  const std::string p = write("slot.wkt", cli_test::wkt_of(kSlot)), q = write("bar.wkt", cli_test::wkt_of(bar_turned(0)));
  const Shape2 P = Shape2::from_file(p, "P"), Q = Shape2::from_file(q, "Q");
  for (double deg : {90.0, -180.0, 30.0, -2.5}) {
    char a[32];
    std::snprintf(a, sizeof a, "%g", deg);
    const Result r = run("depth " + quote(p) + " " + quote(q) + " --json --offset=0.1,0.2 --rotate-q=" + a);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const Depth2 s = Pair2(P, Q.rotated(deg)).minimum(Vec2(0.1, 0.2));
    EXPECT_EQ(j["depth"].get<double>(), s.depth) << deg;
    EXPECT_EQ(j["translation"][0].get<double>(), s.translation.x()) << deg;
    EXPECT_EQ(j["translation"][1].get<double>(), s.translation.y()) << deg;
    EXPECT_EQ(j["rotation_exact"].get<bool>(), Shape2::rotation_is_exact(deg)) << deg;
    const Result h = run("depth " + quote(p) + " " + quote(q) + " --offset=0.1,0.2 --rotate-q=" + a);
    ASSERT_EQ(h.status, 0);
    EXPECT_EQ(h.out.find("note: Q's coordinates were rotated") != std::string::npos, !Shape2::rotation_is_exact(deg)) << h.out;
  }
  // batch --rotate-q DEG: the same answers; the rounding note goes to stderr.
  const std::string csv = write("q.csv", "0.1,0.2,0,0\n0.1,0.2,1,0\n");
  for (double deg : {90.0, 30.0}) {
    const Result r = run("batch " + quote(p) + " " + quote(q) + " --queries " + quote(csv) + " --rotate-q=" + (deg == 90 ? "90" : "30"));
    ASSERT_EQ(r.status, 0) << r.err;
    const Pair2 pair(P, Q.rotated(deg));
    const Depth2 s = pair.minimum(Vec2(0.1, 0.2)), d = pair.along(Vec2(0.1, 0.2), Vec2(1, 0));
    std::string expected = "depth,tx,ty\n";
    io::append_csv_row(expected, s);
    io::append_csv_row(expected, d);
    EXPECT_EQ(r.out, expected) << deg;
    EXPECT_EQ(r.err.empty(), deg == 90) << r.err;
  }
  // Turned by 90° the bar lies across the slot: deeply overlapping; unturned it fits (apart).
  EXPECT_TRUE(Pair2(P, Q.rotated(90)).overlapping(Vec2(0.1, 0.2)));
  EXPECT_FALSE(Pair2(P, Q).overlapping(Vec2(0, 0)));
}

TEST_F(CliGeneralized, BadInput) {
  const std::string p = write("slot.wkt", cli_test::wkt_of(kSlot)), q = write("bar.wkt", cli_test::wkt_of(bar_turned(0)));
  expect_error("depth " + quote(p) + " " + quote(q) + " --generalized --direction 1,0",
               "--generalized: asks for the minimum depth under rigid motion; drop --direction");
  expect_error("depth " + quote(p) + " " + quote(q) + " --rotate-p 3", "--rotate-p: 2D rotates Q only (--rotate-q DEG)");
  expect_error("depth " + quote(p) + " " + quote(q) + " --rotate-q x", "--rotate-q: expected DEG (one number), got 'x'");
}

}  // namespace
