// pendepth — distance and shape cast of two polygons on their boundaries (boundary_distance.hpp).
#include "nonconvex2/boundary_distance.hpp"

#include "geometry/exact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace pendepth::nonconvex2 {

namespace {

using exact::accurate_ratio;
using exact::accurate_value;
using exact::exact_sign;

constexpr double kInf = std::numeric_limits<double>::infinity();

// A vertex of one shape against an edge [a, b] of the other, in the edge's frame: the point is
// x0 + sh exactly (a vertex of Q with sh = t against P, or a vertex of P with sh = −t against Q),
// and for the cast it moves along dir (d, resp. −d).
struct Pair {
  Vec2 x0, sh, a, b, dir{0, 0};
  std::uint32_t vertex = 0, edge = 0;
  bool q_vertex = true;
  // distance: 0 nearest point a, 1 nearest point b, 2 inside the edge.
  // cast: 0 crossing hit, 1 collinear reaching a, 2 collinear reaching b, 3 collinear at s = 0.
  int kind = 0;
  int flip = 1;  // cast, kind 0: sign making the denominator positive
  std::uint32_t end = 0;  // distance, kind 0 or 1: the edge's vertex nearest to the point
};

constexpr std::uint32_t kNoEnd = 0xffffffffu;

// Two vertex–vertex candidates naming the same vertex of P and the same vertex of Q.
bool same_vertices(const Pair& a, const Pair& b) {
  const std::uint32_t ap = a.q_vertex ? a.end : a.vertex, aq = a.q_vertex ? a.vertex : a.end;
  const std::uint32_t bp = b.q_vertex ? b.end : b.vertex, bq = b.q_vertex ? b.vertex : b.end;
  return ap == bp && aq == bq;
}

template <class L>
auto px(const Pair& c, L l) { return l(c.x0.x()) + l(c.sh.x()); }
template <class L>
auto py(const Pair& c, L l) { return l(c.x0.y()) + l(c.sh.y()); }

// ---- distance: squared distance = dnum / dden ----
template <class L>
auto dnum(const Pair& c, L l) {
  const auto x = px(c, l), y = py(c, l);
  if (c.kind == 0) {
    const auto u = x - l(c.a.x()), v = y - l(c.a.y());
    return u * u + v * v;
  }
  if (c.kind == 1) {
    const auto u = x - l(c.b.x()), v = y - l(c.b.y());
    return u * u + v * v;
  }
  const auto ex = l(c.b.x()) - l(c.a.x()), ey = l(c.b.y()) - l(c.a.y());
  const auto cr = ex * (y - l(c.a.y())) - ey * (x - l(c.a.x()));
  return cr * cr;
}
template <class L>
auto dden(const Pair& c, L l) {
  if (c.kind != 2) return l(1.0);
  const auto ex = l(c.b.x()) - l(c.a.x()), ey = l(c.b.y()) - l(c.a.y());
  return ex * ex + ey * ey;
}

// Which part of [a, b] is nearest to the point: sets c.kind.
void classify_nearest(Pair& c) {
  const int s1 = exact_sign([&](auto l) {
    return (px(c, l) - l(c.a.x())) * (l(c.b.x()) - l(c.a.x())) + (py(c, l) - l(c.a.y())) * (l(c.b.y()) - l(c.a.y()));
  });
  if (s1 <= 0) {
    c.kind = 0;
    return;
  }
  const int s2 = exact_sign([&](auto l) {
    return (px(c, l) - l(c.b.x())) * (l(c.b.x()) - l(c.a.x())) + (py(c, l) - l(c.b.y())) * (l(c.b.y()) - l(c.a.y()));
  });
  c.kind = s2 >= 0 ? 1 : 2;
}

double distance_value(const Pair& c) {
  if (c.kind != 2) return accurate_value([&](auto l) { return dnum(c, l); });
  return accurate_ratio([&](auto l) { return dnum(c, l); }, [&](auto l) { return dden(c, l); });
}

// ---- cast: ray parameter (units of dir) = snum / sden, sden > 0 ----
template <class L>
auto snum(const Pair& c, L l) {
  const auto wx = l(c.a.x()) - px(c, l), wy = l(c.a.y()) - py(c, l);  // a − X0
  if (c.kind == 0) {
    const auto v = wx * (l(c.b.y()) - l(c.a.y())) - wy * (l(c.b.x()) - l(c.a.x()));  // cross(a − X0, e)
    return c.flip > 0 ? v : -v;
  }
  if (c.kind == 1) return wx * l(c.dir.x()) + wy * l(c.dir.y());
  if (c.kind == 2) return (l(c.b.x()) - px(c, l)) * l(c.dir.x()) + (l(c.b.y()) - py(c, l)) * l(c.dir.y());
  return l(0.0);
}
template <class L>
auto sden(const Pair& c, L l) {
  if (c.kind == 0) {
    const auto v = l(c.dir.x()) * (l(c.b.y()) - l(c.a.y())) - l(c.dir.y()) * (l(c.b.x()) - l(c.a.x()));
    return c.flip > 0 ? v : -v;
  }
  if (c.kind == 3) return l(1.0);
  return l(c.dir.x()) * l(c.dir.x()) + l(c.dir.y()) * l(c.dir.y());
}
// mu·sden for kind 0 (the hit point is a + mu·e): cross(dir, X0 − a), sign-normalised.
template <class L>
auto smu(const Pair& c, L l) {
  const auto v = l(c.dir.x()) * (py(c, l) - l(c.a.y())) - l(c.dir.y()) * (px(c, l) - l(c.a.x()));
  return c.flip > 0 ? v : -v;
}

// Whether the moving point meets [a, b] at some s >= 0; sets c.kind and c.flip.
bool classify_hit(Pair& c) {
  const int den = exact_sign([&](auto l) {
    return l(c.dir.x()) * (l(c.b.y()) - l(c.a.y())) - l(c.dir.y()) * (l(c.b.x()) - l(c.a.x()));
  });
  if (den != 0) {
    c.kind = 0;
    c.flip = den;
    if (exact_sign([&](auto l) { return snum(c, l); }) < 0) return false;
    if (exact_sign([&](auto l) { return smu(c, l); }) < 0) return false;
    return exact_sign([&](auto l) { return sden(c, l) - smu(c, l); }) >= 0;
  }
  c.flip = 1;
  if (exact_sign([&](auto l) { return smu(c, l); }) != 0) return false;  // parallel, not collinear
  c.kind = 1;
  const int ta = exact_sign([&](auto l) { return snum(c, l); });
  c.kind = 2;
  const int tb = exact_sign([&](auto l) { return snum(c, l); });
  if ((ta <= 0 && tb >= 0) || (ta >= 0 && tb <= 0)) {
    c.kind = 3;  // the point is on the segment already
    return true;
  }
  if (ta < 0) return false;  // both behind
  const int ab = exact_sign([&](auto l) {
    return (l(c.b.x()) - l(c.a.x())) * l(c.dir.x()) + (l(c.b.y()) - l(c.a.y())) * l(c.dir.y());
  });
  c.kind = ab > 0 ? 1 : 2;
  return true;
}

double cast_value(const Pair& c) {
  if (c.kind == 3) return 0;
  return accurate_ratio([&](auto l) { return snum(c, l); }, [&](auto l) { return sden(c, l); });
}

// Is candidate c (value vc) strictly smaller than the best b (value vb)? Values are within a few
// ulps of num/den, so values apart by more than 2^-40 relative order them; otherwise the exact
// sign of the cross-multiplied difference does.
template <class Num, class Den>
bool smaller(const Pair& c, double vc, const Pair& b, double vb, Num&& num, Den&& den) {
  if (vc < vb * (1 - 0x1p-40)) return true;
  if (vc > vb * (1 + 0x1p-40) + 0x1p-1000) return false;
  return exact_sign([&](auto l) { return num(c, l) * den(b, l) - num(b, l) * den(c, l); }) < 0;
}

double norm_of(double x, double y) { return std::hypot(x, y); }

// x0 + sh + (b − a)·λ etc. are computed in double for the witnesses only.
Vec2 accurate_diff(const Vec2& p, const Vec2& sh, const Vec2& a) {
  return Vec2(accurate_value([&](auto l) { return l(p.x()) + l(sh.x()) - l(a.x()); }),
              accurate_value([&](auto l) { return l(p.y()) + l(sh.y()) - l(a.y()); }));
}

void build_tree(const Polygon& S, geometry::BoxTree& tree) {
  const auto v = S.vertices();
  std::vector<Vec2> lo(v.size()), hi(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2 &a = v[k], &b = v[S.next(k)];
    lo[k] = a.cwiseMin(b);
    hi[k] = a.cwiseMax(b);
  }
  tree.build_boxes(v.size(), [&](std::size_t k) -> const Vec2& { return lo[k]; },
                   [&](std::size_t k) -> const Vec2& { return hi[k]; });
}

// The absolute error of the rounded point x0 + sh, with a margin.
double point_pad(const Vec2& X) { return (std::abs(X.x()) + std::abs(X.y())) * 0x1p-50 + 0x1p-1000; }

// The nearest vertex–edge pair so far, and the rule that replaces it (filter, exact order,
// first of equals kept).
struct Nearest {
  Pair best;
  double best_v = kInf, best_d = kInf;
  bool have = false;

