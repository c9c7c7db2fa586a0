// Convolved triangles R_i = T_i ⊕ (−Q), implicit (DHS §4.1 Step 2); see the header for the
// representation. Build O(N log N + N log m); every query on one R_i is O(log m): binary searches
// guided by floating-point values whose answers are confirmed (or, rarely, redone) with exact
// predicates, so the result is the exact one.
#include "polygon2/convolved_triangles.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/exact.hpp"

namespace pendepth::polygon2 {

using exact::exact_sign;
using predicates::compare_angle;

namespace {

const Vec2 kZero(0, 0);

// Exact sign of orient(a1 + b1, a2 + b2, t).
int orient_sums(const Vec2& a1, const Vec2& b1, const Vec2& a2, const Vec2& b2, const Vec2& t) {
  // Double filter on the regrouped formula ux = (a2 − a1) + (b2 − b1), wx = (t − a1) − b1: each
  // factor is off by <= (2u + u²)·M with M = |first| + |second| of its computed parts, so
  // |computed − exact| <= (6u + O(u²))·(Mux·Mwy + Muy·Mwx); 8u covers that and the rounding of
  // the magnitude, kTiny underflow. Tight where the structure makes a2 − a1 or t − a1 small (fan
  // vertices sharing a P vertex, points near the sum). NaN/inf fall through to the tiered evaluation.
  const double dax = a2.x() - a1.x(), dbx = b2.x() - b1.x(), day = a2.y() - a1.y(), dby = b2.y() - b1.y();
  const double tax = t.x() - a1.x(), tay = t.y() - a1.y();
  const double ux = dax + dbx, uy = day + dby, wx = tax - b1.x(), wy = tay - b1.y();
  const double mux = std::abs(dax) + std::abs(dbx), muy = std::abs(day) + std::abs(dby);
  const double mwx = std::abs(tax) + std::abs(b1.x()), mwy = std::abs(tay) + std::abs(b1.y());
  const double bound = 8 * exact::kUnit * (mux * mwy + muy * mwx) + exact::kTiny;
  return exact::exact_sign_filtered(ux * wy - uy * wx, bound, [&](auto L) {
    auto ux = L(a2.x()) + L(b2.x()) - L(a1.x()) - L(b1.x()), uy = L(a2.y()) + L(b2.y()) - L(a1.y()) - L(b1.y());
    auto wx = L(t.x()) - L(a1.x()) - L(b1.x()), wy = L(t.y()) - L(a1.y()) - L(b1.y());
    return ux * wy - uy * wx;
  });
}

// Exact sign of X(a + b) = cross(d1 − d0, a + b − s1 − s2): the side of a + b of the line
// through s1 + s2 with direction d1 − d0.
int side_of_line(const Vec2& a, const Vec2& b, const Vec2& s1, const Vec2& s2, const Vec2& d0, const Vec2& d1) {
  // Structural zeros (a convolution vertex on the line of an edge it ends), frequent in the union
  // build, decided without the rational fallback: the line through s1 + s2 along d1 − d0 contains
  // s1 + d0 and s1 + d1 when s2 = d0 (a B edge at s1), s2 + d0 and s2 + d1 when s1 = d0.
  if (a == s1 && s2 == d0 && (b == d0 || b == d1)) return 0;
  if (b == s2 && s1 == d0 && (a == d0 || a == d1)) return 0;
  // A shared summand cancels exactly: the sign is that of a plain cross product, whose exact
  // zeros (parallel edges of axis-parallel input) the cheap tiers certify without rationals.
  if (b == s2) return predicates::cross_edges(d0, d1, s1, a);
  if (a == s1) return predicates::cross_edges(d0, d1, s2, b);
  // Double filter, as in orient_sums, on w = (a − s1) + (b − s2): |error| <= (2u + u²)·M for each
  // difference factor and w factor (M = sum of the |parts|), 8u·(Mdx·Mwy + Mdy·Mwx) overall.
  const double dx = d1.x() - d0.x(), dy = d1.y() - d0.y();
  const double ax = a.x() - s1.x(), bx = b.x() - s2.x(), ay = a.y() - s1.y(), by = b.y() - s2.y();
  const double wx = ax + bx, wy = ay + by;
  const double mdx = std::abs(dx), mdy = std::abs(dy);
  const double mwx = std::abs(ax) + std::abs(bx), mwy = std::abs(ay) + std::abs(by);
  const double bound = 8 * exact::kUnit * (mdx * mwy + mdy * mwx) + exact::kTiny;
  return exact::exact_sign_filtered(dx * wy - dy * wx, bound, [&](auto L) {
    return (L(d1.x()) - L(d0.x())) * (L(a.y()) + L(b.y()) - L(s1.y()) - L(s2.y())) -
           (L(d1.y()) - L(d0.y())) * (L(a.x()) + L(b.x()) - L(s1.x()) - L(s2.x()));
  });
}

// The floating-point values the two filters above start from (no guarantee: guesses only).
double orient_sums_guess(const Vec2& a1, const Vec2& b1, const Vec2& a2, const Vec2& b2, const Vec2& t) {
  const double ux = (a2.x() - a1.x()) + (b2.x() - b1.x()), uy = (a2.y() - a1.y()) + (b2.y() - b1.y());
  const double wx = (t.x() - a1.x()) - b1.x(), wy = (t.y() - a1.y()) - b1.y();
  return ux * wy - uy * wx;
}
double side_of_line_guess(const Vec2& a, const Vec2& b, const Vec2& s1, const Vec2& s2, const Vec2& d0, const Vec2& d1) {
  const double dx = d1.x() - d0.x(), dy = d1.y() - d0.y();
  const double wx = (a.x() - s1.x()) + (b.x() - s2.x()), wy = (a.y() - s1.y()) + (b.y() - s2.y());
  return dx * wy - dy * wx;
}

// The last index in [lo, hi) where a monotone predicate holds (true at lo, false at hi). Binary
// search on a floating-point guess of the predicate, then the exact predicate at the two indices
// around the answer, which decide it (monotone); the exact search only when the guess was wrong.
// The same answer as the exact binary search with about log(hi − lo) fewer exact evaluations.
template <class Guess, class Exact>
std::size_t last_true(std::size_t lo, std::size_t hi, Guess&& guess, Exact&& exact) {
  std::size_t a = lo, b = hi;
  while (b - a > 1) {
    const std::size_t mid = a + (b - a) / 2;
    if (guess(mid)) a = mid;
    else b = mid;
  }
  if ((a == lo || exact(a)) && (b == hi || !exact(b))) return a;
  a = lo;
  b = hi;
  while (b - a > 1) {
    const std::size_t mid = a + (b - a) / 2;
    if (exact(mid)) a = mid;
    else b = mid;
  }
  return a;
}

template <class Lift>
auto cut_num(const Cut& c, const Vec2& t, Lift L) {
  return (L(c.pt.x()) + L(c.pb.x()) - L(t.x())) * (L(c.e1.y()) - L(c.e0.y())) -
         (L(c.pt.y()) + L(c.pb.y()) - L(t.y())) * (L(c.e1.x()) - L(c.e0.x()));
}
template <class Lift>
auto cut_den(const Cut& c, const Vec2& d, Lift L) {
  return L(d.x()) * (L(c.e1.y()) - L(c.e0.y())) - L(d.y()) * (L(c.e1.x()) - L(c.e0.x()));
}

}  // namespace

int cut_sign(const Cut& c, const Vec2& t, const Vec2& d) {
  int n = exact_sign([&](auto L) { return cut_num(c, t, L); });
  int s = exact_sign([&](auto L) { return cut_den(c, d, L); });
  return n * s;
}

int compare_cuts(const Cut& a, const Cut& b, const Vec2& t, const Vec2& d) {
  int sa = exact_sign([&](auto L) { return cut_den(a, d, L); });
  int sb = exact_sign([&](auto L) { return cut_den(b, d, L); });
  int s = exact_sign([&](auto L) { return cut_num(a, t, L) * cut_den(b, d, L) - cut_num(b, t, L) * cut_den(a, d, L); });
  return s * sa * sb;
}

double cut_value(const Cut& c, const Vec2& t, const Vec2& d) {
  return exact::accurate_ratio([&](auto L) { return cut_num(c, t, L); }, [&](auto L) { return cut_den(c, d, L); });
}

ConvolvedTriangles::ConvolvedTriangles(const Polygon& P, const ConvexPolygon& Q, const std::vector<TriangleIds>* tris) {
  const std::size_t m = Q.size();
  q_top_ = Q.top();
  b_.resize(m);
  for (std::size_t j = 0; j < m; ++j) b_[j] = -Q[(q_top_ + j) % m];
  bbox_b_ = {b_[0].x(), b_[0].y(), b_[0].x(), b_[0].y()};
  for (const Vec2& b : b_) {
    bbox_b_[0] = std::min(bbox_b_[0], b.x());
    bbox_b_[1] = std::min(bbox_b_[1], b.y());
    bbox_b_[2] = std::max(bbox_b_[2], b.x());
    bbox_b_[3] = std::max(bbox_b_[3], b.y());
  }
  // For each B edge k: the number of B edges whose angle is < / <= the angle of −(edge k).
  opp_lt_.resize(m);
  opp_le_.resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    const Vec2 &x0 = b_[(k + 1) % m], &x1 = b_[k];
    auto count = [&](bool inclusive) {
      std::size_t lo = 0, hi = m;
      while (lo < hi) {
        std::size_t mid = (lo + hi) / 2;
        const int c = compare_angle(b_[mid], b_[(mid + 1) % m], x0, x1);
        if (c < 0 || (inclusive && c == 0)) lo = mid + 1;
        else hi = mid;
      }
      return static_cast<std::uint32_t>(lo);
    };
    opp_lt_[k] = count(false);
    opp_le_[k] = count(true);
  }
  const auto V = P.vertices();
  // c_j = number of B edges whose angle is < angle(τ_j) (binary search; angles increase along B).
  auto fill_c = [&](Tri& T) {
    for (int j = 0; j < T.n; ++j) {
      const Vec2 &a = T.v[j], &c = T.v[(j + 1) % T.n];
      std::size_t lo = 0, hi = m;
      while (lo < hi) {
        std::size_t mid = (lo + hi) / 2;
        if (compare_angle(b_[mid], b_[(mid + 1) % m], a, c) >= 0) hi = mid;
        else lo = mid + 1;
      }
      T.c[j] = static_cast<std::uint32_t>(lo);
    }
  };
  auto lower_left = [](const Vec2& a, const Vec2& l) { return a.y() < l.y() || (a.y() == l.y() && a.x() < l.x()); };
  std::vector<TriangleIds> own;
  if (!tris) tris = &(own = triangulate(P));
  for (const TriangleIds& ids : *tris) {  // rotated to normal form below (idempotent)
    Tri T;
    int low = 0;
    for (int j = 1; j < 3; ++j)
      if (lower_left(V[ids[j]], V[ids[low]])) low = j;
    for (int j = 0; j < 3; ++j) {
      T.id[j] = ids[(low + j) % 3];
      T.v[j] = V[T.id[j]];
    }
    fill_c(T);
    tri_.push_back(T);
  }
  // The edge sausages f ⊕ B: 2-gons in normal form (v_0 lowest-leftmost).
  for (std::size_t g = 0; g < V.size(); ++g) {
    Tri T;
    T.n = 2;
    std::uint32_t a = static_cast<std::uint32_t>(g), b = static_cast<std::uint32_t>(P.next(g));
    if (lower_left(V[b], V[a])) std::swap(a, b);
    T.id = {a, b, a};
    T.v = {V[a], V[b], V[a]};
    fill_c(T);
    seg_.push_back(T);
  }
  // Triangles around each vertex (CSR).
  fan_start_.assign(V.size() + 1, 0);
  for (const Tri& T : tri_)
    for (int j = 0; j < 3; ++j) ++fan_start_[T.id[j] + 1];
  for (std::size_t v = 0; v < V.size(); ++v) fan_start_[v + 1] += fan_start_[v];
  fan_.resize(fan_start_.back());
  std::vector<std::uint32_t> fill(fan_start_.begin(), fan_start_.end() - 1);
  for (std::size_t i = 0; i < tri_.size(); ++i)
    for (int j = 0; j < 3; ++j) fan_[fill[tri_[i].id[j]]++] = static_cast<std::uint32_t>(i);
}

