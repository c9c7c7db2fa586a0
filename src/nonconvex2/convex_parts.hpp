// Private: a convex decomposition from a triangulation (Hertel–Mehlhorn): triangles merged across
// their shared diagonals while both ends of the diagonal stay convex (exact turn signs).
//
// Contract: `tris` is a triangulation of one polygon (Tri normal form: CCW, global vertex ids;
// coordinates may be the polygon's or its negation); every triangle lands in exactly one part;
// each part is a convex polygon (no right turn; straight vertices possible) given CCW by the
// vertex ids and coordinates of its triangles. With `merge` false (polygons with holes, whose
// triangle adjacency is not a tree) the parts are the triangles themselves. Every diagonal left
// between two parts is essential: removing it would make a reflex vertex (so the parts are at most
// 4× the minimum number, Hertel & Mehlhorn 1983).
// Cost: O(T·d) to pair the diagonals (d the largest vertex degree; O(T log T) for T > 1024), O(T) exact turn tests and
// O(1) splices, O(T) output.
// Used by the no-fit-polygon classification (nfp_classify.cpp): a point test against the open
// sums of convex parts needs far fewer sums, and meets far fewer sums on their boundary, than one
// against the sums of triangles (both unions are the same set O).
#pragma once

#include <cstdint>
#include <vector>

#include "nonconvex2/pair_sums.hpp"

namespace pendepth::nonconvex2 {

struct ConvexParts {
  std::vector<Vec2> v;                // ring vertices, part after part (CCW)
  std::vector<std::uint32_t> id;      // their global vertex ids
  std::vector<std::uint32_t> start;   // part k is [start[k], start[k + 1])
  std::vector<Vec2> lo, hi;           // boxes (exact: input coordinates)
  std::size_t size() const { return lo.size(); }
  /// Frees the storage when it is large (after a large shape), so that an object kept for reuse
  /// across calls (convex_parts reuses its capacity) does not pin a large shape's memory.
  void trim() {
    if (v.capacity() > (std::size_t(1) << 12)) *this = ConvexParts();
  }
};

/// Fills `out` (its vectors' capacity reused: a caller that keeps one ConvexParts per thread and
/// shape role, trim()med after use, allocates nothing per call on small shapes).
void convex_parts(const std::vector<Tri>& tris, bool merge, ConvexParts& out);

}  // namespace pendepth::nonconvex2
