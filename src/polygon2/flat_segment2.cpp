// A segment against a non-convex polygon (with holes): the general path of FlatDepth2
// (flat_depth2.hpp, "General"; issue 16 item 4).
//
// Notation: P's vertices p_g (rings, interior on the left of every edge g → next(g)), F = [a, b],
// u = b − a, S_x = F + x. O = {x : S_x meets int P}, C its complement (closed), M = P ⊕ (−F).
// Candidates: the segments of t-space on which ∂O and ∂M lie: E(g, j) = edge g of P − q_j
// (q_0 = a, q_1 = b) and V(g) = [p_g − b, p_g − a]. A point is a triple (X, Y, W), W > 0, standing
// for (X/W, Y/W), every coordinate a polynomial in the input doubles, so every test is an exact
// sign (src/geometry/exact.hpp) and every value one accurate ratio.
//
// meets(x): S_x meets int P ⇔ an end lies in int P; or an end lies on ∂P with the segment leaving
// it into P (strictly to the edge's left, or inside the vertex's open interior cone); or the open
// segment crosses an open edge properly; or a vertex of P lies strictly inside the segment with u
// or −u strictly inside its interior cone. (Walk from a point of S_x ∩ int P towards an end: the
// first boundary point reached is one of these.)
// Completeness: the nearest point of C to t ∈ O is on ∂O, so it is a foot of t on a candidate,
// an end of one, or a crossing of two; the first point of C on a ray from t is a crossing of the
// ray with a candidate; the last exit likewise. Each is tested with meets().
// Cost: meets() visits only P's edges whose boxes (a bucket box tree built once per pair) meet a
// rigorous floating box around the tested segment, or the horizontal half-line from an end for
// its parity; signs that box already fixes (an edge end above or below the box, an edge wholly
// right of it) are read off it, the others are exact. So a test costs O(log n + the edges near
// the segment or met by the end's half-line) instead of O(n); every answer is the one the full
// scan gives (`brute`, kept as the tests' reference). σ also pairs its near candidates for
// crossings by a sweep on their boxes (O(k log k + pairs) instead of O(k²)), in the all-pairs order.
#include "polygon2/flat_depth2.hpp"

#include "geometry/box_tree.hpp"
#include "geometry/exact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

namespace pendepth::polygon2 {

using exact::exact_sign;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

struct FlatDepth2::General {
  std::vector<Vec2> p;
  std::vector<std::size_t> ring;
  std::array<Vec2, 2> f;
  struct Cand {  // from p[g0] − f[j0] to p[g1] − f[j1]
    std::size_t g0, g1;
    int j0, j1;
  };
  std::vector<Cand> cands;
  std::vector<signed char> cone_u, cone_mu;  // u / −u strictly inside P's interior cone at g
  std::vector<signed char> edge_u;           // sign cross(e_g, u)
  // Boxes of P's edges g → next(g) (exact: their corners are input doubles) in a bucket tree:
  // meets() visits only the edges whose boxes meet a rigorous box around the tested point or
  // segment. `brute` (tests only) takes the full O(n) scans instead; both decide the same exact
  // predicates, so they answer alike.
  std::vector<Vec2> elo, ehi;
  geometry::BoxTree tree;
  bool brute = false;

  std::size_t next(std::size_t g) const {
    const auto r = std::upper_bound(ring.begin(), ring.end(), g);
    return g + 1 == *r ? *(r - 1) : g + 1;
  }
  std::size_t prev(std::size_t g) const {
    const auto r = std::upper_bound(ring.begin(), ring.end(), g);
    return g == *(r - 1) ? *r - 1 : g - 1;
  }

