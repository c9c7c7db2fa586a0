// End-to-end tests of the CLI on two non-convex polygons (issue 5 item 5, docs/design.md §3):
//   - `depth` (σ, σ_d, complete separation; JSON with ring-aware features) equals PairDepth2 run
//     in-process on the same files, bit for bit (same algorithm, same inputs);
//   - `batch` (answered on NoFitPolygon2) equals NoFitPolygon2 in-process bit for bit and
//     PairDepth2 to a few ulps of the shapes' scale, for σ and σ_d, CSV and JSON Lines;
//   - `nfp` prints WKT that parses back (io::parse_wkt_geometry) to exactly NoFitPolygon2's rings,
//     slits and points; --json likewise; the printed polygons agree with PairDepth2's overlap test
//     at random placements away from the boundary (even-odd point in polygon on the parsed rings);
//   - degenerate fits, analytic: a U-shaped slot exactly Q's width gives the slit x = 1,
//     y ∈ [1, 3]; a square hole exactly Q's size gives the isolated point (1, 1); depth 0 on
//     them, σ = 0.25 and σ_d = 1 next to them;
//   - `--svg` draws the no-fit polygon (panel, rings, slit, point);
//   - bad input: exit 2, one line naming file and line (polygon validation, queries, formats).
// Inputs: random star polygons with and without holes (pinned seed), nesting pieces from
// ../shared/data/nesting, and the analytic shapes above.
#include <pendepth/depth2.hpp>
#include <pendepth/depth2_polygon_polygon.hpp>
#include <pendepth/io.hpp>
#include <pendepth/nfp2.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>

#include "cli/cli_fixture.hpp"
#include "polygon2/shapes.hpp"
#include "test_scale.hpp"

using pendepth::Depth2;
using pendepth::NoFitPolygon2;
using pendepth::PairDepth2;
using pendepth::Polygon;
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

Rings scaled(const Rings& rings, double s, const Vec2& shift = Vec2(0, 0)) {
  Rings out = rings;
  for (auto& r : out)
    for (Vec2& p : r) p = s * p + shift;
  return out;
}

std::string num(double x) {
  std::string s;
  io::append_double(s, x);
  return s;
}
std::string pair_arg(const Vec2& v) { return num(v.x()) + "," + num(v.y()); }

Vec2 vec_of(const json& j) { return Vec2(j.at(0).get<double>(), j.at(1).get<double>()); }

json polygon_feature(const pendepth::Feature& f, const Polygon& P) {
  if (f.kind == pendepth::FeatureKind::None) return json{{"kind", "none"}, {"index", nullptr}};
  const std::size_t g = std::size_t(f.index);
  json j{{"kind", f.kind == pendepth::FeatureKind::Vertex ? "vertex" : "edge"},
         {"ring", P.ring_of(g)},
         {"index", P.input_index(g)}};
  if (f.kind == pendepth::FeatureKind::Edge) j["end"] = P.input_index(P.next(g));
  return j;
}

const char* kind_name(pendepth::DepthKind k) {
  return k == pendepth::DepthKind::Minimum ? "minimum" : k == pendepth::DepthKind::Directional ? "directional" : "separation";
}

// Every field of the JSON object equals the library's result exactly.
void expect_same(const json& j, const Depth2& r, const Polygon& P, const Polygon& Q, const std::string& what) {
  EXPECT_EQ(j.at("depth").get<double>(), r.depth) << what;
  EXPECT_EQ(vec_of(j.at("translation")), r.translation) << what;
  EXPECT_EQ(vec_of(j.at("normal")), r.normal) << what;
  EXPECT_EQ(vec_of(j.at("witness_p")), r.witness_p) << what;
  EXPECT_EQ(vec_of(j.at("witness_q")), r.witness_q) << what;
  EXPECT_EQ(j.at("overlapping").get<bool>(), r.overlapping) << what;
  EXPECT_EQ(j.at("kind").get<std::string>(), kind_name(r.kind)) << what;
  EXPECT_EQ(j.at("feature_p"), polygon_feature(r.feature_p, P)) << what;
  EXPECT_EQ(j.at("feature_q"), polygon_feature(r.feature_q, Q)) << what;
}

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> v;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

