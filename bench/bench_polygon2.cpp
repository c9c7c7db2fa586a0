// Benchmark: a simple polygon P (n vertices, holes allowed) against a convex Q (m vertices), DHS §4
// — pendepth's implicit structure against the explicit Minkowski sums of CGAL (reduced
// convolution) and Clipper (MinkowskiSum), each followed by a scan of the explicit sum per query,
// on the same inputs in the same run (docs/design.md §6).
//
// Benchmark names are <what>/<implementation>/<shape>/<n>/<m>:
//   build/pendepth        PolygonDepth2 construction: triangulation, convolved triangles, union
//                         boundary and its ray-shooting index (DHS §4.1, §4.3)
//   build/cgal            CGAL::minkowski_sum_2(P, −Q) with Epeck (reduced convolution, the default
//                         of CGAL 5.5), then the sum's vertices rounded to doubles for the scans
//   build/clipper         ClipperLib::MinkowskiSum(−Q, rings of P, closed) on coordinates scaled
//                         by 2^20 and rounded to integers (Clipper's grid), union included
//   sigma_d/pendepth      PolygonDepth2::along, the fast σ_d path (DHS §4.3)
//   sigma_d/pendepth_scan polygon2::along_scan (src/polygon2/query_impl.hpp), every piece of ∂O, O(n log m) (DHS §4.2)
//   sigma/pendepth        PolygonDepth2::minimum, σ (DHS §4.2, Lemma 4.3)
//   build/pendepth_fixed8 PolygonDirectionSet for 8 directions (DHS §6); counter bytes_per_direction
//   sigma_d/pendepth_fixed PolygonDirectionSet::along, query i along direction i mod 8
//   validate/pendepth     Polygon construction (validation + normal form; step 2 is
//                         polygon2::check_edges of src/polygon2/edge_sweep.cpp: box sweep with
//                         an O(N) budget, then the O(N log N) Shamos–Hoey sweep)
//   validate/edge_sweep   polygon2::check_edges_sweep alone (Shamos–Hoey)
//   validate/box_sweep    polygon2::check_edges_boxes without budget (the former step 2: every
//                         pair of edges with overlapping boxes checked, O(N log N + K))
//   sigma_d/cgal_scan, sigma/cgal_scan, sigma_d/clipper_scan, sigma/clipper_scan
//                         scans of an explicit sum: point in polygon (crossing number with the
//                         exact orientation predicate on the doubles), then the nearest edge
//                         (σ) or the first edge the ray leaves through (σ_d), in double
// Shapes: `star` (regular-ish star-shaped ring, radii in [60, 100], Q of diameter ≈ 10), `comb`
// (n/4 teeth of width 1 and height 20 with gaps of 3, Q of diameter ≈ 2 that fits the gaps) and
// `spiral` (thick Archimedean spiral of 5 turns, arms 3 wide and 27 apart, Q of diameter ≈ 10;
// build/pendepth only, for bench/plot_scaling.py).
// CGAL's reduced convolution crashes on polygons with holes in Debian's CGAL 5.5.1 (in the hole
// filter), so all shapes here are hole-free; pendepth handles holes (tests/polygon2).
// Queries: kQueries placements t = p − centroid(Q) with p uniform in P (so nearly all overlap) and
// random unit directions, generated outside the timed loops from a fixed seed.
// The explicit sums are M = P ⊕ (−Q); pendepth answers on O (equal to int M except on slits of
// touching placements, DHS Lemma 2.1's non-degeneracy), so the scans' answers are compared with
// pendepth's and the largest difference and the count above 1e-6 are exported as counters
// (Clipper's differ by its grid, ≈ 1e-6).
// Peers run only while n·m ≤ PENDEPTH_BENCH_PEER_BUDGET (CGAL, default 10⁵: its build takes
// seconds beyond) and n·m ≤ PENDEPTH_BENCH_CLIPPER_BUDGET (Clipper, default 10⁴: 100 × 100 already
// takes ~1 s). Sizes: PENDEPTH_BENCH_N and
// PENDEPTH_BENCH_M (comma lists; defaults 10,100,1000,10000,100000 and 4,16,100,1000).
// bench/run_polygon2.sh prints the tables of docs/benchmarks.md from this program's JSON output.
#include <benchmark/benchmark.h>
#include <pendepth/depth2_polygon_convex.hpp>

#include "polygon2/edge_sweep.hpp"
#include "polygon2/query_impl.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/minkowski_sum_2.h>

#ifdef PENDEPTH_BENCH_CLIPPER
#include <clipper.hpp>
#endif

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "common.hpp"
#include "explicit_sum.hpp"

