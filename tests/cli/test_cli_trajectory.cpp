// `pendepth trajectory P Q --poses FILE [--json] [--cold]` (issue 18 item 3): σ at every pose,
// warm-started; the output equals --cold byte for byte (CSV and JSON, 2D and 3D), every row equals
// the library's single answer for that pose (2D: quarter turns exactly the hand-rotated shape,
// other angles Shape2::rotated), bad pose files exit 2 naming the file and line, and a failed
// write exits 3.
#include <pendepth/pendepth.hpp>

#include "cli/cli_fixture.hpp"

#include <cmath>
#include <random>

using namespace cli_test;
using namespace pendepth;

namespace {

class CliTrajectory : public CliFixture {
 protected:
  std::string ell() { return write("L.wkt", "POLYGON ((0 0, 4 0, 4 2, 2 2, 2 4, 0 4, 0 0))\n"); }
  std::string bar() { return write("R.wkt", "POLYGON ((0 0, 1 0, 1 2, 0 2, 0 0))\n"); }
  std::string hull(int k) {
    char name[64];
    std::snprintf(name, sizeof name, "%s/hulls/hull%02d.obj", PENDEPTH_SHARED_DATA, k);
    return name;
  }
  // Lines of the CSV output after the header.
  static std::vector<std::string> rows(const std::string& out) {
    std::vector<std::string> r;
    std::size_t pos = out.find('\n') + 1;
    while (pos < out.size()) {
      const std::size_t end = out.find('\n', pos);
      r.push_back(out.substr(pos, end - pos));
      pos = end + 1;
    }
    return r;
  }
};

std::string csv_row(const Depth2& r) {
  std::string s;
  io::append_csv_row(s, r);
  return s.substr(0, s.size() - 1);
}
std::string csv_row(const Depth3& r) {
  std::string s;
  io::append_csv_row(s, r);
  return s.substr(0, s.size() - 1);
}

TEST_F(CliTrajectory, TwoDimensionalWarmEqualsColdAndTheLibrary) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-0.3, 0.3);
  std::vector<std::array<double, 3>> poses;
  const double angles[] = {0, 0, 90, 90, 90, 33.5, 33.5, -45, 180, 270, 0, -0.0, 12.25};
  double x = 1, y = 1;
  for (double a : angles)
    for (int k = 0; k < 3; ++k) poses.push_back({x += U(rng), y += U(rng), a});
  std::string text = "x,y,angle_deg\n# a comment\n";
  for (const auto& p : poses) {
    io::append_double(text, p[0]), text += ',', io::append_double(text, p[1]), text += ',', io::append_double(text, p[2]);
    text += '\n';
  }
  const std::string file = write("poses.csv", text);
  const std::string P = ell(), Q = bar();
  for (const std::string extra : {"", " --json"}) {
    const Result warm = run("trajectory " + quote(P) + " " + quote(Q) + " --poses " + quote(file) + extra);
    const Result cold = run("trajectory " + quote(P) + " " + quote(Q) + " --poses " + quote(file) + " --cold" + extra);
    ASSERT_EQ(warm.status, 0) << warm.err;
    EXPECT_EQ(warm.out, cold.out);
    EXPECT_EQ(warm.err, "");
  }
  // Each row: the library's answer for Q rotated by the angle; quarter turns are exact, so the
  // shape rotated by hand (90°: (x, y) -> (-y, x)) gives the same row.
  const auto out = rows(run("trajectory " + quote(P) + " " + quote(Q) + " --poses " + quote(file)).out);
  ASSERT_EQ(out.size(), poses.size());
  const Shape2 SP = Shape2::from_file(P), SQ = Shape2::from_file(Q);
  const Shape2 Q90(std::vector<Vec2>{{0, 0}, {0, 1}, {-2, 1}, {-2, 0}});
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const Vec2 t(poses[k][0], poses[k][1]);
    EXPECT_EQ(out[k], csv_row(Pair2(SP, SQ.rotated(poses[k][2])).minimum(t))) << k;
    if (poses[k][2] == 0) EXPECT_EQ(out[k], csv_row(Pair2(SP, SQ).minimum(t))) << k;
    if (poses[k][2] == 90) EXPECT_EQ(out[k], csv_row(Pair2(SP, Q90).minimum(t))) << k;
  }
  // The front-door function gives the same answers.
  std::vector<Placement2> pl;
  for (const auto& p : poses) pl.push_back({Vec2(p[0], p[1]), p[2]});
  const auto lib = trajectory(SP, SQ, pl);
  for (std::size_t k = 0; k < poses.size(); ++k) EXPECT_EQ(out[k], csv_row(lib[k])) << k;
}