double extent(const Polygon& P) {
  double e = 0;
  for (const Vec2& p : P.vertices()) e = std::max({e, std::abs(p.x()), std::abs(p.y())});
  return e;
}

// "A few ulps" of a depth: the values of ∂O are exact points rounded once, so two exact methods
// differ by a small multiple of the unit roundoff at the coordinates' scale.
double tolerance(const Polygon& P, const Polygon& Q, const Vec2& t) {
  return 16 * std::numeric_limits<double>::epsilon() * (extent(P) + extent(Q) + t.norm());
}

// Even-odd point in polygon over all rings of all polygons (double arithmetic; callers keep the
// point far from the boundary).
bool inside_rings(const std::vector<Rings>& polygons, const Vec2& p) {
  bool in = false;
  for (const auto& poly : polygons)
    for (const auto& r : poly)
      for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
        if ((r[i].y() > p.y()) != (r[j].y() > p.y()) &&
            p.x() < r[j].x() + (p.y() - r[j].y()) * (r[i].x() - r[j].x()) / (r[i].y() - r[j].y()))
          in = !in;
  return in;
}

double distance_to_segments(const std::vector<Rings>& polygons, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& poly : polygons)
    for (const auto& r : poly)
      for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
        const Vec2 e = r[i] - r[j];
        const double s = std::clamp((p - r[j]).dot(e) / e.squaredNorm(), 0.0, 1.0);
        best = std::min(best, (p - r[j] - s * e).norm());
      }
  return best;
}

// U-shaped part: base [0,3]×[0,1], arms [0,1]×[1,3] and [2,3]×[1,3]; the slot [1,2]×[1,3] is
// exactly as wide as the unit square.
const Rings kU{{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}};
// [0,3]² with the hole [1,2]²: the unit square fits the hole exactly.
const Rings kFrame{{{0, 0}, {3, 0}, {3, 3}, {0, 3}}, {{1, 1}, {1, 2}, {2, 2}, {2, 1}}};
const Rings kUnit{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};

// A random pair: P a star polygon of radius ~100 (with `holes` holes), Q a star polygon of radius
// ~30 with up to one hole, both possibly on the integer grid (collinear and touching contacts).
std::pair<Rings, Rings> random_pair(std::mt19937_64& rng, int n, int m, int holes, bool grid) {
  const Rings P = rings_of(polygon2_test::random_polygon(rng, n, holes, grid));
  Rings Q = rings_of(polygon2_test::random_polygon(rng, m, int(rng() % 2), grid));
  Q = scaled(Q, grid ? 1.0 : 0.3);
  if (grid) {  // keep the grid: shrink by an integer factor instead, then re-validate
    for (;;) {
      Rings q = rings_of(polygon2_test::random_polygon(rng, m, 0, true));
      for (auto& r : q)
        for (Vec2& p : r) p = Vec2(std::round(p.x() / 3), std::round(p.y() / 3));
      try {
        Polygon(q, "Q");
        return {P, q};
      } catch (const pendepth::InvalidInput&) {
      }
    }
  }
  return {P, Q};
}

class CliNonconvex : public cli_test::CliFixture {
 protected:
  json depth_json(const std::string& p, const std::string& q, const Vec2& t, const std::string& extra) {
    const Result r = run("depth " + quote(p) + " " + quote(q) + " --offset=" + pair_arg(t) + " " + extra + " --json");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(lines_of(r.out).size(), 1u) << r.out;
    return r.status == 0 ? json::parse(r.out) : json();
  }
  std::string nfp_text(const std::string& p, const std::string& q, const std::string& extra = "") {
    const Result r = run("nfp " + quote(p) + " " + quote(q) + " " + extra);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(lines_of(r.out).size(), 1u);
    return r.out;
  }
};

