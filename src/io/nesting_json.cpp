// pendepth — the ESICUP / jagua-rs JSON nesting-instance reader (include/pendepth/nesting.hpp).
//
// Contract: strict. Every field this reader uses is checked for presence and type; each problem
// is one InvalidInput "SOURCE: item K (id X): problem" (or "SOURCE: problem" above the items).
// Each item's shape is validated once, as a Shape2 (the polygon checks of polygon.hpp). The JSON
// parser is nlohmann-json (Debian's nlohmann-json3-dev, header-only, private to the library).
// Cost: O(size of the text) plus the validation of each shape (O(n log n) per shape).
#include <pendepth/io.hpp>
#include <pendepth/nesting.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace pendepth {

namespace {

using nlohmann::json;

struct Context {
  std::string where;  // "SOURCE" or "SOURCE: item K (id X)"
  [[noreturn]] void fail(const std::string& problem) const { throw InvalidInput(where + ": " + problem); }
};

const json& field(const json& obj, const char* key, const Context& cx, const std::string& what) {
  const auto it = obj.find(key);
  if (it == obj.end()) cx.fail(what + ": missing \"" + key + "\"");
  return *it;
}

const char* type_name(const json& j) { return j.type_name(); }

double number(const json& j, const Context& cx, const std::string& what) {
  if (!j.is_number()) cx.fail(what + ": expected a number, got " + type_name(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) cx.fail(what + ": not a finite number");
  return v;
}

// A ring [[x, y], ...]: the repeated closing vertex is left to Shape2 (it accepts one).
std::vector<Vec2> ring(const json& j, const Context& cx, const std::string& what) {
  if (!j.is_array()) cx.fail(what + ": expected an array of [x, y] points, got " + type_name(j));
  std::vector<Vec2> out;
  out.reserve(j.size());
  for (std::size_t k = 0; k < j.size(); ++k) {
    const json& p = j[k];
    const std::string pw = what + " point " + std::to_string(k);
    if (!p.is_array() || p.size() != 2) cx.fail(pw + ": expected [x, y]");
    out.emplace_back(number(p[0], cx, pw + " x"), number(p[1], cx, pw + " y"));
  }
  return out;
}

Shape2 item_shape(const json& shape, const Context& cx) {
  if (!shape.is_object()) cx.fail(std::string("shape: expected an object, got ") + type_name(shape));
  const json& type = field(shape, "type", cx, "shape");
  if (!type.is_string()) cx.fail("shape: \"type\" is not a string");
  const std::string t = type.get<std::string>();
  const json& data = field(shape, "data", cx, "shape");
  std::vector<Vec2> outer;
  std::vector<std::vector<Vec2>> holes;
  if (t == "simple_polygon") {
    outer = ring(data, cx, "shape data");
  } else if (t == "polygon") {
    if (!data.is_object()) cx.fail(std::string("shape data: expected {\"outer\": ..., \"inner\": ...}, got ") + type_name(data));
    outer = ring(field(data, "outer", cx, "shape data"), cx, "shape outer ring");
    if (const auto it = data.find("inner"); it != data.end()) {
      if (!it->is_array()) cx.fail(std::string("shape inner: expected an array of rings, got ") + type_name(*it));
      for (std::size_t h = 0; h < it->size(); ++h) holes.push_back(ring((*it)[h], cx, "shape hole " + std::to_string(h + 1)));
    }
  } else if (t == "multi_polygon") {
    cx.fail("shape type \"multi_polygon\" is not supported (one item must be one polygon)");
  } else {
    cx.fail("unknown shape type \"" + t + "\" (expected simple_polygon or polygon)");
  }
  try {
    return Shape2(std::move(outer), std::move(holes), "shape");
  } catch (const InvalidInput& e) {
    cx.fail(e.what());
  }
}

}  // namespace

NestingInstance parse_nesting_instance(std::string_view text, std::string_view source) {
  Context top{std::string(source)};
  json doc;
  try {
    doc = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    top.fail("invalid JSON (byte " + std::to_string(e.byte) + ")");
  }
  if (!doc.is_object()) top.fail(std::string("expected a JSON object, got ") + type_name(doc));
  NestingInstance inst;
  if (const auto it = doc.find("name"); it != doc.end()) {
    if (!it->is_string()) top.fail("\"name\" is not a string");
    inst.name = it->get<std::string>();
  }
  const json& items = field(doc, "items", top, "instance");
  if (!items.is_array()) top.fail(std::string("\"items\": expected an array, got ") + type_name(items));
  if (items.empty()) top.fail("\"items\" is empty");
  inst.items.reserve(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    const json& it = items[k];
    Context cx{top.where + ": item " + std::to_string(k)};
    if (!it.is_object()) cx.fail(std::string("expected an object, got ") + type_name(it));
    const json& id = field(it, "id", cx, "item");
    std::string ids;
    if (id.is_number_integer()) ids = id.dump();
    else if (id.is_string()) ids = id.get<std::string>();
    else cx.fail(std::string("\"id\": expected an integer or a string, got ") + type_name(id));
    cx.where += " (id " + ids + ")";
    const json& demand = field(it, "demand", cx, "item");
    if (!demand.is_number_unsigned()) cx.fail("\"demand\": expected a non-negative integer");
    std::vector<double> rot;
    if (const auto r = it.find("allowed_orientations"); r != it.end() && !r->is_null()) {
      if (!r->is_array()) cx.fail(std::string("\"allowed_orientations\": expected an array of angles, got ") + type_name(*r));
      if (r->empty()) cx.fail("\"allowed_orientations\" is empty");
      for (std::size_t a = 0; a < r->size(); ++a) rot.push_back(number((*r)[a], cx, "allowed_orientations[" + std::to_string(a) + "]"));
    } else {
      rot = {0.0};
    }
    Shape2 shape = item_shape(field(it, "shape", cx, "item"), cx);
    inst.items.push_back(NestingItem{std::move(ids), demand.get<std::size_t>(), std::move(shape), std::move(rot)});
  }
  return inst;
}

NestingInstance read_nesting_instance(const std::filesystem::path& path) {
  return parse_nesting_instance(io::read_text_file(path), path.string());
}

}  // namespace pendepth
