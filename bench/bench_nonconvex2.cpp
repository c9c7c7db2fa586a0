// Benchmark: two simple non-convex polygons (issue 5, DHS §6, survey §2) — pendepth's per-pair
// no-fit polygon NoFitPolygon2 and its per-query PairDepth2 against the explicit Minkowski sums of
// CGAL (reduced convolution) and Clipper (MinkowskiSum), each followed by a scan of the explicit
// sum per query, on the same inputs in the same run (docs/design.md §6).
//
// Benchmark names are <what>/<implementation>/<case>/<n>/<m> (case: albano, shirts, trousers, star):
//   build/pendepth      NoFitPolygon2 construction (reduced convolution cut exactly by the open
//                       convex pair sums, rings, slits, points, query index)
//   build/cgal          CGAL::minkowski_sum_2(P, −Q) with Epeck (reduced convolution, the default
//                       of CGAL 5.5), then the sum's vertices rounded to doubles for the scans
//   build/clipper       ClipperLib::MinkowskiSum(pattern −Q, path P, closed) on coordinates scaled
//                       to Clipper's integer grid, then unioned (non-zero) with P − q0 and −Q + p0:
//                       the swept quads cover ∂P ⊕ ∂(−Q) only, and A ⊕ B = (∂A ⊕ ∂B) ∪ (A + b) ∪
//                       (a + B) for simple polygons, as Clipper's documentation of MinkowskiSum
//                       suggests for filled results
//   sigma/pendepth_nfp, sigma_d/pendepth_nfp    NoFitPolygon2::minimum / ::along (the full Depth2:
//                       depth, translation, normal, witnesses, features)
//   sigma/pendepth_nfp_lean, sigma_d/pendepth_nfp_lean  NoFitPolygon2::depth_value /
//                       ::directional_depth_value (depth and translation only, the same bits)
//   sigma/pendepth_pair, sigma_d/pendepth_pair  PairDepth2::minimum / ::along (no NFP)
//   sigma/pendepth_pair2, sigma_d/pendepth_pair2  the front door: Pair2(P, Q, Prepare::Full)
//                       ::minimum / ::along (its engine: the no-fit polygon when neither piece is
//                       convex, the polygon × convex structure otherwise)
//   overlap/<impl>      the overlap test alone (NoFitPolygon2 / Pair2 / PairDepth2 ::overlapping,
//                       the scan's even-odd location) on placements uniform in the no-fit
//                       polygon's box grown by 10%; items/s = overlap tests per second
//   sigma/cgal_scan, sigma_d/cgal_scan, sigma/clipper_scan, sigma_d/clipper_scan
//                       scans of an explicit sum: point in polygon (crossing number with the
//                       exact orientation predicate on the doubles), then the nearest edge (σ)
//                       or the first edge the ray crosses (σ_d), in double
// Cases:
//   <instance>          real pieces from ../shared/data/nesting (unrotated): every ordered pair
//                       of albano (64); of shirts, trousers, baldacci4, gardeyn2/4/6 every third
//                       ordered pair in row-major order, at most 24 (22 and 24 pairs). One benchmark
//                       iteration of a build builds every pair of the instance; the counter
//                       `pairs` gives the count, and the tables divide by it (per-pair times).
//                       Queries cycle through the pairs (each query on the next pair, so the
//                       structures of 22–64 pairs compete for the cache); with
//                       PENDEPTH_BENCH_QUERY_ORDER=pair the same queries run grouped by pair (the
//                       16–46 queries of one pair in a row: warm), for every implementation
//                       alike. n, m: the largest piece sizes.
//   <instance>-<kind>   build only: every ordered pair of the instance in which both pieces are
//                       convex (kind convex), one is (mixed) or neither is (nonconvex).
//   star/<n>/<m>        random star-shaped P (radii [60, 100]) and Q (radii [6, 10]), n = m.
//   scale-<family>/<n>/6  build only, one pair, once: P a comb (teeth and gaps 1 wide; comb45: rotated by 45°, rounded), a random
//                       star or a thick 5-turn spiral of about n vertices, Q an L-shape of 6
//                       (PENDEPTH_BENCH_SCALE_N, default 1000,3000,10000): the growth with n.
// Queries: kQueries placements t = p − centroid(Q) with p uniform in P (nearly all overlap) and
// random unit directions, generated outside the timed loops from a fixed seed. Before timing,
// the scans' and PairDepth2's answers are compared with NoFitPolygon2's; the largest difference
// and the count above 1e-6·scale are exported as counters (Clipper's differ by its grid).
// NoFitPolygon2 runs while n·m ≤ PENDEPTH_BENCH_NFP_BUDGET (default 10⁵: its build takes ~10 s at
// 300 × 300 stars at this commit; beyond, the checks use PairDepth2 as the reference).
// PairDepth2's σ runs while n·m ≤ PENDEPTH_BENCH_PAIR_SIGMA_BUDGET (default 10³: ~20 ms per query
// at 30 × 30 stars, far more beyond).
// Peers run while n·m ≤ PENDEPTH_BENCH_PEER_BUDGET (CGAL, default 10⁵) and n·m ≤
// PENDEPTH_BENCH_CLIPPER_BUDGET (Clipper, default 10⁴). Star sizes: PENDEPTH_BENCH_N (comma list,
// default 10,30,100,300; at 1000 NoFitPolygon2's build takes ~6 min CPU at this commit, and CGAL
// with its budget raised ran out of 23 GB of memory). bench/run_nonconvex2.sh prints the tables of docs/benchmarks.md.
#include <benchmark/benchmark.h>
#include <pendepth/depth2_polygon_polygon.hpp>
#include <pendepth/nfp2.hpp>
#include <pendepth/pendepth.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/minkowski_sum_2.h>