// True when the CLI reads these rings as a convex polygon (one ring that ConvexPolygon accepts).
bool convex(const Rings& rings) {
  if (rings.size() != 1) return false;
  try {
    pendepth::ConvexPolygon(rings[0], "X");
    return true;
  } catch (const pendepth::InvalidInput&) {
    return false;
  }
}

// The pairs of the depth / batch / nfp comparisons, both shapes non-convex (or with holes), so
// the CLI takes the two-polygon path: random ones, and nesting pieces (the first two non-convex
// pieces of albano and of shirts, in both orders).
std::vector<std::pair<Rings, Rings>> test_pairs(int random_count) {
  std::mt19937_64 rng(20261121);
  std::vector<std::pair<Rings, Rings>> pairs;
  for (int k = 0; k < random_count;) {
    auto pq = random_pair(rng, 8 + int(rng() % 25), 5 + int(rng() % 12), k % 3 == 2 ? 2 : k % 3, k % 2 == 1);
    if (convex(pq.first) || convex(pq.second)) continue;
    pairs.push_back(std::move(pq));
    ++k;
  }
  for (const char* file : {"albano.json", "shirts.json"}) {
    std::vector<Rings> nonconvex;
    for (const auto& piece : polygon2_test::nesting_pieces(file))
      if (!convex(Rings{piece}) && nonconvex.size() < 2) nonconvex.push_back(Rings{piece});
    EXPECT_EQ(nonconvex.size(), 2u) << file;
    if (nonconvex.size() == 2) {
      pairs.push_back({nonconvex[0], nonconvex[1]});
      pairs.push_back({nonconvex[1], nonconvex[0]});
    }
  }
  return pairs;
}

// Placements around P's box (most overlap).
std::vector<Vec2> placements(std::mt19937_64& rng, const Polygon& P, int count) {
  Vec2 lo = P.vertices()[0], hi = lo;
  for (const Vec2& p : P.vertices()) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y());
  std::vector<Vec2> t;
  for (int i = 0; i < count; ++i) t.emplace_back(ux(rng), uy(rng));
  return t;
}

Vec2 random_direction(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> ua(0, 2 * polygon2_test::kPi);
  const double a = ua(rng);
  return Vec2(std::cos(a), std::sin(a));
}

}  // namespace

TEST_F(CliNonconvex, DepthMatchesPairDepth2) {
  std::mt19937_64 rng(7);
  int checked = 0, overlapping = 0;
  for (const auto& [rp, rq] : test_pairs(pendepth_test::scaled(8))) {
    const Polygon P(rp, "P"), Q(rq, "Q");
    const std::string fp = write("P.wkt", wkt_of(rp)), fq = write("Q.wkt", wkt_of(rq));
    const PairDepth2 lib(P, Q);
    for (const Vec2& t : placements(rng, P, 3)) {
      const Vec2 d = random_direction(rng);
      const std::string what = fp + " t=" + pair_arg(t) + " d=" + pair_arg(d);
      const Depth2 m = lib.minimum(t);
      expect_same(depth_json(fp, fq, t, ""), m, P, Q, what + " σ");
      expect_same(depth_json(fp, fq, t, "--direction=" + pair_arg(d)), lib.along(t, d), P, Q, what + " σ_d");
      expect_same(depth_json(fp, fq, t, "--direction=" + pair_arg(d) + " --separate"), lib.separation(t, d), P, Q,
                  what + " separation");
      ++checked;
      overlapping += m.overlapping;
    }
  }
  EXPECT_GE(overlapping, checked / 3) << "most placements should overlap";
  // The human summary names the ring of each feature.
  const std::string fu = write("U.wkt", wkt_of(kU)), ff = write("F.wkt", wkt_of(kFrame));
  const Result r = run("depth " + quote(ff) + " " + quote(fu) + " --offset=1.5,1.5");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("minimum depth"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("of the outer ring of Q"), std::string::npos) << r.out;
}

