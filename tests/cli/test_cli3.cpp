// End-to-end tests of `pendepth` on 3D shapes (docs/design.md §3): analytic cube depths in every
// mesh format, rotations, exit codes and one-line errors naming file and line (or byte offset),
// and batch output equal bit for bit to the library's answers.
#include <pendepth/depth3.hpp>
#include <pendepth/io.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <bit>
#include <charconv>
#include <cstdint>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include "cli/cli_fixture.hpp"

using pendepth::ConvexPolytope;
using pendepth::Depth3;
using pendepth::Pose3;
using pendepth::Vec3;
namespace io = pendepth::io;
namespace fs = std::filesystem;
using nlohmann::json;

using cli_test::quote;
using cli_test::Result;
using cli_test::slurp;

namespace {

// The corners of the box [0, s]³, in the order x fastest.
std::vector<Vec3> box(double s) {
  std::vector<Vec3> c;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) c.emplace_back(s * x, s * y, s * z);
  return c;
}

std::string obj_text(const std::vector<Vec3>& pts) {
  std::string s = "# written by test_cli3\n";
  for (const Vec3& p : pts) {
    s += "v";
    for (int k = 0; k < 3; ++k) {
      s += ' ';
      io::append_double(s, p[k]);
    }
    s += '\n';
  }
  return s;
}

std::string off_text(const std::vector<Vec3>& pts) {
  std::string s = "OFF\n" + std::to_string(pts.size()) + " 0 0\n";
  for (const Vec3& p : pts) {
    for (int k = 0; k < 3; ++k) {
      io::append_double(s, p[k]);
      s += k < 2 ? ' ' : '\n';
    }
  }
  return s;
}

class Cli3 : public cli_test::CliFixture {
 protected:
  json run_json(const std::string& args) {
    const Result r = run(args + " --json");
    EXPECT_EQ(r.status, 0) << args << ": " << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    return r.status == 0 ? json::parse(r.out) : json();
  }

  // P = [0,2]³ and Q = [0,1]³.
  std::string cube_p() { return write("P.obj", obj_text(box(2))); }
  std::string cube_q() { return write("Q.obj", obj_text(box(1))); }
};

Vec3 vec_of(const json& j) { return Vec3(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()); }

void expect_same(const json& j, const Depth3& r) {
  EXPECT_EQ(j.at("depth").get<double>(), r.depth);
  EXPECT_EQ(vec_of(j.at("translation")), r.translation);
  EXPECT_EQ(vec_of(j.at("normal")), r.normal);
  EXPECT_EQ(vec_of(j.at("witness_p")), r.witness_p);
  EXPECT_EQ(vec_of(j.at("witness_q")), r.witness_q);
  EXPECT_EQ(j.at("overlapping").get<bool>(), r.overlapping);
  EXPECT_EQ(j.at("lower_bound").get<double>(), r.lower_bound);
  EXPECT_EQ(j.at("upper_bound").get<double>(), r.upper_bound);
}

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> v;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

// "a,b,c,d" → numbers, read exactly; fails the test if the row is malformed.
std::vector<double> row_numbers(const std::string& row) {
  std::vector<double> v;
  const char* p = row.data();
  const char* end = p + row.size();
  while (p < end) {
    double x = 0;
    auto [ptr, ec] = std::from_chars(p, end, x);
    EXPECT_EQ(ec, std::errc()) << row;
    if (ec != std::errc()) break;
    v.push_back(x);
    p = ptr + (ptr < end && *ptr == ',');
  }
  return v;
}

void append_row(std::string& csv, std::initializer_list<double> xs) {
  for (double x : xs) {
    io::append_double(csv, x);
    csv += ',';
  }
  csv.back() = '\n';
}

}  // namespace