#ifdef PENDEPTH_BENCH_CLIPPER
#include <clipper.hpp>
#endif

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "common.hpp"
#include "explicit_sum.hpp"

namespace {

using pendepth::NoFitPolygon2;
using pendepth::PairDepth2;
using pendepth::Polygon;
using pendepth::Vec2;
namespace pb = pendepth::bench;
using pb::env_sizes;
using pb::crossings;
using pb::ExplicitSum;

constexpr double kCheckSeconds = 1.0;

// ---- inputs ----

std::vector<Vec2> star_ring(std::size_t n, double rmin, double rmax, pb::Rng& rng) {
  std::vector<Vec2> r(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double th = 2 * std::numbers::pi * (double(k) + rng.uniform(0, 0.9)) / double(n);
    const double rad = rng.uniform(rmin, rmax);
    r[k] = Vec2(rad * std::cos(th), rad * std::sin(th));
  }
  return r;
}

std::vector<std::vector<Vec2>> nesting_pieces(const std::string& instance) {
  std::ifstream in(std::string(PENDEPTH_SHARED_DATA) + "/nesting/" + instance + ".json");
  if (!in) throw std::runtime_error("cannot read nesting instance " + instance);
  nlohmann::json j;
  in >> j;
  std::vector<std::vector<Vec2>> out;
  for (const auto& item : j["items"]) {
    std::vector<Vec2> r;
    // Consecutive repeated vertices dropped (gardeyn6 has some; a polygon rejects them).
    for (const auto& p : item["shape"]["data"])
      if (const Vec2 v(p[0].get<double>(), p[1].get<double>()); r.empty() || r.back() != v) r.push_back(v);
    if (r.size() > 1 && r.front() == r.back()) r.pop_back();
    out.push_back(std::move(r));
  }
  return out;
}


using K = CGAL::Exact_predicates_exact_constructions_kernel;

ExplicitSum cgal_sum(const Polygon& P, const Polygon& Q) {
  CGAL::Polygon_2<K> cp, cq;
  for (const Vec2& p : P.ring(0)) cp.push_back(K::Point_2(p.x(), p.y()));
  // −Q counter-clockwise (a point reflection keeps the orientation).
  for (const Vec2& q : Q.ring(0)) cq.push_back(K::Point_2(-q.x(), -q.y()));
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
  return out;
}

#ifdef PENDEPTH_BENCH_CLIPPER
// Clipper's grid: coordinates scaled so the largest |coordinate| of the pair is below 2^28, so
// every sum stays in Clipper's fast 64-bit range (|x| < 2^30).
ExplicitSum clipper_sum(const Polygon& P, const Polygon& Q) {
  double big = 1;
  for (const Vec2& p : P.vertices()) big = std::max({big, std::abs(p.x()), std::abs(p.y())});
  for (const Vec2& q : Q.vertices()) big = std::max({big, std::abs(q.x()), std::abs(q.y())});
  const double scale = std::ldexp(1.0, 27 - std::ilogb(big));
  auto grid = [&](double x) { return ClipperLib::cInt(std::llround(x * scale)); };
  ClipperLib::Path pattern, path;
  for (const Vec2& q : Q.ring(0)) pattern.emplace_back(grid(-q.x()), grid(-q.y()));
  for (const Vec2& p : P.ring(0)) path.emplace_back(grid(p.x()), grid(p.y()));
  ClipperLib::Paths quads;
  ClipperLib::MinkowskiSum(pattern, path, quads, true);
  // Fill: P translated by −q0 and −Q translated by p0.
  ClipperLib::Path p_shift, q_shift;
  for (const auto& p : path) p_shift.emplace_back(p.X + pattern[0].X, p.Y + pattern[0].Y);
  for (const auto& q : pattern) q_shift.emplace_back(q.X + path[0].X, q.Y + path[0].Y);
  ClipperLib::Clipper c;
  c.AddPaths(quads, ClipperLib::ptSubject, true);
  c.AddPath(p_shift, ClipperLib::ptClip, true);
  c.AddPath(q_shift, ClipperLib::ptClip, true);
  ClipperLib::Paths solution;
  c.Execute(ClipperLib::ctUnion, solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  ExplicitSum out;
  for (const auto& ring : solution) {
    std::vector<Vec2> r;
    for (const auto& p : ring) r.emplace_back(double(p.X) / scale, double(p.Y) / scale);
    out.add_ring(r);
  }
  return out;
}
#endif

// ---- one case: pairs, queries, lazily built structures ----

struct Pair {
  Polygon P, Q;
  std::unique_ptr<NoFitPolygon2> nfp;
  std::unique_ptr<PairDepth2> pair;
  std::unique_ptr<ExplicitSum> cgal, clipper;
  std::unique_ptr<pendepth::Pair2> front;  // the front door, Prepare::Full
  double scale = 1;  // largest |coordinate| of P and Q
};

struct Query {
  std::size_t pair;
  Vec2 t, d;
};

// PENDEPTH_BENCH_QUERY_ORDER=pair: a query list grouped by pair (stable), for the cache's share.
void order_queries(std::vector<Query>& q) {
  const char* v = std::getenv("PENDEPTH_BENCH_QUERY_ORDER");
  if (v && std::string(v) == "pair")
    std::stable_sort(q.begin(), q.end(), [](const Query& a, const Query& b) { return a.pair < b.pair; });
}

struct Case {
  std::string name;
  std::size_t n = 0, m = 0;
  std::vector<Pair> pairs;
  std::vector<Query> queries;
  std::vector<Query> overlap_queries;  // t uniform in the no-fit polygon's box grown by 10% (made on first use)
  bool with_nfp = true;  // NoFitPolygon2 within its budget: the reference of the answer checks

  void add_pair(const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
    Polygon P = Polygon::simple(p, "P"), Q = Polygon::simple(q, "Q");
    n = std::max(n, P.size());
    m = std::max(m, Q.size());
    double s = 1;
    for (const Vec2& v : P.vertices()) s = std::max({s, std::abs(v.x()), std::abs(v.y())});
    for (const Vec2& v : Q.vertices()) s = std::max({s, std::abs(v.x()), std::abs(v.y())});
    pairs.push_back(Pair{std::move(P), std::move(Q), nullptr, nullptr, nullptr, nullptr, nullptr, s});
  }

  void make_queries(pb::Rng& rng) {
    for (std::size_t k = 0; queries.size() < pb::kQueries; ++k) {
      const std::size_t i = k % pairs.size();
      const Polygon &P = pairs[i].P, &Q = pairs[i].Q;
      const std::vector<Vec2> outer(P.ring(0).begin(), P.ring(0).end());
      Vec2 lo = outer[0], hi = outer[0], c(0, 0);
      for (const Vec2& p : outer) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      for (const Vec2& q : Q.ring(0)) c += q;
      c /= double(Q.ring(0).size());
      Vec2 p;
      do p = Vec2(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()));
      while (crossings(outer, p) % 2 == 0);
      const double a = rng.uniform(0, 2 * std::numbers::pi);
      queries.push_back(Query{i, p - c, Vec2(std::cos(a), std::sin(a))});
    }
    order_queries(queries);
  }

  const NoFitPolygon2& nfp(std::size_t i) {
    if (!pairs[i].nfp) pairs[i].nfp = std::make_unique<NoFitPolygon2>(pairs[i].P, pairs[i].Q);
    return *pairs[i].nfp;
  }
  const pendepth::Pair2& front(std::size_t i) {
    if (!pairs[i].front)
      pairs[i].front = std::make_unique<pendepth::Pair2>(pendepth::Shape2(pairs[i].P), pendepth::Shape2(pairs[i].Q),
                                                         pendepth::Prepare::Full);
    return *pairs[i].front;
  }
  void make_overlap_queries() {
    if (!overlap_queries.empty()) return;
    pb::Rng rng(0x0ddba11u ^ pairs.size());
    for (std::size_t k = 0; overlap_queries.size() < pb::kQueries; ++k) {
      const std::size_t i = k % pairs.size();
      Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
      for (const auto& poly : nfp(i).polygons())
        for (const auto& ring : poly)
          for (const Vec2& v : ring) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
      const Vec2 pad = 0.05 * (hi - lo);
      lo -= pad, hi += pad;
      overlap_queries.push_back(Query{i, Vec2(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y())), Vec2(1, 0)});
    }
    order_queries(overlap_queries);
  }
  const PairDepth2& pair(std::size_t i) {
    if (!pairs[i].pair) pairs[i].pair = std::make_unique<PairDepth2>(pairs[i].P, pairs[i].Q);
    return *pairs[i].pair;
  }
  const ExplicitSum& sum(std::size_t i, bool cgal) {
    std::unique_ptr<ExplicitSum>& slot = cgal ? pairs[i].cgal : pairs[i].clipper;
    if (!slot) {
#ifdef PENDEPTH_BENCH_CLIPPER
      slot = std::make_unique<ExplicitSum>(cgal ? cgal_sum(pairs[i].P, pairs[i].Q) : clipper_sum(pairs[i].P, pairs[i].Q));
#else
      slot = std::make_unique<ExplicitSum>(cgal_sum(pairs[i].P, pairs[i].Q));
#endif
    }
    return *slot;
  }
};