TEST_F(CliNonconvex, BatchMatchesNfpAndPairDepth2) {
  std::mt19937_64 rng(11);
  int queries = 0;
  for (const auto& [rp, rq] : test_pairs(pendepth_test::scaled(12))) {
    const Polygon P(rp, "P"), Q(rq, "Q");
    const std::string fp = write("P.wkt", wkt_of(rp)), fq = write("Q.wkt", wkt_of(rq));
    const PairDepth2 pair(P, Q);
    const NoFitPolygon2 nfp(P, Q);
    std::vector<Vec2> ts = placements(rng, P, 40), ds;
    std::string csv = "x,y,dx,dy\n";
    for (std::size_t i = 0; i < ts.size(); ++i) {
      ds.push_back(i % 3 == 0 ? Vec2(0, 0) : random_direction(rng) * (i % 3 == 1 ? 1.0 : 1e-3));
      csv += pair_arg(ts[i]) + "," + pair_arg(ds[i]) + "\n";
    }
    const std::string fc = write("q.csv", csv);
    const Result rc = run("batch " + quote(fp) + " " + quote(fq) + " --queries " + quote(fc));
    const Result rj = run("batch " + quote(fp) + " " + quote(fq) + " --queries " + quote(fc) + " --json");
    ASSERT_EQ(rc.status, 0) << rc.err;
    ASSERT_EQ(rj.status, 0) << rj.err;
    const auto rows = lines_of(rc.out), objs = lines_of(rj.out);
    ASSERT_EQ(rows.size(), ts.size() + 1);
    ASSERT_EQ(objs.size(), ts.size());
    EXPECT_EQ(rows[0], "depth,tx,ty");
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const bool zero = ds[i].x() == 0 && ds[i].y() == 0;
      const Depth2 want = zero ? nfp.minimum(ts[i]) : nfp.along(ts[i], ds[i]);
      const Depth2 ref = zero ? pair.minimum(ts[i]) : pair.along(ts[i], ds[i]);
      const std::string what = fp + " query " + std::to_string(i);
      std::string row;
      io::append_csv_row(row, want);
      EXPECT_EQ(rows[i + 1] + "\n", row) << what;
      expect_same(json::parse(objs[i]), want, P, Q, what);
      const double tol = tolerance(P, Q, ts[i]);
      EXPECT_EQ(want.overlapping, ref.overlapping) << what;
      EXPECT_NEAR(want.depth, ref.depth, tol) << what;
      EXPECT_NEAR(want.translation.x(), ref.translation.x(), tol) << what;
      EXPECT_NEAR(want.translation.y(), ref.translation.y(), tol) << what;
      ++queries;
    }
  }
  EXPECT_GT(queries, 0);
}

TEST_F(CliNonconvex, NfpRoundTripsAndMatchesOverlap) {
  std::mt19937_64 rng(13);
  int inside_checked = 0, outside_checked = 0;
  for (const auto& [rp, rq] : test_pairs(pendepth_test::scaled(12))) {
    const Polygon P(rp, "P"), Q(rq, "Q");
    const std::string fp = write("P.wkt", wkt_of(rp)), fq = write("Q.wkt", wkt_of(rq));
    const NoFitPolygon2 nfp(P, Q);
    const std::string text = nfp_text(fp, fq);
    const io::Geometry2 g = io::parse_wkt_geometry(text, "nfp output");
    EXPECT_EQ(g.polygons, nfp.polygons()) << fp;
    ASSERT_EQ(g.lines.size(), nfp.slits().size()) << fp;
    for (std::size_t k = 0; k < g.lines.size(); ++k)
      EXPECT_EQ(g.lines[k], (std::vector<Vec2>{nfp.slits()[k][0], nfp.slits()[k][1]})) << fp;
    EXPECT_EQ(g.points, nfp.points()) << fp;
    const bool plain = nfp.slits().empty() && nfp.points().empty();
    EXPECT_EQ(text.rfind(plain ? "MULTIPOLYGON (((" : "GEOMETRYCOLLECTION (", 0), 0u) << text.substr(0, 40);
    ASSERT_FALSE(g.polygons.empty());

    // JSON: the same numbers.
    const json j = json::parse(nfp_text(fp, fq, "--json"));
    ASSERT_EQ(j.at("polygons").size(), nfp.polygons().size());
    for (std::size_t k = 0; k < nfp.polygons().size(); ++k) {
      ASSERT_EQ(j["polygons"][k].size(), nfp.polygons()[k].size());
      for (std::size_t r = 0; r < nfp.polygons()[k].size(); ++r) {
        ASSERT_EQ(j["polygons"][k][r].size(), nfp.polygons()[k][r].size());
        for (std::size_t i = 0; i < nfp.polygons()[k][r].size(); ++i)
          EXPECT_EQ(vec_of(j["polygons"][k][r][i]), nfp.polygons()[k][r][i]);
      }
    }
    EXPECT_EQ(j.at("lines").size(), nfp.slits().size());
    EXPECT_EQ(j.at("points").size(), nfp.points().size());

    // The printed rings bound PairDepth2's overlap set: even-odd inside ⇔ overlapping, at
    // placements farther than a millionth of the scale from every printed edge.
    const PairDepth2 pair(P, Q);
    const double far = 1e-6 * (extent(P) + extent(Q));
    for (const Vec2& t : placements(rng, P, 60)) {
      if (distance_to_segments(g.polygons, t) <= far) continue;
      const bool in = inside_rings(g.polygons, t);
      // Slits and points lie inside cl O but are not overlapping placements; generic t is off them.
      EXPECT_EQ(in, pair.overlapping(t)) << fp << " t=" << pair_arg(t);
      (in ? inside_checked : outside_checked) += 1;
    }
  }
  EXPECT_GT(inside_checked, 0);
  EXPECT_GT(outside_checked, 0);
}

