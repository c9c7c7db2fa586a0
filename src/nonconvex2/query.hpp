// Private: helpers shared by the PairDepth2 queries (validation, norms, contact ends).
#pragma once

#include "nonconvex2/pair_sums.hpp"

namespace pendepth::nonconvex2 {

/// Validates (t, d) like the other ray queries and returns d scaled by a power of two (exact, same
/// direction) so its largest component is in [1, 2). Throws InvalidInput.
Vec2 check_and_scale(const Vec2& t, const Vec2& d);
/// Throws InvalidInput for a non-finite placement.
void check_point(const Vec2& t);
/// |d| to about one ulp.
double norm_accurate(const Vec2& d);
/// Which end of edge line E (0: c1 + c2, 1: c1 + c2 + e1 − e0) lies exactly on the line t + λ·d;
/// -1 if neither.
int end_on_ray(const Line& E, const Vec2& t, const Vec2& d);

}  // namespace pendepth::nonconvex2
