// Private: queries of rounded shapes (a core ⊕ a ball) from the signed distance of their cores
// (rounded3.cpp; docs/design.md "Primitives").
#pragma once

#include <pendepth/depth3.hpp>

#include <functional>

namespace pendepth::primitives {

/// The signed distance of the two cores with Q's pose translated by `offset` (P's pose fixed);
/// when the cores touch (distance 0, not overlapping), `touch_normal` (if non-null) receives a unit
/// outward normal of M_core at 0 (a supporting plane of M_core through 0).
using CoreDistance = std::function<Distance3(const Vec3& offset, Vec3* touch_normal)>;

/// Exact decisions on the cores (convex3/distance_compare.hpp), r = rp + rq never rounded:
/// `at(d, λ, rp, rq, slope)` = the sign of dist(core_P, core_Q moved by λ·d) − r (λ·d never
/// rounded; −1 when the cores meet), and (slope non-null) the sign of its derivative in λ;
/// `line(d, rp, rq)` = the sign of the distance from core_P to the line {core_Q + s·d} minus r.
struct CoreCompare {
  std::function<int(const Vec3& d, double lambda, double rp, double rq, int* slope)> at;
  std::function<int(const Vec3& d, double rp, double rq)> line;
};

/// P = core_P ⊕ B(rp), Q = core_Q ⊕ B(rq), r = rp + rq > 0: M = M_core ⊕ B(r).
Distance3 rounded_distance(const CoreDistance& core, const CoreCompare& cmp, double rp, double rq);
Depth3 rounded_minimum(const CoreDistance& core, const CoreCompare& cmp, double rp, double rq);
/// σ_d: the exit of the ray s·d̂ from M (d world frame, non-zero).
Depth3 rounded_along(const CoreDistance& core, const CoreCompare& cmp, double rp, double rq, const Vec3& d);
/// The cast: the entry of the ray s·d̂ (s >= 0) into M.
Cast3 rounded_cast(const CoreDistance& core, const CoreCompare& cmp, double rp, double rq, const Vec3& d);

}  // namespace pendepth::primitives