TEST_F(CliNonconvex, ConvexInputsWork) {
  // nfp takes any two polygons: for two axis squares the no-fit polygon is the square of the
  // summed sides around the difference of the corners: [−1, 2]² for [0,2]² and the unit square.
  const std::string fa = write("A.wkt", "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))\n"), fb = write("B.wkt", wkt_of(kUnit));
  const io::Geometry2 g = io::parse_wkt_geometry(nfp_text(fa, fb));
  ASSERT_EQ(g.polygons.size(), 1u);
  ASSERT_EQ(g.polygons[0].size(), 1u);
  std::vector<Vec2> ring = g.polygons[0][0];
  std::vector<Vec2> want{{-1, -1}, {2, -1}, {2, 2}, {-1, 2}};
  ASSERT_EQ(ring.size(), 4u);
  std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end(), [](const Vec2& a, const Vec2& b) {
                return a.y() < b.y() || (a.y() == b.y() && a.x() < b.x());
              }), ring.end());
  EXPECT_EQ(ring, want);
  EXPECT_TRUE(g.lines.empty());
  EXPECT_TRUE(g.points.empty());
}

TEST_F(CliNonconvex, SlotAndHoleExactFits) {
  const std::string fu = write("U.wkt", wkt_of(kU)), ff = write("F.wkt", wkt_of(kFrame)), fs = write("S.wkt", wkt_of(kUnit));
  // The U's slot: the slit x = 1, 1 ≤ y ≤ 3 (Q slides between the arms, touching both).
  const std::string slot = nfp_text(fu, fs);
  EXPECT_EQ(slot.rfind("GEOMETRYCOLLECTION (MULTIPOLYGON (((", 0), 0u) << slot;
  EXPECT_NE(slot.find("MULTILINESTRING (("), std::string::npos) << slot;
  EXPECT_EQ(slot.find("MULTIPOINT"), std::string::npos) << slot;
  const io::Geometry2 gu = io::parse_wkt_geometry(slot);
  ASSERT_EQ(gu.lines.size(), 1u) << slot;
  std::vector<Vec2> s = gu.lines[0];
  std::sort(s.begin(), s.end(), [](const Vec2& a, const Vec2& b) { return a.y() < b.y(); });
  EXPECT_EQ(s, (std::vector<Vec2>{{1, 1}, {1, 3}})) << slot;
  EXPECT_TRUE(gu.points.empty());

  // The frame's hole: the isolated point (1, 1).
  const std::string hole = nfp_text(ff, fs);
  EXPECT_EQ(hole.rfind("GEOMETRYCOLLECTION (MULTIPOLYGON (((", 0), 0u) << hole;
  EXPECT_EQ(hole.find("MULTILINESTRING"), std::string::npos) << hole;
  const io::Geometry2 gf = io::parse_wkt_geometry(hole);
  EXPECT_EQ(gf.points, (std::vector<Vec2>{{1, 1}})) << hole;
  EXPECT_TRUE(gf.lines.empty());

  // Two non-convex polygons: P = the U, Q = an L of box [0,1]² (the square minus its top-left
  // quarter), which slides in the slot exactly like the square: the same slit.
  const std::string fl = write("L.wkt", "POLYGON ((0 0, 1 0, 1 1, 0.5 1, 0.5 0.5, 0 0.5, 0 0))\n");
  const io::Geometry2 gl = io::parse_wkt_geometry(nfp_text(fu, fl));
  ASSERT_EQ(gl.lines.size(), 1u);
  s = gl.lines[0];
  std::sort(s.begin(), s.end(), [](const Vec2& a, const Vec2& b) { return a.y() < b.y(); });
  EXPECT_EQ(s, (std::vector<Vec2>{{1, 1}, {1, 3}}));
  // Batch on the no-fit polygon: at t = (1, 2) the L touches both arms (depth 0); at (1.25, 2) it
  // overlaps the right arm by 0.25, so σ = 0.25 (back onto the slit, move (−0.25, 0)), and along
  // +y its column [1.75, 2.25] × [2, 3] must rise by 1 to clear the arm's top y = 3.
  const std::string csv = write("q.csv", "1,2,0,0\n1.25,2,0,0\n1.25,2,0,1\n");
  const Result b = run("batch " + quote(fu) + " " + quote(fl) + " --queries " + quote(csv));
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_EQ(b.out, "depth,tx,ty\n0,0,0\n0.25,-0.25,0\n1,0,1\n");
  const json j = depth_json(fu, fl, Vec2(1, 2), "");
  EXPECT_FALSE(j.at("overlapping").get<bool>());
  EXPECT_EQ(j.at("depth").get<double>(), 0);

  // The frame against the L: at t = (1, 1) the L lies in the hole touching it; every move
  // overlaps the frame (right/left: the bottom row spans the hole's width; up/down: the right
  // column spans its height), so (1, 1) is an isolated point; moved right by 0.25, σ = 0.25.
  const io::Geometry2 gfl = io::parse_wkt_geometry(nfp_text(ff, fl));
  EXPECT_EQ(gfl.points, (std::vector<Vec2>{{1, 1}}));
  EXPECT_TRUE(gfl.lines.empty());
  const json h0 = depth_json(ff, fl, Vec2(1, 1), "");
  EXPECT_FALSE(h0.at("overlapping").get<bool>());
  const json h1 = depth_json(ff, fl, Vec2(1.25, 1), "");
  EXPECT_TRUE(h1.at("overlapping").get<bool>());
  EXPECT_EQ(h1.at("depth").get<double>(), 0.25);
}

