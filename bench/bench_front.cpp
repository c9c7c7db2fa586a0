// Batches through the front door (include/pendepth/pendepth.hpp) on 1 and 2 threads: the
// speed-up of Pair2 / Pair3 batch calls over the cores, per kind of query (issue 14: ≥ 1.8× on
// 2 cores for queries of ≥ 1 µs). Wall-clock time (UseRealTime), 4096 queries per batch, shapes
// and pairs prepared once outside the timed loop, as a user would.
//
//   bench_front --benchmark_filter=... ; the argument is the thread count (1, 2).
// Ratios (time at 1 thread / time at 2) are in docs/benchmarks.md.
#include <pendepth/pendepth.hpp>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "common.hpp"

namespace {

using namespace pendepth;

constexpr std::size_t kBatch = 4096;

std::vector<Shape2> nesting_pieces(const std::string& instance) {
  std::ifstream in(std::string(PENDEPTH_SHARED_DATA) + "/nesting/" + instance + ".json");
  nlohmann::json j;
  in >> j;
  std::vector<Shape2> out;
  for (const auto& item : j["items"]) {
    std::vector<Vec2> r;
    for (const auto& p : item["shape"]["data"]) r.push_back({p[0].get<double>(), p[1].get<double>()});
    out.emplace_back(r, std::vector<std::vector<Vec2>>{}, instance);
  }
  return out;
}

// Placements over the box of the configuration space of P and Q (a mix of overlapping and
// apart), directions uniform.
void placements(const Shape2& P, const Shape2& Q, std::vector<Vec2>& ts, std::vector<Vec2>& ds) {
  Vec2 lo(1e300, 1e300), hi(-1e300, -1e300), qlo(1e300, 1e300), qhi(-1e300, -1e300);
  const auto pr = P.rings(), qr = Q.rings();
  for (const Vec2& p : pr[0]) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  for (const Vec2& q : qr[0]) qlo = qlo.cwiseMin(q), qhi = qhi.cwiseMax(q);
  const Vec2 a = lo - qhi, b = hi - qlo;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0, 1), w(-1, 1);
  ts.clear();
  ds.clear();
  for (std::size_t k = 0; k < kBatch; ++k) {
    ts.emplace_back(a.x() + u(rng) * (b.x() - a.x()), a.y() + u(rng) * (b.y() - a.y()));
    ds.emplace_back(w(rng), w(rng) + 1e-3);
  }
}

enum class Query { Minimum, Along, Overlap };

void run2(benchmark::State& state, const Pair2& pair, Query q) {
  std::vector<Vec2> ts, ds;
  placements(pair.P(), pair.Q(), ts, ds);
  std::vector<Depth2> out(ts.size());
  std::unique_ptr<bool[]> o(new bool[ts.size()]);
  const unsigned threads = static_cast<unsigned>(state.range(0));
  for (auto _ : state) {
    if (q == Query::Minimum) pair.minimum(ts, out, threads);
    else if (q == Query::Along) pair.along(ts, ds, out, threads);
    else pair.overlapping(ts, std::span<bool>(o.get(), ts.size()), threads);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(ts.size()));
}

const Pair2& convex_pair(std::size_t n) {
  static std::map<std::size_t, Pair2> pairs;
  auto it = pairs.find(n);
  if (it == pairs.end()) {
    pendepth::bench::Rng rng(7 + n);
    const Shape2 P(pendepth::bench::random_ellipse_polygon(n, rng, "P"));
    const Shape2 Q(pendepth::bench::random_ellipse_polygon(n, rng, "Q"));
    it = pairs.emplace(n, Pair2(P, Q, Prepare::Full)).first;
  }
  return it->second;
}

// Two trousers pieces (non-convex): the no-fit polygon engine (built once).
const Pair2& nesting_pair() {
  static const Pair2 pair = [] {
    std::vector<Shape2> nonconvex;
    for (const Shape2& s : nesting_pieces("trousers"))
      if (!s.is_convex()) nonconvex.push_back(s);
    return Pair2(nonconvex.at(0), nonconvex.at(1), Prepare::Full);
  }();
  return pair;
}

// Two generated star polygons of 40 vertices (not from ../shared/data): the no-fit polygon engine.
const Pair2& star_pair() {
  static const Pair2 pair = [] {
    std::mt19937_64 rng(17);
    const auto star = [&](double r0, double r1) {
      std::uniform_real_distribution<double> u(r0, r1);
      std::vector<Vec2> ring;
      for (int k = 0; k < 40; ++k) {
        const double a = 2 * 3.14159265358979323846 * k / 40, r = u(rng);
        ring.emplace_back(r * std::cos(a), r * std::sin(a));
      }
      return Shape2(ring, {}, "star");
    };
    return Pair2(star(0.5, 2.0), star(0.3, 1.0), Prepare::Full);
  }();
  return pair;
}

