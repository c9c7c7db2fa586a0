// Private: triangulation of a simple polygon with holes (DHS §4.1 Step 1).
#pragma once

#include <pendepth/polygon.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace pendepth::polygon2 {

/// Triangle as three global vertex indices into P.vertices(), counter-clockwise.
using TriangleIds = std::array<std::uint32_t, 3>;

/// Which algorithm produced a triangulation (for tests and measurements).
enum class TriangulationPath { ear_clipping, cdt_fallback, cdt };

/// Polygons without holes and with at most this many vertices are ear-clipped.
inline constexpr std::size_t kEarMax = 32;

/// Triangles with pairwise disjoint interiors whose union is exactly P (no Steiner points: every
/// triangle vertex is a vertex of P, no vertex of P lies on a triangle edge except at its ends;
/// N - 2 + 2h triangles for N vertices and h holes), each strictly counter-clockwise.
/// Hole-free P with N <= kEarMax: exact ear clipping, O(N^2) (O(N·r) predicates for r reflex or
/// straight vertices; about ten times cheaper than the CDT on nesting pieces, docs/benchmarks.md);
/// should no ear be found (impossible for a valid P, kept as a safety net) the CDT triangulates P
/// instead.
/// Otherwise: constrained Delaunay triangulation (CGAL, exact predicates), faces inside P
/// selected by nesting depth, O(N log N). `path`, if given, receives the algorithm used.
std::vector<TriangleIds> triangulate(const Polygon& P, TriangulationPath* path = nullptr);
/// The same triangles written into `out` (replacing its content, reusing its capacity: a caller
/// that keeps `out` allocates nothing per small polygon).
void triangulate(const Polygon& P, std::vector<TriangleIds>& out, TriangulationPath* path = nullptr);

}  // namespace pendepth::polygon2