std::map<std::string, std::unique_ptr<Case>>& cases() {
  static std::map<std::string, std::unique_ptr<Case>> c;
  return c;
}

Case& nesting_case(const std::string& instance) {
  auto& slot = cases()["nesting/" + instance];
  if (slot) return *slot;
  slot = std::make_unique<Case>();
  slot->name = "nesting/" + instance;
  const auto pieces = nesting_pieces(instance);
  const bool all = instance == "albano";
  std::size_t k = 0;
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t j = 0; j < pieces.size(); ++j, ++k)
      if (all || (k % 3 == 0 && slot->pairs.size() < 24)) slot->add_pair(pieces[i], pieces[j]);
  pb::Rng rng(0x51ed270bu ^ std::hash<std::string>{}(instance));
  slot->make_queries(rng);
  return *slot;
}

// Every ordered pair of an instance whose number of convex pieces is `convex` (2: both, 1: one,
// 0: neither), for the build by convexity; no queries. Convex: no right turn (exact).
bool convex_piece(const std::vector<Vec2>& r) {
  const Polygon P = Polygon::simple(r, "piece");
  const auto V = P.vertices();
  for (std::size_t g = 0; g < P.size(); ++g)
    if (pendepth::predicates::orient2d(V[g], V[P.next(g)], V[P.next(P.next(g))]) < 0) return false;
  return true;
}

