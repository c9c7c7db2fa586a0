// Trajectories (issue 18 item 3, issue 16 item 6; survey §3.3 coherent motion): σ at every pose of
// a path, warm-started from the previous pose, against a cold query per pose — same inputs, same
// run; the answers are identical bit for bit (tests/front/test_warm3.cpp), so only time differs.
//
//   motion3/<step>/{cold,warm}   the 60 shared real hulls (../shared/data/hulls, 4–~60 vertices),
//                                pairs (i, i+7); per pair a 64-pose path of Q around P (start
//                                overlapping, each step a translation of step·r in a random
//                                direction and a rotation of step_deg about a random axis; r =
//                                P's radius; drifting out is pulled back). Pair3::minimum cold vs
//                                Pair3::minimum(…, WarmStart3&). Steps: small (0.002 r, 0.2°),
//                                medium (0.02 r, 2°), large (0.2 r, 20°), jump (independent poses).
//   motion3/ellipsoids<n>/small/{cold,warm}  the same small steps on 15 hulls of n random points
//                                on ellipsoids (semi-axes in [0.5, 1.5]), n = 100, 1000, 10000.
//   motion2/<angles>/{cold,warm} nesting pieces (shirts, albano: non-convex), pairs (i, i+1), a
//                                256-placement path per pair (small steps); angles constant,
//                                changing every 16 placements among 0/90/180/270, or a new random
//                                angle at every placement. pendepth::trajectory warm (one Pair2
//                                per run of equal angles) vs cold (a Pair2 per placement).
// Counters: us_per_query, supports (3D: support queries per query).
#include <pendepth/pendepth.hpp>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include "hulls3.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace pendepth;

// ---- 3D ---------------------------------------------------------------------------------------
struct Path3 {
  int pair = 0;
  std::vector<Pose3> poses;
};
struct Case3 {
  std::vector<Pair3> pairs;
  std::vector<Path3> paths;
  std::size_t queries = 0;
};

using pendepth::bench::centroid;

const std::vector<Shape3>& hulls() {
  static const std::vector<Shape3> H = [] {
    std::vector<Shape3> h;
    for (const auto& f : pendepth::test3::shared_hull_files()) h.push_back(Shape3::from_file(f, f));
    return h;
  }();
  return H;
}

// n > 0: instead of the real hulls, 8 pairs of hulls of n random points on ellipsoids.
std::vector<Shape3> ellipsoid_hulls(std::size_t n) {
  std::mt19937_64 rng(0x7a3 + n);
  std::uniform_real_distribution<double> U(-1, 1);
  std::normal_distribution<double> G;
  std::vector<Shape3> h;
  for (int k = 0; k < 15; ++k) {
    const Vec3 axes(1 + 0.5 * U(rng), 1 + 0.5 * U(rng), 1 + 0.5 * U(rng));
    std::vector<Vec3> pts;
    for (std::size_t i = 0; i < n; ++i) {
      Vec3 v(G(rng), G(rng), G(rng));
      pts.push_back(v.normalized().cwiseProduct(axes));
    }
    h.push_back(Shape3::hull(pts, "ellipsoid"));
  }
  return h;
}

Case3 make_case3(double step, double step_deg, std::size_t n = 0) {
  const std::vector<Shape3> E = n ? ellipsoid_hulls(n) : std::vector<Shape3>{};
  const auto& H = n ? E : hulls();
  Case3 c;
  std::mt19937_64 rng(0x7a1);
  std::uniform_real_distribution<double> U(-1, 1);
  std::normal_distribution<double> G;
  auto unit = [&] {
    Vec3 v(G(rng), G(rng), G(rng));
    return v.normalized();
  };
  for (std::size_t i = 0; i < H.size(); ++i) {
    const Shape3 &P = H[i], &Q = H[(i + 7) % H.size()];
    c.pairs.emplace_back(P, Q);
    const Vec3 cp = centroid(P.polytope()), cq = centroid(Q.polytope());
    double r = 0;
    for (const Vec3& v : P.polytope().vertices()) r = std::max(r, (v - cp).norm());
    Path3 path;
    path.pair = static_cast<int>(i);
    Eigen::Quaterniond rot(Eigen::AngleAxisd(3.1 * U(rng), unit()));
    Vec3 off = 0.3 * r * Vec3(U(rng), U(rng), U(rng));
    for (int k = 0; k < 64; ++k) {
      if (step_deg < 0) {  // independent poses
        rot = Eigen::Quaterniond(Eigen::AngleAxisd(3.1 * U(rng), unit()));
        off = 0.3 * r * Vec3(U(rng), U(rng), U(rng));
      } else {
        off += step * r * unit();
        if (off.norm() > 0.4 * r) off *= 0.5;
        rot = (Eigen::Quaterniond(Eigen::AngleAxisd(step_deg * M_PI / 180, unit())) * rot).normalized();
      }
      path.poses.emplace_back(rot, cp + off - rot.toRotationMatrix() * cq);
    }
    c.queries += path.poses.size();
    c.paths.push_back(std::move(path));
  }
  return c;
}