void ConvolvedTriangles::vertex(std::size_t i, std::size_t k, int& slot, std::size_t& bj) const { vertex_of(tri_[i], k, slot, bj); }


Cut ConvolvedTriangles::edge(std::size_t i, std::size_t k) const { return edge_of(tri_[i], i, k); }

Cut ConvolvedTriangles::edge_of(const Tri& T, std::size_t idx, std::size_t k) const {
  const std::size_t m = b_.size();
  k %= m + T.n;
  int slot;
  std::size_t bj;
  vertex_of(T, k, slot, bj);
  Cut c;
  c.tri = static_cast<std::uint32_t>(idx);
  c.pt = T.v[slot];
  c.pb = b_[bj];
  c.b = static_cast<std::uint32_t>(bj);
  const int a = [&] { int x = 0; while (x < T.n && x + T.c[x] < k) ++x; return x; }();
  if (a < T.n && a + T.c[a] == k) {  // the triangle edge τ_a
    c.e0 = T.v[a];
    c.e1 = T.v[(a + 1) % T.n];
    c.p_from = T.id[a];
    c.p_to = T.id[(a + 1) % T.n];
    c.b_edge = false;
  } else {
    c.e0 = b_[bj];
    c.e1 = b_[(bj + 1) % m];
    c.p_from = c.p_to = T.id[slot];
    c.b_edge = true;
  }
  return c;
}

