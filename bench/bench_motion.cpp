// Generalized depth PD_g (include/pendepth/motion.hpp, issue 18) against the translational σ on
// nesting pieces: the same pairs and placements in one run. Pairs: every ordered pair of the
// first 5 pieces of an instance, Q placed with its box centre on P's plus an offset of 10 % of
// P's box (pinned seed), overlapping placements only. One "query" answers one pair from scratch,
// as a single question would: σ = Pair2(P, Q, prepare) + minimum (second argument: 0 Auto, 1
// Queries); PD_g = generalized_depth (its probes build one Pair2 per angle; the branch and bound
// bounds angle intervals until the gap closes or max_intervals runs out). Counters: probes (σ about three centres at an angle) and angle
// intervals of the branch and bound per PD_g query, the mean relative gap
// (upper − lower)/upper, the fraction of queries whose gap closed (≤ 1e-6), the mean PD_g / σ.
//
//   bench_motion --benchmark_filter=...   (arguments: the instance index 0 albano, 1 shirts,
//   2 trousers; the Prepare of σ's pair or of PD_g's probes: 0 Auto, 1 Queries)
//
// 3D meshes (issue 18 item 2): BM_Sigma3Mesh (Pair3 built + σ with certified bounds) against
// BM_Generalized3Mesh (generalized_depth: the same σ, then the rotation search, default 64 probes)
// on the same posed pairs; argument 0: a bar stuck diagonally between two blocks of a wall
// (tests/motion/test_generalized3_mesh.cpp; φ = −0.05, −0.1, −0.2), 1: random polycube pairs
// (6 and 4 voxels, pinned seed, random poses, overlapping only). Decompositions are built once,
// outside the timing (Mesh3 keeps them). Counters as in 2D.
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh3/mesh_gen.hpp"  // polycube meshes (tests/mesh3)

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace pendepth;

const char* const kInstances[] = {"albano", "shirts", "trousers"};

struct Case {
  Shape2 P, Q;
  Vec2 t;
};

std::vector<Case> cases(int instance) {
  std::ifstream in(std::string(PENDEPTH_SHARED_DATA) + "/nesting/" + kInstances[instance] + ".json");
  nlohmann::json j;
  in >> j;
  std::vector<Shape2> pieces;
  for (const auto& item : j["items"]) {
    std::vector<Vec2> r;
    for (const auto& p : item["shape"]["data"]) r.push_back({p[0].get<double>(), p[1].get<double>()});
    pieces.emplace_back(r, std::vector<std::vector<Vec2>>{}, kInstances[instance]);
    if (pieces.size() == 5) break;
  }
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  std::vector<Case> out;
  for (const Shape2& P : pieces)
    for (const Shape2& Q : pieces) {
      Vec2 plo(1e300, 1e300), phi(-1e300, -1e300), qlo = plo, qhi = phi;
      const auto pr = P.rings(), qr = Q.rings();
      for (const Vec2& p : pr[0]) plo = plo.cwiseMin(p), phi = phi.cwiseMax(p);
      for (const Vec2& q : qr[0]) qlo = qlo.cwiseMin(q), qhi = qhi.cwiseMax(q);
      const Vec2 t = 0.5 * (plo + phi - qlo - qhi) + Vec2(u(rng) * (phi - plo).x(), u(rng) * (phi - plo).y());
      if (Pair2(P, Q).overlapping(t)) out.push_back({P, Q, t});
    }
  return out;
}

void BM_Sigma(benchmark::State& state) {
  const auto cs = cases(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& c = cs[i++ % cs.size()];
    benchmark::DoNotOptimize(Pair2(c.P, c.Q, state.range(1) == 0 ? Prepare::Auto : Prepare::Queries).minimum(c.t));
  }
  state.counters["pairs"] = double(cs.size());
}

void BM_Generalized(benchmark::State& state) {
  const auto cs = cases(static_cast<int>(state.range(0)));
  GeneralizedOptions2 o;
  o.prepare = state.range(1) == 0 ? Prepare::Auto : Prepare::Queries;
  std::size_t i = 0, n = 0, probes = 0, intervals = 0, closed = 0;
  double gap = 0, ratio = 0;
  for (auto _ : state) {
    const Case& c = cs[i++ % cs.size()];
    const GeneralizedDepth2 r = generalized_depth(c.P, c.Q, c.t, o);
    ++n, probes += r.probes, intervals += r.intervals, closed += r.converged;
    gap += (r.upper_bound - r.lower_bound) / r.upper_bound;
    ratio += r.depth / r.sigma;
  }
  state.counters["pairs"] = double(cs.size());
  state.counters["probes"] = double(probes) / double(n);
  state.counters["intervals"] = double(intervals) / double(n);
  state.counters["gap"] = gap / double(n);
  state.counters["closed"] = double(closed) / double(n);
  state.counters["pdg/sigma"] = ratio / double(n);
}

