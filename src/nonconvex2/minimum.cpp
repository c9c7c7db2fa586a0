// σ for two simple polygons with holes (issue 5 item 3): σ(t) = dist(t, ℝ² \ O) for t ∈ O,
// O = ∪ int S_ij (depth2_nonconvex.hpp). DHS §6 leaves the non-convex minimum depth open (O(n⁴)
// by building the convolution); this is a pruned exact search that never builds M.
//
// 1. Upper bound U = min σ_d(t) over 8 directions (each point t + σ_d·d̂ lies outside O).
// 2. The nearest point c of the closed complement lies on ∂O ⊆ ∪ ∂S_ij, within distance U, so only
//    the sums meeting the closed disk D(t, U) matter (dual-tree descent with conservative
//    box–disk tests). c lies on an edge of such a sum and in no open such sum; conversely a point of
//    an edge within D(t, U) covered by no open relevant sum is outside O (sums that miss the disk
//    cannot cover it). A point beyond U that only looks uncovered never beats the true answer.
// 3. Edges are visited in order of a conservative floating lower bound of their distance to t,
//    stopping when it exceeds the best candidate (the bound tightens as candidates are found).
//    Each edge is cut by the other relevant sums: exact λ parameters along the edge (the same line
//    algebra as the ray queries, the edge being the ray from one sum vertex to the next), the
//    uncovered closed pieces are swept in exact entry order, and the nearest point of each piece to
//    t is its projection or an end (exact comparisons). Candidates are compared by exact squared
//    distances; the chosen one is evaluated with exact::accurate_ratio.
// Worst case O(K²) exact tests for K sums meeting the disk (K ≤ nm), plus 8 σ_d queries.
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/exact.hpp"
#include "nonconvex2/query.hpp"

