// σ_d for two simple polygons with holes (issue 5 item 2; DHS §4.2 generalised, §6 "no o(n²)
// algorithm known" for the fixed-direction depth of two non-convex polygons).
//
// O = ∪ int S_ij (depth2_polygon_polygon.hpp); the line t + λ·d meets each open S_ij in an open interval
// and σ_d is the end `cur` of the connected component of their union containing λ = 0 (intervals
// sharing only an endpoint are not connected). Pruning: a best-first dual traversal of the two box
// hierarchies, node pairs keyed by the λ at which the line enters box(A) ⊕ (−box(B)) (a lower bound
// of the entry of every interval below that pair). Pairs whose box the line misses, or leaves
// before the running `cur`, are dropped. Intervals that start after `cur` wait in a heap ordered by
// exact entry and join when `cur` passes their entry. The traversal stops as soon as the smallest
// key exceeds `cur`: no unexamined interval can start before the component's end.
// All λ comparisons are exact (compare_lines); the keys are conservative doubles used only for
// pruning and the stopping test, with margins that keep them lower bounds.
// Worst case O(nm log(nm)) (every pair examined); measured counts in docs/algorithms.md.
#include <cmath>
#include <queue>

#include "nonconvex2/query.hpp"

namespace pendepth {

using nonconvex2::Line;
using nonconvex2::Ray;

Depth2 PairDepth2::along(const Vec2& t, const Vec2& d_in, PairQueryStats* stats) const {
  const Vec2 d = nonconvex2::check_and_scale(t, d_in);
  const Ray ray = Ray::query(t, d);
  const Impl& S = *impl_;

  Line cur;
  bool have = false;      // false: cur is λ = 0
  double cur_value = 0;   // cur to a few ulps (for the conservative stopping test only)
  auto before_cur = [&](const Line& c) { return have ? nonconvex2::compare_lines(c, cur, ray) < 0 : nonconvex2::line_sign(c, ray) < 0; };
  auto after_cur = [&](const Line& c) { return have ? nonconvex2::compare_lines(c, cur, ray) > 0 : nonconvex2::line_sign(c, ray) > 0; };

  struct Iv {
    Line entry, exit;
  };
  auto later_entry = [&](const Iv& a, const Iv& b) { return nonconvex2::compare_lines(a.entry, b.entry, ray) > 0; };
  std::priority_queue<Iv, std::vector<Iv>, decltype(later_entry)> waiting(later_entry);

  struct Job {
    double key;
    std::int32_t a, b;
    bool operator>(const Job& o) const { return key > o.key; }
  };
  std::priority_queue<Job, std::vector<Job>, std::greater<Job>> jobs;
  auto push = [&](std::int32_t a, std::int32_t b) {
    Vec2 lo, hi;
    nonconvex2::sum_box(S.hp.nodes[a].lo, S.hp.nodes[a].hi, S.hb.nodes[b].lo, S.hb.nodes[b].hi, lo, hi);
    double l0, l1;
    if (stats) ++stats->node_pairs;
    if (!nonconvex2::ray_box(t, d, lo, hi, l0, l1)) return;
    if (l1 < cur_value - std::abs(cur_value) * 0x1p-40) return;  // leaves the box before cur
    jobs.push({l0, a, b});
  };
  auto extend = [&](const Line& exit) {
    cur = exit;
    have = true;
    cur_value = nonconvex2::line_value(cur, ray);
  };

  push(0, 0);
  while (!jobs.empty()) {
    const Job J = jobs.top();
    if (J.key > cur_value + std::abs(cur_value) * 0x1p-40 + 0x1p-1000) break;  // nothing starts before cur
    jobs.pop();
    const auto &A = S.hp.nodes[J.a], &B = S.hb.nodes[J.b];
    const bool la = A.left < 0, lb = B.left < 0;
    if (!la || !lb) {
      if (lb || (!la && (A.hi - A.lo).sum() >= (B.hi - B.lo).sum())) {
        push(A.left, J.b);
        push(A.right, J.b);
      } else {
        push(J.a, B.left);
        push(J.a, B.right);
      }
      continue;
    }
    if (stats) ++stats->pairs;
    Iv iv;
    if (!nonconvex2::sum_interval(nonconvex2::make_sum(S.tp[A.tri], S.tb[B.tri]), ray, iv.entry, iv.exit)) continue;
    if (!after_cur(iv.exit)) continue;
    if (!before_cur(iv.entry)) {
      waiting.push(iv);
      continue;
    }
    extend(iv.exit);
    // Intervals that were waiting for cur to pass their entry.
    while (!waiting.empty() && before_cur(waiting.top().entry)) {
      const Iv w = waiting.top();
      waiting.pop();
      if (after_cur(w.exit)) extend(w.exit);
    }
  }

  Depth2 r;
  r.kind = DepthKind::Directional;
  if (!have) return r;
  const double dn = nonconvex2::norm_accurate(d);
  const double depth = std::max(0.0, cur_value * dn);
  r = S.contact(cur, t, depth * (d / dn), nonconvex2::end_on_ray(cur, t, d));
  r.depth = depth;
  r.normal = d / dn;
  r.kind = DepthKind::Directional;
  r.overlapping = true;
  return r;
}

}  // namespace pendepth