Case& nesting_split_case(const std::string& instance, int convex) {
  auto& slot = cases()["nesting-split/" + instance + "/" + std::to_string(convex)];
  if (slot) return *slot;
  slot = std::make_unique<Case>();
  slot->name = "nesting-split/" + instance;
  const auto pieces = nesting_pieces(instance);
  std::vector<int> cv;
  for (const auto& p : pieces) cv.push_back(convex_piece(p) ? 1 : 0);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t j = 0; j < pieces.size(); ++j)
      if (cv[i] + cv[j] == convex) slot->add_pair(pieces[i], pieces[j]);
  return *slot;
}

// Every ordered pair of the first `cap` pieces of an instance (all of them when cap is 0), for
// the build over whole instances (issue 19 item 2); no queries.
Case& nesting_all_case(const std::string& instance, std::size_t cap) {
  auto& slot = cases()["nesting-all/" + instance];
  if (slot) return *slot;
  slot = std::make_unique<Case>();
  slot->name = "nesting-all/" + instance;
  auto pieces = nesting_pieces(instance);
  if (cap > 0 && pieces.size() > cap) pieces.resize(cap);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t j = 0; j < pieces.size(); ++j) slot->add_pair(pieces[i], pieces[j]);
  return *slot;
}

Case& star_case(std::size_t n) {
  auto& slot = cases()["star/" + std::to_string(n)];
  if (slot) return *slot;
  slot = std::make_unique<Case>();
  slot->name = "star";
  pb::Rng rng(0x9e3779b9u ^ (n * 1000003u));
  const std::vector<Vec2> p = star_ring(n, 60, 100, rng), q = star_ring(n, 6, 10, rng);
  slot->add_pair(p, q);
  slot->make_queries(rng);
  return *slot;
}