namespace pendepth {

namespace {

using exact::exact_sign;
using nonconvex2::Line;
using nonconvex2::Ray;
using nonconvex2::Sum;

// A parameter μ on an edge ray E (point o + μ·dir): 0, 1, the crossing with a line, or the
// orthogonal projection of t.
struct Param {
  enum Kind { Zero, One, Cut, Proj, Value } kind = Zero;
  Line line;
  double value = 0;  // Value: μ = value (an exact double)
};

template <class L>
auto param_nd(const Param& p, const Ray& E, const Vec2& t, L lift) {
  using T = decltype(lift(0.0));
  switch (p.kind) {
    case Param::Zero:
      return std::pair<T, T>{lift(0.0), lift(1.0)};
    case Param::One:
      return std::pair<T, T>{lift(1.0), lift(1.0)};
    case Param::Cut:
      return std::pair<T, T>{nonconvex2::line_num(p.line, E, lift), nonconvex2::line_den(p.line, E, lift)};
    case Param::Value:
      return std::pair<T, T>{lift(p.value), lift(1.0)};
    default: {
      auto dx = nonconvex2::ray_dx(E, lift), dy = nonconvex2::ray_dy(E, lift);
      auto wx = lift(t.x()) - lift(E.o1.x()) - lift(E.o2.x()), wy = lift(t.y()) - lift(E.o1.y()) - lift(E.o2.y());
      return std::pair<T, T>{wx * dx + wy * dy, dx * dx + dy * dy};
    }
  }
}

// A cut through the edge's start or end vertex is the symbolic parameter 0 or 1.
Param normalised(const Param& p, const Ray& E) {
  if (p.kind != Param::Cut) return p;
  const int k = nonconvex2::known_lambda(p.line, E);
  return k < 0 ? p : Param{k == 0 ? Param::Zero : Param::One, {}};
}

int compare_params(const Param& a_in, const Param& b_in, const Ray& E, const Vec2& t) {
  const Param a = normalised(a_in, E), b = normalised(b_in, E);
  if (a.kind == Param::Cut && b.kind == Param::Cut) return nonconvex2::compare_lines(a.line, b.line, E);
  auto fixed = [](const Param& p) { return p.kind == Param::Zero ? 0 : p.kind == Param::One ? 1 : -1; };
  if (fixed(a) >= 0 && fixed(b) >= 0) return (fixed(a) > fixed(b)) - (fixed(a) < fixed(b));
  const int sa = exact_sign([&](auto L) { return param_nd(a, E, t, L).second; });
  const int sb = exact_sign([&](auto L) { return param_nd(b, E, t, L).second; });
  const int s = exact_sign([&](auto L) {
    auto [na, da] = param_nd(a, E, t, L);
    auto [nb, db] = param_nd(b, E, t, L);
    return na * db - nb * da;
  });
  return s * sa * sb;
}

// Candidate nearest point: on edge E at parameter `at` (a point of the edge).
struct Cand {
  Ray E;
  Param at;
  Line edge;
};

// Squared distance from t to the candidate as num / den (den > 0).
template <class L>
auto sq_dist(const Cand& c, const Vec2& t, L lift) {
  auto [n, dd] = param_nd(c.at, c.E, t, lift);
  auto dx = nonconvex2::ray_dx(c.E, lift), dy = nonconvex2::ray_dy(c.E, lift);
  auto x = (lift(c.E.o1.x()) + lift(c.E.o2.x()) - lift(t.x())) * dd + n * dx;
  auto y = (lift(c.E.o1.y()) + lift(c.E.o2.y()) - lift(t.y())) * dd + n * dy;
  return std::pair{x * x + y * y, dd * dd};
}

double seg_dist(const Vec2& t, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a, at = t - a;
  const double l2 = ab.squaredNorm();
  const double u = l2 > 0 ? std::clamp(at.dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (at - u * ab).norm();
}

// Floating filter: both points lie in int S by a margin far above every rounding involved (the
// points themselves are within ~2^-50 relative of exact points of the edge, the sum vertices and
// the cross products within a few ulps), so the closed segment between them is certified inside.
bool surely_inside(const Sum& S, const Vec2& c0, const Vec2& c1, double scale) {
  const double margin = scale * 0x1p-36;
  for (const Line& c : S.e) {
    const Vec2 e = c.e1 - c.e0, v = c.c1 + c.c2;
    const double len = std::abs(e.x()) + std::abs(e.y());
    for (const Vec2* p : {&c0, &c1}) {
      const Vec2 w = *p - v;
      if (e.x() * w.y() - e.y() * w.x() <= margin * len) return false;
    }
  }
  return true;
}

// Floating filter: both points lie strictly outside one edge line of S by the same margin, so the
// segment between them misses S (and cannot be covered by it).
bool surely_outside(const Sum& S, const Vec2& c0, const Vec2& c1, double scale) {
  const double margin = scale * 0x1p-36;
  for (const Line& c : S.e) {
    const Vec2 e = c.e1 - c.e0, v = c.c1 + c.c2;
    const double len = std::abs(e.x()) + std::abs(e.y());
    const Vec2 w0 = c0 - v, w1 = c1 - v;
    if (e.x() * w0.y() - e.y() * w0.x() < -margin * len && e.x() * w1.y() - e.y() * w1.x() < -margin * len) return true;
  }
  return false;
}

}  // namespace

Depth2 PairDepth2::minimum(const Vec2& t, PairQueryStats* stats) const {
  nonconvex2::check_point(t);
  Depth2 r;
  r.kind = DepthKind::Minimum;
  if (!overlapping(t, stats)) return r;
  const Impl& S = *impl_;

  double U = std::numeric_limits<double>::infinity();
  for (const Vec2& dir : {Vec2(1, 0), Vec2(1, 1), Vec2(0, 1), Vec2(-1, 1), Vec2(-1, 0), Vec2(-1, -1), Vec2(0, -1), Vec2(1, -1)})
    U = std::min(U, along(t, dir, stats).depth);
  const double R = U * (1 + 0x1p-40) + 0x1p-1000;

  // Sums meeting the closed disk D(t, R) (conservative box test).
  std::vector<Sum> sums;
  std::vector<std::pair<Vec2, Vec2>> boxes;
  S.descend(
      [&](const Vec2& lo, const Vec2& hi) {
        const double dx = std::max({lo.x() - t.x(), 0.0, t.x() - hi.x()}), dy = std::max({lo.y() - t.y(), 0.0, t.y() - hi.y()});
        return std::hypot(dx, dy) <= R * (1 + 0x1p-45);
      },
      [&](std::uint32_t i, std::uint32_t j) {
        sums.push_back(nonconvex2::make_sum(S.tp[i], S.tb[j]));
        Vec2 lo, hi;
        nonconvex2::sum_box(S.tp[i].lo, S.tp[i].hi, S.tb[j].lo, S.tb[j].hi, lo, hi);
        boxes.push_back({lo, hi});
        return false;
      },
      stats);

  // Coordinate magnitude of each sum (scales the floating filter's margin).
  std::vector<double> scale_of;
  for (const Sum& F : sums) {
    double m = 0;
    for (const auto& v : F.v) m = std::max(m, v.p.cwiseAbs().maxCoeff() + v.b.cwiseAbs().maxCoeff());
    scale_of.push_back(m);
  }
  // Edges by a conservative lower bound of their distance to t.
  struct EdgeRef {
    double lb;
    std::uint32_t s, k;
  };
  std::vector<EdgeRef> edges;
  const double tn = t.cwiseAbs().maxCoeff();
  for (std::uint32_t s = 0; s < sums.size(); ++s)
    for (std::uint32_t k = 0; k < 6; ++k) {
      const auto &v0 = sums[s].v[k], &v1 = sums[s].v[(k + 1) % 6];
      const Vec2 a = v0.p + v0.b, b = v1.p + v1.b;
      const double slack = (a.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff() + tn + R) * 0x1p-40;
      edges.push_back({seg_dist(t, a, b) - slack, s, k});
    }
  std::sort(edges.begin(), edges.end(), [](const EdgeRef& a, const EdgeRef& b) { return a.lb < b.lb; });

  Cand best;
  bool found = false;
  double best_value = R;  // the answer is ≤ U ≤ R
  auto consider = [&](const Cand& c) {
    if (found) {
      const int s = exact_sign([&](auto L) {
        auto [n1, d1] = sq_dist(c, t, L);
        auto [n2, d2] = sq_dist(best, t, L);
        return n1 * d2 - n2 * d1;
      });
      if (s >= 0) return;
    }
    best = c;
    found = true;
    best_value = std::sqrt(exact::accurate_ratio([&](auto L) { return sq_dist(c, t, L).first; },
                                                 [&](auto L) { return sq_dist(c, t, L).second; }));
  };

  struct Cover {
    Line entry, exit;
  };
  std::vector<Cover> covers;
  std::uint32_t last_swallower = std::numeric_limits<std::uint32_t>::max();
  for (const EdgeRef& er : edges) {
    if (er.lb > best_value * (1 + 0x1p-40)) break;
    const Sum& F = sums[er.s];
    const auto &v0 = F.v[er.k], &v1 = F.v[(er.k + 1) % 6];
    // The edge as a ray: from vertex k (= c1 + c2) with direction e1 − e0 (= vertex k+1 − vertex k).
    Ray E;
    E.o1 = F.e[er.k].c1;
    E.o2 = F.e[er.k].c2;
    E.a1 = F.e[er.k].e1;
    E.b1 = F.e[er.k].e0;
    E.sym = true;
    E.p0 = F.e[er.k].p0;
    E.q0 = F.e[er.k].q0;
    E.p1 = F.e[er.k].p1;
    E.q1 = F.e[er.k].q1;
    // Only the part of the edge inside the disk D(t, best) can hold a better candidate: covers that
    // miss it are skipped. Points outside it may then look uncovered, but a piece's nearest point
    // lies in the disk whenever any of its points does, so such pieces never beat `best`.
    const Vec2 a = v0.p + v0.b, b = v1.p + v1.b, ab = b - a, ta = a - t;
    const double rr = best_value * (1 + 0x1p-40) + (a.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff() + tn) * 0x1p-40;
    const double A2 = ab.squaredNorm(), B1 = ab.dot(ta), C0 = ta.squaredNorm() - rr * rr;
    const double disc = B1 * B1 - A2 * C0;
    double mu0 = 0, mu1 = 1;
    if (A2 > 0 && disc >= 0) {
      const double sq = std::sqrt(disc);
      mu0 = std::max(0.0, (-B1 - sq) / A2 - 0x1p-30);
      mu1 = std::min(1.0, (-B1 + sq) / A2 + 0x1p-30);
    }
    const Vec2 c0 = a + mu0 * ab, c1 = a + mu1 * ab;
    const double m = rr * 0x1p-30 + (a.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff()) * 0x1p-40;  // roundings
    const Vec2 slo = c0.cwiseMin(c1) - Vec2(m, m), shi = c0.cwiseMax(c1) + Vec2(m, m);
    const double scale_edge = a.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff() + rr;
    // The sweep runs over [lo_end, hi_end] = [μ0, μ1] (exact doubles; 0 and 1 symbolic).
    const Param lo_end = mu0 == 0 ? Param{Param::Zero, {}} : Param{Param::Value, {}, mu0};
    const Param hi_end = mu1 == 1 ? Param{Param::One, {}} : Param{Param::Value, {}, mu1};
    if (mu0 > mu1) continue;
    covers.clear();
    bool swallowed = false;  // one open sum covers all of [μ0, μ1]: nothing to find on this edge
    auto try_cover = [&](std::uint32_t s) {
      const auto& [lo, hi] = boxes[s];
      if (lo.x() > shi.x() || hi.x() < slo.x() || lo.y() > shi.y() || hi.y() < slo.y()) return;
      if (surely_outside(sums[s], c0, c1, scale_of[s] + scale_edge)) return;
      if (surely_inside(sums[s], c0, c1, scale_of[s] + scale_edge)) {
        swallowed = true;
        last_swallower = s;
        return;
      }
      if (stats) ++stats->pairs;
      Cover cv;
      if (!nonconvex2::sum_interval(sums[s], E, cv.entry, cv.exit, &F.e[er.k])) return;
      const Param en{Param::Cut, cv.entry}, ex{Param::Cut, cv.exit};
      if (compare_params(ex, lo_end, E, t) <= 0 || compare_params(en, hi_end, E, t) >= 0) return;
      if (compare_params(en, lo_end, E, t) < 0 && compare_params(ex, hi_end, E, t) > 0) {
        swallowed = true;
        last_swallower = s;
        return;
      }
      covers.push_back(cv);
    };
    if (last_swallower != er.s && last_swallower < sums.size()) try_cover(last_swallower);
    for (std::uint32_t s = 0; s < sums.size() && !swallowed; ++s)
      if (s != er.s && s != last_swallower) try_cover(s);
    if (swallowed) continue;
    std::sort(covers.begin(), covers.end(),
              [&](const Cover& x, const Cover& y) { return nonconvex2::compare_lines(x.entry, y.entry, E) < 0; });
    const Param proj{Param::Proj, {}};
    auto emit = [&](const Param& lo, const Param& hi) {  // nearest point of the closed piece [lo, hi]
      Cand c{E, proj, F.e[er.k]};
      if (compare_params(proj, lo, E, t) <= 0) c.at = lo;
      else if (compare_params(proj, hi, E, t) >= 0) c.at = hi;
      consider(c);
    };
    Param s = lo_end;
    bool covered_to_end = false;
    for (const Cover& cv : covers) {
      const Param a{Param::Cut, cv.entry}, bq{Param::Cut, cv.exit};
      if (compare_params(a, s, E, t) >= 0) {
        emit(s, a);
        s = bq;
      } else if (compare_params(bq, s, E, t) > 0) {
        s = bq;
      }
      if (compare_params(s, hi_end, E, t) > 0) {
        covered_to_end = true;
        break;
      }
    }
    if (!covered_to_end) emit(s, hi_end);
  }

  // found is guaranteed: the point t + U·d̂ of the best direction is outside O within the disk.
  if (!found) return r;
  const Ray& E = best.E;
  auto coord = [&](int axis) {
    return exact::accurate_ratio(
        [&](auto L) {
          auto [n, dd] = param_nd(best.at, E, t, L);
          auto o = axis == 0 ? L(E.o1.x()) + L(E.o2.x()) - L(t.x()) : L(E.o1.y()) + L(E.o2.y()) - L(t.y());
          auto dv = axis == 0 ? nonconvex2::ray_dx(E, L) : nonconvex2::ray_dy(E, L);
          return o * dd + n * dv;
        },
        [&](auto L) { return param_nd(best.at, E, t, L).second; });
  };
  const Vec2 translation(coord(0), coord(1));
  int end = -1;
  if (compare_params(best.at, Param{Param::Zero, {}}, E, t) == 0) end = 0;
  else if (compare_params(best.at, Param{Param::One, {}}, E, t) == 0) end = 1;
  r = S.contact(best.edge, t, translation, end);
  r.depth = best_value;
  r.kind = DepthKind::Minimum;
  r.overlapping = true;
  return r;
}

}  // namespace pendepth