  General(const std::vector<std::vector<Vec2>>& rings, std::span<const Vec2> F) {
    f = {F[0], F[1]};
    ring.push_back(0);
    for (const auto& r : rings) {
      p.insert(p.end(), r.begin(), r.end());
      ring.push_back(p.size());
    }
    const std::size_t n = p.size();
    for (std::size_t g = 0; g < n; ++g) {
      cands.push_back({g, next(g), 0, 0});
      cands.push_back({g, next(g), 1, 1});
      cands.push_back({g, g, 1, 0});
    }
    cone_u.resize(n);
    cone_mu.resize(n);
    edge_u.resize(n);
    for (std::size_t g = 0; g < n; ++g) {
      const Vec2 &a = p[prev(g)], &m = p[g], &b = p[next(g)];
      auto cross_w = [&](const Vec2& from, const Vec2& to, double s) {
        return exact_sign([&](auto c) {
          const auto ux = c(s) * (c(f[1].x()) - c(f[0].x())), uy = c(s) * (c(f[1].y()) - c(f[0].y()));
          return (c(to.x()) - c(from.x())) * uy - (c(to.y()) - c(from.y())) * ux;
        });
      };
      const int turn = exact_sign([&](auto c) {
        return (c(m.x()) - c(a.x())) * (c(b.y()) - c(m.y())) - (c(m.y()) - c(a.y())) * (c(b.x()) - c(m.x()));
      });
      for (const double s : {1.0, -1.0}) {
        const int c1 = cross_w(a, m, s), c2 = cross_w(m, b, s);
        const bool in = turn > 0 ? (c1 > 0 && c2 > 0) : turn < 0 ? (c1 > 0 || c2 > 0) : c1 > 0;
        (s > 0 ? cone_u : cone_mu)[g] = in;
      }
      edge_u[g] = static_cast<signed char>(cross_w(m, b, 1.0));
    }
    elo.resize(n);
    ehi.resize(n);
    for (std::size_t g = 0; g < n; ++g) {
      elo[g] = p[g].cwiseMin(p[next(g)]);
      ehi[g] = p[g].cwiseMax(p[next(g)]);
    }
    tree.build_buckets<4>(n, [&](std::size_t g) -> const Vec2& { return elo[g]; },
                          [&](std::size_t g) -> const Vec2& { return ehi[g]; });
  }

  // A rigorous box around the end q_j + x (false if the floating enclosure fails: callers scan).
  template <class X>
  bool end_box(const X& x, int j, Vec2& lo, Vec2& hi) const {
    const auto r = x(exact::LiftFl{});
    const exact::Fl W = r[2];
    const double ew = exact::safe_bound(W.e), wlo = W.v - ew, whi = W.v + ew;
    if (!(wlo > 0) || !std::isfinite(whi)) return false;
    for (int k = 0; k < 2; ++k) {
      const exact::Fl N = exact::Fl{f[j][k], 0} * W + r[k];
      const double en = exact::safe_bound(N.e), nlo = N.v - en, nhi = N.v + en;
      if (!std::isfinite(nlo) || !std::isfinite(nhi)) return false;
      lo[k] = geometry::widen_down(nlo >= 0 ? nlo / whi : nlo / wlo);
      hi[k] = geometry::widen_up(nhi >= 0 ? nhi / wlo : nhi / whi);
    }
    return true;
  }
  // Visits edges g (until f returns true) whose boxes meet [qlo, qhi] — all of them when
  // `all` (the boxes failed) or in brute mode.
  template <class F>
  bool edges_until(bool all, const Vec2& qlo, const Vec2& qhi, F&& f) const {
    if (all || brute) {
      for (std::size_t g = 0; g < p.size(); ++g)
        if (f(static_cast<std::uint32_t>(g))) return true;
      return false;
    }
    return tree.overlap_until(qlo, qhi, f);
  }

  // ---- meets(x) for a point functor x(c) -> {X, Y, W}, W > 0 ----