// ---- scaling families (issue 19 item 4): one pair, P of about n vertices, Q a small L ----

// Comb: `teeth` teeth 1 wide and 10 high, gaps 1 wide, on a base 2 high (4·teeth − 2 vertices).
std::vector<Vec2> comb_ring(std::size_t teeth) {
  const double W = 2.0 * double(teeth) - 1;
  std::vector<Vec2> r{{0, 0}, {W, 0}};
  for (std::size_t k = teeth; k-- > 0;) {
    const double x0 = 2.0 * double(k);
    r.push_back({x0 + 1, 12});
    r.push_back({x0, 12});
    if (k > 0) r.push_back({x0, 2}), r.push_back({x0 - 1, 2});
  }
  return r;
}

// Thick Archimedean spiral, 5 turns, centre line r = 20 + 30·θ/2π, half-width 1.5 (arms 27
// apart), `steps` samples per side (2·steps + 2 vertices).
std::vector<Vec2> spiral_ring(std::size_t steps) {
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

// family: comb, comb45 (the comb rotated by 45°, rounded), star (random radii [60, 100]) or spiral; Q an L whose 0.5-wide arm points down
// (it enters the comb's gaps).
Case& family_case(const std::string& family, std::size_t n) {
  auto& slot = cases()["scale/" + family + "/" + std::to_string(n)];
  if (slot) return *slot;
  slot = std::make_unique<Case>();
  slot->name = "scale-" + family;
  pb::Rng rng(0x2545f491u ^ (n * 1000003u));
  const std::vector<Vec2> L{{0, 0}, {0.5, 0}, {0.5, 2.5}, {3, 2.5}, {3, 3}, {0, 3}};
  std::vector<Vec2> p = family == "comb" || family == "comb45" ? comb_ring((n + 2) / 4) : family == "spiral" ? spiral_ring(n / 2 - 1) : star_ring(n, 60, 100, rng);
  if (family == "comb45") {  // rotated by 45° as a user would (cos and sin of π/4 differ in the last bit), rounded
    const double c = std::cos(std::numbers::pi / 4), s = std::sin(std::numbers::pi / 4);
    for (Vec2& v : p) v = Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
  }
  slot->add_pair(p, L);
  return *slot;
}

void set_counters(benchmark::State& state, const Case& c) {
  state.counters["n"] = double(c.n);
  state.counters["m"] = double(c.m);
  state.counters["pairs"] = double(c.pairs.size());
}

// ---- benchmarks ----

void BM_build_pendepth(benchmark::State& state, Case* c) {
  for (auto _ : state) {
    for (Pair& p : c->pairs) {
      NoFitPolygon2 nfp(p.P, p.Q);
      benchmark::DoNotOptimize(nfp.polygons().size());
      // Kept for the size counters and the queries (no second build of a slow big case).
      if (!p.nfp) p.nfp = std::make_unique<NoFitPolygon2>(std::move(nfp));
    }
  }
  set_counters(state, *c);
  pendepth::NfpSize total;
  for (std::size_t i = 0; i < c->pairs.size(); ++i) {
    const pendepth::NfpSize s = c->nfp(i).size();
    total.candidates += s.candidates, total.pieces += s.pieces, total.rings += s.rings;
    total.slits += s.slits, total.points += s.points, total.bytes += s.bytes;
  }
  const double k = double(c->pairs.size());
  state.counters["candidates"] = double(total.candidates) / k;
  state.counters["pieces"] = double(total.pieces) / k;
  state.counters["rings"] = double(total.rings) / k;
  state.counters["slits"] = double(total.slits);
  state.counters["points"] = double(total.points);
  state.counters["bytes"] = double(total.bytes) / k;
}

// The whole-instance path of pendepth nfp / nfp-all (issue 19 item 2): one Shape2 per piece, made
// anew each iteration (so each piece's triangulation and convex parts are made once per
// iteration, shared by its pairs), and no_fit_polygon for every ordered pair (the rings only, no
// query structures). `c` is a nesting-all case: pair i·N + j is (piece i, piece j). `share` false
// (build/pendepth_unshared): new Shape2 objects for every pair, so nothing is shared (the export-
// only build's own share of the gain).
void BM_build_shapes(benchmark::State& state, Case* c, bool share) {
  const auto N = static_cast<std::size_t>(std::lround(std::sqrt(double(c->pairs.size()))));
  for (auto _ : state) {
    std::vector<pendepth::Shape2> shapes;
    shapes.reserve(N);
    for (std::size_t i = 0; i < N; ++i) shapes.emplace_back(c->pairs[i * N].P);
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j)
        benchmark::DoNotOptimize(
            (share ? pendepth::no_fit_polygon(shapes[i], shapes[j])
                   : pendepth::no_fit_polygon(pendepth::Shape2(c->pairs[i * N + j].P), pendepth::Shape2(c->pairs[i * N + j].Q)))
                .polygons.size());
  }
  set_counters(state, *c);
}

