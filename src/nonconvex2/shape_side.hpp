// Private: the per-shape work of the polygon × polygon structures (PairDepth2, NoFitPolygon2),
// computed once per shape and role and shared by every pair built from it (issue 19 item 2).
//
// A ShapeSide is one polygon in one role: as P (its triangles as they are) or as Q (the triangles
// of −Q, vertex ids Q's), with the box hierarchy over those triangles and, on first use, their
// convex parts (convex_parts.hpp; Hertel–Mehlhorn merge when the polygon has no holes) and the
// no-fit polygon classifier's per-shape maps and pieces (nfp_classify.cpp). Every
// field is a deterministic function of the polygon and the role, so a pair built from shared
// sides is the same bits as one built from fresh ones, whatever the order or thread of the pairs.
// A ShapeCache (owned by Shape2's shared data, src/front/shape2_data.hpp) makes each role's side
// on first request, thread-safe (std::call_once); nfp-all's parallel pairs share them.
// Cost: triangulation O(n log n), hierarchy O(n log n), parts O(n·d) (convex_parts.hpp), once per
// shape and role instead of once per pair.
#pragma once

#include <pendepth/polygon.hpp>

#include <memory>
#include <mutex>
#include <vector>

#include "nonconvex2/convex_parts.hpp"
#include "nonconvex2/pair_sums.hpp"
#include "polygon2/triangulation.hpp"

namespace pendepth::nonconvex2 {

struct ShapeSide {
  Polygon shape;           // the polygon (not negated: ids and next() are the shape's)
  bool negated = false;    // role Q: the triangles are those of −shape
  std::vector<Tri> tris;   // normal form (pair_depth.cpp)
  BoxTree tree;            // over tris
  ShapeSide(const Polygon& s, bool negate);
  /// The convex parts of tris (built on first use, thread-safe).
  const ConvexParts& parts() const;
  /// The no-fit polygon classifier's per-shape data (nfp_classify.cpp), each built on first use,
  /// thread-safe: the part of parts() holding each boundary edge g → next(g) (~0 for none), and
  /// for large pairs the pieces (parts without straight vertices, split at 12 corners), the piece
  /// holding each boundary edge, per-piece coordinate bounds and the box tree over the pieces.
  struct Pieces {
    ConvexParts r;
    std::vector<std::uint32_t> edge_piece;
    std::vector<double> smax;
    BoxTree tree;
  };
  const std::vector<std::uint32_t>& edge_parts() const;
  const Pieces& pieces() const;

 private:
  mutable std::once_flag parts_once_, edge_once_, pieces_once_;
  mutable ConvexParts parts_;
  mutable std::vector<std::uint32_t> edge_parts_;
  mutable Pieces pieces_;
};

/// A fresh side (no cache): the engine-level constructors.
std::shared_ptr<const ShapeSide> make_side(const Polygon& shape, bool negate);

/// Both roles of one shape, each made on first request (thread-safe), and the role-free pieces
/// other engines share: the triangulation's id triples (role P's, normal form; polygon × convex,
/// polygon2::ConvolvedTriangles) and the box tree over the edges (BoundaryPair2, signed distance
/// and cast).
class ShapeCache {
 public:
  std::shared_ptr<const ShapeSide> side(const Polygon& shape, bool negate) const {
    const int r = negate ? 1 : 0;
    std::call_once(once_[r], [&] { side_[r] = make_side(shape, negate); });
    return side_[r];
  }
  const std::vector<polygon2::TriangleIds>& triangles(const Polygon& shape) const;  // pair_depth.cpp
  std::shared_ptr<const BoxTree> edge_tree(const Polygon& shape) const;             // pair_depth.cpp

 private:
  mutable std::once_flag once_[2], tri_once_, edge_once_;
  mutable std::shared_ptr<const ShapeSide> side_[2];
  mutable std::vector<polygon2::TriangleIds> tri_;
  mutable std::shared_ptr<const BoxTree> edge_;
};

}  // namespace pendepth::nonconvex2
