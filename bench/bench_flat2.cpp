// Points and segments against solid 2D shapes through Pair2 (issue 16 item 4; src/polygon2/
// flat_depth2.cpp): µs per query of σ, σ_d and the signed distance for a point Q against convex
// polygons and star-shaped non-convex polygons, and a segment Q against both, at
// n = 16 … 1024; in the same run, the same queries with Q a small triangle (the solid engines:
// convex × convex, polygon × convex) as the reference. Pairs prepared once outside the loop;
// 4096 pre-generated placements over M's box (a mix of overlapping and apart), cycled.
//
//   bench_flat2 [--benchmark_filter=...]      tables: docs/benchmarks.md "Points and segments in 2D"
#include <pendepth/pendepth.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace {

using namespace pendepth;

Shape2 convex_n(int n) {
  std::vector<Vec2> v;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    v.emplace_back(100 * std::cos(a), 100 * std::sin(a));
  }
  return Shape2(v);
}

Shape2 star_n(int n) {
  std::mt19937_64 rng(n);
  std::uniform_real_distribution<double> r(50, 100);
  std::vector<Vec2> v;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n, rad = i % 2 ? r(rng) : 100;
    v.emplace_back(rad * std::cos(a), rad * std::sin(a));
  }
  return Shape2(v);
}

enum class Kind { Point, Segment, Triangle };
enum class Query { Minimum, Along, Distance };

Shape2 moving(Kind k) {
  switch (k) {
    case Kind::Point: return Shape2::point(Vec2(1.25, -0.5));
    case Kind::Segment: return Shape2::segment(Vec2(-10, -3), Vec2(12, 5));
    case Kind::Triangle: break;
  }
  return Shape2(std::vector<Vec2>{{-1, -1}, {2, -0.5}, {0.25, 1.5}});
}

void run(benchmark::State& s, bool convex, Kind kind, Query query) {
  const int n = static_cast<int>(s.range(0));
  const Pair2 pair(convex ? convex_n(n) : star_n(n), moving(kind));
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-120, 120), a(0, 2 * std::numbers::pi);
  std::vector<Vec2> ts(4096), ds(4096);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    ts[i] = Vec2(u(rng), u(rng));
    const double t = a(rng);
    ds[i] = Vec2(std::cos(t), std::sin(t));
  }
  std::size_t i = 0;
  for (auto _ : s) {
    const std::size_t k = i++ & 4095;
    switch (query) {
      case Query::Minimum: benchmark::DoNotOptimize(pair.minimum(ts[k]).depth); break;
      case Query::Along: benchmark::DoNotOptimize(pair.along(ts[k], ds[k]).depth); break;
      case Query::Distance: benchmark::DoNotOptimize(pair.signed_distance(ts[k]).distance); break;
    }
  }
  s.SetLabel(std::string(to_string(pair.engine())));
}

#define FLAT_BENCH(name, convex, kind, query)                                                        \
  void BM_##name(benchmark::State& s) { run(s, convex, Kind::kind, Query::query); }                  \
  BENCHMARK(BM_##name)->RangeMultiplier(4)->Range(16, 1024)->Unit(benchmark::kMicrosecond);

FLAT_BENCH(point_convex_sigma, true, Point, Minimum)
FLAT_BENCH(triangle_convex_sigma, true, Triangle, Minimum)
FLAT_BENCH(point_convex_distance, true, Point, Distance)
FLAT_BENCH(triangle_convex_distance, true, Triangle, Distance)
FLAT_BENCH(point_convex_sigma_d, true, Point, Along)
FLAT_BENCH(triangle_convex_sigma_d, true, Triangle, Along)
FLAT_BENCH(segment_convex_sigma, true, Segment, Minimum)
FLAT_BENCH(segment_convex_distance, true, Segment, Distance)
FLAT_BENCH(segment_convex_sigma_d, true, Segment, Along)
FLAT_BENCH(segment_star_sigma, false, Segment, Minimum)
FLAT_BENCH(segment_star_distance, false, Segment, Distance)
FLAT_BENCH(segment_star_sigma_d, false, Segment, Along)
FLAT_BENCH(point_star_sigma, false, Point, Minimum)
FLAT_BENCH(triangle_star_sigma, false, Triangle, Minimum)
FLAT_BENCH(point_star_distance, false, Point, Distance)
FLAT_BENCH(triangle_star_distance, false, Triangle, Distance)
FLAT_BENCH(point_star_sigma_d, false, Point, Along)
FLAT_BENCH(triangle_star_sigma_d, false, Triangle, Along)

}  // namespace

BENCHMARK_MAIN();
