// pendepth — primitive shape specs: a shape argument of the CLI (and of any program) may name a
// primitive instead of a file (issue 16 item 7; docs/cli.md "Primitive specs"; src/io/shape_spec.cpp).
//
//   sphere:R  capsule:R,H  box:X,Y,Z  rounded:R:FILE  point:X,Y,Z  segment:X1,Y1,Z1,X2,Y2,Z2
//   (3D; capsule: the segment (0,0,−H)–(0,0,H) ⊕ ball R; box: half extents; rounded: FILE's shape
//   ⊕ ball R); cylinder:R,H (axis z, half height H), cone:R,H (base radius R at z = −H, apex at
//   z = H), ellipsoid:A,B,C (semi-axes); 2D: point:X,Y and segment:X1,Y1,X2,Y2 (Shape2::point /
//   segment).
#pragma once

#include <pendepth/pendepth.hpp>

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pendepth::io {

struct ShapeSpec {
  std::string kind;             ///< sphere, capsule, box, rounded, point, segment, ...
  std::vector<double> numbers;  ///< the numbers, in order
  std::string file;             ///< rounded: the core's file
  std::string text;             ///< the spec as given (for messages)
  int dimension = 3;            ///< 2 for point:X,Y and segment:X1,Y1,X2,Y2
};

/// nullopt when `arg` is not a spec (no known `KIND:` prefix: a file path); else the parsed spec.
/// Throws InvalidInput naming the spec for a malformed one (wrong count, not a number, not
/// finite, an empty file) and for a known kind that is not implemented.
std::optional<ShapeSpec> parse_shape_spec(std::string_view arg);

/// The 2D shape of a parsed spec of dimension 2 (Shape2::point, Shape2::segment). Throws
/// InvalidInput naming the spec for a 3D spec or invalid values (a segment's ends coincide).
pendepth::Shape2 shape2_from_spec(const ShapeSpec& spec, std::string_view name = "shape");

/// The shape of a parsed spec of dimension 3 (Shape3 primitives; `rounded` reads its file as Shape3::from_file,
/// `hull` as there). Throws InvalidInput naming the spec for invalid sizes.
Shape3 shape3_from_spec(const ShapeSpec& spec, std::string_view name = "shape", bool hull = false);

/// A point set read from `source` (a file without faces, a file whose points are coplanar, or
/// --hull's vertices) as a shape: its hull when the points span 3D, else the lower-dimensional
/// Shape3::flat (a point, a segment, a flat polygon; exact dimension test). Errors are prefixed
/// with `source` and name `name`; an empty or non-finite set gives the hull's errors.
Shape3 shape3_from_points(std::span<const Vec3> points, std::string_view source, std::string_view name);

/// The exact affine dimension of the points (−1 when empty; 3 when some point is not finite).
int affine_dimension(std::span<const Vec3> points);

}  // namespace pendepth::io
