// bench_mesh3 (issue 17): closed-mesh validation (Mesh3::validate: closed, manifold, oriented, no
// self-intersection, volume sign, convexity) against CGAL's Polygon_mesh_processing checks of the
// same properties (is_closed, does_self_intersect, is_outward_oriented on a Surface_mesh, Epick),
// and the exact convex decomposition (CGAL Nef convex_decomposition_3) with its piece counts.
// Inputs: tori of n × n/2 quads (2·n²/2 triangles), combs of k teeth (polycubes).
// Pair3 on meshes (issue 17 items 3–5): µs per query (overlap, σ_d, signed distance, σ bounds) by
// mesh size — a comb of k teeth against an L block, a torus against a smaller torus, CGAL sample
// meshes (libcgal-demo: cross, star, tripod, against themselves) — at random translations where
// the boxes overlap, and the error of "the hulls of both meshes" against the exact σ_d; a mesh
// against a point, a sphere, a segment and a triangle (BM_MeshMixed). With FCL 0.7 (libfcl-dev):
// its mesh–mesh collide (contacts, largest penetration_depth) and distance on the same poses —
// µs per query (BM_MeshFcl) and error against the exact answers (BM_MeshFclError).
#include <pendepth/io.hpp>
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh3/mesh_pair.hpp"
#include "mesh3/mesh_sigma_exact.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <benchmark/benchmark.h>
#ifdef PENDEPTH_BENCH_FCL
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>
#endif

#include <cmath>
#include <filesystem>
#include <cstdint>
#include <map>
#include <optional>
#include <random>

namespace {

using pendepth::Vec3;
namespace io = pendepth::io;

io::MeshFile torus(int n, int m) {
  io::MeshFile f;
  f.source = "torus";
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * pi * i / n, w = 2 * pi * j / m;
      f.points.emplace_back((3 + std::cos(w)) * std::cos(u), (3 + std::cos(w)) * std::sin(u), std::sin(w));
    }
  auto id = [&](int i, int j) { return static_cast<std::size_t>(((i + n) % n) * m + (j + m) % m); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      for (const auto& t : {std::array{id(i, j), id(i + 1, j), id(i + 1, j + 1)}, std::array{id(i, j), id(i + 1, j + 1), id(i, j + 1)}}) {
        f.begin_face(f.faces());
        f.indices.insert(f.indices.end(), t.begin(), t.end());
      }
    }
  f.face_start.push_back(f.indices.size());
  return f;
}

// A comb of k teeth: a bar of 2k − 1 unit voxels with a tooth of 2 voxels on every other one, as
// outward quads.
io::MeshFile voxels(const std::map<std::array<int, 3>, bool>& vox, const char* source) {
  io::MeshFile f;
  f.source = source;
  std::map<std::array<int, 3>, std::size_t> id;
  auto vid = [&](std::array<int, 3> p) {
    auto [it, fresh] = id.emplace(p, f.points.size());
    if (fresh) f.points.emplace_back(p[0], p[1], p[2]);
    return it->second;
  };
  for (const auto& [v, _] : vox)
    for (int a = 0; a < 3; ++a)
      for (int s : {-1, 1}) {
        auto nb = v;
        nb[a] += s;
        if (vox.count(nb)) continue;
        const int b = (a + 1) % 3, c = (a + 2) % 3, cb[4] = {0, 1, 1, 0}, cc[4] = {0, 0, 1, 1};
        f.begin_face(f.faces());
        for (int q = 0; q < 4; ++q) {
          const int j = s > 0 ? q : 3 - q;
          auto p = v;
          p[a] += s > 0;
          p[b] += cb[j];
          p[c] += cc[j];
          f.indices.push_back(vid(p));
        }
      }
  f.face_start.push_back(f.indices.size());
  return f;
}

io::MeshFile comb(int k) {
  std::map<std::array<int, 3>, bool> vox;
  for (int x = 0; x < 2 * k - 1; ++x) vox[{x, 0, 0}] = true;
  for (int x = 0; x < 2 * k - 1; x += 2) vox[{x, 1, 0}] = vox[{x, 2, 0}] = true;
  return voxels(vox, "comb");
}

