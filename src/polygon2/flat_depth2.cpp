// A point or a segment against a solid 2D shape: exact queries on the explicit M = P ⊕ (−F)
// (flat_depth2.hpp for the contract, notation and cost; issue 16 item 4).
//
// Every decision is the exact sign of a polynomial in the input doubles (P's vertices, F's ends,
// t, d): a vertex of M is the pair (p, q) and enters each formula as p − q, never rounded.
// Nearest features and first hits are chosen in two steps: a floating interval per candidate
// (rigorous bounds from exact::Fl), then exact comparisons among the candidates whose intervals
// reach the best upper bound.
#include "polygon2/flat_depth2.hpp"

#include "geometry/exact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pendepth::polygon2 {

using exact::exact_sign;
using V = FlatDepth2::V;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <class L>
auto mx(L c, const V& m) {
  return c(m.p.x()) - c(m.q.x());
}
template <class L>
auto my(L c, const V& m) {
  return c(m.p.y()) - c(m.q.y());
}

// d scaled by a power of two (exact, same direction) so that its largest component is in [1, 2).
Vec2 scaled(const Vec2& d) {
  const int e = std::ilogb(std::max(std::abs(d.x()), std::abs(d.y())));
  return Vec2(std::ldexp(d.x(), -e), std::ldexp(d.y(), -e));
}

double norm_of(double x, double y) { return std::hypot(x, y); }

// A rigorous enclosure [lo, hi] of num/den (den > 0 in exact arithmetic) from Fl evaluations.
void enclose(const exact::Fl& num, const exact::Fl& den, double& lo, double& hi) {
  const double en = exact::safe_bound(num.e), ed = exact::safe_bound(den.e);
  const double nlo = num.v - en, nhi = num.v + en, dlo = den.v - ed, dhi = den.v + ed;
  if (!std::isfinite(nlo) || !std::isfinite(nhi) || !std::isfinite(dlo) || !std::isfinite(dhi) || !(dlo > 0)) {
    lo = -kInf;
    hi = kInf;
    return;
  }
  constexpr double kDown = 1 - 0x1p-50, kUp = 1 + 0x1p-50;
  lo = nlo >= 0 ? nlo / dhi * kDown : nlo / dlo * kUp;
  hi = nhi >= 0 ? nhi / dlo * kUp : nhi / dhi * kDown;
}

// Exact sign of a·d' − b·d for two ratios a/d, b/d' given as {num, den} formulas (den > 0).
template <class F, class G>
int compare_ratios(F&& f, G&& g) {
  return exact_sign([&](auto c) {
    const auto x = f(c);
    const auto y = g(c);
    return x.first * y.second - y.first * x.second;
  });
}

}  // namespace

