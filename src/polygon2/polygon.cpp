// Polygon (simple, with holes): validation and normal form (docs/design.md §1.3).
//
// Every decision is an exact predicate on the input doubles. Ring simplicity and ring–ring
// disjointness are checked together by a sort-and-sweep over the edges' x-extents with a y-extent
// prefilter: O(N log N + K), K = edge pairs with overlapping bounding boxes (O(N^2) worst case,
// linear-ish on real pieces). Containment of the holes: one exact point-in-ring test per
// (hole, ring) pair, O(h·N).
#include <pendepth/polygon.hpp>

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

std::string ring_name(std::size_t k) {
  return k == 0 ? "ring 0 (outer)" : "ring " + std::to_string(k) + " (hole " + std::to_string(k) + ")";
}

std::string fmt_point(const Vec2& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

// r on the closed segment pq, given orient(p, q, r) == 0.
bool on_collinear_segment(const Vec2& p, const Vec2& q, const Vec2& r) {
  return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
         std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
}

// Do the closed segments a0a1 and b0b1 share a point?
bool segments_intersect(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  int o1 = orient2d(a0, a1, b0), o2 = orient2d(a0, a1, b1);
  int o3 = orient2d(b0, b1, a0), o4 = orient2d(b0, b1, a1);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on_collinear_segment(a0, a1, b0)) || (o2 == 0 && on_collinear_segment(a0, a1, b1)) ||
         (o3 == 0 && on_collinear_segment(b0, b1, a0)) || (o4 == 0 && on_collinear_segment(b0, b1, a1));
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

struct Edge {
  std::size_t ring, i;  // ring index, input edge index
  Vec2 a, b;
  double xlo, xhi, ylo, yhi;
};

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
  std::vector<Edge> edges;
  for (std::size_t k = 0; k < rings.size(); ++k)
    for (std::size_t i = 0, n = rings[k].size(); i < n; ++i) {
      const Vec2 &a = rings[k][i], &b = rings[k][(i + 1) % n];
      edges.push_back({k, i, a, b, std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()),
                       std::max(a.y(), b.y())});
    }
  std::sort(edges.begin(), edges.end(), [](const Edge& e, const Edge& f) { return e.xlo < f.xlo; });
  for (std::size_t u = 0; u < edges.size(); ++u) {
    const Edge& e = edges[u];
    for (std::size_t w = u + 1; w < edges.size() && edges[w].xlo <= e.xhi; ++w) {
      const Edge& f = edges[w];
      if (f.ylo > e.yhi || e.ylo > f.yhi) continue;
      if (e.ring != f.ring) {
        if (segments_intersect(e.a, e.b, f.a, f.b)) {
          const Edge &x = e.ring < f.ring ? e : f, &y = e.ring < f.ring ? f : e;
          fail(name, ring_name(x.ring) + " and " + ring_name(y.ring) + " touch or cross (edge " +
                         std::to_string(x.i) + " of ring " + std::to_string(x.ring) + ", edge " +
                         std::to_string(y.i) + " of ring " + std::to_string(y.ring) + ")");
        }
        continue;
      }
      const std::size_t n = rings[e.ring].size();
      const Edge &x = e.i < f.i ? e : f, &y = e.i < f.i ? f : e;  // x.i < y.i
      bool bad;
      if (y.i == x.i + 1) {  // share x.b == y.a
        bad = orient2d(x.a, x.b, y.b) == 0 && predicates::dot_edges(x.a, x.b, y.a, y.b) < 0;
      } else if (x.i == 0 && y.i == n - 1) {  // share y.b == x.a
        bad = orient2d(y.a, y.b, x.b) == 0 && predicates::dot_edges(y.a, y.b, x.a, x.b) < 0;
      } else {
        bad = segments_intersect(x.a, x.b, y.a, y.b);
      }
      if (bad)
        fail(name, ring_name(e.ring) + ": self-intersecting (edges " + std::to_string(x.i) + " and " +
                       std::to_string(y.i) + " intersect)");
    }
  }

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