TEST_F(Cli3, CubeMinimumJsonAnalyticAndLibrary) {
  const std::string P = cube_p(), Q = cube_q();
  const json j = run_json("depth " + quote(P) + " " + quote(Q) + " --offset 0.5,0.25,0.5");
  for (const char* key : {"depth", "translation", "normal", "witness_p", "witness_q", "kind", "overlapping", "feature_p",
                          "feature_q", "lower_bound", "upper_bound"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j.size(), 11u);
  EXPECT_EQ(j["kind"], "minimum");
  // Q + t = [.5,1.5]×[.25,1.25]×[.5,1.5] in [0,2]³: the nearest exit is down in y by 1.25 (the
  // others need 1.5 or 1.75).
  EXPECT_EQ(j["depth"].get<double>(), 1.25);
  EXPECT_EQ(vec_of(j["translation"]), Vec3(0, -1.25, 0));
  EXPECT_EQ(vec_of(j["normal"]), Vec3(0, -1, 0));
  // Face-face contact: Q's face y = 1, moved to [.5,1.5]×{0}×[.5,1.5], on P's face y = 0. The
  // witness lies in that square; the features name P's face (its three input vertices have
  // y = 0) and a vertex of Q's contact face (input y = 1).
  const Vec3 w = vec_of(j["witness_p"]);
  EXPECT_EQ(vec_of(j["witness_q"]), w);
  EXPECT_EQ(w.y(), 0.0);
  EXPECT_TRUE(w.x() >= 0.5 && w.x() <= 1.5 && w.z() >= 0.5 && w.z() <= 1.5) << w.transpose();
  EXPECT_EQ(j["feature_p"]["kind"], "face");
  ASSERT_EQ(j["feature_p"]["vertices"].size(), 3u);
  for (const json& v : j["feature_p"]["vertices"]) EXPECT_EQ(box(2).at(v.get<std::size_t>()).y(), 0.0);
  EXPECT_EQ(j["feature_q"]["kind"], "vertex");
  EXPECT_EQ(box(1).at(j["feature_q"]["index"].get<std::size_t>()).y(), 1.0);

  const ConvexPolytope PP = io::read_convex_polytope(P, "P"), QQ = io::read_convex_polytope(Q, "Q");
  expect_same(j, pendepth::minimum_depth(PP, Pose3(), QQ, Pose3(Vec3(0.5, 0.25, 0.5))));
}

TEST_F(Cli3, CubeDirectionalSeparationSummaryTouching) {
  const std::string P = cube_p(), Q = cube_q(), pq = quote(P) + " " + quote(Q);
  json j = run_json("depth " + pq + " --offset=-0.5,0.5,0.5 --direction 3,0,0");
  EXPECT_EQ(j["kind"], "directional");
  EXPECT_EQ(j["depth"].get<double>(), 2.5);  // Q's face x = −0.5 must reach x = 2
  EXPECT_EQ(vec_of(j["normal"]), Vec3(1, 0, 0));
  EXPECT_EQ(vec_of(j["translation"]), Vec3(2.5, 0, 0));

  // Diagonal: Q + t = [.5,1.5]³ leaves along (1,1,1) after 1.5 per axis: 1.5·√3 (rounded d̂).
  j = run_json("depth " + pq + " --offset 0.5,0.5,0.5 --direction 1,1,1");
  EXPECT_NEAR(j["depth"].get<double>(), 1.5 * std::sqrt(3.0), 4e-15);

  // Complete separation of convex shapes is σ_d.
  j = run_json("depth " + pq + " --offset 0.5,0.5,0.5 --direction 0,0,-1 --separate");
  EXPECT_EQ(j["kind"], "separation");
  EXPECT_EQ(j["depth"].get<double>(), 1.5);
  const json jd = run_json("depth " + pq + " --offset 0.5,0.5,0.5 --direction 0,0,-1");
  for (const char* key : {"depth", "translation", "normal", "witness_p", "feature_p", "feature_q"})
    EXPECT_EQ(j[key], jd[key]) << key;

  Result r = run("depth " + pq + " --offset 0.5,0.5,0.5 --direction 0,-1,0");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("directional depth"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("depth:       1.5\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("translation: (0, -1.5, 0)"), std::string::npos) << r.out;

  r = run("depth " + pq + " --offset 5,5,5");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("overlapping: no"), std::string::npos) << r.out;
  // Face contact, edge contact, vertex contact: touching is depth 0.
  for (const char* t : {"2,0,0", "2,2,0.5", "-1,-1,-1"}) {
    j = run_json("depth " + pq + " --offset=" + t);
    EXPECT_EQ(j["depth"].get<double>(), 0.0) << t;
    EXPECT_FALSE(j["overlapping"].get<bool>()) << t;
    EXPECT_EQ(j["feature_p"]["kind"], "none");
  }
}

TEST_F(Cli3, EveryMeshFormatGivesTheSameAnswer) {
  const std::string P = cube_p();
  // The 12 triangles of [0,1]³ (orientation does not matter to the hull).
  const int tri[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                          {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  std::string ascii = "solid cube\n", binary = "solid but binary";  // binary: detected by size
  binary.resize(80, ' ');
  auto put_u32 = [&](std::uint32_t x) {
    for (int k = 0; k < 4; ++k) binary += static_cast<char>((x >> (8 * k)) & 0xFF);
  };
  put_u32(12);
  for (const auto& t : tri) {
    ascii += "facet normal 0 0 0\nouter loop\n";
    for (int k = 0; k < 3; ++k) put_u32(0);
    for (int v : t) {
      const Vec3 c = box(1)[v];
      ascii += "vertex " + std::to_string(c.x()) + " " + std::to_string(c.y()) + " " + std::to_string(c.z()) + "\n";
      for (int k = 0; k < 3; ++k) put_u32(std::bit_cast<std::uint32_t>(static_cast<float>(c[k])));
    }
    binary += std::string(2, '\0');
    ascii += "endloop\nendfacet\n";
  }
  ascii += "endsolid cube\n";
  const std::string Q_obj = cube_q(), Q_off = write("Q.off", off_text(box(1))), Q_ascii = write("Q.stl", ascii),
                    Q_bin = write("Qb.STL", binary), P_off = write("P.off", off_text(box(2)));
  ASSERT_EQ(binary.size(), 84u + 50u * 12u);
  const std::string args = " --offset 0.5,0.25,0.75 --direction 1,0.5,0.25";
  const json want = run_json("depth " + quote(P) + " " + quote(Q_obj) + args);
  EXPECT_EQ(want["kind"], "directional");
  // Along λ·(1, .5, .25), x separates first (0.5 + λ = 2): depth 1.5·|d|.
  EXPECT_NEAR(want["depth"].get<double>(), 1.5 * std::sqrt(1 + 0.25 + 0.0625), 1e-15);
  for (const std::string& p : {P, P_off})
    for (const std::string& q : {Q_obj, Q_off, Q_ascii, Q_bin}) {
      const json j = run_json("depth " + quote(p) + " " + quote(q) + args);
      for (const char* key : {"depth", "translation", "normal", "witness_p", "witness_q"})
        EXPECT_EQ(j[key], want[key]) << p << " " << q << " " << key;
    }
}

TEST_F(Cli3, RotationsAreNormalisedQuaternions) {
  // Centred cubes P = [−1,1]³, Q = [−½,½]³: rotations about their origins keep them overlapping.
  std::vector<Vec3> pc = box(2), qc = box(1);
  for (Vec3& v : pc) v -= Vec3(1, 1, 1);
  for (Vec3& v : qc) v -= Vec3(0.5, 0.5, 0.5);
  const std::string P = write("Pc.obj", obj_text(pc)), Q = write("Qc.obj", obj_text(qc)), pq = quote(P) + " " + quote(Q);
  const ConvexPolytope PP = io::read_convex_polytope(P, "P"), QQ = io::read_convex_polytope(Q, "Q");
  // 90° about z maps Q onto itself; at t = (.5,.25,.25), Q + t = [0,1]×[−¼,¾]² leaves by x+ after 1.
  json j = run_json("depth " + pq + " --rotate-q 2,0,0,2 --offset 0.5,0.25,0.25");
  EXPECT_NEAR(j["depth"].get<double>(), 1.0, 1e-15);
  EXPECT_NEAR((vec_of(j["normal"]) - Vec3(1, 0, 0)).norm(), 0.0, 1e-15);
  expect_same(j, pendepth::minimum_depth(PP, Pose3(), QQ, Pose3(Eigen::Quaterniond(1, 0, 0, 1), Vec3(0.5, 0.25, 0.25))));
  // The same quaternion at extreme scales: rescaled exactly, not rejected as zero or infinite.
  for (const char* q : {"1e-300,0,0,1e-300", "1e300,0,0,1e300"}) {
    const json k = run_json("depth " + pq + " --rotate-q " + q + " --offset 0.5,0.25,0.25");
    EXPECT_NEAR(k["depth"].get<double>(), 1.0, 1e-15) << q;
  }

  // Rotating P too: only the relative pose matters, results come back in the world frame.
  const Eigen::Quaterniond qp(0.9, 0.1, -0.3, 0.2), qq(0.5, -0.4, 0.1, 0.7);
  const Vec3 t(0.3, -0.2, 0.1), d(0.3, -1, 0.2);
  const std::string rot = " --rotate-p 0.9,0.1,-0.3,0.2 --rotate-q 0.5,-0.4,0.1,0.7 --offset=0.3,-0.2,0.1";
  j = run_json("depth " + pq + rot);
  const Depth3 m = pendepth::minimum_depth(PP, Pose3(qp, Vec3::Zero()), QQ, Pose3(qq, t));
  ASSERT_TRUE(m.overlapping);
  expect_same(j, m);
  // Rotating the whole scene by qp⁻¹ gives the same depth (rotation invariance, up to rounding).
  const Depth3 m0 = pendepth::minimum_depth(PP, Pose3(), QQ, Pose3(qp.normalized().inverse() * qq.normalized(),
                                                                   qp.normalized().inverse() * t));
  EXPECT_NEAR(m0.depth, m.depth, 1e-14);
  j = run_json("depth " + pq + rot + " --direction 0.3,-1,0.2");
  expect_same(j, pendepth::directional_depth(PP, Pose3(qp, Vec3::Zero()), QQ, Pose3(qq, t), d));
  EXPECT_LE(m.depth, j["depth"].get<double>());  // σ ≤ σ_d
}

TEST_F(Cli3, SharedHulls) {
  const std::string data = std::string(PENDEPTH_SHARED_DATA) + "/hulls/";
  const ConvexPolytope P = io::read_convex_polytope(data + "hull07.obj", "P");
  const ConvexPolytope Q = io::read_convex_polytope(data + "hull12.obj", "Q");
  // Q placed so that its first vertex sits at P's centroid: they overlap.
  Vec3 cp = Vec3::Zero();
  for (const Vec3& v : P.vertices()) cp += v;
  cp /= double(P.size());
  const Vec3 t = cp - Q[0];
  std::string ts;
  append_row(ts, {t.x(), t.y(), t.z()});
  ts.pop_back();
  const std::string pq = quote(data + "hull07.obj") + " " + quote(data + "hull12.obj");
  json j = run_json("depth " + pq + " --offset=" + ts);
  const Depth3 m = pendepth::minimum_depth(P, Pose3(), Q, Pose3(t));
  ASSERT_TRUE(m.overlapping);
  expect_same(j, m);
  j = run_json("depth " + pq + " --offset=" + ts + " --direction 0,1,0");
  expect_same(j, pendepth::directional_depth(P, Pose3(), Q, Pose3(t), Vec3(0, 1, 0)));
}

TEST_F(Cli3, BadInputExitsWithOneLine) {
  const std::string P = cube_p(), Q = cube_q(), pq = quote(P) + " " + quote(Q);
  const std::string wkt = write("sq.wkt", "POLYGON ((0 0, 1 0, 1 1, 0 1))\n");
  expect_error("depth " + quote(P) + " " + quote(wkt), wkt + ": Q is a 2D shape but P (" + P + ") is 3D; both must be 2D (.wkt) or both 3D (.obj, .off, .stl, .ply)");
  expect_error("depth " + quote(wkt) + " " + quote(Q), Q + ": Q is a 3D shape but P (" + wkt + ") is 2D; both must be 2D (.wkt) or both 3D (.obj, .off, .stl, .ply)");
  expect_error("batch " + quote(P) + " " + quote(wkt) + " --queries " + quote(wkt),
               wkt + ": Q is a 2D shape but P (" + P + ") is 3D; both must be 2D (.wkt) or both 3D (.obj, .off, .stl, .ply)");

  const std::string svg = (dir_ / "x.svg").string();
  expect_error("depth " + pq + " --svg " + quote(svg), "--svg draws 2D shapes only");
  EXPECT_FALSE(fs::exists(svg));
  expect_error("depth " + pq + " --rotate-q 0,0,0,0", "--rotate-q: the quaternion is zero (it must be a rotation)");
  expect_error("depth " + pq + " --rotate-p 0,-0,0,0", "--rotate-p: the quaternion is zero (it must be a rotation)");
  expect_error("depth " + pq + " --rotate-q 1,0,0", "--rotate-q: expected QW,QX,QY,QZ (four numbers), got '1,0,0'");
  expect_error("depth " + pq + " --rotate-q 1,0,0,inf", "--rotate-q: non-finite number in '1,0,0,inf'");
  expect_error("depth " + pq + " --offset 1,2", "--offset: expected X,Y,Z (three numbers), got '1,2'");
  expect_error("depth " + pq + " --offset 1,2,3,4", "--offset: expected X,Y,Z (three numbers), got '1,2,3,4'");
  expect_error("depth " + pq + " --direction 0,0,-0", "--direction: the direction is zero");
  expect_error("depth " + pq + " --direction 1,0,nan", "--direction: non-finite number in '1,0,nan'");

  const std::string bad = write("bad.obj", "v 0 0 0\nv 1 0 0\n# c\nv 0 1 zero\n");
  expect_error("depth " + quote(bad) + " " + quote(Q), bad + ":4: malformed vertex line: z is not a number: 'zero'");
  // A lone face (coplanar points), the same points without the face, and three points: flat shapes
  // (Shape3::flat), with or without --hull, answered against a solid; two flat shapes are refused.
  const std::string flat = write("flat.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 3 2\n");
  const std::string flat_pts = write("flat_pts.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0.5 0.5 0\n");
  const std::string few = write("few.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  for (const std::string& cmd : {"depth", "distance", "depth --direction 0.3,-0.2,1", "cast --direction -1,-0.5,-0.25"}) {
    const std::string args = " --offset 0.25,0.5,0.125";
    const Result a = run(cmd + " " + quote(P) + " " + quote(flat) + args);
    EXPECT_EQ(a.status, 0) << cmd << ": " << a.err;
    if (cmd.starts_with("depth"))  // (the summary line of depth)
      EXPECT_NE(a.out.find("Q Q (a flat polygon of 4 vertices)"), std::string::npos) << cmd << ": " << a.out;
    EXPECT_EQ(run(cmd + " " + quote(P) + " " + quote(flat) + args + " --hull").out, a.out) << cmd;
    EXPECT_EQ(run(cmd + " " + quote(P) + " " + quote(flat_pts) + args).out, a.out) << cmd;
    const Result t = run(cmd + " " + quote(few) + " " + quote(Q) + args);
    EXPECT_EQ(t.status, 0) << cmd << ": " << t.err;
    if (cmd.starts_with("depth"))
      EXPECT_NE(t.out.find("P P (a flat polygon of 3 vertices)"), std::string::npos) << cmd << ": " << t.out;
  }
  expect_error("depth " + quote(flat) + " " + quote(few),
               "pair: both shapes are lower-dimensional (P P of dimension 2, Q Q of dimension 2): M = P ⊕ (−Q) has no "
               "interior; one shape must be solid");
  const std::string stl = write("trunc.stl", std::string(80, 'x') + std::string("\x02\0\0\0", 4) + std::string(99, '\0'));
  expect_error("depth " + quote(P) + " " + quote(stl),
               stl + ": binary STL of 2 triangles must have 184 bytes, the file has 183 (byte offset 80)");
  const std::string missing = (dir_ / "missing.stl").string();
  expect_error("depth " + quote(P) + " " + quote(missing), missing + ": cannot read file (No such file or directory)");

  const std::string csv = write("q.csv", "x,y,z,dx,dy,dz\n0.5,0.5,0.5,0,0,0\n0.5,0.5,1,0\n");
  expect_error("batch " + pq + " --queries " + quote(csv), csv + ":3: expected 6 numbers, got 4 (a 2D query; the shapes are 3D)");
  const std::string csv2 = write("q2.csv", "0.5,0.5,0.5,0,0,0\n\n0.5,abc,1,0,0,0\n");
  expect_error("batch " + pq + " --queries " + quote(csv2), csv2 + ":3: field 2 is not a number: 'abc'");
  expect_error("batch " + pq + " --queries " + quote(missing), missing + ": cannot read file (No such file or directory)");
  expect_error("batch " + pq + " --queries " + quote(csv2) + " --rotate-q 0,0,0,0",
               "--rotate-q: the quaternion is zero (it must be a rotation)");
}

TEST_F(Cli3, BatchMatchesLibraryBitForBit) {
  std::mt19937_64 rng(271828);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(-1.1, 1.1), ud(-1, 1);
  std::vector<Vec3> pp, qp;
  // Coordinates on the grid 2⁻²⁰, so support-point differences (points of ∂M) are exact doubles.
  auto snap = [](Vec3 v) {
    for (int k = 0; k < 3; ++k) v[k] = std::ldexp(std::round(std::ldexp(v[k], 20)), -20);
    return v;
  };
  for (int i = 0; i < 120; ++i) pp.push_back(snap(Vec3(g(rng), g(rng), g(rng)).normalized() * (i % 2 ? 1.0 : 0.7)));
  for (int i = 0; i < 40; ++i) qp.push_back(snap(Vec3(0.2, -0.1, 0.1) + 0.5 * Vec3(g(rng), 0.6 * g(rng), g(rng)).normalized()));
  const std::string pf = write("P.obj", obj_text(pp)), qf = write("Q.off", off_text(qp));
  const ConvexPolytope P = io::read_convex_polytope(pf, "P"), Q = io::read_convex_polytope(qf, "Q");

  std::vector<std::pair<Vec3, Vec3>> qs;
  std::string csv = "x,y,z,dx,dy,dz\n# random offsets, half of them asking for the minimum\n";
  for (int k = 0; k < 144; ++k) {
    Vec3 t(u(rng), u(rng), u(rng));
    if (k % 12 == 0) {  // a point of ∂M (support points for ±u): touching, depth 0
      const Vec3 w(ud(rng), ud(rng), ud(rng));
      t = P[P.support(w)] - Q[Q.support(-w)];
    }
    const Vec3 d = k % 2 ? Vec3(ud(rng), ud(rng), ud(rng)) : Vec3(0, 0, 0);
    qs.emplace_back(t, d);
    append_row(csv, {t.x(), t.y(), t.z(), d.x(), d.y(), d.z()});
  }
  const std::string file = write("q.csv", csv);
  const Eigen::Quaterniond rq(0.8, 0.2, -0.5, 0.1);
  auto expected = [&](std::size_t k, bool rotated) {
    const auto& [t, d] = qs[k];
    const Pose3 pose_q = rotated ? Pose3(rq, t) : Pose3(t);
    return d.isZero(0) ? pendepth::minimum_depth(P, Pose3(), Q, pose_q) : pendepth::directional_depth(P, Pose3(), Q, pose_q, d);
  };

  Result r = run("batch " + quote(pf) + " " + quote(qf) + " --queries " + quote(file));
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<std::string> rows = lines_of(r.out);
  ASSERT_EQ(rows.size(), qs.size() + 1);
  EXPECT_EQ(rows[0], "depth,tx,ty,tz");
  int overlapping = 0, touching = 0;
  for (std::size_t k = 0; k < qs.size(); ++k) {
    const Depth3 e = expected(k, false);
    const std::vector<double> v = row_numbers(rows[k + 1]);
    ASSERT_EQ(v.size(), 4u) << rows[k + 1];
    EXPECT_EQ(v[0], e.depth) << k;
    EXPECT_EQ(Vec3(v[1], v[2], v[3]), e.translation) << k;
    overlapping += e.overlapping;
    if (k % 12 == 0) touching += v[0] == 0;
  }
  EXPECT_GT(overlapping, 50);
  EXPECT_EQ(touching, 12);

  r = run("batch " + quote(pf) + " " + quote(qf) + " --queries " + quote(file) + " --json --rotate-q 0.8,0.2,-0.5,0.1");
  ASSERT_EQ(r.status, 0) << r.err;
  rows = lines_of(r.out);
  ASSERT_EQ(rows.size(), qs.size());
  for (std::size_t k = 0; k < qs.size(); ++k) {
    const json j = json::parse(rows[k]);
    EXPECT_EQ(j.size(), 11u);
    EXPECT_EQ(j["kind"], qs[k].second.isZero(0) ? "minimum" : "directional");
    const Depth3 e = expected(k, true);
    expect_same(j, e);
    std::string want;
    io::append_json(want, e, P, Q);
    EXPECT_EQ(rows[k], want);
  }
}

TEST_F(Cli3, BatchDirectionScaleAndEmpty) {
  const std::string P = cube_p(), Q = cube_q(), pq = quote(P) + " " + quote(Q);
  std::string csv;
  for (const char* d : {"1,0,0", "5e-324,0,0", "1e-300,0,0", "1e300,0,0", "1.7e308,0,0"}) csv += std::string("0.5,0.5,0.5,") + d + "\n";
  csv += "0.5,0.5,0.5,1e-310,0,1e-310\n0.5,0.5,0.5,1e308,0,1e308\n";  // diagonal: analytic 1.5·√2
  csv += "0.5,0.5,0.5,0,0,0\n9,9,9,1,1,1\n";
  const std::string file = write("q.csv", csv);
  Result r = run("batch " + pq + " --queries " + quote(file));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = lines_of(r.out);
  ASSERT_EQ(rows.size(), 10u);
  EXPECT_EQ(rows[0], "depth,tx,ty,tz");
  EXPECT_EQ(rows[1], "1.5,1.5,0,0");
  for (std::size_t k = 2; k <= 7; ++k) {  // a few ulps: d̂ is rounded
    const std::vector<double> v = row_numbers(rows[k]);
    ASSERT_EQ(v.size(), 4u) << rows[k];
    const bool diagonal = k >= 6;
    EXPECT_NEAR(v[0], diagonal ? 1.5 * std::sqrt(2.0) : 1.5, 1e-15) << rows[k];
    EXPECT_NEAR((Vec3(v[1], v[2], v[3]) - Vec3(1.5, 0, diagonal ? 1.5 : 0)).norm(), 0.0, 1e-15) << rows[k];
  }
  // σ at the centre [.5,1.5]³ of [0,2]³: 1.5 along one of the six axis directions.
  const std::vector<double> c = row_numbers(rows[8]);
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[0], 1.5);
  EXPECT_EQ(Vec3(c[1], c[2], c[3]).cwiseAbs().maxCoeff(), 1.5);
  EXPECT_EQ(Vec3(c[1], c[2], c[3]).cwiseAbs().sum(), 1.5);
  EXPECT_EQ(rows[9], "0,0,0,0");
  const std::string empty = write("e.csv", "x,y,z,dx,dy,dz\n");
  r = run("batch " + pq + " --queries " + quote(empty));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "depth,tx,ty,tz\n");
}