  // Vertex x0 + sh (rounded: X) against the edge a → b (indices: vertex k, edge e from e to e_next).
  void consider(const Vec2& X, const Vec2& x0, const Vec2& sh, const Vec2& a, const Vec2& b, std::uint32_t k,
                std::uint32_t e, std::uint32_t e_next, bool q_vertex) {
    if (have) {
      // Floating filter: the point–segment distance in double is within err of the exact one
      // (a few roundings of the coordinates' magnitude; 2^-40 is a wide margin). A pair
      // certainly farther than the best so far needs no exact evaluation.
      const Vec2 ev = b - a, w = X - a;
      const double lam = std::clamp(w.dot(ev) / ev.squaredNorm(), 0.0, 1.0);
      const double approx = (w - lam * ev).norm();
      const double mag = std::max({X.cwiseAbs().maxCoeff(), a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()});
      const double err = mag * 0x1p-40 + 0x1p-1000;
      if (approx - err > best_d * (1 + 0x1p-40) + err) return;
    }
    Pair c{x0, sh, a, b};
    c.vertex = k;
    c.edge = e;
    c.q_vertex = q_vertex;
    classify_nearest(c);
    c.end = c.kind == 0 ? e : c.kind == 1 ? e_next : kNoEnd;
    // The same two vertices met before (through the edge's neighbour, or from the other
    // side): the same distance exactly, and the first one stays.
    if (have && c.kind != 2 && best.kind != 2 && same_vertices(c, best)) return;
    const double v = distance_value(c);
    if (!have || smaller(c, v, best, best_v, [](const Pair& p, auto l) { return dnum(p, l); },
                         [](const Pair& p, auto l) { return dden(p, l); })) {
      best = c;
      best_v = v;
      best_d = std::sqrt(v);
      have = true;
    }
  }
};

Distance2 assemble(const Nearest& near, const Polygon& P_, const Polygon& Q_, const Vec2& t) {
  const Pair& best = near.best;
  const double best_v = near.best_v;
  Distance2 r;
  const Polygon& E = best.q_vertex ? P_ : Q_;
  const std::uint32_t a_index = best.edge, b_index = static_cast<std::uint32_t>(E.next(best.edge));
  Feature fv{FeatureKind::Vertex, static_cast<int>(best.vertex)};
  Feature fe = best.kind == 2 ? Feature{FeatureKind::Edge, static_cast<int>(best.edge)}
                              : Feature{FeatureKind::Vertex, static_cast<int>(best.kind == 0 ? a_index : b_index)};
  r.feature_q = best.q_vertex ? fv : fe;
  r.feature_p = best.q_vertex ? fe : fv;
  // The nearest point on the edge, in the edge's frame.
  Vec2 foot = best.kind == 0 ? best.a : best.b;
  if (best.kind == 2) {
    const double lambda = accurate_ratio(
        [&](auto l) {
          return (px(best, l) - l(best.a.x())) * (l(best.b.x()) - l(best.a.x())) +
                 (py(best, l) - l(best.a.y())) * (l(best.b.y()) - l(best.a.y()));
        },
        [&](auto l) { return dden(best, l); });
    foot = best.a + lambda * (best.b - best.a);
  }
  const Vec2 point = best.x0 + best.sh;  // the vertex, in the edge's frame
  // Back to the world frame: the edge's frame is P's (q_vertex) or Q's (shift by t).
  const Vec2 vertex_world = best.q_vertex ? point : best.x0;
  const Vec2 foot_world = best.q_vertex ? foot : foot + t;
  r.witness_q = best.q_vertex ? vertex_world : foot_world;
  r.witness_p = best.q_vertex ? foot_world : vertex_world;
  const bool touching = exact_sign([&](auto l) { return dnum(best, l); }) == 0;
  if (touching) {
    r.distance = 0;
    r.witness_q = r.witness_p;  // one contact point
    return r;
  }
  r.distance = std::sqrt(best_v);
  // Unit normal from P towards Q; the vertex–edge direction in the edge's frame is vertex − foot.
  Vec2 dir;
  if (best.kind == 2) {
    const Vec2 e(accurate_value([&](auto l) { return l(best.b.x()) - l(best.a.x()); }),
                 accurate_value([&](auto l) { return l(best.b.y()) - l(best.a.y()); }));
    dir = Vec2(e.y(), 0 - e.x());  // the edge's outward side (its shape's interior is on the left)
  } else {
    dir = accurate_diff(best.x0, best.sh, foot);
  }
  if (!best.q_vertex && best.kind == 2) dir = Vec2(0, 0) - dir;  // P's vertex is outside Q's edge: P → Q is inward
  if (!best.q_vertex && best.kind != 2) dir = Vec2(0, 0) - dir;  // vertex of P − foot on Q points Q → P
  const double len = norm_of(dir.x(), dir.y());
  r.normal = dir / len;
  r.translation = Vec2(0, 0) - r.distance * r.normal;
  return r;
}

}  // namespace

