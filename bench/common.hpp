// Shared helpers of the pendepth benchmark programs: a pinned random generator, the regular-ish
// random convex polygons every 2D benchmark uses, and cycling through pre-generated queries.
#pragma once

#include <pendepth/polygon.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace pendepth::bench {

/// Fixed-seed generator; every input of a run is a function of (seed, size) only.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * std::generate_canonical<double, 53>(engine_);
  }

 private:
  std::mt19937_64 engine_;
};

/// n points on a random ellipse (semi-axes in [0.75, 2], random rotation, centre in
/// [-0.5, 0.5]²) at jittered angles 2π(k + u_k)/n, u_k ∈ [0, 0.9): regular-ish, no two points
/// closer than a tenth of the regular spacing. Hulled exactly, so the result has n vertices
/// unless rounding made a vertex non-strictly convex (never observed).
inline ConvexPolygon random_ellipse_polygon(std::size_t n, Rng& rng, std::string_view name) {
  const double a = rng.uniform(1.0, 2.0), b = rng.uniform(0.75, 1.5);
  const double phi = rng.uniform(0, 2 * std::numbers::pi);
  const double cx = rng.uniform(-0.5, 0.5), cy = rng.uniform(-0.5, 0.5);
  const double c = std::cos(phi), s = std::sin(phi);
  std::vector<Vec2> pts(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double th = 2 * std::numbers::pi * (double(k) + rng.uniform(0, 0.9)) / double(n);
    const double x = a * std::cos(th), y = b * std::sin(th);
    pts[k] = Vec2(cx + c * x - s * y, cy + s * x + c * y);
  }
  return ConvexPolygon::hull(pts, name);
}

/// Number of pre-generated queries per size; a power of two so cycling is a mask.
inline constexpr std::size_t kQueries = 1024;
inline std::size_t next_query(std::size_t i) { return (i + 1) & (kQueries - 1); }

/// A comma list of sizes from the environment variable `name` (e.g. PENDEPTH_BENCH_N), or
/// `fallback` when it is unset or empty.
inline std::vector<std::size_t> env_sizes(const char* name, std::vector<std::size_t> fallback) {
  const char* v = std::getenv(name);
  if (!v || !*v) return fallback;
  std::vector<std::size_t> out;
  std::stringstream ss(v);
  for (std::string f; std::getline(ss, f, ',');)
    if (!f.empty()) out.push_back(std::stoull(f));
  return out;
}

}  // namespace pendepth::bench
