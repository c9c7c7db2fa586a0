// Private: triangulation of a simple polygon with holes (DHS §4.1 Step 1).
#pragma once

#include <pendepth/polygon.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace pendepth::polygon2 {

/// Triangle as three global vertex indices into P.vertices(), counter-clockwise.
using TriangleIds = std::array<std::uint32_t, 3>;

/// Triangles with pairwise disjoint interiors whose union is exactly P (no Steiner points: every
/// triangle vertex is a vertex of P; N - 2 + 2h triangles for N vertices and h holes).
/// Constrained Delaunay triangulation (CGAL, exact predicates; no constructions are needed because
/// validated rings never cross), then faces inside P selected by nesting depth. O(N log N).
std::vector<TriangleIds> triangulate(const Polygon& P);

}  // namespace pendepth::polygon2
