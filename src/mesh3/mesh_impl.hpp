// Private: the data of a validated Mesh3 (include/pendepth/mesh3.hpp).
#pragma once

#include <pendepth/mesh3.hpp>

#include <mutex>
#include <optional>

namespace pendepth {

struct Mesh3::Impl {
  std::string name, source;
  std::vector<Vec3> points;
  std::vector<std::array<std::size_t, 3>> triangles;  // outward
  std::vector<std::size_t> face_of;
  bool convex = false, flipped = false;
  double volume = 0;
  std::size_t reflex_edges = 0;
  std::once_flag decomposed;
  std::optional<ConvexDecomposition3> decomposition;
};

}  // namespace pendepth
