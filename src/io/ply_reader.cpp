// PLY reader (Turk's polygon file format): ASCII and binary (little and big endian) 1.0, the
// vertex positions and the face vertex lists (docs/design.md §3; include/pendepth/io.hpp).
//
// Strict like the other mesh readers: the header must declare what the body holds, the body must
// hold exactly that (ASCII: one element per line; binary: exactly the declared bytes), and every
// error names the file and the header or body line (ASCII) or the byte offset (binary).
#include <pendepth/io.hpp>

#include "io/number.hpp"
#include "io/printable.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>

namespace pendepth::io {
namespace {

enum class Type { I8, U8, I16, U16, I32, U32, F32, F64 };

std::optional<Type> type_of(std::string_view s) {
  if (s == "char" || s == "int8") return Type::I8;
  if (s == "uchar" || s == "uint8") return Type::U8;
  if (s == "short" || s == "int16") return Type::I16;
  if (s == "ushort" || s == "uint16") return Type::U16;
  if (s == "int" || s == "int32") return Type::I32;
  if (s == "uint" || s == "uint32") return Type::U32;
  if (s == "float" || s == "float32") return Type::F32;
  if (s == "double" || s == "float64") return Type::F64;
  return std::nullopt;
}

std::size_t size_of(Type t) {
  switch (t) {
    case Type::I8: case Type::U8: return 1;
    case Type::I16: case Type::U16: return 2;
    case Type::I32: case Type::U32: case Type::F32: return 4;
    case Type::F64: return 8;
  }
  return 0;
}

bool is_float(Type t) { return t == Type::F32 || t == Type::F64; }

struct Property {
  std::string name;
  Type type = Type::F32;        // the item type for lists
  bool list = false;
  Type count_type = Type::U8;   // lists only
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> props;
};

enum class Encoding { Ascii, Little, Big };

[[noreturn]] void fail_line(std::string_view source, std::size_t line, const std::string& what) {
  throw InvalidInput(std::string(source) + ":" + std::to_string(line) + ": " + what);
}
[[noreturn]] void fail_byte(std::string_view source, std::size_t offset, const std::string& what) {
  throw InvalidInput(std::string(source) + ": " + what + " (byte offset " + std::to_string(offset) + ")");
}

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> w;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    const std::size_t b = i;
    while (i < line.size() && !blank(line[i])) ++i;
    if (i > b) w.push_back(line.substr(b, i - b));
  }
  return w;
}

// One value of a property: integers exactly (as double: every PLY integer type fits), floats as
// read. `ok` false when an ASCII token is not a number of the type.
bool ascii_value(std::string_view tok, Type t, double& x) {
  if (is_float(t)) {
    const char* end = nullptr;
    const auto st = detail::read_decimal(tok.data(), tok.data() + tok.size(), x, end);
    if (st == detail::Decimal::NotNumber || end != tok.data() + tok.size()) return false;
    if (st != detail::Decimal::Ok) x = std::numeric_limits<double>::infinity();  // caught by the caller
    return true;
  }
  std::int64_t v = 0;
  auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (ec != std::errc() || ptr != tok.data() + tok.size()) return false;
  x = static_cast<double>(v);
  return true;
}

double binary_value(const char* p, Type t, bool big) {
  unsigned char b[8];
  const std::size_t n = size_of(t);
  for (std::size_t i = 0; i < n; ++i) b[i] = static_cast<unsigned char>(p[big ? n - 1 - i : i]);
  std::uint64_t u = 0;
  for (std::size_t i = 0; i < n; ++i) u |= std::uint64_t(b[i]) << (8 * i);
  switch (t) {
    case Type::I8: return static_cast<std::int8_t>(u);
    case Type::U8: return static_cast<std::uint8_t>(u);
    case Type::I16: return static_cast<std::int16_t>(u);
    case Type::U16: return static_cast<std::uint16_t>(u);
    case Type::I32: return static_cast<std::int32_t>(u);
    case Type::U32: return static_cast<std::uint32_t>(u);
    case Type::F32: return std::bit_cast<float>(static_cast<std::uint32_t>(u));
    case Type::F64: return std::bit_cast<double>(u);
  }
  return 0;
}

