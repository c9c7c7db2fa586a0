// Exact convex decomposition of a validated closed mesh (include/pendepth/mesh3.hpp;
// docs/algorithms.md "Convex decomposition"; issue 17 item 2).
//
// CGAL's Nef_polyhedron_3 with the exact kernel (Epeck: lazy GMP rationals), then
// convex_decomposition_3 (Hachenberger, "Exact Minkowski sums of polyhedra and exact and
// efficient decomposition of polyhedra into convex pieces", Algorithmica 2009): the solid is cut
// by planes through its reflex edges until no reflex edge is left; O(r²) pieces for r reflex
// edges at worst. The cuts create new vertices where a cut plane crosses an edge of the mesh or of
// another cut: their coordinates are rationals, in general not doubles. Each piece is returned as
// the hull of its vertices rounded to the nearest double (ties to the lower), and the pieces with
// a rounded vertex are counted (ConvexDecomposition3::rounded_pieces), and a sliver piece that
// rounding makes flat is dropped (dropped_slivers; seen on CGAL's dragknob.off): when both are 0
// the pieces are exact — their volumes sum exactly to the mesh's and they tile it. A decomposition that uses
// only the mesh's own vertices does not exist in general (Schönhardt's polyhedron needs Steiner
// points), so the rounding is stated rather than avoided.
//
// The CGAL Nef headers are heavy to compile: they stay in this one file.
#include <pendepth/mesh3.hpp>

#include "mesh3/mesh_impl.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_decomposition_3.h>

#include <map>
#include <set>

namespace pendepth {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Nef = CGAL::Nef_polyhedron_3<K>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Poly = CGAL::Polyhedron_3<K>;

// The double nearest to the exact value x (ties to the lower); `exact` tells whether x is one.
double nearest(const K::FT& x, bool& exact) {
  const auto& e = CGAL::exact(x);
  const std::pair<double, double> iv = CGAL::to_interval(e);
  if (iv.first == iv.second) {
    exact = true;
    return iv.first;
  }
  exact = false;
  using ET = std::decay_t<decltype(e)>;
  return e - ET(iv.first) <= ET(iv.second) - e ? iv.first : iv.second;
}

// Exactly: do the points span less than 3 dimensions?
bool flat(const std::vector<Vec3>& v) {
  for (std::size_t i = 1; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j) {
      if (predicates::collinear3(v[0], v[i], v[j])) continue;
      for (std::size_t k = j + 1; k < v.size(); ++k)
        if (predicates::orient3d(v[0], v[i], v[j], v[k]) != 0) return false;
      return true;  // v[0], v[i], v[j] span a plane holding every point
    }
  return true;
}

}  // namespace

ConvexDecomposition3 convex_decomposition(const Mesh3& mesh) {
  Mesh sm;
  const auto pts = mesh.points();
  std::map<std::size_t, Mesh::Vertex_index> vid;
  for (const auto& t : mesh.triangles())
    for (std::size_t v : t)
      if (!vid.count(v)) vid.emplace(v, sm.add_vertex(K::Point_3(pts[v].x(), pts[v].y(), pts[v].z())));
  for (const auto& t : mesh.triangles()) sm.add_face(vid.at(t[0]), vid.at(t[1]), vid.at(t[2]));

  Nef N(sm);
  CGAL::convex_decomposition_3(N);

  std::set<std::array<double, 3>> mesh_vertices;
  for (const auto& [i, v] : vid) mesh_vertices.insert({pts[i].x(), pts[i].y(), pts[i].z()});
  std::set<std::array<double, 3>> cut;

  ConvexDecomposition3 out;
  out.reflex_edges = mesh.reflex_edges();
  for (auto ci = ++N.volumes_begin(); ci != N.volumes_end(); ++ci) {  // the first is the outer volume
    if (!ci->mark()) continue;
    Poly P;
    N.convert_inner_shell_to_polyhedron(ci->shells_begin(), P);
    std::vector<Vec3> v;
    bool rounded = false;
    for (auto it = P.points_begin(); it != P.points_end(); ++it) {
      bool ex[3];
      const Vec3 q(nearest(it->x(), ex[0]), nearest(it->y(), ex[1]), nearest(it->z(), ex[2]));
      const bool exact = ex[0] && ex[1] && ex[2];
      rounded = rounded || !exact;
      if (!exact || !mesh_vertices.count({q.x(), q.y(), q.z()})) cut.insert({q.x(), q.y(), q.z()});
      v.push_back(q);
    }
    const std::string name = mesh.name() + " piece " + std::to_string(out.pieces.size());
    if (!flat(v)) {
      out.pieces.push_back(ConvexPolytope::hull(v, name));
    } else {  // a sliver thinner than the rounding: only a rounded piece can be flat
      ++out.dropped_slivers;
      continue;
    }
    if (rounded) ++out.rounded_pieces;
  }
  out.cut_vertices = cut.size();
  return out;
}

}  // namespace pendepth
