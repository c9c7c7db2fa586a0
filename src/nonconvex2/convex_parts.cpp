// Convex parts of a triangulated polygon (Hertel–Mehlhorn): see convex_parts.hpp.
// Rings are circular linked lists over vertex slots (three per triangle): removing a diagonal
// splices two rings in O(1); the slots a splice drops point to the kept slot of the same vertex.
#include "nonconvex2/convex_parts.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/exact.hpp"

namespace pendepth::nonconvex2 {

namespace {
// Exact turn at b on a → b → c: > 0 left, 0 straight, < 0 right. predicates::cross_edges with
// its static filter inlined (the call and the generic filter cost more than the arithmetic);
// what the filter cannot decide (straight turns of integer pieces) goes to the exact predicate.
inline int turn(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double p1 = (b.x() - a.x()) * (c.y() - b.y()), p2 = (b.y() - a.y()) * (c.x() - b.x());
  const double d = p1 - p2, bound = exact::kCrossBound * (std::abs(p1) + std::abs(p2)) + exact::kTiny;
  if (d > bound) return 1;
  if (d < -bound) return -1;
  return predicates::cross_edges(a, b, b, c);
}
}  // namespace

void convex_parts(const std::vector<Tri>& tris, bool merge, ConvexParts& out) {
  const auto T = static_cast<std::uint32_t>(tris.size());
  const std::uint32_t n3 = 3 * T;
  out.v.clear(), out.id.clear(), out.start.clear(), out.lo.clear(), out.hi.clear();
  out.v.reserve(n3), out.id.reserve(n3), out.start.reserve(T + 1), out.lo.reserve(T), out.hi.reserve(T);
  auto V = [&](std::uint32_t s) -> const Vec2& { return tris[s / 3].v[s % 3]; };
  // Work arrays in one buffer kept by the thread (this runs once per shape and pair: fresh
  // vectors would allocate on every call): per slot its vertex id and the id of the next vertex
  // of its triangle (the triangle edge from the slot), the ring links next, prev, alias (3T
  // each), the parts' union-find (T), then the per-vertex lists (nv + 3T, merge only).
  std::uint32_t nv = 0;
  if (merge)
    for (const Tri& t : tris) nv = std::max({nv, t.id[0] + 1, t.id[1] + 1, t.id[2] + 1});
  thread_local std::vector<std::uint32_t> work;
  thread_local std::vector<std::uint64_t> sorted;  // large: directed edges (start << 32 | end), slots in `order`
  thread_local std::vector<std::uint32_t> order;
  work.resize(std::size_t(5) * n3 + T + (merge ? nv + n3 : 0));
  std::uint32_t *const id = work.data(), *const to = id + n3, *const next = to + n3, *const prev = next + n3,
                       *const alias = prev + n3, *const part = alias + n3;
  for (std::uint32_t t = 0, s = 0; t < T; ++t, s += 3) {
    id[s] = tris[t].id[0], id[s + 1] = tris[t].id[1], id[s + 2] = tris[t].id[2];
    to[s] = id[s + 1], to[s + 1] = id[s + 2], to[s + 2] = id[s];
    next[s] = s + 1, next[s + 1] = s + 2, next[s + 2] = s;
    prev[s] = s + 2, prev[s + 1] = s, prev[s + 2] = s + 1;
    alias[s] = s, alias[s + 1] = s + 1, alias[s + 2] = s + 2;
    part[t] = t;
  }
  auto live = [&](std::uint32_t s) {
    while (alias[s] != s) s = alias[s] = alias[alias[s]];
    return s;
  };
  auto find = [&](std::uint32_t t) {
    while (part[t] != t) t = part[t] = part[part[t]];
    return t;
  };
  if (merge && T > 1) {
    // Directed triangle edges a → b by their slot of a, listed per start vertex; a diagonal is an
    // edge whose reverse also occurs (a polygon edge belongs to one triangle).
    constexpr std::uint32_t kNone = ~std::uint32_t(0);
    std::uint32_t *const head = part + T, *const link = head + nv;
    std::fill(head, head + nv, kNone);
    for (std::uint32_t s = 0; s < n3; ++s) link[s] = head[id[s]], head[id[s]] = s;
    // A vertex of high degree (a fan: a triangulation joins a long straight run of vertices to a
    // few far ones) would make the list walks O(T·d) = O(T²): large triangulations look the
    // reverse edge up in the directed edges sorted by (start, end) instead, O(T log T). The
    // reverse edge is unique, so both find the same slot.
    const bool big = T > 1024;
    if (big) {
      order.resize(n3);
      for (std::uint32_t s = 0; s < n3; ++s) order[s] = s;
      std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return id[x] != id[y] ? id[x] < id[y] : to[x] < to[y]; });
      sorted.resize(n3);
      for (std::uint32_t k = 0; k < n3; ++k) sorted[k] = (std::uint64_t(id[order[k]]) << 32) | to[order[k]];
    }
    auto reverse_edge = [&](std::uint32_t a, std::uint32_t b) {
      if (big) {
        const std::uint64_t key = (std::uint64_t(b) << 32) | a;
        const auto it = std::lower_bound(sorted.begin(), sorted.end(), key);
        return it != sorted.end() && *it == key ? order[std::size_t(it - sorted.begin())] : kNone;
      }
      std::uint32_t r = head[b];
      while (r != kNone && to[r] != a) r = link[r];
      return r;
    };
    for (std::uint32_t s = 0; s < n3; ++s) {
      const std::uint32_t a = id[s], b = to[s];
      if (a > b) continue;  // each diagonal once
      const std::uint32_t r = reverse_edge(a, b);
      if (r == kNone) continue;  // a polygon edge
      const std::uint32_t X = find(s / 3), Y = find(r / 3);
      if (X == Y) continue;
      // The diagonal is still an edge of both rings: a → b in X (slots u → v), b → a in Y.
      const std::uint32_t u = live(s), v = next[u], yb = live(r), ya = next[yb];
      const std::uint32_t y_after_a = next[ya], y_before_b = prev[yb];
      if (turn(V(prev[u]), V(u), V(y_after_a)) < 0 || turn(V(y_before_b), V(v), V(next[v])) < 0) continue;
      next[u] = y_after_a, prev[y_after_a] = u;
      next[y_before_b] = v, prev[v] = y_before_b;
      alias[ya] = u, alias[yb] = v;
      part[Y] = X;
    }
  }
  // Each ring once, from the live slot of its representative triangle.
  for (std::uint32_t t = 0; t < T; ++t) {
    if (find(t) != t) continue;
    const std::uint32_t s0 = live(3 * t);
    out.start.push_back(std::uint32_t(out.v.size()));
    Vec2 lo = V(s0), hi = lo;
    std::uint32_t s = s0;
    do {
      const Vec2& x = V(s);
      out.v.push_back(x);
      out.id.push_back(id[s]);
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
      s = next[s];
    } while (s != s0);
    out.lo.push_back(lo);
    out.hi.push_back(hi);
  }
  out.start.push_back(std::uint32_t(out.v.size()));
  // Large shapes do not pin their memory in the thread.
  if (work.size() > (std::size_t(1) << 16)) work = {}, sorted = {}, order = {};
}

}  // namespace pendepth::nonconvex2
