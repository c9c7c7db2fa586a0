// Convex parts of a triangulated polygon (Hertel–Mehlhorn): see convex_parts.hpp.
// Rings are circular linked lists over vertex slots (three per triangle): removing a diagonal
// splices two rings in O(1); the slots a splice drops point to the kept slot of the same vertex.
#include "nonconvex2/convex_parts.hpp"

#include <algorithm>

namespace pendepth::nonconvex2 {

namespace {
// Exact turn at b on a → b → c: > 0 left, 0 straight, < 0 right.
int turn(const Vec2& a, const Vec2& b, const Vec2& c) { return predicates::cross_edges(a, b, b, c); }
}  // namespace

void convex_parts(const std::vector<Tri>& tris, bool merge, ConvexParts& out) {
  const auto T = static_cast<std::uint32_t>(tris.size());
  out.v.clear(), out.id.clear(), out.start.clear(), out.lo.clear(), out.hi.clear();
  out.v.reserve(3 * T), out.id.reserve(3 * T), out.start.reserve(T + 1), out.lo.reserve(T), out.hi.reserve(T);
  auto V = [&](std::uint32_t s) -> const Vec2& { return tris[s / 3].v[s % 3]; };
  auto I = [&](std::uint32_t s) { return tris[s / 3].id[s % 3]; };
  std::vector<std::uint32_t> links(10 * T);  // one allocation: next, prev, alias (3T each), part (T)
  std::uint32_t *next = links.data(), *prev = next + 3 * T, *alias = prev + 3 * T, *part = alias + 3 * T;
  for (std::uint32_t s = 0; s < 3 * T; ++s) {
    next[s] = s % 3 == 2 ? s - 2 : s + 1;
    prev[s] = s % 3 == 0 ? s + 2 : s - 1;
    alias[s] = s;
  }
  for (std::uint32_t t = 0; t < T; ++t) part[t] = t;
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
    auto tri_next = [](std::uint32_t s) { return s % 3 == 2 ? s - 2 : s + 1; };
    std::uint32_t nv = 0;
    for (std::uint32_t s = 0; s < 3 * T; ++s) nv = std::max(nv, I(s) + 1);
    constexpr std::uint32_t kNone = ~std::uint32_t(0);
    std::vector<std::uint32_t> lists(nv + 3 * T, kNone);
    std::uint32_t *head = lists.data(), *link = head + nv;
    for (std::uint32_t s = 0; s < 3 * T; ++s) link[s] = head[I(s)], head[I(s)] = s;
    for (std::uint32_t s = 0; s < 3 * T; ++s) {
      const std::uint32_t a = I(s), b = I(tri_next(s));
      if (a > b) continue;  // each diagonal once
      std::uint32_t r = head[b];
      while (r != kNone && I(tri_next(r)) != a) r = link[r];
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
      out.v.push_back(V(s));
      out.id.push_back(I(s));
      lo = lo.cwiseMin(V(s));
      hi = hi.cwiseMax(V(s));
      s = next[s];
    } while (s != s0);
    out.lo.push_back(lo);
    out.hi.push_back(hi);
  }
  out.start.push_back(std::uint32_t(out.v.size()));
}

}  // namespace pendepth::nonconvex2
