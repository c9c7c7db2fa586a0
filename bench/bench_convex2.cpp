// Benchmark: 2D convex intersection depth (DHS §3) — pendepth's queries against the naive linear
// methods and Box2D's b2CollidePolygons, on the same inputs in the same run (docs/design.md §6).
//
// Notation: P fixed, Q moving, placement t, M = P ⊕ (−Q), n = |P| = m = |Q| (4 … 10⁶).
// Benchmark names are <query>/<implementation>/<n>:
//   sigma_d/pendepth          directional_depth: prune-and-search, O(log n + log m)
//   sigma_d/naive_scan        ray exit over every edge line of a prebuilt explicit M, O(n + m)
//   sigma_d/naive_build_scan  the same, building M first (merge + edge lines), O(n + m)
//   sigma_field/pendepth      DepthField::minimum, O(log(n + m)) after preprocessing
//   sigma_merge/pendepth      minimum_depth: exact slope-order merge, O(n + m)
//   sigma/naive_scan          min distance to the edge lines of a prebuilt M, O(n + m)
//   sigma/naive_build_scan    the same, building M first
//   field_build/pendepth      DepthField construction (and destruction), per pair
//   sigma/box2d               b2CollidePolygons, polygon radius 0 (n <= b2_maxPolygonVertices)
//   sigma/box2d_world         the same + b2WorldManifold::Initialize, which yields the depth
// Signed distance and cast (issue 16), names <query>/<implementation>/<engine>/<n>, placements
// apart (|t| beyond both shapes' reach; casts aimed at M, most hit):
//   distance/pendepth         Pair2::signed_distance (the boundary vertex–edge search, box trees)
//   distance/scan             plain double minimum over every vertex–edge pair, O(nm)
//   distance/box2d            b2Distance (GJK, float), convex engine, n <= 64
//   cast/pendepth             Pair2::cast (convex: the ray's entry into M, O(log n + log m);
//                             others: first boundary contact)
//   cast/scan                 plain double first vertex–edge contact over every pair, O(nm)
//   cast/box2d                b2ShapeCast (conservative advancement, float; stops within
//                             b2_linearSlop = 0.005 of contact), convex engine, n <= 64
// Engines: convex (two ellipse polygons of n vertices), polygon-convex (a star of n vertices,
// an ellipse of 8), no-fit-polygon and pair-per-query (two stars of n and n/2 vertices).
// Every query benchmark cycles through the same kQueries placements t ∈ int M (and directions),
// generated outside the timed loop from a fixed seed. The naive references are plain double and
// independent of pendepth (own merge from the vertex arrays); before timing, each size's fixture
// checks them against pendepth and exports the largest disagreement as counters; a disagreement
// beyond kAgreeTol fails the benchmark. bench/run_convex2.sh prints the tables of
// docs/benchmarks.md from this program's JSON output.
#include <benchmark/benchmark.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_polygon_shape.h>
#include <pendepth/depth2.hpp>
#include <pendepth/pendepth.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "common.hpp"

