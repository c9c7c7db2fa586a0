// Private: the right envelope of a simple polygon's outer ring seen from infinity along a direction
// (DHS §6: "an envelope of a polygon is the same as its (external) visibility polygon from the
// point x = ∞"), in linear time.
//
// Frame: u(x) = dir·x (along dir), w(x) = dir × x (the level, across dir). For every level w in the
// open range (w_min, w_max) of the outer ring, E(w) = max{u : x ∈ P, w(x) = w}. Only the outer
// ring matters: a hole lies inside the outer ring, so at every level the rightmost point of P is on
// the outer ring, and the outer ring alone bounds the region that Q, coming from infinity, can see.
// E is piecewise linear; each maximal piece lies on one outer-ring edge e with dir × e > 0 (P's
// interior on its −u side) and ends at the levels of two vertices (two non-crossing edges can only
// trade places where one of them ends).
#pragma once

#include <pendepth/polygon.hpp>

#include <cstdint>
#include <vector>

namespace pendepth::nonconvex2 {

/// One piece of E: on the open level interval (w(V[lo]), w(V[hi])) the envelope is edge `edge`
/// (global edge index: from vertex `edge` to Polygon::next(edge)). lo and hi are vertex indices
/// that only name levels.
struct EnvelopePiece {
  std::uint32_t lo, hi, edge;
};

/// E of `shape`'s outer ring seen from +∞ along `dir` (dir ≠ 0): maximal pieces in increasing level,
/// consecutive pieces sharing a level (no gaps), the first starting at the lowest level of the ring
/// and the last ending at the highest. Every decision is an exact sign of a polynomial in the input
/// doubles (the rotated coordinates are never rounded). O(n) time for the n vertices of the outer
/// ring: a stack-based visibility walk (envelope.cpp).
std::vector<EnvelopePiece> right_envelope(const Polygon& shape, const Vec2& dir);

}  // namespace pendepth::nonconvex2
