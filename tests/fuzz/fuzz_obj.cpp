// libFuzzer target: the OBJ reader. Invariants: only InvalidInput (one printable line); accepted
// vertices are finite and at most one per line.
#include <pendepth/io.hpp>

#include "fuzz_common.hpp"

#include <algorithm>

PENDEPTH_FUZZ_TARGET(fuzz_obj) {
  if (size > 4096) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  fuzz::allowed([&] {
    const auto pts = pendepth::io::parse_obj_points(text, "f.obj");
    fuzz::check(pts.size() <= static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1,
                "more vertices than lines");
    for (const pendepth::Vec3& p : pts) fuzz::check(p.allFinite(), "non-finite vertex accepted");
  });
  return 0;
}