  // Where the end q_j + x lies: 1 inside, -1 outside, 0 on ∂P (onv: the vertex or -1; one: the edge).
  // Edges that miss the box [lo.x, +∞] × [lo.y, hi.y] around the end neither contain it nor
  // cross the rightward ray from it, so only the others are visited (mirrored for the leftward).
  template <class X>
  int locate_end(const X& x, int j, long& onv, long& one, bool all, const Vec2& lo, const Vec2& hi) const {
    bool odd = false;
    onv = one = -1;
    auto ax = [&](auto c) {
      const auto r = x(c);
      return std::array{c(f[j].x()) * r[2] + r[0], c(f[j].y()) * r[2] + r[1], r[2]};
    };
    const bool fast = !all && !brute;
    // The half-line runs towards the nearer side of P's box (+x unless the fast path chose −x):
    // both parities are exact, so they agree.
    const bool left = fast && tree.nodes[0].hi.x() - hi.x() > lo.x() - tree.nodes[0].lo.x();
    const Vec2 qlo(left ? -kInf : lo.x(), lo.y()), qhi(left ? hi.x() : kInf, hi.y());
    const bool on = edges_until(all, qlo, qhi, [&](std::uint32_t gi) {
      const std::size_t g = gi;
      const Vec2 &s = p[g], &e = p[next(g)];
      // Signs the end's box already fixes are read off it (the box is rigorous).
      const int ys = fast && s.y() > hi.y()   ? 1
                     : fast && s.y() < lo.y() ? -1
                                              : exact_sign([&](auto c) { const auto A = ax(c); return c(s.y()) * A[2] - A[1]; });
      const int ye = fast && e.y() > hi.y()   ? 1
                     : fast && e.y() < lo.y() ? -1
                                              : exact_sign([&](auto c) { const auto A = ax(c); return c(e.y()) * A[2] - A[1]; });
      if (ys * ye > 0) return false;
      if (fast && ys * ye < 0 && (left ? ehi[g].x() < lo.x() : elo[g].x() > hi.x())) {  // wholly on the ray's side
        odd = !odd;
        return false;
      }
      const int o = exact_sign([&](auto c) {
        const auto A = ax(c);
        return (c(e.x()) - c(s.x())) * (A[1] - c(s.y()) * A[2]) - (c(e.y()) - c(s.y())) * (A[0] - c(s.x()) * A[2]);
      });
      if (o == 0) {
        const int xs = exact_sign([&](auto c) { const auto A = ax(c); return c(s.x()) * A[2] - A[0]; });
        const int xe = exact_sign([&](auto c) { const auto A = ax(c); return c(e.x()) * A[2] - A[0]; });
        if (ys != 0 || ye != 0 || xs * xe <= 0) {
          if (xs == 0 && ys == 0) onv = static_cast<long>(g);
          else if (xe == 0 && ye == 0) onv = static_cast<long>(next(g));
          one = static_cast<long>(g);
          return true;
        }
        return false;
      }
      if ((ys > 0) != (ye > 0) && (ye > 0) == (left ? o < 0 : o > 0)) odd = !odd;
      return false;
    });
    if (on) return 0;
    return odd ? 1 : -1;
  }

  // The point functor with its evaluations in exact_sign's tiers computed once each (the floating
  // one up front, the others when first asked for): the same values the functor returns, so every
  // sign is the one it gives.
  template <class X>
  struct Cached {
    const X& x;
    std::array<exact::Fl, 3> fl;
    mutable std::optional<decltype(std::declval<const X&>()(exact::LiftFlX{}))> flx;
    mutable std::optional<decltype(std::declval<const X&>()(exact::LiftDD{}))> dd;
    mutable std::optional<decltype(std::declval<const X&>()(exact::LiftEx{}))> ex;
    template <class L>
    auto operator()(L c) const {
      if constexpr (std::is_same_v<L, exact::LiftFl>) {
        return fl;
      } else if constexpr (std::is_same_v<L, exact::LiftFlX>) {
        if (!flx) flx = x(c);
        return *flx;
      } else if constexpr (std::is_same_v<L, exact::LiftDD>) {
        if (!dd) dd = x(c);
        return *dd;
      } else if constexpr (std::is_same_v<L, exact::LiftEx>) {
        if (!ex) ex = x(c);
        return *ex;
      } else {
        return x(c);
      }
    }
  };

  template <class X>
  bool meets(const X& x0) const {
    if (brute) return meets_point(x0);
    return meets_point(Cached<X>{x0, x0(exact::LiftFl{}), {}, {}, {}});
  }

  template <class X>
  bool meets_point(const X& x) const {
    std::array<Vec2, 2> lo{Vec2(0, 0), Vec2(0, 0)}, hi = lo;
    const bool all = !end_box(x, 0, lo[0], hi[0]) || !end_box(x, 1, lo[1], hi[1]);
    for (int j = 0; j < 2; ++j) {
      long v, e;
      const int w = locate_end(x, j, v, e, all, lo[j], hi[j]);
      if (w > 0) return true;
      if (w == 0) {
        const bool into = v >= 0 ? (j == 0 ? cone_u : cone_mu)[static_cast<std::size_t>(v)] != 0
                                 : edge_u[static_cast<std::size_t>(e)] * (j == 0 ? 1 : -1) > 0;
        if (into) return true;
      }
    }
    auto A = [&](auto c, int j) {
      const auto r = x(c);
      return std::array{c(f[j].x()) * r[2] + r[0], c(f[j].y()) * r[2] + r[1], r[2]};
    };
    auto sd = [&](std::size_t g) {
      return exact_sign([&](auto c) {
        const auto a = A(c, 0);
        const auto ux = c(f[1].x()) - c(f[0].x()), uy = c(f[1].y()) - c(f[0].y());
        return ux * (c(p[g].y()) * a[2] - a[1]) - uy * (c(p[g].x()) * a[2] - a[0]);
      });
    };
    // A proper crossing or a vertex inside the segment: only edges whose boxes meet the segment's
    // (every vertex g starts edge g, whose box holds it).
    return edges_until(all, lo[0].cwiseMin(lo[1]), hi[0].cwiseMax(hi[1]), [&](std::uint32_t gi) {
      const std::size_t g = gi;
      const Vec2 &s = p[g], &e = p[next(g)];
      const int sg = sd(g);
      if (sg != 0 && sg * sd(next(g)) < 0) {
        auto o = [&](int j) {
          return exact_sign([&](auto c) {
            const auto a = A(c, j);
            return (c(e.x()) - c(s.x())) * (a[1] - c(s.y()) * a[2]) - (c(e.y()) - c(s.y())) * (a[0] - c(s.x()) * a[2]);
          });
        };
        if (o(0) * o(1) < 0) return true;
      }
      if (sg == 0 && (cone_u[g] || cone_mu[g])) {
        auto along = [&](int j) {  // (p_g − end j)·u
          return exact_sign([&](auto c) {
            const auto a = A(c, j);
            const auto ux = c(f[1].x()) - c(f[0].x()), uy = c(f[1].y()) - c(f[0].y());
            return (c(s.x()) * a[2] - a[0]) * ux + (c(s.y()) * a[2] - a[1]) * uy;
          });
        };
        if (along(0) > 0 && along(1) < 0) return true;
      }
      return false;
    });
  }

