// ConvexPolygon: validation and normal form (docs/design.md §1.3; docs/algorithms.md §R2.1).
// Every decision (duplicate, collinear, turn direction, winding) is an exact predicate.
#include <pendepth/polygon.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace pendepth {

namespace {

std::string fmt_point(const Vec2& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

[[noreturn]] void fail(std::string_view name, const std::string& what) {
  throw InvalidInput(std::string(name) + ": " + what);
}

bool lower_left(const Vec2& a, const Vec2& b) {  // a strictly lower-then-lefter than b
  return a.y() < b.y() || (a.y() == b.y() && a.x() < b.x());
}

// Do the closed segments a0a1 and b0b1 intersect (exact)?
bool segments_intersect(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  using predicates::orient2d;
  int o1 = orient2d(a0, a1, b0), o2 = orient2d(a0, a1, b1);
  int o3 = orient2d(b0, b1, a0), o4 = orient2d(b0, b1, a1);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  auto on = [](const Vec2& p, const Vec2& q, const Vec2& r) {  // r on segment pq, given collinear
    return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
           std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
  };
  return (o1 == 0 && on(a0, a1, b0)) || (o2 == 0 && on(a0, a1, b1)) ||
         (o3 == 0 && on(b0, b1, a0)) || (o4 == 0 && on(b0, b1, a1));
}

}  // namespace

ConvexPolygon::ConvexPolygon(std::span<const Vec2> ring, std::string_view name) : name_(name) {
  for (std::size_t i = 0; i < ring.size(); ++i)
    if (!std::isfinite(ring[i].x()) || !std::isfinite(ring[i].y()))
      fail(name, "vertex " + std::to_string(i) + " has a non-finite coordinate");

  // 1. Drop consecutive duplicates, including a repeated closing vertex.
  std::vector<Vec2> pts;
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (!pts.empty() && pts.back() == ring[i]) continue;
    pts.push_back(ring[i]);
    idx.push_back(i);
  }
  while (pts.size() > 1 && pts.front() == pts.back()) {
    pts.pop_back();
    idx.pop_back();
  }
  {
    std::vector<Vec2> distinct = pts;
    std::sort(distinct.begin(), distinct.end(),
              [](const Vec2& a, const Vec2& b) { return lower_left(a, b); });
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    if (distinct.size() < 3)
      fail(name, "fewer than 3 distinct points (" + std::to_string(distinct.size()) + ")");
  }

  // 2. Remove collinear pass-through vertices (orient == 0, moving forward) with a worklist.
  std::size_t n = pts.size();
  std::vector<std::size_t> prv(n), nxt(n);
  std::vector<char> alive(n, 1);
  for (std::size_t i = 0; i < n; ++i) {
    prv[i] = (i + n - 1) % n;
    nxt[i] = (i + 1) % n;
  }
  std::vector<std::size_t> work(n);
  std::iota(work.begin(), work.end(), 0);
  std::size_t count = n;
  while (!work.empty() && count >= 3) {
    std::size_t i = work.back();
    work.pop_back();
    if (!alive[i]) continue;
    const Vec2 &a = pts[prv[i]], &b = pts[i], &c = pts[nxt[i]];
    if (predicates::orient2d(a, b, c) == 0 && predicates::dot_edges(a, b, b, c) > 0) {
      alive[i] = 0;
      --count;
      nxt[prv[i]] = nxt[i];
      prv[nxt[i]] = prv[i];
      work.push_back(prv[i]);
      work.push_back(nxt[i]);
    }
  }
  std::vector<Vec2> q;
  std::vector<std::size_t> qi;
  for (std::size_t i = 0; i < n; ++i)
    if (alive[i]) {
      q.push_back(pts[i]);
      qi.push_back(idx[i]);
    }
  n = q.size();
  bool all_collinear = true;
  for (std::size_t k = 2; k < n && all_collinear; ++k)
    all_collinear = predicates::orient2d(q[0], q[1], q[k]) == 0;
  if (n < 3 || all_collinear) fail(name, "zero area (all vertices are collinear)");

