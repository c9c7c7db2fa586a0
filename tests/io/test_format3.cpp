// 3D result writers: the JSON object parses (nlohmann-json as the independent reader), carries
// every key with values that read back bit for bit, and its feature indices point at input
// vertices that really carry the contact (the witness lies on the named vertex, edge or face of
// the input point list); CSV rows read back exactly.
#include <pendepth/io.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <random>

using pendepth::ConvexPolytope;
using pendepth::Depth3;
using pendepth::Pose3;
using pendepth::Vec3;
namespace io = pendepth::io;
using nlohmann::json;

namespace {

// Points on a sphere plus interior points, shuffled: hull indices differ from input indices.
std::vector<Vec3> cloud(std::mt19937_64& rng, std::size_t n, const Vec3& c, double r) {
  std::normal_distribution<double> g;
  std::vector<Vec3> p;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 v = Vec3(g(rng), g(rng), g(rng)).normalized();
    p.push_back(c + r * (i % 3 == 0 ? 0.5 : 1.0) * v);
  }
  std::shuffle(p.begin(), p.end(), rng);
  return p;
}

Vec3 vec_of(const json& j) {
  EXPECT_EQ(j.size(), 3u);
  return Vec3(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>());
}

double seg_dist(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double s = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + s * ab - x).norm();
}

// Distance from x to the feature of the input point list `pts` described by j (moved by `shift`).
double feature_dist(const json& j, const std::vector<Vec3>& pts, const Vec3& shift, const Vec3& x) {
  const std::string kind = j.at("kind");
  if (kind == "vertex") return (pts.at(j.at("index").get<std::size_t>()) + shift - x).norm();
  if (kind == "edge")
    return seg_dist(x, pts.at(j.at("index").get<std::size_t>()) + shift, pts.at(j.at("end").get<std::size_t>()) + shift);
  EXPECT_EQ(kind, "face");
  const json& v = j.at("vertices");
  const Vec3 a = pts.at(v.at(0).get<std::size_t>()) + shift, b = pts.at(v.at(1).get<std::size_t>()) + shift,
             c = pts.at(v.at(2).get<std::size_t>()) + shift;
  const Vec3 n = (b - a).cross(c - a).normalized();
  return std::abs((x - a).dot(n));
}

}  // namespace

TEST(Format3, JsonFeaturesPointAtTheInputVerticesOfTheContact) {
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  int kinds[3] = {0, 0, 0};  // vertex, edge, face features seen
  for (int trial = 0; trial < 40; ++trial) {
    const std::vector<Vec3> pp = cloud(rng, 60, Vec3(0, 0, 0), 1), qp = cloud(rng, 30, Vec3(0, 0, 0), 0.6);
    const ConvexPolytope P = ConvexPolytope::hull(pp, "P"), Q = ConvexPolytope::hull(qp, "Q");
    const Vec3 t(u(rng), u(rng), u(rng));
    const Depth3 r = trial % 2 ? pendepth::minimum_depth(P, Pose3(), Q, Pose3(t))
                               : pendepth::directional_depth(P, Pose3(), Q, Pose3(t), Vec3(u(rng), u(rng), 1));
    ASSERT_TRUE(r.overlapping);
    std::string out;
    io::append_json(out, r, P, Q);
    const json j = json::parse(out);
    ASSERT_EQ(j.size(), 11u);
    EXPECT_EQ(j.at("depth").get<double>(), r.depth);
    EXPECT_EQ(vec_of(j.at("translation")), r.translation);
    EXPECT_EQ(vec_of(j.at("normal")), r.normal);
    EXPECT_EQ(vec_of(j.at("witness_p")), r.witness_p);
    EXPECT_EQ(vec_of(j.at("witness_q")), r.witness_q);
    EXPECT_EQ(j.at("kind"), trial % 2 ? "minimum" : "directional");
    EXPECT_TRUE(j.at("overlapping").get<bool>());
    EXPECT_EQ(j.at("lower_bound").get<double>(), r.lower_bound);
    EXPECT_EQ(j.at("upper_bound").get<double>(), r.upper_bound);
    // The witness touches the named feature of P and of the moved Q (Q + t + translation).
    const double tol = 1e-12 * (1 + r.depth);
    EXPECT_LE(feature_dist(j.at("feature_p"), pp, Vec3::Zero(), r.witness_p), tol) << out;
    EXPECT_LE(feature_dist(j.at("feature_q"), qp, t + r.translation, r.witness_q), tol) << out;
    for (const char* f : {"feature_p", "feature_q"}) {
      const std::string k = j.at(f).at("kind");
      kinds[k == "vertex" ? 0 : k == "edge" ? 1 : 2]++;
    }
    // Face vertices are counter-clockwise seen from outside: the other input points are behind.
    for (const auto& [key, pts] : {std::pair{"feature_p", &pp}, std::pair{"feature_q", &qp}}) {
      const json& fj = j.at(key);
      if (fj.at("kind") != "face") continue;
      const json& v = fj.at("vertices");
      const Vec3 a = pts->at(v[0].get<std::size_t>()), b = pts->at(v[1].get<std::size_t>()), c = pts->at(v[2].get<std::size_t>());
      for (const Vec3& x : *pts) EXPECT_LE(pendepth::predicates::orient3d(a, b, c, x), 0);
    }
  }
  EXPECT_GT(kinds[0], 0);
  EXPECT_GT(kinds[2], 0);
}

