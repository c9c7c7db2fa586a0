// Result writers: the JSON object parses (nlohmann-json as the independent reader), carries every
// key with values that read back bit for bit, and its feature indices point at the input vertices
// that really bound the contact; CSV rows read back exactly.
#include <pendepth/io.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <random>

using pendepth::ConvexPolygon;
using pendepth::Depth2;
using pendepth::FeatureKind;
using pendepth::Vec2;
namespace io = pendepth::io;
using nlohmann::json;

namespace {

// A clockwise ring with a repeated vertex and a start that is not the lowest-leftmost vertex, so
// the input indices differ from the normal-form indices.
std::vector<Vec2> random_ring(std::mt19937_64& rng, std::size_t n, Vec2 center, double radius) {
  std::uniform_real_distribution<double> ang(0, 2 * M_PI);
  std::vector<double> a(n);
  for (double& x : a) x = ang(rng);
  std::sort(a.begin(), a.end(), std::greater<>());  // clockwise
  std::vector<Vec2> ring;
  for (double x : a) ring.push_back(center + radius * Vec2(std::cos(x), std::sin(x)));
  ring.insert(ring.begin() + 1, ring[1]);  // dropped by the normal form
  std::rotate(ring.begin(), ring.begin() + std::ptrdiff_t(n / 2), ring.end());
  return ring;
}

Vec2 vec_of(const json& j) { return Vec2(j.at(0).get<double>(), j.at(1).get<double>()); }

// Distance from x to segment ab.
double seg_dist(const Vec2& x, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double s = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + s * ab - x).norm();
}

// The feature as JSON must name input vertices of `ring` that bound the witness point w.
void check_feature(const json& f, const std::vector<Vec2>& ring, const Vec2& shift, const Vec2& w) {
  const std::string kind = f.at("kind");
  const double tol = 1e-9 * (1 + w.norm());
  if (kind == "vertex") {
    EXPECT_LT((ring.at(f.at("index").get<std::size_t>()) + shift - w).norm(), tol);
  } else {
    ASSERT_EQ(kind, "edge");
    const Vec2 a = ring.at(f.at("index").get<std::size_t>()) + shift;
    const Vec2 b = ring.at(f.at("end").get<std::size_t>()) + shift;
    EXPECT_LT(seg_dist(w, a, b), tol);
  }
}

}  // namespace

TEST(Format, JsonKeysValuesAndInputFeatureIndices) {
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> u(-3, 3), ud(-1, 1);
  int overlapping = 0, edges = 0, vertices = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto rp = random_ring(rng, 3 + rng() % 12, Vec2(0, 0), 2);
    const auto rq = random_ring(rng, 3 + rng() % 12, Vec2(0.5, -0.5), 1);
    const ConvexPolygon P(rp, "P"), Q(rq, "Q");
    const Vec2 t(u(rng), u(rng)), d(ud(rng), ud(rng));
    const Depth2 r = trial % 2 ? pendepth::minimum_depth(P, Q, t) : pendepth::directional_depth(P, Q, t, d);
    std::string s;
    io::append_json(s, r, P, Q);
    const json j = json::parse(s);
    for (const char* key : {"depth", "translation", "normal", "witness_p", "witness_q", "kind", "overlapping",
                            "feature_p", "feature_q"})
      EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j.size(), 9u);
    EXPECT_EQ(j["depth"].get<double>(), r.depth);
    EXPECT_EQ(vec_of(j["translation"]), r.translation);
    EXPECT_EQ(vec_of(j["normal"]), r.normal);
    EXPECT_EQ(vec_of(j["witness_p"]), r.witness_p);
    EXPECT_EQ(vec_of(j["witness_q"]), r.witness_q);
    EXPECT_EQ(j["kind"], trial % 2 ? "minimum" : "directional");
    EXPECT_EQ(j["overlapping"].get<bool>(), r.overlapping);
    if (!r.overlapping) {
      EXPECT_EQ(j["feature_p"], json::parse(R"({"kind":"none","index":null})"));
      continue;
    }
    ++overlapping;
    // witness_p lies on P's feature; witness_q on Q's feature after the move t + translation.
    check_feature(j["feature_p"], rp, Vec2(0, 0), r.witness_p);
    check_feature(j["feature_q"], rq, t + r.translation, r.witness_q);
    for (const char* f : {"feature_p", "feature_q"}) (j[f]["kind"] == "edge" ? edges : vertices)++;
  }
  EXPECT_GT(overlapping, 100);
  EXPECT_GT(edges, 50);
  EXPECT_GT(vertices, 50);
}

TEST(Format, JsonOfNonOverlapAndSeparation) {
  const ConvexPolygon P({{0, 0}, {2, 0}, {2, 2}, {0, 2}}), Q({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  std::string s;
  io::append_json(s, pendepth::minimum_depth(P, Q, Vec2(5, 5)), P, Q);
  EXPECT_EQ(s,
            R"({"depth":0,"translation":[0,0],"normal":[0,0],"witness_p":[0,0],"witness_q":[0,0],)"
            R"("kind":"minimum","overlapping":false,"feature_p":{"kind":"none","index":null},)"
            R"("feature_q":{"kind":"none","index":null}})");
  s.clear();
  io::append_json(s, pendepth::separation_depth(P, Q, Vec2(0.5, 0.5), Vec2(1, 0)), P, Q);
  const json j = json::parse(s);
  EXPECT_EQ(j["kind"], "separation");
  EXPECT_EQ(j["depth"].get<double>(), 1.5);  // analytic: Q's left side must reach x = 2
}

TEST(Format, CsvRowReadsBack) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1e9, 1e9);
  for (int k = 0; k < 1000; ++k) {
    Depth2 r;
    r.depth = std::abs(u(rng)) * 1e-12;
    r.translation = Vec2(u(rng), -u(rng) * 1e-300);
    std::string s;
    io::append_csv_row(s, r);
    ASSERT_EQ(s.back(), '\n');
    double v[3];
    const char* p = s.data();
    for (double& x : v) {
      auto [ptr, ec] = std::from_chars(p, s.data() + s.size(), x);
      ASSERT_EQ(ec, std::errc());
      p = ptr + 1;
    }
    EXPECT_EQ(v[0], r.depth);
    EXPECT_EQ(v[1], r.translation.x());
    EXPECT_EQ(v[2], r.translation.y());
  }
}

TEST(Format, SummaryMentionsDepthAndFeatures) {
  const ConvexPolygon P({{0, 0}, {2, 0}, {2, 2}, {0, 2}}), Q({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const Depth2 r = pendepth::directional_depth(P, Q, Vec2(0.5, 0.25), Vec2(0, -1));
  const std::string s = io::summary(r, P, Q);
  EXPECT_NE(s.find("directional depth"), std::string::npos) << s;
  EXPECT_NE(s.find("depth:       1.25\n"), std::string::npos) << s;  // analytic: top of Q to y = 0
  EXPECT_NE(s.find("translation: (0, -1.25)"), std::string::npos) << s;
  EXPECT_NE(s.find("overlapping: yes"), std::string::npos) << s;
}
