// pendepth — the no-fit polygons of a whole instance (include/pendepth/pendepth.hpp,
// no_fit_polygons; issue 19 item 3).
//
// Contract: see the header. Steps: (1) the rotation lists are checked and every (shape, rotation)
// copy is made once (Shape2::rotated: exact for quarter turns, else rounded once and validated);
// (2) the pairs, numbered in the order i, a, j, b, are built in chunks, each chunk in parallel
// (front::parallel_for over TBB), every entry written to its own slot: entries depend on their
// own pair only, so the result is the same bits for any thread count or schedule; (3) between
// chunks the calling thread reports progress. A pair that throws (outside the numeric domain)
// is recorded in its slot and the first one, in pair order, is rethrown after its chunk.
// Cost: one Shape2::rotated per (shape, rotation), then one no_fit_polygon per pair.
#include <pendepth/pendepth.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

#include "front/batch.hpp"

namespace pendepth {

std::vector<NoFitPolygonEntry> no_fit_polygons(std::span<const Shape2> shapes, std::span<const std::vector<double>> rotations,
                                               unsigned threads, const std::function<void(std::size_t, std::size_t)>& progress) {
  const std::size_t n = shapes.size();
  if (rotations.size() != 1 && rotations.size() != n)
    throw InvalidInput("no_fit_polygons: " + std::to_string(rotations.size()) + " rotation lists for " + std::to_string(n) +
                       " shapes (give one list, or one per shape)");
  auto angles = [&](std::size_t i) -> const std::vector<double>& { return rotations.size() == 1 ? rotations[0] : rotations[i]; };
  // Step 1: the rotated copies, once per (shape, rotation); first[i] indexes shape i's.
  std::vector<Shape2> copies;
  std::vector<double> copy_angle;
  std::vector<std::size_t> first(n + 1, 0), owner;
  for (std::size_t i = 0; i < n; ++i) {
    const std::vector<double>& r = angles(i);
    if (r.empty()) throw InvalidInput("no_fit_polygons: the rotation list of shape " + std::to_string(i) + " (" + shapes[i].name() + ") is empty");
    for (const double a : r) {
      if (!std::isfinite(a))
        throw InvalidInput("no_fit_polygons: shape " + std::to_string(i) + " (" + shapes[i].name() + "): rotation is not finite");
      copies.push_back(a == 0 ? shapes[i] : shapes[i].rotated(a));
      copy_angle.push_back(a);
      owner.push_back(i);
    }
    first[i + 1] = copies.size();
  }
  // Step 2: every (copy of i, copy of j), i.e. every ordered pair of copies: the order i, a, j, b
  // is the order of copy pairs (x, y) with x, y running over the copies.
  const std::size_t C = copies.size(), total = C * C;
  std::vector<NoFitPolygonEntry> out(total);
  std::vector<std::exception_ptr> failed(total);
  auto run = [&](std::size_t k) {
    const std::size_t x = k / C, y = k % C;
    NoFitPolygonEntry& e = out[k];
    e.i = owner[x], e.j = owner[y], e.rotation_i = copy_angle[x], e.rotation_j = copy_angle[y];
    try {
      e.nfp = no_fit_polygon(copies[x], copies[y]);
    } catch (...) {
      failed[k] = std::current_exception();
    }
  };
  // Chunks of at least 64 pairs keep both cores busy between two reports.
  const std::size_t chunk = progress ? std::max<std::size_t>(64, total / 256) : std::max<std::size_t>(1, total);
  if (progress) progress(0, total);
  for (std::size_t b = 0; b < total; b += chunk) {
    const std::size_t len = std::min(chunk, total - b);
    front::parallel_for(len, threads, [&](std::size_t k) { run(b + k); });
    for (std::size_t k = b; k < b + len; ++k)
      if (failed[k]) std::rethrow_exception(failed[k]);
    if (progress) progress(b + len, total);
  }
  return out;
}

}  // namespace pendepth
