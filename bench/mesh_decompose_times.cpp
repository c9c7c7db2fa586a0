// Closed meshes: validation and convex decomposition, timed one file at a time
// (docs/benchmarks.md "Closed meshes: validation and convex decomposition"). Not a Google
// Benchmark: one run per mesh, seconds each; bench/run_mesh_decompose.sh runs it over CGAL's sample
// meshes, each under a watchdog (timeout), so a decomposition that takes minutes is cut off and
// reported as such instead of hanging the run.
//
//   mesh_decompose_times FILE   → one line: file, triangles, reflex edges, validate s, then (after
//                                 a flush, so a killed run still shows its validation) pieces,
//                                 rounded pieces, cut vertices, cells, decomposition s — or "convex" /
//                                 the InvalidInput message.
#include <pendepth/io.hpp>
#include <pendepth/mesh3.hpp>

#include "mesh3/convex_decomposition_nef.hpp"

#include <chrono>
#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2 && argc != 4) {
    std::fprintf(stderr, "usage: mesh_decompose_times FILE [MAX_REFLEX_PER_CELL MAX_DEPTH]\n");
    return 2;
  }
  using clock = std::chrono::steady_clock;
  auto secs = [](clock::time_point a) { return std::chrono::duration<double>(clock::now() - a).count(); };
  std::printf("%s", argv[1]);
  try {
    const auto t0 = clock::now();
    const pendepth::io::MeshFile f = pendepth::io::read_mesh(argv[1]);
    const pendepth::Mesh3 m = pendepth::Mesh3::validate(f, "mesh");
    std::printf(" triangles %zu reflex %zu validate_s %.3f", m.triangles().size(), m.reflex_edges(), secs(t0));
    std::fflush(stdout);
    if (m.convex()) {
      std::printf(" convex\n");
      return 0;
    }
    const auto t1 = clock::now();
    const pendepth::ConvexDecomposition3 d =
        argc == 4 ? pendepth::detail::convex_decomposition(m, {std::stoul(argv[2]), std::stoi(argv[3])})
                  : pendepth::convex_decomposition(m);
    std::printf(" pieces %zu rounded %zu dropped %zu cut_vertices %zu cells %zu decompose_s %.3f\n", d.pieces.size(),
                d.rounded_pieces, d.dropped_slivers, d.cut_vertices, d.cells, secs(t1));
  } catch (const std::exception& e) {
    std::printf(" invalid: %s\n", e.what());
  }
  return 0;
}