namespace {

using pendepth::ConvexPolygon;
using pendepth::Polygon;
using pendepth::PolygonDepth2;
using pendepth::Vec2;
namespace pb = pendepth::bench;
using pb::env_sizes;
using pb::crossings;
using pb::ExplicitSum;


// ---- inputs ----

std::vector<Vec2> star_ring(std::size_t n, pb::Rng& rng) {
  std::vector<Vec2> r(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double th = 2 * std::numbers::pi * (double(k) + rng.uniform(0, 0.9)) / double(n);
    const double rad = rng.uniform(60, 100);
    r[k] = Vec2(rad * std::cos(th), rad * std::sin(th));
  }
  return r;
}

// n/4 teeth (4 vertices each): base [0, W] × [0, 2], teeth of width 1 and height 20, gaps of 3.
std::vector<Vec2> comb_ring(std::size_t n) {
  const std::size_t teeth = std::max<std::size_t>(2, n / 4);
  const double tw = 1, gw = 3, h = 20, base = 2;
  const double W = double(teeth) * tw + double(teeth - 1) * gw;
  std::vector<Vec2> r{{0, 0}, {W, 0}};
  for (std::size_t k = teeth; k-- > 0;) {
    const double x0 = double(k) * (tw + gw), x1 = x0 + tw;
    r.push_back({x1, base + h});
    r.push_back({x0, base + h});
    if (k > 0) {
      r.push_back({x0, base});
      r.push_back({x0 - gw, base});
    }
  }
  return r;
}

// Thick Archimedean spiral (as bench_nonconvex2's): 5 turns, centre line r = 20 + 30·θ/2π,
// half-width 1.5 (arms 27 apart), about n vertices.
std::vector<Vec2> spiral_ring(std::size_t n) {
  const std::size_t steps = std::max<std::size_t>(2, n / 2 - 1);
  std::vector<Vec2> outer, inner;
  const double turns = 5, b = 30 / (2 * std::numbers::pi), w = 1.5;
  for (std::size_t k = 0; k <= steps; ++k) {
    const double th = turns * 2 * std::numbers::pi * double(k) / double(steps), rad = 20 + b * th;
    outer.emplace_back((rad + w) * std::cos(th), (rad + w) * std::sin(th));
    inner.emplace_back((rad - w) * std::cos(th), (rad - w) * std::sin(th));
  }
  std::vector<Vec2> ring(inner.begin(), inner.end());
  ring.insert(ring.end(), outer.rbegin(), outer.rend());
  return ring;
}

ConvexPolygon scaled_q(std::size_t m, double scale, pb::Rng& rng) {
  const ConvexPolygon Q0 = pb::random_ellipse_polygon(m, rng, "Q");
  std::vector<Vec2> v;
  for (const Vec2& p : Q0.vertices()) v.push_back(scale * p);
  return ConvexPolygon(v, "Q");
}


using K = CGAL::Exact_predicates_exact_constructions_kernel;

ExplicitSum cgal_sum(const Polygon& P, const ConvexPolygon& Q, std::size_t* vertices = nullptr) {
  CGAL::Polygon_2<K> cp, cq;
  for (const Vec2& p : P.ring(0)) cp.push_back(K::Point_2(p.x(), p.y()));
  // −Q counter-clockwise (a point reflection keeps the orientation).
  for (const Vec2& q : Q.vertices()) cq.push_back(K::Point_2(-q.x(), -q.y()));
  const CGAL::Polygon_with_holes_2<K> sum = CGAL::minkowski_sum_2(cp, cq);
  ExplicitSum out;
  auto add = [&](const CGAL::Polygon_2<K>& ring) {
    std::vector<Vec2> r;
    for (auto it = ring.vertices_begin(); it != ring.vertices_end(); ++it)
      r.emplace_back(CGAL::to_double(it->x()), CGAL::to_double(it->y()));
    out.add_ring(r);
  };
  add(sum.outer_boundary());
  for (auto h = sum.holes_begin(); h != sum.holes_end(); ++h) add(*h);
  if (vertices) *vertices = out.vertices();
  return out;
}

#ifdef PENDEPTH_BENCH_CLIPPER
constexpr double kClipperScale = 1 << 20;

ExplicitSum clipper_sum(const Polygon& P, const ConvexPolygon& Q) {
  auto grid = [](double x) { return ClipperLib::cInt(std::llround(x * kClipperScale)); };
  ClipperLib::Path pattern;
  for (const Vec2& q : Q.vertices()) pattern.emplace_back(grid(-q.x()), grid(-q.y()));
  ClipperLib::Paths paths;
  for (std::size_t k = 0; k < P.ring_count(); ++k) {
    paths.emplace_back();
    for (const Vec2& p : P.ring(k)) paths.back().emplace_back(grid(p.x()), grid(p.y()));
  }
  // Closed paths: Clipper unions the swept quads with the rings translated by pattern[0], which
  // fills P's interior (P ⊕ B = (∂P ⊕ B) ∪ (P + b0)).
  ClipperLib::Paths solution;
  ClipperLib::MinkowskiSum(pattern, paths, solution, true);
  ExplicitSum out;
  for (const auto& path : solution) {
    std::vector<Vec2> r;
    for (const auto& p : path) r.emplace_back(double(p.X) / kClipperScale, double(p.Y) / kClipperScale);
    out.add_ring(r);
  }
  return out;
}
#endif

// ---- one case: shapes, queries, and lazily built structures ----

struct Case {
  std::string shape;
  std::size_t n = 0, m = 0;
  std::optional<Polygon> P;
  std::optional<ConvexPolygon> Q;
  std::vector<Vec2> t, d;
  std::unique_ptr<PolygonDepth2> pd;
  std::unique_ptr<pendepth::PolygonDirectionSet> fixed;
  std::unique_ptr<ExplicitSum> cgal, clipper;
  std::size_t cgal_vertices = 0;

