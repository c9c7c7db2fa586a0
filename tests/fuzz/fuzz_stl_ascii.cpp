// libFuzzer target: the ASCII STL reader (inputs not starting with "solid" get it prepended, and
// a newline is appended to one whose size makes it binary STL, so executions reach the text
// parser). Invariants: only InvalidInput (one printable line);
// accepted vertices are finite, distinct, at most one per line.
#include <pendepth/io.hpp>

#include "fuzz_common.hpp"

#include <algorithm>
#include <string>

PENDEPTH_FUZZ_TARGET(fuzz_stl_ascii) {
  if (size > 4096) return 0;
  std::string text(reinterpret_cast<const char*>(data), size);
  if (text.rfind("solid", 0) != 0) text.insert(0, "solid fuzz\n");
  // A size of 84 + 50·count (count at byte 80) makes it binary STL (fuzz_stl_binary's domain).
  if (text.size() >= 84) {
    const auto* u = reinterpret_cast<const unsigned char*>(text.data() + 80);
    const std::uint64_t count = u[0] | u[1] << 8 | u[2] << 16 | std::uint64_t(u[3]) << 24;
    if (text.size() == 84 + 50 * count) text += '\n';
  }
  fuzz::allowed([&] {
    const auto pts = pendepth::io::parse_stl_points(text, "f.stl");
    fuzz::check(pts.size() <= static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1,
                "more vertices than lines");
    for (std::size_t i = 0; i < pts.size(); ++i) {
      fuzz::check(pts[i].allFinite(), "non-finite vertex accepted");
      if (pts.size() < 64)
        for (std::size_t j = 0; j < i; ++j) fuzz::check(pts[i] != pts[j], "repeated vertex returned");
    }
  });
  return 0;
}