const Pair2& nesting_pair_per_query() {
  static const Pair2 pair(nesting_pair().P(), nesting_pair().Q(), Prepare::Queries);
  return pair;
}

void BM_convex2_sigma_n8(benchmark::State& s) { run2(s, convex_pair(8), Query::Minimum); }
void BM_convex2_sigma_d_n64(benchmark::State& s) { run2(s, convex_pair(64), Query::Along); }
void BM_nfp_sigma(benchmark::State& s) { run2(s, nesting_pair(), Query::Minimum); }
void BM_nfp_sigma_d(benchmark::State& s) { run2(s, nesting_pair(), Query::Along); }
void BM_nfp_overlap(benchmark::State& s) { run2(s, nesting_pair(), Query::Overlap); }
void BM_pair_per_query_sigma_d(benchmark::State& s) { run2(s, nesting_pair_per_query(), Query::Along); }
void BM_star_nfp_sigma(benchmark::State& s) { run2(s, star_pair(), Query::Minimum); }

// ---- 3D: two hulls of the shared data (real game objects), random poses of Q ----

const Pair3& hull_pair() {
  static const Pair3 pair(Shape3::from_file(std::string(PENDEPTH_SHARED_DATA) + "/hulls/hull03.obj", "P"),
                          Shape3::from_file(std::string(PENDEPTH_SHARED_DATA) + "/hulls/hull12.obj", "Q"));
  return pair;
}

// Hulls of 64 random points on an ellipsoid each (generated, not from ../shared/data).
const Pair3& ellipsoid_pair() {
  static const Pair3 pair = [] {
    std::mt19937_64 rng(23);
    std::normal_distribution<double> g;
    const auto cloud = [&](const Vec3& axes) {
      std::vector<Vec3> p;
      for (int k = 0; k < 64; ++k) p.push_back(Vec3(g(rng), g(rng), g(rng)).normalized().cwiseProduct(axes));
      return Shape3::hull(p, "ellipsoid");
    };
    return Pair3(cloud(Vec3(2, 1, 0.7)), cloud(Vec3(1, 0.8, 0.5)));
  }();
  return pair;
}

void run3(benchmark::State& state, const Pair3& pair, bool along) {
  std::mt19937_64 rng(9);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(-1, 1);
  double radius = 0;
  for (const Vec3& v : pair.P().polytope().vertices()) radius = std::max(radius, v.norm());
  std::vector<Pose3> poses;
  std::vector<Vec3> ds;
  for (std::size_t k = 0; k < kBatch; ++k) {
    poses.emplace_back(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)),
                       Vec3(u(rng), u(rng), u(rng)) * radius);
    ds.emplace_back(g(rng), g(rng), g(rng) + 1e-3);
  }
  std::vector<Depth3> out(poses.size());
  const unsigned threads = static_cast<unsigned>(state.range(0));
  for (auto _ : state) {
    if (along) pair.along(poses, ds, out, threads);
    else pair.minimum(poses, out, threads);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(poses.size()));
}

void BM_convex3_sigma(benchmark::State& s) { run3(s, hull_pair(), false); }
void BM_convex3_sigma_d(benchmark::State& s) { run3(s, hull_pair(), true); }
void BM_ellipsoids_sigma(benchmark::State& s) { run3(s, ellipsoid_pair(), false); }

#define THREADS(b) BENCHMARK(b)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMicrosecond)
THREADS(BM_convex2_sigma_n8);
THREADS(BM_convex2_sigma_d_n64);
THREADS(BM_nfp_overlap);
THREADS(BM_nfp_sigma);
THREADS(BM_nfp_sigma_d);
THREADS(BM_pair_per_query_sigma_d);
THREADS(BM_star_nfp_sigma);
THREADS(BM_convex3_sigma);
THREADS(BM_convex3_sigma_d);
THREADS(BM_ellipsoids_sigma);

