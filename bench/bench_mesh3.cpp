// bench_mesh3 (issue 17): closed-mesh validation (Mesh3::validate: closed, manifold, oriented, no
// self-intersection, volume sign, convexity) against CGAL's Polygon_mesh_processing checks of the
// same properties (is_closed, does_self_intersect, is_outward_oriented on a Surface_mesh, Epick),
// and the exact convex decomposition (CGAL Nef convex_decomposition_3) with its piece counts.
// Inputs: tori of n × n/2 quads (2·n²/2 triangles), combs of k teeth (polycubes).
#include <pendepth/io.hpp>
#include <pendepth/mesh3.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>

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
io::MeshFile comb(int k) {
  std::map<std::array<int, 3>, bool> vox;
  for (int x = 0; x < 2 * k - 1; ++x) vox[{x, 0, 0}] = true;
  for (int x = 0; x < 2 * k - 1; x += 2) vox[{x, 1, 0}] = vox[{x, 2, 0}] = true;
  io::MeshFile f;
  f.source = "comb";
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

}  // namespace

BENCHMARK(BM_Validate_pendepth)->RangeMultiplier(4)->Range(8, 512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Validate_CGAL_PMP)->RangeMultiplier(4)->Range(8, 512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Decompose_torus)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Decompose_comb)->Arg(2)->Arg(8)->Arg(32)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