TEST_F(CliNonconvex, SvgDrawsTheNoFitPolygon) {
  const std::string fu = write("U.wkt", wkt_of(kU));
  const std::string fl = write("L.wkt", "POLYGON ((0 0, 1 0, 1 1, 0.5 1, 0.5 0.5, 0 0.5, 0 0))\n");
  const std::string svg = (dir_ / "out.svg").string();
  const Result r = run("depth " + quote(fu) + " " + quote(fl) + " --offset=1.25,2 --direction=0,1 --svg " + quote(svg));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string s = slurp(svg);
  EXPECT_EQ(s.rfind("<svg", 0), 0u);
  EXPECT_NE(s.find("no-fit polygon"), std::string::npos);
  EXPECT_NE(s.find("class=\"slit\""), std::string::npos);
  EXPECT_NE(s.find("directional depth σ_d = 1"), std::string::npos);
  // The configuration panel draws the NFP's rings: one <polygon> or <path> more than the
  // workspace's P, Q + t and Q + t + v.
  std::size_t shapes = 0;
  for (std::size_t at = 0; (at = s.find("<polygon", at)) != std::string::npos; ++at) ++shapes;
  for (std::size_t at = 0; (at = s.find("<path fill-rule", at)) != std::string::npos; ++at) ++shapes;
  EXPECT_EQ(shapes, 4u);
  // A holed P against the L: the exact fit in the hole is drawn as a point.
  const std::string ff = write("F.wkt", wkt_of(kFrame));
  ASSERT_EQ(run("depth " + quote(ff) + " " + quote(fl) + " --offset=1.25,1 --svg " + quote(svg)).status, 0);
  const std::string s2 = slurp(svg);
  EXPECT_NE(s2.find("class=\"fit-point\""), std::string::npos);
  EXPECT_NE(s2.find("minimum depth σ = 0.25"), std::string::npos);
}

