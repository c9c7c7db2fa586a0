// Lower-dimensional shapes and primitives in Pair3 (issue 16 items 4, 5), peers in one run: the
// signed distance and σ of a solid hull against a point, a segment, a triangle, a sphere, a
// capsule and another hull of the same size (the existing solid–solid engine), random poses
// (half overlapping). Counters: µs per query. BM_RoundedFlatCores: rounded shapes on two
// lower-dimensional cores.
#include <pendepth/pendepth.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

using namespace pendepth;

namespace {

std::vector<Vec3> sphere_points(std::mt19937_64& rng, int n) {
  std::normal_distribution<double> g;
  std::vector<Vec3> p;
  while (static_cast<int>(p.size()) < n) p.push_back(Vec3(g(rng), g(rng), g(rng)).normalized());
  return p;
}

Shape3 other(int kind, std::mt19937_64& rng, int n) {
  switch (kind) {
    case 0: return Shape3::point(Vec3(0, 0, 0));
    case 1: return Shape3::segment(Vec3(0, 0, -0.5), Vec3(0, 0, 0.5));
    case 2: return Shape3::flat(std::vector<Vec3>{Vec3(-0.5, -0.3, 0), Vec3(0.5, -0.3, 0), Vec3(0, 0.6, 0)});
    case 3: return Shape3::sphere(0.5);
    case 4: return Shape3::capsule(0.3, 0.5);
    default: return Shape3::hull(sphere_points(rng, n));
  }
}
const char* kNames[] = {"point", "segment", "triangle", "sphere", "capsule", "hull"};

void run(benchmark::State& state, bool distance) {
  const int kind = static_cast<int>(state.range(0)), n = static_cast<int>(state.range(1));
  std::mt19937_64 rng(42);
  const Pair3 pair(Shape3::hull(sphere_points(rng, n)), other(kind, rng, n));
  std::uniform_real_distribution<double> U(-1.6, 1.6);
  std::normal_distribution<double> g;
  std::vector<Pose3> poses;
  for (int i = 0; i < 256; ++i)
    poses.emplace_back(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)), Vec3(U(rng), U(rng), U(rng)));
  std::size_t i = 0;
  double sink = 0;
  for (auto _ : state) {
    const Pose3& q = poses[i++ % poses.size()];
    sink += distance ? pair.signed_distance(Pose3(), q).distance : pair.minimum(Pose3(), q).depth;
  }
  benchmark::DoNotOptimize(sink);
  state.SetLabel(std::string(kNames[kind]) + " vs hull " + std::to_string(n));
  state.counters["us_per_query"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-6,
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_SignedDistance(benchmark::State& s) { run(s, true); }
void BM_Minimum(benchmark::State& s) { run(s, false); }

// Curved primitives (src/primitives/support3.cpp, certified brackets): pairs of ~unit size, random
// poses (about half overlapping); counters: µs per query and the mean certified gap achieved
// (upper − lower, relative to |value| + 1e-3).
Shape3 curved_pair_shape(int kind, bool p, std::mt19937_64& rng) {
  switch (kind) {
    case 0: return p ? Shape3::cylinder(0.5, 0.7) : Shape3::hull(sphere_points(rng, 16));
    case 1: return p ? Shape3::cone(0.6, 0.7) : Shape3::hull(sphere_points(rng, 16));
    case 2: return p ? Shape3::ellipsoid(0.5, 0.8, 0.6) : Shape3::hull(sphere_points(rng, 16));
    case 3: return p ? Shape3::cylinder(0.5, 0.7) : Shape3::ellipsoid(0.5, 0.8, 0.6);
    case 4: return p ? Shape3::cone(0.6, 0.7) : Shape3::box(0.5, 0.4, 0.3);
    default: return p ? Shape3::ellipsoid(0.5, 0.8, 0.6) : Shape3::sphere(0.5);
  }
}
const char* kCurvedNames[] = {"cylinder vs hull 16", "cone vs hull 16", "ellipsoid vs hull 16",
                              "cylinder vs ellipsoid", "cone vs box", "ellipsoid vs sphere"};

void run_curved(benchmark::State& state, bool distance) {
  const int kind = static_cast<int>(state.range(0));
  std::mt19937_64 rng(42);
  const Shape3 P = curved_pair_shape(kind, true, rng);
  const Pair3 pair(P, curved_pair_shape(kind, false, rng));
  std::uniform_real_distribution<double> U(-1.2, 1.2);
  std::normal_distribution<double> g;
  std::vector<Pose3> poses;
  for (int i = 0; i < 256; ++i)
    poses.emplace_back(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)), Vec3(U(rng), U(rng), U(rng)));
  std::size_t i = 0;
  double sink = 0, gap = 0;
  for (auto _ : state) {
    const Pose3& q = poses[i++ % poses.size()];
    if (distance) {
      const Distance3 r = pair.signed_distance(Pose3(), q);
      sink += r.distance, gap += (r.upper_bound - r.lower_bound) / (std::abs(r.distance) + 1e-3);
    } else {
      const Depth3 r = pair.minimum(Pose3(), q);
      sink += r.depth, gap += (r.upper_bound - r.lower_bound) / (r.depth + 1e-3);
    }
  }
  benchmark::DoNotOptimize(sink);
  state.SetLabel(kCurvedNames[kind]);
  state.counters["us_per_query"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-6,
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["mean_rel_gap"] = gap / static_cast<double>(state.iterations());
}
void BM_CurvedSignedDistance(benchmark::State& s) { run_curved(s, true); }
void BM_CurvedMinimum(benchmark::State& s) { run_curved(s, false); }

