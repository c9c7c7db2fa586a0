// Test shape generators for 3D convex polytopes (pinned seeds; docs/algorithms.md §R5 degenerate
// families).
#pragma once

#include <pendepth/io.hpp>  // read_obj_vertices
#include <pendepth/polytope.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>
#include "test_ulps.hpp"

namespace pendepth::test3 {

/// All integer points with x² + y² + z² = N: strictly convex, massively coplanar faces.
inline std::vector<Vec3> integer_sphere(int N) {
  std::vector<Vec3> p;
  int R = static_cast<int>(std::sqrt(double(N))) + 1;
  for (int x = -R; x <= R; ++x)
    for (int y = -R; y <= R; ++y)
      for (int z = -R; z <= R; ++z)
        if (x * x + y * y + z * z == N) p.emplace_back(x, y, z);
  return p;
}

/// Integer points with x² + y² = N (a strictly convex polygon with many parallel edges).
inline std::vector<Vec2> integer_circle(int N) {
  std::vector<Vec2> p;
  int R = static_cast<int>(std::sqrt(double(N))) + 1;
  for (int x = -R; x <= R; ++x)
    for (int y = -R; y <= R; ++y)
      if (x * x + y * y == N) p.emplace_back(x, y);
  return p;
}

inline std::vector<Vec3> prism(int N, double h = 7) {
  std::vector<Vec3> p;
  for (const auto& c : integer_circle(N)) p.emplace_back(c.x(), c.y(), h), p.emplace_back(c.x(), c.y(), -h);
  return p;
}

inline std::vector<Vec3> bipyramid(int N) {
  std::vector<Vec3> p;
  for (const auto& c : integer_circle(N)) p.emplace_back(c.x(), c.y(), 0);
  p.emplace_back(0, 0, 9);
  p.emplace_back(0, 0, -11);
  return p;
}

/// Full integer grid {0..k-1}³: the hull is the cube, everything else inside or on it.
inline std::vector<Vec3> grid(int k) {
  std::vector<Vec3> p;
  for (int x = 0; x < k; ++x)
    for (int y = 0; y < k; ++y)
      for (int z = 0; z < k; ++z) p.emplace_back(x, y, z);
  return p;
}

inline std::vector<Vec3> random_sphere(std::mt19937_64& rng, int n, double r = 1) {
  std::normal_distribution<double> g;
  std::vector<Vec3> p;
  while (static_cast<int>(p.size()) < n) {
    Vec3 v(g(rng), g(rng), g(rng));
    if (v.norm() > 1e-3) p.push_back(r * v.normalized());
  }
  return p;
}

inline std::vector<Vec3> random_ball(std::mt19937_64& rng, int n, double r = 1) {
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<Vec3> p;
  while (static_cast<int>(p.size()) < n) {
    Vec3 v(U(rng), U(rng), U(rng));
    if (v.norm() <= 1) p.push_back(r * v);
  }
  return p;
}

/// |a − b| in ulps of the larger magnitude (0 when both are 0).
inline double ulps(double a, double b) { return pendepth_test::ulps_in_binade(a, b); }

/// The .obj files of PENDEPTH_SHARED_DATA/hulls, sorted by name.
inline std::vector<std::string> shared_hull_files() {
  std::vector<std::string> f;
  for (const auto& e : std::filesystem::directory_iterator(std::string(PENDEPTH_SHARED_DATA) + "/hulls"))
    if (e.path().extension() == ".obj") f.push_back(e.path().string());
  std::sort(f.begin(), f.end());
  return f;
}

/// The hulls of the shared hull files' vertices, in file order (each named by its file).
inline std::vector<ConvexPolytope> shared_hulls() {
  std::vector<ConvexPolytope> H;
  for (const auto& f : shared_hull_files()) H.push_back(ConvexPolytope::hull(read_obj_vertices(f), f));
  return H;
}

struct NamedCloud {
  std::string name;
  std::vector<Vec3> pts;
};

/// The degenerate + random families used by hull and support tests.
inline std::vector<NamedCloud> standard_clouds() {
  std::vector<NamedCloud> c;
  for (int N : {3, 25, 50, 65, 125, 325, 425, 1105})
    c.push_back({"sphere" + std::to_string(N), integer_sphere(N)});
  for (int N : {25, 65, 325, 1105, 5525}) {
    c.push_back({"prism" + std::to_string(N), prism(N)});
    c.push_back({"bipyramid" + std::to_string(N), bipyramid(N)});
  }
  c.push_back({"grid5", grid(5)});
  c.push_back({"tet", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
  std::mt19937_64 rng(20240611);
  for (int n : {4, 5, 8, 20, 100, 500, 2000}) c.push_back({"rsphere" + std::to_string(n), random_sphere(rng, n)});
  for (int n : {10, 100, 1000}) c.push_back({"rball" + std::to_string(n), random_ball(rng, n)});
  return c;
}

}  // namespace pendepth::test3