// ---- 3D mesh pairs ----

struct Case3 {
  Shape3 P, Q;
  Pose3 pose_q;
};

Shape3 mesh_of(const mesh3_test::Gen& g, const char* name) {
  return Shape3::from_mesh(Mesh3::validate(mesh3_test::to_file(g, name), name));
}

std::vector<Case3> cases3(int kind) {
  std::vector<Case3> out;
  if (kind == 0) {
    std::set<mesh3_test::Voxel> v;
    for (int x = 0; x < 3; ++x)
      for (int y = 0; y < 3; ++y) v.insert({x, y, 0});
    v.insert({0, 2, 1}), v.insert({2, 0, 1});
    auto map = [](mesh3_test::Gen g, const std::array<std::vector<double>, 3>& grid) {
      for (Vec3& p : g.points)
        for (int a = 0; a < 3; ++a) p[a] = grid[a][static_cast<std::size_t>(p[a])];
      return g;
    };
    const Shape3 P = mesh_of(map(mesh3_test::polycube(v), {{{-7, -2, 2, 7}, {-3, -1, 1, 3}, {-2, -1, 3}}}), "P");
    const Shape3 Q = mesh_of(map(mesh3_test::cube(), {{{-6, 6}, {-1, 1}, {0, 2}}}), "Q");
    for (double phi : {-0.05, -0.1, -0.2})
      out.push_back({P, Q, Pose3(Eigen::Quaterniond(Eigen::AngleAxisd(phi, Vec3::UnitZ())), Vec3::Zero())});
    return out;
  }
  std::mt19937_64 rng(18);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int attempt = 0; out.size() < 4 && attempt < 200; ++attempt) {
    try {
      const Shape3 P = mesh_of(mesh3_test::polycube(mesh3_test::random_polycube(rng, 6)), "P");
      const Shape3 Q = mesh_of(mesh3_test::polycube(mesh3_test::random_polycube(rng, 4)), "Q");
      const Pose3 pq(Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)), Vec3(0.5 + u(rng), 0.5 + u(rng), 0.5 * u(rng)));
      if (!P.is_convex() && Pair3(P, Q).overlapping(Pose3(), pq)) out.push_back({P, Q, pq});
    } catch (const InvalidInput&) {  // a non-manifold union
    }
  }
  return out;
}

void BM_Sigma3Mesh(benchmark::State& state) {
  const auto cs = cases3(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    const Case3& c = cs[i++ % cs.size()];
    benchmark::DoNotOptimize(Pair3(c.P, c.Q).minimum(Pose3(), c.pose_q));
  }
  state.counters["pairs"] = double(cs.size());
}

void BM_Generalized3Mesh(benchmark::State& state) {
  const auto cs = cases3(static_cast<int>(state.range(0)));
  std::size_t i = 0, n = 0, probes = 0, closed = 0;
  double gap = 0, ratio = 0;
  for (auto _ : state) {
    const Case3& c = cs[i++ % cs.size()];
    const GeneralizedDepth3 r = generalized_depth(c.P, Pose3(), c.Q, c.pose_q);
    ++n, probes += r.probes, closed += r.converged;
    gap += (r.upper_bound - r.lower_bound) / r.upper_bound;
    ratio += r.depth / r.sigma;
  }
  state.counters["pairs"] = double(cs.size());
  state.counters["probes"] = double(probes) / double(n);
  state.counters["gap"] = gap / double(n);
  state.counters["closed"] = double(closed) / double(n);
  state.counters["pdg/sigma"] = ratio / double(n);
}

}  // namespace

BENCHMARK(BM_Sigma3Mesh)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_Generalized3Mesh)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_Sigma)->ArgsProduct({{0, 1, 2}, {0, 1}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Generalized)->ArgsProduct({{0, 1, 2}, {0}})->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_Generalized)->ArgsProduct({{0}, {1}})->Unit(benchmark::kMillisecond)->Iterations(16);
BENCHMARK_MAIN();
