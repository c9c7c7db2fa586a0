// (1+δ)-approximate σ of huge point sets (approximate_minimum_depth, src/motion/) against the
// exact σ (ConvexPolytope::hull of both sets, then minimum_depth), n = 10⁴ … 10⁷ points per set.
//
//   Approx/<family>/<n>/<-log10 δ>  one whole approximate call (no state survives between calls)
//   Exact/build/<family>/<n>        both exact hulls + the first minimum_depth (builds adjacency)
//   Exact/query/<family>/<n>        one minimum_depth after that preprocessing
// Families: "offset" (an ellipsoid and a rotated, shifted sphere: one clear optimum direction) and
// "concentric" (two concentric spheres: every direction optimal, the kernels' worst case). Every
// point lies on its surface, so every point is a hull vertex.
// Counters of Approx: upper/lower − 1 (certified gap), err = upper/σ_exact − 1 (when the exact
// σ was computed: n ≤ PENDEPTH_BENCH_EXACT_MAX, default 10⁵), kernel and working-set sizes,
// refinement rounds and full scans. Sizes: PENDEPTH_BENCH_N (comma list).
#include <benchmark/benchmark.h>

#include <pendepth/approximate.hpp>
#include <pendepth/depth3.hpp>
#include <pendepth/polytope.hpp>

#include "common.hpp"

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace pendepth;

std::vector<Vec3> ellipsoid(std::size_t n, const Vec3& radii, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::normal_distribution<double> N;
  std::vector<Vec3> pts(n);
  for (auto& p : pts) {
    const Vec3 v(N(g), N(g), N(g));
    p = v.normalized().cwiseProduct(radii);
  }
  return pts;
}

struct Input {
  std::vector<Vec3> P, Q;
  Pose3 pp, pq;
  double exact = std::nan("");  // σ of the full hulls, when computed
};

// The last input only (two sets of 10⁷ points take 480 MB).
const Input& input(const std::string& family, std::size_t n) {
  static std::string key;
  static std::unique_ptr<Input> in;
  static std::map<std::string, double> exact_cache;
  const std::string k = family + "/" + std::to_string(n);
  if (key != k) {
    in.reset();
    in = std::make_unique<Input>();
    if (family == "offset") {
      in->P = ellipsoid(n, Vec3(1.5, 1, 1.2), 1), in->Q = ellipsoid(n, Vec3(1, 1, 1), 2);
      in->pq = Pose3(Eigen::Quaterniond(1, 0.2, 0.3, 0.1), Vec3(0.2, 0.1, 0));
    } else {
      in->P = ellipsoid(n, Vec3(1, 1, 1), 3), in->Q = ellipsoid(n, Vec3(0.5, 0.5, 0.5), 4);
    }
    key = k;
  }
  const std::size_t exact_max = bench::env_sizes("PENDEPTH_BENCH_EXACT_MAX", {100000})[0];
  if (std::isnan(in->exact) && n <= exact_max) {
    auto it = exact_cache.find(k);
    if (it == exact_cache.end()) {
      const auto HP = ConvexPolytope::hull(in->P), HQ = ConvexPolytope::hull(in->Q);
      it = exact_cache.emplace(k, minimum_depth(HP, in->pp, HQ, in->pq).depth).first;
    }
    in->exact = it->second;
  }
  return *in;
}

void approx(benchmark::State& state, std::string family, std::size_t n, int neg_log_delta) {
  const Input& in = input(family, n);
  const double delta = std::pow(10.0, -neg_log_delta);
  ApproxDepth3 r;
  for (auto _ : state) {
    r = approximate_minimum_depth(in.P, in.pp, in.Q, in.pq, delta);
    benchmark::DoNotOptimize(r);
  }
  state.counters["gap"] = r.upper_bound / r.lower_bound - 1;
  if (!std::isnan(in.exact)) state.counters["err"] = r.upper_bound / in.exact - 1;
  state.counters["converged"] = r.converged;
  state.counters["kernel"] = double(r.kernel_p + r.kernel_q);
  state.counters["working"] = double(r.working_p + r.working_q);
  state.counters["rounds"] = double(r.rounds);
  state.counters["scans"] = double(r.full_scans);
}

void exact_build(benchmark::State& state, std::string family, std::size_t n) {
  const Input& in = input(family, n);
  for (auto _ : state) {
    const auto HP = ConvexPolytope::hull(in.P), HQ = ConvexPolytope::hull(in.Q);
    benchmark::DoNotOptimize(minimum_depth(HP, in.pp, HQ, in.pq));
  }
}

void exact_query(benchmark::State& state, std::string family, std::size_t n) {
  const Input& in = input(family, n);
  const auto HP = ConvexPolytope::hull(in.P), HQ = ConvexPolytope::hull(in.Q);
  benchmark::DoNotOptimize(minimum_depth(HP, in.pp, HQ, in.pq));  // adjacency built once
  for (auto _ : state) benchmark::DoNotOptimize(minimum_depth(HP, in.pp, HQ, in.pq));
}

const bool registered = [] {
  const auto sizes = bench::env_sizes("PENDEPTH_BENCH_N", {10000, 100000, 1000000, 10000000});
  const std::size_t exact_max = bench::env_sizes("PENDEPTH_BENCH_EXACT_MAX", {100000})[0];
  for (const std::string family : {"offset", "concentric"}) {
    for (std::size_t n : sizes) {
      const auto iters = n >= 1000000 ? 1 : 3;
      for (int d : {2, 3})
        benchmark::RegisterBenchmark(("Approx/" + family + "/" + std::to_string(n) + "/" + std::to_string(d)).c_str(),
                                     approx, family, n, d)
            ->Unit(benchmark::kMillisecond)
            ->Iterations(iters);
      if (n <= exact_max) {
        benchmark::RegisterBenchmark(("Exact/build/" + family + "/" + std::to_string(n)).c_str(), exact_build, family, n)
            ->Unit(benchmark::kMillisecond)
            ->Iterations(1);
        benchmark::RegisterBenchmark(("Exact/query/" + family + "/" + std::to_string(n)).c_str(), exact_query, family, n)
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