std::shared_ptr<const geometry::BoxTree> BoundaryPair2::edge_tree(const Polygon& S) {
  auto tree = std::make_shared<geometry::BoxTree>();
  build_tree(S, *tree);
  return tree;
}

BoundaryPair2::BoundaryPair2(const Polygon& P, const Polygon& Q) : BoundaryPair2(P, Q, edge_tree(P), edge_tree(Q)) {}

BoundaryPair2::BoundaryPair2(const Polygon& P, const Polygon& Q, std::shared_ptr<const geometry::BoxTree> p_tree,
                             std::shared_ptr<const geometry::BoxTree> q_tree)
    : P_(P), Q_(Q), p_tree_(std::move(p_tree)), q_tree_(std::move(q_tree)), p_edges_(*p_tree_), q_edges_(*q_tree_) {}

Distance2 BoundaryPair2::distance(const Vec2& t) const {
  Nearest near;
  const double& best_v = near.best_v;
  const Vec2 minus_t = Vec2(0, 0) - t;
  // Every vertex of one shape against the other shape's edge tree, branch and bound.
  auto run = [&](const Polygon& V, const Vec2& sh, const Polygon& E, const geometry::BoxTree& tree, bool q_vertex) {
    const auto vs = V.vertices();
    const auto es = E.vertices();
    for (std::size_t k = 0; k < vs.size(); ++k) {
      const Vec2 X = vs[k] + sh;
      const double pad = point_pad(X);
      std::int32_t stack[128];
      int top = 0;
      stack[top++] = 0;
      while (top > 0) {
        const auto& n = tree.nodes[stack[--top]];
        const double dx = std::max({n.lo.x() - X.x(), X.x() - n.hi.x(), 0.0});
        const double dy = std::max({n.lo.y() - X.y(), X.y() - n.hi.y(), 0.0});
        const double gx = std::max(dx * (1 - 0x1p-50) - pad, 0.0), gy = std::max(dy * (1 - 0x1p-50) - pad, 0.0);
        if ((gx * gx + gy * gy) * (1 - 0x1p-50) > best_v * (1 + 0x1p-30)) continue;
        if (n.left >= 0) {
          // Nearer child last (popped first).
          const auto& L = tree.nodes[n.left];
          const auto& R = tree.nodes[n.right];
          auto box_d = [&](const geometry::BoxTree::Node& m) {
            const double ax = std::max({m.lo.x() - X.x(), X.x() - m.hi.x(), 0.0});
            const double ay = std::max({m.lo.y() - X.y(), X.y() - m.hi.y(), 0.0});
            return ax * ax + ay * ay;
          };
          if (box_d(L) <= box_d(R)) {
            stack[top++] = n.right;
            stack[top++] = n.left;
          } else {
            stack[top++] = n.left;
            stack[top++] = n.right;
          }
          continue;
        }
        const std::uint32_t e = n.tri;
        near.consider(X, vs[k], sh, es[e], es[E.next(e)], static_cast<std::uint32_t>(k), e,
                      static_cast<std::uint32_t>(E.next(e)), q_vertex);
      }
    }
  };
  run(Q_, t, P_, p_edges_, true);
  run(P_, minus_t, Q_, q_edges_, false);
  return assemble(near, P_, Q_, t);
}

