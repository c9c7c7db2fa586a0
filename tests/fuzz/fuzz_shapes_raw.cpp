// libFuzzer target: raw bytes through the readers into the front door, as the command-line tool
// reads `-`: the format guessed from the content (io::guess_shape_format), the shape read and
// validated, then queried against itself and a fixed convex and non-convex companion
// (fuzz_shapes.hpp invariants). Any magnitude the numeric domain accepts (docs/robustness.md):
// a pair it rejects throws InvalidInput, which is allowed. Coordinates are kept below
// kRawCoordLimit = 1e300 only because the invariants want finite depths, and a pair of shapes
// near DBL_MAX may rightly answer an explicit infinity (tests/front/test_domain.cpp covers it).
// The input of the one finding (3D σ lost its translation when 1e-44 and 1 mixed; fixed in
// minimum_expand.cpp) is in the corpus.
#include <pendepth/io.hpp>

#include "fuzz_shapes.hpp"

namespace io = pendepth::io;

namespace {

constexpr double kRawCoordLimit = 1e300;

bool small(const std::vector<std::vector<fuzz::Vec2>>& rings, std::size_t max_vertices) {
  std::size_t n = 0;
  for (const auto& r : rings) {
    n += r.size();
    for (const auto& p : r)
      if (std::fabs(p.x()) > kRawCoordLimit || std::fabs(p.y()) > kRawCoordLimit) return false;
  }
  return n <= max_vertices;
}

}  // namespace

PENDEPTH_FUZZ_TARGET(fuzz_shapes_raw) {
  if (size > 4096) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const auto format = io::guess_shape_format(bytes);
  if (!format) return 0;
  // The placements come from a hash of the input (its bytes are the shape).
  std::uint8_t seed[64];
  std::uint64_t h = 1469598103934665603ull;
  for (char c : bytes) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  for (std::size_t i = 0; i < sizeof seed; ++i) seed[i] = static_cast<std::uint8_t>(h >> (8 * (i % 8))) ^ std::uint8_t(i * 37);
  fuzz::Bytes b(seed, sizeof seed);
  if (*format == io::ShapeFormat::Wkt) {
    fuzz::allowed([&] {
      const io::Shape2 s = io::shape2_from_wkt(io::parse_wkt_polygon(bytes, "<stdin>"), "<stdin>", "P");
      const fuzz::Shape2 P = s.convex ? fuzz::Shape2(*s.convex) : fuzz::Shape2(*s.polygon);
      if (!small(P.rings(), 48)) return;
      const fuzz::Shape2 square(std::vector<fuzz::Vec2>{{0, 0}, {4, 0}, {4, 3}, {0, 3}});
      const fuzz::Shape2 ell(std::vector<fuzz::Vec2>{{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 5}, {0, 5}});
      fuzz::exercise2(b, P, P);
      fuzz::exercise2(b, P, square);
      fuzz::exercise2(b, ell, P);
    });
  } else {
    fuzz::allowed([&] {
      const auto pts = io::parse_mesh_points(bytes, *format, "<stdin>");
      if (pts.size() > 64) return;
      for (const fuzz::Vec3& p : pts)
        if (p.cwiseAbs().maxCoeff() > kRawCoordLimit) return;
      const fuzz::Shape3 P(io::convex_polytope_from_points(pts, "<stdin>", "P"));
      const fuzz::Shape3 cube = fuzz::Shape3::hull(std::vector<fuzz::Vec3>{
          {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}});
      fuzz::exercise3(b, P, P);
      fuzz::exercise3(b, P, cube);
    });
  }
  return 0;
}