FlatDepth2::FlatDepth2(const std::vector<std::vector<Vec2>>& rings, bool convex, std::span<const Vec2> F)
    : nf_(static_cast<int>(F.size())) {
  if (F.size() == 1) {
    int g = 0;
    ring_.push_back(0);
    for (const auto& ring : rings) {
      for (const Vec2& p : ring) v_.push_back(V{p, F[0], g++, 0});
      ring_.push_back(v_.size());
    }
    return;
  }
  if (!convex) {
    general_ = flat_general::build(rings, F);
    return;
  }
  // M = hull{p − a, p − b}: Andrew's monotone chain on the exact differences.
  std::vector<V> pts;
  int g = 0;
  for (const Vec2& p : rings[0]) {
    pts.push_back(V{p, F[0], g, 0});
    pts.push_back(V{p, F[1], g, 1});
    ++g;
  }
  auto less = [](const V& a, const V& b) {
    const int sx = exact_sign([&](auto c) { return mx(c, a) - mx(c, b); });
    if (sx != 0) return sx < 0;
    return exact_sign([&](auto c) { return my(c, a) - my(c, b); }) < 0;
  };
  auto same = [](const V& a, const V& b) {
    return exact_sign([&](auto c) { return mx(c, a) - mx(c, b); }) == 0 &&
           exact_sign([&](auto c) { return my(c, a) - my(c, b); }) == 0;
  };
  std::stable_sort(pts.begin(), pts.end(), less);
  pts.erase(std::unique(pts.begin(), pts.end(), same), pts.end());
  auto turn = [](const V& o, const V& a, const V& b) {
    return exact_sign([&](auto c) {
      return (mx(c, a) - mx(c, o)) * (my(c, b) - my(c, o)) - (my(c, a) - my(c, o)) * (mx(c, b) - mx(c, o));
    });
  };
  std::vector<V> h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, lo = k + 1; i-- > 0;) {
    while (k >= lo && turn(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);  // the last point repeats the first
  v_ = std::move(h);
  ring_ = {0, v_.size()};
}

std::size_t FlatDepth2::next(std::size_t k) const {
  const auto r = std::upper_bound(ring_.begin(), ring_.end(), k);
  return k + 1 == *r ? *(r - 1) : k + 1;
}

std::size_t FlatDepth2::prev(std::size_t k) const {
  const auto r = std::upper_bound(ring_.begin(), ring_.end(), k);
  return k == *(r - 1) ? *r - 1 : k - 1;
}

// Exact point location: on an edge (closed) → Boundary; else the parity of the crossings of the
// ray towards +x (half-open rule on y).
FlatDepth2::Where FlatDepth2::locate(const Vec2& t) const {
  bool odd = false;
  for (std::size_t k = 0; k < v_.size(); ++k) {
    const V &u = v_[k], &w = v_[next(k)];
    const int yu = exact_sign([&](auto c) { return my(c, u) - c(t.y()); });
    const int yw = exact_sign([&](auto c) { return my(c, w) - c(t.y()); });
    if (yu * yw > 0) continue;
    const int o = exact_sign([&](auto c) {
      return (mx(c, w) - mx(c, u)) * (c(t.y()) - my(c, u)) - (my(c, w) - my(c, u)) * (c(t.x()) - mx(c, u));
    });
    if (o == 0) {
      if (yu != 0 || yw != 0) return Where::Boundary;
      const int xu = exact_sign([&](auto c) { return mx(c, u) - c(t.x()); });
      const int xw = exact_sign([&](auto c) { return mx(c, w) - c(t.x()); });
      if (xu * xw <= 0) return Where::Boundary;
      continue;
    }
    if ((yu > 0) != (yw > 0) && (yw > 0 ? o > 0 : o < 0)) odd = !odd;
  }
  return odd ? Where::Inside : Where::Outside;
}

bool FlatDepth2::overlapping(const Vec2& t) const {
  if (general_) return flat_general::overlapping(*general_, t);
  return locate(t) == Where::Inside;
}

// The nearest point of ∂M to t: a vertex, or the foot on an edge strictly between its ends.
FlatDepth2::Near FlatDepth2::nearest(const Vec2& t) const {
  auto sq = [&](const Near& n, auto c) {
    if (!n.edge) {
      const V& m = v_[n.k];
      const auto dx = mx(c, m) - c(t.x()), dy = my(c, m) - c(t.y());
      return std::make_pair(dx * dx + dy * dy, c(1.0));
    }
    const V &u = v_[n.k], &w = v_[next(n.k)];
    const auto ex = mx(c, w) - mx(c, u), ey = my(c, w) - my(c, u);
    const auto cr = ex * (c(t.y()) - my(c, u)) - ey * (c(t.x()) - mx(c, u));
    return std::make_pair(cr * cr, ex * ex + ey * ey);
  };
  struct Cand {
    Near n;
    double lo, hi;
  };
  std::vector<Cand> cands;
  cands.reserve(2 * v_.size());
  double best_hi = kInf;
  auto add = [&](const Near& n) {
    const auto r = sq(n, exact::LiftFl{});
    double lo, hi;
    enclose(r.first, r.second, lo, hi);
    if (lo > best_hi) return;
    best_hi = std::min(best_hi, hi);
    cands.push_back({n, lo, hi});
  };
  for (std::size_t k = 0; k < v_.size(); ++k) add(Near{false, k});
  for (std::size_t k = 0; k < v_.size(); ++k) {
    const V &u = v_[k], &w = v_[next(k)];
    // The foot strictly inside the edge: (t − u)·e > 0 and (w − t)·e > 0.
    auto dot = [&](const V& a, int s, auto c) {
      const auto ex = mx(c, w) - mx(c, u), ey = my(c, w) - my(c, u);
      return c(double(s)) * ((c(t.x()) - mx(c, a)) * ex + (c(t.y()) - my(c, a)) * ey);
    };
    if (exact_sign([&](auto c) { return dot(u, 1, c); }) <= 0) continue;
    if (exact_sign([&](auto c) { return dot(w, -1, c); }) <= 0) continue;
    add(Near{true, k});
  }
  const Cand* best = nullptr;
  for (const Cand& c : cands) {
    if (c.lo > best_hi) continue;
    if (!best || compare_ratios([&](auto l) { return sq(c.n, l); }, [&](auto l) { return sq(best->n, l); }) < 0)
      best = &c;
  }
  return best->n;
}

Feature FlatDepth2::feature_p(bool edge, std::size_t k) const {
  if (!edge) return {FeatureKind::Vertex, v_[k].pi};
  const V &u = v_[k], &w = v_[next(k)];
  if (u.pi == w.pi) return {FeatureKind::Vertex, u.pi};
  return {FeatureKind::Edge, u.pi};
}

Feature FlatDepth2::feature_q(bool edge, std::size_t k) const {
  if (!edge) return {FeatureKind::Vertex, v_[k].qi};
  const V &u = v_[k], &w = v_[next(k)];
  if (u.qi == w.qi) return {FeatureKind::Vertex, u.qi};
  return {FeatureKind::Edge, 0};
}

// The contact point (world frame) of P and F + x for a point x of M on feature (edge, k).
Vec2 FlatDepth2::contact(bool edge, std::size_t k, const Vec2& x) const {
  if (!edge) return v_[k].p;
  const V &u = v_[k], &w = v_[next(k)];
  if (u.pi == w.pi) return u.p;   // a vertex of P on the segment
  if (u.qi == w.qi) return u.q + x;  // an end of F on an edge of P
  // An edge of P along the segment: any common point; the one at x's position on the edge.
  const Vec2 a = u.p - u.q, e = (w.p - w.q) - a;
  const double mu = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return u.p + mu * (w.p - u.p);
}

namespace {

// The outward unit normal of M's edge from u to w (M's interior on its left) and its length.
Vec2 edge_normal(const V& u, const V& w) {
  const double ex = exact::accurate_value([&](auto c) { return mx(c, w) - mx(c, u); });
  const double ey = exact::accurate_value([&](auto c) { return my(c, w) - my(c, u); });
  const double len = norm_of(ex, ey);
  return Vec2(ey / len, (0 - ex) / len);
}

// The offset from t to the nearest feature of ∂M, each value rounded once from its exact expression:
// a vertex m → the vector m − t; an edge u → w → cross(w − u, t − u) / |w − u| (> 0 when t is on
// the interior's side) and the edge's outward unit normal. Shared by σ and the signed distance.
struct NearOffset {
  Vec2 to_vertex = Vec2(0, 0);
  double edge_value = 0;
  Vec2 normal = Vec2(0, 0);
};

NearOffset near_offset(const V& u, const V* w, const Vec2& t) {
  NearOffset o;
  if (!w) {
    o.to_vertex = Vec2(exact::accurate_value([&](auto c) { return mx(c, u) - c(t.x()); }),
                       exact::accurate_value([&](auto c) { return my(c, u) - c(t.y()); }));
    return o;
  }
  const double cr = exact::accurate_value([&](auto c) {
    return (mx(c, *w) - mx(c, u)) * (c(t.y()) - my(c, u)) - (my(c, *w) - my(c, u)) * (c(t.x()) - mx(c, u));
  });
  const double ex = exact::accurate_value([&](auto c) { return mx(c, *w) - mx(c, u); });
  const double ey = exact::accurate_value([&](auto c) { return my(c, *w) - my(c, u); });
  const double len = norm_of(ex, ey);
  o.edge_value = cr / len;
  o.normal = Vec2(ey / len, (0 - ex) / len);
  return o;
}

}  // namespace

Depth2 FlatDepth2::minimum(const Vec2& t) const {
  if (general_) return flat_general::minimum(*general_, t);
  Depth2 r;
  r.kind = DepthKind::Minimum;
  if (locate(t) != Where::Inside) return r;
  r.overlapping = true;
  const Near n = nearest(t);
  const NearOffset o = near_offset(v_[n.k], n.edge ? &v_[next(n.k)] : nullptr, t);
  if (!n.edge) {
    r.translation = o.to_vertex;
    r.depth = norm_of(r.translation.x(), r.translation.y());
    r.normal = r.translation / r.depth;
  } else {
    r.depth = o.edge_value;
    r.normal = o.normal;
    r.translation = r.depth * r.normal;
  }
  r.witness_p = r.witness_q = contact(n.edge, n.k, t + r.translation);
  r.feature_p = feature_p(n.edge, n.k);
  r.feature_q = feature_q(n.edge, n.k);
  return r;
}

Distance2 overlap_distance(const Depth2& s) {
  Distance2 r;
  r.distance = -s.depth;
  r.translation = s.translation;
  r.normal = s.normal;
  r.witness_p = s.witness_p;
  r.witness_q = s.witness_q - s.translation;
  r.feature_p = s.feature_p;
  r.feature_q = s.feature_q;
  r.overlapping = true;
  return r;
}

Distance2 FlatDepth2::signed_distance(const Vec2& t) const {
  if (general_) return flat_general::signed_distance(*general_, t);
  const Where where = locate(t);
  if (where == Where::Inside) return overlap_distance(minimum(t));
  Distance2 r;
  const Near n = nearest(t);
  r.feature_p = feature_p(n.edge, n.k);
  r.feature_q = feature_q(n.edge, n.k);
  if (where == Where::Boundary) {
    r.witness_p = r.witness_q = contact(n.edge, n.k, t);
    return r;
  }
  const NearOffset o = near_offset(v_[n.k], n.edge ? &v_[next(n.k)] : nullptr, t);
  if (!n.edge) {
    r.translation = o.to_vertex;
    r.distance = norm_of(r.translation.x(), r.translation.y());
    r.normal = (Vec2(0, 0) - r.translation) / r.distance;
  } else {
    r.distance = 0 - o.edge_value;  // (−cr) / len = −(cr / len): rounding is symmetric
    r.normal = o.normal;
    r.translation = Vec2(0, 0) - r.distance * r.normal;
  }
  r.witness_p = contact(n.edge, n.k, t + r.translation);
  r.witness_q = r.witness_p - r.translation;
  return r;
}

namespace {

// λ of a hit of the ray t + λ·d as {num, den}, den > 0: a vertex m on the ray, λ = (m − t)·d / |d|²;
// a proper crossing of the edge u → w (s = the sign of cross(d, w − t)), λ = cross(u − t, e) / cross(d, e).
template <class L>
auto hit_lambda(L c, const V& u, const V* w, int s, const Vec2& t, const Vec2& d) {
  if (!w) {
    const auto num = (mx(c, u) - c(t.x())) * c(d.x()) + (my(c, u) - c(t.y())) * c(d.y());
    return std::make_pair(num, c(d.x()) * c(d.x()) + c(d.y()) * c(d.y()));
  }
  const auto ex = mx(c, *w) - mx(c, u), ey = my(c, *w) - my(c, u);
  const auto num = (mx(c, u) - c(t.x())) * ey - (my(c, u) - c(t.y())) * ex;
  const auto den = c(d.x()) * ey - c(d.y()) * ex;
  return std::make_pair(c(double(s)) * num, c(double(s)) * den);
}

}  // namespace

// The hits of the ray t + λd with λ > 0: `first` = the least λ among every vertex on the line and
// every edge crossing it (the entry or exit of the ray), else the greatest λ among the places
// where the ray leaves M (the last exit). Every decision exact.
bool FlatDepth2::extreme_hit(const Vec2& t, const Vec2& d, bool first, Hit& out) const {
  const std::size_t n = v_.size();
  std::vector<signed char> side(n);
  for (std::size_t k = 0; k < n; ++k)
    side[k] = static_cast<signed char>(exact_sign([&](auto c) {
      return c(d.x()) * (my(c, v_[k]) - c(t.y())) - c(d.y()) * (mx(c, v_[k]) - c(t.x()));
    }));
  bool found = false;
  Hit best;
  int best_s = 0;
  const int order = first ? -1 : 1;  // the sign of compare(new, best) that replaces best
  auto lam = [&](const Hit& h, int s, auto c) {
    return hit_lambda(c, v_[h.k], h.edge ? &v_[next(h.k)] : nullptr, s, t, d);
  };
  auto consider = [&](const Hit& h, int s) {
    if (exact_sign([&](auto c) { return lam(h, s, c).first; }) <= 0) return;
    if (!found || compare_ratios([&](auto c) { return lam(h, s, c); }, [&](auto c) { return lam(best, best_s, c); }) == order) {
      best = h;
      best_s = s;
      found = true;
    }
  };
  // −d strictly inside M's interior cone at vertex k (the ray was inside just before it).
  auto inside_before = [&](std::size_t k) {
    const V &a = v_[prev(k)], &m = v_[k], &b = v_[next(k)];
    auto cross_w = [&](const V& from, const V& to) {
      return exact_sign([&](auto c) {
        const auto ex = mx(c, to) - mx(c, from), ey = my(c, to) - my(c, from);
        return ex * (c(0.0) - c(d.y())) - ey * (c(0.0) - c(d.x()));
      });
    };
    const int turn = exact_sign([&](auto c) {
      return (mx(c, m) - mx(c, a)) * (my(c, b) - my(c, m)) - (my(c, m) - my(c, a)) * (mx(c, b) - mx(c, m));
    });
    const int c1 = cross_w(a, m), c2 = cross_w(m, b);
    if (turn > 0) return c1 > 0 && c2 > 0;
    if (turn < 0) return c1 > 0 || c2 > 0;
    return c1 > 0;
  };
  for (std::size_t k = 0; k < n; ++k) {
    if (side[k] == 0 && (first || inside_before(k))) consider(Hit{false, k}, 0);
    const int su = side[k], sw = side[next(k)];
    if (su * sw < 0 && (first || sw > 0)) consider(Hit{true, k}, sw);  // last exit: from M's inner side out
  }
  out = best;
  return found;
}

Depth2 FlatDepth2::hit_result(const Hit& h, const Vec2& t, const Vec2& d) const {
  const V& u = v_[h.k];
  const V* w = h.edge ? &v_[next(h.k)] : nullptr;
  int s = 0;
  if (w)
    s = exact_sign([&](auto c) { return c(d.x()) * (my(c, *w) - c(t.y())) - c(d.y()) * (mx(c, *w) - c(t.x())); });
  const double lambda = exact::accurate_ratio_of([&](auto c) { return hit_lambda(c, u, w, s, t, d); });
  const double dn = norm_of(d.x(), d.y());
  Depth2 r;
  r.translation = lambda * d;
  r.depth = lambda * dn;
  r.normal = d / dn;
  r.witness_p = r.witness_q = contact(h.edge, h.k, t + r.translation);
  r.feature_p = feature_p(h.edge, h.k);
  r.feature_q = feature_q(h.edge, h.k);
  return r;
}

Depth2 FlatDepth2::along(const Vec2& t, const Vec2& d0) const {
  if (general_) return flat_general::along(*general_, t, scaled(d0));
  Depth2 r;
  r.kind = DepthKind::Directional;
  if (locate(t) != Where::Inside) return r;
  const Vec2 d = scaled(d0);
  Hit h;
  extreme_hit(t, d, true, h);  // t inside the bounded M: the ray leaves it
  r = hit_result(h, t, d);
  r.overlapping = true;
  r.kind = DepthKind::Directional;
  return r;
}

Depth2 FlatDepth2::separation(const Vec2& t, const Vec2& d0) const {
  if (general_) return flat_general::separation(*general_, t, scaled(d0));
  const bool inside = locate(t) == Where::Inside;
  const Vec2 d = scaled(d0);
  Depth2 r;
  Hit h;
  if (extreme_hit(t, d, false, h)) r = hit_result(h, t, d);
  r.overlapping = inside;
  r.kind = DepthKind::Separation;
  return r;
}

Cast2 FlatDepth2::cast(const Vec2& t, const Vec2& d0) const {
  if (general_) return flat_general::cast(*general_, t, scaled(d0));
  Cast2 r;
  const Where where = locate(t);
  if (where == Where::Inside) {
    r.hit = r.overlapping = true;
    return r;
  }
  auto normal_at = [&](bool edge, std::size_t k) {
    return edge ? edge_normal(v_[k], v_[next(k)]) : edge_normal(v_[prev(k)], v_[k]);
  };
  if (where == Where::Boundary) {
    const Near n = nearest(t);
    r.hit = true;
    r.normal = normal_at(n.edge, n.k);
    r.witness_p = r.witness_q = contact(n.edge, n.k, t);
    r.feature_p = feature_p(n.edge, n.k);
    r.feature_q = feature_q(n.edge, n.k);
    return r;
  }
  const Vec2 d = scaled(d0);
  Hit h;
  if (!extreme_hit(t, d, true, h)) {
    r.distance = kInf;
    return r;
  }
  const Depth2 x = hit_result(h, t, d);
  r.hit = true;
  r.distance = x.depth;
  r.translation = x.translation;
  r.normal = normal_at(h.edge, h.k);
  r.witness_p = r.witness_q = x.witness_p;
  r.feature_p = x.feature_p;
  r.feature_q = x.feature_q;
  return r;
}

NoFitPolygonParts FlatDepth2::parts() const {
  if (general_)
    throw InvalidInput("pair: the no-fit polygon of a segment and a non-convex polygon is not built (queries are answered "
                       "without it)");
  NoFitPolygonParts out;
  std::vector<std::vector<Vec2>> poly;
  for (std::size_t k = 0; k + 1 < ring_.size(); ++k) {
    std::vector<Vec2> ring;
    for (std::size_t i = ring_[k]; i < ring_[k + 1]; ++i) {
      const V& m = v_[i];
      ring.emplace_back(exact::accurate_value([&](auto c) { return mx(c, m); }),
                        exact::accurate_value([&](auto c) { return my(c, m); }));
    }
    poly.push_back(std::move(ring));
  }
  out.polygons.push_back(std::move(poly));
  return out;
}

}  // namespace pendepth::polygon2
