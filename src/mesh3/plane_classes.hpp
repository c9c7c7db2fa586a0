// Private: equality of planes and the classes of equal planes of the exact mesh σ
// (mesh_sigma_exact.cpp; issue 17 item 4, docs/benchmarks.md "Exact mesh σ: plane classes, one
// rounding guard"), kept apart from the sums' geometry so that tests/mesh3/test_plane_classes.cpp
// can drive them with constructed planes (equal planes written differently, distinct planes at
// exactly equal distance, one-ulp neighbours) against GMP rationals.
#pragma once

#include "mesh3/plane_number.hpp"

#include <CGAL/Interval_nt.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace pendepth::mesh3::detail {

// Certainly not the same plane: the distances from 0 (|c|/|n| accurate to a few ulps, as
// minkowski_facets gives them; the margin of the distance prunes) differ.
inline bool distances_differ(double a, double b) { return std::abs(a - b) > (a + b) * 0x1p-40 + 0x1p-1000; }

// planes pa and pb are the same plane n·x = c: b.n = t·a.n with t != 0 and b.c = t·a.c, exactly;
// same_side: also t > 0 (the same half-space n·x <= c). Ps gives for each p: dist(p) (|c|/|n|,
// a few ulps); ni(p), ci(p): enclosures of n (.x .y .z) and c (Interval_nt<true>: a proven
// forward error bound); exact(p): .n (.x .y .z) and .c as PlaneNumbers. filtered: the distance
// margin and the interval enclosures decide when they can (the filter's products in
// Interval_nt<false> under one rounding guard: the same enclosures as Interval_nt<true>), the
// exact numbers otherwise; unfiltered: the exact numbers only. O(1) interval operations, one
// exact test only when the planes are equal or nearly so.
template <class Ps>
bool same_plane(const Ps& ps, std::size_t pa, std::size_t pb, bool same_side, bool filtered) {
  auto cross = [](const auto& a, const auto& b) {
    return std::array{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  };
  auto dot = [](const auto& a, const auto& b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
  if (filtered) {
    if (distances_differ(ps.dist(pa), ps.dist(pb))) return false;
    using IF = CGAL::Interval_nt<false>;
    struct V {
      IF x, y, z;
    };
    auto fast = [](const CGAL::Interval_nt<true>& v) { return IF(v.inf(), v.sup()); };
    auto fast3 = [&](const auto& v) { return V{fast(v.x), fast(v.y), fast(v.z)}; };
    auto nonzero = [](const IF& v) { return v.inf() > 0 || v.sup() < 0; };
    CGAL::Protect_FPU_rounding<true> up;
    const V na = fast3(ps.ni(pa)), nb = fast3(ps.ni(pb));
    for (const IF& x : cross(na, nb))
      if (nonzero(x)) return false;
    const IF ab = dot(na, nb);
    if (same_side && !(ab.sup() > 0)) return false;
    if (nonzero(fast(ps.ci(pa)) * ab - fast(ps.ci(pb)) * dot(na, na))) return false;
  }
  const auto &ea = ps.exact(pa), &eb = ps.exact(pb);
  for (const PlaneNumber& x : cross(ea.n, eb.n))
    if (!is_zero(x)) return false;
  const PlaneNumber ab = dot(ea.n, eb.n);
  if (same_side && !is_positive(ab)) return false;
  return ea.c * ab == eb.c * dot(ea.n, ea.n);
}

// Classes of equal planes (either side; planes with n != 0): cls[p] = the first plane in `order`
// (every plane, by increasing dist) that is the same plane as p (same_plane, either side,
// filtered: decided exactly). Candidates are the representatives within the distance margin of p
// (distances_differ: equal planes have equal distances up to a few ulps), so the sweep is O(P·w)
// filter tests for P planes and w representatives at one distance (a symmetric mesh's planes at
// equal distances), one exact test per plane equal to an earlier one.
template <class Ps>
void plane_classes(const Ps& ps, const std::vector<std::size_t>& order, std::vector<std::size_t>& cls) {
  cls.assign(order.size(), 0);
  std::vector<std::size_t> reps;  // representatives, in order of distance
  std::size_t start = 0;          // reps[start, end) are within the margin of the current plane
  for (std::size_t p : order) {
    while (start < reps.size() && distances_differ(ps.dist(reps[start]), ps.dist(p))) ++start;
    std::size_t r = p;
    for (std::size_t k = start; k < reps.size() && r == p; ++k)
      if (same_plane(ps, reps[k], p, false, true)) r = reps[k];
    cls[p] = r;
    if (r == p) reps.push_back(p);
  }
}

}  // namespace pendepth::mesh3::detail