  // 3. Turn signs. A zero turn left now is a spike (the boundary folds back on itself).
  std::vector<int> turn(n);
  std::size_t low = 0;
  for (std::size_t i = 0; i < n; ++i) {
    turn[i] = predicates::orient2d(q[(i + n - 1) % n], q[i], q[(i + 1) % n]);
    if (turn[i] == 0)
      fail(name, "spike at vertex " + std::to_string(qi[i]) + " " + fmt_point(q[i]) +
                     ": the boundary folds back on itself");
    if (lower_left(q[i], q[low])) low = i;
  }
  const int orient = turn[low];  // the lowest-leftmost vertex is convex in any simple ring
  bool mixed = std::any_of(turn.begin(), turn.end(), [&](int s) { return s != orient; });
  if (mixed) {
    if (n <= 4096)
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j) {
          if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
          if (segments_intersect(q[i], q[(i + 1) % n], q[j], q[(j + 1) % n]))
            fail(name, "self-intersecting: edge " + std::to_string(qi[i]) + " and edge " +
                           std::to_string(qi[j]) + " intersect");
        }
    std::size_t r = 0;
    while (turn[r] == orient) ++r;
    fail(name, "not convex: reflex vertex " + std::to_string(qi[r]) + " " + fmt_point(q[r]));
  }
  if (orient < 0) {
    std::reverse(q.begin(), q.end());
    std::reverse(qi.begin(), qi.end());
  }

  // 4. Winding: with all turns left, edge angles increase modulo 2*pi; the number of cyclic
  // descents equals the number of turns around the interior. A simple ring has exactly one.
  std::size_t descents = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a0 = q[i], &a1 = q[(i + 1) % n], &b1 = q[(i + 2) % n];
    if (predicates::compare_angle(a0, a1, a1, b1) >= 0) ++descents;
  }
  if (descents != 1)
    fail(name, "self-intersecting: the ring winds " + std::to_string(descents) +
                   " times around its interior");

  v_ = std::move(q);
  input_index_ = std::move(qi);
  finish();
}

void ConvexPolygon::finish() {
  std::size_t n = v_.size(), low = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (lower_left(v_[i], v_[low])) low = i;
  std::rotate(v_.begin(), v_.begin() + low, v_.end());
  std::rotate(input_index_.begin(), input_index_.begin() + low, input_index_.end());
  top_ = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (lower_left(v_[top_], v_[i])) top_ = i;
  sample_.clear();
  for (std::size_t i = 0; i < n; i += kBlock) {
    sample_.push_back(v_[i]);
    sample_.push_back(v_[(i + 1) % n]);
  }
}

ConvexPolygon ConvexPolygon::hull(std::span<const Vec2> points, std::string_view name) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i].x()) || !std::isfinite(points[i].y()))
      fail(name, "point " + std::to_string(i) + " has a non-finite coordinate");
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const Vec2 &p = points[a], &r = points[b];
    return p.x() < r.x() || (p.x() == r.x() && p.y() < r.y());
  });
  order.erase(std::unique(order.begin(), order.end(),
                          [&](std::size_t a, std::size_t b) { return points[a] == points[b]; }),
              order.end());
  std::vector<std::size_t> h(2 * order.size() + 1);
  std::size_t k = 0;
  for (int pass = 0; pass < 2; ++pass) {
    std::size_t start = k;
    for (std::size_t t = 0; t < order.size(); ++t) {
      std::size_t i = pass == 0 ? order[t] : order[order.size() - 1 - t];
      while (k >= start + 2 && predicates::orient2d(points[h[k - 2]], points[h[k - 1]], points[i]) <= 0) --k;
      h[k++] = i;
    }
    --k;  // last point of each chain is the first of the next
  }
  h.resize(k);
  if (h.size() < 3) fail(name, "fewer than 3 non-collinear points: the hull has zero area");
  ConvexPolygon P;
  P.name_ = name;
  for (std::size_t i : h) {
    P.v_.push_back(points[i]);
    P.input_index_.push_back(i);
  }
  P.finish();
  return P;
}

double ConvexPolygon::area() const {
  double a = 0;
  for (std::size_t i = 0, n = v_.size(); i < n; ++i) {
    const Vec2 &p = v_[i], &r = v_[(i + 1) % n];
    a += (p.x() - v_[0].x()) * (r.y() - v_[0].y()) - (p.y() - v_[0].y()) * (r.x() - v_[0].x());
  }
  return a / 2;
}

}  // namespace pendepth