void BM_Validate_pendepth(benchmark::State& st) {
  const io::MeshFile f = torus(static_cast<int>(st.range(0)), static_cast<int>(st.range(0)) / 2);
  for (auto _ : st) benchmark::DoNotOptimize(pendepth::Mesh3::validate(f, "torus"));
  st.counters["triangles"] = static_cast<double>(f.faces());
  // Time per triangle (printed with its unit, e.g. "1.5u" = 1.5 µs).
  st.counters["per_triangle"] =
      benchmark::Counter(static_cast<double>(f.faces()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_Validate_CGAL_PMP(benchmark::State& st) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  const io::MeshFile f = torus(static_cast<int>(st.range(0)), static_cast<int>(st.range(0)) / 2);
  for (auto _ : st) {
    Mesh m;  // building the halfedge structure is part of CGAL's check of manifoldness
    for (const auto& p : f.points) m.add_vertex(K::Point_3(p.x(), p.y(), p.z()));
    for (std::size_t t = 0; t < f.faces(); ++t)
      m.add_face(Mesh::Vertex_index(static_cast<unsigned>(f.indices[3 * t])), Mesh::Vertex_index(static_cast<unsigned>(f.indices[3 * t + 1])),
                 Mesh::Vertex_index(static_cast<unsigned>(f.indices[3 * t + 2])));
    bool ok = CGAL::is_closed(m) && !CGAL::Polygon_mesh_processing::does_self_intersect(m) &&
              CGAL::Polygon_mesh_processing::is_outward_oriented(m);
    benchmark::DoNotOptimize(ok);
  }
  st.counters["triangles"] = static_cast<double>(f.faces());
  // Time per triangle (printed with its unit, e.g. "1.5u" = 1.5 µs).
  st.counters["per_triangle"] =
      benchmark::Counter(static_cast<double>(f.faces()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void decomposition(benchmark::State& st, const io::MeshFile& f) {
  const pendepth::Mesh3 m = pendepth::Mesh3::validate(f, f.source);
  pendepth::ConvexDecomposition3 d;
  for (auto _ : st) d = pendepth::convex_decomposition(m);
  st.counters["triangles"] = static_cast<double>(m.triangles().size());
  st.counters["reflex_edges"] = static_cast<double>(d.reflex_edges);
  st.counters["pieces"] = static_cast<double>(d.pieces.size());
  st.counters["rounded_pieces"] = static_cast<double>(d.rounded_pieces);
  st.counters["cut_vertices"] = static_cast<double>(d.cut_vertices);
}

void BM_Decompose_torus(benchmark::State& st) {
  decomposition(st, torus(static_cast<int>(st.range(0)), static_cast<int>(st.range(0)) / 2));
}
void BM_Decompose_comb(benchmark::State& st) { decomposition(st, comb(static_cast<int>(st.range(0)))); }

// ---- Pair3 on meshes ----
io::MeshFile l_block() { return voxels({{{0, 0, 0}, true}, {{1, 0, 0}, true}, {{0, 1, 0}, true}}, "L"); }

struct MeshCase {
  std::string name;
  io::MeshFile p, q;
};

std::vector<MeshCase> mesh_cases() {
  std::vector<MeshCase> c;
  for (int k : {2, 8, 32}) c.push_back({"comb" + std::to_string(k) + "_L", comb(k), l_block()});
  for (int n : {8, 16}) c.push_back({"torus" + std::to_string(n) + "_torus8", torus(n, n / 2), torus(8, 4)});
#ifdef PENDEPTH_CGAL_MESHES
  for (const char* name : {"cross.off", "star.off", "tripod.off"}) {
    const io::MeshFile f = io::read_mesh(std::string(PENDEPTH_CGAL_MESHES) + "/" + name);
    c.push_back({std::string(name) + "_self", f, f});
  }
#endif
  return c;
}

struct Prepared {
  pendepth::Pair3 pair, hulls;
  std::vector<pendepth::Pose3> poses;
  std::vector<Vec3> dirs;
  std::size_t triangles = 0, pieces = 0;
};

const Prepared& prepared(std::size_t index) {
  static std::map<std::size_t, std::unique_ptr<Prepared>> cache;
  auto& e = cache[index];
  if (!e) {
    const MeshCase mc = mesh_cases()[index];
    const pendepth::Mesh3 mp = pendepth::Mesh3::validate(mc.p, "P"), mq = pendepth::Mesh3::validate(mc.q, "Q");
    const pendepth::Shape3 sp = pendepth::Shape3::from_mesh(mp), sq = pendepth::Shape3::from_mesh(mq);
    e.reset(new Prepared{pendepth::Pair3(sp, sq), pendepth::Pair3(pendepth::Shape3(sp.polytope()), pendepth::Shape3(sq.polytope())),
                         {}, {}, mp.triangles().size() + mq.triangles().size(),
                         mp.decomposition().pieces.size() + mq.decomposition().pieces.size()});
    // Translations of Q (its box centre onto a random point of P's box, every other one pushed
// out by half P's box diagonal in a random direction: some apart), random directions.
    Vec3 lo = mp.points()[0], hi = lo, qlo = mq.points()[0], qhi = qlo;
    for (const Vec3& v : mp.points()) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    for (const Vec3& v : mq.points()) qlo = qlo.cwiseMin(v), qhi = qhi.cwiseMax(v);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> U(0, 1);
    for (int k = 0; k < 64; ++k) {
      Vec3 x = lo + (hi - lo).cwiseProduct(Vec3(U(rng), U(rng), U(rng)));
      if (k % 2) x += 0.5 * (hi - lo).norm() * Vec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5).normalized();
      e->poses.emplace_back(x - (qlo + qhi) / 2);
      e->dirs.emplace_back(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
    }
  }
  return *e;
}

template <class Run>
void mesh_query(benchmark::State& st, Run run) {
  const Prepared& p = prepared(static_cast<std::size_t>(st.range(0)));
  std::size_t i = 0;
  for (auto _ : st) {
    run(p, i % p.poses.size());
    ++i;
  }
  st.SetLabel(mesh_cases()[static_cast<std::size_t>(st.range(0))].name);
  st.counters["triangles"] = static_cast<double>(p.triangles);
  st.counters["pieces"] = static_cast<double>(p.pieces);
}

void BM_MeshOverlap(benchmark::State& st) {
  mesh_query(st, [](const Prepared& p, std::size_t i) { benchmark::DoNotOptimize(p.pair.overlapping(pendepth::Pose3(), p.poses[i])); });
}
void BM_MeshAlong(benchmark::State& st) {
  mesh_query(st, [](const Prepared& p, std::size_t i) { benchmark::DoNotOptimize(p.pair.along(pendepth::Pose3(), p.poses[i], p.dirs[i])); });
}
// The same σ_d and σ-bounds queries with every pair's interval forced onto the DK descents
// (mesh3::LinePath::Descent; Auto uses the implicit facets of small pairs): before/after.
struct ForceDescent {
  ForceDescent() { pendepth::mesh3::line_path = pendepth::mesh3::LinePath::Descent; }
  ~ForceDescent() { pendepth::mesh3::line_path = pendepth::mesh3::LinePath::Auto; }
};
void BM_MeshAlongDescent(benchmark::State& st) {
  ForceDescent f;
  mesh_query(st, [](const Prepared& p, std::size_t i) { benchmark::DoNotOptimize(p.pair.along(pendepth::Pose3(), p.poses[i], p.dirs[i])); });
}
void BM_MeshMinimumBoundsDescent(benchmark::State& st) {
  ForceDescent f;
  mesh_query(st, [](const Prepared& p, std::size_t i) { benchmark::DoNotOptimize(p.pair.minimum(pendepth::Pose3(), p.poses[i])); });
}
void BM_MeshDistance(benchmark::State& st) {
  mesh_query(st, [](const Prepared& p, std::size_t i) { benchmark::DoNotOptimize(p.pair.signed_distance(pendepth::Pose3(), p.poses[i])); });
}
// The shape cast (src/mesh3/mesh_cast.cpp): half the poses overlap (answered by the overlap
// test alone), the others cast along a random direction.
void BM_MeshCast(benchmark::State& st) {
  mesh_query(st, [](const Prepared& p, std::size_t i) { benchmark::DoNotOptimize(p.pair.cast(pendepth::Pose3(), p.poses[i], p.dirs[i])); });
}
// σ (minimum): the exact σ where it ends within its work limit (mesh_sigma_exact.cpp), and
// the same query on the bounds alone (a mesh3::SigmaBoundsOnly guard: the path before it).
void minimum_query(benchmark::State& st) {
  mesh_query(st, [](const Prepared& p, std::size_t i) { benchmark::DoNotOptimize(p.pair.minimum(pendepth::Pose3(), p.poses[i])); });
  // How often the certified bounds meet (equal or adjacent doubles: exact), and their mean
  // relative gap, over the first 16 poses.
  const Prepared& p = prepared(static_cast<std::size_t>(st.range(0)));
  int over = 0, met = 0;
  double gap = 0;
  for (std::size_t k = 0; k < 16; ++k) {
    const auto& pose = p.poses[k];
    const pendepth::Depth3 r = p.pair.minimum(pendepth::Pose3(), pose);
    if (!r.overlapping) continue;
    ++over;
    met += r.upper_bound <= std::nextafter(r.lower_bound, INFINITY);
    gap += (r.upper_bound - r.lower_bound) / r.upper_bound;
  }
  st.counters["overlapping"] = over;
  st.counters["bounds_met"] = met;
  st.counters["mean_rel_gap"] = over ? gap / over : 0;
}
void BM_MeshMinimumBounds(benchmark::State& st) { minimum_query(st); }
void BM_MeshMinimumBoundsOnly(benchmark::State& st) {
  pendepth::mesh3::SigmaBoundsOnly bounds_only;  // the benchmark runs its loop on this thread
  minimum_query(st);
}
// The mesh pair of a case and its exact queries: the poses among the first 16 whose certified
// bounds do not meet (the ones minimum() sends to the exact σ), each with its upper bound.
struct ExactQueries {
  pendepth::mesh3::MeshPair m;
  std::vector<std::pair<std::size_t, double>> q;  // pose, upper bound
};
ExactQueries exact_queries(const Prepared& p) {
  bool exact = true;
  ExactQueries e{pendepth::mesh3::MeshPair::make(pendepth::mesh3::pieces_of(p.pair.P(), exact),
                                                 pendepth::mesh3::pieces_of(p.pair.Q(), exact), exact),
                 {}};
  pendepth::mesh3::SigmaBoundsOnly bounds_only;
  for (std::size_t k = 0; k < 16; ++k) {
    const pendepth::Depth3 r = pendepth::mesh3::minimum(e.m, pendepth::Pose3(), p.poses[k]);
    if (r.overlapping && r.lower_bound < r.upper_bound) e.q.emplace_back(k, r.upper_bound);
  }
  return e;
}
// The parts of the last exact query's work count (mesh3::SigmaExactWork), by name.
std::vector<std::pair<const char*, double>> work_parts() {
  const pendepth::mesh3::SigmaExactWork& w = pendepth::mesh3::last_exact_work;
  std::vector<std::pair<const char*, double>> r;
  for (const auto& [name, v] : {std::pair{"setup", w.setup}, {"lines", w.lines}, {"tests", w.tests},
                                {"exact_lines", w.exact_lines}, {"exact_tests", w.exact_tests},
                                {"exact_intervals", w.exact_intervals}, {"refined", w.refined}, {"fined", w.fined}})
    r.emplace_back(name, static_cast<double>(v));
  return r;
}

// The exact σ alone (mesh3::exact_minimum, no work limit) on the case's exact queries, in turn.
// Args: mesh case, tier (0 the filtered tier, 1 everything exact: a mesh3::SigmaExactUnfiltered
// guard — the reference). Counters: queries, mean candidate facets in range, mean work
// (kExactSigmaMaxWork's units) and its parts.
void BM_MeshSigmaExact(benchmark::State& st) {
  if (static_cast<std::size_t>(st.range(0)) >= mesh_cases().size()) {
    st.SkipWithError("no such mesh case (CGAL sample meshes not found)");
    return;
  }
  const Prepared& p = prepared(static_cast<std::size_t>(st.range(0)));
  const ExactQueries e = exact_queries(p);
  std::optional<pendepth::mesh3::SigmaExactUnfiltered> unfiltered;
  if (st.range(1) == 1) unfiltered.emplace();
  std::size_t i = 0;
  double facets = 0, work = 0;
  std::map<std::string, double> parts;  // the work count's parts, summed
  for (auto _ : st) {
    if (e.q.empty()) continue;
    const auto& [k, upper] = e.q[i % e.q.size()];
    const auto r = pendepth::mesh3::exact_minimum(e.m, pendepth::Pose3(), p.poses[k], upper, SIZE_MAX);
    facets += r ? static_cast<double>(r->candidates) : 0;
    work += static_cast<double>(pendepth::mesh3::last_exact_work.units);
    for (const auto& [name, v] : work_parts()) parts[name] += v;
    ++i;
  }
  st.SetLabel(mesh_cases()[static_cast<std::size_t>(st.range(0))].name + (st.range(1) ? " exact" : " filtered"));
  st.counters["queries"] = static_cast<double>(e.q.size());
  st.counters["candidates"] = i ? facets / static_cast<double>(i) : 0;
  st.counters["work"] = i ? work / static_cast<double>(i) : 0;  // kExactSigmaMaxWork's units
  for (const auto& [name, v] : parts) st.counters["w_" + name] = i ? v / static_cast<double>(i) : 0;
}

// One of BM_MeshSigmaExact's queries (args: mesh case, its index among the case's queries; one
// iteration): CPU time and the work count's parts per query, to fit the work model's weights
// (kExactSigmaMaxWork: docs/benchmarks.md "Exact mesh σ: tight λ enclosures").
void BM_MeshSigmaExactQuery(benchmark::State& st) {
  const std::size_t mc = static_cast<std::size_t>(st.range(0)), index = static_cast<std::size_t>(st.range(1));
  if (mc >= mesh_cases().size()) {
    st.SkipWithError("no such mesh case (CGAL sample meshes not found)");
    return;
  }
  const Prepared& p = prepared(mc);
  const ExactQueries e = exact_queries(p);
  if (index >= e.q.size()) {
    st.SkipWithError("no such query");
    return;
  }
  const auto& [k, upper] = e.q[index];
  for (auto _ : st)
    benchmark::DoNotOptimize(pendepth::mesh3::exact_minimum(e.m, pendepth::Pose3(), p.poses[k], upper, SIZE_MAX));
  st.SetLabel(mesh_cases()[mc].name + " pose " + std::to_string(k));
  st.counters["units"] = static_cast<double>(pendepth::mesh3::last_exact_work.units);
  for (const auto& [name, v] : work_parts()) st.counters[name] = v;
}

// The hulls of both meshes (what users do today) against the exact σ_d.
void BM_MeshHullError(benchmark::State& st) {
  mesh_query(st, [](const Prepared& p, std::size_t i) { benchmark::DoNotOptimize(p.hulls.along(pendepth::Pose3(), p.poses[i], p.dirs[i])); });
  const Prepared& p = prepared(static_cast<std::size_t>(st.range(0)));
  double worst = 0, sum = 0;
  int n = 0, false_hits = 0;
  // 128 translations: Q's box centre uniform in P's box grown by Q's box; random directions.
  const auto bp = p.pair.P().polytope().vertices(), bq = p.pair.Q().polytope().vertices();
  Vec3 lo = bp[0], hi = lo, qlo = bq[0], qhi = qlo;
  for (const Vec3& v : bp) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  for (const Vec3& v : bq) qlo = qlo.cwiseMin(v), qhi = qhi.cwiseMax(v);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  for (int i = 0; i < 128; ++i) {
    const Vec3 c = lo - (qhi - qlo) / 2 + (hi - lo + qhi - qlo).cwiseProduct(Vec3(U(rng), U(rng), U(rng)));
    const pendepth::Pose3 pose(c - (qlo + qhi) / 2);
    const Vec3 d(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
    const double exact = p.pair.along(pendepth::Pose3(), pose, d).depth;
    const double hull = p.hulls.along(pendepth::Pose3(), pose, d).depth;
    if (exact == 0) {
      false_hits += hull > 0;
      continue;
    }
    const double e = std::abs(hull - exact) / exact;
    worst = std::max(worst, e), sum += e, ++n;
  }
  st.counters["exact_nonzero"] = n;
  st.counters["hull_rel_err_mean"] = n ? sum / n : 0;
  st.counters["hull_rel_err_max"] = worst;
  st.counters["hull_says_overlap_when_apart"] = false_hits;
}

#ifdef PENDEPTH_BENCH_FCL
// ---- FCL 0.7 on the same meshes: what users read as "the mesh–mesh depth" today ----
// fcl::collide on two fcl::BVHModel (enable_contact) tests triangle pairs only
// (narrowphase/detail/traversal/collision/mesh_collision_traversal_node-inl.h, leafTesting →
// Intersect::intersect_Triangle, intersect-inl.h): one Contact per intersecting triangle pair
// (up to 2 points), whose penetration_depth is the smaller of (a) the depth of Q's triangle's
// deepest vertex below P's triangle's plane and (b) the depth of P's deepest vertex below Q's
// plane, with that plane's normal (n_P, or −n_Q) — a local, per-triangle-pair quantity, not a
// translation of the meshes. Users take the largest one and its normal. A mesh inside the other
// (no triangle pair crossing) is no collision. fcl::distance on two BVHModels is the least
// triangle–triangle distance (TriangleDistance::triDistance): 0 when surfaces cross, never
// negative, so enable_signed_distance (distance-inl.h: only when min_distance < 0) does nothing.
template <class BV>
std::shared_ptr<fcl::BVHModel<BV>> fcl_model(const pendepth::Mesh3& m) {
  auto b = std::make_shared<fcl::BVHModel<BV>>();
  std::vector<fcl::Vector3d> v(m.points().begin(), m.points().end());
  std::vector<fcl::Triangle> t;
  for (const auto& x : m.triangles()) t.emplace_back(x[0], x[1], x[2]);
  b->beginModel();
  b->addSubModel(v, t);
  b->endModel();
  return b;
}

struct FclPair {
  std::shared_ptr<fcl::CollisionGeometryd> p[2], q[2];  // [0] OBBRSS, [1] AABB
};
const FclPair& fcl_pair(std::size_t index) {
  static std::map<std::size_t, std::unique_ptr<FclPair>> cache;
  auto& e = cache[index];
  if (!e) {
    const Prepared& p = prepared(index);
    const pendepth::Mesh3 &mp = *p.pair.P().mesh(), &mq = *p.pair.Q().mesh();
    e.reset(new FclPair{{fcl_model<fcl::OBBRSSd>(mp), fcl_model<fcl::AABBd>(mp)}, {fcl_model<fcl::OBBRSSd>(mq), fcl_model<fcl::AABBd>(mq)}});
  }
  return *e;
}

fcl::Transform3d fcl_pose(const pendepth::Pose3& pose) {
  fcl::Transform3d t = fcl::Transform3d::Identity();
  t.linear() = pose.rotation.toRotationMatrix();
  t.translation() = pose.translation;
  return t;
}

// What a user reads from fcl::collide with contacts: collision, the largest penetration_depth and
// its normal (from P to Q: the direction to move Q).
struct FclDepth {
  bool collision = false;
  std::size_t contacts = 0;
  double depth = 0;
  Vec3 normal{0, 0, 0};
};
FclDepth fcl_depth(const FclPair& f, int bv, const pendepth::Pose3& pose) {
  fcl::CollisionRequestd req(std::size_t{1} << 24, true);  // never stop at a contact count
  fcl::CollisionResultd res;
  fcl::collide(f.p[bv].get(), fcl::Transform3d::Identity(), f.q[bv].get(), fcl_pose(pose), req, res);
  FclDepth d{res.isCollision(), res.numContacts()};
  for (std::size_t k = 0; k < res.numContacts(); ++k)
    if (const auto& c = res.getContact(k); k == 0 || c.penetration_depth > d.depth) d.depth = c.penetration_depth, d.normal = c.normal;
  return d;
}
double fcl_distance(const FclPair& f, int bv, const pendepth::Pose3& pose) {
  fcl::DistanceRequestd req(false, true);  // signed requested: no effect on BVH pairs (above)
  fcl::DistanceResultd res;
  fcl::distance(f.p[bv].get(), fcl::Transform3d::Identity(), f.q[bv].get(), fcl_pose(pose), req, res);
  return res.min_distance;
}

// µs per query of FCL on the 64 poses of mesh_query. Args: mesh case, BV (0 OBBRSS, 1 AABB),
// query (0 collide without contacts: the overlap peer, 1 collide with all contacts: the depth
// peer, 2 distance).
void BM_MeshFcl(benchmark::State& st) {
  const int bv = static_cast<int>(st.range(1)), query = static_cast<int>(st.range(2));
  const FclPair& f = fcl_pair(static_cast<std::size_t>(st.range(0)));
  mesh_query(st, [&](const Prepared& p, std::size_t i) {
    if (query == 1) benchmark::DoNotOptimize(fcl_depth(f, bv, p.poses[i]));
    else if (query == 2) benchmark::DoNotOptimize(fcl_distance(f, bv, p.poses[i]));
    else {
      fcl::CollisionRequestd req;
      fcl::CollisionResultd res;
      benchmark::DoNotOptimize(fcl::collide(f.p[bv].get(), fcl::Transform3d::Identity(), f.q[bv].get(), fcl_pose(p.poses[i]), req, res));
    }
  });
  static const char* bvs[] = {" OBBRSS", " AABB"};
  static const char* q[] = {" collide", " contacts", " distance"};
  st.SetLabel(mesh_cases()[static_cast<std::size_t>(st.range(0))].name + bvs[bv] + q[query]);
}

// The same peers on one side of the exact overlap test, so that the means compare like with like:
// overlapping poses, pendepth σ against FCL's collide with all contacts; apart poses, pendepth's
// signed distance against fcl::distance. Args: mesh case, side (0 overlapping, 1 apart), engine
// (0 pendepth, 1 FCL OBBRSS, 2 FCL AABB).
void BM_MeshFclSide(benchmark::State& st) {
  const std::size_t index = static_cast<std::size_t>(st.range(0));
  const bool apart = st.range(1) == 1;
  const int engine = static_cast<int>(st.range(2));
  const Prepared& p = prepared(index);
  const FclPair& f = fcl_pair(index);
  const pendepth::Pose3 id;
  std::vector<pendepth::Pose3> poses;
  for (const pendepth::Pose3& pose : p.poses)
    if (p.pair.overlapping(id, pose) != apart) poses.push_back(pose);
  std::size_t i = 0;
  for (auto _ : st) {
    const pendepth::Pose3& pose = poses[i++ % poses.size()];
    if (engine == 0 && apart) benchmark::DoNotOptimize(p.pair.signed_distance(id, pose));
    else if (engine == 0) benchmark::DoNotOptimize(p.pair.minimum(id, pose));
    else if (apart) benchmark::DoNotOptimize(fcl_distance(f, engine - 1, pose));
    else benchmark::DoNotOptimize(fcl_depth(f, engine - 1, pose));
  }
  static const char* e[] = {" pendepth", " FCL OBBRSS", " FCL AABB"};
  st.SetLabel(mesh_cases()[index].name + (apart ? " apart: distance" : " overlapping: depth") + e[engine]);
  st.counters["poses"] = static_cast<double>(poses.size());
}

// Relative error of `value` against an answer known to lie in [lo, hi] (0 < lo ≤ hi): the least
// |value − x| / x over x in the bracket — exact when lo == hi, a certified lower bound otherwise.
double rel_error(double value, double lo, double hi) {
  if (value < lo) return (lo - value) / lo;
  if (value > hi) return (value - hi) / hi;
  return 0;
}

struct ErrorStat {
  int n = 0;
  double sum = 0, worst = 0;
  void add(double e) { ++n, sum += e, worst = std::max(worst, e); }
  void report(benchmark::State& st, const std::string& name) const {
    st.counters[name + "_n"] = n;
    st.counters[name + "_mean"] = n ? sum / n : 0;
    st.counters[name + "_max"] = worst;
  }
};

// FCL's mesh–mesh answer (OBBRSS; contacts do not depend on the BV) and the convex hulls' σ against
// pendepth's exact answers on the 64 poses of mesh_query, outside any timing (1 iteration):
// overlapping poses: FCL's largest depth against σ (exact where the bounds meet, else the bracket:
// counters *_bracket), against the exact σ_d along FCL's own normal (does moving Q by FCL's answer
// separate?), the hulls' σ against σ; apart poses: fcl::distance against the exact distance;
// misses both ways (exact interior-overlap test); means of σ's upper bound, FCL's depth and its
// contact count over the overlapping poses it reports.
void BM_MeshFclError(benchmark::State& st) {
  const std::size_t index = static_cast<std::size_t>(st.range(0));
  const Prepared& p = prepared(index);
  const FclPair& f = fcl_pair(index);
  const pendepth::Pose3 id;
  for (auto _ : st) {
  }
  int over = 0, met = 0, missed = 0, missed_bool = 0, false_hits = 0, hull_hits = 0, separates = 0, with_normal = 0, under = 0,
      dist_zero = 0, dist_pos = 0;
  double sigma_sum = 0, fcl_sum = 0, contacts = 0;  // over overlapping poses FCL reports
  ErrorStat sigma, sigma_bracket, along_normal, normal_excess, hull_sigma, hull_sigma_bracket, distance;
  for (const pendepth::Pose3& pose : p.poses) {
    const bool exact_over = p.pair.overlapping(id, pose);
    const FclDepth fd = fcl_depth(f, 0, pose);
    const double fdist = fcl_distance(f, 0, pose);
    fcl::CollisionResultd plain;  // collide without contacts: the plain yes / no
    fcl::collide(f.p[0].get(), fcl::Transform3d::Identity(), f.q[0].get(), fcl_pose(pose), fcl::CollisionRequestd(), plain);
    if (!exact_over) {
      false_hits += plain.isCollision();
      hull_hits += p.hulls.overlapping(id, pose);
      const double d = p.pair.signed_distance(id, pose).distance;
      if (d > 0) distance.add(std::abs(fdist - d) / d);
      continue;
    }
    ++over;
    dist_zero += fdist == 0, dist_pos += fdist > 0;
    const pendepth::Depth3 s = p.pair.minimum(id, pose), h = p.hulls.minimum(id, pose);
    const bool exact = s.lower_bound == s.upper_bound;
    met += exact;
    (exact ? hull_sigma : hull_sigma_bracket).add(rel_error(h.depth, s.lower_bound, s.upper_bound));
    missed_bool += !plain.isCollision();
    if (!fd.collision) {
      ++missed;
      continue;
    }
    (exact ? sigma : sigma_bracket).add(rel_error(fd.depth, s.lower_bound, s.upper_bound));
    sigma_sum += s.upper_bound, fcl_sum += fd.depth, contacts += static_cast<double>(fd.contacts);
    under += fd.depth < s.lower_bound;
    if (fd.normal.norm() > 0) {
      ++with_normal;
      const double a = p.pair.along(id, pose, fd.normal).depth;
      separates += fd.depth >= a;
      along_normal.add(std::abs(fd.depth - a) / a);
      normal_excess.add(rel_error(a, s.lower_bound, s.upper_bound));  // FCL's direction against σ's
    }
  }
  st.SetLabel(mesh_cases()[index].name);
  st.counters["poses"] = static_cast<double>(p.poses.size());
  st.counters["overlapping"] = over;
  st.counters["sigma_exact"] = met;
  st.counters["fcl_no_contact_overlap"] = missed;
  st.counters["fcl_no_collision_overlap"] = missed_bool;
  st.counters["fcl_collision_apart"] = false_hits;
  st.counters["hull_overlap_apart"] = hull_hits;
  st.counters["fcl_under_sigma"] = under;
  st.counters["fcl_move_separates"] = separates;
  st.counters["fcl_with_normal"] = with_normal;
  st.counters["fcl_dist_zero_overlap"] = dist_zero;
  st.counters["fcl_dist_pos_overlap"] = dist_pos;
  const double reported = over - missed;
  st.counters["sigma_upper_mean"] = reported ? sigma_sum / reported : 0;
  st.counters["fcl_depth_mean"] = reported ? fcl_sum / reported : 0;
  st.counters["fcl_contacts_mean"] = reported ? contacts / reported : 0;
  sigma.report(st, "fcl_sigma");
  sigma_bracket.report(st, "fcl_sigma_bracket");
  along_normal.report(st, "fcl_sigma_d_normal");
  normal_excess.report(st, "sigma_d_normal_over_sigma");
  hull_sigma.report(st, "hull_sigma");
  hull_sigma_bracket.report(st, "hull_sigma_bracket");
  distance.report(st, "fcl_distance");
}
#endif

// A mesh against a point (its signed distance field: src/mesh3/mesh_point.cpp), a sphere of
// radius 0.4 (the piece walk: src/mesh3/mesh_mixed.cpp) or a segment of length ~1.2 (exact
// rationals on the triangles: src/mesh3/mesh_segment.cpp): µs per query. Args: mesh case (1 comb
// of 8 teeth, 2 comb of 32, 4 torus 16 × 8 — points only: its rounded decomposition has pieces too
// thin for the flat and rounded-shape engines), shape (0 point, 1 sphere, 2 segment), query (0
// signed distance, 1 σ_d, 2 σ, 3 cast, 4 overlap; 100 a fine torus 64 × 32 = 4096 triangles,
// points only). Translations uniform in the
// mesh's box (about half inside), random directions.
constexpr std::size_t kFineTorus = 100;
io::MeshFile mixed_mesh(std::size_t mesh) { return mesh == kFineTorus ? torus(64, 32) : mesh_cases()[mesh].p; }
std::string mixed_name(std::size_t mesh) {
  if (mesh == kFineTorus) return "torus64";
  const std::string& n = mesh_cases()[mesh].name;
  return n.substr(0, n.find('_'));
}
struct Mixed {
  pendepth::Pair3 pair;
  std::vector<pendepth::Pose3> poses;
  std::vector<Vec3> dirs;
};
const Mixed& mixed(std::size_t mesh, int shape) {
  static std::map<std::pair<std::size_t, int>, std::unique_ptr<Mixed>> cache;
  auto& e = cache[{mesh, shape}];
  if (!e) {
    const pendepth::Mesh3 m = pendepth::Mesh3::validate(mixed_mesh(mesh), "P");
    const pendepth::Shape3 s = shape == 0   ? pendepth::Shape3::point(Vec3::Zero())
                               : shape == 1 ? pendepth::Shape3::sphere(0.4)
                               : shape == 2 ? pendepth::Shape3::segment(Vec3(-0.5, -0.3, -0.2), Vec3(0.5, 0.3, 0.2))
                                            : pendepth::Shape3::flat(std::vector<Vec3>{Vec3(-0.5, -0.3, -0.2), Vec3(0.5, 0.3, 0.2),
                                                                                       Vec3(0.1, -0.4, 0.3)},
                                                                     "triangle");
    e.reset(new Mixed{pendepth::Pair3(pendepth::Shape3::from_mesh(m), s), {}, {}});
    Vec3 lo = m.points()[0], hi = lo;
    for (const Vec3& v : m.points()) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> U(0, 1);
    for (int k = 0; k < 64; ++k) {
      e->poses.emplace_back(lo + (hi - lo).cwiseProduct(Vec3(U(rng), U(rng), U(rng))));
      e->dirs.emplace_back(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
    }
  }
  return *e;
}
void BM_MeshMixed(benchmark::State& st) {
  const std::size_t mesh = static_cast<std::size_t>(st.range(0));
  const int shape = static_cast<int>(st.range(1)), query = static_cast<int>(st.range(2));
  const Mixed& x = mixed(mesh, shape);
  const pendepth::Pose3 id;
  std::size_t i = 0;
  for (auto _ : st) {
    const std::size_t k = i++ % x.poses.size();
    if (query == 0) benchmark::DoNotOptimize(x.pair.signed_distance(id, x.poses[k]));
    else if (query == 1) benchmark::DoNotOptimize(x.pair.along(id, x.poses[k], x.dirs[k]));
    else if (query == 2) benchmark::DoNotOptimize(x.pair.minimum(id, x.poses[k]));
    else if (query == 3) benchmark::DoNotOptimize(x.pair.cast(id, x.poses[k], x.dirs[k]));
    else benchmark::DoNotOptimize(x.pair.overlapping(id, x.poses[k]));
  }
  static const char* q[] = {"distance", "along", "minimum", "cast", "overlap"};
  static const char* sh[] = {"_point_", "_sphere_", "_segment_", "_triangle_"};
  st.SetLabel(mixed_name(mesh) + sh[shape] + q[query]);
  int over = 0;
  for (const auto& pose : x.poses) over += x.pair.overlapping(id, pose);
  st.counters["overlapping"] = over;
}

void mesh_args(benchmark::internal::Benchmark* b) {
  for (std::size_t i = 0; i < mesh_cases().size(); ++i) b->Arg(static_cast<int>(i));
  b->Unit(benchmark::kMicrosecond);
}

}  // namespace

BENCHMARK(BM_MeshOverlap)->Apply(mesh_args);
BENCHMARK(BM_MeshAlong)->Apply(mesh_args);
BENCHMARK(BM_MeshDistance)->Apply(mesh_args);
BENCHMARK(BM_MeshCast)->Apply(mesh_args);
BENCHMARK(BM_MeshMinimumBounds)->Apply(mesh_args);
BENCHMARK(BM_MeshMinimumBoundsOnly)->Apply(mesh_args);
BENCHMARK(BM_MeshSigmaExact)->ArgsProduct({{0, 1, 2, 3, 4, 5, 6, 7}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MeshSigmaExactQuery)->ArgsProduct({{0, 1, 2, 3, 4, 5, 6, 7}, {0, 1, 2, 3, 4, 5, 6, 7, 8}})->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MeshAlongDescent)->Apply(mesh_args);
BENCHMARK(BM_MeshMinimumBoundsDescent)->Apply(mesh_args);
BENCHMARK(BM_MeshHullError)->Apply(mesh_args);
#ifdef PENDEPTH_BENCH_FCL
BENCHMARK(BM_MeshFcl)->ArgsProduct({{0, 1, 2, 3, 4, 5, 6, 7}, {0, 1}, {0, 1, 2}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MeshFclSide)->ArgsProduct({{0, 1, 2, 3, 4, 5, 6, 7}, {0, 1}, {0, 1, 2}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MeshFclError)->DenseRange(0, 7)->Iterations(1)->Unit(benchmark::kMillisecond);
#endif
BENCHMARK(BM_MeshMixed)
    ->Apply([](benchmark::internal::Benchmark* b) {
      for (const auto& [mesh, shape] :
           {std::pair<int, int>{1, 0}, {4, 0}, {static_cast<int>(kFineTorus), 0}, {1, 1}, {2, 1}, {1, 2}, {2, 2}, {1, 3}, {2, 3}})
        for (int q = 0; q < 5; ++q) b->Args({mesh, shape, q});
    })
    ->Unit(benchmark::kMicrosecond);

BENCHMARK(BM_Validate_pendepth)->RangeMultiplier(4)->Range(8, 512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Validate_CGAL_PMP)->RangeMultiplier(4)->Range(8, 512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Decompose_torus)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Decompose_comb)->Arg(2)->Arg(8)->Arg(32)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
