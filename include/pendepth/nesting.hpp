// pendepth — nesting instances: the ESICUP / jagua-rs JSON format (src/io/nesting_json.cpp).
//
//   NestingInstance inst = read_nesting_instance("shirts.json");
//   std::vector<Shape2> shapes;  for (auto& it : inst.items) shapes.push_back(it.shape);
//   auto nfps = no_fit_polygons(shapes, {{0.0, 180.0}});          // pendepth.hpp
//
// The format (jagua-rs's JSON instances, as converted from the ESICUP data sets):
//   { "name": "...", "items": [ { "id": 0, "demand": 2, "allowed_orientations": [0.0, 180.0],
//       "shape": { "type": "simple_polygon", "data": [[x, y], ...] } }, ... ], ... }
// with "shape" also { "type": "polygon", "data": { "outer": [[x, y], ...], "inner": [[[x, y],
// ...], ...] } } (holes). Other keys (strip_height, bins, dxf, zones, ...) are ignored.
// "allowed_orientations" absent (jagua-rs: any rotation) reads as [0]. A ring may repeat its first
// vertex at the end. "multi_polygon" shapes are rejected (one item is one polygon here).
#pragma once

#include <pendepth/pendepth.hpp>

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace pendepth {

/// One item of a nesting instance: its shape validated once as a Shape2 (named "shape").
struct NestingItem {
  std::string id;      ///< the "id" field as written (a number or a string)
  std::size_t demand;  ///< copies to place (≥ 0)
  Shape2 shape;
  std::vector<double> allowed_orientations;  ///< degrees, counter-clockwise; [0] when absent
};

struct NestingInstance {
  std::string name;  ///< the "name" field ("" when absent)
  std::vector<NestingItem> items;
};

/// Parses an instance. Throws InvalidInput "SOURCE: problem" for malformed JSON (with its byte
/// offset), a missing or mistyped field, a non-finite coordinate or angle, an empty "items", or a
/// shape that is not a valid simple polygon with holes — "SOURCE: item K (id X): <the Shape2
/// validation message>". O(size of the text) plus the shapes' validation.
NestingInstance parse_nesting_instance(std::string_view text, std::string_view source = "<json>");
/// Reads and parses a file (SOURCE = the path as given); "PATH: cannot read file (reason)".
NestingInstance read_nesting_instance(const std::filesystem::path& path);

}  // namespace pendepth
