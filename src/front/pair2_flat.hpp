// Private: Pair2 with a point or a segment (issue 16 item 4; src/front/pair2_flat.cpp): the
// lower-dimensional shape always plays F in polygon2::FlatDepth2; when it is P, the pair is
// answered swapped (Q fixed, P placed at −t along −d) and mapped back, as Pair2 does for
// convex × polygon. Shapes in engine coordinates (src/front/scale.hpp); answers too.
#pragma once

#include <pendepth/pendepth.hpp>

#include "polygon2/flat_depth2.hpp"

namespace pendepth::front {

struct FlatPair2 {
  /// P, Q in engine coordinates, at least one of them lower-dimensional. Throws InvalidInput when
  /// both are.
  FlatPair2(const Shape2& P, const Shape2& Q);

  bool overlapping(const Vec2& t) const;
  Depth2 minimum(const Vec2& t) const;
  Depth2 along(const Vec2& t, const Vec2& d) const;
  Depth2 separation(const Vec2& t, const Vec2& d) const;
  Distance2 signed_distance(const Vec2& t) const;
  Cast2 cast(const Vec2& t, const Vec2& d) const;
  /// M's rings, in engine coordinates (the caller scales them back).
  NoFitPolygonParts parts() const;

  bool swapped = false;  // P is the point or segment
  polygon2::FlatDepth2 engine;
};

}  // namespace pendepth::front
