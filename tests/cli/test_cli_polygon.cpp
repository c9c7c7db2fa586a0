// End-to-end tests of `pendepth depth/batch` on a polygon with holes against a convex polygon
// (docs/design.md §3, DHS §4, §6): the CLI picks PolygonDepth2 by shape kind; its answers equal the
// library's bit for bit (JSON and CSV, σ, σ_d, separation); analytic values on a U-shaped part
// and a square with a square hole; the role swap (P convex, Q non-convex) against the library run
// on the swapped pair; features with rings and input indices; SVG with holes and ∂O; bad input.
#include <pendepth/depth2.hpp>
#include <pendepth/depth2_polygon_convex.hpp>
#include <pendepth/io.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <random>
#include <sstream>

#include "cli/cli_fixture.hpp"
#include "polygon2/shapes.hpp"

using pendepth::ConvexPolygon;
using pendepth::Depth2;
using pendepth::Polygon;
using pendepth::PolygonDepth2;
using pendepth::Vec2;
namespace io = pendepth::io;
using nlohmann::json;

using cli_test::quote;
using cli_test::rings_of;
using cli_test::Rings;
using cli_test::Result;
using cli_test::slurp;
using cli_test::wkt_of;

namespace {

std::string num(double x) {
  std::string s;
  io::append_double(s, x);
  return s;
}
std::string pair_arg(const Vec2& v) { return num(v.x()) + "," + num(v.y()); }

Vec2 vec_of(const json& j) { return Vec2(j.at(0).get<double>(), j.at(1).get<double>()); }

void expect_same(const json& j, const Depth2& r, const std::string& what) {
  EXPECT_EQ(j.at("depth").get<double>(), r.depth) << what;
  EXPECT_EQ(vec_of(j.at("translation")), r.translation) << what;
  EXPECT_EQ(vec_of(j.at("normal")), r.normal) << what;
  EXPECT_EQ(vec_of(j.at("witness_p")), r.witness_p) << what;
  EXPECT_EQ(vec_of(j.at("witness_q")), r.witness_q) << what;
  EXPECT_EQ(j.at("overlapping").get<bool>(), r.overlapping) << what;
}

// The JSON form of a feature of the polygon: ring and input indices (Polygon numbering).
json polygon_feature(const pendepth::Feature& f, const Polygon& P) {
  if (f.kind == pendepth::FeatureKind::None) return json{{"kind", "none"}, {"index", nullptr}};
  const std::size_t g = std::size_t(f.index);
  json j{{"kind", f.kind == pendepth::FeatureKind::Vertex ? "vertex" : "edge"},
         {"ring", P.ring_of(g)},
         {"index", P.input_index(g)}};
  if (f.kind == pendepth::FeatureKind::Edge) j["end"] = P.input_index(P.next(g));
  return j;
}

json convex_feature(const pendepth::Feature& f, const ConvexPolygon& Q) {
  if (f.kind == pendepth::FeatureKind::None) return json{{"kind", "none"}, {"index", nullptr}};
  const std::size_t i = std::size_t(f.index) % Q.size();
  json j{{"kind", f.kind == pendepth::FeatureKind::Vertex ? "vertex" : "edge"}, {"index", Q.input_index(i)}};
  if (f.kind == pendepth::FeatureKind::Edge) j["end"] = Q.input_index((i + 1) % Q.size());
  return j;
}

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> v;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

// U-shaped part: base [0,3]×[0,1], arms [0,1]×[1,3] and [2,3]×[1,3]; the pocket [1,2]×[1,3] fits
// the unit square exactly.
const Rings kU{{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}};
// A 10×10 square with the square hole [4,6]².
const Rings kHoled{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{4, 4}, {4, 6}, {6, 6}, {6, 4}}};
const Rings kUnit{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};

class CliPolygon : public cli_test::CliFixture {
 protected:
  json depth_json(const std::string& p, const std::string& q, const Vec2& t, const std::string& extra) {
    const Result r = run("depth " + quote(p) + " " + quote(q) + " --offset=" + pair_arg(t) + " " + extra + " --json");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(lines_of(r.out).size(), 1u) << r.out;
    return r.status == 0 ? json::parse(r.out) : json();
  }
};

}  // namespace

