// Private: the stored no-fit polygon (nfp2.hpp): the uncovered closed pieces of the reduced-
// convolution candidates (exact, symbolic), a box hierarchy over them, and the exported rings.
#pragma once

#include <pendepth/nfp2.hpp>

#include <vector>

#include "nonconvex2/edge_cut.hpp"
#include "nonconvex2/pair_sums.hpp"

namespace pendepth {

namespace nonconvex2 {

/// One uncovered closed piece [lo, hi] (μ on E, lo ≤ hi exactly) of a candidate E, an edge of a
/// pair sum whose line is `edge`; O lies on its left. A zero-length piece is a single point.
struct NfpPiece {
  Ray E;
  Line edge;
  Param lo, hi;
  Vec2 a, b;      // the ends, each coordinate to a few ulps
  Vec2 blo, bhi;  // conservative box of the exact piece
};

}  // namespace nonconvex2

struct NoFitPolygon2::Impl {
  PairDepth2::Impl S;  // triangulations, box hierarchies, the exact overlap test and contact()
  std::vector<nonconvex2::NfpPiece> pieces;
  nonconvex2::BoxTree tree;  // over the piece boxes (leaf `tri` = piece index)
  std::vector<std::vector<std::vector<Vec2>>> polys;
  std::vector<std::array<Vec2, 2>> slits;
  std::vector<Vec2> points;
  NfpSize sz;
  Impl(const Polygon& P, const Polygon& Q);
  bool overlapping(const Vec2& t) const;
};

/// Links the pieces into rings, slits and isolated points (nfp_rings.cpp).
void nfp_export(NoFitPolygon2::Impl& nfp);

}  // namespace pendepth