void BM_build_peer(benchmark::State& state, Case* c, bool cgal) {
  std::size_t vertices = 0, rings = 0;
  for (auto _ : state) {
    vertices = 0, rings = 0;
    for (Pair& p : c->pairs) {
#ifdef PENDEPTH_BENCH_CLIPPER
      ExplicitSum s = cgal ? cgal_sum(p.P, p.Q) : clipper_sum(p.P, p.Q);
#else
      ExplicitSum s = cgal_sum(p.P, p.Q);
#endif
      vertices += s.vertices();
      rings += s.rings();
      benchmark::DoNotOptimize(vertices);
      std::unique_ptr<ExplicitSum>& slot = cgal ? p.cgal : p.clipper;
      if (!slot) slot = std::make_unique<ExplicitSum>(std::move(s));  // kept for the scans
    }
  }
  set_counters(state, *c);
  state.counters["sum_vertices"] = double(vertices) / double(c->pairs.size());
  state.counters["sum_rings"] = double(rings) / double(c->pairs.size());
}

enum class Impl { Nfp, NfpLean, Pair, CgalScan, ClipperScan, Front };

double answer(Case& c, const Query& q, Impl impl, bool minimum) {
  switch (impl) {
    case Impl::Nfp: return minimum ? c.nfp(q.pair).minimum(q.t).depth : c.nfp(q.pair).along(q.t, q.d).depth;
    case Impl::NfpLean: {
      const pendepth::DepthValue2 v = minimum ? c.nfp(q.pair).depth_value(q.t) : c.nfp(q.pair).directional_depth_value(q.t, q.d);
      benchmark::DoNotOptimize(v.translation);
      return v.depth;
    }
    case Impl::Pair: return minimum ? c.pair(q.pair).minimum(q.t).depth : c.pair(q.pair).along(q.t, q.d).depth;
    case Impl::Front: return minimum ? c.front(q.pair).minimum(q.t).depth : c.front(q.pair).along(q.t, q.d).depth;
    case Impl::CgalScan:
    case Impl::ClipperScan: {
      const ExplicitSum& s = c.sum(q.pair, impl == Impl::CgalScan);
      return minimum ? s.sigma(q.t) : s.sigma_d(q.t, q.d);
    }
  }
  return 0;
}

void BM_query(benchmark::State& state, Case* c, Impl impl, bool minimum) {
  // Structures built and answers checked against NoFitPolygon2 (PairDepth2 beyond the NFP's
  // budget) before timing.
  const Impl reference = c->with_nfp ? Impl::Nfp : Impl::Pair;
  // At most kCheckSeconds of checking: PairDepth2's σ takes up to seconds per query on big stars.
  double max_diff = 0, differ = 0, overlapping = 0, checked = 0;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < pb::kQueries; k += 4) {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > kCheckSeconds) break;
    ++checked;
    const Query& q = c->queries[k];
    const double want = answer(*c, q, reference, minimum), got = answer(*c, q, impl, minimum);
    max_diff = std::max(max_diff, std::abs(got - want));
    differ += std::abs(got - want) > 1e-6 * c->pairs[q.pair].scale;
    overlapping += want > 0;
  }
  // Build every pair's structure before timing (queries cycle through the pairs).
  for (std::size_t k = 0; k < std::min(pb::kQueries, c->pairs.size()); ++k) answer(*c, c->queries[k], impl, minimum);
  std::size_t i = 0;
  double sum = 0;
  for (auto _ : state) {
    sum += answer(*c, c->queries[i], impl, minimum);
    i = pb::next_query(i);
  }
  benchmark::DoNotOptimize(sum);
  set_counters(state, *c);
  state.counters["max_abs_diff"] = max_diff;
  state.counters["differ"] = differ;
  state.counters["checked"] = checked;
  state.counters["overlapping"] = overlapping;
}