namespace {

using pendepth::ConvexPolygon;
using pendepth::DepthField;
using pendepth::Vec2;
namespace pb = pendepth::bench;

constexpr double kInf = std::numeric_limits<double>::infinity();
// Largest accepted |naive − pendepth| (input units; shapes have diameter ≈ 2–4). The naive
// double evaluation is off by far less; this only catches a broken build or a wrong benchmark.
constexpr double kAgreeTol = 1e-9;

// Explicit M = P ⊕ (−Q) as edge lines nx·x + ny·y <= c (unit outward normals), by the textbook
// merge of the two edge sequences in slope order from each polygon's lowest-leftmost vertex.
// Stored as separate arrays so the scans are simple streaming loops. build() reuses its buffers,
// so naive_build_scan times the work, not the allocator.
class NaiveM {
 public:
  void build(std::span<const Vec2> P, std::span<const Vec2> Q) {
    const std::size_t n = P.size(), m = Q.size();
    // Lowest-leftmost vertex of P, and of −Q (= highest-rightmost of Q).
    std::size_t ia = 0, ib = 0;
    for (std::size_t k = 1; k < n; ++k)
      if (P[k].y() < P[ia].y() || (P[k].y() == P[ia].y() && P[k].x() < P[ia].x())) ia = k;
    for (std::size_t k = 1; k < m; ++k)
      if (Q[k].y() > Q[ib].y() || (Q[k].y() == Q[ib].y() && Q[k].x() > Q[ib].x())) ib = k;
    ax_.resize(n + 2), ay_.resize(n + 2), bx_.resize(m + 2), by_.resize(m + 2);
    for (std::size_t k = 0, s = ia; k < n + 2; ++k, s = (s + 1 == n ? 0 : s + 1))
      ax_[k] = P[s].x(), ay_[k] = P[s].y();
    for (std::size_t k = 0, s = ib; k < m + 2; ++k, s = (s + 1 == m ? 0 : s + 1))
      bx_[k] = -Q[s].x(), by_[k] = -Q[s].y();
    vx_.clear(), vy_.clear();
    std::size_t i = 0, j = 0;
    while (i < n || j < m) {
      vx_.push_back(ax_[i] + bx_[j]), vy_.push_back(ay_[i] + by_[j]);
      const double cr = (ax_[i + 1] - ax_[i]) * (by_[j + 1] - by_[j]) -
                        (ay_[i + 1] - ay_[i]) * (bx_[j + 1] - bx_[j]);
      if (cr >= 0 && i < n) ++i;
      if (cr <= 0 && j < m) ++j;
    }
    const std::size_t N = vx_.size();
    nx_.resize(N), ny_.resize(N), c_.resize(N);
    for (std::size_t k = 0; k < N; ++k) {
      const std::size_t k1 = k + 1 == N ? 0 : k + 1;
      const double ex = vx_[k1] - vx_[k], ey = vy_[k1] - vy_[k];
      const double len = std::sqrt(ex * ex + ey * ey);
      nx_[k] = ey / len, ny_[k] = -ex / len;
      c_[k] = nx_[k] * vx_[k] + ny_[k] * vy_[k];
    }
  }

  std::size_t size() const { return c_.size(); }
  Vec2 vertex(std::size_t k) const { return Vec2(vx_[k], vy_[k]); }

  // σ(t): min over edges of the signed distance to the edge line (t ∈ int M ⇔ all positive).
  double sigma(const Vec2& t) const {
    const double tx = t.x(), ty = t.y();
    double best = kInf;
    for (std::size_t k = 0; k < c_.size(); ++k)
      best = std::min(best, c_[k] - nx_[k] * tx - ny_[k] * ty);
    return best > 0 ? best : 0;
  }

  // σ_d(t) for unit d: exit of the ray t + s·d over the edges it approaches (n·d > 0); the same
  // pass decides t ∈ int M, without which the exit parameter means nothing.
  double sigma_d(const Vec2& t, const Vec2& d) const {
    const double tx = t.x(), ty = t.y(), dx = d.x(), dy = d.y();
    double inside = kInf, exit = kInf;
    for (std::size_t k = 0; k < c_.size(); ++k) {
      const double dist = c_[k] - nx_[k] * tx - ny_[k] * ty;
      const double den = nx_[k] * dx + ny_[k] * dy;
      inside = std::min(inside, dist);
      exit = std::min(exit, den > 0 ? dist / den : kInf);
    }
    return inside > 0 ? exit : 0;
  }