  // ---- candidates ----

  template <class L>
  auto end(L c, const Cand& k, int which) const {
    const Vec2& q = p[which ? k.g1 : k.g0];
    const Vec2& r = f[which ? k.j1 : k.j0];
    return std::array{c(q.x()) - c(r.x()), c(q.y()) - c(r.y())};
  }
};

namespace flat_general {

using G = FlatDepth2::General;

namespace {

// A point of t-space: an end of candidate k (which = l), the foot of t on k, the crossing of k and
// l (s = sign cross(e_k, e_l)), or the ray point t + λ·d with λ = num/den of `ray` below.
struct Pt {
  enum Kind { End, Foot, Cross, Ray } kind = End;
  std::size_t k = 0, l = 0;
  int s = 1;
  double lo = 0, hi = kInf;  // enclosure of |x − t|² (or of λ for ray points)
};

// λ of the ray t + λ·d at candidate k: a proper or end crossing (l = 0: {cross(u0 − t, e), cross(d, e)}
// times s) or a candidate end on the ray's line (l = 1 + which: {(end − t)·d, |d|²}).
template <class L>
std::array<decltype(std::declval<L>()(0.0)), 2> ray_lambda(L c, const G& g, const Pt& x, const Vec2& t, const Vec2& d) {
  const auto& k = g.cands[x.k];
  if (x.l > 0) {
    const auto e = g.end(c, k, static_cast<int>(x.l - 1));
    return {(e[0] - c(t.x())) * c(d.x()) + (e[1] - c(t.y())) * c(d.y()), c(d.x()) * c(d.x()) + c(d.y()) * c(d.y())};
  }
  const auto u0 = g.end(c, k, 0), u1 = g.end(c, k, 1);
  const auto ex = u1[0] - u0[0], ey = u1[1] - u0[1];
  return {c(double(x.s)) * ((u0[0] - c(t.x())) * ey - (u0[1] - c(t.y())) * ex),
          c(double(x.s)) * (c(d.x()) * ey - c(d.y()) * ex)};
}

template <class L>
std::array<decltype(std::declval<L>()(0.0)), 3> coords(L c, const G& g, const Pt& x, const Vec2& t, const Vec2& d) {
  const auto& k = g.cands[x.k];
  switch (x.kind) {
    case Pt::End: {
      const auto e = g.end(c, k, static_cast<int>(x.l));
      return {e[0], e[1], c(1.0)};
    }
    case Pt::Foot: {
      const auto u0 = g.end(c, k, 0), u1 = g.end(c, k, 1);
      const auto ex = u1[0] - u0[0], ey = u1[1] - u0[1];
      const auto num = (c(t.x()) - u0[0]) * ex + (c(t.y()) - u0[1]) * ey, den = ex * ex + ey * ey;
      return {u0[0] * den + num * ex, u0[1] * den + num * ey, den};
    }
    case Pt::Cross: {
      const auto& m = g.cands[x.l];
      const auto u0 = g.end(c, k, 0), u1 = g.end(c, k, 1), v0 = g.end(c, m, 0), v1 = g.end(c, m, 1);
      const auto ex = u1[0] - u0[0], ey = u1[1] - u0[1], fx = v1[0] - v0[0], fy = v1[1] - v0[1];
      const auto den = c(double(x.s)) * (ex * fy - ey * fx);
      const auto num = c(double(x.s)) * ((v0[0] - u0[0]) * fy - (v0[1] - u0[1]) * fx);
      return {u0[0] * den + num * ex, u0[1] * den + num * ey, den};
    }
    case Pt::Ray: break;
  }
  const auto l = ray_lambda(c, g, x, t, d);
  return {c(t.x()) * l[1] + l[0] * c(d.x()), c(t.y()) * l[1] + l[0] * c(d.y()), l[1]};
}

// |x − t|² as {num, den}.
template <class L>
auto dist2(L c, const G& g, const Pt& x, const Vec2& t) {
  const auto r = coords(c, g, x, t, Vec2(1, 0));
  const auto dx = r[0] - c(t.x()) * r[2], dy = r[1] - c(t.y()) * r[2];
  return std::array{dx * dx + dy * dy, r[2] * r[2]};
}

void enclose(const exact::Fl& num, const exact::Fl& den, double& lo, double& hi) {
  const double en = exact::safe_bound(num.e), ed = exact::safe_bound(den.e);
  const double nlo = num.v - en, nhi = num.v + en, dlo = den.v - ed, dhi = den.v + ed;
  if (!std::isfinite(nhi) || !std::isfinite(dhi) || !std::isfinite(nlo) || !(dlo > 0)) {
    lo = -kInf;
    hi = kInf;
    return;
  }
  lo = nlo >= 0 ? nlo / dhi * (1 - 0x1p-50) : nlo / dlo * (1 + 0x1p-50);
  hi = nhi >= 0 ? nhi / dlo * (1 + 0x1p-50) : nhi / dhi * (1 - 0x1p-50);
}

// Exact: |x − t| < |y − t|.
bool nearer(const G& g, const Pt& x, const Pt& y, const Vec2& t) {
  return exact_sign([&](auto c) {
           const auto a = dist2(c, g, x, t), b = dist2(c, g, y, t);
           return a[0] * b[1] - b[0] * a[1];
         }) < 0;
}

bool meets_at(const G& g, const Pt& x, const Vec2& t, const Vec2& d) {
  return g.meets([&](auto c) { return coords(c, g, x, t, d); });
}

// The candidates' ends and the feet of t strictly inside them, with their enclosures.
std::vector<Pt> ends_and_feet(const G& g, const Vec2& t) {
  std::vector<Pt> out;
  for (std::size_t k = 0; k < g.cands.size(); ++k) {
    if (g.cands[k].g0 != g.cands[k].g1) out.push_back({Pt::End, k, 0});  // every p − q once (E's first ends)
    auto dot = [&](int which) {
      return exact_sign([&](auto c) {
        const auto u0 = g.end(c, g.cands[k], 0), u1 = g.end(c, g.cands[k], 1);
        const auto ex = u1[0] - u0[0], ey = u1[1] - u0[1];
        const auto& w = which ? u1 : u0;
        return c(which ? -1.0 : 1.0) * ((c(t.x()) - w[0]) * ex + (c(t.y()) - w[1]) * ey);
      });
    };
    if (dot(0) > 0 && dot(1) > 0) out.push_back({Pt::Foot, k, 0});
  }
  for (Pt& x : out) {
    const auto r = dist2(exact::LiftFl{}, g, x, t);
    enclose(r[0], r[1], x.lo, x.hi);
  }
  return out;
}

// The nearest point among `pts` (enclosures set) that `valid` accepts, exactly; false if none.
template <class Valid>
bool nearest_valid(const G& g, std::vector<Pt>& pts, const Vec2& t, Valid&& valid, Pt& best, double& best_hi) {
  std::sort(pts.begin(), pts.end(), [](const Pt& a, const Pt& b) { return a.lo < b.lo; });
  bool found = false;
  for (const Pt& x : pts) {
    if (found && x.lo > best_hi) break;
    if (!valid(x)) continue;
    if (!found || nearer(g, x, best, t)) {
      best = x;
      found = true;
      best_hi = std::min(best_hi, x.hi);
    }
  }
  return found;
}

Vec2 translation_to(const G& g, const Pt& x, const Vec2& t, const Vec2& d) {
  auto comp = [&](int i) {
    return exact::accurate_ratio_of([&](auto c) {
      const auto r = coords(c, g, x, t, d);
      return std::make_pair(r[i] - c(i ? t.y() : t.x()) * r[2], r[2]);
    });
  };
  return Vec2(comp(0), comp(1));
}

// Features and the contact point (world frame) of P and F + x at a point on candidate k.
void contact(const G& g, const Pt& x, const Vec2& xw, Feature& fp, Feature& fq, Vec2& w) {
  const auto& k = g.cands[x.k];
  if (x.kind == Pt::End) {
    const std::size_t v = x.l ? k.g1 : k.g0;
    fp = {FeatureKind::Vertex, static_cast<int>(v)};
    fq = {FeatureKind::Vertex, x.l ? k.j1 : k.j0};
    w = g.p[v];
  } else if (k.g0 == k.g1) {
    fp = {FeatureKind::Vertex, static_cast<int>(k.g0)};
    fq = {FeatureKind::Edge, 0};
    w = g.p[k.g0];
  } else {
    fp = {FeatureKind::Edge, static_cast<int>(k.g0)};
    fq = {FeatureKind::Vertex, k.j0};
    w = g.f[k.j0] + xw;
  }
}

// The ray's events: λ > 0 where t + λ·d meets a candidate, sorted exactly (ties kept once each).
std::vector<Pt> ray_events(const G& g, const Vec2& t, const Vec2& d) {
  std::vector<Pt> ev;
  auto side = [&](const G::Cand& k, int which) {
    return exact_sign([&](auto c) {
      const auto e = g.end(c, k, which);
      return c(d.x()) * (e[1] - c(t.y())) - c(d.y()) * (e[0] - c(t.x()));
    });
  };
  for (std::size_t k = 0; k < g.cands.size(); ++k) {
    const int s0 = side(g.cands[k], 0), s1 = side(g.cands[k], 1);
    Pt x{Pt::Ray, k, 0};
    if (s0 == 0) x.l = 1, ev.push_back(x);
    if (s1 == 0) x.l = 2, ev.push_back(x);
    if (s0 * s1 < 0) {
      x.l = 0;
      x.s = s1;  // sign of cross(d, e)
      ev.push_back(x);
    }
  }
  auto lam = [&](const Pt& x, auto c) { return ray_lambda(c, g, x, t, d); };
  std::erase_if(ev, [&](const Pt& x) { return exact_sign([&](auto c) { return lam(x, c)[0]; }) <= 0; });
  for (Pt& x : ev) {
    const auto r = lam(x, exact::LiftFl{});
    enclose(r[0], r[1], x.lo, x.hi);
  }
  std::sort(ev.begin(), ev.end(), [&](const Pt& a, const Pt& b) {
    if (a.hi < b.lo) return true;
    if (b.hi < a.lo) return false;
    return exact_sign([&](auto c) {
             const auto x = lam(a, c), y = lam(b, c);
             return x[0] * y[1] - y[0] * x[1];
           }) < 0;
  });
  return ev;
}

Depth2 ray_result(const G& g, const Pt& x, const Vec2& t, const Vec2& d) {
  const double lambda = exact::accurate_ratio_of([&](auto c) {
    const auto l = ray_lambda(c, g, x, t, d);
    return std::make_pair(l[0], l[1]);
  });
  const double dn = std::hypot(d.x(), d.y());
  Depth2 r;
  r.translation = lambda * d;
  r.depth = lambda * dn;
  r.normal = d / dn;
  contact(g, x, t + r.translation, r.feature_p, r.feature_q, r.witness_p);
  r.witness_q = r.witness_p;
  return r;
}

}  // namespace

std::shared_ptr<const FlatDepth2::General> build(const std::vector<std::vector<Vec2>>& rings, std::span<const Vec2> F,
                                                 bool brute) {
  auto g = std::make_shared<G>(rings, F);
  g->brute = brute;
  return g;
}

bool overlapping(const G& g, const Vec2& t) {
  return g.meets([&](auto c) { return std::array{c(t.x()), c(t.y()), c(1.0)}; });
}

Depth2 minimum(const G& g, const Vec2& t) {
  Depth2 r;
  if (!overlapping(g, t)) return r;
  r.overlapping = true;
  const Vec2 d(1, 0);
  auto valid = [&](const Pt& x) { return !meets_at(g, x, t, d); };
  std::vector<Pt> pts = ends_and_feet(g, t);
  Pt best;
  double best_hi = kInf;
  bool found = nearest_valid(g, pts, t, valid, best, best_hi);
  // Crossings of two candidates that may lie nearer: both candidates within best_hi (a rigorous
  // box test on the rounded ends, padded).
  std::vector<std::size_t> near;
  std::vector<std::array<double, 4>> box;  // padded boxes of the near candidates: x0, x1, y0, y1
  for (std::size_t k = 0; k < g.cands.size(); ++k) {
    const auto& c = g.cands[k];
    const Vec2 a = g.p[c.g0] - g.f[c.j0], b = g.p[c.g1] - g.f[c.j1];
    const double pad = 0x1p-48 * (g.p[c.g0].cwiseAbs().maxCoeff() + g.p[c.g1].cwiseAbs().maxCoeff() +
                                  g.f[0].cwiseAbs().maxCoeff() + g.f[1].cwiseAbs().maxCoeff() + t.cwiseAbs().maxCoeff());
    const double dx = std::max({0.0, std::min(a.x(), b.x()) - pad - t.x(), t.x() - std::max(a.x(), b.x()) - pad});
    const double dy = std::max({0.0, std::min(a.y(), b.y()) - pad - t.y(), t.y() - std::max(a.y(), b.y()) - pad});
    if ((dx * dx + dy * dy) * (1 - 0x1p-50) <= best_hi) {
      near.push_back(k);
      box.push_back({std::min(a.x(), b.x()) - pad, std::max(a.x(), b.x()) + pad, std::min(a.y(), b.y()) - pad,
                     std::max(a.y(), b.y()) + pad});
    }
  }
  std::vector<Pt> cross;
  auto orient = [&](std::size_t k, std::size_t l, int which) {
    return exact_sign([&](auto c) {
      const auto u0 = g.end(c, g.cands[k], 0), u1 = g.end(c, g.cands[k], 1), w = g.end(c, g.cands[l], which);
      return (u1[0] - u0[0]) * (w[1] - u0[1]) - (u1[1] - u0[1]) * (w[0] - u0[0]);
    });
  };
  // The pairs i < j of near candidates whose boxes meet, found by a sweep over x and then taken in
  // (i, j) order: the order of `cross` (and so of its sort, and the tie-breaking) is the one the
  // all-pairs loop makes.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  {
    std::vector<std::uint32_t> by_x(near.size());
    for (std::size_t i = 0; i < near.size(); ++i) by_x[i] = static_cast<std::uint32_t>(i);
    std::sort(by_x.begin(), by_x.end(), [&](std::uint32_t a, std::uint32_t b) { return box[a][0] < box[b][0]; });
    for (std::size_t a = 0; a < by_x.size(); ++a) {
      const auto& A = box[by_x[a]];
      for (std::size_t b = a + 1; b < by_x.size() && !(A[1] < box[by_x[b]][0]); ++b) {
        const auto& B = box[by_x[b]];
        if (A[3] < B[2] || B[3] < A[2]) continue;
        pairs.emplace_back(std::min(by_x[a], by_x[b]), std::max(by_x[a], by_x[b]));
      }
    }
    std::sort(pairs.begin(), pairs.end());
  }
  for (const auto& [i, j] : pairs) {
    const std::size_t k = near[i], l = near[j];
    const int o1 = orient(k, l, 0), o2 = orient(k, l, 1);
    if (o1 * o2 > 0 || (o1 == 0 && o2 == 0)) continue;
    const int o3 = orient(l, k, 0), o4 = orient(l, k, 1);
    if (o3 * o4 > 0) continue;
    const int s = exact_sign([&](auto c) {
      const auto u0 = g.end(c, g.cands[k], 0), u1 = g.end(c, g.cands[k], 1);
      const auto v0 = g.end(c, g.cands[l], 0), v1 = g.end(c, g.cands[l], 1);
      return (u1[0] - u0[0]) * (v1[1] - v0[1]) - (u1[1] - u0[1]) * (v1[0] - v0[0]);
    });
    if (s == 0) continue;
    Pt x{Pt::Cross, k, l, s};
    const auto r = dist2(exact::LiftFl{}, g, x, t);
    enclose(r[0], r[1], x.lo, x.hi);
    if (x.lo <= best_hi) cross.push_back(x);
  }
  Pt best2;
  if (nearest_valid(g, cross, t, valid, best2, best_hi) && (!found || nearer(g, best2, best, t))) best = best2, found = true;
  if (!found) return r;  // unreachable: a bounded O has a boundary
  r.translation = translation_to(g, best, t, d);
  r.depth = std::hypot(r.translation.x(), r.translation.y());
  r.normal = r.translation / r.depth;
  contact(g, best, t + r.translation, r.feature_p, r.feature_q, r.witness_p);
  r.witness_q = r.witness_p;
  return r;
}

Depth2 along(const G& g, const Vec2& t, const Vec2& d) {
  Depth2 r;
  r.kind = DepthKind::Directional;
  if (!overlapping(g, t)) return r;
  for (const Pt& x : ray_events(g, t, d))
    if (!meets_at(g, x, t, d)) {
      r = ray_result(g, x, t, d);
      break;
    }
  r.overlapping = true;
  r.kind = DepthKind::Directional;
  return r;
}

Depth2 separation(const G& g, const Vec2& t, const Vec2& d) {
  const bool inside = overlapping(g, t);
  const std::vector<Pt> ev = ray_events(g, t, d);
  Depth2 r;
  for (std::size_t i = ev.size(); i-- > 0;) {
    // The midpoint of (λ_{i−1}, λ_i) (λ_{−1} = 0) in O: the ray leaves O for the last time at λ_i.
    bool in;
    if (i == 0) {
      in = g.meets([&](auto c) {
        const auto l = ray_lambda(c, g, ev[0], t, d);
        const auto w = c(2.0) * l[1];
        return std::array{c(t.x()) * w + l[0] * c(d.x()), c(t.y()) * w + l[0] * c(d.y()), w};
      });
    } else {
      in = g.meets([&](auto c) {
        const auto a = ray_lambda(c, g, ev[i - 1], t, d), b = ray_lambda(c, g, ev[i], t, d);
        const auto num = a[0] * b[1] + b[0] * a[1], w = c(2.0) * a[1] * b[1];
        return std::array{c(t.x()) * w + num * c(d.x()), c(t.y()) * w + num * c(d.y()), w};
      });
    }
    if (in) {
      r = ray_result(g, ev[i], t, d);
      break;
    }
  }
  r.overlapping = inside;
  r.kind = DepthKind::Separation;
  return r;
}

Distance2 signed_distance(const G& g, const Vec2& t) {
  if (overlapping(g, t)) return overlap_distance(minimum(g, t));
  Distance2 r;
  // Apart or touching: the nearest point of the closed M, on the candidates.
  std::vector<Pt> pts = ends_and_feet(g, t);
  Pt best;
  double hi = kInf;
  nearest_valid(g, pts, t, [](const Pt&) { return true; }, best, hi);
  const bool touching = exact_sign([&](auto c) { return dist2(c, g, best, t)[0]; }) == 0;
  if (!touching) {
    r.translation = translation_to(g, best, t, Vec2(1, 0));
    r.distance = std::hypot(r.translation.x(), r.translation.y());
    r.normal = (Vec2(0, 0) - r.translation) / r.distance;
  }
  contact(g, best, t + r.translation, r.feature_p, r.feature_q, r.witness_p);
  r.witness_q = r.witness_p - r.translation;
  return r;
}

Cast2 cast(const G& g, const Vec2& t, const Vec2& d) {
  Cast2 r;
  if (overlapping(g, t)) {
    r.hit = r.overlapping = true;
    return r;
  }
  std::vector<Pt> pts = ends_and_feet(g, t);
  Pt best;
  double hi = kInf;
  nearest_valid(g, pts, t, [](const Pt&) { return true; }, best, hi);
  if (exact_sign([&](auto c) { return dist2(c, g, best, t)[0]; }) == 0) {  // touching
    r.hit = true;
    contact(g, best, t, r.feature_p, r.feature_q, r.witness_p);
    r.witness_q = r.witness_p;
    return r;
  }
  const std::vector<Pt> ev = ray_events(g, t, d);
  if (ev.empty()) {
    r.distance = kInf;
    return r;
  }
  const Depth2 x = ray_result(g, ev.front(), t, d);
  r.hit = true;
  r.distance = x.depth;
  r.translation = x.translation;
  r.witness_p = r.witness_q = x.witness_p;
  r.feature_p = x.feature_p;
  r.feature_q = x.feature_q;
  // The normal of the candidate hit (M's outward side is the ray's incoming side).
  const auto& k = g.cands[ev.front().k];
  const Vec2 e = (g.p[k.g1] - g.f[k.j1]) - (g.p[k.g0] - g.f[k.j0]);
  Vec2 n = e.norm() > 0 ? Vec2(Vec2(e.y(), -e.x()) / e.norm()) : Vec2(Vec2(0, 0) - d / d.norm());
  if (n.dot(d) > 0) n = Vec2(0, 0) - n;
  r.normal = n;
  return r;
}

}  // namespace flat_general

}  // namespace pendepth::polygon2
