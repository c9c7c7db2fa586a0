// Private: Shape2's shared, immutable data (include/pendepth/pendepth.hpp), with the per-shape
// caches every pair built from the shape reuses (issue 19 item 2): the polygon of a convex shape
// and the triangulated sides of the polygon × polygon structures (nonconvex2/shape_side.hpp),
// each made on first use, thread-safe. A pair's answer never depends on whether a cache was
// already filled (the cached values are deterministic functions of the shape).
#pragma once

#include <pendepth/pendepth.hpp>

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "nonconvex2/shape_side.hpp"

namespace pendepth {

struct Shape2::Data {
  std::optional<ConvexPolygon> convex;
  mutable std::optional<Polygon> polygon;  // for a convex shape: built on first use
  mutable std::once_flag polygon_once;
  std::string name;
  std::vector<Vec2> flat;  // a point (one vertex) or a segment (two): no convex, no polygon
  nonconvex2::ShapeCache sides;  // the polygon's triangulated sides (roles P and −Q)
  // The shape in engine coordinates for each power-of-two scale a pair used (src/front/scale.hpp,
  // pair2.cpp's engine_shape), so scaled pairs share the scaled copy's caches too. Insert only,
  // under the mutex; each entry is a deterministic function of the shape and the exponent.
  mutable std::mutex scaled_mutex;
  mutable std::vector<std::pair<int, Shape2>> scaled;
};

namespace front {

/// The shape's polygon in role P (negate false) or −Q (true), triangulated once per shape and
/// role. Precondition: a solid shape (dimension 2).
std::shared_ptr<const nonconvex2::ShapeSide> shape_side(const Shape2& s, bool negate);
/// The per-shape caches of s (its shared data).
const nonconvex2::ShapeCache& shape_cache(const Shape2& s);
/// The copy of s scaled by 2^-e made by `make` on the first request for e, then shared
/// (thread-safe; a throwing `make` caches nothing).
Shape2 scaled_shape(const Shape2& s, int e, const std::function<Shape2()>& make);

}  // namespace front
}  // namespace pendepth