bool overlaps(Case& c, const Query& q, Impl impl) {
  switch (impl) {
    case Impl::Nfp:
    case Impl::NfpLean: return c.nfp(q.pair).overlapping(q.t);
    case Impl::Pair: return c.pair(q.pair).overlapping(q.t);
    case Impl::Front: return c.front(q.pair).overlapping(q.t);
    case Impl::CgalScan:
    case Impl::ClipperScan: return c.sum(q.pair, impl == Impl::CgalScan).inside(q.t);
  }
  return false;
}

// The overlap test alone (issue 19 item 1): placements uniform in the no-fit polygon's box grown
// by 10% (about half overlap); `differ` counts answers unlike NoFitPolygon2's (the scans' even-odd
// on rounded vertices may differ on the boundary).
void BM_overlap(benchmark::State& state, Case* c, Impl impl) {
  c->make_overlap_queries();
  double differ = 0, overlapping = 0;
  for (const Query& q : c->overlap_queries) {
    const bool want = overlaps(*c, q, Impl::Nfp);
    differ += overlaps(*c, q, impl) != want;
    overlapping += want;
  }
  std::size_t i = 0, sum = 0;
  for (auto _ : state) {
    sum += overlaps(*c, c->overlap_queries[i], impl);
    i = pb::next_query(i);
  }
  benchmark::DoNotOptimize(sum);
  set_counters(state, *c);
  state.SetItemsProcessed(state.iterations());
  state.counters["differ"] = differ;
  state.counters["overlapping"] = overlapping / double(c->overlap_queries.size());
}


double env_number(const char* name, double fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atof(v) : fallback;
}

void register_case(Case& c, const std::string& tag, double nfp_budget, double budget, double clipper_budget,
                   double pair_sigma_budget) {
  const double nm = double(c.n) * double(c.m);
  c.with_nfp = nm <= nfp_budget;
  const bool cgal = nm <= budget;
  const bool clipper = nm <= clipper_budget;
  (void)clipper;
  if (c.with_nfp)
    benchmark::RegisterBenchmark(("build/pendepth/" + tag).c_str(), BM_build_pendepth, &c)
        ->Unit(benchmark::kMicrosecond);
  if (cgal)
    benchmark::RegisterBenchmark(("build/cgal/" + tag).c_str(), BM_build_peer, &c, true)->Unit(benchmark::kMicrosecond);
#ifdef PENDEPTH_BENCH_CLIPPER
  if (clipper)
    benchmark::RegisterBenchmark(("build/clipper/" + tag).c_str(), BM_build_peer, &c, false)
        ->Unit(benchmark::kMicrosecond);
#endif
  if (c.with_nfp) {
    benchmark::RegisterBenchmark(("overlap/pendepth_nfp/" + tag).c_str(), BM_overlap, &c, Impl::Nfp);
    benchmark::RegisterBenchmark(("overlap/pendepth_pair2/" + tag).c_str(), BM_overlap, &c, Impl::Front);
    benchmark::RegisterBenchmark(("overlap/pendepth_pair/" + tag).c_str(), BM_overlap, &c, Impl::Pair);
    if (cgal) benchmark::RegisterBenchmark(("overlap/cgal_scan/" + tag).c_str(), BM_overlap, &c, Impl::CgalScan);
  }
  for (bool minimum : {true, false}) {
    const std::string q = minimum ? "sigma" : "sigma_d";
    if (c.with_nfp) benchmark::RegisterBenchmark((q + "/pendepth_nfp/" + tag).c_str(), BM_query, &c, Impl::Nfp, minimum);
    if (c.with_nfp) benchmark::RegisterBenchmark((q + "/pendepth_nfp_lean/" + tag).c_str(), BM_query, &c, Impl::NfpLean, minimum);
    if (c.with_nfp) benchmark::RegisterBenchmark((q + "/pendepth_pair2/" + tag).c_str(), BM_query, &c, Impl::Front, minimum);
    if (!minimum || nm <= pair_sigma_budget)
      benchmark::RegisterBenchmark((q + "/pendepth_pair/" + tag).c_str(), BM_query, &c, Impl::Pair, minimum);
    if (cgal) benchmark::RegisterBenchmark((q + "/cgal_scan/" + tag).c_str(), BM_query, &c, Impl::CgalScan, minimum);
#ifdef PENDEPTH_BENCH_CLIPPER
    if (clipper)
      benchmark::RegisterBenchmark((q + "/clipper_scan/" + tag).c_str(), BM_query, &c, Impl::ClipperScan, minimum);
#endif
  }
}

}  // namespace