void bm_motion3(benchmark::State& state, double step, double step_deg, bool warm, std::size_t n) {
  const Case3 c = make_case3(step, step_deg, n);
  std::size_t supports = 0, queries = 0;
  const Pose3 pp;
  for (auto _ : state) {
    for (const Path3& path : c.paths) {
      const Pair3& pair = c.pairs[path.pair];
      WarmStart3 ws;
      for (const Pose3& pq : path.poses) {
        const Depth3 d = warm ? pair.minimum(pp, pq, ws) : pair.minimum(pp, pq);
        benchmark::DoNotOptimize(d.depth);
        supports += d.candidates;
      }
    }
    queries += c.queries;
  }
  state.counters["us_per_query"] = benchmark::Counter(
      static_cast<double>(queries) * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["supports"] = static_cast<double>(supports) / static_cast<double>(std::max<std::size_t>(queries, 1));
  state.SetItemsProcessed(static_cast<int64_t>(queries));
}

// ---- 2D ---------------------------------------------------------------------------------------
std::vector<Shape2> nesting_pieces(const std::string& instance) {
  std::ifstream in(std::string(PENDEPTH_SHARED_DATA) + "/nesting/" + instance + ".json");
  nlohmann::json j;
  in >> j;
  std::vector<Shape2> out;
  for (const auto& item : j["items"]) {
    std::vector<Vec2> r;
    for (const auto& p : item["shape"]["data"]) r.emplace_back(p[0].get<double>(), p[1].get<double>());
    if (r.size() > 1 && r.front() == r.back()) r.pop_back();
    out.emplace_back(r, std::vector<std::vector<Vec2>>{}, instance);
  }
  return out;
}

struct Path2 {
  Shape2 P, Q;
  std::vector<Placement2> poses;
};

// angles: 0 constant, 1 every 16 placements among quarter turns, 2 a random angle each time.
std::vector<Path2> make_case2(int angles) {
  std::vector<Path2> out;
  std::mt19937_64 rng(0x7a2);
  std::uniform_real_distribution<double> U(-1, 1);
  for (const char* inst : {"shirts", "albano"}) {
    const auto pieces = nesting_pieces(inst);
    for (std::size_t i = 0; i + 1 < pieces.size() && i < 6; ++i) {
      Path2 p{pieces[i], pieces[i + 1], {}};
      double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
      const auto rings = p.P.rings();
      for (const Vec2& v : rings[0])
        for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
      const double r = 0.5 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
      Vec2 c(0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])), t = c;
      double deg = 0;
      for (int k = 0; k < 256; ++k) {
        t += 0.01 * r * Vec2(U(rng), U(rng));
        if ((t - c).norm() > 0.5 * r) t = c;
        if (angles == 1 && k % 16 == 15) deg = 90.0 * std::floor(2 + 2 * U(rng));
        if (angles == 2) deg = 180 * U(rng);
        p.poses.push_back({t, deg});
      }
      out.push_back(std::move(p));
    }
  }
  return out;
}

void bm_motion2(benchmark::State& state, int angles, bool warm) {
  const auto paths = make_case2(angles);
  std::size_t queries = 0;
  for (auto _ : state) {
    for (const Path2& p : paths) {
      const auto r = trajectory(p.P, p.Q, p.poses, warm);
      benchmark::DoNotOptimize(r.data());
      queries += r.size();
    }
  }
  state.counters["us_per_query"] = benchmark::Counter(
      static_cast<double>(queries) * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetItemsProcessed(static_cast<int64_t>(queries));
}

const int registered = [] {
  struct Step {
    const char* name;
    double step, deg;
  };
  for (const Step s : {Step{"small", 0.002, 0.2}, Step{"medium", 0.02, 2}, Step{"large", 0.2, 20}, Step{"jump", 0, -1}})
    for (bool warm : {false, true})
      benchmark::RegisterBenchmark((std::string("motion3/") + s.name + (warm ? "/warm" : "/cold")).c_str(), bm_motion3,
                                   s.step, s.deg, warm, std::size_t{0})
          ->Unit(benchmark::kMillisecond);
  for (std::size_t n : {100, 1000, 10000})
    for (bool warm : {false, true})
      benchmark::RegisterBenchmark(
          ("motion3/ellipsoids" + std::to_string(n) + "/small" + (warm ? "/warm" : "/cold")).c_str(), bm_motion3, 0.002,
          0.2, warm, n)
          ->Unit(benchmark::kMillisecond);
  const char* names[] = {"constant", "quarter-turns", "random"};
  for (int a = 0; a < 3; ++a)
    for (bool warm : {false, true})
      benchmark::RegisterBenchmark((std::string("motion2/") + names[a] + (warm ? "/warm" : "/cold")).c_str(),
                                   bm_motion2, a, warm)
          ->Unit(benchmark::kMillisecond);
  return 0;
}();

}  // namespace

BENCHMARK_MAIN();
