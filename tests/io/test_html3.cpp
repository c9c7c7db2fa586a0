// The 3D HTML page writer (src/io/html3.cpp, issue 21): the scene JSON inside the page is valid,
// finite and normalised at any scale, text cannot end the page's script block, and depth_scene3
// shows what a depth answer needs (features, witnesses, move, M and its facet). The page in a real
// browser: tests/html3/check_pages.py.
#include <pendepth/depth3.hpp>
#include <pendepth/io.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using pendepth::ConvexPolytope;
using pendepth::Depth3;
using pendepth::Pose3;
using pendepth::Vec3;
namespace io = pendepth::io;
using nlohmann::json;

json scene_json(const std::string& page) {
  const std::string open = "<script id=\"pendepth-scene\" type=\"application/json\">";
  const std::size_t a = page.find(open);
  EXPECT_NE(a, std::string::npos);
  const std::size_t b = page.find("</script>", a);
  return json::parse(page.substr(a + open.size(), b - a - open.size()));
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

std::vector<Vec3> cube(double s, const Vec3& at = Vec3::Zero()) {
  std::vector<Vec3> c;
  for (int i = 0; i < 8; ++i) c.push_back(at + s * Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  return c;
}

std::vector<double> view_coordinates(const json& scene) {
  std::vector<double> xs;
  for (const auto& m : scene["meshes"])
    for (double x : m["vertices"]) xs.push_back(x);
  for (const auto& p : scene["points"])
    for (double x : p["at"]) xs.push_back(x);
  for (const auto& a : scene["arrows"]) {
    for (double x : a["from"]) xs.push_back(x);
    for (double x : a["to"]) xs.push_back(x);
  }
  return xs;
}

bool has_layer(const json& scene, const std::string& id) {
  const auto& l = scene["layers"];
  return std::any_of(l.begin(), l.end(), [&](const json& x) { return x["id"] == id; });
}

TEST(Html3, ViewCoordinatesAreFiniteAndNormalisedAtEveryScale) {
  for (const double s : {1e-310, 1e-200, 1.0, 1e200, 1e300, 8e307}) {
    io::Scene3 scene;
    io::Scene3::Mesh m;
    m.vertices = cube(s, Vec3(-s, 0.25 * s, s));
    m.triangles = {{0, 1, 2}, {1, 3, 2}};
    scene.meshes.push_back(m);
    scene.points.push_back({"", "#000000", "p", Vec3(-s, -s, -s)});
    const json j = scene_json(io::html_page(scene));
    const std::vector<double> xs = view_coordinates(j);
    ASSERT_EQ(xs.size(), 27u);
    double largest = 0;
    for (double x : xs) {
      ASSERT_TRUE(std::isfinite(x)) << s;
      largest = std::max(largest, std::abs(x));
    }
    EXPECT_LE(largest, 1.0) << s;
    EXPECT_GE(largest, 0.5) << s;
  }
}

TEST(Html3, NonFiniteCoordinateIsInvalidInput) {
  io::Scene3 scene;
  scene.points.push_back({"", "#000000", "p", Vec3(0, std::nan(""), 0)});
  try {
    io::html_page(scene);
    ADD_FAILURE() << "no error";
  } catch (const pendepth::InvalidInput& e) {  // the coordinate is named (and printing it does not assert)
    EXPECT_NE(std::string(e.what()).find("non-finite coordinate (0, nan, 0)"), std::string::npos) << e.what();
  }
}

TEST(Html3, TextCannotEndTheScriptBlock) {
  const std::string plain = io::html_page(io::Scene3{});
  io::Scene3 scene;
  scene.title = "</script><script>alert(1)</script><!--";
  scene.numbers.push_back({"\"quoted\" \\ </SCRIPT>", "line\nbreak"});
  const std::string page = io::html_page(scene);
  EXPECT_EQ(count(page, "</script"), count(plain, "</script"));
  EXPECT_EQ(count(page, "<!--"), count(plain, "<!--"));
  const json j = scene_json(page);
  EXPECT_EQ(j["title"], scene.title);
  EXPECT_EQ(j["numbers"][0][0], scene.numbers[0][0]);
  EXPECT_EQ(j["numbers"][0][1], scene.numbers[0][1]);
}

TEST(Html3, PageIsSelfContained) {
  const std::string page = io::html_page(io::Scene3{});
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_EQ(page.find("<script src"), std::string::npos);
  EXPECT_EQ(page.find("<link"), std::string::npos);
  EXPECT_NE(page.find("THREE.OrbitControls"), std::string::npos);
  EXPECT_NE(page.find("data-pendepth-status"), std::string::npos);
}

// Unit cubes, Q at (0.75, 0.5, 0.5): σ = 0.25 along +x, P's face x = 1 (two triangles) against
// Q's face x = 0.75 → the features, the move, M and M's facet x = 1 are all in the scene.
TEST(Html3, DepthSceneShowsTheAnswer) {
  const ConvexPolytope P = ConvexPolytope::hull(cube(1)), Q = ConvexPolytope::hull(cube(1));
  const Pose3 pp, pq(Vec3(0.75, 0.5, 0.5));
  const Depth3 r = pendepth::minimum_depth(P, pp, Q, pq);
  ASSERT_TRUE(r.overlapping);
  ASSERT_NEAR(r.depth, 0.25, 1e-15);
  const io::Scene3 s = io::depth_scene3(P, pp, Q, pq, r);
  const json j = scene_json(io::html_page(s));
  for (const char* id : {"P", "Q", "Q_moved", "move", "witness", "M"}) EXPECT_TRUE(has_layer(j, id)) << id;
  EXPECT_FALSE(has_layer(j, "direction"));
  ASSERT_EQ(s.meshes.size(), 4u);  // P, Q, Q moved, M
  const auto& hp = s.meshes[0].highlight;
  EXPECT_EQ(hp.triangles.size() + 2 * hp.edges.size() + 4 * hp.vertices.size() > 0, true);
  if (r.feature_p.kind == pendepth::FeatureKind3::Face) EXPECT_EQ(hp.triangles.size(), 2u);  // the whole square
  ASSERT_EQ(s.arrows.size(), 2u);  // v from the witness, t → t + v in M's layer
  EXPECT_EQ(s.arrows[0].to - s.arrows[0].from, r.translation);
  const auto& M = s.meshes[3];
  EXPECT_EQ(M.vertices.size(), 8u);  // the sum of two unit cubes is the cube [-1, 1]³
  ASSERT_EQ(M.highlight.triangles.size(), 2u);
  for (int t : M.highlight.triangles)
    for (int k : M.triangles[t]) EXPECT_EQ(M.vertices[k].dot(r.facet_normal), 1.0);
  EXPECT_FALSE(j["layers"].back()["visible"].get<bool>());  // M is hidden at first
}

TEST(Html3, DepthSceneNotOverlappingDrawsNoAnswer) {
  const ConvexPolytope P = ConvexPolytope::hull(cube(1)), Q = ConvexPolytope::hull(cube(1));
  for (const Vec3& t : {Vec3(1, 0, 0), Vec3(3, 0.5, 0)}) {  // touching, apart
    const Pose3 pp, pq(t);
    const Depth3 r = pendepth::minimum_depth(P, pp, Q, pq);
    ASSERT_FALSE(r.overlapping);
    const io::Scene3 s = io::depth_scene3(P, pp, Q, pq, r);
    const json j = scene_json(io::html_page(s));
    EXPECT_FALSE(has_layer(j, "Q_moved"));
    EXPECT_FALSE(has_layer(j, "witness"));
    EXPECT_TRUE(s.arrows.empty());
    ASSERT_EQ(s.points.size(), 1u);  // t, in M's layer
    EXPECT_TRUE(s.meshes[0].highlight.triangles.empty());
  }
}

TEST(Html3, MinkowskiSumIsSkippedAboveTheCap) {
  const ConvexPolytope P = ConvexPolytope::hull(cube(1)), Q = ConvexPolytope::hull(cube(1));
  const Pose3 pp, pq(Vec3(0.5, 0.5, 0.5));
  io::Html3Options opt;
  opt.M_max_pairs = 63;
  opt.direction = Vec3(0, 0, 2);
  const Depth3 r = pendepth::directional_depth(P, pp, Q, pq, *opt.direction);
  const io::Scene3 s = io::depth_scene3(P, pp, Q, pq, r, opt);
  const json j = scene_json(io::html_page(s));
  EXPECT_FALSE(has_layer(j, "M"));
  EXPECT_TRUE(has_layer(j, "direction"));
  const auto& notes = s.notes;
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) { return n.rfind("M not drawn", 0) == 0; }));
}

// Q at its pose overflows (vertices ±1.5e308 moved by 1e308): left out with a note, the page
// still holds P and valid JSON.
TEST(Html3, DepthSceneLeavesOutWhatOverflows) {
  std::vector<Vec3> big;
  for (const Vec3& v : cube(2)) big.push_back(1.5e308 * (v - Vec3::Ones()));  // ±1.5e308
  const ConvexPolytope P = ConvexPolytope::hull(big), Q = ConvexPolytope::hull(big);
  const Pose3 pp, pq(Vec3(1e308, 0, 0));
  Depth3 r;  // whatever the engines answer, the picture must be valid: take "not overlapping"
  const io::Scene3 s = io::depth_scene3(P, pp, Q, pq, r);
  const json j = scene_json(io::html_page(s));
  EXPECT_TRUE(has_layer(j, "P"));
  EXPECT_FALSE(has_layer(j, "Q"));
  EXPECT_FALSE(has_layer(j, "M"));
  const auto& notes = s.notes;
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) { return n.find("not finite") != std::string::npos; }));
}

}  // namespace