int main(int argc, char** argv) {
  const double nfp_budget = env_number("PENDEPTH_BENCH_NFP_BUDGET", 1e5);
  const double pair_sigma_budget = env_number("PENDEPTH_BENCH_PAIR_SIGMA_BUDGET", 1e3);
  const double budget = env_number("PENDEPTH_BENCH_PEER_BUDGET", 1e5);
  const double clipper_budget = env_number("PENDEPTH_BENCH_CLIPPER_BUDGET", 1e4);
  // Queries on every ESICUP instance (issue 19 item 1); pairs beyond the budgets (gardeyn4's
  // pieces of up to 1044 vertices) register no NoFitPolygon2 or peer rows.
  for (const std::string instance : {"albano", "shirts", "trousers", "baldacci4", "gardeyn2", "gardeyn4", "gardeyn6"}) {
    Case& c = nesting_case(instance);
    register_case(c, instance + "/" + std::to_string(c.n) + "/" + std::to_string(c.m), nfp_budget, budget,
                  clipper_budget, pair_sigma_budget);
  }
  // The build by convexity of the pair (every ordered pair of each instance): builds only.
  for (const std::string instance : {"albano", "shirts", "trousers"})
    for (int convex = 2; convex >= 0; --convex) {
      Case& c = nesting_split_case(instance, convex);
      if (c.pairs.empty()) continue;
      static const char* kind[] = {"nonconvex", "mixed", "convex"};
      const std::string tag = instance + "-" + kind[convex] + "/" + std::to_string(c.n) + "/" + std::to_string(c.m);
      benchmark::RegisterBenchmark(("build/pendepth/" + tag).c_str(), BM_build_pendepth, &c)->Unit(benchmark::kMicrosecond);
      benchmark::RegisterBenchmark(("build/cgal/" + tag).c_str(), BM_build_peer, &c, true)->Unit(benchmark::kMicrosecond);
    }
  // The build over every ordered pair of each ESICUP instance (issue 19 item 2): all pieces, or
  // the first PENDEPTH_BENCH_ALL_CAP (default 12) of the large instances gardeyn2 (50 pieces of
  // up to 241 vertices) and gardeyn6 (85); gardeyn4 has 5 pieces of up to 1044 vertices.
  // Builds only; CGAL and Clipper (pieces within its budget) in the same run.
  {
    const auto cap = std::size_t(env_number("PENDEPTH_BENCH_ALL_CAP", 12));
    for (const std::string instance : {"albano", "shirts", "trousers", "baldacci4", "gardeyn2", "gardeyn4", "gardeyn6"}) {
      Case& c = nesting_all_case(instance, instance == "gardeyn2" || instance == "gardeyn6" ? cap : 0);
      const std::string tag = instance + "-all/" + std::to_string(c.n) + "/" + std::to_string(c.m);
      benchmark::RegisterBenchmark(("build/pendepth/" + tag).c_str(), BM_build_pendepth, &c)->Unit(benchmark::kMicrosecond);
      benchmark::RegisterBenchmark(("build/pendepth_shapes/" + tag).c_str(), BM_build_shapes, &c, true)->Unit(benchmark::kMicrosecond);
      benchmark::RegisterBenchmark(("build/pendepth_unshared/" + tag).c_str(), BM_build_shapes, &c, false)->Unit(benchmark::kMicrosecond);
      benchmark::RegisterBenchmark(("build/cgal/" + tag).c_str(), BM_build_peer, &c, true)->Unit(benchmark::kMicrosecond);
#ifdef PENDEPTH_BENCH_CLIPPER
      if (double(c.n) * double(c.m) <= clipper_budget)
        benchmark::RegisterBenchmark(("build/clipper/" + tag).c_str(), BM_build_peer, &c, false)->Unit(benchmark::kMicrosecond);
#endif
    }
  }
  for (std::size_t n : env_sizes("PENDEPTH_BENCH_N", {10, 30, 100, 300})) {
    Case& c = star_case(n);
    register_case(c, "star/" + std::to_string(c.n) + "/" + std::to_string(c.m), nfp_budget, budget, clipper_budget,
                  pair_sigma_budget);
  }
  // Scaling of the build with n (issue 19 item 4): comb, star and spiral against an L-shape.
  for (const std::string family : {"comb", "comb45", "star", "spiral"})
    for (std::size_t n : env_sizes("PENDEPTH_BENCH_SCALE_N", {1000, 3000, 10000})) {
      Case& c = family_case(family, n);
      benchmark::RegisterBenchmark(("build/pendepth/scale-" + family + "/" + std::to_string(c.n) + "/" + std::to_string(c.m)).c_str(),
                                   BM_build_pendepth, &c)
          ->Unit(benchmark::kMillisecond)
          ->Iterations(1);
    }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
