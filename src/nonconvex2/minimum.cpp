// σ for two simple polygons with holes (issue 5 item 3): σ(t) = dist(t, ℝ² \ O) for t ∈ O,
// O = ∪ int S_ij (depth2_polygon_polygon.hpp). DHS §6 leaves the non-convex minimum depth open (O(n⁴)
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
#include "nonconvex2/edge_cut.hpp"
#include "nonconvex2/query.hpp"

namespace pendepth {

namespace {

using exact::exact_sign;
using nonconvex2::Line;
using nonconvex2::Ray;
using nonconvex2::Sum;

using nonconvex2::Cand;
using nonconvex2::Cover;
using nonconvex2::Param;
using nonconvex2::compare_params;
using nonconvex2::seg_dist;
using nonconvex2::sq_dist;
using nonconvex2::surely_inside;
using nonconvex2::surely_outside;


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
      if (nonconvex2::same_point(c, best)) return;  // a tie recognised symbolically (no rationals)
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
    const Param proj{Param::Proj, {}};
    nonconvex2::uncovered_pieces(covers, E, t, lo_end, hi_end, [&](const Param& lo, const Param& hi) {
      Cand c{E, proj, F.e[er.k]};  // nearest point of the closed piece [lo, hi]
      if (compare_params(proj, lo, E, t) <= 0) c.at = lo;
      else if (compare_params(proj, hi, E, t) >= 0) c.at = hi;
      consider(c);
    });
  }

  // found is guaranteed: the point t + U·d̂ of the best direction is outside O within the disk.
  if (!found) return r;
  const Vec2 translation = nonconvex2::cand_translation(best, t);
  const int end = nonconvex2::cand_end(best, t);
  r = S.contact(best.edge, t, translation, end);
  r.depth = best_value;
  r.kind = DepthKind::Minimum;
  r.overlapping = true;
  return r;
}

}  // namespace pendepth