Distance2 BoundaryPair2::distance_near(const Vec2& t, std::size_t ip, std::size_t iq) const {
  // The segments of M through vertex (ip, iq) and through its two possible predecessors on M's
  // boundary: each a vertex of one shape against an edge of the other (all inside M, so none
  // is nearer than M; the nearest point of M lies on one of them).
  Nearest near;
  const auto pv = P_.vertices(), qv = Q_.vertices();
  const std::size_t n = pv.size(), m = qv.size();
  const Vec2 minus_t = Vec2(0, 0) - t;
  for (const auto& [a, b] : {std::array<std::size_t, 2>{ip, iq}, std::array<std::size_t, 2>{(ip + n - 1) % n, iq},
                             std::array<std::size_t, 2>{ip, (iq + m - 1) % m}}) {
    for (const std::size_t e : {(a + n - 1) % n, a})
      near.consider(Vec2(qv[b] + t), qv[b], t, pv[e], pv[(e + 1) % n], static_cast<std::uint32_t>(b),
                    static_cast<std::uint32_t>(e), static_cast<std::uint32_t>((e + 1) % n), true);
    for (const std::size_t e : {(b + m - 1) % m, b})
      near.consider(Vec2(pv[a] - t), pv[a], minus_t, qv[e], qv[(e + 1) % m], static_cast<std::uint32_t>(a),
                    static_cast<std::uint32_t>(e), static_cast<std::uint32_t>((e + 1) % m), false);
  }
  return assemble(near, P_, Q_, t);
}

