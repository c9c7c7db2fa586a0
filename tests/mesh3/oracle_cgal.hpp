// Independent CGAL oracles for test_mesh3 (CGAL headers only in oracle_cgal.cpp).
#pragma once

#include <pendepth/geometry.hpp>

#include <array>
#include <vector>

namespace mesh3_test {

/// CGAL::Polygon_mesh_processing::does_self_intersect (Epick, exact predicates) on a closed
/// triangle mesh.
bool cgal_self_intersects(const std::vector<pendepth::Vec3>& pts, const std::vector<std::array<std::size_t, 3>>& tris);

/// CGAL::Side_of_triangle_mesh (Epick): 1 inside, 0 on the boundary, -1 outside.
class CgalInside {
 public:
  CgalInside(const std::vector<pendepth::Vec3>& pts, const std::vector<std::array<std::size_t, 3>>& tris);
  ~CgalInside();
  int side(const pendepth::Vec3& q) const;

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace mesh3_test