bool ConvolvedTriangles::contains_interior(std::size_t i, const Vec2& t) const { return contains_of(tri_[i], t); }
bool ConvolvedTriangles::segment_contains_interior(std::size_t g, const Vec2& t) const { return contains_of(seg_[g], t); }

bool ConvolvedTriangles::contains_of(const Tri& T, const Vec2& t) const {
  const std::size_t K = b_.size() + T.n;
  auto pt = [&](std::size_t k, Vec2& a, Vec2& b) {
    int slot;
    std::size_t bj;
    vertex_of(T, k, slot, bj);
    a = T.v[slot];
    b = b_[bj];
  };
  Vec2 a0, b0, a, b;
  pt(0, a0, b0);
  auto f = [&](std::size_t k) {  // t strictly left of the ray v_0 -> v_k
    pt(k, a, b);
    return orient_sums(a0, b0, a, b, t);
  };
  if (f(1) <= 0 || f(K - 1) >= 0) return false;
  // Last k in [1, K-2] with f(k) > 0 (monotone: true then false).
  const std::size_t lo = last_true(
      1, K - 1,
      [&](std::size_t k) {
        pt(k, a, b);
        return orient_sums_guess(a0, b0, a, b, t) > 0;
      },
      [&](std::size_t k) { return f(k) > 0; });
  Vec2 a1, b1, a2, b2;
  pt(lo, a1, b1);
  pt(lo + 1, a2, b2);
  return orient_sums(a1, b1, a2, b2, t) > 0;
}

