// Shape3 from mesh files (docs/design.md §3): a file without faces is a point set (its hull), a
// closed convex mesh takes the convex path, a non-convex closed mesh is a mesh shape.
#include <pendepth/io.hpp>
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>
#include <pendepth/shape_spec.hpp>

namespace pendepth {

Shape3 Shape3::from_file(const std::filesystem::path& path, std::string_view name, bool hull) {
  io::MeshFile file = io::read_mesh(path);
  // A point set — or a file whose points are coplanar: a flat shape (io::shape3_from_points).
  if (hull || file.faces() == 0 || io::affine_dimension(file.points) < 3)
    return io::shape3_from_points(file.points, file.source, name);
  return from_mesh(Mesh3::validate(file, name));
}

Shape3 Shape3::from_mesh(const Mesh3& mesh) {
  Shape3 s(io::convex_polytope_from_points(mesh.used_points(), mesh.source(), mesh.name()));
  s.mesh_ = std::make_shared<const Mesh3>(mesh);
  return s;
}

bool Shape3::is_convex() const { return !mesh_ || mesh_->convex(); }
const Mesh3* Shape3::mesh() const { return mesh_.get(); }

}  // namespace pendepth
