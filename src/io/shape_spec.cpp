// Primitive shape specs (include/pendepth/shape_spec.hpp): KIND:NUMBERS[:FILE], parsed strictly
// (every number as the readers read numbers, src/io/number.hpp; no trailing text).
#include <pendepth/shape_spec.hpp>

#include <pendepth/io.hpp>
#include <pendepth/polytope.hpp>

#include "io/number.hpp"

#include <array>

namespace pendepth::io {

namespace {

struct Kind {
  const char* name;
  int count;           // numbers expected (3D)
  int count2;          // numbers of the 2D form, or -1
  bool file;           // KIND:NUMBERS:FILE
  const char* form;
};
constexpr std::array<Kind, 9> kKinds{{
    {"sphere", 1, -1, false, "sphere:R"},
    {"capsule", 2, -1, false, "capsule:R,H"},
    {"box", 3, -1, false, "box:X,Y,Z"},
    {"rounded", 1, -1, true, "rounded:R:FILE"},
    {"point", 3, 2, false, "point:X,Y,Z"},
    {"segment", 6, 4, false, "segment:X1,Y1,Z1,X2,Y2,Z2"},
    {"cylinder", 2, -1, false, "cylinder:R,H"},
    {"cone", 2, -1, false, "cone:R,H"},
    {"ellipsoid", 3, -1, false, "ellipsoid:A,B,C"},
}};

}  // namespace

std::optional<ShapeSpec> parse_shape_spec(std::string_view arg) {
  const std::size_t colon = arg.find(':');
  if (colon == std::string_view::npos) return std::nullopt;
  const std::string_view name = arg.substr(0, colon);
  const Kind* kind = nullptr;
  for (const Kind& k : kKinds)
    if (name == k.name) kind = &k;
  if (!kind) return std::nullopt;  // a path that happens to hold a colon
  ShapeSpec s;
  s.kind = kind->name;
  s.text = std::string(arg);
  auto fail = [&](const std::string& why) -> InvalidInput {
    return InvalidInput("shape spec '" + s.text + "': " + why + " (expected " + kind->form + ")");
  };
  std::string_view rest = arg.substr(colon + 1);
  if (kind->file) {
    const std::size_t c2 = rest.find(':');
    if (c2 == std::string_view::npos || c2 + 1 == rest.size()) throw fail("no file");
    s.file = std::string(rest.substr(c2 + 1));
    rest = rest.substr(0, c2);
  }
  const char* p = rest.data();
  const char* const end = rest.data() + rest.size();
  while (true) {
    double x = 0;
    const char* after = p;
    const detail::Decimal r = detail::read_decimal(p, end, x, after);
    if (r == detail::Decimal::NotNumber) throw fail("'" + std::string(p, end) + "' is not a number");
    if (r != detail::Decimal::Ok) throw fail("'" + std::string(p, after) + "' is not finite");
    s.numbers.push_back(x);
    p = after;
    if (p == end) break;
    if (*p != ',') throw fail("unexpected '" + std::string(p, end) + "'");
    ++p;
  }
  const int n = static_cast<int>(s.numbers.size());
  if (n != kind->count && n != kind->count2)
    throw fail(std::to_string(n) + " number" + (n == 1 ? "" : "s") + " given");
  if (n == kind->count2) s.dimension = 2;
  return s;
}

Shape3 shape3_from_spec(const ShapeSpec& s, std::string_view name, bool hull) {
  const auto& v = s.numbers;
  if (s.dimension != 3) throw InvalidInput("shape spec '" + s.text + "': a 2D shape where a 3D one is needed");
  try {
    if (s.kind == "sphere") return Shape3::sphere(v[0], name);
    if (s.kind == "capsule") return Shape3::capsule(v[0], v[1], name);
    if (s.kind == "box") return Shape3::box(v[0], v[1], v[2], name);
    if (s.kind == "point") return Shape3::point(Vec3(v[0], v[1], v[2]), name);
    if (s.kind == "segment") return Shape3::segment(Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]), name);
    if (s.kind == "cylinder") return Shape3::cylinder(v[0], v[1], name);
    if (s.kind == "cone") return Shape3::cone(v[0], v[1], name);
    if (s.kind == "ellipsoid") return Shape3::ellipsoid(v[0], v[1], v[2], name);
    if (s.kind == "rounded") return Shape3::rounded(Shape3::from_file(s.file, name, hull), v[0], name);
  } catch (const InvalidInput& e) {
    throw InvalidInput("shape spec '" + s.text + "': " + e.what());
  }
  throw InvalidInput("shape spec '" + s.text + "': unknown kind");
}

pendepth::Shape2 shape2_from_spec(const ShapeSpec& s, std::string_view name) {
  const auto& v = s.numbers;
  if (s.dimension != 2)
    throw InvalidInput("shape spec '" + s.text + "': not a 2D shape (2D specs: point:X,Y and segment:X1,Y1,X2,Y2)");
  try {
    if (s.kind == "point") return pendepth::Shape2::point(Vec2(v[0], v[1]), name);
    if (s.kind == "segment") return pendepth::Shape2::segment(Vec2(v[0], v[1]), Vec2(v[2], v[3]), name);
  } catch (const InvalidInput& e) {
    throw InvalidInput("shape spec '" + s.text + "': " + e.what());
  }
  throw InvalidInput("shape spec '" + s.text + "': unknown kind");
}

int affine_dimension(std::span<const Vec3> p) {
  if (p.empty()) return -1;
  for (const Vec3& x : p)
    if (!x.allFinite()) return 3;
  std::size_t b = 0, c = 0;
  for (b = 1; b < p.size() && p[b] == p[0]; ++b) {}
  if (b == p.size()) return 0;
  for (c = 1; c < p.size() && predicates::collinear3(p[0], p[b], p[c]); ++c) {}
  if (c == p.size()) return 1;
  for (std::size_t d = 1; d < p.size(); ++d)
    if (predicates::orient3d(p[0], p[b], p[c], p[d]) != 0) return 3;
  return 2;
}

Shape3 shape3_from_points(std::span<const Vec3> points, std::string_view source, std::string_view name) {
  const int dim = affine_dimension(points);
  if (dim < 0 || dim == 3) return Shape3(convex_polytope_from_points(points, source, name));
  try {
    return Shape3::flat(points, name);
  } catch (const InvalidInput& e) {
    throw InvalidInput(std::string(source) + ": " + e.what());
  }
}

}  // namespace pendepth::io