bool ConvolvedTriangles::line_interval(std::size_t i, const Vec2& t, const Vec2& d, Cut& entry, Cut& exit) const {
  return line_interval_impl(tri_[i], i, t, kZero, dir_of(kZero, kZero, d, -1), entry, exit);
}

bool ConvolvedTriangles::line_interval(std::size_t i, const Cut& line, Cut& entry, Cut& exit) const {
  return line_interval_impl(tri_[i], i, line.pt, line.pb, line_dir(line), entry, exit);
}

bool ConvolvedTriangles::line_interval(std::size_t i, const Cut& line, const LineDir& dir, Cut& entry, Cut& exit) const {
  return line_interval_impl(tri_[i], i, line.pt, line.pb, dir, entry, exit);
}

bool ConvolvedTriangles::segment_line_interval(std::size_t g, const Vec2& t, const Vec2& d, Cut& entry, Cut& exit) const {
  return line_interval_impl(seg_[g], g, t, kZero, dir_of(kZero, kZero, d, -1), entry, exit);
}

bool ConvolvedTriangles::segment_line_interval(std::size_t g, const Cut& line, Cut& entry, Cut& exit) const {
  return line_interval_impl(seg_[g], g, line.pt, line.pb, line_dir(line), entry, exit);
}

bool ConvolvedTriangles::segment_line_interval(std::size_t g, const Cut& line, const LineDir& dir, Cut& entry,
                                               Cut& exit) const {
  return line_interval_impl(seg_[g], g, line.pt, line.pb, dir, entry, exit);
}

LineDir ConvolvedTriangles::line_dir(const Cut& line) const {
  return dir_of(line.pb, line.e0, line.e1, line.b_edge ? int(line.b) : -1);
}

LineDir ConvolvedTriangles::dir_of(const Vec2& s2, const Vec2& d0, const Vec2& d1, int bedge) const {
  const std::size_t m = b_.size();
  // A B edge's own rank is known without predicates (only when the line really is that edge).
  const int be_idx =
      (bedge >= 0 && s2 == d0 && d0 == b_[std::size_t(bedge) % m] && d1 == b_[(std::size_t(bedge) + 1) % m]) ? bedge : -1;
  LineDir r;
  r.d0 = d0;
  r.d1 = d1;
  if (be_idx >= 0) {
    r.b = {static_cast<std::uint32_t>(be_idx + 1), static_cast<std::uint32_t>(be_idx), opp_le_[be_idx], opp_lt_[be_idx]};
    return r;
  }
  // B edges with angle < (<= when inclusive) angle(x1 − x0); the same-edge tie decided by construction.
  auto count = [&](const Vec2& x0, const Vec2& x1, bool inclusive) {
    std::size_t lo = 0, hi = m;
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      const Vec2 &e0 = b_[mid], &e1 = b_[(mid + 1) % m];
      const int s = (e0 == x0 && e1 == x1) ? 0 : compare_angle(e0, e1, x0, x1);
      if (s < 0 || (inclusive && s == 0)) lo = mid + 1;
      else hi = mid;
    }
    return static_cast<std::uint32_t>(lo);
  };
  r.b = {count(d0, d1, true), count(d0, d1, false), count(d1, d0, true), count(d1, d0, false)};
  return r;
}