 private:
  std::vector<double> ax_, ay_, bx_, by_;  // P and −Q from their lowest vertex, 2 wrap-around
  std::vector<double> vx_, vy_;            // vertices of M
  std::vector<double> nx_, ny_, c_;        // edge lines of M
};

b2PolygonShape to_box2d(const ConvexPolygon& poly) {
  std::vector<b2Vec2> pts;
  for (const Vec2& v : poly.vertices()) pts.emplace_back(float(v.x()), float(v.y()));
  b2PolygonShape shape;
  shape.Set(pts.data(), int32(pts.size()));
  shape.m_radius = 0;  // no b2_polygonRadius skin: compare the bare polygons
  return shape;
}

// The depth a Box2D user reads: −(deepest manifold point's separation) along the reference-face
// normal; 0 for an empty manifold.
double box2d_depth(const b2PolygonShape& A, const b2Transform& xa, const b2PolygonShape& B,
                   const b2Transform& xb) {
  b2Manifold man;
  b2CollidePolygons(&man, &A, xa, &B, xb);
  if (man.pointCount == 0) return 0;
  b2WorldManifold wm;
  wm.Initialize(&man, xa, A.m_radius, xb, B.m_radius);
  float s = wm.separations[0];
  for (int i = 1; i < man.pointCount; ++i) s = std::min(s, wm.separations[i]);
  return -double(s);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Everything the benchmarks of one size share, built (and checked) outside any timing.
struct Fixture {
  explicit Fixture(std::size_t n_)
      : n(n_),
        rng(20261121u + n_),
        P(pb::random_ellipse_polygon(n_, rng, "P")),
        Q(pb::random_ellipse_polygon(n_, rng, "Q")) {
    M.build(P.vertices(), Q.vertices());
    // Placements: c + r·(v − c) for a random vertex v of M, c the mean vertex of M (interior),
    // r = 0.999·√u — spread over int M by area, never on ∂M.
    Vec2 c(0, 0);
    for (std::size_t k = 0; k < M.size(); ++k) c += M.vertex(k);
    c /= double(M.size());
    auto placement = [&](double r) {
      const auto k = std::size_t(rng.uniform(0, double(M.size())));
      return Vec2(c + r * (M.vertex(std::min(k, M.size() - 1)) - c));
    };
    for (std::size_t q = 0; q < pb::kQueries; ++q) {
      t.push_back(placement(0.999 * std::sqrt(rng.uniform(0, 1))));
      const double a = rng.uniform(0, 2 * std::numbers::pi);
      d.emplace_back(std::cos(a), std::sin(a));
    }
    field = std::make_unique<DepthField>(P, Q);
    check();
    if (n <= b2_maxPolygonVertices) box2d_setup(placement);
  }

  // Agreement of the naive references and pendepth on the first `checked` queries (all of them
  // up to n = 4096; fewer above, where minimum_depth costs milliseconds).
  void check() {
    checked = std::min(pb::kQueries, std::max<std::size_t>(32, (std::size_t(1) << 22) / n));
    for (std::size_t q = 0; q < checked; ++q) {
      const pendepth::Depth2 merge = pendepth::minimum_depth(P, Q, t[q]);
      const pendepth::Depth2 fld = field->minimum(t[q]);
      const pendepth::Depth2 dir = pendepth::directional_depth(P, Q, t[q], d[q]);
      if (!merge.overlapping || !fld.overlapping || !dir.overlapping)
        error = "placement " + std::to_string(q) + " not in int M";
      err_merge = std::max(err_merge, std::abs(merge.depth - M.sigma(t[q])));
      err_field = std::max(err_field, std::abs(fld.depth - merge.depth));
      err_sigma_d = std::max(err_sigma_d, std::abs(dir.depth - M.sigma_d(t[q], d[q])));
    }
    if (std::max({err_merge, err_field, err_sigma_d}) > kAgreeTol)
      error = "naive and pendepth disagree: sigma " + std::to_string(err_merge) + ", field " +
              std::to_string(err_field) + ", sigma_d " + std::to_string(err_sigma_d);
  }

  // Box2D shapes and transforms for the same placements; its float32 depth error against
  // pendepth's minimum_depth over all placements and over a shallow set (r ∈ [0.95, 0.999]).
  template <class Placement>
  void box2d_setup(Placement&& placement) {
    bp = to_box2d(P), bq = to_box2d(Q);
    if (std::size_t(bp.m_count) != P.size() || std::size_t(bq.m_count) != Q.size())
      error = "Box2D's hull changed the polygons";
    xa.SetIdentity();
    std::vector<double> err_all, err_shallow;
    for (std::size_t q = 0; q < pb::kQueries; ++q) {
      xb.emplace_back(b2Vec2(float(t[q].x()), float(t[q].y())), b2Rot(0));
      err_all.push_back(std::abs(box2d_depth(bp, xa, bq, xb[q]) -
                                 pendepth::minimum_depth(P, Q, t[q]).depth));
      const Vec2 s = placement(rng.uniform(0.95, 0.999));
      const b2Transform xs(b2Vec2(float(s.x()), float(s.y())), b2Rot(0));
      err_shallow.push_back(
          std::abs(box2d_depth(bp, xa, bq, xs) - pendepth::minimum_depth(P, Q, s).depth));
    }
    b2_err_max = *std::max_element(err_all.begin(), err_all.end());
    b2_err_median = median(err_all);
    b2_err_shallow_max = *std::max_element(err_shallow.begin(), err_shallow.end());
    b2_err_shallow_median = median(err_shallow);
  }

  std::size_t n;
  pb::Rng rng;
  ConvexPolygon P, Q;
  NaiveM M;
  std::vector<Vec2> t, d;  // kQueries placements in int M and unit directions
  std::unique_ptr<DepthField> field;
  std::string error;  // non-empty: the benchmarks of this size report it and do not run
  std::size_t checked = 0;
  double err_merge = 0, err_field = 0, err_sigma_d = 0;
  b2PolygonShape bp, bq;
  b2Transform xa;
  std::vector<b2Transform> xb;
  double b2_err_max = 0, b2_err_median = 0, b2_err_shallow_max = 0, b2_err_shallow_median = 0;
};

// Benchmarks are registered size by size, so one fixture is alive at a time (10⁶ needs ~0.5 GB).
const Fixture& fixture(std::size_t n) {
  static std::unique_ptr<Fixture> current;
  if (!current || current->n != n) {
    current.reset();
    current = std::make_unique<Fixture>(n);
  }
  return *current;
}

// Shared prologue: fetch the fixture, refuse to time a failed one, attach size counters.
const Fixture* prepare(benchmark::State& st, std::size_t n) {
  const Fixture& f = fixture(n);
  if (!f.error.empty()) {
    st.SkipWithError(f.error.c_str());
    return nullptr;
  }
  st.counters["n"] = double(f.P.size());
  st.counters["M_edges"] = double(f.M.size());
  return &f;
}

void agreement_counters(benchmark::State& st, const Fixture& f) {
  st.counters["checked"] = double(f.checked);
  st.counters["max_abs_diff_sigma"] = f.err_merge;
  st.counters["max_abs_diff_field"] = f.err_field;
  st.counters["max_abs_diff_sigma_d"] = f.err_sigma_d;
}

void sigma_d_pendepth(benchmark::State& st, std::size_t n) {
  const Fixture* f = prepare(st, n);
  if (!f) return;
  std::size_t q = 0;
  for (auto _ : st) {
    pendepth::Depth2 r = pendepth::directional_depth(f->P, f->Q, f->t[q], f->d[q]);
    benchmark::DoNotOptimize(r);
    q = pb::next_query(q);
  }
  agreement_counters(st, *f);
}

void sigma_d_naive_scan(benchmark::State& st, std::size_t n) {
  const Fixture* f = prepare(st, n);
  if (!f) return;
  std::size_t q = 0;
  for (auto _ : st) {
    double s = f->M.sigma_d(f->t[q], f->d[q]);
    benchmark::DoNotOptimize(s);
    q = pb::next_query(q);
  }
}

void sigma_d_naive_build_scan(benchmark::State& st, std::size_t n) {
  const Fixture* f = prepare(st, n);
  if (!f) return;
  NaiveM M;
  M.build(f->P.vertices(), f->Q.vertices());  // first build sizes the buffers
  std::size_t q = 0;
  for (auto _ : st) {
    M.build(f->P.vertices(), f->Q.vertices());
    double s = M.sigma_d(f->t[q], f->d[q]);
    benchmark::DoNotOptimize(s);
    q = pb::next_query(q);
  }
}

void sigma_field_pendepth(benchmark::State& st, std::size_t n) {
  const Fixture* f = prepare(st, n);
  if (!f) return;
  std::size_t q = 0;
  for (auto _ : st) {
    pendepth::Depth2 r = f->field->minimum(f->t[q]);
    benchmark::DoNotOptimize(r);
    q = pb::next_query(q);
  }
  st.counters["field_nodes"] = double(f->field->node_count());
  st.counters["field_max_steps"] = double(f->field->max_search_depth());
  agreement_counters(st, *f);
}

void sigma_merge_pendepth(benchmark::State& st, std::size_t n) {
  const Fixture* f = prepare(st, n);
  if (!f) return;
  std::size_t q = 0;
  for (auto _ : st) {
    pendepth::Depth2 r = pendepth::minimum_depth(f->P, f->Q, f->t[q]);
    benchmark::DoNotOptimize(r);
    q = pb::next_query(q);
  }
  agreement_counters(st, *f);
}

void sigma_naive_scan(benchmark::State& st, std::size_t n) {
  const Fixture* f = prepare(st, n);
  if (!f) return;
  std::size_t q = 0;
  for (auto _ : st) {
    double s = f->M.sigma(f->t[q]);
    benchmark::DoNotOptimize(s);
    q = pb::next_query(q);
  }
}

void sigma_naive_build_scan(benchmark::State& st, std::size_t n) {
  const Fixture* f = prepare(st, n);
  if (!f) return;
  NaiveM M;
  M.build(f->P.vertices(), f->Q.vertices());
  std::size_t q = 0;
  for (auto _ : st) {
    M.build(f->P.vertices(), f->Q.vertices());
    double s = M.sigma(f->t[q]);
    benchmark::DoNotOptimize(s);
    q = pb::next_query(q);
  }
}

void field_build_pendepth(benchmark::State& st, std::size_t n) {
  const Fixture* f = prepare(st, n);
  if (!f) return;
  for (auto _ : st) {
    DepthField field(f->P, f->Q);
    benchmark::DoNotOptimize(field);
  }
}

void sigma_box2d(benchmark::State& st, std::size_t n) {
  const Fixture* f = prepare(st, n);
  if (!f) return;
  b2Manifold man;
  std::size_t q = 0;
  for (auto _ : st) {
    b2CollidePolygons(&man, &f->bp, f->xa, &f->bq, f->xb[q]);
    benchmark::DoNotOptimize(man);
    q = pb::next_query(q);
  }
  st.counters["b2_err_max"] = f->b2_err_max;
  st.counters["b2_err_median"] = f->b2_err_median;
  st.counters["b2_err_shallow_max"] = f->b2_err_shallow_max;
  st.counters["b2_err_shallow_median"] = f->b2_err_shallow_median;
}

void sigma_box2d_world(benchmark::State& st, std::size_t n) {
  const Fixture* f = prepare(st, n);
  if (!f) return;
  std::size_t q = 0;
  for (auto _ : st) {
    double depth = box2d_depth(f->bp, f->xa, f->bq, f->xb[q]);
    benchmark::DoNotOptimize(depth);
    q = pb::next_query(q);
  }
}

// ---- signed distance and cast (issue 16) ----

std::vector<Vec2> star_ring(std::size_t n, pb::Rng& rng) {
  std::vector<Vec2> r(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double th = 2 * std::numbers::pi * (double(k) + rng.uniform(0, 0.9)) / double(n);
    const double rad = rng.uniform(0.8, 2.0);
    r[k] = Vec2(rad * std::cos(th), rad * std::sin(th));
  }
  return r;
}

struct DistanceFixture {
  std::unique_ptr<pendepth::Pair2> pair;
  std::vector<std::vector<Vec2>> p_rings, q_rings;  // normal-form rings for the scans
  std::vector<Vec2> ts, ds;
  std::vector<b2Vec2> bp, bq;                        // Box2D copies (convex engine)
};

// Every vertex of one ring set against every edge of the other, shifted by sh: plain double.
double scan_distance(const DistanceFixture& f, const Vec2& t) {
  double best = kInf;
  auto run = [&](const auto& vr, const auto& er, const Vec2& sh) {
    for (const auto& ring : vr)
      for (const Vec2& v0 : ring) {
        const Vec2 v = v0 + sh;
        for (const auto& er_ring : er)
          for (std::size_t k = 0; k < er_ring.size(); ++k) {
            const Vec2 a = er_ring[k], e = er_ring[(k + 1) % er_ring.size()] - a;
            const double lam = std::clamp((v - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
            best = std::min(best, (v - a - lam * e).squaredNorm());
          }
      }
  };
  run(f.q_rings, f.p_rings, t);
  run(f.p_rings, f.q_rings, Vec2(-t));
  return std::sqrt(best);
}

// First contact of vertices moving along dir against edges: plain double, O(nm).
double scan_cast(const DistanceFixture& f, const Vec2& t, const Vec2& d) {
  double best = kInf;
  auto run = [&](const auto& vr, const auto& er, const Vec2& sh, const Vec2& dir) {
    for (const auto& ring : vr)
      for (const Vec2& v0 : ring) {
        const Vec2 v = v0 + sh;
        for (const auto& er_ring : er)
          for (std::size_t k = 0; k < er_ring.size(); ++k) {
            const Vec2 a = er_ring[k], e = er_ring[(k + 1) % er_ring.size()] - a;
            const double den = dir.x() * e.y() - dir.y() * e.x();
            if (den == 0) continue;
            const Vec2 w = a - v;
            const double s = (w.x() * e.y() - w.y() * e.x()) / den, mu = (w.x() * dir.y() - w.y() * dir.x()) / den;
            if (s >= 0 && mu >= 0 && mu <= 1) best = std::min(best, s);
          }
      }
  };
  run(f.q_rings, f.p_rings, t, d);
  run(f.p_rings, f.q_rings, Vec2(-t), Vec2(-d));
  return best * d.norm();
}

const DistanceFixture* distance_fixture(const std::string& engine, std::size_t n) {
  static std::map<std::pair<std::string, std::size_t>, std::unique_ptr<DistanceFixture>> cache;
  auto& slot = cache[{engine, n}];
  if (slot) return slot.get();
  pb::Rng rng(1600 + n);
  auto f = std::make_unique<DistanceFixture>();
  pendepth::Shape2 P = pendepth::Shape2(pb::random_ellipse_polygon(n, rng, "P"));
  pendepth::Shape2 Q = pendepth::Shape2(pb::random_ellipse_polygon(engine == "convex" ? n : 8, rng, "Q"));
  pendepth::Prepare prep = pendepth::Prepare::Auto;
  if (engine != "convex") P = pendepth::Shape2(star_ring(n, rng), {}, "P");
  if (engine == "no-fit-polygon" || engine == "pair-per-query") {
    Q = pendepth::Shape2(star_ring(std::max<std::size_t>(n / 2, 4), rng), {}, "Q");
    prep = engine == "no-fit-polygon" ? pendepth::Prepare::Full : pendepth::Prepare::Queries;
  }
  f->pair = std::make_unique<pendepth::Pair2>(P, Q, prep);
  if (std::string(pendepth::to_string(f->pair->engine())) != engine) return nullptr;
  f->p_rings = P.rings();
  f->q_rings = Q.rings();
  for (std::size_t k = 0; k < pb::kQueries; ++k) {
    const double a = rng.uniform(0, 2 * std::numbers::pi), r = rng.uniform(5.6, 8.0);
    f->ts.emplace_back(r * std::cos(a), r * std::sin(a));
    const double b = a + std::numbers::pi + rng.uniform(-0.4, 0.4);
    f->ds.emplace_back(std::cos(b), std::sin(b));
  }
  if (engine == "convex") {
    for (const Vec2& v : f->p_rings[0]) f->bp.emplace_back(float(v.x()), float(v.y()));
    for (const Vec2& v : f->q_rings[0]) f->bq.emplace_back(float(v.x()), float(v.y()));
  }
  slot = std::move(f);
  return slot.get();
}

enum class DistImpl { Pendepth, Scan, Box2d };

void distance_bench(benchmark::State& st, const std::string& engine, std::size_t n, DistImpl impl, bool cast) {
  const DistanceFixture* f = distance_fixture(engine, n);
  if (!f) {
    st.SkipWithError("engine not chosen for this size");
    return;
  }
  // Agreement of the double scan with pendepth (a broken build or benchmark, not accuracy).
  double worst = 0;
  for (std::size_t q = 0; q < 64; ++q) {
    const double a = cast ? f->pair->cast(f->ts[q], f->ds[q]).distance : f->pair->signed_distance(f->ts[q]).distance;
    const double b = cast ? scan_cast(*f, f->ts[q], f->ds[q]) : scan_distance(*f, f->ts[q]);
    if (std::isfinite(a) || std::isfinite(b)) worst = std::max(worst, std::abs(a - b));
  }
  if (!(worst <= kAgreeTol)) {
    st.SkipWithError("scan and pendepth disagree");
    return;
  }
  b2DistanceProxy pa, pq;
  if (impl == DistImpl::Box2d) {
    pa.Set(f->bp.data(), int32(f->bp.size()), 0);
    pq.Set(f->bq.data(), int32(f->bq.size()), 0);
  }
  std::size_t q = 0, hits = 0;
  for (auto _ : st) {
    const Vec2 &t = f->ts[q], &d = f->ds[q];
    double v = 0;
    switch (impl) {
      case DistImpl::Pendepth: v = cast ? f->pair->cast(t, d).distance : f->pair->signed_distance(t).distance; break;
      case DistImpl::Scan: v = cast ? scan_cast(*f, t, d) : scan_distance(*f, t); break;
      case DistImpl::Box2d: {
        b2Transform xa, xb;
        xa.SetIdentity();
        xb.Set(b2Vec2(float(t.x()), float(t.y())), 0);
        if (cast) {
          b2ShapeCastInput in{pa, pq, xa, xb, b2Vec2(float(16 * d.x()), float(16 * d.y()))};
          b2ShapeCastOutput out;
          v = b2ShapeCast(&out, &in) ? 16 * out.lambda : kInf;
        } else {
          b2DistanceInput in{pa, pq, xa, xb, false};
          b2SimplexCache cache;
          cache.count = 0;
          b2DistanceOutput out;
          b2Distance(&out, &cache, &in);
          v = out.distance;
        }
        break;
      }
    }
    hits += std::isfinite(v);
    benchmark::DoNotOptimize(v);
    q = pb::next_query(q);
  }
  st.counters["finite_share"] = double(hits) / double(st.iterations());
  st.counters["scan_diff_max"] = worst;
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  using Fn = void (*)(benchmark::State&, std::size_t);
  struct Entry {
    const char* name;
    Fn fn;
  };
  const Entry all[] = {
      {"sigma_d/pendepth", sigma_d_pendepth},
      {"sigma_d/naive_scan", sigma_d_naive_scan},
      {"sigma_d/naive_build_scan", sigma_d_naive_build_scan},
      {"sigma_field/pendepth", sigma_field_pendepth},
      {"sigma_merge/pendepth", sigma_merge_pendepth},
      {"sigma/naive_scan", sigma_naive_scan},
      {"sigma/naive_build_scan", sigma_naive_build_scan},
      {"field_build/pendepth", field_build_pendepth},
  };
  const std::size_t sizes[] = {4, 8, 64, 512, 4096, 32768, 262144, 1000000};
  for (std::size_t n : sizes) {
    auto add = [n](const char* name, Fn fn) {
      auto* b = benchmark::RegisterBenchmark((std::string(name) + "/" + std::to_string(n)).c_str(),
                                             [fn, n](benchmark::State& st) { fn(st, n); });
      b->Unit(benchmark::kNanosecond);
    };
    for (const Entry& e : all) add(e.name, e.fn);
    if (n <= std::size_t(b2_maxPolygonVertices)) {
      add("sigma/box2d", sigma_box2d);
      add("sigma/box2d_world", sigma_box2d_world);
    }
  }
  for (const char* engine : {"convex", "polygon-convex", "no-fit-polygon", "pair-per-query"})
    for (std::size_t n : {8, 16, 64, 512})
      for (bool cast : {false, true}) {
        const bool convex = std::string(engine) == "convex";
        const std::string tag = std::string(engine) + "/" + std::to_string(n);
        const std::string what = cast ? "cast/" : "distance/";
        if (!convex && n == 512 && std::string(engine) == "no-fit-polygon") continue;  // its build: seconds
        auto reg = [&](const char* impl, DistImpl k) {
          benchmark::RegisterBenchmark((what + impl + "/" + tag).c_str(), [engine, n, k, cast](benchmark::State& st) {
            distance_bench(st, engine, n, k, cast);
          })->Unit(benchmark::kNanosecond);
        };
        reg("pendepth", DistImpl::Pendepth);
        reg("scan", DistImpl::Scan);
        if (convex && n <= 64) reg("box2d", DistImpl::Box2d);
      }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