// ---- Per-pair setup with per-shape work shared (issue 19 item 2) ----
// Pair2(P, Q, Prepare::Queries) over every ordered pair of an instance's pieces (PairDepth2 for
// two non-convex pieces, PolygonDepth2 for a convex one against a non-convex one, nothing for two
// convex pieces). Arg 0 "cold": each pair gets brand-new Shape2 copies (made outside the timed
// region), so it triangulates both pieces as every pair did before Shape2 shared that work;
// arg 1 "shared": the same Shape2 objects for every pair (their caches filled by the first
// iteration). Time per iteration / `pairs` = setup per pair. Arguments: cold/shared, then the
// pair selection (setup_instance).
Shape2 fresh_copy(const Shape2& s) { return s.is_convex() ? Shape2(ConvexPolygon(s.convex())) : Shape2(Polygon(s.polygon())); }

void pair_setup(benchmark::State& s, const std::vector<Shape2>& pieces, const std::vector<std::pair<int, int>>& pairs) {
  const bool shared = s.range(0) == 1;
  std::vector<Shape2> ps, qs;
  for (auto _ : s) {
    if (!shared) {
      s.PauseTiming();
      ps.clear(), qs.clear();
      for (const auto& [i, j] : pairs) ps.push_back(fresh_copy(pieces[i])), qs.push_back(fresh_copy(pieces[j]));
      s.ResumeTiming();
    }
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const Pair2 pair = shared ? Pair2(pieces[pairs[k].first], pieces[pairs[k].second], Prepare::Queries)
                                : Pair2(ps[k], qs[k], Prepare::Queries);
      benchmark::DoNotOptimize(pair.engine());
    }
  }
  s.counters["pairs"] = double(pairs.size());
}

std::vector<std::pair<int, int>> all_pairs(std::size_t n) {
  std::vector<std::pair<int, int>> p;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) p.emplace_back(int(i), int(j));
  return p;
}

// Every ordered pair of the instance's pieces (arg 2 = 0), or only the pairs of two non-convex
// pieces (arg 2 = 1: the PairDepth2 engine alone, without the polygon × convex union boundaries).
void setup_instance(benchmark::State& s, const std::vector<Shape2>& pieces) {
  std::vector<std::pair<int, int>> pairs = all_pairs(pieces.size());
  if (s.range(1) == 1)
    std::erase_if(pairs, [&](const auto& p) { return pieces[p.first].is_convex() || pieces[p.second].is_convex(); });
  pair_setup(s, pieces, pairs);
}
void BM_pair2_setup_albano(benchmark::State& s) {
  static const auto pieces = nesting_pieces("albano");
  setup_instance(s, pieces);
}
void BM_pair2_setup_shirts(benchmark::State& s) {
  static const auto pieces = nesting_pieces("shirts");
  setup_instance(s, pieces);
}
void BM_pair2_setup_trousers(benchmark::State& s) {
  static const auto pieces = nesting_pieces("trousers");
  setup_instance(s, pieces);
}

// A polygon with holes (a 64-gon with six 12-gon holes) against six convex polygons, both ways
// round (polygon-convex and convex-polygon engines: PolygonDepth2 on the polygon's triangulation).
void BM_pair2_setup_holes_convex(benchmark::State& s) {
  static const std::vector<Shape2> pieces = [] {
    auto ngon = [](int n, double r, Vec2 c, double phase) {
      std::vector<Vec2> v;
      for (int k = 0; k < n; ++k) {
        const double a = phase + 2 * M_PI * k / n;
        v.emplace_back(c.x() + r * std::cos(a), c.y() + r * std::sin(a));
      }
      return v;
    };
    std::vector<std::vector<Vec2>> holes;
    for (int h = 0; h < 6; ++h) {
      auto ring = ngon(12, 9, Vec2(55 * std::cos(h * M_PI / 3), 55 * std::sin(h * M_PI / 3)), 0.1);
      std::reverse(ring.begin(), ring.end());
      holes.push_back(ring);
    }
    std::vector<Shape2> out{Shape2(ngon(64, 100, Vec2(0, 0), 0), holes, "holed")};
    for (int m : {3, 4, 6, 8, 16, 32}) out.push_back(Shape2(ngon(m, 7, Vec2(0, 0), 0.3), {}, "convex"));
    return out;
  }();
  std::vector<std::pair<int, int>> pairs;
  for (int c = 1; c < 7; ++c) pairs.emplace_back(0, c), pairs.emplace_back(c, 0);
  pair_setup(s, pieces, pairs);
}

#define SETUP(b) BENCHMARK(b)->ArgsProduct({{0, 1}, {0, 1}})->Unit(benchmark::kMicrosecond)
SETUP(BM_pair2_setup_albano);
SETUP(BM_pair2_setup_shirts);
SETUP(BM_pair2_setup_trousers);
BENCHMARK(BM_pair2_setup_holes_convex)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
