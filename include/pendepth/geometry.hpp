// pendepth — vectors, the error type and robust predicates.
//
// Exactness rule (docs/design.md §2): every combinatorial decision is the exact sign of a polynomial
// in the input doubles. Predicates evaluate it in double with a running forward error bound and
// fall back to exact rational arithmetic (GMP) only when the bound cannot certify the sign.
#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <string>

namespace pendepth {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

/// Thrown for invalid input at the API boundary (bad shapes, zero directions, unreadable files).
/// The message names the shape, ring, vertex and the reason.
class InvalidInput : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

namespace predicates {

/// Exact sign of orient2d(a, b, c) = (b - a) x (c - a): +1 if c is left of a->b (CCW), -1 right,
/// 0 collinear. Filtered double, exact fallback. Inputs must be finite.
int orient2d(const Vec2& a, const Vec2& b, const Vec2& c);

/// Exact sign of the cross product a x b.
int cross(const Vec2& a, const Vec2& b);

/// Exact sign of (a1 - a0) x (b1 - b0): the turn from edge vector a to edge vector b.
int cross_edges(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1);

/// Exact sign of (a1 - a0) . (b1 - b0).
int dot_edges(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1);

/// Exact comparison of the polar angles of two non-zero edge vectors (a1 - a0) and (b1 - b0),
/// angles taken in [0, 2*pi) from the +x axis: -1 if a's angle is smaller, 0 equal, +1 larger.
int compare_angle(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1);

}  // namespace predicates
}  // namespace pendepth
