// PairDepth2 (issue 5 items 1-3): overlap test, σ_d, σ and complete separation of two simple
// polygons with holes against the independent exact CGAL oracle (oracle.hpp), plus the geometric
// properties every answer must have. Inputs: random star-shaped pairs (with and without holes,
// integer and real coordinates), combs whose teeth fit each other exactly, a slot Q fits exactly,
// collinear contacts, every ordered pair of the albano nesting instance. Pinned seeds.
#include <pendepth/depth2_polygon_polygon.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include "oracle.hpp"
#include "polygon2/shapes.hpp"
#include "test_scale.hpp"
#include "test_ulps.hpp"

namespace {

using nonconvex2_test::PairOracle;
using pendepth::Depth2;
using pendepth::PairDepth2;
using pendepth::PairQueryStats;
using pendepth::Polygon;
using pendepth::Vec2;

constexpr double kMaxUlps = 8;

// Relative error in units of 2^-52; an exact zero must be reproduced exactly.
double ulps(double a, double b) { return pendepth_test::ulps_of_want(a, b); }

struct Stats {
  std::size_t queries = 0, overlapping = 0, minimum_queries = 0, pair_total = 0, pairs_examined = 0, along_queries = 0;
  std::size_t sep_outside = 0, min_pairs = 0;
  double max_along = 0, max_sep = 0, max_min = 0;
  double t_along = 0, t_sep = 0, t_min = 0, t_oracle = 0;  // seconds
};

// Seconds spent in f(), added to `acc`.
template <class F>
auto timed(double& acc, F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  auto r = f();
  acc += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

Stats& totals() {
  static Stats s;
  return s;
}

Polygon star(std::mt19937_64& rng, int n, double rmin, double rmax, bool grid) {
  for (;;) {
    try {
      return Polygon::simple(polygon2_test::star_ring(rng, n, Vec2(0, 0), rmin, rmax, grid), "star");
    } catch (const pendepth::InvalidInput&) {
    }
  }
}

void bbox(const Polygon& S, Vec2& lo, Vec2& hi) {
  lo = hi = S.vertices()[0];
  for (const Vec2& p : S.vertices()) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
}

// Distance from `x` to feature f of S translated by `offset` (a vertex, or the segment of an edge).
double feature_distance(const Polygon& S, const pendepth::Feature& f, const Vec2& offset, const Vec2& x) {
  const Vec2 a = S.vertices()[f.index] + offset;
  if (f.kind == pendepth::FeatureKind::Vertex) return (x - a).norm();
  const Vec2 b = S.vertices()[S.next(f.index)] + offset, ab = b - a;
  const double u = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (x - a - u * ab).norm();
}

// The reported contact: witness_p on P's feature, witness_q on the moved Q's feature, the two equal
// (a touching contact), up to the rounding of the reported doubles.
void check_contact(const Polygon& P, const Polygon& Q, const Vec2& t, const Depth2& r, const std::string& what) {
  if (r.depth == 0) return;
  ASSERT_NE(r.feature_p.kind, pendepth::FeatureKind::None) << what;
  ASSERT_NE(r.feature_q.kind, pendepth::FeatureKind::None) << what;
  EXPECT_NEAR(r.normal.norm(), 1, 1e-15) << what;
  const double scale = 1e-9 * (1 + t.norm() + r.depth + P.vertices()[0].norm() + Q.vertices()[0].norm());
  EXPECT_LE(feature_distance(P, r.feature_p, Vec2(0, 0), r.witness_p), scale) << what;
  EXPECT_LE(feature_distance(Q, r.feature_q, t + r.translation, r.witness_q), scale) << what;
  EXPECT_LE((r.witness_p - r.witness_q).norm(), scale) << what;
}

// All checks for one pair: `nt` random placements (plus vertex differences), `nd` directions each,
// σ on every `min_every`-th overlapping placement (0: never).
void check_pair(const Polygon& P, const Polygon& Q, std::mt19937_64& rng, int nt, int nd, int min_every, const std::string& what) {
  PairDepth2 query(P, Q);
  PairOracle oracle(P, Q);
  Stats& st = totals();
  Vec2 plo, phi, qlo, qhi;
  bbox(P, plo, phi);
  bbox(Q, qlo, qhi);
  std::uniform_real_distribution<double> ux(plo.x() - qhi.x(), phi.x() - qlo.x()), uy(plo.y() - qhi.y(), phi.y() - qlo.y());
  std::vector<Vec2> ts;
  for (int k = 0; k < nt; ++k) {
    Vec2 t(ux(rng), uy(rng));
    if (k % 3 == 1) t = Vec2(std::round(t.x()), std::round(t.y()));
    if (k % 3 == 2) t = P.vertices()[rng() % P.size()] - Q.vertices()[rng() % Q.size()];  // a vertex of M's arrangement
    ts.push_back(t);
  }
  std::uniform_real_distribution<double> ua(0, 2 * polygon2_test::kPi);
  int overlapping_seen = 0;
  for (const Vec2& t : ts) {
    const bool ov = query.overlapping(t);
    ASSERT_EQ(ov, oracle.inside(t)) << what << " t=" << t.transpose();
    if (oracle.has_M()) {
      const int side = oracle.side_of_M(t);
      if (ov) EXPECT_EQ(side, 1) << what << ": O must lie in int M";
      if (side < 0) EXPECT_FALSE(ov) << what;
    }
    ++st.queries;
    st.overlapping += ov;
    for (int k = 0; k < nd; ++k) {
      Vec2 d;
      switch (k % 4) {
        case 0: {
          const double a = ua(rng);
          d = Vec2(std::cos(a), std::sin(a));
          break;
        }
        case 1:
          d = (k / 4) % 2 ? Vec2(0, (k / 8) % 2 ? 1 : -1) : Vec2((k / 8) % 2 ? 1 : -1, 0);
          break;
        case 2: {  // parallel to an edge of P
          const std::size_t g = rng() % P.size();
          d = P.vertices()[P.next(g)] - P.vertices()[g];
          break;
        }
        default: {  // parallel to an edge of Q
          const std::size_t g = rng() % Q.size();
          d = Q.vertices()[g] - Q.vertices()[Q.next(g)];
        }
      }
      PairQueryStats ps;
      const Depth2 a = timed(st.t_along, [&] { return query.along(t, d, &ps); });
      ++st.along_queries;
      st.pairs_examined += ps.pairs;
      st.pair_total += query.triangle_count_p() * query.triangle_count_q();
      const double want = timed(st.t_oracle, [&] { return oracle.along(t, d); });
      const double e = ulps(a.depth, want);
      st.max_along = std::max(st.max_along, e);
      ASSERT_LE(e, kMaxUlps) << what << " along t=" << t.transpose() << " d=" << d.transpose() << " got " << a.depth << " want " << want;
      EXPECT_EQ(a.overlapping, ov);
      const Depth2 s = timed(st.t_sep, [&] { return query.separation(t, d); });
      const double ws = timed(st.t_oracle, [&] { return oracle.separation(t, d); });
      const double es = ulps(s.depth, ws);
      st.max_sep = std::max(st.max_sep, es);
      ASSERT_LE(es, kMaxUlps) << what << " separation t=" << t.transpose() << " d=" << d.transpose() << " got " << s.depth << " want " << ws;
      EXPECT_EQ(s.overlapping, ov);
      EXPECT_GE(s.depth, a.depth * (1 - 1e-12)) << what;
      if (!ov && s.depth > 0) ++st.sep_outside;
      // Just short of the answer Q still overlaps P (the open interval before the exit).
      if (a.depth > 1e-6) EXPECT_TRUE(query.overlapping(t + (1 - 1e-9) * a.translation)) << what;
      if (s.depth > 1e-6) EXPECT_TRUE(query.overlapping(t + (1 - 1e-9) * s.translation)) << what;
      check_contact(P, Q, t, a, what + " along");
      check_contact(P, Q, t, s, what + " separation");
    }
    if (ov && min_every > 0 && overlapping_seen++ % min_every == 0) {
      PairQueryStats ps;
      const Depth2 m = timed(st.t_min, [&] { return query.minimum(t, &ps); });
      st.min_pairs += ps.pairs;
      ++st.minimum_queries;
      const double want = timed(st.t_oracle, [&] { return oracle.minimum(t); });
      const double e = ulps(m.depth, want);
      st.max_min = std::max(st.max_min, e);
      ASSERT_LE(e, kMaxUlps) << what << " minimum t=" << t.transpose() << " got " << m.depth << " want " << want;
      EXPECT_TRUE(m.overlapping);
      EXPECT_NEAR(m.translation.norm(), m.depth, m.depth * 1e-14);
      check_contact(P, Q, t, m, what + " minimum");
      if (m.depth > 1e-6) EXPECT_TRUE(query.overlapping(t + (1 - 1e-9) * m.translation)) << what;
      for (int k = 0; k < 64; ++k) {
        const double ang = 2 * polygon2_test::kPi * k / 64;
        EXPECT_LE(m.depth, query.along(t, Vec2(std::cos(ang), std::sin(ang))).depth * (1 + 1e-12)) << what;
      }
    }
  }
}

TEST(PairDepth2, RandomStarPairs) {
  std::mt19937_64 rng(20260521);
  for (int it = 0; it < pendepth_test::scaled(16); ++it) {
    const bool grid = it % 2;
    const Polygon P = it % 3 == 0 ? polygon2_test::random_polygon(rng, 12 + int(rng() % 12), 1 + int(rng() % 2), grid)
                                  : star(rng, 8 + int(rng() % 16), 50, 100, grid);
    const Polygon Q = star(rng, 5 + int(rng() % 10), 15, 45, grid);
    check_pair(P, Q, rng, 15, 4, 4, "random " + std::to_string(it));
  }
}

TEST(PairDepth2, QWithHoles) {
  std::mt19937_64 rng(777);
  for (int it = 0; it < pendepth_test::scaled(4); ++it) {
    const Polygon P = star(rng, 10, 50, 100, it % 2);
    const Polygon Q = polygon2_test::random_polygon(rng, 10, 1, it % 2);
    check_pair(P, Q, rng, 12, 4, 3, "Q with a hole " + std::to_string(it));
  }
}

// P: comb with gaps gw; Q: comb with teeth gw and gaps tw, upside down: Q's teeth fill P's pockets
// exactly at t0, where every contact is a touch.
struct Combs {
  static constexpr double tw = 3, gw = 2, h = 5, base = 2;
  static constexpr int teeth = 4;
  Polygon P = Polygon::simple(polygon2_test::comb_ring(teeth, tw, gw, h, base), "comb P");
  Polygon Q = [] {
    auto r = polygon2_test::comb_ring(teeth - 1, gw, tw, h, base);
    for (auto& p : r) p = Vec2(p.x(), -p.y());
    return Polygon::simple(r, "comb Q");
  }();
  Vec2 t0{tw, 2 * base + h};
};

TEST(PairDepth2, CombsFitExactly) {
  Combs c;
  PairDepth2 q(c.P, c.Q);
  EXPECT_FALSE(q.overlapping(c.t0));
  for (const Vec2& d : {Vec2(1, 0), Vec2(0, 1), Vec2(0, -1), Vec2(-1, 0), Vec2(1, 2)}) {
    EXPECT_EQ(q.along(c.t0, d).depth, 0);
    EXPECT_EQ(q.minimum(c.t0).depth, 0);
  }
  // Pushed down by s: back up by exactly s; sideways by x: back by x.
  for (double s : {0.25, 0.5, 1.0, 1.5}) {
    const Vec2 t = c.t0 - Vec2(0, s);
    ASSERT_TRUE(q.overlapping(t));
    const Depth2 up = q.along(t, Vec2(0, 1));
    EXPECT_EQ(up.depth, s);
    EXPECT_EQ(q.separation(t, Vec2(0, 1)).depth, s);
    EXPECT_FALSE(q.overlapping(t + up.translation));
    const Depth2 m = q.minimum(t);
    EXPECT_EQ(m.depth, s);
    EXPECT_FALSE(q.overlapping(t + m.translation));
    const Vec2 tx = c.t0 + Vec2(s / 4, 0);
    ASSERT_TRUE(q.overlapping(tx));
    EXPECT_EQ(q.along(tx, Vec2(-1, 0)).depth, s / 4);
    EXPECT_EQ(q.minimum(tx).depth, s / 4);
    // Sliding the fitted comb out sideways is blocked: along +x it must leave P's last tooth.
    EXPECT_GT(q.along(tx, Vec2(1, 0)).depth, s / 4);
  }
  std::mt19937_64 rng(4242);
  check_pair(c.P, c.Q, rng, pendepth_test::scaled(40), 4, 2, "combs");
  // Placements on the fit's lines (exact, degenerate): the slit placements t0 + (0, s), s > 0.
  PairOracle oracle(c.P, c.Q);
  for (double s : {0.0, 0.5, 3.0, 5.0, 7.0}) {
    const Vec2 t = c.t0 + Vec2(0, s);
    EXPECT_EQ(q.overlapping(t), oracle.inside(t));
    EXPECT_EQ(q.along(t, Vec2(0, -1)).depth, oracle.along(t, Vec2(0, -1)));
  }
}

TEST(PairDepth2, SlotExactlyQsWidth) {
  // U-shape: base [0,7]x[0,2], walls [0,2] and [5,7] up to y = 8; slot [2,5] x [2,8], width 3.
  const Polygon P = Polygon::simple(std::vector<Vec2>{{0, 0}, {7, 0}, {7, 8}, {5, 8}, {5, 2}, {2, 2}, {2, 8}, {0, 8}}, "U");
  const Polygon Q = Polygon::simple(std::vector<Vec2>{{0, 0}, {3, 0}, {3, 1}, {0, 1}}, "block");
  PairDepth2 q(P, Q);
  for (double y : {2.0, 3.5, 7.0, 8.0}) {  // sliding along the slot: touching only
    const Vec2 t(2, y);
    EXPECT_FALSE(q.overlapping(t));
    for (const Vec2& d : {Vec2(0, 1), Vec2(0, -1), Vec2(1, 0), Vec2(1, 1)}) {
      EXPECT_EQ(q.along(t, d).depth, 0);
      EXPECT_EQ(q.along(t, d).overlapping, false);
    }
    EXPECT_EQ(q.minimum(t).depth, 0);
  }
  // Overlapping the base by s: up along the slot by s (the slit placements do not overlap), and the
  // complete separation upwards is also s.
  for (double s : {0.25, 0.5, 0.75}) {
    const Vec2 t(2, 2 - s);
    EXPECT_EQ(q.along(t, Vec2(0, 1)).depth, s);
    EXPECT_EQ(q.separation(t, Vec2(0, 1)).depth, s);
    EXPECT_EQ(q.minimum(t).depth, s);
  }
  // From below P, moving up: the last contact is leaving the base into the slot.
  EXPECT_EQ(q.separation(Vec2(2, -5), Vec2(0, 1)).depth, 7);
  EXPECT_EQ(q.along(Vec2(2, -5), Vec2(0, 1)).depth, 0);
  // One unit to the right Q no longer fits: it must leave through the top of the wall.
  EXPECT_EQ(q.separation(Vec2(3, -5), Vec2(0, 1)).depth, 13);
  std::mt19937_64 rng(99);
  check_pair(P, Q, rng, pendepth_test::scaled(40), 4, 2, "slot");
}

TEST(PairDepth2, CollinearContactsAreTouching) {
  const Polygon P = Polygon::simple(std::vector<Vec2>{{0, 0}, {2, 0}, {4, 0}, {4, 2}, {0, 2}}, "rect with a collinear vertex");
  const Polygon Q = Polygon::simple(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "unit");
  PairDepth2 q(P, Q);
  for (const Vec2& t : {Vec2(4, 0.5), Vec2(1, 2), Vec2(-1, -1), Vec2(4, 2), Vec2(1.5, -1), Vec2(2, -1)}) {
    EXPECT_FALSE(q.overlapping(t)) << t.transpose();
    EXPECT_EQ(q.along(t, Vec2(-1, 0)).depth, 0);
    EXPECT_EQ(q.minimum(t).depth, 0);
  }
  // Inside, exactly: the nearest exit of a unit square at (1.5, 0.25) in a 4x2 rectangle is down by 1.25.
  const Depth2 m = q.minimum(Vec2(1.5, 0.25));
  EXPECT_EQ(m.depth, 1.25);
  EXPECT_EQ(m.translation, Vec2(0, -1.25));
  EXPECT_EQ(q.along(Vec2(1.5, 0.25), Vec2(1, 0)).depth, 2.5);
  EXPECT_EQ(q.separation(Vec2(-3, 0.25), Vec2(1, 0)).depth, 7);
  std::mt19937_64 rng(5);
  check_pair(P, Q, rng, pendepth_test::scaled(30), 4, 2, "collinear");
}

TEST(PairDepth2, NestingAlbanoEveryOrderedPair) {
  const auto pieces = polygon2_test::nesting_pieces("albano.json");
  std::mt19937_64 rng(31337);
  std::vector<Polygon> polys;
  for (std::size_t k = 0; k < pieces.size(); ++k) polys.push_back(Polygon::simple(pieces[k], "albano " + std::to_string(k)));
  for (std::size_t i = 0; i < polys.size(); ++i)
    for (std::size_t j = 0; j < polys.size(); ++j)
      check_pair(polys[i], polys[j], rng, pendepth_test::scaled(8), 3, 2, "albano " + std::to_string(i) + "/" + std::to_string(j));
}

TEST(PairDepth2, InvalidQueriesThrow) {
  Combs c;
  PairDepth2 q(c.P, c.Q);
  EXPECT_THROW(q.along(c.t0, Vec2(0, 0)), pendepth::InvalidInput);
  EXPECT_THROW(q.separation(c.t0, Vec2(NAN, 1)), pendepth::InvalidInput);
  EXPECT_THROW(q.minimum(Vec2(INFINITY, 0)), pendepth::InvalidInput);
  EXPECT_THROW(q.overlapping(Vec2(0, NAN)), pendepth::InvalidInput);
}

// Measured accuracy, pruning and timing of everything this process ran (printed once at the end).
class Summary : public ::testing::Environment {
 public:
  void TearDown() override {
    const Stats& s = totals();
    if (s.queries == 0) return;
    std::cout << "[nonconvex2] placements " << s.queries << " (overlapping " << s.overlapping << "), sigma_d queries " << s.along_queries
              << ", sigma queries " << s.minimum_queries << ", separation positive from outside " << s.sep_outside << "\n"
              << "[nonconvex2] max ulps vs oracle: sigma_d " << s.max_along << ", separation " << s.max_sep << ", sigma " << s.max_min << "\n"
              << "[nonconvex2] sigma_d pairs examined " << s.pairs_examined << " of " << s.pair_total << " ("
              << (s.pair_total ? 100.0 * double(s.pairs_examined) / double(s.pair_total) : 0) << "%)"
              << ", sigma exact cover tests per query " << (s.minimum_queries ? s.min_pairs / s.minimum_queries : 0) << "\n"
              << "[nonconvex2] mean time (us): sigma_d " << 1e6 * s.t_along / double(std::max<std::size_t>(s.along_queries, 1))
              << ", separation " << 1e6 * s.t_sep / double(std::max<std::size_t>(s.along_queries, 1)) << ", sigma "
              << 1e6 * s.t_min / double(std::max<std::size_t>(s.minimum_queries, 1)) << "; oracle total " << s.t_oracle << " s\n";
  }
};
[[maybe_unused]] ::testing::Environment* const summary_env = ::testing::AddGlobalTestEnvironment(new Summary);

}  // namespace