TEST_F(CliTrajectory, ThreeDimensionalWarmEqualsColdAndTheLibrary) {
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> U(-1, 1);
  const Shape3 P = Shape3::from_file(hull(3)), Q = Shape3::from_file(hull(11));
  Vec3 c = Vec3::Zero();
  for (const Vec3& v : P.polytope().vertices()) c += v / double(P.size());
  Eigen::Quaterniond q(1, 0, 0, 0);
  Vec3 t = c;
  std::vector<Pose3> poses;
  std::string text;
  for (int k = 0; k < 60; ++k) {
    t += 0.02 * Vec3(U(rng), U(rng), U(rng));
    if (k == 30) t += Vec3(0.5, -0.3, 0.2);  // a jump
    q = (Eigen::Quaterniond(1, 0.01 * U(rng), 0.01 * U(rng), 0.01 * U(rng)) * q);
    poses.emplace_back(q, t);
    for (double x : {t.x(), t.y(), t.z(), q.w(), q.x(), q.y(), q.z()}) io::append_double(text, x), text += ',';
    text.back() = '\n';
  }
  const std::string file = write("poses3.csv", text);
  for (const std::string extra : {"", " --json"}) {
    const Result warm = run("trajectory " + quote(hull(3)) + " " + quote(hull(11)) + " --poses " + quote(file) + extra);
    const Result cold =
        run("trajectory " + quote(hull(3)) + " " + quote(hull(11)) + " --poses " + quote(file) + " --cold" + extra);
    ASSERT_EQ(warm.status, 0) << warm.err;
    EXPECT_EQ(warm.out, cold.out);
  }
  const auto out = rows(run("trajectory " + quote(hull(3)) + " " + quote(hull(11)) + " --poses " + quote(file)).out);
  ASSERT_EQ(out.size(), poses.size());
  const Pair3 pair(P, Q);
  std::size_t overlapping = 0;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const Depth3 d = pair.minimum(Pose3(), poses[k]);
    overlapping += d.overlapping;
    EXPECT_EQ(out[k], csv_row(d)) << k;
  }
  EXPECT_GT(overlapping, 20u);  // the path is mostly overlapping: the warm start is exercised
}

TEST_F(CliTrajectory, BadPoseFilesExitTwoNamingTheLine) {
  const std::string P = ell(), Q = bar();
  auto check = [&](const std::string& text, const std::string& message, const std::string& p, const std::string& q) {
    const std::string f = write("bad.csv", text);
    expect_error("trajectory " + quote(p) + " " + quote(q) + " --poses " + quote(f), f + ":" + message);
  };
  check("1,1,0\n1,x,0\n", "2: field 2 is not a number: 'x'", P, Q);
  check("1,1\n", "1: expected 3 numbers, got 2", P, Q);
  check("x,y,angle\n1,1,0\n", "1: field 1 is not a number: 'x' (a header line must be exactly 'x,y,angle_deg')", P, Q);
  check("1,1,0\n1,1,inf\n", "2: field 3 is not a finite number: 'inf'", P, Q);
  check("1,1,0,0,0,0,1\n", "1: expected 3 numbers, got 7 (a 3D pose x,y,z,qw,qx,qy,qz; the shapes are 2D)", P, Q);
  check("x,y,z,qw,qx,qy,qz\n0,0,0,0,0,0,0\n", "2: the rotation quaternion is zero (it must be a rotation)", hull(0), hull(1));
  check("0,0,0,1,0,0,0\n1,2,3\n", "2: expected 7 numbers, got 3 (a 2D pose x,y,angle_deg; the shapes are 3D)", hull(0),
        hull(1));
  // A missing file and a missing option.
  const Result r = run("trajectory " + quote(P) + " " + quote(Q) + " --poses " + quote((dir_ / "none.csv").string()));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(run("trajectory " + quote(P) + " " + quote(Q)).status, 2);
  // Header and blank lines only: just the CSV header.
  const std::string empty = write("empty.csv", "x,y,angle_deg\n\n");
  const Result e = run("trajectory " + quote(P) + " " + quote(Q) + " --poses " + quote(empty));
  EXPECT_EQ(e.status, 0);
  EXPECT_EQ(e.out, "depth,tx,ty\n");
}

TEST_F(CliTrajectory, FailedWriteExitsThree) {
  ASSERT_TRUE(fs::exists("/dev/full")) << "the test needs /dev/full (every Linux has it)";
  const std::string P = ell(), Q = bar(), f = write("p.csv", "1,1,0\n1,1,90\n");
  const fs::path err = dir_ / "err.txt";
  const std::string cmd = quote(PENDEPTH_CLI) + " trajectory " + quote(P) + " " + quote(Q) + " --poses " + quote(f) +
                          " > /dev/full 2> " + quote(err.string());
  const int rc = std::system(cmd.c_str());
  EXPECT_EQ(WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, 3);
  EXPECT_EQ(slurp(err), "pendepth: standard output: cannot write (No space left on device)\n");
}

}  // namespace
