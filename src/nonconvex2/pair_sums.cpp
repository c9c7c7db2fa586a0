// Convex pair sums S_ij = T_i ⊕ (−U_j) of two triangulations, implicit (DHS §4.1 Step 2 with both
// shapes decomposed), and their exact line algebra (see pair_sums.hpp). Sum construction O(1)
// (5 exact angle comparisons); interval / containment O(1) (≤ 16 exact signs). The box
// hierarchies over the triangulations: src/geometry/box_tree.hpp (build O(s log s) for s
// triangles).
#include "nonconvex2/pair_sums.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/exact.hpp"

namespace pendepth::nonconvex2 {

using exact::exact_sign;

bool same_line(const Line& a, const Line& b) {
  const bool same_edge = (a.e0 == b.e0 && a.e1 == b.e1) || (a.e0 == b.e1 && a.e1 == b.e0);
  if (!same_edge || a.q_edge != b.q_edge) return false;
  // A line through one sum vertex only (p0 = p1 and q0 = q1: nfp_classify's cross line at a
  // straight vertex of both shapes) is no input edge's line: never a symbolic tie.
  if ((a.p0 == a.p1 && a.q0 == a.q1) || (b.p0 == b.p1 && b.q0 == b.q1)) return false;
  // A triangle edge of P translated by the same −Q vertex, or an edge of −U by the same P vertex
  // (the anchor c1 resp. c2 is an endpoint of the edge itself).
  return a.q_edge ? a.c1 == b.c1 : a.c2 == b.c2;
}

int known_lambda(const Line& c, const Ray& r) {
  if (!r.sym) return -1;
  // Line c passes through its start vertex (p0, q0) and end vertex (p1, q1).
  auto through = [&](std::uint32_t p, std::uint32_t q) { return (c.p0 == p && c.q0 == q) || (c.p1 == p && c.q1 == q); };
  if (through(r.p0, r.q0)) return 0;
  if (through(r.p1, r.q1)) return 1;
  return -1;
}

namespace {
// Exact sign of λ(c) − k for k ∈ {0, 1}.
int sign_minus(const Line& c, const Ray& r, int k) {
  const int den = exact_sign([&](auto L) { return line_den(c, r, L); });
  if (k == 0) return den * exact_sign([&](auto L) { return line_num(c, r, L); });
  return den * exact_sign([&](auto L) { return line_num(c, r, L) - line_den(c, r, L); });
}
}  // namespace

int line_sign(const Line& c, const Ray& r) {
  if (const int k = known_lambda(c, r); k >= 0) return k;
  return exact_sign([&](auto L) { return line_num(c, r, L); }) * exact_sign([&](auto L) { return line_den(c, r, L); });
}

int compare_lines(const Line& a, const Line& b, const Ray& r) {
  if (same_line(a, b)) return 0;  // neighbouring sums share edge lines: a symbolic tie
  const int ka = known_lambda(a, r), kb = known_lambda(b, r);
  if (ka >= 0 && kb >= 0) return (ka > kb) - (ka < kb);
  if (ka >= 0) return -sign_minus(b, r, ka);
  if (kb >= 0) return sign_minus(a, r, kb);
  {  // One floating pass for the four polynomials; the exact tiers only when it cannot decide.
    const exact::LiftFl F;
    const exact::Fl na = line_num(a, r, F), da = line_den(a, r, F), nb = line_num(b, r, F), db = line_den(b, r, F);
    const int fa = exact::certified_sign(da), fb = exact::certified_sign(db), fs = exact::certified_sign(na * db - nb * da);
    if (fa != 2 && fb != 2 && fs != 2) return fs * fa * fb;
  }
  const int sa = exact_sign([&](auto L) { return line_den(a, r, L); });
  const int sb = exact_sign([&](auto L) { return line_den(b, r, L); });
  const int s = exact_sign([&](auto L) { return line_num(a, r, L) * line_den(b, r, L) - line_num(b, r, L) * line_den(a, r, L); });
  return s * sa * sb;
}

double line_value(const Line& c, const Ray& r) {
  return exact::accurate_ratio([&](auto L) { return line_num(c, r, L); }, [&](auto L) { return line_den(c, r, L); });
}

namespace {
// Exact: the line of ray r meets the closed segment of c (from c1 + c2 to c1 + c2 + e1 − e0).
bool meets_segment(const Line& c, const Ray& r) {
  int side[2];
  for (int end = 0; end < 2; ++end)
    side[end] = exact_sign([&](auto L) {
      auto x = L(c.c1.x()) + L(c.c2.x()) - L(r.o1.x()) - L(r.o2.x()), y = L(c.c1.y()) + L(c.c2.y()) - L(r.o1.y()) - L(r.o2.y());
      if (end == 1) {
        x = x + L(c.e1.x()) - L(c.e0.x());
        y = y + L(c.e1.y()) - L(c.e0.y());
      }
      return ray_dx(r, L) * y - ray_dy(r, L) * x;
    });
  return side[0] * side[1] <= 0;
}

// Keeps the bound `best` (smallest exit when sign = -1, largest entry when +1); on a tie (a sum
// edge of P and one of −Q on one line) the edge whose segment holds the crossing wins, so the
// reported contact features are the ones actually touching.
void keep_bound(const Line& c, const Line*& best, const Ray& r, int sign) {
  if (!best) {
    best = &c;
    return;
  }
  const int s = compare_lines(c, *best, r) * sign;
  if (s > 0 || (s == 0 && !meets_segment(*best, r) && meets_segment(c, r))) best = &c;
}
}  // namespace

bool sum_interval(const Sum& S, const Ray& r, Line& entry, Line& exit, const Line* along) {
  const Line *lo = nullptr, *hi = nullptr;
  for (const Line& c : S.e) {
    // The ray runs along an edge of S (common in σ, where the ray is an edge of a neighbouring
    // sum): it never enters int S. Decided symbolically; the numeric zero would need rationals.
    if (along && same_line(c, *along)) return false;
    // Inside c's half-plane: cross(e, o + λ·dir − c) > 0, i.e. λ·cross(dir, e) < cross(c − o, e)
    // (num = cross(c − o, e), den = cross(dir, e)).
    const int den = exact_sign([&](auto L) { return line_den(c, r, L); });
    if (den == 0) {  // parallel: the whole line is strictly inside the half-plane, or nothing is
      if (known_lambda(c, r) >= 0) return false;  // through a vertex of the ray: on c's line
      if (exact_sign([&](auto L) { return line_num(c, r, L); }) <= 0) return false;
      continue;
    }
    if (den > 0) keep_bound(c, hi, r, -1);  // upper bound (exit)
    else keep_bound(c, lo, r, +1);
  }
  if (!lo || !hi || compare_lines(*lo, *hi, r) >= 0) return false;
  entry = *lo;
  exit = *hi;
  return true;
}

bool sum_contains(const Sum& S, const Vec2& t) {
  for (const Line& c : S.e) {
    const int s = exact_sign([&](auto L) {
      auto ex = L(c.e1.x()) - L(c.e0.x()), ey = L(c.e1.y()) - L(c.e0.y());
      auto wx = L(t.x()) - L(c.c1.x()) - L(c.c2.x()), wy = L(t.y()) - L(c.c1.y()) - L(c.c2.y());
      return ex * wy - ey * wx;
    });
    if (s <= 0) return false;
  }
  return true;
}

Sum make_sum(const Tri& T, const Tri& B) {
  Sum S;
  int i = 0, j = 0;
  for (int k = 0; k < 6; ++k) {
    SumVertex& v = S.v[k];
    v.p = T.v[i % 3];
    v.b = B.v[j % 3];
    v.pid = T.id[i % 3];
    v.qid = B.id[j % 3];
    Line& c = S.e[k];
    c.c1 = v.p;
    c.c2 = v.b;
    // Edge angles of both normal forms increase in [0, 2π); ties take the triangle edge first.
    const bool take_t =
        j == 3 || (i < 3 && predicates::compare_angle(T.v[i], T.v[(i + 1) % 3], B.v[j], B.v[(j + 1) % 3]) <= 0);
    if (take_t) {
      c.e0 = T.v[i];
      c.e1 = T.v[(i + 1) % 3];
      c.p0 = T.id[i];
      c.p1 = T.id[(i + 1) % 3];
      c.q0 = c.q1 = v.qid;
      c.q_edge = false;
      ++i;
    } else {
      c.e0 = B.v[j];
      c.e1 = B.v[(j + 1) % 3];
      c.p0 = c.p1 = v.pid;
      c.q0 = B.id[j];
      c.q1 = B.id[(j + 1) % 3];
      c.q_edge = true;
      ++j;
    }
  }
  return S;
}

void sum_box(const Vec2& alo, const Vec2& ahi, const Vec2& blo, const Vec2& bhi, Vec2& lo, Vec2& hi) {
  using geometry::widen_down, geometry::widen_up;
  lo = Vec2(widen_down(alo.x() + blo.x()), widen_down(alo.y() + blo.y()));
  hi = Vec2(widen_up(ahi.x() + bhi.x()), widen_up(ahi.y() + bhi.y()));
}

}  // namespace pendepth::nonconvex2
