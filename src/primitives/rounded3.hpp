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

/// P = core_P ⊕ B(rp), Q = core_Q ⊕ B(rq), r = rp + rq > 0: M = M_core ⊕ B(r).
Distance3 rounded_distance(const CoreDistance& core, double rp, double rq);
Depth3 rounded_minimum(const CoreDistance& core, double rp, double rq);
/// σ_d: the exit of the ray s·d̂ from M (d world frame, non-zero).
Depth3 rounded_along(const CoreDistance& core, double rp, double rq, const Vec3& d);
/// The cast: the entry of the ray s·d̂ (s >= 0) into M.
Cast3 rounded_cast(const CoreDistance& core, double rp, double rq, const Vec3& d);

}  // namespace pendepth::primitives