std::array<double, 4> ConvolvedTriangles::box(std::size_t i) const { return box_of(tri_[i]); }
std::array<double, 4> ConvolvedTriangles::segment_box(std::size_t g) const { return box_of(seg_[g]); }

std::array<double, 4> ConvolvedTriangles::box_of(const Tri& T) const {
  std::array<double, 4> r{bbox_b_[0], bbox_b_[1], bbox_b_[2], bbox_b_[3]};
  double x0 = std::min({T.v[0].x(), T.v[1].x(), T.v[2].x()}), x1 = std::max({T.v[0].x(), T.v[1].x(), T.v[2].x()});
  double y0 = std::min({T.v[0].y(), T.v[1].y(), T.v[2].y()}), y1 = std::max({T.v[0].y(), T.v[1].y(), T.v[2].y()});
  r[0] += x0;
  r[1] += y0;
  r[2] += x1;
  r[3] += y1;
  // Each coordinate is one rounded sum: pad by two ulps of its magnitude (and a tiny absolute).
  for (double& v : r) {
    const double pad = std::abs(v) * 0x1p-51 + 0x1p-1000;
    v += (&v - r.data()) < 2 ? -pad : pad;
  }
  return r;
}

// The line is s1 + s2 + μ·(d1 − d0); entry/exit cuts give μ as their λ with that line as the ray.
bool ConvolvedTriangles::line_interval_impl(const Tri& T, std::size_t i, const Vec2& s1, const Vec2& s2, const LineDir& dir,
                                            Cut& entry, Cut& exit) const {
  const std::size_t K = b_.size() + T.n;
  const Vec2 &d0 = dir.d0, &d1 = dir.d1;
  // Front edges (cross(d, e) > 0) have angles in (θ, θ + π): vertices fs .. fe (cyclic); back
  // edges vertices bs .. be. X(v) = cross(d, v − t) increases along the front chain from its
  // minimum at fs to its maximum at fe, and decreases along the back chain.
  // Ranks in the edge order of R: the triangle's edges below ±d (one angle comparison each serves
  // both the strict and the inclusive count) plus B's (precomputed in dir).
  std::array<std::uint32_t, 4> n = dir.b;
  for (int j = 0; j < T.n; ++j) {
    const Vec2 &e0 = T.v[j], &e1 = T.v[(j + 1) % T.n];
    const int sf = (e0 == d0 && e1 == d1) ? 0 : compare_angle(e0, e1, d0, d1);
    const int sr = (e0 == d1 && e1 == d0) ? 0 : compare_angle(e0, e1, d1, d0);
    n[0] += sf <= 0;
    n[1] += sf < 0;
    n[2] += sr <= 0;
    n[3] += sr < 0;
  }
  const std::size_t fs = n[0] % K, be = n[1] % K, bs = n[2] % K, fe = n[3] % K;
  auto X = [&](std::size_t k) {
    int slot;
    std::size_t bj;
    vertex_of(T, k, slot, bj);
    return side_of_line(T.v[slot], b_[bj], s1, s2, d0, d1);
  };
  if (X(fs) >= 0 || X(fe) <= 0) return false;
  const std::size_t nf = (fe + K - fs) % K, nb = (be + K - bs) % K;
  auto G = [&](std::size_t k) {
    int slot;
    std::size_t bj;
    vertex_of(T, k, slot, bj);
    return side_of_line_guess(T.v[slot], b_[bj], s1, s2, d0, d1);
  };
  // Exit: last offset o in [0, nf) with X(v_{fs+o}) <= 0 (X(fs) < 0, X(fe) > 0).
  const std::size_t ox = last_true(
      0, nf, [&](std::size_t o) { return G((fs + o) % K) <= 0; }, [&](std::size_t o) { return X((fs + o) % K) <= 0; });
  exit = edge_of(T, i, (fs + ox) % K);
  // Entry: last offset o in [0, nb) with X(v_{bs+o}) >= 0 (X(bs) > 0, X(be) < 0).
  const std::size_t on = last_true(
      0, nb, [&](std::size_t o) { return G((bs + o) % K) >= 0; }, [&](std::size_t o) { return X((bs + o) % K) >= 0; });
  entry = edge_of(T, i, (bs + on) % K);
  return true;
}

}  // namespace pendepth::polygon2