  Case(std::string s, std::size_t n_, std::size_t m_) : shape(std::move(s)), n(n_), m(m_) {
    pb::Rng rng(0x9e3779b9u ^ (n * 1000003u) ^ (m * 7919u) ^ (shape == "comb" ? 0x5bd1e995u : 0u));
    const std::vector<Vec2> ring = shape == "comb" ? comb_ring(n) : shape == "spiral" ? spiral_ring(n) : star_ring(n, rng);
    P.emplace(Polygon::simple(ring, "P"));
    this->n = P->size();
    Q.emplace(scaled_q(m, shape == "comb" ? 0.7 : 5.0, rng));
    Vec2 lo = ring[0], hi = ring[0], c(0, 0);
    for (const Vec2& p : ring) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    for (const Vec2& q : Q->vertices()) c += q;
    c /= double(Q->size());
    const std::vector<Vec2> outer(P->ring(0).begin(), P->ring(0).end());
    while (t.size() < pb::kQueries) {
      const Vec2 p(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()));
      if (crossings(outer, p) % 2 == 0) continue;
      t.push_back(p - c);
      const double a = rng.uniform(0, 2 * std::numbers::pi);
      d.emplace_back(std::cos(a), std::sin(a));
    }
  }
  const PolygonDepth2& depth() {
    if (!pd) pd = std::make_unique<PolygonDepth2>(*P, *Q);
    return *pd;
  }
  // 8 fixed directions: the first 8 query directions.
  std::vector<Vec2> fixed_directions() const { return std::vector<Vec2>(d.begin(), d.begin() + 8); }
  const pendepth::PolygonDirectionSet& direction_set() {
    if (!fixed) fixed = std::make_unique<pendepth::PolygonDirectionSet>(depth(), fixed_directions());
    return *fixed;
  }
};

std::map<std::tuple<std::string, std::size_t, std::size_t>, std::unique_ptr<Case>>& cases() {
  static std::map<std::tuple<std::string, std::size_t, std::size_t>, std::unique_ptr<Case>> c;
  return c;
}

Case& get_case(const std::string& shape, std::size_t n, std::size_t m) {
  auto& slot = cases()[{shape, n, m}];
  if (!slot) slot = std::make_unique<Case>(shape, n, m);
  return *slot;
}

void set_size_counters(benchmark::State& state, const Case& c) {
  state.counters["n"] = double(c.n);
  state.counters["m"] = double(c.m);
}

// ---- benchmarks ----

void BM_build_pendepth(benchmark::State& state, std::string shape, std::size_t n, std::size_t m) {
  Case& c = get_case(shape, n, m);
  for (auto _ : state) {
    PolygonDepth2 pd(*c.P, *c.Q);
    benchmark::DoNotOptimize(pd.triangle_count());
  }
  set_size_counters(state, c);
  const auto st = c.depth().boundary_stats();
  state.counters["triangles"] = double(c.depth().triangle_count());
  state.counters["boundary_vertices"] = double(st.vertices);
  state.counters["boundary_segments"] = double(st.segments);
  state.counters["boundary_arcs"] = double(st.arcs);
  state.counters["bytes"] = double(st.bytes);
}