TEST_F(CliNonconvex, BadInput) {
  const std::string fu = write("U.wkt", wkt_of(kU)), fs = write("S.wkt", wkt_of(kUnit));
  auto polygon_message = [](const Rings& rings, const char* name) {
    try {
      Polygon(rings, name);
    } catch (const pendepth::InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("valid");
  };
  // Polygon validation, with the line of the vertex the message names, for nfp, depth and batch.
  const std::string self = write("self.wkt", "POLYGON (\n(0 0,\n4 0,\n4 4,\n2 -1,\n0 4))\n");
  std::string msg = polygon_message(Rings{{{0, 0}, {4, 0}, {4, 4}, {2, -1}, {0, 4}}}, "Q");
  ASSERT_EQ(msg.rfind("Q: ring 0 (outer): self-intersecting (edges 0 and ", 0), 0u) << msg;
  expect_error("nfp " + quote(fu) + " " + quote(self), self + ":2: " + msg);
  const std::string outside =
      write("out.wkt", "POLYGON ((0 0, 10 0, 10 10, 0 10),\n(2 2, 4 2, 4 4, 2 4),\n(20 20, 21 20, 21 21))\n");
  expect_error("depth " + quote(fu) + " " + quote(outside), outside + ":3: Q: ring 2 (hole 2) lies outside the outer ring");
  expect_error("nfp " + quote(outside) + " " + quote(fs), outside + ":3: P: ring 2 (hole 2) lies outside the outer ring");
  const std::string csv = write("q.csv", "0,0,0,0\n");
  expect_error("batch " + quote(outside) + " " + quote(fu) + " --queries " + quote(csv),
               outside + ":3: P: ring 2 (hole 2) lies outside the outer ring");
  // Parse errors of the WKT reader.
  const std::string open = write("open.wkt", "POLYGON ((0 0, 1 0, 1 1\n");
  const Result r = run("nfp " + quote(open) + " " + quote(fu));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind(open + ":2: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  // Missing file, 3D shape, bad queries, zero direction.
  const std::string missing = (dir_ / "missing.wkt").string();
  expect_error("nfp " + quote(missing) + " " + quote(fu), missing + ": cannot read file (" + std::strerror(ENOENT) + ")");
  const std::string obj = write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n");
  expect_error("nfp " + quote(fu) + " " + quote(obj), obj + ": nfp takes 2D shapes (.wkt) only");
  const std::string badq = write("bad.csv", "1,1,0,0\n1,1,nan,0\n");
  const std::string fl = write("L.wkt", "POLYGON ((0 0, 1 0, 1 1, 0.5 1, 0.5 0.5, 0 0.5, 0 0))\n");
  expect_error("batch " + quote(fu) + " " + quote(fl) + " --queries " + quote(badq),
               badq + ":2: field 3 is not a finite number: 'nan'");
  expect_error("depth " + quote(fu) + " " + quote(fl) + " --direction 0,0", "--direction: the direction is zero");
  // A usage error (missing Q) is exit 2 too.
  const Result u = run("nfp " + quote(fu));
  EXPECT_EQ(u.status, 2);
}

TEST(WktGeometry, RoundTripAndErrors) {
  // The writer's text reads back to the same doubles, for every part kind.
  io::Geometry2 g;
  g.polygons = {{{{0.1, 0.2}, {3, 0}, {3, 1.0 / 3}}, {{1, 0.1}, {2, 0.2}, {1.5, 0.25}}}, {{{10, 10}, {11, 10}, {11, 11}}}};
  g.lines = {{{1e-300, -5}, {7, 1e300}}};
  g.points = {{-0.0, 2.5}};
  const std::string text = io::to_wkt(g);
  EXPECT_EQ(text.rfind("GEOMETRYCOLLECTION (MULTIPOLYGON (((0.1 0.2, 3 0, ", 0), 0u) << text;
  const io::Geometry2 back = io::parse_wkt_geometry(text);
  EXPECT_EQ(back.polygons, g.polygons);
  EXPECT_EQ(back.lines, g.lines);
  EXPECT_EQ(back.points, g.points);
  io::Geometry2 only;
  only.polygons = {g.polygons[1]};
  EXPECT_EQ(io::to_wkt(only), "MULTIPOLYGON (((10 10, 11 10, 11 11, 10 10)))");
  EXPECT_EQ(io::to_wkt(io::Geometry2{}), "MULTIPOLYGON EMPTY");
  EXPECT_TRUE(io::parse_wkt_geometry("MULTIPOLYGON EMPTY").polygons.empty());
  // Other spellings accepted by the reader.
  const io::Geometry2 p = io::parse_wkt_geometry("multipoint (1 2, 3 4)");
  EXPECT_EQ(p.points, (std::vector<Vec2>{{1, 2}, {3, 4}}));
  const io::Geometry2 q = io::parse_wkt_geometry("GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 0 1)), LINESTRING (0 0, 1 1), POINT (5 5))");
  EXPECT_EQ(q.polygons.size(), 1u);
  EXPECT_EQ(q.lines.size(), 1u);
  EXPECT_EQ(q.points.size(), 1u);
  // Errors name source and line.
  auto error = [](const std::string& t) {
    try {
      io::parse_wkt_geometry(t, "src");
    } catch (const pendepth::InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("MULTIPOLYGON (((0 0, 1 0, 0 0)))"), "src:1: ring 0 of polygon 0 has 2 point(s); a ring needs at least 3");
  EXPECT_EQ(error("MULTILINESTRING ((0 0))"), "src:1: line 0 has 1 point(s); a line needs at least 2");
  EXPECT_EQ(error("MULTIPOLYGON Z (((0 0 0, 1 0 0, 0 1 0)))"), "src:1: MULTIPOLYGON Z: only 2D coordinates are supported");
  EXPECT_EQ(error("CIRCLE (1 2)").rfind("src:1: unknown geometry type 'CIRCLE'", 0), 0u);
  EXPECT_EQ(error("MULTIPOINT ((1 2)) x"), "src:1: trailing text after the geometry: 'x'");
  EXPECT_EQ(error("MULTIPOLYGON (((0 0, 1 0, 0 1)),\n((0 0, 1 0 0 1)))"),
            "src:2: point 1 of ring 0 of polygon 1 has more than 2 coordinates (only 2D is supported)");
  EXPECT_EQ(error("MULTIPOLYGON (((0 0, 1 0, 0 1)\n x"), "src:2: missing ',' or ')' after ring 0 of polygon 0, got 'x'");
  EXPECT_EQ(error("GEOMETRYCOLLECTION (GEOMETRYCOLLECTION EMPTY)"), "src:1: nested GEOMETRYCOLLECTION is not supported");
  // The writer refuses what it cannot print.
  io::Geometry2 bad;
  bad.lines = {{{0, 0}}};
  EXPECT_THROW(io::to_wkt(bad), pendepth::InvalidInput);
  bad.lines.clear();
  bad.points = {{std::numeric_limits<double>::infinity(), 0}};
  EXPECT_THROW(io::to_wkt(bad), pendepth::InvalidInput);
}
