// libFuzzer target: the WKT readers (parse_wkt_polygon, parse_wkt_geometry) and the 2D shape
// validation behind them. Invariants: only InvalidInput is thrown, with a one-line printable
// message; what is accepted is finite, has rings of >= 3 points, and reads back exactly from
// to_wkt; the validated shape is convex or a polygon, never both.
#include <pendepth/io.hpp>

#include "fuzz_common.hpp"

namespace io = pendepth::io;

PENDEPTH_FUZZ_TARGET(fuzz_wkt) {
  if (size > 4096) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  fuzz::allowed([&] {
    const io::WktPolygon w = io::parse_wkt_polygon(text, "f.wkt");
    fuzz::check(!w.rings.empty() && w.rings.size() == w.lines.size(), "rings and lines");
    for (std::size_t r = 0; r < w.rings.size(); ++r) {
      fuzz::check(w.rings[r].size() >= 3 && w.rings[r].size() == w.lines[r].size(), "ring size");
      for (const pendepth::Vec2& p : w.rings[r])
        fuzz::check(std::isfinite(p.x()) && std::isfinite(p.y()), "non-finite vertex accepted");
      const std::string back = io::to_wkt(w.rings[r]);
      const io::WktPolygon again = io::parse_wkt_polygon(back, "back.wkt");
      fuzz::check(again.rings.size() == 1 && again.rings[0] == w.rings[r], "WKT round trip");
    }
    const io::Shape2 s = io::shape2_from_wkt(w, "f.wkt", "P");
    fuzz::check(s.convex.has_value() != s.polygon.has_value(), "convex xor polygon");
  });
  fuzz::allowed([&] {
    const io::Geometry2 g = io::parse_wkt_geometry(text, "f.wkt");
    const io::Geometry2 again = io::parse_wkt_geometry(io::to_wkt(g), "back.wkt");
    fuzz::check(again.polygons == g.polygons && again.lines == g.lines && again.points == g.points,
                "WKT geometry round trip");
  });
  return 0;
}
