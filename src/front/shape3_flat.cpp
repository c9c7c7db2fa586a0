// Shape3's lower-dimensional shapes (points, segments, flat polygons; docs/design.md
// "Lower-dimensional shapes") and the accessors that tell them from solids.
#include <pendepth/pendepth.hpp>

#include "convex3/flat3.hpp"
#include "primitives/support3.hpp"

namespace pendepth {

Shape3::Shape3(convex3::FlatShape3 flat) : flat_(std::make_shared<const convex3::FlatShape3>(std::move(flat))) {}

Shape3 Shape3::point(const Vec3& p, std::string_view name) {
  const Vec3 v[1] = {p};
  return Shape3(convex3::flat_shape(v, name));
}

Shape3 Shape3::segment(const Vec3& a, const Vec3& b, std::string_view name) {
  const Vec3 v[2] = {a, b};
  convex3::FlatShape3 f = convex3::flat_shape(v, name);
  if (f.dim != 1) throw InvalidInput(std::string(name) + ": the segment's two ends coincide (use a point)");
  return Shape3(std::move(f));
}

Shape3 Shape3::flat(std::span<const Vec3> points, std::string_view name) {
  return Shape3(convex3::flat_shape(points, name));
}

int Shape3::dimension() const { return flat_ && radius_ == 0 ? flat_->dim : 3; }
std::span<const Vec3> Shape3::flat_vertices() const {
  return flat_ ? std::span<const Vec3>(flat_->v) : std::span<const Vec3>();
}
const convex3::FlatShape3* Shape3::flat_shape() const { return flat_.get(); }

const ConvexPolytope& Shape3::polytope() const {
  if (!p_ && curved_) throw InvalidInput(name() + " is a curved primitive (a cylinder, a cone, an ellipsoid): it has no polytope");
  if (!p_)
    throw InvalidInput(name() + (radius_ > 0 ? " is a rounded shape with a lower-dimensional core (a sphere, a capsule)"
                                             : " is a lower-dimensional shape (a point, a segment, a flat polygon)") +
                       ": it has no polytope");
  return *p_;
}
std::size_t Shape3::size() const { return flat_ ? flat_->v.size() : p_ ? p_->size() : 0; }
const std::string& Shape3::name() const {
  return radius_ > 0 ? rounded_name_ : flat_ ? flat_->name : curved_ ? curved_->name : p_->name();
}

}  // namespace pendepth
