// Private: the medial axis of the convex polygon M = P ⊕ (−Q), by the shrinking wavefront (DHS §3,
// Theorem 3.2; docs/algorithms.md §R3.1). For convex M the medial axis is its straight skeleton: a
// tree whose leaves are the N vertices of M and whose N − 2 internal nodes are centres of maximal
// inscribed disks, each touching three edge lines. Build O(N log N), memory O(N).
//
// Coordinates are relative to `origin` (the centre of M's bounding box) so shapes far from (0,0)
// keep their precision: edge k's line is {x : normal[k]·(x − origin) = offset[k]}, M lies on
// the side normal·(x − origin) <= offset.
#pragma once

#include "convex2/minkowski_sum.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace pendepth::convex2 {

struct MedialAxis {
  /// adj value meaning "this branch ends at a vertex of M".
  static constexpr std::int32_t kLeaf = -1;

  Vec2 origin{0, 0};
  std::vector<Vec2> normal;    ///< unit outward normal of edge k of M (double)
  std::vector<double> offset;  ///< offset of edge k's line, relative to origin

  /// Internal node j < N − 2: centre[j] (relative to origin) is equidistant from the lines of
  /// edges line[j][0..2], listed in counter-clockwise order of their normals. The spoke towards
  /// line e is the ray centre + s·normal[e]. Sector k — directions from normal[line[j][k]]
  /// counter-clockwise to normal[line[j][(k+1)%3]], possibly wider than 180° — contains the
  /// branch towards adj[j][k] (an internal node, or kLeaf) and the medial edge between it and
  /// node j separates the cells of those two lines.
  std::vector<Vec2> centre;
  std::vector<std::array<std::uint32_t, 3>> line;
  /// Nodes are numbered in creation order. Every node but the root has exactly one later
  /// neighbour, adj[j][2] > j: the node that consumed the wavefront vertex j started.
  std::vector<std::array<std::int32_t, 3>> adj;
  /// wide[j]: the sector of node j spanning 180° or more (at most one), or 3 if none. Decided
  /// exactly from M's edge vectors, so it is right even where rounded normals are out of order.
  std::vector<std::uint8_t> wide;
  std::int32_t root = 0;  ///< the node created last (from the final three lines)

  /// False when rounding left an edge-collapse event undefined (two bisectors parallel or
  /// diverging in double: three consecutive edges of M whose directions are so close, below
  /// ~1e-16 rad, that their rounded normals coincide; or overflow). The tree is then incomplete
  /// and must not be used.
  bool ok = true;
};

/// Medial axis of M: edge-collapse events (centre = intersection of the two bisectors that
/// bound the shrinking edge) in a min-heap keyed by disk radius, lazy deletion by version
/// stamps; simultaneous events (regular polygons, rectangles) give coincident nodes joined by
/// zero-length medial edges, so every internal node keeps degree 3. O(N log N), N = M.size().
MedialAxis medial_axis(const MinkowskiSum& M);

}  // namespace pendepth::convex2
