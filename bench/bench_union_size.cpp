// Size and speed of the implicit union boundary ∂O of PolygonDepth2 (DHS §4.1 Step 3, §4.2-4.3):
// explicit vertices, segments, arcs and heap bytes against n + m, build time, and per-query time
// of σ_d (hierarchy ray shooting, piece scan, triangle scan) and σ, for n = 10 … 10^5 and
// m = 4 … 10^3 on four shape families. Plain program (no peers): prints one table row per pair.
//   usage: bench_union_size [max_n] [max_m] [shape: star|smooth|comb|spiral] [min_n]
#include <pendepth/depth2_polygon_convex.hpp>

#include "polygon2/query_impl.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace {

using pendepth::Vec2;
constexpr double kPi = 3.14159265358979323846;

// Star-shaped ring, n vertices at sorted random angles, radii in [rmin, rmax].
std::vector<Vec2> star(std::mt19937_64& rng, int n, double rmin, double rmax) {
  std::uniform_real_distribution<double> ua(0, 2 * kPi), ur(rmin, rmax);
  std::vector<double> a(n);
  for (double& x : a) x = ua(rng);
  std::sort(a.begin(), a.end());
  std::vector<Vec2> r;
  for (double x : a) r.push_back(ur(rng) * Vec2(std::cos(x), std::sin(x)));
  return r;
}

// Comb with n/4 teeth of width 2, gaps 3, height 10 (pockets open upwards).
std::vector<Vec2> comb(int n) {
  const int teeth = std::max(2, n / 4);
  std::vector<Vec2> r{{0, 0}, {5.0 * teeth - 3, 0}};
  for (int k = teeth - 1; k >= 0; --k) {
    const double x0 = 5.0 * k;
    r.push_back({x0 + 2, 12});
    r.push_back({x0, 12});
    if (k > 0) {
      r.push_back({x0, 2});
      r.push_back({x0 - 3, 2});
    }
  }
  return r;
}

// Thick spiral with n vertices (n/2 per side), arms 2π·2 apart, half-width 2.5.
std::vector<Vec2> spiral(int n) {
  const int steps = std::max(4, n / 2 - 1);
  const double turns = std::max(1.0, steps / 40.0);
  std::vector<Vec2> outer, inner;
  for (int k = 0; k <= steps; ++k) {
    const double th = turns * 2 * kPi * k / steps, r = 3 + 2 * th;
    const Vec2 u(std::cos(th), std::sin(th));
    outer.push_back((r + 2.5) * u);
    inner.push_back((r - 2.5) * u);
  }
  std::vector<Vec2> ring(inner.begin(), inner.end());
  ring.insert(ring.end(), outer.rbegin(), outer.rend());
  return ring;
}

std::vector<Vec2> regular(int m, double radius) {
  std::vector<Vec2> r;
  for (int k = 0; k < m; ++k) r.push_back(radius * Vec2(std::cos(2 * kPi * (k + 0.3) / m), std::sin(2 * kPi * (k + 0.3) / m)));
  return r;
}

double now_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

int main(int argc, char** argv) {
  const int max_n = argc > 1 ? std::atoi(argv[1]) : 100000;
  const int max_m = argc > 2 ? std::atoi(argv[2]) : 1000;
  const std::string only = argc > 3 ? argv[3] : "";
  const int min_n = argc > 4 ? std::atoi(argv[4]) : 0;
  std::printf("%-7s %7s %5s | %5s %7s %7s %6s %10s %7s | %9s | %9s %9s %9s %9s\n", "shape", "n", "m", "rings", "vertex",
              "segment", "arc", "bytes", "B/(n+m)", "build ms", "along us", "scan us", "tri us", "min us");
  std::mt19937_64 rng(12345);
  for (const std::string shape : {"star", "smooth", "comb", "spiral"})
    for (int n : {10, 100, 1000, 10000, 100000}) {
      if (n > max_n || n < min_n || (!only.empty() && only != shape)) continue;
      std::vector<Vec2> ring = shape == "star"     ? star(rng, n, 60, 100)
                               : shape == "smooth" ? star(rng, n, 95, 100)
                               : shape == "comb"   ? comb(n)
                                                   : spiral(n);
      std::optional<pendepth::Polygon> Pv;
      try {
        Pv.emplace(pendepth::Polygon::simple(ring, shape));
      } catch (const pendepth::InvalidInput& e) {
        std::printf("%s n=%d: %s\n", shape.c_str(), n, e.what());
        continue;
      }
      const pendepth::Polygon& P = *Pv;
      Vec2 lo = ring[0], hi = ring[0];
      for (const Vec2& p : ring) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
      // Q about a tenth of P's extent for stars and spirals; a 2.5-radius tool for combs.
      const double qr = shape == "comb" ? 2.5 : 0.1 * (hi - lo).norm();
      for (int m : {4, 32, 256, 1000}) {
        if (m > max_m) continue;
        const pendepth::ConvexPolygon Q(regular(m, qr), "Q");
        const double t0 = now_ms();
        pendepth::PolygonDepth2 pd(P, Q);
        const double build = now_ms() - t0;
        const auto s = pd.boundary_stats();
        std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y()), ua(0, 2 * kPi);
        std::vector<Vec2> ts, ds;
        while (ts.size() < 200) {
          const Vec2 t(ux(rng), uy(rng));
          if (pd.overlapping(t)) ts.push_back(t);
        }
        for (std::size_t k = 0; k < ts.size(); ++k) ds.push_back(Vec2(std::cos(ua(rng)), std::sin(ua(rng))));
        double sink = 0;
        auto per_query = [&](int count, auto&& f) {
          const double a = now_ms();
          for (int k = 0; k < count; ++k) sink += f(ts[k % ts.size()], ds[k % ds.size()]);
          return (now_ms() - a) * 1000 / count;
        };
        const double q_along = per_query(2000, [&](const Vec2& t, const Vec2& d) { return pd.along(t, d).depth; });
        const int slow = n >= 10000 ? 20 : 200;
        const double q_scan = per_query(slow, [&](const Vec2& t, const Vec2& d) { return pendepth::polygon2::along_scan(pd, t, d).depth; });
        const double q_tri = per_query(slow, [&](const Vec2& t, const Vec2& d) { return pendepth::polygon2::along_triangles(pd, t, d).depth; });
        const double q_min = per_query(2000, [&](const Vec2& t, const Vec2&) { return pd.minimum(t).depth; });
        std::printf("%-7s %7zu %5zu | %5zu %7zu %7zu %6zu %10zu %7.0f | %9.2f | %9.2f %9.2f %9.2f %9.2f%s\n", shape.c_str(),
                    P.size(), Q.size(), s.rings, s.vertices, s.segments, s.arcs, s.bytes,
                    double(s.bytes) / double(P.size() + Q.size()), build, q_along, q_scan, q_tri, q_min, sink < 0 ? "!" : "");
        std::fflush(stdout);
      }
    }
  return 0;
}
