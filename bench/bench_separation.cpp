// Complete separation of two simple polygons along d (issue 5 item 1, DHS §6): the linear-time
// envelope walk (src/nonconvex2/envelope.cpp) against the previous divide-and-conquer envelope
// (tests/nonconvex2/envelope_dc.hpp, O(n log n)), for one envelope and for one
// PairDepth2::separation query (both variants include the overlap test the query reports).
// P: a random star polygon or a thick spiral with n vertices; Q: a 16-vertex star. n = 10 … 10^5.
// BM_Overlapping times the overlap test alone (reported by every separation query).
//   bench_separation --benchmark_filter=Envelope
#include <pendepth/depth2_polygon_polygon.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <random>

#include "envelope_dc.hpp"
#include "nonconvex2/envelope.hpp"

namespace {

using pendepth::Polygon;
using pendepth::Vec2;

// A star polygon: n sorted random angles, radii in [r/2, r].
Polygon star(std::mt19937_64& rng, int n, double r) {
  std::uniform_real_distribution<double> ua(0, 2 * std::numbers::pi), ur(r / 2, r);
  std::vector<double> ang(n);
  for (double& a : ang) a = ua(rng);
  std::sort(ang.begin(), ang.end());
  std::vector<Vec2> ring;
  for (double a : ang) ring.push_back(ur(rng) * Vec2(std::cos(a), std::sin(a)));
  return Polygon::simple(ring, "star");
}

// A thick Archimedean spiral with n vertices (deep winding pocket: most edges hidden).
Polygon spiral(int n) {
  const int steps = n / 2 - 1;
  std::vector<Vec2> outer, inner;
  for (int k = 0; k <= steps; ++k) {
    const double th = 4 * 2 * std::numbers::pi * k / steps, rad = 2 + th;
    const Vec2 u(std::cos(th), std::sin(th));
    outer.push_back((rad + 1) * u);
    inner.push_back((rad - 1) * u);
  }
  std::vector<Vec2> ring(inner.begin(), inner.end());
  ring.insert(ring.end(), outer.rbegin(), outer.rend());
  return Polygon::simple(ring, "spiral");
}

struct Case {
  Polygon P, Q;
  pendepth::PairDepth2 query;
  Vec2 t, d{0.6, 0.8};
  Case(Polygon p, Polygon q) : P(std::move(p)), Q(std::move(q)), query(P, Q), t(P.vertices()[0] - Q.vertices()[0] + Vec2(0.3141, 0.2718)) {}  // generic: no exact contact
};

// Inputs are built once per (shape, n) and reused by the four benchmarks.
const Case& input(int shape, int n) {
  static std::map<std::pair<int, int>, std::unique_ptr<Case>> cache;
  auto& c = cache[{shape, n}];
  if (!c) {
    std::mt19937_64 rng(1234 + n);
    Polygon Q = star(rng, 16, 10);
    c = std::make_unique<Case>(shape == 0 ? star(rng, n, 100) : spiral(n), std::move(Q));
  }
  return *c;
}

void BM_EnvelopeWalk(benchmark::State& st) {
  const Case& c = input(int(st.range(0)), int(st.range(1)));
  for (auto _ : st) benchmark::DoNotOptimize(pendepth::nonconvex2::right_envelope(c.P, c.d).size());
  st.counters["n"] = double(c.P.size());
}
void BM_EnvelopeDC(benchmark::State& st) {
  const Case& c = input(int(st.range(0)), int(st.range(1)));
  for (auto _ : st) benchmark::DoNotOptimize(nonconvex2_test::oracle::Envelope(c.P, c.d).build().size());
  st.counters["n"] = double(c.P.size());
}
void BM_SeparationWalk(benchmark::State& st) {
  const Case& c = input(int(st.range(0)), int(st.range(1)));
  for (auto _ : st) benchmark::DoNotOptimize(c.query.separation(c.t, c.d).depth);
  st.counters["n"] = double(c.P.size());
}
void BM_SeparationDC(benchmark::State& st) {
  const Case& c = input(int(st.range(0)), int(st.range(1)));
  for (auto _ : st)
    benchmark::DoNotOptimize(nonconvex2_test::oracle::oracle_separation(c.P, c.Q, c.t, c.d, c.query.overlapping(c.t)).depth);
  st.counters["n"] = double(c.P.size());
}

// The overlap test alone: the part of a separation query that is not the envelope walk and merge.
void BM_Overlapping(benchmark::State& st) {
  const Case& c = input(int(st.range(0)), int(st.range(1)));
  for (auto _ : st) benchmark::DoNotOptimize(c.query.overlapping(c.t));
  st.counters["n"] = double(c.P.size());
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int shape : {0, 1})
    for (int n : {10, 100, 1000, 10000, 100000}) b->Args({shape, n});
  b->ArgNames({"spiral", "n"})->Unit(benchmark::kMicrosecond);
}

BENCHMARK(BM_EnvelopeWalk)->Apply(sizes);
BENCHMARK(BM_EnvelopeDC)->Apply(sizes);
BENCHMARK(BM_SeparationWalk)->Apply(sizes);
BENCHMARK(BM_SeparationDC)->Apply(sizes);
BENCHMARK(BM_Overlapping)->Apply(sizes);

}  // namespace

BENCHMARK_MAIN();