TEST(Format3, NotOverlappingCsvAndSummary) {
  std::mt19937_64 rng(5);
  const ConvexPolytope P = ConvexPolytope::hull(cloud(rng, 40, Vec3(0, 0, 0), 1), "P");
  const ConvexPolytope Q = ConvexPolytope::hull(cloud(rng, 40, Vec3(0, 0, 0), 1), "Q");
  const Depth3 apart = pendepth::minimum_depth(P, Pose3(), Q, Pose3(Vec3(5, 0, 0)));
  std::string out;
  io::append_json(out, apart, P, Q);
  EXPECT_EQ(out,
            "{\"depth\":0,\"translation\":[0,0,0],\"normal\":[0,0,0],\"witness_p\":[0,0,0],\"witness_q\":[0,0,0],"
            "\"kind\":\"minimum\",\"overlapping\":false,\"feature_p\":{\"kind\":\"none\",\"index\":null},"
            "\"feature_q\":{\"kind\":\"none\",\"index\":null},\"lower_bound\":0,\"upper_bound\":0}");
  EXPECT_NE(io::summary(apart, P, Q).find("overlapping: no"), std::string::npos);

  const Depth3 r = pendepth::minimum_depth(P, Pose3(), Q, Pose3(Vec3(0.1, 0.2, 0.3)));
  ASSERT_TRUE(r.overlapping);
  std::string row;
  io::append_csv_row(row, r);
  ASSERT_EQ(row.back(), '\n');
  double v[4];
  const char* p = row.data();
  const char* end = row.data() + row.size() - 1;
  for (double& x : v) {
    auto [ptr, ec] = std::from_chars(p, end, x);
    ASSERT_EQ(ec, std::errc()) << row;
    p = ptr + (ptr < end);
  }
  EXPECT_EQ(p, end);
  EXPECT_EQ(v[0], r.depth);
  EXPECT_EQ(Vec3(v[1], v[2], v[3]), r.translation);
  const std::string s = io::summary(r, P, Q);
  EXPECT_NE(s.find("minimum depth"), std::string::npos) << s;
  EXPECT_NE(s.find("overlapping: yes"), std::string::npos) << s;
  std::string depth_line = "depth:       ";
  io::append_double(depth_line, r.depth);
  EXPECT_NE(s.find(depth_line + "\n"), std::string::npos) << s;
  EXPECT_NE(s.find("  features:    "), std::string::npos) << s;
  EXPECT_NE(s.find(" of Q\n"), std::string::npos) << s;
}
