#include "oracle_cgal.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

namespace mesh3_test {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

Mesh make(const std::vector<pendepth::Vec3>& pts, const std::vector<std::array<std::size_t, 3>>& tris) {
  Mesh m;
  for (const auto& p : pts) m.add_vertex(K::Point_3(p.x(), p.y(), p.z()));
  for (const auto& t : tris)
    m.add_face(Mesh::Vertex_index(static_cast<unsigned>(t[0])), Mesh::Vertex_index(static_cast<unsigned>(t[1])),
               Mesh::Vertex_index(static_cast<unsigned>(t[2])));
  return m;
}
}  // namespace

bool cgal_self_intersects(const std::vector<pendepth::Vec3>& pts, const std::vector<std::array<std::size_t, 3>>& tris) {
  const Mesh m = make(pts, tris);
  return CGAL::Polygon_mesh_processing::does_self_intersect(m);
}

struct CgalInside::Impl {
  Mesh mesh;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, K>> side;
};

CgalInside::CgalInside(const std::vector<pendepth::Vec3>& pts, const std::vector<std::array<std::size_t, 3>>& tris)
    : impl_(new Impl) {
  impl_->mesh = make(pts, tris);
  impl_->side = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, K>>(impl_->mesh);
}
CgalInside::~CgalInside() { delete impl_; }

int CgalInside::side(const pendepth::Vec3& q) const {
  const auto s = (*impl_->side)(K::Point_3(q.x(), q.y(), q.z()));
  return s == CGAL::ON_BOUNDED_SIDE ? 1 : s == CGAL::ON_BOUNDARY ? 0 : -1;
}

}  // namespace mesh3_test