Cast2 BoundaryPair2::cast(const Vec2& t, const Vec2& d_in) const {
  // d scaled by a power of two (same direction, exact) so that its products stay in range.
  const int ex = std::ilogb(std::max(std::abs(d_in.x()), std::abs(d_in.y())));
  const Vec2 d(std::ldexp(d_in.x(), -ex), std::ldexp(d_in.y(), -ex));
  Pair best;
  double best_v = kInf;
  bool have = false;
  const Vec2 minus_t = Vec2(0, 0) - t, minus_d = Vec2(0, 0) - d;
  auto run = [&](const Polygon& V, const Vec2& sh, const Vec2& dir, const Polygon& E, const geometry::BoxTree& tree,
                 bool q_vertex) {
    const auto vs = V.vertices();
    const auto es = E.vertices();
    for (std::size_t k = 0; k < vs.size(); ++k) {
      const Vec2 X = vs[k] + sh;
      const double pad = point_pad(X);
      const Vec2 padv(pad, pad);
      std::int32_t stack[128];
      int top = 0;
      stack[top++] = 0;
      while (top > 0) {
        const auto& n = tree.nodes[stack[--top]];
        double lmin, lmax;
        if (!geometry::ray_box(X, dir, Vec2(n.lo - padv), Vec2(n.hi + padv), lmin, lmax)) continue;
        if (lmax < 0 || lmin > best_v * (1 + 0x1p-30)) continue;
        if (n.left >= 0) {
          stack[top++] = n.right;
          stack[top++] = n.left;
          continue;
        }
        const std::uint32_t e = n.tri;
        Pair c{vs[k], sh, es[e], es[E.next(e)], dir};
        c.vertex = static_cast<std::uint32_t>(k);
        c.edge = e;
        c.q_vertex = q_vertex;
        if (!classify_hit(c)) continue;
        const double v = cast_value(c);
        if (!have || smaller(c, v, best, best_v, [](const Pair& p, auto l) { return snum(p, l); },
                             [](const Pair& p, auto l) { return sden(p, l); })) {
          best = c;
          best_v = v;
          have = true;
        }
      }
    }
  };
  run(Q_, t, d, P_, p_edges_, true);
  run(P_, minus_t, minus_d, Q_, q_edges_, false);

  Cast2 r;
  if (!have) {
    r.distance = kInf;
    return r;
  }
  r.hit = true;
  const Polygon& E = best.q_vertex ? P_ : Q_;
  const auto b_index = static_cast<int>(E.next(best.edge));
  Feature fe{FeatureKind::Edge, static_cast<int>(best.edge)};
  if (best.kind == 1) fe = {FeatureKind::Vertex, static_cast<int>(best.edge)};
  if (best.kind == 2) fe = {FeatureKind::Vertex, b_index};
  if (best.kind == 0) {
    if (exact_sign([&](auto l) { return smu(best, l); }) == 0) fe = {FeatureKind::Vertex, static_cast<int>(best.edge)};
    else if (exact_sign([&](auto l) { return sden(best, l) - smu(best, l); }) == 0) fe = {FeatureKind::Vertex, b_index};
  }
  const Feature fv{FeatureKind::Vertex, static_cast<int>(best.vertex)};
  r.feature_q = best.q_vertex ? fv : fe;
  r.feature_p = best.q_vertex ? fe : fv;
  // s in units of d, then of d̂.
  const double s = best_v;
  const double dn = std::sqrt(accurate_value([&](auto l) { return l(d.x()) * l(d.x()) + l(d.y()) * l(d.y()); }));
  r.distance = s * dn;
  r.translation = s * d;
  // The outward normal of M at the entry: P's edge normal (a vertex of Q hits it), or the inward
  // normal of Q's edge (a vertex of P hits it); for collinear contacts the same formula (⟂ d).
  const Vec2 e(accurate_value([&](auto l) { return l(best.b.x()) - l(best.a.x()); }),
               accurate_value([&](auto l) { return l(best.b.y()) - l(best.a.y()); }));
  Vec2 nrm = best.q_vertex ? Vec2(e.y(), 0 - e.x()) : Vec2(0 - e.y(), e.x());
  r.normal = nrm / norm_of(nrm.x(), nrm.y());
  // The contact point: a vertex of Q moved, or the vertex of P.
  r.witness_p = best.q_vertex ? Vec2(best.x0 + t + r.translation) : best.x0;
  r.witness_q = r.witness_p;
  return r;
}

}  // namespace pendepth::nonconvex2