TEST_F(CliPolygon, AnalyticPocketAndSeparation) {
  const std::string U = write("U.wkt", wkt_of(kU)), S = write("S.wkt", wkt_of(kUnit));
  // Q + t = [1.25,2.25]×[1.5,2.5] overlaps the right arm by 0.25: σ and σ_{−x} move it into the
  // pocket (touching both arms: depth 0.25); complete separation leftwards must clear the left
  // arm too: the right side of Q at x = 0, a move of 2.25.
  const Vec2 t(1.25, 1.5);
  json j = depth_json(U, S, t, "");
  EXPECT_EQ(j["kind"], "minimum");
  EXPECT_TRUE(j["overlapping"].get<bool>());
  EXPECT_EQ(j["depth"].get<double>(), 0.25);
  EXPECT_EQ(vec_of(j["translation"]), Vec2(-0.25, 0));
  EXPECT_EQ(j["feature_p"]["ring"], 0);

  j = depth_json(U, S, t, "--direction=-1,0");
  EXPECT_EQ(j["kind"], "directional");
  EXPECT_EQ(j["depth"].get<double>(), 0.25);
  EXPECT_EQ(vec_of(j["normal"]), Vec2(-1, 0));

  j = depth_json(U, S, t, "--direction=-7,0 --separate");
  EXPECT_EQ(j["kind"], "separation");
  EXPECT_EQ(j["depth"].get<double>(), 2.25);
  EXPECT_EQ(vec_of(j["translation"]), Vec2(-2.25, 0));
  // The final contact: Q's right edge (x = 0 after the move) on the left arm's outer edge, the
  // outer ring's edge from input vertex 7 (0,3) to vertex 0 (0,0), or one of its endpoints.
  EXPECT_EQ(j["feature_p"]["ring"], 0);
  EXPECT_EQ(vec_of(j["witness_p"]).x(), 0.0);

  // Sliding up the pocket Q fits exactly is touching all the way: σ_d up from inside is 0.5
  // (from y = 0.5 out of the base into the pocket), and so is the complete separation.
  j = depth_json(U, S, Vec2(1, 0.5), "--direction 0,1");
  EXPECT_EQ(j["depth"].get<double>(), 0.5);
  j = depth_json(U, S, Vec2(1, 0.5), "--direction 0,1 --separate");
  EXPECT_EQ(j["depth"].get<double>(), 0.5);
  // Rightwards from the same placement Q overlaps the base until it leaves it at x = 3.
  j = depth_json(U, S, Vec2(1, 0.5), "--direction 1,0");
  EXPECT_EQ(j["depth"].get<double>(), 2.0);

  // Touching the pocket's walls exactly, and far away: not overlapping, depth 0.
  for (const Vec2& u : {Vec2(1, 1), Vec2(1, 2), Vec2(-5, 0)}) {
    j = depth_json(U, S, u, "");
    EXPECT_FALSE(j["overlapping"].get<bool>());
    EXPECT_EQ(j["depth"].get<double>(), 0.0);
    EXPECT_EQ(j["feature_p"]["kind"], "none");
  }

  // Human summary names the ring.
  const Result r = run("depth " + quote(U) + " " + quote(S) + " --offset 1.25,1.5");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("minimum depth"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("depth:       0.25\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("of the outer ring of P"), std::string::npos) << r.out;
}

TEST_F(CliPolygon, AnalyticHole) {
  const std::string H = write("H.wkt", wkt_of(kHoled)), S = write("S.wkt", wkt_of(kUnit));
  // Q + t = [3.5,4.5]×[4.5,5.5]: 0.5 to the right it lies inside the hole; upwards it stays on
  // the strip left of the hole until it leaves P at y = 10.
  const Vec2 t(3.5, 4.5);
  json j = depth_json(H, S, t, "");
  EXPECT_EQ(j["depth"].get<double>(), 0.5);
  EXPECT_EQ(vec_of(j["translation"]), Vec2(0.5, 0));
  // The contact is Q's left edge on the hole's edge x = 4 strictly between its vertices.
  EXPECT_EQ(j["feature_p"]["kind"], "edge");
  EXPECT_EQ(j["feature_p"]["ring"], 1);
  EXPECT_EQ(j["feature_p"]["index"], 0);  // hole as given: (4,4) → (4,6) is edge 0
  EXPECT_EQ(j["feature_p"]["end"], 1);
  j = depth_json(H, S, t, "--direction 0,1");
  EXPECT_EQ(j["depth"].get<double>(), 5.5);
  j = depth_json(H, S, t, "--direction 1,0 --separate");  // through the hole and out: x ≥ 10
  EXPECT_EQ(j["depth"].get<double>(), 6.5);
  // Inside the hole, not touching: no overlap.
  j = depth_json(H, S, Vec2(4.5, 4.5), "");
  EXPECT_FALSE(j["overlapping"].get<bool>());
}

TEST_F(CliPolygon, DepthMatchesLibraryBitForBit) {
  std::mt19937_64 rng(0x5eed4c11);
  const Polygon P = polygon2_test::random_polygon(rng, 40, 3, false);
  const ConvexPolygon Q = ConvexPolygon::hull(polygon2_test::star_ring(rng, 9, Vec2(3, -2), 10, 20, false));
  const std::string fp = write("P.wkt", wkt_of(rings_of(P))), fq = write("Q.wkt", io::to_wkt(Q) + "\n");
  const Polygon PP = io::read_polygon(fp, "P");
  const ConvexPolygon QQ = io::read_convex_polygon(fq, "Q");
  const PolygonDepth2 lib(PP, QQ);
  std::uniform_real_distribution<double> u(-110, 110), ua(0, 2 * polygon2_test::kPi);
  int overlapping = 0;
  for (int k = 0; k < 8; ++k) {
    const Vec2 t(u(rng), u(rng));
    const double a = ua(rng);
    const Vec2 d(std::cos(a), std::sin(a));
    const std::string what = "t = " + pair_arg(t) + ", d = " + pair_arg(d);
    json j = depth_json(fp, fq, t, "");
    Depth2 want = lib.minimum(t);
    expect_same(j, want, what);
    EXPECT_EQ(j["feature_p"], polygon_feature(want.feature_p, PP)) << what;
    EXPECT_EQ(j["feature_q"], convex_feature(want.feature_q, QQ)) << what;
    overlapping += want.overlapping;

    j = depth_json(fp, fq, t, "--direction=" + pair_arg(d));
    want = lib.along(t, d);
    expect_same(j, want, what);
    EXPECT_EQ(j["feature_p"], polygon_feature(want.feature_p, PP)) << what;
    EXPECT_EQ(j["kind"], "directional");

    j = depth_json(fp, fq, t, "--direction=" + pair_arg(d) + " --separate");
    want = lib.separation(t, d);
    expect_same(j, want, what);
    EXPECT_EQ(j["feature_q"], convex_feature(want.feature_q, QQ)) << what;
    EXPECT_EQ(j["kind"], "separation");
  }
  EXPECT_GE(overlapping, 2);  // the placements exercise real answers
}

TEST_F(CliPolygon, BatchMatchesLibraryBitForBit) {
  std::mt19937_64 rng(0xba7c4);
  const Polygon P = polygon2_test::random_polygon(rng, 60, 2, true);
  const ConvexPolygon Q = ConvexPolygon::hull(polygon2_test::star_ring(rng, 7, Vec2(0, 0), 8, 15, false));
  const std::string fp = write("P.wkt", wkt_of(rings_of(P))), fq = write("Q.wkt", io::to_wkt(Q) + "\n");
  const Polygon PP = io::read_polygon(fp, "P");
  const ConvexPolygon QQ = io::read_convex_polygon(fq, "Q");
  const PolygonDepth2 lib(PP, QQ);
  std::uniform_real_distribution<double> u(-110, 110);
  std::vector<std::pair<Vec2, Vec2>> qs;
  std::string csv = "x,y,dx,dy\n";
  for (int k = 0; k < 300; ++k) {
    const Vec2 t(u(rng), u(rng));
    const Vec2 d = k % 3 == 0 ? Vec2(0, 0) : Vec2(u(rng), u(rng));
    qs.emplace_back(t, d);
    csv += pair_arg(t) + "," + pair_arg(d) + "\n";
  }
  const std::string fcsv = write("q.csv", csv);
  const Result r = run("batch " + quote(fp) + " " + quote(fq) + " --queries " + quote(fcsv));
  ASSERT_EQ(r.status, 0) << r.err;
  const Result rj = run("batch " + quote(fp) + " " + quote(fq) + " --queries " + quote(fcsv) + " --json");
  ASSERT_EQ(rj.status, 0) << rj.err;
  const auto rows = lines_of(r.out), objs = lines_of(rj.out);
  ASSERT_EQ(rows.size(), qs.size() + 1);
  ASSERT_EQ(objs.size(), qs.size());
  EXPECT_EQ(rows[0], "depth,tx,ty");
  int positive = 0;
  for (std::size_t k = 0; k < qs.size(); ++k) {
    const auto& [t, d] = qs[k];
    const Depth2 want = d.isZero(0) ? lib.minimum(t) : lib.along(t, d);
    std::string row;
    io::append_csv_row(row, want);
    row.pop_back();
    EXPECT_EQ(rows[k + 1], row) << k;
    const json j = json::parse(objs[k]);
    expect_same(j, want, std::to_string(k));
    EXPECT_EQ(j["kind"], d.isZero(0) ? "minimum" : "directional");
    positive += want.depth > 0;
  }
  EXPECT_GE(positive, 20);
}

// P convex and Q non-convex: the CLI runs PolygonDepth2 on (Q, P) at −t along −d. Checked against
// the library on the unswapped pair (translation negated, features swapped, witnesses mapped into
// the other frame) and against the analytic U case.
TEST_F(CliPolygon, SwappedRolesAreSymmetric) {
  const std::string U = write("U.wkt", wkt_of(kU)), S = write("S.wkt", wkt_of(kUnit));
  json j = depth_json(S, U, Vec2(-1.25, -1.5), "");  // the pocket case seen from the square
  EXPECT_EQ(j["depth"].get<double>(), 0.25);
  EXPECT_EQ(vec_of(j["translation"]), Vec2(0.25, 0));
  EXPECT_EQ(j["feature_q"]["ring"], 0);   // the polygon is Q now
  EXPECT_FALSE(j["feature_p"].contains("ring"));
  j = depth_json(S, U, Vec2(-1.25, -1.5), "--direction 1,0 --separate");
  EXPECT_EQ(j["depth"].get<double>(), 2.25);
  EXPECT_EQ(vec_of(j["translation"]), Vec2(2.25, 0));
  // After the move U sits at (−1.25 + 2.25, −1.5) = (1, −1.5): its left arm's outer edge x = 1
  // touches the square's right edge x = 1.
  EXPECT_EQ(vec_of(j["witness_p"]).x(), 1.0);
  EXPECT_EQ(vec_of(j["witness_q"]).x(), 1.0);

  std::mt19937_64 rng(0x5a9);
  const Polygon P = polygon2_test::random_polygon(rng, 30, 1, false);
  const ConvexPolygon Q = ConvexPolygon::hull(polygon2_test::star_ring(rng, 6, Vec2(0, 0), 12, 20, false));
  const std::string fp = write("P.wkt", wkt_of(rings_of(P))), fq = write("Q.wkt", io::to_wkt(Q) + "\n");
  const Polygon PP = io::read_polygon(fp, "P");
  const ConvexPolygon QQ = io::read_convex_polygon(fq, "Q");
  const PolygonDepth2 lib(PP, QQ);
  std::uniform_real_distribution<double> u(-100, 100), ua(0, 2 * polygon2_test::kPi);
  int overlapping = 0;
  for (int k = 0; k < 6; ++k) {
    const Vec2 t(u(rng), u(rng));
    const double a = ua(rng);
    const Vec2 d(std::cos(a), std::sin(a));
    const std::string what = "t = " + pair_arg(t) + ", d = " + pair_arg(d);
    for (int kind = 0; kind < 3; ++kind) {
      // Q fixed, P placed at −t, moving along −d.
      const std::string extra = kind == 0 ? "" : "--direction=" + pair_arg(-d) + (kind == 2 ? " --separate" : "");
      const json s = depth_json(fq, fp, -t, extra);
      const Depth2 want = kind == 0 ? lib.minimum(t) : kind == 1 ? lib.along(t, d) : lib.separation(t, d);
      overlapping += want.overlapping;
      EXPECT_EQ(s["depth"].get<double>(), want.depth) << what;
      EXPECT_EQ(vec_of(s["translation"]), Vec2(0, 0) - want.translation) << what;
      EXPECT_EQ(vec_of(s["normal"]), Vec2(0, 0) - want.normal) << what;
      EXPECT_EQ(s["overlapping"].get<bool>(), want.overlapping) << what;
      EXPECT_EQ(s["feature_p"], convex_feature(want.feature_q, QQ)) << what;
      EXPECT_EQ(s["feature_q"], polygon_feature(want.feature_p, PP)) << what;
      if (want.overlapping || want.depth > 0) {
        // Frames: (P at 0, Q at t + v) ↦ (Q at 0, P at −t − v) is x ↦ x − t − v.
        const Vec2 shift = t + want.translation;
        EXPECT_LT((vec_of(s["witness_p"]) - (want.witness_q - shift)).norm(), 1e-12 * (1 + shift.norm())) << what;
        EXPECT_LT((vec_of(s["witness_q"]) - (want.witness_p - shift)).norm(), 1e-12 * (1 + shift.norm())) << what;
      }
    }
  }
  EXPECT_GE(overlapping, 2);

  // Batch, swapped: CSV rows equal to the library's with the translation negated.
  std::string csv;
  std::vector<std::pair<Vec2, Vec2>> qs;
  for (int k = 0; k < 100; ++k) {
    const Vec2 t(u(rng), u(rng)), d = k % 2 ? Vec2(u(rng), u(rng)) : Vec2(0, 0);
    qs.emplace_back(t, d);
    csv += pair_arg(-t) + "," + pair_arg(-d) + "\n";
  }
  const Result r = run("batch " + quote(fq) + " " + quote(fp) + " --queries " + quote(write("q.csv", csv)));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = lines_of(r.out);
  ASSERT_EQ(rows.size(), qs.size() + 1);
  for (std::size_t k = 0; k < qs.size(); ++k) {
    Depth2 want = qs[k].second.isZero(0) ? lib.minimum(qs[k].first) : lib.along(qs[k].first, qs[k].second);
    want.translation = Vec2(0, 0) - want.translation;
    std::string row;
    io::append_csv_row(row, want);
    row.pop_back();
    EXPECT_EQ(rows[k + 1], row) << k;
  }
}

TEST_F(CliPolygon, SvgDrawsHolesAndUnionBoundary) {
  const std::string H = write("H.wkt", wkt_of(kHoled)), S = write("S.wkt", wkt_of(kUnit));
  const std::string svg = (dir_ / "pic.svg").string();
  const Result r = run("depth " + quote(H) + " " + quote(S) + " --offset 3.5,4.5 --direction 1,0 --svg " + quote(svg));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string s = slurp(svg);
  EXPECT_EQ(s.rfind("<svg ", 0), 0u);
  EXPECT_EQ(s.substr(s.size() - 7), "</svg>\n");
  // P with its hole is one even-odd path of 2 rings; ∂O (outer boundary and the hole of O, which
  // is the hole shrunk by Q) another path of 2 rings.
  std::size_t paths = 0, subpaths = 0;
  for (std::size_t at = s.find("<path fill-rule=\"evenodd\""); at != std::string::npos;
       at = s.find("<path fill-rule=\"evenodd\"", at + 1)) {
    ++paths;
    const std::size_t end = s.find("/>", at);
    for (std::size_t z = s.find(" Z", at); z < end; z = s.find(" Z", z + 1)) ++subpaths;
  }
  const PolygonDepth2 lib(Polygon(kHoled, "P"), ConvexPolygon(kUnit[0]));
  EXPECT_EQ(lib.boundary_rings().size(), 2u);
  EXPECT_EQ(paths, 2u);
  EXPECT_EQ(subpaths, 4u);
  EXPECT_NE(s.find("∂O"), std::string::npos);
  EXPECT_NE(s.find("directional depth σ_d = 0.5"), std::string::npos);
}

TEST_F(CliPolygon, BadInput) {
  const std::string S = write("S.wkt", wkt_of(kUnit)), U = write("U.wkt", wkt_of(kU));
  // (Two non-convex polygons are supported: tests/cli/test_cli_nonconvex.cpp.)
  const std::string csv = write("q.csv", "0,0,0,0\n");

  // Validation errors carry the line of the ring/vertex the message names.
  const std::string outside = write("out.wkt", "POLYGON ((0 0, 10 0, 10 10, 0 10),\n(2 2, 4 2, 4 4, 2 4),\n(20 20, 21 20, 21 21))\n");
  expect_error("depth " + quote(outside) + " " + quote(S), outside + ":3: P: ring 2 (hole 2) lies outside the outer ring");
  // The message is the library's (Polygon validation); the line is the one of the vertex or edge
  // it names first in the ring it names.
  auto polygon_message = [](const Rings& rings, const char* name) {
    try {
      Polygon(rings, name);
    } catch (const pendepth::InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("valid");
  };
  const Rings cross_rings{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{2, 2}, {4, 2}, {4, 4}, {2, 4}}, {{3, 3}, {6, 3}, {6, 6}, {3, 6}}};
  const std::string crossing = write("cross.wkt", "POLYGON ((0 0, 10 0, 10 10, 0 10),\n(2 2, 4 2, 4 4, 2 4),\n(3 3, 6 3, 6 6, 3 6))\n");
  std::string msg = polygon_message(cross_rings, "Q");
  ASSERT_EQ(msg.rfind("Q: ring 1 (hole 1) and ring 2 (hole 2) touch or cross (edge ", 0), 0u) << msg;
  expect_error("batch " + quote(S) + " " + quote(crossing) + " --queries " + quote(csv), crossing + ":2: " + msg);
  const std::string self = write("self.wkt", "POLYGON (\n(0 0,\n4 0,\n4 4,\n2 -1,\n0 4))\n");
  msg = polygon_message(Rings{{{0, 0}, {4, 0}, {4, 4}, {2, -1}, {0, 4}}}, "P");
  ASSERT_EQ(msg.rfind("P: ring 0 (outer): self-intersecting (edges 0 and ", 0), 0u) << msg;
  expect_error("depth " + quote(self) + " " + quote(S), self + ":2: " + msg);
  const std::string repeated = write("rep.wkt", "POLYGON ((0 0,\n4 0, 4 4, 2 1,\n4 0, 0 4))\n");
  msg = polygon_message(Rings{{{0, 0}, {4, 0}, {4, 4}, {2, 1}, {4, 0}, {0, 4}}}, "P");
  ASSERT_EQ(msg, "P: ring 0 (outer): vertices 1 and 4 coincide at (4, 0)");
  expect_error("depth " + quote(repeated) + " " + quote(S), repeated + ":2: " + msg);

  // Query errors name the query file's line; the direction option is checked as for convex pairs.
  const std::string badq = write("bad.csv", "1,1,0,0\n1,1,nan,0\n");
  expect_error("batch " + quote(U) + " " + quote(S) + " --queries " + quote(badq), badq + ":2: field 3 is not a finite number: 'nan'");
  expect_error("depth " + quote(U) + " " + quote(S) + " --direction 0,0", "--direction: the direction is zero");
}