constexpr const char* kAxis[] = {"x", "y", "z"};

}  // namespace

MeshFile parse_ply(std::string_view bytes, std::string_view source) {
  MeshFile m;
  m.source = std::string(source);
  // ---- header: lines up to and including `end_header` ----
  std::size_t pos = 0, line_no = 0;
  auto next_header_line = [&](std::string_view& line) {
    if (pos >= bytes.size()) fail_line(source, line_no, "the file ends inside the PLY header (no 'end_header')");
    const std::size_t e = bytes.find('\n', pos);
    const std::size_t end = e == std::string_view::npos ? bytes.size() : e;
    line = bytes.substr(pos, end - pos);
    pos = e == std::string_view::npos ? bytes.size() : e + 1;
    ++line_no;
  };
  std::string_view line;
  next_header_line(line);
  if (words(line) != std::vector<std::string_view>{"ply"})
    fail_line(source, 1, "not a PLY file: the first line must be 'ply'");
  Encoding enc = Encoding::Ascii;
  bool have_format = false;
  std::vector<Element> elements;
  std::vector<std::size_t> element_line;
  for (;;) {
    next_header_line(line);
    const auto w = words(line);
    if (w.empty()) continue;
    if (w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") {
      if (w.size() != 1) fail_line(source, line_no, "malformed 'end_header' line");
      break;
    }
    if (w[0] == "format") {
      if (have_format) fail_line(source, line_no, "a second 'format' line");
      if (w.size() != 3 || w[2] != "1.0")
        fail_line(source, line_no, "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      if (w[1] == "ascii") enc = Encoding::Ascii;
      else if (w[1] == "binary_little_endian") enc = Encoding::Little;
      else if (w[1] == "binary_big_endian") enc = Encoding::Big;
      else fail_line(source, line_no, "unknown PLY format '" + detail::printable(w[1]) + "'");
      have_format = true;
      continue;
    }
    if (!have_format) fail_line(source, line_no, "expected the 'format' line after 'ply'");
    if (w[0] == "element") {
      std::uint64_t n = 0;
      auto [ptr, ec] = w.size() == 3 ? std::from_chars(w[2].data(), w[2].data() + w[2].size(), n)
                                     : std::from_chars_result{nullptr, std::errc::invalid_argument};
      if (w.size() != 3 || ec != std::errc() || ptr != w[2].data() + w[2].size())
        fail_line(source, line_no, "expected 'element NAME COUNT' (COUNT a non-negative integer)");
      elements.push_back({std::string(w[1]), n, {}});
      element_line.push_back(line_no);
      continue;
    }
    if (w[0] == "property") {
      if (elements.empty()) fail_line(source, line_no, "a 'property' line before any 'element' line");
      Property p;
      if (w.size() == 5 && w[1] == "list") {
        const auto ct = type_of(w[2]), it = type_of(w[3]);
        if (!ct || is_float(*ct)) fail_line(source, line_no, "list count type '" + detail::printable(w[2]) + "' is not an integer type");
        if (!it) fail_line(source, line_no, "unknown property type '" + detail::printable(w[3]) + "'");
        p = {std::string(w[4]), *it, true, *ct};
      } else if (w.size() == 3) {
        const auto t = type_of(w[1]);
        if (!t) fail_line(source, line_no, "unknown property type '" + detail::printable(w[1]) + "'");
        p = {std::string(w[2]), *t, false, Type::U8};
      } else {
        fail_line(source, line_no, "expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
      }
      elements.back().props.push_back(p);
      continue;
    }
    fail_line(source, line_no, "unexpected '" + detail::printable(w[0]) + "' in the PLY header");
  }
  if (!have_format) fail_line(source, line_no, "no 'format' line in the PLY header");

  // The vertex element with float/double x, y, z; the face element's index list.
  std::size_t vertex_el = elements.size(), face_el = elements.size();
  std::array<std::size_t, 3> xyz = {~std::size_t(0), ~std::size_t(0), ~std::size_t(0)};
  std::size_t index_prop = ~std::size_t(0);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const Element& el = elements[e];
    if (el.name == "vertex") {
      vertex_el = e;
      for (std::size_t k = 0; k < el.props.size(); ++k)
        for (int a = 0; a < 3; ++a)
          if (el.props[k].name == kAxis[a]) {
            if (el.props[k].list || !is_float(el.props[k].type))
              fail_line(source, element_line[e], std::string("vertex property ") + kAxis[a] + " must be float or double");
            xyz[a] = k;
          }
      for (int a = 0; a < 3; ++a)
        if (xyz[a] == ~std::size_t(0))
          fail_line(source, element_line[e], std::string("the vertex element has no '") + kAxis[a] + "' property");
    } else if (el.name == "face") {
      face_el = e;
      for (std::size_t k = 0; k < el.props.size(); ++k)
        if (el.props[k].name == "vertex_indices" || el.props[k].name == "vertex_index") {
          if (!el.props[k].list || is_float(el.props[k].type))
            fail_line(source, element_line[e], "the face property " + el.props[k].name + " must be a list of integers");
          index_prop = k;
        }
      if (index_prop == ~std::size_t(0))
        fail_line(source, element_line[e], "the face element has no 'vertex_indices' list");
    }
  }
  if (vertex_el == elements.size()) fail_line(source, line_no, "the PLY header declares no 'vertex' element");
  const std::uint64_t nv = elements[vertex_el].count;
  m.points.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(nv, bytes.size() / 3 + 1)));
  m.byte_offsets = enc != Encoding::Ascii;

  // Where face f's indices are checked (after all elements: a face may precede the vertices).
  auto check_index = [&](double v, std::size_t f, std::size_t where) {
    if (v < 0 || v >= static_cast<double>(nv)) {
      const std::string what = "face " + std::to_string(f) + ": vertex index " + std::to_string(static_cast<std::int64_t>(v)) +
                                " is out of range (the file has " + std::to_string(nv) + (nv == 1 ? " vertex)" : " vertices)");
      if (enc == Encoding::Ascii) fail_line(source, where, what);
      fail_byte(source, where, what);
    }
  };

  if (enc == Encoding::Ascii) {
    auto next_body_line = [&](std::string_view& out, const std::string& wanted) {
      for (;;) {
        if (pos >= bytes.size()) fail_line(source, line_no, "the file ends before " + wanted);
        const std::size_t e = bytes.find('\n', pos);
        const std::size_t end = e == std::string_view::npos ? bytes.size() : e;
        out = bytes.substr(pos, end - pos);
        pos = e == std::string_view::npos ? bytes.size() : e + 1;
        ++line_no;
        if (!words(out).empty()) return;
      }
    };
    for (std::size_t e = 0; e < elements.size(); ++e) {
      const Element& el = elements[e];
      for (std::uint64_t i = 0; i < el.count; ++i) {
        const std::string what = el.name + " " + std::to_string(i);
        next_body_line(line, what + " (the header declares " + std::to_string(el.count) + " " + el.name + " elements)");
        const auto w = words(line);
        std::size_t t = 0;
        Vec3 p(0, 0, 0);
        if (e == face_el) m.begin_face(line_no);
        for (std::size_t k = 0; k < el.props.size(); ++k) {
          const Property& pr = el.props[k];
          auto value = [&](Type type, const char* role) {
            if (t >= w.size()) fail_line(source, line_no, "malformed " + what + ": too few values");
            double x = 0;
            if (!ascii_value(w[t], type, x))
              fail_line(source, line_no, "malformed " + what + ": " + role + " '" + detail::printable(w[t]) +
                                             "' is not " + (is_float(type) ? "a number" : "an integer"));
            ++t;
            return x;
          };
          if (!pr.list) {
            const double x = value(pr.type, ("property " + pr.name).c_str());
            if (e == vertex_el)
              for (int a = 0; a < 3; ++a)
                if (k == xyz[a]) {
                  if (!std::isfinite(x))
                    fail_line(source, line_no, what + " has a non-finite " + kAxis[a] + ": '" + detail::printable(w[t - 1]) + "'");
                  p[a] = x;
                }
            continue;
          }
          const double count = value(pr.count_type, ("list count of " + pr.name).c_str());
          if (count < 0) fail_line(source, line_no, "malformed " + what + ": negative list count");
          if (e == face_el && k == index_prop && count < 3)
            fail_line(source, line_no, "malformed " + what + ": " + std::to_string(static_cast<int>(count)) + " vertices (at least 3)");
          for (std::uint64_t j = 0; j < static_cast<std::uint64_t>(count); ++j) {
            const double x = value(pr.type, ("list item of " + pr.name).c_str());
            if (e == face_el && k == index_prop) {
              check_index(x, m.faces(), line_no);
              m.indices.push_back(static_cast<std::size_t>(x));
            }
          }
        }
        if (t != w.size())
          fail_line(source, line_no, "malformed " + what + ": " + std::to_string(w.size() - t) + " values more than its properties");
        if (e == vertex_el) m.points.push_back(p);
      }
    }
    while (pos < bytes.size()) {
      const std::size_t e = bytes.find('\n', pos);
      const std::size_t end = e == std::string_view::npos ? bytes.size() : e;
      line = bytes.substr(pos, end - pos);
      pos = e == std::string_view::npos ? bytes.size() : e + 1;
      ++line_no;
      if (!words(line).empty()) fail_line(source, line_no, "unexpected '" + detail::printable(words(line)[0]) + "' after the last element");
    }
    return m;
  }

  const bool big = enc == Encoding::Big;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const Element& el = elements[e];
    for (std::uint64_t i = 0; i < el.count; ++i) {
      const std::size_t start = pos;
      Vec3 p(0, 0, 0);
      if (e == face_el) m.begin_face(start);
      auto read = [&](Type t) {
        if (bytes.size() - pos < size_of(t))
          fail_byte(source, pos, "the file ends inside " + el.name + " " + std::to_string(i) + " (the header declares " +
                                     std::to_string(el.count) + " " + el.name + " elements)");
        const double x = binary_value(bytes.data() + pos, t, big);
        pos += size_of(t);
        return x;
      };
      for (std::size_t k = 0; k < el.props.size(); ++k) {
        const Property& pr = el.props[k];
        if (!pr.list) {
          const std::size_t at = pos;
          const double x = read(pr.type);
          if (e == vertex_el)
            for (int a = 0; a < 3; ++a)
              if (k == xyz[a]) {
                if (!std::isfinite(x))
                  fail_byte(source, at, "vertex " + std::to_string(i) + ": " + kAxis[a] + " is not a finite number");
                p[a] = x;
              }
          continue;
        }
        const std::size_t at = pos;
        const double count = read(pr.count_type);
        if (count < 0) fail_byte(source, at, el.name + " " + std::to_string(i) + ": negative list count");
        if (e == face_el && k == index_prop && count < 3)
          fail_byte(source, at, "face " + std::to_string(i) + ": " + std::to_string(static_cast<int>(count)) + " vertices (at least 3)");
        for (std::uint64_t j = 0; j < static_cast<std::uint64_t>(count); ++j) {
          const std::size_t item_at = pos;
          const double x = read(pr.type);
          if (e == face_el && k == index_prop) {
            check_index(x, m.faces(), item_at);
            m.indices.push_back(static_cast<std::size_t>(x));
          }
        }
      }
      if (e == vertex_el) m.points.push_back(p);
    }
  }
  if (pos != bytes.size())
    fail_byte(source, pos, std::to_string(bytes.size() - pos) + " bytes after the last element");
  return m;
}

}  // namespace pendepth::io
