// pendepth — Shape2: a validated 2D shape, convex or not (include/pendepth/pendepth.hpp).
//
// A single ring that ConvexPolygon accepts is kept in the convex normal form (docs/design.md §1),
// so pairs with it use the O(log) convex engines; anything else is a Polygon (simple, with holes).
#include <pendepth/io.hpp>
#include <pendepth/pendepth.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <mutex>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "front/shape2_data.hpp"

namespace pendepth {

const Shape2::Data& shape_data(const Shape2& s) { return *s.d_; }

std::shared_ptr<const nonconvex2::ShapeSide> front::shape_side(const Shape2& s, bool negate) {
  return shape_data(s).sides.side(s.polygon(), negate);
}

const nonconvex2::ShapeCache& front::shape_cache(const Shape2& s) { return shape_data(s).sides; }

Shape2 front::scaled_shape(const Shape2& s, int e, const std::function<Shape2()>& make) {
  const Shape2::Data& d = shape_data(s);
  auto find = [&]() -> const Shape2* {
    for (const auto& [k, c] : d.scaled)
      if (k == e) return &c;
    return nullptr;
  };
  {
    std::lock_guard lock(d.scaled_mutex);
    if (const Shape2* c = find()) return *c;
  }
  Shape2 made = make();  // outside the lock: validation is O(n log n)
  std::lock_guard lock(d.scaled_mutex);
  if (const Shape2* c = find()) return *c;  // another thread was first: the same shape, keep one
  d.scaled.emplace_back(e, made);
  return made;
}

namespace {

std::shared_ptr<Shape2::Data> from_io(io::Shape2 s, std::string_view name) {
  auto d = std::make_shared<Shape2::Data>();
  d->convex = std::move(s.convex);
  d->polygon = std::move(s.polygon);
  d->name = std::string(name);
  return d;
}

}  // namespace

Shape2::Shape2(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes, std::string_view name) {
  std::vector<std::vector<Vec2>> rings;
  rings.reserve(1 + holes.size());
  rings.push_back(std::move(outer));
  for (auto& h : holes) rings.push_back(std::move(h));
  if (rings.size() == 1) {
    // Same rule as a file: convex when ConvexPolygon accepts the ring; a reflex vertex or a ring
    // winding twice makes it a general polygon, any other defect is reported as it is.
    try {
      d_ = from_io(io::Shape2{ConvexPolygon(rings[0], name), std::nullopt}, name);
      return;
    } catch (const InvalidInput& e) {
      const std::string msg = e.what();
      if (msg.find("not convex") == std::string::npos && msg.find("self-intersecting") == std::string::npos)
        throw;
    }
  }
  d_ = from_io(io::Shape2{std::nullopt, Polygon(rings, name)}, name);
}

Shape2::Shape2(ConvexPolygon convex) {
  const std::string name = convex.name();
  d_ = from_io(io::Shape2{std::move(convex), std::nullopt}, name);
}

Shape2::Shape2(Polygon polygon) {
  const std::string name = polygon.name();
  d_ = from_io(io::Shape2{std::nullopt, std::move(polygon)}, name);
}

Shape2 Shape2::from_wkt(std::string_view text, std::string_view name) {
  Shape2 s;
  s.d_ = from_io(io::shape2_from_wkt(io::parse_wkt_polygon(text, name), name, name), name);
  return s;
}

Shape2 Shape2::from_file(const std::filesystem::path& path, std::string_view name) {
  Shape2 s;
  s.d_ = from_io(io::read_shape2(path, name), name);
  return s;
}

bool Shape2::is_convex() const { return d_->convex.has_value(); }

std::size_t Shape2::hole_count() const { return d_->convex || !d_->flat.empty() ? 0 : d_->polygon->hole_count(); }

const ConvexPolygon& Shape2::convex() const {
  if (!d_->convex) throw std::logic_error("Shape2::convex(): " + d_->name + " is not convex");
  return *d_->convex;
}

const Polygon& Shape2::polygon() const {
  if (!d_->flat.empty())
    throw InvalidInput(d_->name + " is a " + (d_->flat.size() == 1 ? "point" : "segment") + ": it has no polygon");
  if (d_->convex)
    std::call_once(d_->polygon_once, [&] { d_->polygon.emplace(Polygon::simple(d_->convex->vertices(), d_->name)); });
  return *d_->polygon;
}

std::vector<std::vector<Vec2>> Shape2::rings() const {
  std::vector<std::vector<Vec2>> out;
  if (!d_->flat.empty()) {
    out.push_back(d_->flat);
  } else if (d_->convex) {
    out.emplace_back(d_->convex->vertices().begin(), d_->convex->vertices().end());
  } else {
    for (std::size_t k = 0; k < d_->polygon->ring_count(); ++k)
      out.emplace_back(d_->polygon->ring(k).begin(), d_->polygon->ring(k).end());
  }
  return out;
}

std::size_t Shape2::size() const {
  return !d_->flat.empty() ? d_->flat.size() : d_->convex ? d_->convex->size() : d_->polygon->size();
}

const std::string& Shape2::name() const { return d_->name; }

std::array<std::size_t, 2> Shape2::input_vertex(std::size_t vertex) const {
  if (vertex >= size())
    throw InvalidInput(d_->name + ": vertex " + std::to_string(vertex) + " out of range (" +
                       std::to_string(size()) + " vertices)");
  if (!d_->flat.empty()) return {0, vertex};
  if (d_->convex) return {0, d_->convex->input_index(vertex)};
  return {d_->polygon->ring_of(vertex), d_->polygon->input_index(vertex)};
}

namespace {

// `degrees` reduced to [0, 360), exactly (fmod is exact).
double reduce_degrees(double degrees) {
  double r = std::fmod(degrees, 360.0);
  if (r < 0) r += 360.0;
  return r == 360.0 ? 0.0 : r;
}

}  // namespace

bool Shape2::rotation_is_exact(double degrees) {
  return std::isfinite(degrees) && std::fmod(reduce_degrees(degrees), 90.0) == 0.0;
}

Shape2 Shape2::rotated(double degrees) const {
  if (!std::isfinite(degrees))
    throw InvalidInput(d_->name + ": rotation angle is not finite (" + std::to_string(degrees) + " degrees)");
  const double r = reduce_degrees(degrees);
  std::function<Vec2(const Vec2&)> turn;
  if (rotation_is_exact(r)) {
    switch (static_cast<int>(r / 90.0)) {
      case 0: turn = [](const Vec2& p) { return p; }; break;
      case 1: turn = [](const Vec2& p) { return Vec2(-p.y(), p.x()); }; break;
      case 2: turn = [](const Vec2& p) { return Vec2(-p.x(), -p.y()); }; break;
      default: turn = [](const Vec2& p) { return Vec2(p.y(), -p.x()); }; break;
    }
  } else {
    const double rad = r * (std::numbers::pi / 180.0);
    const double c = std::cos(rad), s = std::sin(rad);
    turn = [c, s](const Vec2& p) { return Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y()); };
  }
  char suffix[64];
  std::snprintf(suffix, sizeof suffix, "@%.17g", degrees);
  const std::string name = d_->name + suffix;
  std::vector<std::vector<Vec2>> rings = this->rings();
  for (auto& ring : rings)
    for (auto& p : ring) p = turn(p);
  if (!d_->flat.empty()) return rings[0].size() == 1 ? point(rings[0][0], name) : segment(rings[0][0], rings[0][1], name);
  std::vector<Vec2> outer = std::move(rings.front());
  rings.erase(rings.begin());
  return Shape2(std::move(outer), std::move(rings), name);
}

// ---- points and segments (issue 16 item 4; docs/design.md "Lower-dimensional shapes") ----

namespace {

void check_finite(const Vec2& p, std::string_view name, const char* what) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
    throw InvalidInput(std::string(name) + ": " + what + " (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) +
                       ") is not finite");
}

}  // namespace

Shape2 Shape2::point(const Vec2& p, std::string_view name) {
  check_finite(p, name, "the point");
  Shape2 s;
  auto d = std::make_shared<Data>();
  d->flat = {p};
  d->name = std::string(name);
  s.d_ = std::move(d);
  return s;
}

Shape2 Shape2::segment(const Vec2& a, const Vec2& b, std::string_view name) {
  check_finite(a, name, "the segment's first end");
  check_finite(b, name, "the segment's second end");
  if (a == b) throw InvalidInput(std::string(name) + ": the segment's two ends coincide (use a point)");
  Shape2 s = point(a, name);
  std::const_pointer_cast<Data>(s.d_)->flat.push_back(b);
  return s;
}

int Shape2::dimension() const { return d_->flat.empty() ? 2 : static_cast<int>(d_->flat.size()) - 1; }

std::span<const Vec2> Shape2::flat_vertices() const { return d_->flat; }

}  // namespace pendepth