void BM_build_cgal(benchmark::State& state, std::string shape, std::size_t n, std::size_t m) {
  Case& c = get_case(shape, n, m);
  std::size_t vertices = 0;
  for (auto _ : state) {
    ExplicitSum s = cgal_sum(*c.P, *c.Q, &vertices);
    benchmark::DoNotOptimize(s.vertices());
  }
  set_size_counters(state, c);
  state.counters["sum_vertices"] = double(vertices);
}

#ifdef PENDEPTH_BENCH_CLIPPER
void BM_build_clipper(benchmark::State& state, std::string shape, std::size_t n, std::size_t m) {
  Case& c = get_case(shape, n, m);
  std::size_t vertices = 0;
  for (auto _ : state) {
    ExplicitSum s = clipper_sum(*c.P, *c.Q);
    vertices = s.vertices();
    benchmark::DoNotOptimize(vertices);
  }
  set_size_counters(state, c);
  state.counters["sum_vertices"] = double(vertices);
}
#endif

void BM_build_fixed(benchmark::State& state, std::string shape, std::size_t n, std::size_t m) {
  Case& c = get_case(shape, n, m);
  const PolygonDepth2& pd = c.depth();
  std::size_t bytes = 0;
  for (auto _ : state) {
    pendepth::PolygonDirectionSet set(pd, c.fixed_directions());
    bytes = set.bytes();
    benchmark::DoNotOptimize(bytes);
  }
  set_size_counters(state, c);
  state.counters["bytes_per_direction"] = double(bytes) / 8;
}

void BM_query_fixed(benchmark::State& state, std::string shape, std::size_t n, std::size_t m) {
  Case& c = get_case(shape, n, m);
  const pendepth::PolygonDirectionSet& set = c.direction_set();
  std::size_t i = 0;
  double sum = 0;
  for (auto _ : state) {
    sum += set.along(c.t[i], i & 7).depth;
    i = pb::next_query(i);
  }
  benchmark::DoNotOptimize(sum);
  set_size_counters(state, c);
}

enum class Query { AlongFast, AlongScan, Minimum };

void BM_query_pendepth(benchmark::State& state, std::string shape, std::size_t n, std::size_t m, Query q) {
  Case& c = get_case(shape, n, m);
  const PolygonDepth2& pd = c.depth();
  std::size_t i = 0;
  double sum = 0;
  for (auto _ : state) {
    const pendepth::Depth2 r = q == Query::AlongFast   ? pd.along(c.t[i], c.d[i])
                               : q == Query::AlongScan ? pendepth::polygon2::along_scan(pd, c.t[i], c.d[i])
                                                       : pd.minimum(c.t[i]);
    sum += r.depth;
    i = pb::next_query(i);
  }
  benchmark::DoNotOptimize(sum);
  set_size_counters(state, c);
}

// A scan of an explicit sum; before timing, its answers are compared with pendepth's.
void BM_query_scan(benchmark::State& state, std::string shape, std::size_t n, std::size_t m, bool cgal, bool minimum) {
  Case& c = get_case(shape, n, m);
  std::unique_ptr<ExplicitSum>& slot = cgal ? c.cgal : c.clipper;
  if (!slot) {
#ifdef PENDEPTH_BENCH_CLIPPER
    slot = std::make_unique<ExplicitSum>(cgal ? cgal_sum(*c.P, *c.Q) : clipper_sum(*c.P, *c.Q));
#else
    slot = std::make_unique<ExplicitSum>(cgal_sum(*c.P, *c.Q));
#endif
  }
  const ExplicitSum& s = *slot;
  const PolygonDepth2& pd = c.depth();
  double max_diff = 0, overlapping = 0, differ = 0;
  for (std::size_t k = 0; k < pb::kQueries; k += 4) {
    const double want = minimum ? pd.minimum(c.t[k]).depth : pd.along(c.t[k], c.d[k]).depth;
    const double got = minimum ? s.sigma(c.t[k]) : s.sigma_d(c.t[k], c.d[k]);
    max_diff = std::max(max_diff, std::abs(got - want));
    differ += std::abs(got - want) > 1e-6;
    overlapping += want > 0;
  }
  std::size_t i = 0;
  double sum = 0;
  for (auto _ : state) {
    sum += minimum ? s.sigma(c.t[i]) : s.sigma_d(c.t[i], c.d[i]);
    i = pb::next_query(i);
  }
  benchmark::DoNotOptimize(sum);
  set_size_counters(state, c);
  state.counters["sum_vertices"] = double(s.vertices());
  state.counters["max_abs_diff"] = max_diff;
  state.counters["differ"] = differ;
  state.counters["checked"] = double(pb::kQueries / 4);
  state.counters["overlapping"] = overlapping;
}