// Rounded shapes on two lower-dimensional cores (src/convex3/flat3.cpp flat_flat_distance): cores
// summing to dimension 2 (capsule–capsule, sphere–rounded triangle: the existing path) against
// 3 and 4 (rounded triangle–capsule, two rounded squares), signed distance and cast, random poses
// (about half overlapping).
Shape3 rounded_kind(int k) {
  const std::vector<Vec3> tri{Vec3(-0.5, -0.3, 0), Vec3(0.5, -0.3, 0), Vec3(0, 0.6, 0)};
  const std::vector<Vec3> sq{Vec3(-0.5, -0.5, 0), Vec3(0.5, -0.5, 0), Vec3(0.5, 0.5, 0), Vec3(-0.5, 0.5, 0)};
  switch (k) {
    case 0: return Shape3::capsule(0.2, 0.5);
    case 1: return Shape3::sphere(0.3);
    case 2: return Shape3::rounded(Shape3::flat(tri), 0.1);
    default: return Shape3::rounded(Shape3::flat(sq), 0.1);
  }
}
void BM_RoundedFlatCores(benchmark::State& state) {
  const int a = static_cast<int>(state.range(0)), b = static_cast<int>(state.range(1));
  const bool cast = state.range(2) != 0;
  const Pair3 pair(rounded_kind(a), rounded_kind(b));
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> U(-0.8, 0.8);
  std::normal_distribution<double> g;
  std::vector<Pose3> poses;
  std::vector<Vec3> dirs;
  for (int i = 0; i < 256; ++i) {
    poses.emplace_back(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)), Vec3(U(rng), U(rng), U(rng)));
    dirs.push_back(-poses.back().translation + 0.3 * Vec3(g(rng), g(rng), g(rng)));
  }
  std::size_t i = 0;
  double sink = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % poses.size();
    sink += cast ? pair.cast(Pose3(), poses[k], dirs[k]).lower_bound : pair.signed_distance(Pose3(), poses[k]).distance;
  }
  benchmark::DoNotOptimize(sink);
  const char* names[] = {"capsule", "sphere", "rounded triangle", "rounded square"};
  state.SetLabel(std::string(names[a]) + " vs " + names[b] + (cast ? " cast" : " distance"));
  state.counters["us_per_query"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-6,
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(BM_CurvedSignedDistance)->DenseRange(0, 5);
BENCHMARK(BM_CurvedMinimum)->DenseRange(0, 5);
BENCHMARK(BM_SignedDistance)->ArgsProduct({{0, 1, 2, 3, 4, 5}, {16, 64}});
BENCHMARK(BM_Minimum)->ArgsProduct({{0, 1, 2, 3, 4, 5}, {16, 64}});
BENCHMARK(BM_RoundedFlatCores)->Args({0, 0, 0})->Args({1, 2, 0})->Args({2, 0, 0})->Args({3, 3, 0})
    ->Args({0, 0, 1})->Args({1, 2, 1})->Args({2, 0, 1})->Args({3, 3, 1});
BENCHMARK_MAIN();
