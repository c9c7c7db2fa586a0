// libFuzzer target: the binary STL reader. The first byte chooses the input: odd, the raw bytes;
// even, an 80-byte header and a triangle count that matches the rest (so most executions read
// triangles rather than stop at the size check). Invariants: only InvalidInput (one printable
// line); accepted vertices are finite, distinct, at most 3 per triangle.
#include <pendepth/io.hpp>

#include "fuzz_common.hpp"

#include <string>

PENDEPTH_FUZZ_TARGET(fuzz_stl_binary) {
  if (size < 1 || size > 8192) return 0;
  std::string bytes;
  std::size_t triangles = 0;
  if (data[0] & 1) {
    bytes.assign(reinterpret_cast<const char*>(data + 1), size - 1);
  } else {
    triangles = (size - 1) / 50;
    bytes.assign(80, ' ');
    for (int k = 0; k < 4; ++k) bytes += static_cast<char>((triangles >> (8 * k)) & 0xFF);
    bytes.append(reinterpret_cast<const char*>(data + 1), 50 * triangles);
  }
  fuzz::allowed([&] {
    const auto pts = pendepth::io::parse_stl_points(bytes, "f.stl");
    if (!(data[0] & 1)) fuzz::check(pts.size() <= 3 * triangles, "more vertices than triangle corners");
    for (std::size_t i = 0; i < pts.size(); ++i) {
      fuzz::check(pts[i].allFinite(), "non-finite vertex accepted");
      if (pts.size() < 64)
        for (std::size_t j = 0; j < i; ++j) fuzz::check(pts[i] != pts[j], "repeated vertex returned");
    }
  });
  return 0;
}