void BM_validate(benchmark::State& state, std::string shape, std::size_t n, std::size_t m, int impl) {
  Case& c = get_case(shape, n, m);
  const auto r = c.P->ring(0);
  const std::vector<std::vector<Vec2>> rings{std::vector<Vec2>(r.begin(), r.end())};
  for (auto _ : state) {
    if (impl == 0) {
      Polygon P(rings, "P");
      benchmark::DoNotOptimize(P.size());
    } else if (impl == 1) {
      pendepth::polygon2::check_edges_sweep(rings, "P");
    } else {
      pendepth::polygon2::check_edges_boxes(rings, "P", std::numeric_limits<std::size_t>::max());
    }
  }
  state.counters["n"] = double(c.n);
}

}  // namespace

int main(int argc, char** argv) {
  const auto ns = env_sizes("PENDEPTH_BENCH_N", {10, 100, 1000, 10000, 100000});
  const auto ms = env_sizes("PENDEPTH_BENCH_M", {4, 16, 100, 1000});
  const char* budget_env = std::getenv("PENDEPTH_BENCH_PEER_BUDGET");
  const double budget = budget_env && *budget_env ? std::atof(budget_env) : 1e5;
  const char* clipper_env = std::getenv("PENDEPTH_BENCH_CLIPPER_BUDGET");
  const double clipper_budget = clipper_env && *clipper_env ? std::atof(clipper_env) : 1e4;
  for (const std::string shape : {"star", "comb", "spiral"}) {
    for (std::size_t n : ns) {
      for (std::size_t m : ms) {
        const std::string tag = shape + "/" + std::to_string(n) + "/" + std::to_string(m);
        const bool peers = double(n) * double(m) <= budget;
        const bool clipper = double(n) * double(m) <= clipper_budget;
        (void)clipper;
        benchmark::RegisterBenchmark(("build/pendepth/" + tag).c_str(), BM_build_pendepth, shape, n, m)
            ->Unit(benchmark::kMicrosecond);
        if (m == ms.front()) {
          const std::string vtag = shape + "/" + std::to_string(n);
          const char* impls[] = {"pendepth", "edge_sweep", "box_sweep"};
          for (int impl = 0; impl < 3; ++impl)
            benchmark::RegisterBenchmark(("validate/" + std::string(impls[impl]) + "/" + vtag).c_str(), BM_validate,
                                         shape, n, m, impl)
                ->Unit(benchmark::kMillisecond);
        }
        if (shape == "spiral") continue;  // the scaling plot's third family: the build only
        if (peers) {
          benchmark::RegisterBenchmark(("build/cgal/" + tag).c_str(), BM_build_cgal, shape, n, m)
              ->Unit(benchmark::kMicrosecond);
#ifdef PENDEPTH_BENCH_CLIPPER
          if (clipper)
            benchmark::RegisterBenchmark(("build/clipper/" + tag).c_str(), BM_build_clipper, shape, n, m)
                ->Unit(benchmark::kMicrosecond);
#endif
        }
        benchmark::RegisterBenchmark(("sigma_d/pendepth/" + tag).c_str(), BM_query_pendepth, shape, n, m,
                                     Query::AlongFast);
        benchmark::RegisterBenchmark(("sigma_d/pendepth_scan/" + tag).c_str(), BM_query_pendepth, shape, n, m,
                                     Query::AlongScan);
        benchmark::RegisterBenchmark(("sigma/pendepth/" + tag).c_str(), BM_query_pendepth, shape, n, m,
                                     Query::Minimum);
        benchmark::RegisterBenchmark(("build/pendepth_fixed8/" + tag).c_str(), BM_build_fixed, shape, n, m)
            ->Unit(benchmark::kMicrosecond);
        benchmark::RegisterBenchmark(("sigma_d/pendepth_fixed/" + tag).c_str(), BM_query_fixed, shape, n, m);
        if (peers) {
          for (bool minimum : {false, true}) {
            const std::string q = minimum ? "sigma" : "sigma_d";
            benchmark::RegisterBenchmark((q + "/cgal_scan/" + tag).c_str(), BM_query_scan, shape, n, m, true, minimum);
#ifdef PENDEPTH_BENCH_CLIPPER
            if (clipper)
              benchmark::RegisterBenchmark((q + "/clipper_scan/" + tag).c_str(), BM_query_scan, shape, n, m, false,
                                           minimum);
#endif
          }
        }
      }
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
