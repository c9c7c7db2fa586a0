// Polygon (simple, with holes): validation and normal form (docs/design.md §1.3).
//
// Every decision is an exact predicate on the input doubles. Ring simplicity and ring–ring
// disjointness are checked together by a sweep over the edges (src/polygon2/edge_sweep.cpp: a
// box sweep with an O(N) budget, then a Shamos–Hoey sweep): O(N log N). Containment of the holes: one exact point-in-ring
// test per (hole, ring) pair, O(h·N).
#include <pendepth/polygon.hpp>

#include "polygon2/edge_sweep.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace pendepth {

namespace {

using predicates::orient2d;

[[noreturn]] void fail(const std::string& name, const std::string& what) {
  throw InvalidInput(name + ": " + what);
}

std::string ring_name(std::size_t k) { return polygon2::validation_ring_name(k); }

std::string fmt_point(const Vec2& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

// Winding number of ring r around p (p not on the ring), exact: half-open rule on y.
int winding(std::span<const Vec2> r, const Vec2& p) {
  int w = 0;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const Vec2 &a = r[i], &b = r[(i + 1) % n];
    if (a.y() <= p.y()) {
      if (b.y() > p.y() && orient2d(a, b, p) > 0) ++w;
    } else if (b.y() <= p.y() && orient2d(a, b, p) < 0) {
      --w;
    }
  }
  return w;
}

}  // namespace

std::size_t Polygon::ring_of(std::size_t g) const {
  return static_cast<std::size_t>(std::upper_bound(offset_.begin(), offset_.end(), g) - offset_.begin()) - 1;
}

Polygon Polygon::simple(std::span<const Vec2> outer, std::string_view name) {
  return Polygon(std::vector<std::vector<Vec2>>{std::vector<Vec2>(outer.begin(), outer.end())}, name);
}

Polygon::Polygon(const std::vector<std::vector<Vec2>>& rings_in, std::string_view name_in)
    : name_(name_in) {
  const std::string& name = name_;
  if (rings_in.empty()) fail(name, "no rings (an outer ring is required)");

  // 1. Per ring: finiteness, closing vertex, distinct points, repeated vertices, zero area.
  std::vector<std::vector<Vec2>> rings;
  for (std::size_t k = 0; k < rings_in.size(); ++k) {
    std::vector<Vec2> r = rings_in[k];
    for (std::size_t i = 0; i < r.size(); ++i)
      if (!std::isfinite(r[i].x()) || !std::isfinite(r[i].y()))
        fail(name, ring_name(k) + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
    if (r.size() > 1 && r.front() == r.back()) r.pop_back();
    std::vector<std::size_t> order(r.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return r[a].x() < r[b].x() || (r[a].x() == r[b].x() && (r[a].y() < r[b].y() || (r[a].y() == r[b].y() && a < b)));
    });
    std::size_t distinct = r.empty() ? 0 : 1;
    for (std::size_t j = 1; j < order.size(); ++j) distinct += r[order[j]] != r[order[j - 1]];
    if (distinct < 3)
      fail(name, ring_name(k) + ": fewer than 3 distinct points (" + std::to_string(distinct) + ")");
    for (std::size_t j = 1; j < order.size(); ++j)
      if (r[order[j]] == r[order[j - 1]])
        fail(name, ring_name(k) + ": vertices " + std::to_string(order[j - 1]) + " and " +
                       std::to_string(order[j]) + " coincide at " + fmt_point(r[order[j]]));
    bool collinear = true;
    for (std::size_t i = 2; i < r.size() && collinear; ++i) collinear = orient2d(r[0], r[1], r[i]) == 0;
    if (collinear) fail(name, ring_name(k) + ": zero area (all vertices are collinear)");
    rings.push_back(std::move(r));
  }

  // 2. Edge sweep: within a ring, non-adjacent edges must not meet and adjacent edges must not
  // fold back; edges of different rings must not meet at all.
  polygon2::check_edges(rings, name);

  // 3. Orientation (the lowest-leftmost vertex of a simple ring is strictly convex) and
  // containment of the holes (rings are now pairwise disjoint, so one vertex decides).
  std::vector<int> orient(rings.size());
  for (std::size_t k = 0; k < rings.size(); ++k) {
    const auto& r = rings[k];
    std::size_t low = 0, n = r.size();
    for (std::size_t i = 1; i < n; ++i)
      if (r[i].y() < r[low].y() || (r[i].y() == r[low].y() && r[i].x() < r[low].x())) low = i;
    orient[k] = orient2d(r[(low + n - 1) % n], r[low], r[(low + 1) % n]);
  }
  for (std::size_t k = 1; k < rings.size(); ++k) {
    if (winding(rings[0], rings[k][0]) == 0)
      fail(name, ring_name(k) + " lies outside the outer ring");
    for (std::size_t l = 1; l < rings.size(); ++l)
      if (l != k && winding(rings[l], rings[k][0]) != 0)
        fail(name, ring_name(k) + " lies inside " + ring_name(l));
  }

  // 4. Normal form and exact area.
  mpq_class area2 = 0;
  offset_.push_back(0);
  for (std::size_t k = 0; k < rings.size(); ++k) {
    const auto& r = rings[k];
    const std::size_t n = r.size();
    const bool reverse = (k == 0) != (orient[k] > 0);
    for (std::size_t j = 0; j < n; ++j) {
      std::size_t i = reverse ? (n - j) % n : j;
      v_.push_back(r[i]);
      input_index_.push_back(i);
    }
    offset_.push_back(v_.size());
    for (std::size_t j = offset_[k]; j < offset_[k + 1]; ++j) {
      const Vec2 &a = v_[j], &b = v_[j + 1 == offset_[k + 1] ? offset_[k] : j + 1];
      area2 += mpq_class(a.x()) * mpq_class(b.y()) - mpq_class(a.y()) * mpq_class(b.x());
    }
  }
  area_ = mpq_class(area2 / 2).get_d();
}

}  // namespace pendepth
